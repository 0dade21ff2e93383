// What `ceilplan rainflow` (and any command echoing its input) reads and writes with: the
// column-picking CSV reader, the escaping of echoed text, and outputs that appear whole or not
// at all.

#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/io/temporary_output.hpp"

#include "ceilplan/core/error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ceilplan::io {
namespace {

CsvColumns parse(const std::string& text, const std::vector<std::string>& required,
                 const std::vector<std::string>& optional = {}) {
  std::istringstream input(text);
  return CsvColumns::parse(input, "log.csv", required, optional);
}

std::string errorOf(const std::string& text, const std::vector<std::string>& required) {
  try {
    parse(text, required);
  } catch (const ceilplan::InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PrintableText, EscapesControlBytesAndInvalidUtf8ButKeepsLetters) {
  EXPECT_EQ(ceilplan::printableText("soc_%"), "soc_%");
  EXPECT_EQ(ceilplan::printableText("Ladezustand \xC2\xB5"), "Ladezustand \xC2\xB5");  // µ is a letter
  EXPECT_EQ(ceilplan::printableText("\x1b[2J\r\n\x07"), "\\x1B[2J\\x0D\\x0A\\x07");
  EXPECT_EQ(ceilplan::printableText("\xC2\x9B"
                                    "31m"),
            "\\xC2\\x9B31m");  // C1 CSI, as UTF-8
  EXPECT_EQ(ceilplan::printableText("\x9B"
                                    "31m"),
            "\\x9B31m");                                         // C1 CSI, raw byte
  EXPECT_EQ(ceilplan::printableText("\xE2\x82"), "\\xE2\\x82");  // a cut sequence
  EXPECT_EQ(ceilplan::printableText(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(ceilplan::printableText(std::string(100, 'x'), 8), "xxxxxxxx...");
}

TEST(CsvColumns, PicksTheNamedColumnsAndIgnoresTheOthers) {
  const CsvColumns table = parse("t_s,current_a,soc,mode\n0,9.5,0.95,discharge\n30,9.5,0.93,\"idle, on the pad\"\n",
                                 {"soc"}, {"t_s", "temperature_c"});
  EXPECT_EQ(table.rowCount(), 2u);
  EXPECT_EQ(table.column("soc"), (std::vector<double>{0.95, 0.93}));
  EXPECT_EQ(table.column("t_s"), (std::vector<double>{0.0, 30.0}));
  EXPECT_FALSE(table.hasColumn("temperature_c"));  // optional and absent
  EXPECT_FALSE(table.hasColumn("mode"));           // present, never read
  EXPECT_EQ(table.columnNames().size(), 4u);
  EXPECT_EQ(table.lineOfRow(1), 3u);
}

TEST(CsvColumns, AcceptsAByteOrderMarkCrlfQuotesAndComments) {
  const CsvColumns table = parse("\xEF\xBB\xBF\"soc\" , t_s\r\n# logged\r\n\r\n 0.5 ,\"1\"\r\n", {"soc", "t_s"});
  EXPECT_EQ(table.column("soc"), (std::vector<double>{0.5}));
  EXPECT_EQ(table.column("t_s"), (std::vector<double>{1.0}));
}

TEST(CsvColumns, RefusesBadInputInOneLineNamingLineAndColumn) {
  EXPECT_EQ(errorOf("t_s,soc\n0,0.5\n1,0.4,9\n", {"soc"}), "log.csv line 3: 3 fields, but the header names 2 columns");
  EXPECT_EQ(errorOf("t_s,soc\n0,nan\n", {"soc"}), "log.csv line 2, column 'soc': 'nan' is not a finite number");
  EXPECT_EQ(errorOf("t_s,soc\n0,1e999\n", {"soc"}), "log.csv line 2, column 'soc': '1e999' is not a finite number");
  EXPECT_EQ(errorOf("soc\n\x1b]0;owned\x07\n", {"soc"}),
            "log.csv line 2, column 'soc': '\\x1B]0;owned\\x07' is not a number");
  EXPECT_EQ(errorOf("t_s,SOC\n", {"soc"}), "log.csv has no column 'soc'; columns: t_s, SOC");
  EXPECT_EQ(errorOf("soc,\"mode\n", {"soc"}), "log.csv line 1: a quoted field is not closed");
  EXPECT_EQ(errorOf("soc,soc\n", {"soc"}), "log.csv line 1: column 'soc' appears twice in the header");
  EXPECT_EQ(errorOf("", {"soc"}), "log.csv is empty; expected a header row of column names");
  EXPECT_NE(errorOf("\x7f"
                    "ELF\x02\x01,x\n",
                    {"soc"})
                .find("header holds control characters"),
            std::string::npos);
}

TEST(CsvColumns, ReadsAnEmptyFieldOrNoneAsInfinityOnlyWhereAsked) {
  std::istringstream input("gap_m,current_a\nnone,9.5\n,9.4\n0.05,8\n");
  const CsvColumns table = CsvColumns::parse(input, "log.csv", {"current_a"}, {"gap_m"}, {"gap_m"});
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(table.column("gap_m"), (std::vector<double>{inf, inf, 0.05}));
  EXPECT_EQ(errorOf("gap_m,current_a\nnone,9.5\n", {"gap_m"}),
            "log.csv line 2, column 'gap_m': 'none' is not a number");
  std::istringstream elsewhere("gap_m,current_a\n0.05,\n");
  EXPECT_THROW(CsvColumns::parse(elsewhere, "log.csv", {"current_a"}, {"gap_m"}, {"gap_m"}), ceilplan::InputError);
}

TEST(TemporaryOutput, AppearsOnlyWhenCommittedAndIsRemovedOtherwise) {
  const auto dir = std::filesystem::path(CEILPLAN_TEST_TMP) / "temporary_output";
  std::filesystem::remove_all(dir);
  const auto final_path = dir / "sub" / "cycles.json";
  {
    TemporaryOutput output(final_path);
    // In a staging directory beside the final path: the rename stays on one disk.
    EXPECT_EQ(output.path().parent_path().parent_path(), final_path.parent_path());
    EXPECT_EQ(output.path().filename(), final_path.filename());
    std::ofstream(output.path()) << "{}";
    EXPECT_FALSE(std::filesystem::exists(final_path));
    output.commit();
  }
  EXPECT_TRUE(std::filesystem::exists(final_path));
  std::filesystem::remove(final_path);
  try {
    TemporaryOutput output(final_path);
    std::ofstream(output.path()) << "{";
    throw std::runtime_error("the work failed half way");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(std::filesystem::is_empty(final_path.parent_path())) << "temporary left behind";
}

}  // namespace
}  // namespace ceilplan::io
