"""Loaded models: immutable parameters and compiled functions; numbers in, numbers out.

``snakecg.load(robot)`` gives a :class:`RobotModel` (inertia, Jacobians, poses);
``snakecg.load(scene)`` a :class:`SceneModel`, which adds the coupled snake + object analysis
of Reyes & Ma 2017. Every method takes one sample (``q`` of shape ``(n_s,)``) or a batch
(``(N, n_s)``) and evaluates the whole batch in one compiled call; nothing here imports
SymPy or Jinja2.
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import artifacts
from ._inputs import as_batch, broadcast_batches, expand
from .errors import InputError
from .native import load_backend
from .robot import Robot, Scene
from .solver import (ABSENT, HELD, LOST, PIVOT_TOL, REGULARIZATION, SLIDE_NEG, SLIDE_POS,
                     _violations_one, default_max_iter, solve_active_set)

__all__ = ["load", "RobotModel", "SceneModel", "ForwardResult"]

_BACKENDS: dict[tuple[int, str], tuple[object, dict, Path]] = {}


def _backend(n_joints: int, prefer: str, progress=None):
    key = (n_joints, prefer)
    if key not in _BACKENDS:
        folder, manifest = artifacts.model_dir(n_joints, progress=progress)
        backend = load_backend(folder, manifest, prefer=prefer, progress=progress)
        _BACKENDS[key] = (backend, manifest, folder)
    return _BACKENDS[key]


def load(obj, *, backend: str = "compiled", progress=None):
    """Load the model of a :class:`~snakecg.Robot` or a :class:`~snakecg.Scene`.

    The generated model for the joint count is taken from the package or the user cache
    (generated once if missing), compiled once into a cached shared library and shared by
    every robot with that joint count. ``backend="casadi"`` evaluates with CasADi's
    in-process virtual machine instead of the compiled C.
    """
    if isinstance(obj, Scene):
        return SceneModel(obj, backend=backend, progress=progress)
    if isinstance(obj, Robot):
        return RobotModel(obj, backend=backend, progress=progress)
    raise InputError(f"load() takes a snakecg.Robot or snakecg.Scene, got {type(obj).__name__}")


class RobotModel:
    """A snake robot's compiled model: ``mass_matrix``, ``link_jacobians``, ``link_poses``..."""

    def __init__(self, robot: Robot, *, backend: str = "compiled", progress=None):
        if not isinstance(robot, Robot):
            raise InputError(f"robot must be a snakecg.Robot, got {type(robot).__name__}")
        self.robot = robot
        self.backend, self.manifest, self.folder = _backend(robot.joints, backend, progress)
        self.n_joints = robot.joints
        self.n_links = robot.n_links
        self.n_coordinates = robot.n_coordinates
        self.n_constraints = robot.n_links + 1
        (K,) = self.backend(
            "derived_parameters",
            1,
            [np.asarray(robot.mass, float), np.asarray(robot.length, float),
             np.asarray(robot.inertia, float), np.asarray(robot.com, float)],
        )
        self.parameters = np.ascontiguousarray(K[0, :, 0])
        """The parameter vector ``K`` (raw link parameters, then derived constants)."""

    @property
    def backend_kind(self) -> str:
        return self.backend.kind

    # helpers ---------------------------------------------------------------------------
    def _q(self, q, name="q"):
        return as_batch(name, q, self.n_coordinates,
                        what=f" = (n_joints + 3,) for a {self.n_joints}-joint robot")

    def _call(self, fname: str, n: int, inputs: list[np.ndarray]):
        return self.backend(fname, n, inputs)

    @staticmethod
    def _arg(arr: np.ndarray, n: int) -> np.ndarray:
        """Batch argument: 1-D (broadcast) when one sample serves all, else ``(n, size)``."""
        return arr[0] if arr.shape[0] == 1 and n >= 1 else arr

    # public ----------------------------------------------------------------------------
    def mass_matrix(self, q) -> np.ndarray:
        """Inertia matrix ``M_s(q)`` of eq. (4): ``(n_s, n_s)``, or ``(N, n_s, n_s)``."""
        qa, batched = self._q(q)
        n = qa.shape[0]
        (M,) = self._call("mass_matrix", n, [self._arg(qa, n), self.parameters])
        return M if batched else M[0]

    def link_jacobians(self, q) -> np.ndarray:
        """Link Jacobians ``J_i`` of eq. (3): ``(n_l, 3, n_s)``, or ``(N, n_l, 3, n_s)``.

        ``J_i qdot`` is the twist ``(v_x, v_y, omega)`` of the COM of link ``i + 1``.
        """
        qa, batched = self._q(q)
        n = qa.shape[0]
        (J,) = self._call("link_jacobians", n, [self._arg(qa, n), self.parameters])
        J = J.reshape(n, self.n_links, 3, self.n_coordinates)
        return J if batched else J[0]

    def link_poses(self, q) -> np.ndarray:
        """``(x_i, y_i, phi_i)`` of every link COM: ``(n_l, 3)``, or ``(N, n_l, 3)``."""
        qa, batched = self._q(q)
        n = qa.shape[0]
        (P,) = self._call("link_poses", n, [self._arg(qa, n), self.parameters])
        P = np.ascontiguousarray(P.transpose(0, 2, 1))
        return P if batched else P[0]

    def bias_forces(self, q, v) -> np.ndarray:
        """Coriolis and centripetal terms ``h_s(q, qdot)`` of eq. (4): ``(n_s,)`` or ``(N, n_s)``."""
        qa, bq = self._q(q)
        va, bv = self._q(v, "v")
        n = broadcast_batches(q=(qa, bq), v=(va, bv))
        (h,) = self._call("bias_forces", n, [self._arg(qa, n) if not bq else qa,
                                              self._arg(va, n) if not bv else va, self.parameters])
        h = h[:, :, 0]
        return h if (bq or bv) else h[0]

    def com(self, q) -> np.ndarray:
        """The robot's centre of mass ``(x, y)``: ``(2,)`` or ``(N, 2)``."""
        P = self.link_poses(q)
        m = np.asarray(self.robot.mass)
        return np.einsum("...ik,i->...k", P[..., :2], m) / m.sum()


# ------------------------------------------------------------------------------------------
@dataclass
class ForwardResult:
    """Outcome of :meth:`SceneModel.forward` for one sample or a batch (leading axis N).

    * ``qdd`` (n_s): snake accelerations; ``a_obj`` (3): object acceleration (x, y, psi);
    * ``lam`` (n_c): constraint forces, row 0 the contact (N, pushes the object along the
      normal), row ``i`` the lateral force of the wheel of link ``i`` (N, along
      ``(-sin phi_i, cos phi_i)``); ``w`` (n_c): the rows' accelerations;
    * ``contact``: the contact is kept (``lam_c >= 0``) or lost; ``wheel_state`` (n_l):
      ``"none"``, ``"stick"``, ``"slide+"`` / ``"slide-"`` (force at ``+-mu m g``);
    * norms: ``norm_lambda = lam^T G_c lam``, ``norm_a_obj = a_obj^T I_obj a_obj`` (eq. 27),
      ``norm_qdd = qdd^T M_s qdd`` (eq. 26), slippage ratio ``sr`` (eq. 30, 0 when the
      contact is lost);
    * ``singular``: the held rows were dependent (least-norm forces, see ``snakecg.solver``);
      ``conditioning``: the smallest pivot of the held rows' Delassus matrix relative to its
      diagonal (1: independent rows; the forces carry a relative error of about
      ``1e-16 / conditioning``; below ``1e-10`` the sample is treated as ``singular`` and
      reported with ``conditioning = 0``).
    """

    qdd: np.ndarray
    a_obj: np.ndarray
    lam: np.ndarray
    w: np.ndarray
    contact: np.ndarray
    wheel_state: np.ndarray
    norm_lambda: np.ndarray
    norm_a_obj: np.ndarray
    norm_qdd: np.ndarray
    sr: np.ndarray
    gap: np.ndarray
    singular: np.ndarray
    conditioning: np.ndarray = None
    tau: np.ndarray = field(repr=False, default=None)

    @property
    def sliding(self) -> np.ndarray:
        return np.isin(self.wheel_state, ("slide+", "slide-"))

    def to_dict(self) -> dict:
        """JSON-ready dictionary (schema in docs/cli.md)."""
        out = {}
        for k in ("tau", "qdd", "a_obj", "lam", "w", "contact", "wheel_state", "norm_lambda",
                  "norm_a_obj", "norm_qdd", "sr", "singular", "conditioning"):
            v = getattr(self, k)
            out[k] = np.asarray(v).tolist()
        return out


_STATE_NAMES = np.array(["none", "stick", "lost", "slide+", "slide-"])
#: Names of the wheel rows' states (a wheel row is never "lost"; read as "none").
_WHEEL_STATE_NAMES = np.where(_STATE_NAMES == "lost", "none", _STATE_NAMES)


class SceneModel(RobotModel):
    """The coupled snake + object of a :class:`~snakecg.Scene`: forward analysis, maps,
    extremes over the input region, torque optimisation and simulation."""

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
        # one-sample path of forward: initial row states, bounds as floats, per-thread buffers
        self._state0 = [int(s) for s in np.where(present, HELD, ABSENT)]
        self._bounds_list = [float(b) for b in bounds]
        self._zeros_one = (np.zeros(self.n_coordinates), np.zeros(3))
        self._local = threading.local()

    # placement ----------------------------------------------------------------------------
    def place_object(self, q):
        """Object pose ``(x_o, y_o, psi)``, contact point in the object frame ``rho`` and the
        world contact point for the scene's contact (shapes ``(3,)``, ``(2,)``, ``(2,)`` or
        batched)."""
        qa, batched = self._q(q)
        n = qa.shape[0]
        q_obj, rho, P = self._place(qa, n)
        if batched:
            return q_obj, rho, P
        return q_obj[0], rho[0], P[0]

    def _place(self, qa, n):
        q_obj, rho, P = self._call(
            "place_object", n,
            [self._arg(qa, n), self.parameters, self._contact_link,
             np.array([self.scene.contact_offset]), np.array([self.scene.object_distance]),
             self._side],
        )
        return q_obj[:, :, 0], rho[:, :, 0], P[:, :, 0]

    # forward -------------------------------------------------------------------------------
    def forward(self, q, tau, *, v=None, v_obj=None, f_obj=None, q_obj=None, rho=None,
                max_iter: int | None = None) -> ForwardResult:
        """Accelerations, constraint forces, active set and norms (eqs. 12-30).

        ``q`` ``(n_s,)`` or ``(N, n_s)``; ``tau`` ``(n_a,)`` or ``(N, n_a)`` (one broadcasts
        against the other). Optional: snake velocities ``v``, object twist ``v_obj``, external
        wrench on the object ``f_obj`` (F_x, F_y, torque). The object's pose ``q_obj`` and the
        contact point in its frame ``rho`` default to the scene's placement (the object
        touching the contact link at ``contact_offset``).
        """
        na = self.n_joints
        if max_iter is not None and (isinstance(max_iter, bool)
                                     or not isinstance(max_iter, (int, np.integer))
                                     or max_iter < 1):
            raise InputError(f"max_iter must be an integer >= 1 (active-set iterations before"
                             f" enumerating), or None for the default; got {max_iter!r}")
        qa, bq = self._q(q)
        ta, bt = as_batch("tau", tau, na, what=f" (one torque per joint, n_a = {na})")
        parts = {"q": (qa, bq), "tau": (ta, bt)}
        extra = {}
        for name, val, size in (("v", v, self.n_coordinates), ("v_obj", v_obj, 3),
                                ("f_obj", f_obj, 3), ("q_obj", q_obj, 3), ("rho", rho, 2)):
            if val is not None:
                arr = as_batch(name, val, size)
                parts[name] = arr
                extra[name] = arr[0]
        n = broadcast_batches(**parts)
        batched = any(b for _, b in parts.values())
        if ("q_obj" in extra) != ("rho" in extra):
            raise InputError("q_obj and rho go together: give both or neither")
        if not batched and self.backend.kind == "compiled":
            res = self._forward_one(qa[0], ta[0], extra, max_iter)
            if res is not None:
                return res
        if "q_obj" not in extra:
            q_obj_a, rho_a = self._place(qa, qa.shape[0])[:2]
        else:
            q_obj_a, rho_a = extra["q_obj"], extra["rho"]
        zeros_ns = np.zeros(self.n_coordinates)
        base = {
            "q": qa, "v": extra.get("v", zeros_ns[None, :]), "tau": ta,
            "q_obj": q_obj_a, "v_obj": extra.get("v_obj", np.zeros((1, 3))),
            "f_obj": extra.get("f_obj", np.zeros((1, 3))), "rho": rho_a,
        }
        sol = self._solve(base, n, max_iter=max_iter)
        return self._result(sol, expand(ta, n), batched)

    def _forward_one(self, q, tau, extra, max_iter):
        """``forward`` for one sample through preallocated one-sample buffers of the compiled
        functions (the general path's per-call numpy and ctypes overhead is ~10x the C time).
        The same active-set passes as :func:`~snakecg.solver.solve_active_set`; returns None to
        leave the rare cases to the general path: dependent held rows (regularised re-solve)
        and no convergence within ``max_iter`` passes (enumeration)."""
        ks = getattr(self._local, "kernels", None)
        if ks is None:
            from .native import BoundFunction  # one-sample buffers

            be, K = self.backend, self.parameters
            place = BoundFunction(be, "place_object", {
                "K": K, "contact_link": self._contact_link,
                "contact_offset": [self.scene.contact_offset],
                "object_distance": [self.scene.object_distance], "side": self._side})
            cd = BoundFunction(be, "constrained_dynamics", {
                "K": K, "contact_link": self._contact_link, "side": self._side,
                "object_mass": self._object_mass, "object_inertia": self._object_inertia,
                "wheel_offset": self._wheel_offset, "regularization": [0.0]})
            ks = self._local.kernels = (place, cd, *(cd.out_names.index(k) for k in
                                                     ("lam", "w", "pivot_ratio")))
        place, cd, i_lam, i_w, i_pivot = ks
        if "q_obj" in extra:
            q_obj, rho = extra["q_obj"][0], extra["rho"][0]
        else:
            q_obj, rho, _ = place.one(q=q)
        zeros = self._zeros_one
        cd.set(q=q, tau=tau, q_obj=q_obj, rho=rho,
               v=extra["v"][0] if "v" in extra else zeros[0],
               v_obj=extra["v_obj"][0] if "v_obj" in extra else zeros[1],
               f_obj=extra["f_obj"][0] if "f_obj" in extra else zeros[1])
        state, bounds = list(self._state0), self._bounds_list
        for _ in range(default_max_iter(len(state)) if max_iter is None else max_iter):
            outs = cd.one(free=[float(s == HELD) for s in state],
                          lam_fixed=[u if s == SLIDE_POS else -u if s == SLIDE_NEG else 0.0
                                     for s, u in zip(state, bounds)])
            lam, w = outs[i_lam].tolist(), outs[i_w].tolist()
            if not (outs[i_pivot][0] > PIVOT_TOL and all(map(math.isfinite, lam))):
                return None
            new = _violations_one(state, lam, w, bounds)
            if new == state:
                break
            state = new
        else:
            return None
        o = dict(zip(cd.out_names, outs))
        contact = state[0] == HELD
        return ForwardResult(
            qdd=o["qdd"].copy(), a_obj=o["a_obj"].copy(), lam=o["lam"].copy(),
            w=o["w"].copy(), contact=np.bool_(contact),
            wheel_state=_WHEEL_STATE_NAMES[state[1:]],
            norm_lambda=np.float64(o["norm_lambda"][0]),
            norm_a_obj=np.float64(o["norm_a_obj"][0]), norm_qdd=np.float64(o["norm_qdd"][0]),
            sr=np.float64(o["sr"][0] if contact else 0.0), gap=np.float64(o["gap"][0]),
            singular=np.bool_(False), conditioning=np.float64(outs[i_pivot][0]), tau=tau,
        )

    def _solve(self, base: dict, n: int, *, max_iter=None):
        order = ["q", "v", "tau", "q_obj", "v_obj", "f_obj"]

        names = self.backend.signatures["constrained_dynamics"].out_names

        def pick(arr, idx):
            # every input is float64 and C-contiguous (as_batch, _free_and_fixed, __init__)
            if arr.shape[0] == 1:
                return arr[0]
            m = len(idx)
            if m == arr.shape[0] and idx[0] == 0 and idx[-1] == m - 1:  # sorted: all samples
                return arr
            return np.ascontiguousarray(arr[idx])

        def call(idx, free, lam_fixed, reg):
            m = len(idx)
            args = [pick(base[k], idx) for k in order] + [
                self.parameters, self._contact_link, self._side, self._object_mass,
                self._object_inertia, pick(base["rho"], idx), self._wheel_offset,
                free, lam_fixed, np.asarray(reg, dtype=float).reshape(m, 1),
            ]
            outs = self._call("constrained_dynamics", m, args)
            res = {}
            for name_, o in zip(names, outs):  # views, no copies
                if o.shape[1:] == (1, 1):
                    res[name_] = o[:, 0, 0]
                elif o.shape[2] == 1:
                    res[name_] = o[:, :, 0]
                else:
                    res[name_] = o
            return res

        return solve_active_set(call, n, self.present, self.bounds, max_iter=max_iter)

    def _result(self, sol, tau, batched) -> ForwardResult:
        o = sol.outputs
        state = sol.state
        contact = state[:, 0] == HELD
        wheel_state = _WHEEL_STATE_NAMES[state[:, 1:]]
        r = ForwardResult(
            qdd=o["qdd"], a_obj=o["a_obj"], lam=o["lam"], w=o["w"], contact=contact,
            wheel_state=wheel_state, norm_lambda=o["norm_lambda"], norm_a_obj=o["norm_a_obj"],
            norm_qdd=o["norm_qdd"], gap=o["gap"], singular=sol.singular,
            conditioning=np.where(sol.singular, 0.0, np.minimum(o["pivot_ratio"], 1.0)),
            tau=tau,
            sr=np.where(contact, o["sr"], 0.0),  # eq. 30; no interaction without contact
        )
        if not batched:
            for k in r.__dataclass_fields__:
                val = getattr(r, k)
                if isinstance(val, np.ndarray):
                    setattr(r, k, val[0])
        return r

    # linear maps ---------------------------------------------------------------------------
    def maps(self, q, *, contact: bool = True, wheel_state=None) -> dict[str, np.ndarray]:
        """The paper's linear maps at rest for a given active set (default: everything held).

        Keys (each ``(..., rows, cols)``): ``qdd_from_tau`` (eq. 22), ``qdd_from_f_obj``
        (eq. 23), ``a_obj_from_tau`` (eq. 24), ``a_obj_from_f_obj`` (eq. 25),
        ``lam_from_tau``/``lam_from_f_obj`` (eq. 17), ``xi_tau`` (eq. 28), ``omega_tau``
        (eq. 29), ``lambda_form_tau`` (``lam^T G_c lam`` as a form in ``tau``),
        ``input_metric`` (``B^T M_s^-1 B``, eq. 31 corrected), ``projector_constrained``
        (eq. 14), ``projector_orthogonal`` (eq. 19), ``delassus`` (``G_c``), plus the
        ``*_offset`` vectors produced by sliding wheels' fixed forces and ``w_*`` maps of the
        rows' accelerations. ``pivot_ratio`` and ``singular``: the held rows were dependent;
        such samples are re-evaluated with a tiny Tikhonov term (least-norm forces, as in
        ``forward``).
        """
        qa, batched = self._q(q)
        n = qa.shape[0]
        state = np.where(self.present, HELD, ABSENT).astype(np.int8)
        if not contact:
            state[0] = LOST
        if wheel_state is not None:
            ws = [wheel_state] if isinstance(wheel_state, str) else list(wheel_state)
            if len(ws) != self.n_links:
                raise InputError(f"wheel_state must list {self.n_links} link states (one per"
                                 f" link: 'stick', 'slide+', 'slide-', or 'none' without a"
                                 f" wheel), got {wheel_state!r}")
            codes = {"stick": HELD, "slide+": SLIDE_POS, "slide-": SLIDE_NEG}
            for i, s in enumerate(ws):
                if self.present[i + 1] and s not in codes:
                    raise InputError(f"wheel_state[{i}] must be 'stick', 'slide+' or 'slide-'"
                                     f" (link {i + 1} has a wheel), got {s!r}")
                if not self.present[i + 1]:
                    if s not in ("none", *codes):
                        raise InputError(f"wheel_state[{i}] must be a wheel state ('none' for"
                                         f" link {i + 1}, which has no wheel), got {s!r}")
                    continue
                state[i + 1] = codes[s]
        out = self._maps(qa, n, state)
        return out if batched else {k: v[0] for k, v in out.items()}

    def _maps(self, qa, n, state):
        from .solver import _free_and_fixed

        free, lam_fixed = _free_and_fixed(state[None, :], self.bounds)
        args, raw = self._at_rest("interaction_maps", qa, n, free[0], lam_fixed[0])
        names = list(raw)
        res = {}
        for name_, o in raw.items():
            if name_ == "pivot_ratio":  # the only scalar (a 1x1 map is still a matrix)
                res[name_] = o[:, 0, 0].copy()
            elif o.shape[2] == 1 and name_.endswith("offset"):
                res[name_] = np.ascontiguousarray(o[:, :, 0])
            else:
                res[name_] = np.ascontiguousarray(o)
        # dependent held rows: re-solve those samples with the solver's Tikhonov term
        finite = np.all(np.isfinite(res["lam_from_tau"].reshape(n, -1)), axis=1)
        singular = ~(res["pivot_ratio"] > PIVOT_TOL) | ~finite
        if np.any(singular):
            sub = np.flatnonzero(singular)
            scale = np.abs(np.diagonal(res["delassus"][sub], axis1=1, axis2=2)).max(axis=1)
            reg = (REGULARIZATION * np.maximum(scale, 1e-300)).reshape(-1, 1)
            sub_args = [a[sub] if a.ndim == 2 else a for a in args[:-1]] + [reg]
            again = self._call("interaction_maps", len(sub), sub_args)
            for name_, o in zip(names, again):
                if name_ != "pivot_ratio":
                    res[name_][sub] = o.reshape(res[name_][sub].shape)
        res["singular"] = singular
        return res

    def _at_rest(self, fname: str, qa, n: int, *free_args):
        """Evaluate a generated at-rest function (``interaction_maps``, ``metric_forms``,
        ``metric_extremes``) at the scene's placement of the object.

        ``free_args`` are the inputs that follow ``wheel_offset`` up to ``regularization``
        (the held-row masks, fixed forces); ``regularization`` is 0. Returns the argument list
        and ``{output name: (n, rows, cols) array}``.
        """
        q_obj, rho, _ = self._place(qa, n)
        args = [self._arg(qa, n), self.parameters, self._contact_link, self._side,
                self._object_mass, self._object_inertia, self._arg(q_obj, n),
                self._arg(rho, n), self._wheel_offset, *free_args, np.zeros(1)]
        args = [np.ascontiguousarray(a, dtype=float) for a in args]
        outs = self._call(fname, n, args)
        return args, dict(zip(self.backend.signatures[fname].out_names, outs))

    def _metric_forms(self, qa, n, state):
        """Quadratic forms of the metrics at rest (generated ``metric_forms``), batched.

        Samples whose held rows are dependent fall back to :meth:`_maps` (regularised).
        """
        from .solver import _free_and_fixed

        free, _ = _free_and_fixed(state[None, :], self.bounds)
        _, raw = self._at_rest("metric_forms", qa, n, free[0])
        res = {}
        for name_, o in raw.items():
            if name_ == "pivot_ratio":  # the only scalar (a 1x1 form is still a matrix)
                res[name_] = o[:, 0, 0].copy()
            elif name_ == "contact_from_tau":
                res[name_] = np.ascontiguousarray(o[:, 0, :])
            else:
                res[name_] = np.ascontiguousarray(o)
        finite = np.all(np.isfinite(res["omega_tau"].reshape(n, -1)), axis=1)
        singular = ~(res["pivot_ratio"] > PIVOT_TOL) | ~finite
        if np.any(singular):
            sub = np.flatnonzero(singular)
            again = self._maps(np.ascontiguousarray(qa[sub] if qa.shape[0] > 1 else qa),
                               len(sub), state)
            for k in ("omega_tau", "xi_tau", "lambda_form_tau", "input_metric"):
                res[k][sub] = again[k]
            res["contact_from_tau"][sub] = again["lam_from_tau"][:, 0, :]
        res["singular"] = singular
        return res

    # analysis (snakecg.analysis) -------------------------------------------------------------
    def extremes(self, q, **kwargs):
        """Best and worst ``norm_a_obj``, ``norm_qdd``, ``norm_lambda`` and ``sr`` over the
        input ellipsoid of eq. (31); see :func:`snakecg.analysis.extremes`."""
        from .analysis import extremes

        return extremes(self, q, **kwargs)

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
        sliding). Keywords: ``tau_max``, ``radius`` (input region: box and/or ellipsoid of
        eq. 31, default ``radius=1``), ``direction``, ``a_min``, ``a_obj``, ``allow_slide``.
        Returns an :class:`~snakecg.optimize.OptimizeResult` (``tau``, ``status`` with
        ``reason``, ``analysis`` = the forward result at ``tau``); see
        :func:`snakecg.optimize.optimize` and docs/optimize.md.
        """
        from .optimize import optimize

        return optimize(self, q, objective=objective, **kwargs)

    # simulation (snakecg.simulate) -------------------------------------------------------------
    def simulate(self, q0, tau, duration, v0=None, **kwargs):
        """Integrate snake + object from ``q0`` (and velocities ``v0``, default rest) for
        ``duration`` seconds under joint torques ``tau``: a constant ``(n_a,)``, a function
        ``tau(t)`` or a feedback law ``tau(t, state)``. Contact separation and impacts, wheels
        breaking away and sticking again are events. Returns a
        :class:`~snakecg.simulate.Trajectory` (``t``, ``q``, ``v``, ``q_obj``, ``v_obj``,
        ``lam``, ``contact``, ``wheel_state``, ... and ``summary``); keywords and details in
        :func:`snakecg.simulate.simulate` and docs/simulate.md.
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
        and docs/shapes.md.
        """
        from .shape import optimize_shape

        return optimize_shape(self, objective, **kwargs)
