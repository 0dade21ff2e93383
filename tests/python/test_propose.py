"""ceilplan.propose: `ceilplan propose` from Python. A mission proposed from a map reads back as a
mission and tours; bad values are refused with ValueError, missing files with FileNotFoundError,
and nothing is written."""

import os

import pytest

import ceilplan

SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
WAREHOUSE = os.path.join(SOURCE, "maps", "warehouse.bt")
QUAD = os.path.join(SOURCE, "maps", "vehicles", "quad.yaml")


def test_a_proposed_mission_reads_back_and_tours(tmp_path):
    out = tmp_path / "proposed.yaml"
    proposal = ceilplan.propose(WAREHOUSE, QUAD, out, max_regions=1, gsd_mm_px=6.0)
    assert [region["name"] for region in proposal["regions"]] == ["overhead_1"]
    region = proposal["regions"][0]
    assert region["box_min"][2] == pytest.approx(7.95)  # the roof's underside at 8 m, half a voxel around it
    assert region["box_max"][2] == pytest.approx(8.05)
    assert region["area_m2"] == pytest.approx(117.6, abs=0.1)  # one bay between trusses: 4.9 x 24 m
    assert proposal["dropped_regions"] > 0
    assert not proposal["home_given"]
    assert proposal["home_height_m"] == pytest.approx(0.5)
    assert os.path.isfile(proposal["picture"]) and str(proposal["picture"]).endswith("proposed.svg")
    mission = ceilplan.Mission.load(out)
    assert mission.surfaces == ["overhead_1"]
    tour = ceilplan.plan_tour(mission, mode="ceiling")
    coverage = tour.coverage
    assert coverage["regions"][0]["covered_reachable_pct"] >= 99.0


def test_bad_values_and_missing_files_write_nothing(tmp_path):
    out = tmp_path / "m.yaml"
    with pytest.raises(ValueError, match="the given home"):
        ceilplan.propose(WAREHOUSE, QUAD, out, home=[1.5, 8.0, 0.0])
    with pytest.raises(ValueError, match="a crop box's y minimum"):
        ceilplan.propose(WAREHOUSE, QUAD, out, crop=[0, 1, 0, 1, 1, 1])
    with pytest.raises(ValueError, match="max_regions"):
        ceilplan.propose(WAREHOUSE, QUAD, out, max_regions=0)
    with pytest.raises(ValueError, match="phantom5"):
        ceilplan.propose(WAREHOUSE, QUAD, out, camera="phantom5")
    with pytest.raises(ValueError, match="must end in .yaml"):
        ceilplan.propose(WAREHOUSE, QUAD, tmp_path / "m.txt")
    with pytest.raises(FileNotFoundError):
        ceilplan.propose(tmp_path / "none.bt", QUAD, out)
    assert list(tmp_path.iterdir()) == []


def test_progress_reports_indexing_and_the_proposal(tmp_path):
    stages = []
    ceilplan.propose(WAREHOUSE, QUAD, tmp_path / "proposed.yaml", max_regions=1, gsd_mm_px=6.0,
                     progress=lambda stage, fraction: stages.append(stage))
    assert any(stage.startswith("indexing ") for stage in stages)
    assert "finding overhead surfaces" in stages
