"""snakecg.geometry against brute-force point sampling and against shapes of the paper.

The references sample every segment densely and measure with plain NumPy (pairwise point
distances; inside-ness of a point by the four half-planes of the plate's edges, its depth as
the least perpendicular distance to an edge line), so they share no code with the module.
The sampling error is bounded by half the sample spacing on each segment.
"""

from __future__ import annotations

import numpy as np
import pytest

from snakecg import Robot, Scene, geometry

N_SAMPLES = 4001


def _samples(a, b, n=N_SAMPLES):
    t = np.linspace(0.0, 1.0, n)[:, None]
    return a[None, :] * (1 - t) + b[None, :] * t


def _brute_segment_distance(a0, a1, b0, b1):
    pa, pb = _samples(a0, a1, 1201), _samples(b0, b1, 1201)
    d = np.sqrt(((pa[:, None, :] - pb[None, :, :]) ** 2).sum(-1))
    spacing = (np.linalg.norm(a1 - a0) + np.linalg.norm(b1 - b0)) / 1200 / 2
    return d.min(), spacing


def _plate_corners(q_obj, side):
    c, psi = q_obj[:2], q_obj[2]
    R = np.array([[np.cos(psi), -np.sin(psi)], [np.sin(psi), np.cos(psi)]])
    h = side / 2
    return np.array([c + R @ v for v in ([-h, -h], [h, -h], [h, h], [-h, h])])  # anticlockwise


def _brute_penetration(a, b, q_obj, side):
    pts = _samples(a, b)
    corners = _plate_corners(q_obj, side)
    depth = np.full(len(pts), np.inf)
    for k in range(4):
        e0, e1 = corners[k], corners[(k + 1) % 4]
        edge = e1 - e0
        normal_in = np.array([-edge[1], edge[0]]) / np.linalg.norm(edge)
        depth = np.minimum(depth, (pts - e0) @ normal_in)  # signed distance to the edge line
    spacing = np.linalg.norm(b - a) / (N_SAMPLES - 1) / 2
    return max(0.0, depth.max()), spacing


def test_segment_distance_matches_sampling(rng):
    for _ in range(60):
        a0, a1, b0, b1 = rng.uniform(-1, 1, (4, 2))
        if rng.random() < 0.2:  # parallel and collinear cases
            b0 = a0 + rng.uniform(-1, 1) * (a1 - a0) + rng.choice([0.0, 0.1]) * rng.normal(size=2)
            b1 = b0 + rng.uniform(-2, 2) * (a1 - a0)
        got = float(geometry.segment_distance(a0, a1, b0, b1))
        ref, spacing = _brute_segment_distance(a0, a1, b0, b1)
        assert got <= ref + 1e-12
        assert got >= ref - spacing - 1e-12


def test_segment_distance_batched_and_degenerate(rng):
    A0, A1, B0, B1 = rng.uniform(-1, 1, (4, 7, 2))
    batched = geometry.segment_distance(A0, A1, B0, B1)
    single = [float(geometry.segment_distance(A0[i], A1[i], B0[i], B1[i])) for i in range(7)]
    np.testing.assert_allclose(batched, single)
    # a zero-length segment is a point; crossing segments are at distance 0
    p = np.array([0.3, 0.4])
    assert geometry.segment_distance(p, p, np.array([0.0, 0.0]), np.array([1.0, 0.0])) == \
        pytest.approx(0.4)
    assert geometry.segment_distance([-1, 0], [1, 0], [0, -1], [0, 1]) == 0.0


def test_object_penetration_matches_sampling(rng):
    side = geometry.OBJECT_SIDE
    hits = 0
    for _ in range(200):
        q_obj = np.array([*rng.uniform(-0.05, 0.05, 2), rng.uniform(-np.pi, np.pi)])
        a, b = rng.uniform(-0.12, 0.12, (2, 2))
        got = float(geometry.object_penetration(a, b, q_obj, side))
        ref, spacing = _brute_penetration(a, b, q_obj, side)
        assert got >= ref - 1e-12
        assert got <= ref + spacing + 1e-12
        hits += ref > 0
    assert 20 < hits < 180  # both cases were exercised


def test_object_penetration_touching_face_is_zero():
    q_obj = np.array([0.0, 0.05, 0.0])  # plate above the x axis, its lower face on y = 0
    assert geometry.object_penetration([-0.2, 0.0], [0.2, 0.0], q_obj) == pytest.approx(0.0)
    assert geometry.object_penetration([-0.2, 0.01], [0.2, 0.01], q_obj) == pytest.approx(0.01)
    assert geometry.object_penetration([0.0, -0.2], [0.0, 0.3], q_obj) == pytest.approx(0.05)


def test_self_distance_of_a_folded_chain():
    # straight chain of 1 m links, a U turn, a chain whose third link crosses the first
    robot = Robot(joints=2, length=1.0)
    def poses(phis, start=(0.0, 0.0)):
        p = np.array(start, float)
        out = []
        for phi in phis:
            e = np.array([np.cos(phi), np.sin(phi)])
            out.append([*(p + 0.5 * e), phi])
            p = p + e
        return np.array(out)
    rear, front = geometry.link_segments(robot, poses([0.0, 0.0, 0.0]))
    np.testing.assert_allclose(front[:, 0], [1.0, 2.0, 3.0])
    assert geometry.self_distance(rear, front) == pytest.approx(1.0)
    # U turn: a 0.2 m link 2 at right angles, links 1 and 3 parallel 0.2 m apart
    robot_u = Robot(joints=2, length=(1.0, 0.2, 1.0))
    def poses_l(phis, lengths):
        p = np.zeros(2)
        out = []
        for phi, L in zip(phis, lengths):
            e = np.array([np.cos(phi), np.sin(phi)])
            out.append([*(p + 0.5 * L * e), phi])
            p = p + L * e
        return np.array(out)
    rear, front = geometry.link_segments(robot_u, poses_l([0, np.pi / 2, np.pi], (1, .2, 1)))
    assert geometry.self_distance(rear, front) == pytest.approx(0.2)
    assert not geometry.self_intersecting(rear, front, clearance=0.1)
    assert geometry.self_intersecting(rear, front, clearance=0.3)
    crossing = poses_l([0, 0.75 * np.pi, -0.6 * np.pi], (1, 1, 1))  # link 3 crosses link 1
    rear, front = geometry.link_segments(robot, crossing)
    assert geometry.self_distance(rear, front) == 0.0


@pytest.fixture(scope="module")
def model3():
    import snakecg

    return snakecg.load(Scene(Robot(joints=3), scenario="ideal_wheels"))


def test_feasibility_of_paper_shapes(model3):
    deg = np.deg2rad
    straight = np.zeros(6)
    # Fig. 6's "best ||a_obj||^2" shape of scenarios 2 and 3: the head passes through the plate
    through_object = np.array([0, 0, 0, *deg([-135.0, -115.0, -55.0])])
    coiled = np.array([0, 0, 0, *deg([135.0, 135.0, 135.0])])
    f = geometry.feasibility(model3, np.stack([straight, through_object, coiled]))
    assert f.feasible.tolist() == [True, False, False]
    assert f.penetrates_object.tolist()[:2] == [False, True]
    assert f.self_distance[0] == pytest.approx(0.15)   # links 1 and 3 of a straight snake
    assert f.self_intersecting[2]
    # brute force on the same shapes: every non-contacting link's samples vs the plate
    rear, front = geometry.link_segments(model3.robot, model3.link_poses(through_object))
    q_obj = model3.place_object(through_object)[0]
    ref = max(_brute_penetration(rear[i], front[i], q_obj, geometry.OBJECT_SIDE)[0]
              for i in range(1, 4))
    assert f.penetration[1] == pytest.approx(ref, abs=1e-4)
    single = geometry.feasibility(model3, through_object)
    assert not single.feasible and single.penetration == pytest.approx(f.penetration[1])


def test_component_formulas_equal_the_vector_ones_bit_for_bit():
    """point_segment_distance and object_penetration work component by component (faster on
    the batches of a sweep); they must give exactly what the dot-product / norm formulas of
    the definitions give, so that a feasibility flag never depends on the formulation:
    random segments, degenerate ones (a point), shared ends, grid-rounded coordinates, a
    plate at angle 0, and broadcast shapes."""
    rng = np.random.default_rng(11)
    n = 20000
    p, a, b = (rng.normal(scale=0.1, size=(n, 2)) for _ in range(3))
    b[:500] = a[:500]                                  # degenerate segments
    p[500:1000] = b[500:1000]                          # the point is an end
    p[1000:2000], a[1000:2000], b[1000:2000] = (np.round(x[1000:2000], 2) for x in (p, a, b))

    def psd(p, a, b):  # t = (p - a).d / d.d clipped to [0, 1]; |p - (a + t d)|
        d = b - a
        dd = np.einsum("...k,...k->...", d, d)
        t = np.einsum("...k,...k->...", p - a, d) / np.where(dd > 0, dd, 1.0)
        t = np.clip(np.where(dd > 0, t, 0.0), 0.0, 1.0)
        return np.linalg.norm(p - (a + t[..., None] * d), axis=-1)

    np.testing.assert_array_equal(geometry.point_segment_distance(p, a, b), psd(p, a, b))
    sub = (p[:6, None], a[None, :5], b[None, :5])
    np.testing.assert_array_equal(geometry.point_segment_distance(*sub), psd(*sub))
    assert geometry.point_segment_distance(p[0], a[0], b[0]).shape == ()

    q_obj = np.hstack([rng.normal(scale=0.01, size=(n, 2)), rng.uniform(-4, 4, (n, 1))])
    q_obj[2000:3000, 2] = 0.0

    def penetration(a, b, q_obj, side=geometry.OBJECT_SIDE):  # stacked 2-vectors
        c, psi = q_obj[..., :2], q_obj[..., 2]
        cs, sn = np.cos(psi), np.sin(psi)

        def local(x):
            d = x - c
            return np.stack([cs * d[..., 0] + sn * d[..., 1],
                             -sn * d[..., 0] + cs * d[..., 1]], -1)

        la, lb = local(a), local(b)
        d = lb - la
        ts = [np.zeros(la.shape[:-1]), np.ones(la.shape[:-1])]
        with np.errstate(divide="ignore", invalid="ignore"):
            ts += [-la[..., 0] / d[..., 0], -la[..., 1] / d[..., 1]]
            ts += [-(la[..., 0] - s * la[..., 1]) / (d[..., 0] - s * d[..., 1])
                   for s in (1.0, -1.0)]
        best = np.zeros(la.shape[:-1])
        for t in ts:
            t = np.clip(np.nan_to_num(t, nan=0.0, posinf=0.0, neginf=0.0), 0.0, 1.0)
            best = np.maximum(best, side / 2 - np.max(np.abs(la + t[..., None] * d), axis=-1))
        return best

    a3, b3 = a * 0.5, b * 0.5                          # many segments inside the plate
    got = geometry.object_penetration(a3, b3, q_obj)
    np.testing.assert_array_equal(got, penetration(a3, b3, q_obj))
    assert 0 < np.count_nonzero(got) < n
