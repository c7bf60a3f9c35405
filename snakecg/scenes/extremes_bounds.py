"""Certified bounds of the metrics of a general scene over the input ellipsoid's boundary,
for scenes whose pieces are not polyhedra (Coulomb and anisotropic sets): a branch and bound
on a cover of the sphere by the compiled forward solve.

Why it is a certificate: at rest the accelerations are the proximal point of the free ones in
the inertia metric ``|x|_M`` (Gauss's principle: ``a = argmin 1/2 |a - a_free|_M^2 + phi(a)``,
``phi`` convex), so ``a`` and ``a - a_free`` are 1-Lipschitz functions of ``a_free``, whose
``M``-norm distance is ``|du|`` in whitened torques ``u = L^T tau`` (``|M^-1 B dtau|_M^2 =
dtau^T N dtau``, eq. 31). ``M`` is block diagonal (snake, objects), so the square root of
every norm (``norm_qdd``, each object's, their sum, ``norm_lambda = |a - a_free|_M^2``) moves
by at most ``|du|``; on the unit sphere ``|a_free|_M = 1`` and every norm lies in [0, 1].

The sphere is covered by the cells of a grid on the faces of the cube ``[-1, 1]^n_a``,
radially projected (1-Lipschitz outside the unit ball): a cell of half-size ``e`` lies within
``rho = e sqrt(n_a - 1)`` of its centre's image. At every centre the forward solve gives the
value ``v``; on the cell ``sqrt(value) <= sqrt(v) + rho`` (and ``>= sqrt(v) - rho``). For
``sr = Omega / D``: ``sqrt(Omega) <= sqrt(Omega_c) + rho``, ``sqrt(D) >= sqrt(D_c) - rho``.
Cells whose bound may beat the best value by more than ``gap`` (absolute: the free motion's
norm is 1) are split in ``2^(n_a - 1)``, until none is left or ``budget`` solves are spent. A
pad of 1e-7 (the solve's tolerance is 1e-9) covers rounding. Not covered: ``sr`` where the
system barely moves (``(sqrt(D_c) + rho)^2 < gap``: there ``sr`` is 0/0 in the limit, and such
cells are not split), and ``min_kept`` (the best sample with every contact of an object held).
"""

from __future__ import annotations

import itertools

import numpy as np

from .packing import CR_W, SO_NC
from .solve import HELD, solve

__all__ = ["Sampler", "bounds", "PAD"]

#: Absolute pad on the square roots of the norms for the solve's rounding.
PAD = 1e-7


class Sampler:
    """The compiled forward solve of one configuration (:class:`~snakecg.scenes.maps.Problem`)
    at many torques, the rows found once; the metrics of every sample."""

    def __init__(self, model, p):
        self.model, self.p = model, p
        nb = p.n_blocks
        self.kind = np.array(p.kind, dtype=np.int64).reshape(1, nb)
        self.start = np.array(p.start, dtype=np.int64).reshape(1, nb)
        self.par = np.array(p.par, dtype=float).reshape(1, nb, 3)
        self.count = 0
        self.kept_blocks = [b for b, lab in enumerate(p.rows.labels) if lab[0] == "contact"
                            and "object" in (p.rows.contacts[lab[1]].a[0],
                                             p.rows.contacts[lab[1]].b[0])]

    def __call__(self, tau) -> dict:
        """``{metric: (K,)}``, ``_D`` (``|a|_M^2``), ``_ok`` (solved), ``_kept``, ``sr`` and
        ``_a`` (the accelerations, K x n); with contact friction also ``_solutions`` (the
        forward solve's count of Coulomb solutions per sample)."""
        p, K = self.p, tau.shape[0]
        self.count += K
        f = tau @ p.B.T
        if p.tangent:  # Coulomb at the contacts: the model's forward (its fixed point)
            return self._forward(tau, f)
        m, nb = p.A.shape[0], p.n_blocks
        if nb:
            A = np.broadcast_to(p.A, (K, m, p.n))
            kind = np.broadcast_to(self.kind, (K, nb))
            start = np.broadcast_to(self.start, (K, nb))
            par = np.broadcast_to(self.par, (K, nb, 3))
        else:
            A, kind = np.zeros((K, 1, p.n)), np.full((K, 1), -1)
            start, par = np.zeros((K, 1), dtype=np.int64), np.zeros((K, 1, 3))
        res = solve(self.model.core, np.broadcast_to(p.M, (K, p.n, p.n)), f, A,
                    np.full(K, m), kind, start, par)
        a = res["a"]
        ns, no = p.n_s, p.n_o
        out = {"norm_qdd": np.einsum("ki,ij,kj->k", a[:, :ns], p.M_s, a[:, :ns])}
        total = np.zeros(K)
        for j in range(no):
            sl = slice(ns + 3 * j, ns + 3 * j + 3)
            out[f"norm_a_obj[{j + 1}]"] = np.einsum("ki,ij,kj->k", a[:, sl], p.M[sl, sl],
                                                     a[:, sl])
            total = total + out[f"norm_a_obj[{j + 1}]"]
        out["norm_a_obj"] = total
        d = a - f @ p.Minv.T
        out["norm_lambda"] = np.einsum("ki,ij,kj->k", d, p.M, d)
        D = total + out["norm_qdd"]
        out["_D"] = D
        free = np.einsum("ki,ij,kj->k", f, p.Minv, f)
        out["_free"] = free
        # eq. (30); 0 where the system does not move: |a|_M^2 below 1e-12 of the free
        # motion's, where the ratio is one of rounding errors
        moving = D > 1e-12 * free
        out["sr"] = np.where(moving, total / np.where(moving, D, 1.0), 0.0)
        out["_ok"] = res["info"]["status"] == 0
        out["_a"] = a
        st = res["state"]
        out["_kept"] = (np.all(st[:, self.kept_blocks] == HELD, axis=1) if self.kept_blocks
                        else np.ones(K, bool))
        return out


    def _forward(self, tau, f) -> dict:
        """The metrics from the model's forward solve (contacts with Coulomb friction: the
        solve of :mod:`snakecg.scenes.solve` alone does not take them)."""
        p, K = self.p, tau.shape[0]
        res = self.model.forward(np.broadcast_to(p.q, (K, p.n_s)), tau)
        no = p.n_o
        if no:
            a = np.hstack([res.qdd, np.asarray(res.a_obj).reshape(K, 3 * no)])
            each = np.asarray(res.norm_a_obj_each).reshape(K, no)
        else:
            a = np.asarray(res.qdd).reshape(K, p.n_s)
        out = {"norm_qdd": np.asarray(res.norm_qdd, dtype=float),
               "norm_a_obj": np.asarray(res.norm_a_obj, dtype=float)}
        for j in range(no):
            out[f"norm_a_obj[{j + 1}]"] = each[:, j]
        d = a - f @ p.Minv.T  # (norm_lambda: |a - a_free|_M^2, friction forces counted)
        out["norm_lambda"] = np.einsum("ki,ij,kj->k", d, p.M, d)
        D = out["norm_a_obj"] + out["norm_qdd"]
        free = np.einsum("ki,ij,kj->k", f, p.Minv, f)
        moving = D > 1e-12 * free
        out.update(_D=D, _free=free, _a=a, _ok=np.asarray(res.status) == 0,
                   sr=np.where(moving, out["norm_a_obj"] / np.where(moving, D, 1.0), 0.0),
                   _solutions=np.asarray(res.solutions))
        # kept: every contact of an object touching (its record's state 0: held)
        rows, off = res._out, self.model.packed.offset["contacts"]
        kept = np.ones(K, bool)
        for c in range(int(rows[:, SO_NC].max(initial=0))):
            r = rows[:, off + CR_W * c: off + CR_W * (c + 1)]
            obj = (r[:, 0] == 1) | (r[:, 2] == 1)
            kept &= ~(obj & (c < rows[:, SO_NC]) & (r[:, 12] != 0))
        out["_kept"] = kept
        return out


def _to_sphere(face, c):
    """Cube-face points (face = (axis, sign)), free coordinates ``c`` (K, d-1), radially
    onto the unit sphere."""
    axis, sign = face
    K, dm1 = c.shape
    x = np.empty((K, dm1 + 1))
    x[:, axis] = sign
    x[:, [i for i in range(dm1 + 1) if i != axis]] = c
    return x / np.linalg.norm(x, axis=1, keepdims=True)


def _cell_bounds(vals, rho, names):
    """Upper and lower bounds of every metric on the cells (centre values ``vals``)."""
    ub, lb = {}, {}
    for m in names:
        if m == "sr":
            continue
        s = np.sqrt(np.maximum(vals[m], 0.0))
        ub[m] = np.minimum((s + rho + PAD) ** 2, 1.0 + 1e-9)
        lb[m] = np.maximum(s - rho - PAD, 0.0) ** 2
    so, sd = np.sqrt(np.maximum(vals["norm_a_obj"], 0)), np.sqrt(np.maximum(vals["_D"], 0))
    den = sd - rho - PAD
    ub["sr"] = np.where(den > 0, np.minimum(((so + rho + PAD) / np.where(den > 0, den, 1.0))
                                            ** 2, 1.0), 1.0)
    lb["sr"] = (np.maximum(so - rho - PAD, 0) / (sd + rho + PAD)) ** 2
    still = (sd + rho + PAD) ** 2  # an upper bound of |a|_M^2 on the cell
    return ub, lb, still


def bounds(sampler, names, T, gap, budget):
    """Branch and bound on the sphere ``|u| = 1``. Returns ``best`` (``{(attr, metric):
    (value, u)}`` for max, min, min_kept), ``bound_max``, ``bound_min`` (dicts), whether
    every cell was resolved, and why not. ``T``: whitened to torques, ``tau = T u``."""
    na = T.shape[0]
    best = {}
    for m in names:
        best[("max", m)] = (-np.inf, None)
        best[("min", m)] = (np.inf, None)
        best[("min_kept", m)] = (np.inf, None)
    bmax = {m: -np.inf for m in names}
    bmin = {m: np.inf for m in names}
    if na == 1:
        live = [((0, 1.0), np.zeros((1, 0)), 0.0), ((0, -1.0), np.zeros((1, 0)), 0.0)]
    else:
        per = int(np.clip(np.ceil((budget / 20 / (2 * na)) ** (1 / (na - 1))), 2, 64))
        e = 1.0 / per
        g = -1 + e + 2 * e * np.arange(per)
        c = np.array(list(itertools.product(g, repeat=na - 1))).reshape(-1, na - 1)
        live = [((ax, s), c, e) for ax in range(na) for s in (1.0, -1.0)]
    closed, why = True, ""
    while live:
        u = np.vstack([_to_sphere(face, c) for face, c, _ in live])
        owner = np.concatenate([np.full(len(c), i) for i, (_, c, _) in enumerate(live)])
        rho = np.array([e for _, _, e in live])[owner] * np.sqrt(na - 1)
        vals = sampler(u @ T.T)
        if not np.all(vals["_ok"]):
            return None, None, None, False, ("the forward solve did not answer a sample on "
                                             "the ellipsoid")
        ub, lb, still = _cell_bounds(vals, rho, names)
        for m in names:
            v = vals[m]
            for attr, pick, w in (("max", np.argmax, v), ("min", np.argmin, v),
                                  ("min_kept", np.argmin, np.where(vals["_kept"], v,
                                                                   np.inf))):
                i = int(pick(w))
                if (w[i] > best[(attr, m)][0]) if attr == "max" else (w[i] < best[(attr,
                                                                                   m)][0]):
                    best[(attr, m)] = (float(w[i]), u[i])
        # a cell still matters where a bound may beat its metric's best by more than the gap
        excess = np.full(len(u), -np.inf)
        flags = {}
        for m in names:
            hi, lo = best[("max", m)][0], best[("min", m)][0]
            xm, xn = ub[m] - hi - gap, lo - gap - lb[m]
            if m == "sr":  # the 0/0 limit where nothing moves: left out, not split
                xm = np.where(still >= gap, xm, -np.inf)
                xn = np.where(still >= gap, xn, -np.inf)
            flags[m] = (xm, xn)
            excess = np.maximum(excess, np.maximum(xm, xn))
        need = (excess > 0) & (rho > 0)
        # within the budget: the cells farthest from closing are split first
        room = (budget - sampler.count) // 2 ** (na - 1)
        if need.sum() > room:
            order = np.argsort(-np.where(need, excess, -np.inf))
            need[:] = False
            need[order[:max(room, 0)]] = True
            closed, why = False, f"the budget of {budget} forward solves ended first"
        for m in names:
            xm, xn = flags[m]
            keep = ~need
            in_sr = (still >= gap) if m == "sr" else np.ones(len(u), bool)
            bmax[m] = max(bmax[m], float(np.max(ub[m][keep & in_sr], initial=-np.inf)))
            bmin[m] = min(bmin[m], float(np.min(lb[m][keep & in_sr], initial=np.inf)))
        nxt = []
        offs = np.array(list(itertools.product((-0.5, 0.5), repeat=na - 1)))
        for i, (face, c, e) in enumerate(live):
            sel = need[owner == i]
            if sel.any():
                cc = c[sel]
                nxt.append((face, (cc[:, None, :] + e * offs[None]).reshape(-1, na - 1),
                            e / 2))
        live = nxt
    return best, bmax, bmin, closed, why
