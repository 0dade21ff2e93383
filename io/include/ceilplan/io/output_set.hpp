#pragma once
/// @file
/// A command's whole output set, all or nothing: every output (files and directories) is staged
/// beside its final path and all are put in place together only when the last one is complete.
/// On an error, SIGINT, SIGTERM or SIGHUP none of them appears and the staging is removed.
///
/// Before any work the set is checked: no output may be one of the command's inputs (compared by
/// identity: the same file through another name, a symbolic or a hard link, counts), lie inside
/// another output or hold an input, be a device, FIFO, socket or symbolic link, or be a directory
/// ceilplan did not write. A directory output replaces the old directory whole (never merges into
/// it) and carries kOutputMarkerName, so that the next run knows it may replace it.

#include "ceilplan/io/temporary_output.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ceilplan::io {

/// The file every output directory ceilplan writes holds. An existing directory is replaced only
/// if it holds this file or is empty.
inline constexpr const char* kOutputMarkerName = ".ceilplan-output";

/// Checks, before any work, that the output file `file` can be written: it is not a directory,
/// the nearest existing directory above it is one and is writable (permission bits count, as in
/// OutputSet::checkWritable), and an existing file there is not read-only. Throws
/// ceilplan::InputError naming the file and the problem.
void checkWritableFile(const std::filesystem::path& file);

/// One output of a command: `flag` names it in messages ("--json").
struct Output {
  std::string flag;            ///< names the output in messages, e.g. "--json"
  std::filesystem::path path;  ///< empty: not asked for
  bool directory = false;      ///< the output is a directory
};

/// One input the outputs must leave alone (a file read, or one the command will read).
struct Input {
  std::string flag;            ///< names the input in messages, e.g. "--map"
  std::filesystem::path path;  ///< empty: none
};

/// The checks OutputSet makes before staging (see above). Throws ceilplan::InputError naming the
/// flag, the path and what to do.
void checkOutputs(const std::vector<Output>& outputs, const std::vector<Input>& inputs);

/// A command's outputs, staged and put in place all or none (docs/cli.md, "Outputs").
class OutputSet {
 public:
  /// Checks, before any work, that `dir` can receive outputs: it is a directory or does not exist
  /// yet, and it, or the nearest existing directory above it, is writable (a directory with no
  /// write permission bit counts as read-only even for root). Throws ceilplan::InputError naming
  /// the location and the problem.
  static void checkWritable(const std::filesystem::path& dir);

  /// checkOutputs, then stages every output asked for (a directory with its marker inside).
  OutputSet(std::vector<Output> outputs, const std::vector<Input>& inputs);
  /// One output directory, given with --out.
  explicit OutputSet(std::filesystem::path dir, const std::vector<Input>& inputs = {});

  /// Where to write the output given with `flag` (empty if it was not asked for), in the layout
  /// it will have; and where it goes.
  const std::filesystem::path& path(const std::string& flag) const;
  /// Where the output given with `flag` goes once committed.
  const std::filesystem::path& finalPath(const std::string& flag) const;
  /// The same for the first output.
  const std::filesystem::path& path() const { return path(outputs_.front().flag); }
  /// Where the first output goes once committed.
  const std::filesystem::path& finalPath() const { return finalPath(outputs_.front().flag); }

  /// Puts every staged output in place, all or none (TemporaryOutput::commitAll).
  void commit();

 private:
  std::vector<Output> outputs_;
  std::vector<std::unique_ptr<TemporaryOutput>> staged_;  ///< one per output; null where not asked for
};

}  // namespace ceilplan::io
