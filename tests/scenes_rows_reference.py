"""The reference of the general scenes' contacts and rows: the closest points
(tests/scenes_geometry_reference.py, plain NumPy) and the rows of eqs. 7-11 built per sample in
Python, written apart from the engine's C (``snakecg/engine/scene_geometry.c``,
``scene_rows.c``) that the tests hold against it. Nothing here calls the engine.
"""

from __future__ import annotations

import numpy as np

from snakecg.errors import InputError
from snakecg.scenes.contacts import Contact, Rows, link_ends
from snakecg.scenes.description import GeneralScene
from snakecg.scenes.geometry import box_corners

from scenes_geometry_reference import Shape, closest
from snakecg.scenes.packing import scene_size  # the scene's extent: a definition, shared
from snakecg.scenes.solve import BOX, DISC, FREE, SPLIT, UNILATERAL

__all__ = ["shapes", "rows_of", "pair_gaps", "place_objects"]


def place_objects(scene: GeneralScene, poses) -> np.ndarray:
    """Every object's pose ``(x, y, theta)`` at the link COM poses ``(n_l, 3)``, from the
    geometry: a ``touching`` object's face (a disc's nearest point) on the link's edge point
    at ``offset`` from its rear end, on the named side (left: the link's left normal), the
    object turned with the link; so its centre lies ``half_depth`` beyond that point along
    the side's normal."""
    out = np.empty((scene.n_objects, 3))
    for j, o in enumerate(scene.objects):
        if o.pose is not None:
            out[j] = o.pose
            continue
        k = o.touching["link"] - 1
        x, y, phi = poses[k]
        along = np.array([np.cos(phi), np.sin(phi)])
        side = np.array([-along[1], along[0]])  # left of the link, looking forward
        if o.touching.get("side", "left") == "right":
            side = -side
        rear = np.array([x, y]) - scene.robot.com[k] * along
        edge = rear + o.touching.get("offset", scene.robot.length[k] / 2) * along \
            + scene.radius * side
        depth = o.radius if o.shape == "disc" else o.size[1] / 2
        out[j] = (*(edge + depth * side), phi)
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


def _pairs(bodies, margin):
    """The broad phase: ``(ia, ib)`` of the bodies that can touch (not two obstacles, not
    neighbouring links) whose bounding circles (a wall: none) are within ``margin``."""
    centre = np.array([sh.pts.mean(axis=0) for _, sh in bodies])
    reach = np.array([np.inf if sh.kind == "halfplane" else
                      np.sqrt(((sh.pts - sh.pts.mean(axis=0)) ** 2).sum(axis=1)).max()
                      + sh.radius for _, sh in bodies])
    for ia in range(len(bodies)):
        ba, sa = bodies[ia]
        if ba[0] == "obstacle" or sa.kind == "halfplane":
            continue
        for ib in range(ia + 1, len(bodies)):
            bb, sb = bodies[ib]
            if ba[0] == "link" and bb[0] == "link" and abs(ba[1] - bb[1]) < 2:
                continue
            if np.hypot(*(centre[ia] - centre[ib])) > reach[ia] + reach[ib] + margin:
                continue
            yield ia, ib


def pair_gaps(scene: GeneralScene, poses, obj_poses, margin: float) -> list:
    """``[(body_a, body_b, d)]``: the signed distance of every pair that can touch whose
    bounding circles are within ``margin`` of each other."""
    bodies = shapes(scene, poses, obj_poses)
    size = scene_size(scene)
    return [(bodies[ia][0], bodies[ib][0], float(closest(bodies[ia][1], bodies[ib][1],
                                                         size)[0]))
            for ia, ib in _pairs(bodies, margin)]


def rows_of(scene: GeneralScene, masses, poses, J, *, index=None, obj_poses=None,
            tol=None) -> tuple[Rows, np.ndarray]:
    """The rows of one configuration (link COM poses ``poses`` (n_l, 3), link Jacobians
    ``J`` (n_l, 3, n_s)) and the objects' poses. Raises :class:`InputError` on overlap
    (``index``: the sample's, named in the message). ``obj_poses`` (n_objects, 3): the
    objects where they are (a simulation's state; default: placed by the scene); ``tol`` (m):
    the contact tolerance (default the scene's)."""
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

    for ia, ib in _pairs(bodies, 2 * tol):
        (ba, sa), (bb, sb) = bodies[ia], bodies[ib]
        d, pairs = closest(sa, sb, size, tol)
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
