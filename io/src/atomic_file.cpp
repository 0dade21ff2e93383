#include "ceilplan/io/atomic_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/temporary_output.hpp"

#include <cerrno>

#include <fstream>
#include <string>
#include <system_error>

namespace ceilplan::io {

namespace {

// "cannot write FILE: No space left on device", with the reason the system gave (errno, cleared
// before the stream's work), never "Success".
[[noreturn]] void writeFailed(const std::filesystem::path& path) {
  const int error = errno;
  throw ceilplan::Error(
      "cannot write " + printableText(finalPathOf(path).string(), 256) + ": " +
      (error != 0 ? std::generic_category().message(error) : std::string("the write failed (disk full?)")));
}

}  // namespace

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write) {
  checkOutputs({{"", path}}, {});
  TemporaryOutput output(path);
  write(output.path());
  output.commit();
}

void writeTextAtomically(const std::filesystem::path& path, const std::function<void(std::ostream& out)>& write) {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    errno = 0;
    std::ofstream out(temporary);
    if (!out) writeFailed(path);
    write(out);
    out.flush();
    if (!out) writeFailed(path);
  });
}

}  // namespace ceilplan::io
