#pragma once
/// @file
/// Data-sheet cycle life: a Woehler law N(DoD) = N100 * DoD^-k with Miner's rule, and the
/// founding paper's FEC baseline on the same N100 (Kocer et al. 2019; docs/ageing.md).

#include "ceilplan/battery/ageing_model.hpp"
#include "ceilplan/battery/cycle_ageing_model.hpp"
#include "ceilplan/core/error.hpp"

namespace ceilplan::battery {

/// [open] calibration parameters (docs/ageing.md: no public LiPo cycle-life
/// versus DoD data; N100 comes from a pack's data sheet, k about 1.2 to 2.1).
struct WoehlerParameters {
  double cycles_at_full_depth = 300.0;     ///< N100: full cycles to end of life at DoD 1 [open]
  double exponent = 1.5;                   ///< k [open]
  double end_of_life_capacity_loss = 0.2;  ///< end of life at SOH 0.8, the usual data-sheet rule

  /// Throws ceilplan::InputError unless N100 > 0, k >= 0 and 0 < end-of-life loss <= 1.
  void validate() const;
};

/// N(depth) = N100 * depth^-k; infinite at depth 0. Depth is clamped to 1.
double woehlerCyclesToEndOfLife(double depth, const WoehlerParameters& parameters);

/// Miner's rule: damage = sum n_i / N(DoD_i); capacity lost = damage * end-of-life loss.
class WoehlerAgeingModel : public CycleAgeingModel {
 public:
  /// A Woehler model with `parameters` (N100 and exponent k).
  explicit WoehlerAgeingModel(const WoehlerParameters& parameters = {});
  std::string name() const override { return "woehler"; }
  ValidityRange validity() const override;
  std::unique_ptr<AgeingModel> clone() const override;

  /// Miner damage so far (1 = end of life), open ranges as half cycles.
  double damage() const;
  double cycleWear() const override { return damage(); }
  std::string cycleWearName() const override { return "Miner damage"; }

 private:
  void addCycle(const RainflowCycle& cycle) override;
  double capacityLossWith(const std::vector<RainflowCycle>& open) const override;
  double damageWith(const std::vector<RainflowCycle>& open) const;

  WoehlerParameters parameters_;
  double closed_damage_ = 0.0;
};

/// The founding paper's baseline: loss proportional to full equivalent cycles counted against
/// the nominal capacity (Kocer et al. 2019, eq. 3-6: FEC = integral |i| dt / (2 C_nom)), reaching
/// end of life after N100 FEC. From an SOC history, FEC = sum |dSOC| SOH / 2, each swing weighted
/// by the state of health it happened at (the sum |dSOC| / 2 of NREL BLAST-Lite when SOH = 1), so
/// a faded pack counts the charge it really moves, not its deeper SOC swings.
class FecAgeingModel : public AgeingModel {
 public:
  /// An FEC model reaching end of life after `parameters`' N100 FEC.
  explicit FecAgeingModel(const WoehlerParameters& parameters = {});
  std::string name() const override { return "fec"; }
  ValidityRange validity() const override;
  std::unique_ptr<AgeingModel> clone() const override;

  /// FEC so far, against the nominal capacity.
  double fullEquivalentCycles() const { return fec_; }
  double cycleWear() const override { return fec_; }
  std::string cycleWearName() const override { return "FEC"; }

 private:
  void consume(const AgeingSample* previous, const AgeingSample* samples, std::size_t count) override;
  double modelCapacityLoss() const override;

  WoehlerParameters parameters_;
  double fec_ = 0.0;
};

}  // namespace ceilplan::battery
