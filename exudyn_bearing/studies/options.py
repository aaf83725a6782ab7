"""The command line's options, one function per command (:mod:`exudyn_bearing.studies.cli`
runs the commands): units and sign conventions of the loads in one place, the traction
choices from the registry of traction laws (:data:`contact.traction_laws.TRACTION_LAWS`)."""
from __future__ import annotations

import argparse
import re

from contact.ballrace import ContactLaw as ContactLawDefaults
from contact.traction_laws import TRACTION_LAWS

__all__ = ["COMMANDS", "AXIAL_HELP", "RADIAL_HELP", "DefaultsFormatter", "join_negative_values"]


#: the loads' help: units and sign conventions, the same in every command
AXIAL_HELP = ("axial force on the inner race, N, along the bearing axis (+z of the bearing frame): it presses the "
              "inner race against the balls' contact side; >= 0 (a load the other way: mount the bearing the other "
              "way round)")
RADIAL_HELP = "radial force on the inner race, N, along the bearing frame's x axis"
#: single-value options whose value may start with a minus sign ("-300,300", "-300:300:5")
_LIST_OPTIONS = ("--axial", "--radial", "--rpm", "--sizes")
_NUMBER_LIST = re.compile(r"^-[0-9.][0-9.eE+\-]*([,:][-+]?[0-9.][0-9.eE+\-]*)*$")


def join_negative_values(argv):
    """``--axial -300,300`` → ``--axial=-300,300``: argparse reads a value starting with "-"
    that is not a plain number as an option."""
    out = []
    for token in argv:
        if out and out[-1] in _LIST_OPTIONS and _NUMBER_LIST.match(token):
            out[-1] = f"{out[-1]}={token}"
        else:
            out.append(token)
    return out


def _traction_option(p) -> None:
    p.add_argument("--traction", choices=tuple(TRACTION_LAWS), default=None,
                   help="ball-race traction law: " + "; ".join(f"{m.name} = {m.summary}" for m in TRACTION_LAWS.values())
                        + " (default: the bearing file's [contact_law], else crook-limited)")
    # the losses beyond the paper (MODEL.md §11), off by default
    p.add_argument("--rolling-resistance", action="store_true",
                   help="hydrodynamic rolling resistance at each contact (MODEL.md §11b; or the bearing file's "
                        "[contact_law])")
    p.add_argument("--thermal-film", action="store_true",
                   help="inlet-shear-heating reduction of the film thickness (MODEL.md §11e; or the bearing file's "
                        "[contact_law])")


class DefaultsFormatter(argparse.HelpFormatter):
    """Appends "(default: X)" where an option has a default and its help does not name one."""

    def _get_help_string(self, action):
        text = action.help or ""
        if (action.default not in (None, False, argparse.SUPPRESS) and "default" not in text
                and action.option_strings):
            text += " (default: %(default)s)"
        return text




def _loads_options(p) -> None:
    """The options of ``loads``."""
    p.add_argument("--axial", type=float, default=0.0, help=AXIAL_HELP)
    p.add_argument("--radial", type=float, default=0.0, help=RADIAL_HELP)
    p.add_argument("--rpm", type=float, default=0.0, help="inner-race speed, rev/min (0: no centrifugal force)")
    p.add_argument("--moment", type=float, nargs=2, metavar=("MX", "MY"), help="tilting moment, N m (frees the tilt)")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    p.add_argument("--fixed-angle", action="store_true", help="the paper's fixed contact angle (P4–P6)")
    p.add_argument("--hold-axial", action="store_true", help="hold the axial displacement at zero")
    p.add_argument("--exact-hertz", action="store_true", help="exact elliptic integrals instead of Brewe–Hamrock")
    p.add_argument("--json", action="store_true", help="print JSON instead of a table")


def _simulate_options(p) -> None:
    """The options of ``simulate``."""
    from ..simulation.runner import SOLVERS

    p.add_argument("--axial", type=float, default=0.0, help=AXIAL_HELP)
    p.add_argument("--radial", type=float, default=0.0, help=RADIAL_HELP)
    p.add_argument("--rpm", type=float, default=1800.0, help="inner-race speed, rev/min (outer race fixed)")
    p.add_argument("--time", type=float, default=0.05, help="simulated time, s")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    p.add_argument("--solver", choices=SOLVERS, default="generalized-alpha", help="time integrator")
    p.add_argument("--step", type=float, default=None,
                   help="time step, s (default: 1e-4, less for small, stiff balls; docs/MODEL.md §10a)")
    p.add_argument("--output-step", type=float, default=5e-4, help="output period, s")
    p.add_argument("--order", type=int, default=None,
                   help="traction quadrature order (default: the bearing file's [contact_law], else "
                        f"{ContactLawDefaults.quadrature_order})")
    _traction_option(p)
    p.add_argument("--no-drag", action="store_true", help="switch the ball drag off (with the jet oil's momentum, "
                   "[drag] oil_flow)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.add_argument("--error-estimate", action="store_true",
                   help="repeat at half the step and report the differences as an error estimate")
    p.add_argument("--start", choices=("auto", "steady", "rolling"), default="auto",
                   help="start state: steady (axial: the steady state; combined load: every ball's own balance, "
                        "MODEL.md §12a), rolling (pure rolling), auto (steady where it applies, else rolling)")
    p.add_argument("--plot", metavar="PNG", help="save the paper-style plots of the run (needs the plot extra); "
                   "with temperatures also PNG's name + '_temperatures.png'")
    _temperature_options(p)
    p.add_argument("--profile", action="store_true",
                   help="split the integration's time: force evaluations, Jacobians, Exudyn's own work and glue")


def _steady_options(p) -> None:
    """The options of ``steady``."""
    p.add_argument("--axial", type=float, default=0.0, help=AXIAL_HELP + "; > 0 here without radial load")
    p.add_argument("--radial", type=float, default=0.0,
                   help=RADIAL_HELP + "; not 0: every ball's own balance under the combined load, the "
                        "quasi-dynamic state (MODEL.md §12a)")
    p.add_argument("--rpm", type=float, default=1800.0, help="inner-race speed, rev/min (outer race fixed)")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    _traction_option(p)
    p.add_argument("--no-drag", action="store_true", help="switch the ball drag off (with the jet oil's momentum, "
                   "[drag] oil_flow)")
    p.add_argument("--thermal", action="store_true",
                   help="solve the thermal network with the state (MODEL.md §14): the bearing file's [thermal], "
                        "else its defaults; a file with [thermal] solves it without this flag")
    p.add_argument("--json", action="store_true", help="print JSON")


def _render_options(p) -> None:
    """The options of ``render``."""
    p.add_argument("--axial", type=float, default=1300.0, help=AXIAL_HELP)
    p.add_argument("--radial", type=float, default=0.0, help=RADIAL_HELP)
    p.add_argument("--rpm", type=float, default=1800.0, help="inner-race speed, rev/min")
    p.add_argument("--time", type=float, default=0.002, help="simulated time, s")
    p.add_argument("--frames", type=int, default=4, help="number of frames spread over the run")
    p.add_argument("--backend", choices=("auto", "opengl", "raytracer"), default="auto",
                   help="auto: OpenGL with an X display (e.g. xvfb-run), else the raytracer")
    p.add_argument("--out", required=True, help="output directory")
    p.add_argument("--gif", help="also write the frames as an animated GIF to this file")
    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    _traction_option(p)


def _signal_options(p, time: float, per: str = "") -> None:
    """The options of a vibration signal: its length, sampling, band, masking, fluctuation and
    housing (``vibration`` and ``dataset``; ``per``: e.g. " per case")."""
    p.add_argument("--time", type=float, default=time, help="simulated time" + per + ", s")
    p.add_argument("--settle", type=float, default=0.02, help="start left out of the spectra, s")
    p.add_argument("--sample-rate", type=float, default=20000.0, help="output sample rate, Hz (the step is at most "
                                                                        "its period; the housing is recorded through an "
                                                                        "anti-aliasing filter at 0.4 x this rate)")
    p.add_argument("--band", nargs="+", default=["auto"], metavar="BAND",
                   help="envelope band: auto (the band of the largest spectral kurtosis, Antoni's fast "
                        "kurtogram, MODEL.md eq. 13.9), housing (0.6-1.4 x the housing resonance), or LOW:HIGH "
                        "(or LOW HIGH) in Hz")
    p.add_argument("--snr", type=float, metavar="DB", help="measurement noise at this signal-to-noise ratio, dB "
                                                            "(default: none; MODEL.md §13b)")
    p.add_argument("--unbalance", type=float, default=0.0, metavar="A",
                   help="the shaft's unbalance line on the housing, m/s^2 (default 0)")
    p.add_argument("--mesh", type=float, nargs="+", metavar="X", help="a gear mesh on the shaft: TEETH AMPLITUDE_m/s^2 "
                                                                      "[MODULATION 0-1] (sidebands at +- the shaft)")
    p.add_argument("--housing-mode", type=float, nargs=3, action="append", metavar=("HZ", "ZETA", "KG"),
                   help="a further housing resonance between the seat and the sensor, driven by the bearing's force "
                        "(frequency, damping ratio, modal mass; repeat for more; default none)")
    p.add_argument("--speed-fluctuation", type=float, default=0.0, metavar="PCT",
                   help="the shaft speed's random fluctuation, RMS %% of the rpm (default 0: steady)")
    p.add_argument("--load-fluctuation", type=float, default=0.0, metavar="PCT",
                   help="the load's random fluctuation, RMS %% of the load (default 0: steady)")
    p.add_argument("--fluctuation-bandwidth", type=float, default=5.0, metavar="HZ",
                   help="the fluctuations' highest frequency, Hz (default 5)")
    p.add_argument("--seed", type=int, default=0, help="seed of the noise and the fluctuations (default 0)")
    p.add_argument("--housing-frequency", type=float, help="housing resonance, Hz (default: the bearing file's "
                                                           "[housing], else 3000)")
    p.add_argument("--housing-mass", type=float, help="housing mass (ring included), kg (default: the file's, else 2)")
    p.add_argument("--housing-damping", type=float, help="housing damping ratio (default: the file's, else 0.05)")


def _temperature_options(p) -> None:
    """The thermal network integrated with the bodies (``simulate`` and ``vibration``)."""
    p.add_argument("--thermal", action="store_true",
                   help="integrate the thermal network with the bodies (MODEL.md §14g): the bearing file's "
                        "[thermal], else its defaults; a file with [thermal] runs it without this flag")
    p.add_argument("--initial-temperatures", choices=("auto", "steady", "inlet"), default="auto",
                   help="with temperatures: start from the thermal steady state (constant loads; combined "
                        "or radial: the quasi-dynamic one), every node at the oil inlet, or auto (steady where "
                        "it applies, else inlet)")


def _vibration_options(p) -> None:
    """The options of ``vibration``."""
    p.add_argument("--bearing", help="bearing TOML file with [[defect]] / [waviness] (default: the reference bearing)")
    p.add_argument("--rpm", type=float, required=True, help="inner-race speed, rev/min (outer race on the housing)")
    p.add_argument("--axial", type=float, default=0.0, help=AXIAL_HELP)
    p.add_argument("--radial", type=float, default=0.0, help=RADIAL_HELP)
    _signal_options(p, time=0.5)
    p.add_argument("--out", default="out/vibration", help="output directory (signal.csv, vibration.json)")
    p.add_argument("--error-estimate", action="store_true",
                   help="repeat at half the step and report the changes of the strongest envelope line "
                        "(twice the amplitude's change bounds its error, MODEL.md §13c)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.add_argument("--plot", metavar="PNG", help="signal, spectrum and envelope spectrum with the fault frequencies; "
                   "with temperatures also PNG's name + '_temperatures.png'")
    _temperature_options(p)
    p.add_argument("--plot-max", type=float, metavar="HZ", help="the plot's envelope spectrum up to HZ (default: "
                                                                 "5 x the highest of BPFO, BPFI, 2 BSF)")


def _dataset_options(p) -> None:
    """The options of ``dataset``."""
    p.add_argument("--bearing", help="bearing TOML file, its [waviness] and [housing] kept, no [[defect]] "
                                     "(default: the reference bearing)")
    p.add_argument("--faults", default="none,outer,inner,ball",
                   help="fault types, a comma list of none (a perfect bearing), outer, inner (a notch across the "
                        "track where the radial load presses), ball (a round pit on ball 0)")
    p.add_argument("--sizes", default="0.0005,0.001", help="fault lengths along the rolling direction (a pit's "
                                                             "diameter), m: start:stop:count or a,b,c")
    p.add_argument("--depth", type=float, default=0.2e-3, help="fault depth, m")
    p.add_argument("--axial", default="1300", help="axial loads, N: start:stop:count or a,b,c (" +
                   AXIAL_HELP.split(", N, ", 1)[1] + ")")
    p.add_argument("--radial", default="500", help="radial loads, N: start:stop:count or a,b,c (along the bearing "
                                                   "frame's x axis)")
    p.add_argument("--rpm", default="1800", help="inner-race speeds, rpm: start:stop:count or a,b,c")
    _signal_options(p, time=0.2, per=" per case")
    p.add_argument("--out", default="out/dataset", help="output directory (one NPZ per case, index.csv, inputs.json; "
                                                        "resumes what it finds there)")
    p.add_argument("--workers", type=int, default=None, help="local worker processes (default: CPU count)")
    p.add_argument("--scheduler", help="Dask scheduler address (runs the cases on that cluster)")
    _traction_option(p)


def _skid_map_options(p) -> None:
    """The options of ``skid-map``."""
    from . import skidmap

    p.add_argument("--bearing", help="bearing TOML file (default: the reference bearing)")
    p.add_argument("--axial", default=",".join(f"{v:g}" for v in skidmap.DEFAULT_AXIAL),
                   help="axial loads, N: start:stop:count or a,b,c (" + AXIAL_HELP.split(", N, ", 1)[1] + ")")
    p.add_argument("--radial", default="0", help="radial loads, N: start:stop:count or a,b,c (along the bearing "
                                                 "frame's x axis)")
    p.add_argument("--rpm", default=",".join(f"{v:g}" for v in skidmap.DEFAULT_RPM), help="inner-race speeds, rpm")
    p.add_argument("--time", type=float, default=skidmap.DEFAULT_TIME,
                   help="fixed simulated time per point, s (default: until settled, 0.1 s doubling up to "
                        f"{skidmap.MAX_TIME:g} s)")
    p.add_argument("--out", default="out/skid_map", help="output directory (resumes what it finds there)")
    p.add_argument("--workers", type=int, default=None, help="local worker processes (default: CPU count)")
    p.add_argument("--scheduler", help="Dask scheduler address (runs the grid on that cluster)")
    p.add_argument("--no-refine", action="store_true",
                   help="skip the thresholds' steady-state refinement and its dynamic confirmation")
    _traction_option(p)


#: command -> (its help line, the function adding its options)
COMMANDS = {
    "loads": ("quasi-static load distribution (MODEL.md §4)", _loads_options),
    "simulate": ("dynamic Exudyn run of one bearing (MODEL.md §1–§7)", _simulate_options),
    "steady": ("steady rolling state under pure axial load, no time integration (MODEL.md §12)", _steady_options),
    "render": ("render a run to PNG frames (headless: Xvfb/OpenGL or the raytracer)", _render_options),
    "vibration": ("housing vibration with race defects and waviness (MODEL.md §13)", _vibration_options),
    "skid-map": ("skid-risk map over load and speed (the main job)", _skid_map_options),
    "dataset": ("labelled vibration signals over fault type, size, load and speed (MODEL.md §13b)",
                _dataset_options),
}
