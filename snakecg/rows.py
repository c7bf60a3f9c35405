"""Near-dependent constraint rows, solved from the rows themselves (no squared matrix).

The compiled ``constrained_dynamics`` solves the held rows through the Delassus matrix
``G_c = A I^-1 A^T``: its condition number is the square of that of the rows
``R = L^-1 A^T`` (``I = L L^T``), so rows that are dependent to within ``d`` (two wheels at
nearly the same point, ``d ~ 1e-7``) lose everything at ``d^2 ~ 1e-14``. Here the same
complementarity problem is solved with the QR factorization of the held rows in the
``I^-1`` metric: in ``z = L^T a`` (``a`` the accelerations of snake and object)

    z = z_0 + R_H lam_H,   R_H^T z = -Adot_H v,   z_0 = L^-1 (f - p + A_F^T lam_F),

so with ``R_H = Q R_1``: ``z = (1 - Q Q^T) z_0 - Q R_1^-T Adot_H v`` and
``lam_H = -R_1^-1 (Q^T z_0 + R_1^-T Adot_H v)``. The accelerations, norms and ``sr`` carry a
relative error of about ``1e-16 / sqrt(pivot ratio)`` instead of ``1e-16 / pivot ratio``;
the individual forces of nearly dependent rows, about ``1e-16 / sqrt(pivot ratio)`` of their
(large) size.

Everything comes from the generated kinematics (``mass_matrix``, ``link_jacobians``,
``link_poses``, ``link_bias_accelerations``, ``contact_row_local``) and the wheel row of
``derive/constraints.py`` (``a_w = (-sin phi, cos phi, wheel_offset)``), written here in NumPy.
"""

from __future__ import annotations

import numpy as np

from . import kernels
from .engine.rules import (
    DEPENDENT,
    IMPOSSIBLE,
    MASS_SINGULAR,
    MASS_TOL,
    NO_ANSWER,
    NOT_FINITE,
    REASONS,
    ROW_TOL,
    WEAK,
    reason_of,
)

__all__ = ["RowSystem", "mass_pivot_ratio", "ROW_TOL", "REASONS", "reason_of"]







def mass_pivot_ratio(M: np.ndarray) -> np.ndarray:
    """Smallest Cholesky pivot of each ``M`` relative to its diagonal, ``(N,)`` in [0, 1]
    (0 where ``M`` is not numerically positive definite)."""
    d = np.sqrt(np.abs(np.diagonal(M, axis1=-2, axis2=-1)))
    d = np.where(d > 0, d, 1.0)
    S = M / d[..., :, None] / d[..., None, :]
    out = np.zeros(M.shape[0])
    try:
        L = np.linalg.cholesky(S)
        out = np.min(np.diagonal(L, axis1=-2, axis2=-1), axis=-1) ** 2
    except np.linalg.LinAlgError:  # some sample is not positive definite: one at a time
        for i in range(M.shape[0]):
            try:
                out[i] = np.min(np.diagonal(np.linalg.cholesky(S[i]))) ** 2
            except np.linalg.LinAlgError:
                out[i] = 0.0
    return np.where(np.isfinite(out), out, 0.0)


class RowSystem:
    """The dense system of ``n`` samples: ``I``, its Cholesky factor, rows ``A``, ``Adot v``,
    forces ``f - p``; :meth:`call` has the interface of the compiled ``constrained_dynamics``
    for :func:`snakecg.solver.solve_active_set`."""

    def __init__(self, model, base: dict, n: int):
        ns, nl, nc = model.n_coordinates, model.n_links, model.n_constraints

        def take(k):
            a = base[k]
            return np.ascontiguousarray(np.broadcast_to(a, (n, a.shape[1])))

        q, v, tau = take("q"), take("v"), take("tau")
        q_obj, v_obj, f_obj, rho = take("q_obj"), take("v_obj"), take("f_obj"), take("rho")
        be, K = model.backend, model.parameters
        (M,) = be("mass_matrix", n, [q, K])
        (J,) = be("link_jacobians", n, [q, K])
        J = J.reshape(n, nl, 3, ns)
        (poses,) = be("link_poses", n, [q, K])  # (n, 3, nl)
        (bias,) = be("link_bias_accelerations", n, [q, v, K])  # (n, 3, nl)
        (h,) = be("bias_forces", n, [q, v, K])
        twist = np.einsum("nlij,nj->nli", J, v)
        m_obj, i_obj = model.scene.object_mass, model.scene.object_inertia
        self.I_obj = np.diag([m_obj, m_obj, i_obj])
        nd = ns + 3
        I = np.zeros((n, nd, nd))
        I[:, :ns, :ns] = M
        I[:, ns:, ns:] = self.I_obj
        A = np.zeros((n, nc, nd))
        Adv = np.zeros((n, nc))
        k = model.scene.contact_link - 1
        outs = be("contact_row_local", n, [
            np.ascontiguousarray(poses[:, :, k]), np.ascontiguousarray(twist[:, k]),
            np.ascontiguousarray(bias[:, :, k]), np.array([model.robot.com[k]]), q_obj,
            v_obj, rho, model.scene_inputs["side"]])
        o = dict(zip(be.signatures["contact_row_local"].out_names, outs))
        A[:, 0, :ns] = np.einsum("ni,nij->nj", o["a_link"][:, 0, :], J[:, k])
        A[:, 0, ns:] = o["g_obj"][:, 0, :]
        Adv[:, 0] = o["adot_v"][:, 0, 0]
        self.gap, self.s = o["gap"][:, 0, 0], o["s"][:, 0, 0]
        for i in range(nl):
            if not model.present[i + 1]:
                continue
            phi = poses[:, 2, i]
            a_w = np.stack([-np.sin(phi), np.cos(phi),
                            np.full(n, model.scene_inputs["wheel_offset"][i])], axis=1)
            om = twist[:, i, 2]
            a_w_dot = np.stack([-np.cos(phi) * om, -np.sin(phi) * om, np.zeros(n)], axis=1)
            A[:, i + 1, :ns] = np.einsum("ni,nij->nj", a_w, J[:, i])
            Adv[:, i + 1] = (np.sum(a_w_dot * twist[:, i], axis=1)
                             + np.sum(a_w * bias[:, :, i], axis=1))
        f = np.zeros((n, nd))
        f[:, 3:ns] = tau
        f[:, :ns] -= h[:, :, 0] if h.ndim == 3 else h
        f[:, ns:] = f_obj
        M = np.array(M)
        self.n, self.ns, self.nc = n, ns, nc
        with np.errstate(all="ignore"):
            # a sample whose system is not finite, or whose I is not numerically positive
            # definite, is never handed to LAPACK (which may spin on inf): ok False, NaN out
            ok = (np.all(np.isfinite(I.reshape(n, -1)), axis=1)
                  & np.all(np.isfinite(A.reshape(n, -1)), axis=1)
                  & np.all(np.isfinite(Adv), axis=1) & np.all(np.isfinite(f), axis=1))
            L = np.broadcast_to(np.eye(nd), (n, nd, nd)).copy()
            for j in np.flatnonzero(ok):
                try:
                    L[j] = np.linalg.cholesky(I[j])
                except np.linalg.LinAlgError:
                    ok[j] = False
            ok &= np.all(np.isfinite(L.reshape(n, -1)), axis=1)
            ok &= np.all(np.diagonal(L, axis1=1, axis2=2) > 0, axis=1)
            L[~ok] = np.eye(nd)
            A[~ok] = 0.0
            Adv[~ok] = 0.0
            f[~ok] = 0.0
            I[~ok] = np.eye(nd)
            M[~ok] = np.eye(ns)
            Rall = np.linalg.solve(L, np.swapaxes(A, 1, 2))  # L^-1 A^T: (n, nd, nc)
            ok &= np.all(np.isfinite(Rall.reshape(n, -1)), axis=1)
            Rall[~ok] = 0.0
            G = np.swapaxes(Rall, 1, 2) @ Rall
            ok &= np.all(np.isfinite(G.reshape(n, -1)), axis=1)
            G[~ok] = 0.0
        self.ok = ok
        self.M, self.I, self.A, self.Adv, self.f = M, I, A, Adv, f
        self.mass_ratio = mass_pivot_ratio(M)
        self.L, self.Rall, self.G = L, Rall, G

    def call(self, idx, free, lam_fixed, reg):
        """``constrained_dynamics`` outputs for samples ``idx`` with held rows ``free``."""
        idx = np.asarray(idx)
        m = len(idx)
        nc, ns = self.nc, self.ns
        free = np.broadcast_to(free, (m, nc)).astype(bool)
        lam_fixed = np.broadcast_to(lam_fixed, (m, nc))
        L, R, Adv = self.L[idx], self.Rall[idx], self.Adv[idx]
        z0 = np.linalg.solve(L, (self.f[idx] + np.einsum("nci,nc->ni", self.A[idx],
                                                         lam_fixed))[:, :, None])[:, :, 0]
        lam = np.array(lam_fixed, dtype=float)
        z = z0.copy()
        ratio = np.ones(m)
        good = self.ok[idx] & np.all(np.isfinite(z0), axis=1)
        for j in range(m):  # the held set differs per sample; a few rows each
            H = np.flatnonzero(free[j])
            if not good[j]:  # not finite: nothing to factor (NaN, flagged by finish)
                ratio[j] = np.nan
                continue
            if H.size == 0:
                continue
            try:
                lam_h, z[j], ratio[j] = _held_rows(R[j][:, H], z0[j], Adv[j][H])
            except np.linalg.LinAlgError:  # LAPACK gave up: no answer for this sample
                good[j] = False
                ratio[j] = np.nan
                continue
            lam[j, H] = lam_h
        z[~good] = np.nan
        lam[~good] = np.nan
        a = np.linalg.solve(np.swapaxes(L, 1, 2), z[:, :, None])[:, :, 0]
        qdd, a_obj = a[:, :ns], a[:, ns:]
        w = np.einsum("nci,ni->nc", self.A[idx], a) + Adv
        norm_qdd = np.einsum("ni,nij,nj->n", qdd, self.M[idx], qdd)
        norm_a = np.einsum("ni,ij,nj->n", a_obj, self.I_obj, a_obj)
        Rl = np.einsum("nic,nc->ni", R, lam)
        tot = norm_a + norm_qdd
        return {
            "qdd": qdd, "a_obj": a_obj, "lam": lam, "w": w, "gap": self.gap[idx],
            "s": self.s[idx], "norm_lambda": np.sum(Rl * Rl, axis=1), "norm_a_obj": norm_a,
            "norm_qdd": norm_qdd, "sr": norm_a / np.maximum(tot, 1e-300),
            "pivot_ratio": ratio, "delassus": self.G[idx],
            "b": np.einsum("nic,ni->nc", R, z0) + Adv,
        }


def _held_rows(RH, z0, adv):
    """The held rows' forces, ``z`` and pivot ratio of one sample (module docstring)."""
    Q, R1 = np.linalg.qr(RH)
    col = np.linalg.norm(RH, axis=0)
    dg = np.abs(np.diag(R1))
    ratio = float(np.min((dg / np.where(col > 0, col, 1.0)) ** 2))
    if not ratio > ROW_TOL:  # dependent even for the rows: least-norm forces
        lam_h = -np.linalg.lstsq(RH, z0, rcond=1e-10)[0]
        lam_h -= np.linalg.lstsq(RH.T @ RH, adv, rcond=1e-10)[0]
        return lam_h, z0 + RH @ lam_h, ratio
    y = np.linalg.solve(R1.T, adv)
    z = z0 - Q @ (Q.T @ z0 + y)
    return -np.linalg.solve(R1, Q.T @ z0 + y), z, ratio





def _sane(o, idx):
    """Samples whose results are physically possible: finite, norms >= 0, 0 <= sr <= 1
    (to rounding)."""
    norms = np.stack([o["norm_qdd"][idx], o["norm_a_obj"][idx], o["norm_lambda"][idx]], 1)
    scale = np.abs(norms).max(axis=1)
    fin = np.all(np.isfinite(norms), axis=1) & np.isfinite(o["sr"][idx])
    fin &= np.all(np.isfinite(o["qdd"][idx]), axis=1) & np.all(np.isfinite(o["lam"][idx]), 1)
    with np.errstate(invalid="ignore"):
        ok = np.all(norms >= -1e-12 * scale[:, None], axis=1)
        ok &= (o["sr"][idx] >= -1e-12) & (o["sr"][idx] <= 1 + 1e-12)
    return fin & ok


def finish(model, base: dict, n: int, sol, max_iter=None):
    """Complete an active-set solution of the compiled path (in place, returned):

    * samples whose held rows are weakly independent (Delassus pivot ratio below
      :data:`WEAK`) or dependent are solved again from the rows themselves
      (:class:`RowSystem`); they stay ``singular`` only when the rows are dependent even so
      (pivot ratio of the rows below :data:`ROW_TOL`);
    * ``sol.conditioning`` (N,): the smallest of the mass matrix's pivot ratio and the rows'
      (``sqrt`` of the Delassus pivot ratio where solved from the rows), 0 for singular;
    * a sample whose mass matrix is not numerically positive definite (pivot ratio below
      ``1e-13``) or whose results are physically impossible (non-finite, a negative norm,
      ``sr`` outside [0, 1]) is flagged ``singular`` with conditioning 0, and its results
      are NaN (no row state: every row reads ``none``);
    * ``sol.reason`` (N,): the code of :data:`REASONS` of each flagged sample (0 otherwise).
    """
    from .solver import ABSENT, PIVOT_TOL, solve_active_set

    o = sol.outputs
    q = np.ascontiguousarray(np.broadcast_to(base["q"], (n, base["q"].shape[1])))
    M = kernels.call(model.backend, "mass_matrix", n, q=q, K=model.parameters)["M"]
    mass = mass_pivot_ratio(M)
    piv = np.where(sol.singular, 0.0, np.minimum(o["pivot_ratio"], 1.0))
    cond = piv.copy()
    weak = np.flatnonzero(sol.singular | ~(piv > WEAK))
    weak = weak[mass[weak] > PIVOT_TOL]
    unfinite = np.zeros(n, bool)
    with np.errstate(all="ignore"):
        unfinite |= ~np.all(np.isfinite(o["delassus"].reshape(n, -1)), axis=1)
    if weak.size:
        sub = {k: (v if v.shape[0] == 1 else v[weak]) for k, v in base.items()}
        rs = RowSystem(model, sub, len(weak))
        again = solve_active_set(lambda idx, free, lam_fixed, reg: rs.call(idx, free, lam_fixed,
                                                                           reg),
                                 len(weak), model.present, model.bounds, max_iter=max_iter)
        for k in o:
            if k in again.outputs:
                o[k][weak] = again.outputs[k].reshape(o[k][weak].shape)
        sol.state[weak] = again.state
        ratio = np.minimum(again.outputs["pivot_ratio"], 1.0)
        dep = ~(ratio > ROW_TOL)
        sol.singular[weak] = dep
        cond[weak] = np.where(dep, 0.0, np.sqrt(ratio))
        unfinite[weak] |= ~rs.ok
    reason = np.where(sol.singular, DEPENDENT, 0)
    sane = _sane(o, np.arange(n))
    reason[~sane] = IMPOSSIBLE
    reason[unfinite & ~sane] = NOT_FINITE
    reason[~(mass > MASS_TOL)] = MASS_SINGULAR
    sol.singular |= reason > 0
    lost = np.isin(reason, NO_ANSWER)
    if np.any(lost):  # no answer: NaN, never an impossible number
        for k in ("qdd", "a_obj", "lam", "w", "norm_lambda", "norm_a_obj", "norm_qdd", "sr"):
            o[k][lost] = np.nan
        sol.state[lost] = ABSENT
    cond = np.where(sol.singular, 0.0, np.minimum(cond, mass))
    sol.conditioning = cond
    sol.reason = reason
    return sol
