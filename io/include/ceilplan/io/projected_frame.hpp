#pragma once
/// @file
/// Projected coordinates (UTM, a national grid: any EPSG projected CRS) to ceilplan's local map
/// frame (x east, y north, z up, metres) around a geodetic origin, with PROJ and GeographicLib.

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/geodetic_origin.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace ceilplan::io {

/// The local frame's origin is a mission file's `origin` (mission::GeodeticOrigin); its altitude
/// is in the data's own height system (usually above sea level).
using mission::GeodeticOrigin;

/// A projected CRS (PROJ) and a local ENU frame at an origin in it: how `ceilplan import --crs` moves data into map
/// coordinates.
class ProjectedFrame {
 public:
  /// `crs` is "EPSG:<code>" of a projected CRS (or a compound one with a projected part);
  /// `origin_projected` is the local origin in that CRS's coordinates (easting, northing,
  /// height). Throws ceilplan::InputError for a malformed or unknown code, a CRS that is not
  /// projected, or an origin PROJ cannot transform.
  ProjectedFrame(const std::string& crs, const Eigen::Vector3d& origin_projected);
  ~ProjectedFrame();
  ProjectedFrame(const ProjectedFrame&) = delete;
  ProjectedFrame& operator=(const ProjectedFrame&) = delete;

  /// The checks of the constructor that do not need an origin, so a bad --crs is refused before
  /// any file is read.
  static void validate(const std::string& crs);

  /// A local origin near the data: the centre of their horizontal bounding box rounded to whole
  /// metres, at the lowest height rounded down to a whole metre.
  static Eigen::Vector3d originNear(const std::vector<Eigen::Vector3d>& projected);

  /// "EPSG:<code>".
  const std::string& crs() const { return crs_; }
  /// The CRS's name, as PROJ gives it.
  const std::string& crsName() const { return name_; }
  /// The local origin in the CRS's coordinates.
  const Eigen::Vector3d& originProjected() const { return origin_projected_; }
  /// The local origin, geodetic.
  const GeodeticOrigin& origin() const { return origin_; }

  /// Projected coordinates to the local ENU frame, in place. Throws ceilplan::InputError
  /// naming the first point PROJ cannot transform.
  void toLocal(std::vector<Eigen::Vector3d>& points) const;

 private:
  struct Projection;
  std::string crs_;
  std::string name_;
  Eigen::Vector3d origin_projected_;
  GeodeticOrigin origin_;
  std::unique_ptr<Projection> projection_;
};

}  // namespace ceilplan::io
