#include "ceilplan/io/atomic_file.hpp"

#include "ceilplan/core/error.hpp"

#include <unistd.h>

#include <fstream>
#include <string>
#include <system_error>

namespace ceilplan::io {

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw ceilplan::Error("cannot create directory " + path.parent_path().string() + ": " + ec.message());
  }
  fs::path temporary = path;
  temporary += ".tmp" + std::to_string(::getpid());
  try {
    write(temporary);
  } catch (...) {
    fs::remove(temporary, ec);
    throw;
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw ceilplan::Error("cannot write " + path.string() + ": " + ec.message());
  }
}

void writeTextAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream& out)>& write) {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    if (!out) throw ceilplan::Error("cannot open " + path.string() + " for writing");
    write(out);
    out.flush();
    if (!out) throw ceilplan::Error("failed while writing " + path.string());
  });
}

}  // namespace ceilplan::io
