"""An independent NumPy geometry of the simulation's contact check, for the tests.

Written apart from ``snakecg.geometry`` and ``snakecg/engine/geometry.c``: the links from the
coordinates by their own chain, the plate from its corners in the world frame, and

* a link's depth in the plate as a small linear program solved by enumeration: the depth of
  the point ``a + t (b - a)`` is the least of its four signed distances to the edges' lines
  (each linear in ``t``), and the largest such least value over ``t`` in ``[0, 1]`` lies at
  an end or where two of the four lines meet (the package instead works in the plate's frame
  with ``h - max(|x|, |y|)``);
* two links cross when the 2 x 2 system ``a0 + s (a1 - a0) = b0 + u (b1 - b0)`` has its
  solution inside ``(0, 1)^2`` (``numpy.linalg.solve``; the package uses orientation signs);
  their depth is then the least distance from an end of one to the other.

Every function is vectorised over a leading axis of samples. ``check_trajectory`` is the
property the suite asserts over every simulation it runs (``conftest.py``): no sample before
the reported first violation overlaps beyond the tolerance, and the violation is where the
trajectory says.
"""

from __future__ import annotations

import numpy as np

#: The documented tolerance: 1e-6 of the longest link.
RELATIVE_TOLERANCE = 1e-6


def link_ends(robot, q):
    """Rear and front ends ``(N, n_l, 2)`` of the links at ``q`` ``(N, n_s)``: link 1's COM
    ``(x, y)`` and angle ``theta``, then relative joint angles."""
    q = np.atleast_2d(np.asarray(q, float))
    n_l = len(robot.length)
    rear = np.empty((len(q), n_l, 2))
    front = np.empty_like(rear)
    phi = q[:, 2].copy()
    for i in range(n_l):
        if i:
            phi = phi + q[:, 2 + i]
        e = np.stack([np.cos(phi), np.sin(phi)], axis=-1)
        rear[:, i] = q[:, :2] - robot.com[0] * e if i == 0 else front[:, i - 1]
        front[:, i] = rear[:, i] + robot.length[i] * e
    return rear, front


def plate_corners(q_obj, half):
    """The plate's corners ``(N, 4, 2)``, anticlockwise."""
    q_obj = np.atleast_2d(np.asarray(q_obj, float))
    out = []
    for lx, ly in ((-half, -half), (half, -half), (half, half), (-half, half)):
        c, s = np.cos(q_obj[:, 2]), np.sin(q_obj[:, 2])
        out.append(np.stack([q_obj[:, 0] + c * lx - s * ly, q_obj[:, 1] + s * lx + c * ly], -1))
    return np.stack(out, axis=1)


def plate_depth(a, b, corners):
    """How deep the segments ``a``-``b`` ``(N, 2)`` reach into the convex plates
    ``corners`` ``(N, 4, 2)``: ``max over t of min over edges`` of the signed distance
    (inside positive), 0 when outside."""
    edges = np.roll(corners, -1, axis=1) - corners
    normal = np.stack([-edges[..., 1], edges[..., 0]], -1) / np.linalg.norm(
        edges, axis=-1, keepdims=True)                       # inward: anticlockwise corners
    alpha = np.einsum("nkj,nkj->nk", a[:, None, :] - corners, normal)   # d_k(0)
    beta = np.einsum("nkj,nj->nk", normal, b - a)                        # d_k'(t)
    cands = [np.zeros(len(a)), np.ones(len(a))]
    for k in range(4):
        for m in range(k + 1, 4):
            with np.errstate(divide="ignore", invalid="ignore"):
                t = (alpha[:, m] - alpha[:, k]) / (beta[:, k] - beta[:, m])
            cands.append(np.clip(np.where(np.isfinite(t), t, 0.0), 0.0, 1.0))
    best = np.zeros(len(a))
    for t in cands:
        best = np.maximum(best, (alpha + beta * t[:, None]).min(axis=1))
    return best


def point_segment(p, a, b):
    """Distance from the points ``p`` to the segments ``a``-``b`` (all ``(N, 2)``)."""
    d = b - a
    t = np.clip(np.einsum("nj,nj->n", p - a, d) / np.maximum(np.einsum("nj,nj->n", d, d),
                                                             1e-300), 0.0, 1.0)
    return np.linalg.norm(p - (a + t[:, None] * d), axis=-1)


def crossing_depth(a0, a1, b0, b1):
    """How deep two segments cross (``(N,)``): the least distance from an end of one to the
    other when the solution ``(s, u)`` of ``a0 + s (a1 - a0) = b0 + u (b1 - b0)`` lies in
    ``(0, 1)^2``, else 0."""
    A = np.stack([a1 - a0, b0 - b1], axis=-1)  # (N, 2, 2): columns a1 - a0, -(b1 - b0)
    det = np.linalg.det(A)
    ok = np.abs(det) > 1e-300
    su = np.zeros((len(a0), 2))
    su[ok] = np.linalg.solve(A[ok], (b0 - a0)[ok][..., None])[..., 0]
    crossing = ok & (su[:, 0] > 0) & (su[:, 0] < 1) & (su[:, 1] > 0) & (su[:, 1] < 1)
    ends = np.min([point_segment(a0, b0, b1), point_segment(a1, b0, b1),
                   point_segment(b0, a0, a1), point_segment(b1, a0, a1)], axis=0)
    return np.where(crossing, ends, 0.0)


def sat_depths(scene, q, q_obj):
    """``(N, n_l)``: each link's penetration depth in the plate (the least translation that
    parts them; 0 apart) by the separating axis theorem: minus the largest gap of their
    projections over the axes normal to and along the link and the plate's edges."""
    rear, front = link_ends(scene.robot, q)
    corners = plate_corners(q_obj, scene.object_distance)                # (N, 4, 2)
    edges = np.roll(corners, -1, axis=1) - corners
    out = np.zeros(rear.shape[:2])
    for i in range(rear.shape[1]):
        seg = np.stack([rear[:, i], front[:, i]], axis=1)                 # (N, 2, 2)
        d = seg[:, 1] - seg[:, 0]
        axes = np.concatenate([edges[:, :2], d[:, None], np.stack([-d[:, 1], d[:, 0]],
                                                                   -1)[:, None]], axis=1)
        axes = axes / np.linalg.norm(axes, axis=-1, keepdims=True)
        axes = np.concatenate([axes, -axes], axis=1)                      # (N, 8, 2)
        ps = np.einsum("npj,naj->nap", seg, axes)
        pc = np.einsum("npj,naj->nap", corners, axes)
        gap = pc.min(axis=-1) - ps.max(axis=-1)                           # (N, 8)
        out[:, i] = np.maximum(0.0, -gap.max(axis=1))
    return out


def overlaps(scene, q, q_obj):
    """Every overlap ``(N, n_pairs)`` and the pairs' bodies (``(link, "object")`` or
    ``(link, link)``, links from 1): each link with the object (the square plate of side
    ``2 object_distance`` at ``q_obj``), then non-neighbouring links."""
    rear, front = link_ends(scene.robot, q)
    corners = plate_corners(q_obj, scene.object_distance)
    n_l = rear.shape[1]
    cols, bodies = [], []
    for i in range(n_l):
        cols.append(plate_depth(rear[:, i], front[:, i], corners))
        bodies.append((i + 1, "object"))
    for i in range(n_l):
        for j in range(i + 2, n_l):
            cols.append(crossing_depth(rear[:, i], front[:, i], rear[:, j], front[:, j]))
            bodies.append((i + 1, j + 1))
    return np.stack(cols, axis=-1), bodies


def tolerance(scene) -> float:
    return RELATIVE_TOLERANCE * max(scene.robot.length)


def first_crossing(scene, t, q, q_obj):
    """The first time the largest overlap exceeds the tolerance, by linear interpolation
    between the samples ``t`` around it, and its bodies; ``None`` when it never does."""
    d, bodies = overlaps(scene, q, q_obj)
    deepest = d.max(axis=1)
    tol = tolerance(scene)
    beyond = np.flatnonzero(deepest > tol)
    if not beyond.size:
        return None
    j = int(beyond[0])
    assert j > 0, "overlapping at the first sample"
    f = (tol - deepest[j - 1]) / (deepest[j] - deepest[j - 1])
    return t[j - 1] + f * (t[j] - t[j - 1]), bodies[int(np.argmax(d[j]))]


def check_trajectory(scene, mode, traj) -> None:
    """The property over every simulation: with the check on, no sample before the first
    violation overlaps beyond the tolerance (rounding aside); the violation's sample has the
    overlap the trajectory reports, between the bodies it names; a stopped run ends there."""
    if mode == "off":
        assert traj.violation is None
        return
    d, bodies = overlaps(scene, traj.q, traj.q_obj)
    tol = tolerance(scene)
    v = traj.violation
    before = traj.t < v.t if v is not None else np.ones(len(traj.t), dtype=bool)
    worst = d[before].max() if before.any() else 0.0
    assert worst <= tol * (1 + 1e-6), f"a sample overlaps by {worst:.3g} m > {tol:.3g} m"
    if v is None:
        return
    ns = traj.q.shape[1]
    dv, _ = overlaps(scene, v.y[:ns], v.y[ns:ns + 3])
    assert bodies[int(np.argmax(dv[0]))] == tuple(v.bodies)
    assert abs(dv[0].max() - v.depth) <= 1e-9 * tol
    assert v.depth >= tol * (1 - 1e-6)
    if mode == "stop":  # the run ends at the violation, its state the last sample
        assert traj.t[-1] == v.t
        np.testing.assert_array_equal(traj.q[-1], v.y[:ns])
        np.testing.assert_array_equal(traj.q_obj[-1], v.y[ns:ns + 3])
