#include "open3d_input_checks.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/printable_text.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io::detail {
namespace {

// Open3D reads PCD lines with fgets into 1024 bytes (a longer line would count
// as two), and rply PLY header lines into as many.
constexpr std::size_t kMaxLineBytes = 1000;
constexpr std::uint64_t kMaxCount = std::numeric_limits<std::int32_t>::max();  // Open3D counts in int
// Open3D splits larger faces by ear clipping, cubic in the corners: a uchar
// count's range.
constexpr std::uint64_t kMaxFaceCorners = 255;

std::vector<std::string> wordsOf(const std::string& line, const char* separators) {
  std::vector<std::string> words;
  for (std::size_t start = line.find_first_not_of(separators); start != std::string::npos;) {
    const std::size_t end = line.find_first_of(separators, start);
    words.push_back(line.substr(start, end - start));
    start = line.find_first_not_of(separators, end);
  }
  return words;
}

std::optional<std::uint64_t> wholeNumber(const std::string& word, std::uint64_t max) {
  if (word.empty() || word.size() > 18) return std::nullopt;
  std::uint64_t value = 0;
  for (const char c : word) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  if (value > max) return std::nullopt;
  return value;
}

// The next line without its '\n'; false at the end of the file. A line longer
// than kMaxLineBytes is cut there (and refused), so a file without line breaks
// is not read whole.
bool readLine(std::istream& in, std::string& line) {
  line.clear();
  std::streambuf& text = *in.rdbuf();
  int c = text.sbumpc();
  if (c == std::char_traits<char>::eof()) return false;
  for (; c != std::char_traits<char>::eof() && c != '\n' && line.size() <= kMaxLineBytes; c = text.sbumpc())
    line += static_cast<char>(c);
  return true;
}

// A header line: at most kMaxLineBytes, no control byte but tab and CR.
bool headerText(const std::string& line) {
  return line.size() <= kMaxLineBytes && std::none_of(line.begin(), line.end(), [](char c) {
           const auto byte = static_cast<unsigned char>(c);
           return (byte < 0x20 && c != '\t' && c != '\r') || byte == 0x7f;
         });
}

std::string records(std::uint64_t count) { return std::to_string(count) + (count == 1 ? " record" : " records"); }

struct Refusal {
  const std::filesystem::path& file;
  std::string kind;
  [[noreturn]] void operator()(const std::string& problem) const {
    throw InputError(printableText(file.string(), 256) + ": not a readable " + kind + " (" + problem + ")");
  }
};

std::uint64_t bytesAfter(std::ifstream& in, const std::filesystem::path& file) {
  const std::uint64_t size = std::filesystem::file_size(file);
  const std::streamoff position = in.tellg();
  return position >= 0 && static_cast<std::uint64_t>(position) <= size ? size - static_cast<std::uint64_t>(position)
                                                                       : 0;
}

// ---- PCD

struct PcdField {
  std::string name;
  std::uint64_t size = 4;  // Open3D's defaults when SIZE, TYPE or COUNT is missing
  char type = 'F';
  std::uint64_t count = 1;
};

// What Open3D's binary PCD reader decodes; any other coordinate it reads as 0.
bool decodable(const PcdField& field) { return field.type == 'F' ? field.size == 4 : field.size != 8; }

}  // namespace

void checkPcdFile(const std::filesystem::path& file) {
  const Refusal refuse{file, "point cloud"};
  std::ifstream in(file, std::ios::binary);
  std::vector<PcdField> fields;
  std::vector<std::string> seen;
  std::uint64_t width = 0, height = 0, points = 0;
  std::string storage, line;
  std::uint64_t line_number = 0;
  while (storage.empty()) {
    const std::string at = "PCD header line " + std::to_string(++line_number) + ": ";
    if (!readLine(in, line)) refuse("the PCD header ends before its DATA line");
    if (!headerText(line)) refuse(at + "longer than 1000 bytes, or a control byte");
    const std::vector<std::string> words = wordsOf(line, " \t\r");
    if (words.empty() || words[0][0] == '#') continue;
    const std::string entry = words[0] == "COLUMNS" ? "FIELDS" : words[0];
    constexpr std::array<const char*, 10> kEntries = {"VERSION", "FIELDS", "SIZE",      "TYPE",   "COUNT",
                                                      "WIDTH",   "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
    if (std::find(kEntries.begin(), kEntries.end(), entry) == kEntries.end())
      refuse(at + "'" + printableText(words[0], 24) +
             "' is no PCD v0.7 entry (VERSION, FIELDS, SIZE, TYPE, COUNT, "
             "WIDTH, HEIGHT, VIEWPOINT, POINTS, DATA)");
    if (std::find(seen.begin(), seen.end(), entry) != seen.end()) refuse(at + "a second " + entry + " line");
    seen.push_back(entry);
    const std::size_t values = words.size() - 1;
    const bool per_field = entry == "SIZE" || entry == "TYPE" || entry == "COUNT";
    if (per_field && values != fields.size())
      refuse(at + entry + " gives " + std::to_string(values) + " values for " + std::to_string(fields.size()) +
             " fields" + (fields.empty() ? " (FIELDS must come first)" : ""));
    const bool single = entry == "WIDTH" || entry == "HEIGHT" || entry == "POINTS" || entry == "DATA";
    if (single && values != 1) refuse(at + entry + " takes one value");
    if (entry == "FIELDS") {
      if (values == 0) refuse(at + "FIELDS names no field");
      for (std::size_t i = 1; i < words.size(); ++i) fields.push_back({words[i]});
    } else if (entry == "SIZE") {
      // COUNT places the fields by their sizes: a SIZE after it would move them
      // again.
      if (std::find(seen.begin(), seen.end(), "COUNT") != seen.end()) refuse(at + "SIZE after COUNT");
      for (std::size_t i = 0; i < values; ++i) {
        const auto size = wholeNumber(words[i + 1], 8);
        if (!size || (*size != 1 && *size != 2 && *size != 4 && *size != 8))
          refuse(at + "a field size of '" + printableText(words[i + 1], 24) + "' (1, 2, 4 or 8 bytes)");
        fields[i].size = *size;
      }
    } else if (entry == "TYPE") {
      for (std::size_t i = 0; i < values; ++i) {
        if (words[i + 1] != "F" && words[i + 1] != "I" && words[i + 1] != "U")
          refuse(at + "a field type of '" + printableText(words[i + 1], 24) + "' (F, I or U)");
        fields[i].type = words[i + 1][0];
      }
    } else if (entry == "COUNT") {
      for (std::size_t i = 0; i < values; ++i) {
        const auto count = wholeNumber(words[i + 1], 65536);
        if (!count || *count == 0)
          refuse(at + "a field count of '" + printableText(words[i + 1], 24) + "' (1 or more)");
        fields[i].count = *count;
      }
    } else if (entry == "WIDTH" || entry == "HEIGHT" || entry == "POINTS") {
      const auto value = wholeNumber(words[1], kMaxCount);
      if (!value || *value == 0)
        refuse(at + entry + " '" + printableText(words[1], 24) + "' is not a whole number from 1 to " +
               std::to_string(kMaxCount));
      (entry == "WIDTH" ? width : entry == "HEIGHT" ? height : points) = *value;
      // Open3D multiplies WIDTH by HEIGHT where it reads HEIGHT.
      if (entry == "HEIGHT" && width == 0) refuse(at + "HEIGHT before WIDTH");
    } else if (entry == "DATA") {
      if (words[1] != "ascii" && words[1] != "binary" && words[1] != "binary_compressed")
        refuse(at + "DATA '" + printableText(words[1], 24) + "' (ascii, binary or binary_compressed)");
      storage = words[1];
    }
  }
  if (fields.empty() || width == 0 || height == 0 || points == 0)
    refuse("the PCD header lacks FIELDS, WIDTH, HEIGHT or POINTS");
  if (points != width * height)
    refuse("the PCD header's POINTS " + std::to_string(points) + " is not WIDTH x HEIGHT (" + std::to_string(width) +
           " x " + std::to_string(height) + ")");

  std::uint64_t values_per_point = 0, bytes_per_point = 0;
  for (const PcdField& field : fields) {
    values_per_point += field.count;
    bytes_per_point += field.size * field.count;
    // A file Open3D reads, wrongly: said as such.
    if (storage != "ascii" && (field.name == "x" || field.name == "y" || field.name == "z") && !decodable(field))
      throw InputError(printableText(file.string(), 256) + ": " + storage + " PCD with " + std::to_string(field.size) +
                       "-byte coordinates of type " + field.type +
                       ", which the PCD reader (Open3D 0.16) reads as zeros; "
                       "save it as ascii PCD or as PLY");
  }
  const std::uint64_t data_bytes = points * bytes_per_point;
  const std::uint64_t available = bytesAfter(in, file);
  if (storage == "binary" && available < data_bytes)
    refuse("the binary PCD announces " + std::to_string(points) + " points of " + std::to_string(bytes_per_point) +
           " bytes but holds " + std::to_string(available) + " bytes of data");
  if (storage == "binary_compressed") {
    std::uint32_t sizes[2] = {0, 0};  // compressed, uncompressed, as the file's machine wrote them
    if (available < sizeof sizes || !in.read(reinterpret_cast<char*>(sizes), sizeof sizes))
      refuse("the compressed PCD ends before its data sizes");
    if (sizes[1] != data_bytes || sizes[0] > available - sizeof sizes)
      refuse("the compressed PCD's data sizes (" + std::to_string(sizes[0]) + " compressed, " +
             std::to_string(sizes[1]) + " uncompressed) do not fit " + std::to_string(points) + " points of " +
             std::to_string(bytes_per_point) + " bytes in " + std::to_string(available) + " bytes");
  }
  if (storage == "ascii") {
    // Open3D skips a row with fewer values than a point has, reads POINTS rows
    // whatever follows them, and leaves the points it finds no row for
    // uninitialised: the rows must be the points.
    std::uint64_t rows = 0;
    while (readLine(in, line)) {
      ++line_number;
      const std::string at = "PCD line " + std::to_string(line_number) + ": ";
      if (line.size() > kMaxLineBytes) refuse(at + "longer than 1000 bytes");
      line.resize(std::min(line.find('\0'),
                           line.size()));  // Open3D's line ends at a NUL
      const std::size_t values = wordsOf(line, " \t\r").size();
      if (values == 0) continue;
      if (values < values_per_point)
        refuse(at + "'" + printableText(line, 40) + "' holds " + std::to_string(values) + " values where a point has " +
               std::to_string(values_per_point) + "; fix or delete the line");
      if (++rows > points)
        refuse("the ascii PCD announces " + std::to_string(points) + " points but holds more rows (line " +
               std::to_string(line_number) + ")");
    }
    if (rows < points)
      refuse("the ascii PCD announces " + std::to_string(points) + " points but holds " + std::to_string(rows) +
             " rows");
  }
}

// ---- PLY

namespace {

struct PlyType {
  const char* name;
  int bytes;
  char kind;  // 'i' signed, 'u' unsigned, 'f' floating point
};
constexpr std::array<PlyType, 16> kPlyTypes = {{{"char", 1, 'i'},
                                                {"int8", 1, 'i'},
                                                {"uchar", 1, 'u'},
                                                {"uint8", 1, 'u'},
                                                {"short", 2, 'i'},
                                                {"int16", 2, 'i'},
                                                {"ushort", 2, 'u'},
                                                {"uint16", 2, 'u'},
                                                {"int", 4, 'i'},
                                                {"int32", 4, 'i'},
                                                {"uint", 4, 'u'},
                                                {"uint32", 4, 'u'},
                                                {"float", 4, 'f'},
                                                {"float32", 4, 'f'},
                                                {"double", 8, 'f'},
                                                {"float64", 8, 'f'}}};

std::optional<PlyType> plyType(const std::string& name) {
  for (const PlyType& type : kPlyTypes)
    if (name == type.name) return type;
  return std::nullopt;
}

struct PlyProperty {
  std::string name;
  PlyType value;
  std::optional<PlyType> count;  // a list's count
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

// Reads the body of a PLY file: words of ascii text (rply's separators) or
// binary values.
class PlyBody {
 public:
  PlyBody(std::ifstream& in, bool ascii, bool big_endian) : in_(in), ascii_(ascii), big_endian_(big_endian) {}

  // The next value as a number; nullopt at the end of the file or for a word
  // that is no number.
  std::optional<double> value(const PlyType& type) {
    if (ascii_) {
      // Coordinates are rply's to parse: only their presence matters here.
      if (type.kind == 'f') return skipWord() ? std::optional<double>(0.0) : std::nullopt;
      const std::optional<std::string> word = nextWord();
      if (!word) return std::nullopt;
      const bool negative = (*word)[0] == '-';
      const auto magnitude = wholeNumber(negative ? word->substr(1) : *word, kMaxCount + 1);
      if (!magnitude) return std::nullopt;
      return negative ? -static_cast<double>(*magnitude) : static_cast<double>(*magnitude);
    }
    unsigned char bytes[8];
    if (!in_.read(reinterpret_cast<char*>(bytes), type.bytes)) {
      ended_ = true;
      return std::nullopt;
    }
    if (big_endian_) std::reverse(bytes, bytes + type.bytes);
    return decoded(bytes, type);
  }

  // Whether a value could not be read because the file ended.
  bool ended() const { return ended_; }

  // Whether anything but separators (ascii) or any byte (binary) follows the
  // values read so far.
  bool moreData() {
    std::streambuf& text = *in_.rdbuf();
    for (int c = text.sbumpc(); c != std::char_traits<char>::eof(); c = text.sbumpc())
      if (!ascii_ || !separator(c)) return true;
    return false;
  }

  // Skips `count` values of `bytes` each (binary); false when the file holds
  // fewer.
  bool skip(std::uint64_t count, int bytes, std::uint64_t available) {
    if (count > available / static_cast<std::uint64_t>(bytes)) return false;
    return static_cast<bool>(
        in_.seekg(static_cast<std::streamoff>(count * static_cast<std::uint64_t>(bytes)), std::ios::cur));
  }

 private:
  static bool separator(int c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

  bool skipWord() {
    std::streambuf& text = *in_.rdbuf();
    int c = text.sbumpc();
    while (c != std::char_traits<char>::eof() && separator(c)) c = text.sbumpc();
    if (c == std::char_traits<char>::eof()) return !(ended_ = true);
    while (c != std::char_traits<char>::eof() && !separator(c)) c = text.sbumpc();
    return true;
  }

  std::optional<std::string> nextWord() {
    std::string word;
    std::streambuf& text = *in_.rdbuf();
    for (int c = text.sbumpc(); c != std::char_traits<char>::eof(); c = text.sbumpc()) {
      if (separator(c)) {
        if (!word.empty()) return word;
      } else {
        word += static_cast<char>(c);
      }
    }
    if (word.empty()) {
      ended_ = true;
      return std::nullopt;
    }
    return word;
  }

  static double decoded(const unsigned char* bytes, const PlyType& type) {
    if (type.kind == 'f') {
      if (type.bytes == 4) {
        float value;
        std::memcpy(&value, bytes, 4);
        return value;
      }
      double value;
      std::memcpy(&value, bytes, 8);
      return value;
    }
    std::uint64_t raw = 0;
    for (int i = type.bytes - 1; i >= 0; --i) raw = (raw << 8) | bytes[i];
    if (type.kind == 'i' && (raw >> (8 * type.bytes - 1)) != 0)
      return static_cast<double>(raw) - std::ldexp(1.0, 8 * type.bytes);
    return static_cast<double>(raw);
  }

  std::ifstream& in_;
  bool ascii_, big_endian_;
  bool ended_ = false;
};

}  // namespace

void checkPlyFile(const std::filesystem::path& file, const std::string& kind) {
  const Refusal refuse{file, kind};
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!readLine(in, line) || (line != "ply" && line != "ply\r")) refuse("not a PLY file (no 'ply' first line)");
  std::string format;
  std::vector<PlyElement> elements;
  for (int number = 2;; ++number) {
    const std::string at = "PLY header line " + std::to_string(number) + ": ";
    if (!readLine(in, line)) refuse("the PLY header ends before end_header");
    if (!headerText(line)) refuse(at + "longer than 1000 bytes, or a control byte");
    const std::vector<std::string> words = wordsOf(line, " \t\r");
    if (words.empty()) refuse(at + "empty");
    const std::string& keyword = words[0];
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (number == 2 || keyword == "format") {
      if (number != 2 || words.size() != 3 || words[2] != "1.0" ||
          (words[1] != "ascii" && words[1] != "binary_little_endian" && words[1] != "binary_big_endian"))
        refuse(at +
               "the second line must be 'format "
               "ascii|binary_little_endian|binary_big_endian 1.0'");
      format = words[1];
    } else if (keyword == "element") {
      const auto count = words.size() == 3 ? wholeNumber(words[2], kMaxCount) : std::nullopt;
      if (!count) refuse(at + "give 'element NAME COUNT', COUNT a whole number up to " + std::to_string(kMaxCount));
      elements.push_back({words[1], *count, {}});
    } else if (keyword == "property") {
      if (elements.empty()) refuse(at + "a property before any element");
      const bool list = words.size() == 5 && words[1] == "list";
      const auto count = list ? plyType(words[2]) : std::nullopt;
      const auto value = words.size() >= 3 ? plyType(words[list ? 3 : 1]) : std::nullopt;  // "property" alone
      if ((!list && words.size() != 3) || !value || (list && (!count || count->kind == 'f')))
        refuse(at +
               "give 'property TYPE NAME' or 'property list COUNT_TYPE "
               "TYPE NAME' with PLY's types, an integer count");
      elements.back().properties.push_back({words.back(), *value, count});
    } else if (keyword == "end_header") {
      // rply starts binary data one byte after the word: a CR or blank there
      // would shift it.
      if (words.size() != 1 || (format != "ascii" && line != "end_header")) refuse(at + "give 'end_header' alone");
      break;
    } else {
      refuse(at + "'" + printableText(keyword, 24) + "' is no PLY header keyword");
    }
  }

  const auto vertex =
      std::find_if(elements.begin(), elements.end(), [](const PlyElement& e) { return e.name == "vertex"; });
  const std::uint64_t vertices = vertex == elements.end() ? 0 : vertex->count;
  PlyBody body(in, format == "ascii", format == "binary_big_endian");
  for (const PlyElement& element : elements) {
    const bool lists = std::any_of(element.properties.begin(), element.properties.end(),
                                   [](const PlyProperty& p) { return p.count.has_value(); });
    const std::string what = "the PLY's " + printableText(element.name, 24) + " element";
    if (!lists && format != "ascii") {
      std::uint64_t record_bytes = 0;
      for (const PlyProperty& property : element.properties)
        record_bytes += static_cast<std::uint64_t>(property.value.bytes);
      const std::uint64_t available = bytesAfter(in, file);
      if (record_bytes > 0 && !body.skip(element.count, static_cast<int>(record_bytes), available))
        refuse(what + " announces " + records(element.count) + " of " + std::to_string(record_bytes) +
               " bytes, more than the file's remaining " + std::to_string(available) + " bytes hold");
      continue;
    }
    for (std::uint64_t record = 0; record < element.count; ++record) {
      const std::string where = what + ", record " + std::to_string(record) + ": ";
      // A value missing because the file ends says how much is missing;
      // otherwise, which value.
      const auto unreadable = [&](const std::string& value) {
        if (body.ended())
          refuse(what + " announces " + records(element.count) + "; the file ends in record " + std::to_string(record));
        refuse(where + value);
      };
      for (const PlyProperty& property : element.properties) {
        const bool corners =
            element.name == "face" && (property.name == "vertex_indices" || property.name == "vertex_index");
        if (corners && !property.count) refuse(where + property.name + " must be a list");
        std::uint64_t items = 1;
        if (property.count) {
          const std::optional<double> count = body.value(*property.count);
          if (!count || *count < 0) unreadable("a list count that is no whole number of 0 or more");
          items = static_cast<std::uint64_t>(*count);
          if (corners && (items < 3 || items > kMaxFaceCorners))
            refuse(where + "a face of " + std::to_string(items) + " corners (3 to " + std::to_string(kMaxFaceCorners) +
                   ")");
        }
        if (!corners && format != "ascii") {
          if (!body.skip(items, property.value.bytes, bytesAfter(in, file)))
            refuse(what + " announces " + records(element.count) + "; the file ends in record " +
                   std::to_string(record));
          continue;
        }
        for (std::uint64_t item = 0; item < items; ++item) {
          const std::optional<double> value = body.value(property.value);
          if (!value) unreadable(corners ? "a vertex index that is no whole number" : "a value that is no number");
          if (corners && !(*value >= 0 && *value < static_cast<double>(vertices) && *value == std::floor(*value)))
            refuse(where + "a face names vertex " + formatNumber(*value) + " of " + std::to_string(vertices));
        }
      }
    }
  }
  // rply stops after the elements its header announces: anything after them was
  // not read.
  if (body.moreData())
    refuse(
        "data after the last element its header announces; do the header's "
        "element counts match the data?");
}

// ---- XYZ

void checkXyzFile(const std::filesystem::path& file, std::size_t numbers_per_line) {
  const Refusal refuse{file, "point cloud"};
  std::ifstream in(file, std::ios::binary);
  std::string line;
  for (std::uint64_t line_number = 1; readLine(in, line); ++line_number) {
    if (line.size() > kMaxLineBytes) refuse("line " + std::to_string(line_number) + " is longer than 1000 bytes");
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const char* cursor = line.c_str();
    std::size_t read = 0;
    for (; read < numbers_per_line; ++read) {
      char* end = nullptr;
      std::strtod(cursor, &end);
      if (end == cursor) break;
      cursor = end;
    }
    if (read < numbers_per_line)
      refuse("line " + std::to_string(line_number) + ": '" + printableText(line, 40) + "' is not " +
             std::to_string(numbers_per_line) + " numbers; fix or delete the line");
  }
}

}  // namespace ceilplan::io::detail
