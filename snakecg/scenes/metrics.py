"""The paper's metrics on a general scene, and the result of a forward solve.

Per sample (computed by the engine, ``snakecg/engine/scene_rows.c``): ``||qdd_s||^2 = qdd^T
M_s qdd`` (eq. 26), ``||a_o||^2 = a_o^T I_o a_o`` per object (eq. 27) and their sum,
``||lambda||^2 = lam^T G_c lam`` (the constraint forces' own metric, as the paper's scenarios
report it), and ``sr = sum_o ||a_o||^2 / (sum_o ||a_o||^2 + ||qdd_s||^2)`` (eq. 30, 0 where
both are 0). A sample the solve did not answer has NaN metrics and its status says why.

:class:`SceneResult` reads the engine's output rows: the arrays are views into them; the
per-contact, per-ground-block and per-object entries are built when first read.
"""

from __future__ import annotations

import numpy as np

from .packing import BODY_KINDS, CR_W, FRICTION_STATES, SO_NC, SO_NORM_A, SO_NORM_L, \
    SO_NORM_QDD, SO_OVERLAP, SO_SOLUTIONS, SO_SR
from .solve import BOX, DISC, FREE, INFO, SLIDE, SLIDE_NEG, SLIDE_POS, SPLIT, UNILATERAL, ZERO

__all__ = ["SceneResult", "STATUS_NAMES"]

STATUS_NAMES = ("solved", "not_converged", "singular_mass", "overlap", "", "too_many_contacts",
                "failed", "not_converged", "overflow")
_KIND_NAMES = {FREE: "ideal_wheel", UNILATERAL: "contact", BOX: "wheel", DISC: "coulomb",
               SPLIT: "anisotropic"}
_REASONS = {1: "the active-set solve did not converge",
            2: "the mass matrix is not positive definite",
            6: "a generated function of the model failed at this configuration",
            7: "Coulomb friction at the contacts: the fixed point on the tangent rows' bounds "
               "(s <- mu lam_n) did not settle, or its answer failed Coulomb's conditions",
            8: "the forces or accelerations overflowed double precision (torques or forces "
               "too large for the scene's masses and sizes: scale them down)"}


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


class SceneResult:
    """The forward solve of a general scene: one sample (``qdd`` ``(n_s,)``) or a batch
    (``(N, n_s)``); ``a_obj`` ``(..., n_objects, 3)``; per sample the ``contacts``, ``ground``
    rows and ``objects`` as lists of dicts (for a batch, a list of them per sample);
    ``certificate``: the KKT residuals (relative primal, dual, complementarity),
    ``dependent``: the held rows were dependent (statically indeterminate; the forces the
    minimum-norm ones inside their sets: 1, or not found to rounding, a basic solution of
    the face kept: 2; with contact friction, Coulomb's own piece decides: 0 where it allows
    one force at these accelerations, 1 where its family's minimum-norm member is returned
    (sticking contacts in their cones, slipping ones on their rays), 2 where that member was
    not found), or nearly dependent beyond what the solve resolves (3: a near miss,
    certified to its ``certificate``, at most 1e-7 instead of 1e-9), ``status``
    (:data:`STATUS_NAMES`) and
    ``reason`` (why a sample was not solved, '' when it was). With contact friction
    (``mu_contact``), ``uniqueness``: ``unique`` (certified: every piece was enumerated and
    one solution meets Coulomb's conditions), ``several`` (enumeration found others: the
    answer is one of ``solutions``), or ``not_certified`` (not enumerated, or some piece's
    equations were singular); ``None`` on a frictionless scene."""

    # filled when first read (class defaults: a one-sample result, made by the model's
    # one-sample forward, sets four fields: _model, _buf (q, tau, then the output row),
    # _ccap and batched)
    _rows_out = _given = _buf = _detail = _reasons = _lists = None

    def __init__(self, model, out: np.ndarray, ccap: int, batched: bool, inputs: tuple):
        self._model, self._rows_out, self._ccap = model, out, ccap
        self.batched = batched
        self._given = inputs  # (q, tau, f_obj) of every sample, for the details
        self._buf = self._detail = self._reasons = self._lists = None

    @property
    def _out(self) -> np.ndarray:
        """The engine's output rows ``(N, width)``."""
        if self._rows_out is None:
            ns, na = self._model.n_coordinates, self._model.n_joints
            self._rows_out = self._buf[None, ns + na:]
        return self._rows_out

    @property
    def _inputs(self) -> tuple:
        if self._given is None:
            ns, na = self._model.n_coordinates, self._model.n_joints
            self._given = (self._buf[None, :ns], self._buf[None, ns:ns + na],
                           self._model._zero_f)
        return self._given

    # the arrays: views into the engine's rows (a batch) or numbers (one sample) -----------
    def _col(self, k):
        return self._out[:, k] if self.batched else self._out[0, k]

    def _span(self, name: str, size: int):
        o = self._model.packed.offset[name]
        return self._out[:, o:o + size] if self.batched else self._out[0, o:o + size]

    @property
    def qdd(self) -> np.ndarray:
        return self._span("qdd", self._model.packed.n_s)

    @property
    def a_obj(self) -> np.ndarray:
        no = self._model.packed.n_objects
        span = self._span("a_obj", 3 * no)  # (no objects: a batch's rows still count)
        return span.reshape((len(span), no, 3) if self.batched else (no, 3))

    @property
    def norm_a_obj_each(self) -> np.ndarray:
        return self._span("each", self._model.packed.n_objects)

    norm_qdd = property(lambda self: self._col(SO_NORM_QDD))
    norm_a_obj = property(lambda self: self._col(SO_NORM_A))
    norm_lambda = property(lambda self: self._col(SO_NORM_L))
    sr = property(lambda self: self._col(SO_SR))

    @property
    def status(self):
        return self._out[:, 0].astype(int) if self.batched else int(self._out[0, 0])

    @property
    def dependent(self):
        return self._out[:, 1].astype(int) if self.batched else int(self._out[0, 1])

    @property
    def solutions(self):
        """The distinct solutions of Coulomb's conditions that enumeration found (0: not
        enumerated; negative: some piece was singular, so others may exist)."""
        return self._out[:, SO_SOLUTIONS].astype(int) if self.batched else int(
            self._out[0, SO_SOLUTIONS])

    @property
    def uniqueness(self):
        """Per sample: ``unique``, ``several`` or ``not_certified`` (class docstring); None
        where the scene has no contact friction."""
        if not self._model.packed.friction:
            return None
        sol = np.atleast_1d(self.solutions)
        words = ["unique" if k == 1 else "several" if abs(k) >= 2 else "not_certified"
                 for k in sol]
        return words if self.batched else words[0]

    @property
    def certificate(self) -> dict:
        return {k: self._col(INFO.index(k)) for k in ("primal", "dual", "complementarity")}

    # the per-sample entries -------------------------------------------------------------
    def _sample_lists(self, s: int):
        pk, off, sc = self._model.packed, self._model.packed.offset, self._model.scene
        row = self._out[s]
        status = int(row[0])
        no = pk.n_objects
        pose = row[off["pose"]:off["pose"] + 3 * no].reshape(no, 3)
        a_obj = row[off["a_obj"]:off["a_obj"] + 3 * no].reshape(no, 3)
        each = row[off["each"]:off["each"] + no]
        objects = [{"object": j + 1, "pose": pose[j].tolist(), "a": a_obj[j].tolist(),
                    "norm_a": float(each[j])} for j in range(no)]
        if status == 3 or status >= 5:
            return [], [], objects
        contacts = []
        base = off["contacts"]
        for c in range(int(row[SO_NC])):
            r = row[base + CR_W * c: base + CR_W * (c + 1)]
            entry = {"bodies": [sc.body_name(BODY_KINDS[int(r[0])], int(r[1])),
                                sc.body_name(BODY_KINDS[int(r[2])], int(r[3]))],
                     "point": ((r[4:6] + r[6:8]) / 2).tolist(),
                     "normal": r[8:10].tolist(), "gap": float(r[10]),
                     "force": float(r[11]), "state": state_name(UNILATERAL, int(r[12]))}
            if pk.friction:  # the tangent (-n_y, n_x), the force along it on the second body
                entry.update(mu=float(r[13]), tangent=[-float(r[9]), float(r[8])],
                             friction=float(r[14]),
                             friction_state=FRICTION_STATES[int(r[15])] if r[13] > 0
                             else "none")
            contacts.append(entry)
        ground = []
        g = row[off["ground"]:off["ground"] + 3 * pk.n_ground].reshape(-1, 3)
        for b, (kind, size, label) in enumerate(zip(pk.kinds, pk.sizes, pk.labels)):
            what = "link" if label[0] in ("wheel", "ground") else "object"
            ground.append({what: label[1] + 1, "model": _KIND_NAMES[kind],
                           "force": g[b, :size].tolist(), "state": state_name(kind,
                                                                              int(g[b, 2]))})
        return contacts, ground, objects

    def _all_lists(self):
        if self._lists is None:
            rows = range(self._out.shape[0]) if self.batched else [0]
            self._lists = [self._sample_lists(s) for s in rows]
        return self._lists

    @property
    def contacts(self) -> list:
        lists = [x[0] for x in self._all_lists()]
        return lists if self.batched else lists[0]

    @property
    def ground(self) -> list:
        lists = [x[1] for x in self._all_lists()]
        return lists if self.batched else lists[0]

    @property
    def objects(self) -> list:
        lists = [x[2] for x in self._all_lists()]
        return lists if self.batched else lists[0]

    @property
    def reason(self) -> list:
        """Why each sample was not solved ('' where it was), one per sample."""
        if self._reasons is None:
            self._reasons = [self._reason_of(s) for s in range(self._out.shape[0])]
        return self._reasons

    def _reason_of(self, s: int) -> str:
        row = self._out[s]
        status = int(row[0])
        if status == 3:
            return self._model.overlap_message(row[SO_OVERLAP:SO_OVERLAP + 6],
                                               s if self.batched else None)
        if status == 5:
            return (f"more than {self._ccap} contacts at this configuration, beyond the "
                    f"{self._model.packed.contacts_max} rows the solve takes")
        return _REASONS.get(status, "")

    # the solver's arrays and the rows, for checks ---------------------------------------
    @property
    def _raw(self) -> dict:
        """The solver's arrays of every sample: ``lam``, ``w`` (rows), ``state`` (blocks),
        ``info`` (by field): solved again with the rows kept."""
        return self._details()["raw"]

    @property
    def _rows(self) -> list:
        """Every sample's rows (:class:`snakecg.scenes.contacts.Rows`; None where it
        overlaps)."""
        return self._details()["rows"]

    @property
    def _q(self):
        q = self._inputs[0]
        return q if self.batched else q[0]

    def _details(self) -> dict:
        if self._detail is None:
            self._detail = self._model.details(self._out, self._inputs)
        return self._detail

    def sample(self, i: int) -> SceneResult:
        """Sample ``i`` of a batch as a one-sample result."""
        one = SceneResult(self._model, self._out[i:i + 1], self._ccap, False,
                          tuple(x[i:i + 1] for x in self._inputs))
        one._reasons = [self.reason[i]]
        return one

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
                "contacts": r.contacts, "ground": r.ground, "objects": r.objects,
                **({"uniqueness": r.uniqueness, "solutions": int(r.solutions)}
                   if self._model.packed.friction else {})}

    def __repr__(self) -> str:
        if self.batched:
            return f"<SceneResult of {self._out.shape[0]} samples>"
        return (f"SceneResult(status={STATUS_NAMES[int(self.status)]!r}, "
                f"sr={float(self.sr):.6g}, contacts={int(self._out[0, SO_NC])})")
