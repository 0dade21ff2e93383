#include "ceilplan/io/point_cloud_file.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/csv_columns.hpp"

#include "file_kind.hpp"
#include "open3d_input_checks.hpp"
#include "open3d_log.hpp"
#include "ply_counts.hpp"

#include <open3d/geometry/PointCloud.h>
#include <open3d/io/PointCloudIO.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace ceilplan::io {
namespace {

constexpr std::array<const char*, 6> kCloudExtensions = {".pcd", ".ply", ".xyz", ".xyzn", ".xyzrgb", ".pts"};
constexpr std::array<const char*, 6> kMeshOnlyExtensions = {".stl", ".obj", ".off", ".gltf", ".glb", ".fbx"};

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& problem) {
  throw ceilplan::InputError(printableText(file.string(), 256) + ": " + problem);
}

// A PCD header's count, or -1 when the line does not hold one whole number.
long long countIn(std::istringstream& words) {
  long long count = -1;
  std::string extra;
  if (!(words >> count) || count < 0 || (words >> extra)) return -1;
  return count;
}

// Checks a PCD header before Open3D reads the file. Open3D 0.16 (Debian bookworm) reads binary
// fields of 8-byte floats as zeros, and reads POINTS points whatever WIDTH x HEIGHT say, and an
// ascii file's lines whatever POINTS says: each is refused rather than imported wrong.
void checkPcdHeader(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line, fields, sizes;
  long long width = -1, height = -1, points = -1;
  for (int lines = 0; lines < 64 && std::getline(in, line); ++lines) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "FIELDS") fields = line;
    if (key == "SIZE") sizes = line;
    if (key == "WIDTH") width = countIn(words);
    if (key == "HEIGHT") height = countIn(words);
    if (key == "POINTS") points = countIn(words);
    if (key != "DATA") continue;
    if (width < 0 || height < 0 || points < 0)
      refuse(file, "the PCD header needs WIDTH, HEIGHT and POINTS, each a whole number");
    // Without multiplying, which could overflow.
    if (width == 0 ? points != 0 : points % width != 0 || points / width != height)
      refuse(file, "the PCD header's WIDTH x HEIGHT (" + std::to_string(width) + " x " + std::to_string(height) +
                       ") is not its POINTS (" + std::to_string(points) + "); is the file damaged?");
    std::string storage;
    words >> storage;
    if (storage == "ascii") {
      long long rows = 0;
      while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos) ++rows;
      if (rows != points)
        refuse(file, "the PCD header promises " + std::to_string(points) + " points, the file holds " +
                         std::to_string(rows) + " rows; is the file damaged?");
      return;
    }
    std::istringstream names(fields), bytes(sizes);
    std::string name, size;
    names >> name;  // "FIELDS"
    bytes >> size;  // "SIZE"
    while (names >> name && bytes >> size)
      if ((name == "x" || name == "y" || name == "z") && size == "8")
        refuse(file, storage +
                         " PCD with 8-byte coordinates, which the PCD reader (Open3D 0.16) reads as zeros; save it as "
                         "ascii PCD or as PLY");
    return;
  }
}

// Open3D's .xyz, .xyzn and .xyzrgb readers skip a line that does not start with the format's
// numbers without a word: every line must (what follows them is ignored, as Open3D does).
void checkXyzLines(const std::filesystem::path& file, std::size_t numbers_per_line) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  for (std::size_t line_number = 1; std::getline(in, line); ++line_number) {
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
      throw ceilplan::InputError(printableText(file.string(), 256) + " line " + std::to_string(line_number) + ": '" +
                                 printableText(line, 40) + "' is not " + std::to_string(numbers_per_line) +
                                 " numbers; fix or delete the line");
  }
}

}  // namespace

std::string pointCloudExtensions() { return detail::joined(kCloudExtensions); }

std::vector<Eigen::Vector3d> readPointCloud(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string extension =
      detail::requireReadableFileOfKind(file, kCloudExtensions, kMeshOnlyExtensions, "point cloud", "mesh");

  if (extension == ".pcd") checkPcdHeader(file);
  if (extension == ".xyz") checkXyzLines(file, 3);
  if (extension == ".xyzn" || extension == ".xyzrgb") checkXyzLines(file, 6);
  if (extension == ".ply") detail::checkPlyCounts(file);
  if (extension == ".pcd") detail::checkPcdFile(file);
  if (extension == ".ply") detail::checkPlyFile(file, "point cloud");

  open3d::geometry::PointCloud cloud;
  open3d::io::ReadPointCloudOption option;
  option.remove_nan_points = false;
  option.remove_infinite_points = false;
  if (const auto failure = detail::failureOf([&] { return open3d::io::ReadPointCloud(name, cloud, option); }))
    throw ceilplan::InputError(name + ": not a readable point cloud" + (failure->empty() ? "" : " (Open3D: " + *failure + ")"));
  if (cloud.points_.empty()) throw ceilplan::InputError(name + ": the point cloud has no points");
  return std::move(cloud.points_);
}

environment::SensorOrigins readSensorOrigins(const std::filesystem::path& path, std::size_t point_count) {
  const std::string file = path.string();
  const CsvColumns table = CsvColumns::read(path, {}, {"x", "y", "z", "first_point"});
  for (const char* column : {"x", "y", "z"})
    if (!table.hasColumn(column))
      throw ceilplan::InputError("--origins " + file + ": no column '" + column + "' (expected x,y,z or first_point,x,y,z)");
  const std::size_t rows = table.rowCount();
  if (rows == 0) throw ceilplan::InputError("--origins " + file + ": no origin rows");
  environment::SensorOrigins origins;
  for (std::size_t row = 0; row < rows; ++row)
    origins.origin_m.emplace_back(table.column("x")[row], table.column("y")[row], table.column("z")[row]);
  if (table.hasColumn("first_point")) {
    for (std::size_t row = 0; row < rows; ++row) {
      const double first = table.column("first_point")[row];
      if (!(first >= 0.0) || first != std::floor(first))
        throw ceilplan::InputError("--origins " + file + " line " + std::to_string(table.lineOfRow(row)) +
                                   ": first_point must be a whole number >= 0, got " + formatNumber(first));
      origins.first_point.push_back(static_cast<std::size_t>(first));
    }
  } else if (rows == 1) {
    origins.first_point = {0};
  } else if (rows == point_count) {
    for (std::size_t row = 0; row < rows; ++row) origins.first_point.push_back(row);
  } else {
    throw ceilplan::InputError("--origins " + file + ": " + std::to_string(rows) + " rows of x,y,z for " + std::to_string(point_count) +
                               " points; give one row per point, a single row, or a first_point column for one row per scan");
  }
  try {
    origins.validate(point_count);
  } catch (const ceilplan::InputError& e) {
    throw ceilplan::InputError("--origins " + file + ": " + e.what());
  }
  return origins;
}

}  // namespace ceilplan::io
