"""Input files from Python: the library's checks, so a FIFO, a device or a directory is refused
as a map before it is opened, and a missing map names the file."""

import os
import subprocess
import sys

import pytest

import ceilplan


def test_a_missing_map_names_the_file(tmp_path):
    with pytest.raises(ceilplan.InputError, match="none.bt: no such map file"):
        ceilplan.Environment.load(tmp_path / "none.bt")


@pytest.mark.parametrize("kind", ["fifo", "device", "directory"])
def test_a_map_that_is_not_a_regular_file_is_refused_without_blocking(tmp_path, kind):
    if kind == "fifo":
        path = tmp_path / "pipe.bt"
        os.mkfifo(path)
        says = "is a FIFO (named pipe), not a map file"
    elif kind == "device":
        path = "/dev/zero"
        says = "is a device, not a map file"
    else:
        path = tmp_path / "folder.bt"
        path.mkdir()
        says = "is a directory, not a map file"
    # In a child process with a timeout: a reader blocked on the FIFO fails the test, not hangs it.
    script = ("import sys, ceilplan\n"
              "try:\n    ceilplan.Environment.load(sys.argv[1])\n"
              "except ceilplan.InputError as e:\n    print(e)\n    sys.exit(2)\n")
    result = subprocess.run([sys.executable, "-c", script, str(path)], capture_output=True, text=True, timeout=60)
    assert result.returncode == 2, result.stderr
    assert says in result.stdout


def test_a_missions_wind_reads_and_sets_as_the_files_key():
    mission = ceilplan.Mission.load(os.path.join(os.environ["CEILPLAN_SOURCE_DIR"], "maps", "bridge.yaml"))
    assert mission.wind == {"speed_m_s": 0.0, "from_deg": 0.0, "gust_m_s": 0.0, "sheltered_fraction": 0.0}
    mission.wind = {"speed_m_s": 8, "from_deg": 90, "gust_m_s": 3}
    assert mission.wind["speed_m_s"] == 8.0 and mission.wind["from_deg"] == 90.0 and mission.wind["gust_m_s"] == 3.0
    with pytest.raises(ceilplan.InputError, match="unknown key 'gusts'"):
        mission.wind = {"speed_m_s": 8, "from_deg": 90, "gusts": 3}
    with pytest.raises(ceilplan.InputError, match="from_deg must be in"):
        mission.wind = {"speed_m_s": 8, "from_deg": 360}
    with pytest.raises(ceilplan.InputError, match="missing key 'from_deg'"):
        mission.wind = {"speed_m_s": 8}
    assert mission.wind["from_deg"] == 90.0  # a refused wind leaves the last one
