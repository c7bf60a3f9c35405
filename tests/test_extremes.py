"""Extremes over the input ellipsoid (eq. 31) and the polar COM coordinates (issue #3).

References: dense sampling of the ellipsoid's boundary evaluated with the exact forward
solve, and plain numpy geometry for the polar coordinates.
"""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
import snakecg.robot_model
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


def _reference_values(ref, maps, taus):
    from reference import solve_rest_batch

    return solve_rest_batch(ref, maps, np.atleast_2d(taus))


def _scipy_polish(ref, maps, u0, metric, largest, kept_only):
    """Local optimum of the reference's metric on the unit sphere ``u`` (tau = L^-T u) from
    ``u0``, by SciPy's SLSQP (the piecewise map is continuous; SLSQP follows its pieces)."""
    from scipy.optimize import minimize

    L = np.linalg.cholesky(maps["N"])
    sign = -1.0 if largest else 1.0

    def f(u):
        r = _reference_values(ref, maps, np.linalg.solve(L.T, u))
        v = r[metric][0]
        if kept_only and not r["contact"][0]:
            return 1e3
        return sign * v

    res = minimize(f, u0, method="SLSQP",
                   constraints=[{"type": "eq", "fun": lambda u: u @ u - 1.0}],
                   options={"ftol": 1e-14, "maxiter": 200})
    u = res.x / np.linalg.norm(res.x)
    return np.linalg.solve(L.T, u)


@pytest.mark.parametrize("joints,configs,count", [
    (2, 5, 4000), (3, 3, 20000), pytest.param(4, 2, 20000, marks=pytest.mark.slow)])
def test_exact_wheel_extremes_against_the_reference(joints, configs, count):
    """Bounded wheels, n_a <= 4: the exact extremes are certified, attained by the independent
    dense reference (tests/reference.py) at the reported torques, never beaten by a dense
    sample of the boundary solved by the reference, nor by SciPy's SLSQP started from the best
    samples."""
    from reference import Reference, rest_maps

    model = _scene(joints, "wheels", kappa=100.0)
    ref = Reference(model.scene)
    qs = _configs(joints, configs, seed=40 + joints)
    ex = model.extremes(qs)
    assert ex.certified.all()
    rng = np.random.default_rng(joints)
    d = rng.normal(size=(count, joints))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    for i, q in enumerate(qs):
        maps = rest_maps(ref, q)
        L = np.linalg.cholesky(maps["N"])
        taus = np.linalg.solve(L.T, d.T).T
        dense = _reference_values(ref, maps, taus)
        for m in METRICS:
            vals = dense[m]
            scale = max(np.abs(vals).max(), 1e-30)
            # attained: the reference at the reported torques gives the reported values
            for tau, target in ((ex.tau_max[m][i], ex.max[m][i]),
                                (ex.tau_min_kept[m][i], ex.min_kept[m][i])):
                assert tau @ maps["N"] @ tau == pytest.approx(1.0, rel=1e-9)
                got = _reference_values(ref, maps, tau)[m][0]
                assert got == pytest.approx(target, rel=1e-7, abs=1e-10 * scale), (i, m)
            # never beaten by the dense sample ...
            assert vals.max() <= ex.max[m][i] * (1 + 1e-9) + 1e-12 * scale, (i, m)
            kept = vals[dense["contact"]]
            assert kept.min() >= ex.min_kept[m][i] * (1 - 1e-9) - 1e-12 * scale, (i, m)
            # ... nor by a local optimisation from its best points
            top = np.argsort(-vals)[:1]
            for j in top:
                t = _scipy_polish(ref, maps, d[j], m, True, False)
                v = _reference_values(ref, maps, t)[m][0]
                assert v <= ex.max[m][i] * (1 + 1e-9) + 1e-12 * scale, (i, m, "scipy")
            if m in ("norm_qdd", "norm_lambda"):
                j = np.argmin(np.where(dense["contact"], vals, np.inf))
                t = _scipy_polish(ref, maps, d[j], m, False, True)
                r = _reference_values(ref, maps, t)
                if r["contact"][0]:
                    assert r[m][0] >= ex.min_kept[m][i] * (1 - 1e-9) - 1e-12 * scale


def test_exact_wheel_extremes_at_the_cited_configurations():
    """Case study 2 (kappa = 100, mu = 0.1). At (-5, -5, -5) degrees the best sr was reported
    0.98748029 by sampling; a dense sample of 200,000 directions reaches 0.9874875, the
    exact maximum is higher still (a narrow ridge where wheel 3 is at its friction bound), and
    the independent reference attains it at the returned torque. At
    (-38.78, 129.94, 133.93) degrees the contact-kept minimum of ||qdd||^2 was reported as
    0.015108 against a true 0.0049067 or less."""
    from reference import Reference, rest_maps

    model = _scene(3, "wheels", kappa=100.0, mu=0.1)
    ref = Reference(model.scene)
    q1 = np.r_[0.0, 0.0, 0.0, np.deg2rad([-5.0, -5.0, -5.0])]
    q2 = np.r_[0.0, 0.0, 0.0, np.deg2rad([-38.78, 129.94, 133.93])]
    ex = model.extremes(np.stack([q1, q2]))
    assert ex.certified.all()
    assert ex.max["sr"][0] >= 0.98748774
    got = _reference_values(ref, rest_maps(ref, q1), ex.tau_max["sr"][0])["sr"][0]
    assert got == pytest.approx(ex.max["sr"][0], rel=1e-9)
    assert ex.max["sr"][0] == pytest.approx(0.98783775, abs=1e-8)
    assert ex.min_kept["norm_qdd"][1] <= 0.0049067
    got = _reference_values(ref, rest_maps(ref, q2), ex.tau_min_kept["norm_qdd"][1])
    assert got["norm_qdd"][0] == pytest.approx(ex.min_kept["norm_qdd"][1], rel=1e-9)
    assert got["contact"][0]


def _refine_on_sphere(model, qs, Linv_T, m, u, steps=600, seed=0):
    """Local maxima of the forward solver's metric ``m`` on the unit spheres ``u`` (tau =
    L^-T u), all configurations at once: a pattern search over 16 tangent directions, turned
    at random every step (the maxima often sit on a ridge, a wheel at its friction bound),
    whose step shrinks where none improves, down to 1e-11."""
    n, k = len(qs), 16
    rng = np.random.default_rng(seed)

    def value(uu):
        lt = np.repeat(Linv_T, len(uu) // n, axis=0)
        q = np.repeat(qs, len(uu) // n, axis=0)
        return getattr(model.forward(q, np.einsum("nij,nj->ni", lt, uu)), m)

    best = value(u)
    step = np.full(n, 0.05)
    for _ in range(steps):
        if step.max() < 1e-11:
            break
        t1 = np.cross(u, np.where(np.abs(u[:, :1]) < 0.9, [[1.0, 0, 0]], [[0, 1.0, 0]]))
        t1 /= np.linalg.norm(t1, axis=1, keepdims=True)
        t2 = np.cross(u, t1)
        ang = (np.arange(k) + rng.uniform(size=(n, 1))) * (2 * np.pi / k)  # (n, k)
        trial = u[:, None] + step[:, None, None] * (np.cos(ang)[:, :, None] * t1[:, None]
                                                    + np.sin(ang)[:, :, None] * t2[:, None])
        trial /= np.linalg.norm(trial, axis=2, keepdims=True)
        vals = value(trial.reshape(-1, 3)).reshape(n, k)
        j = np.argmax(vals, axis=1)
        top = vals[np.arange(n), j]
        up = top > best
        u = np.where(up[:, None], trial[np.arange(n), j], u)
        best = np.where(up, top, best)
        step = np.where(up, 1.5 * step, 0.6 * step)
    return best


def test_exact_wheel_extremes_on_random_configurations():
    """Bounded wheels, 3 joints (kappa = 100, mu = 0.1), 200 random configurations against
    the forward solver: no point of a dense sample of the boundary (1,500 directions each)
    beats the exact maxima or the contact-kept minima, and a local refinement of each maximum
    from the best sample (a pattern search on the sphere through the forward solver) never
    beats it by more than 1e-9. The refinement reaches the maximum within 1e-3 almost always
    and within 1e-6 mostly: many maxima sit on a ridge (a wheel at its friction bound), which
    a pattern search follows only slowly."""
    model = _scene(3, "wheels", kappa=100.0, mu=0.1)
    qs = _configs(3, 200, seed=11)
    ex = model.extremes(qs)
    assert ex.certified.all()
    d = sphere_directions(3, 1500)
    L = np.linalg.cholesky(model.maps(qs)["input_metric"])  # (200, 3, 3), N = L L^T
    Linv_T = np.swapaxes(np.linalg.inv(L), 1, 2)  # tau = L^-T u
    res = model.forward(np.repeat(qs, len(d), axis=0),
                        np.einsum("nij,kj->nki", Linv_T, d).reshape(-1, 3))
    kept = res.contact.reshape(len(qs), len(d))
    for m in METRICS:
        vals = getattr(res, m).reshape(len(qs), len(d))
        scale = np.abs(vals).max(axis=1) + 1e-30
        assert np.all(vals.max(axis=1) <= ex.max[m] * (1 + 1e-9) + 1e-12 * scale), m
        low = np.where(kept, vals, np.inf).min(axis=1)
        assert np.all(low >= ex.min_kept[m] * (1 - 1e-9) - 1e-12 * scale), m
        refined = _refine_on_sphere(model, qs, Linv_T, m, d[np.argmax(vals, axis=1)])
        assert np.all(refined <= ex.max[m] * (1 + 1e-9) + 1e-12 * scale), m
        gap = ex.max[m] - refined
        assert np.mean(gap <= 1e-3 * ex.max[m] + 1e-12 * scale) >= 0.95, m
        assert np.mean(gap <= 1e-6 * ex.max[m] + 1e-12 * scale) >= 0.6, m


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


def test_sampled_wheel_extremes_keep_the_callers_backend(monkeypatch):
    """The sampled wheel extremes start from the ideal-wheel extremes of the same robot,
    evaluated on a second model: that model uses the caller's backend, so a model loaded with
    ``backend="casadi"`` never asks for a compiled library."""

    asked = []
    real = snakecg.robot_model._backend

    def spy(n_joints, prefer, progress=None):
        asked.append(prefer)
        return real(n_joints, prefer, progress)

    monkeypatch.setattr(snakecg.robot_model, "_backend", spy)
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels"),
                         backend="casadi")
    q = np.array([0.0, 0.0, 0.0, 0.4, -0.3])
    ex = model.extremes(q, exact=False, samples=8, refine=1, starts=1)
    assert asked and set(asked) == {"casadi"}
    assert np.all(ex.max["norm_qdd"] >= ex.min["norm_qdd"])


@pytest.mark.parametrize("joints", [2, 3])
@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
def test_extremes_at_repeated_roots_are_attained_by_their_torques(joints, scenario):
    """Without wheels, ||qdd_s||^2 is tau^T B^T M^-1 B tau = 1 on the ellipsoid wherever the
    contact is lost (a law of eq. 31's metric), so its largest value is exactly 1: a triple
    root of the closed form's cubic, which it gave as 1 + 7e-9 (above every value the
    ellipsoid holds, and above what its own torque attains) at 897 of 2,000 random
    configurations. Every reported extreme is now the one its torque attains: the forward
    solve at the returned torque gives it to 1e-12, and frictionless, max ||qdd_s||^2 is 1 to
    1e-12."""
    model = _scene(joints, scenario)
    Q = _configs(joints, 2000, seed=3)
    ex = model.extremes(Q)
    if scenario == "frictionless":
        np.testing.assert_allclose(ex.max["norm_qdd"], 1.0, rtol=0, atol=1e-12)
    for values, taus in ((ex.max, ex.tau_max), (ex.min_kept, ex.tau_min_kept)):
        for m in METRICS:
            got = getattr(model.forward(Q, taus[m]), m)
            np.testing.assert_allclose(values[m], got, rtol=1e-12,  # (the metric's scale)
                                       atol=1e-12 * np.abs(ex.max[m]).max(), err_msg=m)
