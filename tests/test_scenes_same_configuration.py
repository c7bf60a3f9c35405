"""A batch whose samples share a configuration (a torque map, the torques an optimiser tries
at one pose) finds the contacts, rows and inertia once and keeps them, with the solve's
Z = L^-1 A^T and Gram matrix G = A M^-1 A^T, for the samples after it at the same q.

What it keeps is a function of q alone, so the answers must be the same bits as those of the
one-sample calls, which find everything afresh. Here on the 10-joint benchmark scene
(statically indeterminate: Coulomb ground, four pegs, two objects), on a scene with Coulomb
friction at its contacts and on the paper's scene; with the configuration changing inside the
batch (what is kept must be dropped); and the kept samples' answers are also held to the
KKT conditions of an independent dense NumPy model."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import snakecg
from snakecg.scenes import GeneralScene

from scene_rows_equal import rows_equal
from scenes_reference import dense_problem, indeterminate_scene, kkt_violations

FIELDS = ("qdd", "a_obj", "norm_lambda", "norm_qdd", "norm_a_obj", "sr", "status")


def _rows_of(model, Q, T):
    """The engine's rows, every sample cold (``chunk=1``: no start from a neighbour's pieces,
    as a one-sample call), the batch in one call."""
    return model._run(Q, T, model._zero_f, len(Q), True, chunk=1)


def _alone(model, Q, T):
    """Each sample a batch of its own, cold (rows of the widest room: the rooms may differ)."""
    rows = [model._run(q[None], t[None], model._zero_f, 1, True, chunk=1) for q, t in zip(Q, T)]
    width = max(r.shape[1] for r in rows)
    return np.vstack([np.pad(r, ((0, 0), (0, width - r.shape[1]))) for r in rows])


def _ten_joints():
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(10))]
    return snakecg.load(indeterminate_scene(q)), q


def test_a_batch_at_one_configuration_answers_as_the_one_sample_calls_bit_for_bit():
    model, q = _ten_joints()
    T = np.random.default_rng(11).normal(0, 0.1, (40, 10))
    Q = np.repeat(q[None], len(T), axis=0)
    batch, alone = _rows_of(model, Q, T), _alone(model, Q, T)
    assert np.all(batch[:, 0] == 0)  # (solved)
    assert rows_equal(batch, alone)


def test_what_is_kept_is_dropped_where_the_configuration_changes():
    """Two configurations in runs of 1-4 samples (and a -0.0 against 0.0 that compares equal
    as a number but is another input): each sample as the one-sample call."""
    model, q = _ten_joints()
    rng = np.random.default_rng(12)
    q2 = q.copy()
    q2[5] += 1e-9  # (the same contacts, within their tolerance: the pegs touch at q)
    q3 = q.copy()
    q3[0] = -0.0
    runs = rng.integers(1, 5, 12)
    Q = np.vstack([np.repeat([(q, q2, q3)[i % 3]], r, axis=0) for i, r in enumerate(runs)])
    T = rng.normal(0, 0.1, (len(Q), 10))
    batch, alone = _rows_of(model, Q, T), _alone(model, Q, T)
    assert np.all(batch[:, 0] == 0)
    assert rows_equal(batch, alone)


@pytest.mark.parametrize("which", ["pegs", "contact friction", "paper"])
def test_one_sample_calls_keep_the_last_calls_rows_and_answer_as_cold_ones(which):
    """``model.forward(q, tau)`` one sample at a time keeps the engine's scratch from call to
    call, and with it the last call's rows, Z and G where q is the same bytes: along runs of
    three configurations (q moved by 1e-9 within the contacts' tolerance, and a -0.0), each
    call's row is the bytes of that sample solved cold as a batch of its own."""
    if which == "paper":
        model = snakecg.load(GeneralScene.from_scene(
            snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100)))
        q = np.r_[0.0, 0.0, 0.0, 0.4, -0.3, 0.5]
    else:
        model, q = _ten_joints()
        if which == "contact friction":
            model = snakecg.load(dataclasses.replace(model.scene, mu_contact=0.4))
    rng = np.random.default_rng(16)
    q2 = q.copy()
    q2[5] += 1e-9
    q3 = q.copy()
    q3[0] = -0.0
    runs = rng.integers(1, 5, 9)
    Q = np.vstack([np.repeat([(q, q2, q3)[i % 3]], r, axis=0) for i, r in enumerate(runs)])
    T = rng.normal(0, 0.1 if model.n_joints > 3 else 0.05, (len(Q), model.n_joints))
    calls = [model.forward(qs.copy(), ts.copy()) for qs, ts in zip(Q, T)]
    assert all(not c.batched for c in calls)
    alone = _alone(model, Q, T)
    assert np.all(alone[:, 0] == 0)
    ns = model.n_coordinates
    for c, a in zip(calls, alone):
        assert rows_equal(c._buf[ns + model.n_joints:], a)


def test_the_kept_samples_hold_the_kkt_conditions_of_a_dense_model():
    """The samples after the second at one q solve on the kept G (the second computes and
    keeps it): their forces and accelerations against the dense model's KKT conditions."""
    model, q = _ten_joints()
    T = np.random.default_rng(13).normal(0, 0.1, (12, 10))
    res = model.forward(np.repeat(q[None], len(T), axis=0), T)
    for i in range(2, len(T)):
        one = res.sample(i)
        assert one.status == 0, one.reason
        p = dense_problem(one, model, T[i])
        lam = one._raw["lam"][0][:len(p["b"])]
        a = np.r_[np.asarray(one.qdd).ravel(), np.asarray(one.a_obj).ravel()]
        assert kkt_violations(p, lam, a) == []


@pytest.mark.parametrize("which", ["contact friction", "paper"])
def test_other_paths_at_one_configuration_answer_as_the_one_sample_calls(which):
    """Contact friction (scene_friction.c's solve: the rows kept, not G) and the paper's scene
    (scene_tiny.c's path) at one q, each sample as the one-sample call."""
    if which == "paper":
        model = snakecg.load(GeneralScene.from_scene(
            snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100)))
        q = np.r_[0.0, 0.0, 0.0, 0.4, -0.3, 0.5]
        T = np.random.default_rng(14).normal(0, 0.05, (30, 3))
    else:
        base, q = _ten_joints()
        model = snakecg.load(dataclasses.replace(base.scene, mu_contact=0.4))
        T = np.random.default_rng(15).normal(0, 0.1, (20, 10))
    Q = np.repeat(q[None], len(T), axis=0)
    batch, alone = _rows_of(model, Q, T), _alone(model, Q, T)
    assert np.all(batch[:, 0] == 0)
    assert rows_equal(batch, alone)
