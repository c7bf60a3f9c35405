"""The compiled model of a robot alone (:class:`RobotModel`): inertia, Jacobians, poses and
bias forces of the generated functions, one compiled call per batch; and the loading of a
joint count's generated model (its backend, cached per process). The facade
(:mod:`snakecg.model`) and the scene models build on it."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from . import artifacts, kernels
from ._inputs import as_batch, broadcast_batches, check_batch_memory
from .errors import InputError
from .native import ManifestMismatch, load_backend
from .robot import Robot

__all__ = ["RobotModel"]

_BACKENDS: dict[tuple[int, str], tuple[object, dict, Path]] = {}


def _backend(n_joints: int, prefer: str, progress=None):
    key = (n_joints, prefer)
    if key not in _BACKENDS:
        folder, manifest = artifacts.model_dir(n_joints, progress=progress)
        try:
            backend = load_backend(folder, manifest, prefer=prefer, progress=progress)
        except ManifestMismatch as exc:  # an edited manifest: the model generated again
            folder, manifest = artifacts.regenerate(n_joints, folder, exc, progress=progress)
            backend = load_backend(folder, manifest, prefer=prefer, progress=progress)
        _BACKENDS[key] = (backend, manifest, folder)
    return _BACKENDS[key]


def _check_load_args(backend, progress) -> None:
    """``backend`` and ``progress`` of :func:`load`, checked before any generation."""
    if not isinstance(backend, str) or backend not in ("compiled", "casadi"):
        raise InputError(f"backend must be 'compiled' or 'casadi', got {backend!r:.60}")
    if progress is not None and progress is not False and not callable(progress):
        raise InputError(f"progress must be None, False or a callable taking a message, got "
                         f"{type(progress).__name__}")


class RobotModel:
    """A snake robot's compiled model: ``mass_matrix``, ``link_jacobians``, ``link_poses``..."""

    def __init__(self, robot: Robot, *, backend: str = "compiled", progress=None):
        if not isinstance(robot, Robot):
            raise InputError(f"robot must be a snakecg.Robot, got {type(robot).__name__}")
        _check_load_args(backend, progress)
        self.robot = robot
        self.backend, self.manifest, self.folder = _backend(robot.joints, backend, progress)
        self.n_joints = robot.joints
        self.n_links = robot.n_links
        self.n_coordinates = robot.n_coordinates
        self.n_constraints = robot.n_links + 1
        K = kernels.call(self.backend, "derived_parameters", 1, link_mass=robot.mass,
                         link_length=robot.length, link_inertia=robot.inertia,
                         link_com=robot.com)["K"]
        self.parameters = np.ascontiguousarray(K[0, :, 0])
        """The parameter vector ``K`` (raw link parameters, then derived constants)."""

    @property
    def backend_kind(self) -> str:
        return self.backend.kind

    # helpers ---------------------------------------------------------------------------
    def configurations(self, q, name: str = "q") -> tuple[np.ndarray, bool]:
        """``q`` checked (:class:`InputError` naming ``name`` otherwise) as a C-contiguous
        float64 ``(N, n_s)`` batch, and whether it was one (``(n_s,)`` gives ``N = 1``)."""
        return as_batch(name, q, self.n_coordinates,
                        what=f" = (n_joints + 3,) for a {self.n_joints}-joint robot")

    _q = configurations

    def _call(self, fname: str, n: int, inputs: list[np.ndarray]):
        return self.backend(fname, n, inputs)

    def _named(self, fname: str, n: int, **inputs):
        """Generated function ``fname`` with its inputs and outputs by name."""
        return kernels.call(self.backend, fname, n, **inputs)

    @staticmethod
    def _arg(arr: np.ndarray, n: int) -> np.ndarray:
        """Batch argument: 1-D (broadcast) when one sample serves all, else ``(n, size)``."""
        return arr[0] if arr.shape[0] == 1 and n >= 1 else arr

    def _check_memory(self, method: str, n: int, fnames, extra: int = 0) -> None:
        """Refuse a batch of ``n`` rows whose results would exceed the memory limit
        (``SNAKECG_MAX_MEMORY``), before any work: per row, the outputs of the generated
        functions ``fnames`` twice (the driver's buffer and the arrays returned) and
        ``extra`` more doubles."""
        if n > 1:
            sig = self.backend.signatures
            per_row = 16 * sum(r * c for f in fnames for r, c in sig[f].out_shapes)
            check_batch_memory(method, n, per_row + 8 * extra, what="results")

    # public ----------------------------------------------------------------------------
    def mass_matrix(self, q) -> np.ndarray:
        """Inertia matrix ``M_s(q)`` of eq. (4): ``(n_s, n_s)``, or ``(N, n_s, n_s)``."""
        qa, batched = self._q(q)
        n = qa.shape[0]
        self._check_memory("mass_matrix", n, ["mass_matrix"])
        M = self._named("mass_matrix", n, q=self._arg(qa, n), K=self.parameters)["M"]
        return M if batched else M[0]

    def link_jacobians(self, q) -> np.ndarray:
        """Link Jacobians ``J_i`` of eq. (3): ``(n_l, 3, n_s)``, or ``(N, n_l, 3, n_s)``.

        ``J_i qdot`` is the twist ``(v_x, v_y, omega)`` of the COM of link ``i + 1``.
        """
        qa, batched = self._q(q)
        n = qa.shape[0]
        self._check_memory("link_jacobians", n, ["link_jacobians"])
        J = self._named("link_jacobians", n, q=self._arg(qa, n), K=self.parameters)["J"]
        J = J.reshape(n, self.n_links, 3, self.n_coordinates)
        return J if batched else J[0]

    def link_poses(self, q) -> np.ndarray:
        """``(x_i, y_i, phi_i)`` of every link COM: ``(n_l, 3)``, or ``(N, n_l, 3)``."""
        qa, batched = self._q(q)
        n = qa.shape[0]
        self._check_memory("link_poses", n, ["link_poses"], extra=3 * self.n_links)
        P = self._named("link_poses", n, q=self._arg(qa, n), K=self.parameters)["poses"]
        P = np.ascontiguousarray(P.transpose(0, 2, 1))
        return P if batched else P[0]

    def bias_forces(self, q, v) -> np.ndarray:
        """Coriolis and centripetal terms ``h_s(q, qdot)`` of eq. (4): ``(n_s,)`` or ``(N, n_s)``."""
        qa, bq = self._q(q)
        va, bv = self._q(v, "v")
        n = broadcast_batches(q=(qa, bq), v=(va, bv))
        self._check_memory("bias_forces", n, ["bias_forces"], extra=2 * self.n_coordinates)
        h = self._named("bias_forces", n, q=self._arg(qa, n) if not bq else qa,
                        v=self._arg(va, n) if not bv else va, K=self.parameters)["h"]
        h = h[:, :, 0]
        return h if (bq or bv) else h[0]

    def com(self, q) -> np.ndarray:
        """The robot's centre of mass ``(x, y)``: ``(2,)`` or ``(N, 2)``."""
        qa, _ = self._q(q)
        self._check_memory("com", qa.shape[0], ["link_poses"], extra=3 * self.n_links + 4)
        P = self.link_poses(q)
        m = np.asarray(self.robot.mass)
        return np.einsum("...ik,i->...k", P[..., :2], m) / m.sum()

    # CasADi functions as public API (snakecg.casadi_api, docs/how-to/casadi.md) -------------------
    def casadi_function(self, name: str, *, bind: bool = False, **inputs):
        """The generated :class:`casadi.Function` ``name`` (e.g. ``"constrained_dynamics"``).

        ``bind=True``: the function of ``q``, ``tau``, ... only, with
        :meth:`function_inputs` embedded and the object placed from ``q``; keyword
        ``inputs`` override embedded values (``None`` keeps one an input). See
        :func:`snakecg.casadi_api.casadi_function`.
        """
        from .casadi_api import casadi_function

        return casadi_function(self, name, bind=bind, **inputs)

    def function_inputs(self, name: str, q=None) -> dict:
        """Every input of the generated function ``name`` that the robot or scene fixes
        (``K``, contact link, side, object mass, ..., the at-rest state and the first active
        set), by name; with ``q`` also the object's placement ``q_obj``, ``rho``. See
        :func:`snakecg.casadi_api.function_inputs`."""
        from .casadi_api import function_inputs

        return function_inputs(self, name, q)

    def __repr__(self) -> str:
        what = getattr(self, "scene", None) or self.robot
        return f"<{type(self).__name__} of {what!r}, backend {self.backend_kind!r}>"
