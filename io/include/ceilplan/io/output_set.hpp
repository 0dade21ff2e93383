#pragma once
// A command's whole output set, all or nothing: every file is written into a staging directory
// beside the output directory and moved into it only when the last one is complete. On an error,
// SIGINT or SIGTERM nothing reaches the output directory and the staging directory is removed.

#include "ceilplan/io/temporary_output.hpp"

#include <filesystem>

namespace ceilplan::io {

// Checks, before any work, that the output file `file` can be written: it is not a directory,
// the nearest existing directory above it is one and is writable (permission bits count, as in
// OutputSet::checkWritable), and an existing file there is not read-only. Throws
// ceilplan::InputError naming the file and the problem.
void checkWritableFile(const std::filesystem::path& file);

class OutputSet {
 public:
  // Checks, before any work, that `dir` can receive outputs: it is a directory or does not exist
  // yet, and it, or the nearest existing directory above it, is writable (a directory with no
  // write permission bit counts as read-only even for root). Throws ceilplan::InputError naming
  // the location and the problem.
  static void checkWritable(const std::filesystem::path& dir);

  // checkWritable(dir), then creates the staging directory.
  explicit OutputSet(std::filesystem::path dir);

  // Where to write: the same layout as the output directory will have.
  const std::filesystem::path& path() const { return staging_.path(); }
  const std::filesystem::path& finalPath() const { return staging_.finalPath(); }

  // Moves every staged file into the output directory (TemporaryOutput::commitMerging).
  void commit() { staging_.commitMerging(); }

 private:
  TemporaryOutput staging_;
};

}  // namespace ceilplan::io
