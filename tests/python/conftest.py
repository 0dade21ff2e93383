"""Fixtures shared by the Python tests: what takes long is planned once per session."""

import os
import threading
from pathlib import Path

import pytest

import ceilplan


@pytest.fixture(scope="session")
def bridge_both():
    """The bridge's tour in both modes, with the progress reports received while it was planned:
    (TourComparison, [(stage, fraction, thread id)], the planning thread's id)."""
    reports = []

    def progress(stage, fraction):
        reports.append((stage, fraction, threading.get_ident()))

    mission = ceilplan.Mission.load(Path(os.environ["CEILPLAN_SOURCE_DIR"]) / "maps" / "bridge.yaml")
    both = ceilplan.plan_tour(mission, mode="both", progress=progress)
    return both, reports, threading.get_ident()
