"""Spatial snakes: serial chains of revolute joints about any axes on a floating base.

:class:`SpatialRobot` describes one (from Python, a URDF or an MJCF file);
``snakecg.load(robot)`` gives its compiled :class:`SpatialModel` (mass matrix, Jacobians,
bias forces, poses, constraint rows; see docs/how-to/spatial.md). :class:`SpatialScene` puts it
on the ground against an object; ``snakecg.load(scene)`` gives its forward analysis.
"""

from .robot import SpatialRobot
from .scene import SpatialScene

__all__ = ["SpatialRobot", "SpatialScene", "SpatialModel", "SpatialSceneModel"]


def __getattr__(name):
    if name == "SpatialModel":
        from .model import SpatialModel

        return SpatialModel
    if name == "SpatialSceneModel":
        from .analysis import SpatialSceneModel

        return SpatialSceneModel
    raise AttributeError(f"module 'snakecg.spatial' has no attribute {name!r}")
