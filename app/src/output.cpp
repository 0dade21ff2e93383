#include "output.hpp"

#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/provenance.hpp"

#include <CLI/CLI.hpp>

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <system_error>

namespace ceilplan::app {

namespace {

// Whether a progress line is drawn on stderr, so that print() clears it before a report goes to
// the same terminal. Drawn and cleared from the thread that runs the command only.
bool& progressLineDrawn() {
  static bool drawn = false;
  return drawn;
}

// Draws `text` over what the line held.
void drawProgressLine(const std::string& text) {
  std::cerr << '\r' << text << "\033[K" << std::flush;
  progressLineDrawn() = true;
}

// A cleared line leaves nothing behind: whatever is printed next starts on a clean line.
void clearProgressLine() {
  if (progressLineDrawn()) std::cerr << "\r\033[K" << std::flush;
  progressLineDrawn() = false;
}

int percentOf(double fraction) { return static_cast<int>(std::lround(100.0 * std::clamp(fraction, 0.0, 1.0))); }

// The terminal's width in columns, 80 when it does not say.
std::size_t terminalColumns() {
  winsize size{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

}  // namespace

void print(const std::string& text) {
  clearProgressLine();  // drawn again by the next report
  std::cout << printableLines(text) << std::flush;
}

namespace {
std::string& invocationText() {
  static std::string text = "ceilplan";
  return text;
}

// The --config file of the command line, an input like any other: its flags are not on the line.
std::string& configFile() {
  static std::string file;
  return file;
}
}  // namespace

void recordInvocation(int argc, const char* const* argv) {
  invocationText() = io::commandLine(argc, argv);
  const std::string flag = "--config";
  for (int k = 1; k < argc; ++k) {
    const std::string argument = argv[k];
    if (argument == flag && k + 1 < argc) configFile() = argv[k + 1];
    if (argument.rfind(flag + "=", 0) == 0) configFile() = argument.substr(flag.size() + 1);
  }
}

io::Provenance commandProvenance() { return io::Provenance::of(invocationText()).input("config", configFile()); }

namespace {
const CLI::Option*& configOption() {
  static const CLI::Option* option = nullptr;
  return option;
}
}  // namespace

void recordConfigOption(const CLI::Option* option) { configOption() = option; }

std::vector<io::Input> commandInputs(std::vector<io::Input> inputs) {
  const CLI::Option* config = configOption();
  if (config != nullptr && config->count() > 0) inputs.push_back({"--config", config->as<std::string>()});
  return inputs;
}

ProgressCallback terminalProgress() {
  // The stages running, each with its percentage: stages that run at once (the two modes of
  // `tour --mode both`) share the line. A stage replaces the one before it in its lane, the text
  // before its first ": " ("ceiling mode"), and leaves the line at 100 %.
  struct Lanes {
    bool enabled = ::isatty(STDERR_FILENO) == 1;
    std::vector<std::pair<std::string, int>> running;  // stage, percent
    ~Lanes() {
      if (enabled && !running.empty()) clearProgressLine();
    }
  };
  auto lanes = std::make_shared<Lanes>();
  return [lanes](const std::string& stage, double fraction) {
    if (!lanes->enabled) return;
    const auto lane = [](const std::string& name) { return name.substr(0, name.find(": ")); };
    auto it = std::find_if(lanes->running.begin(), lanes->running.end(),
                           [&](const auto& entry) { return lane(entry.first) == lane(stage); });
    const int percent = percentOf(fraction);
    if (fraction >= 1.0) {
      if (it != lanes->running.end()) lanes->running.erase(it);
    } else if (it == lanes->running.end()) {
      lanes->running.emplace_back(stage, percent);
    } else if (it->first == stage && it->second == percent) {
      return;  // nothing new to draw
    } else {
      *it = {stage, percent};
    }
    if (lanes->running.empty()) {
      clearProgressLine();
      return;
    }
    std::string text;
    for (const auto& [name, share] : lanes->running)
      text += (text.empty() ? "" : " | ") + printableText(name, 96) + ' ' + std::to_string(share) + " %";
    drawProgressLine(text.substr(0, terminalColumns() - 1));  // one line: a wrapped one cannot be redrawn
  };
}

}  // namespace ceilplan::app
