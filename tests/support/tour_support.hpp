#pragma once
// Whether a tour stays within what its map's data support, checked from the tour's own output
// files against the OctoMap read directly (octomap::OcTree::search and castRay), independent of
// ceilplan's planner and its voxel index: every flown point and viewpoint in known free space, and
// every photo's and inspection's line of sight clear of occupied and unknown space up to the
// surface it looks at (issue 24, "The map knows where its data ends").

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>
#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace ceilplan::testing {

// "occupied", "free" or "unknown" at a point of the map.
inline std::string stateAt(const octomap::OcTree& tree, const Eigen::Vector3d& point) {
  const octomap::OcTreeNode* node = tree.search(point.x(), point.y(), point.z());
  if (!node) return "unknown";
  return tree.isNodeOccupied(node) ? "occupied" : "free";
}

// The rows of a CSV output whose first line is its provenance comment, as named fields.
inline std::vector<std::map<std::string, std::string>> readOutputCsv(const std::filesystem::path& file) {
  std::istringstream lines(readWholeFile(file));
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("# ceilplan ", 0), 0u) << file << ": " << line;
  std::getline(lines, line);
  std::vector<std::string> header;
  std::istringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::map<std::string, std::string>& row = rows.emplace_back();
    std::string field;
    for (std::size_t c = 0; c < header.size() && std::getline(fields, field, ','); ++c) row[header[c]] = field;
  }
  return rows;
}

inline Eigen::Vector3d pointOf(const std::map<std::string, std::string>& row) {
  return {std::stod(row.at("x")), std::stod(row.at("y")), std::stod(row.at("z"))};
}

inline Eigen::Vector3d pointOf(const nlohmann::json& triple) {
  return {triple.at(0).get<double>(), triple.at(1).get<double>(), triple.at(2).get<double>()};
}

// The camera's optical axis (docs/coverage.md, photos.csv): yaw clockwise from north (+y),
// gimbal pitch up from level.
inline Eigen::Vector3d opticalAxis(double yaw_deg, double gimbal_pitch_deg) {
  const double degree = std::acos(-1.0) / 180.0;
  const double yaw = yaw_deg * degree, pitch = gimbal_pitch_deg * degree;
  return {std::cos(pitch) * std::sin(yaw), std::cos(pitch) * std::cos(yaw), std::sin(pitch)};
}

// What one mode's tour directory was checked for, to assert the checks saw something.
struct SupportFigures {
  std::size_t route_points = 0;  // resampled along path.csv
  std::size_t viewpoints = 0;
  std::size_t photos = 0;
  std::size_t sight_lines = 0;  // viewpoint to point target
};

// Checks one mode's tour directory (tour.json, path.csv, photos.csv when it covers surfaces)
// against `tree`: the route between consecutive samples of each sortie, every `step_voxels` of a
// voxel, and every viewpoint lie in known free space (unknown too, only under the `free` policy);
// each photo's optical axis meets an occupied voxel through known free voxels only, within twice
// the photo's distance to what it covers plus a voxel; each point target is seen from its
// viewpoint through known free space up to half a voxel from the point (it lies on a face).
inline SupportFigures expectTourWithinItsData(const std::filesystem::path& mode_dir, const octomap::OcTree& tree,
                                              double step_voxels = 0.25) {
  SCOPED_TRACE(mode_dir.string());
  SupportFigures figures;
  const auto tour = nlohmann::json::parse(readWholeFile(mode_dir / "tour.json"));
  const bool unknown_is_free = tour["unknown_space"]["policy"] == "free";
  const double resolution_m = tree.getResolution();
  const auto supported = [&](const Eigen::Vector3d& at) {
    const std::string state = stateAt(tree, at);
    return state == "free" || (unknown_is_free && state == "unknown");
  };

  const auto samples = readOutputCsv(mode_dir / "path.csv");
  for (std::size_t s = 0; s < samples.size(); ++s) {
    if (samples[s].at("phase") == "recharge") continue;
    const Eigen::Vector3d from = pointOf(samples[s]);
    Eigen::Vector3d to = from;
    if (s + 1 < samples.size() && samples[s + 1].at("phase") != "recharge" &&
        samples[s + 1].at("sortie") == samples[s].at("sortie"))
      to = pointOf(samples[s + 1]);
    const double length_m = (to - from).norm();
    const int steps = std::max(1, static_cast<int>(std::ceil(length_m / (step_voxels * resolution_m))));
    for (int k = 0; k < steps; ++k) {
      const Eigen::Vector3d at = from + (to - from) * (static_cast<double>(k) / steps);
      ++figures.route_points;
      if (supported(at)) continue;
      ADD_FAILURE() << "route point at " << at.transpose() << " (path.csv row " << s + 1 << ") is "
                    << stateAt(tree, at);
      return figures;  // the first is enough: a route leaving its data leaves it for many points
    }
  }

  for (const auto& target : tour["targets"]) {
    if (target["viewpoint"].is_null()) continue;
    const Eigen::Vector3d viewpoint = pointOf(target["viewpoint"]);
    ++figures.viewpoints;
    EXPECT_TRUE(supported(viewpoint)) << target["name"] << " viewpoint at " << viewpoint.transpose() << " is "
                                      << stateAt(tree, viewpoint);
    if (target["name"].get<std::string>().find("_photo") != std::string::npos) continue;  // photos: below
    const Eigen::Vector3d point = pointOf(target["point"]);
    const double distance_m = (point - viewpoint).norm();
    ++figures.sight_lines;
    for (double s = 0; s < distance_m - resolution_m / 2; s += step_voxels * resolution_m) {
      const Eigen::Vector3d at = viewpoint + (point - viewpoint) * (s / distance_m);
      EXPECT_EQ(stateAt(tree, at), "free") << target["name"] << " sight line at " << at.transpose();
    }
  }

  if (!std::filesystem::exists(mode_dir / "photos.csv")) return figures;
  for (const auto& photo : readOutputCsv(mode_dir / "photos.csv")) {
    const Eigen::Vector3d camera = pointOf(photo);
    const Eigen::Vector3d axis = opticalAxis(std::stod(photo.at("yaw_deg")), std::stod(photo.at("gimbal_pitch_deg")));
    const double reach_m = 2.0 * std::stod(photo.at("distance_m")) + resolution_m;
    ++figures.photos;
    EXPECT_TRUE(supported(camera)) << "photo " << photo.at("index") << " camera at " << camera.transpose();
    // With unknown cells not ignored, castRay stops at the first unknown one and says false.
    octomap::point3d hit;
    const bool hit_occupied = tree.castRay(octomap::point3d(camera.x(), camera.y(), camera.z()),
                                           octomap::point3d(axis.x(), axis.y(), axis.z()), hit,
                                           /*ignoreUnknownCells=*/unknown_is_free, reach_m);
    EXPECT_TRUE(hit_occupied) << "photo " << photo.at("index") << " (" << photo.at("region") << ") from "
                              << camera.transpose() << " along " << axis.transpose() << " meets "
                              << (tree.search(hit) ? "nothing" : "unknown space") << " at " << hit
                              << " before a surface within " << reach_m << " m";
  }
  return figures;
}

}  // namespace ceilplan::testing
