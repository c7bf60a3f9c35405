"""Call a generated function by the names of its inputs and outputs.

The manifest of a model lists, per function, its inputs and outputs with names, shapes and
order (read by the generator from the CasADi functions themselves). This module is the one
place that turns names into the positional order the backends take, so the rest of the
runtime never indexes by position::

    out = kernels.call(model.backend, "mass_matrix", n, q=q, K=model.parameters)
    M = out["M"]          # or out.M

:class:`Outputs` is a tuple (old positional code keeps working) whose entries are also
reachable by name.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .errors import InputError

__all__ = ["Outputs", "call", "arguments", "outputs_type", "at_origin"]


class Outputs(tuple):
    """The outputs of one call, in signature order; ``out["name"]`` or ``out.name`` too."""

    __slots__ = ()
    _names: tuple[str, ...] = ()
    _index: Mapping[str, int] = {}

    def __getitem__(self, key):
        if isinstance(key, str):
            try:
                key = self._index[key]
            except KeyError:
                raise KeyError(f"{self._function} has no output {key!r}; outputs: "
                               f"{', '.join(self._names)}") from None
        return tuple.__getitem__(self, key)

    def __getattr__(self, name):
        index = type(self)._index
        if name in index:
            return tuple.__getitem__(self, index[name])
        raise AttributeError(name)

    def keys(self):
        return self._names

    def items(self):
        return zip(self._names, self)

    def as_dict(self) -> dict:
        return dict(zip(self._names, self))

    _function = "function"


_TYPES: dict[tuple[str, tuple[str, ...]], type] = {}


def outputs_type(function: str, names) -> type:
    """The :class:`Outputs` subclass of a function with output ``names`` (cached)."""
    key = (function, tuple(names))
    cls = _TYPES.get(key)
    if cls is None:
        cls = type(f"{function}_outputs", (Outputs,), {
            "__slots__": (), "_names": key[1], "_function": function,
            "_index": {n: k for k, n in enumerate(key[1])}})
        _TYPES[key] = cls
    return cls


def arguments(signature, inputs: Mapping[str, object]) -> list[np.ndarray]:
    """Inputs given by name, in the signature's order, as float64 C-contiguous arrays
    (``(size,)`` broadcasts; ``(n, ...)`` is flattened to ``(n, size)``). Every input is
    required; an unknown or missing name is an :class:`InputError` naming them all."""
    names = signature.in_names
    missing = [k for k in names if k not in inputs]
    unknown = [k for k in inputs if k not in names]
    if missing or unknown:
        what = []
        if missing:
            what.append("missing " + ", ".join(missing))
        if unknown:
            what.append("unknown " + ", ".join(unknown))
        raise InputError(f"{signature.name}: {'; '.join(what)} (inputs: {', '.join(names)})")
    out = []
    for k in names:
        a = np.ascontiguousarray(inputs[k], dtype=float)
        if a.ndim > 2:
            a = a.reshape(a.shape[0], -1)
        out.append(a)
    return out


def call(backend, name: str, n: int, **inputs) -> Outputs:
    """Evaluate generated function ``name`` on ``n`` samples with its inputs by name.

    Outputs are ``(n, rows, cols)`` arrays (the backends' layout) in an :class:`Outputs`.
    """
    sig = backend.signatures.get(name)
    if sig is None:
        raise InputError(f"the model has no generated function {name!r}; functions: "
                         f"{', '.join(backend.signatures)}")
    outs = backend(name, n, arguments(sig, inputs))
    return outputs_type(name, sig.out_names)(outs)


def at_origin(q, q_obj=None):
    """Configurations ``q`` (``(..., n_q)``) with the base at the origin, and the object's
    poses ``q_obj`` (``(..., 3)``, or None) moved with it: the paper's scene has no fixed
    body, so its contact system (and every at-rest map of it) is evaluated there, as the
    compiled core's ``sc_contact_system`` does; far from the origin the world coordinates of
    the contact and the object cancel (at 1e16 m the forces' norm came out 2.8 times the
    true one). Copies; ``(q, q_obj)``."""
    q0 = np.array(q, dtype=float)
    if q_obj is not None:
        q_obj = np.array(q_obj, dtype=float)
        q_obj[..., :2] -= q0[..., :2]
    q0[..., :2] = 0.0
    return q0, q_obj
