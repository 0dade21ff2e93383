"""Landing confidence from Python: a calibrated vehicle, `reserve_confidence` and gusty wind give
every sortie its odds of landing above the reserve, and the tour's own sampled check agrees."""

import math
import os
from pathlib import Path

import ceilplan

SOURCE = Path(os.environ["CEILPLAN_SOURCE_DIR"])

# The calibration of docs/energy.md ("Uncertainty"), with a wider hover-power error so that the
# confidence binds on the bridge with a small pack.
CALIBRATION = """
calibration:
  samples: 120
  residual_rms_a: 0.3
  residual_std_a: 0.3
  parameters: [hover_power_w, k2_m]
  covariance: [[25.0, 0.0], [0.0, 4.0e-5]]
"""


def calibrated_bridge(tmp_path, wind):
    vehicle = tmp_path / "quad_calibrated.yaml"
    vehicle.write_text((SOURCE / "maps" / "vehicles" / "quad.yaml").read_text() + CALIBRATION)
    text = (SOURCE / "maps" / "bridge.yaml").read_text()
    text = text.replace("map: bridge.bt", f"map: {SOURCE / 'maps' / 'bridge.bt'}")
    text = text.replace("vehicle: vehicles/quad.yaml", f"vehicle: {vehicle}")
    text = text.replace("capacity_ah: 5.2 ", "capacity_ah: 0.75")
    text = text.replace("charge_current_a: 10.4", "charge_current_a: 10.4\n  reserve_confidence: 0.99")
    mission_file = tmp_path / "bridge_calibrated.yaml"
    mission_file.write_text(text + f"wind: {wind}\n")
    return ceilplan.Mission.load(mission_file)


def test_every_sortie_lands_above_the_reserve_with_the_asked_odds_in_gusts(tmp_path):
    mission = calibrated_bridge(tmp_path, "{speed_m_s: 8, from_deg: 90, gust_m_s: 3}")
    tour = ceilplan.plan_tour(mission, mode="ceiling")
    assert len(tour.sorties) >= 2
    for sortie in tour.sorties:
        assert sortie["p_land_above_reserve"] >= 0.99 - 1e-9
        assert 0.25 <= sortie["soc_p01"] < sortie["min_soc"]
        assert sortie["landing_soc_std"] > 0.0
        sampled = sortie["sampled_landing"]
        assert sampled["seed"] == 1 and sampled["draws"] > 0
        p = sortie["p_land_above_reserve"]
        # The tour's own Monte Carlo check flies each drawn gust through the model.
        assert abs(sampled["p_land_above_reserve"] - p) <= 4.0 * math.sqrt(p * (1.0 - p) / sampled["draws"]) + 0.002
