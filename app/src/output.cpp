#include "output.hpp"

#include "ceilplan/io/provenance.hpp"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <system_error>

namespace ceilplan::app {

Progress::Progress(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled) {}

Progress::Progress(std::string label) : Progress(std::move(label), ::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { finish(); }

void Progress::update(double fraction) {
  if (!enabled_) return;
  if (fraction >= 1.0) {  // done: whatever is printed next starts on a clean line
    finish();
    return;
  }
  const int percent = static_cast<int>(std::lround(100.0 * std::clamp(fraction, 0.0, 1.0)));
  if (percent == last_percent_) return;
  last_percent_ = percent;
  std::cerr << '\r' << label_ << ' ' << percent << " %" << std::flush;
}

void Progress::finish() {
  if (enabled_ && last_percent_ >= 0) std::cerr << "\r\033[K" << std::flush;  // a finished line leaves nothing behind
  enabled_ = false;
}

namespace {
std::string& invocationText() {
  static std::string text = "ceilplan";
  return text;
}
}  // namespace

void recordInvocation(int argc, const char* const* argv) { invocationText() = io::commandLine(argc, argv); }

const std::string& invocation() { return invocationText(); }

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
  struct Lines {
    std::string stage;
    std::unique_ptr<Progress> line;
  };
  auto lines = std::make_shared<Lines>();
  return [lines](const std::string& stage, double fraction) {
    if (stage != lines->stage || !lines->line) {
      lines->line.reset();
      lines->line = std::make_unique<Progress>(stage);
      lines->stage = stage;
    }
    lines->line->update(fraction);
    if (fraction >= 1.0) lines->line.reset();  // the stage may run again (tour --mode both)
  };
}

}  // namespace ceilplan::app
