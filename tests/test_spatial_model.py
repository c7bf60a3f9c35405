"""The spatial runtime: SpatialRobot validation, the compiled model's batches against its
samples and CasADi's own evaluation, physical properties, the C export and the CLI."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import snakecg

from test_spatial_references import random_robot, rel


def _q(rng, robot, n):
    quat = rng.normal(size=(n, 4))
    quat /= np.linalg.norm(quat, axis=1)[:, None]
    return np.c_[rng.normal(size=(n, 3)), quat, rng.uniform(-2, 2, (n, robot.joints))]


def test_robot_validation_collects_every_problem():
    with pytest.raises(snakecg.InputError, match=r"mass must be >= 0.*joint_axis of joint\(s\) 2 "
                                                  r"is zero.*effort_limits must be positive"):
        snakecg.SpatialRobot(joints=2, mass=[1, -1, 1], joint_axis=[(0, 0, 1), (0, 0, 0)],
                             effort_limits=[1, -2])
    with pytest.raises(snakecg.InputError, match="inertia of link 1 breaks the triangle"):
        snakecg.SpatialRobot(joints=1, inertia=(1, 1, 3, 0, 0, 0))
    with pytest.raises(snakecg.InputError, match="joints must be an integer >= 1"):
        snakecg.SpatialRobot(joints=0)
    # beyond what the model's products hold in double precision (an axis is a direction)
    for kw, name in ((dict(mass=1e300), "mass"), (dict(joint_xyz=(1e60, 0, 0)), "joint_xyz"),
                     (dict(inertia=(1e60, 1e60, 1e60, 0, 0, 0)), "inertia")):
        with pytest.raises(snakecg.InputError, match=rf"{name} must be at most 1e\+50"):
            snakecg.SpatialRobot(joints=2, **kw)


def test_a_joint_axis_of_any_finite_length_is_its_direction():
    """(1e300, 1e300, 0) once overflowed its norm to inf and read as (0, 0, 0): a snake
    whose first joint had no axis. Any finite axis longer than 1e-12 is its unit direction
    (the axes of one direction at lengths 1, 1e300 and 1e-6 give the same unit vector, the
    reference (1, 1, 0) / sqrt(2)), and a shorter one is refused as zero."""
    ref = np.array([1.0, 1.0, 0.0]) / np.sqrt(2.0)
    for scale in (1.0, 1e300, 1e-6):
        robot = snakecg.SpatialRobot(joints=2, joint_axis=[tuple(scale * np.array([1, 1, 0])),
                                                           (0, 0, 1)])
        np.testing.assert_allclose(np.asarray(robot.joint_axis)[0], ref, rtol=0, atol=1e-15)
    with pytest.raises(snakecg.InputError, match=r"joint_axis of joint\(s\) 1 is zero"):
        snakecg.SpatialRobot(joints=2, joint_axis=[(1e-300, 1e-300, 0), (0, 0, 1)])


def test_batches_equal_samples_and_casadi(rng):
    """The block drivers (16 samples per loop) and the per-sample path give the same numbers,
    equal to CasADi's in-process evaluation of the serialized functions (to 1e-13)."""
    robot = random_robot(rng, 4)
    model = snakecg.load(robot)
    q, v = _q(rng, robot, 37), rng.normal(size=(37, robot.nv))
    M, h = model.mass_matrix(q), model.bias_forces(q, v)
    for k in (0, 15, 16, 36):
        assert np.array_equal(M[k], model.mass_matrix(q[k]))
        assert np.array_equal(h[k], model.bias_forces(q[k], v[k]))
    f = model.casadi_function("mass_matrix", bind=True)
    assert rel(M[5], np.array(f(q[5]))) <= 1e-13
    g = model.casadi_function("bias_forces")
    assert rel(h[5], np.array(g(q[5], v[5], model.parameters)).ravel()) <= 1e-13


def test_physics_properties(rng):
    """M is symmetric positive definite; the kinetic energy 1/2 v^T M v equals the links'
    1/2 (m |v_C|^2 + w^T I w) from the point and link Jacobians; the power of h at zero
    gravity is v^T h = 1/2 v^T Mdot v (finite difference along the flow qdot = G v)."""
    robot = snakecg.SpatialRobot(joints=3, joint_axis=rng.normal(size=(3, 3)),
                                 gravity=(0, 0, 0), com=rng.normal(0, 0.05, (4, 3)))
    model = snakecg.load(robot)
    q, v = _q(rng, robot, 1)[0], rng.normal(size=robot.nv)
    M = model.mass_matrix(q)
    assert np.allclose(M, M.T, atol=0) and np.linalg.eigvalsh(M).min() > 0
    J = model.link_jacobians(q)
    T = model.link_poses(q)
    energy = 0.0
    for i in range(robot.n_links):
        vc = model.point_jacobian(q, i + 1, robot.com[i]) @ v
        w = J[i, 3:] @ v
        xx, yy, zz, xy, xz, yz = robot.inertia[i]
        Iw = T[i, :3, :3] @ np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]) @ T[i, :3, :3].T
        energy += 0.5 * (robot.mass[i] * vc @ vc + w @ Iw @ w)
    assert abs(0.5 * v @ M @ v - energy) <= 1e-13 * energy
    G = model.kinematic_map(q)
    eps = 1e-6
    Mdot = (model.mass_matrix(q + eps * G @ v) - model.mass_matrix(q - eps * G @ v)) / (2 * eps)
    assert abs(v @ model.bias_forces(q, v) - 0.5 * v @ Mdot @ v) <= 1e-7 * abs(v @ M @ v)


def test_rows_are_the_point_jacobians(rng):
    """Ground rows are the z rows of the support points' Jacobians; wheel rows are lateral
    (orthogonal to the heading in the plane); Adot v of the ground rows is the z of the
    points' bias accelerations."""
    robot = random_robot(rng, 3)
    model = snakecg.load(robot)
    q, v = _q(rng, robot, 1)[0], rng.normal(size=robot.nv)
    g = model.ground_rows(q, v)
    w = model.wheel_rows(q, v)
    T = model.link_poses(q)
    for i in range(robot.n_links):
        Jp = model.point_jacobian(q, i + 1, robot.com[i])
        assert rel(g["A"][i], Jp[2]) <= 1e-13
        assert abs(g["adot_v"][i] - model.point_bias_acceleration(q, v, i + 1,
                                                                   robot.com[i])[2]) <= 1e-12
        assert abs(g["height"][i] - model.point_position(q, i + 1, robot.com[i])[2]) <= 1e-13
        heading = T[i, :3, 0]
        lat = np.array([-heading[1], heading[0], 0]) / np.hypot(*heading[:2])
        assert rel(w["A"][i], lat @ Jp) <= 1e-12


def test_inputs_are_checked(rng):
    model = snakecg.load(snakecg.SpatialRobot(joints=1))
    with pytest.raises(snakecg.InputError, match=r"q must be numeric with shape \(8,\)"):
        model.mass_matrix(np.zeros(7).tolist() + ["x"])
    with pytest.raises(snakecg.InputError, match=r"link must be an integer from 1"):
        model.point_jacobian(np.r_[np.zeros(6), 1, 0], 3, [0, 0, 0])


@pytest.mark.skipif(shutil.which("make") is None or shutil.which("cc") is None,
                    reason="the C export example needs make and a C compiler")
def test_export_builds_and_matches(tmp_path):
    """`snakecg export` of a spatial robot builds with make and prints the model's numbers."""
    robot = snakecg.SpatialRobot(joints=2)
    from snakecg.export import export_library

    export_library(robot, tmp_path / "lib")
    subprocess.run(["make", "-s", "-C", str(tmp_path / "lib")], check=True, capture_output=True)
    out = subprocess.run([str(tmp_path / "lib" / "example")], check=True, capture_output=True,
                         text=True).stdout.splitlines()
    q = robot.neutral()
    q[7:] = [0.3 * ((i % 3) - 1) for i in range(7, 9)]
    h = snakecg.load(robot).bias_forces(q, np.zeros(robot.nv))
    printed = [float(line.split("=")[1]) for line in out[1:]]
    assert np.allclose(printed, h, rtol=1e-15, atol=1e-15)


_DRIVER = r"""
#include <stdio.h>
#include <stdlib.h>
#include "snakecg_sp{na}.h"
#define NQ SNAKECG_SP{na}_NQ
#define NV SNAKECG_SP{na}_NV
#define NL SNAKECG_SP{na}_N_LINKS
static void put(const char* name, const double* x, int n) {{
  int i;
  printf("%s", name);
  for (i = 0; i < n; ++i) printf(" %.17g", x[i]);
  printf("\n");
}}
int main(int argc, char** argv) {{
  double q[NQ], v[NV], M[NV * NV], h[NV], J[6 * NL * NV], b[6 * NL];
  int i;
  for (i = 0; i < NQ; ++i) q[i] = atof(argv[1 + i]);
  for (i = 0; i < NV; ++i) v[i] = atof(argv[1 + NQ + i]);
  if (snakecg_sp{na}_robot_mass_matrix(q, M) || snakecg_sp{na}_robot_bias_forces(q, v, h)
      || snakecg_sp{na}_robot_link_jacobians(q, J)
      || snakecg_sp{na}_robot_link_bias_accelerations(q, v, b)) return 1;
  put("M", M, NV * NV); put("h", h, NV); put("J", J, 6 * NL * NV); put("b", b, 6 * NL);
  return 0;
}}
"""


@pytest.mark.skipif(shutil.which("make") is None or shutil.which("cc") is None,
                    reason="the C export needs make and a C compiler")
def test_cli_export_of_a_urdf_chain_is_pinocchio(rng, tmp_path):
    """`snakecg export --robot chain.urdf` of a random 3-D chain: the library built with its
    Makefile, called from a C program of the test through the baked wrappers, gives
    Pinocchio's crba, rnea, joint Jacobians and classical accelerations (1e-12)."""
    pin = pytest.importorskip("pinocchio")
    pytest.importorskip("yourdfpy")
    from test_spatial_files import _urdf
    from test_spatial_references import pinocchio_chain

    robot = random_robot(rng, 4)
    path = _urdf(robot, tmp_path / "chain.urdf")
    lib = tmp_path / "lib"
    res = subprocess.run([sys.executable, "-m", "snakecg.cli", "export", "--robot", str(path),
                          "--out", str(lib)], capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    assert "snakecg_sp3.h" in res.stdout
    subprocess.run(["make", "-s", "-C", str(lib), "libsnakecg_sp3.a"], check=True,
                   capture_output=True)
    (lib / "check.c").write_text(_DRIVER.format(na=robot.joints))
    subprocess.run(["cc", "-O2", "-std=gnu99", "-o", str(lib / "check"), str(lib / "check.c"),
                    str(lib / "libsnakecg_sp3.a"), "-lm"], check=True, cwd=lib)
    model = pinocchio_chain(robot)
    model.gravity.linear = np.array([0.0, 0.0, -9.81])  # a URDF has no gravity: the default
    data = model.createData()
    nv, nl = model.nv, robot.n_links
    for _ in range(3):
        q = pin.randomConfiguration(model, -2 * np.ones(model.nq), 2 * np.ones(model.nq))
        v = rng.normal(size=nv)
        out = subprocess.run([str(lib / "check"), *map(repr, np.r_[q, v].tolist())],
                             check=True, capture_output=True, text=True).stdout
        got = {line.split()[0]: np.array(line.split()[1:], float) for line in out.splitlines()}
        Mp = pin.crba(model, data, q)
        assert rel(got["M"].reshape(nv, nv).T, np.triu(Mp) + np.triu(Mp, 1).T) <= 1e-12
        assert rel(got["h"], pin.rnea(model, data, q, v, np.zeros(nv))) <= 1e-12
        J = got["J"].reshape(nv, nl, 6).transpose(1, 2, 0)  # column-major (6 n_l) x n_v
        bias = got["b"].reshape(nl, 6)  # column-major 6 x n_l: one column per link
        pin.forwardKinematics(model, data, q, v, np.zeros(nv))
        pin.computeJointJacobians(model, data, q)
        for i in range(nl):
            assert rel(J[i], pin.getJointJacobian(model, data, i + 1,
                                                  pin.LOCAL_WORLD_ALIGNED)) <= 1e-12
            acc = pin.getClassicalAcceleration(model, data, i + 1, pin.LOCAL_WORLD_ALIGNED)
            assert rel(bias[i], np.r_[acc.linear, acc.angular]) <= 1e-12


def test_cli_export_takes_a_spatial_scene_file(tmp_path):
    """`snakecg export --scene` of a spatial scene file (and --robot of its TOML) exports
    the scene's robot, its parameters baked in."""
    from snakecg.spatial.scene_file import read_spatial_scene

    scene = Path(__file__).resolve().parents[1] / "examples" / "spatial" / "yaw_pitch.toml"
    for flag in ("--scene", "--robot"):
        out = tmp_path / flag.strip("-")
        res = subprocess.run([sys.executable, "-m", "snakecg.cli", "export", flag, str(scene),
                              "--out", str(out), "--json"], capture_output=True, text=True)
        assert res.returncode == 0, res.stderr
        assert json.loads(res.stdout)["header"].endswith("snakecg_sp3.h")
        K = snakecg.load(read_spatial_scene(scene).robot).parameters
        text = (out / "robot_params.c").read_text()
        baked = text.split("{", 1)[1].split("}", 1)[0].replace("\n", " ")
        assert np.array_equal(np.array(baked.split(","), float), K)


def test_cli_show_and_export(tmp_path):
    run = lambda *a: subprocess.run([sys.executable, "-m", "snakecg.cli", *a],  # noqa: E731
                                    capture_output=True, text=True)
    r = run("show", "--spatial", "--joints", "1", "mass_matrix")
    assert r.returncode == 0 and "R2_00 = " in r.stdout
    r = run("show", "--spatial", "--joints", "1", "nothing")
    assert r.returncode == 2 and "unknown name 'nothing'" in r.stderr


def test_casadi_backend_equals_compiled(rng):
    """Without a compiler (backend="casadi"): CasADi's in-process evaluation of the
    serialized functions gives the compiled numbers (to 1e-13)."""
    robot = random_robot(rng, 3)
    compiled, vm = snakecg.load(robot), snakecg.load(robot, backend="casadi")
    assert vm.backend_kind == "casadi"
    q, v = _q(rng, robot, 5), rng.normal(size=(5, robot.nv))
    assert rel(vm.mass_matrix(q), compiled.mass_matrix(q)) <= 1e-13
    assert rel(vm.bias_forces(q, v), compiled.bias_forces(q, v)) <= 1e-13
    assert rel(vm.link_jacobians(q), compiled.link_jacobians(q)) <= 1e-13
