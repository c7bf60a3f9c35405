"""max_sr on general scenes at two edges, against Clarabel on a dense model of the scene
(scenes_reference.clarabel_accelerations: the Gauss problem, written apart from the solve):

* a box flush on a link beside pegs makes the held rows dependent: the answer's torque must
  keep every link's set sticking (the scale to the limits read one member of the forces,
  which pulled at a contact, and the forward check said ``failed``);
* torque limits too small to move an object whose own ground friction holds it: every piece
  is empty, which IPOPT could not tell on the pieces where that object slides (``failed``);
* an object that may slide on its own ground friction: IPOPT's ratio on the pieces where it
  sticks went to a torque of 4e-10 N m, where every condition holds within IPOPT's absolute
  tolerances, and the forward check said ``failed`` (0.120 against the piece's 0.340);
* a box flush on a link (dependent rows) and a link's anisotropic set that starts to slide
  by less than the solve's tolerance (relative to the largest set, an object's): the scale
  along the ray took that torque as sticking and sr was already 0.3 % off (``failed``)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import snakecg
from snakecg import Robot
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject
from snakecg.scenes.solve import BOX, DISC, SPLIT

from scenes_reference import clarabel_accelerations, dense_problem

pytest.importorskip("cvxpy")


def _robot(mass, length, inertia):
    return Robot(joints=len(mass) - 1, mass=mass, length=length, inertia=inertia)


def _scene_flush_box():
    robot = _robot((0.8552157598941496, 1.7019116978095954, 1.3732430540965517,
                    0.6411929633605988),
                   (0.14331269402364738, 0.1479051298140834, 0.11597389146370786,
                    0.17345771514092145),
                   (0.0013410160597642103, 0.002173684571486986, 0.002550220547864091,
                    0.0022918840612425337))
    ground = (Ground(model="frictionless"), Ground(model="coulomb", mu=0.2109964119568679),
              Ground(model="coulomb", mu=0.5404410887448364),
              Ground(model="wheels", mu=0.2558341084131589,
                     wheel_offset=-0.017568529915139925))
    box = SceneObject(shape="box", size=(0.05677456951414635, 0.03179835438632742),
                      mass=9.424233271733211,
                      touching={"link": 1, "offset": 0.07874284085835788, "side": "left"})
    pegs = tuple(Obstacle(shape="peg", center=c, radius=r) for c, r in (
        ((0.052740258642254435, 0.8534310804678726), 0.014092796876882977),
        ((0.05156686030495214, 0.9169539290751094), 0.01585338279032794),
        ((0.032632854727531906, 0.7646312811503598), 0.044845565991743566)))
    q = np.array([0.09151670328235219, 0.6701043548284794, 1.519002020124132,
                  0.5331955395410819, -0.6750829810348691, 0.7917284982583495])
    return GeneralScene(robot, ground=ground, objects=(box,), obstacles=pegs), q, 0.5


def _scene_heavy_disc():
    robot = _robot((1.3759727288514352, 0.59520493736899, 0.9927624384970846,
                    1.411045644697602),
                   (0.16376769769234967, 0.14936091155193737, 0.16731978902207906,
                    0.11819117554838314),
                   (0.001906303020897483, 0.0020774144692882897, 0.0021921400543396235,
                    0.0013544677156445506))
    ground = (Ground(model="coulomb", mu=0.08694089096112537),
              Ground(model="coulomb", mu=0.3508028260250204), Ground(model="frictionless"),
              Ground(model="coulomb", mu=0.22850015170919974))
    disc = SceneObject(shape="disc", radius=0.058794588200377584, mass=30.071148177710615,
                       mu=0.32502269784512927,
                       touching={"link": 4, "offset": 0.05006961763143633, "side": "right"})
    peg = Obstacle(shape="peg", center=(1.7683842444260562, -0.4193065255915541),
                   radius=0.048973267840629324)
    q = np.array([1.6027634061447278, -0.6411354470284832, 0.45591365571078724,
                  0.6517806687562111, -0.9953188381614265, -0.7241152968676414])
    return GeneralScene(robot, ground=ground, objects=(disc,), obstacles=(peg,)), q, 0.05


def _scene_two_discs():
    robot = _robot((0.9703507066621369, 0.9259166189817085, 0.5570369576885752),
                   (0.15641399670824452, 0.17355912247095756, 0.17296290344748638),
                   (0.0038450888501069475, 0.003457541600628893, 0.002578011465067754))
    ground = (Ground(model="ideal_wheels", wheel_offset=0.00015341107311684157),
              Ground(model="coulomb", mu=0.5284293187190451),
              Ground(model="coulomb", mu=0.22121566448288676))
    objects = (SceneObject(shape="disc", radius=0.044189590175901614, mass=44.062493329274574,
                           mu=0.34371310343572237,
                           touching={"link": 3, "offset": 0.02042013139299756,
                                     "side": "right"}),
               SceneObject(shape="disc", radius=0.031883374697713865, mass=39.46037920986185,
                           touching={"link": 2, "offset": 0.04187105882173765,
                                     "side": "right"}))
    peg = Obstacle(shape="peg", center=(-0.19640395137325883, -2.2476558278086904),
                   radius=0.04052375718536825)
    q = np.array([-0.0833388012320119, -2.087437366645121, -2.331284822761952,
                  -0.10522014188878548, -0.027615189655070704])
    return GeneralScene(robot, ground=ground, objects=objects, obstacles=(peg,)), q, 0.05


def _scene_sliding_object():
    robot = _robot((1.0768806731459948, 1.0519313797951957, 1.3945529921526838),
                   (0.18307655298497244, 0.10459250492472597, 0.11579023809370018),
                   (0.003846061580595479, 0.003042624938226542, 0.002986035262999499))
    ground = (Ground(model="ideal_wheels", wheel_offset=-0.009457975040213108),
              Ground(model="frictionless"),
              Ground(model="wheels", mu=0.513248824060886, wheel_offset=0.012484733134225622))
    objects = (SceneObject(shape="disc", radius=0.04266486575146265, mass=28.79435188538917,
                           touching={"link": 1, "offset": 0.09234005106890181,
                                     "side": "right"}),
               SceneObject(shape="box", size=(0.05100229301037387, 0.036517578358602906),
                           mass=11.03025243500924,
                           touching={"link": 3, "offset": 0.060772384164873273,
                                     "side": "left"}),
               SceneObject(shape="disc", radius=0.02821084343516636, mass=10.944605251075078,
                           mu=0.2791039468703105,
                           touching={"link": 2, "offset": 0.0730016591849396, "side": "left"}))
    peg = Obstacle(shape="peg", center=(2.169741954441701, -1.0897089516969283),
                   radius=0.03959074203368931)
    q = np.array([2.2364622867192825, -1.08057426201449, 0.7645235110261921,
                  -0.20691243421730587, -0.8169560330636769])
    return GeneralScene(robot, ground=ground, objects=objects, obstacles=(peg,)), q, 0.05


def _scene_flush_box_anisotropic():
    robot = _robot((1.3901158169347585, 1.4904866171339741, 1.2821844328926568),
                   (0.11561632192183742, 0.14956204270267082, 0.1284961212224372),
                   (0.001313787734432316, 0.0016103338122336864, 0.003275780727789544))
    ground = (Ground(model="frictionless"),
              Ground(model="anisotropic", mu_forward=0.270259222406368,
                     mu_backward=0.3568722068637149, mu_lateral=0.6016210709758053),
              Ground(model="anisotropic", mu_forward=0.18492134820431438,
                     mu_backward=0.07255462235820839, mu_lateral=0.5070428901491286))
    objects = (SceneObject(shape="box", size=(0.037376721492481474, 0.023475042980635755),
                           mass=43.50831598792518,
                           touching={"link": 1, "offset": 0.09466169023793972,
                                     "side": "left"}),
               SceneObject(shape="disc", radius=0.035031196570805986, mass=25.200564178298837,
                           mu=0.19308282796708048,
                           touching={"link": 3, "offset": 0.10970545166199831,
                                     "side": "left"}))
    q = np.array([-0.13578915049305734, 0.004231402255222685, 0.7949527477291713,
                  0.3073852411621085, 0.014951031588471109])
    return GeneralScene(robot, ground=ground, objects=objects), q, 0.05


def _reference(model, q, tau, up=1.0):
    """Clarabel's accelerations at tau, sr from them, and the largest acceleration of a
    link's sticking rows (wheels and Coulomb sets: zero where the link sticks). ``up``: the
    problem solved with the applied force and the sets' sizes times ``up`` and the
    accelerations divided by it (the problem is positively homogeneous at rest: the same
    answer, within Clarabel's absolute tolerances where the torques are small)."""
    res = model.forward(q, tau)
    p = dense_problem(res, model, tau)
    p = dict(p, a_free=p["a_free"] * up, f=p["f"] * up,
             blocks=[(k, r, tuple(np.asarray(par, float) * up)) for k, r, par in p["blocks"]])
    a, status = clarabel_accelerations(p)
    assert status == "optimal"
    a = a / up
    ns, M = model.n_coordinates, p["M"]
    nq = a[:ns] @ M[:ns, :ns] @ a[:ns]
    no = a[ns:] @ M[ns:, ns:] @ a[ns:]
    rows = [s + i for (kind, s, _), lab in zip(p["blocks"], res._rows[0].labels)
            if lab[0] in ("wheel", "ground") and kind in (BOX, DISC, SPLIT)
            for i in range(1 if kind == BOX else 2)]
    slide = np.abs(p["A"][rows] @ a).max() if rows else 0.0
    return no / (no + nq) if no + nq > 0 else 0.0, slide, max(1.0, np.abs(a).max()), nq + no


def test_max_sr_torque_keeps_every_link_sticking_on_dependent_rows():
    scene, q, tau_max = _scene_flush_box()
    model = snakecg.load(scene)
    res = model.optimize(q, "max_sr", tau_max=tau_max, allow_slide=False)
    assert res.status == "optimal", res.reason
    # every link sticks at the answer and just inside it (Clarabel, an interior point, is
    # within about 3e-7 on the sets' boundary), sr the optimum's
    for f, tol in ((1.0, 1e-6), (0.99, 1e-9)):
        sr, slide, scale, _ = _reference(model, q, f * res.tau)
        assert slide <= tol * scale and abs(sr - res.objective_value) <= tol, (f, slide, sr)
    # the largest such torque on its ray: 0.1 % more lets a link slide
    _, slide_more, scale_more, _ = _reference(model, q, 1.001 * res.tau)
    assert slide_more > 1e-5 * scale_more
    # no sampled torque of the box with every link sticking does better (forward solve)
    rng = np.random.default_rng(7)
    T = np.vstack([rng.uniform(-tau_max, tau_max, (3000, 3)),
                   np.array(list(itertools.product((-tau_max, tau_max), repeat=3)))])
    r = model.forward(np.tile(q, (len(T), 1)), T)
    stick = np.array([all(not g["state"].startswith("slide") for g in gs if "link" in g)
                      for gs in r.ground]) & (r.status == 0)
    assert stick.sum() > 100 and r.sr[stick].max() <= res.objective_value + 1e-9


@pytest.mark.parametrize("build", [_scene_heavy_disc, _scene_two_discs])
def test_max_sr_is_infeasible_where_no_sticking_torque_moves_anything(build):
    scene, q, tau_max = build()
    model = snakecg.load(scene)
    res = model.optimize(q, "max_sr", tau_max=tau_max, allow_slide=False)
    assert res.status == "infeasible", (res.status, res.reason)
    # Clarabel at torques of the box: where every link sticks, nothing moves
    rng = np.random.default_rng(3)
    na = scene.robot.joints
    T = np.vstack([np.array(list(itertools.product((-tau_max, tau_max), repeat=na))),
                   rng.uniform(-tau_max, tau_max, (24, na))])
    sticking = 0
    for tau in T:
        _, slide, scale, motion = _reference(model, q, tau)
        if slide <= 1e-8 * scale:
            sticking += 1
            assert motion <= 1e-9  # (Clarabel to about 1e-6 in a; moving: above 1e-3)
    assert sticking >= 4


def test_max_sr_stops_where_a_set_starts_to_slide_on_dependent_rows():
    scene, q, radius = _scene_flush_box_anisotropic()
    model = snakecg.load(scene)
    res = model.optimize(q, "max_sr", tau_max=None, radius=radius, allow_slide=False)
    assert res.status == "local", (res.status, res.reason)  # (the object's sliding pieces)
    # Clarabel (its interior point blurs the set's boundary at the answer itself): 1 % inside
    # along the ray every link sticks and sr is the optimum's; 2 % beyond, a link's set
    # slides and sr has dropped to 0.74
    sr, slide, scale, _ = _reference(model, q, 0.99 * res.tau, up=1e2)
    assert abs(sr - res.objective_value) <= 1e-6 and slide <= 1e-9 * scale, (sr, slide)
    sr_more, slide_more, scale_more, _ = _reference(model, q, 1.02 * res.tau, up=1e2)
    assert slide_more > 1e-7 * scale_more and sr_more < res.objective_value - 1e-2


def test_max_sr_with_an_object_that_may_slide_answers_on_the_region_boundary():
    scene, q, radius = _scene_sliding_object()
    model = snakecg.load(scene)
    res = model.optimize(q, "max_sr", tau_max=None, radius=radius, allow_slide=False)
    # the pieces where every object sticks are cones, solved exactly; where the object slides
    # they are not convex (IPOPT): local, and the certificate says which won
    assert res.status == "local", (res.status, res.reason)
    assert "sliding_pieces" in res.certificate
    # the torque on the input ellipsoid (a dense N = B^T M_s^-1 B), not near 0
    ns = model.n_coordinates
    M = dense_problem(model.forward(q, np.zeros(2)), model, np.zeros(2))["M"]
    N = np.linalg.inv(M[:ns, :ns])[3:, 3:]
    assert res.tau @ N @ res.tau == pytest.approx(radius ** 2, rel=1e-6)
    # Clarabel's sr there is the answer's, every link sticking
    sr, slide, scale, _ = _reference(model, q, res.tau, up=1e3)
    assert abs(sr - res.objective_value) <= 1e-6 and slide <= 1e-7 * scale
    # no sampled torque of the ellipsoid with every link sticking does better
    rng = np.random.default_rng(5)
    U = rng.normal(size=(4000, 2))
    U *= (rng.uniform(0, 1, (4000, 1)) ** 0.5) / np.linalg.norm(U, axis=1, keepdims=True)
    T = np.linalg.solve(np.linalg.cholesky(N).T, U.T).T * radius
    r = model.forward(np.tile(q, (len(T), 1)), T)
    stick = np.array([all(not g["state"].startswith("slide") for g in gs if "link" in g)
                      for gs in r.ground]) & (r.status == 0)
    assert stick.sum() > 1000 and r.sr[stick].max() <= res.objective_value + 1e-9
