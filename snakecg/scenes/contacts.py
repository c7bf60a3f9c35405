"""A configuration's contacts and constraint rows as Python objects (:class:`Contact`,
:class:`Rows`: what a :class:`~snakecg.scenes.metrics.SceneResult` reports for checks; the
engine finds and builds them, ``snakecg/engine/scene_rows.c``), and the placement of the
links and objects at a configuration (what the drawing shows).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .description import GeneralScene

__all__ = ["Contact", "Rows", "link_ends", "place_objects"]


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
