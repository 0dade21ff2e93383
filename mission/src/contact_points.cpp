#include "ceilplan/mission/contact_points.hpp"

#include <cmath>
#include <map>
#include <tuple>

namespace ceilplan::mission {

std::vector<InspectionTarget> contactTargets(const environment::VoxelGrid& grid, const ContactGrid& contact) {
  contact.validate();
  return contactTargets(
      contact, extractRegionSurface(grid, contact.shape, contact.faces, "contact grid '" + contact.name + "'"));
}

std::vector<InspectionTarget> contactTargets(const ContactGrid& contact, const RegionSurface& surface) {
  contact.validate();
  const double spacing = contact.spacing_m;
  // Per face direction: the extent of the element centres in that face's plane.
  struct Plane {
    int p = 0, q = 0;  // the in-plane axes
    Eigen::Vector2d min = Eigen::Vector2d::Constant(INFINITY), max = Eigen::Vector2d::Constant(-INFINITY);
  };
  std::map<int, Plane> planes;
  for (const auto& element : surface.elements) {
    Plane& plane = planes[element.face];
    plane.p = (element.face / 2 + 1) % 3;
    plane.q = (element.face / 2 + 2) % 3;
    const Eigen::Vector2d at(element.centre_m[plane.p], element.centre_m[plane.q]);
    plane.min = plane.min.cwiseMin(at);
    plane.max = plane.max.cwiseMax(at);
  }
  // Per lattice node, the element nearest it in the plane (the first on ties).
  std::map<std::tuple<int, long, long>, std::pair<double, std::size_t>> nearest;
  for (std::size_t e = 0; e < surface.elements.size(); ++e) {
    const auto& element = surface.elements[e];
    const Plane& plane = planes[element.face];
    const Eigen::Vector2d extent = plane.max - plane.min;
    // Lattice centred on the extent: its first node leaves equal margins at both ends.
    const Eigen::Vector2d first = plane.min + 0.5 * (extent - spacing * (extent / spacing).array().floor().matrix());
    const Eigen::Vector2d at(element.centre_m[plane.p], element.centre_m[plane.q]);
    const long ip = std::lround((at.x() - first.x()) / spacing), iq = std::lround((at.y() - first.y()) / spacing);
    const double offset = (at - first - spacing * Eigen::Vector2d(ip, iq)).norm();
    if (offset > 0.5 * spacing + 1e-9) continue;
    const auto key = std::make_tuple(element.face, iq, ip);
    const auto found = nearest.find(key);
    if (found == nearest.end() || offset < found->second.first) nearest[key] = {offset, e};
  }
  std::vector<InspectionTarget> targets;
  for (const auto& [key, best] : nearest) {
    InspectionTarget target;
    target.name = contact.name + "_" + std::to_string(targets.size() + 1);
    target.point_m = surface.elements[best.second].centre_m;
    target.standoff_min_m = 0.0;
    target.standoff_max_m = contact.reach_m;
    target.dwell_s = contact.dwell_s;
    targets.push_back(target);
  }
  return targets;
}

}  // namespace ceilplan::mission
