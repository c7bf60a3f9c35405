"""What kind of model an object is, without importing :mod:`snakecg.model`: the feature
packages (analysis, optimize, simulate, shape, figures) check their ``model`` argument here,
so that they import the engine and never the facade that calls them."""

from __future__ import annotations

__all__ = ["SCENE_MODEL", "is_scene_model"]

#: The ``model_kind`` of a :class:`snakecg.SceneModel` (a robot in a scene).
SCENE_MODEL = "scene"


def is_scene_model(obj) -> bool:
    """Whether ``obj`` is a :class:`snakecg.SceneModel` (its class says so by
    ``model_kind``)."""
    return getattr(type(obj), "model_kind", None) == SCENE_MODEL
