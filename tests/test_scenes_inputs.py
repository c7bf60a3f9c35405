"""The general path's batch refuses a call whose inputs hold a value that is not finite, a
torque or wrench beyond 1e150, or a base position beyond a million scene sizes, and names the
first such sample (scene_inputs.c: the entries filtered by their bits, contiguous rows as one
run, then compared): the engine's code against NumPy's ``isfinite`` and comparisons over the
same rows, for q, tau and the objects' wrenches, contiguous, broadcast (stride 0) and
strided, with the edge cases that must pass (the largest finite joint angle, the smallest
subnormal, -0.0, the limits themselves, 2^498 where the bit filter turns) and those just
beyond the limits."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.engine.rules import FORCE_LIMIT as FORCE
from snakecg.scenes import GeneralScene
from snakecg.scenes.model import POSITION_SPAN as SPAN
from snakecg.scenes.packing import scene_size

# (the engine's own copies, scene_inputs.c/.h, are held to these by the refusals at the
# limits and just beyond them below)


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


def _expected(rows, qlim):
    """-3 - (the first sample refused, by NumPy), or 0."""
    q, tau, fo = rows
    bad = (~np.isfinite(q).all(1) | ~(np.abs(q[:, :2]) <= qlim).all(1)
           | ~(np.abs(tau) <= FORCE).all(1) | ~(np.abs(fo) <= FORCE).all(1))
    bad = np.flatnonzero(bad)
    return -3 - int(bad[0]) if bad.size else 0


@pytest.mark.parametrize("layout", ["contiguous", "strided", "broadcast"])
def test_first_sample_not_finite_named(paper, layout):
    rng = np.random.default_rng(3)
    N, widths = 9, (6, 3, 3)
    qlim = SPAN * scene_size(paper.scene)
    big = np.finfo(float).max
    edge = [  # (that pass: in q beyond its base, the base's limits, the forces' limits)
        [[big, -big, 5e-324, -0.0, 0.0], [qlim, -qlim, 0.5 * qlim]],
        [[FORCE, -FORCE, 2.0 ** 498, 5e-324, -0.0]], [[FORCE, -FORCE, 2.0 ** 498, -0.0]]]
    beyond = [[np.nextafter(qlim, np.inf), -big], [np.nextafter(FORCE, np.inf), -big, 2.0 ** 499],
              [np.nextafter(-FORCE, -np.inf), big]]
    for trial in range(60):
        pad = 2 if layout == "strided" else 0  # rows wider than their values: a stride
        bases = [np.c_[rng.uniform(-0.5, 0.5, (N, w)), np.zeros((N, pad))] for w in widths]
        bases[1][:, :3] *= 0.1
        bases[2][:, :3] = 0.0
        if trial % 3 == 0:  # values at the edge somewhere: never refused
            which = rng.integers(3)
            if which == 0 and trial % 2:  # the base's x or y at its limits
                bases[0][rng.integers(N), rng.integers(2)] = edge[0][1][trial % 3]
            else:  # (a joint angle: any finite value)
                j = rng.integers(2, 6) if which == 0 else rng.integers(widths[which])
                vals = edge[which][0]
                bases[which][rng.integers(N), j] = vals[trial % len(vals)]
        if trial % 7 == 5:  # a value just beyond a limit: refused
            which, k = rng.integers(3), rng.integers(N)
            j = rng.integers(2) if which == 0 else rng.integers(widths[which])
            bases[which][k, j] = beyond[which][trial % len(beyond[which])]
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
        expect = _expected(rows, qlim)
        if expect == 0:
            assert code == 0, (trial, code)
        else:
            assert code == expect, (trial, code, expect)
