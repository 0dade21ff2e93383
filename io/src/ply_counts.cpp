#include "ply_counts.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"

#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace ceilplan::io::detail {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& problem) {
  throw InputError(printableText(file.string(), 256) + ": " + problem + "; is the file damaged?");
}

struct Element {
  std::string name;
  std::uintmax_t count = 0;
  std::uintmax_t row_bytes = 0;  // binary: bytes per row, when every property has a known fixed size
  bool variable_rows = false;    // a list property, or a type this check does not know
};

std::uintmax_t typeBytes(const std::string& type) {
  static const std::map<std::string, std::uintmax_t> sizes = {
      {"char", 1},   {"uchar", 1},  {"int8", 1},  {"uint8", 1},  {"short", 2},   {"ushort", 2},
      {"int16", 2},  {"uint16", 2}, {"int", 4},   {"uint", 4},   {"int32", 4},   {"uint32", 4},
      {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto found = sizes.find(type);
  return found == sizes.end() ? 0 : found->second;
}

}  // namespace

void checkPlyCounts(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return;  // not a PLY: Open3D says so
  std::string format;
  std::vector<Element> elements;
  bool ended = false;
  for (int lines = 0; lines < 1024 && std::getline(in, line); ++lines) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "format") words >> format;
    if (key == "element") {
      Element element;
      if (!(words >> element.name >> element.count)) refuse(file, "a PLY 'element' line without a count");
      elements.push_back(element);
    }
    if (key == "property" && !elements.empty()) {
      std::string type;
      words >> type;
      const std::uintmax_t bytes = typeBytes(type);
      if (bytes == 0) elements.back().variable_rows = true;  // "list", or unknown: Open3D's reader judges
      elements.back().row_bytes += bytes;
    }
    if (key == "end_header") {
      ended = true;
      break;
    }
  }
  if (!ended) refuse(file, "the PLY header has no 'end_header' line");
  std::uintmax_t promised_rows = 0;
  for (const Element& element : elements) promised_rows += element.count;
  if (format == "ascii") {
    std::uintmax_t rows = 0;
    while (std::getline(in, line))
      if (line.find_first_not_of(" \t\r") != std::string::npos) ++rows;
    if (rows != promised_rows)
      refuse(file, "the PLY header promises " + std::to_string(promised_rows) +
                       " rows of data (its element counts), the file holds " + std::to_string(rows));
    return;
  }
  for (const Element& element : elements)
    if (element.variable_rows || element.row_bytes == 0) return;  // Open3D's reader checks what it reads
  const auto data_start = static_cast<std::uintmax_t>(in.tellg());
  const std::uintmax_t data_bytes = std::filesystem::file_size(file) - data_start;
  std::uintmax_t promised_bytes = 0;
  for (const Element& element : elements) {
    if (element.count > data_bytes / element.row_bytes)  // also keeps the sum from overflowing
      refuse(file, "the PLY header promises " + std::to_string(element.count) + " " + printableText(element.name, 20) +
                       " rows, more than its " + std::to_string(data_bytes) + " bytes of data hold");
    promised_bytes += element.count * element.row_bytes;
  }
  if (data_bytes != promised_bytes)
    refuse(file, "the PLY header's element counts promise " + std::to_string(promised_bytes) +
                     " bytes of data, the file holds " + std::to_string(data_bytes));
}

}  // namespace ceilplan::io::detail
