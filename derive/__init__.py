"""snakecg's derivation layer (installed as ``snakecg_derive``).

SymPy derives the model of a planar snake robot with ``n_a`` joints pushing an object
(Reyes & Ma 2017), symbolic in every physical parameter; :mod:`.render` turns the result into
CasADi functions built in Python (:mod:`.build`, :mod:`.coupled`), the C that CasADi emits
and a readable record of each model.

Data flows one way: ``derive`` (symbolic, slow, run rarely) -> ``generated`` -> ``snakecg``
(runtime). Nothing here is imported by the runtime on its normal path.
"""

from importlib import import_module

_LAZY = {"SnakeSymbols": ".symbols", "derive_model": ".model", "ModelDerivation": ".model",
         "FunctionSpec": ".spec", "ModelSpec": ".spec"}


def __getattr__(name):
    # SymPy is imported on first use only: the runtime reads .catalog without it
    if name in _LAZY:
        return getattr(import_module(_LAZY[name], __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["SnakeSymbols", "derive_model", "ModelDerivation", "FunctionSpec", "ModelSpec"]
