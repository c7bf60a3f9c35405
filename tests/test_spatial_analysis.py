"""The paper's analysis on a spatial snake lying on the ground (SpatialScene.forward) against
independent references: the planar model (case study 2's robot with its joints turned to yaw,
lying flat, in all three scenarios, to 1e-12), and a dense NumPy model from Pinocchio's M, h,
Jacobians and classical accelerations solving the same complementarity problem by
enumerating the active sets (least-norm forces by SVD, the friction bounds' coupling as one
linear solve per active set)."""

from __future__ import annotations

import itertools
import json
from pathlib import Path

import numpy as np
import pytest
from test_spatial_contact import _embed, _flat, _reference

import snakecg
from snakecg.errors import InputError

ROOT = Path(__file__).resolve().parents[1]

SCENARIOS = ("frictionless", "wheels", "ideal_wheels")


def _close(a, b, tol):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.abs(a - b).max()) <= tol * max(1.0, float(np.abs(b).max()))


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_flat_yaw_chain_gives_the_planar_numbers(rng, scenario):
    """Case study 2's robot (3 joints, the paper's links) with its joints turned to yaw and
    lying flat gives the planar qdd (through v = E v_s), the contact and wheel forces, the
    wheel states, the four metrics and sr to 1e-12; the ground carries each link's weight."""
    planar = snakecg.Robot(joints=3)
    pm = snakecg.load(snakecg.Scene(robot=planar, scenario=scenario))
    sm = snakecg.load(snakecg.SpatialScene(_flat(planar), scenario=scenario))
    nc = planar.n_links + 1
    Q = np.c_[rng.normal(size=(40, 3)), np.deg2rad(rng.uniform(-120, 120, (40, 3)))]
    T = rng.normal(size=(40, 3)) * rng.choice([0.1, 1.0, 10.0], size=(40, 1))
    embedded = [_embed(planar, qs, np.zeros(6)) for qs in Q]
    a = pm.forward(Q, T)
    b = sm.forward(np.array([e[0] for e in embedded]), T)
    assert not np.any(a.singular) and not np.any(b.singular)
    kept = a.contact.sum()
    assert 5 <= kept <= 35  # both kinds of sample are in the batch
    assert np.array_equal(a.contact, b.contact)
    assert np.array_equal(a.wheel_state, b.wheel_state)
    # each sample's force scale: its forces, and its torques over the shortest link
    scale = np.maximum(np.abs(a.lam).max(axis=1), np.abs(T).max(axis=1) / min(planar.length))
    for i, (_, _, E) in enumerate(embedded):
        assert _close(b.qdd[i], E @ a.qdd[i], 1e-12)
        assert _close(b.lam[i, :nc], a.lam[i], 1e-12 * scale[i])
        assert _close(b.a_obj[i], a.a_obj[i], 1e-12)
    for k in ("norm_lambda", "norm_a_obj", "norm_qdd", "sr"):
        assert _close(getattr(b, k), getattr(a, k), 1e-12), k
    # the weight on the ground, level: 2 n_l ground and pitch rows of which 2 n_l - 3 depend
    # on the others (their least-norm forces), to 1e-11 of the sample's force scale
    for i in range(40):
        ground = max(scale[i], 9.81 * max(planar.mass))
        assert _close(b.normal[i], 9.81 * np.array(planar.mass), 1e-11 * ground)
        assert _close(b.pitch_moment[i], np.zeros(planar.n_links), 1e-11 * ground)


def test_five_yaw_joints_give_the_planar_numbers(rng):
    """Six links lying flat (three ground rows dependent, the linear algebra as matrices):
    the planar scenario 2 to 1e-12, each link's weight on the ground."""
    planar = snakecg.Robot(joints=5)
    pm = snakecg.load(snakecg.Scene(robot=planar, scenario="wheels", contact_link=6))
    sm = snakecg.load(snakecg.SpatialScene(_flat(planar), scenario="wheels", contact_link=6))
    Q = np.c_[rng.normal(size=(30, 3)), np.deg2rad(rng.uniform(-60, 60, (30, 5)))]
    T = rng.normal(size=(30, 5))
    a = pm.forward(Q, T)
    b = sm.forward(np.array([_embed(planar, qs, np.zeros(8))[0] for qs in Q]), T)
    assert not np.any(b.singular)
    scale = np.maximum(np.abs(a.lam).max(axis=1), np.abs(T).max(axis=1) / min(planar.length))
    for i in range(30):
        assert _close(b.lam[i, :7], a.lam[i], 1e-12 * scale[i])
    for k in ("norm_lambda", "norm_a_obj", "norm_qdd", "sr"):
        assert _close(getattr(b, k), getattr(a, k), 1e-12), k
    assert np.array_equal(a.wheel_state, b.wheel_state)
    for i in range(30):
        assert _close(b.normal[i], np.full(6, 9.81), 1e-11 * max(scale[i], 9.81))


def _enumerate(ref, sc, scenario, wheels, mu, nl):
    """The solution of the complementarity problem on ``ref``'s G_c and b by enumeration:
    every active set of the contact and the wheels, the ground rows held, the held forces the
    least-norm ones (pseudo-inverse), a sliding wheel's force +-mu N_i solved with them (0
    where N_i is not positive)."""
    G, b = ref["delassus"], ref["b"]
    nc = G.shape[0]
    ground = list(range(nl + 1, 3 * nl + 1))  # the ground and pitch rows
    # "free": a wheel of a link whose normal force is not positive (no friction: force 0)
    wheel_choices = [("stick",) if scenario == "ideal_wheels" else
                     ("stick", "slide+", "slide-", "free") for _ in wheels]
    found = []
    for contact in ("held", "lost"):
        for ws in itertools.product(*wheel_choices):
            held = ([0] if contact == "held" else []) + \
                [r for r, s in zip(wheels, ws) if s == "stick"] + ground
            slide = {r: {"slide+": 1.0, "slide-": -1.0, "free": 0.0}[s]
                     for r, s in zip(wheels, ws) if s != "stick"}
            # lam_F = C lam (the sliding forces from the held ground forces), lam_H from
            # G_HH lam_H = -(b_H + G_HF lam_F), least-norm: one linear solve for lam_H
            C = np.zeros((nc, nc))
            for r, s in slide.items():
                C[r, nl + r] = s * mu
            H = np.zeros((nc, nc))
            H[held, held] = 1.0
            Pinv = np.zeros((nc, nc))
            Pinv[np.ix_(held, held)] = np.linalg.pinv(G[np.ix_(held, held)], rcond=1e-10)
            # lam = lam_H + C lam_H with lam_H = -Pinv (b + G C lam_H)
            lam_h = np.linalg.solve(np.eye(nc) + Pinv @ G @ C, -Pinv @ b)
            lam = lam_h + C @ lam_h
            w = G @ lam + b
            scale = max(1.0, np.abs(lam).max())
            tol = 1e-9 * scale
            N = lam[nl + 1:2 * nl + 1]
            ok = np.abs(w[held]).max() <= 1e-9 * max(1.0, np.abs(b).max())
            ok &= (lam[0] >= -tol) if contact == "held" else (w[0] >= -tol and lam[0] == 0)
            for r, s in zip(wheels, ws):
                bound = mu * N[r - 1]
                if scenario == "wheels" and s == "stick":
                    ok &= abs(lam[r]) <= bound + tol
                elif s == "slide+":
                    ok &= N[r - 1] > 0 and w[r] <= tol
                elif s == "slide-":
                    ok &= N[r - 1] > 0 and w[r] >= -tol
                elif s == "free":
                    ok &= N[r - 1] <= 0
            if ok:
                found.append((lam, contact, ws))
    return found


def _kkt_report(lam, ref, nl, mu):  # pragma: no cover - a failure's diagnosis
    w = ref["delassus"] @ lam + ref["b"]
    return {"lam": lam, "w": w, "bounds": mu * lam[nl + 1:2 * nl + 1]}


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("kind", ("yaw_pitch", "yaw_unequal"))
def test_forward_against_enumeration_on_pinocchio(rng, scenario, kind):
    """A yaw-pitch snake (ground rows independent) and a yaw snake with unequal links (ground
    rows dependent: least-norm support), lying flat, at random shapes, torques, velocities
    and object wrenches: forces, accelerations and metrics equal the enumeration's on
    Pinocchio's model to 1e-9, and the active set is the one it finds."""
    if kind == "yaw_pitch":
        robot = snakecg.SpatialRobot(joints=3)
    else:
        robot = snakecg.SpatialRobot(joints=3, mass=[0.6, 1.4, 0.9, 1.2],
                                     com=[(0.07, 0, 0), (0.08, 0, 0), (0.06, 0, 0), (0.09, 0, 0)],
                                     joint_axis=(0, 0, 1))
    scene = snakecg.SpatialScene(robot, scenario=scenario, mu=0.3, contact_link=4, kappa=5)
    model = snakecg.load(scene)
    nl = robot.n_links
    pitch = np.array([np.allclose(a, (0, 1, 0)) for a in robot.joint_axis])
    checked = 0
    for _ in range(12):
        q = robot.neutral()
        th = rng.uniform(-3, 3)
        q[:2] = rng.normal(size=2)
        q[3:7] = (0, 0, np.sin(th / 2), np.cos(th / 2))
        q[7:] = np.where(pitch, 0.0, rng.uniform(-1.2, 1.2, robot.joints))  # flat
        tau = rng.normal(size=robot.joints) * 0.3
        v = np.zeros(robot.nv)
        v[[0, 1, 5]] = rng.normal(size=3) * 0.5
        v[6:] = np.where(pitch, 0.0, rng.normal(size=robot.joints))
        f_obj = rng.normal(size=3)
        res = model.forward(q, tau, v=v, f_obj=f_obj)
        assert not res.singular, res.reason
        sc = {"K": model.robot_model.parameters, "contact_link": np.eye(nl)[3],
              "side": 1.0, "object_mass": scene.object_mass,
              "object_inertia": scene.object_inertia, "wheel_offset": np.zeros(nl)}
        pose = model.robot_model.link_poses(q)[3]
        e = pose[:2, 0] / np.linalg.norm(pose[:2, 0])
        n = np.array([-e[1], e[0]])
        P = pose[:2, 3] + scene.contact_offset * e
        q_obj = np.r_[P + scene.object_distance * n, np.arctan2(e[1], e[0])]
        rho = np.array([0.0, -scene.object_distance])
        ref, _ = _reference(robot, q, v, np.asarray(tau), q_obj, np.zeros(3), f_obj, rho, sc)
        wheels = list(scene.wheel_links) if scene.has_wheels else []
        found = _enumerate(ref, sc, scenario, wheels, scene.mu, nl)
        assert found, _kkt_report(res.lam, ref, nl, scene.mu)
        lam = found[0][0]
        for other, _, _ in found[1:]:  # several active sets: one solution
            assert _close(other, lam, 1e-8)
        assert _close(res.lam, lam, 1e-9)
        qdd = ref["qdd_free"] + ref["qdd_from_lam"] @ lam
        assert _close(res.qdd, qdd, 1e-9)
        M = ref["M"]
        P_rows = slice(0, nl + 1)
        G = ref["delassus"]
        assert _close(res.norm_qdd, qdd @ M @ qdd, 1e-9)
        assert _close(res.norm_lambda, lam[P_rows] @ G[P_rows, P_rows] @ lam[P_rows], 1e-9)
        assert bool(res.contact) == (found[0][1] == "held")
        checked += bool(res.contact)
    assert checked >= 1


def test_pitch_torque_moves_the_normal_forces():
    """What the plane hides: on a yaw-pitch snake lying flat, a pitch torque shifts the
    weight between the links (the normal forces change, their sum stays the weight) and so
    the wheels' friction bounds in scenario 2; a yaw torque alone leaves them at rest's."""
    robot = snakecg.SpatialRobot(joints=3)
    model = snakecg.load(snakecg.SpatialScene(robot, scenario="wheels", contact_link=4))
    q = robot.neutral()
    q[7:] = (0.4, 0.0, -0.3)
    yaw_only = model.forward(q, [0.2, 0.0, 0.1])
    pitched = model.forward(q, [0.2, 1.0, 0.1])
    weight = 9.81 * robot.total_mass
    assert abs(pitched.normal.sum() - weight) <= 1e-9 * weight
    assert np.abs(pitched.normal - yaw_only.normal).max() > 1.0


def test_a_configuration_off_the_ground_is_flagged(capsys):
    """The ground's rows hold a link's height and slope only where it lies on the plane: a
    pitch joint bent by 0.3 rad or by 1e-7 rad lifts the links beyond it (the axis's slope
    sin(angle) by the closed form), and forward returns NaN with the flag and why, as
    extremes and optimize do; a sample lying flat in the same batch is the one-sample
    answer; the CLI fails in one line."""
    from snakecg.cli import main

    robot = snakecg.SpatialRobot(joints=3)  # yaw, pitch, yaw
    model = snakecg.load(snakecg.SpatialScene(robot, scenario="wheels", contact_link=4))
    q = np.tile(robot.neutral(), (3, 1))
    q[:, 7:] = [[0.4, 0.0, -0.3], [0.4, 0.3, -0.3], [0.4, 1e-7, -0.3]]
    slope = np.abs(model.robot_model.link_poses(q)[:, :, 2, 0]).max(axis=1)
    np.testing.assert_allclose(slope[1:], np.sin([0.3, 1e-7]), rtol=1e-12)
    res = model.forward(q, [0.2, 1.0, 0.1])
    assert list(res.singular) == [False, True, True]
    assert res.reason[0] == "" and all("not lying on the ground" in r for r in res.reason[1:])
    assert np.isnan(res.sr[1:]).all() and np.isnan(res.qdd[1:]).all()
    assert np.array_equal(res[0].raw, model.forward(q[0], [0.2, 1.0, 0.1]).raw)
    rc = main(["forward", "--scene", str(ROOT / "examples" / "spatial" / "yaw_pitch.toml"),
               "--q", "0,0,0,0.4,0.3,-0.3", "--tau", "0.2,1,0.1", "--quiet"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1 and "not lying on the ground" in err[0]
    rc = main(["optimize", "max-sr", "--scene",
               str(ROOT / "examples" / "spatial" / "yaw_pitch.toml"), "--q",
               "0,0,0,0.4,0.3,-0.3", "--quiet"])
    out = capsys.readouterr().out  # the status, why, and no analysis of nothing answered
    assert rc == 1 and out.startswith("max_sr: failed (") and "not lying on the ground" in out
    assert "contact" not in out and "(;" not in out


def test_forward_batch_json_and_bad_input():
    robot = snakecg.SpatialRobot(joints=2)
    model = snakecg.load(snakecg.SpatialScene(robot, scenario="wheels"))
    q = np.tile(robot.neutral(), (3, 1))
    q[:, 7:] = [[0.1, 0.0], [0.3, 0.0], [-0.2, 0.0]]
    res = model.forward(q, [0.1, 0.2])
    one = model.forward(q[1], [0.1, 0.2])
    assert len(res) == 3 and np.array_equal(res[1].raw, one.raw)
    json.loads(json.dumps(one.to_dict(), allow_nan=False))
    bad = robot.neutral()
    bad[3:7] = (0, 0, 0, 2.0)
    with pytest.raises(InputError, match="quaternion"):
        model.forward(bad, [0.1, 0.2])
    with pytest.raises(InputError, match="tau"):
        model.forward(robot.neutral(), [0.1])
    with pytest.raises(InputError, match="rho"):
        model.forward(robot.neutral(), [0.1, 0.2], q_obj=[0, 0, 0])
    with pytest.raises(InputError, match="scenario"):
        snakecg.SpatialScene(robot, scenario="ice")


def test_runtime_core_is_strict_c99_with_a_spatial_layout(tmp_path):
    """The engine's files of a spatial scene's library (contact.c and forward.c) with the
    layout of a spatial model (n_q != n_v, the spatial scene fields) compile with the strict
    flags and -Wextra."""
    import subprocess

    from test_generated_fresh import GENERATED, STRICT, _compiler

    from snakecg.engine.layout import header
    from snakecg.native import ENGINE_DIR
    from snakecg.spatial.artifacts import CORE_FILES, core_manifest

    manifest = json.loads((GENERATED / "spatial" / "na3" / "manifest.json").read_text())
    (tmp_path / "snakecg_layout.h").write_text(header(core_manifest(manifest)))
    sources = [name for name in CORE_FILES if name.endswith(".c")]
    assert sources == ["contact.c", "forward.c"]
    for name in sources:
        res = subprocess.run([_compiler(), *STRICT, "-Wextra", "-I", str(tmp_path), "-c",
                              str(ENGINE_DIR / name), "-o", str(tmp_path / "core.o")],
                             capture_output=True, text=True, timeout=600)
        assert res.returncode == 0, f"{name}:\n{res.stderr[-3000:]}"


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_each_link_lies_on_its_line(rng, scenario):
    """A lying link is held along its axis (height and slope), not at one point: on a
    yaw-pitch snake, a two-link pitch snake and a two-link yaw snake with a product of inertia
    lying flat, with random torques (pitch torques
    among them) and planar velocities, the vertical acceleration of both ends of every link's
    axis (Pinocchio's classical acceleration at the engine's qdd) is zero, and the ground's
    forces carry the weight (Newton's law on the whole chain, Pinocchio's COM acceleration)."""
    from test_spatial_references import pinocchio_chain

    pin = pytest.importorskip("pinocchio")
    robots = (snakecg.SpatialRobot(joints=3),
              # one pitch joint: held on two COMs alone, the links would seesaw
              snakecg.SpatialRobot(joints=1, joint_axis=(0, 1, 0)),
              # a product of inertia: turning in yaw needs a moment about the link's axis
              snakecg.SpatialRobot(joints=1, joint_axis=(0, 0, 1),
                                   inertia=(0.0004, 0.002, 0.002, 0.0, 0.0005, 0.0)))
    for robot in robots:
        model = snakecg.load(snakecg.SpatialScene(robot, scenario=scenario, mu=0.3,
                                                  contact_link=robot.n_links))
        pm = pinocchio_chain(robot)
        pd = pm.createData()
        yaw = np.array([np.allclose(a, (0, 0, 1)) for a in robot.joint_axis])
        for _ in range(6):
            q = robot.neutral()
            q[:2] = rng.normal(size=2)
            th = rng.uniform(-3, 3)
            q[3:7] = (0, 0, np.sin(th / 2), np.cos(th / 2))
            q[7:] = np.where(yaw, rng.uniform(-1.2, 1.2, robot.joints), 0.0)
            v = np.zeros(robot.nv)
            v[[0, 1, 5]] = rng.normal(size=3) * 0.5
            v[6:] = np.where(yaw, rng.normal(size=robot.joints), 0.0)
            tau = rng.normal(size=robot.joints)
            res = model.forward(q, tau, v=v)
            assert not res.singular, res.reason
            pin.forwardKinematics(pm, pd, q, v, res.qdd)
            for i in range(robot.n_links):
                frame = pin.SE3(np.eye(3), np.zeros(3))
                for end in (0.0, 0.15):  # the link's axis from its rear joint to its front
                    frame.translation = np.array([end, 0.0, 0.0])
                    jid = i + 1
                    placed = pd.oMi[jid]
                    a = pin.getClassicalAcceleration(pm, pd, jid,
                                                     pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)
                    vel = pin.getVelocity(pm, pd, jid, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)
                    r = placed.rotation @ frame.translation
                    acc = a.linear + np.cross(a.angular, r) + np.cross(
                        vel.angular, np.cross(vel.angular, r))
                    assert abs(acc[2]) <= 1e-9 * max(1.0, np.abs(res.qdd).max()), (i, end)
            pin.centerOfMass(pm, pd, q, v, res.qdd)
            weight = 9.81 * robot.total_mass
            assert abs(res.normal.sum() - weight - robot.total_mass * pd.acom[0][2]) \
                <= 1e-9 * weight
