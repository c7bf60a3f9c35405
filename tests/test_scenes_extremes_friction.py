"""Extremes over the input ellipsoid on general scenes with Coulomb friction at the contacts
(``mu_contact``), held against references written apart from the pieces' search:

* every piece of Coulomb's law as affine maps built by a dense NumPy solve of its equations
  (tests/scenes_coulomb_reference.py) on a dense circle of the ellipsoid's boundary (2
  joints), refined near the extremes: the exact extreme is at least every solution's value
  there and reached within the grid's resolution; at the returned torque one of the
  reference's solutions has the value, and the count of distinct solutions (``solutions``)
  is the reference's;
* ``forward`` (the engine's Coulomb solve) on dense samples of the boundary (2 and 3 joints):
  no sample beats an extreme;
* what the dissipation of every force gives on the sampled method: every value in [0, 1].
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import snakecg
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject
from snakecg.scenes import extremes as extremes_module

from scenes_coulomb_reference import Pieces
from scenes_reference import POLYHEDRAL, small_scenes

MUS = (0.2, 0.5, 1.0, 2.0)


def frictional(rng, count, joints):
    """Random small scenes (polyhedral ground, objects and pegs touching links) of ``joints``
    joints, each with a random mu_contact."""
    out = []
    while len(out) < count:
        for model0, q, _ in small_scenes(rng, 4, POLYHEDRAL, object_friction=False):
            if model0.n_joints != joints or len(out) >= count:
                continue
            mu = float(rng.choice(MUS))
            out.append((snakecg.load(dataclasses.replace(model0.scene, mu_contact=mu)), q))
    return out


def _angles(ref, tau):
    s, V = np.linalg.eigh(ref.N)
    u = np.sqrt(s) * (V.T @ tau)
    return float(np.arctan2(u[1], u[0]))


def _circle(ref, th):
    return ref.boundary(np.stack([np.cos(th), np.sin(th)], axis=1))


@pytest.fixture(scope="module")
def two_joint():
    return frictional(np.random.default_rng(0), 12, 2)  # (two with several solutions)


def test_exact_extremes_against_every_piece_on_a_dense_circle(two_joint):
    stats = {"several": 0, "checked": 0}
    for model, q in two_joint:
        ex = model.extremes(q)
        assert ex.method.startswith("exact pieces") and ex.certified, ex.reason
        ref = Pieces(model, q)
        th = np.linspace(0, 2 * np.pi, 12000, endpoint=False)
        coarse = ref.extremes(_circle(ref, th))
        keys = [k for k in coarse if k[1] in ex.max]
        # refined (steps of 2e-6 rad) near every returned torque and every grid's best
        win = np.linspace(-3.2e-4, 3.2e-4, 321)
        centres = [_angles(ref, getattr(ex, "tau_" + attr)[m]) for attr, m in keys] + [
            _angles(ref, coarse[k][1]) for k in keys]
        fine = ref.extremes(_circle(ref, np.concatenate([c + win for c in centres])))
        for attr, m in keys:
            got, tau = getattr(ex, attr)[m], getattr(ex, "tau_" + attr)[m]
            v_ref, v_fine = coarse[(attr, m)][0], fine.get((attr, m), coarse[(attr, m)])[0]
            best = max(v_ref, v_fine) if attr == "max" else min(v_ref, v_fine)
            if attr == "max":  # no solution anywhere beats it, and it is reached
                assert got >= best - 1e-9, (attr, m, got, best)
            else:
                assert got <= best + 1e-9, (attr, m, got, best)
            assert got == pytest.approx(best, abs=2e-5), (attr, m)
            # the value is one of the reference's solutions at the returned torque
            assert tau @ ref.N @ tau == pytest.approx(1.0, rel=1e-9)
            sols = ref.solutions_at(tau)
            assert any(abs(s[1][m] - got) <= 1e-7 for s in sols), (attr, m, got, sols)
            k = ex.solutions[attr][m]
            if ref.singular == 0:
                assert k == len(sols), (attr, m, k, len(sols))
            stats["several"] += abs(k) >= 2
            stats["checked"] += 1
        if any(abs(k) >= 2 or k < 0 for d in ex.solutions.values() for k in d.values()):
            assert "several solutions" in ex.uniqueness
        else:
            assert ex.uniqueness == ""
    print(stats)
    assert stats["checked"] >= 100 and stats["several"] >= 1, stats


@pytest.mark.parametrize("joints", [2, 3])
def test_no_forward_sample_beats_an_extreme(joints):
    rng = np.random.default_rng(100 + joints)
    for model, q in frictional(rng, 5, joints):
        ex = model.extremes(q)
        assert ex.certified, ex.reason
        M = model.mass_matrix(q)
        N = np.linalg.inv(M)[3:, 3:]
        t = rng.normal(size=(4000, joints))
        t /= np.sqrt(np.einsum("ki,ij,kj->k", t, N, t))[:, None]
        res = model.forward(np.repeat(q[None], len(t), axis=0), t)
        ok = res.status == 0
        assert ok.mean() > 0.95
        still = res.norm_a_obj + res.norm_qdd < 1e-12
        vals = {"norm_a_obj": res.norm_a_obj, "norm_qdd": res.norm_qdd,
                "norm_lambda": res.norm_lambda, "sr": np.where(still, 0.0, res.sr)}
        for m, v in vals.items():
            assert v[ok].max() <= ex.max[m] + 1e-9, m
            assert v[ok].min() >= ex.min[m] - 1e-9, m


def _box_on_wall_scene(ground, mu=0.5):
    """A 2-joint snake whose first link presses a box on a wall."""
    robot = snakecg.Robot(joints=2)
    box = SceneObject(shape="box", size=(0.06, 0.04), mass=1.0,
                      touching={"link": 2, "offset": 0.05, "side": "left"})
    m0 = snakecg.load(GeneralScene(robot, ground=ground, objects=(box,)))
    pose = m0.object_poses(np.zeros(5))[0]
    wall = Obstacle(shape="wall", point=(0.0, pose[1] + 0.02), normal=(0.0, -1.0))
    return GeneralScene(robot, ground=ground, objects=(box,), obstacles=(wall,),
                        mu_contact=mu)


def test_coulomb_ground_with_contact_friction_is_sampled_and_says_so():
    """No Lipschitz bound without Gauss's principle: the values are attained by the forward
    solve at their torques, not certified, and the bounds are 1 and 0 (every force
    dissipates, so |a|_M <= |a_free|_M = 1 for every solution)."""
    model = snakecg.load(_box_on_wall_scene(Ground(model="coulomb", mu=0.05)))
    q = np.zeros(5)
    res = model.forward(q, np.zeros(2))
    assert len(res.contacts) >= 2 and any(c["mu"] > 0 for c in res.contacts)
    ex = model.extremes(q, budget=2000)
    assert ex.method.startswith("sampled, not certified: contact friction on Coulomb")
    with pytest.raises(InputError, match=r"exact=True needs every block to be a 1-D set .* "
                                         r"use exact=None for sampled values"):
        model.extremes(q, exact=True)
    assert not ex.certified and "not certified" in ex.reason and ex.samples == 2000
    for m in ("norm_a_obj", "norm_qdd", "norm_lambda", "sr"):
        assert ex.bound_max[m] == 1.0 and ex.bound_min[m] == 0.0
        assert 0.0 <= ex.min[m] <= ex.max[m] <= 1.0 + 1e-9
        r = model.forward(q, ex.tau_max[m])
        got = {"norm_a_obj": r.norm_a_obj, "norm_qdd": r.norm_qdd,
               "norm_lambda": r.norm_lambda, "sr": r.sr}[m]
        assert got == pytest.approx(ex.max[m], abs=1e-12)


def test_more_pieces_than_the_cap_fall_back_to_sampling(monkeypatch):
    model, q = frictional(np.random.default_rng(5), 1, 2)[0]
    exact = model.extremes(q)
    monkeypatch.setattr(extremes_module, "MAX_STATES", 2)
    ex = model.extremes(q, budget=3000)
    assert ex.method.startswith("sampled, not certified: contact friction and")
    assert "(more than 2)" in ex.method and not ex.certified
    for m in ("norm_a_obj", "norm_qdd", "norm_lambda", "sr"):  # the samples stay inside
        assert ex.max[m] <= exact.max[m] + 1e-9 and ex.min[m] >= exact.min[m] - 1e-9
    with pytest.raises(InputError, match=r"exact: \d+ states at this configuration \(more "
                                         r"than 2\); use exact=None for sampled values "
                                         r"\(with contact friction they are not certified\)"):
        model.extremes(q, exact=True)


def test_a_batch_with_contact_friction_stacks_the_counts():
    model, q = frictional(np.random.default_rng(9), 1, 2)[0]
    one = model.extremes(q)
    both = model.extremes(np.stack([q, q]))
    for attr in ("max", "min", "min_kept"):
        for m, k in one.solutions[attr].items():
            assert list(both.solutions[attr][m]) == [k, k]
            assert np.allclose(getattr(both, attr)[m], getattr(one, attr)[m], equal_nan=True)
    assert list(both.uniqueness) == [one.uniqueness] * 2
