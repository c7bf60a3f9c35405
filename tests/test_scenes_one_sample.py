"""The general path's one-sample forward keeps the engine's scratch from one call to the next
(scene_rows.c's core_scene_forward_call with keep): a sequence of calls, with refused samples
(overlapping shapes, inputs not finite) between them, gives each sample the accelerations
Clarabel finds for its own problem and the same bytes as a freshly loaded model's first call;
the scratch is freed with the closure."""

from __future__ import annotations

import gc
import inspect
import threading

import numpy as np
import pytest

import snakecg
from snakecg import Robot, Scene
from snakecg.errors import InputError
from snakecg.scenes import load_scene

from scene_rows_equal import rows_equal
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


@pytest.fixture(scope="module")
def paper():
    scene = Scene(Robot(joints=3), scenario="wheels", kappa=100)
    return snakecg.load(scene), load_scene(scene)


def test_the_instance_s_forward_from_threads_at_once(paper):
    """The one-sample forward bound in the instance takes its buffer as a one-token list's
    token: four threads calling it at once (a busy buffer sends a call the class's general
    way) each get their sample's answer: the paper's own path's accelerations (1e-12) and the
    bytes of a batch of that one sample, with every sample cold."""
    old, new = paper
    rng = np.random.default_rng(5)
    Q = np.c_[np.zeros((64, 3)), rng.uniform(-1.0, 1.0, (64, 3))]
    T = rng.normal(0, 0.05, (64, 3))
    want = [old.forward(q, t).qdd for q, t in zip(Q, T)]
    cold = new._run(Q, T, new._zero_f, len(Q), True, chunk=1)
    got = {}

    def work(k):
        for rep in range(40):
            s = (7 * k + rep) % len(Q)
            got[k, rep] = (s, new.forward(Q[s].copy(), T[s].copy()))

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert len(got) == 160
    for s, res in got.values():
        assert not res.batched and res.status == 0
        assert np.abs(res.qdd - want[s]).max() <= 1e-12 * max(1.0, np.abs(want[s]).max())
        assert rows_equal(res._out[0], cold[s])


def test_inputs_the_fast_way_declines_go_the_general_way(paper):
    """Lists, float32 arrays, a batch of one and a wrench go the class's general way with the
    same answers (to the paper's own path, 1e-12); bad input still gets its clear error."""
    old, new = paper
    q, tau = np.array([0.0, 0.0, 0.0, 0.3, -0.4, 0.2]), np.array([0.02, -0.01, 0.03])
    want = old.forward(q, tau).qdd
    for args in ((list(q), list(tau)), (q, tau.tolist())):
        r = new.forward(*args)
        assert not r.batched and np.abs(r.qdd - want).max() <= 1e-12 * np.abs(want).max()
    q32 = q.astype(np.float32)  # (its own numbers: q rounded to single precision)
    want32 = old.forward(q32.astype(float), tau).qdd
    r = new.forward(q32, tau)
    assert not r.batched and np.abs(r.qdd - want32).max() <= 1e-12 * np.abs(want32).max()
    r = new.forward(q[None], tau)
    assert r.batched and np.abs(r.qdd[0] - want).max() <= 1e-12 * np.abs(want).max()
    r = new.forward(q, tau, f_obj=np.zeros((1, 3)))
    assert np.abs(r.qdd - want).max() <= 1e-12 * np.abs(want).max()
    with pytest.raises(InputError, match="q"):
        new.forward(q[:5], tau)
    with pytest.raises(InputError, match="tau"):
        new.forward(q, np.zeros(4))
    with pytest.raises(InputError, match="tau"):
        new.forward(q, np.array([0.0, np.inf, 0.0]))
    assert "f_obj" in str(inspect.signature(new.forward))
    assert new.forward.__doc__ == type(new).forward.__doc__


def test_a_busy_buffer_sends_the_call_the_general_way(paper):
    """With the buffer's token taken (another thread's call under way) a one-sample call goes
    the class's general way: the same bytes as the fast way's, which the next call takes
    again once the token is back."""
    old, new = paper
    q, tau = np.array([0.0, 0.0, 0.0, -0.5, 0.3, 0.6]), np.array([0.01, 0.03, -0.02])
    fast = new.forward(q, tau)
    token = inspect.getclosurevars(new.forward).nonlocals["take"].__self__  # (the list)
    assert token == [True]
    token.pop()
    try:
        busy = new.forward(q, tau)
    finally:
        token.append(True)
    assert busy._buf is None and not busy.batched  # (a result of the general way's rows)
    assert rows_equal(busy._out[0], fast._out[0])
    want = old.forward(q, tau).qdd
    assert np.abs(busy.qdd - want).max() <= 1e-12 * max(1.0, np.abs(want).max())
    assert new.forward(q, tau)._buf is not None and token == [True]
