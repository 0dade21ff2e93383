#pragma once
// A small reader for numeric CSV files: a header row of column names, then rows of numbers.
// Errors (ceilplan::InputError) name the file, the line and the column.

#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace ceilplan::io {

class CsvTable {
 public:
  // Reads `path`. Blank lines and lines starting with '#' are skipped; fields are separated by
  // commas and may be padded with spaces; names may be double-quoted. Throws ceilplan::InputError
  // ("FILE line N, column 'NAME': ...") on a missing file, an empty or duplicate header name, a
  // row of the wrong width, or a field that is not a finite number. An empty field is allowed
  // (path.csv leaves a gap to no ceiling empty) until its column is asked for.
  static CsvTable read(const std::filesystem::path& path);
  // Same, from a stream; `source` names it in errors.
  static CsvTable parse(std::istream& input, const std::string& source);

  const std::vector<std::string>& columnNames() const { return names_; }
  bool hasColumn(const std::string& name) const;
  // Throws ceilplan::InputError naming the columns available if there is no such column, or
  // naming the line of the first empty field in it.
  const std::vector<double>& column(const std::string& name) const;
  // Same, with empty fields as NaN.
  const std::vector<double>& columnWithGaps(const std::string& name) const;
  std::size_t rowCount() const { return lines_.size(); }
  // The 1-based file line a row came from, for error messages.
  std::size_t lineOfRow(std::size_t row) const { return lines_.at(row); }
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> columns_;
  std::vector<std::size_t> lines_;
};

}  // namespace ceilplan::io
