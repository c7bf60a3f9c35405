"""Exact extremes over the input ellipsoid for bounded wheels (the ``wheels`` scenario).

With bounded wheels the solution of the contact/wheel problem (``snakecg.solver``) is a
continuous, piecewise affine function of the torque: each *state* ``sigma`` (contact held or
lost, every wheel sticking or sliding either way) holds on a polyhedron ``R_sigma`` of
torques, on which ``lam``, ``w``, ``qdd`` and ``a_obj`` are affine in ``tau`` (eqs. 12-25 with
the sliding wheels' fixed forces ``+-mu m_i g``). In the whitened coordinates
``u = L^T tau`` (``N = B^T M_s^-1 B = L L^T``, eq. 31) the input boundary is the unit sphere
and each metric is, on a piece, a quadratic ``u^T A u + 2 g^T u + c`` (or, for ``sr``, a
ratio of two).

Method (exact, certified):

1. *Pieces*: starting from the states of a few directions solved by the package's forward
   solver, the pieces meeting the sphere are found by walking across their facets: a facet
   of ``R_sigma`` (one condition at equality) that meets the sphere inside ``R_sigma`` leads
   to the neighbouring state (that one row flipped). Whether a facet meets the sphere is
   decided exactly by the stationary points of a linear function on every face of
   ``R_sigma`` cut with the sphere (closed form). The sphere is connected, so the walk visits
   every piece with a non-empty patch on it.
2. *Per piece*, the extremes of the quadratic on ``sphere ∩ R_sigma`` are attained at KKT
   points: for every set ``S`` of active conditions (``|S| < n_a``) the sphere cut by them is
   a smaller sphere ``u = u_0 + Z y, |y| = r``, on which the stationary points of
   ``y^T A_r y + 2 g_r^T y`` solve ``(A_r - mu I) y = -g_r``: the real eigenvalues of the
   ``2k x 2k`` linearization ``[[A_r, -I], [-g_r g_r^T / r^2, A_r]]`` (Gander, Golub and
   von Matt 1989), plus the "hard case" points built from the eigenvectors of ``A_r``. Every
   candidate inside ``R_sigma`` is evaluated; the best is the piece's extreme. Pieces whose
   unconstrained bound cannot beat the best value found are skipped.
3. ``sr = Omega / (Omega + Xi)``: Dinkelbach's iteration, ``t <- sr(u*)`` with ``u*`` the
   global maximiser of ``Omega - t (Omega + Xi)`` (step 2), until that maximum is ``<= 0``
   (within 1e-12 of the scale): a certificate that no torque on the boundary does better.
4. Every reported extreme is re-evaluated by the package's forward solver at the returned
   torque; ``certified`` is False where the two differ by more than 1e-7 (relative) or a
   Dinkelbach iteration did not close.
"""

from __future__ import annotations

import itertools

import numpy as np

from .solver import ABSENT, HELD, LOST, SLIDE_NEG, SLIDE_POS

__all__ = ["wheel_extremes"]

#: Feasibility tolerance of a candidate point (normalized conditions).
FEAS_TOL = 1e-9


# ------------------------------------------------------------------------------------------
# primitives per configuration
# ------------------------------------------------------------------------------------------
def primitives(model, qa):
    """At rest, per configuration: ``G`` (n, nc, nc), ``Bt`` (w at lam = 0 per tau),
    ``Q0`` (qdd at lam = 0 per tau), ``Kq``/``Ka`` (qdd / a_obj per unit row force), ``M``,
    ``N`` and the whitening ``T = L^-T`` (tau = T u)."""
    n, nc = qa.shape[0], model.n_constraints
    zeros = np.zeros(nc)
    _, raw = model._at_rest("interaction_maps", qa, n, zeros, zeros)
    G = np.array(raw["delassus"])
    Bt = np.array(raw["w_from_tau"])
    Q0 = np.array(raw["qdd_from_tau"])
    A0 = np.array(raw["a_obj_from_tau"])
    N = np.array(raw["input_metric"])
    Kq = np.zeros((n, model.n_coordinates, nc))
    Ka = np.zeros((n, 3, nc))
    for j in np.flatnonzero(model.present):
        e = np.zeros(nc)
        e[j] = 1.0
        _, r = model._at_rest("interaction_maps", qa, n, zeros, e)
        Kq[:, :, j] = r["qdd_offset"][:, :, 0]
        Ka[:, :, j] = r["a_obj_offset"][:, :, 0]
    M = model.mass_matrix(qa)
    if M.ndim == 2:
        M = M[None]
    L = np.linalg.cholesky(N)
    T = np.swapaxes(np.linalg.inv(L), 1, 2)
    I_obj = np.diag([model.scene.object_mass, model.scene.object_mass,
                     model.scene.object_inertia])
    return dict(G=G, Bt=Bt @ T, Q0=Q0 @ T, A0=A0 @ T, Kq=Kq, Ka=Ka, M=M, T=T, I_obj=I_obj)


def all_states(model):
    """Every state of the rows (``(S, nc)`` int8): contact held/lost x wheel states."""
    choices = []
    for r, p in enumerate(model.present):
        if not p:
            choices.append((ABSENT,))
        elif r == 0:
            choices.append((HELD, LOST))
        elif np.isfinite(model.bounds[r]):
            choices.append((HELD, SLIDE_POS, SLIDE_NEG))
        else:
            choices.append((HELD,))
    return np.array(list(itertools.product(*choices)), dtype=np.int8)


# ------------------------------------------------------------------------------------------
# one piece: affine maps and its conditions
# ------------------------------------------------------------------------------------------
def piece(prim, bounds, p, states):
    """Affine maps ``x = X u + x0`` of a batch of (configuration ``p``, state) pairs and the
    piece's conditions ``a_k . u + b_k >= 0`` (normalized; unused slots ``0 . u + 1``).

    Returns a dict with ``lam``, ``w``, ``qdd``, ``a_obj`` as ``(X, x0)`` and ``cond``
    ``(P, m, na + 1)``, ``flip`` ``(P, m)`` (the state code a row moves to across that facet,
    -1 for none) and ``row`` ``(P, m)`` (which row).
    """
    G, Bt = prim["G"][p], prim["Bt"][p]
    P, nc, na = Bt.shape
    ub = np.where(np.isfinite(bounds), bounds, 0.0)
    held = states == HELD
    lam_f = np.where(states == SLIDE_POS, ub, 0.0) - np.where(states == SLIDE_NEG, ub, 0.0)
    D = held.astype(float)
    Gp = D[:, :, None] * G * D[:, None, :] + np.eye(nc) * (1.0 - D)[:, None, :]
    rhs = np.concatenate([Bt, (G @ lam_f[:, :, None])], axis=2)  # (P, nc, na + 1)
    sol = -np.linalg.solve(Gp, D[:, :, None] * rhs)
    Lam = sol[:, :, :na]
    lam0 = sol[:, :, na] + lam_f
    W = G @ Lam + Bt
    w0 = np.einsum("pij,pj->pi", G, lam0)
    Kq, Ka = prim["Kq"][p], prim["Ka"][p]
    Q = prim["Q0"][p] + Kq @ Lam
    q0 = np.einsum("pij,pj->pi", Kq, lam0)
    Aa = prim["A0"][p] + Ka @ Lam
    a0 = np.einsum("pij,pj->pi", Ka, lam0)
    # conditions
    conds, flips, rows = [], [], []
    one = np.zeros((P, na + 1))
    one[:, na] = 1.0

    def add(mask, vec, to, r):
        conds.append(np.where(mask[:, None], vec, one))
        flips.append(np.where(mask, to, -1))
        rows.append(np.full(P, r))

    add(states[:, 0] == HELD, np.concatenate([Lam[:, 0], lam0[:, 0:1]], axis=1), LOST, 0)
    add(states[:, 0] == LOST, np.concatenate([W[:, 0], w0[:, 0:1]], axis=1), HELD, 0)
    for r in range(1, nc):
        if not np.isfinite(bounds[r]):
            continue
        lr = np.concatenate([Lam[:, r], lam0[:, r:r + 1]], axis=1)
        wr = np.concatenate([W[:, r], w0[:, r:r + 1]], axis=1)
        hold = states[:, r] == HELD
        upper, lower = -lr.copy(), lr.copy()
        upper[:, na] += bounds[r]
        lower[:, na] += bounds[r]
        add(hold, upper, SLIDE_POS, r)
        add(hold, lower, SLIDE_NEG, r)
        add(states[:, r] == SLIDE_POS, -wr, HELD, r)
        add(states[:, r] == SLIDE_NEG, wr, HELD, r)
    cond = np.stack(conds, axis=1)
    flip = np.stack(flips, axis=1)
    row = np.stack(rows, axis=1)
    # keep only the slots some pair uses, then normalize
    used = np.any(flip >= 0, axis=0)
    cond, flip, row = cond[:, used], flip[:, used], row[:, used]
    scale = np.abs(cond).max(axis=2, keepdims=True)
    cond = cond / np.where(scale > 0, scale, 1.0)
    return dict(lam=(Lam, lam0), w=(W, w0), qdd=(Q, q0), a_obj=(Aa, a0), cond=cond,
                flip=flip, row=row, G=G, M=prim["M"][p])


def forms(pc, prim, metric):
    """The metric on each piece as ``(A, g, c)``: ``u^T A u + 2 g^T u + c``."""
    if metric == "norm_qdd":
        (X, x0), P_ = pc["qdd"], pc["M"]
    elif metric == "norm_a_obj":
        (X, x0), P_ = pc["a_obj"], prim["I_obj"][None]
    elif metric == "norm_lambda":
        (X, x0), P_ = pc["lam"], pc["G"]
    else:
        raise ValueError(metric)
    PX = P_ @ X
    A = np.swapaxes(X, 1, 2) @ PX
    A = 0.5 * (A + np.swapaxes(A, 1, 2))
    g = np.einsum("pij,pi->pj", PX, x0)
    c = np.einsum("pi,pij,pj->p", x0, np.broadcast_to(P_, (len(x0),) + P_.shape[1:]), x0)
    return A, g, c


# ------------------------------------------------------------------------------------------
# faces of a piece cut with the sphere
# ------------------------------------------------------------------------------------------
def _subsets(m, na):
    out = []
    for k in range(0, min(m, na - 1) + 1):
        out.extend(itertools.combinations(range(m), k))
    return out


def faces(cond, na):
    """For every subset S of conditions (|S| < na): the sphere cut by ``a_S u + b_S = 0`` as
    ``u = u0 + Z y, |y| = r``. Returns a list of ``(S, u0 (P, na), Z (P, na, k), r (P,),
    valid (P,))``."""
    P, m, _ = cond.shape
    out = []
    for S in _subsets(m, na):
        if not S:
            out.append((S, np.zeros((P, na)), np.broadcast_to(np.eye(na), (P, na, na)),
                        np.ones(P), np.ones(P, bool)))
            continue
        a = cond[:, S, :na]  # (P, s, na)
        b = cond[:, S, na]
        if len(S) == 1:  # closed form: u0 = -b a / |a|^2, Z from a Householder reflection
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
            out.append((S, u0, np.ascontiguousarray(H[:, :, 1:]),
                        np.sqrt(np.maximum(r2, 0.0)), valid))
            continue
        if len(S) == 2 and na == 3:  # closed form: Z = a1 x a2, u0 = a^T (a a^T)^-1 (-b)
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
            out.append((S, u0, Z, np.sqrt(np.maximum(r2, 0.0)), valid))
            continue
        Q, R = np.linalg.qr(np.swapaxes(a, 1, 2), mode="complete")  # a^T = Q R
        Rs = R[:, :len(S), :]
        d = np.abs(np.diagonal(Rs, axis1=1, axis2=2))
        valid = d.min(axis=1) > 1e-12
        Rs_safe = Rs + np.eye(len(S)) * (~valid)[:, None, None]
        # a u = -b with u = Q1 x: R^T x = -b
        x = np.linalg.solve(np.swapaxes(Rs_safe, 1, 2), -b[:, :, None])[:, :, 0]
        u0 = np.einsum("pij,pj->pi", Q[:, :, :len(S)], x)
        r2 = 1.0 - np.sum(u0 * u0, axis=1)
        valid &= r2 >= 0
        out.append((S, u0, Q[:, :, len(S):], np.sqrt(np.maximum(r2, 0.0)), valid))
    return out


def _feasible(cond, u):
    """``(P, C)`` bool: candidate points ``u`` (P, C, na) satisfy every condition."""
    na = u.shape[2]
    val = u @ np.swapaxes(cond[:, :, :na], 1, 2) + cond[:, None, :, na]
    return np.all(val >= -FEAS_TOL, axis=2)


def linear_candidates(fc, direction):
    """Stationary points of ``direction . u`` on each face (exact, closed form)."""
    S, u0, Z, r, valid = fc
    k = Z.shape[2]
    if k == 1:
        y = np.stack([r[:, None], -r[:, None]], axis=1) * np.ones((1, 1, 1))
    else:
        gz = np.einsum("pik,i->pk", Z, direction)
        nz = np.linalg.norm(gz, axis=1, keepdims=True)
        gz = np.where(nz > 1e-14, gz / np.maximum(nz, 1e-300), np.eye(k)[0])
        y = np.stack([gz, -gz], axis=1) * r[:, None, None]
    return u0[:, None, :] + y @ np.swapaxes(Z, 1, 2)


def quadratic_candidates(fc, A, g):
    """Stationary points of ``u^T A u + 2 g^T u`` on each face: (P, C, na)."""
    S, u0, Z, r, valid = fc
    P, na, k = Z.shape
    r_safe = np.maximum(r, 1e-100)  # a smaller circle is a point for every candidate
    if k == 1:
        y = np.stack([r, -r], axis=1)[:, :, None]
        return u0[:, None, :] + y @ np.swapaxes(Z, 1, 2)
    Ar = np.swapaxes(Z, 1, 2) @ A @ Z
    Ar = 0.5 * (Ar + np.swapaxes(Ar, 1, 2))
    gr = np.einsum("pik,pi->pk", Z, np.einsum("pij,pj->pi", A, u0) + g)
    # easy case: the 2k x 2k linearization of the secular equation
    E = np.zeros((P, 2 * k, 2 * k))
    E[:, :k, :k] = Ar
    E[:, :k, k:] = -np.eye(k)
    E[:, k:, :k] = -gr[:, :, None] * gr[:, None, :] / (r_safe ** 2)[:, None, None]
    E[:, k:, k:] = Ar
    mus = np.sort(np.linalg.eigvals(E).real, axis=1)  # (P, 2k); a double root adjacent
    ev, V = np.linalg.eigh(Ar)
    gv = np.einsum("pki,pk->pi", V, gr)
    cands = []
    eye = np.eye(k)
    escale = np.abs(ev).max(axis=1, keepdims=True) + np.abs(gr).max(axis=1, keepdims=True) / \
        r_safe[:, None] + 1e-300
    tiny = 1e-13 * escale
    near_tol = 1e-7 * escale
    idx = np.arange(k)
    # hard case (g_r orthogonal to an eigenvector v_i of A_r, mu = its eigenvalue):
    # y = y_p + t v_i with y_p the least-norm part orthogonal to v_i, |y| = r
    hard = []
    for i in range(k):
        den = ev - ev[:, i:i + 1]
        ok = (idx != i) & (np.abs(den) > tiny)
        coef = np.where(ok, -gv / np.where(ok, den, 1.0), 0.0)
        yp = (V @ coef[:, :, None])[:, :, 0]
        t = np.sqrt(np.maximum(r ** 2 - np.sum(yp * yp, axis=1), 0.0))
        hard.append((yp, t[:, None] * V[:, :, i]))
    for j in range(2 * k):
        # y = -(A_r - mu I)^-1 g_r in A_r's eigenbasis; where mu is (numerically) an
        # eigenvalue of A_r, the hard-case point of that eigenvector instead (one sign per
        # root of the pair the linearization then has)
        den = ev - mus[:, j:j + 1]
        y = -(V @ (gv / np.where(np.abs(den) < tiny, tiny, den))[:, :, None])[:, :, 0]
        near = np.abs(den) < near_tol
        for i in range(k):
            yp, tv = hard[i]
            yh = yp + tv if j % 2 == 0 else yp - tv
            y = np.where(near[:, i:i + 1], yh, y)
        cands.append(y)
    y = np.stack(cands, axis=1)  # (P, C, k)
    ny = np.linalg.norm(y, axis=2, keepdims=True)
    y = np.where(ny > 0, y / np.maximum(ny, 1e-300), eye[0]) * r[:, None, None]
    return u0[:, None, :] + y @ np.swapaxes(Z, 1, 2)


def _quad(A, g, c, u):
    return (np.sum((u @ A) * u, axis=2) + 2 * (u @ g[:, :, None])[:, :, 0]) + c[:, None]


# ------------------------------------------------------------------------------------------
# the walk over the pieces
# ------------------------------------------------------------------------------------------
def _state_lookup(states):
    """Index of a state from its codes: ``lookup[key(state)]`` (-1 for none)."""
    nc = states.shape[1]
    base = 5 ** np.arange(nc)
    lookup = np.full(5 ** nc, -1, dtype=np.int64)
    lookup[states.astype(np.int64) @ base] = np.arange(len(states))
    return lookup, base


def explore(model, prim, qa, states):
    """Pieces meeting the sphere: ``(pairs_p, pairs_s)`` index arrays (configuration, state)."""
    n, na = qa.shape[0], model.n_joints
    S = len(states)
    lookup, base = _state_lookup(states)
    # seeds: the states of a few directions, from the package's forward solver
    from .analysis import sphere_directions

    dirs = sphere_directions(na, {1: 2, 2: 4, 3: 6}.get(na, 12))
    taus = np.einsum("bij,kj->bki", prim["T"], dirs).reshape(-1, na)
    res = model.forward(np.repeat(qa, len(dirs), axis=0), taus)
    st = _forward_states(model, res)
    visited = np.zeros((n, S), bool)
    visited[np.repeat(np.arange(n), len(dirs)), lookup[st.astype(np.int64) @ base]] = True
    frontier = visited.copy()
    direction = np.cos(np.arange(na) + 0.3) + 0.1 * np.arange(na)
    direction = direction / np.linalg.norm(direction)
    rounds = 0
    while frontier.any() and rounds < 4 * S:
        rounds += 1
        p, s = np.nonzero(frontier)
        pc = piece(prim, model.bounds, p, states[s])
        new = np.zeros((n, S), bool)
        ar = np.arange(len(s))
        for fc in faces(pc["cond"], na):
            Sset, _, _, _, valid = fc
            if not Sset:
                continue
            u = linear_candidates(fc, direction)
            ok = _feasible(pc["cond"], u).any(axis=1) & valid
            if not ok.any():
                continue
            # neighbours across each active facet, and across all of them at once
            flips = [[j] for j in Sset] + ([list(Sset)] if len(Sset) > 1 else [])
            for js in flips:
                nxt = states[s].copy()
                good = ok.copy()
                for j in js:
                    f = pc["flip"][:, j]
                    good &= f >= 0
                    rr = pc["row"][:, j]
                    nxt[ar, rr] = np.where(f >= 0, f, nxt[ar, rr])
                idx = np.flatnonzero(good)
                key = lookup[nxt[idx].astype(np.int64) @ base]
                ok_key = key >= 0
                new[p[idx[ok_key]], key[ok_key]] = True
        frontier = new & ~visited
        visited |= new
    p, s = np.nonzero(visited)
    return p, s, rounds


def _forward_states(model, res):
    """Row-state codes (N, nc) of a forward result."""
    n = res.contact.shape[0]
    nc = model.n_constraints
    st = np.zeros((n, nc), np.int8)
    st[:, 0] = np.where(res.contact, HELD, LOST)
    ws = np.asarray(res.wheel_state)
    for r in range(1, nc):
        if not model.present[r]:
            continue
        st[:, r] = np.select([ws[:, r - 1] == "slide+", ws[:, r - 1] == "slide-"],
                             [SLIDE_POS, SLIDE_NEG], HELD)
    return st


# ------------------------------------------------------------------------------------------
# extremes of a metric over the pieces
# ------------------------------------------------------------------------------------------
def _scatter_best(n, p, vals, us, sign):
    """Per configuration: the best (max for sign=+1, min for -1) of per-pair values."""
    best = np.full(n, -np.inf)
    np.maximum.at(best, p, sign * vals)
    # the argument: the pair that attains it
    hit = (sign * vals >= best[p]) & np.isfinite(vals)
    u = np.zeros((n, us.shape[1]))
    idx = np.flatnonzero(hit)
    u[p[idx]] = us[idx]
    return sign * best, u


def _take_faces(fcs, idx):
    return [(S, u0[idx], Z[idx], r[idx], v[idx]) for S, u0, Z, r, v in fcs]


def piece_extremes(cond, fcs, A, g, c, na, p, n, kept):
    """Max and min of ``u^T A u + 2 g^T u + c`` on ``sphere ∩ piece`` for every pair.

    The whole sphere is searched first: its stationary values bound the piece's quadratic.
    The faces (conditions at equality) follow, vertices first, and a face is searched only
    for pairs whose bound could still beat the best value found so far for their
    configuration (max over every pair, min over the kept pairs or over every pair).
    Returns ``vmax, umax, vmin, umin`` per pair (``-inf``/``+inf`` where the piece misses
    the sphere).
    """
    P = A.shape[0]
    vmax, vmin = np.full(P, -np.inf), np.full(P, np.inf)
    umax, umin = np.zeros((P, na)), np.zeros((P, na))
    order = [0] + sorted(range(1, len(fcs)), key=lambda i: -len(fcs[i][0]))
    up_max = lo_min = None
    for i in order:
        S, u0, Z, r, valid = fcs[i]
        if i == 0:
            sel = np.arange(P)
        else:
            best_max = np.full(n, -np.inf)
            np.maximum.at(best_max, p, vmax)
            best_min = np.full(n, -np.inf)
            np.maximum.at(best_min, p, np.where(kept, -vmin, -np.inf))
            best_all = np.full(n, -np.inf)
            np.maximum.at(best_all, p, -vmin)
            thr_min = np.where(kept, -best_min[p], -best_all[p])
            thr_max = best_max[p]
            slack = 1e-12 * (np.abs(up_max) + np.abs(lo_min))
            want = valid & ((up_max > thr_max + slack) | (lo_min < thr_min - slack))
            sel = np.flatnonzero(want)
            if sel.size == 0:
                continue
            if Z.shape[2] >= 2:  # a smaller sphere: bound the quadratic on it first
                hi, lo = _face_bounds(A[sel], g[sel], c[sel], u0[sel], Z[sel], r[sel])
                keep = (hi > thr_max[sel] + slack[sel]) | (lo < thr_min[sel] - slack[sel])
                sel = sel[keep]
                if sel.size == 0:
                    continue
        sub = (S, u0[sel], np.ascontiguousarray(Z[sel]), r[sel], valid[sel])
        u = quadratic_candidates(sub, A[sel], g[sel])
        v = _quad(A[sel], g[sel], c[sel], u)
        if i == 0:  # bounds of the piece's quadratic on the whole sphere
            up_max, lo_min = v.max(axis=1), v.min(axis=1)
        feas = _feasible(cond[sel], u) & valid[sel][:, None]
        rows = np.arange(len(sel))
        vm = np.where(feas, v, -np.inf)
        j = np.argmax(vm, axis=1)
        best = vm[rows, j]
        better = best > vmax[sel]
        vmax[sel[better]] = best[better]
        umax[sel[better]] = u[rows[better], j[better]]
        vn = np.where(feas, v, np.inf)
        j = np.argmin(vn, axis=1)
        best = vn[rows, j]
        better = best < vmin[sel]
        vmin[sel[better]] = best[better]
        umin[sel[better]] = u[rows[better], j[better]]
    return vmax, umax, vmin, umin


def _face_bounds(A, g, c, u0, Z, r):
    """Upper and lower bounds of ``u^T A u + 2 g^T u + c`` on ``u = u0 + Z y, |y| = r``:
    ``f(u0) +- 2 |g_r| r + lambda_max/min(A_r) r^2`` (exact eigenvalues for a circle,
    the Frobenius norm otherwise)."""
    Ar = np.swapaxes(Z, 1, 2) @ A @ Z
    gr = (np.swapaxes(Z, 1, 2) @ ((A @ u0[:, :, None])[:, :, 0] + g)[:, :, None])[:, :, 0]
    f0 = _quad(A, g, c, u0[:, None])[:, 0]
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


def _per_config(n, p, vals, us, mask, largest):
    """Best per configuration of per-pair values over the pairs in ``mask``."""
    sign = 1.0 if largest else -1.0
    sv = np.where(mask & np.isfinite(vals), sign * vals, -np.inf)
    best = np.full(n, -np.inf)
    np.maximum.at(best, p, sv)
    u = np.zeros((n, us.shape[1]))
    hit = np.flatnonzero((sv >= best[p]) & np.isfinite(sv))
    u[p[hit]] = us[hit]
    return sign * best, u


def _chunk(model, qa):
    n, na = qa.shape[0], model.n_joints
    prim = primitives(model, qa)
    states = all_states(model)
    p, s, rounds = explore(model, prim, qa, states)
    pc = piece(prim, model.bounds, p, states[s])
    kept = states[s, 0] == HELD
    every = np.ones(len(p), bool)
    T = prim["T"]
    res = {"max": {}, "min": {}, "min_kept": {}, "u_max": {}, "u_min": {}, "u_min_kept": {}}
    fm = {m: forms(pc, prim, m) for m in ("norm_a_obj", "norm_qdd", "norm_lambda")}
    cond = pc["cond"]
    fcs = faces(cond, na)
    pair_u, pair_ok = {}, {}
    for m, (A, g, c) in fm.items():
        vmax, umax, vmin, umin = piece_extremes(cond, fcs, A, g, c, na, p, n, kept)
        pair_u[m + "_max"], pair_ok[m + "_max"] = umax, np.isfinite(vmax)
        pair_u[m + "_min"], pair_ok[m + "_min"] = umin, np.isfinite(vmin)
        res["max"][m], res["u_max"][m] = _per_config(n, p, vmax, umax, every, True)
        res["min"][m], res["u_min"][m] = _per_config(n, p, vmin, umin, every, False)
        res["min_kept"][m], res["u_min_kept"][m] = _per_config(n, p, vmin, umin, kept, False)
    # sr = Omega / (Omega + Xi) on the kept pieces (0 where the contact is lost): Dinkelbach
    (Ao, go, co), (Aq, gq, cq) = fm["norm_a_obj"], fm["norm_qdd"]
    Ad, gd, cd = Ao + Aq, go + gq, co + cq
    closed = np.ones(n, bool)
    kp = np.flatnonzero(kept)
    has = np.zeros(n, bool)
    has[p[kp]] = True
    # starting ratios: sr at the extreme points of the norms found on the kept pieces
    pts = np.concatenate([pair_u[m][kp] for m in pair_u], axis=0)
    own = np.tile(kp, len(pair_u))
    ok = np.all(np.isfinite(pts), axis=1) & np.concatenate([pair_ok[m][kp] for m in pair_ok])
    pts, own = pts[ok], own[ok]
    om = _quad(Ao[own], go[own], co[own], pts[:, None])[:, 0]
    dd = _quad(Ad[own], gd[own], cd[own], pts[:, None])[:, 0]
    # D = Omega + Xi vanishes where the wheels brace the snake (a torque that moves nothing):
    # sr there is 0/0, a limit; such points only bound nothing. eps: the rounding level of D.
    d_scale = res["max"]["norm_qdd"] + res["max"]["norm_a_obj"]
    eps = 1e-12 * np.where(np.isfinite(d_scale) & (d_scale > 0), d_scale, 1.0)
    good = dd > 1e3 * eps[p[own]]
    pts, own, om, dd = pts[good], own[good], om[good], dd[good]
    sr0 = om / dd
    for largest in (True, False):
        t, u_best = _per_config(n, p[own], sr0, pts, np.ones(len(own), bool), largest)
        t = np.clip(np.where(np.isfinite(t), t, 0.0 if largest else 1.0), 0.0, 1.0)
        done = ~has
        for _ in range(30):
            sel = kp[~done[p[kp]]]
            if sel.size == 0:
                break
            ps = p[sel]
            ts = t[ps]
            A = Ao[sel] - ts[:, None, None] * Ad[sel]
            g = go[sel] - ts[:, None] * gd[sel]
            c = co[sel] - ts * cd[sel]
            vmax, umax, vmin, umin = piece_extremes(
                cond[sel], _take_faces(fcs, sel), A, g, c, na, ps, n, np.ones(len(sel), bool))
            vals, us = (vmax, umax) if largest else (vmin, umin)
            h, u = _per_config(n, ps, vals, us, np.ones(len(sel), bool), largest)
            # the ratio at the maximiser (minimiser) of Omega - t D, from its own piece
            sv = vals if largest else -vals
            best = np.full(n, -np.inf)
            np.maximum.at(best, ps, np.where(np.isfinite(sv), sv, -np.inf))
            hit = np.flatnonzero((sv >= best[ps]) & np.isfinite(sv))
            sr_u = t.copy()
            uu = us[hit][:, None]
            sr_u[ps[hit]] = (_quad(Ao[sel[hit]], go[sel[hit]], co[sel[hit]], uu)[:, 0]
                             / np.maximum(_quad(Ad[sel[hit]], gd[sel[hit]], cd[sel[hit]],
                                                uu)[:, 0], 1e-300))
            sr_u = np.clip(sr_u, 0.0, 1.0)  # Omega <= Omega + Xi
            active = np.zeros(n, bool)
            active[ps] = True
            # certificate: max (min) of Omega - t D over the boundary <= eps (>= -eps)
            improve = active & ~done & ((h > eps) if largest else (h < -eps))
            t = np.where(improve, sr_u, t)
            u_best = np.where(improve[:, None], u, u_best)
            done |= active & ~improve
        closed &= done
        key = "max" if largest else "min_kept"
        res[key]["sr"] = np.where(has, np.clip(t, 0.0, 1.0), 0.0 if largest else np.nan)
        res["u_" + key]["sr"] = u_best
    lost_any = np.zeros(n, bool)
    lost_any[p[~kept]] = True
    res["min"]["sr"] = np.where(lost_any, 0.0, res["min_kept"]["sr"])
    # where the contact can be lost, sr = 0 there: any point of a lost piece
    _, u_lost = _per_config(n, p, np.where(kept, np.nan, 0.0), pair_u["norm_qdd_min"],
                            ~kept & pair_ok["norm_qdd_min"], False)
    res["u_min"]["sr"] = np.where(lost_any[:, None], u_lost, res["u_min_kept"]["sr"])
    tau = {k: {m: np.einsum("nij,nj->ni", T, v) for m, v in res["u_" + k].items()}
           for k in ("max", "min", "min_kept")}
    return res, tau, closed, dict(pieces=len(p), rounds=rounds)


def _ratio_at(u, pk, kp, Ao, go, co, Ad, gd, cd, n, largest, vals, us):
    """sr of the pair that attains the per-configuration best of ``Omega - t D``."""
    sign = 1.0 if largest else -1.0
    sv = np.where(np.isfinite(vals), sign * vals, -np.inf)
    best = np.full(n, -np.inf)
    np.maximum.at(best, pk, sv)
    hit = np.flatnonzero((sv >= best[pk]) & np.isfinite(sv))
    out = np.zeros(n)
    uu = us[hit][:, None, :]
    i = kp[hit]
    om = _quad(Ao[i], go[i], co[i], uu)[:, 0]
    dd = _quad(Ad[i], gd[i], cd[i], uu)[:, 0]
    out[pk[hit]] = om / np.maximum(dd, 1e-300)
    return out


def wheel_extremes(model, qa, chunk: int = 1024):
    """Exact extremes of every metric for bounded wheels (see the module docstring).

    Returns an :class:`~snakecg.analysis.Extremes` with ``certified`` (N,) and ``pieces``
    (the number of (configuration, state) pieces meeting the sphere).
    """
    from .analysis import METRICS, Extremes

    n, na = qa.shape[0], model.n_joints
    ex = Extremes(method="wheels: exact piecewise solve (every wheel state meeting the input "
                         "boundary, KKT points of each piece, Dinkelbach for sr), certified "
                         "by the forward solver")
    parts = []
    for s0 in range(0, n, chunk):
        parts.append(_chunk(model, np.ascontiguousarray(qa[s0:s0 + chunk])))
    cert = np.concatenate([c for _, _, c, _ in parts])
    for key, tkey in (("max", "tau_max"), ("min", "tau_min"), ("min_kept", "tau_min_kept")):
        for m in METRICS:
            # the norms are sums of squares: rounding below 0 is clipped
            getattr(ex, key)[m] = np.maximum(
                np.concatenate([r[key][m] for r, _, _, _ in parts]), 0.0)
            getattr(ex, tkey)[m] = np.concatenate([t[key][m] for _, t, _, _ in parts])
    # certificate: the forward solver at the returned torques gives the same values
    for key, tkey in (("max", "tau_max"), ("min_kept", "tau_min_kept")):
        taus = np.stack([getattr(ex, tkey)[m] for m in METRICS], axis=1)  # (n, 4, na)
        res = model.forward(np.repeat(qa, len(METRICS), axis=0), taus.reshape(-1, na))
        for k, m in enumerate(METRICS):
            val = getattr(res, m).reshape(n, len(METRICS))[:, k]
            ref = getattr(ex, key)[m]
            scale = np.maximum(np.abs(ref), 1e-300)
            # (a contact-kept minimum may sit on the facet lam_c = 0, where the forward solver
            # reads the contact as lost: the values agree by continuity)
            bad = ~(np.abs(val - ref) <= 1e-7 * scale + 1e-12 * np.abs(ex.max[m]))
            cert &= ~bad
    ex.certified = cert
    ex.pieces = sum(i["pieces"] for _, _, _, i in parts)
    return ex
