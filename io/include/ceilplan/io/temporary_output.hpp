#pragma once
// Outputs that appear whole or not at all, even when the user presses Ctrl-C: each is written
// under a temporary sibling name and renamed into place once complete. Until then it is removed
// on an error (the destructor) and on SIGINT or SIGTERM.
//
// Nothing runs in signal context. installSignalCleanup() blocks SIGINT and SIGTERM in the calling
// thread, and so in every thread started after it, and starts one thread that takes them with
// sigwait(): it removes every temporary output still registered (and the parent directories
// created for it, when empty), then lets the signal end the process as it would have (exit
// status 128 + the signal's number).

#include <filesystem>
#include <vector>

namespace ceilplan::io {

// Call once, first thing in main(), before any other thread starts (a thread started earlier
// would still take the signals and end the process without the cleanup). Further calls do
// nothing.
void installSignalCleanup();

// Where `path`, a file being written inside a temporary output (or the temporary itself), will
// be once committed; any other path as it is. For messages: the user named the final path.
std::filesystem::path finalPathOf(const std::filesystem::path& path);

// One output (a file, or a directory the caller fills) under a temporary sibling name:
// "<name>.tmp<pid>" next to the final path. Missing parent directories are created, and removed
// again if the output is never committed.
class TemporaryOutput {
 public:
  // With `directory`, the temporary is made as an empty directory. Parents and the directory are
  // made under the signal cleanup's lock: once an interruption is being cleaned up, no
  // constructor creates anything.
  explicit TemporaryOutput(std::filesystem::path final_path, bool directory = false);
  ~TemporaryOutput();  // removes the temporary unless committed
  TemporaryOutput(const TemporaryOutput&) = delete;
  TemporaryOutput& operator=(const TemporaryOutput&) = delete;

  // Where to write.
  const std::filesystem::path& path() const { return temporary_; }
  const std::filesystem::path& finalPath() const { return final_; }

  // Renames the temporary onto the final path. Atomic with respect to the signal cleanup: an
  // interruption finds either the temporary (and removes it) or the complete output. Throws
  // ceilplan::Error naming the final path if the rename fails (the temporary is then removed).
  void commit();

  // For a temporary directory: moves every file in it to the same place under the final
  // directory (created if missing; files of the same names replaced, others left alone), all
  // under the signal cleanup's lock, so an interruption finds either none or all of them moved.
  void commitMerging();

 private:
  std::filesystem::path final_;
  std::filesystem::path temporary_;
  std::vector<std::filesystem::path> created_parents_;  // deepest first
  bool committed_ = false;
};

}  // namespace ceilplan::io
