"""The general path's batch refuses a call whose inputs hold a value that is not finite and
names the first such sample (scene_inputs.c: the entries tested by their bits, contiguous rows
as one run): the engine's code against NumPy's ``isfinite`` over the same rows, for q, tau and
the objects' wrenches, contiguous, broadcast (stride 0) and strided, with the edge cases of
finite values (the largest, the smallest subnormal, -0.0) that must pass."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.scenes import GeneralScene


@pytest.fixture(scope="module")
def paper():
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100)
    return snakecg.load(GeneralScene.from_scene(scene))


def _code(model, arrays, strides, N):
    """The engine's code for N samples of (q, tau, fo) rows at the given strides."""
    ccap = 16
    mcap = model.packed.rows_room(ccap)
    out = np.empty((N, model.packed.width(ccap)))
    (q, tau, fo), (sq, st, sf) = arrays, strides
    return model._engine(model._pk, N, q.ctypes.data, sq, tau.ctypes.data, st, fo.ctypes.data,
                         sf, ccap, mcap, out.ctypes.data, 0, 0, 0, 0, 1)


def _expected(rows):
    """-3 - (the first sample with an entry not finite, NumPy's isfinite), or 0."""
    bad = np.flatnonzero(~np.all(np.concatenate([np.isfinite(r) for r in rows], axis=1), 1))
    return -3 - int(bad[0]) if bad.size else 0


@pytest.mark.parametrize("layout", ["contiguous", "strided", "broadcast"])
def test_first_sample_not_finite_named(paper, layout):
    rng = np.random.default_rng(3)
    N, widths = 9, (6, 3, 3)
    edge = [np.finfo(float).max, -np.finfo(float).max, 5e-324, -0.0, 0.0]
    for trial in range(60):
        pad = 2 if layout == "strided" else 0  # rows wider than their values: a stride
        bases = [np.c_[rng.uniform(-0.5, 0.5, (N, w)), np.zeros((N, pad))] for w in widths]
        bases[1][:, :3] *= 0.1
        bases[2][:, :3] = 0.0
        if trial % 3 == 0:  # finite edge values somewhere: never refused
            which = rng.integers(3)
            bases[which][rng.integers(N), rng.integers(widths[which])] = edge[trial % 5]
        if trial % 4 != 3:  # one or two values not finite at random places
            for _ in range(1 + trial % 2):
                which, k = rng.integers(3), rng.integers(N)
                j = rng.integers(widths[which])
                bases[which][k, j] = (np.nan, np.inf, -np.inf)[trial % 3]
                if pad and trial % 5 == 0:  # a pad that is not finite is never read
                    bases[which][k, widths[which]] = np.nan
        strides = [b.shape[1] for b in bases]
        if layout == "broadcast":  # one of the three given once for every sample (stride 0)
            b = trial % 3
            strides[b] = 0
            rows_b = np.repeat(bases[b][:1], N, axis=0)
        arrays = [np.ascontiguousarray(a) for a in bases]
        rows = [a[:, :w] for a, w in zip(arrays, widths)]
        if layout == "broadcast":
            rows[b] = rows_b[:, :widths[b]]
        code = _code(paper, arrays, strides, N)
        expect = _expected(rows)
        if expect == 0:
            assert code == 0, (trial, code)
        else:
            assert code == expect, (trial, code, expect)
