#pragma once
/// @file
/// report.html: one self-contained file that opens offline in any browser with WebGL and shows a
/// plan in 3D (docs/report.md): the structure near the route (occupied voxels, instanced, shaded
/// by height), each route coloured by current with its sorties and the home point, targets and
/// viewpoints, photo frusta and coverage colouring when given, a state-of-charge chart linked to
/// the 3D view, a toggle between plans (ceiling and free mode) and the comparison table. Orbit,
/// pan and zoom with the mouse. three.js r111 (Debian's libjs-three) is embedded at build time.

#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ceilplan::io {

/// One flown sample (the flight record): time from the first take-off, recharges included.
struct ReportSample {
  double t_s = 0.0;  ///< from the first take-off
  /// map frame
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double current_a = 0.0;  ///< pack current
  double soc = 0.0;        ///< fraction
  int sortie = 1;          ///< 1-based
};

/// A target drawn in the report.
struct ReportTarget {
  std::string name;  ///< its name
  /// the point inspected
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> viewpoint_m;  ///< where the vehicle hovers to inspect it
};

/// A photo's field of view, drawn as a pyramid from the camera.
struct ReportPhoto {
  /// the camera, map frame
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double yaw_deg = 0.0;              ///< heading, clockwise from north
  double gimbal_pitch_deg = 0.0;     ///< +90 up
  double horizontal_fov_deg = 60.0;  ///< across the image width
  double vertical_fov_deg = 45.0;    ///< across the image height
  double range_m = 1.0;              ///< how far the pyramid reaches (e.g. the distance to the surface)
};

/// A square of inspected surface, coloured by `value` (e.g. the GSD reached); NaN: not covered
/// (drawn red).
struct ReportSurfacePatch {
  /// centre of the square
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  /// unit, out of the surface
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double size_m = 0.1;  ///< edge length of the square
  double value = 0.0;   ///< the colour's value; NaN: not covered
};

/// One plan (a mode): what the toggle switches between.
struct ReportPlan {
  std::string name;                                          ///< "ceiling", "free", ...
  std::vector<ReportSample> samples;                         ///< the flown samples
  std::vector<ReportTarget> targets;                         ///< the targets
  std::vector<ReportPhoto> photos;                           ///< the photos' fields of view
  std::vector<ReportSurfacePatch> coverage;                  ///< the surface patches
  std::string coverage_label = "GSD [mm/px]";                ///< what the patches' value is
  std::vector<std::pair<std::string, std::string>> summary;  ///< figure, value
};

/// Structure near the routes: voxel centres on a regular grid of `voxel_m`, each with the faces
/// to draw (bits 0-5: -x, +x, -y, +y, -z, +z; only faces towards free space are ever seen).
struct ReportStructure {
  double voxel_m = 0.1;                    ///< voxel size
  std::vector<Eigen::Vector3d> centres_m;  ///< voxel centres
  std::vector<std::uint8_t> faces;         ///< parallel to centres_m; empty: all six
};

/// Everything report.html shows (docs/report.md): the structure, one or more plans and their comparison.
struct ReportModel {
  std::string title = "ceilplan";  ///< the page's title
  /// the take-off point
  Eigen::Vector3d home_m = Eigen::Vector3d::Zero();
  double reserve_soc = 0.0;                               ///< the lowest landing SOC allowed, drawn on the SOC plot
  ReportStructure structure;                              ///< the structure near the routes
  std::vector<ReportPlan> plans;                          ///< at least one
  std::vector<std::string> comparison_header;             ///< the comparison table's header; empty: no table
  std::vector<std::vector<std::string>> comparison_rows;  ///< its rows, as wide as the header

  /// Throws ceilplan::InputError naming what is wrong: no plan, a plan without samples,
  /// non-finite numbers, a SOC outside [0, 1], time going backwards, a row of the wrong width.
  void validate() const;
};

/// The occupied voxels of `grid` within `radius_m` of the route points (checked every half metre
/// along the route) that show a face to free space (what a camera in free space can see), with
/// those faces. More than `max_voxels` and the structure is coarsened (2x2x2 voxels, then 3x3x3,
/// ...) until it fits; a coarse cell draws the faces any of its voxels shows.
ReportStructure structureNear(const environment::VoxelGrid& grid, const std::vector<Eigen::Vector3d>& route_m,
                              double radius_m = 3.0, std::size_t max_voxels = 250000);

/// The whole HTML document.
std::string reportHtml(const ReportModel& model);
/// Written atomically (whole or not at all).
void writeReportHtml(const std::filesystem::path& file, const ReportModel& model);

}  // namespace ceilplan::io
