#pragma once
/// @file
/// The one error hierarchy of ceilplan. Every module throws these, with a one-line message that
/// says what was wrong in the library's terms and, where it can, what to do; the command line
/// adds the flag or file name and maps each kind to its exit code (docs/cli.md).

#include <stdexcept>
#include <string>
#include <system_error>

namespace ceilplan {

/// Base of every error ceilplan throws on purpose. Thrown as such: a computation failed (a fit
/// did not converge, a planned path failed its re-check, a file could not be written).
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The input is wrong: a missing, corrupt or wrong-kind file, an unknown key, a number out of
/// its physical range, a point outside the map, a start inside an obstacle.
class InputError : public Error {
 public:
  using Error::Error;
};

/// An input file that cannot be read as one: missing, a directory, a device, unreadable.
/// `reason` says which as the system would (std::errc::no_such_file_or_directory,
/// is_a_directory, permission_denied, ...), so a front end can tell it from other bad input
/// (Python raises FileNotFoundError or OSError, docs/python.md).
class InputFileError : public InputError {
 public:
  /// An InputError with `message`, readable by a front end as the system error `reason`.
  InputFileError(const std::string& message, std::errc reason) : InputError(message), reason_(reason) {}
  /// Why the file could not be read, as the system would say it (std::errc::no_such_file_or_directory, ...).
  std::errc reason() const { return reason_; }

 private:
  std::errc reason_;
};

/// The input is well formed but asks for something that cannot be done: the battery runs out,
/// a target cannot be reached and returned from.
class InfeasibleError : public Error {
 public:
  using Error::Error;
};

/// No path joins two places (none exists, or none was found in the time given); the message
/// says which and, where known, where the search was blocked.
class NoPathError : public InfeasibleError {
 public:
  using InfeasibleError::InfeasibleError;
};

/// Inside a catch block: throws the error being handled again with `context` put before its
/// message ("leg home -> a: " + what), keeping its kind; any other exception becomes an Error.
[[noreturn]] void rethrowWithContext(const std::string& context);

}  // namespace ceilplan
