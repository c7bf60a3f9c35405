"""A general scene packed for the engine's forward (``snakecg/engine/scene_rows.c``), and the
layout of its outputs.

:func:`pack` writes the scene once per model as one flat float64 vector (a header, then one
record per link, object, obstacle and ground block, then the model's parameters ``K``);
:class:`Packed` keeps it with the ground blocks' table (kind, rows, set, label: constant for
the model) and reads the engine's output rows by name. The offsets and widths here are the
C's ``SP_*``, ``SO_*`` and ``*_W``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .description import GeneralScene
from .geometry import box_corners
from .solve import BOX, DISC, FREE, SPLIT

__all__ = ["Packed", "pack", "scene_size"]

SP_HEAD, LINK_W, OBJ_W, OBS_W, GB_W, CR_W = 16, 2, 12, 14, 8, 16
SP_SIZE = 4  # the head's scene_size (engine.h's SP_SIZE)
GB_WHEEL, GB_COULOMB, GB_SPLIT, GB_OBJECT = 0, 1, 2, 3
#: one sample's output row: the solve's info (INFO order), the contact count, the norms, sr,
#: an overlap's record (bodies, depth, tolerance), then qdd, a_obj, the objects' norms and
#: poses, the ground blocks (force 2, state), the contacts (CR_W each: bodies (4), points
#: (4), normal (2), gap, force, state, the pair's Coulomb coefficient, its friction force
#: along the tangent (-n_y, n_x) and state); SO_SOLUTIONS: the solutions of Coulomb's
#: conditions that enumeration found (0: not enumerated; negative: some piece's equations
#: were singular, so others may exist), scene_friction.c
SO_NC, SO_NORM_QDD, SO_NORM_A, SO_NORM_L, SO_SR, SO_OVERLAP, SO_SOLUTIONS, SO_QDD = \
    8, 9, 10, 11, 12, 13, 19, 20
BODY_KINDS = ("link", "object", "obstacle")
#: a contact's friction state (its record's last field, scene_friction.c)
FRICTION_STATES = ("stick", "open", "slip")
#: contacts read per sample in a first pass (a sample with more is solved again with room for
#: every pair's)
CONTACTS_FIRST = 16
#: rows the engine's solve takes (scene_solve.c)
MAX_ROWS = 500


def scene_size(scene: GeneralScene) -> float:
    """The scene's extent (m): the robot's length, the objects' and obstacles' sizes."""
    size = float(sum(scene.robot.length)) + 2 * scene.radius
    for o in scene.objects:
        size += 2 * o.radius if o.shape == "disc" else float(np.hypot(*o.size))
    for o in scene.obstacles:
        if o.shape == "peg":
            size += 2 * o.radius
        elif o.shape == "box":
            size += float(np.hypot(*o.size))
    return size


def _ground_blocks(scene: GeneralScene, masses) -> list[tuple]:
    """``(type, body, wheel_offset, par, kind, rows, label)`` per ground block, in row order:
    a wheel (bounded: BOX, |lam| <= mu m_i g; ideal: FREE) on its link's lateral row, Coulomb
    (DISC of radius mu m_i g) or anisotropic Coulomb (SPLIT: mu_forward, mu_backward,
    mu_lateral times m_i g, along and across the link) at a link's COM; an object's Coulomb
    friction with the ground (DISC, mu m g)."""
    g = scene.gravity
    out = []
    for i, gr in enumerate(scene.ground):
        load = masses[i] * g
        if gr.model == "ideal_wheels":
            out.append((GB_WHEEL, i, gr.wheel_offset, (0.0, 0.0, 0.0), FREE, 1, ("wheel", i)))
        elif gr.model == "wheels":
            out.append((GB_WHEEL, i, gr.wheel_offset, (gr.mu * load, 0.0, 0.0), BOX, 1,
                        ("wheel", i)))
        elif gr.model == "coulomb":
            out.append((GB_COULOMB, i, 0.0, (gr.mu * load, 0.0, 0.0), DISC, 2, ("ground", i)))
        elif gr.model == "anisotropic":
            out.append((GB_SPLIT, i, 0.0, (gr.mu_forward * load, gr.mu_backward * load,
                                           gr.mu_lateral * load), SPLIT, 2, ("ground", i)))
    for j, o in enumerate(scene.objects):
        if o.mu is not None:
            out.append((GB_OBJECT, j, 0.0, (o.mu * o.mass * g, 0.0, 0.0), DISC, 2,
                        ("object_ground", j)))
    return out


def _pairs(scene: GeneralScene) -> int:
    """Pairs of bodies the engine tests (not obstacle with obstacle, not neighbouring links)."""
    nl, no, nob = scene.robot.n_links, scene.n_objects, len(scene.obstacles)
    links = nl * (nl - 1) // 2 - (nl - 1)
    return links + nl * (no + nob) + no * (no - 1) // 2 + no * nob


@dataclass(frozen=True)
class Packed:
    """A scene packed for the engine: ``vector`` (the C's input), the ground blocks (``kinds``,
    ``sizes``, ``pars``, ``labels``), the sizes of an output row."""

    vector: np.ndarray
    kinds: tuple
    sizes: tuple
    pars: tuple
    labels: tuple
    n_s: int
    n_objects: int
    ground_rows: int
    contacts_max: int
    tolerance: float
    offset: dict
    """where the per-sample fields start in an output row"""
    friction: bool = False
    """some pair may touch with contact friction (a tangent row beside each such contact)"""

    @property
    def n_ground(self) -> int:
        return len(self.kinds)

    def rows_room(self, ccap: int) -> int:
        """Rows of a sample with room for ``ccap`` contacts (a normal and, with friction, a
        tangent row each) and the ground's."""
        return (2 if self.friction else 1) * ccap + self.ground_rows

    def width(self, ccap: int) -> int:
        """Doubles of one sample's output row with room for ``ccap`` contacts."""
        return SO_QDD + self.n_s + 7 * self.n_objects + 3 * self.n_ground + CR_W * ccap


def pack(scene: GeneralScene, parameters: np.ndarray, n_s: int) -> Packed:
    """The scene (and the model's parameter vector ``K``) as the engine's flat vector."""
    r = scene.robot
    nl, no, nob = r.n_links, scene.n_objects, len(scene.obstacles)
    masses = np.asarray(r.mass, dtype=float)
    blocks = _ground_blocks(scene, masses)
    size = scene_size(scene)
    links = np.array([[r.com[i], r.length[i]] for i in range(nl)], dtype=float)
    objects = np.zeros((no, OBJ_W))
    for j, o in enumerate(scene.objects):
        rec = objects[j]
        rec[0] = 1.0 if o.shape == "disc" else 0.0
        if o.shape == "box":
            rec[1:3] = o.size
        else:
            rec[3] = o.radius
        rec[4], rec[5], rec[10] = o.mass, o.plate_inertia, o.half_depth
        if o.pose is not None:
            rec[6], rec[7:10] = 0.0, o.pose
        else:
            t = o.touching
            k = t["link"] - 1
            rec[6], rec[7] = 1.0, k
            rec[8] = t.get("offset", r.length[k] / 2)
            rec[9] = 1.0 if t.get("side", "left") == "left" else -1.0
    obstacles = np.zeros((nob, OBS_W))
    for k, o in enumerate(scene.obstacles):
        rec = obstacles[k]
        if o.shape == "peg":
            rec[0], rec[1:3], rec[3] = 0.0, o.center, o.radius
        elif o.shape == "wall":
            rec[0], rec[1:3] = 1.0, o.point
            rec[4:6] = np.asarray(o.normal, float) / np.hypot(*o.normal)
        else:
            rec[0], rec[1:3] = 2.0, o.center
            rec[6:14] = box_corners(o.center, o.size, o.angle).ravel()
    ground = np.array([[t, b, woff, *par, kind, 0.0] for t, b, woff, par, kind, _, _ in blocks],
                      dtype=float).reshape(-1, GB_W)
    # every body's own Coulomb coefficient at contacts (-1: none, the scene's applies)
    own = np.array([-1.0] * nl + [-1.0 if o.mu_contact is None else o.mu_contact
                                  for o in (*scene.objects, *scene.obstacles)])
    parts = [links.ravel(), objects.ravel(), obstacles.ravel(), ground.ravel(), own,
             np.asarray(parameters, dtype=float).ravel()]
    starts = np.cumsum([SP_HEAD] + [p.size for p in parts[:-1]])
    head = np.zeros(SP_HEAD)
    mg = sum(b[5] for b in blocks)
    friction = scene.has_contact_friction
    head[:12] = (no, nob, scene.radius, scene.tolerance * size, size, len(blocks), mg,
                 *starts[:4], starts[5])
    head[12:15] = starts[4], scene.mu_contact, float(friction)  # SP_MU, SP_MUC, SP_FRICTION
    vector = np.ascontiguousarray(np.concatenate([head, *parts]))
    ng = len(blocks)
    offset = {"qdd": SO_QDD, "a_obj": SO_QDD + n_s, "each": SO_QDD + n_s + 3 * no,
              "pose": SO_QDD + n_s + 4 * no, "ground": SO_QDD + n_s + 7 * no,
              "contacts": SO_QDD + n_s + 7 * no + 3 * ng}
    return Packed(vector, tuple(b[4] for b in blocks), tuple(b[5] for b in blocks),
                  tuple(b[3] for b in blocks), tuple(b[6] for b in blocks), n_s, no, mg,
                  max(1, min(4 * _pairs(scene), (MAX_ROWS - mg) // (2 if friction else 1))),
                  scene.tolerance * size, offset, friction)
