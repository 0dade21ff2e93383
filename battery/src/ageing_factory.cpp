#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/core/error.hpp"

#include <stdexcept>

namespace ceilplan::battery {

const std::vector<std::string>& ageingModelNames() {
  static const std::vector<std::string> names{"fec", "xu", "schmalstieg", "woehler"};
  return names;
}

std::unique_ptr<AgeingModel> makeAgeingModel(const std::string& name, const AgeingModelOptions& options) {
  if (name == "fec") return std::make_unique<FecAgeingModel>(options.woehler);
  if (name == "xu") return std::make_unique<XuAgeingModel>(options.conditions, options.xu);
  if (name == "schmalstieg")
    return std::make_unique<SchmalstiegAgeingModel>(options.conditions, options.cell_voltage_of_soc,
                                                    options.schmalstieg);
  if (name == "woehler") return std::make_unique<WoehlerAgeingModel>(options.woehler);
  std::string known;
  for (const auto& n : ageingModelNames()) known += (known.empty() ? "" : ", ") + n;
  throw ceilplan::InputError("unknown ageing model '" + name + "'; choose one of " + known);
}

}  // namespace ceilplan::battery
