"""A tour from Python holds what `ceilplan tour` prints and writes: both modes, every path.csv
column, the sorties' legs and waypoints; long work reports progress and can be stopped."""

import csv
import json
import os
import signal
import subprocess
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import ceilplan

MAPS = Path(os.environ["CEILPLAN_SOURCE_DIR"]) / "maps"
PATH_CSV_COLUMNS = ["t_s", "x", "y", "z", "speed_m_s", "ceiling_gap_m", "current_a", "soc", "sortie", "ground_gap_m",
                    "phase", "assumed_free"]


@pytest.fixture(scope="module")
def both(bridge_both):
    return bridge_both[0]


@pytest.fixture(scope="module")
def cli_both(tmp_path_factory):
    out = tmp_path_factory.mktemp("cli") / "both"
    subprocess.run([os.environ["CEILPLAN_EXE"], "tour", "--mission", str(MAPS / "bridge.yaml"), "--mode", "both",
                    "--out", str(out)], check=True, capture_output=True)
    return out


def read_path_csv(file):
    lines = [line for line in Path(file).read_text().splitlines() if not line.startswith("#")]
    rows = list(csv.reader(lines))
    return rows[0], rows[1:]


def test_mode_both_is_the_command_lines(both, cli_both, tmp_path):
    assert isinstance(both, ceilplan.TourComparison)
    assert (both.ceiling.mode, both.free.mode) == ("ceiling", "free")
    for mode, tour in (("ceiling", both.ceiling), ("free", both.free)):
        cli = json.loads((cli_both / mode / "tour.json").read_text())
        assert tour.charge_ah == pytest.approx(cli["charge_ah"], abs=1e-9), mode
        assert tour.fec == pytest.approx(cli["fec"], abs=1e-12), mode
    # The table it prints and the comparison it writes, to the character.
    assert both.table == (cli_both / "comparison.txt").read_text()
    written = json.loads((cli_both / "comparison.json").read_text())
    written.pop("provenance")
    assert both.comparison == written
    assert both.comparison["reduction_pct"]["charge"] > 0.0  # the deck saves charge
    # Its files are the command line's.
    out = tmp_path / "both"
    both.write(out)
    assert sorted(p.relative_to(out) for p in out.rglob("*")) == sorted(p.relative_to(cli_both)
                                                                       for p in cli_both.rglob("*"))
    provenance = json.loads((out / "comparison.json").read_text())["provenance"]["command"]
    assert "plan_tour(mission, mode='both'" in provenance and ".write(" in provenance
    assert json.loads((out / "free" / "tour.json").read_text())["charge_ah"] == both.free.charge_ah


def test_an_unknown_mode_is_refused_before_any_work():
    mission = ceilplan.Mission.load(MAPS / "bridge.yaml")
    started = time.monotonic()
    with pytest.raises(ValueError, match="ceiling.*free"):
        ceilplan.plan_tour(mission, mode="sideways")
    assert time.monotonic() - started < 1.0


def test_samples_are_path_csv_column_by_column(both, cli_both):
    for mode, tour in (("ceiling", both.ceiling), ("free", both.free)):
        header, rows = read_path_csv(cli_both / mode / "path.csv")
        samples = tour.samples
        assert header == PATH_CSV_COLUMNS
        assert list(samples) == header
        assert all(len(samples[name]) == len(rows) for name in header), mode
        for k, name in enumerate(header):
            field = [row[k] for row in rows]
            if name == "phase":
                assert list(samples[name]) == field
            elif name in ("sortie", "assumed_free"):
                assert [int(value) for value in samples[name]] == [int(value) for value in field], name
            else:  # written with 12 significant digits; an empty field is no surface, NaN
                written = np.array([float(value) if value else np.nan for value in field])
                np.testing.assert_allclose(samples[name], written, rtol=1e-11, atol=1e-12, equal_nan=True,
                                           err_msg=f"{mode} {name}")
        assert set(samples["phase"]) == {"leg", "dwell", "recharge"}
        assert samples["assumed_free"].dtype == bool


def test_route_samples_are_plan_path_csv(tmp_path):
    bridge = ceilplan.Environment.load(MAPS / "bridge.bt")
    start, goal = (6.0, 0.7, 5.85), (14.0, 0.7, 5.85)
    route = ceilplan.plan(bridge, start, goal, planner="lattice")
    subprocess.run([os.environ["CEILPLAN_EXE"], "plan", "--map", str(MAPS / "bridge.bt"), "--planner", "lattice",
                    "--start", ",".join(map(str, start)), "--goal", ",".join(map(str, goal)), "--out",
                    str(tmp_path / "cli")], check=True, capture_output=True)
    header, rows = read_path_csv(tmp_path / "cli" / "path.csv")
    assert list(route["samples"]) == header
    np.testing.assert_allclose(route["samples"]["ground_gap_m"],
                               [float(row[header.index("ground_gap_m")]) if row[header.index("ground_gap_m")]
                                else np.nan for row in rows], rtol=1e-11, equal_nan=True)


def test_sorties_carry_their_legs_and_waypoints(both, cli_both):
    for mode, tour in (("ceiling", both.ceiling), ("free", both.free)):
        written = json.loads((cli_both / mode / "tour.json").read_text())["sorties"]
        geojson = json.loads((cli_both / mode / "routes.geojson").read_text())
        sorties = tour.sorties
        assert len(sorties) == len(written)
        for k, sortie in enumerate(sorties):
            assert isinstance(sortie, ceilplan.Sortie)
            assert sortie["sortie"] == k + 1
            # tour.json's sortie, legs and their waypoints included
            assert {key: sortie[key] for key in written[k]} == written[k]
            assert all(isinstance(leg, ceilplan.Leg) for leg in sortie["legs"])
            assert sortie["legs"][0]["from"] == "home" and sortie["legs"][-1]["to"] == "home"
            assert [leg["to"] for leg in sortie["legs"][:-1]] == sortie["targets"]
            # the waypoints the autopilot files and routes.geojson fly
            exported = [f["properties"] for f in geojson["features"]
                        if f["properties"]["kind"] == "waypoint" and f["properties"]["sortie"] == k + 1]
            assert sortie["waypoints"] == exported
            assert sum(w["take_photo"] for w in sortie["waypoints"]) == len(sortie["targets"])
            assert sortie["home"] == pytest.approx(sortie["legs"][0]["waypoints"][0])


def test_progress_reports_each_stage_from_the_calling_thread(bridge_both):
    _, reports, caller = bridge_both  # plan_tour(mission, mode="both", progress=...)
    assert {thread for _, _, thread in reports} == {caller}
    stages = [stage for stage, _, _ in reports]
    assert stages[0].startswith("indexing ") and stages[0].endswith("bridge.bt")
    assert any(stage.startswith("ceiling mode: ") for stage in stages)
    assert any(stage.startswith("free mode: ") for stage in stages)
    assert all(isinstance(stage, str) and 0.0 <= fraction <= 1.0 for stage, fraction, _ in reports)
    ends = {stage for stage, fraction, _ in reports if fraction == 1.0}
    assert {"ceiling mode: building the roadmap", "free mode: building the roadmap"} <= ends
    # The two modes are planned at once (docs/python.md, "Progress and Ctrl-C"): their stages
    # interleave, and within a stage a mode's fraction never goes back.
    last = {}
    for stage, fraction, _ in reports:
        assert fraction >= last.get(stage, 0.0) or fraction == 0.0, (stage, fraction, last.get(stage))
        last[stage] = fraction


class Stop(Exception):
    pass


@pytest.mark.parametrize("after", [1, 5])
def test_an_exception_raised_by_progress_cancels_the_tour_and_comes_out(after):
    calls = []

    def progress(stage, fraction):
        calls.append(stage)
        if len(calls) == after:
            raise Stop(f"stopped at {stage}")

    mission = ceilplan.Mission.load(MAPS / "bridge.yaml")
    with pytest.raises(Stop, match="stopped at"):
        ceilplan.plan_tour(mission, mode="both", progress=progress)
    assert len(calls) == after  # cancelled: never called again
    assert ceilplan.duty(days=1)["study_days"] == 1  # and the module works on


def test_progress_must_be_callable():
    with pytest.raises(ValueError, match="progress must be a callable"):
        ceilplan.plan_tour(ceilplan.Mission.load(MAPS / "open.yaml"), progress="yes")


def test_other_threads_run_while_a_map_loads_with_progress():
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.01)

    thread = threading.Thread(target=tick)
    thread.start()
    try:
        before = len(ticks)
        stages = []
        ceilplan.Environment.load(MAPS / "bridge.bt", progress=lambda stage, fraction: stages.append(stage))
        assert len(ticks) > before + 5  # the GIL was released while the library worked
        assert stages and stages[-1].startswith("indexing ") and stages[-1].endswith("bridge.bt")
    finally:
        stop.set()
        thread.join()


def test_ctrl_c_stops_a_tour_with_keyboard_interrupt():
    mission = ceilplan.Mission.load(MAPS / "bridge.yaml")
    stages = []

    # Ctrl-C at the tour's first report (a timer a second in raced the roadmaps, which both build
    # within 1.1 to 1.5 s of the start on this machine).
    def progress(stage, fraction):
        stages.append((stage, fraction))
        if len(stages) == 1:
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        ceilplan.plan_tour(mission, mode="both", progress=progress)
    # Stopped long before the two modes (planned at once) have both built their roadmaps, as a
    # whole tour does (a KeyboardInterrupt after plan_tour had returned would have let every
    # stage through).
    ends = {stage for stage, fraction in stages if fraction == 1.0}
    assert stages and not {"ceiling mode: building the roadmap", "free mode: building the roadmap"} <= ends
