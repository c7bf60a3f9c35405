"""Geometric feasibility of a snake's shape: segment distances, self-intersection and
penetration of the pushed object.

The paper's joint grid (case study 2) keeps every shape, including ones whose links cross
each other or pass through the object; this module tells which ones are physically possible,
so that figures can mark them and Table 2 or a sweep can leave them out.

The geometry is the model's: every link is the segment from its rear end to its front end
(links are lines, their width is the ``clearance``), the object is the Scene's square plate
of side :data:`OBJECT_SIDE` (0.1 m) centred at the object's COM and turned by its angle
``psi``, touched at the middle of a face. All functions are vectorised NumPy: leading axes
are batch axes.

* :func:`point_segment_distance`, :func:`segment_distance`: Euclidean distances in the plane.
* :func:`link_segments`: rear and front ends of every link from the link poses.
* :func:`self_distance`, :func:`self_intersecting`: closest approach of non-adjacent links.
* :func:`object_penetration`: how deep a link segment enters the plate.
* :func:`feasibility`: both checks for configurations of a :class:`~snakecg.SceneModel`.
* :data:`INFEASIBLE_MARK` and :func:`infeasible_footnote`: how every table marks a value
  attained by a shape that is not physically possible (Table 2, ``sweep --summary``).
* :class:`ContactCheck`: what a simulation checks at every step, sample and event (every
  link against the object, the contacting one included, and non-neighbouring links against
  each other, as overlap depths), with its tolerance :func:`contact_tolerance`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "OBJECT_SIDE",
    "SELF_CLEARANCE",
    "PENETRATION_TOLERANCE",
    "CONTACT_TOLERANCE",
    "ContactCheck",
    "Feasibility",
    "chain_segments",
    "contact_tolerance",
    "feasibility",
    "infeasible_footnote",
    "INFEASIBLE_MARK",
    "link_radius",
    "link_segments",
    "object_depth",
    "segment_overlap",
    "object_penetration",
    "point_segment_distance",
    "segment_distance",
    "self_distance",
    "self_intersecting",
]

#: Side of the Scene's square plate [m] (the object of the paper's case studies).
OBJECT_SIDE = 0.1
#: Default clearance [m]: non-adjacent links closer than this count as intersecting (the
#: paper's links are lines; 1 cm stands for the width of a real link's body).
SELF_CLEARANCE = 0.01
#: A link entering the plate by less than this [m] only touches it (the contacting link lies
#: on the plate's face; rounding puts it a few ulp inside).
PENETRATION_TOLERANCE = 1e-9
#: The mark of a table entry attained by a shape that is not physically possible (Fig. 6
#: frames such shapes in red).
INFEASIBLE_MARK = "*"


def infeasible_footnote(clearance: float = SELF_CLEARANCE) -> str:
    """The footnote that explains :data:`INFEASIBLE_MARK` under a table."""
    return (f"{INFEASIBLE_MARK} a shape that is not physically possible (links closer than "
            f"{clearance:g} m or inside the object)")

#: A simulation stops when two bodies overlap by more than this fraction of the longest link
#: (:func:`contact_tolerance`: 1.5e-7 m for the paper's 0.15 m links).
CONTACT_TOLERANCE = 1e-6


def _cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def point_segment_distance(p, a, b) -> np.ndarray:
    """Distance from points ``p`` to segments ``a``-``b`` (arrays ``(..., 2)``, broadcast)."""
    p, a, b = (np.asarray(x, float) for x in (p, a, b))
    # component by component (the same operations, in the same order, as the dot products
    # and the norm of the vectors; several times faster on large batches)
    ax, ay = a[..., 0], a[..., 1]
    dx, dy = b[..., 0] - ax, b[..., 1] - ay
    dd = dx * dx + dy * dy
    t = ((p[..., 0] - ax) * dx + (p[..., 1] - ay) * dy) / np.where(dd > 0, dd, 1.0)
    t = np.clip(np.where(dd > 0, t, 0.0), 0.0, 1.0)
    ex, ey = p[..., 0] - (ax + t * dx), p[..., 1] - (ay + t * dy)
    return np.sqrt(ex * ex + ey * ey)


def segment_distance(a0, a1, b0, b1) -> np.ndarray:
    """Distance between segments ``a0``-``a1`` and ``b0``-``b1`` (arrays ``(..., 2)``).

    Zero when they cross; otherwise the closest pair involves an end point of one of them,
    so the distance is the least of the four end-point-to-segment distances.
    """
    a0, a1, b0, b1 = (np.asarray(x, float) for x in (a0, a1, b0, b1))
    da, db = a1 - a0, b1 - b0
    s1, s2 = _cross(db, a0 - b0), _cross(db, a1 - b0)
    s3, s4 = _cross(da, b0 - a0), _cross(da, b1 - a0)
    crossing = (s1 * s2 < 0) & (s3 * s4 < 0)
    d = np.minimum(
        np.minimum(point_segment_distance(a0, b0, b1), point_segment_distance(a1, b0, b1)),
        np.minimum(point_segment_distance(b0, a0, a1), point_segment_distance(b1, a0, a1)),
    )
    return np.where(crossing, 0.0, d)


def link_segments(robot, poses) -> tuple[np.ndarray, np.ndarray]:
    """Rear and front ends ``(..., n_l, 2)`` of every link from the poses ``(..., n_l, 3)``
    (``x, y, phi`` of each link's COM, as :meth:`SceneModel.link_poses` returns them)."""
    poses = np.asarray(poses, float)
    e = np.stack([np.cos(poses[..., 2]), np.sin(poses[..., 2])], axis=-1)
    com = np.asarray(robot.com, float)[:, None]
    length = np.asarray(robot.length, float)[:, None]
    rear = poses[..., :2] - com * e
    return rear, rear + length * e


def self_distance(rear, front) -> np.ndarray:
    """Least distance between non-adjacent links (``|i - j| >= 2``): shape ``(...)``.

    ``inf`` for robots with fewer than three links (adjacent links share a joint and are not
    compared).
    """
    rear, front = np.asarray(rear, float), np.asarray(front, float)
    n_l = rear.shape[-2]
    d = np.full(rear.shape[:-2], np.inf)
    for i in range(n_l):
        for j in range(i + 2, n_l):
            d = np.minimum(d, segment_distance(rear[..., i, :], front[..., i, :],
                                               rear[..., j, :], front[..., j, :]))
    return d


def self_intersecting(rear, front, clearance: float = SELF_CLEARANCE) -> np.ndarray:
    """Shapes whose non-adjacent links come closer than ``clearance`` [m], or meet."""
    return _too_close(self_distance(rear, front), clearance)


def _too_close(distance, clearance):
    """Closer than ``clearance``, or meeting (crossing links are 0 apart: a clearance of 0
    still refuses them)."""
    return (distance < clearance) | (distance <= 0.0)


def object_penetration(a, b, q_obj, side: float = OBJECT_SIDE) -> np.ndarray:
    """How deep the segment ``a``-``b`` enters the square plate: shape ``(...)``.

    ``q_obj`` ``(..., 3)`` is the plate's pose ``(x, y, psi)``. The depth is the largest, over
    the segment's points, of the distance from the point to the plate's boundary when the
    point is inside (0 when the segment stays outside or on the boundary).
    """
    a, b, q_obj = (np.asarray(x, float) for x in (a, b, q_obj))
    c, psi = q_obj[..., :2], q_obj[..., 2]
    cs, sn = np.cos(psi), np.sin(psi)

    def local(p):  # the point in the plate's frame, (x, y) component by component
        dx, dy = p[..., 0] - c[..., 0], p[..., 1] - c[..., 1]
        return cs * dx + sn * dy, -sn * dx + cs * dy

    (ax, ay), (bx, by) = local(a), local(b)
    h = side / 2
    # depth(p) = h - max(|x|, |y|) is concave along the segment; its maximum over t in [0, 1]
    # is at an end or where two of the four linear pieces h -+ x, h -+ y meet.
    ts = [np.zeros(ax.shape), np.ones(ax.shape)]
    dx, dy = bx - ax, by - ay
    with np.errstate(divide="ignore", invalid="ignore"):
        ts.append(-ax / dx)  # x = 0 or y = 0 crossings (where |x| or |y| turns)
        ts.append(-ay / dy)
        for s in (1.0, -1.0):  # |x| = |y| crossings: x = s y
            ts.append(-(ax - s * ay) / (dx - s * dy))
    best = np.zeros(ax.shape)
    for t in ts:
        t = np.clip(np.nan_to_num(t, nan=0.0, posinf=0.0, neginf=0.0), 0.0, 1.0)
        best = np.maximum(best, h - np.maximum(np.abs(ax + t * dx), np.abs(ay + t * dy)))
    return best


@dataclass(frozen=True)
class Feasibility:
    """Outcome of :func:`feasibility` for a batch of configurations (arrays of shape ``(N,)``).

    * ``self_distance``: least distance between non-adjacent links [m];
    * ``self_intersecting``: ``self_distance < clearance``;
    * ``penetration``: deepest entry of a link (other than the contacting one) into the plate;
    * ``penetrates_object``: ``penetration > PENETRATION_TOLERANCE``;
    * ``feasible``: neither.
    """

    self_distance: np.ndarray
    self_intersecting: np.ndarray
    penetration: np.ndarray
    penetrates_object: np.ndarray
    clearance: float

    @property
    def feasible(self) -> np.ndarray:
        return ~(self.self_intersecting | self.penetrates_object)


def feasibility(model, q, *, clearance: float = SELF_CLEARANCE,
                side: float = OBJECT_SIDE) -> Feasibility:
    """Self-intersection and object penetration of configurations ``q`` ``(n_s,)`` or
    ``(N, n_s)`` of a :class:`~snakecg.SceneModel` (its robot, contact link and side).

    The contacting link touches the plate along a face and is not tested against it; every
    other link is.
    """
    q = np.asarray(q, float)
    batched = q.ndim == 2
    Q = q if batched else q[None]
    rear, front = link_segments(model.robot, model.link_poses(Q))
    q_obj, _, _ = model.place_object(Q)
    k = model.scene.contact_link - 1
    pen = np.zeros(len(Q))
    for i in range(rear.shape[1]):
        if i != k:
            pen = np.maximum(pen, object_penetration(rear[:, i], front[:, i], q_obj, side))
    dist = self_distance(rear, front)
    out = Feasibility(self_distance=dist, self_intersecting=_too_close(dist, clearance),
                      penetration=pen,
                      penetrates_object=pen > PENETRATION_TOLERANCE, clearance=clearance)
    if batched:
        return out
    return Feasibility(**{f: (np.asarray(getattr(out, f))[0] if f != "clearance" else clearance)
                          for f in out.__dataclass_fields__})


# --- what a simulation checks --------------------------------------------------------------

def contact_tolerance(robot) -> float:
    """The overlap a simulation tolerates [m]: :data:`CONTACT_TOLERANCE` times the longest
    link of ``robot`` (contacts held by the model sit within rounding of zero)."""
    return CONTACT_TOLERANCE * float(max(robot.length))


def link_radius(robot) -> float:
    """The links' radius [m]: the robot's ``radius`` when it has one (capsules), else 0
    (segments)."""
    return float(getattr(robot, "radius", 0.0) or 0.0)


def chain_segments(robot, q) -> tuple[np.ndarray, np.ndarray]:
    """Rear and front ends ``(..., n_l, 2)`` of every link at the coordinates ``q``
    ``(..., n_s)``: ``(x, y, theta)`` the COM and angle of link 1, then each joint's angle
    relative to the link before (the chain of :meth:`SceneModel.link_poses`, in NumPy).
    Link ``i``'s front end is link ``i + 1``'s rear end."""
    q = np.asarray(q, float)
    phi = np.concatenate([q[..., 2:3], q[..., 2:3] + np.cumsum(q[..., 3:], axis=-1)], axis=-1)
    e = np.stack([np.cos(phi), np.sin(phi)], axis=-1)
    length = np.asarray(robot.length, float)[:, None]
    rear1 = q[..., :2] - float(robot.com[0]) * e[..., 0, :]
    front = rear1[..., None, :] + np.cumsum(length * e, axis=-2)
    rear = np.concatenate([rear1[..., None, :], front[..., :-1, :]], axis=-2)
    return rear, front


def segment_overlap(a0, a1, b0, b1, radius: float = 0.0) -> np.ndarray:
    """How deep two links overlap [m]: ``2 radius - d``, 0 when apart (shape ``(...)``).

    ``d`` is the distance between the segments ``a0``-``a1`` and ``b0``-``b1`` (arrays
    ``(..., 2)``) or, when they cross, minus the least distance from an end of one to the
    other (how far the nearest end must move back to uncross them): continuous in the ends,
    0 at the instant they touch.
    """
    a0, a1, b0, b1 = (np.asarray(x, float) for x in (a0, a1, b0, b1))
    da, db = a1 - a0, b1 - b0
    crossing = ((_cross(db, a0 - b0) * _cross(db, a1 - b0) < 0)
                & (_cross(da, b0 - a0) * _cross(da, b1 - a0) < 0))
    ends = np.minimum(
        np.minimum(point_segment_distance(a0, b0, b1), point_segment_distance(a1, b0, b1)),
        np.minimum(point_segment_distance(b0, a0, a1), point_segment_distance(b1, a0, a1)))
    return np.maximum(0.0, 2 * radius - np.where(crossing, -ends, ends))


def _plate_edges(q_obj, half):
    """The plate's corners ``(..., 4, 2)``, anticlockwise."""
    q_obj = np.asarray(q_obj, float)
    cs, sn = np.cos(q_obj[..., 2]), np.sin(q_obj[..., 2])
    local = np.array([[-half, -half], [half, -half], [half, half], [-half, half]])
    x = q_obj[..., None, 0] + cs[..., None] * local[:, 0] - sn[..., None] * local[:, 1]
    y = q_obj[..., None, 1] + sn[..., None] * local[:, 0] + cs[..., None] * local[:, 1]
    return np.stack([x, y], axis=-1)


def object_depth(a, b, q_obj, half: float, radius: float = 0.0) -> np.ndarray:
    """How deep a link enters the square plate of half side ``half`` at the pose ``q_obj``
    ``(..., 3)`` [m], 0 when apart (shape ``(...)``): ``radius`` plus the depth of the
    segment ``a``-``b``'s deepest point inside the plate (:func:`object_penetration`), or,
    when the segment stays outside, ``radius`` minus its distance to the plate."""
    inside = object_penetration(a, b, q_obj, 2 * half)
    if radius <= 0:
        return inside
    corners = _plate_edges(q_obj, half)
    dist = np.min([segment_distance(a, b, corners[..., k, :], corners[..., (k + 1) % 4, :])
                   for k in range(4)], axis=0)
    return np.maximum(0.0, np.where(inside > 0, radius + inside, radius - dist))


class ContactCheck:
    """The geometry a simulation checks: every link of ``robot`` against the object (the
    square plate of half side ``half`` centred at its COM, turned with it) and every pair of
    non-neighbouring links against each other (neighbours share a joint and always touch),
    each as an overlap depth [m]. A link is a segment, or a capsule of the robot's
    ``radius``. ``tolerance`` [m] (default :func:`contact_tolerance`): the largest overlap
    allowed.

    ``pairs``: the pairs checked, ``(i, None)`` link ``i`` (from 0) with the object, then
    ``(i, j)`` links ``i < j - 1``.
    """

    def __init__(self, robot, half: float, *, tolerance: float | None = None,
                 radius: float | None = None):
        self.robot = robot
        self.half = float(half)
        self.radius = link_radius(robot) if radius is None else float(radius)
        self.tolerance = contact_tolerance(robot) if tolerance is None else float(tolerance)
        n_l = len(robot.length)
        self.pairs = [(i, None) for i in range(n_l)] + [
            (i, j) for i in range(n_l) for j in range(i + 2, n_l)]

    @classmethod
    def of_scene(cls, scene, **kw) -> ContactCheck:
        """The check of a :class:`~snakecg.Scene`: its object is the square plate of side
        ``2 object_distance`` (0.1 m by default), touched at the middle of a face."""
        return cls(scene.robot, scene.object_distance, **kw)

    def depths(self, q, q_obj) -> np.ndarray:
        """The overlap of every pair at ``q`` ``(..., n_s)``, ``q_obj`` ``(..., 3)``:
        ``(..., len(pairs))``."""
        rear, front = chain_segments(self.robot, q)
        q_obj = np.asarray(q_obj, float)
        out = []
        for i, j in self.pairs:
            if j is None:
                out.append(object_depth(rear[..., i, :], front[..., i, :], q_obj, self.half,
                                        self.radius))
            else:
                out.append(segment_overlap(rear[..., i, :], front[..., i, :], rear[..., j, :],
                                           front[..., j, :], self.radius))
        return np.stack(out, axis=-1)

    def deepest(self, q, q_obj) -> tuple[np.ndarray, np.ndarray]:
        """The largest overlap at each state and the index of its pair (the first of equals)."""
        d = self.depths(q, q_obj)
        k = np.argmax(d, axis=-1)
        return np.take_along_axis(d, k[..., None], axis=-1)[..., 0], k

    def kind(self, pair: int) -> str:
        """``"penetration"`` (a link and the object) or ``"self_contact"`` (two links)."""
        return "penetration" if self.pairs[pair][1] is None else "self_contact"

    def bodies(self, pair: int) -> tuple:
        """The pair's bodies: link numbers (from 1, tail first), or ``"object"``."""
        i, j = self.pairs[pair]
        return (i + 1, "object" if j is None else j + 1)
