"""Gaits: joint torques that make a snake move, for :func:`~snakecg.simulate.simulate`.

* :class:`Serpenoid` is Hirose's serpenoid curve sampled at the joints (lateral undulation):
  joint ``j`` (1 = the tail's joint) follows
  ``q_j(t) = amplitude * sin(2 pi frequency t + (j - 1) phase_lag) + offset``.
  A negative ``phase_lag`` sends the wave from the tail towards the head (the tail's joint
  leads); a positive one from the head towards the tail. ``offset`` bends the whole body
  (turning).
* :class:`SerpenoidPD` is the feedback law ``tau(t, state)`` of a joint-space PD controller
  that tracks a serpenoid, ``tau = kp (q_ref - q) + kd (qdot_ref - qdot)``, saturated to a
  torque box (by default the robot's effort limits).
* :class:`TorqueTable` is a torque that follows a table of samples in time, linearly
  interpolated or held (zero-order) between them, a law ``tau(t)``.

All three are plain callables: any other law ``tau(t)`` or ``tau(t, state)`` plugs in the same
way.
"""

from __future__ import annotations

import math

import numpy as np

from .._inputs import to_float
from ..engine.binding import SCENE_LAWS
from ..errors import InputError

__all__ = ["Serpenoid", "SerpenoidPD", "TorqueTable", "serpenoid_controller"]


#: Largest angle (rad) and frequency (Hz) of a serpenoid: beyond them the curve means nothing.
ANGLE_MAX, FREQUENCY_MAX = 1e3, 1e6


def _finite(name: str, value, *, nonnegative: bool = False, largest: float = ANGLE_MAX
            ) -> float:
    ok = not isinstance(value, bool) and isinstance(value, (int, float, np.integer, np.floating))
    v = to_float(value) if ok else math.nan
    if not math.isfinite(v) or (nonnegative and v < 0) or abs(v) > largest:
        lo = "0" if nonnegative else f"-{largest:g}"
        raise InputError(f"{name} must be a number from {lo} to {largest:g}, got {value!r}")
    return v


def _gains(name: str, value, n: int, problems: list[str]) -> np.ndarray:
    arr = np.asarray(value, dtype=float) if not isinstance(value, (str, bytes)) else None
    if arr is None or arr.ndim > 1 or (arr.ndim == 1 and arr.shape != (n,)) \
            or not np.all(np.isfinite(arr)) or np.any(arr < 0):
        problems.append(f"{name} must be a number >= 0 or {n} of them (one per joint), "
                        f"got {value!r}")
        return np.zeros(n)
    return np.broadcast_to(arr, (n,)).astype(float)


class Serpenoid:
    """Hirose's serpenoid curve at the joints: ``q_j(t) = amplitude sin(2 pi frequency t +
    (j - 1) phase_lag) + offset`` for ``j = 1..n_joints`` (rad, s, Hz).

    :meth:`angles`, :meth:`rates` and :meth:`accelerations` give the reference and its time
    derivatives at ``t``, each an ``(n_joints,)`` array.
    """

    def __init__(self, n_joints: int, amplitude, frequency, phase_lag, offset=0.0):
        if isinstance(n_joints, bool) or not isinstance(n_joints, (int, np.integer)) \
                or n_joints < 1:
            raise InputError(f"n_joints must be an integer >= 1, got {n_joints!r}")
        self.n_joints = int(n_joints)
        self.amplitude = _finite("amplitude", amplitude)  # the sign mirrors the wave
        self.frequency = _finite("frequency", frequency, nonnegative=True,
                                 largest=FREQUENCY_MAX)
        self.phase_lag = _finite("phase_lag", phase_lag)
        self.offset = _finite("offset", offset)
        self._phases = np.arange(self.n_joints) * self.phase_lag

    def _arg(self, t) -> np.ndarray:
        return 2.0 * math.pi * self.frequency * float(t) + self._phases

    def angles(self, t) -> np.ndarray:
        return self.amplitude * np.sin(self._arg(t)) + self.offset

    def rates(self, t) -> np.ndarray:
        w = 2.0 * math.pi * self.frequency
        return self.amplitude * w * np.cos(self._arg(t))

    def accelerations(self, t) -> np.ndarray:
        w = 2.0 * math.pi * self.frequency
        return -self.amplitude * w * w * np.sin(self._arg(t))

    def __repr__(self) -> str:
        return (f"Serpenoid(n_joints={self.n_joints}, amplitude={self.amplitude:g}, "
                f"frequency={self.frequency:g}, phase_lag={self.phase_lag:g}, "
                f"offset={self.offset:g})")


class SerpenoidPD:
    """Feedback law ``tau(t, state)``: a PD controller on the joint angles that tracks a
    :class:`Serpenoid`, ``tau = kp (q_ref(t) - q) + kd (qdot_ref(t) - qdot)``, each torque
    clipped to ``[-tau_max_j, tau_max_j]``.

    ``kp`` (N m/rad) and ``kd`` (N m s/rad): one number or one per joint. ``tau_max``:
    ``"robot"`` (default: the robot's effort limits, no clipping where it has none), a number
    or one per joint (N m), or None (no clipping). ``history`` is not kept: the trajectory
    records the torques it applied.
    """

    def __init__(self, model, curve: Serpenoid, *, kp, kd, tau_max="robot"):
        na = int(model.n_joints)
        if not isinstance(curve, Serpenoid):
            raise InputError(f"curve must be a snakecg.simulate.Serpenoid, got {curve!r:.60}")
        problems: list[str] = []
        if curve.n_joints != na:
            problems.append(f"curve has {curve.n_joints} joints, the model {na}")
        self.kp = _gains("kp", kp, na, problems)
        self.kd = _gains("kd", kd, na, problems)
        self.tau_max = self._box(model, tau_max, na, problems)
        if problems:
            raise InputError("; ".join(problems))
        self.curve = curve
        # the law's compiled home (scene_run.c's core_scene_law), where the model has one
        self._law = getattr(getattr(model, "core", None), "scene_law", None)
        self._params = self.engine_law(na)[1]
        self._ns = na + 3

    def __getstate__(self):
        state = self.__dict__.copy()
        state["_law"] = None  # a compiled entry point does not pickle: NumPy's copy then
        return state

    @staticmethod
    def _box(model, tau_max, na: int, problems: list[str]):
        if isinstance(tau_max, str) and tau_max == "robot":
            e = getattr(getattr(model, "robot", None), "effort_limits", None)
            return None if e is None else np.asarray(e, dtype=float).copy()
        if tau_max is None:
            return None
        arr = np.asarray(tau_max, dtype=float) if not isinstance(tau_max, (str, bytes)) \
            else np.array(math.nan)
        if arr.ndim > 1 or (arr.ndim == 1 and arr.shape != (na,)) \
                or not np.all(np.isfinite(arr)) or np.any(arr <= 0):
            problems.append(f"tau_max must be 'robot', None, a number > 0 or {na} of them "
                            f"(N m, one per joint), got {tau_max!r:.60}")
            return None
        return np.broadcast_to(arr, (na,)).astype(float)

    def engine_law(self, n_a: int):
        """``("serpenoid_pd", parameters)``: the law as the compiled engine's run evaluates it
        (``snakecg/engine/scene_run.c``, the formula of :meth:`__call__` and
        :class:`Serpenoid`): amplitude, ``2 pi frequency``, offset, whether to clip, then the
        joints' phases, ``kp``, ``kd`` and ``tau_max`` (n_a each); None for another model's
        joint count."""
        c = self.curve
        if c.n_joints != n_a:
            return None
        clip = self.tau_max is not None
        return "serpenoid_pd", np.concatenate((
            [c.amplitude, 2.0 * math.pi * c.frequency, c.offset, 1.0 if clip else 0.0],
            c._phases, self.kp, self.kd, self.tau_max if clip else np.zeros(n_a)))

    def __call__(self, t, state) -> np.ndarray:
        q = np.ascontiguousarray(state.q, dtype=float)
        v = np.ascontiguousarray(state.v, dtype=float)
        if self._law is not None and q.shape == v.shape == (self._ns,):
            tau = np.empty(self._ns - 3)
            self._law(SCENE_LAWS["serpenoid_pd"], self._params.ctypes.data, float(t),
                      q.ctypes.data, v.ctypes.data, math.inf, tau.ctypes.data)
            return tau
        # without a compiled engine (backend="casadi"): the same formula in NumPy
        c = self.curve
        tau = self.kp * (c.angles(t) - state.q[3:]) + self.kd * (c.rates(t) - state.v[3:])
        if self.tau_max is not None:
            np.clip(tau, -self.tau_max, self.tau_max, out=tau)
        return tau


def serpenoid_controller(model, *, amplitude, frequency, phase_lag, offset=0.0, kp, kd,
                         tau_max="robot") -> SerpenoidPD:
    """A :class:`SerpenoidPD` law for ``model``: lateral undulation with ``amplitude`` (rad),
    ``frequency`` (Hz), ``phase_lag`` between neighbouring joints (rad) and ``offset`` (rad),
    tracked with gains ``kp``, ``kd`` within ``tau_max`` (see :class:`SerpenoidPD`)."""
    curve = Serpenoid(int(model.n_joints), amplitude, frequency, phase_lag, offset)
    return SerpenoidPD(model, curve, kp=kp, kd=kd, tau_max=tau_max)


class TorqueTable:
    """A torque law ``tau(t)`` from a table: ``times`` (k,) strictly increasing (s) and
    ``torques`` (k, n_a) (N m). Between samples the torque is interpolated linearly
    (``interpolation="linear"``) or held at the earlier sample (``"previous"``, a zero-order
    hold); before the first sample and after the last it keeps the end value."""

    INTERPOLATIONS = ("linear", "previous")

    def __init__(self, times, torques, *, interpolation: str = "linear"):
        problems: list[str] = []
        t = np.asarray(times, dtype=float) if not isinstance(times, (str, bytes)) else None
        if t is None or t.ndim != 1 or t.size < 1 or not np.all(np.isfinite(t)) \
                or np.any(np.diff(t) <= 0):
            problems.append(f"times must be finite, strictly increasing seconds, one "
                            f"dimension, got {times!r:.60}")
            t = None
        tq = np.asarray(torques, dtype=float) if not isinstance(torques, (str, bytes)) \
            else None
        if tq is None or tq.ndim != 2 or (t is not None and tq.shape[0] != t.size) \
                or not np.all(np.isfinite(tq)):
            k = "k" if t is None else str(t.size)
            problems.append(f"torques must be finite numbers of shape ({k}, n_a) (one row per "
                            f"time), got shape {np.shape(torques)}")
        if interpolation not in self.INTERPOLATIONS:
            problems.append(f"interpolation must be one of {', '.join(self.INTERPOLATIONS)}, "
                            f"got {interpolation!r}")
        if problems:
            raise InputError("; ".join(problems))
        self.times, self.torques, self.interpolation = t, tq, interpolation

    @property
    def n_joints(self) -> int:
        return int(self.torques.shape[1])

    def engine_law(self, n_a: int):
        """``("table" or "hold", parameters)``: the table as the compiled engine's run
        evaluates it (``snakecg/engine/scene_run.c``, the rule of :meth:`__call__`): the
        count k, the times, the torques row by row; None where the engine would not give the
        answer of :meth:`__call__` and its checks (another joint count, a torque beyond the
        force limit: the run's check then says so)."""
        from ..engine.rules import FORCE_LIMIT

        if self.n_joints != n_a or np.any(np.abs(self.torques) > FORCE_LIMIT):
            return None
        name = "table" if self.interpolation == "linear" else "hold"
        return name, np.concatenate(([float(self.times.size)], self.times,
                                     self.torques.reshape(-1)))

    def __call__(self, t) -> np.ndarray:
        ts, tq = self.times, self.torques
        i = int(np.searchsorted(ts, t, side="right")) - 1  # ts[i] <= t < ts[i + 1]
        if i < 0:
            return tq[0].copy()
        if i >= ts.size - 1 or self.interpolation == "previous":
            return tq[i].copy()
        s = (t - ts[i]) / (ts[i + 1] - ts[i])
        return (1.0 - s) * tq[i] + s * tq[i + 1]
