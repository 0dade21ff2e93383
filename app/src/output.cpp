#include "output.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <system_error>

namespace ceilplan::app {

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw std::runtime_error("cannot create directory " + path.parent_path().string() + ": " + ec.message());
  }
  fs::path temporary = path;
  temporary += ".tmp" + std::to_string(::getpid());
  try {
    write(temporary);
  } catch (...) {
    fs::remove(temporary, ec);
    throw;
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw std::runtime_error("cannot write " + path.string() + ": " + ec.message());
  }
}

void writeTextAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream& out)>& write) {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    if (!out) throw std::runtime_error("cannot open " + path.string() + " for writing");
    write(out);
    out.flush();
    if (!out) throw std::runtime_error("failed while writing " + path.string());
  });
}

Progress::Progress(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled) {}

Progress::Progress(std::string label) : Progress(std::move(label), ::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { finish(); }

void Progress::update(double fraction) {
  if (!enabled_) return;
  const int percent = static_cast<int>(std::lround(100.0 * std::clamp(fraction, 0.0, 1.0)));
  if (percent == last_percent_) return;
  last_percent_ = percent;
  std::cerr << '\r' << label_ << ' ' << percent << " %" << std::flush;
}

void Progress::finish() {
  if (enabled_ && last_percent_ >= 0) std::cerr << '\n';
  enabled_ = false;
}

}  // namespace ceilplan::app
