"""The paper's metrics on a general scene, and the result of a forward solve.

Per sample: ``||qdd_s||^2 = qdd^T M_s qdd`` (eq. 26), ``||a_o||^2 = a_o^T I_o a_o`` per object
(eq. 27) and their sum, ``||lambda||^2 = lam^T G_c lam`` (the constraint forces' own metric,
as the paper's scenarios report it), and ``sr = sum_o ||a_o||^2 / (sum_o ||a_o||^2 +
||qdd_s||^2)`` (eq. 30, 0 where both are 0). A sample the solve did not answer has NaN
metrics and its status says why.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .solve import BOX, DISC, FREE, SPLIT, UNILATERAL, ZERO, SLIDE, SLIDE_NEG, SLIDE_POS

__all__ = ["SceneResult", "norms", "STATUS_NAMES"]

STATUS_NAMES = ("solved", "not_converged", "singular_mass", "overlap")
_KIND_NAMES = {FREE: "ideal_wheel", UNILATERAL: "contact", BOX: "wheel", DISC: "coulomb",
               SPLIT: "anisotropic"}


def state_name(kind: int, code: int) -> str:
    """A block's state in words: contacts 'held'/'open', friction 'stick'/'slide'
    ('slide+'/'slide-' for a bounded wheel), 'none' for a set of size 0."""
    if kind == UNILATERAL:
        return "held" if code == 0 else "open"
    if code == 0:
        return "stick"
    if code == ZERO:
        return "none"
    return {SLIDE: "slide", SLIDE_POS: "slide+", SLIDE_NEG: "slide-"}[int(code)]


def norms(qdd, M_s, a_obj, inertia, a, a_free, M_full):
    """``(norm_qdd, norm_a_obj_each, norm_a_obj, norm_lambda)`` of a batch (eqs. 26, 27)."""
    nq = np.einsum("ni,nij,nj->n", qdd, M_s, qdd)
    each = np.einsum("noi,oi,noi->no", a_obj, inertia, a_obj)
    d = a - a_free
    nl = np.einsum("ni,nij,nj->n", d, M_full, d)  # lam^T G lam = (A^T lam)^T M^-1 (A^T lam)
    return nq, each, each.sum(axis=1), nl


@dataclass
class SceneResult:
    """The forward solve of a general scene: one sample (``qdd`` ``(n_s,)``) or a batch
    (``(N, n_s)``); ``a_obj`` ``(..., n_objects, 3)``; per sample the ``contacts``, ``ground``
    rows and ``objects`` as lists of dicts; ``certificate``: the KKT residuals (relative
    primal, dual, complementarity), ``dependent``: the held rows were dependent (statically
    indeterminate; forces minimum-norm on the face: 1, or not attained: 2), ``status``."""

    qdd: np.ndarray
    a_obj: np.ndarray
    norm_qdd: np.ndarray
    norm_a_obj: np.ndarray
    norm_a_obj_each: np.ndarray
    norm_lambda: np.ndarray
    sr: np.ndarray
    status: np.ndarray
    dependent: np.ndarray
    certificate: dict
    contacts: list
    ground: list
    objects: list
    reason: list = field(default_factory=list)
    batched: bool = True

    def sample(self, i: int) -> SceneResult:
        """Sample ``i`` of a batch as a one-sample result."""
        return SceneResult(self.qdd[i], self.a_obj[i], self.norm_qdd[i], self.norm_a_obj[i],
                           self.norm_a_obj_each[i], self.norm_lambda[i], self.sr[i],
                           self.status[i], self.dependent[i],
                           {k: v[i] for k, v in self.certificate.items()}, self.contacts[i],
                           self.ground[i], self.objects[i], [self.reason[i]], False)

    def to_dict(self) -> dict:
        """One sample's fields for JSON (``qdd``, ``a_obj``, the norms, ``sr``, one entry per
        contact, ground block and object, the certificate)."""
        r = self if not self.batched else self.sample(0)
        return {"qdd": np.asarray(r.qdd).tolist(), "a_obj": np.asarray(r.a_obj).tolist(),
                "norm_lambda": float(r.norm_lambda), "norm_a_obj": float(r.norm_a_obj),
                "norm_qdd": float(r.norm_qdd), "sr": float(r.sr),
                "status": STATUS_NAMES[int(r.status)], "reason": r.reason[0],
                "dependent": int(r.dependent), "certificate": {k: float(v) for k, v in
                                                               r.certificate.items()},
                "contacts": r.contacts, "ground": r.ground, "objects": r.objects}
