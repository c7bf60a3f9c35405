"""Optimal torques on a general scene (snakecg.scenes.optimize): the pushes against a conic
reference in cvxpy (Clarabel) that enumerates the contact states itself over a dense model of
the accelerations and forces, max_sr against dense forward samples and the paper's own path,
and the sliding (search) answers checked by the forward solve."""

from __future__ import annotations

import itertools
import json

import numpy as np
import pytest

import snakecg
from snakecg import Robot, Scene
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, Ground, SceneObject
from snakecg.scenes.solve import BOX, DISC, FREE, UNILATERAL
from snakecg.scenes.toml_reading import read_scene

from scenes_reference import POLYHEDRAL, dense_problem, small_scenes

cp = pytest.importorskip("cvxpy")


def clarabel_push(p, ns, objective, obj, d, a_min=None, radius=None, tau_max=None,
                  a_obj=None):
    """The best value of the push over every contact state (held: the row still, its force
    >= 0; open: no force, the row separating), every wheel and friction set sticking: one
    conic problem per state in cvxpy, solved by Clarabel."""
    A, M = p["A"], p["M"]
    n, m = M.shape[0], A.shape[0]
    na = ns - 3
    N = np.linalg.inv(M[:ns, :ns])[3:, 3:]
    Lc = np.linalg.cholesky(N)
    contacts = [b for b, (k, _, _) in enumerate(p["blocks"]) if k == UNILATERAL]
    best = None
    for held in itertools.product((True, False), repeat=len(contacts)):
        tau, a, lam = cp.Variable(na), cp.Variable(n), cp.Variable(m)
        B = np.zeros((n, na))
        B[3:ns] = np.eye(na)
        cons = [M @ a == B @ tau + A.T @ lam]
        for b, (kind, s, par) in enumerate(p["blocks"]):
            if kind == UNILATERAL:
                if held[contacts.index(b)]:
                    cons += [A[s] @ a == 0, lam[s] >= 0]
                else:
                    cons += [lam[s] == 0, A[s] @ a >= 0]
            elif kind == FREE:
                cons.append(A[s] @ a == 0)
            elif kind == BOX:
                cons += [A[s] @ a == 0, cp.abs(lam[s]) <= par[0] * (1 - 1e-7)]
            elif kind == DISC:
                cons += [A[s:s + 2] @ a == 0, cp.norm(lam[s:s + 2]) <= par[0] * (1 - 1e-7)]
        if radius is not None:
            cons.append(cp.norm(Lc.T @ tau) <= radius)
        if tau_max is not None:
            cons.append(cp.abs(tau) <= tau_max)
        ao = a[ns + 3 * obj:ns + 3 * obj + 3]
        if objective == "strongest_push":
            prob = cp.Problem(cp.Maximize(d @ ao), cons)
        else:
            cons.append(d @ ao >= a_min if a_obj is None else ao == a_obj)
            Ls = np.linalg.cholesky(M[:ns, :ns])
            prob = cp.Problem(cp.Minimize(cp.sum_squares(Ls.T @ a[:ns])), cons)
        try:
            prob.solve(solver="CLARABEL", tol_gap_abs=1e-10, tol_gap_rel=1e-10, tol_feas=1e-10)
        except cp.error.SolverError:  # (an equality no torque meets on this state)
            continue
        if prob.status == "optimal":
            v = prob.value
            if best is None or (v > best if objective == "strongest_push" else v < best):
                best = v
    return best


@pytest.mark.parametrize("models,radius", [(POLYHEDRAL, 1.0),
                                           (("coulomb", "wheels", "frictionless"), 20.0)])
def test_pushes_against_clarabel(models, radius, rng):
    """Every contact state enumerated by the reference; links sticking (allow_slide=False:
    a Coulomb set is a second-order cone)."""
    pushed = 0
    for model, q, res in small_scenes(rng, 12, models, object_friction=False,
                                      need_object=True):
        p = dense_problem(res, model, np.zeros(model.n_joints))
        ns = model.n_coordinates
        d = rng.normal(size=2)
        d = np.r_[d / np.linalg.norm(d), 0.0]
        ref = clarabel_push(p, ns, "strongest_push", 0, d, radius=radius)
        got = model.optimize(q, "strongest_push", direction=d[:2], allow_slide=False,
                             radius=radius)
        assert got.status == "optimal", got.reason
        assert got.objective_value == pytest.approx(ref, rel=1e-5, abs=1e-8)
        if ref > 1e-6:
            pushed += 1
            a_min = 0.5 * ref
            ref2 = clarabel_push(p, ns, "least_slip_push", 0, d, a_min=a_min, radius=radius)
            got2 = model.optimize(q, "least_slip_push", direction=d[:2], a_min=a_min,
                                  allow_slide=False, radius=radius)
            assert got2.status == "optimal", got2.reason
            assert got2.objective_value == pytest.approx(ref2, rel=1e-5, abs=1e-10)
            assert d @ got2.analysis.a_obj[0] >= a_min * (1 - 1e-6)
    assert pushed >= 3


def test_a_push_no_torque_changes_on_a_piece_is_checked_not_passed_to_ipopt():
    """Three objects on a frictionless 1-joint snake: on some contact states the pushed
    object's acceleration does not depend on the torque, and CasADi refuses a constant
    condition (it raised RuntimeError out of optimize). Those pieces are decided by the
    condition's value; the answer is Clarabel's over every contact state."""
    robot = Robot(joints=1, mass=(0.5179040453259469, 1.4963516062092332),
                  length=(0.19373994546517515, 0.11652964384607623),
                  inertia=(0.0017896647044172655, 0.0011250885138521139))
    objects = (SceneObject(shape="box", size=(0.06134934472601476, 0.046407417831574),
                           mass=8.066406127719972,
                           touching={"link": 2, "offset": 0.022304617650974978,
                                     "side": "left"}),
               SceneObject(shape="disc", radius=0.049693793692157956, mass=40.28983888549939,
                           touching={"link": 1, "offset": 0.15623557730675847,
                                     "side": "left"}),
               SceneObject(shape="disc", radius=0.05589945518532717, mass=44.799812053157666,
                           touching={"link": 2, "offset": 0.05022891599725762,
                                     "side": "right"}))
    model = snakecg.load(GeneralScene(robot, ground=Ground(model="frictionless"),
                                      objects=objects))
    q = np.array([0.23049326381128246, -0.6055586165587867, 1.7853796198919296,
                  -1.1827608386171597])
    d = np.array([-0.3395352074108784, 0.9405933462067716, 0.0])
    a_min = 1.1010182993397373
    got = model.optimize(q, "least_slip_push", direction=d[:2], a_min=a_min, tau_max=3.0,
                         allow_slide=False)
    assert got.status == "optimal", got.reason
    p = dense_problem(model.forward(q, np.zeros(1)), model, np.zeros(1))
    ref = clarabel_push(p, model.n_coordinates, "least_slip_push", 0, d, a_min=a_min,
                        tau_max=np.array([3.0]))
    assert got.objective_value == pytest.approx(ref, rel=1e-5)
    assert d[:2] @ got.analysis.a_obj[0][:2] >= a_min * (1 - 1e-6)


ONE_JOINT_TWO_OBJECTS = """
[robot]
joints = 1
length = 0.15
mass = 1.0
inertia = 0.002

[ground]
model = "frictionless"

[[object]]
shape = "box"
size = [0.08, 0.06]
mass = 1.5
touching = { link = 1, offset = 0.075, side = "left" }

[[object]]
shape = "disc"
radius = 0.04
mass = 1.0
touching = { link = 2, offset = 0.1, side = "right" }
"""


def test_a_full_object_acceleration_asked_of_one_joint(tmp_path):
    """a_obj (three entries) asked of a 1-joint snake: the equality is taken on the range of
    the torque's map (else IPOPT has too few degrees of freedom and CasADi warned on every
    piece, on standard error). Reachable: the torque that gives it, Clarabel's value; not
    reachable: infeasible; the command line's standard error stays empty."""
    import subprocess
    import sys

    p = tmp_path / "s.toml"
    p.write_text(ONE_JOINT_TWO_OBJECTS)
    model = snakecg.load(read_scene(p))
    q = np.array([0.0, 0.0, 0.0, 0.3])
    for t in (0.05, -0.05, 0.2):
        a = model.forward(q, np.array([t])).a_obj[0]
        got = model.optimize(q, "least_slip_push", a_obj=tuple(a), tau_max=1.0,
                             allow_slide=False)
        assert got.status == "optimal", got.reason
        assert got.tau[0] == pytest.approx(t, rel=1e-6)
        dp = dense_problem(model.forward(q, np.zeros(1)), model, np.zeros(1))
        ref = clarabel_push(dp, model.n_coordinates, "least_slip_push", 0, None,
                            tau_max=np.array([1.0]), a_obj=a)
        assert got.objective_value == pytest.approx(ref, rel=1e-5)
    r = subprocess.run([sys.executable, "-m", "snakecg.cli", "optimize", "least-slip-push",
                        "--scene", str(p), "--q", "0,0,0,0.3", "--a-obj", "0.1,0,0",
                        "--json"], capture_output=True, text=True, timeout=600)
    assert r.returncode == 1 and r.stderr == "", r.stderr[:300]
    assert json.loads(r.stdout)["status"] == "infeasible"


def test_paper_scene_through_the_general_path_matches_its_optimizer(rng):
    """The paper's wheels scene: the general optimizer against the paper's own (a second
    path), and max_sr against dense forward samples with every wheel sticking."""
    scene = Scene(Robot(joints=3), scenario="wheels")
    gen, paper = snakecg.load(GeneralScene.from_scene(scene)), snakecg.load(scene)
    for _ in range(3):
        q = np.r_[0.0, 0.0, 0.0, rng.uniform(-1.2, 1.2, 3)]
        r1, r2 = gen.optimize(q, "max_sr"), paper.optimize(q, "max_sr", tau_max=None)
        assert r1.status == "optimal" and r2.status == "optimal"
        assert r1.objective_value == pytest.approx(r2.objective_value, abs=1e-9)
        M = gen.mass_matrix(q)
        N = np.linalg.inv(M)[3:, 3:]
        t = rng.normal(size=(3000, 3))
        t /= np.sqrt(np.einsum("ki,ij,kj->k", t, N, t))[:, None]
        t *= rng.uniform(0, 1, (3000, 1))
        res = gen.forward(np.repeat(q[None], 3000, axis=0), t)
        stick = np.array([all(g["state"] in ("stick", "none") for g in gr)
                          for gr in res.ground])
        assert res.sr[stick].max() <= r1.objective_value + 1e-9
        for obj, kw in (("strongest_push", {"tau_max": 0.3}),
                        ("least_slip_push", {"direction": [0, 1], "a_min": 0.002,
                                             "tau_max": 0.3})):
            if obj == "strongest_push":
                a = paper.optimize(q, obj, tau_max=0.3).analysis.a_obj[:2]
                kw["direction"] = a / np.linalg.norm(a)
            g, pp = gen.optimize(q, obj, **kw), paper.optimize(q, obj, **kw)
            assert g.status == pp.status
            if g.status == "optimal":
                assert g.objective_value == pytest.approx(pp.objective_value, rel=1e-5,
                                                          abs=1e-10)


def test_sliding_links_are_searched_and_checked():
    """Coulomb ground: the snake moves by sliding; the answer is a search ('local'), its
    value the forward solve's own at tau, inside the limits, the task met."""
    model = snakecg.load(read_scene("examples/scenes/wall_push.toml"))
    q = np.zeros(6)
    r = model.optimize(q, "least_slip_push", direction=[0, 1], a_min=0.1, tau_max=2.0)
    assert r.status == "local" and "not certified" in r.reason
    assert np.all(np.abs(r.tau) <= 2.0 + 1e-12)
    assert r.analysis.a_obj[0][1] >= 0.1 and r.objective_value == r.analysis.norm_qdd
    s = model.optimize(q, "strongest_push", direction=[0, 1], tau_max=2.0)
    assert s.status == "local" and s.objective_value >= 0.1
    # allow_slide=False: every link sticks; the conic pieces say no push is possible
    stuck = model.optimize(q, "strongest_push", direction=[0, 1], tau_max=2.0,
                           allow_slide=False)
    assert stuck.status in ("local", "optimal")
    assert stuck.objective_value <= s.objective_value + 1e-9
    assert all(g["state"] in ("stick", "none") for g in stuck.analysis.ground
               if g.get("link"))


def test_bad_queries_are_refused_before_any_work():
    model = snakecg.load(read_scene("examples/scenes/two_objects.toml"))
    q = [0, 0, 0, 0.6, -0.6, 0.6]
    with pytest.raises(InputError, match=r"object must be an object number 1\.\.2"):
        model.optimize(q, "strongest_push", object=3, direction=[0, 1])
    with pytest.raises(InputError, match="least_slip_push needs a task"):
        model.optimize(q, "least_slip_push")
    with pytest.raises(InputError, match="strongest_push needs a direction"):
        model.optimize(q, "strongest_push")
    with pytest.raises(InputError, match="objective must be one of"):
        model.optimize(q, "fastest")
    with pytest.raises(InputError, match="a_obj .* needs every link's set sticking"):
        model.optimize(q, "least_slip_push", a_obj=[0, 0.1, 0])
    pegs = snakecg.load(read_scene("examples/scenes/pegs.toml"))
    with pytest.raises(InputError, match="needs an object in the scene"):
        pegs.optimize(q, "max_sr")
