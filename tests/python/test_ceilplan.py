"""The Python module as a user's script meets it: vehicles, maps, routes and tours."""

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import ceilplan

SOURCE = Path(os.environ["CEILPLAN_SOURCE_DIR"])
MAPS = SOURCE / "maps"


def test_default_vehicle_draws_the_founding_papers_currents():
    quad = ceilplan.Vehicle.default()
    assert quad.current_a() == pytest.approx(9.5, abs=1e-9)
    assert quad.current_a(ceiling_gap_m=0.05) == pytest.approx(8.0, abs=1e-9)
    assert quad.current_a(speed_m_s=5.0) != pytest.approx(9.5, abs=1e-3)


def test_vehicle_file_and_built_in_vehicle_agree():
    assert ceilplan.Vehicle.load(MAPS / "vehicles/quad.yaml").current_a(ceiling_gap_m=0.05) == pytest.approx(
        ceilplan.Vehicle.default().current_a(ceiling_gap_m=0.05), abs=1e-12)


@pytest.fixture(scope="module")
def bridge():
    return ceilplan.Environment.load(MAPS / "bridge.bt")


def test_probe_under_the_deck(bridge):
    # The deck's underside is at 6.0 m; rotor plane 3 cm above the body centre.
    probe = bridge.probe(10.0, 0.0, 5.5)
    assert probe["valid"]
    assert probe["ceiling"]["nearest_gap_m"] == pytest.approx(6.0 - 5.53, abs=0.11)
    assert probe["clearance_m"] > 0.0
    assert bridge.probe(6.0, 0.0, 6.05)["valid"] is False  # inside the deck


def test_plan_then_evaluate_the_same_route(bridge):
    route = ceilplan.plan(bridge, (-4.0, 0.0, 0.5), (10.0, 0.0, 5.5), time_limit_s=1.0, seed=1)
    assert len(route["waypoints"]) >= 2
    assert route["charge_ah"] > 0.0
    samples = route["samples"]
    assert isinstance(samples["t_s"], np.ndarray) and samples["t_s"].shape == samples["soc"].shape
    again = ceilplan.evaluate(bridge, route["waypoints"])
    assert again["valid"]
    assert again["charge_ah"] == pytest.approx(route["charge_ah"], rel=1e-12)


def test_a_route_matches_the_command_line_with_the_same_defaults(bridge, tmp_path):
    # The lattice planner is deterministic: with the defaults both front ends share (its 0.2 m
    # spacing among them), Python and `ceilplan plan` fly the same route.
    start, goal = (6.0, 0.7, 5.85), (14.0, 0.7, 5.85)
    route = ceilplan.plan(bridge, start, goal, planner="lattice")
    subprocess.run([os.environ["CEILPLAN_EXE"], "plan", "--map", str(MAPS / "bridge.bt"), "--planner", "lattice",
                    "--start", ",".join(map(str, start)), "--goal", ",".join(map(str, goal)), "--out",
                    str(tmp_path / "cli")], check=True, capture_output=True)
    cli = json.loads((tmp_path / "cli" / "plan.json").read_text())
    assert route["charge_ah"] == pytest.approx(cli["charge_ah"], abs=1e-12)
    np.testing.assert_allclose(np.array(route["waypoints"]), np.array(cli["waypoints"]), rtol=0, atol=1e-12)
    coarser = ceilplan.plan(bridge, start, goal, planner="lattice", lattice_spacing_m=0.4, refine=False)
    assert coarser["charge_ah"] != pytest.approx(cli["charge_ah"], abs=1e-9)
    with pytest.raises(ValueError, match="band fraction"):
        ceilplan.plan(bridge, start, goal, band_fraction=1.5)


def test_bad_input_raises_a_value_error(bridge):
    with pytest.raises(ValueError, match="outside the map"):
        ceilplan.plan(bridge, (1e6, 0, 0), (10.0, 0.0, 5.5), planner="lattice")
    with pytest.raises(ceilplan.Error, match="not a valid state"):
        ceilplan.plan(bridge, (6.0, 0.0, 6.05), (10.0, 0.0, 5.5), planner="lattice")
    with pytest.raises(ceilplan.InputError):
        ceilplan.Mission.load(MAPS / "nowhere.yaml")


def test_tour_matches_the_command_line(tmp_path):
    mission = ceilplan.Mission.load(MAPS / "bridge.yaml")
    tour = ceilplan.plan_tour(mission, mode="ceiling")
    out = tmp_path / "cli"
    subprocess.run([os.environ["CEILPLAN_EXE"], "tour", "--mission", str(MAPS / "bridge.yaml"), "--mode", "ceiling",
                    "--out", str(out), "--no-export"], check=True, capture_output=True)
    cli = json.loads((out / "tour.json").read_text())
    assert tour.charge_ah == pytest.approx(cli["charge_ah"], abs=1e-9)
    assert tour.fec == pytest.approx(cli["fec"], abs=1e-12)
    assert len(tour.sorties) == len(cli["sorties"])
    assert set(tour.wear) == {"fec", "xu", "woehler", "schmalstieg"}
    samples = tour.samples
    assert np.all(np.diff(samples["t_s"]) >= 0.0)
    assert samples["soc"][0] == pytest.approx(0.95)
    tour.write(tmp_path / "py")
    written = json.loads((tmp_path / "py" / "tour.json").read_text())
    assert written["charge_ah"] == cli["charge_ah"]
    # Where the files came from: the call that planned them and the one that wrote them.
    command = written["provenance"]["command"]
    assert "ceilplan.plan_tour(mission, mode='ceiling', seed=" in command and ".write(" in command
    assert tour.photos is None and tour.coverage is None  # point targets only
    assert tour.stops_rechosen is False and cli["stops_rechosen"] is False


def test_coverage_tour_exposes_its_photos_and_coverage(tmp_path):
    # A strip of the bridge's soffit at 1 mm/px, contact points and a target (tests/coverage/missions).
    mission = ceilplan.Mission.load(SOURCE / "tests/coverage/missions/bridge_strip.yaml")
    assert mission.surfaces == ["strip"]
    assert mission.contact_grids == ["probe"]
    tour = ceilplan.plan_tour(mission, mode="ceiling")
    photos = tour.photos
    n = len(photos["index"])
    assert n > 5
    assert list(photos["index"]) == list(range(1, n + 1))
    assert set(photos["region"]) == {"strip"}
    assert np.all(np.diff(photos["t_s"]) > 0.0)
    assert np.all(photos["gsd_mm_px"] <= 1.0)
    assert np.all((photos["gimbal_pitch_deg"] >= -30.0) & (photos["gimbal_pitch_deg"] <= 90.0))
    assert isinstance(photos, ceilplan.Photos) and repr(photos) == f"Photos(photos={n}, regions=['strip'])"
    assert isinstance(tour.coverage, ceilplan.Coverage) and repr(tour.coverage).startswith(f"Coverage(photos={n}, strip ")
    (region,) = tour.coverage["regions"]
    assert region["name"] == "strip"
    assert region["photos"] == n
    assert region["covered_reachable_pct"] >= 99.0
    # The same photos and coverage as the files `ceilplan tour` writes.
    tour.write(tmp_path / "strip")
    rows = [line for line in (tmp_path / "strip" / "photos.csv").read_text().splitlines() if not line.startswith("#")]
    assert rows[0] == "index,sortie,t_s,x,y,z,yaw_deg,gimbal_pitch_deg,distance_m,gsd_mm_px,region"
    assert len(rows) == n + 1
    for k, row in enumerate(rows[1:]):
        fields = row.split(",")
        assert int(fields[1]) == photos["sortie"][k]
        assert float(fields[3]) == pytest.approx(photos["x"][k], abs=5e-4)
        assert float(fields[5]) == pytest.approx(photos["z"][k], abs=5e-4)
        assert float(fields[6]) == pytest.approx(photos["yaw_deg"][k], abs=5e-3)
    written = json.loads((tmp_path / "strip" / "coverage.json").read_text())
    assert written.pop("provenance")["command"].startswith("python: ceilplan.plan_tour(")  # the file records its call
    assert written == tour.coverage
