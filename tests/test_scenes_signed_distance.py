"""The engine's signed distance of every pair of shapes (snakecg/engine/scene_geometry.c:
the depth from the hull of the cores' Minkowski difference) against the tests' reference
(tests/scenes_geometry_reference.py: the separating axis theorem where the cores overlap,
the closest features apart), on random poses that overlap as often as not; its continuity
through contact; the contacts of a corner crossing a link (one) and of a flush face (the two
ends of the overlap, one where shorter than the tolerance)."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg import Robot
from snakecg.scenes import GeneralScene, Obstacle, SceneObject
from snakecg.scenes.contacts import StateRows, link_ends

from snakecg.errors import InputError

from scenes_geometry_reference import closest
from scenes_rows_reference import rows_of, shapes

# (a, b) of every kind of pair: link (segment or capsule) with a box, a disc, a peg, a wall,
# a box obstacle and a link; a box object with a disc, a peg, a wall, a box; a disc with a
# peg, a wall, a box
PAIRS = [(("link", 0), ("object", 0)), (("link", 0), ("object", 1)),
         (("link", 0), ("obstacle", 0)), (("link", 0), ("obstacle", 1)),
         (("link", 0), ("obstacle", 2)), (("link", 0), ("link", 2)),
         (("object", 0), ("object", 1)), (("object", 0), ("obstacle", 0)),
         (("object", 0), ("obstacle", 1)), (("object", 0), ("obstacle", 2)),
         (("object", 1), ("obstacle", 0)), (("object", 1), ("obstacle", 1)),
         (("object", 1), ("obstacle", 2))]


def _model(radius, rng):
    """A 3-link robot near the origin, a box and a disc object, a peg, a wall and a box
    obstacle, each within reach of link 1 (0.15 m long, from -0.075 to 0.075 on x)."""
    obstacles = (Obstacle(shape="peg", center=tuple(rng.uniform(-0.05, 0.05, 2)),
                          radius=float(rng.uniform(0.005, 0.03))),
                 Obstacle(shape="wall", point=tuple(rng.uniform(-0.03, 0.03, 2)),
                          normal=tuple(rng.normal(size=2))),
                 Obstacle(shape="box", center=tuple(rng.uniform(-0.05, 0.05, 2)),
                          size=tuple(rng.uniform(0.02, 0.1, 2)),
                          angle=float(rng.uniform(-3, 3))))
    objects = (SceneObject(shape="box", size=tuple(rng.uniform(0.02, 0.1, 2)), mass=1.0,
                           pose=(0.0, 0.2, 0.0)),
               SceneObject(shape="disc", radius=float(rng.uniform(0.005, 0.04)), mass=1.0,
                           pose=(0.0, -0.2, 0.0)))
    return snakecg.load(GeneralScene(Robot(joints=2), radius=radius, objects=objects,
                                     obstacles=obstacles))


def _reference(model, q, qo, a, b):
    bodies = dict(shapes(model.scene, model.link_poses(q), qo))
    return closest(bodies[a], bodies[b], model.packed.vector[4])


def test_signed_distances_of_every_pair_against_the_reference(rng):
    """Random poses of the objects and the robot's first link near the obstacles: the
    engine's distance of every pair equals the reference's to 1e-12 of the scene's size,
    apart and overlapping (both seen often for every pair)."""
    seen = {}
    for trial in range(12):
        model = _model(0.0 if trial % 2 == 0 else 0.01, rng)
        size = model.packed.vector[4]
        engine = StateRows(model, 1e-6 * size)
        for _ in range(40):
            q = np.r_[rng.uniform(-0.03, 0.03, 2), rng.uniform(-3, 3), rng.uniform(-2.5, 2.5, 2)]
            qo = np.c_[rng.uniform(-0.06, 0.06, (2, 2)), rng.uniform(-3, 3, 2)]
            for a, b in PAIRS:
                if (a, b) == (("link", 0), ("link", 2)) and rng.random() < 0.5:
                    q[3:] = rng.uniform(2.6, 3.1, 2)  # folded: link 3 back over link 1
                d = engine.gap(q, qo, a, b)
                dr, _ = _reference(model, q, qo, a, b)
                assert abs(d - dr) <= 1e-12 * size, (a, b, d, dr)
                apart, over = seen.get((a, b), (0, 0))
                seen[a, b] = (apart + (dr > 0), over + (dr < 0))
    assert set(seen) == set(PAIRS)
    assert all(apart >= 20 and over >= 20 for apart, over in seen.values()), seen


def test_contacts_of_overlapping_shapes_against_the_reference(rng):
    """Random poses, a tolerance of 2 to 20 % of the scene's size so that overlapping pairs
    keep their contacts: the engine's contacts (bodies, surface points, normals, gaps) equal
    the reference's to 1e-13 of the scene's size, or both refuse the same overlap."""
    compared = overlapping = refused = 0
    for trial in range(12):
        model = _model(0.0 if trial % 2 == 0 else 0.01, rng)
        size = model.packed.vector[4]
        for _ in range(20):
            tol = float(rng.uniform(0.02, 0.2) * size)
            q = np.r_[rng.uniform(-0.03, 0.03, 2), rng.uniform(-3, 3), rng.uniform(-2.5, 2.5, 2)]
            qo = np.c_[rng.uniform(-0.06, 0.06, (2, 2)), rng.uniform(-3, 3, 2)]
            P, J = model.link_poses(q), model.link_jacobians(q)
            try:
                ref, _ = rows_of(model.scene, model.masses, P, J, obj_poses=qo, tol=tol)
            except InputError as exc:
                with pytest.raises(InputError) as got:
                    StateRows(model, tol).rows(q, qo)
                assert str(got.value) == str(exc)
                refused += 1
                continue
            rows, _, _ = StateRows(model, tol).rows(q, qo)
            assert len(rows.contacts) == len(ref.contacts)
            for c, r in zip(rows.contacts, ref.contacts):
                assert (c.a, c.b, c.row) == (r.a, r.b, r.row)
                for x, y in ((c.point_a, r.point_a), (c.point_b, r.point_b),
                             (c.normal, r.normal)):
                    np.testing.assert_allclose(x, y, rtol=0, atol=1e-13 * size)
                assert abs(c.gap - r.gap) <= 1e-13 * size
                overlapping += c.gap < 0
            np.testing.assert_allclose(rows.A, ref.A, rtol=0,
                                       atol=1e-12 * max(1.0, abs(ref.A).max()))
            compared += 1
    assert compared >= 50 and overlapping >= 200 and refused >= 50, (compared, overlapping,
                                                                     refused)


@pytest.mark.parametrize("radius", [0.0, 0.01])
def test_the_distance_is_continuous_through_contact(rng, radius):
    """Each object, turned at random, driven straight through link 1 and each obstacle in
    steps of 0.1 mm (out of a wall along its normal): the distance goes from positive to
    negative and back, and changes by
    no more than the step (a signed distance is 1-Lipschitz in a translation), so a
    crossing is never seen as touching and a depth never jumps."""
    model = _model(radius, rng)
    engine = StateRows(model, 1e-6 * model.packed.vector[4])
    q = np.array([0.0, 0.0, 0.0, 0.4, -0.4])  # link 1 from (-0.075, 0) to (0.075, 0)
    peg, wall, box = model.scene.obstacles
    s = np.linspace(-0.15, 0.15, 3001)
    checked = 0
    for j in (0, 1):
        for b, centre, u in ((("link", 0), (0.0, 0.0), None), (("obstacle", 0), peg.center, None),
                             (("obstacle", 1), wall.point, wall.normal),
                             (("obstacle", 2), box.center, None)):
            u = rng.normal(size=2) if u is None else np.asarray(u, float)
            u /= np.hypot(*u)
            th = float(rng.uniform(-3, 3))
            d = []
            for si in s:
                qo = np.array([[0.0, 0.5, 0.0], [0.0, -0.5, 0.0]])  # the other object away
                qo[j] = [*(np.asarray(centre) + si * u), th]
                a2, b2 = ((b, ("object", j)) if b[0] == "link" else (("object", j), b))
                d.append(engine.gap(q, qo, a2, b2))
            d = np.array(d)
            if b == ("obstacle", 1):  # from inside the wall out along its normal
                assert d[0] < 0 < d[-1], (j, b)
            else:
                assert d[0] > 0 > d[len(s) // 2] and d[-1] > 0, (j, b)
            assert np.abs(np.diff(d)).max() <= (s[1] - s[0]) * (1 + 1e-9), (j, b)
            checked += 1
    assert checked == 8


def _one_link_and_box(radius, size):
    """Link 1 from (-0.075, 0) to (0.075, 0) (q = 0), link 2 turned down out of the way, and
    a box placed by the state."""
    box = SceneObject(shape="box", size=size, mass=1.0, pose=(0.0, 0.3, 0.0))
    model = snakecg.load(GeneralScene(Robot(joints=1), radius=radius, objects=(box,)))
    q = np.array([0.0, 0.0, 0.0, -1.0])
    ends = link_ends(model.scene, model.link_poses(q))[0]
    np.testing.assert_allclose(ends, [[-0.075, 0.0], [0.075, 0.0]], atol=1e-15)
    return model, q


def _contacts(model, q, qo, tol):
    rows, _, _ = StateRows(model, tol).rows(q, np.atleast_2d(qo))
    return [c for c in rows.contacts if (c.a, c.b) == (("link", 0), ("object", 0))]


@pytest.mark.parametrize("radius", [0.0, 0.01])
def test_a_corner_across_a_link_is_one_contact_at_its_depth(rng, radius):
    """A box's corner pushed across link 1 (a segment, or a capsule's surface) by depths
    from 1e-10 m to half the tolerance, the box turned at random: one contact, at the corner,
    the link's normal, its gap minus the depth (the closed form: the corner's height)."""
    model, q = _one_link_and_box(radius, (0.04, 0.03))
    tol = 1e-6
    for _ in range(10):
        th = float(rng.uniform(0.15, np.pi / 2 - 0.15) + rng.integers(4) * np.pi / 2)
        c, s = np.cos(th), np.sin(th)
        local = np.array([[-0.02, -0.015], [0.02, -0.015], [0.02, 0.015], [-0.02, 0.015]])
        corners = local @ np.array([[c, s], [-s, c]])  # turned by th
        low = corners[np.argmin(corners[:, 1])]
        for depth in (1e-10, 1e-8, 0.5 * tol):
            centre = np.array([-0.02, radius - depth]) - low
            got = _contacts(model, q, [*centre, th], tol)
            assert len(got) == 1
            k = got[0]
            np.testing.assert_allclose(k.normal, [0.0, 1.0], atol=1e-12)
            assert k.gap == pytest.approx(-depth, rel=1e-6, abs=1e-16)
            np.testing.assert_allclose(k.point_b, centre + low, atol=1e-15)
            np.testing.assert_allclose(k.point_a, [centre[0] + low[0], radius], atol=1e-15)


@pytest.mark.parametrize("radius", [0.0, 0.01])
def test_a_flush_face_is_the_two_ends_of_the_overlap_or_its_middle(radius):
    """A box lying flush on link 1, just apart or just inside (gaps of half the tolerance
    either way, and 1e-10 m inside): two contacts at the ends of the shared stretch (the
    box's bottom corners, 0.1 m apart); where the box overlaps the link's end by less than
    the tolerance, one contact at the middle of that stretch, apart and inside alike (but
    where the box is deeper in a segment than that stretch: it parts sideways, by the
    stretch; a capsule's round end keeps it parting upwards)."""
    model, q = _one_link_and_box(radius, (0.1, 0.04))
    tol = 1e-6
    for gap in (0.5 * tol, -1e-10, -0.5 * tol):
        y = radius + 0.02 + gap
        got = _contacts(model, q, [0.0, y, 0.0], tol)
        assert len(got) == 2
        np.testing.assert_allclose(sorted(k.point_b[0] for k in got), [-0.05, 0.05], atol=1e-15)
        for k in got:
            assert k.gap == pytest.approx(gap, rel=1e-6)
            np.testing.assert_allclose(k.normal, [0.0, 1.0], atol=1e-12)
        for short in (0.3 * tol, 0.9 * tol):  # the box's right edge past the link's rear end
            got = _contacts(model, q, [-0.125 + short, y, 0.0], tol)
            assert len(got) == 1
            if radius == 0 and -gap > short:  # deeper than the stretch: parted sideways
                np.testing.assert_allclose(got[0].normal, [-1.0, 0.0], atol=1e-12)
                assert got[0].gap == pytest.approx(-short, rel=1e-6)
                continue
            np.testing.assert_allclose(got[0].point_b, [-0.075 + 0.5 * short, y - 0.02],
                                       atol=1e-15)
            assert got[0].gap == pytest.approx(gap, rel=1e-6)
        got = _contacts(model, q, [-0.125 + 1.1 * tol, y, 0.0], tol)
        assert len(got) == 2


@pytest.mark.parametrize("radius", [0.0, 0.01])
def test_a_box_nearly_flush_on_a_link_against_the_reference(rng, radius):
    """The pushes' pair: a box lying on link 1 nearly flush (any of its four faces, tilted by
    1e-12 to 1e-2 rad either way or not at all), along the link anywhere from past its rear
    end to past its front, from 1e-3 m apart to 1e-3 m inside (and a few deep overlaps):
    the engine's contacts (surface points, normals, gaps) equal the separating axis
    reference's (tests/scenes_geometry_reference.py) to 1e-14 of the scene's size, or both
    refuse the same overlap."""
    model, q = _one_link_and_box(radius, (0.1, 0.04))
    size = model.packed.vector[4]
    P, J = model.link_poses(q), model.link_jacobians(q)
    tol = 0.035  # the deep overlaps within it (not refused); flush stretches up to 0.1 m
    compared = flush = deep = 0
    for trial in range(400):
        face = int(rng.integers(4))
        tilt = 0.0 if trial % 5 == 0 else float(rng.choice([-1, 1]) * 10 ** rng.uniform(-12, -2))
        th = face * np.pi / 2 + tilt
        half = 0.02 if face % 2 == 0 else 0.05  # the face's distance from the box's centre
        gap = float(rng.choice([-1, 1]) * 10 ** rng.uniform(-12, -3))
        if trial % 20 == 1:
            gap = -float(rng.uniform(0.005, 0.03))  # deep
        qo = np.array([[rng.uniform(-0.14, 0.14), radius + half + gap, th]])
        try:
            ref, _ = rows_of(model.scene, model.masses, P, J, obj_poses=qo, tol=tol)
        except InputError as exc:
            with pytest.raises(InputError) as refused:
                StateRows(model, tol).rows(q, qo)
            assert str(refused.value) == str(exc)
            continue
        rows, _, _ = StateRows(model, tol).rows(q, qo)
        got = [c for c in rows.contacts if c.b == ("object", 0)]
        want = [c for c in ref.contacts if c.b == ("object", 0)]
        assert len(got) == len(want)
        for c, r in zip(got, want):
            assert (c.a, c.b, c.row) == (r.a, r.b, r.row)
            for x, y in ((c.point_a, r.point_a), (c.point_b, r.point_b), (c.normal, r.normal)):
                np.testing.assert_allclose(x, y, rtol=0, atol=1e-14 * size)
            assert abs(c.gap - r.gap) <= 1e-14 * size
        compared += len(got) > 0
        flush += len(got) == 2
        deep += any(c.gap < -0.004 for c in got)
    assert compared >= 350 and flush >= 150 and deep >= 10, (compared, flush, deep)
