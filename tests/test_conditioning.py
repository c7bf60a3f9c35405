"""``ForwardResult.conditioning`` warns before rows become dependent (issue #7)."""

from __future__ import annotations

import numpy as np

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
