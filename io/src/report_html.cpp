#include "ceilplan/io/report_html.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/json_values.hpp"
#include "json_number.hpp"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <unordered_map>
#include <utility>

namespace ceilplan::io {

// The page parts compiled in by io/CMakeLists.txt (io/report/embed_text.cmake).
namespace report_assets {
extern const std::string_view Three;
extern const std::string_view OrbitControls;
extern const std::string_view PageTemplate;
extern const std::string_view ViewerScript;
}  // namespace report_assets

namespace {

// Millimetres are plenty for a view; shorter numbers keep the file small. Dividing by the
// count per unit gives the double nearest the decimal, so it prints short.
double rounded(double value, double per_unit = 1e3) { return std::round(value * per_unit) / per_unit; }

nlohmann::json point(const Eigen::Vector3d& p) { return {rounded(p.x()), rounded(p.y()), rounded(p.z())}; }

void requireFinite(const Eigen::Vector3d& p, const std::string& what) {
  if (!p.allFinite()) throw InputError("report: " + what + " must be finite, got " + formatPoint(p));
}

// A JSON array of `count` numbers, `value(k)` each, appended as jsonText writes it: a long
// tour's samples run to millions of numbers, which are not made a document first.
template <class Value>
void appendNumbers(std::string& text, std::size_t count, Value&& value) {
  text += '[';
  for (std::size_t k = 0; k < count; ++k) {
    if (k) text += ',';
    appendJsonNumber(text, value(k));
  }
  text += ']';
}

// The text of the samples' object: one array per figure, as jsonText writes its keys (in order).
void appendSamples(std::string& text, const std::vector<ReportSample>& samples) {
  const std::size_t n = samples.size();
  text += "{\"current\":";
  appendNumbers(text, n, [&](std::size_t k) { return rounded(samples[k].current_a); });
  text += ",\"soc\":";
  appendNumbers(text, n, [&](std::size_t k) { return rounded(samples[k].soc, 1e5); });
  text += ",\"sortie\":";
  appendNumbers(text, n, [&](std::size_t k) { return static_cast<long>(samples[k].sortie); });
  text += ",\"t\":";
  appendNumbers(text, n, [&](std::size_t k) { return rounded(samples[k].t_s); });
  for (int axis = 0; axis < 3; ++axis) {
    text += axis == 0 ? ",\"x\":" : axis == 1 ? ",\"y\":" : ",\"z\":";
    appendNumbers(text, n, [&](std::size_t k) { return rounded(samples[k].position_m[axis]); });
  }
  text += '}';
}

// The text of one plan's object, its keys in jsonText's order. The objects are filled by moving
// their parts in: a braced list copies each part.
void appendPlan(std::string& text, const ReportPlan& plan) {
  nlohmann::json::array_t targets, photos, patches, summary;
  targets.reserve(plan.targets.size());
  for (const ReportTarget& t : plan.targets)
    targets.push_back({{"name", t.name},
                       {"point", point(t.point_m)},
                       {"viewpoint", t.viewpoint_m ? point(*t.viewpoint_m) : nlohmann::json(nullptr)}});
  photos.reserve(plan.photos.size());
  for (const ReportPhoto& p : plan.photos)
    photos.push_back({{"p", point(p.position_m)},
                      {"yaw_deg", rounded(p.yaw_deg, 100)},
                      {"pitch_deg", rounded(p.gimbal_pitch_deg, 100)},
                      {"hfov_deg", p.horizontal_fov_deg},
                      {"vfov_deg", p.vertical_fov_deg},
                      {"range_m", p.range_m}});
  patches.reserve(plan.coverage.size());
  for (const ReportSurfacePatch& p : plan.coverage)
    patches.push_back({{"c", point(p.centre_m)},
                       {"n", {rounded(p.normal.x()), rounded(p.normal.y()), rounded(p.normal.z())}},
                       {"s", p.size_m},
                       {"v", std::isnan(p.value) ? nlohmann::json(nullptr) : nlohmann::json(p.value)}});
  for (const auto& [figure, value] : plan.summary) summary.push_back({figure, value});
  nlohmann::json coverage = nlohmann::json::object();
  coverage["label"] = plan.coverage_label;
  coverage["patches"] = std::move(patches);
  text += "{\"coverage\":" + jsonText(coverage);
  text += ",\"name\":" + jsonText(nlohmann::json(plan.name));
  text += ",\"photos\":" + jsonText(nlohmann::json(std::move(photos)));
  text += ",\"samples\":";
  appendSamples(text, plan.samples);
  text += ",\"summary\":" + jsonText(nlohmann::json(std::move(summary)));
  text += ",\"targets\":" + jsonText(nlohmann::json(std::move(targets))) + "}";
}

// The structure's object: voxel centres as integer steps from the lowest corner, each followed
// by its face bits (a third of the text of coordinates).
void appendStructure(std::string& text, const ReportStructure& structure) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(0.0);
  if (!structure.centres_m.empty()) {
    low = structure.centres_m.front();
    for (const Eigen::Vector3d& c : structure.centres_m) low = low.cwiseMin(c);
  }
  text += "{\"cells\":";
  appendNumbers(text, 4 * structure.centres_m.size(), [&](std::size_t k) -> long {
    const std::size_t v = k / 4;
    const int axis = static_cast<int>(k % 4);
    if (axis == 3) return structure.faces.empty() ? 63 : structure.faces[v];
    return std::lround((structure.centres_m[v][axis] - low[axis]) / structure.voxel_m);
  });
  text += ",\"origin\":" + jsonText(point(low));
  text += ",\"voxel_m\":" + jsonText(nlohmann::json(structure.voxel_m)) + "}";
}

// JSON inside a <script> element: "</" must not appear.
std::string scriptSafe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

// The page's data, script-safe: jsonText of the document {comparison, home, plans, reserve_soc,
// structure, title}, written part by part, its large arrays straight into the text.
std::string pageData(const ReportModel& model) {
  model.validate();
  nlohmann::json comparison = nlohmann::json::object();
  comparison["header"] = model.comparison_header;
  comparison["rows"] = model.comparison_rows;
  std::string text = "{\"comparison\":" + jsonText(comparison);
  text += ",\"home\":" + jsonText(point(model.home_m));
  text += ",\"plans\":[";
  for (std::size_t p = 0; p < model.plans.size(); ++p) {
    if (p) text += ',';
    appendPlan(text, model.plans[p]);
  }
  text += "],\"reserve_soc\":" + jsonText(nlohmann::json(model.reserve_soc));
  text += ",\"structure\":";
  appendStructure(text, model.structure);
  text += ",\"title\":" + jsonText(nlohmann::json(model.title)) + "}";
  return scriptSafe(std::move(text));
}

// The page in order, part by part: the template up to each placeholder, then what replaces it
// (the placeholders stand in the template in this order). Written out as it goes, a long tour's
// page is never held whole beside its data.
template <typename Emit>
void emitPage(std::string_view data, Emit&& emit) {
  const std::string_view page = report_assets::PageTemplate;
  const std::pair<std::string_view, std::string_view> parts[] = {{"/*CEILPLAN:THREE*/", report_assets::Three},
                                                                 {"/*CEILPLAN:ORBIT*/", report_assets::OrbitControls},
                                                                 {"/*CEILPLAN:DATA*/", data},
                                                                 {"/*CEILPLAN:APP*/", report_assets::ViewerScript}};
  std::size_t from = 0;
  for (const auto& [placeholder, value] : parts) {
    const std::size_t at = page.find(placeholder, from);
    if (at == std::string_view::npos)
      throw Error("report template lacks " + std::string(placeholder) + " in its place");
    emit(page.substr(from, at - from));
    emit(value);
    from = at + placeholder.size();
  }
  emit(page.substr(from));
}

}  // namespace

void ReportModel::validate() const {
  if (plans.empty()) throw InputError("report: no plan to show");
  requireFinite(home_m, "home");
  if (!(reserve_soc >= 0.0 && reserve_soc <= 1.0))
    throw InputError("report: reserve SOC must lie in [0, 1], got " + formatNumber(reserve_soc));
  if (!(structure.voxel_m > 0.0) || !std::isfinite(structure.voxel_m))
    throw InputError("report: structure voxel size must be positive, got " + formatNumber(structure.voxel_m));
  for (const Eigen::Vector3d& c : structure.centres_m) requireFinite(c, "structure voxel");
  if (!structure.faces.empty() && structure.faces.size() != structure.centres_m.size())
    throw InputError("report: structure has " + std::to_string(structure.faces.size()) + " face masks for " +
                     std::to_string(structure.centres_m.size()) + " voxels");
  for (const ReportPlan& plan : plans) {
    const std::string what = "plan '" + plan.name + "'";
    if (plan.samples.empty()) throw InputError("report: " + what + " has no samples");
    for (std::size_t k = 0; k < plan.samples.size(); ++k) {
      const ReportSample& s = plan.samples[k];
      const std::string where = what + " sample " + std::to_string(k + 1);
      requireFinite(s.position_m, where + " position");
      if (!std::isfinite(s.t_s) || !std::isfinite(s.current_a))
        throw InputError("report: " + where + " has a non-finite time or current");
      if (!(s.soc >= 0.0 && s.soc <= 1.0))
        throw InputError("report: " + where + " SOC must lie in [0, 1], got " + formatNumber(s.soc));
      if (k > 0 && s.t_s < plan.samples[k - 1].t_s) throw InputError("report: " + where + ": time goes backwards");
    }
    for (const ReportTarget& t : plan.targets) {
      requireFinite(t.point_m, what + " target " + t.name);
      if (t.viewpoint_m) requireFinite(*t.viewpoint_m, what + " viewpoint of " + t.name);
    }
    for (const ReportPhoto& p : plan.photos) {
      requireFinite(p.position_m, what + " photo");
      if (!(p.range_m > 0.0) || !(p.horizontal_fov_deg > 0.0 && p.horizontal_fov_deg < 180.0) ||
          !(p.vertical_fov_deg > 0.0 && p.vertical_fov_deg < 180.0) || !std::isfinite(p.yaw_deg) ||
          !std::isfinite(p.gimbal_pitch_deg))
        throw InputError("report: " + what + " has a photo with a bad angle, field of view or range");
    }
    for (const ReportSurfacePatch& p : plan.coverage) {
      requireFinite(p.centre_m, what + " coverage patch");
      if (!(p.normal.norm() > 0.0) || !(p.size_m > 0.0))
        throw InputError("report: " + what + " has a coverage patch without a normal or size");
    }
  }
  for (const auto& row : comparison_rows)
    if (!comparison_header.empty() && row.size() != comparison_header.size())
      throw InputError("report: a comparison row has " + std::to_string(row.size()) + " cells, the header " +
                       std::to_string(comparison_header.size()));
}

ReportStructure structureNear(const environment::VoxelGrid& grid, const std::vector<Eigen::Vector3d>& route_m,
                              double radius_m, std::size_t max_voxels) {
  if (!(radius_m >= 0.0) || !std::isfinite(radius_m))
    throw InputError("report: structure radius must be finite and non-negative, got " + formatNumber(radius_m));
  const environment::GridFrame& frame = grid.frame();
  const double r = frame.resolution_m();
  // Probes along the route, half a metre apart.
  constexpr double kProbeSpacing_m = 0.5;
  std::vector<Eigen::Vector3d> probes;
  double route_length_m = 0.0;
  for (std::size_t k = 1; k < route_m.size(); ++k) route_length_m += (route_m[k] - route_m[k - 1]).norm();
  if (std::isfinite(route_length_m))
    probes.reserve(route_m.size() + static_cast<std::size_t>(route_length_m / kProbeSpacing_m));
  for (std::size_t k = 0; k < route_m.size(); ++k) {
    requireFinite(route_m[k], "route point");
    if (probes.empty()) {
      probes.push_back(route_m[k]);
      continue;
    }
    const Eigen::Vector3d d = route_m[k] - probes.back();
    const int steps = static_cast<int>(std::floor(d.norm() / kProbeSpacing_m));
    const Eigen::Vector3d from = probes.back();
    for (int s = 1; s <= steps; ++s) probes.push_back(from + d * (s * kProbeSpacing_m / d.norm()));
  }
  if (route_m.size() > 1 && (route_m.back() - probes.back()).norm() > 0.0) probes.push_back(route_m.back());
  const auto isFree = [&](int i, int j, int k) { return grid.at(i, j, k) == environment::CellState::Free; };
  const int reach = static_cast<int>(std::ceil(radius_m / r));
  // Whether probe p's sphere takes voxel (i, j, k): its row within reach, its centre within the
  // row's run of centres inside the sphere.
  const auto takes = [&](const Eigen::Vector3d& p, int i, int j, int k) {
    if (std::abs(j - frame.indexOf(1, p.y())) > reach || std::abs(k - frame.indexOf(2, p.z())) > reach) return false;
    const double dz = frame.centreOf(2, k) - p.z(), dy = frame.centreOf(1, j) - p.y();
    const double rest = radius_m * radius_m - dz * dz - dy * dy;
    if (rest < 0.0) return false;
    const double half = std::sqrt(rest);
    return i >= frame.indexOf(0, p.x() - half) && i <= frame.indexOf(0, p.x() + half) &&
           std::abs(frame.centreOf(0, i) - p.x()) <= half;
  };
  // A probe farther than this (squared) from a voxel's centre cannot take it: `takes` is the
  // sphere's test, computed otherwise, and the margin is far above its rounding. Most probes in
  // the buckets around a voxel are (often a whole bucket's, from its probes' box), and this is
  // cheaper than `takes`.
  const double beyond_m2 = radius_m * radius_m * (1.0 + 1e-6) + 1e-9;
  // Each voxel is visited once, not once per probe whose sphere holds it (spheres half a metre
  // apart overlap a dozen times over): the probes are bucketed in cubes at least the radius
  // wide, so every probe that may take a voxel lies in the 27 cubes around the voxel's.
  const double bucket_m = radius_m + r;
  const auto bucketOf = [&](const Eigen::Vector3d& p) {
    return std::array<long, 3>{std::lround(std::floor(p.x() / bucket_m)), std::lround(std::floor(p.y() / bucket_m)),
                               std::lround(std::floor(p.z() / bucket_m))};
  };
  // The buckets in a dense box of them: a voxel's 27 neighbours are looked up for every surface
  // voxel near the route, millions on a large structure.
  std::array<long, 3> first_bucket{}, bucket_count{};
  for (int axis = 0; axis < 3 && !probes.empty(); ++axis) {
    long first = std::numeric_limits<long>::max(), last = std::numeric_limits<long>::min();
    for (const Eigen::Vector3d& p : probes) {
      first = std::min(first, bucketOf(p)[axis]);
      last = std::max(last, bucketOf(p)[axis]);
    }
    first_bucket[axis] = first;
    bucket_count[axis] = last - first + 1;
  }
  // A bucket's place in `buckets`, -1 outside the box.
  const auto bucketIndex = [&](long x, long y, long z) -> long {
    x -= first_bucket[0], y -= first_bucket[1], z -= first_bucket[2];
    if (x < 0 || y < 0 || z < 0 || x >= bucket_count[0] || y >= bucket_count[1] || z >= bucket_count[2]) return -1;
    return (z * bucket_count[1] + y) * bucket_count[0] + x;
  };
  std::vector<std::vector<Eigen::Vector3d>> buckets(
      static_cast<std::size_t>(bucket_count[0] * bucket_count[1] * bucket_count[2]));
  std::vector<Eigen::AlignedBox3d> bucket_boxes(buckets.size());  // around each bucket's probes
  constexpr int kMost = std::numeric_limits<int>::max(), kLeast = std::numeric_limits<int>::min();
  environment::Index3 low{kMost, kMost, kMost}, high{kLeast, kLeast, kLeast};
  for (const Eigen::Vector3d& p : probes) {
    const std::array<long, 3> bucket = bucketOf(p);
    const auto at = static_cast<std::size_t>(bucketIndex(bucket[0], bucket[1], bucket[2]));
    buckets[at].push_back(p);
    bucket_boxes[at].extend(p);
    for (int axis = 0; axis < 3; ++axis) {
      low[axis] = std::min(low[axis], frame.indexOf(axis, p[axis]) - reach - 1);
      high[axis] = std::max(high[axis], frame.indexOf(axis, p[axis]) + reach + 1);
    }
  }
  const environment::Index3& size = frame.size();
  // Voxel -> faces towards free space, in linear order (each voxel is visited once, in order).
  std::vector<std::pair<std::size_t, std::uint8_t>> voxels;
  voxels.reserve(std::min<std::size_t>(max_voxels, std::size_t{1} << 20));  // most routes take fewer
  for (int k = std::max(0, low[2]); k <= std::min(size[2] - 1, high[2]); ++k)
    for (int j = std::max(0, low[1]); j <= std::min(size[1] - 1, high[1]); ++j) {
      // The box is inside the grid: its rows are read by linear index, without a bounds check
      // each (the route's box spans a large structure's millions of voxels).
      const std::size_t row = frame.linear(0, j, k);
      for (int i = std::max(0, low[0]); i <= std::min(size[0] - 1, high[0]); ++i) {
        if (grid.atLinear(row + i) != environment::CellState::Occupied) continue;
        const std::uint8_t faces =
            static_cast<std::uint8_t>(isFree(i - 1, j, k) | isFree(i + 1, j, k) << 1 | isFree(i, j - 1, k) << 2 |
                                      isFree(i, j + 1, k) << 3 | isFree(i, j, k - 1) << 4 | isFree(i, j, k + 1) << 5);
        if (!faces) continue;
        const Eigen::Vector3d centre_m(frame.centreOf(0, i), frame.centreOf(1, j), frame.centreOf(2, k));
        const std::array<long, 3> centre = bucketOf(centre_m);
        bool taken = false;
        for (long dx = -1; dx <= 1 && !taken; ++dx)
          for (long dy = -1; dy <= 1 && !taken; ++dy)
            for (long dz = -1; dz <= 1 && !taken; ++dz) {
              const long bucket = bucketIndex(centre[0] + dx, centre[1] + dy, centre[2] + dz);
              if (bucket < 0 ||
                  bucket_boxes[static_cast<std::size_t>(bucket)].squaredExteriorDistance(centre_m) > beyond_m2)
                continue;
              for (const Eigen::Vector3d& p : buckets[static_cast<std::size_t>(bucket)])
                if ((centre_m - p).squaredNorm() <= beyond_m2 && takes(p, i, j, k)) {
                  taken = true;
                  break;
                }
            }
        if (taken) voxels.emplace_back(frame.linear(i, j, k), faces);
      }
    }
  // Coarsen until it fits: a coarse cell holds any chosen voxel and draws any face they show.
  for (int factor = 1;; ++factor) {
    if (factor == 1 && voxels.size() > max_voxels) continue;  // uncoarsened, each voxel is its own cell
    std::vector<environment::Index3> cells;
    std::vector<std::uint8_t> faces;
    std::unordered_map<std::size_t, std::size_t> cell_of;
    if (factor == 1) {
      cells.reserve(voxels.size());
      faces.reserve(voxels.size());
    }
    for (const auto& [voxel, voxel_faces] : voxels) {
      const environment::Index3 index = frame.unlinear(voxel);
      if (factor == 1) {  // each voxel is its own cell, visited once
        cells.push_back(index);
        faces.push_back(voxel_faces);
        continue;
      }
      const environment::Index3 cell{index[0] / factor, index[1] / factor, index[2] / factor};
      const auto [at, inserted] = cell_of.emplace(frame.linear(cell[0], cell[1], cell[2]), cells.size());
      if (inserted) {
        cells.push_back(cell);
        faces.push_back(0);
      }
      faces[at->second] |= voxel_faces;
    }
    if (cells.size() <= max_voxels || factor > 16) {
      ReportStructure structure;
      structure.voxel_m = r * factor;
      structure.faces = std::move(faces);
      structure.centres_m.reserve(cells.size());
      for (const environment::Index3& cell : cells) {
        Eigen::Vector3d centre;
        for (int axis = 0; axis < 3; ++axis) centre[axis] = frame.faceOf(axis, cell[axis] * factor) + 0.5 * r * factor;
        structure.centres_m.push_back(centre);
      }
      return structure;
    }
  }
}

std::string reportHtml(const ReportModel& model) {
  const std::string data = pageData(model);
  std::string page;
  emitPage(data, [&](std::string_view part) { page.append(part); });
  return page;
}

void writeReportHtml(const std::filesystem::path& file, const ReportModel& model) {
  const std::string data = pageData(model);
  writeTextAtomically(file, [&](std::ostream& out) {
    emitPage(data, [&](std::string_view part) { out.write(part.data(), static_cast<std::streamsize>(part.size())); });
  });
}

}  // namespace ceilplan::io
