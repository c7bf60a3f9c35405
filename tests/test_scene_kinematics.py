"""The generated ``scene_kinematics`` (link poses, Jacobians and M_s in one function, the joints'
sines and cosines taken once; what a general scene's forward and time step call) against NumPy
written apart: the links' centres of mass and headings from the chain's own planar kinematics
(tests/capsule_reference.py's ends), the Jacobians by central differences of those poses, and
M_s = sum_i J_i^T diag(m_i, m_i, I_i) J_i (eq. 4) from those Jacobians (and M_s symmetric entry
for entry); and the separate ``link_poses`` and ``link_jacobians`` byte for byte,
``mass_matrix`` to its rounding (CasADi orders a few of the shared graph's sums otherwise: an
ulp or two)."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from capsule_reference import link_segments


def _poses(robot, q):
    """(n_l, 3): each link's centre of mass (its rear end plus c_i along it) and heading."""
    c = np.asarray(robot.com)
    out = []
    for i, (rear, front) in enumerate(link_segments(robot, q)):
        e = (front - rear) / np.hypot(*(front - rear))
        out.append([*(rear + c[i] * e), q[2] + np.sum(q[3:3 + i])])
    return np.array(out)


@pytest.mark.parametrize("joints", [1, 3, 5])
def test_scene_kinematics_against_numpy(joints, rng, random_robot):
    robot = random_robot(joints)
    model = snakecg.load(snakecg.Scene(robot))
    ns, nl = robot.n_coordinates, robot.n_links
    Q = np.c_[rng.uniform(-1, 1, (6, 2)), rng.uniform(-np.pi, np.pi, (6, ns - 2))]
    out = model._named("scene_kinematics", len(Q), q=Q, K=model.parameters)
    h = 1e-6
    for k, q in enumerate(Q):
        P = out["poses"][k].T  # (n_l, 3)
        J = out["J"][k].reshape(nl, 3, ns)
        np.testing.assert_allclose(P, _poses(robot, q), rtol=0, atol=1e-14)
        fd = np.stack([(_poses(robot, q + h * e) - _poses(robot, q - h * e)) / (2 * h)
                       for e in np.eye(ns)], axis=-1)
        np.testing.assert_allclose(J, fd, rtol=0, atol=1e-8)
        D = [np.diag([m, m, i]) for m, i in zip(robot.mass, robot.inertia)]
        M = sum(J[i].T @ D[i] @ J[i] for i in range(nl))
        np.testing.assert_allclose(out["M"][k], M, rtol=0, atol=1e-13 * np.abs(M).max())
        # symmetric entry for entry, as a mass matrix is (the general scenes copy its columns
        # as the rows of their inertia)
        assert np.array_equal(out["M"][k], out["M"][k].T)
        assert np.array_equal(P, model.link_poses(q))
        assert np.array_equal(J, model.link_jacobians(q))
        np.testing.assert_allclose(out["M"][k], model.mass_matrix(q), rtol=0,
                                   atol=4e-16 * np.abs(M).max())


@pytest.mark.parametrize("joints", [1, 3, 5])
def test_scene_sines_and_bias_forces_from_them(joints, rng, random_robot):
    """``scene_kinematics``' links' cosines and sines (what the scene's placement reads)
    against NumPy's of the reference headings; ``bias_forces_cs`` from them (what the time
    step calls) against the dense NumPy reference's h_s (tests/reference.py: J_i by complex
    step, Jdot_i v by central differences) and against ``bias_forces`` from q bit for bit."""
    from reference import Reference

    robot = random_robot(joints)
    scene = snakecg.Scene(robot)
    model, ref = snakecg.load(scene), Reference(scene)
    ns, nl = robot.n_coordinates, robot.n_links
    Q = np.c_[rng.uniform(-1, 1, (6, 2)), rng.uniform(-np.pi, np.pi, (6, ns - 2))]
    V = rng.uniform(-2, 2, (6, ns))
    cs = model._named("scene_kinematics", len(Q), q=Q, K=model.parameters)["cs"]
    # (the engine's memory: column i = link i's (cos, sin), column-major)
    flat = cs.transpose(0, 2, 1).reshape(len(Q), 2 * nl)
    h = model._named("bias_forces_cs", len(Q), cs=flat, q=Q, v=V, K=model.parameters)["h"]
    for k, (q, v) in enumerate(zip(Q, V)):
        phi = _poses(robot, q)[:, 2]
        np.testing.assert_allclose(cs[k], np.stack([np.cos(phi), np.sin(phi)]), rtol=0,
                                   atol=4e-15)
        href = ref.bias_forces(q, v)
        scale = np.abs(href).max()
        np.testing.assert_allclose(h[k].ravel(), href, rtol=0, atol=1e-7 * scale)
        # the same sums in the same order as from q (the inputs named as the chain's own)
        assert np.array_equal(h[k].ravel(), model.bias_forces(q, v))
