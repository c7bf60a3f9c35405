"""The compiled runtime core (snakecg/engine/forward.c) against the reference path.

The reference is the Python active-set iteration of snakecg.solver on the generated
``constrained_dynamics`` (the CasADi backend answers every sample with it), itself checked
against an independent dense model in test_interaction.py. The core must find the same active
sets and the same numbers (to 1e-12 relative), whatever the batch layout, threads or
workspace.
"""

from __future__ import annotations

import pickle
import threading

import numpy as np
import pytest

import snakecg
from snakecg import forward as forward_mod
from snakecg.errors import InputError

SCENARIOS = ("frictionless", "wheels", "ideal_wheels")
FIELDS = ("tau", "qdd", "a_obj", "lam", "w", "norm_lambda", "norm_a_obj", "norm_qdd", "sr",
          "gap")


def _pair(joints, scenario, **kw):
    scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario,
                          **{"kappa": 100, **kw})
    compiled = snakecg.load(scene)
    if compiled.core is None:
        pytest.fail("the compiled backend is needed here: the C build failed")
    return compiled, snakecg.load(scene, backend="casadi")


def _inputs(rng, joints, n):
    ns = joints + 3
    q = np.zeros((n, ns))
    q[:, :3] = rng.uniform(-1, 1, (n, 3))
    q[:, 3:] = rng.uniform(-2.4, 2.4, (n, joints))
    tau = rng.normal(0, 0.05, (n, joints)) * np.exp(rng.uniform(-4, 2, (n, 1)))
    return q, tau


def _same(core_res, ref_res, what):
    np.testing.assert_array_equal(core_res.contact, ref_res.contact, err_msg=what)
    np.testing.assert_array_equal(core_res.wheel_state, ref_res.wheel_state, err_msg=what)
    np.testing.assert_array_equal(core_res.singular, ref_res.singular, err_msg=what)
    for k in FIELDS:
        a, b = np.asarray(getattr(core_res, k)), np.asarray(getattr(ref_res, k))
        scale = np.abs(b).reshape(len(b), -1).max(axis=1).reshape((-1,) + (1,) * (b.ndim - 1))
        if k == "w":  # a held row's w is 0 to rounding of A a: relative to the accelerations
            acc = np.abs(np.hstack([ref_res.qdd, ref_res.a_obj])).max(axis=1, keepdims=True)
            scale = np.maximum(scale, acc)
        assert np.all(np.abs(a - b) <= 1e-12 * np.maximum(scale, 1e-300) + 1e-300), (what, k)
    np.testing.assert_allclose(core_res.conditioning, ref_res.conditioning, rtol=1e-8,
                               atol=1e-14, err_msg=what)


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("joints", [2, 3, 4])
def test_core_equals_reference_path(rng, joints, scenario):
    compiled, reference = _pair(joints, scenario)
    n = 600
    q, tau = _inputs(rng, joints, n)
    core_res = compiled.forward(q, tau)
    ref_res = reference.forward(q, tau)
    assert np.count_nonzero(core_res.raw[:, compiled.columns.status]) < n // 20
    _same(core_res, ref_res, f"{joints} joints, {scenario}")
    # moving bodies, an external wrench, and a given object placement
    ns = joints + 3
    v = rng.normal(0, 0.3, (n, ns))
    v_obj, f_obj = rng.normal(0, 0.2, (n, 3)), rng.normal(0, 0.5, (n, 3))
    _same(compiled.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj),
          reference.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj), "moving")
    q_obj, rho = compiled.place_object(q)[:2]
    rho = rho + rng.uniform(-0.02, 0.02, rho.shape)
    _same(compiled.forward(q, tau, q_obj=q_obj, rho=rho),
          reference.forward(q, tau, q_obj=q_obj, rho=rho), "placed")
    # one sample at a time: the same numbers as in the batch
    for i in range(0, n, 97):
        one = compiled.forward(q[i], tau[i])
        np.testing.assert_array_equal(one.raw[:-1], core_res.raw[i, :-1])


def test_marked_samples_take_the_reference_path():
    """Two ideal wheels 1e-7 rad from coinciding: the core marks the sample (weakly
    independent rows) and the answer is the reference path's (rows factored directly)."""
    compiled, reference = _pair(3, "ideal_wheels", kappa=10,
                                wheel_offset=(0, 0.075, -0.075, 0))
    q = np.array([0.0, 0.0, 0.0, 0.5, 1e-7, -0.8])
    tau = np.array([0.1, -0.05, 0.08])
    res = compiled.forward(q, tau)
    assert res.raw[compiled.columns.status] == 1.0
    ref = reference.forward(q, tau)  # the same path on CasADi's evaluation of the functions
    assert 1e-9 < res.conditioning < 1e-6 and not res.singular
    for k in FIELDS:  # to the stated accuracy, 1e-16 / conditioning
        np.testing.assert_allclose(getattr(res, k), getattr(ref, k), err_msg=k,
                                   rtol=1e-16 / res.conditioning * 100, atol=1e-12)
    assert 2.7e-3 < res.sr < 2.75e-3  # the 50-digit value, test_conditioning.py


def test_workspaces_and_threads_give_the_same_rows(rng):
    compiled, _ = _pair(3, "wheels")
    q, tau = _inputs(rng, 3, 200)
    expected = compiled.forward(q, tau).raw
    results = {}

    def worker(k, data):
        rows = [compiled.forward(q[i], tau[i], data=data).raw for i in range(len(q))]
        results[k] = np.array(rows)

    threads = [threading.Thread(target=worker, args=(k, compiled.create_data() if k % 2 else
                                                     None)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for k in range(4):
        np.testing.assert_array_equal(results[k][:, :-1], expected[:, :-1], err_msg=str(k))
    # a workspace of another model of the same size is re-bound, not misused
    other = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="frictionless"))
    data = other.create_data()
    np.testing.assert_array_equal(compiled.forward(q[0], tau[0], data=data).raw[:-1],
                                  expected[0, :-1])


def test_out_reuses_the_result_array(rng):
    compiled, _ = _pair(2, "wheels")
    q, tau = _inputs(rng, 2, 50)
    first = compiled.forward(q, tau)
    raw = first.raw
    again = compiled.forward(q[::-1].copy(), tau[::-1].copy(), out=first)
    assert again.raw is raw
    np.testing.assert_array_equal(again.raw[:, :-1], compiled.forward(q, tau).raw[::-1, :-1])
    with pytest.raises(InputError, match="out holds results of shape"):
        compiled.forward(q[:10], tau[:10], out=first)
    with pytest.raises(InputError, match="out must be a ForwardResult"):
        compiled.forward(q, tau, out=np.zeros((50, raw.shape[1])))


def test_bad_input_is_refused_naming_it(rng):
    compiled, _ = _pair(2, "frictionless")
    q, tau = _inputs(rng, 2, 20)
    tau[13, 1] = np.nan
    with pytest.raises(InputError, match=r"tau must be finite, found nan at index \(13, 1\)"):
        compiled.forward(q, tau)
    tau[13, 1] = 1e200
    with pytest.raises(InputError, match="tau must have every entry within"):
        compiled.forward(q, tau)
    with pytest.raises(InputError, match="tau must be finite"):
        compiled.forward(q[0], [0.1, float("inf")])
    with pytest.raises(InputError, match="v must be finite"):
        compiled.forward(q[0], tau[0], v=[0, 0, 0, 0, np.nan])


def test_results_pickle_and_index(rng):
    compiled, _ = _pair(3, "wheels")
    q, tau = _inputs(rng, 3, 5)
    res = compiled.forward(q, tau)
    back = pickle.loads(pickle.dumps(res))
    np.testing.assert_array_equal(back.raw, res.raw)
    assert list(back[2].wheel_state) == list(res.wheel_state[2]) and len(back) == 5
    assert float(back[3].sr) == float(res.sr[3])
    assert isinstance(forward_mod.ForwardResult, type)
