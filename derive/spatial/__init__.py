"""The spatial chain: a serial chain of revolute joints about any axes on a floating base.

SymPy derives its kinematics and dynamics symbolic in every parameter (:mod:`.model`, built on
:mod:`.chain`), :mod:`.render` turns them into CasADi functions, C and a manifest under
``generated/spatial/na<N>/``. :mod:`.closed` holds the closed form (poses differentiated
directly) for inspection and as an independent check of the recursion for a few links.
"""

from importlib import import_module

_LAZY = {"SpatialSymbols": ".symbols", "derive_spatial_model": ".model",
         "render_spatial_model": ".render", "write_spatial_model": ".render"}


def __getattr__(name):
    if name in _LAZY:
        return getattr(import_module(_LAZY[name], __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = list(_LAZY)
