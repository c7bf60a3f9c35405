"""The constraint forces: an exact active-set solve of the contact/wheel complementarity problem.

At the acceleration level (eqs. 12-14) the rows' accelerations are ``w = G_c lam + b`` with
the Delassus matrix ``G_c = A I^-1 A^T`` and ``b = A I^-1 (f - p) + Adot v``, and

* contact (row 0): ``lam_c >= 0, w_c >= 0, lam_c w_c = 0``;
* ideal wheel: ``w_i = 0``, ``lam_i`` free;
* bounded wheel: ``|lam_i| <= u_i = mu m_i g``; ``w_i = 0`` inside the bound,
  ``w_i <= 0`` at ``lam_i = +u_i`` and ``w_i >= 0`` at ``lam_i = -u_i`` (friction opposes
  the sliding acceleration).

These are exactly the KKT conditions of the convex QP ``min 1/2 lam^T G_c lam + b^T lam``
over the box ``{lam_c >= 0, -u <= lam_w <= u}``. For a given active set the compiled
``constrained_dynamics`` solves the held rows with equality and fixes the others; this
module picks the active set:

1. a primal-dual active-set iteration, vectorized over the batch (start from "everything
   holds"; move every row that violates its condition; repeat); at termination the KKT
   conditions hold to tolerance, so the answer is the QP's exact solution;
2. for the rare sample that has not settled after ``max_iter`` iterations, enumeration of
   every active set (``2 * 3^{n_wheels}``), keeping the one that satisfies the KKT conditions.

When ``G_c`` restricted to the held rows is singular (dependent constraints, e.g. a wheel row
parallel to the contact row), the pivot ratio of its LDL factorization drops to zero; the
sample is then re-solved with a tiny Tikhonov term (the least-norm solution in the limit) and
flagged ``singular``.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from .engine.rules import (
    ABSENT,
    FORCE_LIMIT,
    HELD,
    LOST,
    PIVOT_TOL,
    POSITION_LIMIT,
    REGULARIZATION,
    REL_TOL,
    ROUND_REL,
    SLIDE_NEG,
    SLIDE_POS,
    default_max_iter,
)

__all__ = ["ActiveSetSolution", "solve_active_set", "PIVOT_TOL", "check_input_range"]



@dataclass
class ActiveSetSolution:
    outputs: dict[str, np.ndarray]
    state: np.ndarray  # (N, n_c) int8 row states
    singular: np.ndarray  # (N,) bool
    iterations: int
    enumerated: int
    conditioning: np.ndarray = None  # (N,), set by snakecg.rows.finish
    reason: np.ndarray = None  # (N,) codes of snakecg.rows.REASONS, set by snakecg.rows.finish


def _free_and_fixed(state: np.ndarray, bounds: np.ndarray):
    free = (state == HELD).astype(float)
    lam_fixed = np.where(state == SLIDE_POS, bounds, 0.0) - np.where(state == SLIDE_NEG, bounds, 0.0)
    lam_fixed = np.where(np.isfinite(lam_fixed), lam_fixed, 0.0)
    return np.ascontiguousarray(free), np.ascontiguousarray(lam_fixed)


def _violations(state, lam, w, bounds, tol_lam, tol_w):
    """Boolean (N, n_c) of rows whose condition fails, and the state they should move to."""
    new = state.copy()
    bounded = np.isfinite(bounds)
    # contact, row 0
    held_c = state[:, 0] == HELD
    lost_c = state[:, 0] == LOST
    new[held_c & (lam[:, 0] < -tol_lam[:, 0]), 0] = LOST
    new[lost_c & (w[:, 0] < -tol_w[:, 0]), 0] = HELD
    # wheels, rows 1..
    s = state[:, 1:]
    lw, ww, ub = lam[:, 1:], w[:, 1:], bounds[1:]
    tol_lam, tol_w = tol_lam[:, 1:], tol_w[:, 1:]
    bw = np.broadcast_to(bounded[1:], s.shape)
    n1 = new[:, 1:]
    n1[(s == HELD) & bw & (lw > ub + tol_lam)] = SLIDE_POS
    n1[(s == HELD) & bw & (lw < -ub - tol_lam)] = SLIDE_NEG
    n1[(s == SLIDE_POS) & (ww > tol_w)] = HELD
    n1[(s == SLIDE_NEG) & (ww < -tol_w)] = HELD
    new[:, 1:] = n1
    return new







_LIMITS = {"tau": FORCE_LIMIT, "f_obj": FORCE_LIMIT, "v": FORCE_LIMIT ** 0.5,
           "v_obj": FORCE_LIMIT ** 0.5}


def check_position_range(parts: dict) -> None:
    """Refuse an object pose or contact point beyond :data:`POSITION_LIMIT` (checked on every
    path, before any work: such a system overflows float64 and LAPACK may never return on
    it). ``parts``: ``{name: (array, batched)}``."""
    from .errors import InputError

    for name in ("q_obj", "rho"):
        if name in parts:
            arr = parts[name][0]
            with np.errstate(invalid="ignore"):
                big = np.abs(arr) > POSITION_LIMIT
            if np.any(big):
                idx = tuple(int(i) for i in np.argwhere(big)[0])
                raise InputError(f"{name} must have every entry within +-{POSITION_LIMIT:.0e}"
                                 f" (m, rad: the object's pose and contact point; beyond it"
                                 f" the contact row overflows float64), found {arr[idx]:.3e} at"
                                 f" index {idx}")


def check_input_range(parts: dict) -> None:
    """Refuse finite inputs whose results would overflow float64 (the norms are quadratic in
    the forces and quartic in the velocities): ``|tau|, |f_obj| <= 1e150``,
    ``|v|, |v_obj| <= 1e75``. ``parts``: ``{name: (array, batched)}``."""
    from .errors import InputError

    for name, limit in _LIMITS.items():
        if name in parts:
            arr = parts[name][0]
            big = np.abs(arr) > limit
            if np.any(big):
                idx = tuple(int(i) for i in np.argwhere(big)[0])
                raise InputError(f"{name} must have every entry within +-{limit:.0e} (the norms"
                                 f" are quadratic in the forces and would overflow float64),"
                                 f" found {arr[idx]:.3e} at index {idx}")








def _tolerances(out):
    """Decision tolerances of every row, relative to the row's own scale (no absolute floor).

    Row ``r`` is judged against ``s_r = max(|lam_r|, |w_r| / G_rr, |b_r| / G_rr,
    ROUND_REL sum_j |G_rj lam_j| / G_rr)`` (force units; ``b = w - G lam``, the row's
    acceleration at zero force): ``tol_lam_r = REL_TOL s_r`` and ``tol_w_r = REL_TOL G_rr
    s_r`` (``(N, n_c)`` each). Scaling every input force (torque, external wrench, wheel
    bounds) by ``s`` scales every term by ``s``: the decisions do not depend on the units or
    the magnitude of the torque. A row's own scale, not the sample's largest force: nearly
    dependent wheel rows carry huge pinning forces that cancel in the other rows, and must not
    widen their tolerance (the last term is the rounding level of those cancellations). The
    compiled rule (``sc_next_states``, snakecg/engine/contact.c) is this one, operation for
    operation.
    """
    lam, w, G = out["lam"], out["w"], out["delassus"]
    nc = lam.shape[1]
    d = np.abs(np.diagonal(G, axis1=1, axis2=2))
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        gr = np.where((d > 0) & np.isfinite(d), d, _g_scale(G)[:, None])
        b = np.array(w, dtype=float)
        cross = np.zeros_like(b)
        for j in range(nc):  # in the C's order
            t = G[:, :, j] * lam[:, j:j + 1]
            b -= t
            cross += np.abs(t)
        s = np.maximum(np.maximum(np.abs(lam), np.abs(w) / gr),
                       np.maximum(np.abs(b) / gr, ROUND_REL * cross / gr))
    return REL_TOL * s, REL_TOL * gr * s


def _g_scale(G):
    """Largest diagonal of each Delassus matrix (1 where it is not positive and finite)."""
    g = np.abs(np.diagonal(G, axis1=1, axis2=2)).max(axis=1)
    return np.where((g > 0) & np.isfinite(g), g, 1.0)


def _evaluate(call, idx, state, bounds):
    free, lam_fixed = _free_and_fixed(state, bounds)
    out = call(idx, free, lam_fixed, np.zeros(len(idx)))
    bad = ~(out["pivot_ratio"] > PIVOT_TOL) | ~np.all(np.isfinite(out["lam"]), axis=1)
    singular = np.zeros(len(idx), dtype=bool)
    if np.any(bad):
        sub = np.flatnonzero(bad)
        scale = np.abs(np.diagonal(out["delassus"][sub], axis1=1, axis2=2)).max(axis=1)
        reg = REGULARIZATION * np.maximum(scale, 1e-300)
        again = call(idx[sub], free[sub], lam_fixed[sub], reg)
        for k in out:
            out[k][sub] = again[k]
        singular[sub] = True
    return out, singular


def solve_active_set(call, n: int, present: np.ndarray, bounds: np.ndarray, *,
                     max_iter: int | None = None) -> ActiveSetSolution:
    """Solve the complementarity problem for ``n`` samples.

    ``call(idx, free, lam_fixed, regularization)`` evaluates the compiled
    ``constrained_dynamics`` on the samples ``idx`` and returns a dict of 2-D outputs
    (``lam``, ``w`` of shape ``(len(idx), n_c)``, scalars as ``(len(idx),)``).
    ``present`` (n_c,) marks existing rows (row 0: contact), ``bounds`` (n_c,) the wheel
    force bounds (``inf`` for ideal wheels and the contact).
    """
    nc = len(present)
    if max_iter is None:
        max_iter = default_max_iter(nc)
    state = np.where(present, HELD, ABSENT).astype(np.int8)
    state = np.repeat(state[None, :], n, axis=0)
    idx_all = np.arange(n)
    outputs = None
    singular = np.zeros(n, dtype=bool)
    active = idx_all
    iterations = 0
    while active.size and iterations < max_iter:
        iterations += 1
        out, sing = _evaluate(call, active, state[active], bounds)
        if outputs is None:  # the first pass covers every sample, in order: keep its arrays
            outputs, singular = out, sing
        else:
            for k, v in out.items():
                outputs[k][active] = v
            singular[active] = sing
        tol_lam, tol_w = _tolerances(out)
        new = _violations(state[active], out["lam"], out["w"], bounds, tol_lam, tol_w)
        changed = np.any(new != state[active], axis=1)
        state[active] = new
        active = active[changed]
    enumerated = 0
    for i in active:  # not settled: enumerate the active sets of this sample
        enumerated += 1
        out_i, state_i, sing_i = _enumerate(call, int(i), present, bounds)
        for k, v in out_i.items():
            outputs[k][i] = v
        state[i] = state_i
        singular[i] = sing_i
    return ActiveSetSolution(outputs, state, singular, iterations, enumerated)


def _enumerate(call, i: int, present, bounds):
    choices = []
    for r, p in enumerate(present):
        if not p:
            choices.append((ABSENT,))
        elif r == 0:
            choices.append((HELD, LOST))
        elif np.isfinite(bounds[r]):
            choices.append((HELD, SLIDE_POS, SLIDE_NEG))
        else:
            choices.append((HELD,))
    combos = np.array(list(itertools.product(*choices)), dtype=np.int8)
    idx = np.full(len(combos), i)
    out, sing = _evaluate(call, idx, combos, bounds)
    tol_lam, tol_w = _tolerances(out)
    lam, w = out["lam"], out["w"]
    # KKT residual of each candidate (0 for the solution)
    res = np.zeros(len(combos))
    if present[0]:  # (the free rows only: a forced row keeps its state)
        res += np.where(combos[:, 0] == HELD, np.maximum(-lam[:, 0], 0),
                        np.maximum(-w[:, 0], 0))
    ub = bounds[1:]
    s, lw, ww = combos[:, 1:], lam[:, 1:], w[:, 1:]
    with np.errstate(invalid="ignore"):
        held_excess = np.where(np.isfinite(ub), np.maximum(np.abs(lw) - ub, 0), 0)
    res += np.sum(np.where(s == HELD, held_excess, 0), axis=1)
    res += np.sum(np.where(s == SLIDE_POS, np.maximum(ww, 0), 0), axis=1)
    res += np.sum(np.where(s == SLIDE_NEG, np.maximum(-ww, 0), 0), axis=1)
    best = int(np.argmin(res))
    return {k: v[best] for k, v in out.items()}, combos[best], bool(sing[best])
