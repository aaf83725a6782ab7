"""The command line as users run it (``python -m exudyn_bearing simulate|skid-map|render``),
in subprocesses: what it prints and writes is checked against numbers derived here
independently (pure-rolling cage speed, ball force balance with the centrifugal force,
Hirano's criterion, step counts), not only its exit code. ``loads`` is covered in
tests/test_quasistatic.py.

Runs are 2–5 ms of simulated time; the whole file takes well under a minute once the
numba kernels are cached on disk (the first use compiles them, ~20–40 s)."""
import csv
import json
import math
import re
import shutil
import struct
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("exudyn")

ROOT = Path(__file__).resolve().parents[1]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"

# the paper's reference bearing (table 1), typed in here, not taken from the package
Z_REF, D_REF, DM_REF, ALPHA_REF, MASS_REF = 16, 25e-3, 155e-3, math.radians(40.0), 0.064


def nominal_cage_speed(rpm, ball_diameter, pitch_diameter, angle):
    """Pure-rolling cage speed, outer race fixed: w_i/2 (1 - D cos(a) / d_m), rad/s."""
    return 0.5 * rpm * math.pi / 30.0 * (1.0 - ball_diameter * math.cos(angle) / pitch_diameter)


def outer_load_from_balance(inner_load, axial_per_ball, centrifugal):
    """Ball in equilibrium: axial components Q_i sin a_i = Q_o sin a_o = F_a/Z, radial
    Q_o cos a_o = Q_i cos a_i + F_c (gyroscopic and traction terms neglected)."""
    radial_inner = math.sqrt(inner_load ** 2 - axial_per_ball ** 2)
    return math.hypot(axial_per_ball, radial_inner + centrifugal)


def cli(*args, cwd, timeout=300):
    """Run the CLI; returns (CompletedProcess, wall seconds)."""
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "exudyn_bearing", *map(str, args)], cwd=cwd, capture_output=True,
                          text=True, timeout=timeout)
    return proc, time.perf_counter() - start


def cli_json(*args, cwd, timeout=300):
    proc, wall = cli(*args, "--json", cwd=cwd, timeout=timeout)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "Traceback" not in proc.stderr
    return json.loads(proc.stdout), wall


def assert_real_png(path, min_bytes=10_000, min_size=(300, 200)):
    """PNG signature, IHDR size and file size read from the bytes; then not one flat colour."""
    data = Path(path).read_bytes()
    assert data[:8] == PNG_SIGNATURE, f"{path} is not a PNG"
    assert data[12:16] == b"IHDR"
    width, height = struct.unpack(">II", data[16:24])
    assert width >= min_size[0] and height >= min_size[1], (width, height)
    assert len(data) > min_bytes, f"{path}: only {len(data)} bytes"
    import matplotlib.image as mpimg

    image = mpimg.imread(path)[..., :3]
    assert image.shape[:2] == (height, width)
    colours = np.unique((image.reshape(-1, 3) * 255).astype(int), axis=0)
    assert len(colours) > 20 and image.std() > 0.02, "image is (nearly) a single colour"


SIMULATE_KEYS = {"axial", "radial", "rpm", "time", "cage_slip_percent", "kinematic_cage_slip_percent", "cage_speed",
                 "cage_speed_nominal", "settled", "wall_time_s", "steps", "solver", "newton_iterations",
                 "jacobian_updates", "details", "error_estimate", "power_loss_W", "drive_power_W", "cpu_time_s",
                 "call_time_s", "integration_profile"}
DETAIL_KEYS = {"attitude_yz_deg", "attitude_xz_deg", "max_inner_load", "max_outer_load", "max_inner_slip",
               "max_traction_coefficient"}
ESTIMATE_KEYS = {"cage_slip_percent", "kinematic_cage_slip_percent", "cage_speed", "max_inner_load", "max_outer_load",
                 "max_inner_slip"}


@pytest.fixture(scope="module")
def reference_run(tmp_path_factory):
    """``simulate --axial 1300 --rpm 1800 --time 0.005 --json`` of the reference bearing (also
    warms the numba kernel cache for the other tests)."""
    cwd = tmp_path_factory.mktemp("reference_run")
    return cli_json("simulate", "--axial", 1300, "--rpm", 1800, "--time", 0.005, cwd=cwd)


# ---------------------------------------------------------------------------- simulate


def test_simulate_json_has_every_documented_key_with_finite_values(reference_run):
    data, _ = reference_run
    assert SIMULATE_KEYS <= set(data), SIMULATE_KEYS - set(data)
    assert DETAIL_KEYS <= set(data["details"]), DETAIL_KEYS - set(data["details"])
    assert not set(data["details"]) & set(data), "details repeats a top-level key"  # issue 16 item 7
    assert set(data["power_loss_W"]) >= {"traction", "ball_drag", "total"} and data["drive_power_W"] > 0
    assert {"solver", "step", "relative_tolerance", "output_step"} <= set(data["solver"])
    assert (data["axial"], data["radial"], data["rpm"], data["time"]) == (1300.0, 0.0, 1800.0, 0.005)
    assert data["solver"]["solver"] == "generalized-alpha" and data["solver"]["step"] == 1e-4  # CLI defaults
    assert data["settled"] is None or isinstance(data["settled"], bool)
    assert data["error_estimate"] is None  # only with --error-estimate
    numbers = [data[k] for k in ("cage_slip_percent", "kinematic_cage_slip_percent", "cage_speed",
                                 "cage_speed_nominal", "wall_time_s")] + list(data["details"].values())
    assert all(isinstance(v, float) and math.isfinite(v) for v in numbers), numbers
    for key in ("steps", "newton_iterations", "jacobian_updates"):
        assert isinstance(data[key], int), key
    # issue 16 item 7: the unit of every key (nested like the data), and what produced it
    units = data["units"]
    assert set(units) == set(data) - {"units", "inputs"}
    assert (units["axial"], units["rpm"], units["cage_speed"], units["wall_time_s"]) == ("N", "rev/min", "rad/s", "s")
    assert units["details"]["max_inner_load"] == "N" and units["details"]["attitude_xz_deg"] == "deg"
    assert set(units["power_loss_W"].values()) == {"W"} and units["solver"]["step"] == "s"
    assert "balls=16" in data["inputs"]["bearing"] and "viscosity" in data["inputs"]["lubricant"]


def test_simulate_json_values_are_physical(reference_run):
    data, wall = reference_run
    w_inner = 1800 * math.pi / 30
    nominal = nominal_cage_speed(1800, D_REF, DM_REF, ALPHA_REF)  # 82.60 rad/s
    assert data["cage_speed_nominal"] == pytest.approx(nominal, rel=1e-9)
    assert 0 < data["cage_speed"] < w_inner
    assert data["cage_speed"] == pytest.approx(nominal, rel=0.05)  # 1.3 kN: a few % slip at most
    # P19 (MODEL.md §7): 200 (w_ref - w_c) / (w_ref + w_c), from the reported speeds
    p19 = 200 * (nominal - data["cage_speed"]) / (nominal + data["cage_speed"])
    assert data["cage_slip_percent"] == pytest.approx(p19, abs=0.05)
    assert abs(data["kinematic_cage_slip_percent"]) < 5
    # 5 ms at the default 1e-4 s step: ~50 steps, at least one Newton iteration each
    assert abs(data["steps"] - 50) <= 2
    assert data["newton_iterations"] >= data["steps"] and data["jacobian_updates"] >= 1
    assert 0 < data["wall_time_s"] < wall  # the solver's own time fits inside the process's
    assert data["settled"] is None  # too short to judge: shorter than the 50 ms the settling test needs
    # ball force balance: axial share F_a/Z <= Q_i <= F_a/(Z sin a0) (the angle grows under load),
    # and the outer load follows from the inner one and the centrifugal force m r_p w_c^2
    d = data["details"]
    share = 1300 / Z_REF
    assert share < d["max_inner_load"] < 1.02 * share / math.sin(ALPHA_REF)
    centrifugal = MASS_REF * DM_REF / 2 * data["cage_speed"] ** 2  # ~34 N
    assert d["max_outer_load"] == pytest.approx(outer_load_from_balance(d["max_inner_load"], share, centrifugal),
                                                rel=0.03)
    assert d["max_outer_load"] > d["max_inner_load"]
    # slip speed is a fraction of the inner race's surface speed (~12 m/s)
    assert 0 <= d["max_inner_slip"] < 0.1 * w_inner * (DM_REF - D_REF) / 2


def test_simulate_error_estimate_is_the_half_step_difference(reference_run, tmp_path):
    plain, _ = reference_run
    data, _ = cli_json("simulate", "--axial", 1300, "--rpm", 1800, "--time", 0.005, "--step", 1e-4,
                       "--error-estimate", cwd=tmp_path)
    est = data["error_estimate"]
    assert isinstance(est, dict)
    assert ESTIMATE_KEYS <= set(est), ESTIMATE_KEYS - set(est)
    assert est["reference_step"] == pytest.approx(0.5 * data["solver"]["step"], rel=1e-12)
    assert est["reference_wall_time_s"] > 0
    assert all(math.isfinite(est[k]) and est[k] >= 0 for k in ESTIMATE_KEYS)
    # the reported run is the same run as without the option
    for key in ("cage_speed", "kinematic_cage_slip_percent", "cage_slip_percent", "steps"):
        assert data[key] == pytest.approx(plain[key], rel=1e-9, abs=1e-12), key
    # and the estimate is what a separate run at half the step and half the Newton tolerances
    # gives (at the default tolerance, Newton's error is as large as the step's here: with the
    # predicted Newton start (MODEL.md §10b) 7.5e-4 rad/s against the step's 8e-4)
    from exudyn_bearing import SolverSettings, simulate

    half = simulate(axial_force=1300, rpm=1800, time=0.005, settings=SolverSettings(
        progress=False, step=5e-5, relative_tolerance=5e-5, absolute_tolerance=5e-7, output_step=5e-4))
    assert abs(half.steps - 100) <= 3
    for key in ("cage_speed", "kinematic_cage_slip_percent", "cage_slip_percent"):
        difference = abs(data[key] - getattr(half, key))  # ~1e-4 rad/s, ~3e-4 pp
        assert est[key] == pytest.approx(difference, rel=1e-6, abs=1e-9), key
    assert est["cage_speed"] > 0  # a 5 ms transient is not step-independent to the last digit


def test_simulate_text_output_and_plot(reference_run, tmp_path):
    plain, _ = reference_run
    proc, _ = cli("simulate", "--axial", 1300, "--rpm", 1800, "--time", 0.005, "--plot", "out.png", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    text = proc.stdout
    nominal = nominal_cage_speed(1800, D_REF, DM_REF, ALPHA_REF)
    speed = re.search(r"cage speed\s+(-?[\d.]+) rad/s \(nominal (-?[\d.]+)\)", text)
    assert speed, text
    assert float(speed.group(2)) == pytest.approx(nominal, abs=6e-4)
    assert float(speed.group(1)) == pytest.approx(plain["cage_speed"], abs=6e-4)  # same run as the JSON one
    kin = re.search(r"kinematic cage slip \(MODEL.md §7\)\s+(-?[\d.]+) %", text)
    assert kin and float(kin.group(1)) == pytest.approx(plain["kinematic_cage_slip_percent"], abs=6e-4)
    assert re.search(r"settled\s+too short to judge", text)  # 5 ms
    assert re.search(rf"{plain['steps']} steps", text)
    assert "plots written to out.png" in text
    assert_real_png(tmp_path / "out.png", min_bytes=30_000, min_size=(800, 700))


ANGULAR_CONTACT_TOML = """\
[bearing]
balls = 12
ball_diameter = 20e-3
pitch_diameter = 120e-3
inner_conformity = 0.52
outer_conformity = 0.53
contact_angle = 30.0
[material]
youngs_modulus = 210e9
poisson_ratio = 0.3
density = 7850
"""


def test_simulate_bearing_file_is_used(reference_run, tmp_path):
    (tmp_path / "my.toml").write_text(ANGULAR_CONTACT_TOML)
    data, _ = cli_json("simulate", "--axial", 1300, "--rpm", 1800, "--time", 0.005, "--bearing", "my.toml",
                       cwd=tmp_path)
    z, d, dm, angle = 12, 20e-3, 120e-3, math.radians(30.0)
    nominal = nominal_cage_speed(1800, d, dm, angle)  # 80.64 rad/s, not the reference's 82.60
    assert data["cage_speed_nominal"] == pytest.approx(nominal, rel=1e-9)
    assert abs(data["cage_speed_nominal"] - reference_run[0]["cage_speed_nominal"]) > 1.0
    assert "balls=12" in data["inputs"]["bearing"]  # the result records the file's bearing
    assert data["cage_speed"] == pytest.approx(nominal, rel=0.05)
    details = data["details"]
    share = 1300 / z  # 108 N per ball with 12 balls (81 N with the reference's 16)
    assert share < details["max_inner_load"] < 1.02 * share / math.sin(angle)
    mass = 7850 * math.pi / 6 * d ** 3  # from the file's density
    centrifugal = mass * dm / 2 * data["cage_speed"] ** 2
    assert details["max_outer_load"] == pytest.approx(
        outer_load_from_balance(details["max_inner_load"], share, centrifugal), rel=0.03)


def _readme_bearing_file():
    """The deep-groove example TOML of the user reference (moved there from the README)."""
    text = (ROOT / "docs" / "REFERENCE.md").read_text(encoding="utf-8")
    section = text.split("## Bearing files", 1)[1]
    return re.search(r"```toml\n(.+?)\n```", section, re.S).group(1)


def test_readme_deep_groove_bearing_file_simulates(tmp_path):
    """The user reference's deep-groove TOML at 600 N axial, 1800 rpm (p_max ~1.4 GPa): failed with the
    paper's pure Crook law, runs with the default limiting shear (MODEL.md §6a)."""
    (tmp_path / "deep_groove.toml").write_text(_readme_bearing_file())
    data, _ = cli_json("simulate", "--axial", 600, "--rpm", 1800, "--time", 0.002, "--bearing", "deep_groove.toml",
                       cwd=tmp_path)
    # free angle from the clearance: cos a0 = 1 - P_d / (2 (r_i + r_o - D))
    angle = math.acos(1 - 10e-6 / (2 * (5.772e-3 + 5.883e-3 - 11.1e-3)))  # 7.7 deg
    assert data["cage_speed_nominal"] == pytest.approx(nominal_cage_speed(1800, 11.1e-3, 43.5e-3, angle), rel=1e-9)
    assert data["cage_speed"] == pytest.approx(data["cage_speed_nominal"], rel=0.05)


# ---------------------------------------------------------------------------- skid-map


def _read_csv(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def _markdown_point_rows(text):
    """Data rows of the first (per-point) table: 9 columns."""
    rows = []
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 9 and re.fullmatch(r"[\d.]+", cells[0]):
            rows.append(cells)
    return rows


@pytest.mark.slow
def test_skid_map_writes_one_row_per_point_and_resumes(reference_run, tmp_path):
    args = ["skid-map", "--axial", "1300,3000", "--rpm", "1800", "--time", "0.005", "--out", "map", "--workers", "2"]
    proc, _ = cli(*args, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    out = tmp_path / "map"
    for name in ("skid_map.csv", "skid_map.md", "thresholds.json", "skid_map.png", "points.jsonl"):
        assert (out / name).is_file(), name
    rows = _read_csv(out / "skid_map.csv")
    assert sorted(float(r["axial"]) for r in rows) == [1300.0, 3000.0]
    by_load = {float(r["axial"]): r for r in rows}
    for r in rows:
        assert (float(r["radial"]), float(r["rpm"]), float(r["time"])) == (0.0, 1800.0, 0.005)
        assert r["error"] == "" and r["settled"] == "too short"  # 5 ms: too short to judge
        for key in ("cage_slip_percent", "kinematic_cage_slip_percent", "peak_ball_slip", "wall_time_s"):
            assert math.isfinite(float(r[key])), key
        assert 0 <= float(r["peak_ball_slip"]) < 12.0  # below the inner race's surface speed
    slip = {a: float(r["kinematic_cage_slip_percent"]) for a, r in by_load.items()}
    assert slip[3000.0] < slip[1300.0]  # more load, less skidding
    # the map's 1.3 kN point is the operating point of `simulate` (it averages the last third
    # at a 1e-4 s output period, simulate's CLI at 5e-4 s)
    assert slip[1300.0] == pytest.approx(reference_run[0]["kinematic_cage_slip_percent"], abs=0.1)
    # markdown: one row per point, the CSV's numbers
    md_rows = _markdown_point_rows((out / "skid_map.md").read_text())
    assert len(md_rows) == 2
    for cells in md_rows:
        r = by_load[float(cells[2])]
        assert float(cells[3]) == pytest.approx(float(r["kinematic_cage_slip_percent"]), abs=6e-4)
        assert float(cells[4]) == pytest.approx(float(r["steady_kinematic_cage_slip_percent"]), abs=6e-4)
        assert float(cells[5]) == pytest.approx(float(r["cage_slip_percent"]), abs=6e-4)
        assert cells[7] == "too short to judge"  # 5 ms
        # each run starts from the steady state and stays on it (MODEL.md §12)
        assert float(r["kinematic_cage_slip_percent"]) == pytest.approx(float(r["steady_kinematic_cage_slip_percent"]),
                                                                        abs=0.05)
    # thresholds: Hirano 10 Z m r_p w_c^2, and the 1 % crossing bisected with the steady
    # state between the bracketing points, confirmed by dynamic runs at the final bracket
    record = json.loads((out / "thresholds.json").read_text())
    (threshold,) = record["thresholds"]
    assert record["units"]["minimum_axial"] == "N" and record["units"]["bracket"] == "N"
    assert "REFERENCE" in record["inputs"]["bearing"] or "Bearing(" in record["inputs"]["bearing"]
    assert threshold["rpm"] == 1800.0
    w_c = nominal_cage_speed(1800, D_REF, DM_REF, ALPHA_REF)
    assert threshold["hirano_minimum_axial"] == pytest.approx(10 * Z_REF * MASS_REF * DM_REF / 2 * w_c ** 2, rel=1e-6)
    assert slip[1300.0] > 1.0 > slip[3000.0]  # the crossing lies between them
    lo, hi = threshold["bracket"]
    assert 1300 <= lo < threshold["minimum_axial"] < hi <= 3000 and hi - lo <= 0.04 * lo + 1e-9
    from exudyn_bearing import steady_state

    assert steady_state(axial_force=lo, rpm=1800).kinematic_cage_slip_percent >= 1.0
    assert steady_state(axial_force=hi, rpm=1800).kinematic_cage_slip_percent < 1.0
    # the steady states the bisection evaluated, which the figure draws: the grid's ends and
    # the bracket's, the slip falling with the load through the 1 % level inside the bracket
    curve = threshold["steady_curve"]
    assert record["units"]["steady_curve"] == "[N, %]"
    assert [1300.0, 3000.0] == [curve[0][0], curve[-1][0]] and [lo, hi] in [[a, b] for (a, _), (b, _) in
                                                                          zip(curve, curve[1:])]
    assert all(s1 > s2 for (_, s1), (_, s2) in zip(curve, curve[1:]))
    assert dict(curve)[lo] >= 1.0 > dict(curve)[hi]
    assert threshold["dynamic_confirms"]
    assert abs(threshold["dynamic_minimum_axial"] - threshold["minimum_axial"]) <= 0.04 * lo
    assert "bisection" in threshold["note"]
    assert_real_png(out / "skid_map.png")

    # the same command again: nothing is recomputed, the journal and the table stay as they were
    journal = (out / "points.jsonl").read_text()
    proc, _ = cli(*args, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "resuming: 2 of 2 points" in proc.stdout
    assert (out / "points.jsonl").read_text() == journal
    assert _read_csv(out / "skid_map.csv") == rows  # incl. the first run's wall times

    # a grid extended by one load: exactly one new run, appended to the journal
    args[2] = "800,1300,3000"
    proc, _ = cli(*args, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "resuming: 2 of 3 points" in proc.stdout
    lines = (out / "points.jsonl").read_text().splitlines()
    assert lines[:2] == journal.splitlines() and len(lines) == 3
    assert json.loads(lines[2])["axial"] == 800.0
    rows3 = {float(r["axial"]): r for r in _read_csv(out / "skid_map.csv")}
    assert sorted(rows3) == [800.0, 1300.0, 3000.0]
    assert rows3[1300.0] == by_load[1300.0] and rows3[3000.0] == by_load[3000.0]
    assert float(rows3[800.0]["kinematic_cage_slip_percent"]) > slip[1300.0]
    assert len(_markdown_point_rows((out / "skid_map.md").read_text())) == 3


# ---------------------------------------------------------------------------- render


@pytest.fixture(scope="module")
def raytraced(tmp_path_factory):
    """``render --backend raytracer`` (no X server needed): two frames over 2 ms."""
    pytest.importorskip("matplotlib")
    out = tmp_path_factory.mktemp("render")
    proc, _ = cli("render", "--time", 0.002, "--frames", 2, "--backend", "raytracer", "--out", out, cwd=out)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return proc, sorted(out.glob("*.png"))


def test_render_raytracer_writes_frames(raytraced):
    proc, files = raytraced
    assert [f.name for f in files] == ["frame0000.png", "frame0001.png"]
    assert "wrote 2 frame(s)" in proc.stdout
    for f in files:
        assert_real_png(f, min_bytes=20_000, min_size=(800, 600))  # the default 800 x 600


def test_render_frames_show_different_states(raytraced):
    _, files = raytraced
    first, last = (f.read_bytes() for f in (files[0], files[-1]))
    assert first != last  # t = 0 and t = 2 ms: the balls have orbited ~9 deg


@pytest.mark.skipif(shutil.which("xvfb-run") is None, reason="Xvfb not installed (Debian package xvfb)")
def test_render_opengl_under_xvfb(tmp_path):
    cmd = ["xvfb-run", "-a", sys.executable, "-m", "exudyn_bearing", "render", "--time", "0.0005", "--frames", "1",
           "--backend", "opengl", "--out", str(tmp_path)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    (frame,) = sorted(tmp_path.glob("*.png"))
    assert_real_png(frame, min_bytes=20_000)


# ---------------------------------------------------------------------------- plots (in-process)


def test_plot_run_and_plot_skid_curve(reference_run, tmp_path):
    plt = pytest.importorskip("matplotlib.pyplot")
    from exudyn_bearing.results.plots import plot_run, plot_skid_curve
    from exudyn_bearing.simulation.runner import simulate

    run = simulate(axial_force=1300.0, rpm=1800.0, time=0.003)
    fig = plot_run(run.results, tmp_path / "run.png", title="F_a 1300 N")
    try:
        assert len(fig.axes) == 6
        t_line = fig.axes[0].get_lines()[0]
        assert max(t_line.get_xdata()) == pytest.approx(3.0, rel=0.02)  # time axis in ms
        for ax in fig.axes[2:]:  # orbit panels: position angle in degrees
            for line in ax.get_lines():
                x = np.asarray(line.get_xdata())
                assert x.size > 16 and x.min() >= 0 and x.max() <= 360
        loads = np.concatenate([line.get_ydata() for line in fig.axes[4].get_lines()])
        share = 1300 / Z_REF
        assert loads.min() > 0.8 * share and loads.max() < 2 * share / math.sin(ALPHA_REF)  # N, not kN
    finally:
        plt.close(fig)
    assert_real_png(tmp_path / "run.png", min_bytes=30_000, min_size=(1000, 1000))

    settled = [False, True, True]
    fig = plot_skid_curve([300, 1300, 3000], [60.0, 2.0, 0.06], [55.0, 2.5, 0.1], attitude_xz=[1.0, 50.0, 55.0],
                          attitude_yz=[0.1, 3.0, 2.0], settled=settled, path=tmp_path / "curve.png")
    try:
        assert len(fig.axes) == 2
        assert list(fig.axes[0].get_lines()[0].get_xdata()) == [300, 1300, 3000]
        for ax in fig.axes:  # unsettled points marked by a red vertical line at their load
            red = [line for line in ax.get_lines() if line.get_color() == "red"]
            assert [line.get_xdata()[0] for line in red] == [300]
    finally:
        plt.close(fig)
    assert_real_png(tmp_path / "curve.png", min_bytes=15_000)


def test_dataset_writes_labelled_cases_in_worker_processes(tmp_path):
    """`dataset` in two worker processes: one NPZ per case and a row in index.csv; the housing
    and masking options reach every case (recorded in inputs.json and each case's inputs), the
    noise seeded per case; a second run resumes without running."""
    args = ["dataset", "--faults", "none,outer", "--sizes", "0.001", "--time", "0.03", "--settle", "0.005",
            "--housing-frequency", "4000", "--snr", "20", "--seed", "3", "--out", "set", "--workers", "2"]
    proc, _ = cli(*args, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    rows = _read_csv(tmp_path / "set" / "index.csv")
    assert [(r["fault"], float(r["size_m"])) for r in rows] == [("none", 0.0), ("outer", 0.001)]
    assert sorted(int(r["seed"]) for r in rows) == [3, 4]
    record = json.loads((tmp_path / "set" / "inputs.json").read_text())
    assert "frequency=4000" in record["housing"] and "snr_db=20" in record["dataset_settings"]
    for r in rows:
        case = np.load(tmp_path / "set" / r["file"])
        inputs = json.loads(str(case["inputs"]))
        assert "snr_db=20" in inputs["masking"]
        stiffness = float(re.search(r"support=\(([0-9.e+]+)", inputs["housing"]).group(1))
        assert stiffness == pytest.approx(2.0 * (2 * math.pi * 4000.0) ** 2, rel=1e-9)  # 2 kg at 4 kHz
        assert case["t_s"].size == 601
    again, _ = cli(*args, cwd=tmp_path)
    assert again.returncode == 0 and "resuming: 2 of 2" in again.stdout, again.stderr[-2000:]


# ---------------------------------------------------------------------------- bad input


BAD_INPUT = [
    pytest.param(["simulate", "--axial", "-5", "--time", "0.002"], r"axial", id="simulate-negative-axial"),
    pytest.param(["simulate", "--axial", "1300", "--radial", "-5", "--time", "0.002"], r"radial",
                 id="simulate-negative-radial"),
    pytest.param(["simulate", "--axial", "1300", "--time", "0"], r"\btime\b", id="simulate-zero-time"),
    pytest.param(["simulate", "--axial", "1300", "--time", "nan"], r"\btime\b", id="simulate-nan-time"),
    pytest.param(["simulate", "--axial", "1300", "--step", "0", "--time", "0.002"], r"\bstep\b",
                 id="simulate-zero-step"),
    pytest.param(["simulate", "--axial", "1300", "--rpm", "nan", "--time", "0.002"], r"\brpm\b",
                 id="simulate-nan-rpm"),
    pytest.param(["simulate", "--axial", "1300", "--order", "0", "--time", "0.002"], r"order",
                 id="simulate-quadrature-order-0"),
    pytest.param(["simulate", "--axial", "1300", "--time", "0.002", "--bearing", "broken.toml"], r"TOML",
                 id="simulate-invalid-toml"),
    pytest.param(["skid-map", "--axial", "abc", "--rpm", "1800", "--time", "0.002", "--out", "m"], r"'abc'",
                 id="skid-map-bad-range"),
    pytest.param(["skid-map", "--axial", "1300:3000:0", "--rpm", "1800", "--time", "0.002", "--out", "m"],
                 r"1300:3000:0", id="skid-map-empty-range"),
    pytest.param(["render", "--frames", "0", "--out", "r"], r"frames", id="render-zero-frames"),
    pytest.param(["dataset", "--faults", "cage", "--out", "d"], r"faults", id="dataset-unknown-fault"),
    pytest.param(["dataset", "--sizes", "0", "--out", "d"], r"sizes", id="dataset-zero-size"),
    pytest.param(["dataset", "--depth", "-1", "--out", "d"], r"depth", id="dataset-negative-depth"),
    pytest.param(["dataset", "--bearing", "faulty.toml", "--out", "d"], r"defect", id="dataset-file-with-defects"),
    pytest.param(["render", "--axial", "-5", "--out", "r"], r"axial", id="render-negative-axial"),
    pytest.param(["simulate", "--axial", "1300", "--time", "0.002", "--bearing", "missing.toml"], r"missing\.toml",
                 id="simulate-missing-bearing-file"),
    pytest.param(["loads", "--axial", "1300", "--bearing", "missing.toml"], r"missing\.toml",
                 id="loads-missing-bearing-file"),
    pytest.param(["simulate", "--axial", "1300", "--time", "0.002", "--plot", "no_such_dir/run.png"], r"run\.png",
                 id="simulate-plot-missing-dir"),
    pytest.param(["render", "--time", "0", "--out", "r"], r"\btime\b",
                 id="render-zero-time"),
    pytest.param(["render", "--time", "-1", "--out", "r"], r"\btime\b",
                 id="render-negative-time"),
    pytest.param(["skid-map", "--axial", "-5", "--rpm", "1800", "--time", "0.002", "--out", "m", "--workers", "1"],
                 r"axial", id="skid-map-negative-load"),
    pytest.param(["skid-map", "--axial", "3000:1300:3", "--rpm", "1800", "--time", "0.002", "--out", "m"],
                 r"3000:1300:3", id="skid-map-reversed-range"),
    pytest.param(["skid-map", "--axial", "1300,nan", "--rpm", "1800", "--time", "0.002", "--out", "m"],
                 r"nan", id="skid-map-nan-load"),
    pytest.param(["skid-map", "--axial", "1e9", "--rpm", "1800", "--time", "0.002", "--out", "m", "--workers", "1",
                  "--no-refine"], r"1 of 1 points failed", id="skid-map-point-failed"),
    pytest.param(["skid-map", "--axial", "1300", "--rpm", "1800", "--time", "0.002", "--out", "m", "--scheduler",
                  "tcp://127.0.0.1:1"], r"--scheduler", id="skid-map-unreachable-scheduler",
                 marks=pytest.mark.slow),  # (the client's 10-s connection timeout)
]


@pytest.mark.parametrize("args, names", BAD_INPUT)
def test_bad_input_is_an_error_message_not_a_traceback(args, names, tmp_path):
    (tmp_path / "broken.toml").write_text("[bearing]\nballs = = 6\n")
    from contact.surface import Defect, SurfaceModel
    from exudyn_bearing import REFERENCE_BEARING
    from exudyn_bearing.bearingfile import BearingFile, dumps_bearing

    (tmp_path / "faulty.toml").write_text(dumps_bearing(BearingFile(
        REFERENCE_BEARING, surface=SurfaceModel((Defect("outer", 0.0, 1e-3, 1e-5),)))))
    proc, _ = cli(*args, cwd=tmp_path, timeout=120)
    assert proc.returncode != 0, proc.stdout[-2000:]
    assert "Traceback" not in proc.stderr, proc.stderr[-2000:]
    assert re.search(r"^error: ", proc.stderr, re.M), proc.stderr[-2000:]
    assert re.search(names, proc.stderr, re.I), proc.stderr[-2000:]


def test_version_and_help_show_defaults(tmp_path):
    from importlib.metadata import version

    proc, _ = cli("--version", cwd=tmp_path)
    assert proc.returncode == 0 and version("exudyn-bearing") in proc.stdout and version("exudyn") in proc.stdout
    proc, _ = cli("simulate", "--help", cwd=tmp_path)
    text = " ".join(proc.stdout.split())
    assert "(default: 1800.0)" in text and "(default: generalized-alpha)" in text  # --rpm, --solver
    proc, _ = cli("skid-map", "--help", cwd=tmp_path)
    assert "until settled" in " ".join(proc.stdout.split())


def test_render_takes_a_bearing_file(tmp_path):
    from exudyn_bearing import Bearing, save_bearing

    deep = Bearing.from_clearance(diametral_clearance=10e-6, balls=6, ball_diameter=11.1e-3, pitch_diameter=43.5e-3,
                                  inner_conformity=5.772 / 11.1, outer_conformity=5.883 / 11.1)
    save_bearing(deep, tmp_path / "deep.toml")
    proc, _ = cli("render", "--axial", "200", "--radial", "1000", "--rpm", "3000", "--time", "0.0005", "--frames", "1",
                  "--backend", "raytracer", "--bearing", "deep.toml", "--out", "r", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-3000:]
    (frame,) = sorted((tmp_path / "r").glob("*.png"))
    assert_real_png(frame, min_bytes=10_000)


@pytest.mark.slow
def test_cage_section_of_a_bearing_file_reaches_simulate_and_steady(tmp_path):
    """A [cage] with a 10-mm outer land and pocket friction (MODEL.md §11d) in the bearing
    file: `simulate` and `steady` run with it (the land's friction torque loads the pockets,
    so the cage loss is far above the frictionless cage's pocket damping, and the steady
    kinematic slip lies above the same bearing's without it) and record it in `inputs`."""
    from exudyn_bearing import REFERENCE_BEARING, BearingFile, save_bearing
    from exudyn_bearing.cage import CageModel

    save_bearing(BearingFile(REFERENCE_BEARING, cage=CageModel(land_width=0.01, pocket_friction=0.3)),
                 tmp_path / "caged.toml")
    save_bearing(REFERENCE_BEARING, tmp_path / "plain.toml")
    run, _ = cli_json("simulate", "--axial", 1300, "--time", 0.005, "--bearing", "caged.toml", cwd=tmp_path)
    assert "pocket_friction=0.3" in run["inputs"]["cage"] and "land_width=0.01" in run["inputs"]["cage"]
    assert run["power_loss_W"]["cage"] > 50.0  # reference bearing: ~85 W of land and pocket friction
    steady = {name: cli_json("steady", "--axial", 1300, "--bearing", f"{name}.toml", cwd=tmp_path)[0]
              for name in ("caged", "plain")}
    assert steady["caged"]["kinematic_cage_slip_percent"] > steady["plain"]["kinematic_cage_slip_percent"] + 0.2
    assert "pocket_friction=0.3" in steady["caged"]["inputs"]["cage"]


def test_output_into_a_closed_pipe_is_not_an_error(tmp_path):
    """`loads ... | head -1`: the reader closes the pipe early; no BrokenPipeError traceback."""
    proc = subprocess.Popen([sys.executable, "-m", "exudyn_bearing", "loads", "--axial", "1300", "--rpm", "1800"],
                            cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    proc.stdout.close()  # before the child writes anything (it takes ~1 s to start)
    _, err = proc.communicate(timeout=120)
    assert "Traceback" not in err and "BrokenPipe" not in err, err[-2000:]


# ---------------------------------------------------------------------------------------
# Commands that agree (loads default to 0, negative and list values parse, units and signs)
# ---------------------------------------------------------------------------------------
def test_loads_default_to_zero_and_a_radial_only_run_needs_no_axial(tmp_path):
    data, _ = cli_json("simulate", "--radial", "1000", "--time", "0.002", cwd=tmp_path)
    assert data["axial"] == 0.0 and data["radial"] == 1000.0 and data["steps"] > 1
    proc, _ = cli("simulate", "--time", "0.002", cwd=tmp_path)
    assert proc.returncode == 2 and "no load" in proc.stderr and "--axial" in proc.stderr, proc.stderr


def test_steady_with_a_radial_load_solves_the_quasi_dynamic_state(tmp_path):
    """``steady --radial`` solves every ball's own balance (MODEL.md §12a): at 1300 N axial +
    1 N radial its skid measure and loads are the axial steady state's (a different solver,
    one ball) and its drive power its losses; the JSON says what produced it."""
    data, _ = cli_json("steady", "--axial", "1300", "--radial", "1", cwd=tmp_path)
    axial, _ = cli_json("steady", "--axial", "1300", cwd=tmp_path)
    assert data["converged"] and data["units"]["inner_load"] == "N" and "bearing" in data["inputs"]
    assert data["kinematic_cage_slip_percent"] == pytest.approx(axial["kinematic_cage_slip_percent"], abs=0.01)
    assert np.allclose(data["inner_load"], axial["inner_load"], rtol=2e-3)
    assert data["drive_power_W"] == pytest.approx(data["power_loss_W"]["total"], rel=1e-4)
    proc, _ = cli("steady", "--axial", "300", "--radial", "200", cwd=tmp_path)
    assert proc.returncode == 0 and "Quasi-dynamic state under combined load" in proc.stdout, proc.stderr[-2000:]
    assert "kinematic cage slip" in proc.stdout and "inner load" in proc.stdout
    proc, _ = cli("steady", cwd=tmp_path)
    assert proc.returncode == 2 and "--axial must be positive" in proc.stderr, proc.stderr
    proc, _ = cli("steady", "--axial", "-300", "--radial", "200", cwd=tmp_path)
    assert proc.returncode == 2 and "axial" in proc.stderr and "Traceback" not in proc.stderr


@pytest.mark.parametrize("args", [["skid-map", "--axial", "-300,300", "--rpm", "900", "--out", "m"],
                                  ["skid-map", "--axial", "300", "--radial", "-100:100:3", "--rpm", "900", "--out", "m"],
                                  ["loads", "--axial", "-300"], ["simulate", "--axial", "-300", "--time", "0.002"]],
                         ids=["list", "range", "loads", "simulate"])
def test_negative_values_parse_and_get_a_message_about_the_direction(args, tmp_path):
    """argparse alone reads "-300,300" as an option ("expected one argument"); the value must
    reach the command, whose message names the key (and, for the axial load, the way round)."""
    proc, _ = cli(*args, cwd=tmp_path, timeout=120)
    assert proc.returncode == 2, proc.stdout[-1000:]
    assert "expected one argument" not in proc.stderr and "Traceback" not in proc.stderr
    key = "radial" if "-100:100:3" in args else "axial"
    assert re.search(rf"^error: .*{key}", proc.stderr, re.M | re.I), proc.stderr
    if key == "axial":
        assert "other way round" in proc.stderr, proc.stderr


@pytest.mark.slow
def test_help_states_units_and_sign_conventions(tmp_path):
    for command in ("loads", "simulate", "steady", "render", "skid-map"):
        proc, _ = cli(command, "--help", cwd=tmp_path)
        text = " ".join(proc.stdout.split())
        assert "N" in text and "bearing axis" in text, (command, text)
        if command != "steady":
            assert "x axis" in text, (command, text)


def test_short_runs_are_too_short_to_judge_not_drifting(reference_run, tmp_path):
    """A run under the 50 ms the settling test needs (its last two sixths would hide a slow
    drift) says so: JSON null, the text "too short to judge", not "still drifting"; a long
    enough run is judged (True or False)."""
    data, _ = reference_run
    assert data["settled"] is None and data["time"] < 0.05
    proc, _ = cli("simulate", "--axial", "1300", "--time", "0.005", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "too short to judge" in proc.stdout and "still drifting" not in proc.stdout
    from exudyn_bearing import settled_label, simulate

    judged = simulate(axial_force=1300.0, rpm=1800.0, time=0.05)
    assert judged.settled is True  # from its steady start
    assert [settled_label(v) for v in (True, False, None)] == ["yes", "no", "too short to judge"]


@pytest.mark.slow
def test_the_skid_measure_is_read_first(reference_run, tmp_path):
    """The kinematic cage slip (the skid measure, MODEL.md §7) comes before the paper's P19 in
    the JSON, the text output, the skid map's CSV columns and markdown, and the summary."""
    data, _ = reference_run
    keys = list(data)
    assert keys.index("kinematic_cage_slip_percent") < keys.index("cage_slip_percent")
    proc, _ = cli("simulate", "--axial", "1300", "--time", "0.005", cwd=tmp_path)
    text = proc.stdout
    assert 0 <= text.index("kinematic cage slip") < text.index("paper's P19"), text
    proc, _ = cli("skid-map", "--axial", "1300", "--rpm", "1800", "--time", "0.002", "--out", "m", "--workers", "1",
                  "--no-refine", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    header = (tmp_path / "m" / "skid_map.csv").read_text().splitlines()[0].split(",")
    assert header.index("kinematic_cage_slip_percent") < header.index("cage_slip_percent")
    md = (tmp_path / "m" / "skid_map.md").read_text()
    assert md.index("kinematic cage slip") < md.index("paper's P19")
    from exudyn_bearing import simulate

    summary = list(simulate(axial_force=1300.0, rpm=1800.0, time=0.002).results.summary())
    assert summary.index("kinematic_cage_slip_percent") < summary.index("cage_slip_percent")


@pytest.mark.slow
def test_assumptions_are_stated_where_results_are_read(tmp_path):
    """The drag's oil fraction and whether rolling resistance and the thermal film are on, in
    the JSON (with units) and the text of simulate and steady (issue 34: a fully flooded drag
    took 130 of 135 W of a 7205 at 12 000 rpm without saying so)."""
    data, _ = cli_json("simulate", "--axial", "1300", "--time", "0.002", "--rolling-resistance", cwd=tmp_path)
    a = data["assumptions"]
    assert a["oil_volume_fraction"] == 1.0 and a["rolling_resistance"] is True and a["thermal_film"] is False
    assert a["limiting_shear_coefficient"] == 0.047 and set(data["units"]["assumptions"]) == set(a)
    data, _ = cli_json("steady", "--axial", "1300", "--no-drag", cwd=tmp_path)
    assert data["assumptions"]["oil_volume_fraction"] is None and data["assumptions"]["rolling_resistance"] is False
    assert "assumptions" in data["units"]
    proc, _ = cli("simulate", "--axial", "1300", "--time", "0.002", cwd=tmp_path)
    assert re.search(r"assumptions\s+ball drag C_D 0.5 at oil fraction 1 \(fully flooded\); rolling resistance off; "
                     r"thermal film off", proc.stdout), proc.stdout


def test_the_call_says_where_its_time_went_and_profile_splits_the_integration(tmp_path):
    """``simulate --profile``: the whole call's parts are non-negative and add up to at most the
    whole; the integration's force evaluations are at least one per Newton iteration (each
    iteration evaluates the residual) and their time, the Jacobians' and the rest add up to
    the integration; the text names them. Without ``--profile`` the split is empty."""
    data, _ = cli_json("simulate", "--axial", 1300, "--time", 0.005, "--profile", cwd=tmp_path)
    call, prof = data["call_time_s"], data["integration_profile"]
    parts = [call[k] for k in ("build", "assembly", "integration", "outputs")]
    assert min(parts) >= 0 and sum(parts) <= call["whole"] + 1e-9 and call["integration"] > 0
    assert data["units"]["call_time_s"]["whole"] == "s" and data["units"]["integration_profile"]["force_evaluation_us"] == "us"
    assert prof["steps"] == data["steps"] and prof["force_evaluations"] >= data["newton_iterations"] > 0
    assert prof["jacobians"] >= 1
    total = prof["force_evaluations_s"] + prof["jacobians_s"] + prof["exudyn_and_glue_s"]
    assert total == pytest.approx(call["integration"], rel=1e-9) and prof["exudyn_and_glue_s"] > 0
    text = subprocess.run([sys.executable, "-m", "exudyn_bearing", "simulate", "--axial", "1300", "--time", "0.005",
                           "--profile"], capture_output=True, text=True, cwd=tmp_path)
    assert text.returncode == 0 and "whole call" in text.stdout and "force evaluations" in text.stdout
    plain, _ = cli_json("simulate", "--axial", 1300, "--time", 0.005, cwd=tmp_path)
    assert plain["integration_profile"] == {} and plain["call_time_s"]["whole"] > 0
