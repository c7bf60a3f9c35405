"""Spatial snakes: serial chains of revolute joints about any axes on a floating base.

:class:`SpatialRobot` describes one (from Python, a URDF or an MJCF file);
``snakecg.load(robot)`` gives its compiled :class:`SpatialModel` (mass matrix, Jacobians,
bias forces, poses, constraint rows; see docs/how-to/spatial.md).
"""

from .robot import SpatialRobot

__all__ = ["SpatialRobot", "SpatialModel"]


def __getattr__(name):
    if name == "SpatialModel":
        from .model import SpatialModel

        return SpatialModel
    raise AttributeError(f"module 'snakecg.spatial' has no attribute {name!r}")
