"""The generated CasADi functions as public API (snakecg.casadi_api, docs/how-to/casadi.md).

References: the dense NumPy model of tests/reference.py (forces and accelerations of eq. 12
for an active set), the derivation's own symbol list (the layout of ``K``), central finite
differences (CasADi's derivatives), and ``model.optimize`` (the docs' ``casadi.Opti`` example
solved by IPOPT must reach the same max-sr).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from reference import Reference

import snakecg
from snakecg.casadi_api import parameter_names

ca = pytest.importorskip("casadi")
ROOT = Path(__file__).resolve().parents[1]


def test_docs_opti_example_reaches_model_optimize(monkeypatch):
    from test_docs import fenced_blocks

    monkeypatch.chdir(ROOT)
    ns: dict = {}
    for _, code in fenced_blocks(ROOT / "docs" / "how-to" / "casadi.md", "python"):
        exec(compile(code, "docs/how-to/casadi.md", "exec"), ns)  # noqa: S102 - the docs example
    sol, out, best, tau = ns["sol"], ns["out"], ns["best"], ns["tau"]
    assert best.status == "optimal"
    sr_opti = float(sol.value(out["sr"]))
    assert sr_opti == pytest.approx(best.objective_value, rel=1e-7)
    # sr depends on the direction of tau only: IPOPT's torque is parallel to optimize's
    t = np.asarray(sol.value(tau)).ravel()
    cos = t @ best.tau / np.linalg.norm(t) / np.linalg.norm(best.tau)
    assert cos == pytest.approx(1.0, abs=1e-6)
    # and the exact forward solve at IPOPT's torque agrees: every wheel sticks, contact kept
    res = ns["model"].forward(ns["q"], t)
    assert res.contact and set(res.wheel_state) <= {"stick", "none"}
    assert res.sr == pytest.approx(sr_opti, rel=1e-9)


@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
def test_function_inputs_reproduce_the_dense_reference(scenario, rng, random_robot):
    robot = random_robot(3)
    scene = snakecg.Scene(robot, scenario=scenario, kappa=30, contact_link=2, side="right",
                          wheel_offset=0.01)
    model = snakecg.load(scene)
    ref = Reference(scene)
    f = model.casadi_function("constrained_dynamics")
    assert f.name_in() == [i["name"] for i in next(
        s for s in model.manifest["functions"] if s["name"] == "constrained_dynamics")["inputs"]]
    bound = model.casadi_function("constrained_dynamics", bind=True)
    assert bound.name_in() == ["q", "tau"]
    for _ in range(3):
        q = rng.uniform(-1, 1, robot.n_coordinates)
        tau = rng.normal(scale=0.05, size=robot.joints)
        inputs = model.function_inputs("constrained_dynamics", q=q)
        assert set(f.name_in()) - set(inputs) == {"q", "tau"}
        out = f(q=q, tau=tau, **inputs)
        sys_ = ref.system(q, tau)
        held = ["held" if p else "absent" for p in ref.present]
        lam = ref.solve_given(sys_, held)
        want = ref.outcome(sys_, lam)
        scale = max(1.0, np.abs(lam).max())
        np.testing.assert_allclose(out["lam"].full().ravel(), lam, atol=1e-9 * scale)
        np.testing.assert_allclose(out["qdd"].full().ravel(), want["qdd"],
                                   atol=1e-8 * max(1, np.abs(want["qdd"]).max()))
        np.testing.assert_allclose(out["a_obj"].full().ravel(), want["a_obj"],
                                   atol=1e-8 * max(1, np.abs(want["a_obj"]).max()))
        b = bound(q=q, tau=tau)
        for k in ("lam", "qdd", "a_obj", "sr"):
            np.testing.assert_allclose(b[k].full(), out[k].full(), rtol=1e-12, atol=1e-14)


def test_casadi_derivatives_match_finite_differences(rng):
    scene = snakecg.Scene(snakecg.Robot(joints=2), scenario="ideal_wheels")
    model = snakecg.load(scene)
    dyn = model.casadi_function("constrained_dynamics", bind=True)
    q_s, tau_s = ca.MX.sym("q", model.n_coordinates), ca.MX.sym("tau", 2)
    o = dyn(q=q_s, tau=tau_s)
    jac = ca.Function("d_a_obj", [q_s, tau_s], [ca.jacobian(o["a_obj"], ca.vertcat(q_s, tau_s))])
    q = np.array([0.1, -0.2, 0.3, -2.2, -2.0])
    tau = np.array([0.1, -0.03])
    J = jac(q, tau).full()

    def a_obj(x):  # the runtime's forward solve (the object placed at each q)
        return model.forward(x[:5], x[5:]).a_obj

    x0, h = np.concatenate([q, tau]), 1e-6
    fd = np.stack([(a_obj(x0 + h * e) - a_obj(x0 - h * e)) / (2 * h) for e in np.eye(7)], 1)
    np.testing.assert_allclose(J, fd, rtol=1e-5, atol=1e-6 * np.abs(fd).max())


@pytest.mark.parametrize("joints", [1, 3])
def test_parameter_layout_matches_the_derivation(joints, random_robot):
    from snakecg_derive.symbols import SnakeSymbols

    names = parameter_names(joints)
    assert names == [str(s) for s in SnakeSymbols(joints).parameters]
    robot = random_robot(joints)
    model = snakecg.load(robot)
    assert len(names) == model.manifest["n_parameters"] == model.parameters.size
    K = dict(zip(names, model.parameters))
    nl = robot.n_links
    for i in range(nl):
        assert K[f"m{i + 1}"] == robot.mass[i] and K[f"l{i + 1}"] == robot.length[i]
        assert K[f"I{i + 1}"] == robot.inertia[i] and K[f"c{i + 1}"] == robot.com[i]
    assert K["mtot"] == pytest.approx(sum(robot.mass), rel=1e-14)
    # gamma_jk = sum_{i >= max(j,k)} m_i a_ij a_ik with the levers a_ij of derive/symbols.py
    m, l, c = np.array(robot.mass), np.array(robot.length), np.array(robot.com)

    def lever(i, j):  # 1-based
        if i == 1:
            return 0.0
        return c[i - 1] if j == i else (l[0] - c[0] if j == 1 else l[j - 1])

    for j in range(1, nl + 1):
        beta = sum(m[i - 1] * lever(i, j) for i in range(j, nl + 1))
        assert K[f"beta{j}"] == pytest.approx(beta, rel=1e-12, abs=1e-15)
        for k in range(j, nl + 1):
            gam = sum(m[i - 1] * lever(i, j) * lever(i, k) for i in range(k, nl + 1))
            assert K[f"gamma{j}_{k}"] == pytest.approx(gam, rel=1e-12, abs=1e-15)
        assert K[f"Jrot{j}"] == pytest.approx(K[f"gamma{j}_{j}"] + robot.inertia[j - 1],
                                              rel=1e-12)


def test_bad_names_and_inputs_are_input_errors():
    robot_model = snakecg.load(snakecg.Robot(joints=2))
    with pytest.raises(snakecg.InputError, match="one of .*mass_matrix"):
        robot_model.casadi_function("mass_matrx")
    with pytest.raises(snakecg.InputError, match="load a snakecg.Scene"):
        robot_model.function_inputs("constrained_dynamics")
    assert set(robot_model.function_inputs("mass_matrix")) == {"K"}
    M = robot_model.casadi_function("mass_matrix", bind=True)
    q = [0.1, 0.2, 0.3, 0.4, 0.5]
    np.testing.assert_allclose(M(q).full(), robot_model.mass_matrix(q), rtol=1e-13)
    scene_model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))
    with pytest.raises(snakecg.InputError, match="has no input 'tua'"):
        scene_model.casadi_function("constrained_dynamics", bind=True, tua=[0, 0])
    with pytest.raises(snakecg.InputError, match="free must be 4 numbers"):
        scene_model.casadi_function("constrained_dynamics", bind=True, free=[1, 1])
    with pytest.raises(snakecg.InputError, match="bind=True"):
        scene_model.casadi_function("constrained_dynamics", free=[1, 1, 1, 1])
    moving = scene_model.casadi_function("constrained_dynamics", bind=True, v=None)
    assert moving.name_in() == ["q", "v", "tau"]
