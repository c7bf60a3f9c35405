"""Statically indeterminate scenes: a snake whose links all rub the ground with Coulomb
friction, pressed on pegs and pushing two objects, has more held force rows than coordinates
at most torques. The forces are then not fixed by the accelerations; the solve reports the
minimum-norm ones inside the friction and contact sets. Checked against an independent conic
reference (cvxpy with Clarabel) that knows nothing of the solve's faces or null spaces."""
from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject

from scenes_reference import (clarabel_min_norm_forces, dense_problem, indeterminate_scene,
                              kkt_violations)


GROUNDS = {"coulomb": Ground(model="coulomb", mu=0.3),
           "anisotropic": Ground(model="anisotropic", mu_forward=0.1, mu_backward=0.3,
                                 mu_lateral=0.5)}


@pytest.mark.parametrize("ground", sorted(GROUNDS))
def test_indeterminate_forces_are_the_minimum_norm_ones_inside_the_sets(ground):
    """On the braced 8-joint scene (isotropic or anisotropic Coulomb friction on every link:
    more force rows than its 17 coordinates), most torques leave the held rows dependent.
    The forces are then the minimum-norm ones inside the sets (flag 1) on all but a few
    samples: equal to Clarabel's to 1e-6 of their scale and no larger in norm."""
    joints = 8
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(joints) + 5)]
    model = snakecg.load(indeterminate_scene(q, joints, GROUNDS[ground]))
    T = np.random.default_rng(7).normal(0, 0.1, (60, joints))
    flags, checked = [], 0
    for tau in T:
        res = model.forward(q, tau)
        assert res.status == 0, res.reason
        flags.append(int(res.dependent))
        if res.dependent != 1 or checked == 25:
            continue
        p = dense_problem(res, model, tau)
        lam = res._raw["lam"][0][:len(p["b"])]
        ref, status = clarabel_min_norm_forces(p, lam)
        assert status == "optimal", status
        scale = np.abs(ref).max()
        assert np.abs(lam - ref).max() <= 1e-6 * scale
        assert np.linalg.norm(lam) <= np.linalg.norm(ref) * (1 + 1e-9)
        checked += 1
    flags = np.bincount(flags, minlength=3)
    assert checked == 25
    assert flags[1] + flags[2] >= 40, flags  # (the scene is indeterminate at most torques)
    assert flags[2] <= 3, flags  # (a basic solution kept: the Newton gave up)


def test_indeterminate_forces_are_the_same_in_a_batch_as_alone():
    """The minimum-norm forces are unique, so a batch (whose samples start from their
    neighbours' pieces and may end on another basic solution of a face) reports the forces of
    the one-sample calls to rounding, not merely the same accelerations."""
    joints = 8
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(joints) + 5)]
    model = snakecg.load(indeterminate_scene(q, joints))
    T = np.random.default_rng(8).normal(0, 0.1, (40, joints))
    batch = model.forward(np.repeat(q[None], len(T), axis=0), T)
    for i, tau in enumerate(T):
        one = model.forward(q, tau)
        if one.dependent == 2 or batch.dependent[i] == 2:
            continue
        a, b = one._raw["lam"][0], batch._raw["lam"][i][:len(one._raw["lam"][0])]
        assert np.abs(a - b).max() <= 1e-11 * np.abs(a).max()


@pytest.mark.parametrize("scale", [1e-12, 1e-11, 1e-10])
def test_nearly_dependent_rows_get_the_minimum_norm_forces_too(scale):
    """The 10-joint benchmark scene (pegs pressed at the links' middles: exactly dependent
    rows) with q moved by 1e-12 to 1e-10, so that the rows are that far from dependent: the
    solve takes them as dependent, and the forces are the minimum-norm ones inside the sets
    (flag 1), Clarabel's to 1e-6 of their scale, where the minimum-norm choice moves the
    accelerations by up to 5e-10 of their scale and the KKT conditions still hold (the
    accelerations are then the new forces', a = a_free + M^-1 A^T lam holding to 1e-10).
    Before, 22 of these 30 samples at 1e-11 kept a basic solution of the face (flag 2), its
    forces up to 88 % of their scale away."""
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(10))]
    model = snakecg.load(indeterminate_scene(q))
    T = np.random.default_rng(0).normal(0, 0.1, (30, 10))
    Q = q + scale * np.random.default_rng(2).standard_normal((30, 13))
    res = model.forward(Q, T)
    assert np.all(res.status == 0) and np.sum(res.dependent == 1) >= 25, res.dependent
    assert not np.any(res.dependent == 2), res.dependent
    for i in np.flatnonzero(res.dependent == 1):
        p = dense_problem(res.sample(int(i)), model, T[i])
        lam = res._raw["lam"][i][:len(p["b"])]
        a = np.r_[np.asarray(res.qdd[i]).ravel(), np.asarray(res.a_obj[i]).ravel()]
        a_ref = p["a_free"] + p["Minv"] @ p["A"].T @ lam
        assert np.abs(a - a_ref).max() <= 1e-10 * max(1.0, np.abs(a_ref).max()), i
        ref, status = clarabel_min_norm_forces(p, lam)
        assert status == "optimal", status
        assert np.abs(lam - ref).max() <= 1e-6 * np.abs(ref).max(), i
        assert np.linalg.norm(lam) <= np.linalg.norm(ref) * (1 + 1e-9), i


# Samples of the 10-joint scene (a box and a disc touching the end links, four pegs touching
# links, Coulomb or anisotropic ground on every link) at random joint angles whose minimum-norm
# choice was not found (flag 2): the Newton inside the sets crept for 62 and 186 damped steps
# before converging, or stalled at 3e-14 and 1e-14 of its scale, above its 1e-14 stop.
# (ground, joint angles, torques, the pegs' centres)
MIN_NORM_EDGES = [
    ("coulomb", [0.30555840429920966, 0.23579223613615086, -0.5598363925864407,
                 -0.3146942489700073, -0.9667989381381752, 0.6358442763742596,
                 0.8414090959374103, 0.496267153121819, 0.8623897187703082,
                 -0.49144201712201374],
     [-0.07345272038700305, 0.04677852515563191, 0.07840072587450517, 0.10533073467829997,
      0.10375375225361907, -0.012823122871448307, 0.03234900898026651, -0.09364117842292623,
      -0.09133250009810633, -0.014290758928091611],
     [[0.1375011610967438, 0.05117230561112994], [0.422145617518882, 0.15102648269729974],
      [0.6294866855856549, -0.00970422916040516], [0.8651089426791679, -0.12364589654793323]]),
    ("coulomb", [-0.5943979152938901, -0.8178943759121693, -0.7997484656795075,
                 -0.7989612504745418, -0.43843405060801843, 0.2932433570690771,
                 -0.9036539177853922, -0.6139000514848452, 0.08055291286261612,
                 -0.23454292944277122],
     [-0.09869424391757109, -0.027263759255815402, -0.11877358533174953, -0.02658462555609635,
      0.06752956185069406, 0.01562551664499599, 0.034875872654111725, 0.09621861714864727,
      0.024417309954886075, -0.09752843817127471],
     [[0.1539367378064482, -0.01714617813030217], [0.1540440052912161, -0.2742767863109182],
      [-0.09606701049705028, -0.3777213127717985], [-0.3778120002783632, -0.2828419509937937]]),
    ("coulomb", [-0.5943979152938901, -0.8178943759121693, -0.7997484656795075,
                 -0.7989612504745418, -0.43843405060801843, 0.2932433570690771,
                 -0.9036539177853922, -0.6139000514848452, 0.08055291286261612,
                 -0.23454292944277122],
     [-0.11019279636551707, 0.040376406109467466, 0.002944549091184988, -0.03685670351848405,
      0.10614179888359176, -0.06409982031580183, -0.016627410609885148, -0.15670204513699978,
      0.00029985785899167727, 0.02168966751551344],
     [[0.1539367378064482, -0.01714617813030217], [0.1540440052912161, -0.2742767863109182],
      [-0.09606701049705028, -0.3777213127717985], [-0.3778120002783632, -0.2828419509937937]]),
    ("anisotropic", [-0.01907740659761714, 0.5364395088883329, 0.9641845325115763,
                     0.797429301606039, -0.42413734942997516, -0.6907284194353402,
                     -0.259873506487468, -0.1727740586686508, 0.034422194822616436,
                     -0.25739292591216967],
     [-0.15009077840556428, -0.07411648539120429, -0.01388745776656371, -0.014545859990399736,
      -0.06399238270412054, -0.0711283805767254, 0.27046730145126413, -0.10114165767406938,
      0.10642717874410097, 0.10344421010140786],
     [[0.15055863986752555, 0.02856382224719894], [0.3919071770630597, 0.14335449572653797],
      [0.27892364619350424, 0.41506393971204464], [0.3583930890408573, 0.6568150221316181]]),
]


@pytest.mark.parametrize("case", range(len(MIN_NORM_EDGES)))
def test_minimum_norm_forces_found_where_the_newton_creeps_or_stalls(case):
    """Four of 16,000 samples at random configurations (a sweep of the 10-joint scene with
    Coulomb and anisotropic ground): the minimum-norm choice is found (flag 1, not a basic
    solution kept), its forces satisfy the dense model's KKT conditions with the same
    accelerations, and their norm is no larger than Clarabel's minimum-norm forces' (to 1e-11;
    the basic solutions kept before were up to 14 % larger) and equal to them within
    Clarabel's accuracy on these flat objectives (1e-5 of their scale)."""
    ground, angles, tau, pegs = MIN_NORM_EDGES[case]
    robot = snakecg.Robot(joints=10)
    objects = (SceneObject(shape="box", size=(0.1, 0.08), mass=2.0, mu=0.2,
                           touching={"link": 1, "offset": 0.075, "side": "left"}),
               SceneObject(shape="disc", radius=0.04, mass=1.0, mu=0.2,
                           touching={"link": 11, "offset": 0.075, "side": "right"}))
    scene = GeneralScene(robot, ground=GROUNDS[ground], objects=objects,
                         obstacles=tuple(Obstacle(shape="peg", center=tuple(c), radius=0.03)
                                         for c in pegs))
    model = snakecg.load(scene)
    q, tau = np.r_[0.0, 0.0, 0.0, angles], np.array(tau)
    res = model.forward(q, tau)
    assert res.status == 0 and int(res.dependent) == 1, (res.status, res.dependent)
    p = dense_problem(res, model, tau)
    lam = res._raw["lam"][0][:len(p["b"])]
    a = np.r_[np.asarray(res.qdd).ravel(), np.asarray(res.a_obj).ravel()]
    assert np.abs(a - (p["a_free"] + p["Minv"] @ p["A"].T @ lam)).max() <= 1e-10 * max(
        1.0, np.abs(a).max())
    assert kkt_violations(p, lam, a) == []
    ref, status = clarabel_min_norm_forces(p, lam)
    assert status == "optimal", status
    assert np.linalg.norm(lam) <= np.linalg.norm(ref) * (1 + 1e-11)
    assert np.abs(lam - ref).max() <= 1e-5 * np.abs(ref).max()
