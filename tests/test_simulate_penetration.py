"""The simulation's contact check: a run ends where a link enters the object or two links
cross, and says so.

References, none of which shares code with the check (``snakecg.geometry.ContactCheck``,
``snakecg/engine/geometry.c``):

* the NumPy geometry of ``overlap_reference.py`` (its own chain, the plate's depth as a small
  linear program over the segment, crossing by a 2 x 2 solve), itself checked here against
  brute-force point sampling;
* for the time of the first violation, an independent tight integration (``rtol`` 1e-12,
  the check off) from the last sample before it, sampled every ~1e-7 of the interval, with
  the first crossing of the tolerance by linear interpolation between those samples;
* for the runs the check must not change, the same run with the check off (array for
  array).

The suite also asserts, over every simulation it runs (``conftest.py``), that no sample
before the first reported violation overlaps beyond the tolerance.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from overlap_reference import (
    crossing_depth,
    first_crossing,
    link_ends,
    overlaps,
    plate_corners,
    plate_depth,
    point_segment,
    tolerance,
)

import snakecg
from snakecg import cli, geometry
from snakecg.simulate import save_figures, simulate

# the user's run: a 4-joint snake from a URDF file, wheels, kappa 10, mu 0.3, constant torque
TAU_USER = np.array([0.3, 0.1, -0.05, 0.02])
Q_USER = np.r_[0.0, 0.0, 0.0, np.deg2rad([30.0, -35.0, 25.0, 20.0])]


def _urdf(joints: int) -> str:
    """A planar snake of the paper's Table 1 links (1 kg, 0.15 m, 0.002 kg m^2), as a user
    would write it: link frames at the rear ends, massless tips at both ends."""
    inertial = ('<inertial><origin xyz="0.075 0 0" rpy="0 0 0"/><mass value="1.0"/>'
                '<inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.002"/>'
                "</inertial>")
    parts = ['<?xml version="1.0"?>', '<robot name="user-snake">']
    parts += [f'<link name="link{i}">{inertial}</link>' for i in range(1, joints + 2)]
    for i in range(1, joints + 1):
        parts.append(f'<joint name="joint{i}" type="revolute"><parent link="link{i}"/>'
                     f'<child link="link{i + 1}"/><origin xyz="0.15 0 0" rpy="0 0 0"/>'
                     '<axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="5" velocity="5"/>'
                     "</joint>")
    parts += ['<link name="tail_tip"/>',
              ('<joint name="tail_tip_joint" type="fixed"><parent link="link1"/>'
               '<child link="tail_tip"/><origin xyz="0 0 0"/></joint>'),
              '<link name="head_tip"/>',
              (f'<joint name="head_tip_joint" type="fixed"><parent link="link{joints + 1}"/>'
               '<child link="head_tip"/><origin xyz="0.15 0 0"/></joint>'),
              "</robot>"]
    return "\n".join(parts)


@pytest.fixture(scope="module")
def user(tmp_path_factory):
    pytest.importorskip("yourdfpy", reason="Robot.from_urdf needs the urdf extra")
    path = tmp_path_factory.mktemp("urdf") / "snake4.urdf"
    path.write_text(_urdf(4))
    robot = snakecg.Robot.from_urdf(path)
    scene = snakecg.Scene(robot, scenario="wheels", kappa=10.0, mu=0.3)
    return snakecg.load(scene), scene, path


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(joints, scenario, **kw):
        key = (joints, scenario, tuple(sorted(kw.items())))
        if key not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, kappa=10.0,
                                  **kw)
            cache[key] = (snakecg.load(scene), scene)
        return cache[key]

    return get


def reference_time(sm, scene, traj, tau):
    """The first time the overlap exceeds the tolerance, from an independent tight
    integration (check off) started at the last sample of ``traj`` before its violation."""
    v = traj.violation
    i = int(np.flatnonzero(traj.t < v.t)[-1])
    span = 2.0 * (v.t - traj.t[i]) + 1e-6
    ref = sm.simulate(traj.q[i], tau, span, v0=traj.v[i], q_obj0=traj.q_obj[i], rho=traj.rho,
                      v_obj0=traj.v_obj[i], rtol=1e-12, atol=1e-14, output_dt=span / 20000,
                      geometry_check="off")
    found = first_crossing(scene, ref.t, ref.q, ref.q_obj)
    assert found is not None
    return traj.t[i] + found[0], found[1]


# ------------------------------------------------------------------------------------------
# the reference geometry itself, against brute-force sampling
# ------------------------------------------------------------------------------------------
def _brute_plate_depth(a, b, corners, n=20001):
    t = np.linspace(0.0, 1.0, n)[:, None]
    pts = a * (1 - t) + b * t
    depth = np.full(n, np.inf)
    for k in range(4):
        e0, e1 = corners[k], corners[(k + 1) % 4]
        edge = e1 - e0
        inward = np.array([-edge[1], edge[0]]) / np.linalg.norm(edge)
        depth = np.minimum(depth, (pts - e0) @ inward)
    return max(0.0, depth.max()), np.linalg.norm(b - a) / (n - 1)


def test_reference_geometry_against_sampling(rng):
    for _ in range(100):
        q_obj = np.r_[rng.uniform(-0.05, 0.05, 2), rng.uniform(-np.pi, np.pi)]
        a, b = rng.uniform(-0.12, 0.12, (2, 2))
        corners = plate_corners(q_obj, 0.05)
        got = plate_depth(a[None], b[None], corners)[0]
        ref, spacing = _brute_plate_depth(a, b, corners[0])
        assert ref - 1e-15 <= got <= ref + spacing + 1e-15
    crossed = 0
    s = np.linspace(0, 1, 20001)[:, None]
    for _ in range(100):  # crossing: an end's distance, by sampling the other segment
        a0, a1, b0, b1 = rng.uniform(-1, 1, (4, 2))
        got = crossing_depth(a0[None], a1[None], b0[None], b1[None])[0]
        pa, pb = a0 + s * (a1 - a0), b0 + s * (b1 - b0)
        gap = np.sqrt(((pa[::40, None] - pb[None, ::40]) ** 2).sum(-1)).min()
        if got > 0:
            crossed += 1
            assert gap < 8e-3  # they meet (to the coarse sampling's spacing)
            ends = min(min(np.linalg.norm(pb - p, axis=1).min() for p in (a0, a1)),
                       min(np.linalg.norm(pa - p, axis=1).min() for p in (b0, b1)))
            assert ends - 1e-4 <= got <= ends + 1e-12
        else:
            assert gap > 0 or min(np.linalg.norm(p - q) for p in (a0, a1)
                                  for q in (b0, b1)) == 0
    assert crossed > 10
    p, a, b = rng.uniform(-1, 1, (3, 5, 2))
    s = np.linspace(0, 1, 100001)[:, None, None]
    brute = np.linalg.norm(a + s * (b - a) - p, axis=-1).min(axis=0)
    np.testing.assert_allclose(point_segment(p, a, b), brute, atol=1e-4)


def test_package_geometry_against_reference(rng, models):
    """ContactCheck (NumPy) and the compiled check (core_contact_depth) give the reference's
    overlaps at random states, segments and capsules; the chain of links is the model's."""
    from snakecg.simulate.contact_check import RunCheck

    sm, scene = models(4, "wheels")
    ns, ny = sm.n_coordinates, 2 * sm.n_coordinates + 9
    Q = np.c_[rng.uniform(-0.2, 0.2, (4000, 2)), rng.uniform(-np.pi, np.pi, (4000, 1)),
              rng.uniform(-2.5, 2.5, (4000, 4))]
    QO = np.c_[rng.uniform(-0.3, 0.3, (4000, 2)), rng.uniform(-np.pi, np.pi, 4000)]
    ref, bodies = overlaps(scene, Q, QO)
    assert (ref.max(axis=1) > 0).mean() > 0.2  # many overlap
    rear, front = link_ends(scene.robot, Q)
    r2, f2 = geometry.link_segments(scene.robot, sm.link_poses(Q))
    np.testing.assert_allclose(rear, r2, atol=1e-14)
    np.testing.assert_allclose(front, f2, atol=1e-14)
    shape = geometry.ContactCheck.of_scene(scene)
    assert [shape.bodies(k) for k in range(len(shape.pairs))] == bodies
    np.testing.assert_allclose(shape.depths(Q, QO), ref, atol=1e-14)
    check = RunCheck(sm, "stop", ns, ny)
    Y = np.zeros((len(Q), ny))
    Y[:, :ns], Y[:, ns:ns + 3] = Q, QO
    depth, pair = check.deepest(Y)
    np.testing.assert_allclose(depth, ref.max(axis=1), atol=1e-14)
    # the pair named is the deepest (two pairs can tie: links crossing at a shared joint)
    np.testing.assert_allclose(ref[np.arange(len(Q)), pair], ref.max(axis=1), atol=1e-14)
    assert check.tolerance == tolerance(scene) == 1e-6 * 0.15
    # capsules: the overlap of a link of radius r, from the reference's segment distances
    r = 0.01
    check.struct.radius = shape_r = r
    depth, _ = check.deepest(Y)
    capsule = geometry.ContactCheck(scene.robot, scene.object_distance, radius=shape_r)
    corners = plate_corners(QO, scene.object_distance)
    want = []
    for i, j in capsule.pairs:
        if j is None:
            inside = plate_depth(rear[:, i], front[:, i], corners)
            dist = np.min([_segment_distance(rear[:, i], front[:, i], corners[:, k],
                                             corners[:, (k + 1) % 4]) for k in range(4)], axis=0)
            want.append(np.where(inside > 0, r + inside, np.maximum(0, r - dist)))
        else:
            cross = crossing_depth(rear[:, i], front[:, i], rear[:, j], front[:, j])
            dist = _segment_distance(rear[:, i], front[:, i], rear[:, j], front[:, j])
            want.append(np.where(cross > 0, 2 * r + cross, np.maximum(0, 2 * r - dist)))
    want = np.stack(want, axis=-1)
    np.testing.assert_allclose(capsule.depths(Q, QO), want, atol=1e-14)
    np.testing.assert_allclose(depth, want.max(axis=1), atol=1e-14)


def _segment_distance(a0, a1, b0, b1):
    """Distance between segments that do not cross: the least end-to-segment distance."""
    d = np.min([point_segment(a0, b0, b1), point_segment(a1, b0, b1),
                point_segment(b0, a0, a1), point_segment(b1, a0, a1)], axis=0)
    return np.where(crossing_depth(a0, a1, b0, b1) > 0, 0.0, d)


# ------------------------------------------------------------------------------------------
# the user's run
# ------------------------------------------------------------------------------------------
def test_user_run_as_reported_without_the_check(user):
    """The run as the user had it (nothing checked): it completes, yet the reference
    geometry sees the contact link millimetres deep in the plate by 0.1 s and deeper later,
    and the links, closer than 1 cm to each other within the second, cross later on."""
    sm, scene, _ = user
    off = sm.simulate(Q_USER, TAU_USER, 2.0, geometry_check="off")
    assert off.summary["status"] == "completed (geometry not checked)"
    assert off.summary["violation"] is None
    d, bodies = overlaps(scene, off.q, off.q_obj)
    link1 = d[:, bodies.index((1, "object"))]
    assert link1[off.at(0.1)] > 5e-3 and link1[off.at(0.25)] > 2e-2
    rear, front = link_ends(scene.robot, off.q)
    links = [k for k, b in enumerate(bodies) if b[1] != "object"]
    near = np.min([_segment_distance(rear[:, i - 1], front[:, i - 1], rear[:, j - 1],
                                     front[:, j - 1]) for i, j in (bodies[k] for k in links)],
                  axis=0)
    assert near[off.t <= 1.0].min() < 1e-2
    crossed = d[:, links].max(axis=1) > tolerance(scene)
    assert crossed.sum() > 50 and 0.5 < off.t[crossed][0] < 2.0


@pytest.mark.parametrize("integrator", ["auto", "scipy"])
def test_user_run_stops_at_the_first_penetration(user, integrator):
    """With the check (the default) the run ends where link 1 first enters the object by
    the tolerance, long before 0.1 s, at the time an independent tight integration finds
    (not at the next output sample); the summary, the trajectory and the figures say so."""
    sm, scene, _ = user
    traj = sm.simulate(Q_USER, TAU_USER, 1.0, integrator=integrator)
    v = traj.violation
    s = traj.summary
    assert s["status"] == "penetration" and v.kind == "penetration"
    assert v.bodies == (1, "object") and s["violation"]["bodies"] == [1, "object"]
    assert 0 < v.t < 0.1 and traj.t[-1] == v.t and traj.n_samples == 2  # before 1/400 s
    assert v.depth == pytest.approx(tolerance(scene), rel=1e-6)
    assert s["violation"]["t"] == v.t and s["contact_check"]["tolerance"] == tolerance(scene)
    t_ref, bodies = reference_time(sm, scene, traj, TAU_USER)
    assert bodies == (1, "object")
    assert abs(v.t - t_ref) < 1e-9, (v.t, t_ref)
    json.dumps(s, allow_nan=False)


def test_paths_agree_on_the_violation(user):
    """Compiled segments, the whole run in C, solve_ivp and a held time law all stop at the
    same violation."""
    sm, _, _ = user
    runs = [sm.simulate(Q_USER, TAU_USER, 0.5),
            sm.simulate(Q_USER, TAU_USER, 0.5, integrator="scipy"),
            sm.simulate(Q_USER, lambda t: TAU_USER, 0.5, control_period=1e-4),
            sm.simulate(Q_USER, lambda t: TAU_USER, 0.5, method="RK45")]
    assert runs[2].summary["integrator"]["compiled_segments"]
    assert not runs[3].summary["integrator"]["compiled_segments"]
    t0 = runs[0].violation.t
    for r in runs:
        assert r.violation.bodies == (1, "object")
        assert abs(r.violation.t - t0) < 1e-9 * (50 if r is runs[3] else 1)


def test_violation_seen_only_at_a_sample(user, monkeypatch):
    """solve_ivp evaluates the check at its steps' ends; an overlap seen first at an output
    sample (the steps' ends made blind here) is located on the dense output of the segment
    integrated again: at the same time."""
    from snakecg.simulate.contact_check import RunCheck

    sm, _, _ = user
    for mode in ("stop", "report"):
        kw = {"integrator": "scipy", "output_dt": 1e-4, "geometry_check": mode}
        seen = sm.simulate(Q_USER, TAU_USER, 0.01, **kw)
        with monkeypatch.context() as m:
            m.setattr(RunCheck, "event", lambda self: _blind)
            blind = sm.simulate(Q_USER, TAU_USER, 0.01, **kw)
        # (2e-14 s: the two locations, at a step's end and on the segment integrated again,
        # agree to the root finding's rounding; 9e-15 s once the contact system is evaluated
        # with the base at the origin)
        assert blind.violation.t == pytest.approx(seen.violation.t, rel=1e-12, abs=2e-14)
        assert blind.violation.bodies == seen.violation.bodies == (1, "object")
        assert blind.t[-1] == (blind.violation.t if mode == "stop" else 0.01)


def _blind(t, y):
    return 1.0


_blind.terminal, _blind.direction = True, -1


def test_numpy_check_without_compiled_library(user):
    """A model evaluated by CasADi (no compiled library): solve_ivp with the NumPy check
    finds the violation the compiled run finds. (The object's pose is given: the scene's
    placement through the compiled batch driver does not serve this backend.)"""
    sm, scene, _ = user
    slow = snakecg.load(scene, backend="casadi")
    q_obj, rho, _ = sm.place_object(Q_USER)
    kw = {"q_obj0": q_obj, "rho": rho}
    a = slow.simulate(Q_USER, TAU_USER, 0.05, **kw)
    b = sm.simulate(Q_USER, TAU_USER, 0.05, **kw)
    assert not a.summary["integrator"]["compiled_segments"]
    assert a.violation.bodies == b.violation.bodies == (1, "object")
    assert abs(a.violation.t - b.violation.t) < 1e-12


def test_report_integrates_on_unchanged(user):
    """``report``: the same trajectory as with the check off, array for array, and the same
    first violation as ``stop``, whose samples are the beginning of it."""
    sm, _, _ = user
    off = sm.simulate(Q_USER, TAU_USER, 0.3, geometry_check="off")
    rep = sm.simulate(Q_USER, TAU_USER, 0.3, geometry_check="report")
    stop = sm.simulate(Q_USER, TAU_USER, 0.3)
    for k, a in off.arrays().items():
        np.testing.assert_array_equal(rep.arrays()[k], a, err_msg=k)
    assert rep.summary["status"] == "penetration"
    assert rep.violation.t == stop.violation.t and rep.violation.bodies == stop.violation.bodies
    stop = sm.simulate(Q_USER, TAU_USER, 0.3, output_dt=1e-5)  # (located between samples)
    assert stop.violation.t == pytest.approx(rep.violation.t, rel=1e-12)
    n = stop.n_samples - 1  # every sample but the violation's is one of the full run's
    fine = sm.simulate(Q_USER, TAU_USER, 0.3, output_dt=1e-5, geometry_check="off")
    np.testing.assert_array_equal(stop.q[:n], fine.q[:n])
    np.testing.assert_array_equal(stop.t[:n], fine.t[:n])
    assert fine.t[n] > stop.t[-1] > fine.t[n - 1]


# ------------------------------------------------------------------------------------------
# self-contact, another link, a feasible push
# ------------------------------------------------------------------------------------------
def test_self_contact_stops_the_run(models):
    """A snake closing a U (joints 1 and 2 at 100 degrees, the object far away) folds links
    1 and 3 onto each other: self_contact at the crossing the reference finds."""
    sm, scene = models(3, "frictionless")
    q0 = np.r_[0.0, 0.0, 0.0, np.deg2rad([100.0, 100.0, 0.0])]
    q_obj, rho, _ = sm.place_object(q0)
    far = {"q_obj0": q_obj + [0.0, 1.0, 0.0], "rho": rho}
    tau = np.array([0.05, 0.05, 0.0])
    for integrator in ("auto", "scipy"):
        traj = sm.simulate(q0, tau, 1.0, integrator=integrator, **far)
        v = traj.violation
        assert traj.summary["status"] == "self_contact" and v.kind == "self_contact"
        assert v.bodies == (1, 3) and 0.2 < v.t < 0.6 and traj.t[-1] == v.t
        assert "links 1 and 3 crossed" in v.describe()
    t_ref, bodies = reference_time(sm, scene, traj, tau)
    assert bodies == (1, 3) and abs(v.t - t_ref) < 1e-9
    with pytest.raises(snakecg.InputError, match="links 1 and 3 cross by"):
        sm.simulate(traj.q[-1] + [0, 0, 0, 0.05, 0.05, 0], tau, 0.1, **far)


def test_another_link_hits_the_object(models):
    """Contact at the middle link; the torques pull it off the object and swing the head
    link into the plate: penetration of link 3, at the reference's time."""
    sm, scene = models(2, "frictionless", contact_link=2)
    q0 = np.r_[0.0, 0.0, 0.0, np.deg2rad([60.0, 60.0])]
    tau = np.array([0.05, 0.05])
    traj = sm.simulate(q0, tau, 0.6)
    v = traj.violation
    assert v.bodies == (3, "object") and 0.4 < v.t < 0.5
    t_ref, bodies = reference_time(sm, scene, traj, tau)
    assert bodies == (3, "object") and abs(v.t - t_ref) < 1e-9


def test_feasible_push_is_unchanged(models):
    """A push that stays physical (a symmetric W shape pushing with its middle link: the
    contact link does not turn against the object) completes, and the check changes nothing:
    the same arrays as with it off. The reference sees no overlap at any of 2000 samples."""
    sm, scene = models(4, "wheels", contact_link=3)
    q0 = np.r_[0.0, 0.0, 0.0, np.deg2rad([30.0, 40.0, 40.0, 30.0])]
    tau = np.array([0.05, 0.02, 0.02, 0.05])
    on = sm.simulate(q0, tau, 0.5)
    off = sm.simulate(q0, tau, 0.5, geometry_check="off")
    assert on.summary["status"] == "completed" and on.violation is None
    assert on.summary["violation"] is None
    assert off.summary["status"] == "completed (geometry not checked)"
    for k, a in off.arrays().items():
        np.testing.assert_array_equal(on.arrays()[k], a, err_msg=k)
    assert on.summary["object_displacement"]["distance"] > 0.01  # a real push
    dense = sm.simulate(q0, tau, 0.5, output_dt=0.5 / 2000)
    d, _ = overlaps(scene, dense.q, dense.q_obj)
    assert d.max() < 1e-9
    py = sm.simulate(q0, tau, 0.5, integrator="scipy")
    assert py.summary["status"] == "completed"


# ------------------------------------------------------------------------------------------
# input, CLI, figures
# ------------------------------------------------------------------------------------------
def test_bad_input_and_initial_overlap(models):
    sm, _ = models(3, "frictionless")
    q0 = np.r_[0.0, 0.0, 0.0, 0.5, -0.6, 0.4]
    with pytest.raises(snakecg.InputError, match="geometry_check must be 'stop', 'report' or"):
        simulate(sm, q0, np.zeros(3), 0.1, geometry_check="on")
    q_obj, rho, _ = sm.place_object(q0)
    inside = q_obj - [0.0, 0.02, 0.0]  # the object pushed 2 cm into link 1
    with pytest.raises(snakecg.InputError, match="link 1 penetrates the object by 0.02 m"):
        simulate(sm, q0, np.zeros(3), 0.1, q_obj0=inside, rho=rho)
    with pytest.raises(snakecg.InputError, match="link 1 penetrates the object"):
        simulate(sm, q0, np.zeros(3), 0.1, q_obj0=inside, rho=rho, geometry_check="report")


def test_cli_says_so(user, tmp_path, capsys):
    _, _, path = user
    args = ["simulate", "--robot", str(path), "--scenario", "wheels", "--kappa", "10",
            "--mu", "0.3", "--q", "0,0,0,30deg,-35deg,25deg,20deg", "--tau",
            "0.3,0.1,-0.05,0.02", "--duration", "1", "--no-figures", "--out", str(tmp_path)]
    rc = cli.main([*args, "--json"])
    cap = capsys.readouterr()
    assert rc == 1
    s = json.loads(cap.out)
    assert s["status"] == "penetration" and s["violation"]["bodies"] == [1, "object"]
    assert 0 < s["violation"]["t"] < 0.1
    (line,) = cap.err.splitlines()
    assert line.startswith("snakecg simulate: penetration: link 1 entered the object at t = ")
    saved = np.load(tmp_path / "trajectory.npz")
    assert saved["t"][-1] == s["violation"]["t"]
    rc = cli.main(args)
    out = capsys.readouterr().out
    assert rc == 1
    assert out.splitlines()[0].endswith(": penetration")
    assert "penetration: link 1 entered the object at t = " in out
    assert "the run stopped there" in out
    rc = cli.main([*args, "--geometry-check", "report", "--json"])
    s = json.loads(capsys.readouterr().out)
    assert rc == 1 and s["status"] == "penetration" and s["duration"] == 1.0
    assert np.load(tmp_path / "trajectory.npz")["t"][-1] == pytest.approx(1.0)


def test_figures_mark_the_end(user, tmp_path):
    from PIL import Image

    sm, _, _ = user
    for mode in ("stop", "report"):
        traj = sm.simulate(Q_USER, TAU_USER, 0.2, output_dt=0.01, geometry_check=mode)
        paths = save_figures(traj, tmp_path / mode, frames=5, dpi=50)
        with Image.open(paths["animation"]) as im:
            assert im.format == "GIF"
        with Image.open(paths["displacement"]) as im:
            px = np.asarray(im.convert("RGB")).reshape(-1, 3).astype(int)
        red = (px[:, 0] > 200) & (px[:, 1] < 60) & (px[:, 2] < 60)
        assert red.sum() > 50  # the red line of the violation
