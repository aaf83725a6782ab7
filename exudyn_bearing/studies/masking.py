"""What masks a bearing's signal on a machine (MODEL.md §13b; issue 50 item 3): the recorded
housing acceleration with the housing's further resonances (driven by the bearing's force on
the housing), measurement noise at a stated signal-to-noise ratio and the lines other machine
parts put on it — the shaft's unbalance at the shaft rate, a gear mesh on the shaft with its
sidebands. Off by default: a clean study sees the bearing alone.

The lines and the noise are added to the recorded signal, as a measurement would carry them;
they are not forces on the model (an unbalance's rotating force, which would also move the
bearing's loads, is not built). Random slip is the model's own: :class:`Fluctuation` makes the
shaft speed and the load vary as slow random processes, so the cage's slip and the passages'
spacing vary with them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Masking", "Fluctuation"]


def _finite(name, value, low=0.0, allow_none=False):
    """Refuse ``value`` by its ``name`` ('record.field') unless a finite number >= ``low``."""
    if value is None and allow_none:
        return
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < low:
        raise ValueError(f"{name} must be a finite number >= {low:g}, got {value!r}")


def _whole(name, value, low=0):
    """Refuse ``value`` by its ``name`` ('record.field') unless an integer >= ``low``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
        raise ValueError(f"{name} must be an integer >= {low}, got {value!r}")


@dataclass(frozen=True)
class Masking:
    """Masking of the housing acceleration (SI units).

    Parameters
    ----------
    snr_db : float or None
        Measurement noise, white and Gaussian at the sample rate, at this signal-to-noise ratio
        in dB against the clean signal's RMS along the load (after the settling time); the same
        noise level on each axis. None: no noise.
    unbalance : float
        Amplitude of the shaft-rate line an unbalanced rotor puts on the housing, m/s², along
        the load. 0: none.
    mesh_teeth : int
        Teeth of a gear on the shaft: a mesh line at teeth × the shaft rate. 0: none.
    mesh_amplitude : float
        Its amplitude, m/s², along the load.
    mesh_modulation : float
        Depth of its amplitude modulation at the shaft rate (0–1): sidebands at ± the shaft rate,
        each mesh_amplitude × mesh_modulation / 2.
    seed : int
        Seed of the noise: the same seed, the same noise.
    modes : tuple of (frequency Hz, damping ratio, modal mass kg)
        The housing's further resonances between the bearing seat and the sensor: each a mode
        driven by the force the bearing puts on the housing (from the modelled housing's own
        motion, F = m a + c v + k x) whose acceleration adds to the recorded one (modal
        superposition, MODEL.md §13b). The bearing feels only the modelled housing: the modes'
        motion does not act back on its contacts (sound where their modal masses are large
        against the ring's). Empty: the modelled housing alone.
    """

    snr_db: float | None = None
    unbalance: float = 0.0
    mesh_teeth: int = 0
    mesh_amplitude: float = 0.0
    mesh_modulation: float = 0.0
    seed: int = 0
    modes: tuple = ()

    def __post_init__(self) -> None:
        _finite("masking.snr_db", self.snr_db, low=-math.inf, allow_none=True)
        _finite("masking.unbalance", self.unbalance)
        _finite("masking.mesh_amplitude", self.mesh_amplitude)
        _finite("masking.mesh_modulation", self.mesh_modulation)
        if self.mesh_modulation > 1.0:
            raise ValueError(f"masking.mesh_modulation must lie in [0, 1], got {self.mesh_modulation!r}")
        _whole("masking.mesh_teeth", self.mesh_teeth)
        _whole("masking.seed", self.seed)
        if self.mesh_teeth and not self.mesh_amplitude:
            raise ValueError("masking.mesh_amplitude: a gear mesh (mesh_teeth) needs its amplitude, m/s^2")
        modes = tuple(tuple(m) for m in self.modes)
        for i, mode in enumerate(modes):
            if len(mode) != 3:
                raise ValueError(f"masking.modes[{i}] must be (frequency Hz, damping ratio, modal mass kg), got {mode!r}")
            for name, value in zip(("frequency", "damping ratio", "modal mass"), mode):
                _finite(f"masking.modes[{i}] {name}", value)
                if not value > 0:
                    raise ValueError(f"masking.modes[{i}] {name} must be positive, got {value!r}")
        object.__setattr__(self, "modes", tuple(tuple(float(v) for v in m) for m in modes))

    @property
    def active(self) -> bool:
        return (self.snr_db is not None or self.unbalance > 0 or (self.mesh_teeth > 0 and self.mesh_amplitude > 0)
                or bool(self.modes))

    def apply(self, t, acceleration, direction, shaft_hz: float, settle: float = 0.0, force=None):
        """The recorded ``acceleration`` (T, 3) m/s² at times ``t`` (T,) s with the masking added:
        the modes' response to the bearing's ``force`` on the housing (T, 3) N (needed with
        ``modes``; :func:`mode_acceleration`), the machine lines along the unit ``direction``
        (3,), the noise on every axis at the SNR against the RMS along ``direction`` from
        ``settle`` s on of the signal with the modes."""
        t = np.asarray(t, dtype=float)
        out = np.array(acceleration, dtype=float, copy=True)
        if self.modes:
            if force is None:
                raise ValueError("masking.modes: the housing's further modes need the bearing's force on the housing")
            for mode in self.modes:
                out += mode_acceleration(t, force, *mode)
        direction = np.asarray(direction, dtype=float) / np.linalg.norm(direction)
        phase = 2.0 * np.pi * shaft_hz * t
        lines = self.unbalance * np.cos(phase)
        if self.mesh_teeth:
            lines = lines + self.mesh_amplitude * (1.0 + self.mesh_modulation * np.cos(phase)) * np.cos(
                self.mesh_teeth * phase)
        clean = out[t >= settle] @ direction
        out += np.outer(lines, direction)
        if self.snr_db is not None:
            rms = float(np.sqrt(np.mean((clean - np.mean(clean)) ** 2))) if clean.size else 0.0
            sigma = rms / 10.0 ** (self.snr_db / 20.0)
            out += np.random.default_rng(self.seed).normal(0.0, sigma, out.shape)
        return out


def mode_acceleration(t, force, frequency: float, damping_ratio: float, modal_mass: float):
    """Acceleration (T, 3) m/s² of one housing mode driven by ``force`` (T, 3) N sampled at the
    uniform times ``t`` (T,) s: ẍ + 2ζω ẋ + ω² x = F/m on each axis apart, H(iΩ) = −Ω² / (m (ω² − Ω²
    + 2iζωΩ)), at rest in its static deflection under the first force. The force is band-limited
    (it is, after the anti-aliasing filter), so the response is computed exactly in the frequency
    domain, zero-padded until the mode's ringing has decayed by 1e-6 (no wrap-around); linear
    interpolation between samples would take 30 % off a mode at 0.3 × the sample rate."""
    from scipy.fft import irfft, next_fast_len, rfft, rfftfreq

    t = np.asarray(t, dtype=float)
    force = np.asarray(force, dtype=float)
    force = force - force[0]
    dt = float(t[1] - t[0])
    omega = 2.0 * math.pi * frequency
    n = next_fast_len(t.size + int(math.ceil(math.log(1e6) / (damping_ratio * omega * dt))))
    w = 2.0 * math.pi * rfftfreq(n, dt)
    h = -w * w / (modal_mass * (omega * omega - w * w + 2j * damping_ratio * omega * w))
    return irfft(rfft(force, n, axis=0) * h[:, None], n, axis=0)[:t.size]


@dataclass(frozen=True)
class Fluctuation:
    """Slow random fluctuations of the shaft speed and the load (MODEL.md §13b): each a sum of
    ``components`` cosines at frequencies drawn uniformly from (0, ``bandwidth_hz``] with
    random phases, √(2/N) Σ cos(2π f_k t + φ_k) (unit RMS over a long run), scaled to the RMS
    share ``speed_percent`` / ``load_percent`` of the mean. ``seed``: the same seed, the same
    fluctuation (speed and load drawn apart). The bearing starts settled at their values at 0."""

    speed_percent: float = 0.0
    load_percent: float = 0.0
    bandwidth_hz: float = 5.0
    components: int = 16
    seed: int = 0

    def __post_init__(self) -> None:
        _finite("fluctuation.speed_percent", self.speed_percent)
        _finite("fluctuation.load_percent", self.load_percent)
        if self.speed_percent >= 30.0 or self.load_percent >= 30.0:
            raise ValueError("fluctuation: speed_percent and load_percent must stay below 30 (an RMS share of the "
                             f"mean), got {self.speed_percent!r}, {self.load_percent!r}")
        _finite("fluctuation.bandwidth_hz", self.bandwidth_hz)
        if not self.bandwidth_hz > 0:
            raise ValueError(f"fluctuation.bandwidth_hz must be positive, got {self.bandwidth_hz!r}")
        _whole("fluctuation.components", self.components, 1)
        _whole("fluctuation.seed", self.seed)

    def process(self, which: str):
        """The unit-RMS random process x(t) of ``which`` ('speed' or 'load'), a function of t s."""
        rng = np.random.default_rng([self.seed, ("speed", "load").index(which)])
        freq = rng.uniform(0.0, self.bandwidth_hz, self.components)
        freq[freq == 0.0] = self.bandwidth_hz
        phase = rng.uniform(0.0, 2.0 * np.pi, self.components)
        scale = math.sqrt(2.0 / self.components)

        def x(t):
            return float(scale * np.sum(np.cos(2.0 * np.pi * freq * t + phase)))
        return x

    def speed(self, rpm: float):
        """rpm(t) = rpm (1 + speed_percent/100 · x(t)), or ``rpm`` itself without a speed fluctuation."""
        if not self.speed_percent:
            return rpm
        x, share = self.process("speed"), 0.01 * self.speed_percent
        return lambda t: rpm * (1.0 + share * x(t))

    def load(self, force: float):
        """F(t) = F (1 + load_percent/100 · x(t)) N, or ``force`` itself without a load fluctuation."""
        if not self.load_percent or not force:
            return force
        x, share = self.process("load"), 0.01 * self.load_percent
        return lambda t: force * (1.0 + share * x(t))

