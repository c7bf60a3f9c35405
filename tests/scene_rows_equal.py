"""Bit-for-bit equality of the general scenes' output rows (the engine's, ``model._out``)
whatever the room each run gave its contacts: a batch's first pass has room for the contacts
its model has met so far, a one-sample call for ``CONTACTS_FIRST``, so two runs of the same
samples may differ in width. The columns both have are equal (NaN where both are NaN), and
every column only one of them has is zero (the room of contacts no sample found)."""

from __future__ import annotations

import numpy as np


def rows_equal(a, b) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    w = min(a.shape[-1], b.shape[-1])
    if a.shape[:-1] != b.shape[:-1] or not np.array_equal(a[..., :w], b[..., :w],
                                                           equal_nan=True):
        return False
    return not (np.any(a[..., w:]) or np.any(b[..., w:]))
