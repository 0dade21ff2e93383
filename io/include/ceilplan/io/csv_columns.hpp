#pragma once
/// @file
/// Numeric columns picked by name from a CSV file whose other columns may hold anything: the
/// `mode` text of `ceilplan duty --csv-dir`'s series, a flight log's flags. Errors are one line
/// naming the file, the line and the column, with the offending text escaped (printableText).

#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace ceilplan::io {

/// A CSV file read by column name, every field checked to be a finite number (path.csv, calibration data, SOC series).
class CsvColumns {
 public:
  /// Reads `path`: a header row of column names, then rows with as many fields. Accepts a UTF-8
  /// byte-order mark, CRLF line ends, fields padded with spaces and double-quoted fields (RFC
  /// 4180, "" for a quote); skips blank lines and lines starting with '#'. Keeps the columns
  /// named in `required` (each must be in the header) and in `optional` (if present), each field
  /// a finite number; in the kept columns named in `none_is_infinite` an empty field or "none"
  /// reads as infinity (a gap with no surface). Throws ceilplan::InputError on a missing,
  /// unreadable or empty file, a directory, a bad header, a row of the wrong width or a field
  /// that is not a finite number.
  static CsvColumns read(const std::filesystem::path& path, const std::vector<std::string>& required,
                         const std::vector<std::string>& optional = {},
                         const std::vector<std::string>& none_is_infinite = {});
  /// Same, from a stream; `source` names it in errors.
  static CsvColumns parse(std::istream& input, const std::string& source, const std::vector<std::string>& required,
                          const std::vector<std::string>& optional = {},
                          const std::vector<std::string>& none_is_infinite = {});

  const std::vector<std::string>& columnNames() const { return names_; }  ///< the whole header
  bool hasColumn(const std::string& name) const;                          ///< kept (read) or not
  /// A kept column; throws ceilplan::InputError naming the header's columns if it was not kept.
  const std::vector<double>& column(const std::string& name) const;
  /// Data rows read.
  std::size_t rowCount() const { return lines_.size(); }
  std::size_t lineOfRow(std::size_t row) const { return lines_.at(row); }  ///< 1-based file line
  /// The file or stream name used in messages.
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::vector<std::string> names_;
  std::vector<std::string> kept_names_;
  std::vector<std::size_t> kept_fields_;  ///< index in the row of each kept column
  std::vector<std::vector<double>> kept_;
  std::vector<std::size_t> lines_;
};

}  // namespace ceilplan::io
