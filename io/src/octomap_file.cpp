#include "ceilplan/io/octomap_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/atomic_file.hpp"

#include <fstream>

namespace ceilplan::io {

void writeOctoMapBinary(const octomap::OcTree& tree, std::ostream& out, const std::filesystem::path& file) {
  out << "# Octomap OcTree binary file\n# (feel free to add / change comments, but leave the first line as it is!)\n#\n"
      << "id " << tree.getTreeType() << "\nsize " << tree.size() << "\nres " << tree.getResolution() << "\ndata\n";
  tree.writeBinaryData(out);
  out.flush();
  if (!out)
    throw ceilplan::Error("cannot write the OctoMap " + printableText(file.string(), 256) +
                          ": the write failed (disk full?)");
}

bool isOctoMapFileName(const std::filesystem::path& file) {
  return file.extension() == ".bt" || file.extension() == ".ot";
}

void writeOctoMapFile(const std::filesystem::path& file, const octomap::OcTree& tree) {
  if (!isOctoMapFileName(file))
    throw ceilplan::InputError(printableText(file.string(), 256) + ": an OctoMap file must end in .bt (or .ot)");
  writeAtomically(file, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    if (file.extension() == ".ot") {
      tree.write(out);
      out.flush();
    } else {
      writeOctoMapBinary(tree, out, file);
    }
    if (!out) throw ceilplan::Error("cannot write " + printableText(file.string(), 256));
  });
}

}  // namespace ceilplan::io
