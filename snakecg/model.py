"""Loaded models: immutable parameters and compiled functions; numbers in, numbers out.

``snakecg.load(robot)`` gives a :class:`RobotModel` (inertia, Jacobians, poses);
``snakecg.load(scene)`` a :class:`SceneModel`, which adds the coupled snake + object analysis
of Reyes & Ma 2017. Every method takes one sample (``q`` of shape ``(n_s,)``) or a batch
(``(N, n_s)``) and evaluates the whole batch in one compiled call; nothing here imports
SymPy or Jinja2.
"""

from __future__ import annotations

from pathlib import Path
from types import MappingProxyType

import numpy as np

from . import artifacts, kernels
from . import maps as _maps_mod
from ._inputs import (
    as_batch,
    broadcast_batches,
    check_batch_memory,
)
from .engine import Data, Layout
from .errors import InputError
from .kinds import SCENE_MODEL
from .forward import ForwardResult, _Columns, forward, forward_one
from .native import ManifestMismatch, load_backend
from .robot import Robot, Scene
from .solver import default_max_iter

__all__ = ["load", "RobotModel", "SceneModel", "ForwardResult"]

#: Rows of one ``extremes`` call on a large batch with bounded wheels (each row needs tens of
#: kB while it runs).
EXTREMES_CHUNK_ROWS = 2048
#: Rows of one ``extremes`` call in the closed-form scenarios (frictionless, ideal wheels:
#: about 1 kB per row at its peak), so that case study 2's 21,952 configurations are one
#: call: each call has a fixed cost (the threads' dispatch, a few dozen NumPy operations).
CLOSED_FORM_CHUNK_ROWS = 32768

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


def load(obj, *, backend: str = "compiled", progress=None):
    """Load the model of a :class:`~snakecg.Robot`, a :class:`~snakecg.Scene`, a
    :class:`~snakecg.SpatialRobot` (a :class:`~snakecg.spatial.model.SpatialModel`) or a
    :class:`~snakecg.SpatialScene` (a :class:`~snakecg.spatial.analysis.SpatialSceneModel`).

    The generated model for the joint count is taken from the package or the user cache
    (generated once if missing), compiled once into a cached shared library and shared by
    every robot with that joint count. ``backend="casadi"`` evaluates with CasADi's
    in-process virtual machine instead of the compiled C. ``progress``: ``None`` prints a
    line on standard error when a generation or compilation starts and one when it ends, with
    its duration, whatever standard error is (a terminal, a pipe, a log, a notebook; silenced
    by ``SNAKECG_PROGRESS=0``, see :mod:`snakecg.progress`), ``False`` never, or a callable
    taking each step's message.
    """
    _check_load_args(backend, progress)
    from .progress import resolve  # None: model builds reported on standard error

    progress = resolve(progress)
    if isinstance(obj, Scene):
        return SceneModel(obj, backend=backend, progress=progress)
    if isinstance(obj, Robot):
        return RobotModel(obj, backend=backend, progress=progress)
    from .spatial import SpatialRobot, SpatialScene

    if isinstance(obj, SpatialRobot):  # a 3-D chain: snakecg.spatial's own model
        from .spatial.model import SpatialModel

        return SpatialModel(obj, backend=backend, progress=progress)
    if isinstance(obj, SpatialScene):  # the paper's analysis in 3-D
        from .spatial.analysis import SpatialSceneModel

        return SpatialSceneModel(obj, backend=backend, progress=progress)
    raise InputError(f"load() takes a snakecg.Robot, snakecg.Scene, snakecg.SpatialRobot or "
                     f"snakecg.SpatialScene, got {type(obj).__name__}")


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


_F64 = np.dtype(np.float64)
#: snakecg.optimize's entry point and argument screen, imported on first use
_LAZY: dict = {}


def _plain(x, size: int) -> bool:
    """A list or tuple of ``size`` Python floats or ints (the one-sample fast path)."""
    if len(x) != size:
        return False
    for e in x:
        t = type(e)
        if t is not float and t is not int:
            return False
    return True


class SceneModel(RobotModel):
    """The coupled snake + object of a :class:`~snakecg.Scene`: forward analysis, maps,
    extremes over the input region, torque optimisation and simulation."""

    #: What the feature packages check their ``model`` argument by (:mod:`snakecg.kinds`).
    model_kind = SCENE_MODEL

    def __init__(self, scene: Scene, *, backend: str = "compiled", progress=None):
        if not isinstance(scene, Scene):
            raise InputError(f"scene must be a snakecg.Scene, got {type(scene).__name__}")
        super().__init__(scene.robot, backend=backend, progress=progress)
        self.scene = scene
        nl = self.n_links
        onehot = np.zeros(nl)
        onehot[scene.contact_link - 1] = 1.0
        self._contact_link = onehot
        self._side = np.array([scene.side_sign])
        self._object_mass = np.array([scene.object_mass])
        self._object_inertia = np.array([scene.object_inertia])
        self._wheel_offset = np.asarray(scene.wheel_offset, dtype=float)
        present = np.zeros(self.n_constraints, dtype=bool)
        present[0] = True
        if scene.has_wheels:
            for i in scene.wheel_links:
                present[i] = True
        self.present = present
        bounds = np.full(self.n_constraints, np.inf)
        if scene.scenario == "wheels":
            bounds[1:] = np.asarray(scene.wheel_bounds())
        self.bounds = bounds
        # the runtime core: the scene's constants in one vector, the output columns, a
        # default workspace (snakecg.engine.data.Data)
        self.core = getattr(self.backend, "core", None)
        layout = self.core.layout if self.core is not None else Layout.of(self.manifest)
        self.columns = _Columns(layout)
        parts = {"K": self.parameters, "contact_link": onehot, "side": self._side,
                 "object_mass": self._object_mass, "object_inertia": self._object_inertia,
                 "wheel_offset": self._wheel_offset, "contact_offset": [scene.contact_offset],
                 "object_distance": [scene.object_distance],
                 "present": present.astype(float), "bounds": bounds}
        self._scene_vector = np.concatenate([np.ravel(np.asarray(parts[k], dtype=float))
                                             for k, _ in layout.scene_fields()])
        self.scene_address = self._scene_vector.ctypes.data
        self.max_iter = default_max_iter(self.n_constraints)
        self.zero_inputs = {"v": np.zeros((1, self.n_coordinates)), "v_obj": np.zeros((1, 3)),
                            "f_obj": np.zeros((1, 3))}
        self._shape_q, self._shape_tau = (self.n_coordinates,), (self.n_joints,)
        self._data = self.create_data().bind(self)
        self.scene_inputs = MappingProxyType({
            "K": self.parameters, "contact_link": onehot, "side": self._side,
            "object_mass": self._object_mass, "object_inertia": self._object_inertia,
            "wheel_offset": self._wheel_offset,
            "contact_offset": np.array([float(scene.contact_offset)]),
            "object_distance": np.array([float(scene.object_distance)])})
        """The inputs of the generated functions that the scene fixes, by name (read-only):
        ``K``, ``contact_link`` (one-hot), ``side``, ``object_mass``, ``object_inertia``,
        ``wheel_offset``, ``contact_offset``, ``object_distance``."""

    # placement ----------------------------------------------------------------------------
    def place_object(self, q):
        """Object pose ``(x_o, y_o, psi)``, contact point in the object frame ``rho`` and the
        world contact point for the scene's contact (shapes ``(3,)``, ``(2,)``, ``(2,)`` or
        batched)."""
        qa, batched = self._q(q)
        n = qa.shape[0]
        self._check_memory("place_object", n, ["place_object"])
        q_obj, rho, P = self._place(qa, n)
        if batched:
            return q_obj, rho, P
        return q_obj[0], rho[0], P[0]

    def place(self, qa, n: int | None = None):
        """:meth:`place_object` of a checked batch ``qa`` (``(N, n_s)``, from
        :meth:`configurations`): ``(q_obj, rho, contact_point)`` of shapes ``(N, 3)``,
        ``(N, 2)``, ``(N, 2)``."""
        return self._place(qa, qa.shape[0] if n is None else n)

    def _place(self, qa, n):
        o = self._named("place_object", n, q=self._arg(qa, n), K=self.parameters,
                        contact_link=self._contact_link,
                        contact_offset=[self.scene.contact_offset],
                        object_distance=[self.scene.object_distance], side=self._side)
        return o["q_obj"][:, :, 0], o["rho"][:, :, 0], o["contact_point"][:, :, 0]

    # forward -------------------------------------------------------------------------------
    def data(self) -> Data:
        """The model's own :class:`~snakecg.engine.data.Data` (every workspace of its steps;
        used by one caller at a time: a second thread gets a fresh one, see
        :meth:`create_data`)."""
        return self._data

    def create_data(self) -> Data:
        """A new :class:`~snakecg.engine.data.Data` for this model (Pinocchio's rule: one per
        thread): give one to each thread that calls :meth:`forward` on one sample at a high
        rate (``data=``)."""
        return Data(self.core.layout if self.core is not None else Layout.of(self.manifest))

    def __getstate__(self):
        raise TypeError("a loaded model holds compiled code and cannot be pickled; pickle its "
                        "Scene and call snakecg.load(scene) where it is needed")

    def forward(self, q, tau, *, v=None, v_obj=None, f_obj=None, q_obj=None, rho=None,
                max_iter: int | None = None, data: Data | None = None,
                out: ForwardResult | None = None) -> ForwardResult:
        """Accelerations, constraint forces, active set and norms (eqs. 12-30).

        ``q`` ``(n_s,)`` or ``(N, n_s)``; ``tau`` ``(n_a,)`` or ``(N, n_a)`` (one broadcasts
        against the other). Optional: snake velocities ``v``, object twist ``v_obj``, external
        wrench on the object ``f_obj`` (F_x, F_y, torque). The object's pose ``q_obj`` and the
        contact point in its frame ``rho`` default to the scene's placement (the object
        touching the contact link at ``contact_offset``). ``data``: a workspace from
        :meth:`create_data` (one per thread); ``out``: an earlier result of the same shape
        whose array is overwritten (no allocation). Solved in compiled code per sample
        (:mod:`snakecg.engine`); see :mod:`snakecg.forward`.
        """
        core = self.core
        if (core is not None and v is None and v_obj is None and f_obj is None and q_obj is None
                and rho is None and max_iter is None and out is None):
            # one sample of float64 arrays or plain lists: straight into a workspace's buffers,
            # one C call, one copy of the result row (the C checks finiteness and range;
            # snakecg.forward.forward_one)
            tq, tt = type(q), type(tau)
            if ((tq is np.ndarray and q.dtype is _F64 and q.shape == self._shape_q
                 or (tq is list or tq is tuple) and _plain(q, self.n_coordinates))
                    and (tt is np.ndarray and tau.dtype is _F64 and tau.shape == self._shape_tau
                         or (tt is list or tt is tuple) and _plain(tau, self.n_joints))):
                res = forward_one(self, core, q, tau, data)
                if res is not None:
                    return res
        return forward(self, q, tau, v=v, v_obj=v_obj, f_obj=f_obj, q_obj=q_obj, rho=rho,
                       max_iter=max_iter, data=data, out=out)

    # linear maps (snakecg.maps) --------------------------------------------------------------
    def maps(self, q, *, contact: bool = True, wheel_state=None) -> dict[str, np.ndarray]:
        """The paper's linear maps at rest for a given active set (default: everything held);
        see :func:`snakecg.maps.maps`."""
        return _maps_mod.maps(self, q, contact=contact, wheel_state=wheel_state)

    def state_maps(self, qa, state) -> dict[str, np.ndarray]:
        """:meth:`maps` of a checked batch for row states (:func:`snakecg.maps.state_maps`)."""
        return _maps_mod.state_maps(self, qa, state)

    def state_forms(self, qa, state) -> dict[str, np.ndarray]:
        """The metrics' quadratic forms at rest (:func:`snakecg.maps.state_forms`)."""
        return _maps_mod.state_forms(self, qa, state)

    def at_rest(self, fname: str, qa, *free_args):
        """A generated at-rest function at the scene's placement (:func:`snakecg.maps.at_rest`)."""
        return _maps_mod.at_rest(self, fname, qa, *free_args)

    # analysis (snakecg.analysis) -------------------------------------------------------------
    def extremes(self, q, **kwargs):
        """Best and worst ``norm_a_obj``, ``norm_qdd``, ``norm_lambda`` and ``sr`` over the
        input ellipsoid of eq. (31); see :func:`snakecg.analysis.extremes`."""
        from .analysis import check_extremes_options, extremes
        from .progress import in_chunks

        check_extremes_options(kwargs)
        qa, batched = self._q(q)
        if not batched:
            return extremes(self, q, **kwargs)
        n = qa.shape[0]
        wheels = self.scene.scenario == "wheels"
        rows = EXTREMES_CHUNK_ROWS if wheels else CLOSED_FORM_CHUNK_ROWS
        if n > rows:
            # bounded working memory (kB per row inside one call): chunks of rows
            check_batch_memory("extremes", n, 8 * (24 + 24 * self.n_joints), what="results")
        # bounded wheels: chunks of 256 rows keep the progress bar alive; large batches solved
        # exactly go in chunks of EXTREMES_CHUNK_ROWS (vectorized over a chunk: faster)
        from .analysis import EXACT_WHEELS_MAX_JOINTS

        chunk = min(rows, 256) if wheels else rows
        exact = kwargs.get("exact")
        if exact is None:
            exact = self.n_joints <= EXACT_WHEELS_MAX_JOINTS
        if wheels and exact is True and n > rows:
            chunk = rows
        return in_chunks(lambda part: extremes(self, part, **kwargs), qa, chunk, "extremes",
                         always=n > rows)

    def com_polar(self, q):
        """Polar coordinates ``(|COM|, angle COM)`` of the snake's COM w.r.t. the contact point,
        the angle measured from the contacting link's axis; see
        :func:`snakecg.analysis.com_polar`."""
        from .analysis import com_polar

        qa, _ = self._q(q)
        self._check_memory("com_polar", qa.shape[0], ["link_poses", "place_object"],
                           extra=3 * self.n_links + 12)
        return com_polar(self, q)

    # optimal torques (snakecg.optimize) --------------------------------------------------------
    def optimize(self, q, objective="max_sr", **kwargs):
        """The optimal joint torque for a task at configuration ``q`` (at rest).

        ``objective``: ``"max_sr"`` (largest slippage ratio, eq. 30), ``"least_slip_push"``
        (a requested object acceleration with the least ``||qdd_s||^2``, eq. 26) or
        ``"strongest_push"`` (largest object acceleration along a direction with no wheel
        sliding). Keywords: ``tau_max`` (default the robot's ``effort_limits``), ``radius``
        (input region: box and/or ellipsoid of eq. 31, default ``radius=1`` without a box),
        ``direction``, ``a_min``, ``a_obj``, ``allow_slide``.
        Returns an :class:`~snakecg.optimize.OptimizeResult` (``tau``, ``status`` with
        ``reason``, ``analysis`` = the forward result at ``tau``); see
        :func:`snakecg.optimize.optimize` and docs/how-to/optimize.md.
        """
        run = _LAZY.get("optimize")
        if run is None:  # imported once (an import inside every call costs microseconds)
            from .optimize import optimize as run
            from .optimize.arguments import screen

            _LAZY["optimize"], _LAZY["screen"] = run, screen
        if not (type(q) is np.ndarray and q.ndim == 1):  # a batch: its memory first
            qa, _ = self._q(q)
            self._check_memory("optimize", qa.shape[0], ["place_object", "interaction_maps"],
                               extra=self.columns.width + 4 * self.n_joints)
        return run(self, q, objective=objective, **_LAZY["screen"](kwargs))

    # simulation (snakecg.simulate) -------------------------------------------------------------
    def simulate(self, q0, tau, duration, v0=None, **kwargs):
        """Integrate snake + object from ``q0`` (and velocities ``v0``, default rest) for
        ``duration`` seconds under joint torques ``tau``: a constant ``(n_a,)``, a function
        ``tau(t)`` or a feedback law ``tau(t, state)``. Contact separation and impacts, wheels
        breaking away and sticking again are events. Returns a
        :class:`~snakecg.simulate.Trajectory` (``t``, ``q``, ``v``, ``q_obj``, ``v_obj``,
        ``lam``, ``contact``, ``wheel_state``, ... and ``summary``); keywords and details in
        :func:`snakecg.simulate.simulate` and docs/how-to/simulate.md.
        """
        from .simulate import simulate

        return simulate(self, q0, tau, duration, v0=v0, **kwargs)

    # optimal shapes (snakecg.shape) ------------------------------------------------------------
    def optimize_shape(self, objective="max_sr", **kwargs):
        """The best shape (joint angles) and torque for a task: ``"max_sr"``,
        ``"strongest_push"``, ``"least_slip_push"`` or ``"max_a_obj"``, by IPOPT on the
        generated functions, multi-started from a coarse grid, under joint limits and (with
        ``feasible=True``) no self-intersection or object penetration. Returns an
        :class:`~snakecg.shape.OptimizeShapeResult`; see :func:`snakecg.shape.optimize_shape`
        and docs/how-to/shapes.md.
        """
        from .shape import optimize_shape

        return optimize_shape(self, objective, **kwargs)
