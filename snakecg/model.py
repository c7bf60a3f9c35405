"""Loaded models: immutable parameters and compiled functions; numbers in, numbers out.

``snakecg.load(robot)`` gives a :class:`RobotModel` (inertia, Jacobians, poses);
``snakecg.load(scene)`` a :class:`SceneModel`, which adds the coupled snake + object analysis
of Reyes & Ma 2017. Every method takes one sample (``q`` of shape ``(n_s,)``) or a batch
(``(N, n_s)``) and evaluates the whole batch in one compiled call; nothing here imports
SymPy or Jinja2.
"""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from . import loading as _loading
from . import maps as _maps_mod
from .engine import Data, Layout
from .errors import InputError
from .kinds import SCENE_MODEL
from .forward import ForwardResult, _Columns, model_forward
from .robot import Robot, Scene
from .robot_model import RobotModel, _check_load_args
from .solver import default_max_iter

__all__ = ["load", "RobotModel", "SceneModel", "ForwardResult"]

#: Rows of one ``extremes`` call on a large batch with bounded wheels (each row needs tens of
#: kB while it runs).
EXTREMES_CHUNK_ROWS = 2048
#: Rows of one ``extremes`` call in the closed-form scenarios (frictionless, ideal wheels:
#: about 1 kB per row at its peak), so that case study 2's 21,952 configurations are one
#: call: each call has a fixed cost (the threads' dispatch, a few dozen NumPy operations).
CLOSED_FORM_CHUNK_ROWS = 32768

def load(obj, *, backend: str = "compiled", progress=None):
    """Load the model of a :class:`~snakecg.Robot`, a :class:`~snakecg.Scene`, a
    :class:`~snakecg.scenes.GeneralScene`, a :class:`~snakecg.SpatialRobot` (a
    :class:`~snakecg.spatial.model.SpatialModel`) or a :class:`~snakecg.SpatialScene` (a
    :class:`~snakecg.spatial.analysis.SpatialSceneModel`).

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
    from .scenes import GeneralScene

    if isinstance(obj, GeneralScene):  # objects, obstacles, contacts from geometry
        from .scenes.model import GeneralSceneModel

        return GeneralSceneModel(obj, backend=backend, progress=progress)
    from .spatial import SpatialRobot, SpatialScene

    if isinstance(obj, SpatialRobot):  # a 3-D chain: snakecg.spatial's own model
        from .spatial.model import SpatialModel

        return SpatialModel(obj, backend=backend, progress=progress)
    if isinstance(obj, SpatialScene):  # the paper's analysis in 3-D
        from .spatial.analysis import SpatialSceneModel

        return SpatialSceneModel(obj, backend=backend, progress=progress)
    raise InputError(f"load() takes a snakecg.Robot, snakecg.Scene, snakecg.SpatialRobot or "
                     f"snakecg.SpatialScene (or a snakecg.scenes.GeneralScene), "
                     f"got {type(obj).__name__}")


#: snakecg.optimize's entry point and argument screen, imported on first use
_LAZY: dict = {}


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
        batched); see :func:`snakecg.maps.place_object`."""
        return _maps_mod.place_object(self, q)

    def place(self, qa, n: int | None = None):
        """:meth:`place_object` of a checked batch ``qa`` (``(N, n_s)``, from
        :meth:`configurations`): ``(q_obj, rho, contact_point)`` of shapes ``(N, 3)``,
        ``(N, 2)``, ``(N, 2)``."""
        return _maps_mod.place(self, qa, qa.shape[0] if n is None else n)

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

    forward = model_forward
    """Accelerations, constraint forces, active set and norms (eqs. 12-30):
    :func:`snakecg.forward.model_forward`, bound as the method (no extra call), so
    ``model.forward(q, tau, ...)`` takes its arguments after the model."""

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
        input ellipsoid of eq. (31); see :func:`snakecg.analysis.extremes_of`."""
        from .analysis import extremes_of

        return extremes_of(self, q, (EXTREMES_CHUNK_ROWS, CLOSED_FORM_CHUNK_ROWS), kwargs)

    def com_polar(self, q):
        """Polar coordinates ``(|COM|, angle COM)`` of the snake's COM w.r.t. the contact point,
        the angle measured from the contacting link's axis; see
        :func:`snakecg.analysis.com_polar`."""
        from .analysis import com_polar

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
            from .optimize.api import optimize_model as run

            _LAZY["optimize"] = run
        return run(self, q, objective, kwargs)

    # simulation (snakecg.simulate) -------------------------------------------------------------
    def simulate(self, q0, tau, duration, v0=None, **kwargs):
        """Integrate snake + object from ``q0`` (and velocities ``v0``, default rest) for
        ``duration`` seconds under joint torques ``tau``: a constant ``(n_a,)``, a function
        ``tau(t)`` or a feedback law ``tau(t, state)``. Contact separation and impacts, wheels
        breaking away and sticking again are events. Returns a
        :class:`~snakecg.simulate.Trajectory` (``t``, ``q``, ``v``, ``q_obj``, ``v_obj``,
        ``lam``, ``contact``, ``wheel_state``, ... and ``summary``); keywords and details in
        :func:`snakecg.simulate.simulate` and docs/how-to/simulate.md. ``contacts="geometry"``
        steps the scene with its square plate and every contact from the geometry instead
        (a :class:`~snakecg.scenes.run_record.SceneRun`).
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


_loading.register(load)  # the features that are given a scene load its model through it
