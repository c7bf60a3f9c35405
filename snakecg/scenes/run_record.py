"""The record of a general scene's simulation (:func:`snakecg.scenes.stepping.simulate_scene`):
the samples, the impacts, the energy balance and the status, with a strict-JSON summary."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .solve import BOX, DISC, SPLIT, UNILATERAL

__all__ = ["SceneEvent", "SceneRun", "SCHEMA"]

SCHEMA = "snakecg.simulate_scene/1"


@dataclass
class SceneEvent:
    """An inelastic impact at ``t``: the contacts' ``bodies`` (names), their normal
    ``impulses`` (N s, >= 0), the kinetic energy ``loss`` (J) and the solve's ``certificate``
    (primal, dual, complementarity residuals, relative)."""

    t: float
    kind: str
    bodies: list
    impulses: list
    loss: float
    certificate: dict

    def as_dict(self) -> dict:
        return {"t": self.t, "kind": self.kind, "bodies": self.bodies,
                "impulses": self.impulses, "loss": self.loss, "certificate": self.certificate}


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
      per step), ``friction_dissipation`` (the ground's, -lam . (A v+) >= 0 per step),
      ``impact_loss`` and ``contact_work`` (the contacts' impulses on their rows' velocities:
      0 but for the gap stabilisation);
    * ``events`` (impacts, :class:`SceneEvent`), ``status`` (``completed``, ``penetration``,
      ``not_converged``), ``message``, ``violation`` (time and bodies, or None);
    * ``certificate``: the largest KKT residuals of the steps' solves.
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
    min_sliding_cosine: float = -1.0
    _acc: list = field(default_factory=lambda: [0.0, 0.0, 0.0, 0.0, 0.0])
    _ns: int = 0
    _names: object = None

    @classmethod
    def start(cls, model, tolerance, dt) -> SceneRun:
        r = cls(tolerance=float(tolerance), dt=float(dt))
        r._ns = model.n_coordinates
        r._names = model.scene.body_name
        return r

    # while running ---------------------------------------------------------------------
    def step_work(self, h, tau, Vp, out, rows) -> None:
        """The step's work of the torques, friction dissipation, contacts' work and impulse,
        the certificate's residuals, and the sliding blocks' impulses against their velocity
        (the cosine of the impulse with -(A v+): 1 for kinetic friction opposing sliding)."""
        ns = self._ns
        self._acc[0] += h * float(tau @ Vp[3:ns])
        lam, A = out["lam"], rows.A
        m = A.shape[0]
        w = A @ Vp if m else np.zeros(0)
        kind = np.asarray(rows.kind, dtype=np.int64)
        start = np.asarray(rows.start, dtype=np.int64)
        size = np.where((kind == DISC) | (kind == SPLIT), 2, 1)
        per_row = np.repeat(kind, size) if m else np.zeros(0, dtype=np.int64)
        fric = np.isin(per_row, (BOX, DISC, SPLIT))
        cont = per_row == UNILATERAL
        self._acc[1] -= float(lam[:m][fric] @ w[fric])
        self._acc[3] += float(lam[:m][cont] @ w[cont])
        self._acc[4] = float(lam[:m][cont].sum())
        # Coulomb discs and bounded wheels: the impulse anti-parallel to the sliding velocity
        for kd in (DISC, BOX):
            st = start[kind == kd]
            if not st.size:
                continue
            idx = st[:, None] + np.arange(2 if kd == DISC else 1)
            wk, lk = w[idx], lam[idx]
            sp = np.sqrt((wk * wk).sum(axis=1))
            ln = np.sqrt((lk * lk).sum(axis=1))
            slide = (sp > 1e-9) & (ln > 0)
            if slide.any():
                cos = -(lk[slide] * wk[slide]).sum(axis=1) / (sp[slide] * ln[slide])
                c = float(cos.min())
                self.min_sliding_cosine = (c if self.min_sliding_cosine < 0 else
                                           min(self.min_sliding_cosine, c))
        info = out["info"]
        for k in ("primal", "dual", "complementarity"):
            self.certificate[k] = max(self.certificate[k], float(info[k]))
        self.steps += 1

    def impact(self, t, V0, V1, Mf, out, rows, scene) -> None:
        loss = 0.5 * float(V0 @ Mf @ V0 - V1 @ Mf @ V1)
        self._acc[2] += loss
        lam = out["lam"]
        bodies, imps = [], []
        for c in rows.contacts:
            if lam[c.row] > 0:
                bodies.append([scene.body_name(*c.a), scene.body_name(*c.b)])
                imps.append(float(lam[c.row]))
        info = out["info"]
        self.events.append(SceneEvent(float(t), "impact", bodies, imps, loss,
                                      {k: float(info[k]) for k in
                                       ("primal", "dual", "complementarity")}))

    def sample(self, t, x, V, tau, Mf, min_gap, rows, out) -> None:
        ns = self._ns
        self.t.append(float(t))
        self.q.append(x[:ns].copy())
        self.v.append(V[:ns].copy())
        self.q_obj.append(x[ns:].reshape(-1, 3).copy())
        self.v_obj.append(V[ns:].reshape(-1, 3).copy())
        self.tau.append(np.array(tau, dtype=float))
        self.min_gap.append(float(min_gap))
        self.n_contacts.append(len(rows.contacts))
        self.contact_impulse.append(self._acc[4])
        self.kinetic_energy.append(0.5 * float(V @ Mf @ V))
        self.work_tau.append(self._acc[0])
        self.friction_dissipation.append(self._acc[1])
        self.impact_loss.append(self._acc[2])
        self.contact_work.append(self._acc[3])

    def finish(self, status, t, message, bodies=None) -> SceneRun:
        self.status = status
        self.message = message
        if status == "penetration":
            self.violation = {"t": float(t), "bodies": [self._names(*b) for b in bodies]
                              if bodies else [], "message": message}
        for k in ("t", "min_gap", "n_contacts", "contact_impulse", "kinetic_energy",
                  "work_tau", "friction_dissipation", "impact_loss", "contact_work"):
            setattr(self, k, np.asarray(getattr(self, k), dtype=float))
        for k in ("q", "v", "q_obj", "v_obj", "tau"):
            setattr(self, k, np.asarray(getattr(self, k), dtype=float))
        return self

    # after -----------------------------------------------------------------------------
    @property
    def summary(self) -> dict:
        """A JSON-ready summary (schema ``snakecg.simulate_scene/1``)."""
        ke = self.kinetic_energy
        return {
            "schema": SCHEMA, "status": self.status, "message": self.message,
            "violation": self.violation, "duration": float(self.t[-1]) if len(self.t) else 0.0,
            "steps": self.steps, "samples": int(len(self.t)), "dt": self.dt,
            "tolerance": self.tolerance,
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
