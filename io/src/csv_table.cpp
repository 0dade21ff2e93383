#include "ceilplan/io/csv_table.hpp"

#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace ceilplan::io {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = line.find(',', begin);
    fields.push_back(trimmed(line.substr(begin, comma - begin)));
    if (comma == std::string::npos) return fields;
    begin = comma + 1;
  }
}

std::string unquoted(const std::string& name) {
  if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
    return name.substr(1, name.size() - 2);
  return name;
}

bool skipped(const std::string& line) {
  const std::string text = trimmed(line);
  return text.empty() || text.front() == '#';
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& path) {
  std::ifstream input(path);
  if (!input)
    throw InputError("cannot open " + path.string() + "; check the path and permissions");
  return parse(input, path.string());
}

CsvTable CsvTable::parse(std::istream& input, const std::string& source) {
  CsvTable table;
  table.source_ = source;
  std::string line;
  std::size_t line_number = 0;
  bool have_header = false;
  while (std::getline(input, line)) {
    ++line_number;
    if (skipped(line)) continue;
    const auto where = [&](std::size_t column) {
      return source + " line " + std::to_string(line_number) +
             (column < table.names_.size() ? ", column '" + table.names_[column] + "'" : "");
    };
    std::vector<std::string> fields = splitFields(line);
    if (!have_header) {
      for (std::string& field : fields) {
        const std::string name = unquoted(field);
        if (name.empty())
          throw InputError(where(table.names_.size()) + ": empty column name in the header");
        if (std::find(table.names_.begin(), table.names_.end(), name) != table.names_.end())
          throw InputError(where(table.names_.size()) + ": column '" + name +
                                   "' appears twice in the header");
        table.names_.push_back(name);
      }
      table.columns_.resize(table.names_.size());
      have_header = true;
      continue;
    }
    if (fields.size() != table.names_.size())
      throw InputError(where(table.names_.size()) + ": " + std::to_string(fields.size()) +
                               " fields, but the header names " +
                               std::to_string(table.names_.size()) + " columns");
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const std::string& field = fields[c];
      char* end = nullptr;
      const double value = std::strtod(field.c_str(), &end);
      if (field.empty()) {
        table.columns_[c].push_back(std::nan(""));
        continue;
      }
      if (end != field.c_str() + field.size())
        throw InputError(where(c) + ": '" + field + "' is not a number");
      if (!std::isfinite(value))
        throw InputError(where(c) + ": '" + field + "' is not a finite number");
      table.columns_[c].push_back(value);
    }
    table.lines_.push_back(line_number);
  }
  if (input.bad()) throw InputError("failed while reading " + source);
  if (!have_header) throw InputError(source + " is empty; expected a header row of column names");
  return table;
}

bool CsvTable::hasColumn(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

const std::vector<double>& CsvTable::columnWithGaps(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) {
    std::string available;
    for (const auto& n : names_) available += (available.empty() ? "" : ", ") + n;
    throw InputError(source_ + " has no column '" + name + "'; columns: " + available);
  }
  return columns_[static_cast<std::size_t>(it - names_.begin())];
}

const std::vector<double>& CsvTable::column(const std::string& name) const {
  const std::vector<double>& values = columnWithGaps(name);
  for (std::size_t row = 0; row < values.size(); ++row)
    if (std::isnan(values[row]))
      throw InputError(source_ + " line " + std::to_string(lines_[row]) + ", column '" + name + "': empty field");
  return values;
}

}  // namespace ceilplan::io
