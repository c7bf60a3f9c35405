"""Optimal shapes (snakecg.shape) against independent references: the paper's 28^n joint
grid evaluated by the exact per-configuration analysis, a SciPy (SLSQP) refinement on the
package's forward solve from the best grid points, the closed-form sr plateaus, the KKT
conditions, and a brute-force geometry check."""

from __future__ import annotations

import itertools
import json
import math
import subprocess
import sys

import numpy as np
import pytest

import snakecg
from snakecg.analysis import joint_grid
from snakecg.errors import InputError
from snakecg.geometry import feasibility, link_segments, segment_distance

KAPPA = 100.0


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(scenario, joints=3, kappa=KAPPA):
        key = (scenario, joints, kappa)
        if key not in cache:
            robot = snakecg.Robot(joints=joints)
            cache[key] = snakecg.load(snakecg.Scene(robot, scenario=scenario, kappa=kappa))
        return cache[key]

    return get


def _kkt_ok(res, tol=1e-8):
    c = res.certificate
    assert c["stationarity"] <= tol, c
    assert c["primal_infeasibility"] <= tol, c
    assert c["complementarity"] <= tol, c


def _plateau(robot, kappa):
    m, l, inertia = robot.mass[0], robot.length[0], robot.inertia[0]
    return kappa / (kappa + 1 + 3 * inertia / (m * l * l))


# ------------------------------------------------------------------------------------------
# closed-form bounds
@pytest.mark.parametrize("kappa", [10.0, 100.0])
@pytest.mark.parametrize("feasible", [False, True])
def test_ideal_wheels_max_sr_plateau(models, kappa, feasible):
    model = models("ideal_wheels", kappa=kappa)
    res = model.optimize_shape("max_sr", feasible=feasible)
    bound = _plateau(model.robot, kappa)
    if kappa == 100.0:
        assert bound == pytest.approx(0.987492, abs=5e-7)
    assert res.status == "optimal", res.reason
    assert res.value <= bound + 1e-12
    assert res.value >= bound - 1e-6
    assert float(res.analysis.sr) == res.value
    _kkt_ok(res)


@pytest.mark.parametrize("joints,kappa", [(2, 100.0), (3, 100.0), (3, 10.0)])
def test_frictionless_max_sr_never_above_mass_ratio(models, joints, kappa):
    model = models("frictionless", joints, kappa)
    res = model.optimize_shape("max_sr", feasible=False)
    nl = model.n_links
    assert res.status == "optimal", res.reason
    assert 0 < res.value <= nl / (nl + kappa)
    _kkt_ok(res)


# ------------------------------------------------------------------------------------------
# the paper's grid, evaluated with the package's exact per-configuration analysis
@pytest.mark.parametrize("joints", [2, 3])
@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
def test_at_least_the_paper_grid(models, scenario, joints):
    model = models(scenario, joints)
    Q = joint_grid(joints)  # 28^n shapes, -135..135 deg every 10 deg
    assert len(Q) == 28 ** joints
    ex = model.extremes(Q)
    for objective, metric in (("max_sr", "sr"), ("max_a_obj", "norm_a_obj")):
        for feasible in (False, True):
            vals = np.asarray(ex.max[metric])
            if feasible:
                vals = np.where(feasibility(model, Q).feasible, vals, -np.inf)
            res = model.optimize_shape(objective, feasible=feasible)
            assert res.status == "optimal", (objective, feasible, res.reason)
            assert res.value >= vals.max() - 1e-12, (objective, feasible)
            _kkt_ok(res)


def test_wheels_at_least_the_grid_with_friction_bounds(models):
    """Scenario 2 with every wheel sticking: the grid's best per-configuration optimum of the
    package's torque optimizer (qpOASES LP, an independent solver) for strongest_push."""
    model = models("wheels")
    Q = joint_grid(3, step_deg=30.0)
    opt = model.optimize(Q, "strongest_push", tau_max=0.3)
    grid = np.where(opt.status == "optimal", opt.objective_value, -np.inf)
    grid = np.where(feasibility(model, Q).feasible, grid, -np.inf)
    res = model.optimize_shape("strongest_push", tau_max=0.3)
    assert res.status == "optimal", res.reason
    assert res.value >= grid.max() - 1e-12
    assert not np.any(np.isin(res.analysis.wheel_state, ("slide+", "slide-")))
    _kkt_ok(res)


# ------------------------------------------------------------------------------------------
# a SciPy local refinement on the package's forward solve, same constraints
def _slsqp(model, objective, q_start, tau_start, *, clearance=None, limit=0.75 * math.pi):
    from scipy.optimize import minimize

    na = model.n_joints
    pose = np.zeros(3)
    bounded = [i for i in range(1, model.n_constraints)
               if model.present[i] and np.isfinite(model.bounds[i])]

    def split(z):
        return np.concatenate([pose, z[:na]]), z[na:]

    def fw(z):
        q, tau = split(z)
        return model.forward(q, tau)

    def metric(z):
        r = fw(z)
        return float(r.sr if objective == "max_sr" else r.norm_a_obj)

    def ellipsoid(z):
        q, tau = split(z)
        N = model.maps(q)["input_metric"]
        return 1.0 - tau @ N @ tau

    cons = [{"type": "eq" if objective == "max_sr" else "ineq", "fun": ellipsoid},
            {"type": "ineq", "fun": lambda z: fw(z).lam[0] * 1e3}]
    for i in bounded:
        u = model.bounds[i]
        cons.append({"type": "ineq", "fun": lambda z, i=i, u=u: u - abs(
            model.maps(split(z)[0])["lam_from_tau"][i] @ split(z)[1])})
    if clearance is not None:
        cons.append({"type": "ineq", "fun": lambda z: feasibility(
            model, split(z)[0], clearance=clearance).self_distance - clearance})
        cons.append({"type": "ineq", "fun": lambda z: -feasibility(
            model, split(z)[0], clearance=clearance).penetration})
    if objective == "max_sr":
        # the torque's inner problem by the package's per-configuration optimizer (its value
        # read from the forward solve); SciPy searches the joint angles
        def split(z):  # noqa: F811
            return np.concatenate([pose, z[:na]]), None

        def metric(z):  # noqa: F811
            r = model.optimize(split(z)[0], "max_sr")
            return float(r.objective_value) if r.status == "optimal" else 0.0

        cons = [c for c in cons[2 + len(bounded):]]

        def fw(z):  # noqa: F811
            q = split(z)[0]
            return model.optimize(q, "max_sr").analysis

        z0 = np.array(q_start[3:], float)
        bnds = [(-limit, limit)] * na
    else:
        z0 = np.concatenate([q_start[3:], tau_start])
        bnds = [(-limit, limit)] * na + [(None, None)] * na
    out = minimize(lambda z: -metric(z), z0, method="SLSQP", bounds=bnds, constraints=cons,
                   options={"maxiter": 100, "ftol": 1e-13})
    z = out.x
    q, tau = split(z)
    feasible = all(c["fun"](z) >= -1e-7 if c["type"] == "ineq" else abs(c["fun"](z)) <= 1e-7
                   for c in cons) and bool(fw(z).contact)
    return metric(z) if feasible else -np.inf


@pytest.mark.parametrize("scenario,objective", [("frictionless", "max_sr"),
                                                ("ideal_wheels", "max_sr"),
                                                ("wheels", "max_a_obj")])
def test_at_least_a_scipy_refinement_of_the_best_grid_points(models, scenario, objective):
    model = models(scenario)
    Q = joint_grid(3)
    ex = model.extremes(Q) if scenario != "wheels" else models("ideal_wheels").extremes(Q)
    metric = "sr" if objective == "max_sr" else "norm_a_obj"
    best = np.argsort(-np.asarray(ex.max[metric]))[:2]
    ref = max(_slsqp(model, objective, Q[b], ex.tau_max[metric][b] * 0.999) for b in best)
    res = model.optimize_shape(objective, feasible=False)
    assert res.status == "optimal", res.reason
    assert np.isfinite(ref)
    assert res.value >= ref - 1e-9


def test_at_least_a_scipy_refinement_with_an_active_clearance(models):
    model = models("wheels")
    clearance = 0.14
    res = model.optimize_shape("max_a_obj", clearance=clearance)
    assert res.status == "optimal", res.reason
    assert any(a.startswith("clearance between links") for a in res.certificate["active"])
    _kkt_ok(res)
    Q = joint_grid(3)
    ok = feasibility(model, Q, clearance=clearance).feasible
    ex = models("ideal_wheels").extremes(Q)
    vals = np.where(ok, ex.max["norm_a_obj"], -np.inf)
    best = np.argsort(-vals)[:1]
    ref = max(_slsqp(model, "max_a_obj", Q[b], ex.tau_max["norm_a_obj"][b] * 0.5,
                     clearance=clearance) for b in best)
    assert np.isfinite(ref)
    assert res.value >= ref - 1e-9
    _geometry_ok(model, res.q, clearance)


# ------------------------------------------------------------------------------------------
def _geometry_ok(model, q, clearance):
    """Independent checks: exact segment distances, and a brute-force sampling of the links
    against each other and the plate."""
    rear, front = link_segments(model.robot, model.link_poses(q))
    nl = model.n_links
    for i in range(nl):
        for j in range(i + 2, nl):
            d = float(segment_distance(rear[i], front[i], rear[j], front[j]))
            assert d >= clearance - 1e-9, (i, j, d)
    t = np.linspace(0, 1, 2001)[:, None]
    pts = [rear[i] + t * (front[i] - rear[i]) for i in range(nl)]
    spacing = max(model.robot.length) / 2000
    for i in range(nl):
        for j in range(i + 2, nl):
            dmin = np.min(np.linalg.norm(pts[i][:, None] - pts[j][None], axis=-1)[::10, ::10])
            assert dmin >= clearance - 10 * spacing
    q_obj = model.place_object(q)[0]
    c, s = math.cos(q_obj[2]), math.sin(q_obj[2])
    for i in range(nl):
        if i == model.scene.contact_link - 1:
            continue
        d = pts[i] - q_obj[:2]
        lx, ly = c * d[:, 0] + s * d[:, 1], -s * d[:, 0] + c * d[:, 1]
        inside = (np.abs(lx) < 0.05 - 1e-9) & (np.abs(ly) < 0.05 - 1e-9)
        assert not inside.any(), i


@pytest.mark.parametrize("scenario", ["frictionless", "wheels"])
def test_geometric_constraints_hold_at_the_answer(models, scenario):
    model = models(scenario)
    for objective in ("max_sr", "max_a_obj"):
        res = model.optimize_shape(objective)
        assert res.status == "optimal", res.reason
        _geometry_ok(model, res.q, 0.01)


def test_same_answer_for_every_ordering_of_the_starts(models):
    model = models("frictionless")
    first = model.optimize_shape("max_sr", starts=4)
    answers = []
    for perm in itertools.permutations(range(4)):
        res = model.optimize_shape("max_sr", q0=first.starts[list(perm)])
        answers.append(res.q)
        assert res.value == pytest.approx(first.value, abs=1e-15)
    for q in answers:
        np.testing.assert_allclose(q, first.q, atol=1e-12, rtol=0)
    again = model.optimize_shape("max_sr", starts=4)  # deterministic
    np.testing.assert_array_equal(again.q, first.q)


def test_least_slip_push_meets_the_task_and_beats_the_grid(models):
    model = models("wheels")
    res = model.optimize_shape("least_slip_push", direction=(0, 1), a_min=0.005)
    assert res.status == "optimal", res.reason
    assert res.analysis.a_obj[1] >= 0.005 * (1 - 1e-6)
    Q = joint_grid(3, step_deg=30.0)
    opt = model.optimize(Q, "least_slip_push", direction=(0, 1), a_min=0.005)
    grid = np.where((opt.status == "optimal") & feasibility(model, Q).feasible,
                    opt.objective_value, np.inf)
    assert res.value <= grid.min() + 1e-12
    _kkt_ok(res)
    # a full planar acceleration: the object can only be pushed along the contact normal,
    # (0, 1) at this pose, so (0, 0.005, 0) is the same task
    full = model.optimize_shape("least_slip_push", a_obj=(0, 0.005, 0))
    assert full.status == "optimal", full.reason
    np.testing.assert_allclose(full.analysis.a_obj, [0, 0.005, 0], atol=1e-10)
    assert full.value == pytest.approx(res.value, rel=1e-9)
    _kkt_ok(full)


# ------------------------------------------------------------------------------------------
def test_bad_input_is_rejected_before_any_work(models):
    model = models("wheels")
    bad = [
        (("max_speed",), {}), (("max_sr",), {"starts": 0}), (("max_sr",), {"starts": True}),
        (("max_sr",), {"joint_limits": (1.0, -1.0)}), (("max_sr",), {"joint_limits": (0, 4)}),
        (("max_sr",), {"q0": [0, 0, 0]}), (("max_sr",), {"q0": [0, 0, 0, 3.0, 0, 0]}),
        (("max_sr",), {"allow_slide": True}), (("max_sr",), {"direction": (1, 0)}),
        (("max_a_obj",), {"a_min": 1.0}), (("max_sr",), {"clearance": -1.0}),
        (("least_slip_push",), {}), (("max_sr",), {"feasible": "yes"}),
        (("max_sr",), {"speed": 1}),
    ]
    for args, kw in bad:
        with pytest.raises(InputError):
            model.optimize_shape(*args, **kw)


def test_cli_json_and_errors(tmp_path):
    fig = tmp_path / "best.png"
    out = subprocess.run([sys.executable, "-m", "snakecg.cli", "optimize-shape", "max-sr",
                          "--joints", "3", "--scenario", "wheels", "--json", "--figure",
                          str(fig)], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout, parse_constant=lambda c: pytest.fail(f"non-strict {c}"))
    assert data["schema"] == "snakecg.optimize_shape/1"
    assert data["status"] == "optimal"
    # sliding wheels searched too: the exact piecewise optimum (the stick-only 0.9874917709
    # was below what extremes finds at that shape)
    assert data["value"] == pytest.approx(0.9878425076, abs=1e-9)
    assert fig.stat().st_size > 1000
    for argv in (["max-sr", "--joints", "3", "--starts", "0"],
                 ["max-sr", "--joints", "3", "--joint-limits", "1"],
                 ["max-a-obj", "--joints", "3", "--direction", "1,0"],
                 ["max-sr", "--joints", "3", "--figure", str(tmp_path / "x.txt")],
                 ["max-sr", "--joints", "3", "--figure", str(tmp_path / "no" / "x.png")],
                 ["max-sr", "--joints", "3", "--q0", "0,0"], ["fastest"]):
        r = subprocess.run([sys.executable, "-m", "snakecg.cli", "optimize-shape", *argv],
                           capture_output=True, text=True, timeout=600)
        assert r.returncode == 2, (argv, r.stderr)
        assert len(r.stderr.strip().splitlines()) == 1, r.stderr
        assert "Traceback" not in r.stderr


# ------------------------------------------------------------------------------------------
# beyond eight joints: the Sobol starts and the generated functions of the mx algebra
@pytest.mark.parametrize("joints", [9, 10])
def test_beyond_eight_joints_against_independent_checks(models, joints, rng):
    """From 9 joints the generated functions keep their matrices (CasADi's ldl solves, MX),
    which SX cannot evaluate (``eval_sx not defined for LinsolLdl``). The answer is checked
    without the NLP: its value is the exact best sr over the input ellipsoid at the shape
    (``extremes``, closed form) and the forward solve at its torque; the geometry holds
    (exact segment distances, sampling); no joint move of 1e-4 rad that stays feasible
    improves it (first order, by finite differences of ``extremes``); and a crude random
    search over 3000 feasible shapes within the limits never beats it."""
    model = models("frictionless", joints)
    res = model.optimize_shape("max_sr", starts=2)
    assert res.status == "optimal", res.reason
    _kkt_ok(res, tol=1e-6)
    ex = model.extremes(res.q)
    assert res.value == pytest.approx(ex.max["sr"], abs=1e-7)
    fw = model.forward(res.q, res.tau)
    assert fw.contact and fw.sr == pytest.approx(res.value, abs=1e-6)
    _geometry_ok(model, res.q, 0.01)
    lo, hi = -0.75 * math.pi, 0.75 * math.pi
    # first-order optimality, independent of IPOPT's multipliers
    h = 1e-4
    moves = []
    for j in range(joints):
        for sgn in (1.0, -1.0):
            q = np.array(res.q, dtype=float)
            q[3 + j] += sgn * h
            if lo <= q[3 + j] <= hi:
                moves.append(q)
    moves = np.array(moves)
    ok = feasibility(model, moves).feasible
    assert ok.sum() >= joints  # most moves stay feasible
    assert np.max(model.extremes(moves[ok]).max["sr"]) <= res.value + 1e-6
    # a crude random search must not win
    Q = np.zeros((3000, joints + 3))
    Q[:, 3:] = rng.uniform(lo, hi, (3000, joints))
    Q = Q[feasibility(model, Q).feasible]
    assert len(Q) >= 100
    best = float(np.max(model.extremes(Q).max["sr"]))
    assert best <= res.value + 1e-9, (best, res.value)
