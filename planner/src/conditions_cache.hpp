#pragma once
// Map conditions at points of the cost model's sampling lattice near structure, computed once
// each and stored compactly (2 numbers per rotor, 3 more); far from structure the model answers
// without the map anyway. For one search on one thread.

#include "ceilplan/planner/flight_cost_model.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace ceilplan::planner::detail {

class ConditionsCache {
 public:
  explicit ConditionsCache(const FlightCostModel& model)
      : model_(model), inverse_step_(1.0 / model.step_m()), rotors_(model.energy().rotorCount()) {
    const environment::GridFrame& frame = model.environment().grid().frame();
    for (int axis = 0; axis < 3; ++axis) anchor_m_[axis] = frame.centreOf(axis, 0);
  }

  PointConditions operator()(const Eigen::Vector3d& point_m) {
    // The sampling lattice of lattice motions: step_m() apart from a voxel centre.
    const Eigen::Vector3d scaled = (point_m - anchor_m_) * inverse_step_;
    const Eigen::Vector3d rounded = scaled.array().round();
    if ((scaled - rounded).cwiseAbs().maxCoeff() > 1e-6 || model_.farFromStructure(point_m))
      return model_.conditionsAt(point_m);
    const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::int64_t>(rounded.x()) & 0x1FFFFF) << 42) |
                              (static_cast<std::uint64_t>(static_cast<std::int64_t>(rounded.y()) & 0x1FFFFF) << 21) |
                              (static_cast<std::uint64_t>(static_cast<std::int64_t>(rounded.z()) & 0x1FFFFF));
    const std::size_t width = 2 * rotors_ + 3;
    const auto [found, inserted] = offsets_.try_emplace(key, values_.size());
    if (inserted) {
      const PointConditions conditions = model_.conditionsAt(point_m);
      for (int r = 0; r < rotors_; ++r) {
        values_.push_back(conditions.rotors[r].gap_m);
        values_.push_back(conditions.rotors[r].coverage);
      }
      values_.push_back(conditions.ground_gap_m);
      values_.push_back(conditions.nearest_ceiling_gap_m);
      values_.push_back(conditions.standoff_shortfall_m);
      return conditions;
    }
    const double* v = values_.data() + found->second;
    PointConditions conditions;
    conditions.rotor_count = rotors_;
    for (int r = 0; r < rotors_; ++r) conditions.rotors[r] = {v[2 * r], v[2 * r + 1]};
    conditions.ground_gap_m = v[width - 3];
    conditions.nearest_ceiling_gap_m = v[width - 2];
    conditions.standoff_shortfall_m = v[width - 1];
    return conditions;
  }

 private:
  const FlightCostModel& model_;
  double inverse_step_;
  Eigen::Vector3d anchor_m_;
  int rotors_;
  std::unordered_map<std::uint64_t, std::size_t> offsets_;
  std::vector<double> values_;
};

}  // namespace ceilplan::planner::detail
