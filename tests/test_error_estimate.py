"""`simulate(..., error_estimate=True)` (CLI --error-estimate): the half-step difference must
predict the actual error of the reported run, checked against a run at a quarter of the step."""
import pytest

pytest.importorskip("exudyn")

from exudyn_bearing.runner import SolverSettings, simulate  # noqa: E402


def test_half_step_estimate_bounds_the_error_against_a_finer_run():
    base = SolverSettings(solver="rk44", step=2e-5, output_step=1e-4)
    run = simulate(axial=1300.0, time=0.003, settings=base, error_estimate=True)
    est = run.error_estimate
    assert est["reference_step"] == pytest.approx(1e-5)
    fine = simulate(axial=1300.0, time=0.003, settings=SolverSettings(solver="rk44", step=5e-6, output_step=1e-4))
    for key in ("kinematic_cage_slip_percent", "cage_slip_percent", "cage_speed"):
        actual = abs(getattr(run, key) - getattr(fine, key))
        assert est[key] >= 0
        # order-4 explicit: the error of h is ~16/15 of |x(h) - x(h/2)|; allow a factor 3
        assert actual <= 3 * est[key] + 1e-9, key
    assert "error_estimate" in run.to_dict()


@pytest.mark.parametrize("kwargs, name", [
    (dict(solver="euler"), "solver"), (dict(step=0.0), "step"), (dict(step=float("nan")), "step"),
    (dict(spectral_radius=1.5), "spectral_radius"), (dict(relative_tolerance=-1e-6), "relative_tolerance"),
    (dict(jacobian="analytic"), "jacobian"), (dict(newton_contractivity=1.0), "newton_contractivity"),
    (dict(newton_contractivity=0.0), "newton_contractivity")])
def test_solver_settings_reject_bad_values(kwargs, name):
    with pytest.raises(ValueError, match=name):
        SolverSettings(**kwargs)
