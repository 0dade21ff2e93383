#include "ceilplan/io/atomic_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/temporary_output.hpp"

#include <fstream>
#include <string>
#include <system_error>

namespace ceilplan::io {

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write) {
  TemporaryOutput output(path);
  write(output.path());
  output.commit();
}

void writeTextAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream& out)>& write) {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    if (!out) throw ceilplan::Error("cannot open " + printableText(path.string(), 256) + " for writing");
    write(out);
    out.flush();
    if (!out) throw ceilplan::Error("failed while writing " + printableText(path.string(), 256) + " (disk full?)");
  });
}

}  // namespace ceilplan::io
