#pragma once
// Reads a path from CSV by column name: the map-frame points of ceilplan's own files
// (path.csv's x, y, z; trajectory.csv's x_m, y_m, z_m) or any CSV with either set of columns,
// other columns ignored.

#include <Eigen/Core>

#include <filesystem>
#include <vector>

namespace ceilplan::io {

// The points in file order, a point repeated on consecutive rows (segment joints, hovering
// setpoints) kept once. Throws ceilplan::InputError naming the file: unreadable or malformed
// CSV (see CsvTable), neither column set (a trajectory written in NED is named as such), fewer
// than 2 distinct points.
std::vector<Eigen::Vector3d> readPathCsv(const std::filesystem::path& file);

}  // namespace ceilplan::io
