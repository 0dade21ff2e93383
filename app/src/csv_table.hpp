#pragma once
// The numeric CSV reader lives in io/ (ceilplan/io/csv_table.hpp); commands name it as before.

#include "ceilplan/io/csv_table.hpp"

namespace ceilplan::app {
using io::CsvTable;
}  // namespace ceilplan::app
