"""Extremes over the input ellipsoid (eq. 31) and the polar COM coordinates (issue #3).

References: dense sampling of the ellipsoid's boundary evaluated with the exact forward
solve, and plain numpy geometry for the polar coordinates.
"""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.analysis import METRICS, joint_grid, sphere_directions


def _scene(joints, scenario, **kw):
    return snakecg.load(snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, **kw))


def _boundary_samples(model, q, count):
    N = model.maps(q)["input_metric"]
    L = np.linalg.cholesky(N)
    d = sphere_directions(model.n_joints, count)
    return np.linalg.solve(L.T, d.T).T  # tau with tau^T N tau = 1


def _configs(joints, n, seed):
    rng = np.random.default_rng(seed)
    q = np.zeros((n, joints + 3))
    q[:, :3] = rng.uniform(-1, 1, (n, 3))
    q[:, 3:] = rng.uniform(-2.3, 2.3, (n, joints))
    return q


@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
@pytest.mark.parametrize("joints", [2, 3])
def test_exact_extremes_bound_dense_sampling(scenario, joints):
    model = _scene(joints, scenario)
    count = 720 if joints == 2 else 6000
    for q in _configs(joints, 4, seed=joints):
        ex = model.extremes(q)
        taus = _boundary_samples(model, q, count)
        res = model.forward(q, taus)
        for m in METRICS:
            vals = getattr(res, m)
            scale = max(abs(vals).max(), 1e-30)
            # the exact maximum is never beaten, and dense sampling comes close to it
            # (sr peaks along a narrow ray with ideal wheels: there only the bound is checked)
            assert vals.max() <= ex.max[m] + 1e-9 * scale
            if m != "sr":
                assert vals.max() >= ex.max[m] - 2e-3 * scale
            assert vals.min() >= ex.min[m] - 1e-9 * scale
            assert vals.min() <= ex.min[m] + 2e-3 * scale
            kept = vals[res.contact]
            assert kept.min() >= ex.min_kept[m] - 1e-9 * scale
            # the reported torques lie on the boundary and attain the reported values
            for tau, target in ((ex.tau_max[m], ex.max[m]), (ex.tau_min_kept[m], ex.min_kept[m])):
                N = model.maps(q)["input_metric"]
                assert tau @ N @ tau == pytest.approx(1.0, rel=1e-9)
                got = getattr(model.forward(q, tau), m)
                assert got == pytest.approx(target, rel=1e-6, abs=1e-8 * scale)


@pytest.mark.parametrize("joints", [2, 3])
def test_wheels_extremes_within_tolerance_of_dense_sampling(joints):
    """Bounded wheels: the sampled + refined maximum is at least the best of a dense sample
    (within 1e-3 relative) and is attained by the torque it reports."""
    model = _scene(joints, "wheels")
    count = 2000 if joints == 2 else 20000
    for q in _configs(joints, 3, seed=10 + joints):
        ex = model.extremes(q)
        taus = _boundary_samples(model, q, count)
        res = model.forward(q, taus)
        for m in METRICS:
            vals = getattr(res, m)
            scale = max(abs(vals).max(), 1e-30)
            assert ex.max[m] >= vals.max() - 1e-3 * scale, m
            got = getattr(model.forward(q, ex.tau_max[m]), m)
            assert got == pytest.approx(ex.max[m], rel=1e-9, abs=1e-12 * scale)


def test_wheels_match_ideal_wheels_when_no_wheel_reaches_its_bound():
    """With a huge friction coefficient the bounded wheels never slide: same extremes."""
    q = _configs(3, 5, seed=3)
    ideal = _scene(3, "ideal_wheels").extremes(q)
    wheels = _scene(3, "wheels", mu=1e6).extremes(q)
    for m in ("norm_a_obj", "sr"):
        np.testing.assert_allclose(wheels.max[m], ideal.max[m], rtol=1e-6)


def test_sr_max_is_the_top_generalized_eigenvalue():
    """Scenario 1 and 3: sr_max = lambda_max(Omega, Omega + Xi) with the contact kept."""
    q = _configs(3, 1, seed=7)[0]
    for scenario in ("frictionless", "ideal_wheels"):
        model = _scene(3, scenario)
        maps = model.maps(q)
        Om, Xi = maps["omega_tau"], maps["xi_tau"]
        from scipy.linalg import eigh

        top = eigh(Om, Om + Xi, eigvals_only=True)[-1]
        assert model.extremes(q).max["sr"] == pytest.approx(top, rel=1e-8)


def test_batched_extremes_equal_single_calls():
    model = _scene(2, "ideal_wheels")
    Q = joint_grid(2)[::97]
    ex = model.extremes(Q)
    for k, q in enumerate(Q):
        one = model.extremes(q)
        for m in METRICS:
            assert one.max[m] == pytest.approx(ex.max[m][k], rel=1e-12)


def test_com_polar_against_plain_geometry():
    model = _scene(3, "frictionless")
    rng = np.random.default_rng(5)
    q = _configs(3, 10, seed=5)
    radius, angle = model.com_polar(q)
    r = model.robot
    for k in range(len(q)):
        # rebuild the chain by hand: link 1 COM at (x, y), angle theta
        x, y, th = q[k, :3]
        phis = th + np.concatenate([[0.0], np.cumsum(q[k, 3:])])
        e = np.stack([np.cos(phis), np.sin(phis)], axis=1)
        rear = np.array([x, y]) - r.com[0] * e[0]
        coms = []
        for i in range(r.n_links):
            coms.append(rear + r.com[i] * e[i])
            rear = rear + r.length[i] * e[i]
        com = np.average(coms, axis=0, weights=r.mass)
        contact = np.array([x, y]) - r.com[0] * e[0] + model.scene.contact_offset * e[0]
        d = com - contact
        assert radius[k] == pytest.approx(np.linalg.norm(d), rel=1e-12)
        ang = np.arctan2(e[0][0] * d[1] - e[0][1] * d[0], e[0] @ d)
        assert angle[k] == pytest.approx(ang, abs=1e-12)
    del rng


def test_joint_grid_is_the_papers_grid():
    Q2 = joint_grid(2)
    assert Q2.shape == (784, 5)
    assert np.rad2deg(Q2[:, 3:]).min() == pytest.approx(-135)
    assert np.rad2deg(Q2[:, 3:]).max() == pytest.approx(135)
    assert len(np.unique(np.round(np.rad2deg(Q2[:, 3]), 6))) == 28
    assert joint_grid(3).shape == (21952, 6)


def test_extremes_rejects_bad_input():
    model = _scene(2, "wheels")
    with pytest.raises(snakecg.InputError, match="samples"):
        model.extremes(np.zeros(5), samples=1)
    with pytest.raises(snakecg.InputError, match="q has shape"):
        model.extremes(np.zeros(4))


@pytest.mark.parametrize("joints", [1, 2, 3])
@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
def test_compiled_closed_form_agrees_with_numpy_eigensolver(joints, scenario):
    """The generated closed-form eigenpairs (n_a <= 3) against numpy.linalg.eigh."""
    from snakecg.analysis import _quadratic_extremes, _quadratic_extremes_numpy

    model = _scene(joints, scenario)
    assert "metric_extremes" in model.backend.signatures
    Q = _configs(joints, 300, seed=20 + joints)
    fast, ref = _quadratic_extremes(model, Q), _quadratic_extremes_numpy(model, Q)
    for attr in ("max", "min", "min_kept"):
        for m in METRICS:
            a, b = getattr(fast, attr)[m], getattr(ref, attr)[m]
            # a double root of the characteristic cubic (rank-deficient form) is resolved
            # to ~1e-8 of the largest eigenvalue by the trigonometric closed form
            scale = np.abs(ref.max[m]).max()
            np.testing.assert_allclose(a, b, rtol=1e-7, atol=1e-7 * scale)
    N = model.maps(Q)["input_metric"]
    for m in METRICS:  # the closed form's torques attain its values on the boundary
        t = fast.tau_max[m]
        np.testing.assert_allclose(np.einsum("bi,bij,bj->b", t, N, t), 1.0, rtol=1e-9)
        got = getattr(model.forward(Q, t), m)
        np.testing.assert_allclose(got, fast.max[m], rtol=1e-6,
                                   atol=1e-9 * np.abs(fast.max[m]).max())
