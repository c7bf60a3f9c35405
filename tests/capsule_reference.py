"""Distances of capsule links to pegs and to each other, in NumPy apart from snakecg's
geometry (the tests' independent reference for "nothing penetrates"): the chain's ends from
its own planar kinematics, point-segment and segment-segment distances."""

from __future__ import annotations

import numpy as np

__all__ = ["point_segment", "segment_segment", "link_segments", "deepest_overlap"]


def point_segment(p, a, b) -> float:
    """Distance of point p to the segment ab."""
    d = b - a
    s = np.clip((p - a) @ d / (d @ d), 0.0, 1.0)
    return float(np.hypot(*(a + s * d - p)))


def segment_segment(a0, a1, b0, b1) -> float:
    """Distance of two segments: 0 where they cross, else the least of the four
    end-to-segment distances."""
    def orient(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])

    if (orient(a0, a1, b0) * orient(a0, a1, b1) < 0 and
            orient(b0, b1, a0) * orient(b0, b1, a1) < 0):
        return 0.0
    return min(point_segment(a0, b0, b1), point_segment(a1, b0, b1),
               point_segment(b0, a0, a1), point_segment(b1, a0, a1))


def link_segments(robot, q) -> list:
    """Rear and front ends of every link: q = (x, y, theta, q1..) with (x, y) the COM of
    link 1 and theta its heading."""
    L, c = np.asarray(robot.length), np.asarray(robot.com)
    th = q[2]
    rear = np.array([q[0], q[1]]) - c[0] * np.array([np.cos(th), np.sin(th)])
    out = []
    for i in range(len(L)):
        if i > 0:
            th += q[2 + i]
        front = rear + L[i] * np.array([np.cos(th), np.sin(th)])
        out.append((rear, front))
        rear = front
    return out


def deepest_overlap(scene, qs) -> float:
    """The largest overlap (m) of a capsule link with a peg or a non-neighbouring link over
    the configurations qs (0 if none)."""
    r, worst = scene.radius, 0.0
    for q in qs:
        segs = link_segments(scene.robot, q)
        for ob in scene.obstacles:
            cen = np.asarray(ob.center)
            for a, b in segs:
                worst = max(worst, ob.radius + r - point_segment(cen, a, b))
        for i in range(len(segs)):
            for j in range(i + 2, len(segs)):
                worst = max(worst, 2 * r - segment_segment(*segs[i], *segs[j]))
    return worst
