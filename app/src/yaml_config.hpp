#pragma once
// Lets every subcommand read `--config FILE.yaml` whose keys are its long flag names
// (`capacity-ah: 5.2`, or `capacity_ah`), a sequence standing for a repeated flag.

#include <CLI/CLI.hpp>

#include <istream>
#include <string>
#include <vector>

namespace ceilplan::app {

class YamlConfig : public CLI::Config {
 public:
  std::string to_config(const CLI::App* app, bool default_also, bool write_description,
                        std::string prefix) const override;
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override;
};

}  // namespace ceilplan::app
