#include "ceilplan/io/proposal_files.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/vehicle_file.hpp"
#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace ceilplan::io {
namespace {

namespace fs = std::filesystem;

// `file` as a mission in `mission_dir` names it: relative when both lie in one top-level
// directory (a project moved whole keeps working), else absolute (/usr/share/..., /tmp/...).
std::string pathFrom(const fs::path& mission_dir, const fs::path& file) {
  const fs::path absolute_file = fs::weakly_canonical(file), absolute_dir = fs::weakly_canonical(mission_dir);
  const auto top = [](const fs::path& path) {
    auto part = path.begin();
    return part == path.end() || ++part == path.end() ? fs::path() : *part;  // the component after the root
  };
  if (top(absolute_file) != top(absolute_dir)) return absolute_file.generic_string();
  return absolute_file.lexically_relative(absolute_dir).generic_string();
}

// A YAML double-quoted scalar: the path may hold anything a file name can.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// The title is the only text from outside: escaped, the SVG stays well-formed XML.
std::string xmlText(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

std::string flowPoint(const Eigen::Vector3d& point, int decimals) {
  return "[" + formatFixed(point.x(), decimals) + ", " + formatFixed(point.y(), decimals) + ", " +
         formatFixed(point.z(), decimals) + "]";
}

// The region as a surface, with the settings: what the mission file will hold.
mission::CoverageRegion coverageRegion(const mission::ProposedRegion& region, const ProposalSettings& settings) {
  mission::CoverageRegion surface;
  surface.name = region.name;
  surface.shape = mission::RegionShape::makeBox(region.box_m.min(), region.box_m.max());
  surface.faces.down = true;
  surface.gsd_mm_px = settings.gsd_mm_px;
  surface.overlap_front_pct = settings.overlap_front_pct;
  surface.overlap_side_pct = settings.overlap_side_pct;
  surface.max_incidence_deg = settings.max_incidence_deg;
  return surface;
}

// The mission's camera: the preset on an upward mount, as overhead surfaces need.
constexpr double kUpwardPitchMin_deg = -30.0, kUpwardPitchMax_deg = 90.0;

// A round length near a fifth of `span_m` for the scale bar: 1, 2 or 5 times a power of ten.
double scaleBarLength_m(double span_m) {
  const double target = std::max(span_m / 5.0, 1e-3);
  const double power = std::pow(10.0, std::floor(std::log10(target)));
  for (const double step : {5.0, 2.0, 1.0})
    if (step * power <= target) return step * power;
  return power;
}

}  // namespace

void ProposalSettings::validate() const {
  mission::cameraPreset(camera_preset);  // names the presets when it is none
  mission::ProposedRegion probe;
  probe.name = "proposed";
  probe.box_m = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  coverageRegion(probe, *this).validate();  // the ranges a mission file allows, in one place
}

mission::MissionProposal proposeMissionFiles(ProposalRequest& request, Provenance provenance,
                                             const ProgressCallback& progress) {
  const fs::path& out = request.mission_file;
  if (out.extension() != ".yaml" && out.extension() != ".yml")
    throw InputError(request.mission_flag + " " + printableText(out.string(), 256) +
                     ": the mission file must end in .yaml or .yml");
  if (request.picture_file.empty()) request.picture_file = fs::path(out).replace_extension(".svg");
  if (request.picture_file.extension() != ".svg")
    throw InputError(request.picture_flag + " " + printableText(request.picture_file.string(), 256) +
                     ": the picture must end in .svg");
  std::vector<Input> inputs = request.other_inputs;
  inputs.push_back({"the map", request.settings.map_file});
  inputs.push_back({"the vehicle", request.settings.vehicle_file});
  OutputSet outputs({{request.mission_flag, out}, {request.picture_flag, request.picture_file}}, inputs);
  request.settings.validate();
  // The room a region needs below it comes from the camera the mission will fly.
  const mission::Camera& camera = mission::cameraPreset(request.settings.camera_preset).camera;
  request.options.standoff_m = mission::proposalStandoff_m(camera, request.settings.gsd_mm_px);
  request.options.validate();
  const environment::VehicleGeometry vehicle = readVehicle(request.settings.vehicle_file).geometry;
  const environment::OccupancyMap map = environment::OccupancyMap::load(request.settings.map_file);
  provenance.input("map", request.settings.map_file).input("vehicle", request.settings.vehicle_file);
  environment::MapIndexOptions index_options;
  index_options.unknown = request.settings.unknown;
  const std::string indexing = "indexing " + request.settings.map_file.string();
  const environment::Environment environment(environment::MapIndex::build(map, index_options,
                                                                          [&](double f) {
                                                                            if (progress) progress(indexing, f);
                                                                          }),
                                             vehicle);
  mission::MissionProposal proposal = mission::proposeMission(environment, request.options, progress);
  writeTextAtomically(outputs.path(request.picture_flag), [&](std::ostream& svg) {
    svg << proposalPictureSvg(environment.grid(), proposal, request.settings.map_file.string());
  });
  writeTextAtomically(outputs.path(request.mission_flag), [&](std::ostream& yaml) {
    yaml << proposedMissionYaml(proposal, request.settings, out, provenance);
  });
  outputs.commit();
  return proposal;
}

std::string proposedMissionYaml(const mission::MissionProposal& proposal, const ProposalSettings& settings,
                                const fs::path& mission_file, const Provenance& provenance) {
  settings.validate();
  const fs::path mission_dir = fs::absolute(mission_file).parent_path();
  const planner::FlightSpeeds speeds;  // the defaults, written out to be changed
  std::ostringstream yaml;
  yaml << "# " << printableText(provenance.line(), 4000) << "\n"
       << "# A coverage mission proposed from the map by `ceilplan propose` (docs/import.md): its overhead\n"
       << "# surfaces with known free space below, largest first. Check the regions and the home in the\n"
       << "# picture beside this file; every value here is a default to change (docs/missions.md, docs/coverage.md).\n"
       << "map: " << quoted(pathFrom(mission_dir, settings.map_file)) << "\n"
       << "vehicle: " << quoted(pathFrom(mission_dir, settings.vehicle_file)) << "\n"
       << "battery:   # the default quadrotor's 4S 5.2 Ah pack: give yours\n"
       << "  capacity_ah: 5.2\n  start_soc: 0.95\n  reserve_soc: 0.25\n  charge_current_a: 5.2\n"
       << "home: " << flowPoint(proposal.home_m, 3)
       << (proposal.home_given ? "   # as given\n" : "   # proposed: known free space low above the floor\n")
       << "# No origin: a scan has no geodetic frame. Add `origin: {lat, lon, alt}` for autopilot files.\n"
       << "speeds: {cruise_m_s: " << formatNumber(speeds.cruise_m_s)
       << ", inspection_m_s: " << formatNumber(speeds.inspection_m_s)
       << ", climb_m_s: " << formatNumber(speeds.climb_m_s) << ", descent_m_s: " << formatNumber(speeds.descent_m_s)
       << "}\n"
       << "seed: " << settings.seed << "\n";
  if (settings.unknown.policy != environment::UnknownPolicy::Occupied)
    yaml << "unknown: {policy: " << environment::unknownPolicyName(settings.unknown.policy)
         << (settings.unknown.policy == environment::UnknownPolicy::Fill
                 ? ", fill_max_m: " + formatNumber(settings.unknown.fill_max_m)
                 : std::string())
         << "}   # as the home was checked\n";
  yaml << "camera:\n  preset: " << settings.camera_preset << "\n"
       << "  gimbal_pitch_deg: [" << formatNumber(kUpwardPitchMin_deg) << ", " << formatNumber(kUpwardPitchMax_deg)
       << "]   # an upward gimbal mount: overhead surfaces are photographed looking up\n"
       << "  capture: {style: hover, hover_s: 2.0}\n"
       << "surfaces:\n";
  for (const mission::ProposedRegion& region : proposal.regions) {
    const mission::CoverageRegion surface = coverageRegion(region, settings);
    yaml << "  - name: " << surface.name << "   # " << formatNumber(region.area_m2, 4) << " m2, " << region.elements
         << " voxel faces\n"
         << "    box: {min: " << flowPoint(region.box_m.min(), 3) << ", max: " << flowPoint(region.box_m.max(), 3)
         << "}\n"
         << "    faces: [down]\n"
         << "    gsd_mm_px: " << formatNumber(surface.gsd_mm_px) << "\n"
         << "    overlap: {front: " << formatNumber(surface.overlap_front_pct)
         << ", side: " << formatNumber(surface.overlap_side_pct) << "}\n"
         << "    max_incidence_deg: " << formatNumber(surface.max_incidence_deg) << "\n";
  }
  return yaml.str();
}

std::string proposalPictureSvg(const environment::VoxelGrid& grid, const mission::MissionProposal& proposal,
                               const std::string& title) {
  const environment::GridFrame& frame = grid.frame();
  const environment::Index3& size = frame.size();
  // At most about 400 cells along the longer side, so that the picture stays small.
  const int step = std::max(1, static_cast<int>(std::ceil(std::max(size[0], size[1]) / 400.0)));
  const int columns = (size[0] + step - 1) / step, rows = (size[1] + step - 1) / step;
  const double cell_m = step * frame.resolution_m();
  const Eigen::AlignedBox3d bounds = frame.bounds();
  const double width_m = columns * cell_m, height_m = rows * cell_m;
  const double scale = 800.0 / std::max(width_m, height_m);  // pixels per metre
  const double margin = 40.0;
  const auto px = [&](double x_m) { return margin + (x_m - bounds.min().x()) * scale; };
  const auto py = [&](double y_m) { return margin + (bounds.min().y() + height_m - y_m) * scale; };  // north up
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << formatFixed(width_m * scale + 2 * margin, 0)
      << "\" height=\"" << formatFixed(height_m * scale + 2 * margin + 30, 0) << "\" font-family=\"sans-serif\" "
      << "font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // What stands below the overhead surfaces: the highest occupied voxel of each cell under the
  // lowest region (racks, girders, piers; the floor lightest), in eight shades, light to dark.
  double below_m = bounds.max().z();
  for (const mission::ProposedRegion& region : proposal.regions) below_m = std::min(below_m, region.box_m.min().z());
  const int below_layer = std::min(size[2], std::max(0, frame.indexOf(2, below_m)));
  const double z_min = bounds.min().z(), z_span = std::max(below_m - z_min, 1e-9);
  svg << "<g shape-rendering=\"crispEdges\">\n";
  for (int row = 0; row < rows; ++row) {
    int run_start = 0, run_shade = -1;
    for (int column = 0; column <= columns; ++column) {
      int top = -1;  // the highest occupied layer under the cell, below the regions
      for (int i = column * step; column < columns && i < std::min(size[0], (column + 1) * step); ++i)
        for (int j = row * step; j < std::min(size[1], (row + 1) * step); ++j)
          for (int k = below_layer - 1; k > top; --k)
            if (grid.at(i, j, k) == environment::CellState::Occupied) {
              top = k;
              break;
            }
      const int shade = top < 0 ? -1 : std::min(7, static_cast<int>(8.0 * (frame.centreOf(2, top) - z_min) / z_span));
      if (shade == run_shade) continue;
      if (run_shade >= 0) {
        const int grey = 230 - 22 * run_shade;
        svg << "<rect x=\"" << formatFixed(px(bounds.min().x() + run_start * cell_m), 1) << "\" y=\""
            << formatFixed(py(bounds.min().y() + (row + 1) * cell_m), 1) << "\" width=\""
            << formatFixed((column - run_start) * cell_m * scale, 1) << "\" height=\""
            << formatFixed(cell_m * scale + 0.5, 1) << "\" fill=\"rgb(" << grey << "," << grey << "," << grey
            << ")\"/>\n";
      }
      run_start = column;
      run_shade = shade;
    }
  }
  svg << "</g>\n";
  for (const mission::ProposedRegion& region : proposal.regions) {
    const Eigen::Vector3d& lo = region.box_m.min();
    const Eigen::Vector3d& hi = region.box_m.max();
    const double width = (hi.x() - lo.x()) * scale, height = (hi.y() - lo.y()) * scale;
    const double cx = px((lo.x() + hi.x()) / 2), cy = py((lo.y() + hi.y()) / 2);
    svg << "<rect x=\"" << formatFixed(px(lo.x()), 1) << "\" y=\"" << formatFixed(py(hi.y()), 1) << "\" width=\""
        << formatFixed(width, 1) << "\" height=\"" << formatFixed(height, 1)
        << "\" fill=\"orange\" fill-opacity=\"0.3\" stroke=\"darkorange\" stroke-width=\"2\"/>\n"
        << "<text x=\"" << formatFixed(cx, 1) << "\" y=\"" << formatFixed(cy, 1)
        << "\" text-anchor=\"middle\" dominant-baseline=\"middle\" fill=\"saddlebrown\""
        << (height > width ? " transform=\"rotate(-90 " + formatFixed(cx, 1) + " " + formatFixed(cy, 1) + ")\"" : "")
        << ">" << region.name << "</text>\n";
  }
  svg << "<circle cx=\"" << formatFixed(px(proposal.home_m.x()), 1) << "\" cy=\""
      << formatFixed(py(proposal.home_m.y()), 1)
      << "\" r=\"7\" fill=\"royalblue\" stroke=\"white\" stroke-width=\"2\"/>\n<text x=\""
      << formatFixed(px(proposal.home_m.x()) + 10, 1) << "\" y=\"" << formatFixed(py(proposal.home_m.y()) + 5, 1)
      << "\" fill=\"royalblue\">home</text>\n";
  const double bar_m = scaleBarLength_m(width_m);
  const double bar_y = height_m * scale + 2 * margin + 10;
  svg << "<line x1=\"" << margin << "\" y1=\"" << formatFixed(bar_y, 1) << "\" x2=\""
      << formatFixed(margin + bar_m * scale, 1) << "\" y2=\"" << formatFixed(bar_y, 1)
      << "\" stroke=\"black\" stroke-width=\"3\"/>\n<text x=\"" << formatFixed(margin + bar_m * scale + 8, 1)
      << "\" y=\"" << formatFixed(bar_y + 5, 1) << "\">" << formatNumber(bar_m) << " m; north up; grey: highest "
      << "occupied voxel below the regions (darker is higher); orange: overhead regions</text>\n<text x=\"" << margin
      << "\" y=\"24\">"
      << "ceilplan propose: " << xmlText(printableText(title, 120)) << "</text>\n</svg>\n";
  return svg.str();
}

std::string proposalText(const mission::MissionProposal& proposal, const fs::path& mission_file,
                         const fs::path& picture_file) {
  double kept_m2 = 0.0;
  for (const mission::ProposedRegion& region : proposal.regions) kept_m2 += region.area_m2;
  std::ostringstream text;
  text << "proposed " << proposal.regions.size() << " overhead region" << (proposal.regions.size() == 1 ? "" : "s")
       << ": " << formatNumber(kept_m2, 4) << " m2 of the " << formatNumber(proposal.overhead_area_m2, 4)
       << " m2 of down-facing surface with known free space below\n";
  for (const mission::ProposedRegion& region : proposal.regions) {
    text << "  " << region.name << ": " << formatNumber(region.area_m2, 4) << " m2 in the box "
         << formatPoint(region.box_m.min()) << " to " << formatPoint(region.box_m.max());
    if (region.box_area_m2 > region.area_m2 + 1e-6)
      text << " (with smaller surfaces inside it: " << formatNumber(region.box_area_m2, 4) << " m2 to cover)";
    text << "\n";
  }
  if (proposal.too_low_area_m2 > 0.0) {
    const std::string room = formatFixed(proposal.min_room_below_m, 2) + " m";
    text << "left out " << formatNumber(proposal.too_low_area_m2, 4)
         << " m2 too low to photograph from below: with less than " << room
         << " of free space below most of its region";
    if (std::isfinite(proposal.ground_m))
      text << ", or less than " << room << " above the ground at " << formatFixed(proposal.ground_m, 2) << " m";
    text << " (the vehicle with its margins and the camera's standoff)\n";
  }
  if (proposal.dropped_regions > 0)
    text << "dropped " << proposal.dropped_regions << " smaller region" << (proposal.dropped_regions == 1 ? "" : "s")
         << " (" << formatFixed(proposal.dropped_area_m2, 1) << " m2 in all): below the least area or beyond the most "
         << "regions\n";
  text << "home " << formatPoint(proposal.home_m) << ": " << (proposal.home_given ? "as given" : "proposed");
  if (std::isfinite(proposal.home_height_m))
    text << ", " << formatFixed(proposal.home_height_m, 2) << " m above the floor";
  text << "\nmission: " << printableText(mission_file.string(), 256) << " (no origin: tours write local-frame files)\n"
       << "picture: " << printableText(picture_file.string(), 256) << "\n";
  return text.str();
}

}  // namespace ceilplan::io
