"""Whether the ground's friction holds every torque of an input region still (a general scene
at rest): the test behind ``optimize`` and ``extremes`` answering "nothing moves" exactly.

A set of constant size (a Coulomb disc or a bounded wheel of radius ``mu m g``, an
anisotropic ellipse) does not scale with the torque, so the torques it holds are not a cone:
small torques stick, large ones slide. Where the ground sets alone fix the snake (a link's
disc holds two directions: on Coulomb ground every link sticking leaves no motion), every
torque the sets can balance gives ``a = 0``: nothing moves, and ``sr`` is 0 by its convention.

The test. ``a = 0`` is the forward solution at ``tau`` exactly when some forces ``lam`` in
their sets balance the torque, ``A^T lam + B tau = 0`` (then every row's acceleration is 0,
every condition of Gauss's principle holds, and its minimiser is unique). Take the contacts'
forces 0 (a unilateral force cannot balance both ``tau`` and ``-tau``), the ideal wheels'
free, and the friction sets' forces ``lam = C y`` with ``C`` the sets' sizes (a split
ellipse: its smaller semi-axis along the link, a disc inside the ellipse), and ``y = Y tau``
the least-norm solution of the balance (the rows least loaded relative to their sets). Where
the balance has a solution for every torque, the largest fraction of a set used over the
region is, per block ``b``, ``r |Y_b T|_2`` on the ellipsoid ``tau^T N tau <= r^2`` (``T``
the whitening, ``N = T^-T T^-1``) and the largest ``|Y_b v|`` over the box's vertices ``v``
(a convex function's largest value on a box is at a vertex; past 12 joints the bound
``sum_j tau_max_j |Y_b e_j|``); on both, the smaller. Every fraction below 1 proves that
friction holds every torque of the region. The test is sufficient: a region it does not
prove held is left to the pieces and the search, which never claim it.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from .maps import whitening
from .solve import BOX, DISC, FREE, SPLIT

__all__ = ["Hold", "friction_holds", "HOLD_MARGIN", "BALANCE_TOL", "MAX_VERTEX_JOINTS"]

#: The region is held when every set is used to at most ``1 - HOLD_MARGIN`` of its size.
HOLD_MARGIN = 1e-6
#: The balance ``A^T lam + B tau = 0`` is solvable for every torque when its least-squares
#: residual is below this, relative to ``|B|``.
BALANCE_TOL = 1e-9
#: Rounds of the balance's reweighting (each a least-norm solve leaning less on the sets used
#: most; the best round is kept: every round's balance is a valid one).
REWEIGHT_ROUNDS = 30
#: The box's vertices are enumerated up to this many joints.
MAX_VERTEX_JOINTS = 12


@dataclass
class Hold:
    """``holds``: friction holds every torque of the region (nothing moves there).
    ``fraction``: the largest fraction of a set the balance uses over the region (NaN where
    the sets alone cannot balance every torque). ``tau``: a torque of the region where that
    fraction is reached. ``block``: that set's block. ``reason``: why not held."""

    holds: bool
    fraction: float
    tau: np.ndarray
    block: int
    reason: str


def _rows(p):
    """The ground sets' rows: free (ideal wheels), and the bounded ones with their sizes
    (``c``) and blocks."""
    free, bounded, size, owner = [], [], [], []
    for b, (k, par, lab) in enumerate(zip(p.kind, p.par, p.rows.labels)):
        if lab[0] == "contact":
            continue
        r = p.start[b]
        if k == FREE:
            free.append(r)
        elif k == BOX and par[0] > 0:
            bounded.append(r), size.append(par[0]), owner.append(b)
        elif k == DISC and par[0] > 0:
            bounded += [r, r + 1]
            size += [par[0], par[0]]
            owner += [b, b]
        elif k == SPLIT and par[2] > 0 and min(par[0], par[1]) > 0:
            bounded += [r, r + 1]
            size += [min(par[0], par[1]), par[2]]
            owner += [b, b]
    return free, bounded, np.array(size), np.array(owner, dtype=int)


def _worst(Yb, T, verts, radius, tau_max):
    """The largest ``|Y_b tau|`` over the region and a torque where it is reached."""
    cands = []
    if radius is not None:
        _, s, vt = np.linalg.svd(Yb @ T)
        cands.append((radius * s[0], radius * (T @ vt[0])))
    if verts is not None:
        g = np.linalg.norm(verts @ Yb.T, axis=1)
        i = int(np.argmax(g))
        cands.append((float(g[i]), verts[i]))
    elif tau_max is not None:
        cands.append((float(np.linalg.norm(Yb, axis=0) @ tau_max),
                      tau_max * np.where(Yb[0] < 0, -1.0, 1.0)))
    return min(cands, key=lambda c: c[0])


def _region_scale(p, radius, tau_max, tau):
    """The largest ``t <= 1`` with ``t tau`` in the region."""
    t = 1.0
    if radius is not None:
        t = min(t, radius / np.sqrt(max(tau @ p.N @ tau, 1e-300)))
    if tau_max is not None:
        big = np.abs(tau) > 0
        t = min(t, float(np.min(tau_max[big] / np.abs(tau[big]), initial=np.inf)))
    return t


def friction_holds(p, radius=None, tau_max=None) -> Hold:
    """Whether friction holds every torque of the region ``tau^T N tau <= radius^2`` and/or
    ``|tau_j| <= tau_max_j`` (problem ``p``: :class:`~snakecg.scenes.maps.Problem`) still;
    see the module docstring."""
    na = p.n_a
    none = np.full(na, np.nan)
    free, bounded, size, owner = _rows(p)
    if not bounded and not free:
        return Hold(False, np.nan, none, -1, "no ground set holds the snake")
    A = p.A
    # the balance A_f^T lam_f + A_c^T C y = -B tau, the free rows projected out
    P = np.eye(p.n)
    if free:
        Af = A[free].T
        P = P - Af @ np.linalg.pinv(Af)
    K = P @ (A[bounded].T * size[None, :]) if bounded else np.zeros((p.n, 0))
    PB = P @ p.B
    if not bounded:
        resid = np.linalg.norm(PB)
    else:
        resid = np.linalg.norm(K @ (np.linalg.pinv(K) @ PB) - PB)
    if resid > BALANCE_TOL * np.linalg.norm(p.B):
        return Hold(False, np.nan, none, -1, "the ground sets alone do not hold the snake "
                                             "still: some torque moves it with every set "
                                             "sticking")
    if not bounded:  # ideal wheels alone lock the snake: every torque is held
        return Hold(True, 0.0, np.zeros(na), -1, "")
    T = whitening(p)
    verts = None
    if tau_max is not None and na <= MAX_VERTEX_JOINTS:
        verts = np.array(list(itertools.product((-1.0, 1.0), repeat=na))) * tau_max
    blocks = np.unique(owner)
    weight = np.ones(len(bounded))
    best = (np.inf, None, -1)
    for _ in range(REWEIGHT_ROUNDS):
        s = 1.0 / np.sqrt(weight)
        Y = -s[:, None] * (np.linalg.pinv(K * s[None, :]) @ PB)
        used = {int(b): _worst(Y[owner == b], T, verts, radius, tau_max) for b in blocks}
        wb = max(used, key=lambda b: used[b][0])
        top = used[wb][0]
        if top < best[0]:
            best = (top, used[wb][1], wb)
        if not top > 0:  # no set is loaded: the ideal wheels hold every torque
            break
        # the next balance leans less on the sets used most
        for b, (g, _) in used.items():
            weight[owner == b] *= (g / top) ** 2
        weight = np.clip(weight / weight.max(), 1e-6, 1.0)
    worst, where, wb = best
    where = where * _region_scale(p, radius, tau_max, where)
    if worst > 1 - HOLD_MARGIN:
        return Hold(False, float(worst), where, wb, f"a torque of the region needs "
                                                    f"{worst:.4g} of a friction set's size")
    return Hold(True, float(worst), where, wb, "")
