"""The record of a general scene's simulation (:func:`snakecg.scenes.stepping.simulate_scene`):
the samples, the impacts, the energy balance and the status, with a strict-JSON summary."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .solve import INFO

__all__ = ["SceneEvent", "SceneRun", "SCHEMA"]

SCHEMA = "snakecg.simulate_scene/1"
#: the engine's step's accumulators and figures (scene_step.c's ST_*): the torques' work, the
#: ground's dissipation, the impacts' loss, the contacts' work (cumulative), the last step's
#: contact impulse, the least sliding cosine, the largest residuals, the steps, the last
#: step's impact (flag, loss), the state's kinetic energy, smallest contact gap, contacts,
#: the steps that held their overlaps
(ST_WORK_TAU, ST_FRICTION, ST_IMPACT_LOSS, ST_CONTACT_WORK, ST_CONTACT_IMPULSE, ST_SLIDING_COS,
 ST_PRIMAL, ST_DUAL, ST_COMPL, ST_STEPS, ST_IMPACT, ST_LOSS, ST_KE, ST_MIN_GAP, ST_NC, ST_HELD,
 ST_WIDTH) = range(17)


@dataclass
class SceneEvent:
    """An inelastic impact at ``t``: the contacts' ``bodies`` (names), their normal
    ``impulses`` (N s, >= 0), the kinetic energy ``loss`` (J) and the solve's ``certificate``
    (primal, dual, complementarity residuals, relative).

    Where the scene has contact friction (else None, and absent from :meth:`as_dict`), for
    the same contacts: the ``tangents`` ``(-n_y, n_x)`` (n the normal from the first body to
    the second), the ``friction_impulses`` (N s) along them on the second body (the first
    takes the opposite; ``|p_t| <= mu p_n``) and the ``friction_states`` (``stick``: the
    contact's sliding stopped; ``slip``: ``|p_t| = mu p_n`` against the sliding after;
    ``none``: the pair has no friction)."""

    t: float
    kind: str
    bodies: list
    impulses: list
    loss: float
    certificate: dict
    tangents: list | None = None
    friction_impulses: list | None = None
    friction_states: list | None = None

    def as_dict(self) -> dict:
        out = {"t": self.t, "kind": self.kind, "bodies": self.bodies,
               "impulses": self.impulses, "loss": self.loss, "certificate": self.certificate}
        if self.friction_impulses is not None:
            out.update(tangents=self.tangents, friction_impulses=self.friction_impulses,
                       friction_states=self.friction_states)
        return out


#: the sample fields (made from the engine's rows when first read)
_COLUMNS = ("t", "min_gap", "n_contacts", "contact_impulse", "kinetic_energy", "work_tau",
            "friction_dissipation", "impact_loss", "contact_work", "q", "v", "q_obj", "v_obj",
            "tau")
#: the fields that are columns of the engine's figures (ST_*)
_ACC = {"min_gap": ST_MIN_GAP, "n_contacts": ST_NC, "contact_impulse": ST_CONTACT_IMPULSE,
        "kinetic_energy": ST_KE, "work_tau": ST_WORK_TAU, "friction_dissipation": ST_FRICTION,
        "impact_loss": ST_IMPACT_LOSS, "contact_work": ST_CONTACT_WORK}


def _finite(x):
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


@dataclass
class SceneRun:
    """A general scene's run, sampled at ``t`` (N,) (every step, or every ``output_every``):

    * state: ``q``, ``v`` (N, n_s), ``q_obj``, ``v_obj`` (N, n_objects, 3); ``tau`` (N, n_a)
      (the torque held over the step that ends at the sample);
    * contacts: ``min_gap`` (N,) the smallest signed distance of the pairs within the contact
      tolerance (m; inf where there is none: every pair is farther apart; >= -tolerance on
      every sample of a completed run), ``n_contacts`` (N,), ``contact_impulse`` (N,) the
      sum of the contacts' normal impulses over the step (N s);
    * energy: ``kinetic_energy`` (N,), cumulative ``work_tau`` (the torques' work, h tau . v+
      per step), ``friction_dissipation`` (the ground's and the contacts' friction,
      -lam . (A v+) >= 0 per step), ``impact_loss`` and ``contact_work`` (the contacts'
      impulses on their rows' velocities: 0 but for the gap stabilisation);
    * ``events`` (impacts, :class:`SceneEvent`), ``status`` (``completed``, ``penetration``,
      ``not_converged``), ``message``, ``violation`` (time and bodies, or None);
    * ``certificate``: the largest KKT residuals of the steps' solves;
    * ``steps``, and ``held_steps``: the steps taken with their overlaps held rather than
      pushed out (the gap stabilisation left out where it asks for what no velocity gives:
      :mod:`snakecg.scenes.stepping`).
    """

    tolerance: float
    dt: float
    t: list = field(default_factory=list)
    q: list = field(default_factory=list)
    v: list = field(default_factory=list)
    q_obj: list = field(default_factory=list)
    v_obj: list = field(default_factory=list)
    tau: list = field(default_factory=list)
    min_gap: list = field(default_factory=list)
    n_contacts: list = field(default_factory=list)
    contact_impulse: list = field(default_factory=list)
    kinetic_energy: list = field(default_factory=list)
    work_tau: list = field(default_factory=list)
    friction_dissipation: list = field(default_factory=list)
    impact_loss: list = field(default_factory=list)
    contact_work: list = field(default_factory=list)
    events: list = field(default_factory=list)
    status: str = "running"
    message: str = ""
    violation: dict | None = None
    certificate: dict = field(default_factory=lambda: {"primal": 0.0, "dual": 0.0,
                                                       "complementarity": 0.0})
    steps: int = 0
    held_steps: int = 0
    min_sliding_cosine: float = -1.0
    _rows: list = field(default_factory=list)
    _ns: int = 0
    _n: int = 0
    _na: int = 0
    _names: object = None
    _engine_acc: object = None
    _data: object = field(default=None, repr=False)

    @classmethod
    def start(cls, model, tolerance, dt) -> SceneRun:
        r = cls(tolerance=float(tolerance), dt=float(dt))
        r._ns = model.n_coordinates
        r._n, r._na = model.n_coordinates + 3 * model.scene.n_objects, model.n_joints
        r._names = model.scene.body_name
        return r

    # while running (from the engine's step, snakecg/engine/scene_step.c) -------------
    def follow(self, acc) -> None:
        """Read the run's accumulators and figures from the engine's array ``acc``
        (``ST_*``) at every sample and at the end."""
        self._engine_acc = acc

    def _read(self) -> None:
        acc = self._engine_acc
        if acc is None:
            return
        self.min_sliding_cosine = float(acc[ST_SLIDING_COS])
        for k, i in (("primal", ST_PRIMAL), ("dual", ST_DUAL), ("complementarity", ST_COMPL)):
            self.certificate[k] = float(acc[i])
        self.steps = int(acc[ST_STEPS])
        self.held_steps = int(acc[ST_HELD])

    def impact(self, t, loss, contacts, lam, info) -> None:
        """An inelastic impact at ``t``: its kinetic energy ``loss``, the contacts of the
        state (with the impact's friction impulses where the scene has contact friction)
        and their normal impulses ``lam`` (by row), the solve's certificate ``info``."""
        bodies, imps, tangents, ft, fs = [], [], [], [], []
        for c in contacts:
            if lam[c.row] > 0:
                bodies.append([self._names(*c.a), self._names(*c.b)])
                imps.append(float(lam[c.row]))
                tangents.append([-float(c.normal[1]), float(c.normal[0])])
                ft.append(float(c.friction))
                fs.append(c.friction_state)
        cert = {k: float(info[INFO.index(k)]) for k in ("primal", "dual", "complementarity")}
        rough = any(c.friction_state is not None for c in contacts)
        self.events.append(SceneEvent(float(t), "impact", bodies, imps, float(loss), cert,
                                      *((tangents, ft, fs) if rough else ())))

    def samples(self, rows) -> None:
        """Samples from the engine's run (``snakecg/engine/scene_run.c``): rows of the time,
        the state ``x``, ``V``, the torque held over the step that ends there and the
        engine's figures at it (``ST_*``); the fields are made from them when first read."""
        if len(rows):
            self._rows.append(np.asarray(rows, dtype=float))

    def finish(self, status, t, message, bodies=None) -> SceneRun:
        self._read()
        self._engine_acc = None  # (read: the engine's array goes on to other runs)
        self.status = status
        self.message = message
        if status == "penetration":
            self.violation = {"t": float(t), "bodies": [self._names(*b) for b in bodies]
                              if bodies else [], "message": message}
        if self._rows:  # the fields made from the rows when first read (__getattr__)
            self._data = (self._rows[0] if len(self._rows) == 1
                          else np.concatenate(self._rows))
            self._rows = []
            for k in _COLUMNS:
                del self.__dict__[k]
        else:
            for k in _COLUMNS:
                setattr(self, k, np.ascontiguousarray(getattr(self, k), dtype=float))
        return self

    def __getattr__(self, name):
        """A sample field of a finished run, made from its rows on first read (kept)."""
        data = self.__dict__.get("_data")
        if data is None or name not in _COLUMNS:
            raise AttributeError(name)
        value = self.__dict__[name] = np.ascontiguousarray(self._column(data, name))
        return value

    def _column(self, data, name) -> np.ndarray:
        """The field ``name`` of the rows ``data`` (the engine's: t, x, V, tau, acc)."""
        ns, n, na = self._ns, self._n, self._na
        if name == "t":
            return data[:, 0]
        if name in ("q", "q_obj"):
            x = data[:, 1:1 + n]
            return x[:, :ns] if name == "q" else x[:, ns:].reshape(len(x), -1, 3)
        if name in ("v", "v_obj"):
            V = data[:, 1 + n:1 + 2 * n]
            return V[:, :ns] if name == "v" else V[:, ns:].reshape(len(V), -1, 3)
        if name == "tau":
            return data[:, 1 + 2 * n:1 + 2 * n + na]
        return data[:, 1 + 2 * n + na + _ACC[name]]

    def states(self) -> np.ndarray:
        """``(q, q_obj)`` of every sample side by side, ``(N, n_s + 3 n_objects)`` (a view of
        the rows where the fields are not made yet)."""
        data = self.__dict__.get("_data")
        if data is not None:
            return data[:, 1:1 + self._n]
        if not len(self.q):
            return np.zeros((0, self._n))
        return np.concatenate((self.q, self.q_obj.reshape(len(self.q), -1)), axis=1)

    # after -----------------------------------------------------------------------------
    @property
    def summary(self) -> dict:
        """A JSON-ready summary (schema ``snakecg.simulate_scene/1``)."""
        ke = self.kinetic_energy
        return {
            "schema": SCHEMA, "status": self.status, "message": self.message,
            "violation": self.violation, "duration": float(self.t[-1]) if len(self.t) else 0.0,
            "steps": self.steps, "held_steps": self.held_steps, "samples": int(len(self.t)),
            "dt": self.dt, "tolerance": self.tolerance,
            "min_gap": _finite(float(np.min(self.min_gap))) if len(self.min_gap) else None,
            "impacts": len(self.events),
            "events": [e.as_dict() for e in self.events[:100]],
            "energy": {"kinetic_start": float(ke[0]) if len(ke) else 0.0,
                       "kinetic_end": float(ke[-1]) if len(ke) else 0.0,
                       "work_tau": float(self.work_tau[-1]) if len(ke) else 0.0,
                       "friction_dissipation": float(self.friction_dissipation[-1])
                       if len(ke) else 0.0,
                       "impact_loss": float(self.impact_loss[-1]) if len(ke) else 0.0,
                       "contact_work": float(self.contact_work[-1]) if len(ke) else 0.0},
            "certificate": self.certificate,
            "q_end": self.q[-1].tolist() if len(self.q) else None,
            "q_obj_end": self.q_obj[-1].tolist() if len(self.q_obj) else None,
        }
