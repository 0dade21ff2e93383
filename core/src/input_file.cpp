#include "ceilplan/core/input_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace ceilplan {
namespace {

// An InputFileError carries why, so Python can raise FileNotFoundError or OSError with errno.
[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& problem, std::errc reason) {
  throw InputFileError(printableText(file.string(), 256) + ": " + problem, reason);
}

std::errc errcOf(int error) { return error ? static_cast<std::errc>(error) : std::errc::io_error; }

// What a file that is not regular is, for the message.
std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

}  // namespace

std::uintmax_t requireInputFile(const std::filesystem::path& file, const std::string& what, std::uintmax_t max_bytes) {
  struct stat status {};
  // stat, not lstat: a link to a regular file is read like the file.
  if (::stat(file.c_str(), &status) != 0) {
    const int error = errno;
    if (error == ENOENT || error == ENOTDIR) refuse(file, "no such " + what, std::errc::no_such_file_or_directory);
    refuse(file, std::string("cannot be read: ") + std::strerror(error), errcOf(error));
  }
  if (!S_ISREG(status.st_mode))
    refuse(file, "is " + kindOf(status.st_mode) + ", not a " + what + "; give a regular file",
           S_ISDIR(status.st_mode) ? std::errc::is_a_directory : std::errc::invalid_argument);
  const auto size_bytes = static_cast<std::uintmax_t>(status.st_size);
  if (size_bytes > max_bytes)
    refuse(file,
           "holds " + std::to_string(size_bytes) + " bytes, more than ceilplan reads for a " + what + " (" +
               std::to_string(max_bytes) + "); is it the right file?",
           std::errc::file_too_large);
  if (!std::ifstream(file, std::ios::binary)) {
    const int error = errno;
    refuse(file, std::string("cannot be read: ") + std::strerror(error), errcOf(error));
  }
  return size_bytes;
}

std::string readInputFile(const std::filesystem::path& file, const std::string& what, std::uintmax_t max_bytes) {
  requireInputFile(file, what, max_bytes);
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) {
    const int error = errno;
    refuse(file, std::string("cannot be read: ") + std::strerror(error), errcOf(error));
  }
  // The file may have grown since it was checked.
  if (bytes.size() > max_bytes)
    refuse(file, "grew past " + std::to_string(max_bytes) + " bytes while it was read", std::errc::file_too_large);
  return bytes;
}

}  // namespace ceilplan
