"""Closest points between the scene's shapes, each a core and a radius: a link's capsule (a
segment, radius the robot's), a disc or peg (a point), a box (a convex polygon, radius 0), a
wall (a half-plane). Plain NumPy on one configuration; every function returns the pairs of
nearest points (two where two features are parallel: the ends of the shared interval).

The signed distance: apart, the least distance of the cores' features; overlapping, minus the
penetration depth by the separating axis theorem (the largest gap of the cores' projections
over the edges' normals and directions, negative when every axis overlaps), the radii
subtracted. The engine finds the contacts (``snakecg/engine/scene_geometry.c``, the depth from
the hull of the cores' Minkowski difference); this module is the tests' reference for its
closest points, written apart from it.
"""

from __future__ import annotations

import numpy as np

__all__ = ["Shape", "closest", "sat_gap"]


class Shape:
    """``kind`` 'segment' (``pts`` 2x2), 'point' (1x2), 'polygon' (kx2, counter-clockwise) or
    'halfplane' (``pts`` = [point], ``normal`` into the free side); ``radius``."""

    __slots__ = ("kind", "pts", "radius", "normal")

    def __init__(self, kind, pts, radius=0.0, normal=None):
        self.kind = kind
        self.pts = np.asarray(pts, dtype=float).reshape(-1, 2)
        self.radius = float(radius)
        self.normal = None if normal is None else np.asarray(normal, float) / np.hypot(*normal)

    def segments(self):
        p = self.pts
        if self.kind == "polygon":
            return [(p[i], p[(i + 1) % len(p)]) for i in range(len(p))]
        if self.kind == "segment":
            return [(p[0], p[1])]
        return [(p[0], p[0])]


def _point_segment(p, a, b):
    d = b - a
    L = d @ d
    t = 0.0 if L == 0 else min(1.0, max(0.0, (p - a) @ d / L))
    return a + t * d, t


def _segment_pairs(a0, a1, b0, b1, scale, merge):
    """Nearest point pairs of two segments: one, or the two ends of the shared stretch of
    parallel ones (its middle where shorter than ``merge``)."""
    da, db = a1 - a0, b1 - b0
    la, lb = np.hypot(*da), np.hypot(*db)
    cross = da[0] * db[1] - da[1] * db[0]
    if la > 0 and lb > 0 and abs(cross) <= 1e-12 * la * lb:
        u = da / la  # parallel: project b's ends on a
        s0, s1 = sorted(((b0 - a0) @ u, (b1 - a0) @ u))
        lo, hi = max(0.0, s0), min(la, s1)
        if hi - lo > 1e-9 * scale:
            out = []
            for s in ((lo, hi) if hi - lo > merge else (0.5 * (lo + hi),)):
                pa = a0 + s * u
                pb, _ = _point_segment(pa, b0, b1)
                out.append((pa, pb))
            return out
    cands = []
    for p in (a0, a1):
        q, _ = _point_segment(p, b0, b1)
        cands.append((p, q))
    for p in (b0, b1):
        q, _ = _point_segment(p, a0, a1)
        cands.append((q, p))
    if la > 0 and lb > 0 and cross != 0:  # crossing interiors
        w = b0 - a0
        t = (w[0] * db[1] - w[1] * db[0]) / cross
        s = (w[0] * da[1] - w[1] * da[0]) / cross
        if 0 < t < 1 and 0 < s < 1:
            x = a0 + t * da
            return [(x, x.copy())]
    dist = [np.hypot(*(q - p)) for p, q in cands]
    best = min(dist)
    return [cands[i] for i in range(4) if dist[i] <= best + 1e-12 * scale]


def sat_gap(A: Shape, B: Shape):
    """``(g, n)``: the largest gap ``min(B . n) - max(A . n)`` of the cores' projections over
    the unit axes normal and along every edge (both ways), and its axis. ``g < 0`` exactly
    where the cores overlap, then minus their penetration depth, ``n`` parting them."""
    best, axis = -np.inf, None
    for sh in (A, B):
        for a, b in sh.segments():
            e = b - a
            L = np.hypot(*e)
            if L == 0:
                continue
            for n in (np.array([e[1], -e[0]]) / L, e / L):
                for m in (n, -n):
                    g = (B.pts @ m).min() - (A.pts @ m).max()
                    if g > best:
                        best, axis = g, m
    return best, axis


def _overlap_pairs(A: Shape, B: Shape, n, scale, merge):
    """The contacts of overlapping cores parted along ``n``: A's supporting feature along
    ``n`` and B's against it; one for a corner, the ends of the shared stretch of two flush
    edges (its middle where shorter than ``merge``)."""
    t = np.array([-n[1], n[0]])
    pa, pb = A.pts @ n, B.pts @ n
    ha, hb = pa.max(), pb.min()
    sa = A.pts[pa >= ha - 1e-9 * scale] @ t
    sb = B.pts[pb <= hb + 1e-9 * scale] @ t
    if np.ptp(sa) <= 1e-9 * scale:
        us = [sa.min()]
    elif np.ptp(sb) <= 1e-9 * scale:
        us = [sb.min()]
    else:
        lo, hi = max(sa.min(), sb.min()), min(sa.max(), sb.max())
        us = [lo, hi] if hi - lo > merge else [0.5 * (lo + hi)]
    return [(ha * n + u * t, hb * n + u * t) for u in us]


def _feature_normal(sh, q, scale):
    """The outward normal of ``sh`` at its core point ``q``, where one exists (an edge's
    interior), else None."""
    if sh.kind == "halfplane":
        return sh.normal
    segs = sh.segments() if sh.kind in ("polygon", "segment") else []
    for a, b in segs:
        e = b - a
        L = np.hypot(*e)
        if L == 0:
            continue
        t = (q - a) @ e / (L * L)
        if 1e-9 < t < 1 - 1e-9 and abs((q - a)[0] * e[1] - (q - a)[1] * e[0]) / L <= 1e-9 * scale:
            n = np.array([e[1], -e[0]]) / L
            return n if sh.kind == "polygon" else None
    return None


def _centroid(sh):
    return sh.pts.mean(axis=0)


def closest(A: Shape, B: Shape, scale: float, merge: float = 0.0):
    """``(d, pairs)``: the signed distance of the two shapes' surfaces (< 0: overlap, its
    depth) and the contacts ``[(ca, cb, n)]``: the surface points on A and B and the unit
    normal from A to B; contacts closer than ``merge`` (the contact tolerance) are one.
    ``A`` is never a half-plane."""
    merge = max(merge, 1e-9 * scale)
    if B.kind == "halfplane":
        n = B.normal
        vals = A.pts @ n - B.pts[0] @ n
        if A.kind == "point":
            vals = vals[:1]
        best = vals.min()
        d = best - A.radius
        out = []
        for i in np.flatnonzero(vals <= best + 1e-12 * scale):
            ca = A.pts[i] - A.radius * n
            out.append((ca, ca - (vals[i] - best) * n - d * n, -n))
        return d, out
    if B.kind == "point" and A.kind in ("segment", "point"):  # a capsule or disc and a point
        q = B.pts[0]
        p = A.pts[0] if A.kind == "point" else _point_segment(q, A.pts[0], A.pts[1])[0]
        dd = float(np.hypot(*(q - p)))
        if dd > 1e-9 * scale:  # else the general path below (the features' normals)
            n = (q - p) / dd
            return dd - A.radius - B.radius, [(p + A.radius * n, q - B.radius * n, n)]
    g, axis = sat_gap(A, B)
    if axis is not None and g < -1e-12 * scale:  # overlapping cores (else touching)
        out = [(p + A.radius * axis, q - B.radius * axis, axis)
               for p, q in _overlap_pairs(A, B, axis, scale, merge)]
        return g - A.radius - B.radius, out
    pairs = []
    for a0, a1 in A.segments():
        for b0, b1 in B.segments():
            pairs += _segment_pairs(a0, a1, b0, b1, scale, merge)
    dist = np.array([np.hypot(*(q - p)) for p, q in pairs])
    core = dist.min()
    keep, out = [], []
    for (p, q), dd in zip(pairs, dist):
        if dd > core + 1e-12 * scale:
            continue
        if any(np.hypot(*(p - p2)) <= merge and np.hypot(*(q - q2)) <= merge
               for p2, q2 in keep):
            continue
        keep.append((p, q))
        if dd > 1e-9 * scale:
            n = (q - p) / dd
        else:
            nb = _feature_normal(B, q, scale)
            na = _feature_normal(A, p, scale)
            if nb is not None:
                n = -nb
            elif na is not None:
                n = na
            else:  # a tip on a segment's side, or corner to corner
                n = None
                for sh, pt, toward, sign in ((A, p, B, 1.0), (B, q, A, -1.0)):
                    if sh.kind == "segment":  # its side's normal, toward the other body
                        e = sh.pts[1] - sh.pts[0]
                        perp = np.array([-e[1], e[0]]) / np.hypot(*e)
                        if (_centroid(toward) - pt) @ perp < 0:
                            perp = -perp
                        n = sign * perp
                        break
                if n is None:
                    c = _centroid(B) - _centroid(A)
                    n = c / np.hypot(*c)
        out.append((p + A.radius * n, q - B.radius * n, n))
    return core - A.radius - B.radius, out
