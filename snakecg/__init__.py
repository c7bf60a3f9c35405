"""snakecg: contact models of planar snake robots that push objects (Reyes & Ma 2017).

Pipeline: ``snakecg_derive`` (SymPy, folder ``derive/``) -> ``snakecg_generated`` (CasADi
builders and C, folder ``generated/``) -> ``snakecg`` (this runtime: numbers in, numbers out).

>>> import snakecg
>>> robot = snakecg.Robot(joints=2)
>>> model = snakecg.load(robot)
>>> model.mass_matrix([0, 0, 0, 0.3, -0.2]).shape
(5, 5)
"""

from .engine import Data
from .errors import ArtifactError, BuildError, InputError, SingularConstraintsError, SnakecgError
from .model import ForwardResult, RobotModel, SceneModel, load
from .robot import SCENARIOS, Robot, Scene
from .spatial import SpatialRobot, SpatialScene
from ._version import __version__

__all__ = [
    "Robot",
    "Scene",
    "SpatialRobot",
    "SpatialScene",
    "SCENARIOS",
    "load",
    "RobotModel",
    "SceneModel",
    "ForwardResult",
    "Data",
    "SnakecgError",
    "InputError",
    "BuildError",
    "ArtifactError",
    "SingularConstraintsError",
    "plot",
    "__version__",
    "sweep",
]


def __getattr__(name):
    # imported on first use: snakecg.plot needs matplotlib, snakecg.sweep the sweep extra
    # (Dask, Zarr)
    if name == "plot":
        from .figures import plot

        return plot
    if name == "sweep":
        from .sweeps import sweep

        return sweep
    raise AttributeError(f"module 'snakecg' has no attribute {name!r}")
