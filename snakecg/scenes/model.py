"""The loaded model of a general scene: the robot's generated functions (mass matrix, link
poses and Jacobians, one compiled call per batch), the rows found from geometry per sample
(:mod:`snakecg.scenes.contacts`) and the compiled exact solve (:mod:`snakecg.scenes.
solve`), at rest."""

from __future__ import annotations

import numpy as np

from .._inputs import as_batch, broadcast_batches, check_batch_memory
from ..errors import InputError
from ..robot_model import RobotModel
from .contacts import rows_of
from .description import GeneralScene
from .metrics import SceneResult, norms, state_name
from .solve import solve

__all__ = ["GeneralSceneModel"]

_REFUSED = ("simulate", "optimize_shape", "com_polar")


class GeneralSceneModel(RobotModel):
    """``forward``, ``maps``, ``extremes`` and ``optimize`` on a
    :class:`~snakecg.scenes.GeneralScene` (at rest)."""

    def __init__(self, scene: GeneralScene, *, backend: str = "compiled", progress=None):
        if not isinstance(scene, GeneralScene):
            raise InputError(f"scene must be a snakecg.scenes.GeneralScene, got "
                             f"{type(scene).__name__}")
        super().__init__(scene.robot, backend=backend, progress=progress)
        self.scene = scene
        self.core = getattr(self.backend, "core", None)
        self.masses = np.asarray(scene.robot.mass, dtype=float)
        self.object_inertia = np.array([[o.mass, o.mass, o.plate_inertia]
                                        for o in scene.objects]).reshape(-1, 3)

    def __getattr__(self, name):
        if name in _REFUSED:
            raise InputError(f"{name} is not available on a general scene yet (forward, "
                             f"maps, extremes, optimize and plot are); use a snakecg.Scene of "
                             f"the paper's scenarios")
        raise AttributeError(name)

    def maps(self, q, *, state=None) -> dict:
        """The linear maps at ``q`` for a block state (:func:`snakecg.scenes.maps.maps`)."""
        from .maps import maps
        return maps(self, q, state=state)

    def extremes(self, q, **kwargs):
        """Extremes of the metrics on the input ellipsoid (:mod:`snakecg.scenes.extremes`)."""
        from .extremes import extremes
        return extremes(self, q, **kwargs)

    def optimize(self, q, objective="max_sr", **kwargs):
        """Optimal torques for a task (:func:`snakecg.scenes.optimize.optimize`)."""
        from .optimize import optimize
        return optimize(self, q, objective, **kwargs)

    def forward(self, q, tau, *, f_obj=None, v=None) -> SceneResult:
        """Accelerations, forces, contact states, norms, sr and the certificate at rest.

        ``q`` ``(n_s,)`` or ``(N, n_s)``; ``tau`` ``(n_a,)`` or ``(N, n_a)``; ``f_obj``: an
        external wrench (F_x, F_y, torque) on every object, ``(n_objects, 3)`` (or batched).
        A sample whose shapes overlap is refused (one sample: :class:`InputError`; in a batch:
        NaN with status ``overlap`` and the reason)."""
        if v is not None and np.any(np.asarray(v, dtype=float) != 0):
            raise InputError("v: a general scene is solved at rest (v = 0); velocities are not "
                             "supported yet")
        na, ns, no = self.n_joints, self.n_coordinates, self.scene.n_objects
        qa, bq = as_batch("q", q, ns, what=f" = (n_joints + 3,) for a {na}-joint robot")
        ta, bt = as_batch("tau", tau, na, what=f" (one torque per joint, n_a = {na})")
        if f_obj is None:
            fo, bf = np.zeros((1, 3 * no)), False
        else:
            arr = np.asarray(f_obj, dtype=float)
            batched_f = arr.ndim == 3
            fo, bf = as_batch("f_obj", arr.reshape(arr.shape[0], -1) if batched_f
                              else arr.reshape(-1), 3 * no,
                              what=f" = (n_objects, 3) wrenches, {no} objects")
        N = broadcast_batches(q=(qa, bq), tau=(ta, bt), f_obj=(fo, bf))
        check_batch_memory("forward", N, 8 * (ns + 3 * no) ** 2 * 6, what="results")
        qa = np.broadcast_to(qa, (N, ns))
        ta = np.broadcast_to(ta, (N, na))
        fo = np.broadcast_to(fo, (N, 3 * no))
        M_s = self.mass_matrix(qa) if N > 0 else np.zeros((0, ns, ns))
        J = self.link_jacobians(qa).reshape(N, self.n_links, 3, ns)
        P = self.link_poses(qa).reshape(N, self.n_links, 3)
        n = ns + 3 * no
        rows, poses, reasons = [], [], []
        for s in range(N):
            try:
                r, op = rows_of(self.scene, self.masses, P[s], J[s],
                                index=s if N > 1 or bq else None)
            except InputError as exc:
                if not (bq or bt or bf):
                    raise
                r, op = None, np.full((no, 3), np.nan)
                reasons.append(str(exc))
            else:
                reasons.append("")
            rows.append(r)
            poses.append(op)
        mmax = max([r.A.shape[0] for r in rows if r is not None] + [1])
        nbmax = max([len(r.kind) for r in rows if r is not None] + [1])
        Mf = np.zeros((N, n, n))
        Mf[:, :ns, :ns] = M_s
        for j in range(no):
            Mf[:, ns + 3 * j + np.arange(3), ns + 3 * j + np.arange(3)] = self.object_inertia[j]
        f = np.zeros((N, n))
        f[:, 3:ns] = ta
        f[:, ns:] = fo
        A = np.zeros((N, mmax, n))
        m = np.zeros(N, dtype=np.int64)
        kind = np.full((N, nbmax), -1, dtype=np.int64)
        start = np.zeros((N, nbmax), dtype=np.int64)
        par = np.zeros((N, nbmax, 3))
        for s, r in enumerate(rows):
            if r is None:
                continue
            k = len(r.kind)
            m[s] = r.A.shape[0]
            A[s, :m[s]] = r.A
            kind[s, :k] = r.kind
            start[s, :k] = r.start
            par[s, :k] = np.reshape(r.par, (-1, 3))
        out = solve(self.core, Mf, f, A, m, kind, start, par)
        a = out["a"]
        a_free = np.linalg.solve(Mf, f[..., None])[..., 0]
        qdd = a[:, :ns]
        a_obj = a[:, ns:].reshape(N, no, 3)
        nq, each, na_sum, nl = norms(qdd, M_s, a_obj, self.object_inertia, a, a_free, Mf)
        # eq. (30); 0 where both norms are rounding (below (1e-13)^2 of the free motion's
        # |a_free|^2_M: a system that does not move)
        denom = na_sum + nq
        free = np.einsum("ni,nij,nj->n", a_free, Mf, a_free)
        moving = denom > 1e-26 * free
        sr = np.where(moving, na_sum / np.where(moving, denom, 1.0), 0.0)
        status = out["info"]["status"].astype(int)
        overlap = np.array([r is None for r in rows])
        status[overlap] = 3
        bad = status != 0
        for arr in (nq, na_sum, nl, sr):
            arr[bad] = np.nan
        each[bad] = np.nan
        qdd[bad] = np.nan
        a_obj[bad] = np.nan
        nq = np.maximum(nq, 0.0)  # rounding of a form that is >= 0
        contacts, ground, objects = [], [], []
        for s, r in enumerate(rows):
            lam, st = out["lam"][s], out["state"][s]
            cs, gs = [], []
            if r is not None:
                for b, (kd, st0, label) in enumerate(zip(r.kind, r.start, r.labels)):
                    size = 2 if kd >= 3 else 1
                    force = lam[st0:st0 + size].tolist()
                    if label[0] == "contact":
                        c = r.contacts[label[1]]
                        cs.append({"bodies": [self.scene.body_name(*c.a),
                                              self.scene.body_name(*c.b)],
                                   "point": ((c.point_a + c.point_b) / 2).tolist(),
                                   "normal": c.normal.tolist(), "gap": c.gap,
                                   "force": force[0], "state": state_name(kd, int(st[b]))})
                    else:
                        what = ("link" if label[0] in ("wheel", "ground") else "object")
                        gs.append({what: label[1] + 1, "model": _model_name(kd),
                                   "force": force, "state": state_name(kd, int(st[b]))})
            contacts.append(cs)
            ground.append(gs)
            objects.append([{"object": j + 1, "pose": poses[s][j].tolist(),
                             "a": a_obj[s, j].tolist(), "norm_a": float(each[s, j])}
                            for j in range(no)])
        reason = [reasons[s] or ({1: "the active-set solve did not converge",
                                  2: "the mass matrix is not positive definite"}
                                 .get(int(status[s]), "")) for s in range(N)]
        cert = {k: out["info"][k] for k in ("primal", "dual", "complementarity")}
        res = SceneResult(qdd, a_obj, nq, na_sum, each, nl, sr, status,
                          out["info"]["dependent"].astype(int), cert, contacts, ground,
                          objects, reason, True)
        res._raw = out  # the solver's arrays (lam, w, state, info) for checks
        res._rows, res._q = rows, qa
        if bq or bt or bf:
            return res
        one = res.sample(0)
        one._raw, one._rows, one._q = out, rows, qa[0]
        return one


def _model_name(kind: int) -> str:
    from .metrics import _KIND_NAMES

    return _KIND_NAMES[kind]
