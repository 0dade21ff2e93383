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
