#include "ceilplan/battery/rainflow.hpp"
#include "ceilplan/core/error.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::battery {
namespace {

RainflowCycle makeCycle(double first, std::size_t first_index, double second, std::size_t second_index, double count) {
  return RainflowCycle{std::fabs(second - first), 0.5 * (first + second), count, first_index, second_index};
}

}  // namespace

void RainflowCounter::pushTurningPoint(std::vector<TurningPoint>& stack, TurningPoint point,
                                       std::vector<RainflowCycle>& closed) {
  stack.push_back(point);
  // ASTM E1049-85 5.4.4: X is the most recent range, Y the one before it.
  while (stack.size() >= 3) {
    const std::size_t n = stack.size();
    const double x = std::fabs(stack[n - 1].value - stack[n - 2].value);
    const double y = std::fabs(stack[n - 2].value - stack[n - 3].value);
    if (x < y) break;
    const TurningPoint& a = stack[n - 3];
    const TurningPoint& b = stack[n - 2];
    if (n == 3) {
      // Y holds the starting point: a half cycle, and the start moves on.
      closed.push_back(makeCycle(a.value, a.index, b.value, b.index, 0.5));
      stack.erase(stack.begin());
    } else {
      closed.push_back(makeCycle(a.value, a.index, b.value, b.index, 1.0));
      stack[n - 3] = stack[n - 1];
      stack.resize(n - 2);
    }
  }
}

void RainflowCounter::add(double value, std::vector<RainflowCycle>& closed) {
  if (!std::isfinite(value))
    throw ceilplan::InputError("rainflow: sample " + std::to_string(samples_seen_) +
                               " is not a finite number; remove or fill it");
  const std::size_t index = samples_seen_++;
  if (index == 0) {
    // The series' first sample is a turning point (ASTM's starting point).
    stack_.push_back({value, index});
    candidate_ = {value, index};
    return;
  }
  if (value == candidate_.value) return;  // a plateau changes nothing
  const int step = value > candidate_.value ? 1 : -1;
  if (direction_ == 0) {
    direction_ = step;
  } else if (step != direction_) {
    pushTurningPoint(stack_, candidate_, closed);
    direction_ = step;
  }
  candidate_ = {value, index};
}

void RainflowCounter::add(const double* values, std::size_t count, std::vector<RainflowCycle>& closed) {
  for (std::size_t i = 0; i < count; ++i) add(values[i], closed);
}

void RainflowCounter::add(const std::vector<double>& values, std::vector<RainflowCycle>& closed) {
  add(values.data(), values.size(), closed);
}

std::vector<RainflowCycle> RainflowCounter::residue() const {
  std::vector<RainflowCycle> cycles;
  if (direction_ == 0) return cycles;  // nothing fed, or a flat series: no range at all
  std::vector<TurningPoint> stack = stack_;
  pushTurningPoint(stack, candidate_, cycles);
  for (std::size_t i = 1; i < stack.size(); ++i)
    cycles.push_back(makeCycle(stack[i - 1].value, stack[i - 1].index, stack[i].value, stack[i].index, 0.5));
  return cycles;
}

std::vector<RainflowCycle> countRainflowCycles(const std::vector<double>& series) {
  RainflowCounter counter;
  std::vector<RainflowCycle> cycles;
  counter.add(series, cycles);
  const std::vector<RainflowCycle> rest = counter.residue();
  cycles.insert(cycles.end(), rest.begin(), rest.end());
  return cycles;
}

RainflowTotals rainflowTotals(const std::vector<RainflowCycle>& cycles) {
  RainflowTotals totals;
  for (const RainflowCycle& c : cycles) {
    (c.count == 1.0 ? totals.full_cycles : totals.half_cycles) += 1.0;
    totals.cycles += c.count;
    totals.count_weighted_range += c.count * c.range;
  }
  return totals;
}

}  // namespace ceilplan::battery
