#include "command_registry.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "yaml_config.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/core/spelling.hpp"
#include "ceilplan/core/version.hpp"
#include "ceilplan/io/temporary_output.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <exception>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace ceilplan::app;
  ceilplan::io::installSignalCleanup();  // before any thread: Ctrl-C leaves no partial output
  recordInvocation(argc, argv);
  CLI::App app{"ceilplan: battery-wear-aware inspection planning for multirotors flying under ceilings"};
  app.require_subcommand(1);
  app.config_formatter(std::make_shared<YamlConfig>(app));
  recordConfigOption(app.set_config("--config", "", "YAML file whose keys are the chosen command's long flag names"));
  app.set_version_flag("--version", ceilplan::buildInformation());
  app.add_subcommand("version", "Print the version, the git revision and the libraries' versions")->callback([] {
    std::cout << ceilplan::buildInformation();
  });
  CLI::App* help = app.add_subcommand("help", "List the commands, or describe one: ceilplan help COMMAND");
  auto topic = std::make_shared<std::string>();
  help->add_option("command", *topic, "the command to describe");
  addRegisteredCommands(app);
  help->callback([&app, topic] {
    // CLI::App::help() would describe the selected subcommand, `help` itself: format the app.
    if (topic->empty()) {
      std::cout << app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
      return;
    }
    try {
      std::cout << app.get_subcommand(*topic)->help(app.get_name());
    } catch (const CLI::OptionNotFound&) {
      throw ceilplan::InputError("no command '" + *topic + "'; 'ceilplan help' lists them");
    }
  });
  // CLI11 would say only "A subcommand is required" for a misspelt one.
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const CLI::App* command : app.get_subcommands({})) names.push_back(command->get_name());
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      std::cerr << "ceilplan: error: no command '" << ceilplan::printableText(argv[1]) << "'"
                << ceilplan::didYouMean(argv[1], names) << "; 'ceilplan help' lists them\n";
      return kExitBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "ceilplan: error: " << e.what() << " (see 'ceilplan --help')\n";
    return kExitBadInput;
  } catch (const ceilplan::NoPathError& e) {
    std::cerr << "ceilplan: no path: " << e.what() << '\n';
    return kExitNoPath;
  } catch (const ceilplan::InfeasibleError& e) {
    std::cerr << "ceilplan: error: " << e.what() << '\n';
    return kExitNoPath;
  } catch (const ceilplan::InputError& e) {
    std::cerr << "ceilplan: error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "ceilplan: error: out of memory; use a coarser map resolution, a smaller map or fewer targets\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << "ceilplan: error: " << e.what() << '\n';
    return kExitFailure;
  }
  return kExitOk;
}
