"""The coupled snake + object equations at one state: the right-hand side within a mode, the
constraint rows' velocities, and the linear maps, projections and impulses used at events.

State layout: ``y = (q, q_obj, v, v_obj, W)`` with ``q``, ``v`` (n_s), ``q_obj``, ``v_obj``
(3) and the three work integrals ``W`` (joint torques, kinetic friction of sliding wheels,
the external wrench on the object); ``x = (q, q_obj)`` and ``V = (v, v_obj)`` have
``n_x = n_s + 3`` entries each.

Within a mode the accelerations are those of eq. (12) with the held rows' accelerations
``w_F = 0`` (eq. 13 with equality), from the compiled ``constrained_dynamics`` of that active
set; the held rows are Baumgarte-stabilised (``gddot = -2 alpha gdot - alpha^2 g`` for the
contact, ``udot = -2 alpha u`` for a sticking wheel).
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from ..kernels import at_origin
from ..native import BoundFunction
from ..solver import PIVOT_TOL, REGULARIZATION
from .records import State

__all__ = ["Dynamics", "N_WORK"]

N_WORK = 3  # work integrals: joint torques, kinetic friction, object wrench
# outputs of constrained_dynamics read by the right-hand side, in this order
_RHS_OUTPUTS = ("qdd", "a_obj", "lam", "gap", "s", "sr", "norm_a_obj", "norm_qdd",
                "pivot_ratio", "delassus")


def _constants(model) -> dict:
    """What :class:`Dynamics` takes from the model and its scene, built once per model (the
    arrays read-only: every run shares them; kept in the model's data)."""
    derived = model.data().derived
    c = derived.get("simulate.constants")
    if c is None:
        scene = model.scene
        ns, na, nl, nc = (model.n_coordinates, model.n_joints, model.n_links,
                          model.n_constraints)
        k = scene.contact_link - 1
        woff = np.asarray(scene.wheel_offset, dtype=float).copy()
        m_obj = scene.object_mass
        c = {"scene": scene, "ns": ns, "na": na, "nl": nl, "nc": nc, "nx": ns + 3,
             "ny": 2 * (ns + 3) + N_WORK, "present": model.present.copy(),
             "bounds": model.bounds.copy(), "k": k, "sigma": scene.side_sign,
             "c_k": float(scene.robot.com[k]), "l_k": float(scene.robot.length[k]),
             "woff": woff, "_woff": woff.tolist(),
             "mo": np.array([m_obj, m_obj, scene.object_inertia]),
             "_zeros_nc": np.zeros(nc)}
        for v in c.values():
            if isinstance(v, np.ndarray):
                v.flags.writeable = False
        derived["simulate.constants"] = c
    return c


class Dynamics:
    """The equations of one run: the model's generated functions bound to the run's
    constants (parameters, object, contact point ``rho`` in the object frame, wrench
    ``f_obj``), the scene's constants, and counters of the evaluations (``nfev`` right-hand
    sides, ``njev`` row-velocity Jacobians, ``singular`` samples with dependent held rows).
    """

    def __init__(self, model, rho: np.ndarray, f_obj: np.ndarray, alpha: float):
        self.__dict__.update(_constants(model))  # scene, sizes, rows, contact link, object
        self.rho, self.f_obj, self.alpha = rho, f_obj, alpha
        self._rho = tuple(rho.tolist())
        self._model = model
        self._cache = None  # (t, mode, tau_fn, y bytes, rates) of the last evaluation
        self.nfev = 0
        self.njev = 0
        self.singular = 0

    @cached_property
    def _posv(self):
        from scipy.linalg.lapack import dposv

        return dposv

    # --- the generated functions, bound on first use (a run in compiled code may need none)
    def _bound(self, name, constants):
        return BoundFunction(self._model.backend, name, constants)

    def _fixed(self):
        inputs = self._model.scene_inputs
        return {k: inputs[k] for k in ("K", "contact_link", "side", "object_mass",
                                       "object_inertia", "wheel_offset")}

    @cached_property
    def cd(self) -> BoundFunction:
        """``constrained_dynamics`` with the run's constants (the right-hand side)."""
        return self._bound("constrained_dynamics", {
            **self._fixed(), "rho": self.rho, "f_obj": self.f_obj,
            "regularization": np.zeros(1)})

    @cached_property
    def _cs(self) -> BoundFunction:
        """``contact_system``: the problem before any active set (the linear maps at
        events)."""
        inputs = self._model.scene_inputs
        return self._bound("contact_system", {
            **self._fixed(), "rho": self.rho, "f_obj": self.f_obj,
            "contact_offset": inputs["contact_offset"],
            "object_distance": inputs["object_distance"], "placed": np.zeros(1)})

    @cached_property
    def _jac(self) -> BoundFunction:
        return self._bound("link_jacobians", {"K": self._model.parameters})

    @cached_property
    def _mass(self) -> BoundFunction:
        return self._bound("mass_matrix", {"K": self._model.parameters})

    @cached_property
    def _out_index(self) -> tuple:
        return tuple(self.cd.out_names.index(n) for n in _RHS_OUTPUTS)

    @cached_property
    def _jac_index(self) -> int:
        return self._jac.out_names.index("J")

    # --- state helpers --------------------------------------------------------------------
    def split(self, y):
        """``(q, q_obj, v, v_obj)``: views into ``y``."""
        ns = self.ns
        return y[:ns], y[ns:ns + 3], y[ns + 3:2 * ns + 3], y[2 * ns + 3:2 * ns + 6]

    def state(self, t, y, mode) -> State:
        """What a feedback law sees at ``(t, y)`` in ``mode`` (copies)."""
        q, qo, v, vo = self.split(y)
        return State(float(t), q.copy(), v.copy(), qo.copy(), vo.copy(), self.rho.copy(),
                     mode.contact_held, mode.wheel_names)

    def mass_matrix(self, q) -> np.ndarray:
        """``M_s(q)`` (a new array) through the one-sample buffers."""
        return np.array(self._mass.one(q=q)["M"])

    def kinetic_energy(self, y) -> float:
        q, qo, v, vo = self.split(y)
        M = self._mass.one(q=q)["M"]
        return 0.5 * float(v @ M @ v) + 0.5 * float(vo @ (self.mo * vo))

    # --- kinematics of the rows -----------------------------------------------------------
    def row_velocities(self, q, v, qo, vo, s) -> np.ndarray:
        """``A V``: the gap rate ``gdot`` (row 0) and the wheels' lateral velocities ``u_i``.

        The link twists ``J v`` (world frame) from the compiled Jacobians; the wheel row of
        link ``i`` is ``(-sin phi_i, cos phi_i, wheel_offset_i)`` on its twist, the contact
        row the normal ``n = side (-sin phi_k, cos phi_k)`` on the velocity of the object's
        contact point relative to the link's, less the sliding term ``side omega_k (s -
        c_k)``. On Python floats: for a handful of links, faster than NumPy's small-array
        calls (and the same operations in the same order)."""
        self.njev += 1
        J = self._jac.one(q=q)[self._jac_index]
        tw = (J @ v).tolist()  # (vx, vy, omega) of each link, flat
        qs = q.tolist()
        woff = self._woff
        k = self.k
        sin, cos = math.sin, math.cos
        out = [0.0]
        phi = qs[2]  # phi_1 = theta, phi_{j+1} = phi_j + q_j
        spk = cpk = 0.0
        for i in range(self.nl):
            if i:
                phi += qs[2 + i]
            sp, cp = sin(phi), cos(phi)
            if i == k:
                spk, cpk = sp, cp
            out.append(-sp * tw[3 * i] + cp * tw[3 * i + 1] + woff[i] * tw[3 * i + 2])
        sig = self.sigma
        n0, n1 = sig * -spk, sig * cpk
        c, sn = math.cos(qo[2]), math.sin(qo[2])
        rx, ry = self._rho
        Rr = (c * rx - sn * ry, sn * rx + c * ry)
        vo0, vo1, vo2 = vo.tolist()
        pdot = (vo0 - vo2 * Rr[1], vo1 + vo2 * Rr[0])
        out[0] = (n0 * (pdot[0] - tw[3 * k]) + n1 * (pdot[1] - tw[3 * k + 1])
                  - sig * tw[3 * k + 2] * (s - self.c_k))
        return np.array(out)

    # --- right-hand side within a mode ----------------------------------------------------
    def rates(self, t, y, mode, tau_fn):
        """Everything at ``(t, y)`` in ``mode`` with the torques ``tau_fn(t, y, mode)``: the
        tuple ``(ydot, lam, gap, s, AV, (tau, sr, norm_a_obj, norm_qdd))``.

        ``ydot``, ``lam`` and ``AV`` are new arrays; ``tau`` is what the torque function
        returned. The last evaluation is cached: the integrator's event functions ask again
        at the same point."""
        yb = y.tobytes()
        c = self._cache
        if c is not None and c[0] == t and c[1] is mode and c[2] is tau_fn and c[3] == yb:
            return c[4]
        self.nfev += 1
        ns, nx = self.ns, self.nx
        q, qo, v, vo = y[:ns], y[ns:nx], y[nx:nx + ns], y[nx + ns:2 * nx]
        tau = tau_fn(t, y, mode)
        cd = self.cd
        iqdd, iaobj, ilam, igap, is_, isr, inao, inqdd, ipiv, idel = self._out_index
        q0, qo0 = at_origin(q, qo)
        o = tuple(cd.one(q=q0, v=v, tau=tau, q_obj=qo0, v_obj=vo, free=mode.free,
                         lam_fixed=mode.lam_fixed))
        F = mode.free_idx
        reg = 0.0
        if F.size and not o[ipiv][0] > PIVOT_TOL:
            # dependent held rows: least-norm forces (as in snakecg.solver)
            self.singular += 1
            scale = np.abs(np.diagonal(o[idel])).max()
            reg = REGULARIZATION * max(scale, 1e-300)
            o = tuple(cd.one(q=q0, v=v, tau=tau, q_obj=qo0, v_obj=vo, free=mode.free,
                             lam_fixed=mode.lam_fixed, regularization=reg))
            cd.set(regularization=0.0)
        lam = o[ilam].copy()
        gap = float(o[igap][0])
        s = float(o[is_][0])
        AV = self.row_velocities(q, v, qo, vo, s)
        if self.alpha > 0 and F.size:
            # Baumgarte: the held rows' accelerations are -2 alpha A_F V (- alpha^2 g for the
            # contact) instead of 0; the forces change by -G_FF^-1 of that, then the
            # accelerations are evaluated again with every force given
            a = self.alpha
            rhs = 2.0 * a * AV[F]
            if mode.contact_held:
                rhs[0] += a * a * gap
            G = o[idel][mode.ff]
            if reg:  # the same Tikhonov term: the whole right-hand side least-norm
                G = G + reg * np.eye(len(F))
            x, info = self._posv(G, rhs)[1:]  # Cholesky solve of G_FF x = rhs (SPD)
            if info != 0:
                x = np.linalg.lstsq(G, rhs, rcond=None)[0]
            lam[F] -= x
            o = tuple(cd.one(free=self._zeros_nc, lam_fixed=lam))
        p_tau = float(tau @ v[3:])
        sl = mode.slide_idx
        p_fric = float(lam[sl] @ AV[sl]) if sl.size else 0.0
        p_obj = float(self.f_obj @ vo)
        ydot = np.concatenate((v, vo, o[iqdd], o[iaobj], (p_tau, p_fric, p_obj)))
        extras = (tau, float(o[isr][0]), float(o[inao][0]), float(o[inqdd][0]))
        val = (ydot, lam, gap, s, AV, extras)
        self._cache = (t, mode, tau_fn, yb, val)
        return val

    # --- linear maps at a state (events only) ---------------------------------------------
    def linear_maps(self, y, tau):
        """``Q = I^-1 A^T`` (nx, n_c), ``G_c``, gap, s and ``A V`` at ``y`` (one evaluation
        of the generated ``contact_system``: ``M_s^-1 A_s^T`` over ``I_obj^-1 A_o^T``)."""
        q, qo, v, vo = self.split(y)
        q0, qo0 = at_origin(q, qo)
        o = self._cs.one(q=q0, v=v, tau=tau, q_obj=qo0, v_obj=vo)
        Q = np.vstack([o["qdd_from_lam"], o["a_obj_from_lam"]])
        G = np.array(o["delassus"])
        gap, s = float(o["gap"][0]), float(o["s"][0])
        AV = self.row_velocities(q, v, qo, vo, s)
        return Q, G, gap, s, AV

    def project(self, y, tau, rows, *, positions: bool):
        """Mass-weighted projection of the velocities onto ``A_F V = 0`` for ``rows`` (and of
        the positions onto ``g = 0`` when the contact is among them and ``positions``).

        Returns the new state, the impulse ``Lam_F`` and the kinetic-energy change."""
        y = y.copy()
        rows = np.asarray(rows, dtype=int)
        nx = self.nx
        if positions and 0 in rows:
            for _ in range(3):
                Q, G, gap, s, AV = self.linear_maps(y, tau)
                if abs(gap) <= 1e-15 * max(1.0, self.l_k):
                    break
                y[:nx] -= Q[:, 0] * (gap / G[0, 0])
        Q, G, gap, s, AV = self.linear_maps(y, tau)
        if rows.size == 0:
            return y, np.zeros(0), 0.0
        GF = G[np.ix_(rows, rows)]
        Lam = -np.linalg.solve(GF, AV[rows])
        y[nx:2 * nx] += Q[:, rows] @ Lam
        dE = -0.5 * float(Lam @ GF @ Lam)
        return y, Lam, dE
