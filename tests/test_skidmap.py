"""Skid-risk map engine (issue: main job): grid, incremental results, resume, failures,
thresholds, Hirano's criterion, and Dask execution identical to local processes."""
import json
import math

import pytest

from exudyn_bearing import REFERENCE_BEARING as B
from exudyn_bearing.studies import skidmap
from exudyn_bearing.criteria import hirano_minimum_axial
from exudyn_bearing.studies.skidmap import SkidMap, SkidPoint, parse_range, skid_map
from tests.helpers import record_keyword

SHORT = 0.003  # s simulated per point: these tests check the engine, not the physics


def test_parse_range():
    assert parse_range("200:3000:8")[0] == 200 and parse_range("200:3000:8")[-1] == 3000
    assert len(parse_range("200:3000:8")) == 8
    assert parse_range("900,1800, 2700") == [900.0, 1800.0, 2700.0]
    with pytest.raises(ValueError, match="range"):
        parse_range("1:2:x")


def test_hirano_reference_bearing():
    """Paper: gross sliding when Z F_c / F_a > 0.1; ~5.4 kN at 1800 rpm (issue text)."""
    w_c = 1800 * math.pi / 30 / 2 * (1 - 0.025 * math.cos(math.radians(40)) / 0.155)
    f_c = 0.064 * 0.0775 * w_c ** 2
    assert hirano_minimum_axial(B, 1800) == pytest.approx(10 * 16 * f_c, rel=1e-12)
    assert hirano_minimum_axial(B, 1800) == pytest.approx(5400, rel=0.01)


def test_threshold_interpolation():
    pts = [SkidPoint(a, 0.0, 1800.0, 0.1, kinematic_cage_slip_percent=s, cage_slip_percent=s, peak_ball_slip=0.1,
                     settled=True) for a, s in ((500, 8.0), (1000, 3.0), (2000, 0.5), (3000, 0.2))]
    t = SkidMap(B, pts).thresholds()[0]
    # between (1000 N, 3 %) and (2000 N, 0.5 %): 1000 + (3 - 1) / 2.5 * 1000
    assert t["minimum_axial"] == pytest.approx(1800.0) and t["note"] == "interpolated"
    assert t["hirano_minimum_axial"] == pytest.approx(hirano_minimum_axial(B, 1800))


@pytest.mark.slow
def test_local_run_writes_incrementally_and_resumes(tmp_path):
    lines = []
    result = skid_map(axial_force=[1300.0, 3000.0], rpm=[1800.0], time=SHORT, out=tmp_path, workers=2,
                      progress=lines.append)
    assert len(result.points) == 2 and all(p.error is None for p in result.points)
    journal = (tmp_path / "points.jsonl").read_text().splitlines()
    assert len(journal) == 2
    header = (tmp_path / "skid_map.csv").read_text().splitlines()[0].split(",")
    assert "kinematic_cage_slip_percent" in header
    assert "Hirano" in (tmp_path / "skid_map.md").read_text()
    # heavier load, less slip (a physics smoke check on the engine's plumbing)
    by_load = {p.axial: p for p in result.points}
    assert by_load[3000.0].kinematic_cage_slip_percent < by_load[1300.0].kinematic_cage_slip_percent
    # second call: nothing recomputed, same table
    lines.clear()
    again = skid_map(axial_force=[1300.0, 3000.0], rpm=[1800.0], time=SHORT, out=tmp_path, workers=2,
                     progress=lines.append)
    assert len((tmp_path / "points.jsonl").read_text().splitlines()) == 2
    assert lines and lines[0].startswith("resuming: 2 of 2")
    assert [p.kinematic_cage_slip_percent for p in again.points] == [p.kinematic_cage_slip_percent for p in result.points]


def test_failed_point_is_reported_and_the_rest_runs(tmp_path, monkeypatch):
    import exudyn_bearing.simulation.runner as sim

    real = sim.simulate

    def flaky(*args, **kwargs):
        if kwargs["axial_force"] == 999.0:
            raise sim.BearingSimulationError("ball 3 inner contact diverged")
        return real(*args, **kwargs)

    monkeypatch.setattr(sim, "simulate", flaky)
    result = skid_map(axial_force=[999.0, 3000.0], rpm=[1800.0], time=SHORT, out=tmp_path, workers=1, progress=None)
    bad, good = result.points
    assert bad.error is not None and "ball 3 inner contact diverged" in bad.error
    assert good.error is None and good.kinematic_cage_slip_percent is not None
    assert "failed: BearingSimulationError" in (tmp_path / "skid_map.md").read_text()
    assert json.loads((tmp_path / "points.jsonl").read_text().splitlines()[0])["error"]


@pytest.mark.slow
def test_dask_local_cluster_gives_identical_results(tmp_path):
    distributed = pytest.importorskip("dask.distributed")
    local = skid_map(axial_force=[1300.0, 3000.0], rpm=[1800.0], time=SHORT, workers=1, progress=None)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        remote = skid_map(axial_force=[1300.0, 3000.0], rpm=[1800.0], time=SHORT, client=client, progress=None)
    # Same points, same numbers to the solver's tolerance: the serial kernel (Dask worker
    # threads) and the threaded one (main thread) are compiled separately, and with fastmath
    # contraction their float32 traction sums may round differently (seen with the elastic
    # film: 1.50481 vs 1.50473 % on a fresh clone); Newton's relative tolerance is 1e-4.
    for a, b in zip(local.points, remote.points):
        assert a.key == b.key
        assert a.kinematic_cage_slip_percent == pytest.approx(b.kinematic_cage_slip_percent, rel=1e-3)
        assert a.cage_slip_percent == pytest.approx(b.cage_slip_percent, rel=1e-3)


def test_resume_refuses_results_of_other_inputs(tmp_path):
    """A map folder remembers its bearing, lubricant, drag, law and version; resuming with
    another bearing or law is refused instead of serving the old points."""
    import dataclasses

    from contact.ballrace import ContactLaw
    from exudyn_bearing import REFERENCE_BEARING, BearingSetup
    from exudyn_bearing.studies.skidmap import _check_inputs

    from exudyn_bearing.presets import REFERENCE_DRAG, REFERENCE_LUBRICANT

    setup = BearingSetup(REFERENCE_BEARING, REFERENCE_LUBRICANT, REFERENCE_DRAG, contact_law=ContactLaw())
    _check_inputs(tmp_path, setup)
    _check_inputs(tmp_path, setup)  # same inputs: fine
    other = dataclasses.replace(REFERENCE_BEARING, balls=15)
    with pytest.raises(ValueError, match="out: .*bearing"):
        _check_inputs(tmp_path, setup.replace(bearing=other))
    with pytest.raises(ValueError, match="out: .*contact_law"):
        _check_inputs(tmp_path, setup.replace(contact_law=ContactLaw(traction="crook")))
    old = tmp_path / "old"
    old.mkdir()
    (old / "points.jsonl").write_text("")
    with pytest.raises(ValueError, match="out: .*no record"):
        _check_inputs(old, setup)


def test_failed_points_are_retried_on_resume(tmp_path):
    """A point that failed (here: 1e9 N, no quasi-static equilibrium) is recorded with its
    error and run again by the next call into the same folder, not served from the journal."""
    lines = []
    first = skid_map(axial_force=[1e9], rpm=[1800.0], time=0.002, out=tmp_path, workers=1, progress=lines.append,
                     refine=False)
    assert first.points[0].error
    lines.clear()
    second = skid_map(axial_force=[1e9], rpm=[1800.0], time=0.002, out=tmp_path, workers=1, progress=lines.append,
                      refine=False)
    assert not any(line.startswith("resuming") for line in lines)
    assert second.points[0].error
    journal = (tmp_path / "points.jsonl").read_text().splitlines()
    assert len(journal) == 2  # both attempts recorded


@pytest.mark.parametrize("kw, name", [(dict(axial_force=[-1.0]), "axial_force"),
                                      (dict(radial_force=[float("nan")]), "radial_force"),
                                      (dict(rpm=[float("inf")]), "rpm"), (dict(time=0.0), "time"),
                                      (dict(axial_force=[0.0]), "axial_force")])
def test_grid_is_validated_before_any_run(kw, name, tmp_path):
    args = dict(axial_force=[1300.0], rpm=[1800.0], time=0.002, out=tmp_path, workers=1, progress=None)
    args.update(kw)
    with pytest.raises(ValueError, match=name):
        skid_map(**args)
    assert not (tmp_path / "points.jsonl").exists()


def test_until_settled_doubles_the_run_up_to_the_cap(monkeypatch, tmp_path):
    """time=None: 0.1 s, 0.2 s, ... until settled, capped. With the first run and the cap
    shrunk to 2 and 8 ms (shorter than the 50 ms a run needs to be judged), the point is run
    at 2, 4 and 8 ms and reported too short to judge at the cap; the markdown says so."""
    monkeypatch.setattr(skidmap, "FIRST_TIME", 0.002)
    monkeypatch.setattr(skidmap, "MAX_TIME", 0.008)
    from exudyn_bearing.simulation import runner

    lengths = record_keyword(monkeypatch, runner, "simulate", "time")
    table = skid_map(axial_force=[1300.0], rpm=[1800.0], time=None, out=tmp_path, workers=1, progress=None,
                     refine=False)
    assert lengths == [0.002, 0.004, 0.008]
    point = table.points[0]
    assert point.simulated_time == 0.008 and point.settled is None and point.time is None
    assert "too short to judge at the cap (0.008 s)" in (tmp_path / "skid_map.md").read_text()


def test_thresholds_refined_on_workers_are_those_refined_here():
    """The thresholds refined on a :class:`CaseRunner`'s two worker processes (as
    :func:`skid_map` refines them, on the workers that ran the points) are, dict for dict,
    the ones refined one after another in this process: the same bisection and runs, only
    elsewhere; two speeds, each bracketed by its grid."""
    from exudyn_bearing.studies.grid import CaseRunner

    pts = [SkidPoint(a, 0.0, rpm, 0.1, kinematic_cage_slip_percent=s, cage_slip_percent=s, peak_ball_slip=0.1,
                     settled=True) for rpm, grid in ((900.0, ((800, 2.2), (1500, 0.27))),
                                                     (1800.0, ((1500, 2.5), (3000, 0.23)))) for a, s in grid]
    result = SkidMap(B, pts)
    here = result.refine_thresholds(confirm_time=0.002, tolerance=0.2)
    with CaseRunner(2) as runner:
        there = result.refine_thresholds(confirm_time=0.002, tolerance=0.2, runner=runner)
    assert [t["rpm"] for t in here] == [900.0, 1800.0] and all("bracket" in t for t in here)
    assert there == here


def test_refinement_takes_the_grid_points_steady_states_and_finds_the_same_threshold(monkeypatch):
    """The bisection's ends are grid points whose runs started from their steady state: with
    the map's own setup it takes those (two steady solves fewer) and refines to the very
    entry it finds solving them; with another oil it solves them again."""
    from dataclasses import replace

    from exudyn_bearing.setup import BearingSetup
    from exudyn_bearing.solvers.steady import steady_state

    setup = BearingSetup(B)
    calls = record_keyword(monkeypatch, skidmap, "steady_state", "axial_force")

    def refined(steady, **kw):
        pts = [SkidPoint(a, 0.0, 900.0, 0.1, kinematic_cage_slip_percent=s, cage_slip_percent=s, peak_ball_slip=0.1,
                         settled=True, steady_kinematic_cage_slip_percent=steady(a))
               for a, s in ((800.0, 2.2), (1500.0, 0.27))]
        calls.clear()
        out = SkidMap(B, pts, setup=setup).refine_thresholds(confirm_time=None, tolerance=0.1, **kw)
        return out, list(calls)

    # the premise: a grid point's run starts from the very steady state the bisection solves
    solved = {a: skidmap._run_point((SkidPoint(a, 0.0, 900.0, 0.002), setup, ()))["steady_kinematic_cage_slip_percent"]
              for a in (800.0, 1500.0)}
    assert solved == {a: steady_state(setup, axial_force=a, rpm=900.0).kinematic_cage_slip_percent
                      for a in (800.0, 1500.0)}
    given, given_calls = refined(solved.get)
    again, again_calls = refined(lambda a: None)
    assert given == again and "bracket" in given[0]
    assert again_calls[:2] == [800.0, 1500.0] and given_calls == again_calls[2:]
    thin = replace(setup.lubricant, viscosity=0.5 * setup.lubricant.viscosity)
    _, other_calls = refined(solved.get, lubricant=thin)
    assert other_calls[:2] == [800.0, 1500.0]
