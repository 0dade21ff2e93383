// Refinement of a path's waypoints (path_refinement.hpp): a long path is refined near its ends,
// each end on its own, and keeps its middle; a shorter one is refined whole.

#include "planner_fixtures.hpp"

#include "ceilplan/planner/path_refinement.hpp"

#include <gtest/gtest.h>

namespace ceilplan::testing {
namespace {

// A 28 m corridor under a flat ceiling at 2.2 m: a path flown at 1.95 m saves charge where the
// refinement raises it towards the ceiling.
double lowCeiling(double, double) { return 2.2; }

struct RefinementScene : PlannerScene {
  RefinementScene() : PlannerScene(corridor(lowCeiling, 28.0)) {}
  planner::Waypoints refine(const planner::Waypoints& path, double end_window_m) const {
    planner::RefinementOptions options;
    options.end_window_m = end_window_m;
    return planner::refinePath(path, planner.rules(), planner.objective(), options);
  }
  double cost(const planner::Waypoints& path) const { return planner.objective().pathCost(path); }
  bool valid(const planner::Waypoints& path) const {
    for (std::size_t k = 1; k < path.size(); ++k)
      if (!planner.rules().isMotionValid(path[k - 1], path[k])) return false;
    return !planner.rules().checkPathDensely(path).has_value();
  }
};

const RefinementScene& scene() {
  static const RefinementScene shared;
  return shared;
}

// 24 m at 1.95 m, its waypoints 6 m from each end: with 6 m end windows, the parts are exactly
// [start, 6 m], [6 m, 18 m] and [18 m, end].
constexpr double kWindowM = 6.0;
const planner::Waypoints kLongPath{{2.0, 0.0, 1.95}, {8.0, 0.0, 1.95}, {20.0, 0.0, 1.95}, {26.0, 0.0, 1.95}};

TEST(PathRefinement, ALongPathsEndsAreEachRefinedAloneAndItsMiddleKept) {
  const RefinementScene& s = scene();
  const planner::Waypoints refined = s.refine(kLongPath, kWindowM);
  const planner::Waypoints head = s.refine({kLongPath[0], kLongPath[1]}, kWindowM);
  const planner::Waypoints tail = s.refine({kLongPath[2], kLongPath[3]}, kWindowM);
  ASSERT_GT(head.size(), 2u) << "the head alone is refined: raised towards the ceiling";
  ASSERT_GT(tail.size(), 2u);
  planner::Waypoints joined = head;  // ends at kLongPath[1]; the middle runs straight on to kLongPath[2]
  joined.insert(joined.end(), tail.begin(), tail.end());
  const planner::Waypoints expected = planner::shortcutPath(joined, s.planner.rules(), s.planner.objective());
  EXPECT_EQ(refined, expected);
  EXPECT_LT(s.cost(refined), s.cost(kLongPath));
  EXPECT_TRUE(s.valid(refined));
  // The middle is not moved: refined whole, its waypoints would rise too.
  const planner::Waypoints whole = s.refine(kLongPath, 0.0);
  EXPECT_NE(whole, refined);
  EXPECT_TRUE(s.valid(whole));
}

TEST(PathRefinement, APathUpToThreeEndWindowsLongIsRefinedWhole) {
  const RefinementScene& s = scene();
  const planner::Waypoints path{{2.0, 0.0, 1.95}, {20.0, 0.0, 1.95}};  // 18 m: three windows
  const planner::Waypoints refined = s.refine(path, kWindowM);
  EXPECT_EQ(refined, s.refine(path, 0.0));
  EXPECT_LT(s.cost(refined), s.cost(path));
  EXPECT_TRUE(s.valid(refined));
}

TEST(PathRefinement, AWindowThatCutsASegmentCutsItWhereTheWindowEnds) {
  const RefinementScene& s = scene();
  // 24 m in one segment: the windows end 6 m in and 6 m short of the end, between waypoints.
  const planner::Waypoints path{kLongPath.front(), kLongPath.back()};
  const planner::Waypoints refined = s.refine(path, kWindowM);
  EXPECT_EQ(refined, s.refine(kLongPath, kWindowM));
  EXPECT_LT(s.cost(refined), s.cost(path));
}

}  // namespace
}  // namespace ceilplan::testing
