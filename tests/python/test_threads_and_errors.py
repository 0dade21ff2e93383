"""The module from several threads at once, without numpy, and its exceptions: the same checks
and messages as the command line, Python's exception classes for bad values and files."""

import errno
import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import ceilplan

SOURCE = Path(os.environ["CEILPLAN_SOURCE_DIR"])
MAPS = SOURCE / "maps"
CLI = os.environ["CEILPLAN_EXE"]
START, GOAL = (6.0, 0.7, 5.85), (14.0, 0.7, 5.85)


def run_python(script, timeout_s):
    """Runs `script` in a fresh interpreter (the module's first calls are what race); a hang
    fails the test at the timeout instead of hanging the suite."""
    return subprocess.run([sys.executable, "-c", textwrap.dedent(script)], capture_output=True, text=True,
                          timeout=timeout_s, env=os.environ)


def test_threads_calling_the_module_at_once_never_deadlock():
    # First two threads whose first plans coincide (one query: they finish together and build
    # their first numpy arrays at once; this hung every run), then a plan, an evaluation, a duty
    # study and a map load at once, each time from threads released together in a fresh interpreter.
    script = f"""
        import json, threading
        import ceilplan
        bridge = ceilplan.Environment.load({str(MAPS / "bridge.bt")!r})

        def at_once(calls):
            results = [None] * len(calls)
            start = threading.Barrier(len(calls))
            def run(k):
                start.wait()
                results[k] = calls[k]()
            threads = [threading.Thread(target=run, args=(k,)) for k in range(len(calls))]
            for t in threads: t.start()
            for t in threads: t.join()
            return results

        plan = lambda: ceilplan.plan(bridge, {START}, {GOAL}, planner="lattice")["charge_ah"]
        first = at_once([plan, plan])
        mixed = at_once([plan, lambda: ceilplan.evaluate(bridge, [{START}, {GOAL}])["charge_ah"],
                         lambda: float(ceilplan.duty(days=1)["cases"][0]["fec"]),
                         lambda: ceilplan.Environment.load({str(MAPS / "bridge.bt")!r}).resolution_m])
        print(json.dumps(first + mixed))
    """
    for _ in range(3):  # each run a fresh interpreter, whose first calls race
        try:
            done = run_python(script, timeout_s=120)
        except subprocess.TimeoutExpired:
            pytest.fail("threads calling the module at once deadlocked (no answer in 120 s)")
        assert done.returncode == 0, done.stderr
        plan_a, plan_b, plan_c, evaluated, fec, resolution_m = json.loads(done.stdout)
        assert plan_a == plan_b == plan_c  # the lattice planner is deterministic, whichever thread runs it
        assert evaluated > 0.0 and fec > 0.0 and resolution_m == 0.1


def test_importing_without_numpy_names_what_is_missing():
    done = run_python("""
        import sys
        sys.modules["numpy"] = None  # as in an interpreter without numpy
        import ceilplan
    """, timeout_s=60)
    assert done.returncode != 0
    last_line = done.stderr.strip().splitlines()[-1]
    assert last_line.startswith("ImportError: ceilplan needs numpy for this interpreter")
    assert "python3-numpy" in last_line and "pip install numpy" in last_line


@pytest.fixture(scope="module")
def bridge():
    return ceilplan.Environment.load(MAPS / "bridge.bt")


def cli_error(*args):
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 2, done.stderr
    return done.stderr


def test_a_lattice_spacing_the_command_line_refuses_is_a_value_error(bridge, tmp_path):
    with pytest.raises(ValueError, match=r"lattice spacing must be a finite number in \[0\.01, 2\] m, got 1e-09"):
        ceilplan.plan(bridge, START, GOAL, lattice_spacing_m=1e-9)
    with pytest.raises(ValueError, match="lattice spacing"):  # whichever planner, as on the command line
        ceilplan.plan(bridge, START, GOAL, planner="BITstar", lattice_spacing_m=3.0)
    assert "must be a finite number in [0.01, 2], got 1e-9" in cli_error(
        "plan", "--map", MAPS / "bridge.bt", "--start", "6,0.7,5.85", "--goal", "14,0.7,5.85",
        "--lattice-spacing-m", "1e-9", "--out", tmp_path / "out")


def test_a_path_of_one_repeated_point_is_a_value_error(bridge, tmp_path):
    message = "a path needs at least 2 distinct points"
    with pytest.raises(ValueError, match=message):
        ceilplan.evaluate(bridge, [START, START])
    path = tmp_path / "path.csv"
    path.write_text("x,y,z\n6,0.7,5.85\n6,0.7,5.85\n")
    assert message in cli_error("evaluate", "--map", MAPS / "bridge.bt", "--path", path)
    # A repeated point among distinct ones is dropped, by both.
    repeated = ceilplan.evaluate(bridge, [START, START, GOAL])
    assert repeated["charge_ah"] == ceilplan.evaluate(bridge, [START, GOAL])["charge_ah"]


def test_seed_zero_is_a_value_error_as_on_the_command_line(bridge, tmp_path):
    mission = ceilplan.Mission.load(MAPS / "bridge.yaml")
    with pytest.raises(ValueError, match=r"seed must be > 0"):
        ceilplan.plan_tour(mission, seed=0)
    with pytest.raises(ValueError, match=r"seed must be > 0"):
        ceilplan.plan(bridge, START, GOAL, seed=0)
    assert "--seed" in cli_error("tour", "--mission", MAPS / "bridge.yaml", "--seed", "0", "--out", tmp_path / "t")
    # Names the tour cannot use are refused as soon, before the map is indexed.
    with pytest.raises(ValueError, match="unknown ageing model 'miner'"):
        ceilplan.plan_tour(mission, ageing_model="miner")
    with pytest.raises(ValueError, match="FastestStar"):
        ceilplan.plan_tour(mission, planner="FastestStar")


@pytest.mark.parametrize("load", [
    lambda path: ceilplan.Environment.load(path),
    lambda path: ceilplan.Environment.load(MAPS / "bridge.bt", battery=path),
    lambda path: ceilplan.Vehicle.load(path),
    lambda path: ceilplan.Mission.load(path),
], ids=["map", "battery", "vehicle", "mission"])
def test_input_files_raise_os_errors(load, tmp_path):
    with pytest.raises(FileNotFoundError, match="nowhere") as missing:
        load(tmp_path / "nowhere")
    assert missing.value.errno == errno.ENOENT
    assert isinstance(missing.value, ceilplan.InputError)  # still ceilplan's, and a bad value
    with pytest.raises(OSError, match="is a directory") as directory:
        load(tmp_path)
    assert directory.value.errno == errno.EISDIR
    assert not isinstance(directory.value, FileNotFoundError)
    assert isinstance(directory.value, ceilplan.InputFileError)


def test_a_device_as_a_map_is_refused_not_read_until_memory_runs_out():
    with pytest.raises(OSError, match="/dev/zero: is a device"):
        ceilplan.Environment.load("/dev/zero")


def test_values_out_of_range_are_value_errors_with_the_librarys_message(bridge):
    with pytest.raises(ValueError, match=r"point 2 has a non-finite coordinate"):
        ceilplan.evaluate(bridge, [START, (float("nan"), 0.7, 5.85)])
    # 1e9 years once overflowed into "a study of -72220160 days".
    with pytest.raises(ValueError, match=r"the study's years must be a finite number in \[0, 100\], got 1e\+09"):
        ceilplan.duty(years=1e9)
