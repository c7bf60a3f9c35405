"""The model loader as the features see it.

The feature packages (figures, sweeps, export, reproduce) sit below the facade
(:mod:`snakecg.model`) and never import it; where one is given a scene rather than a loaded
model, it loads the model through :func:`load` here. The facade registers its
:func:`snakecg.load` when the package is imported, which always happens first: importing any
``snakecg.*`` module runs ``snakecg/__init__.py``, which imports the facade.
"""

from __future__ import annotations

__all__ = ["load", "register"]

_LOADER = []


def register(loader) -> None:
    """Make ``loader`` (:func:`snakecg.load`) the one the features call."""
    _LOADER[:] = [loader]


def load(obj, **kwargs):
    """The model of ``obj`` (a Scene, Robot, GeneralScene, ...), by :func:`snakecg.load`."""
    return _LOADER[0](obj, **kwargs)
