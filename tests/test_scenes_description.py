"""General scenes: the description and its validation, the TOML file, the command line, the
tests' reference closest points (tests/scenes_geometry_reference.py, against dense sampling
of the shapes' boundaries) and the drawing."""

from __future__ import annotations

import json
import re
import subprocess
import sys

import numpy as np
import pytest
from scenes_geometry_reference import Shape, closest
from scenes_reference import SCENE

import snakecg
from snakecg import Robot, Scene
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject
from snakecg.scenes.geometry import box_corners
from snakecg.scenes.toml_reading import read_scene


def test_toml_scene_is_read(tmp_path):
    p = tmp_path / "s.toml"
    p.write_text(SCENE)
    s = read_scene(p)
    assert s.robot.joints == 3 and s.radius == 0.01
    assert all(g.model == "coulomb" and g.mu == 0.3 for g in s.ground)
    o = s.objects[0]
    assert o.plate_inertia == pytest.approx(100.0 * (0.01 + 0.01) / 12)  # uniform plate
    assert s.obstacles[0].shape == "peg"


def test_every_problem_is_named_at_once(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text(SCENE.replace('model = "coulomb"', 'model = "ice"')
                 .replace("mass = 100.0", "mass = -1")
                 .replace("radius = 0.03", "radius = 0")
                 .replace('side = "left"', 'side = "up"'))
    with pytest.raises(InputError) as e:
        read_scene(p)
    msg = str(e.value)
    for part in ("ground.model must be one of", "object[1].mass must be a number > 0",
                 "obstacle[1].radius must be a number > 0", "object[1].touching.side"):
        assert part in msg
    assert "\n" not in msg


def test_a_problem_of_the_one_ground_is_named_once_and_a_touching_offset_on_its_link(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text(SCENE.replace("mu = 0.3", "mu = -0.3"))
    with pytest.raises(InputError) as e:
        read_scene(p)
    assert str(e.value).count("ground.mu must be") == 1, str(e.value)
    robot = Robot(joints=2, length=0.2)
    for offset in (-0.01, 0.21, 5.0):  # beyond the link: the object would not touch it
        box = SceneObject(shape="box", size=(0.1, 0.1), mass=1.0,
                          touching={"link": 2, "offset": offset, "side": "left"})
        with pytest.raises(InputError, match=r"object\[1\]\.touching\.offset must be within "
                           r"link 2, 0 to 0\.2 m from its rear end, got " + str(offset)):
            GeneralScene(robot, objects=(box,))
    for offset in (0.0, 0.2):
        box = SceneObject(shape="box", size=(0.1, 0.1), mass=1.0,
                          touching={"link": 2, "offset": offset, "side": "left"})
        assert GeneralScene(robot, objects=(box,)).objects[0].touching["offset"] == offset


def test_ground_lists_per_link(tmp_path):
    p = tmp_path / "s.toml"
    p.write_text(SCENE.replace('model = "coulomb"',
                               'model = ["wheels", "coulomb", "anisotropic", "frictionless"]'))
    s = read_scene(p)
    assert [g.model for g in s.ground] == ["wheels", "coulomb", "anisotropic", "frictionless"]
    p.write_text(SCENE.replace('model = "coulomb"', 'model = ["wheels", "coulomb"]'))
    with pytest.raises(InputError, match="must have 4 entries"):
        read_scene(p)


def test_the_paper_scene_as_a_general_one():
    s = GeneralScene.from_scene(Scene(Robot(joints=2), scenario="wheels", kappa=50,
                                      contact_link=2, side="right"))
    assert [g.model for g in s.ground] == ["wheels", "frictionless", "wheels"]
    o = s.objects[0]
    assert o.shape == "disc" and o.radius == 0.05 and o.mass == 50.0
    assert o.touching == {"link": 2, "offset": 0.075, "side": "right"}


@pytest.mark.parametrize("a,b", [
    (Shape("segment", [[0, 0], [1, 0]], 0.1), Shape("point", [[0.5, 0.5]], 0.2)),
    (Shape("segment", [[0, 0], [1, 0.3]], 0.05), Shape("polygon", box_corners((0.4, 0.6),
                                                                               (0.3, 0.2), 0.4))),
    (Shape("polygon", box_corners((0, 0), (0.2, 0.1), 0.3)),
     Shape("polygon", box_corners((0.5, 0.2), (0.2, 0.3), -0.7))),
    (Shape("segment", [[0, 0], [1, 0.2]], 0.0), Shape("segment", [[0.2, 0.5], [0.9, 1.5]], 0)),
])
def test_closest_points_against_dense_sampling(a, b):
    """The distance against the nearest pair of points sampled densely on the two shapes'
    boundaries (an independent estimate, accurate to the sampling's spacing squared)."""

    def boundary(sh, k=4000):
        if sh.kind == "point":
            t = np.linspace(0, 2 * np.pi, k, endpoint=False)
            return sh.pts[0] + sh.radius * np.c_[np.cos(t), np.sin(t)]
        pts = []
        for s0, s1 in sh.segments():
            u = np.linspace(0, 1, k)[:, None]
            line = s0 + u * (s1 - s0)
            if sh.radius > 0:
                t = np.linspace(0, 2 * np.pi, 64, endpoint=False)
                ring = sh.radius * np.c_[np.cos(t), np.sin(t)]
                line = (line[:, None, :] + ring[None]).reshape(-1, 2)
            pts.append(line)
        return np.concatenate(pts)

    pa, pb = boundary(a), boundary(b)
    from scipy.spatial import cKDTree

    ref = cKDTree(pb).query(pa)[0].min()
    d, pairs = closest(a, b, 1.0)
    assert d == pytest.approx(ref, abs=2e-3 * max(a.radius, b.radius, 0.05))
    for ca, cb, n in pairs:
        assert np.hypot(*n) == pytest.approx(1.0)
        assert np.allclose(cb - ca, d * n, atol=1e-12)


def test_flush_box_gives_two_contacts():
    robot = Robot(joints=1)
    box = SceneObject(shape="box", size=(0.1, 0.04), mass=2.0,
                      touching={"link": 1, "offset": 0.075, "side": "left"})
    import snakecg

    res = snakecg.load(GeneralScene(robot, objects=(box,))).forward([0, 0, 0.3, 0.2], [0.5])
    assert len(res.contacts) == 2
    pts = np.array([c["point"] for c in res.contacts])
    assert np.hypot(*(pts[0] - pts[1])) == pytest.approx(0.1)


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "snakecg.cli", *args], capture_output=True,
                          text=True, timeout=600)


def test_cli_forward_and_plot_take_a_scene(tmp_path):
    p = tmp_path / "s.toml"
    p.write_text(SCENE)
    r = _cli("forward", "--scene", str(p), "--q", "0,0,0,0.3,-0.3,0.2", "--tau", "0.1,0,0",
             "--json")
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    assert {"qdd", "a_obj", "sr", "contacts", "objects", "ground", "certificate"} <= set(out)
    assert len(out["contacts"]) == 2 and out["contacts"][0]["bodies"] == ["link 1", "object 1"]
    # the text: counts with their nouns, one line per ground set with its force as in the JSON
    r = _cli("forward", "--scene", str(p), "--q", "0,0,0,0.3,-0.3,0.2", "--tau", "0.1,0,0")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert lines[0] == "3 joints, 1 object, 1 obstacle, 2 contacts", lines[0]
    ground = [ln for ln in lines if ln.startswith("  ground under ")]
    assert len(ground) == len(out["ground"])
    for ln, g in zip(ground, out["ground"]):
        body = f"link {g['link']}" if "link" in g else f"object {g['object']}"
        assert ln.startswith(f"  ground under {body} ({g['model']}): force ["), ln
        shown = [float(x) for x in ln.split("[")[1].split("]")[0].split()]
        assert np.allclose(shown, g["force"], rtol=1e-5, atol=1e-6) and ln.endswith(g["state"])
    assert "-0. " not in r.stdout and "-0.]" not in r.stdout
    r = _cli("plot", "--scene", str(p), "--q", "0,0,0,0.3,-0.3,0.2", "--tau", "0.1,0,0",
             "--out", str(tmp_path / "s.png"))
    assert r.returncode == 0, r.stderr and (tmp_path / "s.png").stat().st_size > 0
    bad = tmp_path / "bad.toml"
    bad.write_text(SCENE.replace("mass = 100.0", "mass = 0"))
    r = _cli("forward", "--scene", str(bad), "--q", "0,0,0,0,0,0", "--tau", "0,0,0")
    assert r.returncode == 2 and "object[1].mass" in r.stderr and "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
    # optimize takes a general scene (tests/test_scenes_optimize.py); optimize-shape does not
    r = _cli("optimize", "max_sr", "--scene", str(p), "--q", "0,0,0,0.3,-0.3,0.2",
             "--tau-max", "1", "--json")
    assert r.returncode == 1 and r.stderr == "", r.stderr  # links may slide: a search
    out = json.loads(r.stdout)
    assert out["status"] == "local" and len(out["tau"]) == 3
    assert max(abs(x) for x in out["tau"]) <= 1.0 + 1e-12
    assert 0.0 <= out["analysis"]["sr"] <= 1.0
    r = _cli("optimize-shape", "max-sr", "--scene", str(p))
    assert r.returncode == 2 and "--scene" in r.stderr and "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
    # simulate takes a general scene (tests/test_scenes_stepping.py)
    r = _cli("simulate", "--scene", str(p), "--q", "0,0,0,0,0,0", "--tau", "0,0,0",
             "--duration", "0.01", "--out", str(tmp_path / "run"))
    assert r.returncode == 0, r.stderr


def test_parameters_beyond_double_precision_are_refused_by_name(tmp_path):
    """A robot's or scene's parameter whose products (m l^2, its inverse, the norms'
    squares) would leave double precision is refused before any work, by name; a robot whose
    parameters span more orders of magnitude than the input metric resolves is refused by
    the queries on that metric (one line on the command line), and answered as singular by
    the forward."""
    with pytest.raises(InputError, match=r"length must be at most 1e\+50 in magnitude"):
        Robot(joints=2, length=1e60)
    robot = Robot(joints=2)
    with pytest.raises(InputError, match=r"object\[1\]\.mass must be at most 1e\+50"):
        GeneralScene(robot, objects=(SceneObject(shape="disc", radius=0.04, mass=1e300,
                                                 pose=(0.5, 0.5, 0.0)),))
    with pytest.raises(InputError, match=r"obstacle\[1\]\.center must be at most 1e\+50"):
        GeneralScene(robot, obstacles=(Obstacle(shape="peg", center=(1e60, 0.0),
                                                radius=0.03),))
    p = tmp_path / "big.toml"
    p.write_text(SCENE.replace("length = 0.15", "length = 1e308"))
    r = _cli("forward", "--scene", str(p), "--q", "0,0,0,0,0,0", "--tau", "0.1,0,0", "--json")
    assert r.returncode == 2 and "length must be at most 1e+50" in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and "Traceback" not in r.stderr
    # finite products, but m l^2 = 1e40 against inertias of 2e-3: N is singular in doubles
    p.write_text(SCENE.replace("length = 0.15", "length = 1e20"))
    for args in (("optimize", "strongest-push", "--direction", "1,0"),
                 ("optimize", "max-sr")):
        r = _cli(*args, "--scene", str(p), "--q", "0,0,0,0,0,0", "--json")
        assert r.returncode == 2 and "N = B^T M_s^-1 B" in r.stderr, r.stderr
        assert len(r.stderr.strip().splitlines()) == 1
    model = snakecg.load(read_scene(p))
    assert model.forward(np.zeros(6), np.array([0.1, 0, 0])).status != 0
    ex = model.extremes(np.zeros((2, 6)))
    assert np.all(np.isnan(ex.max["sr"])) and all("N = B^T M_s^-1 B" in x for x in ex.reason)


def test_api_inputs_are_checked_by_name():
    import snakecg

    robot = Robot(joints=1)
    disc = SceneObject(shape="disc", radius=0.03, mass=1.0,
                       touching={"link": 1, "offset": 0.075, "side": "left"})
    model = snakecg.load(GeneralScene(robot, objects=(disc,)))
    with pytest.raises(InputError, match="f_obj"):
        model.forward([0.0] * 4, [0.0], f_obj=[1.0, 2.0])
    with pytest.raises(InputError, match="tau"):
        model.forward([0.0] * 4, [0.0, 1.0])
    with pytest.raises(InputError, match="at rest"):
        model.forward([0.0] * 4, [0.0], v=[0.0, 0.0, 0.0, 1.0])
    with pytest.raises(InputError, match=r"ground must be one Ground or a list of 2"):
        GeneralScene(robot, ground=(Ground(),))
    with pytest.raises(InputError, match="exactly one of pose"):
        GeneralScene(robot, objects=(SceneObject(shape="disc", radius=0.1),))


def test_forces_beyond_double_precision_are_refused_or_flagged():
    """Torques and wrenches beyond 1e150 are refused by name before any work (the paper's
    path's bound: the norms are quadratic in them); within it, a scene whose masses make the
    accelerations overflow (a = tau / m beyond 1e308) answers NaN with status overflow."""
    import snakecg

    robot = Robot(joints=2)
    box = SceneObject(shape="box", size=(0.1, 0.1), mass=1.0,
                      touching={"link": 2, "offset": 0.075, "side": "left"})
    model = snakecg.load(GeneralScene(robot, objects=(box,)))
    q = np.zeros(5)
    with pytest.raises(InputError, match=r"tau must have every entry within \+-1e\+150 .* "
                       r"found 2\.000e\+150 at index \(0, 1\)"):
        model.forward(q, np.array([1.0, 2e150]))
    T = np.ones((4, 2))
    T[2, 0] = -1e300
    with pytest.raises(InputError, match=r"tau .* found -1\.000e\+300 at index \(2, 0\)"):
        model.forward(np.zeros((4, 5)), T)
    with pytest.raises(InputError, match=r"f_obj must have every entry within \+-1e\+150"):
        model.forward(q, np.ones(2), f_obj=[[0.0, 1e151, 0.0]])
    assert model.forward(q, np.array([1e150, -1e150])).status == 0  # (the bound itself)
    light = Robot(joints=2, mass=1e-200, inertia=1e-203)
    tiny = SceneObject(shape="box", size=(0.1, 0.1), mass=1e-200,
                       touching={"link": 2, "offset": 0.075, "side": "left"})
    res = snakecg.load(GeneralScene(light, objects=(tiny,))).forward(q, np.array([1e150, 1.0]))
    assert res.status == 8 and "overflowed" in res.reason[0]
    assert np.isnan(res.qdd).all() and np.isnan(res.a_obj).all()
    assert all(np.isnan(x) for x in (res.sr, res.norm_lambda, res.norm_qdd, res.norm_a_obj))
    assert repr(res).startswith("SceneResult(status='overflow'")


def test_a_base_too_far_for_the_contacts_tolerance_is_refused_by_name():
    """At x = 1e300 every body rounds to one point: every pair touched and the forces were
    NaN with status solved. A base farther than a million scene sizes (where the contacts'
    geometry rounds to 1 % of their tolerance) is refused before any work, everywhere."""
    import snakecg
    from snakecg.scenes.packing import scene_size

    robot = Robot(joints=2)
    peg = Obstacle(shape="peg", center=(0.2, 0.05), radius=0.03)
    scene = GeneralScene(robot, obstacles=(peg,))
    model = snakecg.load(scene)
    lim = 1e6 * scene_size(scene)
    Q = np.zeros((3, 5))
    Q[1, 1] = -1.01 * lim
    msg = re.escape(f"q: the base position (x, y) must be within +-{lim:.3g} m")
    with pytest.raises(InputError, match=msg + r".* at index \(1, 1\)"):
        model.forward(Q, np.zeros((3, 2)))
    far = np.array([1e300, 0.0, 0.0, 0.0, 0.0])
    for call in (lambda: model.forward(far, np.zeros(2)), lambda: model.maps(far),
                 lambda: model.extremes(far), lambda: model.simulate(far, 0.01)):
        with pytest.raises(InputError, match=msg):
            call()
    with pytest.raises(InputError, match=r"v0 must have every entry within \+-1e\+75"):
        model.simulate(np.zeros(5), 0.01, v0=[0.0, 0.0, 0.0, 1e80, 0.0])
    with pytest.raises(InputError, match=r"the state is not finite at t = .* s: it overflowed"):
        model.simulate(np.zeros(5), 0.01, tau=[1e149, 0.0])  # (a = 1e149 m/s^2: V^2 overflows)
    near = np.array([0.99 * lim, -0.99 * lim, 0.3, 0.0, 0.0])
    res = model.forward(near, np.array([0.1, -0.2]))  # alone there: no contact
    assert res.status == 0 and len(res.contacts) == 0


def test_snakecg_plot_draws_a_general_scene():
    import matplotlib

    matplotlib.use("Agg")
    import snakecg

    robot = Robot(joints=2)
    scene = GeneralScene(robot, radius=0.01, ground=Ground(model="coulomb", mu=0.3),
                         objects=(SceneObject(shape="box", size=(0.1, 0.05), mass=2.0,
                                              touching={"link": 2, "offset": 0.075,
                                                        "side": "left"}),),
                         obstacles=(Obstacle(shape="wall", point=(0.0, -0.3),
                                             normal=(0.0, 1.0)),))
    ax = snakecg.plot(scene, [0.0, 0.0, 0.0, 0.3, -0.3], [0.2, 0.1])
    gids = {a.get_gid() for a in ax.get_children() if a.get_gid()}
    assert {"link1", "object1", "obstacle1", "contact_normals", "force_contacts",
            "acc_links"} <= gids
    assert "2 contacts" in ax.get_title()
