#include "command_registry.hpp"
#include "errors.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/version.hpp"
#include "yaml_config.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <memory>

int main(int argc, char** argv) {
  using namespace ceilplan::app;
  CLI::App app{
      "ceilplan: battery-wear-aware inspection planning for multirotors flying under ceilings"};
  app.require_subcommand(1);
  app.config_formatter(std::make_shared<YamlConfig>(app));
  app.set_config("--config", "", "YAML file whose keys are the chosen command's long flag names");
  app.set_version_flag("--version", ceilplan::buildInformation());
  addRegisteredCommands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "ceilplan: error: " << e.what() << " (see 'ceilplan --help')\n";
    return kExitUsage;
  } catch (const ceilplan::NoPathError& e) {
    std::cerr << "ceilplan: no path: " << e.what() << '\n';
    return kExitNoPath;
  } catch (const std::exception& e) {
    std::cerr << "ceilplan: error: " << e.what() << '\n';
    return kExitInputError;
  }
  return kExitOk;
}
