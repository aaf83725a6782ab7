"""Power loss by source (BearingResults.power_loss, MODEL.md §11) against the energy balance
and closed forms: in a settled run the races' drive power equals the sum of all losses."""
import math

import numpy as np
import pytest

from contact.ballrace import ContactLaw
from exudyn_bearing import REFERENCE_BEARING as B, simulate
from exudyn_bearing.bearing import BallDrag
from exudyn_bearing.presets import ESTER_TURBINE_OIL, HIGH_SPEED_35MM_BEARING, HIGH_SPEED_DRAG

OIL_DENSITY = 860.0  # reference oil, kg/m^3 (MODEL.md §8), written out


def _means(run):
    res = run.results
    m = res.last(1 / 3)
    return {k: float(np.mean(v[m])) for k, v in res.power_loss().items()}, float(np.mean(res.drive_power()[m]))


@pytest.mark.parametrize("law", [ContactLaw(), ContactLaw(rolling_resistance=True, thermal_film=True)],
                         ids=["paper physics", "rolling resistance and thermal film"])
def test_drive_power_equals_total_loss(law):
    """Energy balance over the last third of a settled run (1.3 kN, 1800 rpm, from the steady
    state): what the inner race puts in leaves through the sources, within 1 %."""
    run = simulate(axial_force=1300.0, rpm=1800.0, time=0.05, contact_law=law)
    loss, drive = _means(run)
    assert drive > 10.0
    assert loss["total"] == pytest.approx(drive, rel=0.01)
    assert loss["traction"] > 0 and loss["ball_drag"] > 0
    assert (loss["rolling_resistance"] > 0) == law.rolling_resistance
    assert run.power_loss_W["total"] == pytest.approx(loss["total"], rel=1e-12)
    assert run.details["energy_balance_percent"] == pytest.approx(100 * (drive - loss["total"]) / drive, rel=1e-9)


def test_switched_off_sources_are_zero_and_drag_is_the_closed_form():
    """No drag and no rolling resistance: both sources are exactly zero. With drag, its loss
    is sum over the balls of 1/2 C_D (x rho) pi r^2 |v|^3 at the balls' orbital speeds
    (MODEL.md §8), so it scales with the oil fraction."""
    bare = simulate(axial_force=1300.0, rpm=1800.0, time=0.01, ball_drag=None)
    res = bare.results
    assert np.all(res.power_loss()["ball_drag"] == 0.0) and np.all(res.power_loss()["rolling_resistance"] == 0.0)
    for fraction in (1.0, 0.25):
        run = simulate(axial_force=1300.0, rpm=1800.0, time=0.01, ball_drag=BallDrag(0.5, fraction))
        r = run.results
        radius = B.pitch_radius  # the ball speed along the orbit: w_orbit r_c
        speed = r.ball_orbital_speed * radius
        closed = np.sum(0.5 * 0.5 * fraction * OIL_DENSITY * math.pi * B.ball_radius ** 2 * np.abs(speed) ** 3,
                        axis=1)
        assert r.power_loss()["ball_drag"] == pytest.approx(closed, rel=2e-3)


def test_each_source_grows_with_speed_as_its_law_says():
    """The 35-mm high-speed bearing (MODEL.md §11) at 667 N, 28 000 and 48 000 rpm, from its
    steady state (settled: the drive power equals the losses within 2 %), every source on but
    the thermal film (whose speed factor has no closed form). From 28k to 48k rpm (n ratio
    1.71): the ball drag grows as Σ |v|³ of the balls' orbital speeds (closed form, 2e-3);
    the rolling resistance of each race, 2 f u_m with f ∝ a U^0.75 in the EHL limit and
    ∝ a U^(2/3) in the isoviscous-rigid one (Biboulet & Houpert's fit, MODEL.md §11b),
    a ∝ Q^(1/3) and u_m ∝ n, as n^(5/3 + q/3) to n^(7/4 + q/3), q the race's load exponent
    (measured: inner 1.64 in 1.62–1.70; outer 2.31 against 2.08–2.16, the outer contact angle
    falling with speed raises its u_m and R_x: band +0.25 there); the cage land's Petroff
    shear T = k Δω/√(1 − ε²), its loss T Δω. The land's loss in the results holds that shear
    and its force pair's dissipation (contact, film pressure), which grows with the cage's
    whirl; with Petroff's eccentricity factor taken out (the run's own ε) it grows as
    n^2.19 (band 1.8–2.5; 2.18 in earlier runs whose cage stayed centred); the pockets' loss,
    the rest of the cage's, only has to grow. The eccentricity itself is not fixed: at
    48 000 rpm the cage leaves its centre within 10–20 ms and settles at ~130 W against ~68 W
    centred, in runs converged to 1e-6 as at the default tolerance, with either Newton start;
    the traction and spin heat grows."""
    from exudyn_bearing.cage import CageModel

    law = ContactLaw(rolling_resistance=True)
    cage = CageModel(guidance="outer", guide_clearance=0.25e-3, land_width=4e-3)
    runs = {}
    for rpm in (28000.0, 48000.0):
        run = simulate(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, axial_force=667.0, rpm=rpm, time=0.01,
                       ball_drag=HIGH_SPEED_DRAG, contact_law=law, cage=cage)
        loss, drive = _means(run)
        assert loss["total"] == pytest.approx(drive, rel=0.02), rpm
        res = run.results
        last = res.last(1 / 3)
        speed = res.ball_orbital_speed[last] * HIGH_SPEED_35MM_BEARING.pitch_radius
        for race in ("inner", "outer"):
            contacts = getattr(res, race)
            loss[race + "_rolling"] = float(np.mean(np.sum(contacts["rolling_loss"][last], axis=1)))
            loss[race + "_load"] = float(np.mean(contacts["load"][last]))
        eps = np.minimum(res.cage_eccentricity[last] / (0.5 * cage.guide_clearance), 0.95)
        loss["land_centred"] = float(np.mean(res.land_loss[last] * np.sqrt(1.0 - eps ** 2)))
        runs[rpm] = loss, float(np.mean(np.sum(np.abs(speed) ** 3, axis=1)))
    (low, cube_low), (high, cube_high) = runs[28000.0], runs[48000.0]

    def exponent(key):
        return math.log(high[key] / low[key]) / math.log(48.0 / 28.0)

    assert high["ball_drag"] / low["ball_drag"] == pytest.approx(cube_high / cube_low, rel=2e-3)
    for race, extra in (("inner", 0.0), ("outer", 0.25)):
        q = exponent(race + "_load")
        got = exponent(race + "_rolling")
        assert 5 / 3 + q / 3 - 0.05 < got < 7 / 4 + q / 3 + extra, (race, got, q)
    assert low["inner_rolling"] + low["outer_rolling"] == pytest.approx(low["rolling_resistance"], rel=1e-9)
    assert 1.8 < exponent("land_centred") < 2.5, exponent("land_centred")
    assert high["cage"] > low["cage"]
    assert high["traction"] > low["traction"] > 0


def test_land_friction_is_the_short_journal_shear_and_closes_the_balance():
    """Outer-guided cage with a 10-mm land (MODEL.md §11d): the land friction torque is
    Petroff's 2 pi eta R³ L dw / c over sqrt(1 - eps²) (closed form, by hand), the run's cage
    loss is that torque times the cage's slip against the fixed land, and the energy still
    balances within 1 %."""
    from contact.cage import land_friction_constant, land_friction_torque
    from exudyn_bearing import REFERENCE_LUBRICANT as LUB
    from exudyn_bearing.cage import CageModel

    k = land_friction_constant(0.04, 0.09, 0.01, 0.2e-3)
    assert k == pytest.approx(2 * math.pi * 0.04 * 0.09 ** 3 * 0.01 / 0.2e-3, rel=1e-12)
    assert land_friction_torque(k, 5.0, 0.6) == pytest.approx(k * 5.0 / 0.8, rel=1e-12)
    cage = CageModel(land_width=0.01)
    run = simulate(axial_force=1300.0, rpm=1800.0, time=0.05, cage=cage)
    loss, drive = _means(run)
    assert loss["total"] == pytest.approx(drive, rel=0.01)
    # guided by the driven inner race, the power its land torque puts in is drive power too
    inner = simulate(axial_force=1300.0, rpm=1800.0, time=0.05, cage=CageModel(guidance="inner", land_width=0.01))
    loss_i, drive_i = _means(inner)
    assert loss_i["total"] == pytest.approx(drive_i, rel=0.01) and loss_i["cage"] > 1.0
    res = run.results
    m = res.last(1 / 3)
    radius, play = B.pitch_radius + B.ball_radius, 0.5 * cage.guide_clearance
    eps = np.minimum(res.cage_eccentricity[m] / play, 0.95)
    closed = land_friction_constant(LUB.viscosity, radius, 0.01, play) * res.cage_speed[m] ** 2 / np.sqrt(1 - eps ** 2)
    assert loss["cage"] == pytest.approx(float(np.mean(closed)), rel=0.02)
    assert loss["cage"] > 1.0


@pytest.mark.parametrize("kwargs, key", [(dict(land_width=-1e-3), "land_width"),
                                         (dict(land_width=5e-3, guidance="balls"), "land_width"),
                                         (dict(land_radius=0.0), "land_radius")])
def test_bad_cage_land_input_names_the_key(kwargs, key):
    from exudyn_bearing.cage import CageModel

    with pytest.raises(ValueError, match=key):
        CageModel(**kwargs)


def test_land_play_beyond_the_annulus_names_the_key():
    """The 35-mm bearing's 7.144-mm balls leave no room for 2 mm of diametral land play."""
    from exudyn_bearing.cage import CageModel

    with pytest.raises(ValueError, match="guide_clearance"):
        simulate(HIGH_SPEED_35MM_BEARING, ESTER_TURBINE_OIL, axial_force=667.0, rpm=28000.0, time=0.001,
                 cage=CageModel(guide_clearance=2e-3))


def test_negative_oil_fraction_names_the_key():
    with pytest.raises(ValueError, match="oil_volume_fraction"):
        BallDrag(0.5, -0.01)


def test_long_runs_report_progress_on_stderr(monkeypatch, capsys):
    """Issue 16: a run says where it is every PROGRESS_PERIOD s of wall time (here 0: every
    recorded state), on stderr, with the simulated time and the end time; progress=False and
    short runs print nothing."""
    import exudyn_bearing.simulation.runner as runner
    from exudyn_bearing import SolverSettings

    simulate(axial_force=1300.0, rpm=1800.0, time=0.002)
    assert "exudyn_bearing: t =" not in capsys.readouterr().err  # 5-s period: a short run is quiet
    monkeypatch.setattr(runner, "PROGRESS_PERIOD", 0.0)
    simulate(axial_force=1300.0, rpm=1800.0, time=0.002)
    err = capsys.readouterr().err
    assert "exudyn_bearing: t =" in err and "of 0.002 s" in err and "to go" in err
    simulate(axial_force=1300.0, rpm=1800.0, time=0.002, settings=SolverSettings(progress=False))
    assert "exudyn_bearing: t =" not in capsys.readouterr().err


def test_a_bug_in_a_user_function_is_not_reported_as_a_solver_failure(monkeypatch):
    """A NameError raised inside the force user function reaches the caller as Exudyn reports
    it (the user-function error with the NameError), not as a BearingSimulationError
    advising a smaller step."""
    from exudyn_bearing.errors import BearingSimulationError
    from exudyn_bearing.model.connector import BearingConnector

    def broken(self, t, q, q_t):
        raise NameError("name 'x' is not defined")

    monkeypatch.setattr(BearingConnector, "residual_forces", broken)
    with pytest.raises(Exception, match="NameError: name 'x' is not defined") as caught:
        simulate(axial_force=1300.0, rpm=1800.0, time=0.001)
    assert not isinstance(caught.value, BearingSimulationError)


def test_pocket_friction_is_coulomb_at_the_contact_point():
    """A ball pushed along +x by its pocket with N = 5 N, spinning at w about z, cage at rest:
    the contact lies at c - r x, the ball surface slides there at w r along -y, so the friction
    is mu N along +y (Coulomb, far beyond the slip scale), its moment about the centre is
    -r mu N about z (against the spin), and it dissipates mu N w r. Sliding along the normal
    only, a pocket moving with the surface or no pocket load: no friction."""
    from contact.cage import pocket_friction

    mu, n_load, r, w, v_s = 0.1, 5.0, 0.0125, 600.0, 1e-3
    centre = np.array([[0.08, 0.0, 0.0]])
    zero = np.zeros(3)
    force, point, loss = pocket_friction(np.array([[n_load, 0.0, 0.0]]), centre, np.zeros((1, 3)),
                                         np.array([[0.0, 0.0, w]]), zero, zero, zero, r, mu, v_s)
    assert point[0] == pytest.approx(centre[0] - [r, 0.0, 0.0])
    slip = w * r  # 7.5 m/s
    coulomb = mu * n_load * slip / math.hypot(slip, v_s)
    assert force[0] == pytest.approx([0.0, coulomb, 0.0], abs=1e-12)
    assert np.cross(point[0] - centre[0], force[0]) == pytest.approx([0.0, 0.0, -r * coulomb], abs=1e-12)
    assert loss[0] == pytest.approx(coulomb * slip, rel=1e-12)
    # only normal sliding, a pocket carried along with the ball's surface, no load
    f_normal, _, _ = pocket_friction(np.array([[n_load, 0.0, 0.0]]), centre, np.array([[3.0, 0.0, 0.0]]),
                                     np.zeros((1, 3)), zero, zero, zero, r, mu, v_s)
    f_along, _, _ = pocket_friction(np.array([[n_load, 0.0, 0.0]]), centre, np.zeros((1, 3)),
                                    np.array([[0.0, 0.0, w]]), zero, np.array([0.0, -slip, 0.0]), zero, r, mu, v_s)
    f_free, _, l_free = pocket_friction(np.zeros((1, 3)), centre, np.zeros((1, 3)), np.array([[0.0, 0.0, w]]),
                                        zero, zero, zero, r, mu, v_s)
    assert np.all(f_normal == 0.0) and np.all(f_along == 0.0) and np.all(f_free == 0.0) and l_free[0] == 0.0


def test_pocket_friction_steady_and_dynamic_agree_and_close_the_balance():
    """Outer-guided cage with a 10-mm land (its friction torque loads the pockets) and pocket
    friction mu = 0.3 (MODEL.md §11d): a dynamic run from the steady state stays on it, the
    drive power equals the total loss within 1 %, the friction adds to the cage loss, and the
    steady kinematic slip rises with mu (the friction resists the balls' spin)."""
    from exudyn_bearing import steady_state
    from exudyn_bearing.cage import CageModel

    slips = [steady_state(axial_force=1300.0, rpm=1800.0, cage=CageModel(land_width=0.01, pocket_friction=mu))
             .kinematic_cage_slip_percent for mu in (0.0, 0.1, 0.3)]
    assert slips[0] < slips[1] < slips[2]
    plain = simulate(axial_force=1300.0, rpm=1800.0, time=0.05, cage=CageModel(land_width=0.01))
    run = simulate(axial_force=1300.0, rpm=1800.0, time=0.05, cage=CageModel(land_width=0.01, pocket_friction=0.3))
    assert run.initial_steady_state is not None
    assert run.kinematic_cage_slip_percent == pytest.approx(slips[2], abs=0.05)
    loss, drive = _means(run)
    assert loss["total"] == pytest.approx(drive, rel=0.01)
    assert loss["cage"] > _means(plain)[0]["cage"] + 5.0


@pytest.mark.parametrize("kwargs, key", [(dict(pocket_friction=-0.1), "pocket_friction"),
                                         (dict(pocket_friction=float("nan")), "pocket_friction"),
                                         (dict(kind="spring-chain", pocket_friction=0.1), "pocket_friction"),
                                         (dict(pocket_slip_scale=0.0), "pocket_slip_scale")])
def test_bad_pocket_friction_input_names_the_key(kwargs, key):
    from exudyn_bearing.cage import CageModel

    with pytest.raises(ValueError, match=key):
        CageModel(**kwargs)


def _limited_crook_stress(u, p, h, oil, lam):
    """|τ| of Crook's thermal law (MODEL.md §6) limited as Λ p tanh(τ_C/(Λ p)) (§6a), written
    out here: η = η0 e^(c_ηP p), ψ = η c_ηT u²/(8 K), τ_C = (η/h) u asinh(√ψ)/√(ψ(1 + ψ))."""
    eta = oil.viscosity * math.exp(oil.pressure_viscosity * p)
    psi = eta * oil.temperature_viscosity * u * u / (8 * oil.thermal_conductivity)
    g = math.asinh(math.sqrt(psi)) / math.sqrt(psi * (1 + psi)) if psi > 1e-12 else 1 - psi / 3
    tau_c = eta / h * u * g
    return lam * p * math.tanh(tau_c / (lam * p)) if p > 0 else 0.0


def test_traction_heat_of_a_settled_run_is_the_integral_of_stress_times_slip():
    """The 'traction' loss per contact of a settled run (1.3 kN, 1800 rpm, from the steady
    state; the limited Crook law without the film's elasticity, which needs the entrainment
    speed the results do not carry) against ∬ |τ(x, y)| |u(x, y)| dA over the Hertz ellipse
    by scipy, with the local slip u = (u_x − ω y, u_y + ω x) and p = p_max √(1 − x²/b² − y²/a²)
    taken from the run's per-contact states and the stress law written out above. Measured
    2e-7 (the results' heat comes from the numpy rule at order 16); bound 1e-4."""
    from scipy import integrate

    from contact.ballrace import RaceContact
    from exudyn_bearing import REFERENCE_LUBRICANT as OIL

    law = ContactLaw(film_elasticity=False)
    res = simulate(axial_force=1300.0, rpm=1800.0, time=0.005, contact_law=law).results
    checked = 0
    for race, conformity, contacts in (("inner", B.inner_conformity, res.inner),
                                       ("outer", B.outer_conformity, res.outer)):
        params = RaceContact(B.ball_diameter, B.pitch_diameter, conformity, race, B.effective_modulus, B.ball_mass)
        for ball in (0, 5):
            c = {k: float(v[-1, ball]) for k, v in contacts.items()
                 if k in ("load", "contact_angle", "slip_rolling", "slip_transverse", "spin", "film", "heat",
                          "max_pressure")}
            a, b = (float(v) for v in params.hertz(c["contact_angle"], law.hertz_method)[1].semi_axes(c["load"]))
            ux, uy, om, h, pm = c["slip_rolling"], c["slip_transverse"], c["spin"], c["film"], c["max_pressure"]

            def power(y, x):
                p = pm * math.sqrt(max(1 - (x / b) ** 2 - (y / a) ** 2, 0.0))
                u = math.hypot(ux - om * y, uy + om * x)
                return _limited_crook_stress(u, p, h, OIL, OIL.limiting_shear_coefficient) * u

            heat, _ = integrate.dblquad(power, -b, b, lambda x: -a * math.sqrt(max(1 - (x / b) ** 2, 0.0)),
                                        lambda x: a * math.sqrt(max(1 - (x / b) ** 2, 0.0)), epsrel=1e-6)
            assert heat > 0.05  # W: a contact worth checking
            assert c["heat"] == pytest.approx(heat, rel=1e-4), (race, ball, c["heat"], heat)
            checked += 1
    assert checked == 4
    # the run's traction loss is these contacts' heat summed over all balls
    total = res.power_loss()["traction"][-1]
    assert total == pytest.approx(float(np.sum(res.inner["heat"][-1]) + np.sum(res.outer["heat"][-1])), rel=1e-9)
