// libFuzzer target: any bytes given as a path CSV (`ceilplan evaluate --path`) or to the CSV
// column reader give waypoints or a ceilplan::InputError, never a crash, a hang, a leak or
// another exception. Build and run: scripts/fuzz-path-csv.

#include "fuzz_support.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/io/plan_files.hpp"

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    const ceilplan::io::CsvColumns table =
        ceilplan::io::CsvColumns::parse(in, "fuzz input", {}, {"t_s", "soc", "x", "y", "z"});
    for (const std::string& name : {"t_s", "soc", "x", "y", "z"})
      if (table.hasColumn(name) && table.column(name).size() != table.rowCount()) std::abort();
  } catch (const ceilplan::InputError&) {
  }
  try {
    ceilplan::io::readPathWaypoints(ceilplan::fuzzing::inputFile(data, size, "path.csv"));
  } catch (const ceilplan::InputError&) {
  }
  return 0;
}
