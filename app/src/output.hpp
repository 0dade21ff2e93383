#pragma once
// What the commands show besides their results: progress on the terminal, and the command line
// their outputs' provenance records.

#include "ceilplan/core/progress.hpp"
#include "ceilplan/io/output_set.hpp"

#include <string>
#include <vector>

namespace CLI {
class Option;
}

namespace ceilplan::app {

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

// The --config option (main records it): the file it names is an input of every command, which
// no output may replace.
void recordConfigOption(const CLI::Option* option);
// The command's inputs for io::OutputSet: `inputs`, and the --config file if one was given.
std::vector<io::Input> commandInputs(std::vector<io::Input> inputs);

// A library progress callback drawn as Progress lines, one per stage, when stderr is a
// terminal; the last line is cleared when the callback and its copies are gone.
ProgressCallback terminalProgress();

}  // namespace ceilplan::app
