"""Whether a spatial snake's configuration lies on the ground: the configurations the ground's
rows describe (each link held in height and slope on the plane). The forward analysis flags
the others (NaN, ``singular``, :data:`NOT_ON_GROUND`); the queries read the flag."""

from __future__ import annotations

import numpy as np

__all__ = ["FLAT_TOL", "NOT_ON_GROUND", "STATUS_NOT_ON_GROUND", "lying_flat"]

#: A link whose axis's slope (rad) or COM height (m, from link 1's) exceeds this is not flat.
FLAT_TOL = 1e-9
#: Why a sample at a configuration that does not lie on the ground has no answer.
NOT_ON_GROUND = ("the snake is not lying on the ground at this configuration: every link's "
                 "axis must be horizontal and its COM at the height of the others")
#: The status of such a sample (set here, before the solve's answer is read; the compiled
#: solve's own statuses are small integers).
STATUS_NOT_ON_GROUND = 100


def lying_flat(model, qa) -> np.ndarray:
    """``(N,)``: whether each configuration of ``qa`` ``(N, n_q)`` lies on the ground, every
    link's axis horizontal and its COM at the height of link 1's (within :data:`FLAT_TOL`):
    the configurations the ground's rows describe (``model``: a
    :class:`~snakecg.spatial.analysis.SpatialSceneModel`)."""
    T = model.robot_model.link_poses(qa)  # (N, n_l, 4, 4)
    com = np.asarray(model.scene.robot.com)
    heights = np.einsum("bkj,kj->bk", T[:, :, 2, :3], com) + T[:, :, 2, 3]
    slope = np.abs(T[:, :, 2, 0]).max(axis=1)
    level = np.abs(heights - heights[:, :1]).max(axis=1)
    return (slope <= FLAT_TOL) & (level <= FLAT_TOL)
