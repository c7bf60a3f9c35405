"""Starting points of the shape search: a coarse grid (or a seeded Sobol sample) of joint
angles, each point scored by the exact inner optimum over the torque (NumPy, from the
model's batched maps), the best distinct points kept; and the initial separating slabs."""

from __future__ import annotations

import numpy as np

from ._nlp import FRICTION_MARGIN, SR_EPS, geometry_pairs

#: Points of the coarse grid (at most about twice this many; a Sobol sample beyond).
GRID_BUDGET = 4096


def coarse_points(lo, hi, seed: int):
    """Joint-angle samples ``(M, n_a)`` within the limits and the spacing between neighbours.

    An odd number ``k >= 3`` of values per joint (so a symmetric range includes 0) with
    ``k^n_a`` at most about twice :data:`GRID_BUDGET`; when even 3 values are too many, a
    scrambled Sobol sample of :data:`GRID_BUDGET` points drawn with ``seed``.
    """
    na = len(lo)
    k = int(np.floor(GRID_BUDGET ** (1.0 / na) + 1e-9))
    k = k if k % 2 else k - 1
    k = max(k, 3)
    if k ** na <= 2 * GRID_BUDGET:
        axes = [np.linspace(lo[j], hi[j], k) for j in range(na)]
        mesh = np.meshgrid(*axes, indexing="ij")
        pts = np.stack([m.ravel() for m in mesh], axis=1)
        return pts, (hi - lo) / (k - 1)
    from scipy.stats import qmc

    u = qmc.Sobol(na, scramble=True, rng=np.random.default_rng(seed)).random(GRID_BUDGET)
    return lo + u * (hi - lo), (hi - lo) / GRID_BUDGET ** (1.0 / na)


def _solve(A, b):
    return np.linalg.solve(A, b[..., None])[..., 0]


def inner_optimum(model, objective, maps, query):
    """Exact (NumPy) inner optimum over the torque at each configuration of a batch, for the
    same formulation as the NLP: ``(score, tau)``; ``score`` is the NLP's ``value`` (larger is
    better; ``-inf`` where the task cannot be done at the configuration)."""
    L, A_, Xi, Om, N = (maps[k] for k in ("lam_from_tau", "a_obj_from_tau", "xi_tau",
                                          "omega_tau", "input_metric"))
    c = L[:, 0, :]
    cc = np.einsum("ni,ni->n", c, c)
    ok = (cc > 0) & ~maps["singular"]
    cc = np.where(ok, cc, 1.0)
    k = np.trace(Om, axis1=1, axis2=2) / cc
    a_dir = np.einsum("nij,nj->ni", A_, c) / cc[:, None]
    if query.direction is not None:
        gamma = a_dir @ query.direction
    else:
        gamma = np.linalg.norm(a_dir, axis=1)
    eps = SR_EPS * np.trace(Xi, axis1=1, axis2=2) / np.trace(N, axis1=1, axis2=2)
    Xe = Xi + eps[:, None, None] * N
    r = 1.0 if query.radius is None else query.radius
    na = c.shape[1]
    if objective == "max_sr":
        y = _solve(Xe, c)
        score = k * np.einsum("ni,ni->n", c, y)
        tau = y / np.einsum("ni,ni->n", c, y)[:, None]
    elif objective == "least_slip_push":
        y = _solve(Xe, c)
        s = np.einsum("ni,ni->n", c, y)
        if query.a_obj is not None:
            lam = a_dir @ query.a_obj / np.maximum(np.einsum("ni,ni->n", a_dir, a_dir), 1e-300)
            resid = np.linalg.norm(query.a_obj[None] - lam[:, None] * a_dir, axis=1)
        else:
            lam = query.a_min / np.where(gamma > 0, gamma, np.nan)
            resid = np.zeros(len(c))
        tau = (lam / s)[:, None] * y
        score = -np.einsum("ni,nij,nj->n", tau, Xe, tau)
        bad = ~np.isfinite(score) | (lam < 0) | (resid > 1e-9 * max(1.0, float(
            np.linalg.norm(query.a_obj) if query.a_obj is not None else 1.0)))
        bad |= _outside(model, query, L, N, tau)
        # infeasible configurations rank below every feasible one, by their violation
        score = np.where(bad, -1e300 * (1 + np.nan_to_num(resid, nan=1e3)), score)
        tau = np.nan_to_num(tau)
    else:  # max_a_obj, strongest_push: along N^-1 c^T, scaled into every limit
        y = _solve(N, c)
        s = np.sqrt(np.maximum(np.einsum("ni,ni->n", c, y), 1e-300))
        tau = r * y / s[:, None]
        t = _limit_scale(model, query, L, tau)
        tau = tau * t[:, None]
        lam_c = np.einsum("ni,ni->n", c, tau)
        score = (np.sqrt(k) * lam_c if objective == "max_a_obj" else gamma * lam_c)
        if objective == "strongest_push":
            score = np.where(gamma > 0, score, -1e300)
    score = np.where(ok & np.isfinite(score), score, -np.inf)
    return score, np.nan_to_num(tau)[:, :na]


def _limit_scale(model, query, L, tau):
    """Largest ``t <= 1`` with ``t tau`` within the torque box and the friction bounds."""
    t = np.ones(len(tau))
    if query.tau_max is not None:
        with np.errstate(divide="ignore"):
            t = np.minimum(t, np.min(query.tau_max / np.abs(tau), axis=1))
    for i in range(1, model.n_constraints):
        u = model.bounds[i]
        if model.present[i] and np.isfinite(u):
            li = np.abs(np.einsum("ni,ni->n", L[:, i, :], tau))
            with np.errstate(divide="ignore"):
                t = np.minimum(t, u * (1 - 2 * FRICTION_MARGIN) / li)
    return t


def _outside(model, query, L, N, tau):
    bad = np.zeros(len(tau), bool)
    if query.radius is not None:
        bad |= np.einsum("ni,nij,nj->n", tau, N, tau) > query.radius ** 2
    bad |= _limit_scale(model, query, L, tau) < 1.0
    return bad


def mirrored(objective, query, lo, hi) -> bool:
    """Whether the task is symmetric under the mirror image of the shape (every joint angle
    negated, the pose kept): the metrics of ``max_sr`` and ``max_a_obj`` and the pushes along
    the default direction (the contact normal, mirrored with the shape) are, within joint
    limits symmetric about 0; a world-frame ``direction`` or ``a_obj`` is not."""
    return (objective in ("max_sr", "max_a_obj", "strongest_push", "least_slip_push")
            and query.direction is None and query.a_obj is None
            and np.allclose(lo, -hi, rtol=0, atol=1e-12))


def mirror_scores(points, score, rescore):
    """The score of each point's mirror image ``-points``: read off a grid symmetric about 0
    (its points in reverse order), else ``rescore(-points)``."""
    if np.array_equal(points[::-1], -points):
        return score[::-1]
    return rescore(-points)


#: Rounds of the pattern search that follows each candidate start to its basin.
ASCENT_ROUNDS = 10
#: Candidates followed per start asked for.
ASCENT_CANDIDATES = 6


def ascend(points, score, step, lo, hi, rescore, rounds: int = ASCENT_ROUNDS):
    """Follow each point uphill on the score (a compass search: every joint +-h, the best
    move kept, h halved where none improves; starting at half the grid spacing), all points
    at once: ``(ends, values)``. Points that end next to each other lie in one basin."""
    x = points.copy()
    best = score.copy()
    h = np.broadcast_to(0.5 * step, x.shape).copy()
    n, na = x.shape
    for _ in range(rounds):
        moves = []
        for j in range(na):
            for sgn in (1.0, -1.0):
                c = x.copy()
                c[:, j] = np.clip(c[:, j] + sgn * h[:, j], lo[j], hi[j])
                moves.append(c)
        cand = np.stack(moves, axis=1)  # (n, 2 na, na)
        val = rescore(cand.reshape(-1, na)).reshape(n, 2 * na)
        j = np.argmax(val, axis=1)
        vj = val[np.arange(n), j]
        up = vj > best + 1e-12 * np.abs(best)
        x = np.where(up[:, None], cand[np.arange(n), j], x)
        best = np.where(up, vj, best)
        h = np.where(up[:, None], h, 0.5 * h)
    return x, best


def pick_starts(points, score, step, n, mirror=None, basin=None):
    """Up to ``n`` best points, skipping direct neighbours of points already taken (so that
    the starts lie in different basins); ties broken by the coordinates (deterministic).

    ``mirror``: the score of each point's mirror image (a symmetric task, :func:`mirrored`);
    a point whose mirror image lies next to a point already taken, with the same score, is
    that basin's mirror image and is skipped (its answer is the mirror of the other's), so
    the starts go to distinct basins instead of to mirror pairs.
    ``basin(idx)``: ``(ends, values)`` of the points ``idx`` followed uphill (:func:`ascend`);
    a point whose basin's end lies next to (or mirrors) that of a point taken already is
    skipped too, and the candidates are taken in the order of their basins' values."""
    order = np.lexsort(tuple(points[:, j] for j in range(points.shape[1] - 1, -1, -1))
                       + (-score,))
    good = order[score[order] > -1e299]  # the task is possible and the shape feasible
    taken = []

    def near(a, b, tol=1.01):
        return np.max(np.abs((a - b) / step)) <= tol

    def image(idx):  # idx is the mirror image of a start taken already
        if mirror is None or not abs(mirror[idx] - score[idx]) <= 1e-9 * abs(score[idx]):
            return False
        return any(near(-points[idx], points[t]) for t in taken)

    ends = {}
    if basin is not None and good.size:
        # the best candidates (distinct neighbourhoods first), followed to their basins
        cand = []
        for idx in good:
            if all(not near(points[idx], points[t]) for t in cand) and not (
                    mirror is not None and abs(mirror[idx] - score[idx]) <= 1e-9 * abs(
                        score[idx]) and any(near(-points[idx], points[t]) for t in cand)):
                cand.append(idx)
                if len(cand) == ASCENT_CANDIDATES * n:
                    break
        e, v = basin(np.array(cand))
        ends = {idx: (e[k], v[k]) for k, idx in enumerate(cand)}
        rank = sorted(cand, key=lambda i: (-round(ends[i][1], 12), tuple(points[i])))
        for idx in rank:
            end = ends[idx][0]
            same = any(near(end, ends[t][0], 0.25)
                       or (mirror is not None and near(-end, ends[t][0], 0.25))
                       for t in taken)
            if not same:
                taken.append(idx)
                if len(taken) == n:
                    break
    for idx in good:
        if len(taken) == n:
            break
        if idx not in taken and all(not near(points[idx], points[t]) for t in taken) \
                and not image(idx):
            taken.append(idx)
    for idx in good:  # fewer basins than starts: the next best points
        if len(taken) == n:
            break
        if idx not in taken and not image(idx):
            taken.append(idx)
    if not taken:  # nowhere possible: the least violating points
        taken = list(order[np.isfinite(score[order])][:n])
    return np.array(taken, dtype=int)


def initial_slabs(model, q):
    """``(alpha, b)`` per geometry pair at configuration ``q``: the normal from the closest
    points of the two sets and the offset half-way between them."""
    from ..geometry import OBJECT_SIDE, link_segments

    rear, front = link_segments(model.robot, model.link_poses(q))
    q_obj = model.place_object(q)[0]
    h = OBJECT_SIDE / 2
    R = np.array([[np.cos(q_obj[2]), -np.sin(q_obj[2])], [np.sin(q_obj[2]), np.cos(q_obj[2])]])
    corners = q_obj[:2] + (R @ (h * np.array([[1, -1, -1, 1], [1, 1, -1, -1]]))).T
    out = []
    for kind, i, j in geometry_pairs(model):
        A = np.array([rear[i], front[i]])
        B = np.array([rear[j], front[j]]) if kind == "links" else corners
        pa, pb = _closest(A, B, closed=kind == "object")
        d = pb - pa
        if np.linalg.norm(d) < 1e-12:
            d = B.mean(axis=0) - A.mean(axis=0)
        n = d / max(np.linalg.norm(d), 1e-300)
        b = 0.5 * (np.max(A @ n) + np.min(B @ n))
        out += [np.arctan2(n[1], n[0]), b]
    return np.array(out)


def _closest(A, B, closed):
    """Closest points of segment ``A`` (2 points) and segment / closed polygon ``B``."""
    def proj(p, a, b):
        d = b - a
        t = np.clip((p - a) @ d / max(d @ d, 1e-300), 0.0, 1.0)
        return a + t * d

    edges_b = [(B[m], B[(m + 1) % len(B)]) for m in range(len(B) if closed else 1)]
    best = (np.inf, A[0], B[0])
    for a0, a1 in [(A[0], A[1])]:
        for b0, b1 in edges_b:
            for p, s0, s1, first in ((a0, b0, b1, True), (a1, b0, b1, True),
                                     (b0, a0, a1, False), (b1, a0, a1, False)):
                c = proj(p, s0, s1)
                dist = np.linalg.norm(p - c)
                if dist < best[0]:
                    best = (dist, p, c) if first else (dist, c, p)
    return best[1], best[2]
