"""The general scenes' exact solve, against independent references: the paper's three
scenarios through today's path (1e-12), a dense NumPy model of the KKT conditions, brute-force
enumeration of the polyhedral pieces, and Clarabel on the conic (Coulomb) problems."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg import Robot, Scene
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject, load_scene
from snakecg.scenes.solve import BOX, DISC, FREE, UNILATERAL

from overlap_reference import crossing_depth, link_ends
from scenes_reference import (ALL_MODELS, POLYHEDRAL, approximate_accelerations,
                              clarabel_accelerations, clarabel_min_norm_forces, dense_problem,
                              enumerate_pieces, enumerate_polyhedral, kkt_violations,
                              peg_obstacles, random_scene)


@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
@pytest.mark.parametrize("joints", [1, 2, 3])
def test_paper_scenarios_through_the_general_path(scenario, joints, rng):
    scene = Scene(Robot(joints=joints), scenario=scenario, kappa=float(rng.uniform(1, 200)),
                  mu=0.1, contact_link=int(rng.integers(1, joints + 2)))
    old, new = snakecg.load(scene), load_scene(scene)
    q = np.c_[rng.normal(size=(40, 3)), rng.uniform(-0.8, 0.8, (40, joints))]
    tau = rng.normal(size=(40, joints))
    o = old.forward(q, tau)
    r = new.forward(q, tau)
    assert np.all(r.status == 0)
    for name, got, want in (("qdd", r.qdd, o.qdd), ("a_obj", r.a_obj[:, 0], o.a_obj)):
        scale = np.abs(want).max(axis=1, keepdims=True)
        assert np.abs(got - want).max() <= 1e-12 * scale.max(), name
    for name in ("norm_qdd", "norm_a_obj", "norm_lambda"):
        got, want = getattr(r, name), getattr(o, name)
        assert np.all(np.abs(got - want) <= 1e-12 * np.maximum(np.abs(want), 1e-300) +
                      1e-12 * np.abs(o.norm_qdd)), name
    assert np.abs(r.sr - o.sr).max() <= 1e-12
    # the contact force and every wheel's lateral force
    for s in range(40):
        lam = r._raw["lam"][s]
        rows = r._rows[s]
        for (kind, st, par), label in zip(zip(rows.kind, rows.start, rows.par), rows.labels):
            want = o.lam[s, 0] if label[0] == "contact" else o.lam[s, label[1] + 1]
            assert abs(lam[st] - want) <= 1e-11 * max(1.0, np.abs(o.lam[s]).max())


@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
def test_paper_scenarios_one_sample_at_a_time(scenario, rng):
    """The general path's one-sample forward (its own buffers, straight to the engine) on the
    paper's scene against the paper's own closed-form path, sample by sample at random
    configurations and torques, to 1e-12; the same numbers as the general path's batch."""
    scene = Scene(Robot(joints=3), scenario=scenario, kappa=float(rng.uniform(1, 200)),
                  mu=0.1, contact_link=int(rng.integers(1, 5)))
    old, new = snakecg.load(scene), load_scene(scene)
    Q = np.c_[rng.normal(size=(25, 3)), rng.uniform(-0.8, 0.8, (25, 3))]
    T = rng.normal(size=(25, 3))
    batch = new.forward(Q, T)
    for s, (q, tau) in enumerate(zip(Q, T)):
        o, r = old.forward(q, tau), new.forward(q, tau)
        assert not r.batched and r.status == 0, r.reason
        for got, want in ((r.qdd, o.qdd), (r.a_obj[0], o.a_obj)):
            assert np.abs(got - want).max() <= 1e-12 * max(1.0, np.abs(want).max())
        for name in ("norm_qdd", "norm_a_obj", "norm_lambda"):
            got, want = getattr(r, name), getattr(o, name)
            assert abs(got - want) <= 1e-12 * max(abs(want), abs(o.norm_qdd), 1e-300), name
        assert abs(r.sr - o.sr) <= 1e-12 and 0.0 <= r.sr <= 1.0
        # the batch's solves start from the last sample's pieces, the one-sample call's
        # cold: the same piece solved from another start, equal to rounding
        scale = max(1.0, np.abs(r.qdd).max())
        np.testing.assert_allclose(batch.qdd[s], r.qdd, rtol=0, atol=1e-12 * scale)
        assert abs(r.sr - batch.sr[s]) <= 1e-12
        assert batch.norm_lambda[s] == pytest.approx(r.norm_lambda, rel=1e-10,
                                                      abs=1e-14 * r.norm_qdd)


def _solved(rng, models, tries=50):
    """A random solved one-sample problem (resampled on overlap, or without 1-6 contacts)."""
    for _ in range(tries):
        robot, ground, objects, pegs, q, tau = random_scene(rng, models)
        base = GeneralScene(robot, ground=ground, objects=objects)
        try:
            m0 = snakecg.load(base)
            scene = GeneralScene(robot, ground=ground, objects=objects,
                                 obstacles=peg_obstacles(m0, pegs, q))
            model = snakecg.load(scene)
            res = model.forward(q, tau)
        except InputError:
            continue
        if 1 <= len(res.contacts) <= 6:
            return model, res, q, tau
    raise AssertionError("no random scene without overlap")


def test_kkt_conditions_with_a_dense_model(rng):
    for _ in range(60):
        model, res, q, tau = _solved(rng, ALL_MODELS)
        assert res.status == 0, res.reason
        p = dense_problem(res, model, tau)
        a = np.r_[res.qdd, np.ravel(res.a_obj)]
        assert kkt_violations(p, res._raw["lam"][0][:len(p["b"])], a) == []
        for k in ("primal", "dual", "complementarity"):
            assert res.certificate[k] <= 1e-9
        assert res.norm_qdd >= 0 and res.norm_a_obj >= 0 and 0 <= res.sr <= 1


def test_minimum_norm_forces_against_clarabel(rng):
    """Where the held rows are dependent and the flag says the forces are minimum-norm (1),
    they are: against the minimum-norm forces over every force that gives the same
    accelerations, within the sets (Clarabel), to 1e-6 of their scale."""
    checked = 0
    for _ in range(400):
        model, res, q, tau = _solved(rng, ALL_MODELS)
        if res.dependent != 1:
            continue
        p = dense_problem(res, model, tau)
        lam = res._raw["lam"][0][:len(p["b"])]
        ref, status = clarabel_min_norm_forces(p, lam)
        assert status == "optimal"
        assert np.linalg.norm(lam) <= np.linalg.norm(ref) * (1 + 1e-6) + 1e-9
        assert np.abs(lam - ref).max() <= 1e-6 * max(1.0, np.abs(ref).max())
        checked += 1
        if checked == 10:
            break
    assert checked >= 3


def _enumeration_study(rng, count, models=POLYHEDRAL):
    """Mismatches between the compiled solve and brute-force enumeration: no valid piece
    found, or accelerations apart by more than 1e-10 (relative), widened only to what double
    precision resolves on the held rows (the valid piece's, the solve's), 50 eps cond(G_HH) (on
    its range: nearly dependent rows carry forces of 1e4 N that cancel, known to 1e-8 by any
    method). Returns
    the mismatches and how many samples needed the wider tolerance. Polyhedral scenes are
    enumerated over every piece; with friction discs and ellipses, over the pieces of the
    blocks that Clarabel's solution leaves ambiguous (enumerate_pieces)."""
    mismatches, widened = [], 0
    for i in range(count):
        model, res, q, tau = _solved(rng, models)
        p = dense_problem(res, model, tau)
        if set(models) <= set(POLYHEDRAL):
            ref, held = enumerate_polyhedral(p)
        else:
            ref, held = enumerate_pieces(p, approximate_accelerations(p))
        a = np.r_[res.qdd, np.ravel(res.a_obj)]
        cond = 1.0
        mine = [s + i for (kind, s, _), st in zip(p["blocks"], res._raw["state"][0])
                if st == 0 for i in range(2 if kind >= DISC else 1)]  # the solve's held rows
        for rows in (held, mine):
            if rows:
                ev = np.linalg.eigvalsh(p["G"][np.ix_(rows, rows)])
                ev = ev[ev > 1e-13 * ev.max()]  # on its range (exactly dependent: a null space)
                cond = max(cond, ev.max() / ev.min())
        tol = max(1e-10, 50 * np.finfo(float).eps * cond)
        widened += tol > 1e-10
        if ref is None or res.status != 0 or not np.abs(a - ref).max() <= tol * max(
                1.0, np.abs(ref).max()):
            mismatches.append((i, q.tolist(), None if ref is None else
                               float(np.abs(a - ref).max()), cond))
    return mismatches, widened


def test_active_set_against_enumeration(rng):
    mismatches, widened = _enumeration_study(rng, 150)
    assert mismatches == [] and widened <= 5


@pytest.mark.slow
def test_active_set_against_enumeration_study(rng):
    mismatches, widened = _enumeration_study(rng, 10_000)
    print(f"10^4 scenes: {len(mismatches)} mismatches, {widened} on ill-conditioned rows")
    assert mismatches == [] and widened <= 100


def test_every_ground_model_against_enumeration(rng):
    """Coulomb discs, split ellipses, bounded and ideal wheels and contacts: the compiled
    solve's accelerations against the exact pieces enumerated in NumPy (the primal solved on
    each assignment, its KKT conditions checked), 1e-10."""
    mismatches, widened = _enumeration_study(rng, 120, ALL_MODELS)
    assert mismatches == [] and widened <= 5


@pytest.mark.slow
def test_every_ground_model_against_enumeration_study(rng):
    mismatches, widened = _enumeration_study(rng, 10_000, ALL_MODELS)
    print(f"10^4 scenes, every ground model: {len(mismatches)} mismatches, {widened} on "
          "ill-conditioned rows")
    assert mismatches == [] and widened <= 100


def test_conic_problems_against_clarabel(rng):
    worst = 0.0
    for _ in range(25):
        model, res, q, tau = _solved(rng, ("coulomb", "anisotropic", "frictionless"))
        p = dense_problem(res, model, tau)
        ref, status = clarabel_accelerations(p)
        assert status == "optimal"
        a = np.r_[res.qdd, np.ravel(res.a_obj)]
        err = np.abs(a - ref).max() / max(1.0, np.abs(ref).max())
        worst = max(worst, err)
    assert worst <= 1e-6


def test_torques_far_below_the_friction_sets_against_clarabel(rng):
    """A torque 1e-10 of a random scene's: every force is far inside its friction set, so
    every set sticks and the answer is Clarabel's on the dense problem with each friction
    block an equality (its rows do not accelerate), contacts unilateral. The solve's
    acceptance was relative to the sets' sizes: there every piece met it, and most answers
    were wrong by their whole size (contacts held that part, sr off by 0.03-0.3)."""
    s, worst, checked = 1e-10, 0.0, 0
    for _ in range(40):
        model, res, q, tau = _solved(rng, ALL_MODELS)
        tiny = model.forward(q, s * np.asarray(tau))
        assert tiny.status == 0, tiny.reason
        p = dense_problem(tiny, model, s * np.asarray(tau))
        stuck = []
        for kind, r, par in p["blocks"]:
            size = 1 if kind in (UNILATERAL, FREE, BOX) else 2
            sticks = kind not in (UNILATERAL, FREE) and max(par) > 0
            stuck += [(FREE, r + i, par) for i in range(size)] if sticks else [(kind, r, par)]
        # (a cone now: scaled back up, within Clarabel's absolute tolerances)
        up = dict(p, blocks=stuck, a_free=p["a_free"] / s, f=p["f"] / s)
        ref, status = clarabel_accelerations(up)
        assert status == "optimal"
        a = np.r_[tiny.qdd, np.ravel(tiny.a_obj)] / s
        if np.abs(ref).max() < 1e-6 * np.abs(up["a_free"]).max():
            continue  # (nothing moves: the sets lock the snake)
        checked += 1
        worst = max(worst, np.abs(a - ref).max() / np.abs(ref).max())
    assert checked >= 20 and worst <= 1e-6, (checked, worst)


def test_point_jacobians_against_finite_differences(rng):
    """A contact row is n . (v_B - v_A) at the surface points fixed on their bodies: checked
    against the points moved by a small step of q (central differences)."""
    from snakecg.scenes.contacts import link_ends

    model, res, q, tau = _solved(rng, ("frictionless",))
    rows = res._rows[0]
    v = rng.normal(size=model.n_coordinates)
    h = 1e-6
    ends0 = link_ends(model.scene, model.link_poses(q))
    for c in rows.contacts:
        if c.a[0] != "link" or c.b[0] != "obstacle":
            continue
        i = c.a[1]
        a0, a1 = ends0[i]
        s = (c.point_a - a0) @ (a1 - a0) / ((a1 - a0) @ (a1 - a0))
        perp = (c.point_a - (a0 + s * (a1 - a0)))

        def point(qq):
            e0, e1 = link_ends(model.scene, model.link_poses(qq))[i]
            t = (e1 - e0) / np.hypot(*(e1 - e0))
            return e0 + s * (e1 - e0) + np.array([[t[0], -t[1]], [t[1], t[0]]]) @ (
                np.array([[t[0], t[1]], [-t[1], t[0]]]) @ perp)

        vel = (point(q + h * v) - point(q - h * v)) / (2 * h)
        row = rows.A[c.row][:model.n_coordinates]
        assert abs(row @ v - c.normal @ (-vel)) <= 1e-6 * max(1.0, np.abs(vel).max())


def test_dependent_rows_are_flagged_with_minimum_norm_forces():
    """A link pressed on two pegs at one place: the rows are equal (statically
    indeterminate); the forces are split evenly (minimum norm) and the flag says so. The
    reference: the same scene with one peg carries their sum."""
    robot = Robot(joints=1)
    q = np.array([0.0, 0.0, 0.0, 0.3])
    m0 = snakecg.load(GeneralScene(robot))
    x, y, phi = m0.link_poses(q)[0]
    c = (x - 0.02 * np.sin(phi) * 0 + 0.0, y + 0.03)  # a peg above link 1's COM
    peg = Obstacle(shape="peg", center=(float(x), float(y) + 0.03), radius=0.03)
    one = snakecg.load(GeneralScene(robot, obstacles=(peg,))).forward(q, [1.0])
    two = snakecg.load(GeneralScene(robot, obstacles=(peg, peg))).forward(q, [1.0])
    assert len(two.contacts) == 2 and one.contacts[0]["force"] > 0
    assert two.dependent == 1
    f1, f2 = (cc["force"] for cc in two.contacts)
    assert f1 == pytest.approx(f2, rel=1e-12)
    assert f1 + f2 == pytest.approx(one.contacts[0]["force"], rel=1e-12)
    assert np.allclose(two.qdd, one.qdd, rtol=1e-12, atol=1e-12)
    del c


def test_overlap_is_refused_naming_the_bodies_and_depth():
    robot = Robot(joints=1)
    peg = Obstacle(shape="peg", center=(0.0, 0.01), radius=0.03)
    model = snakecg.load(GeneralScene(robot, obstacles=(peg,)))
    with pytest.raises(InputError, match=r"link 1 and obstacle 1 overlap by 0\.02 m"):
        model.forward([0.0, 0.0, 0.0, 0.0], [0.0])
    res = model.forward([[0.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]], [0.0])
    assert res.status.tolist() == [3, 0] and np.isnan(res.sr[0]) and "overlap" in res.reason[0]


def test_other_queries_are_refused_with_one_line():
    model = snakecg.load(GeneralScene(Robot(joints=1)))
    with pytest.raises(InputError, match="optimize_shape is not available on a general scene"):
        model.optimize_shape()


def test_scene_solve_is_strict_c99(tmp_path):
    """The general-scene solve's engine files compile with strict flags (warnings are errors)
    against a real model's layout and the one header."""
    import shutil
    import subprocess

    from snakecg.artifacts import model_dir
    from snakecg.engine.layout import header
    from snakecg.native import ENGINE_DIR

    _, manifest = model_dir(1)
    (tmp_path / "snakecg_layout.h").write_text(header(manifest))
    cc = shutil.which("cc") or shutil.which("gcc")
    for name in ("scene_sets.c", "scene_min_norm.c", "scene_piece.c", "scene_solve.c",
                 "scene_family.c", "scene_friction.c"):
        res = subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", "-O2",
                              "-fPIC", "-I", str(tmp_path), "-I", str(ENGINE_DIR), "-c",
                              str(ENGINE_DIR / name), "-o", str(tmp_path / "s.o")],
                             capture_output=True, text=True, timeout=600)
        assert res.returncode == 0, res.stderr[-3000:]


def test_object_on_object_and_self_contact():
    """A disc pushed by link 1 presses a second disc (placed by its pose against the first),
    which rests on a wall: every contact found, the KKT conditions hold in the dense model and
    the chain's force is equal along it (no friction, no other load on the discs). Links
    folded onto each other are refused by name."""
    robot = Robot(joints=2)
    base = snakecg.load(robot)
    q = np.array([0.0, 0.0, 0.0, 0.4, -0.3])
    x, y, phi = base.link_poses(q)[0]
    d1 = SceneObject(shape="disc", radius=0.03, mass=1.0,
                     touching={"link": 1, "offset": 0.075, "side": "left"})
    c1 = np.array([x, y]) + 0.03 * np.array([-np.sin(phi), np.cos(phi)])
    c2 = c1 + 0.07 * np.array([-np.sin(phi), np.cos(phi)])
    d2 = SceneObject(shape="disc", radius=0.04, mass=2.0, pose=(float(c2[0]), float(c2[1]), 0.0))
    wall = Obstacle(shape="wall", point=(0.0, float(c2[1]) + 0.04), normal=(0.0, -1.0))
    scene = GeneralScene(robot, objects=(d1, d2), obstacles=(wall,))
    model = snakecg.load(scene)
    res = model.forward(q, [0.0, 0.0], f_obj=[[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    pairs = {tuple(c["bodies"]) for c in res.contacts}
    assert pairs == {("link 1", "object 1"), ("object 1", "object 2"),
                     ("object 2", "obstacle 1")}
    # a force F on disc 1 toward disc 2 and the wall: static equilibrium (a physical law)
    # carries F along the chain, the link's contact opens and nothing accelerates
    n = np.array([-np.sin(phi), np.cos(phi)])
    F = 3.0
    f_obj = [[F * n[0], F * n[1], 0.0], [0.0, 0.0, 0.0]]
    res = model.forward(q, [0.0, 0.0], f_obj=f_obj)
    forces = {tuple(c["bodies"]): c["force"] for c in res.contacts}
    assert abs(forces[("link 1", "object 1")]) <= 1e-15 * F  # (zero to rounding: the piece
    # holds it at a force the solve's rounding leaves as 0 or an ulp of the chain's)
    assert forces[("object 1", "object 2")] == pytest.approx(F, rel=1e-12)
    assert forces[("object 2", "obstacle 1")] == pytest.approx(F, rel=1e-12)  # n = (0, 1)
    assert np.abs(res.a_obj).max() <= 1e-12 * F
    p = dense_problem(res, model, [0.0, 0.0], f_obj)
    assert kkt_violations(p, res._raw["lam"][0][:len(p["b"])],
                          np.r_[res.qdd, np.ravel(res.a_obj)]) == []
    folded = GeneralScene(robot, radius=0.02)
    with pytest.raises(InputError, match=r"link 1 and link 3 overlap"):
        snakecg.load(folded).forward([0.0, 0.0, 0.0, 2.9, 2.9], [0.0, 0.0])


def test_a_wheel_without_friction_is_a_frictionless_ground(rng):
    """A bounded wheel of mu = 0 holds no force: the accelerations are the frictionless
    ground's, every sample solved (its zero set's normal cone is every row acceleration; the
    certificate used to count a negative one as a dual residual and report no convergence).
    A sample whose first and last links cross (the independent NumPy crossing) overlaps
    (status 3) in both."""
    wheels = load_scene(GeneralScene(Robot(joints=2), ground=Ground(model="wheels", mu=0.0)))
    free = load_scene(GeneralScene(Robot(joints=2), ground=Ground(model="frictionless")))
    q, tau = rng.normal(size=(30, 5)), rng.normal(size=(30, 2))
    a, b = wheels.forward(q, tau), free.forward(q, tau)
    ok = a.status == 0
    rear, front = link_ends(wheels.scene.robot, q)
    crossing = crossing_depth(rear[:, 0], front[:, 0], rear[:, 2], front[:, 2]) > 0
    assert np.array_equal(~ok, crossing) and ok.sum() >= 25
    assert np.array_equal(a.status, b.status) and np.all(a.status[~ok] == 3)
    np.testing.assert_allclose(a.qdd[ok], b.qdd[ok], rtol=0,
                               atol=1e-12 * np.abs(b.qdd[ok]).max())
