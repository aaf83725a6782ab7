"""`simulate(..., error_estimate=True)` (CLI --error-estimate) reports |x(h) - x(h/2)|, the
half-step difference (tolerances halved too). For a method of order p in its asymptotic
range the actual error of the reported run, against a run at h/8, is
(1 - 8^-p) / (1 - 2^-p) times the estimate: 1.07 for RK44 (p = 4), 1.31 at p = 2, 1.75 at
p = 1. Measured on the reference bearing at 1.3 kN (docs/REFERENCE.md, "How accurate is a run"): RK44
1.06, generalized-alpha (rho_inf 0.5, modified Newton) 2.1-2.3 — in these transients its
error behaves as first order (the Newton tolerance, scaled with the step, contributes).
The tests hold each solver's ratio inside a two-sided band, so an estimate inflated or
deflated by a factor of ~2 or more fails."""
import pytest

pytest.importorskip("exudyn")

from exudyn_bearing.simulation.runner import SolverSettings, simulate  # noqa: E402

KEYS = ("kinematic_cage_slip_percent", "cage_slip_percent", "cage_speed")


def ratios(settings, time):
    run = simulate(axial_force=1300.0, time=time, settings=settings, error_estimate=True)
    est = run.error_estimate
    step = run.solver["step"]  # the recommended step where settings.step is None
    assert step == (settings.step or 1e-4)
    assert est["reference_step"] == pytest.approx(step / 2)
    assert "error_estimate" in run.to_dict()
    fine = simulate(axial_force=1300.0, time=time, settings=SolverSettings(
        solver=settings.solver, step=step / 8, output_step=settings.output_step,
        relative_tolerance=settings.relative_tolerance / 8, absolute_tolerance=run.solver["absolute_tolerance"] / 8))
    out = {}
    for key in KEYS:
        assert est[key] > 0, key
        out[key] = abs(getattr(run, key) - getattr(fine, key)) / est[key]
    return out


def test_rk44_estimate_matches_fourth_order():
    """RK44 at 2e-5 s: actual / estimate = 1.07 in theory; band 0.75-1.5."""
    for key, ratio in ratios(SolverSettings(solver="rk44", step=2e-5, output_step=1e-4), 0.003).items():
        assert 0.75 < ratio < 1.5, (key, ratio)


def test_generalized_alpha_estimate_is_half_the_error():
    """Default generalized-alpha at 1e-4 s over 20 ms: actual / estimate 2.1-2.3 measured
    with the paper's law, 1.19 with the default limited law, 1.45 with Exudyn's
    zero-acceleration Newton start (session 15); with the predicted start (MODEL.md §10b)
    the run's error is 15x smaller (kinematic slip 5e-4 against 7.8e-3 pp, cage speed 5e-4
    against 6.3e-3 rad/s), no longer in the asymptotic range (the h/8 and h/16 references
    differ by a fifth of it), and the ratios are 0.65-0.78 (kinematic slip) and 1.9-2.3
    (cage speed and slip). Band 0.5-3.5 (order 2 would give 1.31, order 1 1.75): the
    README tells users to read twice the estimate as the error of a generalized-alpha run."""
    for key, ratio in ratios(SolverSettings(), 0.02).items():
        assert 0.5 < ratio < 3.5, (key, ratio)


@pytest.mark.parametrize("kwargs, name", [
    (dict(solver="euler"), "solver"), (dict(step=0.0), "step"), (dict(step=float("nan")), "step"),
    (dict(spectral_radius=1.5), "spectral_radius"), (dict(relative_tolerance=-1e-6), "relative_tolerance"),
    (dict(jacobian="analytic"), "jacobian"), (dict(newton_contractivity=1.0), "newton_contractivity"),
    (dict(newton_contractivity=0.0), "newton_contractivity"),
    (dict(step_recovery_iterations=0), "step_recovery_iterations"),
    (dict(step_recovery_iterations=2.5), "step_recovery_iterations")])
def test_solver_settings_reject_bad_values(kwargs, name):
    with pytest.raises(ValueError, match=name):
        SolverSettings(**kwargs)


def test_step_recovery_reaches_exudyn():
    """SolverSettings.step_recovery_iterations is Exudyn's adaptiveStepRecoveryIterations of the
    run (Exudyn's own default is 7)."""
    from exudyn_bearing.simulation.runner import _exudyn_settings

    assert _exudyn_settings(SolverSettings(step=1e-4), 0.01).timeIntegration.adaptiveStepRecoveryIterations == 5
    ss = _exudyn_settings(SolverSettings(step=1e-4, step_recovery_iterations=7), 0.01)
    assert ss.timeIntegration.adaptiveStepRecoveryIterations == 7
