#include "ceilplan/io/octomap_file.hpp"

#include "ceilplan/core/error.hpp"

namespace ceilplan::io {

void writeOctoMapBinary(const octomap::OcTree& tree, std::ostream& out) {
  out << "# Octomap OcTree binary file\n# (feel free to add / change comments, but leave the first line as it is!)\n#\n"
      << "id " << tree.getTreeType() << "\nsize " << tree.size() << "\nres " << tree.getResolution() << "\ndata\n";
  tree.writeBinaryData(out);
  out.flush();
  if (!out) throw ceilplan::Error("writing the OctoMap failed");
}

}  // namespace ceilplan::io
