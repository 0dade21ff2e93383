// Environment::ceilingAndGroundAlong and ColumnIndex::freeSpan, which the cost model's motions use
// instead of one search of every column under every disc at every sample: the same answers to the
// bit as the single-point queries, on shipped maps, over many seeded motions.

#include "analytic_maps.hpp"

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

namespace ceilplan::environment {
namespace {

const std::string kBridge = CEILPLAN_SOURCE_DIR "/maps/bridge.bt";
const std::string kGeb079 = "/usr/share/doc/liboctomap-dev/examples/data/geb079.bt";

void expectSame(const SurfaceGaps& batch, const SurfaceGaps& single, const std::string& where) {
  // EXPECT_EQ on doubles: bit-for-bit equality (infinities included), not a tolerance.
  EXPECT_EQ(batch.nearest_gap_m, single.nearest_gap_m) << where;
  EXPECT_EQ(batch.coverage, single.coverage) << where;
  EXPECT_EQ(batch.mean_gap_m, single.mean_gap_m) << where;
  ASSERT_EQ(batch.rotors.size(), single.rotors.size()) << where;
  for (std::size_t r = 0; r < single.rotors.size(); ++r) {
    EXPECT_EQ(batch.rotors[r].nearest_gap_m, single.rotors[r].nearest_gap_m) << where << " rotor " << r;
    EXPECT_EQ(batch.rotors[r].coverage, single.rotors[r].coverage) << where << " rotor " << r;
    EXPECT_EQ(batch.rotors[r].mean_gap_m, single.rotors[r].mean_gap_m) << where << " rotor " << r;
  }
}

// What the seeded motions met, so a test can tell it exercised every case.
struct Seen {
  long points = 0;
  long covered_rotors = 0;  // a ceiling within reach of part of the disc
  long partial_rotors = 0;  // part of a disc only: its columns disagree
  long ground_seen = 0;
};

// `motions` seeded straight motions inside `box`: lattice edges (0.4 m along one of the 26
// neighbour directions) and longer motions in any direction (up to 3 m along each axis, or to
// another point of the box `across`), sampled every 0.05 m as the cost model samples them; each
// motion's samples asked together and one by one.
Seen compareAlongMotions(const Environment& environment, const Eigen::AlignedBox3d& box, int motions, unsigned seed,
                         bool across = false) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Seen seen;
  for (int m = 0; m < motions; ++m) {
    const Eigen::Vector3d from =
        box.min() + (box.max() - box.min()).cwiseProduct(Eigen::Vector3d(unit(random), unit(random), unit(random)));
    Eigen::Vector3d delta;
    if (m % 2 == 0) {
      std::array<int, 3> offset{0, 0, 0};
      while (offset == std::array<int, 3>{0, 0, 0})
        for (int& o : offset) o = static_cast<int>(random() % 3) - 1;
      delta = 0.4 * Eigen::Vector3d(offset[0], offset[1], offset[2]);
    } else if (across) {
      delta = box.min() +
              (box.max() - box.min()).cwiseProduct(Eigen::Vector3d(unit(random), unit(random), unit(random))) - from;
    } else {
      delta = Eigen::Vector3d(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5) * 6.0;
    }
    const int intervals = std::max(1, static_cast<int>(std::ceil(delta.cwiseAbs().maxCoeff() / 0.05)));
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k <= intervals; ++k) points.push_back(from + delta * (static_cast<double>(k) / intervals));
    if (!environment.contains(points.front()) || !environment.contains(points.back())) continue;
    std::size_t visited = 0;
    environment.ceilingAndGroundAlong(points, [&](std::size_t k, const Environment::CeilingAndGround& batch) {
      ASSERT_EQ(k, visited++);
      const Environment::CeilingAndGround single = environment.ceilingAndGround(points[k]);
      const std::string where = "motion " + std::to_string(m) + " sample " + std::to_string(k);
      expectSame(batch.ceiling, single.ceiling, where + " ceiling");
      expectSame(batch.ground, single.ground, where + " ground");
      ++seen.points;
      for (const RotorGap& rotor : single.ceiling.rotors) {
        seen.covered_rotors += rotor.coverage > 0.0;
        seen.partial_rotors += rotor.coverage > 0.0 && rotor.coverage < 1.0;
      }
      seen.ground_seen += single.ground.coverage > 0.0;
    });
    EXPECT_EQ(visited, points.size()) << "motion " << m;
  }
  return seen;
}

const OccupancyMap& bridge() {
  static const OccupancyMap map = OccupancyMap::load(kBridge);
  return map;
}

TEST(GapBatch, MotionsUnderTheShippedBridgeAnswerAsSinglePointQueries) {
  const Environment environment(bridge(), testing::quad());
  // Under and around the deck, where gaps vary from column to column (girders, cross-frames, piers).
  const Eigen::AlignedBox3d all = environment.grid().frame().bounds();
  const Eigen::AlignedBox3d box(all.min() + Eigen::Vector3d(0.5, 0.5, 0.1),
                                Eigen::Vector3d(all.max().x() - 0.5, all.max().y() - 0.5, 6.5));
  const Seen seen = compareAlongMotions(environment, box, 3000, 26);
  EXPECT_GT(seen.points, 50000);
  EXPECT_GT(seen.covered_rotors, 10000);
  EXPECT_GT(seen.partial_rotors, 1000);
  EXPECT_GT(seen.ground_seen, 10000);
}

TEST(GapBatch, LongMotionsAnsweredInRunsAnswerAsSinglePointQueries) {
  // A refined leg's segment is tens of metres: its samples are asked in runs, each run with the
  // spans of its own columns.
  const Environment environment(bridge(), testing::quad());
  const Eigen::AlignedBox3d all = environment.grid().frame().bounds();
  const Eigen::AlignedBox3d box(all.min() + Eigen::Vector3d(0.5, 0.5, 0.1),
                                Eigen::Vector3d(all.max().x() - 0.5, all.max().y() - 0.5, 6.5));
  const Seen seen = compareAlongMotions(environment, box, 300, 29, true);
  EXPECT_GT(seen.points, 50000);
  EXPECT_GT(seen.covered_rotors, 10000);
  EXPECT_GT(seen.partial_rotors, 1000);
  EXPECT_GT(seen.ground_seen, 8000);
}

TEST(GapBatch, UnknownSpaceAsASurfaceAnswersAsSinglePointQueriesToo) {
  EnvironmentOptions options;
  options.unknown_is_surface = true;
  const Environment environment(bridge(), testing::quad(), options);
  const Seen seen = compareAlongMotions(environment, environment.grid().frame().bounds(), 1500, 27);
  EXPECT_GT(seen.points, 30000);
  EXPECT_GT(seen.covered_rotors, 10000);
}

TEST(GapBatch, MotionsThroughGeb079AnswerAsSinglePointQueries) {
  const OccupancyMap map = OccupancyMap::load(kGeb079);
  MapIndexOptions index;
  index.unknown.policy = UnknownPolicy::Fill;
  const Environment environment(MapIndex::build(map, index), testing::quad());
  const Seen seen = compareAlongMotions(environment, environment.grid().frame().bounds(), 3000, 28);
  EXPECT_GT(seen.points, 30000);
  EXPECT_GT(seen.partial_rotors, 1000);
}

TEST(GapBatch, APointOutsideTheMapIsAnErrorBeforeAnyPointIsAnswered) {
  const Environment environment(bridge(), testing::quad());
  const Eigen::Vector3d inside = environment.grid().frame().bounds().center();
  int visited = 0;
  EXPECT_THROW(environment.ceilingAndGroundAlong({inside, Eigen::Vector3d(1e4, 0.0, 0.0)},
                                                 [&](std::size_t, const Environment::CeilingAndGround&) { ++visited; }),
               ceilplan::InputError);
  EXPECT_EQ(visited, 0);
}

TEST(ColumnFreeSpan, EveryHeightInsideASpanHasItsBoundariesAndNoSpanHoldsARunsHeight) {
  const Environment environment(bridge(), testing::quad());
  const ColumnIndex& columns = environment.columns();
  const GridFrame& frame = columns.frame();
  std::mt19937 random(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::AlignedBox3d box = frame.bounds();
  int spans = 0, runs = 0;
  for (int n = 0; n < 20000; ++n) {
    // Columns a little beyond the grid too, and heights on voxel faces as often as between them.
    const int i = static_cast<int>(random() % (frame.size()[0] + 4)) - 2;
    const int j = static_cast<int>(random() % (frame.size()[1] + 4)) - 2;
    double z = box.min().z() - 0.5 + unit(random) * (box.sizes().z() + 1.0);
    if (n % 4 == 0) z = frame.faceOf(2, static_cast<int>(random() % frame.size()[2]));
    const std::optional<ColumnIndex::FreeSpan> span = columns.freeSpan(i, j, z);
    const ColumnIndex::Boundaries around = columns.around(i, j, z);
    if (!span) {
      // Inside a run, on its face, or outside the grid: around() meets a voxel at z itself.
      EXPECT_TRUE(around.above.face_m == z || around.below.face_m == z) << i << " " << j << " " << z;
      ++runs;
      continue;
    }
    ++spans;
    ASSERT_LT(span->lo, span->hi);
    const double t = columns.voxelHeight(z);
    EXPECT_TRUE(span->lo < t && t < span->hi);
    for (int k = 1; k < 8; ++k) {
      // Heights across the span, each given to around() as a height in metres.
      const double inside_z = frame.faceOf(2, 0) + (span->lo + (span->hi - span->lo) * k / 8.0) * frame.resolution_m();
      if (!(span->lo < columns.voxelHeight(inside_z) && columns.voxelHeight(inside_z) < span->hi)) continue;
      const ColumnIndex::Boundaries expected = columns.around(i, j, inside_z);
      EXPECT_EQ(span->around.above.face_m, expected.above.face_m);
      EXPECT_EQ(span->around.above.state, expected.above.state);
      EXPECT_EQ(span->around.below.face_m, expected.below.face_m);
      EXPECT_EQ(span->around.below.state, expected.below.state);
    }
  }
  EXPECT_GT(spans, 5000);
  EXPECT_GT(runs, 1000);
}

}  // namespace
}  // namespace ceilplan::environment
