#pragma once
// What `ceilplan duty` prints and writes of a duty study (battery::runDutyStudy; docs/battery.md).

#include "ceilplan/battery/duty_study.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace ceilplan::io {

// The study as a table: the scenario, each case's SOC, charge and FEC figures, then each ageing
// model's wear, fade, end of life and reductions, the cases that stopped early and the models'
// validity warnings.
std::string dutyStudyTable(const battery::DutyStudyOptions& options, const battery::DutyStudyResult& result);

// {"scenario": {...}, "cases": [{flight_current_a, min_soc, charge_end_min, fec_per_mission,
// fec_per_day, fec_total, charge_ah_total, discharge_ah_total, reduction_pct, ageing: [...]}]}.
nlohmann::json dutyStudyJson(const battery::DutyStudyOptions& options, const battery::DutyStudyResult& result);

// t_s,current_a,soc,fec,fec_continuous,mode. Atomic.
void writeDutySeriesCsv(const std::filesystem::path& file, const std::vector<battery::Sample>& samples);

// DIR/caseN_mission.csv, caseN_day.csv and caseN_run.csv (duty series of one mission, one day and
// the whole run), caseN_soh.csv (model,day,soh; with ageing models) and cases.csv (case, prefix,
// flight_current_a). Each file atomic.
void writeDutyStudyCsv(const std::filesystem::path& dir, const battery::DutyStudyResult& result);

}  // namespace ceilplan::io
