"""The general path's one-sample forward keeps the engine's scratch from one call to the next
(scene_rows.c's core_scene_forward_call with keep): a sequence of calls, with refused samples
(overlapping shapes, inputs not finite) between them, gives each sample the accelerations
Clarabel finds for its own problem and the same bytes as a freshly loaded model's first call;
the scratch is freed with the closure."""

from __future__ import annotations

import gc

import numpy as np
import pytest

from snakecg.errors import InputError
from snakecg.scenes import load_scene

from scenes_reference import clarabel_accelerations, dense_problem, indeterminate_scene


@pytest.fixture(scope="module")
def pegs():
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(10))]
    return load_scene(indeterminate_scene(q)), q


def test_calls_after_refused_samples_keep_their_answers(pegs):
    model, q = pegs
    rng = np.random.default_rng(11)
    T = rng.normal(0, 0.1, (6, 10))
    over = q.copy()
    over[1] += 0.02  # the links pushed 2 cm sideways into the pegs on one side
    for k, tau in enumerate(T):
        if k % 2:
            with pytest.raises(InputError, match="overlap"):
                model.forward(over, tau)
            with pytest.raises(InputError):
                model.forward(q, np.r_[tau[:-1], np.nan])
        res = model.forward(q, tau)
        assert res.status == 0 and model.forward.args.keep is not None  # (kept, reused)
        # the accelerations are unique: Clarabel's on the sample's own problem
        a_ref, status = clarabel_accelerations(dense_problem(res, model, tau))
        assert status == "optimal"
        a = np.r_[res.qdd, np.ravel(res.a_obj)]
        assert np.abs(a - a_ref).max() <= 1e-6 * max(1.0, np.abs(a_ref).max())
        # a fresh model's first call (a scratch of its own): the same bytes
        fresh = load_scene(model.scene)
        assert np.array_equal(np.asarray(fresh.forward(q, tau)._buf), np.asarray(res._buf),
                              equal_nan=True)


def test_the_kept_scratch_is_freed_with_the_closure(pegs):
    model, q = pegs
    fresh = load_scene(model.scene)
    fresh.forward(q, np.zeros(10))
    args, free = fresh.forward.args, fresh.forward.free
    assert args.keep is not None and free.alive
    del fresh.forward  # (the instance's one-sample forward: the class's general way left)
    gc.collect()
    assert not free.alive and args.keep is None  # (the engine freed it and cleared the slot)
