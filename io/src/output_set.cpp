#include "ceilplan/io/output_set.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/core/version.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <stdexcept>
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

std::string shown(const fs::path& path) { return printableText(path.string(), 256); }

// "--json FILE", or the file alone for an output no flag names.
std::string named(const Output& output) {
  return output.flag.empty() ? shown(output.path) : output.flag + " " + shown(output.path);
}

// The path with every existing part's symbolic links resolved.
fs::path resolved(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  const fs::path canonical = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal() : canonical;
}

// The same file or directory: the same device and inode when both exist (through any link), the
// same resolved path otherwise.
bool sameFile(const fs::path& a, const fs::path& b) {
  struct stat sa {
  }, sb{};
  const bool a_exists = ::stat(a.c_str(), &sa) == 0, b_exists = ::stat(b.c_str(), &sb) == 0;
  if (a_exists && b_exists) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  return !a_exists && !b_exists && resolved(a) == resolved(b);
}

// `inner` lies strictly inside the directory `dir`.
bool inside(const fs::path& inner, const fs::path& dir) {
  const fs::path relative = resolved(inner).lexically_relative(resolved(dir));
  return !relative.empty() && relative != "." && *relative.begin() != "..";
}

// What an existing output must not be: a symbolic link (the rename would replace the link), a
// device, FIFO or socket (a regular file would replace it), a directory ceilplan did not write.
void checkKind(const Output& output) {
  struct stat status {};
  if (::lstat(output.path.c_str(), &status) != 0) return;  // nothing there yet
  const std::string another = output.directory ? "directory" : "file";
  const auto refuse = [&](const std::string& what) {
    throw InputError(named(output) + " is " + what + ", not a regular " + another +
                     ": ceilplan writes only regular files and directories it can replace whole; name another " +
                     another);
  };
  if (S_ISLNK(status.st_mode)) refuse("a symbolic link");
  if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode)) refuse("a device");
  if (S_ISFIFO(status.st_mode)) refuse("a FIFO (named pipe)");
  if (S_ISSOCK(status.st_mode)) refuse("a socket");
  if (!output.directory || !S_ISDIR(status.st_mode)) return;  // a file where a directory goes: checkWritable says so
  std::error_code ec;
  const bool empty = fs::is_empty(output.path, ec);
  if ((ec || !empty) && !fs::exists(output.path / kOutputMarkerName, ec))
    throw InputError(
        named(output) + " is a directory ceilplan did not write: it is not empty and holds no " + kOutputMarkerName +
        " (ceilplan replaces only an empty directory or one it wrote; outputs of versions before the marker "
        "have none): remove it or choose another " +
        output.flag);
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
  const std::string shown_file = shown(file);
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw InputError(shown_file + " is a directory: name a file for the output");
  fs::path existing = fs::absolute(file, ec).parent_path();
  while (!fs::exists(existing, ec)) existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    throw InputError("cannot create " + shown_file + ": " + shown(existing) + " is a file, not a directory");
  if (!writable(existing))
    throw InputError("cannot write " + shown_file + ": the directory " + shown(existing) + " is read-only");
  struct stat status {};
  if (::stat(file.c_str(), &status) == 0 && (status.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0)
    throw InputError("cannot write " + shown_file + ": the file exists and is read-only");
}

void checkOutputs(const std::vector<Output>& outputs, const std::vector<Input>& inputs) {
  std::vector<const Output*> given;
  for (const Output& output : outputs)
    if (!output.path.empty()) given.push_back(&output);
  for (const Output* output : given) {
    for (const Input& input : inputs) {
      if (input.path.empty()) continue;
      if (sameFile(output->path, input.path))
        throw InputError(named(*output) + " is the input " + input.flag +
                         ": an output never replaces an input; name another " +
                         (output->directory ? "directory" : "file"));
      if (output->directory && inside(input.path, output->path))
        throw InputError(named(*output) + " holds the input " + input.flag + " " + shown(input.path) +
                         ", which replacing it would delete: choose another " + output->flag);
    }
    checkKind(*output);
    if (output->directory) {
      OutputSet::checkWritable(output->path);
    } else {
      checkWritableFile(output->path);
    }
  }
  for (std::size_t i = 0; i < given.size(); ++i)
    for (std::size_t j = 0; j < given.size(); ++j) {
      const Output &a = *given[i], &b = *given[j];
      if (i < j && sameFile(a.path, b.path))
        throw InputError(a.flag + " and " + b.flag + " are the same path, " + shown(a.path) +
                         ": give each output its own");
      if (i != j && b.directory && inside(a.path, b.path))
        throw InputError(named(a) + " lies inside " + named(b) +
                         ", which is written whole: give each output its own path");
    }
}

OutputSet::OutputSet(std::vector<Output> outputs, const std::vector<Input>& inputs) : outputs_(std::move(outputs)) {
  for (Output& output : outputs_) {
    if (output.path.empty()) continue;
    const fs::path name = output.path.filename();
    if (!output.directory && (name.empty() || name == "." || name == ".."))
      throw InputError(named(output) + " names a directory: name a file for the output");
    output.path = renameablePath(output.path);
  }
  checkOutputs(outputs_, inputs);
  for (const Output& output : outputs_) {
    if (output.path.empty()) {
      staged_.emplace_back();
      continue;
    }
    staged_.push_back(std::make_unique<TemporaryOutput>(output.path, output.directory));
    if (!output.directory) continue;
    std::ofstream marker(staged_.back()->path() / kOutputMarkerName);
    marker << "Written by ceilplan " << kVersion
           << ". The next ceilplan run writing here replaces this directory whole.\n";
    if (!marker.flush())
      throw ceilplan::Error("cannot write " + shown(output.path) + ": " + std::generic_category().message(errno));
  }
}

OutputSet::OutputSet(fs::path dir, const std::vector<Input>& inputs)
    : OutputSet(std::vector<Output>{{"--out", std::move(dir), true}}, inputs) {}

const fs::path& OutputSet::path(const std::string& flag) const {
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    if (outputs_[i].flag == flag) {
      static const fs::path none;
      return staged_[i] ? staged_[i]->path() : none;
    }
  throw std::logic_error("no output " + flag + " in this set");
}

const fs::path& OutputSet::finalPath(const std::string& flag) const {
  for (const Output& output : outputs_)
    if (output.flag == flag) return output.path;
  throw std::logic_error("no output " + flag + " in this set");
}

void OutputSet::commit() {
  std::vector<TemporaryOutput*> staged;
  for (const auto& output : staged_)
    if (output) staged.push_back(output.get());
  TemporaryOutput::commitAll(staged);
}

}  // namespace ceilplan::io
