#include "ceilplan/io/report_text.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/unknown_space_report.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace ceilplan::io {
namespace {

// printf into a string: the tables keep their column widths.
std::string printed(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printed(const char* format, ...) {
  va_list arguments;
  va_start(arguments, format);
  va_list copy;
  va_copy(copy, arguments);
  std::vector<char> buffer(static_cast<std::size_t>(std::vsnprintf(nullptr, 0, format, copy)) + 1);
  va_end(copy);
  std::vsnprintf(buffer.data(), buffer.size(), format, arguments);
  va_end(arguments);
  return buffer.data();
}

std::string gapText(double gap_m) { return std::isfinite(gap_m) ? formatFixed(gap_m, 4) : "none"; }

std::string gapText(const std::optional<double>& gap_m) { return gap_m ? formatNumber(*gap_m, 4) + " m" : "none"; }

// A ratio or time of the benchmark table: "-" where no run solved, "never" for an infinite time.
std::string cell(double value, int decimals) {
  if (std::isnan(value)) return "-";
  return std::isinf(value) ? "never" : formatFixed(value, decimals);
}

}  // namespace

std::string positionProbeText(const Eigen::Vector3d& body_m, const environment::PositionProbe& probe,
                              const environment::VehicleGeometry& vehicle, const std::string& unknown_line) {
  const environment::SurfaceGaps &ceiling = probe.ceiling, &ground = probe.ground;
  std::string text =
      printed("at: %.3f, %.3f, %.3f (vehicle %s)\n", body_m.x(), body_m.y(), body_m.z(), vehicle.name.c_str());
  text += "ceiling_gap_m: " + gapText(ceiling.nearest_gap_m) +
          "\nceiling_coverage: " + formatFixed(ceiling.coverage, 4) +
          "\nceiling_mean_gap_m: " + gapText(ceiling.mean_gap_m) + "\n";
  text += "ground_gap_m: " + gapText(ground.nearest_gap_m) + "\nground_coverage: " + formatFixed(ground.coverage, 4) +
          "\nground_mean_gap_m: " + gapText(ground.mean_gap_m) + "\n";
  text += "clearance_m: " + gapText(probe.clearance_m) + "\nvalid: " + (probe.violation ? "false" : "true") + "\n";
  if (probe.violation) text += "violation: " + probe.violation->describe() + "\n";
  text += "unknown: " + unknown_line + "\n";
  text += std::string("assumed_free: ") +
          (probe.assumes_free ? "true (the vehicle overlaps unknown space the policy assumed free)" : "false") + "\n";
  for (std::size_t r = 0; r < vehicle.rotor_positions_m.size(); ++r)
    text += "rotor " + std::to_string(r) + ": ceiling gap " + gapText(ceiling.rotors[r].nearest_gap_m) + " coverage " +
            formatFixed(ceiling.rotors[r].coverage, 4) + " | ground gap " + gapText(ground.rotors[r].nearest_gap_m) +
            " coverage " + formatFixed(ground.rotors[r].coverage, 4) + "\n";
  return text;
}

std::string mapStatisticsText(const std::string& map, const environment::MapStatistics& stats) {
  const Eigen::Vector3d lo = stats.extent_m.min(), hi = stats.extent_m.max();
  std::string text = "map: " + map + "\nresolution_m: " + formatNumber(stats.resolution_m) + "\n";
  text += printed("extent_m: [%.3f, %.3f, %.3f] to [%.3f, %.3f, %.3f] (%.1f x %.1f x %.1f m)\n", lo.x(), lo.y(), lo.z(),
                  hi.x(), hi.y(), hi.z(), hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z());
  text += printed("leaves: %zu occupied, %zu free\n", stats.occupied_leaves, stats.free_leaves);
  text += printed("volume_m3: %.1f occupied, %.1f free, %.1f unknown (within the extent)\n", stats.occupied_volume_m3,
                  stats.free_volume_m3, stats.unknown_volume_m3);
  text += "unknown: " + unknownSpaceLine(stats.unknown, stats.unknown_summary) + "\n";
  text += "ceiling_area_share: " + formatFixed(stats.ceiling_area_share, 3) +
          " of the floor area lies under a ceiling (an occupied surface with " +
          formatNumber(stats.ceiling.min_headroom_m) + " m or more of free space below, in patches of " +
          formatNumber(stats.ceiling.min_area_m2) + " m2 or more)\n";
  return text;
}

std::string flightConditionText(const std::string& vehicle, double coverage, const std::optional<double>& ground_gap_m,
                                const energy::FlightCondition& flight) {
  // The wind only where there is some, so still-air output reads as it always has.
  const std::string wind = flight.headwind_m_s == 0.0 ? std::string()
                                                      : printed("  headwind %.3g m/s (airspeed %.3g m/s)",
                                                                flight.headwind_m_s, flight.airspeedM_s());
  return printed("vehicle               %s\n", vehicle.c_str()) +
         printed("soc %.3f  coverage %.3f  ground gap %s  speed %.3g m/s%s  climb %.3g m/s\n", flight.soc, coverage,
                 gapText(ground_gap_m).c_str(), flight.speed_m_s, wind.c_str(), flight.climb_m_s);
}

std::string currentBreakdownText(const std::optional<double>& ceiling_gap_m, const energy::CurrentBreakdown& b) {
  return printed("ceiling gap           %s\n", gapText(ceiling_gap_m).c_str()) +
         printed("current_a             %.4f\npower_w               %.3f\n", b.current_a, b.power_w) +
         printed("  induced_w           %.3f\n  profile_w           %.3f\n", b.induced_w, b.profile_w) +
         printed("  parasitic_w         %.3f\n  climb_w             %.3f\n", b.parasitic_w, b.climb_w) +
         printed("  avionics_w          %.3f\n", b.avionics_w) +
         printed("ceiling_factor        %.5f\nground_factor         %.5f\n", b.ceiling_factor, b.ground_factor) +
         printed("induced_power_factor  %.5f\nterminal_voltage_v    %.3f\n", b.induced_power_factor,
                 b.terminal_voltage_v);
}

std::string currentSweepText(double rotor_radius_m, double free_air_current_a,
                             const std::vector<energy::GapPoint>& sweep) {
  std::string text = printed("free air: current_a %.4f\n", free_air_current_a);
  text += printed("%10s %8s %10s %10s %14s\n", "gap_m", "gap_R", "current_a", "power_w", "ceiling_factor");
  for (const energy::GapPoint& point : sweep)
    text += printed("%10.4f %8.3f %10.4f %10.3f %14.5f\n", point.gap_m, point.gap_m / rotor_radius_m,
                    point.breakdown.current_a, point.breakdown.power_w, point.breakdown.ceiling_factor);
  return text;
}

std::string calibrationText(const std::string& vehicle, const std::filesystem::path& data, std::size_t samples,
                            const energy::CalibrationResult& result) {
  std::string out = printed("vehicle     %s\n", vehicle.c_str());
  out += printed("data        %s (%zu samples)\n", data.c_str(), samples);
  out += printed("rmse_a      %.5f   (largest error %.5f A, %d model evaluations)\n", result.rmse_a,
                 result.max_abs_error_a, result.evaluations);
  out += printed("%-20s %14s %14s %14s %14s\n", "parameter", "fitted", "allowed_min", "allowed_max", "start");
  for (const energy::FittedParameter& f : result.fitted)
    out += printed("%-20s %14.6g %14.6g %14.6g %14.6g%s\n", energy::parameterName(f.parameter).c_str(), f.value,
                   f.lower, f.upper, f.start, f.atBound() ? "  (at its bound)" : "");
  const energy::FitUncertainty& u = result.uncertainty;
  out += printed("residual    std %.5f A, RMS %.5f A (n - p = %d)\n", u.residual_std_a, u.residual_rms_a,
                 u.samples - static_cast<int>(result.fitted.size()));
  if (!u.hasCovariance()) return out + "uncertainty not reported: " + u.unavailable + "\n";
  out += printed("%-20s %14s %14s\n", "parameter", "std_error", "relative");
  for (std::size_t k = 0; k < u.parameters.size(); ++k) {
    const double value = energy::parameterValue(result.parameters, u.parameters[k]);
    out += printed("%-20s %14.4g %13.3g%%\n", energy::parameterName(u.parameters[k]).c_str(), u.standard_errors[k],
                   value != 0.0 ? 100.0 * u.standard_errors[k] / std::fabs(value) : 0.0);
  }
  return out;
}

std::string plannerBenchmarkHeadline(const std::string& mode, const std::string& objective, const std::string& unit,
                                     const planner::PlannerBenchmarkOptions& options, std::uint32_t seed) {
  return printed("bench-planners: %s mode, objective %s (%s), %u runs of %.1f s per planner, seed %u\n", mode.c_str(),
                 objective.c_str(), unit.c_str(), options.runs, options.time_limit_s, seed);
}

std::string latticeReferenceLine(const planner::PlanResult& reference, double lattice_spacing_m) {
  return printed("lattice reference (spacing %s m): %.6g raw, %.6g post-processed, %.1f s\n",
                 formatNumber(lattice_spacing_m).c_str(), reference.search_cost, reference.cost,
                 reference.total_time_s);
}

std::string plannerBenchmarkTable(const std::vector<planner::PlannerBenchmarkRow>& rows, double time_limit_s) {
  std::string text = printed("\n%-16s %7s %11s %12s %12s %12s %13s\n", "planner", "solved", "first [s]", "raw / ref",
                             "final / ref", "best final", "to 5 % [s]");
  for (const planner::PlannerBenchmarkRow& row : rows)
    text += printed("%-16s %3d/%-3zu %11s %12s %12s %12s %13s\n", row.planner.c_str(), row.solved, row.runs,
                    cell(row.median_first_solution_s, 2).c_str(), cell(row.median_raw_cost_ratio, 4).c_str(),
                    cell(row.median_cost_ratio, 4).c_str(), cell(row.best_cost_ratio, 4).c_str(),
                    cell(row.median_time_to_5pct_s, 2).c_str());
  text +=
      "medians over the solved runs; 'raw' and 'final' (after shortcuts and NLopt refinement) against the\n"
      "post-processed lattice reference; 'to 5 %': when the planner's own best cost first came within 5 % of\n"
      "the raw lattice optimum ('never': not within " +
      formatNumber(time_limit_s) + " s)\n";
  return text;
}

std::string generatedSceneLine(const std::string& scene, const environment::SceneOptions& options,
                               const environment::VoxelGrid& grid, std::size_t octree_nodes,
                               const std::filesystem::path& map_file) {
  const bool other_bridge = environment::sceneFromName(scene) == environment::Scene::Bridge &&
                            options.bridge_length_m != environment::kShippedBridgeLength_m;
  const std::string length = other_bridge ? ", length " + formatNumber(options.bridge_length_m) + " m" : "";
  const auto& size = grid.frame().size();
  return printed("scene %s%s, resolution %g m, seed %llu: %d x %d x %d voxels, %zu octree nodes -> %s (%ju bytes)\n",
                 scene.c_str(), length.c_str(), options.resolution_m, static_cast<unsigned long long>(options.seed),
                 size[0], size[1], size[2], octree_nodes, map_file.string().c_str(),
                 static_cast<std::uintmax_t>(std::filesystem::file_size(map_file)));
}

std::string mapImportText(const MapImport& imported, const MapImportOptions& options,
                          const std::filesystem::path& map_file) {
  std::string text = "import: " + imported.source.string() + " -> " + map_file.string() + "\n";
  text += "resolution_m: " + formatNumber(options.resolution_m) + "\n";
  if (imported.skipped_non_finite_points > 0)
    text += "skipped_non_finite_points: " + std::to_string(imported.skipped_non_finite_points) + "\n";
  for (const auto& [name, value] : imported.built.figures)
    text += name + ": " + formatNumber(value, value == std::floor(value) ? 15 : 6) + "\n";
  text += "free_space: " + imported.built.free_space + "\n";
  text += "extent_m: " + formatPoint(imported.extent_m.min()) + " to " + formatPoint(imported.extent_m.max()) + "\n";
  if (imported.frame) {
    const ImportedFrame& frame = *imported.frame;
    text += "crs: " + frame.crs + " (" + frame.crs_name + "); local origin at " +
            formatPoint(frame.origin_projected, 3) + " in it\n";
    text += "origin: {lat: " + formatFixed(frame.origin.latitude_deg, 8) +
            ", lon: " + formatFixed(frame.origin.longitude_deg, 8) +
            ", alt: " + formatFixed(frame.origin.altitude_m, 3) + "}   # for the mission file\n";
  }
  text += "wrote " + map_file.string() + " (" + std::to_string(imported.built.tree->size()) + " octree nodes, " +
          std::to_string(static_cast<std::uintmax_t>(std::filesystem::file_size(map_file))) + " bytes) and " +
          map_file.string() + ".json\n";
  return text;
}

}  // namespace ceilplan::io
