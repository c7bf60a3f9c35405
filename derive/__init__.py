"""snakecg's derivation layer (installed as ``snakecg_derive``).

SymPy derives the model of a planar snake robot with ``n_a`` joints pushing an object
(Reyes & Ma 2017), symbolic in every physical parameter; :mod:`.render` turns the result into
generated Python that builds CasADi functions, plus the C that CasADi emits.

Data flows one way: ``derive`` (symbolic, slow, run rarely) -> ``generated`` -> ``snakecg``
(runtime). Nothing here is imported by the runtime on its normal path.
"""

from .model import ModelDerivation, derive_model
from .symbols import SnakeSymbols
from .spec import FunctionSpec, ModelSpec

__all__ = ["SnakeSymbols", "derive_model", "ModelDerivation", "FunctionSpec", "ModelSpec"]
