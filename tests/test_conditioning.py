"""``ForwardResult.conditioning`` warns before rows become dependent (issue #7)."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg


def test_conditioning_falls_as_two_wheel_rows_become_dependent():
    """Front wheel of link 2 and rear wheel of link 3 sit on joint 2: their lateral rows
    coincide when that joint is straight. The pivot ratio falls as the joint straightens,
    roughly with the square of the angle, and the straight joint is flagged singular."""
    robot = snakecg.Robot(joints=3)
    scene = snakecg.Scene(robot, scenario="ideal_wheels", wheel_offset=(0, 0.075, -0.075, 0))
    model = snakecg.load(scene)
    tau = np.array([0.05, -0.02, 0.01])
    conds = []
    angles = (0.3, 0.03, 0.003)
    for a in angles:
        q = np.array([0.0, 0.0, 0.0, 0.4, a, -0.5])
        res = model.forward(q, tau)
        assert not res.singular
        assert all(np.isfinite(res.lam))
        conds.append(float(res.conditioning))
    assert conds[0] > conds[1] > conds[2] > 0
    # a tenth of the angle: about a hundredth of the pivot ratio (rows differ by O(angle))
    for c0, c1 in zip(conds, conds[1:]):
        assert 0.003 < c1 / c0 < 0.03
    straight = model.forward(np.array([0.0, 0.0, 0.0, 0.4, 0.0, -0.5]), tau)
    assert straight.singular and straight.conditioning == 0.0
    batch = model.forward(np.array([[0.0, 0.0, 0.0, 0.4, a, -0.5] for a in angles]), tau)
    np.testing.assert_allclose(batch.conditioning, conds, rtol=1e-9)


def test_conditioning_of_a_single_contact_row_is_the_mass_matrix_pivot_ratio():
    """One row is independent (pivot ratio 1): the conditioning is then the mass matrix's,
    the smallest Cholesky pivot of the Jacobi-scaled M_s, computed here from the independent
    dense reference."""
    from reference import Reference

    scene = snakecg.Scene(snakecg.Robot(joints=2), scenario="frictionless")
    model = snakecg.load(scene)
    q = np.array([0.0, 0.0, 0.0, -1.0, 1.0])
    res = model.forward(q, np.array([0.05, 0.0]))
    M = Reference(scene).mass_matrix(q)
    d = np.sqrt(np.diag(M))
    expected = np.min(np.diag(np.linalg.cholesky(M / np.outer(d, d)))) ** 2
    assert res.contact and not res.singular
    assert abs(res.conditioning - expected) < 1e-12 * expected
    assert 1e-3 < res.conditioning < 1


def _mp_solve(sys_, held, lam_fixed, digits=50):
    """Accelerations and forces of eqs. (12)-(13) for the held rows, in mpmath at ``digits``
    digits from the reference's dense pieces (no squared-matrix rounding)."""
    import mpmath as mp

    mp.mp.dps = digits
    I = mp.matrix(sys_["I"].tolist())
    A = mp.matrix(sys_["A"].tolist())
    rhs = mp.matrix((sys_["f"] - sys_["p"] + sys_["A"].T @ lam_fixed).tolist())
    Iinv = I ** -1
    H = [i for i in range(A.rows) if held[i]]
    AH = mp.matrix([[A[i, j] for j in range(A.cols)] for i in H])
    G = AH * Iinv * AH.T
    a0 = Iinv * rhs
    bH = AH * a0 + mp.matrix([sys_["Adv"][i] for i in H])
    lamH = -(G ** -1) * bH
    a = a0 + Iinv * AH.T * lamH
    lam = np.array(lam_fixed, dtype=float)
    lam[H] = [float(x) for x in lamH]
    return np.array([float(x) for x in a]), lam


def test_near_dependent_wheel_rows_are_solved_from_the_rows():
    """Two ideal wheels 1e-7 rad from coinciding (3 joints, kappa = 10): the rows are
    independent to 1e-7, so G_c's pivot ratio is ~2e-15. The answer, computed from the rows,
    matches a 50-digit solve of the independent reference's dense system to the stated
    accuracy (1e-16 / conditioning, relative to the whole acceleration, and to 1 for sr), and
    is not flagged."""
    from reference import Reference

    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="ideal_wheels", kappa=10,
                          wheel_offset=(0, 0.075, -0.075, 0))
    model = snakecg.load(scene)
    q = np.array([0.0, 0.0, 0.0, 0.5, 1e-7, -0.8])
    tau = np.array([0.1, -0.05, 0.08])
    ref = Reference(scene)
    sys_ = ref.system(q, tau)
    for res in (model.forward(q, tau), model.forward(q[None], tau[None])):
        res = res if np.ndim(res.sr) == 0 else res[0]
        assert not res.singular
        assert 1e-9 < res.conditioning < 1e-6
        held = np.array([res.contact, False, True, True, True])
        a, lam = _mp_solve(sys_, held, np.zeros(5))
        assert lam[0] >= 0 and res.contact  # the contact is kept in the exact solve too
        ns = ref.ns
        qdd, a_obj = a[:ns], a[ns:]
        acc = 1e-15 / res.conditioning
        assert np.linalg.norm(res.qdd - qdd) <= acc * np.linalg.norm(qdd)
        nq = qdd @ sys_["M"] @ qdd
        na = a_obj @ sys_["I_obj"] @ a_obj
        assert res.norm_qdd == pytest.approx(nq, rel=acc)
        assert res.sr == pytest.approx(na / (na + nq), abs=acc)  # of sr's scale, 1
        assert res.sr == pytest.approx(2.728e-3, rel=1e-3)  # not the zero-angle 7.887e-4


def test_inconsistent_robot_is_flagged_not_answered():
    """Masses 1 and 1e5 kg, lengths 1e-3 and 1e3 m, inertias 1e-9: M_s is numerically
    singular. The cited sample, which gave ||qdd||^2 < 0 and sr = 4.5e307 unflagged, is
    flagged singular with conditioning 0; over random shapes and torques every result is
    either flagged or physically possible (finite, norms >= 0, 0 <= sr <= 1)."""
    robot = snakecg.Robot(joints=1, mass=[1.0, 1e5], length=[1e-3, 1e3], inertia=[1e-9, 1e-9])
    model = snakecg.load(snakecg.Scene(robot))
    res = model.forward([0.0, 0.0, 0.0, -3.03774645687452], [-0.6832544940131859])
    assert res.singular and res.conditioning == 0.0
    rng = np.random.default_rng(12)
    q = np.zeros((400, 4))
    q[:, 3] = rng.uniform(-3.1, 3.1, 400)
    tau = rng.normal(0, 1, (400, 1)) * 10.0 ** rng.uniform(-6, 6, (400, 1))
    for r in (model.forward(q, tau),):
        ok = (np.isfinite(r.norm_qdd) & (r.norm_qdd >= 0) & (r.norm_a_obj >= 0)
              & (r.norm_lambda >= -1e-12 * np.abs(r.norm_lambda)) & (r.sr >= 0) & (r.sr <= 1))
        assert np.all(ok | r.singular)
        assert np.all(r.conditioning[r.singular] == 0.0)
    for i in range(0, 400, 40):  # the one-sample path flags the same way
        one = model.forward(q[i], tau[i])
        phys = one.norm_qdd >= 0 and one.norm_a_obj >= 0 and 0 <= one.sr <= 1
        assert phys or one.singular
