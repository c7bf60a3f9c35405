"""Statically indeterminate scenes: a snake whose links all rub the ground with Coulomb
friction, pressed on pegs and pushing two objects, has more held force rows than coordinates
at most torques. The forces are then not fixed by the accelerations; the solve reports the
minimum-norm ones inside the friction and contact sets. Checked against an independent conic
reference (cvxpy with Clarabel) that knows nothing of the solve's faces or null spaces."""
from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.scenes import Ground

from scenes_reference import clarabel_min_norm_forces, dense_problem, indeterminate_scene


GROUNDS = {"coulomb": Ground(model="coulomb", mu=0.3),
           "anisotropic": Ground(model="anisotropic", mu_forward=0.1, mu_backward=0.3,
                                 mu_lateral=0.5)}


@pytest.mark.parametrize("ground", sorted(GROUNDS))
def test_indeterminate_forces_are_the_minimum_norm_ones_inside_the_sets(ground):
    """On the braced 8-joint scene (isotropic or anisotropic Coulomb friction on every link:
    more force rows than its 17 coordinates), most torques leave the held rows dependent.
    The forces are then the minimum-norm ones inside the sets (flag 1) on all but a few
    samples: equal to Clarabel's to 1e-6 of their scale and no larger in norm."""
    joints = 8
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(joints) + 5)]
    model = snakecg.load(indeterminate_scene(q, joints, GROUNDS[ground]))
    T = np.random.default_rng(7).normal(0, 0.1, (60, joints))
    flags, checked = [], 0
    for tau in T:
        res = model.forward(q, tau)
        assert res.status == 0, res.reason
        flags.append(int(res.dependent))
        if res.dependent != 1 or checked == 25:
            continue
        p = dense_problem(res, model, tau)
        lam = res._raw["lam"][0][:len(p["b"])]
        ref, status = clarabel_min_norm_forces(p, lam)
        assert status == "optimal", status
        scale = np.abs(ref).max()
        assert np.abs(lam - ref).max() <= 1e-6 * scale
        assert np.linalg.norm(lam) <= np.linalg.norm(ref) * (1 + 1e-9)
        checked += 1
    flags = np.bincount(flags, minlength=3)
    assert checked == 25
    assert flags[1] + flags[2] >= 40, flags  # (the scene is indeterminate at most torques)
    assert flags[2] <= 3, flags  # (a basic solution kept: the Newton gave up)


def test_indeterminate_forces_are_the_same_in_a_batch_as_alone():
    """The minimum-norm forces are unique, so a batch (whose samples start from their
    neighbours' pieces and may end on another basic solution of a face) reports the forces of
    the one-sample calls to rounding, not merely the same accelerations."""
    joints = 8
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(joints) + 5)]
    model = snakecg.load(indeterminate_scene(q, joints))
    T = np.random.default_rng(8).normal(0, 0.1, (40, joints))
    batch = model.forward(np.repeat(q[None], len(T), axis=0), T)
    for i, tau in enumerate(T):
        one = model.forward(q, tau)
        if one.dependent == 2 or batch.dependent[i] == 2:
            continue
        a, b = one._raw["lam"][0], batch._raw["lam"][i][:len(one._raw["lam"][0])]
        assert np.abs(a - b).max() <= 1e-11 * np.abs(a).max()


@pytest.mark.parametrize("scale", [1e-12, 1e-11, 1e-10])
def test_nearly_dependent_rows_get_the_minimum_norm_forces_too(scale):
    """The 10-joint benchmark scene (pegs pressed at the links' middles: exactly dependent
    rows) with q moved by 1e-12 to 1e-10, so that the rows are that far from dependent: the
    solve takes them as dependent, and the forces are the minimum-norm ones inside the sets
    (flag 1), Clarabel's to 1e-6 of their scale, where the minimum-norm choice moves the
    accelerations by up to 5e-10 of their scale and the KKT conditions still hold (the
    accelerations are then the new forces', a = a_free + M^-1 A^T lam holding to 1e-10).
    Before, 22 of these 30 samples at 1e-11 kept a basic solution of the face (flag 2), its
    forces up to 88 % of their scale away."""
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(10))]
    model = snakecg.load(indeterminate_scene(q))
    T = np.random.default_rng(0).normal(0, 0.1, (30, 10))
    Q = q + scale * np.random.default_rng(2).standard_normal((30, 13))
    res = model.forward(Q, T)
    assert np.all(res.status == 0) and np.sum(res.dependent == 1) >= 25, res.dependent
    assert not np.any(res.dependent == 2), res.dependent
    for i in np.flatnonzero(res.dependent == 1):
        p = dense_problem(res.sample(int(i)), model, T[i])
        lam = res._raw["lam"][i][:len(p["b"])]
        a = np.r_[np.asarray(res.qdd[i]).ravel(), np.asarray(res.a_obj[i]).ravel()]
        a_ref = p["a_free"] + p["Minv"] @ p["A"].T @ lam
        assert np.abs(a - a_ref).max() <= 1e-10 * max(1.0, np.abs(a_ref).max()), i
        ref, status = clarabel_min_norm_forces(p, lam)
        assert status == "optimal", status
        assert np.abs(lam - ref).max() <= 1e-6 * np.abs(ref).max(), i
        assert np.linalg.norm(lam) <= np.linalg.norm(ref) * (1 + 1e-9), i
