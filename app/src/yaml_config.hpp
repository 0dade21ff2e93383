#pragma once
// Lets every subcommand read `--config FILE.yaml` whose keys are its long flag names
// (`capacity-ah: 5.2`, or `capacity_ah`), a sequence standing for a repeated flag. Flags given
// on the command line win over the file; an unknown key is an error.
//
// CLI11 2.1 reads config files on the main app only, so `--config` belongs to the main app,
// subcommands fall through to it, and this formatter files each key under the subcommand the
// user chose.

#include <CLI/CLI.hpp>

#include <istream>
#include <string>
#include <vector>

namespace ceilplan::app {

// Checks the `--config` file (io::requireFlagFile) before CLI11 opens it: opening a FIFO blocks.
CLI::Validator configFileCheck();

class YamlConfig : public CLI::Config {
 public:
  explicit YamlConfig(const CLI::App& root) : root_(&root) {}

  std::string to_config(const CLI::App* app, bool default_also, bool write_description,
                        std::string prefix) const override;
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override;

 private:
  const CLI::App* root_;
};

}  // namespace ceilplan::app
