"""The compiled engine answers the rare samples itself (engine/rows.c): weakly independent and
dependent held rows, an active set that has not settled, a numerically singular mass matrix.
No sample of the compiled backend reaches the pure-Python engine (snakecg.solver,
snakecg.rows): it is refused here. The answers are held against the independent dense
reference (tests/reference.py: brute-force enumeration of the active sets) and a 50-digit
mpmath solve of its dense system."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg import forward as forward_mod


@pytest.fixture
def no_python_engine(monkeypatch):
    """Any call into the pure-Python engine fails the test."""

    def refuse(*args, **kwargs):
        raise AssertionError("a sample of the compiled backend reached the Python engine")

    monkeypatch.setattr(forward_mod, "_reference_into", refuse)
    monkeypatch.setattr(forward_mod, "_reference_solve", refuse)


def _near_dependent_model():
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="ideal_wheels", kappa=10,
                          wheel_offset=(0, 0.075, -0.075, 0))
    model = snakecg.load(scene)
    if model.core is None:
        pytest.fail("the compiled backend is needed here: the C build failed")
    return scene, model


def test_weak_rows_are_answered_by_the_engine(no_python_engine):
    """Two ideal wheels 1e-7 rad from coinciding: the engine solves the rows directly, to the
    accuracy it states (1e-16 / conditioning) against the 50-digit solve, single and batch."""
    from reference import Reference
    from test_conditioning import _mp_solve

    scene, model = _near_dependent_model()
    q = np.array([0.0, 0.0, 0.0, 0.5, 1e-7, -0.8])
    tau = np.array([0.1, -0.05, 0.08])
    ref = Reference(scene)
    sys_ = ref.system(q, tau)
    a, lam = _mp_solve(sys_, np.array([True, False, True, True, True]), np.zeros(5))
    one, batch = model.forward(q, tau), model.forward(np.stack([q, q]), np.stack([tau, tau]))
    np.testing.assert_array_equal(batch.raw[0], batch.raw[1])
    np.testing.assert_array_equal(one.raw[:-1], batch.raw[0, :-1])
    assert not one.singular and one.reason == "" and 1e-9 < one.conditioning < 1e-6
    acc = 1e-15 / one.conditioning
    ns = ref.ns
    assert np.linalg.norm(one.qdd - a[:ns]) <= acc * np.linalg.norm(a[:ns])
    assert np.linalg.norm(one.a_obj - a[ns:]) <= acc * np.linalg.norm(a)
    assert np.all(np.abs(one.lam - lam) <= acc * np.abs(lam).max())  # of their (huge) size
    na = a[ns:] @ sys_["I_obj"] @ a[ns:]
    nq = a[:ns] @ sys_["M"] @ a[:ns]
    assert one.sr == pytest.approx(na / (na + nq), abs=acc)


def test_dependent_rows_get_least_norm_forces_and_the_flag(no_python_engine):
    """The joint straight: the two wheels' rows coincide. The accelerations are unique (those
    of the system with one of the two rows dropped, solved in 50 digits); the two forces are
    the least-norm pair (equal halves of the dropped system's force); the sample is flagged
    with its reason and conditioning 0."""
    from reference import Reference
    from test_conditioning import _mp_solve

    scene, model = _near_dependent_model()
    q = np.array([0.0, 0.0, 0.0, 0.5, 0.0, -0.8])
    tau = np.array([0.1, -0.05, 0.08])
    sys_ = Reference(scene).system(q, tau)
    np.testing.assert_allclose(sys_["A"][2], sys_["A"][3], atol=1e-12)
    a, lam = _mp_solve(sys_, np.array([True, False, True, False, True]), np.zeros(5))
    res = model.forward(q, tau)
    assert res.singular and res.conditioning == 0.0
    assert "linearly dependent" in res.reason
    ns = len(q)
    np.testing.assert_allclose(res.qdd, a[:ns], rtol=1e-9, atol=1e-9 * np.abs(a).max())
    np.testing.assert_allclose(res.a_obj, a[ns:], rtol=1e-9, atol=1e-9 * np.abs(a).max())
    np.testing.assert_allclose(res.lam[2] + res.lam[3], lam[2], rtol=1e-9)
    np.testing.assert_allclose(res.lam[2], res.lam[3], rtol=1e-9)
    np.testing.assert_allclose(res.lam[[0, 4]], lam[[0, 4]], rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("joints", [2, 3])
def test_unsettled_active_sets_are_enumerated_by_the_engine(no_python_engine, rng, joints):
    """max_iter = 1 leaves most samples of bounded wheels unsettled: the engine enumerates
    their active sets. States and accelerations are the brute-force reference's."""
    from reference import Reference

    scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario="wheels", kappa=100)
    model = snakecg.load(scene)
    ref = Reference(scene)
    n = 40
    q = np.zeros((n, joints + 3))
    q[:, 3:] = rng.uniform(-2.0, 2.0, (n, joints))
    tau = rng.normal(0, 0.5, (n, joints))
    res = model.forward(q, tau, max_iter=1)
    assert np.count_nonzero(res.raw[:, model.columns.status]) > n // 4  # enumerated ones
    names = {"held": "stick", "slide+": "slide+", "slide-": "slide-", "absent": "none"}
    for i in range(n):
        sys_ = ref.system(q[i], tau[i])
        lam, states, viol = ref.solve_enumerate(sys_)
        assert viol < 1e-9
        out = ref.outcome(sys_, lam)
        r = res[i]
        assert bool(r.contact) == (states[0] == "held")
        assert list(r.wheel_state) == [names[s] for s in states[1:]]
        scale = np.abs(np.concatenate([out["qdd"], out["a_obj"]])).max()
        np.testing.assert_allclose(r.qdd, out["qdd"], atol=1e-8 * scale)
        np.testing.assert_allclose(r.a_obj, out["a_obj"], atol=1e-8 * scale)
        assert r.sr == pytest.approx(out["sr"] if states[0] == "held" else 0.0, abs=1e-8)


def test_singular_mass_matrix_is_nan_with_its_reason(no_python_engine):
    """Masses 1 and 1e5 kg, lengths 1e-3 and 1e3 m, inertias 1e-9: M_s is numerically singular
    in float64 (its scaled pivot ratio, computed here by NumPy, is below 1e-13); the engine
    answers NaN with the reason, never an impossible number."""
    robot = snakecg.Robot(joints=1, mass=[1.0, 1e5], length=[1e-3, 1e3], inertia=[1e-9, 1e-9])
    model = snakecg.load(snakecg.Scene(robot))
    q = np.array([0.0, 0.0, 0.0, -3.03774645687452])
    res = model.forward(q, [-0.6832544940131859])
    assert res.singular and res.conditioning == 0.0
    assert "mass matrix" in res.reason
    assert np.isnan(res.sr) and np.all(np.isnan(res.qdd)) and np.all(np.isnan(res.lam))


@pytest.mark.parametrize("case", ["weak", "dependent", "mass"])
def test_both_engines_agree_on_the_hard_samples(case):
    """The pure-Python engine (backend="casadi") and the compiled one, pair by pair on the
    samples the compiled fast path cannot answer: the same row states, flag and reason, the
    same numbers to the accuracy the conditioning states (NaN where there is no answer)."""
    if case == "mass":
        robot = snakecg.Robot(joints=1, mass=[1.0, 1e5], length=[1e-3, 1e3],
                              inertia=[1e-9, 1e-9])
        scene = snakecg.Scene(robot)
        q, tau = np.array([0.0, 0.0, 0.0, -3.03774645687452]), np.array([-0.68325449])
    else:
        scene, _ = _near_dependent_model()
        q = np.array([0.0, 0.0, 0.0, 0.5, 1e-7 if case == "weak" else 0.0, -0.8])
        tau = np.array([0.1, -0.05, 0.08])
    c, p = snakecg.load(scene).forward(q, tau), snakecg.load(scene, backend="casadi").forward(
        q, tau)
    assert c.reason == p.reason and bool(c.singular) == bool(p.singular)
    np.testing.assert_array_equal(c.wheel_state, p.wheel_state)
    assert bool(c.contact) == bool(p.contact)
    rtol = 1e-8 if case != "weak" else 100 * 1e-16 / c.conditioning
    for k in ("qdd", "a_obj", "lam", "sr", "norm_qdd", "norm_a_obj", "norm_lambda"):
        a, b = np.asarray(getattr(c, k)), np.asarray(getattr(p, k))
        np.testing.assert_allclose(a, b, rtol=rtol, atol=rtol * np.max(np.abs(b[np.isfinite(b)]),
                                                                     initial=0),
                                   err_msg=k)
    if case != "weak":
        assert c.conditioning == p.conditioning == 0.0
    else:
        assert c.conditioning == pytest.approx(p.conditioning, rel=1e-6)


def test_face_kernels_take_any_size():
    """The compiled faces, cuts and KKT candidates at n_a = 20 (beyond the former fixed 16):
    the same faces as NumPy's QR cut, the same meets, and the extremes over each face's sphere
    equal to NumPy's eigenvalue linearization and bounding a dense sample of the sphere."""
    from test_sphere_kernel import _dense_face, _pieces, _quadratics

    from snakecg import sphere_kkt as sk
    from snakecg.piecewise import face_kernel

    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels",
                                       kappa=100.0, mu=0.1))
    kernel = face_kernel(model)
    na = 20
    rng = np.random.default_rng(2020)
    cond, used = _pieces(rng, 40, 3, na)
    A, g, c = _quadratics(rng, 40, na)
    d = rng.normal(size=na)
    d /= np.linalg.norm(d)
    ref, got = sk.faces(cond, used, na), sk.faces(cond, used, na, kernel)
    assert len(ref) == len(got) == 4
    for level, (a, b) in enumerate(zip(ref, got)):
        np.testing.assert_array_equal(a.pair, b.pair)
        if level:
            np.testing.assert_allclose(b.u0, a.u0, atol=1e-12)
            np.testing.assert_allclose(b.r, a.r, atol=1e-12)
            np.testing.assert_allclose(b.Z @ np.swapaxes(b.Z, 1, 2),
                                       a.Z @ np.swapaxes(a.Z, 1, 2), atol=1e-12)
            np.testing.assert_array_equal(
                sk.meets(cond, b, d, kernel),
                sk.feasible(cond[a.pair], sk.linear_candidates(a, d)).any(axis=1))
        q, whole = b.pair, level == 0
        u = sk.quadratic_candidates(b.u0, b.Z, b.r, A[q], g[q])
        v = sk.quad(A[q], g[q], c[q], u)
        _, _, _, _, hi, lo = kernel.candidates(
            q, None if whole else b.u0, None if whole else b.Z, None if whole else b.r,
            A, g, c, cond, sk.FEAS_TOL, identity=whole)
        scale = np.abs(v).max() + 1.0
        np.testing.assert_allclose(hi, v.max(axis=1), atol=1e-9 * scale)
        np.testing.assert_allclose(lo, v.min(axis=1), atol=1e-9 * scale)
        dense, _ = _dense_face(b, np.arange(len(q)), A, g, c, 500, rng)
        assert np.all(dense.max(axis=1) <= hi + 1e-9 * scale)
        assert np.all(dense.min(axis=1) >= lo - 1e-9 * scale)


def test_a_singular_mass_matrix_is_refused_before_a_simulation():
    """The robot of the test above (its M_s numerically singular, by NumPy's pivot ratio there):
    simulate refuses it at once, naming the robot, instead of shrinking its steps forever."""
    robot = snakecg.Robot(joints=1, mass=[1.0, 1e5], length=[1e-3, 1e3], inertia=[1e-9, 1e-9])
    model = snakecg.load(snakecg.Scene(robot))
    q = np.array([0.0, 0.0, 0.0, -3.03774645687452])
    with pytest.raises(snakecg.InputError, match="robot: the mass matrix is numerically"):
        model.simulate(q, [-0.68], 0.01)
    ok = snakecg.load(snakecg.Scene(snakecg.Robot(joints=1)))  # a sound robot still runs
    assert ok.simulate(q, [0.0], 0.01).summary["status"] == "completed"
