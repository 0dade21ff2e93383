#include "ceilplan/io/path_csv.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/csv_table.hpp"

#include <array>
#include <string>

namespace ceilplan::io {

std::vector<Eigen::Vector3d> readPathCsv(const std::filesystem::path& file) {
  const CsvTable table = CsvTable::read(file);
  std::array<std::string, 3> names{"x_m", "y_m", "z_m"};
  if (!table.hasColumn("x_m")) names = {"x", "y", "z"};
  if (!table.hasColumn(names[0]) && table.hasColumn("north_m"))
    throw InputError(file.string() +
                     " is in the NED frame (north_m, east_m, down_m); a path is read in the map frame: "
                     "write the trajectory in ENU (x_m, y_m, z_m)");
  if (!table.hasColumn(names[0]))
    throw InputError(file.string() + " has neither x, y, z (path.csv) nor x_m, y_m, z_m (trajectory.csv) columns");
  const std::vector<double>&x = table.column(names[0]), &y = table.column(names[1]), &z = table.column(names[2]);
  std::vector<Eigen::Vector3d> points;
  for (std::size_t row = 0; row < table.rowCount(); ++row) {
    const Eigen::Vector3d p(x[row], y[row], z[row]);
    if (points.empty() || (p - points.back()).norm() > 1e-9) points.push_back(p);
  }
  if (points.size() < 2) throw InputError(file.string() + ": a path needs at least 2 distinct points");
  return points;
}

}  // namespace ceilplan::io
