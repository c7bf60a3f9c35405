"""Friction that holds every torque of a region still (snakecg.scenes.friction_hold) and what
optimize and extremes answer there: the test against Clarabel on the balance the rows define
(the least fraction of the friction sets that balances a torque with nothing moving, contacts
pushing or not), and every answer against dense forward samples of the region (no sample
beats an 'optimal' answer; nothing moves where the region is said to be held)."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from scenes_reference import SCENE, Balance

import snakecg
from snakecg import Robot
from snakecg.scenes import GeneralScene, Ground, SceneObject
from snakecg.scenes.friction_hold import friction_holds
from snakecg.scenes.maps import scene_problem
from snakecg.scenes.toml_reading import read_scene

pytest.importorskip("cvxpy")  # (scenes_reference.Balance: Clarabel)

Q = np.array([0.0, 0.0, 0.0, 0.3, -0.3, 0.2])


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("hold") / "s.toml"
    path.write_text(SCENE)
    return path


@pytest.fixture(scope="module")
def model(scene_file):
    return snakecg.load(read_scene(scene_file))


def inside(rng, model, q, count, radius=None, tau_max=None):
    """``count`` torques of the region (ellipsoid and/or box): a quarter on its boundary,
    the rest spread through it."""
    na = model.n_joints
    N = np.linalg.inv(model.mass_matrix(q))[3:, 3:]
    t = rng.normal(size=(count, na))
    if radius is not None:
        t *= radius / np.sqrt(np.einsum("ki,ij,kj->k", t, N, t))[:, None]
    else:
        t = rng.uniform(-1, 1, (count, na)) * tau_max
        t[: count // 4] = np.sign(t[: count // 4]) * tau_max
    if radius is not None and tau_max is not None:
        t *= np.minimum(1.0, np.min(tau_max / np.abs(t), axis=1))[:, None]
    scale = np.ones(count)
    scale[count // 4:] = rng.uniform(0, 1, count - count // 4) ** (1 / na)
    return t * scale[:, None], N


def forward_samples(model, q, taus):
    res = model.forward(np.repeat(q[None], len(taus), axis=0), taus)
    assert np.all(res.status == 0)
    return res


@pytest.mark.parametrize("region", [dict(radius=1.0), dict(tau_max=0.01)])
def test_reproducer_friction_holds_the_region(model, scene_file, region, rng):
    """The defect's scene: every torque of the region sticks. max_sr is optimal with sr = 0
    (it was 'failed', a piece claiming 0.936 where nothing moves), strongest_push optimal
    with 0, least_slip_push infeasible; Clarabel's balance holds every sampled torque and
    the box's vertices; dense forward samples never beat the answers."""
    radius, tau_max = region.get("radius"), region.get("tau_max")
    tm = None if tau_max is None else np.full(3, tau_max)
    r = model.optimize(Q, "max_sr", **region)
    assert r.status == "optimal", r.reason
    assert r.objective_value == 0.0
    assert "friction holds every torque of the region" in r.reason
    N = np.linalg.inv(model.mass_matrix(Q))[3:, 3:]
    if radius is not None:
        assert r.tau @ N @ r.tau <= radius ** 2 * (1 + 1e-9)
    else:
        assert np.all(np.abs(r.tau) <= tau_max * (1 + 1e-12))
    assert all(g["state"] == "stick" for g in r.analysis.ground)
    s = model.optimize(Q, "strongest_push", direction=[0, 1], **region)
    assert s.status == "optimal" and abs(s.objective_value) <= 1e-12
    lp = model.optimize(Q, "least_slip_push", direction=[0, 1], a_min=1e-3, **region)
    assert lp.status == "infeasible" and "friction holds" in lp.reason
    # the reference: the least fraction of the sets that balances each torque
    bal = Balance(model, Q)
    hold = friction_holds(scene_problem(model, Q), radius, tm)
    if tm is not None:
        vertices = np.array(np.meshgrid(*[[-1.0, 1.0]] * 3)).reshape(3, -1).T * tm
        need = bal(vertices)  # a convex need: the box is held where its vertices are
        assert need.max() <= 1.0
    else:
        taus, _ = inside(rng, model, Q, 120, radius=radius)
        need = bal(taus[:30])  # on the boundary
        assert need.max() <= 1.0
    assert need.max() <= hold.fraction + 1e-7  # the test's fraction bounds the need
    assert hold.fraction <= 1.25 * need.max()  # and is not far from it here
    # dense forward samples: nothing moves anywhere in the region
    taus, _ = inside(rng, model, Q, 4000, radius=radius, tau_max=tm)
    res = forward_samples(model, Q, taus)
    assert (res.norm_a_obj + res.norm_qdd).max() <= 1e-20
    assert res.sr.max() <= r.objective_value
    assert (res.a_obj[:, 0] @ np.array([0.0, 1.0, 0.0])).max() <= s.objective_value + 1e-12


def test_command_line_reproducer(scene_file):
    out = subprocess.run([sys.executable, "-m", "snakecg.cli", "optimize", "max_sr", "--scene",
                          str(scene_file), "--q", "0,0,0,0.3,-0.3,0.2", "--json"],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    import json
    d = json.loads(out.stdout)
    assert d["status"] == "optimal" and d["objective_value"] == 0.0


def test_larger_regions_slide_and_are_not_claimed(model, rng):
    """Radius 3: some torque of the region needs more than a set (Clarabel finds one), so
    the region is not said held. With every link sticking nothing moves: max_sr says so
    ('infeasible', where a piece of rounding errors once claimed sr 0.936), and every dense
    sample that sticks has sr = 0; with sliding allowed the search's answer is the forward
    solve's own value."""
    p = scene_problem(model, Q)
    hold = friction_holds(p, 3.0)
    assert not hold.holds
    taus, _ = inside(rng, model, Q, 60, radius=3.0)
    assert Balance(model, Q)(taus[:15]).max() > 1.0
    stuck = model.optimize(Q, "max_sr", radius=3.0, allow_slide=False)
    assert stuck.status == "infeasible" and "nothing moves" in stuck.reason
    res = forward_samples(model, Q, inside(rng, model, Q, 3000, radius=3.0)[0])
    stick = np.array([all(g["state"] == "stick" for g in gr) for gr in res.ground])
    assert stick.any() and not stick.all()
    assert (res.norm_a_obj + res.norm_qdd)[stick].max() <= 1e-20
    slid = model.optimize(Q, "max_sr", radius=3.0)
    assert slid.status == "local"
    assert slid.objective_value == pytest.approx(float(slid.analysis.sr), abs=0)
    assert slid.objective_value > 0.5


def test_extremes_where_friction_holds(model, rng):
    """The unit ellipsoid is held: every norm is exactly 0 and norm_lambda 1 (certified, no
    branch and bound), against dense forward samples of the boundary."""
    ex = model.extremes(Q)
    assert ex.method.startswith("friction holds") and ex.certified
    assert ex.samples <= 15
    for m in ("norm_a_obj", "norm_qdd", "sr", "norm_a_obj[1]"):
        assert ex.max[m] == ex.min[m] == ex.bound_max[m] == 0.0
    assert ex.max["norm_lambda"] == ex.min["norm_lambda"] == 1.0
    taus, _ = inside(rng, model, Q, 3000, radius=1.0)
    res = forward_samples(model, Q, taus[:750])  # the boundary
    assert (res.norm_a_obj + res.norm_qdd).max() <= 1e-20
    assert np.abs(res.norm_lambda - 1.0).max() <= 1e-9


def random_locking_scene(rng):
    """A 2-3 joint snake on Coulomb or anisotropic ground (per link), a box touching a link,
    a random bent configuration."""
    na = int(rng.integers(2, 4))
    robot = Robot(joints=na, mass=list(rng.uniform(0.5, 2.0, na + 1)),
                  length=list(rng.uniform(0.1, 0.2, na + 1)),
                  inertia=list(rng.uniform(0.001, 0.004, na + 1)))
    ground = tuple(Ground(model=str(rng.choice(["coulomb", "anisotropic"])),
                          mu=float(rng.uniform(0.05, 0.6)),
                          mu_forward=float(rng.uniform(0.05, 0.5)),
                          mu_backward=float(rng.uniform(0.05, 0.5)),
                          mu_lateral=float(rng.uniform(0.05, 0.8))) for _ in range(na + 1))
    box = SceneObject(shape="box", size=(0.06, 0.06), mass=float(rng.uniform(0.5, 20)),
                      touching={"link": int(rng.integers(1, na + 2)), "offset": 0.05,
                                "side": str(rng.choice(["left", "right"]))})
    q = np.r_[0.0, 0.0, 0.0, rng.choice([-1, 1], na) * rng.uniform(0.2, 1.0, na)]
    return snakecg.load(GeneralScene(robot, ground=ground, objects=(box,))), q


def test_holds_against_clarabel_on_random_scenes(rng):
    """On random locking scenes and regions: the test's fraction bounds Clarabel's least
    fraction at every sampled torque (so a region with a sampled need above 1 is never said
    held), and where it says held, dense forward samples move nothing."""
    held = not_held = 0
    for _ in range(8):
        model, q = random_locking_scene(rng)
        p = scene_problem(model, q)
        bal = Balance(model, q)
        na = model.n_joints
        for region in (dict(radius=float(rng.choice([0.3, 1.0, 3.0]))),
                       dict(tau_max=float(rng.choice([0.005, 0.02, 0.1])))):
            tm = None if "tau_max" not in region else np.full(na, region["tau_max"])
            hold = friction_holds(p, region.get("radius"), tm)
            taus, _ = inside(rng, model, q, 200, radius=region.get("radius"), tau_max=tm)
            need = bal(taus[:40])
            assert np.isfinite(hold.fraction)
            assert need.max() <= hold.fraction + 1e-7
            if need.max() > 1.0:
                assert not hold.holds
            if hold.holds:
                held += 1
                res = forward_samples(model, q, taus)
                assert (res.norm_a_obj + res.norm_qdd).max() <= 1e-18 * max(
                    1.0, float(np.abs(taus).max()) ** 2)
                r = model.optimize(q, "max_sr", **region)
                assert r.status == "optimal" and r.objective_value == 0.0
            else:
                not_held += 1
    assert held >= 3 and not_held >= 3
