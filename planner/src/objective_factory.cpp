#include "ceilplan/planner/objective_factory.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/ageing_objective.hpp"
#include "ceilplan/planner/charge_objective.hpp"
#include "ceilplan/planner/fec_objective.hpp"
#include "ceilplan/planner/length_objective.hpp"
#include "ceilplan/planner/time_objective.hpp"

#include <stdexcept>

namespace ceilplan::planner {

const std::vector<std::string>& objectiveNames() {
  static const std::vector<std::string> names{"length", "time", "charge", "fec", "ageing"};
  return names;
}

std::shared_ptr<FlightObjective> makeObjective(const ObjectiveChoice& choice, const ompl::base::SpaceInformationPtr& si,
                                               const FlightCostModel& model) {
  if (choice.name == "length") return std::make_shared<LengthObjective>(si, model);
  if (choice.name == "time") return std::make_shared<TimeObjective>(si, model);
  if (choice.name == "charge") return std::make_shared<ChargeObjective>(si, model);
  if (choice.name == "fec") return std::make_shared<FecObjective>(si, model, choice.nominal_capacity_ah);
  if (choice.name == "ageing") return std::make_shared<AgeingObjective>(si, model, choice.ageing);
  throw ceilplan::InputError("unknown objective '" + choice.name + "': choose length, time, charge, fec or ageing");
}

}  // namespace ceilplan::planner
