#pragma once
/// @file
/// Candidate camera poses for a region and what each one covers. A pose covers a surface element
/// when the element lies in the central (1 - side overlap) x (1 - front overlap) part of the
/// image, at or beyond the minimum focus distance, at or below the required GSD and incidence,
/// and every voxel on the line of sight is known free (environment/visibility.hpp). The poses
/// are valid states of the vehicle (Environment::isStateValid) between the minimum focus
/// distance and the distance the GSD allows. docs/coverage.md, "Candidate views".

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/mission/flight_mode.hpp"
#include "ceilplan/mission/region_surface.hpp"
#include "ceilplan/mission/viewpoint.hpp"
#include "ceilplan/planner/reachable_space.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <vector>

namespace ceilplan::mission {

/// One element a pose covers, with how it sees it.
struct SeenElement {
  std::uint32_t element = 0;   ///< index into RegionSurface::elements
  float gsd_mm_px = 0.0f;      ///< at its distance and incidence
  float incidence_deg = 0.0f;  ///< line of sight to the surface normal
  float distance_m = 0.0f;     ///< camera to the element's centre
};

/// What candidate generation tried (for reports and benchmarks).
struct GenerationStats {
  std::size_t seeds = 0;          ///< lattice seeds (element, distance level)
  std::size_t poses_tried = 0;    ///< admissibility tests
  std::size_t repair_probes = 0;  ///< admissible poses tried for elements the lattice left uncovered
  std::size_t repair_views = 0;   ///< views added by those probes
};

/// One lawnmower tiling of a flat patch: the straight views of its evenly spaced lanes and
/// stations at one distance level and image orientation (docs/coverage.md, "Seeds").
struct Tiling {
  std::uint32_t patch = 0;           ///< the flat patch it tiles (numbered per region)
  std::vector<std::uint32_t> views;  ///< its candidates (those admissible), ascending
};

/// What a candidate's covered elements add up to: the figures its photo reports and its cost
/// reads, kept so that the candidate holds its elements' indices only.
struct CoverSummary {
  double area_m2 = 0.0;     ///< the elements' area
  double distance_m = 0.0;  ///< area-weighted mean distance, camera to element centre
  double gsd_mm_px = 0.0;   ///< area-weighted mean GSD
  double finest_gsd_mm_px = std::numeric_limits<double>::infinity();  ///< the finest GSD among them
};

/// The summary of `covered` (elements of `surface`), summed in the list's order.
CoverSummary summariseCover(const std::vector<SeenElement>& covered, const RegionSurface& surface);

/// Consecutive element indices: first, first + 1, ..., first + count - 1.
struct ElementRun {
  std::uint32_t first = 0;  ///< the first index (into RegionSurface::elements)
  std::uint32_t count = 0;  ///< how many, at least 1
};

/// The runs of an ascending list of element indices.
std::vector<ElementRun> elementRuns(const std::vector<std::uint32_t>& ascending);

/// Walks runs of element indices one index at a time (a forward iterator of std::uint32_t).
class ElementIterator {
 public:
  using iterator_category = std::forward_iterator_tag;  ///< forward only
  using value_type = std::uint32_t;                     ///< an element index
  using difference_type = std::ptrdiff_t;               ///< as any iterator
  using pointer = const std::uint32_t*;                 ///< not used
  using reference = std::uint32_t;                      ///< indices are made, not stored

  /// At index `offset` of `run`.
  ElementIterator(const ElementRun* run, std::uint32_t offset) : run_(run), offset_(offset) {}
  /// The element index.
  std::uint32_t operator*() const { return run_->first + offset_; }
  /// The next index, in this run or the next.
  ElementIterator& operator++() {
    if (++offset_ == run_->count) {
      ++run_;
      offset_ = 0;
    }
    return *this;
  }
  /// Whether both stand at the same index of the same run.
  bool operator==(const ElementIterator& other) const { return run_ == other.run_ && offset_ == other.offset_; }
  /// Whether they differ.
  bool operator!=(const ElementIterator& other) const { return !(*this == other); }

 private:
  const ElementRun* run_;
  std::uint32_t offset_;
};

/// Candidate poses and, for each, the elements it covers as runs of consecutive indices
/// (compressed rows: poses[i] covers the runs runs[offsets[i]] .. runs[offsets[i + 1] - 1],
/// ascending) and their summary. A pose sees a patch of surface, whose elements are numbered
/// row by row, so a run holds a row of the patch: a region's candidates cover tens of millions
/// of elements on a large structure, in a few million runs.
struct CandidateViews {
  std::vector<CameraPose> poses;          ///< the candidate poses
  std::vector<std::uint32_t> offsets{0};  ///< row starts into `runs`, one more than poses
  std::vector<ElementRun> runs;           ///< every pose's covered elements, as runs, row after row
  std::vector<CoverSummary> summaries;    ///< per pose, what its covered elements add up to
  std::vector<std::uint8_t> reachable;    ///< per element: 1 if some candidate covers it
  std::vector<Tiling> tilings;            ///< the lawnmower tilings among the candidates
  /// Per candidate: 1 if only a cover started from the tilings may take it (the views of up and
  /// down patches' second image orientation, across the region's heading); empty: none.
  std::vector<std::uint8_t> tiling_only;

  /// Candidates held.
  std::size_t size() const { return poses.size(); }
  /// Whether only a cover started from the tilings may take `view`.
  bool tilingOnly(std::size_t view) const { return !tiling_only.empty() && tiling_only[view] != 0; }
  /// First element `view` covers.
  ElementIterator begin(std::size_t view) const { return {runs.data() + offsets[view], 0}; }
  /// One past the last element `view` covers.
  ElementIterator end(std::size_t view) const { return {runs.data() + offsets[view + 1], 0}; }
  /// Appends a candidate with the runs of the elements it covers (ascending) and their summary.
  void add(const CameraPose& pose, const std::vector<ElementRun>& covered, const CoverSummary& summary);

  GenerationStats stats;  ///< what generation tried
};

/// What candidate poses cover, shared by candidate generations that run at once over the same
/// map, camera and regions in different flight modes (planTours' modes: free mode's poses are
/// nearly all ceiling mode's unraised ones). A pose's cover is found by the first generation that
/// asks for it, handed to the others, and forgotten once every mode has asked or has finished the
/// region. Thread-safe; the covers are the same whoever finds them.
class SharedCovers {
 public:
  /// Shared by one generation in each of `modes` (distinct).
  explicit SharedCovers(const std::vector<FlightMode>& modes);
  ~SharedCovers();
  SharedCovers(const SharedCovers&) = delete;
  SharedCovers& operator=(const SharedCovers&) = delete;

  /// Covers held now.
  std::size_t size() const;
  /// Covers handed to a mode that did not find them.
  std::size_t handed() const;

  /// The covers and who asked for them (defined where generateCandidateViews uses them).
  struct State;
  /// generateCandidateViews' access to them.
  State& state() const { return *state_; }

 private:
  std::unique_ptr<State> state_;
};

/// How candidate views are generated for a region.
struct ViewGenerationOptions {
  FlightMode mode = FlightMode::Ceiling;  ///< the mode the views are for
  /// Free mode: the conventional distance kept from every structure, airframe to surface. A pose
  /// keeps it (body clearance >= collision radius + standoff) where any pose for its seed does;
  /// elsewhere only the poses of largest clearance (within 0.1 m, or a quarter of it) are kept.
  double free_standoff_m = 1.0;
  /// Rotors never come closer than this to the surface above (as the tour's viewpoints).
  double min_ceiling_gap_m = 0.03;
  int distance_levels = 4;          ///< camera distances per seed, geometric from the GSD's reach down to min focus
                                    ///< (and as many within the room in front of the surface, where that is shorter)
  double seed_spacing_share = 0.5;  ///< seeds every this share of the covered footprint at each distance
  double tilt_share = 0.6;          ///< lattice tilts: this share of the region's max incidence
  int workers = 2;                  ///< threads testing poses
  std::function<void(double)> progress;  ///< fraction of the visibility work done
  /// Poses only where this holds (a tour's planner::ReachableSpace, when its first stops left a
  /// place no route from home reaches); empty: every admissible pose. An element seen only from
  /// elsewhere counts as unreachable.
  planner::ReachablePredicate reachable;
  /// Covers shared with the other modes' generations running at once (planTours sets it); empty:
  /// every cover is found here.
  std::shared_ptr<SharedCovers> shared_covers;
};

/// The distance levels of a region (largest first): from where the whole covered part of an
/// image meets the GSD down to the minimum focus distance. Throws via checkCameraReaches.
/// With `room_m`, the farthest level is at most that far (never nearer than the nearest level):
/// a coarse GSD whose reach lies beyond the floor keeps its levels where a pose can fit.
std::vector<double> distanceLevels(const Camera& camera, const CoverageRegion& region, int levels,
                                   double room_m = std::numeric_limits<double>::infinity());

/// How far from a region's surface a camera can stand: the median, over its elements, of the run
/// of known free voxels along each element's normal, less how far the inflated airframe and the
/// mount offset reach beyond the camera along it (the body must fit there too); at most `far_m`
/// is looked for.
double roomInFront_m(const environment::Environment& environment, const Camera& camera, const RegionSurface& surface,
                     double far_m);

/// Heading (deg from north, [0, 180)) of the region's long horizontal axis: vertical views are
/// yawed along it, so passes along the region fly along the image height (front overlap).
double regionHeading(const RegionSurface& surface);

/// Generates the lattice candidates (straight and tilted views of seed elements at every
/// distance level, raised to hug the structure above in ceiling mode), finds what each covers,
/// then probes every element the lattice left uncovered with a denser set of poses and adds the
/// best one that covers it. Elements still uncovered are unreachable (reachable[e] == 0).
/// Reads the environment only; runs visibility on options.workers threads.
CandidateViews generateCandidateViews(const environment::Environment& environment, const Camera& camera,
                                      const CoverageRegion& region, const RegionSurface& surface,
                                      const ViewGenerationOptions& options = {});

/// What one pose covers under the same rules (for reports and tests).
std::vector<SeenElement> coveredElements(const environment::VoxelGrid& grid, const Camera& camera,
                                         const CoverageRegion& region, const RegionSurface& surface,
                                         const CameraPose& pose);

}  // namespace ceilplan::mission
