"""A configuration's contacts and constraint rows as Python objects (:class:`Contact`,
:class:`Rows`: what a :class:`~snakecg.scenes.metrics.SceneResult` reports for checks; the
engine finds and builds them, ``snakecg/engine/scene_rows.c``), and the placement of the
links and objects at a configuration (what the drawing shows). The time stepping's rows at a
simulation state (objects where they are, its own tolerance) are still built here
(:func:`rows_of`) until the engine's row builder takes object poses.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .description import GeneralScene
from .geometry import Shape, box_corners, closest
from .packing import scene_size
from .solve import BOX, DISC, FREE, SPLIT, UNILATERAL

__all__ = ["Contact", "Rows", "link_ends", "place_objects", "shapes", "candidate_pairs",
           "rows_of"]


@dataclass
class Contact:
    """A contact between bodies ``a`` and ``b`` (``("link", i)``, ``("object", j)``,
    ``("obstacle", k)``, 0-based), at surface points ``point_a``/``point_b`` with the unit
    normal from a to b, and its row index."""

    a: tuple
    b: tuple
    point_a: np.ndarray
    point_b: np.ndarray
    normal: np.ndarray
    gap: float
    row: int


@dataclass
class Rows:
    """The rows ``A`` (m x n) and their blocks ``kind``, ``start``, ``par`` (nb x 3), the
    contacts, and what each block is (``labels``)."""

    A: np.ndarray
    kind: list
    start: list
    par: list
    contacts: list
    labels: list


def _frame(pose):
    return np.array([np.cos(pose[2]), np.sin(pose[2])]), np.array([-np.sin(pose[2]),
                                                                    np.cos(pose[2])])


def link_ends(scene: GeneralScene, poses) -> np.ndarray:
    """Rear and front ends of every link (n_l, 2, 2) from the COM poses."""
    r = scene.robot
    out = np.empty((r.n_links, 2, 2))
    for i, (x, y, phi) in enumerate(poses):
        t = np.array([np.cos(phi), np.sin(phi)])
        rear = np.array([x, y]) - r.com[i] * t
        out[i] = (rear, rear + r.length[i] * t)
    return out


def place_objects(scene: GeneralScene, poses) -> np.ndarray:
    """Every object's pose (x, y, theta) at the link poses (a ``touching`` object on the
    named side of its link, the contact at ``offset`` from the rear end; a box with a face
    along the link)."""
    out = np.empty((scene.n_objects, 3))
    ends = link_ends(scene, poses)
    for j, o in enumerate(scene.objects):
        if o.pose is not None:
            out[j] = o.pose
            continue
        k = o.touching["link"] - 1
        t, nrm = _frame(poses[k])
        off = o.touching.get("offset", scene.robot.length[k] / 2)
        side = 1.0 if o.touching.get("side", "left") == "left" else -1.0
        c = ends[k, 0] + off * t + side * (scene.radius + o.half_depth) * nrm
        out[j] = (c[0], c[1], poses[k][2])
    return out


def shapes(scene: GeneralScene, poses, obj_poses) -> list:
    """``[(body, Shape)]`` for links, objects and obstacles."""
    out = []
    for i, (a, b) in enumerate(link_ends(scene, poses)):
        out.append((("link", i), Shape("segment", [a, b], scene.radius)))
    for j, o in enumerate(scene.objects):
        p = obj_poses[j]
        if o.shape == "disc":
            out.append((("object", j), Shape("point", [p[:2]], o.radius)))
        else:
            out.append((("object", j), Shape("polygon", box_corners(p[:2], o.size, p[2]))))
    for k, o in enumerate(scene.obstacles):
        if o.shape == "peg":
            sh = Shape("point", [o.center], o.radius)
        elif o.shape == "box":
            sh = Shape("polygon", box_corners(o.center, o.size, o.angle))
        else:
            sh = Shape("halfplane", [o.point], 0.0, o.normal)
        out.append((("obstacle", k), sh))
    return out


def candidate_pairs(bodies, margin: float) -> list:
    """The broad phase: index pairs ``(ia, ib)``, ``ia < ib``, of the ``[(body, Shape)]`` that
    can touch (not two obstacles, not neighbouring links) and whose bounding circles (a wall:
    none, it meets every shape) are within ``margin`` of each other."""
    nb = len(bodies)
    if nb < 2:
        return []
    centre = np.empty((nb, 2))
    reach = np.empty(nb)
    kind = np.empty(nb, dtype=np.int64)  # 0 link, 1 object, 2 obstacle
    index = np.empty(nb, dtype=np.int64)
    codes = {"link": 0, "object": 1, "obstacle": 2}
    for i, (b, sh) in enumerate(bodies):
        p = sh.pts
        if sh.kind == "segment":  # the middle, half the length
            (x0, y0), (x1, y1) = p.tolist()
            centre[i] = (0.5 * (x0 + x1), 0.5 * (y0 + y1))
            reach[i] = 0.5 * math.hypot(x1 - x0, y1 - y0) + sh.radius
        elif sh.kind == "point":
            centre[i] = p[0]
            reach[i] = sh.radius
        elif sh.kind == "halfplane":
            centre[i] = p[0]
            reach[i] = np.inf
        else:
            c = p.mean(axis=0)
            centre[i] = c
            reach[i] = np.sqrt(((p - c) ** 2).sum(axis=1)).max() + sh.radius
        kind[i] = codes[b[0]]
        index[i] = b[1]
    ia, ib = np.triu_indices(nb, 1)
    gap = np.hypot(*(centre[ia] - centre[ib]).T)
    with np.errstate(invalid="ignore"):  # inf - inf of two walls: never compared (obstacles)
        near = gap <= reach[ia] + reach[ib] + margin
    ok = near & (kind[ia] != 2) & np.isfinite(reach[ia]) & ~(
        (kind[ia] == 0) & (kind[ib] == 0) & (np.abs(index[ia] - index[ib]) < 2))
    return list(zip(ia[ok].tolist(), ib[ok].tolist()))


def _point_jacobian(body, p, J, poses, obj_poses, n_s, n):
    """(2, n): the velocity of point p fixed on ``body`` in the generalized velocities."""
    out = np.zeros((2, n))
    kind, i = body
    if kind == "link":
        r = p - poses[i][:2]
        out[:, :n_s] = J[i][:2] + np.outer([-r[1], r[0]], J[i][2])
    elif kind == "object":
        r = p - obj_poses[i][:2]
        c = n_s + 3 * i
        out[:, c:c + 3] = [[1.0, 0.0, -r[1]], [0.0, 1.0, r[0]]]
    return out


def rows_of(scene: GeneralScene, masses, poses, J, *, index=None, obj_poses=None,
            tol=None) -> tuple[Rows, np.ndarray]:
    """The rows of one configuration (link COM poses ``poses`` (n_l, 3), link Jacobians
    ``J`` (n_l, 3, n_s)) and the objects' poses. Raises :class:`InputError` on overlap
    (``index``: the sample's, named in the message). ``obj_poses`` (n_objects, 3): the
    objects where they are (a simulation's state; default: placed by the scene); ``tol``
    (m): the contact tolerance (default the scene's, ``tolerance`` times its size)."""
    n_s = J.shape[2]
    n = n_s + 3 * scene.n_objects
    size = scene_size(scene)
    tol = scene.tolerance * size if tol is None else float(tol)
    obj_poses = (place_objects(scene, poses) if obj_poses is None
                 else np.asarray(obj_poses, dtype=float).reshape(scene.n_objects, 3))
    bodies = shapes(scene, poses, obj_poses)
    rows, kind, start, par, contacts, labels = [], [], [], [], [], []

    def block(k, rs, p, label):
        kind.append(k)
        start.append(len(rows))
        par.append(p)
        rows.extend(rs)
        labels.append(label)

    for ia, ib in candidate_pairs(bodies, 2 * tol):
        (ba, sa), (bb, sb) = bodies[ia], bodies[ib]
        d, pairs = closest(sa, sb, size)
        if d < -tol:
            where = "" if index is None else f" in sample {index}"
            raise InputError(
                f"{scene.body_name(*ba)} and {scene.body_name(*bb)} overlap by "
                f"{-d:.3g} m{where} (contacts hold within {tol:.3g} m); move them apart")
        if d > tol:
            continue
        for ca, cb, nrm in pairs:
            Ja = _point_jacobian(ba, ca, J, poses, obj_poses, n_s, n)
            Jb = _point_jacobian(bb, cb, J, poses, obj_poses, n_s, n)
            contacts.append(Contact(ba, bb, ca, cb, nrm, d, len(rows)))
            block(UNILATERAL, [nrm @ (Jb - Ja)], (0.0, 0.0, 0.0),
                  ("contact", len(contacts) - 1))
    g = scene.gravity
    for i, gr in enumerate(scene.ground):
        x, y, phi = poses[i]
        t = np.array([np.cos(phi), np.sin(phi)])
        nl = np.array([-np.sin(phi), np.cos(phi)])
        load = masses[i] * g
        if gr.model in ("wheels", "ideal_wheels"):
            row = nl @ J[i][:2] + gr.wheel_offset * J[i][2]
            full = np.zeros(n)
            full[:n_s] = row
            if gr.model == "ideal_wheels":
                block(FREE, [full], (0.0, 0.0, 0.0), ("wheel", i))
            else:
                block(BOX, [full], (gr.mu * load, 0.0, 0.0), ("wheel", i))
        elif gr.model == "coulomb":
            full = np.zeros((2, n))
            full[:, :n_s] = J[i][:2]
            block(DISC, list(full), (gr.mu * load, 0.0, 0.0), ("ground", i))
        elif gr.model == "anisotropic":
            full = np.zeros((2, n))
            full[0, :n_s] = t @ J[i][:2]
            full[1, :n_s] = nl @ J[i][:2]
            block(SPLIT, list(full), (gr.mu_forward * load, gr.mu_backward * load,
                                      gr.mu_lateral * load), ("ground", i))
    for j, o in enumerate(scene.objects):
        if o.mu is not None:
            full = np.zeros((2, n))
            full[:, n_s + 3 * j:n_s + 3 * j + 2] = np.eye(2)
            block(DISC, list(full), (o.mu * o.mass * g, 0.0, 0.0), ("object_ground", j))
    A = np.array(rows).reshape(len(rows), n)
    return Rows(A, kind, start, par, contacts, labels), obj_poses
