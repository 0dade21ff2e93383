#pragma once
// Output files appear whole or not at all: each is written under a temporary name beside
// its final one, then renamed into place.

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace ceilplan::app {

// Calls `write` with a temporary path in the same directory, then renames it to `path`.
// Creates the parent directory. On any failure the temporary file is removed and the
// error names `path`.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

// Same, for text produced on a stream.
void writeTextAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream& out)>& write);

// Progress for long work: a single updating line on stderr when stderr is a terminal,
// nothing otherwise.
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

}  // namespace ceilplan::app
