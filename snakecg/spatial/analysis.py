"""The paper's forward analysis on a spatial snake lying on the ground (eqs. 12-30 in 3-D).

``snakecg.load(SpatialScene(...))`` gives a :class:`SpatialSceneModel`; its :meth:`forward`
runs the runtime core's complementarity solve (snakecg/engine/forward.c, the planar models'
own) on the generated spatial ``contact_system``: one C call per batch, split over threads
when large. Rows: the contact (row 0), a lateral wheel row per link (rows ``1..n_l``), a
ground row per link (rows ``n_l + 1..2 n_l``, its force the link's normal force) and a pitch
row per link (rows ``2 n_l + 1..3 n_l``): each link lies on the ground along its axis, held
in height and slope and free to roll about its axis, as a capsule on a flat floor (see
snakecg_derive.spatial.contact). The ground and pitch rows always hold (bilateral); where
they depend on each other (a chain stiffer than its supports: any chain of more than one
link lying flat), their forces are the least-norm ones, the limit of a uniformly stiff
ground along the links.
In scenario 2 each wheel's bound is ``mu`` times its link's solved normal force (none where
that force is negative), found by iterating the solve on the bounds to a fixed point.

Metrics (eqs. 26-30 with the spatial metric tensors): ``norm_qdd = qdd^T M qdd`` with the
spatial ``M`` (n_v x n_v), ``norm_a_obj = a^T diag(m, m, I_zz) a``, ``norm_lambda =
lam_P^T G_PP lam_P`` over the contact and wheel rows (the ground's support, which carries the
weight, is not in it; ``normal`` reports it), ``sr`` of eq. (30).
"""

from __future__ import annotations

import math

import numpy as np

from .._inputs import as_batch, broadcast_batches, check_batch_memory
from ..engine import STATUS_EXACT
from ..errors import InputError
from ..forward import WHEEL_STATE_NAMES, ForwardResult, _Columns, _core_batch
from ..solver import check_input_range, default_max_iter
from .ground import NOT_ON_GROUND, STATUS_NOT_ON_GROUND, lying_flat
from .model import SpatialModel
from .scene import SpatialScene

__all__ = ["SUPPORT", "SpatialForwardResult", "SpatialSceneModel"]

#: The row state of a ground row (snakecg/engine/engine.h).
SUPPORT = 5
#: Why a flagged sample has no answer.
NO_ANSWER = ("the compiled solve did not answer this sample exactly (held rows dependent "
             "beyond the ground's support, no convergence of the active set or of the "
             "friction bounds, an ill-conditioned mass matrix, or an impossible result); its "
             "results are NaN")
_ORDER = ("tau", "qdd", "a_obj", "lam", "normal", "pitch_moment", "w", "contact", "wheel_state",
          "norm_lambda", "norm_a_obj", "norm_qdd", "sr", "singular", "conditioning")


class _SpatialColumns(_Columns):
    """The columns of a spatial result, with each link's Gauss-point offset."""

    __slots__ = ("support_offset",)


def support_offsets(robot) -> np.ndarray:
    """``d_i = L_i / (2 sqrt 3)`` per link: the Gauss points of the link's line on the ground
    from its COM (``L_i`` the distance to its next joint; the last link's, to the joint
    before), as in the generated pitch rows."""
    xyz = np.asarray(robot.joint_xyz, dtype=float)
    idx = np.minimum(np.arange(robot.n_links), robot.joints - 1)
    return np.linalg.norm(xyz[idx], axis=1) / (2 * math.sqrt(3))


class SpatialForwardResult(ForwardResult):
    """:class:`snakecg.ForwardResult` of a spatial scene: ``qdd`` has ``n_v`` entries (the
    base twist's rate in the base frame, then the joints'), ``lam`` the
    ``3 n_l + 1`` rows' forces (contact, wheels, ground, pitch), ``normal`` the links' normal
    forces (N, up), ``pitch_moment`` the pitch rows' (N m, about each link's horizontal
    normal at its COM),
    ``wheel_state`` the ``n_l`` wheels'. A sample the solve cannot answer exactly is NaN with
    ``singular`` set and its ``reason``."""

    __slots__ = ()

    def _n_links(self):
        return (self._cols.slices["lam"].stop - self._cols.slices["lam"].start - 1) // 3

    @property
    def wheel_state(self) -> np.ndarray:
        nl = self._n_links()
        st = self._raw[..., self._cols.state + 1: self._cols.state + 1 + nl]
        return WHEEL_STATE_NAMES[np.nan_to_num(st).astype(np.intp)]

    @property
    def normal(self) -> np.ndarray:
        nl = self._n_links()
        return self.lam[..., 1 + nl:1 + 2 * nl]

    @property
    def pitch_moment(self) -> np.ndarray:
        """The ground's moment on each link about its COM (N m), about the horizontal axis
        ``e_z x x_i`` (the link's left): ``-d_i`` times the pitch row's force, ``d_i`` the
        Gauss points' offset (the row's force is the front point's force less the rear's)."""
        nl = self._n_links()
        return -self._cols.support_offset * self.lam[..., 1 + 2 * nl:]

    @property
    def reason(self):
        r = self._raw
        def flag(c):
            return "" if c == STATUS_EXACT else NOT_ON_GROUND if c == STATUS_NOT_ON_GROUND \
                else NO_ANSWER
        if r.ndim == 1:
            return flag(r[self._cols.status])
        return np.array([flag(c) for c in r[:, self._cols.status]], dtype=object)

    def __getitem__(self, i) -> SpatialForwardResult:
        if self._raw.ndim != 2:
            raise TypeError("a one-sample ForwardResult cannot be indexed")
        return SpatialForwardResult(self._raw[i], self._cols)

    def to_dict(self) -> dict:
        """JSON-ready (strict JSON: a NaN of an unanswered sample is ``null``)."""
        def clean(x):
            a = np.asarray(x)
            if a.dtype.kind == "f":
                return np.where(np.isfinite(a), a, None).tolist()
            return a.tolist()
        return {k: clean(getattr(self, k)) for k in _ORDER}


class SpatialSceneModel:
    """The compiled model of a :class:`SpatialScene`: :meth:`forward`, and the chain's own
    functions through ``model.robot_model`` (a :class:`SpatialModel`)."""

    def __init__(self, scene: SpatialScene, *, backend: str = "compiled", progress=None):
        if not isinstance(scene, SpatialScene):
            raise InputError(f"scene must be a snakecg.SpatialScene, got {type(scene).__name__}")
        self.scene = scene
        self.robot_model = SpatialModel(scene.robot, backend=backend, progress=progress)
        rm = self.robot_model
        contact = getattr(rm.backend, "contact", None)
        self.backend = contact(progress) if contact is not None else rm.backend
        self.core = getattr(self.backend, "core", None)
        if self.core is None:
            raise InputError("the spatial analysis runs in the compiled runtime core; this "
                             "model has CasADi's in-process backend (load it with a C "
                             "compiler, CC)")
        nl = rm.n_links
        self.n_joints, self.n_links, self.nq, self.nv = rm.n_joints, nl, rm.nq, rm.nv
        self.n_coordinates = self.nv
        self.n_constraints = nc = 3 * nl + 1
        layout = self.core.layout
        self.columns = _SpatialColumns(layout)
        self.columns.support_offset = support_offsets(scene.robot)
        onehot = np.zeros(nl)
        onehot[scene.contact_link - 1] = 1.0
        present = np.zeros(nc)
        present[0] = 1.0
        friction, normal_row = np.zeros(nc), np.zeros(nc)
        bounds = np.full(nc, np.inf)
        if scene.has_wheels:
            for i in scene.wheel_links:
                present[i] = 1.0
                if scene.scenario == "wheels":
                    friction[i], normal_row[i] = scene.mu, nl + i
        present[nl + 1:] = 2.0  # SUPPORT: held always, may depend on the others
        in_norm = np.r_[np.ones(nl + 1), np.zeros(2 * nl)]
        self.present, self.bounds = present, bounds
        parts = {"K": rm.parameters, "contact_link": onehot, "side": [scene.side_sign],
                 "object_mass": [scene.object_mass], "object_inertia": [scene.object_inertia],
                 "wheel_offset": scene.wheel_offset, "contact_offset": [scene.contact_offset],
                 "object_distance": [scene.object_distance], "present": present,
                 "bounds": bounds, "friction": friction, "normal_row": normal_row,
                 "in_norm": in_norm}
        #: The generated contact_system's scene inputs (snakecg.spatial.maps).
        self.scene_inputs = {k: np.ravel(np.asarray(parts[k], dtype=float))
                             for k in ("K", "contact_link", "side", "object_mass",
                                       "object_inertia", "wheel_offset", "contact_offset",
                                       "object_distance")}
        self._scene_vector = np.concatenate([np.ravel(np.asarray(parts[k], dtype=float))
                                             for k, _ in layout.scene_fields()])
        self.scene_address = self._scene_vector.ctypes.data
        self.max_iter = default_max_iter(nc)
        self.zero_inputs = {"v": np.zeros((1, self.nv)), "v_obj": np.zeros((1, 3)),
                            "f_obj": np.zeros((1, 3))}

    def forward(self, q, tau, *, v=None, v_obj=None, f_obj=None, q_obj=None, rho=None,
                max_iter=None) -> SpatialForwardResult:
        """Accelerations, constraint forces, active set, the four metrics and sr of one
        sample (``q`` of shape ``(n_q,)``) or a batch (``(N, n_q)``); ``tau`` ``(n_a,)`` or
        ``(N, n_a)``; optional velocities ``v`` (n_v) and ``v_obj`` (3), the object's wrench
        ``f_obj`` (3), and its pose ``q_obj = (x, y, psi)`` with the contact point ``rho``
        in its frame (both or neither; neither: the object is placed at the scene's contact).
        One call of the compiled solve for the batch."""
        if max_iter is not None and (isinstance(max_iter, bool) or not isinstance(
                max_iter, (int, np.integer)) or max_iter < 1):
            raise InputError(f"max_iter must be an integer >= 1 or None, got {max_iter!r}")
        named = {"q": (q, self.nq, (f" = (joints + 7,) for a {self.n_joints}-joint spatial "
                                    "robot (x, y, z, qx, qy, qz, qw, joint angles)")),
                 "tau": (tau, self.n_joints, f" (one torque per joint, n_a = {self.n_joints})"),
                 "v": (v, self.nv, " = (joints + 6,) (base twist in the base frame, rates)"),
                 "v_obj": (v_obj, 3, ""), "f_obj": (f_obj, 3, ""), "q_obj": (q_obj, 3, ""),
                 "rho": (rho, 2, "")}
        parts, problems = {}, []
        for name, (val, size, what) in named.items():
            if val is None:
                continue
            try:
                parts[name] = as_batch(name, val, size, what=what)
            except InputError as exc:
                problems.append(str(exc))
        if (q_obj is None) != (rho is None):
            problems.append("q_obj and rho go together: give both or neither")
        if "q" in parts:
            quat = parts["q"][0][:, 3:7]
            bad = np.abs(np.linalg.norm(quat, axis=1) - 1.0) > 1e-9
            if np.any(bad):
                problems.append(f"q's quaternion (entries 3..6) must have unit norm (to 1e-9); "
                                f"sample {int(np.flatnonzero(bad)[0])} has "
                                f"{np.linalg.norm(quat[bad][0]):.12g}")
        if problems:
            raise InputError("; ".join(problems))
        n = broadcast_batches(**parts)
        batched = any(b for _, b in parts.values())
        check_input_range(parts)
        arrays = {k: a for k, (a, _) in parts.items()}
        cols = self.columns
        check_batch_memory("forward", n, 8 * cols.width, what="results")
        iters = self.max_iter if max_iter is None else int(max_iter)
        raw = np.empty((n, cols.width))
        status = _core_batch(self, self.core, arrays, n, iters, raw)
        if status == -1:
            raise MemoryError("snakecg: the runtime core could not allocate its work arrays")
        if status != 0:
            raise InputError(f"forward: an input of sample {-2 - status} is not finite or "
                             f"beyond the force limit")
        lifted = ~lying_flat(self, arrays["q"])  # (the rows hold the ground's plane only)
        if np.any(lifted):
            raw[np.broadcast_to(lifted, (n,)), cols.status] = STATUS_NOT_ON_GROUND
        bad = raw[:, cols.status] != STATUS_EXACT
        if np.any(bad):  # no second solver: NaN with the flag and the reason
            keep = raw[bad][:, [cols.status]]
            raw[bad] = math.nan
            raw[np.ix_(bad, [cols.status])] = keep
            raw[np.ix_(bad, [cols.singular])] = 1.0
            raw[np.ix_(bad, range(cols.slices["tau"].start, cols.slices["tau"].stop))] = \
                np.broadcast_to(arrays["tau"], (n, self.n_joints))[bad]
        return SpatialForwardResult(raw if batched else raw[0], cols)

    def configurations(self, q):
        """``(q as (N, n_q), batched)``, checked (a unit quaternion in entries 3..6)."""
        qa, batched = as_batch("q", q, self.nq, what=(
            f" = (joints + 7,) for a {self.n_joints}-joint spatial robot (x, y, z, qx, qy, "
            "qz, qw, joint angles)"))
        bad = np.abs(np.linalg.norm(qa[:, 3:7], axis=1) - 1.0) > 1e-9
        if np.any(bad):
            raise InputError(f"q's quaternion (entries 3..6) must have unit norm (to 1e-9); "
                             f"sample {int(np.flatnonzero(bad)[0])} is not")
        return qa, batched

    def extremes(self, q, **kwargs):
        """Best and worst ``norm_a_obj``, ``norm_qdd``, ``norm_lambda`` and ``sr`` over the
        input ellipsoid of eq. (31) with the spatial ``M``; see
        :func:`snakecg.spatial.queries.extremes`."""
        from .queries import extremes

        return extremes(self, q, **kwargs)

    def optimize(self, q, objective="max_sr", **kwargs):
        """The optimal joint torque for a task at configuration ``q`` (at rest); see
        :func:`snakecg.spatial.optimal.optimize`."""
        from .optimal import optimize

        return optimize(self, q, objective, **kwargs)

    def __repr__(self) -> str:
        return f"<SpatialSceneModel of {self.scene!r}>"
