#pragma once
/// @file
/// Outputs that appear whole or not at all, even when the user presses Ctrl-C: each is written
/// in a staging directory of its own beside its final path and renamed into place once complete.
/// Until then it is removed on an error (the destructor) and on SIGINT, SIGTERM or SIGHUP.
///
/// Nothing runs in signal context. installSignalCleanup() blocks those signals in the calling
/// thread, and so in every thread started after it, and starts one thread that takes them with
/// sigwait(): it removes every staging directory still registered (and the parent directories
/// created for it, when empty), then lets the signal end the process as it would have (exit
/// status 128 + the signal's number).
///
/// A staging directory is "<name>.tmp-ceilplan-XXXXXX" (mkdtemp: unique, never shared with another
/// run) and records its owner (process id, start time and boot) in "<name>.owner" inside it. One
/// left by a killed run (SIGKILL, power loss) is never used again; the next output of the same
/// name removes it once its owner is gone.

#include <filesystem>
#include <vector>

namespace ceilplan::io {

/// Call once, first thing in main(), before any other thread starts (a thread started earlier
/// would still take the signals and end the process without the cleanup). Further calls do
/// nothing.
void installSignalCleanup();

/// Where `path`, a file being written inside a temporary output (or the temporary itself), will
/// be once committed; any other path as it is. For messages: the user named the final path.
std::filesystem::path finalPathOf(const std::filesystem::path& path);

/// `path` named so that it can be renamed: without a trailing separator, and made absolute when it
/// ends in "." or ".." ("out/" is "out", "." the working directory's absolute path).
std::filesystem::path renameablePath(const std::filesystem::path& path);

/// One output (a file, or a directory the caller fills) staged beside its final path. Missing
/// parent directories are created, and removed again if the output is never committed.
class TemporaryOutput {
 public:
  /// With `directory`, the temporary is made as an empty directory. Parents and the staging
  /// directory are made under the signal cleanup's lock: once an interruption is being cleaned
  /// up, no constructor creates anything.
  explicit TemporaryOutput(std::filesystem::path final_path, bool directory = false);
  ~TemporaryOutput();  ///< removes the staging directory unless committed
  TemporaryOutput(const TemporaryOutput&) = delete;
  TemporaryOutput& operator=(const TemporaryOutput&) = delete;

  /// Where to write.
  const std::filesystem::path& path() const { return temporary_; }
  /// Where it goes once committed.
  const std::filesystem::path& finalPath() const { return final_; }

  /// Puts the temporary in place of the final path: whatever was there (a file, or a directory
  /// the caller has checked may be replaced) is moved aside into the staging directory, the
  /// temporary renamed in, and only then the old one removed. Throws ceilplan::Error naming the
  /// final path if a rename fails (the old one is then back in place, the temporary removed).
  void commit() { commitAll({this}); }

  /// commit() for several outputs at once, all or none: under the signal cleanup's lock (an
  /// interruption finds either none or all of them in place), and a failed rename puts every
  /// output already moved back as it was.
  static void commitAll(const std::vector<TemporaryOutput*>& outputs);

 private:
  std::filesystem::path final_;
  std::filesystem::path staging_;                       ///< the staging directory
  std::filesystem::path temporary_;                     ///< staging_ / final_'s name
  std::vector<std::filesystem::path> created_parents_;  ///< deepest first
  bool committed_ = false;
};

}  // namespace ceilplan::io
