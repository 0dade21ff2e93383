"""ceilplan.duty(): the founding paper's duty study (Kocer et al. 2019, arXiv 1812.11707) with the
CLI's defaults. The paper's figures are regression tests: exactly as its equations give them, and
at the precision the paper prints them."""

import json
import os
import subprocess

import numpy as np
import pytest

import ceilplan

FREE, CEILING = 9.5, 8.0  # A: free flight and under the ceiling (paper)


@pytest.fixture(scope="module")
def paper():
    return ceilplan.duty()


def test_defaults_are_the_papers_two_cases(paper):
    assert [c["flight_current_a"] for c in paper["cases"]] == [FREE, CEILING]
    assert paper["study_days"] == 30
    assert paper["span"] == "30 days"
    assert list(paper["cases"][0]["ageing"]) == ["fec", "xu", "schmalstieg", "woehler"]


@pytest.mark.parametrize("case, current_a, min_soc_pct, charge_end_min, fec_per_mission, fec_per_day, fec_30_days", [
    (0, FREE, 34.1, 43.5, 0.6090, 9.14, 274.0),
    (1, CEILING, 43.7, 40.5, 0.5128, 7.69, 230.8),
])
def test_the_papers_table(paper, case, current_a, min_soc_pct, charge_end_min, fec_per_mission, fec_per_day,
                          fec_30_days):
    c = paper["cases"][case]
    # Exactly: a 20-min flight takes I / 3 Ah of the 5.2 Ah pack; each mission charges it back.
    dod = current_a / 3.0 / 5.2
    assert c["min_soc"] == pytest.approx(0.95 - dod, abs=1e-12)
    assert c["max_dod"] == pytest.approx(dod, abs=1e-12)
    assert c["fec_per_mission"] == pytest.approx(dod, abs=1e-9)
    assert c["fec"] == pytest.approx(450 * dod, abs=1e-9)
    assert c["charge_ah"] == pytest.approx(450 * current_a / 3.0, abs=1e-9)
    assert c["charge_end_s"] == pytest.approx(60 * charge_end_min, abs=1e-9)  # 30 s steps
    # As the paper prints them.
    assert round(100 * c["min_soc"], 1) == min_soc_pct
    assert round(c["fec_per_mission"], 4) == fec_per_mission
    assert c["fec_per_day"] == pytest.approx(fec_per_day, abs=0.006)  # the paper: 15 x its rounded 0.6090
    assert round(c["fec"], 1) == fec_30_days


def test_the_ceiling_effect_cuts_fec_by_15_point_8_percent(paper):
    assert paper["cases"][0]["fec_reduction_pct"] == 0.0
    reduction = paper["cases"][1]["fec_reduction_pct"]
    assert reduction == pytest.approx(100 * (1 - CEILING / FREE), abs=1e-9)
    assert round(reduction, 1) == 15.8


def test_each_ageing_model_wears_the_ceiling_pack_less(paper):
    free, ceiling = (c["ageing"] for c in paper["cases"])
    # One FEC: the fec model counts the first table's FEC.
    assert ceiling["fec"]["cycle_wear"] == pytest.approx(paper["cases"][1]["fec"], abs=1e-9)
    assert ceiling["fec"]["wear_reduction_new_pack_pct"] == pytest.approx(100 * (1 - CEILING / FREE), abs=1e-6)
    # Xu et al. 2018's constants (docs/ageing.md): cycle damage falls 18.2 % with the pack kept new.
    assert ceiling["xu"]["wear_reduction_new_pack_pct"] == pytest.approx(18.2, abs=0.05)
    for model in ("fec", "xu", "schmalstieg", "woehler"):
        assert paper["comparison_days"][model] == 30
        assert 0.0 < ceiling[model]["capacity_fade"] < free[model]["capacity_fade"], model
        assert ceiling[model]["fade_reduction_pct"] > 0.0, model
        assert ceiling[model]["days_to_end_of_life"] > free[model]["days_to_end_of_life"], model
        assert isinstance(ceiling[model]["soh_by_day"], np.ndarray)
        assert len(ceiling[model]["soh_by_day"]) >= 30
    assert free["xu"]["warnings"]  # fitted on LMO cells at 1C


def test_same_numbers_as_the_cli_with_its_defaults(paper, tmp_path):
    out = tmp_path / "duty.json"
    run = subprocess.run([os.environ["CEILPLAN_EXE"], "duty", "--json", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout == paper["table"]
    cli = json.loads(out.read_text())
    for ours, theirs in zip(paper["cases"], cli["cases"]):
        assert ours["fec"] == theirs["fec_total"]
        assert ours["min_soc"] == theirs["min_soc"]
        for model in theirs["ageing"]:
            assert ours["ageing"][model["model"]]["capacity_fade"] == model["capacity_fade"]
            assert ours["ageing"][model["model"]]["wear_reduction_pct"] == model["wear_reduction_pct"]


def test_first_day_samples_are_numpy_arrays(paper):
    day = paper["cases"][0]["first_day"]
    assert isinstance(day["soc"], np.ndarray) and day["soc"].shape == day["t_s"].shape
    assert day["soc"].min() == pytest.approx(paper["cases"][0]["min_soc"], abs=1e-12)
    assert np.all(np.diff(day["t_s"]) >= 0.0)


def test_years_and_no_models():
    study = ceilplan.duty(years=2, models=[], step_s=0.0)
    assert study["study_days"] == 730 and study["span"] == "730 days (2 years)"
    assert study["cases"][0]["ageing"] == {} and study["comparison_days"] == {}


def test_bad_options_raise_value_errors_and_a_depleted_pack_is_infeasible():
    with pytest.raises(ValueError, match="cuts each 45-min mission"):
        ceilplan.duty(step_s=0.1)
    with pytest.raises(ValueError, match="unknown"):
        ceilplan.duty(models=["rainbow"])
    with pytest.raises(ceilplan.InfeasibleError, match="case 9.50 A: mission 3 of day 1"):
        ceilplan.duty(charge_max_s=600.0, models=[])


def test_progress_reports_each_case_of_the_study():
    stages = set()
    ceilplan.duty(days=1, progress=lambda stage, fraction: stages.add(stage))
    assert any(stage.startswith("duty ") for stage in stages)
    assert len({stage for stage in stages if stage.startswith("duty ")}) == 2  # the paper's two flight currents
