#include "ceilplan/io/projected_frame.hpp"

#include "ceilplan/core/format.hpp"

#include <proj.h>
#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>

namespace ceilplan::io {

namespace {

// Owns a PJ for the length of a scope.
struct Object {
  PJ* pj;
  ~Object() {
    if (pj) proj_destroy(pj);
  }
};

}  // namespace

// PROJ objects belong to one context and are not thread-safe: the frame owns its own.
struct ProjectedFrame::Projection {
  // Members own their PROJ objects, so a constructor that throws half-way frees them.
  std::unique_ptr<PJ_CONTEXT, PJ_CONTEXT* (*)(PJ_CONTEXT*)> owned_context{proj_context_create(), proj_context_destroy};
  PJ_CONTEXT* context = owned_context.get();
  std::unique_ptr<PJ, PJ* (*)(PJ*)> to_wgs84{nullptr, proj_destroy};  // (easting, northing) -> (lon, lat) in degrees
  double unit_m = 1.0;  // metres per unit of the CRS's axes (US survey feet exist)
  std::string name;
  GeographicLib::LocalCartesian enu;

  explicit Projection(const std::string& crs) {
    if (!std::regex_match(crs, std::regex("EPSG:[0-9]+")))
      throw ceilplan::InputError("--crs '" + crs + "': expected EPSG:<code>, e.g. EPSG:25832 (ETRS89 / UTM zone 32N)");
    proj_log_level(context, PJ_LOG_NONE);  // errors come back through proj_context_errno
    Object source{proj_create(context, crs.c_str())};
    if (!source.pj)
      throw ceilplan::InputError("unknown coordinate reference system " + crs + ": PROJ's database has no such code");
    Object horizontal{nullptr};
    PJ* projected = source.pj;
    if (proj_get_type(source.pj) == PJ_TYPE_COMPOUND_CRS) {
      horizontal.pj = proj_crs_get_sub_crs(context, source.pj, 0);
      projected = horizontal.pj;
    }
    if (!projected || proj_get_type(projected) != PJ_TYPE_PROJECTED_CRS)
      throw ceilplan::InputError(
          crs + " (" + proj_get_name(source.pj) +
          ") is not a projected coordinate reference system: its coordinates are not metres east and north");
    name = proj_get_name(source.pj);

    Object system{proj_crs_get_coordinate_system(context, projected)};
    if (!system.pj ||
        !proj_cs_get_axis_info(context, system.pj, 0, nullptr, nullptr, nullptr, &unit_m, nullptr, nullptr, nullptr))
      throw ceilplan::InputError(crs + ": PROJ cannot tell its axes' unit (" + lastError() + ")");
    Object wgs84{proj_create(context, "EPSG:4326")};
    Object operation{proj_create_crs_to_crs_from_pj(context, projected, wgs84.pj, nullptr, nullptr)};
    if (!operation.pj) throw ceilplan::InputError(crs + ": PROJ has no transformation to WGS 84 (" + lastError() + ")");
    // Easting first in, longitude first out, whatever axis order the CRS definitions declare.
    to_wgs84.reset(proj_normalize_for_visualization(context, operation.pj));
    if (!to_wgs84) throw ceilplan::InputError(crs + ": PROJ cannot normalise its axis order (" + lastError() + ")");
  }
  Projection(const Projection&) = delete;
  Projection& operator=(const Projection&) = delete;
  std::string lastError() const { return proj_context_errno_string(context, proj_context_errno(context)); }
};

void ProjectedFrame::validate(const std::string& crs) { Projection check(crs); }

ProjectedFrame::ProjectedFrame(const std::string& crs, const Eigen::Vector3d& origin_projected)
    : crs_(crs), origin_projected_(origin_projected), projection_(std::make_unique<Projection>(crs)) {
  if (!origin_projected.allFinite())
    throw ceilplan::InputError("the local origin " + formatPoint(origin_projected) + " is not finite");
  Projection& p = *projection_;
  name_ = p.name;
  PJ_COORD coordinate = proj_coord(origin_projected.x(), origin_projected.y(), 0.0, 0.0);
  const PJ_COORD geodetic = proj_trans(p.to_wgs84.get(), PJ_FWD, coordinate);
  if (!std::isfinite(geodetic.lp.lam) || !std::isfinite(geodetic.lp.phi) || std::abs(geodetic.lp.phi) > 90.0)
    throw ceilplan::InputError("the origin " + formatPoint(origin_projected) + " lies outside where " + crs +
                               " is defined");
  origin_ = GeodeticOrigin{geodetic.lp.phi, geodetic.lp.lam, origin_projected.z() * p.unit_m};
  p.enu.Reset(origin_.latitude_deg, origin_.longitude_deg, origin_.altitude_m);
}

ProjectedFrame::~ProjectedFrame() = default;

Eigen::Vector3d ProjectedFrame::originNear(const std::vector<Eigen::Vector3d>& projected) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& point : projected) {
    lo = lo.cwiseMin(point);
    hi = hi.cwiseMax(point);
  }
  if (projected.empty() || !lo.allFinite() || !hi.allFinite())
    throw ceilplan::InputError("no finite coordinates to place the local origin near");
  return Eigen::Vector3d(std::round(0.5 * (lo.x() + hi.x())), std::round(0.5 * (lo.y() + hi.y())), std::floor(lo.z()));
}

void ProjectedFrame::toLocal(std::vector<Eigen::Vector3d>& points) const {
  const Projection& p = *projection_;
  constexpr std::size_t kBatch = 65536;
  std::vector<double> x(kBatch), y(kBatch);
  for (std::size_t first = 0; first < points.size(); first += kBatch) {
    const std::size_t count = std::min(kBatch, points.size() - first);
    for (std::size_t i = 0; i < count; ++i) {
      x[i] = points[first + i].x();
      y[i] = points[first + i].y();
    }
    proj_trans_generic(p.to_wgs84.get(), PJ_FWD, x.data(), sizeof(double), count, y.data(), sizeof(double), count,
                       nullptr, 0, 0, nullptr, 0, 0);
    for (std::size_t i = 0; i < count; ++i) {
      Eigen::Vector3d& point = points[first + i];
      if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(point.z()))
        throw ceilplan::InputError("point " + std::to_string(first + i) + " " + formatPoint(point) +
                                   " cannot be transformed from " + crs_ + " (outside its area, or not finite)");
      p.enu.Forward(y[i], x[i], point.z() * p.unit_m, point.x(), point.y(), point.z());
    }
  }
}

}  // namespace ceilplan::io
