"""The engine's contacts, rows and metrics of a general scene (snakecg/engine/scene_geometry.c,
scene_rows.c) against references written apart: the closest points and rows built per sample
in Python (tests/scenes_rows_reference.py, plain NumPy on the generated link poses and
Jacobians), the metrics from a dense NumPy model of the same problem (eqs. 26, 27, 30)."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg import Robot
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject
from snakecg.scenes.contacts import StateRows, link_ends

from scene_rows_equal import rows_equal
from scenes_reference import ALL_MODELS, dense_problem, peg_obstacles, random_scene
from scenes_rows_reference import pair_gaps, place_objects, rows_of


def _reference(model, q):
    """The reference's rows (and objects' poses) at q, or the InputError it raises."""
    try:
        return rows_of(model.scene, model.masses, model.link_poses(q), model.link_jacobians(q))
    except InputError as exc:
        return exc


def _same_rows(ref, got, scale):
    assert got.kind == ref.kind and got.start == ref.start and got.labels == ref.labels
    np.testing.assert_allclose(np.array(got.par, float).reshape(-1, 3),
                               np.array(ref.par, float).reshape(-1, 3), rtol=1e-14, atol=0)
    assert got.A.shape == ref.A.shape
    np.testing.assert_allclose(got.A, ref.A, rtol=0, atol=1e-12 * max(1.0, np.abs(ref.A).max()))
    assert len(got.contacts) == len(ref.contacts)
    for c, r in zip(got.contacts, ref.contacts):
        assert (c.a, c.b, c.row) == (r.a, r.b, r.row)
        for x, y in ((c.point_a, r.point_a), (c.point_b, r.point_b), (c.normal, r.normal)):
            np.testing.assert_allclose(x, y, rtol=0, atol=1e-13 * scale)
        assert abs(c.gap - r.gap) <= 1e-13 * scale


def _random_model(rng, extra_obstacles=()):
    robot, ground, objects, pegs, q, tau = random_scene(rng, ALL_MODELS)
    radius = float(rng.choice([0.0, 0.0, 0.005]))
    m0 = snakecg.load(GeneralScene(robot, radius=radius, ground=ground, objects=objects))
    obstacles = peg_obstacles(m0, pegs, q) + tuple(extra_obstacles)
    scene = GeneralScene(robot, radius=radius, ground=ground, objects=objects,
                         obstacles=obstacles)
    return snakecg.load(scene), q, tau


def test_contacts_and_rows_against_the_python_reference(rng):
    """Random scenes (every ground model, boxes, discs and pegs touching links, capsule or
    segment links, walls and box obstacles nearby): the same contacts (bodies, surface points,
    normals, gaps), the same rows and blocks, or the same overlap refused."""
    compared = refused = 0
    for _ in range(80):
        extra = []
        if rng.random() < 0.4:  # a wall or a box somewhere near the robot
            c = rng.normal(scale=0.3, size=2)
            extra.append(Obstacle(shape="wall", point=tuple(c), normal=tuple(rng.normal(size=2)))
                         if rng.random() < 0.5 else
                         Obstacle(shape="box", center=tuple(c), size=(0.1, 0.05),
                                  angle=float(rng.uniform(-3, 3))))
        model, q, tau = _random_model(rng, extra)
        ref = _reference(model, q)
        if isinstance(ref, InputError):
            with pytest.raises(InputError) as got:
                model.forward(q, tau)
            assert str(got.value) == str(ref)
            refused += 1
            continue
        res = model.forward(q, tau)
        rows, obj_poses = ref
        scale = model.packed.vector[4]  # the scene's size
        _same_rows(rows, res._rows[0], scale)
        np.testing.assert_allclose(np.array([o["pose"] for o in res.objects]).reshape(-1, 3),
                                   obj_poses, rtol=0, atol=1e-14 * scale)
        compared += 1
    assert compared >= 40 and refused >= 1


def test_rows_at_simulation_states_against_the_python_reference(rng):
    """The engine's rows at a simulation's state (core_scene_rows): random scenes, the
    configuration moved off the one the pegs were placed at and every object moved and
    turned off its placement by about the tolerance (a random one, 1e-6 to 1e-3 of the
    scene's size): the same contacts (bodies, points, normals, gaps), rows to 1e-12, blocks
    and objects' poses as the reference given the same poses and tolerance, or the same
    overlap refused; the bodies' inertia against the generated mass matrix and the objects'
    masses; the pairs' distances (core_scene_gaps) against the reference's closest points."""
    compared = refused = touching = gaps = 0
    for _ in range(60):
        model, q, _ = _random_model(rng)
        size = model.packed.vector[4]
        tol = float(size * 10 ** rng.uniform(-6, -3))
        q = q + rng.normal(scale=0.3 * tol / max(1.0, size), size=q.shape)
        P, J = model.link_poses(q), model.link_jacobians(q)
        placed = place_objects(model.scene, P)
        qo = placed + rng.normal(size=placed.shape) * [tol, tol, tol / size]
        engine = StateRows(model, tol)
        try:
            ref = rows_of(model.scene, model.masses, P, J, obj_poses=qo, tol=tol)
        except InputError as exc:
            with pytest.raises(InputError) as got:
                engine.rows(q, qo)
            assert str(got.value) == str(exc)
            refused += 1
        else:
            rows, M, poses = engine.rows(q, qo)
            _same_rows(ref[0], rows, size)
            np.testing.assert_array_equal(poses, qo)
            ns = model.n_coordinates
            Mref = np.zeros_like(M)
            Mref[:ns, :ns] = model.mass_matrix(q)
            Mref[ns:, ns:] = np.diag(np.ravel([[o.mass, o.mass, o.plate_inertia]
                                               for o in model.scene.objects]))
            np.testing.assert_allclose(M, Mref, rtol=1e-14, atol=0)
            compared += 1
            touching += len(rows.contacts) > 0
        margin = float(rng.choice([2 * tol, 0.05 * size]))
        want = pair_gaps(model.scene, P, qo, margin)
        got = engine.gaps(q, qo, margin)
        assert [(a, b) for a, b, _ in got] == [(a, b) for a, b, _ in want]
        for (a, b, d), (_, _, dr) in zip(got, want):
            assert abs(d - dr) <= 1e-13 * size
            assert engine.gap(q, qo, a, b) == d
            gaps += 1
    assert compared >= 25 and refused >= 3 and touching >= 10 and gaps >= 60


def test_touching_boxes_walls_and_self_contact_against_the_reference():
    """Flush faces (two contacts each: box on a link, box on a box obstacle, box on a wall),
    a disc on a wall, links folded onto each other: the engine's contacts and rows equal the
    reference's."""
    robot = Robot(joints=3)
    q = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    box = SceneObject(shape="box", size=(0.1, 0.06), mass=2.0,
                      touching={"link": 2, "offset": 0.075, "side": "left"})
    disc = SceneObject(shape="disc", radius=0.03, mass=1.0,
                       touching={"link": 4, "offset": 0.05, "side": "right"})
    base = snakecg.load(GeneralScene(robot, objects=(box, disc)))
    op = base.forward(q, [0.0, 0.0, 0.0]).objects
    bx, by, _ = op[0]["pose"]
    dx, dy, _ = op[1]["pose"]
    tip = link_ends(base.scene, base.link_poses(q))[-1, 1]  # the head's tip on a wall
    obstacles = (Obstacle(shape="box", center=(bx, by + 0.03 + 0.05), size=(0.3, 0.1)),
                 Obstacle(shape="wall", point=(dx, dy - 0.03), normal=(0.0, 1.0)),
                 Obstacle(shape="wall", point=(float(tip[0]), 0.0), normal=(-1.0, 0.0)))
    scene = GeneralScene(robot, ground=Ground(model="anisotropic", mu_forward=0.1,
                                              mu_backward=0.3, mu_lateral=0.5),
                         objects=(box, disc), obstacles=obstacles)
    model = snakecg.load(scene)
    res = model.forward(q, [0.3, -0.2, 0.1])
    rows, _ = _reference(model, q)
    _same_rows(rows, res._rows[0], model.packed.vector[4])
    pairs = [tuple(c["bodies"]) for c in res.contacts]
    assert pairs.count(("link 2", "object 1")) == 2
    assert pairs.count(("object 1", "obstacle 1")) == 2
    assert ("object 2", "obstacle 2") in pairs and ("link 4", "obstacle 3") in pairs
    folded = GeneralScene(robot, radius=0.02)
    qf = np.array([0.0, 0.0, 0.0, 2.9, 2.9, 0.0])
    with pytest.raises(InputError) as got:
        snakecg.load(folded).forward(qf, [0.0, 0.0, 0.0])
    assert str(got.value) == str(_reference(snakecg.load(folded), qf))


def test_many_contacts_are_solved_again_with_room(rng):
    """A link pressed by 20 pegs (more contacts than the engine's first pass keeps): every
    contact found, the same as the reference's, in one sample and in a batch."""
    robot = Robot(joints=1, length=[0.6, 0.6])
    q = np.array([0.0, 0.0, 0.0, 0.0])
    m0 = snakecg.load(GeneralScene(robot))
    x, y, _ = m0.link_poses(q)[0]
    pegs = tuple(Obstacle(shape="peg", center=(float(x - 0.28 + 0.028 * k), float(y) + 0.01),
                          radius=0.01) for k in range(21))
    model = snakecg.load(GeneralScene(robot, ground=Ground(model="coulomb", mu=0.2),
                                      obstacles=pegs))
    res = model.forward(q, [0.5])
    rows, _ = _reference(model, q)
    assert len(res.contacts) == len(rows.contacts) == 21
    _same_rows(rows, res._rows[0], model.packed.vector[4])
    batch = model.forward(np.repeat(q[None], 3, axis=0), [[0.5], [0.0], [-0.5]])
    assert [len(c) for c in batch.contacts] == [21, 21, 21]
    np.testing.assert_array_equal(batch.qdd[0], res.qdd)


def test_metrics_against_a_dense_model(rng):
    """||qdd||^2_M (eq. 26), ||a_o||^2 per object (eq. 27), ||lambda||^2 = lam^T G lam and sr
    (eq. 30) from the rows and forces in NumPy."""
    checked = 0
    for _ in range(40):
        model, q, tau = _random_model(rng)
        try:
            res = model.forward(q, tau)
        except InputError:
            continue
        if res.status != 0:
            continue
        p = dense_problem(res, model, tau)
        lam = res._raw["lam"][0][:len(p["b"])]
        ns = model.n_coordinates
        assert res.norm_qdd == pytest.approx(res.qdd @ p["M"][:ns, :ns] @ res.qdd, rel=1e-10,
                                             abs=1e-14)
        each = [a @ np.diag([o.mass, o.mass, o.plate_inertia]) @ a
                for a, o in zip(res.a_obj, model.scene.objects)]
        np.testing.assert_allclose(res.norm_a_obj_each, each, rtol=1e-10, atol=1e-14)
        assert res.norm_lambda == pytest.approx(lam @ p["G"] @ lam, rel=1e-7,
                                                abs=1e-12 * max(1.0, p["b"] @ p["b"]))
        total = sum(each) + res.norm_qdd
        # at rest (|a|^2_M at most 1e-26 of |a_free|^2_M: the accelerations are rounding) sr
        # is 0, as documented: the ratio of rounding noise is no answer
        rest = total <= 1e-26 * (p["a_free"] @ p["M"] @ p["a_free"])
        assert res.sr == pytest.approx(0.0 if rest else sum(each) / total, rel=1e-9,
                                       abs=1e-12), (total, p["a_free"] @ p["M"] @ p["a_free"])
        checked += 1
    assert checked >= 20


def test_batches_and_threads_give_the_same_samples(rng, monkeypatch):
    """A batch split over threads (SNAKECG_THREADS) equals one thread and the one-sample
    calls; an overlapping sample is NaN with its reason; a non-finite input is refused by
    name."""
    model, q, tau = _random_model(rng)
    while True:
        try:
            model.forward(q, tau)
            break
        except InputError:
            model, q, tau = _random_model(rng)
    N = 1100
    Q = q + rng.normal(scale=1e-3, size=(N, len(q)))
    T = rng.normal(size=(N, model.n_joints))
    one = model.forward(Q, T)
    monkeypatch.setenv("SNAKECG_THREADS", "2")
    two = model.forward(Q, T)
    assert rows_equal(one._out, two._out)
    for i in (0, 17, N - 1):
        try:
            single = model.forward(Q[i], T[i])
        except InputError:
            assert one.status[i] == 3 and "overlap" in one.reason[i]
            continue
        # sample 0 starts cold as the one-sample call does: the same bytes; the others
        # start from the last sample's pieces: the same answer to rounding
        np.testing.assert_allclose(one.qdd[i], single.qdd, rtol=0,
                                   atol=0 if i == 0 else 1e-12 * max(1, np.abs(single.qdd).max()))
        unique = one._raw["info"]["dependent"][i] == 0  # (else the forces need not be)
        assert len(single.contacts) == len(one.contacts[i])
        for c1, c2 in zip(single.contacts, one.contacts[i]):
            assert c1.keys() == c2.keys()
            for k in c1:
                if k == "force" and unique:
                    assert c2[k] == pytest.approx(c1[k], rel=1e-9, abs=1e-12)
                elif k != "force" and (k != "state" or unique):
                    assert c1[k] == c2[k], k
    with pytest.raises(InputError, match="tau must be finite"):
        model.forward(Q[:2], np.r_[T[:1], [[np.nan] * model.n_joints]])


def _edge_point(robot, radius, pose, k, offset, side):
    """Link k's surface point at ``offset`` from its rear end on ``side`` and the side's unit
    normal, from the link's COM pose: the rear end is ``com`` behind the COM along the link."""
    x, y, phi = pose
    along = np.array([np.cos(phi), np.sin(phi)])
    normal = np.array([-np.sin(phi), np.cos(phi)]) * (1.0 if side == "left" else -1.0)
    return np.array([x, y]) + (offset - robot.com[k]) * along + radius * normal, normal


def test_objects_are_placed_by_the_engine_where_they_touch(rng):
    """The engine's placement (``model.object_poses``, the one the forward, the drawing and a
    simulation's start read) on batches of random configurations, checked from the
    geometry: a touching disc's nearest point is the link's surface point at the offset on
    the named side (its centre one radius beyond it along the side's normal); a touching
    box turns with the link and the middle of the face toward the link is that point, the
    face's outward normal against the side's; an object with a pose stays there. Also
    against the reference's placement (tests/scenes_rows_reference.py) to 1e-12."""
    robot = Robot(joints=3)
    objects = (
        SceneObject(shape="box", size=(0.1, 0.06), mass=2.0,
                    touching={"link": 1, "offset": 0.03, "side": "left"}),
        SceneObject(shape="disc", radius=0.04, mass=1.0,
                    touching={"link": 3, "offset": 0.11, "side": "right"}),
        SceneObject(shape="box", size=(0.05, 0.09), mass=1.0,
                    touching={"link": 4, "side": "right"}),  # the default offset: L/2
        SceneObject(shape="disc", radius=0.05, mass=1.0, pose=(1.0, -2.0, 0.3)))
    scene = GeneralScene(robot, radius=0.015, objects=objects)
    model = snakecg.load(scene)
    Q = np.c_[rng.normal(size=(40, 2)), rng.uniform(-np.pi, np.pi, 40),
              rng.uniform(-1.2, 1.2, (40, 3))]
    got = model.object_poses(Q)
    assert got.shape == (40, 4, 3)
    for q, poses in zip(Q, got):
        P = model.link_poses(q)
        for o, pose in zip(objects[:3], poses):
            t = o.touching
            k = t["link"] - 1
            point, normal = _edge_point(robot, scene.radius, P[k], k,
                                        t.get("offset", robot.length[k] / 2), t["side"])
            if o.shape == "disc":
                np.testing.assert_allclose(pose[:2] - o.radius * normal, point, atol=1e-13)
                continue
            assert abs(np.angle(np.exp(1j * (pose[2] - P[k, 2])))) <= 1e-13
            c, s = np.cos(pose[2]), np.sin(pose[2])
            half = 0.5 * np.asarray(o.size)
            local = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)]) * half
            corners = pose[:2] + np.array([[c * x - s * y, s * x + c * y] for x, y in local])
            faces = [(corners[i], corners[(i + 1) % 4]) for i in range(4)]
            mids = [0.5 * (a + b) for a, b in faces]
            near = int(np.argmin([np.hypot(*(m - point)) for m in mids]))
            np.testing.assert_allclose(mids[near], point, atol=1e-13)
            a, b = faces[near]
            outward = np.array([b[1] - a[1], a[0] - b[0]]) / np.hypot(*(b - a))  # CCW corners
            np.testing.assert_allclose(outward, -normal, atol=1e-13)
        np.testing.assert_array_equal(poses[3], (1.0, -2.0, 0.3))
        np.testing.assert_allclose(poses, place_objects(scene, P), rtol=0, atol=1e-12)
    np.testing.assert_array_equal(model.object_poses(Q[5]), got[5])
    res = model.forward(Q, np.zeros(3))  # the forward's bodies are where the drawing's are
    apart = np.flatnonzero(res.status != 3)  # (overlapping samples report no poses)
    assert apart.size >= 10
    for s in apart:  # (the forward places from the kinematics' cosines and sines: an ulp)
        np.testing.assert_allclose([o["pose"] for o in res.objects[s]], got[s], rtol=0,
                                   atol=1e-14)
    with pytest.raises(InputError, match="q"):
        model.object_poses(np.zeros(5))
