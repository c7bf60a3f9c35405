"""The compiled model of a :class:`~snakecg.SpatialRobot`: numbers in, numbers out.

``snakecg.load(spatial_robot)`` gives a :class:`SpatialModel`. Every method takes one sample
(``q`` of shape ``(n_q,)``) or a batch (``(N, n_q)``) and evaluates the batch in one compiled
call. Conventions (Pinocchio's free flyer): ``q = (x, y, z, qx, qy, qz, qw, q_1..q_na)``,
``v = (v_base, w_base, qd_1..qd_na)`` with the base twist in the base frame; Jacobians map
``v`` to world-axes velocities (``LOCAL_WORLD_ALIGNED``: the velocity of a frame's origin and
its angular velocity). Nothing here imports SymPy.
"""

from __future__ import annotations

import numpy as np

from .. import kernels
from .._inputs import as_batch, broadcast_batches
from ..errors import InputError
from .artifacts import load_spatial_backend, spatial_model_dir
from .robot import SpatialRobot

__all__ = ["SpatialModel"]

_BACKENDS: dict = {}


def _backend(n_joints: int, prefer: str, progress=None):
    key = (n_joints, prefer)
    if key not in _BACKENDS:
        folder, manifest = spatial_model_dir(n_joints, progress=progress)
        _BACKENDS[key] = (load_spatial_backend(folder, manifest, prefer=prefer,
                                               progress=progress), manifest, folder)
    return _BACKENDS[key]


class SpatialModel:
    """A spatial snake's compiled model: ``mass_matrix``, ``link_jacobians``,
    ``point_jacobian``, ``bias_forces``, ``link_poses``, the ground, wheel and contact rows."""

    def __init__(self, robot: SpatialRobot, *, backend: str = "compiled", progress=None):
        if not isinstance(robot, SpatialRobot):
            raise InputError(f"robot must be a snakecg.SpatialRobot, got {type(robot).__name__}")
        self.robot = robot
        self.backend, self.manifest, self.folder = _backend(robot.joints, backend, progress)
        self.n_joints, self.n_links = robot.joints, robot.n_links
        self.nq, self.nv = robot.nq, robot.nv
        K = kernels.call(self.backend, "derived_parameters", 1, **robot.parameters())["K"]
        self.parameters = np.ascontiguousarray(K[0, :, 0])
        """The parameter vector ``K`` (raw parameters, then each link's axis frame)."""

    @property
    def backend_kind(self) -> str:
        return self.backend.kind

    # arguments -----------------------------------------------------------------------------
    def configurations(self, q, name: str = "q"):
        return as_batch(name, q, self.nq, what=f" = (joints + 7,) for a {self.n_joints}-joint "
                        "spatial robot (x, y, z, qx, qy, qz, qw, joint angles)")

    def _velocities(self, v):
        return as_batch("v", v, self.nv, what=f" = (joints + 6,) for a {self.n_joints}-joint "
                        "spatial robot (base twist in the base frame, joint rates)")

    def _link(self, link) -> np.ndarray:
        if isinstance(link, (bool, np.bool_)) or not isinstance(link, (int, np.integer)) \
                or not 1 <= link <= self.n_links:
            raise InputError(f"link must be an integer from 1 (the base) to {self.n_links}, "
                             f"got {link!r:.60}")
        onehot = np.zeros(self.n_links)
        onehot[int(link) - 1] = 1.0
        return onehot

    def _points(self, name, value, default):
        if value is None:
            return np.ascontiguousarray(default, dtype=float).ravel()
        a = np.asarray(value, dtype=float)
        if a.shape == (3,):
            a = np.tile(a, (self.n_links, 1))
        if a.shape != (self.n_links, 3) or not np.all(np.isfinite(a)):
            raise InputError(f"{name} must be finite with shape (3,) or ({self.n_links}, 3) "
                             f"(one point per link, in its frame), got shape {a.shape}")
        return np.ascontiguousarray(a.ravel())

    @staticmethod
    def _arg(a: np.ndarray, batched: bool) -> np.ndarray:
        return a if batched else a[0]

    def _qv(self, q, v):
        qa, bq = self.configurations(q)
        va, bv = self._velocities(v)
        n = broadcast_batches(q=(qa, bq), v=(va, bv))
        return n, self._arg(qa, bq), self._arg(va, bv), bq or bv

    def _call(self, fname: str, n: int, **inputs):
        return kernels.call(self.backend, fname, n, K=self.parameters, **inputs)

    # kinematics -----------------------------------------------------------------------------
    def link_poses(self, q) -> np.ndarray:
        """Each link frame in the world as a homogeneous transform: ``(n_l, 4, 4)`` or
        ``(N, n_l, 4, 4)``."""
        qa, batched = self.configurations(q)
        n = qa.shape[0]
        o = self._call("link_poses", n, q=self._arg(qa, batched))
        T = np.zeros((n, self.n_links, 4, 4))
        T[:, :, :3, 3] = o["position"].transpose(0, 2, 1)
        T[:, :, :3, :3] = o["rotation"].reshape(n, 3, self.n_links, 3).transpose(0, 2, 1, 3)
        T[:, :, 3, 3] = 1.0
        return T if batched else T[0]

    def link_jacobians(self, q) -> np.ndarray:
        """``(n_l, 6, n_v)`` or ``(N, n_l, 6, n_v)``: rows (linear velocity of the link
        frame's origin, angular velocity), world axes."""
        qa, batched = self.configurations(q)
        n = qa.shape[0]
        J = self._call("link_jacobians", n, q=self._arg(qa, batched))["J"]
        J = J.reshape(n, self.n_links, 6, self.nv)
        return J if batched else J[0]

    def link_bias_accelerations(self, q, v) -> np.ndarray:
        """``Jdot v`` of every link frame: ``(n_l, 6)`` or ``(N, n_l, 6)``."""
        n, qa, va, batched = self._qv(q, v)
        b = self._call("link_bias_accelerations", n, q=qa, v=va)["bias"]
        b = np.ascontiguousarray(b.transpose(0, 2, 1))
        return b if batched else b[0]

    def point_position(self, q, link: int, point) -> np.ndarray:
        """World position of ``point`` (in link ``link``'s frame, links counted from 1)."""
        return self._point("position", q, link, point)

    def point_jacobian(self, q, link: int, point) -> np.ndarray:
        """``(3, n_v)`` or ``(N, 3, n_v)``: ``v`` to the world velocity of ``point`` (given in
        the frame of link ``link``, counted from 1 = the base)."""
        return self._point("J", q, link, point)

    def _point(self, out, q, link, point):
        qa, batched = self.configurations(q)
        n = qa.shape[0]
        r = self._points("point", point, None)[:3] if np.shape(point) == (3,) else None
        if r is None:
            raise InputError(f"point must be 3 finite numbers, got {point!r:.60}")
        o = self._call("point_jacobian", n, q=self._arg(qa, batched), link=self._link(link),
                       point=r)[out]
        o = o[:, :, 0] if out == "position" else o
        return o if batched else o[0]

    def point_bias_acceleration(self, q, v, link: int, point) -> np.ndarray:
        """``Jdot v`` of a point of a link (world axes): ``(3,)`` or ``(N, 3)``."""
        n, qa, va, batched = self._qv(q, v)
        r = np.asarray(point, dtype=float)
        if r.shape != (3,) or not np.all(np.isfinite(r)):
            raise InputError(f"point must be 3 finite numbers, got {point!r:.60}")
        b = self._call("point_bias_acceleration", n, q=qa, v=va, link=self._link(link),
                       point=r)["bias"][:, :, 0]
        return b if batched else b[0]

    def kinematic_map(self, q) -> np.ndarray:
        """``G(q)`` with ``qdot = G v``: ``(n_q, n_v)`` or ``(N, n_q, n_v)``."""
        qa, batched = self.configurations(q)
        G = kernels.call(self.backend, "kinematic_map", qa.shape[0], q=self._arg(qa, batched))["G"]
        return G if batched else G[0]

    # dynamics -------------------------------------------------------------------------------
    def mass_matrix(self, q) -> np.ndarray:
        """Inertia matrix ``M(q)``: ``(n_v, n_v)`` or ``(N, n_v, n_v)``."""
        qa, batched = self.configurations(q)
        M = self._call("mass_matrix", qa.shape[0], q=self._arg(qa, batched))["M"]
        return M if batched else M[0]

    def bias_forces(self, q, v) -> np.ndarray:
        """``h(q, v)`` (Coriolis, centrifugal and gravity; ``M vdot + h = S^T tau``):
        ``(n_v,)`` or ``(N, n_v)``."""
        n, qa, va, batched = self._qv(q, v)
        h = self._call("bias_forces", n, q=qa, v=va)["h"][:, :, 0]
        return h if batched else h[0]

    # constraint rows ------------------------------------------------------------------------
    def ground_rows(self, q, v, support_points=None) -> dict[str, np.ndarray]:
        """Vertical rows at a support point per link (default: each COM): ``A`` ``(n_l, n_v)``,
        ``adot_v`` and ``height`` ``(n_l,)`` (batched with a leading ``N``)."""
        n, qa, va, batched = self._qv(q, v)
        pts = self._points("support_points", support_points, self.robot.com)
        o = self._call("ground_rows", n, q=qa, v=va, support_points=pts)
        out = {"A": o["A"], "adot_v": o["adot_v"][:, :, 0], "height": o["height"][:, :, 0]}
        return out if batched else {k: a[0] for k, a in out.items()}

    def wheel_rows(self, q, v, wheel_points=None, wheel_heading=(1.0, 0.0, 0.0)):
        """Lateral wheel rows (default: a wheel at each COM rolling along the link's x axis):
        ``A`` ``(n_l, n_v)`` and ``adot_v`` ``(n_l,)``."""
        n, qa, va, batched = self._qv(q, v)
        pts = self._points("wheel_points", wheel_points, self.robot.com)
        heads = self._points("wheel_heading", wheel_heading, None)
        o = self._call("wheel_rows", n, q=qa, v=va, wheel_points=pts, wheel_heading=heads)
        out = {"A": o["A"], "adot_v": o["adot_v"][:, :, 0]}
        return out if batched else {k: a[0] for k, a in out.items()}

    # CasADi -----------------------------------------------------------------------------------
    def casadi_function(self, name: str, *, bind: bool = False):
        """The generated :class:`casadi.Function` ``name`` (inputs and outputs by name, as in
        the manifest); ``bind=True`` embeds this robot's ``K``."""
        from ..casadi_api import _backend as casadi_backend

        names = [f["name"] for f in self.manifest["functions"]]
        if not isinstance(name, str) or name not in names:
            raise InputError(f"name must be the name of a generated function, one of "
                             f"{', '.join(names)}; got {name!r:.60}")
        f = casadi_backend(self).casadi_function(name)
        if not bind or "K" not in f.name_in():
            return f
        import casadi as ca

        args = [ca.MX.sym(f.name_in(k), f.sparsity_in(k)) for k in range(f.n_in())]
        k = f.name_in().index("K")
        call = list(args)
        call[k] = ca.DM(self.parameters)
        keep = [a for i, a in enumerate(args) if i != k]
        return ca.Function(f.name(), keep, f.call(call),
                           [n for i, n in enumerate(f.name_in()) if i != k], f.name_out())

    def __repr__(self) -> str:
        return f"<SpatialModel of {self.robot!r}, backend {self.backend_kind!r}>"

    def __getstate__(self):
        raise TypeError("a loaded model holds compiled code and cannot be pickled; pickle its "
                        "SpatialRobot and call snakecg.load(robot) where it is needed")
