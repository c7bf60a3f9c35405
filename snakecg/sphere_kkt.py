"""KKT points of a quadratic (or linear) function on the unit sphere cut by a piece's faces.

Used by :mod:`snakecg.piecewise`. A *piece* is a polyhedron ``a_k . u + b_k >= 0`` (normalized
conditions ``cond`` ``(P, m, na + 1)``, one row of ``P`` per (configuration, state) pair); its
*faces* are the sets ``S`` of conditions held at equality (``|S| < na``). Each face cut with the
unit sphere is a smaller sphere ``u = u0 + Z y, |y| = r``. The faces of every pair are kept as
flat batches (one per ``|S|``), holding only the faces that meet the sphere, so each step below
is one vectorized call over every pair of a chunk of configurations.

On a face the stationary points of ``y^T A_r y + 2 g_r^T y`` solve ``(A_r - mu I) y = -g_r``
with ``|y| = r``: the real eigenvalues of the ``2k x 2k`` linearization
``[[A_r, -I], [-g_r g_r^T / r^2, A_r]]`` (Gander, Golub and von Matt 1989), plus the "hard case"
points built from the eigenvectors of ``A_r``.
"""

from __future__ import annotations

import itertools
from typing import NamedTuple

import numpy as np

__all__ = [
    "Faces",
    "faces",
    "feasible",
    "linear_candidates",
    "meets",
    "per_config",
    "piece_extremes",
    "quad",
    "quadratic_candidates",
]

#: Feasibility tolerance of a candidate point (normalized conditions).
FEAS_TOL = 1e-9


class Faces(NamedTuple):
    """One batch of faces (all with the same ``|S|``) that meet the sphere: ``pair`` (F,) the
    row of the piece, ``slots`` (F, |S|) its conditions at equality, and the cut sphere
    ``u = u0 + Z y, |y| = r`` (``u0`` (F, na), ``Z`` (F, na, k), ``r`` (F,))."""

    pair: np.ndarray
    slots: np.ndarray
    u0: np.ndarray
    Z: np.ndarray
    r: np.ndarray


def _cut(a, b, na):
    """The sphere cut by ``a u + b = 0`` (``a`` (F, s, na), ``b`` (F, s)): ``u0, Z, r, valid``."""
    s = a.shape[1]
    if s == 1:  # closed form: u0 = -b a / |a|^2, Z from a Householder reflection
        a1, b1 = a[:, 0], b[:, 0]
        na2 = np.sum(a1 * a1, axis=1)
        valid = na2 > 1e-24
        na2 = np.where(valid, na2, 1.0)
        u0 = -(b1 / na2)[:, None] * a1
        ah = a1 / np.sqrt(na2)[:, None]
        sgn = np.where(ah[:, 0] >= 0, 1.0, -1.0)
        v = ah.copy()
        v[:, 0] += sgn
        vv = np.sum(v * v, axis=1)[:, None, None]
        H = np.eye(na) - 2 * v[:, :, None] * v[:, None, :] / vv
        r2 = 1.0 - np.sum(u0 * u0, axis=1)
        valid &= r2 >= 0
        return u0, np.ascontiguousarray(H[:, :, 1:]), np.sqrt(np.maximum(r2, 0.0)), valid
    if s == 2 and na == 3:  # closed form: Z = a1 x a2, u0 = a^T (a a^T)^-1 (-b)
        a1, a2 = a[:, 0], a[:, 1]
        z = np.cross(a1, a2)
        nz = np.linalg.norm(z, axis=1)
        valid = nz > 1e-12
        g11, g12, g22 = (np.sum(a1 * a1, 1), np.sum(a1 * a2, 1), np.sum(a2 * a2, 1))
        det = np.where(valid, g11 * g22 - g12 * g12, 1.0)
        x1 = (-b[:, 0] * g22 + b[:, 1] * g12) / det
        x2 = (-b[:, 1] * g11 + b[:, 0] * g12) / det
        u0 = x1[:, None] * a1 + x2[:, None] * a2
        r2 = 1.0 - np.sum(u0 * u0, axis=1)
        valid &= r2 >= 0
        Z = (z / np.where(valid, nz, 1.0)[:, None])[:, :, None]
        return u0, Z, np.sqrt(np.maximum(r2, 0.0)), valid
    Q, R = np.linalg.qr(np.swapaxes(a, 1, 2), mode="complete")  # a^T = Q R
    Rs = R[:, :s, :]
    d = np.abs(np.diagonal(Rs, axis1=1, axis2=2))
    valid = d.min(axis=1) > 1e-12
    Rs_safe = Rs + np.eye(s) * (~valid)[:, None, None]
    # a u = -b with u = Q1 x: R^T x = -b
    x = np.linalg.solve(np.swapaxes(Rs_safe, 1, 2), -b[:, :, None])[:, :, 0]
    u0 = np.einsum("pij,pj->pi", Q[:, :, :s], x)
    r2 = 1.0 - np.sum(u0 * u0, axis=1)
    valid &= r2 >= 0
    return u0, np.ascontiguousarray(Q[:, :, s:]), np.sqrt(np.maximum(r2, 0.0)), valid


def faces(cond, used, na, kernel=None):
    """Every face (``|S| < na``) of every pair that meets the sphere, as one :class:`Faces`
    batch per ``|S|`` (index 0: the whole sphere). ``used`` (P, m): the pair's real conditions
    (unused slots ``0 . u + 1`` are never at equality). ``kernel``: the compiled path
    (:class:`snakecg.engine.sphere.SphereKernel`), else NumPy's."""
    P, m, _ = cond.shape
    out = [Faces(np.arange(P), np.zeros((P, 0), np.intp), np.zeros((P, na)),
                 np.broadcast_to(np.eye(na), (P, na, na)), np.ones(P))]
    for s in range(1, min(m, na - 1) + 1):
        if kernel is not None:
            out.append(Faces(*kernel.cut(cond, used, s)))
            continue
        combos = np.array(list(itertools.combinations(range(m), s)), dtype=np.intp)
        pi, ci = np.nonzero(np.all(used[:, combos], axis=2))
        slots = combos[ci]
        sub = cond[pi[:, None], slots]
        u0, Z, r, valid = _cut(sub[:, :, :na], sub[:, :, na], na)
        out.append(Faces(pi[valid], slots[valid], u0[valid], Z[valid], r[valid]))
    return out


def feasible(cond, u):
    """``(P, C)`` bool: candidate points ``u`` (P, C, na) satisfy every condition."""
    na = u.shape[2]
    val = u @ np.swapaxes(cond[:, :, :na], 1, 2) + cond[:, None, :, na]
    return np.all(val >= -FEAS_TOL, axis=2)


def meets(cond, fc, direction, kernel=None):
    """(F,) bool: each face's sphere meets its piece (``cond`` per pair): a stationary point of
    ``direction . u`` on it is feasible."""
    if kernel is not None:
        return kernel.meets(fc.pair, fc.u0, fc.Z, fc.r, cond, direction, FEAS_TOL)
    return feasible(cond[fc.pair], linear_candidates(fc, direction)).any(axis=1)


def linear_candidates(fc, direction):
    """Stationary points of ``direction . u`` on each face (exact, closed form): (F, 2, na)."""
    u0, Z, r = fc.u0, fc.Z, fc.r
    k = Z.shape[2]
    if k == 1:
        y = np.stack([r[:, None], -r[:, None]], axis=1) * np.ones((1, 1, 1))
    else:
        gz = np.einsum("pik,i->pk", Z, direction)
        nz = np.linalg.norm(gz, axis=1, keepdims=True)
        gz = np.where(nz > 1e-14, gz / np.maximum(nz, 1e-300), np.eye(k)[0])
        y = np.stack([gz, -gz], axis=1) * r[:, None, None]
    return u0[:, None, :] + y @ np.swapaxes(Z, 1, 2)


def quadratic_candidates(u0, Z, r, A, g):
    """Stationary points of ``u^T A u + 2 g^T u`` on the faces ``u0 + Z y, |y| = r``:
    (F, C, na)."""
    P, _, k = Z.shape
    r_safe = np.maximum(r, 1e-100)  # a smaller circle is a point for every candidate
    if k == 1:
        y = np.stack([r, -r], axis=1)[:, :, None]
        return u0[:, None, :] + y @ np.swapaxes(Z, 1, 2)
    Zt = np.swapaxes(Z, 1, 2)
    Ar = Zt @ A @ Z
    Ar = 0.5 * (Ar + np.swapaxes(Ar, 1, 2))
    gr = (Zt @ ((A @ u0[:, :, None])[:, :, 0] + g)[:, :, None])[:, :, 0]
    # easy case: the 2k x 2k linearization of the secular equation
    E = np.zeros((P, 2 * k, 2 * k))
    E[:, :k, :k] = Ar
    E[:, :k, k:] = -np.eye(k)
    E[:, k:, :k] = -gr[:, :, None] * gr[:, None, :] / (r_safe ** 2)[:, None, None]
    E[:, k:, k:] = Ar
    mus = np.sort(np.linalg.eigvals(E).real, axis=1)  # (P, 2k); a double root adjacent
    ev, V = _eigh(Ar)
    Vt = np.swapaxes(V, 1, 2)
    gv = (gr[:, None, :] @ V)[:, 0]
    eye = np.eye(k)
    escale = np.abs(ev).max(axis=1, keepdims=True) + np.abs(gr).max(axis=1, keepdims=True) / \
        r_safe[:, None] + 1e-300
    tiny = 1e-13 * escale[:, :, None]
    near_tol = 1e-7 * escale[:, :, None]
    # y = -(A_r - mu I)^-1 g_r in A_r's eigenbasis, for every root mu_j [(P, j, k)]
    den = ev[:, None, :] - mus[:, :, None]
    y = -((gv[:, None, :] / np.where(np.abs(den) < tiny, tiny, den)) @ Vt)
    near = np.abs(den) < near_tol
    hit = np.flatnonzero(near.any(axis=(1, 2)))
    if hit.size:
        # where mu_j is (numerically) an eigenvalue of A_r, the "hard case" (g_r orthogonal
        # to an eigenvector v_i of A_r, mu = its eigenvalue): y = y_p +- t v_i with y_p the
        # least-norm part orthogonal to v_i, |y| = r (one sign per root of the pair the
        # linearization then has; the last such eigenvector where several are near)
        evh, gvh, Vth, tinyh = ev[hit], gv[hit], Vt[hit], tiny[hit]
        den = evh[:, None, :] - evh[:, :, None]  # (H, i, l)
        ok = ~eye.astype(bool) & (np.abs(den) > tinyh)
        coef = np.where(ok, -gvh[:, None, :] / np.where(ok, den, 1.0), 0.0)
        yp = coef @ Vth  # (H, i, k)
        t = np.sqrt(np.maximum(r[hit, None] ** 2 - np.sum(yp * yp, axis=2), 0.0))
        tv = t[:, :, None] * Vth
        nh = near[hit]
        last = k - 1 - np.argmax(nh[:, :, ::-1], axis=2)  # (H, 2k)
        rows = np.arange(len(hit))[:, None]
        sgn = np.where(np.arange(2 * k) % 2 == 0, 1.0, -1.0)[None, :, None]
        yh = yp[rows, last] + sgn * tv[rows, last]
        y[hit] = np.where(nh.any(axis=2)[:, :, None], yh, y[hit])
    ny = np.linalg.norm(y, axis=2, keepdims=True)
    y = np.where(ny > 0, y / np.maximum(ny, 1e-300), eye[0]) * r[:, None, None]
    return u0[:, None, :] + y @ np.swapaxes(Z, 1, 2)


def _eigh(S):
    """``np.linalg.eigh`` of symmetric ``S`` (P, k, k); closed form for k = 2."""
    if S.shape[1] != 2:
        return np.linalg.eigh(S)
    a, b, d = S[:, 0, 0], S[:, 0, 1], S[:, 1, 1]
    half = 0.5 * (a - d)
    rad = np.hypot(half, b)
    phi = 0.5 * np.arctan2(b, half)  # the top eigenvector (cos phi, sin phi)
    c, s = np.cos(phi), np.sin(phi)
    ev = np.stack([0.5 * (a + d) - rad, 0.5 * (a + d) + rad], axis=1)
    V = np.stack([np.stack([-s, c], axis=1), np.stack([c, s], axis=1)], axis=2)
    return ev, V


def quad(A, g, c, u):
    """``u^T A u + 2 g^T u + c`` at the points ``u`` (P, C, na): (P, C)."""
    return (np.sum((u @ A) * u, axis=2) + 2 * (u @ g[:, :, None])[:, :, 0]) + c[:, None]


def _face_bounds(A, g, c, u0, Z, r):
    """Upper and lower bounds of ``u^T A u + 2 g^T u + c`` on ``u = u0 + Z y, |y| = r``:
    ``f(u0) +- 2 |g_r| r + lambda_max/min(A_r) r^2`` (exact eigenvalues for a circle,
    the Frobenius norm otherwise)."""
    Ar = np.swapaxes(Z, 1, 2) @ A @ Z
    gr = (np.swapaxes(Z, 1, 2) @ ((A @ u0[:, :, None])[:, :, 0] + g)[:, :, None])[:, :, 0]
    f0 = quad(A, g, c, u0[:, None])[:, 0]
    lin = 2 * np.linalg.norm(gr, axis=1) * r
    if Ar.shape[1] == 2:
        a, b, d = Ar[:, 0, 0], 0.5 * (Ar[:, 0, 1] + Ar[:, 1, 0]), Ar[:, 1, 1]
        rad = np.hypot(0.5 * (a - d), b)
        lmax, lmin = 0.5 * (a + d) + rad, 0.5 * (a + d) - rad
    else:
        fro = np.linalg.norm(Ar, axis=(1, 2))
        lmax, lmin = fro, -fro
    r2 = r * r
    pad = 1e-12 * (np.abs(f0) + lin + np.abs(lmax) * r2 + np.abs(lmin) * r2)
    return f0 + lin + lmax * r2 + pad, f0 - lin + lmin * r2 - pad  # |y| = r exactly


def _merge(vbest, ubest, q, vals, us, sign):
    """``vbest[q]``, ``ubest[q]`` <- the better of themselves and the rows ``vals``, ``us``
    (sign +1: larger, -1: smaller); among equal rows the first wins."""
    sv = sign * vals
    new = np.full(len(vbest), -np.inf)
    np.maximum.at(new, q, sv)
    better = new > sign * vbest
    hit = np.flatnonzero(better[q] & (sv == new[q]))[::-1]
    ubest[q[hit]] = us[hit]
    vbest[better] = sign * new[better]


def _evaluate(cond, fc, rows, A, g, c, out, both=True, kernel=None, skip=None):
    """KKT candidates of the faces ``rows`` of ``fc``, merged into ``out`` (vmax, umax, vmin,
    umin per pair; the min only if ``both``); returns the largest and smallest value over each
    face's candidates (feasible or not). ``kernel``: the compiled path
    (:class:`snakecg.engine.sphere.SphereKernel`, which skips the faces whose bounds stay within
    ``skip``, then returning those bounds), else NumPy's."""
    q = fc.pair[rows]
    if kernel is not None:
        whole = fc.slots.shape[1] == 0  # the whole unit sphere
        vmax, umax, vmin, umin, hi, lo = kernel.candidates(
            q, None if whole else fc.u0[rows], None if whole else fc.Z[rows],
            None if whole else fc.r[rows], A, g, c, cond, FEAS_TOL, identity=whole, skip=skip)
        _merge(out[0], out[1], q, vmax, umax, 1.0)
        if both:
            _merge(out[2], out[3], q, vmin, umin, -1.0)
        return hi, lo
    u = quadratic_candidates(fc.u0[rows], fc.Z[rows], fc.r[rows], A[q], g[q])
    v = quad(A[q], g[q], c[q], u)
    feas = feasible(cond[q], u)
    idx = np.arange(len(q))
    vm = np.where(feas, v, -np.inf)
    j = np.argmax(vm, axis=1)
    _merge(out[0], out[1], q, vm[idx, j], u[idx, j], 1.0)
    if both:
        vn = np.where(feas, v, np.inf)
        j = np.argmin(vn, axis=1)
        _merge(out[2], out[3], q, vn[idx, j], u[idx, j], -1.0)
    return v.max(axis=1), v.min(axis=1)


def piece_extremes(cond, fcs, A, g, c, p, n, kept, floor=None, kernel=None, active=None):
    """Max and min of ``u^T A u + 2 g^T u + c`` on ``sphere ∩ piece`` for every pair.

    The whole sphere is searched first: its stationary values bound the piece's quadratic.
    The faces (conditions at equality) follow, vertices first, and a face is searched only
    for pairs whose bound could still beat the best value found so far for their
    configuration (max over every pair, min over the kept pairs or over every pair).
    Returns ``vmax, umax, vmin, umin`` per pair (``-inf``/``+inf`` where the piece misses
    the sphere).

    With ``floor`` (n,), only the max is sought and only where it exceeds ``floor`` (per
    configuration): pairs and faces whose bound stays below it are skipped, the whole sphere
    too where the bound ``c + 2 |g| + lambda_max(A)`` does (vmin is then not computed).
    ``kernel``: the compiled candidates (:class:`snakecg.engine.sphere.SphereKernel`) or None.
    ``active`` (P,) bool: search only these pairs (the others come back infinite).
    """
    P, na = A.shape[0], A.shape[1]
    both = floor is None
    out = (np.full(P, -np.inf), np.zeros((P, na)), np.full(P, np.inf), np.zeros((P, na)))
    up_max, lo_min = np.full(P, -np.inf), np.full(P, np.inf)
    rows = np.arange(P) if active is None else np.flatnonzero(active)
    skip = None
    if not both and kernel is not None:  # the C bounds the quadratic on the sphere itself
        skip = (floor[p[rows]], -np.inf)
    elif not both:  # |u| = 1: u^T A u <= lambda_max(A), 2 g^T u <= 2 |g|
        lin = 2 * np.linalg.norm(g[rows], axis=1)
        lmax = np.linalg.eigvalsh(A[rows])[:, -1]
        hi = c[rows] + lin + lmax
        rows = rows[hi > floor[p[rows]] - 1e-12 * (np.abs(c[rows]) + lin + np.abs(lmax))]
    if rows.size:
        # the extremes over the whole sphere bound the piece's quadratic
        up_max[rows], lo_min[rows] = _evaluate(cond, fcs[0], rows, A, g, c, out, both, kernel,
                                               skip)
    slack = 1e-12 * (np.abs(up_max) + np.abs(lo_min))
    slack = np.where(np.isfinite(slack), slack, 0.0)
    for fc in fcs[:0:-1]:
        if not len(fc.pair):
            continue
        vmax, _, vmin, _ = out
        best_max = np.full(n, -np.inf)
        np.maximum.at(best_max, p, vmax)
        thr_max = best_max[p]
        if both:
            best_min = np.full(n, -np.inf)
            np.maximum.at(best_min, p, np.where(kept, -vmin, -np.inf))
            best_all = np.full(n, -np.inf)
            np.maximum.at(best_all, p, -vmin)
            thr_min = np.where(kept, -best_min[p], -best_all[p])
            want = (up_max > thr_max + slack) | (lo_min < thr_min - slack)
        else:
            want = (up_max > thr_max + slack) & (up_max > floor[p] - slack)
        rows = np.flatnonzero(want[fc.pair])
        skip = None
        if rows.size and kernel is not None:  # the C bounds the quadratic on each face
            q = fc.pair[rows]
            if both:
                skip = (thr_max[q] + slack[q], thr_min[q] - slack[q])
            else:
                skip = (np.maximum(thr_max[q] + slack[q], floor[p[q]] - slack[q]), -np.inf)
        elif rows.size and fc.Z.shape[2] >= 2:  # bound the quadratic first
            q = fc.pair[rows]
            hi, lo = _face_bounds(A[q], g[q], c[q], fc.u0[rows], fc.Z[rows], fc.r[rows])
            if both:
                keep = (hi > thr_max[q] + slack[q]) | (lo < thr_min[q] - slack[q])
            else:
                keep = (hi > thr_max[q] + slack[q]) & (hi > floor[p[q]] - slack[q])
            rows = rows[keep]
        if rows.size:
            _evaluate(cond, fc, rows, A, g, c, out, both, kernel, skip)
    return out


def per_config(n, p, vals, us, mask, largest):
    """Best per configuration of per-pair values over the pairs in ``mask``."""
    sign = 1.0 if largest else -1.0
    sv = np.where(mask & np.isfinite(vals), sign * vals, -np.inf)
    best = np.full(n, -np.inf)
    np.maximum.at(best, p, sv)
    u = np.zeros((n, us.shape[1]))
    hit = np.flatnonzero((sv >= best[p]) & np.isfinite(sv))
    u[p[hit]] = us[hit]
    return sign * best, u
