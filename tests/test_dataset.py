"""Labelled vibration data sets (studies/dataset.py, issue 50 item 4): the grid, each case's
signal and labels, the resume and its guard, bad input refused by name."""
import csv
import json
from dataclasses import replace

import numpy as np
import pytest

from contact.surface import Defect, SurfaceModel
from exudyn_bearing import REFERENCE_BEARING, BearingSetup
from exudyn_bearing.studies import dataset as ds
from exudyn_bearing.studies.masking import Masking

SHORT = ds.CaseSettings(time=0.06, settle=0.005)


@pytest.fixture(scope="module")
def small_set(tmp_path_factory):
    """A perfect bearing and a 1-mm outer-race notch, one process."""
    out = tmp_path_factory.mktemp("set")
    return ds.dataset(out=out, faults=("none", "outer"), sizes=(1e-3,), settings=SHORT, workers=1, progress=None)


def test_each_case_holds_its_signal_and_labels(small_set):
    """One row per case in index.csv; each NPZ holds the signal at the sample rate over the run
    and its labels; the outer notch's passages come at the run's actual BPFO (their spacing read
    from the balls' positions, the frequency from the mean cage speed)."""
    rows = list(csv.DictReader(open(small_set.folder / "index.csv")))
    assert [r["fault"] for r in rows] == ["none", "outer"]
    assert all(r["error"] == "" for r in rows)
    for row in rows:
        data = np.load(small_set.folder / row["file"])
        assert data["t_s"].size == round(SHORT.time * SHORT.sample_rate) + 1
        assert data["acceleration_m_s2"].shape == (data["t_s"].size, 3)
        assert np.all(np.isfinite(data["signal_m_s2"]))
        labels = json.loads(str(data["labels"]))
        assert labels["fault"] == row["fault"] and labels["size_m"] == float(row["size_m"])
        assert float(row["BPFO_Hz"]) == pytest.approx(labels["fault_frequencies_Hz"]["actual"]["BPFO"])
        assert float(json.loads(str(data["inputs"]))["rpm"]) == 1800.0
    healthy, notch = (np.load(small_set.folder / r["file"]) for r in rows)
    assert healthy["passage_edge_s"].size == 0
    edges = np.sort(notch["passage_edge_s"])
    assert edges.size >= 8
    assert 1.0 / np.median(np.diff(edges)) == pytest.approx(float(notch["actual_BPFO_Hz"]), rel=0.02)
    impacts = notch["passage_impact_s"]
    assert np.all((impacts[np.isfinite(impacts)] > notch["passage_edge_s"][np.isfinite(impacts)]))
    # the notch's envelope line at BPFO, the perfect bearing's far weaker
    assert float(rows[1]["envelope_line_Hz"]) == pytest.approx(float(rows[1]["BPFO_Hz"]), rel=0.03)
    assert float(rows[0]["envelope_line_m_s2"]) < 0.01 * float(rows[1]["envelope_line_m_s2"])


def test_a_resume_serves_only_cases_of_the_same_inputs(small_set, tmp_path, monkeypatch):
    """A second call runs nothing; a case whose file is gone runs again; other settings, another
    bearing or another fault depth are refused by name."""
    import shutil

    folder = shutil.copytree(small_set.folder, tmp_path / "set")
    ran = []
    real = ds._run_case
    monkeypatch.setattr(ds, "_run_case", lambda job: ran.append(job[0].key) or real(job))
    again = ds.dataset(out=folder, faults=("none", "outer"), sizes=(1e-3,), settings=SHORT, workers=1,
                       progress=None)
    assert ran == [] and len(again.cases) == 2
    (folder / again.cases[0].file).unlink()
    monkeypatch.setattr(ds, "_run_case", lambda job: ran.append(job[0].key) or
                        {**vars(replace(job[0], file="x.npz", error="RuntimeError: stopped"))})
    ds.dataset(out=folder, faults=("none", "outer"), sizes=(1e-3,), settings=SHORT, workers=1,
               progress=None)
    assert ran == [again.cases[0].key]
    with pytest.raises(ValueError, match="out: .*dataset_settings"):
        ds.dataset(out=folder, faults=("none",), settings=replace(SHORT, depth=0.1e-3), workers=1,
                   progress=None)
    with pytest.raises(ValueError, match="out: .*bearing"):
        ds.dataset(replace(REFERENCE_BEARING, balls=15), out=folder, faults=("none",), settings=SHORT,
                   workers=1, progress=None)


def test_the_grid_and_the_seeds(tmp_path, monkeypatch):
    """faults x sizes x loads x speeds, one perfect case per load and speed; with masking each
    case gets the seed plus its place, so no two share noise."""
    jobs = []
    monkeypatch.setattr(ds, "_run_case", lambda job: jobs.append(job) or {**vars(replace(job[0], file=None))})
    settings = replace(SHORT, masking=Masking(snr_db=10.0, seed=7))
    result = ds.dataset(out=tmp_path, faults=("none", "inner", "ball"), sizes=(0.5e-3, 1e-3), axial_force=(500, 900),
                        radial_force=(0,), rpm=(1200, 1800), settings=settings, workers=1, progress=None)
    assert len(result.cases) == 2 * 2 * (1 + 2 + 2)
    seeds = [job[3].masking.seed for job in jobs]
    assert sorted(seeds) == list(range(7, 7 + len(jobs)))
    assert [c.seed for c in result.cases] == seeds
    surfaces = {job[0].fault: ds.fault_surface(SurfaceModel(), job[1], job[0].size, job[3].depth) for job in jobs}
    assert surfaces["none"].defects == ()
    assert surfaces["ball"].defects[0].race == "ball" and surfaces["ball"].defects[0].ball == 0
    assert surfaces["inner"].defects[0].depth == SHORT.depth


@pytest.mark.parametrize("kwargs, name", [
    (dict(faults=("cage",)), "faults"), (dict(faults=("outer", Defect("outer", 10.0, 1e-3, 1e-5))), "faults"),
    (dict(sizes=(0.0,)), "sizes"), (dict(sizes=(float("nan"),)), "sizes"), (dict(rpm=(-5.0,)), "rpm"),
    (dict(axial_force=(0.0,), radial_force=(0.0,)), "axial_force, radial_force"),
    (dict(axial_force=(-1.0,)), "axial_force"), (dict(settings=dict(time=0.1)), "settings"),
])
def test_bad_input_is_refused_by_name(tmp_path, kwargs, name):
    with pytest.raises(ValueError, match=name):
        ds.dataset(out=tmp_path, workers=1, progress=None, **kwargs)


@pytest.mark.parametrize("field, value", [("time", 0.0), ("sample_rate", -1.0), ("depth", float("nan")),
                                          ("settle", 0.5), ("band", (5000.0, 100.0)), ("band", "kurtosis"),
                                          ("masking", 3.0)])
def test_bad_settings_are_refused_by_name(field, value):
    with pytest.raises(ValueError, match=f"settings.{field}|band"):
        ds.CaseSettings(**{field: value})


def test_a_bearing_with_its_own_defects_is_refused(tmp_path):
    faulty = BearingSetup(REFERENCE_BEARING, surface=SurfaceModel((Defect("outer", 0.0, 1e-3, 1e-5),)))
    with pytest.raises(ValueError, match="bearing: .*defect"):
        ds.dataset(faulty, out=tmp_path, workers=1, progress=None)


@pytest.mark.slow
def test_a_dask_cluster_writes_the_same_cases(small_set, tmp_path):
    """The set on a local Dask cluster: the same cases, labels to the solver's tolerance."""
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        remote = ds.dataset(out=tmp_path, faults=("none", "outer"), sizes=(1e-3,), settings=SHORT, client=client,
                            progress=None)
    for a, b in zip(small_set.cases, remote.cases):
        assert a.key == b.key and b.error is None and (tmp_path / b.file).is_file()
        assert b.kinematic_cage_slip_percent == pytest.approx(a.kinematic_cage_slip_percent, rel=1e-3)
        assert b.passages == a.passages
