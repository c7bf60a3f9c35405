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

import numpy as np

from ..native import BoundFunction
from ..solver import PIVOT_TOL, REGULARIZATION
from .records import State

__all__ = ["Dynamics", "N_WORK"]

N_WORK = 3  # work integrals: joint torques, kinetic friction, object wrench


class Dynamics:
    """The equations of one run: the model's generated functions bound to the run's
    constants (parameters, object, contact point ``rho`` in the object frame, wrench
    ``f_obj``), the scene's constants, and counters of the evaluations (``nfev`` right-hand
    sides, ``njev`` row-velocity Jacobians, ``singular`` samples with dependent held rows).
    """

    def __init__(self, model, rho: np.ndarray, f_obj: np.ndarray, alpha: float):
        from scipy.linalg.lapack import dposv

        scene = model.scene
        self.scene = scene
        ns, na, nl, nc = (model.n_coordinates, model.n_joints, model.n_links,
                          model.n_constraints)
        self.ns, self.na, self.nl, self.nc = ns, na, nl, nc
        self.nx = ns + 3
        self.ny = 2 * self.nx + N_WORK
        self.rho, self.f_obj, self.alpha = rho, f_obj, alpha
        self.present = model.present.copy()
        self.bounds = model.bounds.copy()
        self.k = scene.contact_link - 1
        self.sigma = scene.side_sign
        self.c_k = float(scene.robot.com[self.k])
        self.l_k = float(scene.robot.length[self.k])
        self.woff = np.asarray(scene.wheel_offset, dtype=float)
        self.mo = np.array([scene.object_mass, scene.object_mass, scene.object_inertia])
        be = model.backend
        self.cd = BoundFunction(be, "constrained_dynamics", {
            "K": model.parameters, "contact_link": model._contact_link, "side": model._side,
            "object_mass": model._object_mass, "object_inertia": model._object_inertia,
            "rho": rho, "wheel_offset": model._wheel_offset, "f_obj": f_obj,
            "regularization": np.zeros(1)})
        self._jac = BoundFunction(be, "link_jacobians", {"K": model.parameters})
        self._mass = BoundFunction(be, "mass_matrix", {"K": model.parameters})
        self._cache_key = None
        self._cache_val = None
        self._zeros_nc = np.zeros(nc)
        self._posv = dposv
        self.nfev = 0
        self.njev = 0
        self.singular = 0

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

    def kinetic_energy(self, y) -> float:
        q, qo, v, vo = self.split(y)
        M = self._mass.one(q=q)["M"]
        return 0.5 * float(v @ M @ v) + 0.5 * float(vo @ (self.mo * vo))

    # --- kinematics of the rows -----------------------------------------------------------
    def row_velocities(self, q, v, qo, vo, s) -> np.ndarray:
        """``A V``: the gap rate ``gdot`` (row 0) and the wheels' lateral velocities ``u_i``."""
        self.njev += 1
        J = self._jac.one(q=q)["J"]
        tw = (J @ v).reshape(self.nl, 3)
        phi = np.cumsum(q[2:])  # phi_1 = theta, phi_{j+1} = phi_j + q_j
        sp, cp = np.sin(phi), np.cos(phi)
        out = np.empty(self.nc)
        out[1:] = -sp * tw[:, 0] + cp * tw[:, 1] + self.woff * tw[:, 2]
        k, sig = self.k, self.sigma
        n = sig * np.array([-sp[k], cp[k]])
        c, sn = math.cos(qo[2]), math.sin(qo[2])
        rx, ry = self.rho
        Rr = (c * rx - sn * ry, sn * rx + c * ry)
        pdot = (vo[0] - vo[2] * Rr[1], vo[1] + vo[2] * Rr[0])
        out[0] = (n[0] * (pdot[0] - tw[k, 0]) + n[1] * (pdot[1] - tw[k, 1])
                  - sig * tw[k, 2] * (s - self.c_k))
        return out

    # --- right-hand side within a mode ----------------------------------------------------
    def rates(self, t, y, mode, tau_fn):
        """Everything at ``(t, y)`` in ``mode`` with the torques ``tau_fn(t, y, mode)``: the
        tuple ``(ydot, lam, gap, s, AV, (tau, sr, norm_a_obj, norm_qdd, p_cons))``.

        The last evaluation is cached: the integrator's event functions ask again at the same
        point."""
        key = (t, mode, tau_fn)
        yb = y.tobytes()
        if self._cache_key is not None and self._cache_key[0] == key and self._cache_key[1] == yb:
            return self._cache_val
        self.nfev += 1
        q, qo, v, vo = self.split(y)
        tau = tau_fn(t, y, mode)
        cd = self.cd
        out = cd.one(q=q, v=v, tau=tau, q_obj=qo, v_obj=vo, free=mode.free,
                     lam_fixed=mode.lam_fixed)
        if mode.free_idx.size and not out["pivot_ratio"][0] > PIVOT_TOL:
            # dependent held rows: least-norm forces (as in snakecg.solver)
            self.singular += 1
            scale = np.abs(np.diagonal(out["delassus"])).max()
            out = cd.one(q=q, v=v, tau=tau, q_obj=qo, v_obj=vo, free=mode.free,
                         lam_fixed=mode.lam_fixed,
                         regularization=REGULARIZATION * max(scale, 1e-300))
            cd.set(regularization=0.0)
        lam = out["lam"].copy()
        gap = float(out["gap"][0])
        s = float(out["s"][0])
        AV = self.row_velocities(q, v, qo, vo, s)
        F = mode.free_idx
        if self.alpha > 0 and F.size:
            a = self.alpha
            c = 2.0 * a * AV[F]
            if mode.contact_held:
                c[0] += a * a * gap
            G = out["delassus"][mode.ff]
            x, info = self._posv(G, c)[1:]  # Cholesky solve of G_FF x = c (SPD)
            if info != 0:
                x = np.linalg.lstsq(G, c, rcond=None)[0]
            lam[F] -= x
            out = cd.one(free=self._zeros_nc, lam_fixed=lam)
        ydot = np.empty(self.ny)
        nx = self.nx
        ydot[:self.ns] = v
        ydot[self.ns:nx] = vo
        ydot[nx:nx + self.ns] = out["qdd"]
        ydot[nx + self.ns:2 * nx] = out["a_obj"]
        p_tau = float(tau @ v[3:])
        sl = mode.slide_idx
        p_fric = float(lam[sl] @ AV[sl]) if sl.size else 0.0
        p_obj = float(self.f_obj @ vo)
        ydot[2 * nx:] = (p_tau, p_fric, p_obj)
        # power of the held rows' forces: zero on the constraints (a drift diagnostic; not
        # integrated: off the constraints, at the integrator's stages, it is noise)
        p_cons = float(lam[F] @ AV[F]) if F.size else 0.0
        extras = (np.array(tau, dtype=float), float(out["sr"][0]), float(out["norm_a_obj"][0]),
                  float(out["norm_qdd"][0]), p_cons)
        val = (ydot, lam, gap, s, AV, extras)
        self._cache_key = (key, yb)
        self._cache_val = val
        return val

    # --- linear maps at a state (events only) ---------------------------------------------
    def linear_maps(self, y, tau):
        """``Q = I^-1 A^T`` (nx, n_c), ``G_c``, gap, s and ``A V`` at ``y``."""
        q, qo, v, vo = self.split(y)
        nc = self.nc
        lf = np.vstack([np.zeros(nc), np.eye(nc)])
        outs = self.cd.many(nc + 1, q=q, v=v, tau=tau, q_obj=qo, v_obj=vo,
                            free=np.zeros((nc + 1, nc)), lam_fixed=lf,
                            regularization=np.zeros(1))
        qdd, a_obj = outs["qdd"], outs["a_obj"]
        Q = np.hstack([qdd[1:] - qdd[0], a_obj[1:] - a_obj[0]]).T
        G = outs["delassus"][0]
        gap, s = float(outs["gap"][0, 0]), float(outs["s"][0, 0])
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
