#pragma once
/// @file
/// Rainflow cycle counting per ASTM E1049-85 (section 5.4.4, "rainflow counting"), streaming:
/// a series fed piece by piece yields exactly the cycles it yields fed at once
/// (docs/ageing.md).

#include "ceilplan/core/error.hpp"

#include <cstddef>
#include <vector>

namespace ceilplan::battery {

/// One counted cycle: `range` is |a - b| (the depth of discharge for an SOC series), `mean` is
/// (a + b) / 2, `count` is 1 (full cycle) or 0.5 (half cycle). `start` and `end` are the global
/// sample indices (0-based, counting every sample fed so far) of its two turning points, in time
/// order; on a plateau a turning point is the plateau's first sample.
struct RainflowCycle {
  double range = 0.0;     ///< the absolute difference of the turning points, the depth of discharge for an SOC series
  double mean = 0.0;      ///< (a + b) / 2
  double count = 0.0;     ///< 1 (full cycle) or 0.5 (half cycle)
  std::size_t start = 0;  ///< global index of the earlier turning point
  std::size_t end = 0;    ///< global index of the later turning point
};

/// Streaming rainflow counter (ASTM E1049-85): fed a series piece by piece, it returns the cycles as they close.
class RainflowCounter {
 public:
  /// Feeds the next sample(s), in time order. Cycles closed by them are appended to `closed`
  /// (nothing is cleared). Throws ceilplan::InputError on a non-finite value, naming its index;
  /// samples before the bad one have been counted.
  void add(double value, std::vector<RainflowCycle>& closed);
  /// Feeds `count` values from `values` (as add(double, ...)).
  void add(const double* values, std::size_t count, std::vector<RainflowCycle>& closed);
  /// Feeds a vector of values (as add(double, ...)).
  void add(const std::vector<double>& values, std::vector<RainflowCycle>& closed);

  /// What the series fed so far still holds, as half cycles: the last extreme is taken as a
  /// turning point (it may close full cycles, as at the end of ASTM's procedure) and every range
  /// left counts as one half cycle. Leaves the counter unchanged, so feeding may go on.
  std::vector<RainflowCycle> residue() const;

  /// Samples fed so far.
  std::size_t samplesSeen() const { return samples_seen_; }
  /// The index of the earliest sample a cycle counted from now on (closed later, or in the
  /// residue) can start at: nothing before it is needed any more.
  std::size_t firstOpenIndex() const { return stack_.empty() ? candidate_.index : stack_.front().index; }

 private:
  struct TurningPoint {
    double value;
    std::size_t index;
  };

  /// Adds a confirmed turning point to `stack` and closes what ASTM's three-point rule closes.
  static void pushTurningPoint(std::vector<TurningPoint>& stack, TurningPoint point,
                               std::vector<RainflowCycle>& closed);

  std::vector<TurningPoint> stack_;  ///< confirmed turning points not yet closed
  TurningPoint candidate_{0.0, 0};   ///< the latest extreme, confirmed once the series turns back
  int direction_ = 0;                ///< +1 rising, -1 falling, 0 before the series first moves
  std::size_t samples_seen_ = 0;
};

/// Counts a whole series at once: full cycles in the order they close, then the residue's half
/// cycles.
std::vector<RainflowCycle> countRainflowCycles(const std::vector<double>& series);

/// What a count adds up to: full and half cycles, cycles in all (a half counts 0.5), and the sum
/// of count x range (the FEC of an SOC series' swings).
struct RainflowTotals {
  double full_cycles = 0.0;           ///< cycles counted with count 1
  double half_cycles = 0.0;           ///< cycles counted with count 0.5
  double cycles = 0.0;                ///< full_cycles + 0.5 half_cycles
  double count_weighted_range = 0.0;  ///< sum of count x range
};
/// The totals of `cycles`.
RainflowTotals rainflowTotals(const std::vector<RainflowCycle>& cycles);

}  // namespace ceilplan::battery
