#pragma once
// What the commands show besides their results: progress on the terminal, and the command line
// their outputs' provenance records.

#include "ceilplan/core/progress.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/provenance.hpp"

#include <string>
#include <vector>

namespace CLI {
class Option;
}

namespace ceilplan::app {

// Writes a command's report to stdout, every line through printableLines: file names, target
// and vehicle names come from the user and must not reach the terminal as raw bytes. A progress
// line on the terminal is cleared first.
void print(const std::string& text);

// The command line as typed (main records it), for the outputs' provenance.
void recordInvocation(int argc, const char* const* argv);
// The provenance every output of this run records: the version, the command line and its
// --config file; the command adds its other input files (and seed).
io::Provenance commandProvenance();

// The --config option (main records it): the file it names is an input of every command, which
// no output may replace.
void recordConfigOption(const CLI::Option* option);
// The command's inputs for io::OutputSet: `inputs`, and the --config file if one was given.
std::vector<io::Input> commandInputs(std::vector<io::Input> inputs);

// A library progress callback drawn on one updating line of stderr when stderr is a terminal,
// nothing otherwise: each stage running with its percentage (stages that run at once, the modes
// of `tour --mode both`, side by side); a stage's line is cleared at 100 %, and the last when
// the callback and its copies are gone.
ProgressCallback terminalProgress();

}  // namespace ceilplan::app
