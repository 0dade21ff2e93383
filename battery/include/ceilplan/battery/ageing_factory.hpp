#pragma once
/// @file
/// Makes the ageing models by name, for side-by-side studies.

#include "ceilplan/battery/ageing_model.hpp"
#include "ceilplan/battery/schmalstieg_ageing.hpp"
#include "ceilplan/battery/woehler_ageing.hpp"
#include "ceilplan/battery/xu_ageing.hpp"
#include "ceilplan/core/error.hpp"

#include <memory>
#include <string>
#include <vector>

namespace ceilplan::battery {

/// What makeAgeingModel needs to build any model: the study's conditions and each model's constants.
struct AgeingModelOptions {
  OperatingConditions conditions;        ///< temperature and chemistry of the study
  CellVoltageOfSoc cell_voltage_of_soc;  ///< needed by "schmalstieg" only
  WoehlerParameters woehler;             ///< used by "fec" (N100) and "woehler"
  XuParameters xu;                       ///< used by "xu"
  SchmalstiegParameters schmalstieg;     ///< used by "schmalstieg"
};

/// "fec", "xu", "schmalstieg", "woehler", in that order.
const std::vector<std::string>& ageingModelNames();

/// Throws ceilplan::InputError for an unknown name (listing the known ones) or bad options.
std::unique_ptr<AgeingModel> makeAgeingModel(const std::string& name, const AgeingModelOptions& options);

}  // namespace ceilplan::battery
