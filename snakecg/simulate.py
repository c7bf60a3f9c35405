"""Pushing over time: the coupled snake + object dynamics integrated from a state (issue #8).

The paper analyses one instant from rest; here the same equations are integrated over time,
with the velocity terms the instant analysis leaves out (``h_s``, the object's velocity terms,
``Adot v``), and with the transitions of the contact and of the wheels handled as events.

State and equations
-------------------
``y = (q, q_obj, v, v_obj, W)``: the snake's coordinates ``q`` (n_s) and velocities ``v``, the
object's pose ``q_obj = (x_o, y_o, psi)`` and twist ``v_obj`` (COM velocity and angular rate,
world frame, so ``d q_obj / dt = v_obj``), and three work integrals ``W`` (joint torques,
kinetic friction of sliding wheels, the external wrench on the object). The contact point is
fixed in the object frame (``rho``, from the scene's placement at ``t = 0``); it slides along
the contact link without friction (assumption 2).

Within a *mode* (which rows hold) the accelerations are those of eq. (12) with the held rows'
accelerations ``w_F = 0`` (eq. 13 with equality), computed by the compiled
``constrained_dynamics`` for that active set. Constraint drift is kept in check by Baumgarte
stabilisation of the held rows: the contact holds ``gddot = -2 alpha gdot - alpha^2 g`` and a
sticking wheel ``udot = -2 alpha u`` (``alpha = stabilization``, 1/s; the exact solution has
``g = gdot = u = 0``, so the term only acts on the integration error). At every event the
positions are projected back onto ``g = 0`` and the velocities onto the held rows (mass-weighted
projection), and the largest residual along the trajectory is reported.

Modes and events (``scipy.integrate.solve_ivp`` with terminal events, the mode re-solved at
each event):

* contact held: ``lam_c`` crossing zero downwards -> the contact separates; the contact point
  leaving the link (``s`` outside ``[0, l_k]``) -> the contact is lost for good;
* contact separated: the gap reaching zero with the point on the link -> plastic impact: the
  normal relative velocity is removed by an impulse that conserves momentum (bilateral ideal
  wheels take impulses too; wheels with bounded friction cannot, their force being finite),
  the kinetic energy lost ``1/2 Lam^T G_FF Lam`` is recorded;
* wheel sticking (``wheels`` scenario): ``|lam_i|`` reaching ``mu m_i g`` -> it breaks away and
  slides with kinetic friction ``-mu m_i g sign(u_i)`` opposing its lateral velocity ``u_i``;
* wheel sliding: ``u_i`` returning to zero -> it sticks again, or slides the other way.

At an event the new active set is the solution of the acceleration-level complementarity
problem (:func:`snakecg.solver.solve_active_set`) over the rows whose status is not fixed by
the velocities (a sliding wheel with ``u_i != 0`` is fixed; a separated contact with a positive
gap is fixed).

Torques: a constant vector, a function of time ``tau(t)``, or a feedback law ``tau(t, state)``
(:class:`State`), evaluated continuously or held over ``control_period`` (zero-order hold: the
law is called once per period with the state at the start of the period).
"""

from __future__ import annotations

import inspect
import math
import time
from dataclasses import dataclass, field

import numpy as np

from ._inputs import as_batch, to_float
from .errors import InputError, SnakecgError
from .solver import ABSENT, HELD, LOST, PIVOT_TOL, REGULARIZATION, SLIDE_NEG, SLIDE_POS
from .native import BoundFunction
from .solver import solve_active_set

__all__ = [
    "simulate",
    "Trajectory",
    "SimEvent",
    "State",
    "SimulationError",
    "least_slip_push_controller",
    "LeastSlipPush",
    "save_figures",
    "save_animation",
    "SCHEMA",
]

#: Version of the summary dictionary (``Trajectory.summary``, ``snakecg simulate --json``).
SCHEMA = "snakecg.simulate/1"

_STATE_NAMES = {ABSENT: "none", HELD: "stick", LOST: "lost", SLIDE_POS: "slide+",
                SLIDE_NEG: "slide-"}
_N_WORK = 3  # work integrals: joint torques, kinetic friction, object wrench
_METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")  # scipy.integrate.solve_ivp
#: Most output samples of one run (duration / output_dt; each sample holds ~1 kB of arrays).
MAX_OUTPUT_SAMPLES = 10**6
#: Most controller periods (duration / control_period; each one solves a torque query) and
#: most steps of the integrator allowed by max_step or fixed_step (duration / step).
MAX_PERIODS = 10**6
MAX_STEPS = 10**7
#: Most frames of an animation (each one is an image of ~100 kB held until the GIF is written).
MAX_FRAMES = 2000
#: Smallest relative tolerance solve_ivp can honour (100 machine epsilons; it raises smaller
#: ones to this with a warning) and largest Baumgarte rate (1/s: beyond it the correction
#: makes the equations stiff and the explicit integrators crawl).
RTOL_MIN = 100 * float(np.finfo(float).eps)
STABILIZATION_MAX = 1e6


class SimulationError(SnakecgError, RuntimeError):
    """The integration failed (integrator error, a torque law that returned bad values...)."""


# ------------------------------------------------------------------------------------------
# Public records
# ------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class State:
    """What a feedback law ``tau(t, state)`` sees.

    ``q`` (n_s), ``v`` (n_s), ``q_obj`` (3), ``v_obj`` (3), ``rho`` (2, the contact point in
    the object frame), ``contact`` (the contact is held in the current mode) and
    ``wheel_state`` (n_l strings, as in :class:`snakecg.ForwardResult`).
    """

    t: float
    q: np.ndarray
    v: np.ndarray
    q_obj: np.ndarray
    v_obj: np.ndarray
    rho: np.ndarray
    contact: bool
    wheel_state: tuple


@dataclass
class SimEvent:
    """A transition: ``kind`` is ``"impact"`` (the contact closes with a plastic impact),
    ``"touch"`` (it closes with no normal velocity), ``"separation"``, ``"off_link"`` (the
    contact point left the link), ``"breakaway"``, ``"stick"``, ``"reverse"`` (a sliding
    wheel that stops and slides back) or ``"projection"`` (velocities made consistent with
    the held rows by an impulse, e.g. initial velocities against ideal wheels); ``row`` is
    the constraint row (0 the contact, ``i`` the wheel of link ``i``); ``before``/``after``
    describe the modes; ``data`` holds numbers such as the impulse and the energy lost."""

    t: float
    kind: str
    row: int
    before: str
    after: str
    data: dict = field(default_factory=dict)

    def to_dict(self) -> dict:
        return {"t": self.t, "kind": self.kind, "row": self.row, "before": self.before,
                "after": self.after, **{k: _jsonable(v) for k, v in self.data.items()}}


@dataclass
class Trajectory:
    """A simulated trajectory, sampled at ``t`` (N,) (uniform output times plus both sides of
    every event, so a time may repeat).

    * state: ``q`` (N, n_s), ``v`` (N, n_s), ``q_obj`` (N, 3), ``v_obj`` (N, 3); ``rho`` (2,);
    * input and forces: ``tau`` (N, n_a), ``lam`` (N, n_c) (row 0 the contact, row ``i`` the
      wheel of link ``i``), accelerations ``qdd`` (N, n_s), ``a_obj`` (N, 3);
    * flags: ``contact`` (N,) bool (held), ``wheel_state`` (N, n_l) (``"none"``, ``"stick"``,
      ``"slide+"``, ``"slide-"``: force at ``+-mu m g``), ``events`` (list of :class:`SimEvent`);
    * metrics: instantaneous ``sr`` (eq. 30), ``norm_a_obj``, ``norm_qdd``; the
      displacement-based slippage ratio ``sr_displacement`` (see docs/simulate.md); the
      snake's COM ``com`` (N, 2); ``link_poses`` (N, n_l, 3);
    * constraint rows: ``gap`` (N,), ``s`` (N,) (contact position along the link),
      ``row_velocity`` (N, n_c) (``gdot``, lateral wheel velocities ``u_i``);
    * energy: ``kinetic_energy`` (N,), ``power_tau``, ``power_friction`` (N,), cumulative
      ``work_tau``, ``work_friction``, ``work_object``, ``impact_loss``
      (N,) and ``energy_residual`` = kinetic energy gained minus all of those;
    * ``summary``: a JSON-ready dictionary (schema ``snakecg.simulate/1``, docs/simulate.md).
    """

    t: np.ndarray
    q: np.ndarray
    v: np.ndarray
    q_obj: np.ndarray
    v_obj: np.ndarray
    rho: np.ndarray
    tau: np.ndarray
    lam: np.ndarray
    qdd: np.ndarray
    a_obj: np.ndarray
    contact: np.ndarray
    wheel_state: np.ndarray
    sr: np.ndarray
    norm_a_obj: np.ndarray
    norm_qdd: np.ndarray
    sr_displacement: np.ndarray
    com: np.ndarray
    link_poses: np.ndarray
    gap: np.ndarray
    s: np.ndarray
    row_velocity: np.ndarray
    kinetic_energy: np.ndarray
    power_tau: np.ndarray
    power_friction: np.ndarray
    work_tau: np.ndarray
    work_friction: np.ndarray
    work_object: np.ndarray
    power_constraint: np.ndarray
    impact_loss: np.ndarray
    energy_residual: np.ndarray
    events: list
    summary: dict
    geometry: dict = field(repr=False, default_factory=dict)

    @property
    def n_samples(self) -> int:
        return int(self.t.shape[0])

    def at(self, t: float) -> int:
        """Index of the last sample at or before time ``t``."""
        return int(max(0, np.searchsorted(self.t, t, side="right") - 1))

    def arrays(self) -> dict[str, np.ndarray]:
        """Every per-sample array by name (for ``numpy.savez``)."""
        skip = {"events", "summary", "geometry"}
        return {k: np.asarray(getattr(self, k)) for k in self.__dataclass_fields__
                if k not in skip}

    def save(self, path) -> None:
        """Write the arrays to a ``.npz`` file (the summary goes to JSON separately),
        atomically: a unique temporary name in the same folder, then ``os.replace``."""
        from ._files import atomic_path

        with atomic_path(path) as tmp, open(tmp, "wb") as fh:
            np.savez_compressed(fh, **self.arrays())


def _jsonable(x):
    if isinstance(x, dict):
        return {k: _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    if isinstance(x, (np.bool_, bool)):
        return bool(x)
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        x = float(x)
        return x if math.isfinite(x) else None
    return x


# ------------------------------------------------------------------------------------------
# Evaluation of the generated functions on one sample, without per-call allocations
# ------------------------------------------------------------------------------------------
class _Mode:
    """An active set: row states (solver codes) and whether the contact point left the link."""

    __slots__ = ("state", "off_link", "free", "lam_fixed", "free_idx", "slide_idx",
                 "contact_held", "wheel_names", "ff")

    def __init__(self, state: np.ndarray, bounds: np.ndarray, off_link: bool):
        self.state = np.asarray(state, dtype=np.int8).copy()
        self.off_link = bool(off_link)
        self.free = (self.state == HELD).astype(float)
        lf = np.zeros(len(state))
        lf[self.state == SLIDE_POS] = bounds[self.state == SLIDE_POS]
        lf[self.state == SLIDE_NEG] = -bounds[self.state == SLIDE_NEG]
        self.lam_fixed = lf
        self.free_idx = np.flatnonzero(self.state == HELD)
        self.ff = np.ix_(self.free_idx, self.free_idx)
        self.slide_idx = np.flatnonzero((self.state == SLIDE_POS) | (self.state == SLIDE_NEG))
        self.contact_held = bool(self.state[0] == HELD)
        self.wheel_names = tuple("none" if s in (ABSENT, LOST) else _STATE_NAMES[int(s)]
                                 for s in self.state[1:])

    def describe(self) -> str:
        c = "held" if self.contact_held else ("off link" if self.off_link else "separated")
        return f"contact {c}; wheels " + " ".join(self.wheel_names)


def _torque_law(tau, n_a: int):
    """``(kind, law)``: kind ``"constant"``, ``"time"`` or ``"feedback"``."""
    if callable(tau):
        try:
            params = inspect.signature(tau).parameters.values()
        except (TypeError, ValueError):
            raise InputError("tau: cannot read the signature of the callable; pass a function "
                             "of t (tau(t)) or of t and the state (tau(t, state))") from None
        pos = [p for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
               and p.default is p.empty]
        var = any(p.kind == p.VAR_POSITIONAL for p in params)
        if len(pos) == 1 and not var:
            return "time", tau
        if len(pos) == 2 or (var and len(pos) <= 2):
            return "feedback", tau
        raise InputError(f"tau: a callable must take (t) or (t, state), it takes {len(pos)}"
                         " required positional arguments")
    arr, batched = as_batch("tau", tau, n_a, what=f" (one torque per joint, n_a = {n_a})")
    if batched:
        raise InputError(f"tau has shape {np.shape(tau)}; a constant torque is ({n_a},); "
                         "pass a function for a torque that changes over time")
    return "constant", arr[0]


def _check_tau(value, n_a: int, t: float) -> np.ndarray:
    try:
        arr = np.asarray(value, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise SimulationError(f"the torque law returned {value!r} at t = {t:.6g} s; expected "
                              f"{n_a} numbers") from None
    if arr.shape != (n_a,) or not np.all(np.isfinite(arr)):
        raise SimulationError(f"the torque law returned {value!r} at t = {t:.6g} s; expected "
                              f"{n_a} finite numbers (one per joint)")
    return arr


def _positive(name, value, *, allow_none=False, allow_zero=False):
    if value is None and allow_none:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name} must be a number, got {value!r}")
    v = to_float(value)
    if not math.isfinite(v) or v < 0 or (v == 0 and not allow_zero):
        raise InputError(f"{name} must be a finite number {'>= 0' if allow_zero else '> 0'},"
                         f" got {value!r}")
    return v


def _check_count(name, duration, step, limit, what):
    """``duration / step`` (a number of samples, periods or steps) within ``limit``."""
    if step is None:
        return
    count = duration / step
    if not count <= limit:
        raise InputError(f"{name} = {step:g} s gives {count:.3g} {what} over {duration:g} s, "
                         f"above the limit of {limit:g}; give {name} >= {duration / limit:.3g} s")


# ------------------------------------------------------------------------------------------
# The simulator
# ------------------------------------------------------------------------------------------
class _Simulator:
    def __init__(self, model, q0, tau, duration, v0, *, v_obj0, q_obj0, rho, f_obj,
                 control_period, method, rtol, atol, max_step, fixed_step, stabilization,
                 output_dt, max_events):
        from .model import SceneModel

        try:
            from scipy.integrate import OdeSolver
            from scipy.linalg.lapack import dposv
        except ImportError:  # pragma: no cover - scipy is a dependency of the simulation
            raise SnakecgError("snakecg.simulate needs SciPy (its solve_ivp integrates the "
                               "dynamics): pip install scipy") from None
        if not isinstance(model, SceneModel):
            raise InputError("simulate needs a model loaded from a snakecg.Scene "
                             "(snakecg.load(scene)), got " + type(model).__name__)
        self.model = model
        scene = model.scene
        self.scene = scene
        ns, na, nl, nc = (model.n_coordinates, model.n_joints, model.n_links,
                          model.n_constraints)
        self.ns, self.na, self.nl, self.nc = ns, na, nl, nc
        self.nx = ns + 3
        self.ny = 2 * self.nx + _N_WORK
        what = f" = (n_joints + 3,) for a {na}-joint robot"
        q0 = self._single("q0", q0, ns, what)
        v0 = np.zeros(ns) if v0 is None else self._single("v0", v0, ns, what)
        v_obj0 = np.zeros(3) if v_obj0 is None else self._single("v_obj0", v_obj0, 3, "")
        if (q_obj0 is None) != (rho is None):
            raise InputError("q_obj0 and rho go together: give both or neither (default: the "
                             "scene's placement of the object against the contact link)")
        if q_obj0 is None:
            q_obj0, rho, _ = model.place_object(q0)
        q_obj0 = self._single("q_obj0", q_obj0, 3, "")
        self.rho = self._single("rho", rho, 2, "")
        self.f_obj = np.zeros(3) if f_obj is None else self._single("f_obj", f_obj, 3, "")
        self.duration = _positive("duration", duration)
        self.kind, self.law = _torque_law(tau, na)
        self.control_period = _positive("control_period", control_period, allow_none=True)
        if self.control_period is not None and self.kind == "constant":
            self.control_period = None
        if not ((isinstance(method, str) and method in _METHODS)
                or (isinstance(method, type) and issubclass(method, OdeSolver))):
            raise InputError(f"method must be one of {', '.join(_METHODS)} (scipy solve_ivp) "
                             f"or an OdeSolver class, got {method!r:.60}")
        self.method = method
        self.rtol = _positive("rtol", rtol)
        if not RTOL_MIN <= self.rtol <= 1:
            raise InputError(f"rtol must be from {RTOL_MIN:.3g} (100 machine epsilons, what "
                             f"solve_ivp can honour) to 1, got {rtol!r}")
        self.atol = _positive("atol", atol)
        self.max_step = _positive("max_step", max_step, allow_none=True)
        self.fixed_step = _positive("fixed_step", fixed_step, allow_none=True)
        self.alpha = _positive("stabilization", stabilization, allow_zero=True)
        if self.alpha > STABILIZATION_MAX:
            raise InputError(f"stabilization must be at most {STABILIZATION_MAX:g} 1/s (the "
                             f"limit: a larger rate makes the equations stiff), got "
                             f"{stabilization!r}")
        if output_dt is None:
            output_dt = self.duration / 400
        self.output_dt = _positive("output_dt", output_dt)
        _check_count("output_dt", self.duration, self.output_dt, MAX_OUTPUT_SAMPLES,
                     "output samples")
        _check_count("control_period", self.duration, self.control_period, MAX_PERIODS,
                     "controller periods (one torque query each)")
        _check_count("max_step", self.duration, self.max_step, MAX_STEPS, "integrator steps")
        _check_count("fixed_step", self.duration, self.fixed_step, MAX_STEPS, "integrator steps")
        if isinstance(max_events, bool) or not isinstance(max_events, (int, np.integer)) \
                or max_events < 0:
            raise InputError(f"max_events must be an integer >= 0, got {max_events!r}")
        self.max_events = int(max_events)
        self.q0, self.v0, self.q_obj0, self.v_obj0 = q0, v0, q_obj0, v_obj0

        # scene constants
        self.present = model.present.copy()
        self.bounds = model.bounds.copy()
        self.k = scene.contact_link - 1
        self.sigma = scene.side_sign
        self.c_k = float(scene.robot.com[self.k])
        self.l_k = float(scene.robot.length[self.k])
        self.woff = np.asarray(scene.wheel_offset, dtype=float)
        self.mo = np.array([scene.object_mass, scene.object_mass, scene.object_inertia])
        be = model.backend
        self._cd = BoundFunction(be, "constrained_dynamics", {
            "K": model.parameters, "contact_link": model._contact_link, "side": model._side,
            "object_mass": model._object_mass, "object_inertia": model._object_inertia,
            "rho": self.rho, "wheel_offset": model._wheel_offset, "f_obj": self.f_obj,
            "regularization": np.zeros(1)})
        self._jac = BoundFunction(be, "link_jacobians", {"K": model.parameters})
        self._mass = BoundFunction(be, "mass_matrix", {"K": model.parameters})
        self._cache_key = None
        self._cache_val = None
        self._zeros_nc = np.zeros(nc)
        self._posv = dposv
        self.nfev = 0
        self.njev = 0
        self.drift_corrected = 0.0  # largest |A V| of a held row projected away at an event
        self.singular = 0
        length = max(scene.robot.length)
        self.gtol = 1e-9 * length

    @staticmethod
    def _single(name, value, size, what):
        try:
            shape = np.shape(value)
        except (TypeError, ValueError):
            shape = None
        if shape != (size,):
            raise InputError(f"{name} has shape {shape}, expected ({size},){what}")
        arr, _ = as_batch(name, value, size, what=what)
        return arr[0].copy()

    # --- state helpers ------------------------------------------------------------------
    def split(self, y):
        ns = self.ns
        return y[:ns], y[ns:ns + 3], y[ns + 3:2 * ns + 3], y[2 * ns + 3:2 * ns + 6]

    def state_view(self, t, y, mode) -> State:
        q, qo, v, vo = self.split(y)
        return State(float(t), q.copy(), v.copy(), qo.copy(), vo.copy(), self.rho.copy(),
                     mode.contact_held, mode.wheel_names)

    def torque_fn(self):
        """The torque function ``(t, y, mode) -> tau`` of the next segment."""
        na = self.na
        if self.kind == "constant":
            const = self.law
            return lambda t, y, m: const
        if self.control_period is not None:
            held = self._held_tau
            return lambda t, y, m: held
        law = self.law
        if self.kind == "time":
            return lambda t, y, m: _check_tau(law(t), na, t)
        return lambda t, y, m: _check_tau(law(t, self.state_view(t, y, m)), na, t)

    def sample_law(self, t, y, mode) -> None:
        """Zero-order hold: evaluate the law at a control instant and hold its value."""
        if self.kind == "time":
            self._held_tau = _check_tau(self.law(t), self.na, t)
        else:
            self._held_tau = _check_tau(self.law(t, self.state_view(t, y, mode)), self.na, t)

    # --- kinematics of the rows -----------------------------------------------------------
    def row_velocities(self, q, v, qo, vo, s):
        """``A V``: the gap rate ``gdot`` (row 0) and the wheels' lateral velocities ``u_i``."""
        self.njev += 1
        J = self._jac.one(q=q)["J"]
        tw = (J @ v).reshape(self.nl, 3)
        phi = np.cumsum(q[2:])  # phi_1 = theta, phi_{j+1} = phi_j + q_j
        sp, cp = np.sin(phi), np.cos(phi)
        out = np.empty(self.nc)
        out[1:] = -sp * tw[:, 0] + cp * tw[:, 1] + self.woff * tw[:, 2]
        k, sig = self.k, self.sigma
        n = sig * np.array([-sp[k], cp[k]])
        c, sn = math.cos(qo[2]), math.sin(qo[2])
        rx, ry = self.rho
        Rr = (c * rx - sn * ry, sn * rx + c * ry)
        pdot = (vo[0] - vo[2] * Rr[1], vo[1] + vo[2] * Rr[0])
        out[0] = (n[0] * (pdot[0] - tw[k, 0]) + n[1] * (pdot[1] - tw[k, 1])
                  - sig * tw[k, 2] * (s - self.c_k))
        return out

    # --- right-hand side within a mode ----------------------------------------------------
    def dynamics(self, t, y, mode, tau_fn):
        """Everything at ``(t, y)`` in ``mode``: a tuple (ydot, lam, gap, s, AV, extras)."""
        key = (t, mode, tau_fn)
        yb = y.tobytes()
        if self._cache_key is not None and self._cache_key[0] == key and self._cache_key[1] == yb:
            return self._cache_val
        self.nfev += 1
        q, qo, v, vo = self.split(y)
        tau = tau_fn(t, y, mode)
        cd = self._cd
        out = cd.one(q=q, v=v, tau=tau, q_obj=qo, v_obj=vo, free=mode.free,
                     lam_fixed=mode.lam_fixed)
        if mode.free_idx.size and not out["pivot_ratio"][0] > PIVOT_TOL:
            # dependent held rows: least-norm forces (as in snakecg.solver)
            self.singular += 1
            scale = np.abs(np.diagonal(out["delassus"])).max()
            out = cd.one(q=q, v=v, tau=tau, q_obj=qo, v_obj=vo, free=mode.free,
                         lam_fixed=mode.lam_fixed,
                         regularization=REGULARIZATION * max(scale, 1e-300))
            cd.set(regularization=0.0)
        lam = out["lam"].copy()
        gap = float(out["gap"][0])
        s = float(out["s"][0])
        AV = self.row_velocities(q, v, qo, vo, s)
        F = mode.free_idx
        if self.alpha > 0 and F.size:
            a = self.alpha
            c = 2.0 * a * AV[F]
            if mode.contact_held:
                c[0] += a * a * gap
            G = out["delassus"][mode.ff]
            x, info = self._posv(G, c)[1:]  # Cholesky solve of G_FF x = c (SPD)
            if info != 0:
                x = np.linalg.lstsq(G, c, rcond=None)[0]
            lam[F] -= x
            out = cd.one(free=self._zeros_nc, lam_fixed=lam)
        ydot = np.empty(self.ny)
        nx = self.nx
        ydot[:self.ns] = v
        ydot[self.ns:nx] = vo
        ydot[nx:nx + self.ns] = out["qdd"]
        ydot[nx + self.ns:2 * nx] = out["a_obj"]
        p_tau = float(tau @ v[3:])
        sl = mode.slide_idx
        p_fric = float(lam[sl] @ AV[sl]) if sl.size else 0.0
        p_obj = float(self.f_obj @ vo)
        ydot[2 * nx:] = (p_tau, p_fric, p_obj)
        # power of the held rows' forces: zero on the constraints (a drift diagnostic; not
        # integrated: off the constraints, at the integrator's stages, it is noise)
        p_cons = float(lam[F] @ AV[F]) if F.size else 0.0
        extras = (np.array(tau, dtype=float), float(out["sr"][0]), float(out["norm_a_obj"][0]),
                  float(out["norm_qdd"][0]), p_cons)
        val = (ydot, lam, gap, s, AV, extras)
        self._cache_key = (key, yb)
        self._cache_val = val
        return val

    # --- linear maps at a state (events only) ---------------------------------------------
    def linear_maps(self, y, tau):
        """``Q = I^-1 A^T`` (nx, n_c), ``G_c``, gap, s and ``A V`` at ``y``."""
        q, qo, v, vo = self.split(y)
        nc = self.nc
        lf = np.vstack([np.zeros(nc), np.eye(nc)])
        outs = self._cd.many(nc + 1, q=q, v=v, tau=tau, q_obj=qo, v_obj=vo,
                             free=np.zeros((nc + 1, nc)), lam_fixed=lf,
                             regularization=np.zeros(1))
        qdd, a_obj = outs["qdd"], outs["a_obj"]
        Q = np.hstack([qdd[1:] - qdd[0], a_obj[1:] - a_obj[0]]).T
        G = outs["delassus"][0]
        gap, s = float(outs["gap"][0, 0]), float(outs["s"][0, 0])
        AV = self.row_velocities(q, v, qo, vo, s)
        return Q, G, gap, s, AV

    def project(self, y, tau, rows, *, positions: bool):
        """Mass-weighted projection of the velocities onto ``A_F V = 0`` for ``rows`` (and of
        the positions onto ``g = 0`` when the contact is among them and ``positions``).

        Returns the new state, the impulse ``Lam_F`` and the kinetic-energy change."""
        y = y.copy()
        rows = np.asarray(rows, dtype=int)
        nx = self.nx
        if positions and 0 in rows:
            for _ in range(3):
                Q, G, gap, s, AV = self.linear_maps(y, tau)
                if abs(gap) <= 1e-15 * max(1.0, self.l_k):
                    break
                y[:nx] -= Q[:, 0] * (gap / G[0, 0])
        Q, G, gap, s, AV = self.linear_maps(y, tau)
        if rows.size == 0:
            return y, np.zeros(0), 0.0
        GF = G[np.ix_(rows, rows)]
        Lam = -np.linalg.solve(GF, AV[rows])
        y[nx:2 * nx] += Q[:, rows] @ Lam
        dE = -0.5 * float(Lam @ GF @ Lam)
        return y, Lam, dE

    # --- active set at an event -------------------------------------------------------------
    def decide(self, y, tau, candidates: np.ndarray, forced: dict[int, int]) -> np.ndarray:
        """Row states: the complementarity problem over ``candidates`` at acceleration level,
        the ``forced`` rows fixed (a sliding wheel's force, a separated contact)."""
        q, qo, v, vo = self.split(y)
        nc = self.nc
        bounds = self.bounds
        fixed_lam = np.zeros(nc)
        for r, st in forced.items():
            if st == SLIDE_POS:
                fixed_lam[r] = bounds[r]
            elif st == SLIDE_NEG:
                fixed_lam[r] = -bounds[r]
        fmask = np.zeros(nc, dtype=bool)
        fmask[list(forced)] = True
        def call(idx, free, lam_fixed, reg):
            m = len(idx)
            lf = np.where(fmask[None, :], fixed_lam[None, :], lam_fixed)
            outs = self._cd.many(m, q=q, v=v, tau=tau, q_obj=qo, v_obj=vo,
                                 free=np.ascontiguousarray(free),
                                 lam_fixed=np.ascontiguousarray(lf),
                                 regularization=np.asarray(reg, float).reshape(m, 1))
            res = {}
            for name, o in outs.items():
                res[name] = o[:, 0].copy() if o.ndim == 2 and o.shape[1] == 1 else o
            return res

        state = np.full(nc, ABSENT, dtype=np.int8)
        if candidates.any():
            sol = solve_active_set(call, 1, candidates, bounds)
            state = sol.state[0].astype(np.int8)
            if sol.singular[0]:
                self.singular += 1
        for r, st in forced.items():
            state[r] = st
        return state

    def settle(self, t, y, prev: _Mode | None, forced: dict[int, int], *, contact_candidate,
               off_link, events: list, impact_kind="impact"):
        """Impacts, projections and the new mode at an event (or at the start)."""
        nc = self.nc
        before = prev.describe() if prev is not None else "start"
        probe = _Mode(np.where(self.present, HELD, ABSENT), self.bounds, off_link)
        tau = np.asarray(self.torque_fn()(t, y, prev or probe), dtype=float)
        Q, G, gap, s, AV = self.linear_maps(y, tau)
        V = y[self.nx:2 * self.nx]
        vtol = 1e-8 * max(1.0, float(np.abs(V).max()))
        ideal = np.flatnonzero(self.present & ~np.isfinite(self.bounds))
        ideal = ideal[ideal > 0]
        bounded = np.flatnonzero(self.present & np.isfinite(self.bounds))
        bounded = bounded[bounded > 0]
        forced = dict(forced)
        records = []
        # rows held before the event carry only integration drift in A V (projected below);
        # a row that was not held is classified by its velocity
        held_before = (prev.state == HELD) if prev is not None else np.zeros(nc, dtype=bool)
        impact = False
        # contact: plastic impact when closing
        contact_in = bool(contact_candidate) and 0 not in forced
        if contact_in and not held_before[0] and AV[0] < -vtol:
            rows = np.concatenate(([0], ideal)).astype(int)
            ke0 = self.kinetic_energy(y)
            y, Lam, dE = self.project(y, tau, rows, positions=True)
            records.append((impact_kind, 0, {
                "closing_velocity": float(AV[0]), "impulse": float(Lam[0]),
                "wheel_impulses": Lam[1:].tolist(), "energy_loss": float(-dE),
                "kinetic_energy_before": ke0}))
            Q, G, gap, s, AV = self.linear_maps(y, tau)
            impact = True
        elif contact_in and not held_before[0] and AV[0] > vtol:
            forced[0] = LOST  # already moving apart
        elif not contact_in and 0 not in forced:
            forced[0] = LOST
        # bounded wheels: sliding when their lateral velocity is not zero (at the start, after
        # an impact, which they cannot resist with a finite force, or when not sticking before)
        for r in bounded:
            if r in forced or (held_before[r] and not impact):
                continue
            if abs(AV[r]) > vtol:
                forced[int(r)] = SLIDE_POS if AV[r] < 0 else SLIDE_NEG
        candidates = self.present.copy()
        for r in forced:
            candidates[r] = False
        # drift-level projection of every candidate row (and the initial velocities of
        # ideal wheels, which may take an impulse)
        rows = np.flatnonzero(candidates)
        if rows.size:
            ke0 = self.kinetic_energy(y)
            y2, Lam, dE = self.project(y, tau, rows, positions=bool(candidates[0]))
            drift = float(np.abs(AV[rows]).max())
            if prev is None and drift > vtol:
                # initial velocities against the held rows (e.g. ideal wheels): an impulse
                records.append(("projection", int(rows[np.argmax(np.abs(AV[rows]))]), {
                    "impulses": Lam.tolist(), "energy_loss": float(-dE),
                    "kinetic_energy_before": ke0}))
            elif prev is not None:
                self.drift_corrected = max(self.drift_corrected, drift)
            y = y2
        state = self.decide(y, tau, candidates, forced)
        mode = _Mode(state, self.bounds, off_link)
        for kind, row, data in records:
            events.append(SimEvent(float(t), kind, row, before, mode.describe(), data))
        return y, mode

    def kinetic_energy(self, y) -> float:
        q, qo, v, vo = self.split(y)
        M = self._mass.one(q=q)["M"]
        return 0.5 * float(v @ M @ v) + 0.5 * float(vo @ (self.mo * vo))

    # --- events of a mode ---------------------------------------------------------------------
    def event_functions(self, mode, tau_fn):
        evs = []

        def make(fn, direction, kind, row):
            fn.terminal = True
            fn.direction = direction
            fn.kind = kind
            fn.row = row
            evs.append(fn)

        dyn = self.dynamics
        if mode.contact_held:
            make(lambda t, y: dyn(t, y, mode, tau_fn)[1][0], -1, "separation", 0)
            make(lambda t, y: dyn(t, y, mode, tau_fn)[3], -1, "off_link", 0)
            make(lambda t, y: self.l_k - dyn(t, y, mode, tau_fn)[3], -1, "off_link", 0)
        elif not mode.off_link:
            make(lambda t, y: dyn(t, y, mode, tau_fn)[2], -1, "gap", 0)
        for r in range(1, self.nc):
            st = mode.state[r]
            b = self.bounds[r]
            if st == HELD and np.isfinite(b):
                make(lambda t, y, r=r, b=b: b - abs(dyn(t, y, mode, tau_fn)[1][r]), -1,
                     "breakaway", r)
            elif st in (SLIDE_POS, SLIDE_NEG):
                d = -1.0 if st == SLIDE_POS else 1.0  # direction of the sliding velocity
                make(lambda t, y, r=r, d=d: d * dyn(t, y, mode, tau_fn)[4][r], -1, "slide_stop", r)
        return evs

    # --- main loop ----------------------------------------------------------------------
    def run(self):
        from scipy.integrate import solve_ivp

        wall0 = time.perf_counter()
        T = self.duration
        y = np.concatenate([self.q0, self.q_obj0, self.v0, self.v_obj0, np.zeros(_N_WORK)])
        self.ke_initial = self.kinetic_energy(y)
        events: list[SimEvent] = []
        # initial mode: the contact is a candidate when the object touches the link face
        Q, G, gap, s, AV = self.linear_maps(y, np.zeros(self.na))
        on_link = -self.gtol <= s <= self.l_k + self.gtol
        if gap < -self.gtol and on_link:
            raise InputError(f"the object penetrates the contact link at t = 0 (gap = {gap:.3g}"
                             " m); move it out along the contact normal")
        touching = abs(gap) <= self.gtol and on_link
        if self.control_period is not None:
            st = np.where(self.present, HELD, ABSENT)
            if not touching:
                st[0] = LOST
            self.sample_law(0.0, y, _Mode(st, self.bounds, not on_link))
        impact_loss = 0.0
        y, mode = self.settle(0.0, y, None, {}, contact_candidate=touching,
                              off_link=not on_link and abs(gap) <= self.gtol,
                              events=events, impact_kind="impact")
        for e in events:
            impact_loss += e.data.get("energy_loss", 0.0)
        samples = []  # (t, y, mode, tau_fn, impact_loss)
        grid = np.arange(1, int(math.floor(T / self.output_dt + 1e-9)) + 1) * self.output_dt
        grid = grid[grid < T - 1e-12 * T]
        grid = np.append(grid, T)
        t = 0.0
        self.initial_mode = mode.describe()
        samples.append((t, y.copy(), mode, self.torque_fn(), impact_loss))
        status = "completed"
        n_events = 0
        segments = 0
        stuck = 0
        next_control = (self.control_period if self.control_period is not None else math.inf)
        opts = dict(method=self.method, rtol=self.rtol, atol=self.atol)
        if self.fixed_step is not None:
            opts.update(rtol=1e30, atol=1e30, first_step=self.fixed_step,
                        max_step=self.fixed_step)
        elif self.max_step is not None:
            opts.update(max_step=self.max_step)
        while t < T * (1 - 1e-13):
            t_end = min(T, next_control)
            if t_end - t <= 1e-12 * T:
                t_end = T if next_control >= T else t_end
            tau_fn = self.torque_fn()
            evs = self.event_functions(mode, tau_fn)
            t_eval = grid[(grid > t) & (grid < t_end)]
            t_eval = np.append(t_eval, t_end)
            fun = (lambda tt, yy, m=mode, f=tau_fn: self.dynamics(tt, yy, m, f)[0])
            if self.fixed_step is not None:
                opts["first_step"] = min(self.fixed_step, t_end - t)
            try:
                sol = solve_ivp(fun, (t, t_end), y, t_eval=t_eval, events=evs or None, **opts)
            except SnakecgError:
                raise
            except (ValueError, np.linalg.LinAlgError, ArithmeticError) as exc:
                raise SimulationError(f"integration failed at t = {t:.6g} s: {exc}") from exc
            segments += 1
            if sol.status < 0:
                raise SimulationError(f"integration failed at t = {t:.6g} s: {sol.message}")
            ys = np.asarray(sol.y).reshape(self.ny, -1) if len(sol.t) else np.zeros((self.ny, 0))
            for tt, yy in zip(sol.t, ys.T):
                if tt > t:
                    samples.append((float(tt), yy.copy(), mode, tau_fn, impact_loss))
            if sol.status == 1:
                fired = [(i, float(te[0]), np.asarray(ye[0])) for i, (te, ye) in
                         enumerate(zip(sol.t_events, sol.y_events)) if len(te)]
                t_e = min(f[1] for f in fired)
                fired = [f for f in fired if f[1] <= t_e + 1e-12 * max(1.0, T)]
                y_e = fired[0][2].copy()
                stuck = stuck + 1 if t_e - t <= 1e-12 * max(1.0, T) else 0
                if samples[-1][0] < t_e:
                    samples.append((t_e, y_e.copy(), mode, tau_fn, impact_loss))
                n_before = len(events)
                y, mode = self.handle(t_e, y_e, mode, [evs[i] for i, _, _ in fired], events)
                for e in events[n_before:]:
                    impact_loss += e.data.get("energy_loss", 0.0)
                n_events += 1
                t = t_e
                samples.append((t, y.copy(), mode, self.torque_fn(), impact_loss))
                if n_events >= self.max_events or stuck > 20:
                    status = (f"stopped at t = {t:.6g} s after {n_events} events"
                              + (" (no progress between events)" if stuck > 20 else ""))
                    break
            else:
                t = t_end
                y = sol.y[:, -1].copy()
                if t >= next_control * (1 - 1e-13):
                    next_control += self.control_period
                    if t < T * (1 - 1e-13):
                        # the held torque jumps: the active set is solved again
                        self.sample_law(t, y, mode)
                        n_before = len(events)
                        y, mode = self.handle(t, y, mode, [], events)
                        for e in events[n_before:]:
                            impact_loss += e.data.get("energy_loss", 0.0)
                        if len(events) > n_before:
                            samples.append((t, y.copy(), mode, self.torque_fn(), impact_loss))
        self.wall = time.perf_counter() - wall0
        self.segments = segments
        self.final_mode = mode.describe()
        return self.assemble(samples, events, status)

    def handle(self, t, y, mode, fired, events):
        """Apply the events ``fired`` at ``(t, y)``; return the new state and mode."""
        forced: dict[int, int] = {}
        off_link = mode.off_link
        contact_candidate = mode.contact_held
        for ev in fired:
            if ev.kind == "separation":
                forced[0] = LOST
                contact_candidate = False
            elif ev.kind == "off_link":
                forced[0] = LOST
                contact_candidate = False
                off_link = True
            elif ev.kind == "gap":
                s = self.dynamics(t, y, mode, self.torque_fn())[3]
                if -self.gtol <= s <= self.l_k + self.gtol:
                    contact_candidate = True
                else:
                    forced[0] = LOST
            elif ev.kind == "breakaway":
                lam = self.dynamics(t, y, mode, self.torque_fn())[1]
                forced[ev.row] = SLIDE_POS if lam[ev.row] > 0 else SLIDE_NEG
        stopped = {ev.row for ev in fired if ev.kind == "slide_stop"}
        # sliding wheels that did not stop keep sliding
        for r in mode.slide_idx:
            if r not in forced and r not in stopped:
                forced[int(r)] = int(mode.state[r])
        n0 = len(events)
        y, new = self.settle(t, y, mode, forced, contact_candidate=contact_candidate,
                             off_link=off_link, events=events)
        events[n0:n0] = self.transitions(t, mode, new, impact=len(events) > n0)
        return y, new

    def transitions(self, t, old: _Mode, new: _Mode, *, impact: bool) -> list[SimEvent]:
        """The events that take ``old`` to ``new``, row by row."""
        before, after = old.describe(), new.describe()
        out = []
        slide = (SLIDE_POS, SLIDE_NEG)
        if old.state[0] == HELD and new.state[0] != HELD:
            kind = "off_link" if new.off_link and not old.off_link else "separation"
            out.append(SimEvent(float(t), kind, 0, before, after, {}))
        elif old.state[0] != HELD and new.state[0] == HELD and not impact:
            out.append(SimEvent(float(t), "touch", 0, before, after, {}))
        for r in range(1, self.nc):
            a, b = old.state[r], new.state[r]
            kind = None
            if a == HELD and b in slide:
                kind = "breakaway"
            elif a in slide and b == HELD:
                kind = "stick"
            elif a in slide and b in slide and a != b:
                kind = "reverse"
            if kind:
                out.append(SimEvent(float(t), kind, r, before, after, {}))
        return out

    # --- post-processing --------------------------------------------------------------------
    def assemble(self, samples, events, status) -> Trajectory:
        model = self.model
        N = len(samples)
        ns, na, nc, nl = self.ns, self.na, self.nc, self.nl
        t = np.array([s[0] for s in samples])
        Y = np.array([s[1] for s in samples])
        tau = np.zeros((N, na))
        lam = np.zeros((N, nc))
        qdd = np.zeros((N, ns))
        a_obj = np.zeros((N, 3))
        sr = np.zeros(N)
        nao = np.zeros(N)
        nqdd = np.zeros(N)
        gap = np.zeros(N)
        s_ = np.zeros(N)
        AVs = np.zeros((N, nc))
        p_tau = np.zeros(N)
        p_fric = np.zeros(N)
        p_cons = np.zeros(N)
        contact = np.zeros(N, dtype=bool)
        wheel_state = np.empty((N, nl), dtype="<U6")
        impact = np.array([s[4] for s in samples])
        for i, (ti, yi, mode, tau_fn, _) in enumerate(samples):
            ydot, li, gi, si, AV, (taui, sri, nai, nqi, pci) = self.dynamics(ti, yi, mode,
                                                                          tau_fn)
            tau[i], lam[i], gap[i], s_[i], AVs[i] = taui, li, gi, si, AV
            nx = self.nx
            qdd[i] = ydot[nx:nx + ns]
            a_obj[i] = ydot[nx + ns:2 * nx]
            sr[i], nao[i], nqdd[i] = sri, nai, nqi
            p_tau[i], p_fric[i], p_cons[i] = ydot[2 * nx], ydot[2 * nx + 1], pci
            contact[i] = mode.contact_held
            wheel_state[i] = mode.wheel_names
        nx = self.nx
        q, q_obj = Y[:, :ns], Y[:, ns:nx]
        v, v_obj = Y[:, nx:nx + ns], Y[:, nx + ns:2 * nx]
        W = Y[:, 2 * nx:]
        M = model.mass_matrix(q)
        ke = 0.5 * np.einsum("ni,nij,nj->n", v, M, v) + 0.5 * (v_obj**2 @ self.mo)
        com = model.com(q)
        poses = model.link_poses(q)
        # displacement-based slippage ratio (metric of the initial configuration)
        M0 = model.mass_matrix(self.q0)
        dq = q - q[0]
        do = q_obj - q_obj[0]
        num = np.einsum("ni,i,ni->n", do, self.mo, do)
        den = num + np.einsum("ni,ij,nj->n", dq, M0, dq)
        with np.errstate(invalid="ignore", divide="ignore"):
            sr_d = np.where(den > 0, num / np.where(den > 0, den, 1.0), np.nan)
        loss = impact  # cumulative kinetic energy removed by impacts / projections
        residual = (ke - self.ke_initial) - (W[:, 0] + W[:, 1] + W[:, 2] - loss)
        geometry = {
            "length": np.asarray(self.scene.robot.length, float),
            "com": np.asarray(self.scene.robot.com, float),
            "wheel_offset": self.woff.copy(),
            "wheel_links": np.flatnonzero(self.present[1:]) + 1,
            "contact_link": self.k + 1,
            "side": self.sigma,
            "object_distance": float(self.scene.object_distance),
            "wheel_bounds": self.bounds[1:].copy(),
        }
        traj = Trajectory(
            t=t, q=q, v=v, q_obj=q_obj, v_obj=v_obj, rho=self.rho.copy(), tau=tau, lam=lam,
            qdd=qdd, a_obj=a_obj, contact=contact, wheel_state=wheel_state, sr=sr,
            norm_a_obj=nao, norm_qdd=nqdd, sr_displacement=sr_d, com=com, link_poses=poses,
            gap=gap, s=s_, row_velocity=AVs, kinetic_energy=ke, power_tau=p_tau,
            power_friction=p_fric, work_tau=W[:, 0].copy(), work_friction=W[:, 1].copy(),
            work_object=W[:, 2].copy(), power_constraint=p_cons, impact_loss=loss,
            energy_residual=residual, events=events, summary={}, geometry=geometry)
        traj.summary = self.summary(traj, status)
        return traj

    def summary(self, tr: Trajectory, status: str) -> dict:
        sc = self.scene
        t = tr.t
        dt = np.diff(t)
        span = max(t[-1] - t[0], 1e-300)
        held = tr.contact
        # time fractions from the piecewise-constant flags of each interval
        held_frac = float(np.sum(dt * held[:-1]) / span) if dt.size else float(held[0])
        sliding = np.isin(tr.wheel_state, ("slide+", "slide-"))
        slide_frac = (np.sum(dt[:, None] * sliding[:-1], axis=0) / span).tolist() \
            if dt.size else sliding[0].astype(float).tolist()
        sr_mean = float(np.sum(0.5 * dt * (tr.sr[1:] + tr.sr[:-1])) / span) if dt.size \
            else float(tr.sr[0])
        first_lost = next((e.t for e in tr.events if e.kind in ("separation", "off_link")),
                          None)
        counts: dict[str, int] = {}
        for e in tr.events:
            counts[e.kind] = counts.get(e.kind, 0) + 1
        held_rows = np.zeros_like(tr.row_velocity, dtype=bool)
        held_rows[:, 0] = held
        held_rows[:, 1:] = tr.wheel_state == "stick"
        gap_res = float(np.abs(tr.gap[held]).max()) if held.any() else 0.0
        gdot_res = float(np.abs(tr.row_velocity[held, 0]).max()) if held.any() else 0.0
        wheel_rows = held_rows[:, 1:]
        u_res = float(np.abs(tr.row_velocity[:, 1:][wheel_rows]).max()) if wheel_rows.any() \
            else 0.0
        do = tr.q_obj[-1] - tr.q_obj[0]
        dc = tr.com[-1] - tr.com[0]
        ke0, ke1 = float(self.ke_initial), float(tr.kinetic_energy[-1])
        return _jsonable({
            "schema": SCHEMA,
            "status": status,
            "joints": sc.robot.joints,
            "scenario": sc.scenario,
            "kappa": sc.kappa,
            "mu": sc.mu,
            "duration": self.duration,
            "torque": self.kind + ("" if self.control_period is None
                                   else f" (held over {self.control_period:g} s)"),
            "initial_mode": self.initial_mode,
            "final_mode": self.final_mode,
            "object_displacement": {"x": do[0], "y": do[1], "psi": do[2],
                                    "distance": float(np.hypot(do[0], do[1]))},
            "snake_com_displacement": {"x": dc[0], "y": dc[1],
                                       "distance": float(np.hypot(dc[0], dc[1]))},
            "sr_initial": tr.sr[0],
            "sr_mean": sr_mean,
            "sr_displacement_final": tr.sr_displacement[-1],
            "contact": {"held_fraction": held_frac, "first_lost_at": first_lost,
                        "held_at_end": bool(held[-1])},
            "wheels": {"slide_fraction": slide_frac},
            "event_counts": counts,
            "events": [e.to_dict() for e in tr.events[:200]],
            "energy": {
                "kinetic_initial": ke0, "kinetic_final": ke1,
                "work_tau": tr.work_tau[-1], "work_friction": tr.work_friction[-1],
                "work_object": tr.work_object[-1],
                "impact_loss": tr.impact_loss[-1], "balance_residual": tr.energy_residual[-1],
            },
            "constraint_residual": {"gap": gap_res, "gap_rate": gdot_res,
                                    "wheel_lateral_velocity": u_res,
                                    "constraint_power": float(np.abs(tr.power_constraint).max()),
                                    "velocity_projected_at_events": self.drift_corrected},
            "integrator": {
                "method": self.method if self.fixed_step is None
                else f"{self.method}, fixed step {self.fixed_step:g} s",
                "rtol": None if self.fixed_step is not None else self.rtol,
                "atol": None if self.fixed_step is not None else self.atol,
                "stabilization": self.alpha, "segments": self.segments,
                "rhs_evaluations": self.nfev, "singular_samples": self.singular,
                "wall_time_s": self.wall,
            },
        })


# ------------------------------------------------------------------------------------------
def simulate(model, q0, tau, duration, v0=None, *, v_obj0=None, q_obj0=None, rho=None,
             f_obj=None, control_period=None, method="DOP853", rtol=1e-9, atol=1e-11,
             max_step=None, fixed_step=None, stabilization=10.0, output_dt=None,
             max_events=1000) -> Trajectory:
    """Integrate the snake + object of ``model`` (a :class:`~snakecg.SceneModel`) from ``q0``.

    Parameters
    ----------
    q0, v0 : (n_s,) initial coordinates and velocities (``v0`` default: at rest).
    tau : the joint torques: a constant ``(n_a,)``, a function of time ``tau(t)``, or a
        feedback law ``tau(t, state)`` (:class:`State`), e.g.
        :func:`least_slip_push_controller`.
    duration : seconds to simulate.
    v_obj0 : the object's initial twist (default 0). ``q_obj0`` and ``rho`` (together): the
        object's pose and the contact point in its frame (default: the scene's placement,
        touching the contact link).
    f_obj : constant external wrench on the object (F_x, F_y, torque), default 0.
    control_period : hold a time function or feedback law constant over this period
        (zero-order hold, evaluated at the start of each period); default: evaluated
        continuously.
    method, rtol, atol, max_step : :func:`scipy.integrate.solve_ivp` settings.
    fixed_step : take steps of exactly this size (convergence studies); overrides the
        tolerances.
    stabilization : Baumgarte rate ``alpha`` (1/s) of the held rows; 0 switches it off.
    output_dt : spacing of the output samples (default ``duration / 400``); events add
        samples on both sides.
    max_events : stop (``summary["status"]`` says so) after this many events.

    Returns a :class:`Trajectory` with the per-sample arrays, the events and ``summary``.
    """
    sim = _Simulator(model, q0, tau, duration, v0, v_obj0=v_obj0, q_obj0=q_obj0, rho=rho,
                     f_obj=f_obj, control_period=control_period, method=method, rtol=rtol,
                     atol=atol, max_step=max_step, fixed_step=fixed_step,
                     stabilization=stabilization, output_dt=output_dt, max_events=max_events)
    return sim.run()


class LeastSlipPush:
    """Feedback law ``tau(t, state)``: the "push with least slippage" torque query
    (``objective="least_slip_push"`` of :mod:`snakecg.optimize`) answered at every call.

    The query is the instant analysis at rest: it sees the current configuration
    ``state.q`` only (velocity terms, the object's actual pose and the contact point's drift
    along the link are left out), which is exactly what a simulation of it can reveal. The
    task: the object's acceleration along ``direction`` at least ``a_min`` (``direction``
    default: the current contact normal), or the full planar acceleration ``a_obj``; torque
    limits ``tau_max`` and/or the ellipsoid ``radius`` as in :func:`snakecg.optimize.optimize`.
    An infeasible task gives the query's closest torque (its strongest push within the
    limits). ``history`` lists ``(t, status, objective_value)`` of every call.
    """

    def __init__(self, model, *, a_min=None, direction="normal", a_obj=None, tau_max=None,
                 radius=None):
        query = getattr(model, "optimize", None)
        if query is None:
            try:
                from .optimize import optimize as _optimize
            except ImportError:
                raise SnakecgError("the least-slippage push query needs snakecg.optimize, "
                                   "which this installation does not have; pass your own "
                                   "feedback law tau(t, state) instead") from None

            def query(q, **kw):
                return _optimize(model, q, **kw)
        if a_obj is None and a_min is None:
            raise InputError("least_slip_push_controller needs a task: a_min (m/s^2 along "
                             "direction, default the contact normal) or a_obj")
        self.model = model
        self._query = query
        self.a_min, self.direction, self.a_obj = a_min, direction, a_obj
        self.limits = {k: v for k, v in (("tau_max", tau_max), ("radius", radius))
                       if v is not None}
        self.history: list[tuple[float, str, float]] = []

    def normal(self, q) -> np.ndarray:
        """The contact normal ``n = side (-sin phi_k, cos phi_k)`` at configuration ``q``."""
        scene = self.model.scene
        k = scene.contact_link - 1
        phi = q[2] + float(np.sum(q[3:3 + k]))
        return scene.side_sign * np.array([-math.sin(phi), math.cos(phi)])

    def __call__(self, t, state):
        if self.a_obj is not None:
            task = {"a_obj": self.a_obj}
        else:
            d = self.normal(state.q) if isinstance(self.direction, str) else self.direction
            task = {"direction": d, "a_min": self.a_min}
        res = self._query(state.q, objective="least_slip_push", **task, **self.limits)
        value = getattr(res, "objective_value", None)
        self.history.append((float(t), str(getattr(res, "status", "")),
                             float(value) if value is not None else math.nan))
        return getattr(res, "tau", res)


def least_slip_push_controller(model, **options) -> LeastSlipPush:
    """The "push with least slippage" query as a feedback law for :func:`simulate`; see
    :class:`LeastSlipPush` (options: ``a_min``, ``direction``, ``a_obj``, ``tau_max``,
    ``radius``). Use it with ``control_period`` (one query per period, zero-order hold). Any
    other law ``tau(t, state)`` plugs into :func:`simulate` the same way."""
    return LeastSlipPush(model, **options)


# ------------------------------------------------------------------------------------------
# Figures and animation
# ------------------------------------------------------------------------------------------
_EVENT_COLORS = {"impact": "tab:red", "separation": "tab:purple", "off_link": "tab:purple",
                 "breakaway": "tab:orange", "stick": "tab:green", "reverse": "tab:olive",
                 "projection": "tab:gray"}


def _pyplot():
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg", "pdf", "svg", "ps", "cairo"):
        matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    return plt


def _mark_events(ax, traj: Trajectory, *, label=True):
    seen = set()
    for e in traj.events:
        c = _EVENT_COLORS.get(e.kind, "k")
        lab = e.kind if (label and e.kind not in seen) else None
        seen.add(e.kind)
        ax.axvline(e.t, color=c, lw=0.8, ls="--", alpha=0.8, label=lab)


def _shade_lost(ax, traj: Trajectory):
    t, held = traj.t, traj.contact
    start = None
    for i in range(len(t)):
        if not held[i] and start is None:
            start = t[i]
        if (held[i] or i == len(t) - 1) and start is not None:
            ax.axvspan(start, t[i], color="0.85", lw=0, zorder=0)
            start = None


def _savefig(fig, path, dpi) -> None:
    from ._files import atomic_path

    with atomic_path(path) as tmp:  # unique temporary name, then os.replace
        fig.savefig(tmp, dpi=dpi, format="png")


def save_figures(traj: Trajectory, folder, *, animation: bool = True, fps: int = 20,
                 frames: int = 100, dpi: int = 110) -> dict[str, str]:
    """Write the summary figures (PNG) and the animation (GIF) of ``traj`` into ``folder``.

    ``displacement.png`` (object and snake COM displacement), ``slippage.png`` (instantaneous
    and displacement-based slippage ratio), ``energy.png`` (power and energy budget),
    ``forces.png`` (constraint forces and active set), ``animation.gif``. Returns the paths.
    """
    from pathlib import Path

    plt = _pyplot()
    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    paths = {}
    t = traj.t
    title = (f"{traj.summary.get('joints')} joints, {traj.summary.get('scenario')}, "
             f"kappa {traj.summary.get('kappa'):g}")

    # displacement -------------------------------------------------------------------------
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.6), sharex=True)
    do = traj.q_obj - traj.q_obj[0]
    dc = traj.com - traj.com[0]
    ax = axes[0]
    ax.plot(t, do[:, 0] * 1e3, label="x")
    ax.plot(t, do[:, 1] * 1e3, label="y")
    ax.plot(t, np.hypot(do[:, 0], do[:, 1]) * 1e3, "k", lw=1.5, label="distance")
    ax.set_ylabel("object COM (mm)")
    ax2 = ax.twinx()
    ax2.plot(t, np.degrees(do[:, 2]), color="tab:gray", lw=0.8, ls=":")
    ax2.set_ylabel("object angle (deg, dotted)", color="tab:gray")
    _shade_lost(ax, traj)
    _mark_events(ax, traj)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("displacement, " + title + " (grey: contact lost)", fontsize=10)
    ax = axes[1]
    ax.plot(t, dc[:, 0] * 1e3, label="x")
    ax.plot(t, dc[:, 1] * 1e3, label="y")
    ax.plot(t, np.hypot(dc[:, 0], dc[:, 1]) * 1e3, "k", lw=1.5, label="distance")
    ax.set_ylabel("snake COM (mm)")
    ax.set_xlabel("t (s)")
    _shade_lost(ax, traj)
    _mark_events(ax, traj, label=False)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    paths["displacement"] = str(out / "displacement.png")
    _savefig(fig, paths["displacement"], dpi)
    plt.close(fig)

    # slippage ratio -----------------------------------------------------------------------
    fig, ax = plt.subplots(figsize=(7, 3.6))
    ax.plot(t, traj.sr, label="sr (instantaneous, eq. 30)")
    ax.plot(t, traj.sr_displacement, label="sr from displacements since t = 0")
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("slippage ratio")
    _shade_lost(ax, traj)
    _mark_events(ax, traj)
    ax.legend(fontsize=8, loc="best")
    ax.set_title("slippage ratio, " + title, fontsize=10)
    fig.tight_layout()
    paths["slippage"] = str(out / "slippage.png")
    _savefig(fig, paths["slippage"], dpi)
    plt.close(fig)

    # power and energy ---------------------------------------------------------------------
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.6), sharex=True)
    ax = axes[0]
    ax.plot(t, traj.power_tau * 1e3, label="joint torques")
    ax.plot(t, traj.power_friction * 1e3, label="wheel friction")
    ax.set_ylabel("power (mW)")
    _mark_events(ax, traj)
    ax.legend(fontsize=8)
    ax.set_title("power and energy budget, " + title, fontsize=10)
    ax = axes[1]
    ke = traj.kinetic_energy - traj.kinetic_energy[0]
    ax.plot(t, ke * 1e3, "k", lw=2, label="kinetic energy gained")
    ax.plot(t, traj.work_tau * 1e3, label="work of joint torques")
    ax.plot(t, traj.work_friction * 1e3, label="work of wheel friction")
    if np.any(traj.work_object):
        ax.plot(t, traj.work_object * 1e3, label="work of the object wrench")
    ax.plot(t, -traj.impact_loss * 1e3, label="lost in impacts")
    ax.plot(t, traj.energy_residual * 1e3, ":", label="balance residual")
    ax.set_ylabel("energy (mJ)")
    ax.set_xlabel("t (s)")
    _mark_events(ax, traj, label=False)
    ax.legend(fontsize=8)
    fig.tight_layout()
    paths["energy"] = str(out / "energy.png")
    _savefig(fig, paths["energy"], dpi)
    plt.close(fig)

    # forces and active set -----------------------------------------------------------------
    nl = traj.wheel_state.shape[1]
    fig, axes = plt.subplots(2, 1, figsize=(7, 5.6), sharex=True,
                             gridspec_kw={"height_ratios": [3, 1.3]})
    ax = axes[0]
    ax.plot(t, traj.lam[:, 0], "k", lw=1.5, label="contact")
    wheel_links = list(traj.geometry.get("wheel_links", range(1, nl + 1)))
    for i in wheel_links:
        ax.plot(t, traj.lam[:, i], lw=1, label=f"wheel {i}")
    bounds = traj.geometry.get("wheel_bounds")
    if bounds is not None and np.isfinite(bounds).any():
        for b in np.unique(np.asarray(bounds)[np.isfinite(bounds)]):
            ax.axhline(b, color="0.5", lw=0.6, ls=":")
            ax.axhline(-b, color="0.5", lw=0.6, ls=":")
    ax.set_ylabel("constraint force (N)")
    _mark_events(ax, traj, label=False)
    ax.legend(fontsize=8, ncol=2)
    ax.set_title("constraint forces and active set (dotted: friction bounds)", fontsize=10)
    ax = axes[1]
    rows = [("contact", np.where(traj.contact, 1, 0))]
    code = {"none": -1, "stick": 1, "slide+": 2, "slide-": 3}
    for i in wheel_links:
        rows.append((f"wheel {i}", np.array([code[s] for s in traj.wheel_state[:, i - 1]])))
    colors = {-1: "white", 0: "0.8", 1: "tab:green", 2: "tab:red", 3: "tab:orange"}
    for r, (name, vals) in enumerate(rows):
        cuts = np.flatnonzero(np.diff(vals)) + 1
        starts = np.concatenate(([0], cuts))
        ends = np.concatenate((cuts, [len(t) - 1]))
        for a, b in zip(starts, ends):
            if t[b] > t[a]:
                ax.broken_barh([(t[a], t[b] - t[a])], (r - 0.4, 0.8),
                               facecolors=colors[int(vals[a])], lw=0)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels([r[0] for r in rows], fontsize=8)
    ax.set_xlabel("t (s)  (green: held/stick, grey: lost, red/orange: slide+/slide-)")
    ax.set_xlim(t[0], t[-1])
    fig.tight_layout()
    paths["forces"] = str(out / "forces.png")
    _savefig(fig, paths["forces"], dpi)
    plt.close(fig)

    if animation:
        paths["animation"] = save_animation(traj, out / "animation.gif", fps=fps, frames=frames)
    return paths


def _frame_indices(t: np.ndarray, frames: int) -> np.ndarray:
    times = np.linspace(t[0], t[-1], max(2, int(frames)))
    idx = np.searchsorted(t, times, side="right") - 1
    return np.clip(idx, 0, len(t) - 1)


def save_animation(traj: Trajectory, path, *, fps: int = 20, frames: int = 100,
                   dpi: int = 80) -> str:
    """An animated GIF of the robot pushing the object: ``frames`` frames evenly spaced in
    time, drawn with matplotlib (links, wheels green when sticking and red when sliding, the
    object as a square of side ``2 object_distance``, the contact point, the paths of the
    object and of the snake's COM) and written by Pillow at ``fps`` frames per second."""
    from matplotlib.patches import Polygon
    from PIL import Image

    if isinstance(frames, bool) or not isinstance(frames, (int, np.integer)) \
            or not 2 <= frames <= MAX_FRAMES:
        raise InputError(f"frames must be an integer from 2 to {MAX_FRAMES} (the limit: every "
                         f"frame is held in memory until the GIF is written), got {frames!r:.60}")

    plt = _pyplot()
    g = traj.geometry
    length, com = np.asarray(g["length"]), np.asarray(g["com"])
    woff = np.asarray(g["wheel_offset"])
    wheel_links = np.asarray(g["wheel_links"], dtype=int)
    half = float(g["object_distance"])
    P = traj.link_poses  # (N, n_l, 3)
    e = np.stack([np.cos(P[..., 2]), np.sin(P[..., 2])], axis=-1)
    rear = P[..., :2] - com[None, :, None] * e
    front = rear + length[None, :, None] * e
    square = np.array([[-half, -half], [half, -half], [half, half], [-half, half]])

    def object_corners(i):
        c, s = np.cos(traj.q_obj[i, 2]), np.sin(traj.q_obj[i, 2])
        R = np.array([[c, -s], [s, c]])
        return traj.q_obj[i, :2] + square @ R.T

    def contact_point(i):
        c, s = np.cos(traj.q_obj[i, 2]), np.sin(traj.q_obj[i, 2])
        R = np.array([[c, -s], [s, c]])
        return traj.q_obj[i, :2] + R @ traj.rho

    idx = _frame_indices(traj.t, frames)
    pts = np.concatenate([rear[idx].reshape(-1, 2), front[idx].reshape(-1, 2),
                          np.concatenate([object_corners(i) for i in idx])])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = max(hi - lo) * 0.55 + 0.02
    mid = 0.5 * (lo + hi)
    fig, ax = plt.subplots(figsize=(4.2, 4.2))
    ax.set_xlim(mid[0] - span, mid[0] + span)
    ax.set_ylim(mid[1] - span, mid[1] + span)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    (links_line,) = ax.plot([], [], "-o", color="tab:blue", lw=3, ms=3)
    (wheels_stick,) = ax.plot([], [], "s", color="tab:green", ms=5, label="wheel sticking")
    (wheels_slide,) = ax.plot([], [], "s", color="tab:red", ms=5, label="wheel sliding")
    obj = Polygon(square, closed=True, fc="tan", ec="saddlebrown", alpha=0.8)
    ax.add_patch(obj)
    (cpt,) = ax.plot([], [], "k.", ms=6)
    (obj_trail,) = ax.plot([], [], color="saddlebrown", lw=0.8)
    (com_trail,) = ax.plot([], [], color="tab:blue", lw=0.8, ls="--", label="snake COM")
    text = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top", fontsize=8)
    ax.legend(loc="lower right", fontsize=7)
    fig.tight_layout()

    def draw(j):
        i = idx[j]
        xs, ys = [], []
        for k in range(length.size):
            xs += [rear[i, k, 0], front[i, k, 0], np.nan]
            ys += [rear[i, k, 1], front[i, k, 1], np.nan]
        links_line.set_data(xs, ys)
        wp = P[i, wheel_links - 1, :2] + woff[wheel_links - 1, None] * e[i, wheel_links - 1]
        sliding = np.char.startswith(traj.wheel_state[i, wheel_links - 1].astype(str), "slide")
        wheels_stick.set_data(wp[~sliding, 0], wp[~sliding, 1])
        wheels_slide.set_data(wp[sliding, 0], wp[sliding, 1])
        obj.set_xy(object_corners(i))
        cp = contact_point(i)
        cpt.set_data([cp[0]], [cp[1]])
        obj_trail.set_data(traj.q_obj[: i + 1, 0], traj.q_obj[: i + 1, 1])
        com_trail.set_data(traj.com[: i + 1, 0], traj.com[: i + 1, 1])
        text.set_text(f"t = {traj.t[i]:.3f} s   contact {'held' if traj.contact[i] else 'lost'}"
                      f"\nsr = {traj.sr[i]:.3f}")
        return links_line, wheels_stick, wheels_slide, obj, cpt, obj_trail, com_trail, text

    # static parts drawn once; each frame restores them and draws only the moving artists
    # (blitting), then Pillow writes the GIF: several times faster than redrawing every
    # tick label per frame
    moving = (links_line, wheels_stick, wheels_slide, obj, cpt, obj_trail, com_trail, text)
    for a in moving:
        a.set_animated(True)
    canvas = fig.canvas
    fig.set_dpi(dpi)
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)
    images = []
    for j in range(len(idx)):
        canvas.restore_region(background)
        for a in draw(j):
            ax.draw_artist(a)
        rgba = np.asarray(canvas.buffer_rgba())
        images.append(Image.fromarray(rgba[..., :3].copy()).quantize(
            colors=32, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE))
    from ._files import atomic_path

    with atomic_path(path) as tmp:  # unique temporary name, then os.replace
        images[0].save(str(tmp), format="GIF", save_all=True, append_images=images[1:],
                       duration=int(round(1000 / fps)), loop=0, optimize=False)
    plt.close(fig)
    return str(path)
