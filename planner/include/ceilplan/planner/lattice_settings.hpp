#pragma once
/// @file
/// What the lattice planners (LatticePlanner, LatticeRoadmap) are told: how far apart their
/// nodes are, in metres, so a mission behaves the same whatever the map's resolution.

#include <cstddef>
#include <functional>

namespace ceilplan::planner {

/// Default node spacings: a tour's roadmap covers the whole map once for all its legs; a single
/// query's lattice A* searches one route and affords a finer lattice (docs/planner.md).
inline constexpr double kTourLatticeSpacing_m = 0.4;
inline constexpr double kQueryLatticeSpacing_m = 0.2;  ///< a single query's lattice A* spacing
/// The spacings the lattice planners accept (--lattice-spacing-m, Python's lattice_spacing_m):
/// finer than a centimetre is finer than any map's voxels, coarser than 2 m misses doorways.
inline constexpr double kMinLatticeSpacing_m = 0.01;
inline constexpr double kMaxLatticeSpacing_m = 2.0;  ///< coarsest spacing accepted

/// How the lattice planners lay out and search their lattice.
struct LatticeSettings {
  /// Between lattice nodes; rounded to a whole number of voxels (at least one), so nodes sit on
  /// voxel centres and lattice motions sample the cost model's half-voxel lattice exactly.
  double spacing_m = kTourLatticeSpacing_m;
  int workers = 1;                          ///< threads building the roadmap
  std::size_t max_expansions = 50'000'000;  ///< the lattice A* gives up beyond
  std::function<void(double)> progress;     ///< share of the roadmap's build done, from the calling thread

  /// Throws ceilplan::InputError for a spacing outside [kMinLatticeSpacing_m, kMaxLatticeSpacing_m]
  /// or fewer than one worker.
  void validate() const;
};

/// The settings of a single query (PlanRequest's default): the query spacing.
inline LatticeSettings queryLatticeSettings() {
  LatticeSettings settings;
  settings.spacing_m = kQueryLatticeSpacing_m;
  return settings;
}

}  // namespace ceilplan::planner
