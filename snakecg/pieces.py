"""The pieces of the bounded-wheel map that meet the input sphere, and their affine maps.

Used by :mod:`snakecg.piecewise`. With bounded wheels the contact/wheel solution is piecewise
affine in the torque: on the polyhedron ``R_sigma`` of each *state* ``sigma`` (contact held or
lost, every wheel sticking or sliding either way) ``lam``, ``w``, ``qdd`` and ``a_obj`` are
affine in ``tau`` (eqs. 12-25 with the sliding wheels' fixed forces ``+-mu m_i g``). In the
whitened coordinates ``u = L^T tau`` (``N = B^T M_s^-1 B = L L^T``, eq. 31) the input boundary
is the unit sphere. :func:`explore` finds, for a batch of configurations at once, every piece
with a non-empty patch on the sphere by walking across the pieces' facets.
"""

from __future__ import annotations

import itertools

import numpy as np

from . import kernels
from .solver import ABSENT, HELD, LOST, SLIDE_NEG, SLIDE_POS
from .sphere_kkt import Faces, faces, meets

__all__ = ["all_states", "explore", "forms", "piece", "primitives"]


def primitives(model, qa):
    """At rest, per configuration: ``G`` (n, nc, nc), ``Bt`` (w at lam = 0 per tau),
    ``Q0`` (qdd at lam = 0 per tau), ``Kq``/``Ka`` (qdd / a_obj per unit row force), ``M``,
    ``N`` and the whitening ``T = L^-T`` (tau = T u)."""
    n, nc = qa.shape[0], model.n_constraints
    zeros = np.zeros(nc)
    _, raw = model.at_rest("interaction_maps", qa, zeros, zeros)
    G = np.array(raw["delassus"])
    Bt = np.array(raw["w_from_tau"])
    Q0 = np.array(raw["qdd_from_tau"])
    A0 = np.array(raw["a_obj_from_tau"])
    N = np.array(raw["input_metric"])
    # qdd and a_obj per unit row force (eq. 18), every row at once (generated
    # contact_system_at_rest, the object placed from q)
    zero = np.zeros(3)
    inputs = model.scene_inputs
    cs = kernels.call(model.backend, "contact_system_at_rest", n,
                      q=kernels.at_origin(qa)[0],
                      tau=np.zeros(model.n_joints), q_obj=zero, f_obj=zero, rho=np.zeros(2),
                      placed=np.ones(1),
                      **{k: inputs[k] for k in ("K", "contact_link", "side", "object_mass",
                                                "object_inertia", "wheel_offset",
                                                "contact_offset", "object_distance")})
    absent = ~np.asarray(model.present, dtype=bool)
    Kq = np.array(cs["qdd_from_lam"])
    Ka = np.array(cs["a_obj_from_lam"])
    Kq[:, :, absent] = 0.0
    Ka[:, :, absent] = 0.0
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
def piece(prim, bounds, p, states, kernel=None):
    """Affine maps ``x = X u + x0`` of a batch of (configuration ``p``, state) pairs and the
    piece's conditions ``a_k . u + b_k >= 0`` (normalized; unused slots ``0 . u + 1``).

    Returns a dict with ``lam``, ``w``, ``qdd``, ``a_obj`` as ``(X, x0)`` and ``cond``
    ``(P, m, na + 1)``, ``flip`` ``(P, m)`` (the state code a row moves to across that facet,
    -1 for an unused slot; each pair's conditions come first) and ``row`` ``(P, m)`` (which
    row). ``kernel``: the compiled path (:class:`snakecg.engine.sphere.SphereKernel`), else
    NumPy's.
    """
    if kernel is not None:
        got = kernel.pieces(p, states, bounds, prim["G"], prim["Bt"], prim["Q0"], prim["A0"],
                            prim["Kq"], prim["Ka"])
        if got is not None:
            Lam, lam0, W, w0, Q, q0, Aa, a0, cond, flip, row = got
            return dict(lam=(Lam, lam0), w=(W, w0), qdd=(Q, q0), a_obj=(Aa, a0), cond=cond,
                        flip=flip, row=row, G=prim["G"][p], M=prim["M"][p])
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
    # each pair's own conditions first, then only the slots some pair uses; normalize
    order = np.argsort(flip < 0, axis=1, kind="stable")
    cond = np.take_along_axis(cond, order[:, :, None], axis=1)
    flip, row = np.take_along_axis(flip, order, axis=1), np.take_along_axis(row, order, axis=1)
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



def _state_lookup(states):
    """Index of a state from its codes: ``lookup[key(state)]`` (-1 for none)."""
    nc = states.shape[1]
    base = 5 ** np.arange(nc)
    lookup = np.full(5 ** nc, -1, dtype=np.int64)
    lookup[states.astype(np.int64) @ base] = np.arange(len(states))
    return lookup, base


def explore(model, prim, qa, states, kernel=None):
    """Pieces meeting the sphere: ``(pairs_p, pairs_s)`` index arrays (configuration, state),
    the number of rounds, and the pieces' maps (:func:`piece`) and faces
    (:func:`~snakecg.sphere_kkt.faces`) built on the way, for those pairs in that order.
    ``kernel``: the compiled faces (:class:`snakecg.engine.sphere.SphereKernel`) or None."""
    n, na = qa.shape[0], model.n_joints
    S = len(states)
    lookup, base = _state_lookup(states)
    # seeds: the states of a few directions, from the package's forward solver
    from .extremes_result import sphere_directions

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
    built = []
    while frontier.any() and rounds < 4 * S:
        rounds += 1
        p, s = np.nonzero(frontier)
        pc = piece(prim, model.bounds, p, states[s], kernel)
        flip, row = pc["flip"], pc["row"]
        fcs = faces(pc["cond"], flip >= 0, na, kernel)
        built.append((p, s, pc, fcs))
        new = np.zeros((n, S), bool)
        for fc in fcs[1:]:
            # a facet meets the sphere inside the piece: a stationary point of a linear
            # function on the face is feasible
            ok = meets(pc["cond"], fc, direction, kernel)
            q, slots = fc.pair[ok], fc.slots[ok]
            if not q.size:
                continue
            ar = np.arange(len(q))
            # neighbours across each active facet, and across all of them at once
            k = slots.shape[1]
            for js in [[j] for j in range(k)] + ([list(range(k))] if k > 1 else []):
                nxt = states[s[q]]
                for j in js:
                    nxt[ar, row[q, slots[:, j]]] = flip[q, slots[:, j]]
                key = lookup[nxt.astype(np.int64) @ base]
                ok_key = key >= 0
                new[p[q[ok_key]], key[ok_key]] = True
        frontier = new & ~visited
        visited |= new
    if frontier.any():  # the walk stopped early: the last ones found are pieces too
        p, s = np.nonzero(frontier)
        pc = piece(prim, model.bounds, p, states[s], kernel)
        built.append((p, s, pc, faces(pc["cond"], pc["flip"] >= 0, na, kernel)))
    return _concat(built) + (rounds,)


def _concat(built):
    """One batch of the walk's rounds ``(p, s, piece, faces)``: ``p, s, piece, faces``."""
    m = max(pc["cond"].shape[1] for _, _, pc, _ in built)
    na = built[0][2]["cond"].shape[2] - 1
    pcs = []
    for _, _, pc, _ in built:  # pad with unused slots (0 . u + 1 >= 0)
        P, k = pc["flip"].shape
        one = np.zeros((P, m - k, na + 1))
        one[:, :, na] = 1.0
        pcs.append(dict(pc, cond=np.concatenate([pc["cond"], one], axis=1),
                        flip=np.pad(pc["flip"], ((0, 0), (0, m - k)), constant_values=-1),
                        row=np.pad(pc["row"], ((0, 0), (0, m - k)))))
    pc = {}
    for key, val in pcs[0].items():
        if isinstance(val, tuple):
            pc[key] = tuple(np.concatenate([d[key][i] for d in pcs]) for i in range(len(val)))
        else:
            pc[key] = np.concatenate([d[key] for d in pcs])
    offsets = np.cumsum([0] + [len(p) for p, _, _, _ in built])
    fcs = []
    for j in range(1 + min(m, na - 1)):  # |S| = j (a round with fewer slots has none)
        parts = [b[3][j] if j < len(b[3]) else
                 Faces(np.zeros(0, np.intp), np.zeros((0, j), np.intp), np.zeros((0, na)),
                       np.zeros((0, na, na - j)), np.zeros(0)) for b in built]
        fcs.append(Faces(np.concatenate([f.pair + o for f, o in zip(parts, offsets)]),
                         *(np.concatenate([f[i] for f in parts]) for i in range(1, 5))))
    return (np.concatenate([p for p, _, _, _ in built]),
            np.concatenate([s for _, s, _, _ in built]), pc, fcs)


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


