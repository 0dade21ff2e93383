#pragma once
// Output files appear whole or not at all: each is written under a temporary name beside
// its final one, then renamed into place.

#include "ceilplan/core/progress.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/output_set.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace ceilplan::app {

using io::checkWritableFile;
using io::writeAtomically;
using io::writeTextAtomically;

// Progress for long work: a single updating line on stderr when stderr is a terminal,
// nothing otherwise. The line is cleared at 100 % and by finish() (or the destructor).
class Progress {
 public:
  Progress(std::string label, bool enabled);
  explicit Progress(std::string label);  // enabled when stderr is a terminal
  ~Progress();
  void update(double fraction);
  void finish();

 private:
  std::string label_;
  bool enabled_;
  int last_percent_ = -1;
};

// The command line as typed (main records it), for the outputs' provenance.
void recordInvocation(int argc, const char* const* argv);
const std::string& invocation();

// A library progress callback drawn as Progress lines, one per stage, when stderr is a
// terminal; the last line is cleared when the callback and its copies are gone.
ProgressCallback terminalProgress();

}  // namespace ceilplan::app
