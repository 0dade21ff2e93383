"""Every public name of the module says what it is, and every result prints as one short line."""

import inspect
import os
from pathlib import Path

import numpy as np
import pytest

import ceilplan

MAPS = Path(os.environ["CEILPLAN_SOURCE_DIR"]) / "maps"
RESULT_TYPES = ["Route", "Evaluation", "Samples", "Sortie", "Leg", "Probe", "Photos", "Coverage", "DutyStudy",
                "DutyCase", "MapImport", "Proposal"]


def described(obj):
    """The text of a docstring beyond the signature line pybind11 writes for any function."""
    doc = inspect.getdoc(obj) or ""
    lines = [line for line in doc.splitlines() if line.strip()]
    name = getattr(obj, "__name__", "")
    if lines and name and lines[0].startswith(name + "("):
        lines = lines[1:]
    return " ".join(lines)


def public_members(cls):
    """What the class itself defines (not what it inherits from dict or object), dunders left out."""
    return [(name, value) for name, value in vars(cls).items() if not name.startswith("_")]


def test_every_public_function_class_and_property_has_a_docstring():
    missing = []
    assert described(ceilplan)
    for name, obj in vars(ceilplan).items():
        if name.startswith("_"):
            continue
        if inspect.isclass(obj):
            if not described(obj):
                missing.append(name)
            for member, value in public_members(obj):
                target = value.fget if isinstance(value, property) else value
                if not described(target) and not (isinstance(value, property) and described(value)):
                    missing.append(f"{name}.{member}")
        elif callable(obj) and not described(obj):
            missing.append(name)
    assert missing == []


def test_docstrings_list_the_values_an_argument_takes():
    plan_tour = inspect.getdoc(ceilplan.plan_tour)
    for value in ("'ceiling'", "'free'", "'both'", "'roadmap'", "'lattice'", "'xu'", "'woehler'", "'schmalstieg'",
                  "progress(stage, fraction)"):
        assert value in plan_tour
    plan = inspect.getdoc(ceilplan.plan)
    for value in ("'length'", "'time'", "'charge'", "'fec'", "'ageing'", "'BITstar'", "'lattice'"):
        assert value in plan
    for value in ("'occupied'", "'free'", "'fill'"):
        assert value in inspect.getdoc(ceilplan.Environment.load)
    assert "'zenmuse_h20_wide'" in inspect.getdoc(ceilplan.propose)


def test_the_result_types_are_dicts_with_their_keys_documented():
    for name in RESULT_TYPES:
        cls = getattr(ceilplan, name)
        assert issubclass(cls, dict), name
        assert cls.__module__ == "ceilplan"
    assert "ground_gap_m" in ceilplan.Samples.__doc__ and "'recharge'" in ceilplan.Samples.__doc__


def short(text, type_name):
    assert "\n" not in text
    assert text.startswith(type_name + "("), text
    assert len(text) <= 240, text
    return text


@pytest.fixture(scope="module")
def bridge():
    return ceilplan.Environment.load(MAPS / "bridge.bt")


def test_results_print_as_one_short_line_with_units(bridge, bridge_both):
    quad = ceilplan.Vehicle.default()
    assert short(repr(quad), "Vehicle") == f"Vehicle(name='{quad.name}')"
    assert "resolution_m=0.1" in short(repr(bridge), "Environment")
    mission = ceilplan.Mission.load(MAPS / "open.yaml")
    assert "targets=" in short(repr(mission), "Mission") and "open.yaml" in repr(mission)

    probe = bridge.probe(10.0, 0.0, 5.5)
    assert isinstance(probe, ceilplan.Probe)
    assert short(repr(probe), "Probe").startswith("Probe(valid=True, clearance_m=")

    route = ceilplan.plan(bridge, (6.0, 0.7, 5.85), (14.0, 0.7, 5.85), planner="lattice")
    assert isinstance(route, ceilplan.Route)
    text = short(repr(route), "Route")
    assert "planner='lattice'" in text and f"charge_ah={route['charge_ah']:.4f}" in text
    check = ceilplan.evaluate(bridge, route["waypoints"])
    assert isinstance(check, ceilplan.Evaluation)
    assert short(repr(check), "Evaluation").startswith("Evaluation(valid=True, length_m=")
    samples = route["samples"]
    assert isinstance(samples, ceilplan.Samples)
    assert f"rows={len(samples['t_s'])}" in short(repr(samples), "Samples")

    both = bridge_both[0]
    text = short(repr(both), "TourComparison")
    assert f"ceiling={both.ceiling.charge_ah:.4f}" in text and f"free={both.free.charge_ah:.4f}" in text
    tour = both.ceiling
    assert isinstance(tour, ceilplan.Tour)
    text = short(repr(tour), "Tour")
    assert text.startswith("Tour(mode='ceiling', ") and f"charge_ah={tour.charge_ah:.4f}" in text
    assert "duration_s=" in text and f"sorties={len(tour.sorties)}" in text
    sortie = tour.sorties[0]
    assert short(repr(sortie), "Sortie").startswith("Sortie(sortie=1, targets=")
    assert short(repr(sortie["legs"][0]), "Leg").startswith("Leg('home' -> ")
    assert short(repr(tour.samples), "Samples")

    study = ceilplan.duty(days=1)
    assert short(repr(study), "DutyStudy").startswith("DutyStudy(study_days=1, 9.5 A: fec=")
    assert short(repr(study["cases"][1]), "DutyCase").startswith("DutyCase(flight_current_a=8.00, ")

    # A result is still the dict it was: equal to one, and serialisable as one.
    assert dict(route) == route and route["charge_ah"] == check["charge_ah"]
    assert isinstance(samples["t_s"], np.ndarray)


def test_results_built_from_dicts_print_their_figures():
    photos = ceilplan.Photos({"index": np.arange(1, 4), "region": ["deck", "deck", "pier"]})
    assert repr(photos) == "Photos(photos=3, regions=['deck', 'pier'])"
    coverage = ceilplan.Coverage({"photos": 3, "regions": [{"name": "deck", "covered_reachable_pct": 99.96}]})
    assert repr(coverage) == "Coverage(photos=3, deck covered_reachable_pct=100.0)"
    summary = ceilplan.MapImport({"map": "deck.bt", "kind": "mesh", "resolution_m": 0.1})
    assert repr(summary) == "MapImport(map='deck.bt', kind='mesh', resolution_m=0.100)"
    proposal = ceilplan.Proposal({"regions": [{}, {}], "overhead_area_m2": 12.34, "home": [0.0, 0.0, 0.5],
                                  "mission": Path("out/proposed.yaml")})
    assert repr(proposal) == "Proposal(regions=2, overhead_area_m2=12.3, home=[0.0, 0.0, 0.5], " \
                             "mission='out/proposed.yaml')"
