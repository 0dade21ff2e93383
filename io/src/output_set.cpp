#include "ceilplan/io/output_set.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <system_error>

namespace ceilplan::io {
namespace {

namespace fs = std::filesystem;

bool writable(const fs::path& dir) {
  struct stat status {};
  if (::stat(dir.c_str(), &status) != 0) return false;
  if ((status.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0) return false;  // read-only, whoever asks
  return ::access(dir.c_str(), W_OK | X_OK) == 0;
}

fs::path checkedDirectory(fs::path dir) {
  OutputSet::checkWritable(dir);
  return dir;
}

}  // namespace

void OutputSet::checkWritable(const fs::path& dir) {
  if (dir.empty()) throw InputError("the output location is empty: name a directory");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(dir.string() + " exists and is not a directory: name a directory for the outputs");
  // The nearest existing directory must take new entries; a file on the way is an error.
  fs::path existing = fs::absolute(dir, ec);
  while (!fs::exists(existing, ec)) existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    throw InputError("cannot create " + dir.string() + ": " + existing.string() + " is a file, not a directory");
  if (!writable(existing)) throw InputError("cannot write into " + existing.string() + ": the directory is read-only");
  // The staging directory is a sibling: the parent must take it too.
  const fs::path parent = fs::absolute(dir, ec).parent_path();
  if (fs::exists(parent, ec) && !writable(parent))
    throw InputError("cannot write next to " + dir.string() + ": " + parent.string() + " is read-only");
}

void checkWritableFile(const fs::path& file) {
  if (file.empty()) throw InputError("the output file name is empty: name a file");
  const std::string shown = printableText(file.string(), 256);
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw InputError(shown + " is a directory: name a file for the output");
  fs::path existing = fs::absolute(file, ec).parent_path();
  while (!fs::exists(existing, ec)) existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    throw InputError("cannot create " + shown + ": " + printableText(existing.string(), 256) + " is a file, not a directory");
  if (!writable(existing))
    throw InputError("cannot write " + shown + ": the directory " + printableText(existing.string(), 256) + " is read-only");
  struct stat status {};
  if (::stat(file.c_str(), &status) == 0 && (status.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0)
    throw InputError("cannot write " + shown + ": the file exists and is read-only");
}

OutputSet::OutputSet(fs::path dir) : staging_(checkedDirectory(std::move(dir)), true) {}

}  // namespace ceilplan::io
