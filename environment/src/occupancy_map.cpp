#include "ceilplan/environment/occupancy_map.hpp"

#include "generated_tree.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/input_file.hpp"

#include <octomap/ColorOcTree.h>
#include <octomap/OcTreeStamped.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace ceilplan::environment {
namespace {

constexpr const char* kBinaryHeader = "# Octomap OcTree binary file";
constexpr const char* kFullHeader = "# Octomap OcTree file";
constexpr int kTreeDepth = 16;  // OctoMap's fixed key depth: leaves never lie deeper

enum class Format { Binary, Full };

// The tree types whose full (.ot) node records ceilplan can read, and each record's payload:
// the occupancy log-odds (float), then what the type adds. OcTreeStamped writes no stamp.
struct TreeType {
  const char* id;
  std::size_t payload_bytes;
};
constexpr TreeType kFullTypes[] = {{"OcTree", 4}, {"ColorOcTree", 4 + 3}, {"OcTreeStamped", 4}};

struct Header {
  Format format;
  std::string id;
  unsigned long long size = 0;
  double resolution = 0.0;
  std::size_t data_offset = 0;
};

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
  throw ceilplan::InputError(name + ": " + problem);
}

const TreeType* fullType(const std::string& id) {
  for (const TreeType& type : kFullTypes)
    if (id == type.id) return &type;
  return nullptr;
}

// Mirrors AbstractOcTree::readHeader (token-based, '#' comments, up to the "data" line) but
// reports what is wrong instead of printing to stderr.
Header parseHeader(const std::string& bytes, const std::string& name) {
  Header header;
  const std::size_t first_end = bytes.find('\n');
  const std::string first_line = bytes.substr(0, first_end);
  if (first_line.rfind(kBinaryHeader, 0) == 0) {
    header.format = Format::Binary;
  } else if (first_line.rfind(kFullHeader, 0) == 0) {
    header.format = Format::Full;
  } else {
    fail(name, "not an OctoMap file (its first line is not an OctoMap .bt or .ot header)");
  }
  if (first_end == std::string::npos) fail(name, "truncated OctoMap file: the header ends early");

  std::size_t position = first_end + 1;
  bool have_size = false;
  while (true) {
    const std::size_t line_end = bytes.find('\n', position);
    if (line_end == std::string::npos) fail(name, "truncated OctoMap file: no 'data' line after the header");
    std::istringstream line(bytes.substr(position, line_end - position));
    position = line_end + 1;
    std::string token;
    if (!(line >> token)) continue;
    if (token == "data") break;
    if (token[0] == '#') continue;
    if (token == "id") {
      line >> header.id;
    } else if (token == "res") {
      if (!(line >> header.resolution)) fail(name, "corrupt OctoMap header: 'res' is not a number");
    } else if (token == "size") {
      std::string text;
      line >> text;
      char* end = nullptr;
      header.size = std::strtoull(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || text[0] == '-' || header.size > 0xffffffffULL)
        fail(name, "corrupt OctoMap header: 'size' is not a node count");
      have_size = true;
    }
  }
  header.data_offset = position;
  if (header.id.empty()) fail(name, "corrupt OctoMap header: no tree type ('id')");
  if (header.id == "1") header.id = "OcTree";  // OctoMap's deprecated id for OcTree
  // Every occupancy tree (ColorOcTree, OcTreeStamped, ...) writes the same .bt data: its
  // occupancy. A .ot holds each node's full record, which only the known types can be read from.
  if (header.format == Format::Full && fullType(header.id) == nullptr)
    fail(name, "holds a " + header.id +
                   ", which ceilplan cannot read from a .ot file; save it as a .bt (binary occupancy) file");
  if (!std::isfinite(header.resolution) || header.resolution < 1e-4 || header.resolution > 100.0)
    fail(name, "corrupt OctoMap header: resolution must be between 0.0001 and 100 m");
  if (!have_size) fail(name, "corrupt OctoMap header: no node count ('size')");
  if (header.size == 0) fail(name, "the map is empty (no known voxel)");
  return header;
}

// Walks the node stream the way OctoMap's readers will, without recursion and with OctoMap's
// depth limit, and counts the nodes; OctoMap itself trusts the stream and would recurse
// without bound or read past its end.
void checkNodeStream(const std::string& bytes, const Header& header, const std::string& name) {
  // 2 child bytes, or the node's record and a child byte.
  const std::size_t node_bytes = header.format == Format::Binary ? 2 : fullType(header.id)->payload_bytes + 1;
  std::size_t position = header.data_offset;
  unsigned long long nodes = 0;
  std::vector<int> pending_depths{0};  // nodes still to read, depth-first
  while (!pending_depths.empty()) {
    const int depth = pending_depths.back();
    pending_depths.pop_back();
    if (bytes.size() - position < node_bytes) fail(name, "truncated OctoMap file: the tree data ends early");
    ++nodes;
    int inner_children = 0;
    int children = 0;
    if (header.format == Format::Binary) {
      for (int b = 0; b < 2; ++b) {
        const auto bits = static_cast<unsigned char>(bytes[position + b]);
        for (int i = 0; i < 4; ++i) {
          const unsigned pair = (bits >> (2 * i)) & 3u;
          if (pair != 0) ++children;
          if (pair == 3) ++inner_children;  // both bits: the child has children of its own
        }
      }
      nodes += children;        // leaves are encoded in their parent's bits
      nodes -= inner_children;  // inner children count when their own record is read
    } else {
      float value;
      std::memcpy(&value, bytes.data() + position, sizeof value);
      if (!std::isfinite(value)) fail(name, "corrupt OctoMap file: a node holds a non-finite value");
      const auto bits = static_cast<unsigned char>(bytes[position + node_bytes - 1]);
      for (int i = 0; i < 8; ++i) inner_children += (bits >> i) & 1u;
    }
    position += node_bytes;
    if (inner_children > 0 && depth >= kTreeDepth)
      fail(name, "corrupt OctoMap file: the tree is deeper than OctoMap's 16 levels");
    for (int i = 0; i < inner_children; ++i) pending_depths.push_back(depth + 1);
  }
  if (nodes != header.size)
    fail(name, "corrupt OctoMap file: the header promises " + std::to_string(header.size) + " nodes, the data holds " +
                   std::to_string(nodes));
  // OctoMap stops reading where the tree ends: whatever follows would be dropped unseen.
  if (position != bytes.size()) {
    const std::string rest = bytes.substr(position, 64);
    if (rest.rfind(kBinaryHeader, 0) == 0 || rest.rfind(kFullHeader, 0) == 0)
      fail(name, "holds a second OctoMap tree after the first; a map file holds one tree, so split the file");
    const std::size_t extra = bytes.size() - position;
    fail(name, "corrupt OctoMap file: " + std::to_string(extra) + (extra == 1 ? " byte follows" : " bytes follow") +
                   " the end of the tree; is the file damaged, or two files joined?");
  }
}

// Debian's OctoMap is built with its debug messages on ("Reading binary octree type
// OcTree" on std::cerr); after our own checks they say nothing useful, so hold them back.
class QuietOctomap {
 public:
  QuietOctomap() : saved_(std::cerr.rdbuf(sink_.rdbuf())) {}
  ~QuietOctomap() { std::cerr.rdbuf(saved_); }
  QuietOctomap(const QuietOctomap&) = delete;
  QuietOctomap& operator=(const QuietOctomap&) = delete;

 private:
  std::ostringstream sink_;
  std::streambuf* saved_;
};

// Copies a tree of another occupancy type node by node into an OcTree: the same nodes (pruned
// blocks stay single leaves) with the same log-odds, without what the type adds (colour, stamps).
template <class Tree>
void copyNodes(const Tree& source, const typename Tree::NodeType* from, detail::GeneratedTree& target,
               octomap::OcTreeNode* to) {
  to->setLogOdds(from->getLogOdds());
  for (unsigned child = 0; child < 8; ++child)
    if (source.nodeChildExists(from, child))
      copyNodes(source, source.getNodeChild(from, child), target, target.createNodeChild(to, child));
}

template <class Tree>
std::unique_ptr<octomap::OcTree> readAsOccupancy(std::istream& data, double resolution, const std::string& name) {
  Tree source(resolution);
  source.readData(data);
  if (!data || source.getRoot() == nullptr) fail(name, "OctoMap could not read the " + source.getTreeType());
  auto tree = std::make_unique<detail::GeneratedTree>(resolution);
  copyNodes(source, source.getRoot(), *tree, tree->createRoot());
  return tree;
}

}  // namespace

OccupancyMap::OccupancyMap(std::unique_ptr<octomap::OcTree> tree, std::string name)
    : tree_(std::move(tree)), name_(std::move(name)) {
  if (!tree_ || tree_->getRoot() == nullptr) fail(name_, "the map is empty (no known voxel)");
}

OccupancyMap OccupancyMap::read(std::istream& in, const std::string& name) {
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) fail(name, "cannot read the file");
  return parse(buffer.str(), name);
}

OccupancyMap OccupancyMap::parse(const std::string& bytes, const std::string& name) {
  if (bytes.empty()) fail(name, "not an OctoMap file (it is empty)");
  const Header header = parseHeader(bytes, name);
  checkNodeStream(bytes, header, name);

  std::unique_ptr<octomap::OcTree> tree;
  const QuietOctomap quiet;
  if (header.format == Format::Binary) {
    // OctoMap reads a canonical header we write, so it cannot parse the original differently.
    std::ostringstream canonical;
    canonical.precision(17);
    canonical << kBinaryHeader << "\nid OcTree\nsize " << header.size << "\nres " << header.resolution << "\ndata\n";
    canonical.write(bytes.data() + header.data_offset, static_cast<std::streamsize>(bytes.size() - header.data_offset));
    std::istringstream stream(canonical.str());
    tree = std::make_unique<octomap::OcTree>(header.resolution);
    if (!tree->readBinary(stream)) fail(name, "OctoMap could not read the binary tree");
  } else {
    std::istringstream data(bytes.substr(header.data_offset));
    if (header.id == "ColorOcTree") {
      tree = readAsOccupancy<octomap::ColorOcTree>(data, header.resolution, name);
    } else if (header.id == "OcTreeStamped") {
      tree = readAsOccupancy<octomap::OcTreeStamped>(data, header.resolution, name);
    } else {
      tree = std::make_unique<octomap::OcTree>(header.resolution);
      tree->readData(data);
      if (!data) fail(name, "OctoMap could not read the tree");
    }
  }
  return OccupancyMap(std::move(tree), name);
}

OccupancyMap OccupancyMap::load(const std::filesystem::path& file) {
  return parse(readInputFile(file, "map file", kMaxFileBytes), file.string());
}

}  // namespace ceilplan::environment
