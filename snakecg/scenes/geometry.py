"""The corners of a box (an object or an obstacle of a general scene): what the packing hands
the engine (``snakecg/engine/scene_geometry.c`` finds the closest points) and what the
drawing shows."""

from __future__ import annotations

import numpy as np

__all__ = ["box_corners"]


def box_corners(center, size, angle) -> np.ndarray:
    """The corners (4, 2) of a box of ``size`` (m) centred at ``center`` turned by ``angle``
    (rad), counter-clockwise."""
    c, s = np.cos(angle), np.sin(angle)
    R = np.array([[c, -s], [s, c]])
    a, b = size[0] / 2, size[1] / 2
    return np.asarray(center, float) + np.array([[-a, -b], [a, -b], [a, b], [-a, b]]) @ R.T
