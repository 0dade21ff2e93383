#include "ceilplan/io/csv_columns.hpp"

#include "ceilplan/core/printable_text.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/input_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

namespace ceilplan::io {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return std::string(text.substr(first, last - first + 1));
}

// Splits one line into fields (RFC 4180 quoting), each trimmed of padding outside the quotes.
// Returns false for an unterminated quote.
bool splitFields(const std::string& line, std::vector<std::string>& fields) {
  fields.clear();
  std::string field;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') {
        field += c;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (c == '"' && trimmed(field).empty()) {
      quoted = was_quoted = true;
      field.clear();
    } else if (c == ',') {
      fields.push_back(was_quoted ? field : trimmed(field));
      field.clear();
      was_quoted = false;
    } else if (!was_quoted || (c != ' ' && c != '\t' && c != '\r')) {
      field += c;
    }
  }
  fields.push_back(was_quoted ? field : trimmed(field));
  return !quoted;
}

bool skipped(const std::string& line) {
  const std::string text = trimmed(line);
  return text.empty() || text.front() == '#';
}

std::string quotedName(const std::string& name) { return "'" + printableText(name) + "'"; }

std::string columnList(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 12;
  std::string list;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i) list += (i ? ", " : "") + printableText(names[i], 24);
  if (names.size() > kShown) list += ", ... (" + std::to_string(names.size()) + " in all)";
  return list;
}

}  // namespace

CsvColumns CsvColumns::read(const std::filesystem::path& path, const std::vector<std::string>& required,
                            const std::vector<std::string>& optional,
                            const std::vector<std::string>& none_is_infinite) {
  const std::string shown = printableText(path.string(), 256);
  requireInputFile(path, "CSV file");
  std::ifstream input(path, std::ios::binary);
  return parse(input, shown, required, optional, none_is_infinite);
}

CsvColumns CsvColumns::parse(std::istream& input, const std::string& source, const std::vector<std::string>& required,
                             const std::vector<std::string>& optional,
                             const std::vector<std::string>& none_is_infinite) {
  CsvColumns table;
  table.source_ = source;
  std::string line;
  std::vector<std::string> fields;
  std::size_t line_number = 0;
  bool have_header = false;
  std::vector<bool> none_allowed;  // per kept column
  while (std::getline(input, line)) {
    ++line_number;
    if (line_number == 1 && line.compare(0, kByteOrderMark.size(), kByteOrderMark) == 0)
      line.erase(0, kByteOrderMark.size());
    if (skipped(line)) continue;
    const std::string where = source + " line " + std::to_string(line_number);
    if (!splitFields(line, fields)) throw ceilplan::InputError(where + ": a quoted field is not closed");
    if (!have_header) {
      if (std::any_of(line.begin(), line.end(),
                      [](char c) { return (c >= 0 && c < 0x20 && c != '\t' && c != '\r') || c == 0x7F; }))
        throw ceilplan::InputError(where + ": the header holds control characters ('" + printableText(line, 24) +
                                   "'); is " + source + " a CSV text file?");
      for (const std::string& name : fields) {
        if (name.empty()) throw ceilplan::InputError(where + ": empty column name in the header");
        if (std::find(table.names_.begin(), table.names_.end(), name) != table.names_.end())
          throw ceilplan::InputError(where + ": column " + quotedName(name) + " appears twice in the header");
        table.names_.push_back(name);
      }
      for (const auto* wanted : {&required, &optional})
        for (const std::string& name : *wanted) {
          if (table.hasColumn(name)) continue;  // asked for twice
          const auto it = std::find(table.names_.begin(), table.names_.end(), name);
          if (it == table.names_.end()) {
            if (wanted == &optional) continue;
            throw ceilplan::InputError(source + " has no column " + quotedName(name) +
                                       "; columns: " + columnList(table.names_));
          }
          table.kept_names_.push_back(name);
          table.kept_fields_.push_back(static_cast<std::size_t>(it - table.names_.begin()));
        }
      table.kept_.resize(table.kept_names_.size());
      for (const std::string& name : table.kept_names_)
        none_allowed.push_back(std::find(none_is_infinite.begin(), none_is_infinite.end(), name) !=
                               none_is_infinite.end());
      have_header = true;
      continue;
    }
    if (fields.size() != table.names_.size())
      throw ceilplan::InputError(where + ": " + std::to_string(fields.size()) + " fields, but the header names " +
                                 std::to_string(table.names_.size()) + " columns");
    for (std::size_t k = 0; k < table.kept_fields_.size(); ++k) {
      const std::string& field = fields[table.kept_fields_[k]];
      if (none_allowed[k] && (field.empty() || field == "none")) {
        table.kept_[k].push_back(std::numeric_limits<double>::infinity());
        continue;
      }
      const std::string at = where + ", column " + quotedName(table.kept_names_[k]) + ": ";
      char* end = nullptr;
      const double value = std::strtod(field.c_str(), &end);
      if (field.empty()) throw ceilplan::InputError(at + "empty field");
      if (end != field.c_str() + field.size())
        throw ceilplan::InputError(at + "'" + printableText(field) + "' is not a number");
      if (!std::isfinite(value))
        throw ceilplan::InputError(at + "'" + printableText(field) + "' is not a finite number");
      table.kept_[k].push_back(value);
    }
    table.lines_.push_back(line_number);
  }
  if (input.bad()) throw ceilplan::InputError("failed while reading " + source);
  if (!have_header) throw ceilplan::InputError(source + " is empty; expected a header row of column names");
  return table;
}

bool CsvColumns::hasColumn(const std::string& name) const {
  return std::find(kept_names_.begin(), kept_names_.end(), name) != kept_names_.end();
}

const std::vector<double>& CsvColumns::column(const std::string& name) const {
  const auto it = std::find(kept_names_.begin(), kept_names_.end(), name);
  if (it == kept_names_.end())
    throw ceilplan::InputError(source_ + " has no column " + quotedName(name) +
                               " read; columns: " + columnList(names_));
  return kept_[static_cast<std::size_t>(it - kept_names_.begin())];
}

}  // namespace ceilplan::io
