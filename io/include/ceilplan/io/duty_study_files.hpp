#pragma once
/// @file
/// What `ceilplan duty` prints and writes of a duty study (battery::runDutyStudy; docs/battery.md).

#include "ceilplan/battery/duty_study.hpp"
#include "ceilplan/io/provenance.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace ceilplan::io {

/// The study as a table: the scenario, each case's SOC, charge and FEC figures, then each ageing
/// model's wear, fade, end of life and reductions, the cases that stopped early and the models'
/// validity warnings.
std::string dutyStudyTable(const battery::DutyStudyOptions& options, const battery::DutyStudyResult& result);

/// {"scenario": {...}, "cases": [{flight_current_a, min_soc, charge_end_min, fec_per_mission,
/// fec_per_day, fec_total, charge_ah_total, discharge_ah_total, reduction_pct, ageing: [...]}]}.
nlohmann::json dutyStudyJson(const battery::DutyStudyOptions& options, const battery::DutyStudyResult& result);

/// The provenance comment line, then t_s,current_a,soc,fec,fec_continuous,mode. Atomic.
void writeDutySeriesCsv(const std::filesystem::path& file, const std::vector<battery::Sample>& samples,
                        const Provenance& provenance);

/// DIR/caseN_mission.csv, caseN_day.csv and caseN_run.csv (duty series of one mission, one day and
/// the whole run), caseN_soh.csv (model,day,soh; with ageing models) and cases.csv (case, prefix,
/// flight_current_a), each starting with the provenance comment line. Each file atomic.
void writeDutyStudyCsv(const std::filesystem::path& dir, const battery::DutyStudyResult& result,
                       const Provenance& provenance);

}  // namespace ceilplan::io
