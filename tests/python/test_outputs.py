"""Tour.write follows the output rules of `ceilplan tour --out` (docs/cli.md, "Outputs")."""

import json
import os
import shutil
from pathlib import Path

import pytest

import ceilplan

MAPS = Path(os.environ["CEILPLAN_SOURCE_DIR"]) / "maps"
MARKER = ".ceilplan-output"


@pytest.fixture(scope="module")
def tour():
    return ceilplan.plan_tour(ceilplan.Mission.load(MAPS / "bridge.yaml"), mode="ceiling")


def staging_left(directory):
    return [p.name for p in Path(directory).iterdir() if ".tmp" in p.name]


def test_a_rewrite_replaces_the_directory_whole(tour, tmp_path):
    out = tmp_path / "tour"
    tour.write(out)  # with the autopilot files
    assert (out / "mission.plan").exists() and (out / MARKER).exists()
    tour.write(out, autopilot=False)
    assert (out / "tour.json").exists() and (out / MARKER).exists()
    assert not (out / "mission.plan").exists(), "the first write's autopilot file was merged into the second"
    assert not (out / "mission.waypoints").exists()
    assert staging_left(tmp_path) == []


def test_an_empty_directory_is_written(tour, tmp_path):
    out = tmp_path / "empty"
    out.mkdir()
    tour.write(out, autopilot=False)
    assert (out / "tour.json").exists()


def test_a_directory_ceilplan_did_not_write_is_refused_and_untouched(tour, tmp_path):
    out = tmp_path / "mine"
    out.mkdir()
    (out / "notes.txt").write_text("keep")
    with pytest.raises(ceilplan.InputError, match="did not write.*remove it or choose another"):
        tour.write(out)
    assert sorted(p.name for p in out.iterdir()) == ["notes.txt"]
    assert (out / "notes.txt").read_text() == "keep"
    assert staging_left(tmp_path) == []


def test_the_missions_map_is_never_an_output(tmp_path):
    shutil.copy(MAPS / "open.bt", tmp_path / "open.bt")
    text = (MAPS / "open.yaml").read_text().replace("map: open.bt", "map: " + str(tmp_path / "open.bt"))
    (tmp_path / "open.yaml").write_text(text.replace("vehicles/", str(MAPS / "vehicles") + "/"))
    mission = ceilplan.Mission.load(tmp_path / "open.yaml")
    tour = ceilplan.plan_tour(mission, mode="ceiling")
    with pytest.raises(ceilplan.InputError, match="is the input the mission's map"):
        tour.write(tmp_path / "open.bt")
    assert (tmp_path / "open.bt").read_bytes() == (MAPS / "open.bt").read_bytes()


def test_a_mission_without_an_origin_writes_its_local_outputs(tmp_path):
    # The coverage strip (tests/coverage/missions) with its origin left out: Tour.write, with
    # the autopilot files asked for, writes every local-frame output and records the geodetic
    # exports it skipped.
    strip = Path(os.environ["CEILPLAN_SOURCE_DIR"]) / "tests/coverage/missions/bridge_strip.yaml"
    text = "".join(line for line in strip.read_text().splitlines(True) if not line.startswith("origin:"))
    (tmp_path / "strip.yaml").write_text(text.replace("../../../maps/", str(MAPS) + "/"))
    tour = ceilplan.plan_tour(ceilplan.Mission.load(tmp_path / "strip.yaml"), mode="ceiling")
    out = tmp_path / "tour"
    tour.write(out)
    for name in ["tour.json", "path.csv", "trajectory.csv", "trajectory.json", "report.html", "map_top.csv",
                 "map_side.csv", "photos.csv", "coverage.json", "coverage_elements.csv"]:
        assert (out / name).is_file(), name
    skipped = ["mission.plan", "mission.waypoints", "mission.kmz", "routes.kml", "routes.geojson"]
    assert not any((out / name).exists() for name in skipped)
    recorded = json.loads((out / "tour.json").read_text())["geodetic_exports_skipped"]
    assert recorded["files"] == skipped
    assert "no 'origin:'" in recorded["reason"]
