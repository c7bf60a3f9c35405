"""The generated model against independent numeric references, at seeded random states.

References written here, from the conventions only (docs/explanation/model.md, notes): link COM
poses of the chain in plain numpy; velocities by complex-step differentiation of those poses (a
finite difference along an imaginary step, exact to rounding for analytic functions); kinetic
energy of the links; Christoffel symbols of finite-differenced ``M_s``; time derivatives of the
constraint rows along a trajectory by central finite differences. Also: compiled C against
CasADi's in-process evaluation, batch semantics, and bad input at the API and CLI boundary.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import snakecg
from snakecg.native import CasadiBackend

ALL_JOINTS = (1, 2, 3, 4, 5, 6, 7, 8)  # 7 and 8 are generated on demand into the cache
SOME_JOINTS = (1, 3, 6)
CS_STEP = 1e-30  # complex step


# ------------------------------------------------------------------------------------------
# Independent reference: the chain in plain numpy (works on complex arrays for complex steps)
# ------------------------------------------------------------------------------------------
def chain(q, robot):
    """COM positions ``(n_l, 2)``, absolute angles ``(n_l,)``, rear ends and axes of the links.

    ``(x, y)`` is the COM of link 1 and ``theta`` its angle; ``phi_{j+1} = phi_j + q_j``; each
    link's rear end is its COM minus ``c_i e_i``; the rear end of link ``i + 1`` is the front
    end of link ``i`` (rear end + ``l_i e_i``).
    """
    q = np.asarray(q)
    length, com = np.asarray(robot.length), np.asarray(robot.com)
    phi = q[2] + np.concatenate([[0.0], np.cumsum(q[3:])])
    axis = np.stack([np.cos(phi), np.sin(phi)], axis=-1)
    rear = [q[:2] - com[0] * axis[0]]
    for i in range(1, robot.n_links):
        rear.append(rear[-1] + length[i - 1] * axis[i - 1])
    rear = np.array(rear)
    return rear + com[:, None] * axis, phi, rear, axis


def link_twists(q, qdot, robot):
    """``(n_l, 3)`` COM velocity and angular velocity of each link, by complex step."""
    p, phi, _, _ = chain(np.asarray(q) + 1j * CS_STEP * np.asarray(qdot), robot)
    return np.column_stack([p.imag / CS_STEP, phi.imag / CS_STEP])


def kinetic_energy(q, qdot, robot):
    """``T = 1/2 sum_i (m_i |v_i|^2 + I_i omega_i^2)``."""
    tw = link_twists(q, qdot, robot)
    m, inertia = np.asarray(robot.mass), np.asarray(robot.inertia)
    return 0.5 * np.sum(m * (tw[:, 0] ** 2 + tw[:, 1] ** 2) + inertia * tw[:, 2] ** 2)


def mass_matrix_by_polarization(q, robot):
    """``M_ab`` from the kinetic energy: ``T(e_a) = M_aa / 2``,
    ``M_ab = T(e_a + e_b) - T(e_a) - T(e_b)``."""
    n = robot.n_coordinates
    eye = np.eye(n)
    T1 = np.array([kinetic_energy(q, eye[a], robot) for a in range(n)])
    M = np.diag(2 * T1)
    for a in range(n):
        for b in range(a + 1, n):
            M[a, b] = M[b, a] = kinetic_energy(q, eye[a] + eye[b], robot) - T1[a] - T1[b]
    return M


def random_q(rng, robot, size=None):
    shape = (robot.n_coordinates,) if size is None else (size, robot.n_coordinates)
    q = rng.uniform(-np.pi, np.pi, shape)
    q[..., :2] = rng.uniform(-3, 3, q[..., :2].shape)
    return q


def assert_scaled_close(M, Mref, tol):
    """``|M_ab - Mref_ab| <= tol sqrt(Mref_aa Mref_bb)`` (the natural scale of an entry of a
    positive definite matrix, by Cauchy-Schwarz)."""
    d = np.sqrt(np.abs(np.diag(Mref)))
    err = np.abs(M - Mref) / np.outer(d, d)
    assert err.max() <= tol, f"max scaled error {err.max():.3e} > {tol:g}"


# ------------------------------------------------------------------------------------------
# M_s against the kinetic energy of the links
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("joints", ALL_JOINTS)
def test_mass_matrix_equals_kinetic_energy_of_links(joints, rng, random_robot):
    for _ in range(3):
        robot = random_robot(joints)
        model = snakecg.load(robot)
        Q = random_q(rng, robot, 4)
        Ms = model.mass_matrix(Q)
        for q, M in zip(Q, Ms):
            assert_scaled_close(M, mass_matrix_by_polarization(q, robot), 1e-12)
            for qdot in rng.normal(size=(5, robot.n_coordinates)):
                T = kinetic_energy(q, qdot, robot)
                assert 0.5 * qdot @ M @ qdot == pytest.approx(T, rel=1e-11)


@pytest.mark.parametrize("joints", ALL_JOINTS)
def test_mass_matrix_symmetric_positive_definite(joints, rng, random_robot):
    robot = random_robot(joints)
    model = snakecg.load(robot)
    Q = random_q(rng, robot, 50)
    Q[0, 3:] = 0.0  # stretched out
    Q[1, 3:] = np.pi  # folded on itself
    M = model.mass_matrix(Q)
    np.testing.assert_allclose(M, M.transpose(0, 2, 1), rtol=0, atol=1e-15 * np.abs(M).max())
    # positive definite: the Cholesky factor exists and no eigenvalue is (relatively) zero
    np.linalg.cholesky(M)
    eig = np.linalg.eigvalsh(M)
    assert np.all(eig[:, 0] > 1e-14 * eig[:, -1])
    # translation block: total mass, the COM moves with (x, y) at fixed angles
    m = robot.total_mass
    np.testing.assert_allclose(M[:, :2, :2], np.broadcast_to(m * np.eye(2), (50, 2, 2)),
                               rtol=1e-14)


# ------------------------------------------------------------------------------------------
# Poses and Jacobians
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("joints", ALL_JOINTS)
def test_link_poses_match_reference_chain(joints, rng, random_robot):
    robot = random_robot(joints)
    model = snakecg.load(robot)
    Q = random_q(rng, robot, 10)
    P = model.link_poses(Q)
    for q, Pq in zip(Q, P):
        p, phi, _, _ = chain(q, robot)
        np.testing.assert_allclose(Pq[:, :2], p, rtol=0, atol=1e-13 * (1 + np.abs(p).max()))
        np.testing.assert_allclose(Pq[:, 2], phi, rtol=0, atol=1e-13)


@pytest.mark.parametrize("joints", ALL_JOINTS)
def test_link_jacobians_against_finite_differences_of_poses(joints, rng, random_robot):
    robot = random_robot(joints)
    model = snakecg.load(robot)
    ns, h = robot.n_coordinates, 1e-6
    for q in random_q(rng, robot, 3):
        J = model.link_jacobians(q)  # (n_l, 3, n_s)
        assert J.shape == (robot.n_links, 3, ns)
        steps = np.concatenate([q + h * np.eye(ns), q - h * np.eye(ns)])
        P = model.link_poses(steps)  # (2 n_s, n_l, 3)
        fd = (P[:ns] - P[ns:]) / (2 * h)  # (n_s, n_l, 3)
        scale = 1 + np.abs(J).max()
        np.testing.assert_allclose(J, fd.transpose(1, 2, 0), rtol=0, atol=1e-8 * scale)
        # and against the complex-step twists of the independent chain, for random qdot
        qdot = rng.normal(size=ns)
        np.testing.assert_allclose(J @ qdot, link_twists(q, qdot, robot), rtol=0,
                                   atol=1e-12 * scale * np.abs(qdot).sum())


@pytest.mark.parametrize("joints", SOME_JOINTS)
def test_link_bias_accelerations_against_finite_differences(joints, rng, random_robot):
    """``Jdot_i qdot = d/dt (J_i(q + t v) v)`` at ``t = 0``."""
    robot = random_robot(joints)
    model = snakecg.load(robot)
    ns, h = robot.n_coordinates, 1e-6
    q, v = random_q(rng, robot), rng.normal(size=ns)
    (bias,) = model.backend("link_bias_accelerations", 1, [q, v, model.parameters])
    J = model.link_jacobians(np.stack([q + h * v, q - h * v]))
    fd = (J[0] - J[1]) @ v / (2 * h)  # (n_l, 3)
    np.testing.assert_allclose(bias[0].T, fd, rtol=0, atol=1e-7 * (1 + np.abs(fd).max()))


# ------------------------------------------------------------------------------------------
# h_s against the Christoffel symbols of dM/dq
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("joints", ALL_JOINTS)
def test_bias_forces_are_christoffel_terms(joints, rng, random_robot):
    """``h_i = sum_jk (dM_ij/dq_k - 1/2 dM_jk/dq_i) v_j v_k`` (Christoffel symbols of the
    first kind contracted with ``v v``), with ``dM/dq`` by central differences."""
    robot = random_robot(joints)
    model = snakecg.load(robot)
    ns, h = robot.n_coordinates, 1e-5
    for q in random_q(rng, robot, 3):
        v = rng.normal(size=ns)
        Ms = model.mass_matrix(np.concatenate([q + h * np.eye(ns), q - h * np.eye(ns)]))
        dM = (Ms[:ns] - Ms[ns:]) / (2 * h)  # dM[k] = dM/dq_k
        ref = np.einsum("kij,j,k->i", dM, v, v) - 0.5 * np.einsum("ijk,j,k->i", dM, v, v)
        got = model.bias_forces(q, v)
        scale = np.abs(model.mass_matrix(q)).max() * (v @ v)
        np.testing.assert_allclose(got, ref, rtol=0, atol=1e-8 * scale)
        # h is quadratic in v
        np.testing.assert_allclose(model.bias_forces(q, -2.5 * v), 6.25 * got, rtol=1e-12,
                                   atol=1e-14 * scale)


# ------------------------------------------------------------------------------------------
# A a + Adot v: the rows' accelerations w of forward() against the rows' rates differentiated
# along the trajectory
# ------------------------------------------------------------------------------------------
def row_rates(q, v, q_obj, v_obj, rho, robot, scene):
    """Independent rows' velocities: the contact gap rate (row 0) and every link's lateral
    wheel velocity (rows 1..n_l), by complex step of the positions along the velocities."""
    k = scene.contact_link - 1
    sigma = scene.side_sign
    woff = np.asarray(scene.wheel_offset)

    def gap(qc, qoc):
        _, phi, rear, _ = chain(qc, robot)
        n = sigma * np.array([-np.sin(phi[k]), np.cos(phi[k])])
        c, s = np.cos(qoc[2]), np.sin(qoc[2])
        P = qoc[:2] + np.array([c * rho[0] - s * rho[1], s * rho[0] + c * rho[1]])
        return n @ (P - rear[k])

    gap_rate = gap(q + 1j * CS_STEP * v, q_obj + 1j * CS_STEP * v_obj).imag / CS_STEP
    tw = link_twists(q, v, robot)
    _, phi, _, _ = chain(q, robot)
    # wheel at woff from the COM along the link: its lateral velocity is n_i . v_com + woff w
    lateral = -np.sin(phi) * tw[:, 0] + np.cos(phi) * tw[:, 1] + woff * tw[:, 2]
    return np.concatenate([[gap_rate], lateral])


@pytest.mark.parametrize("joints", SOME_JOINTS)
@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
def test_row_accelerations_against_finite_differences(joints, scenario, rng, random_robot):
    robot = random_robot(joints)
    for _ in range(2):
        scene = snakecg.Scene(
            robot, scenario=scenario, kappa=float(rng.uniform(1, 200)),
            contact_link=int(rng.integers(1, robot.n_links + 1)),
            side=str(rng.choice(["left", "right"])),
            wheel_offset=tuple(rng.uniform(-0.5, 0.5, robot.n_links) * np.array(robot.length)),
        )
        model = snakecg.load(scene)
        ns = robot.n_coordinates
        q, v = random_q(rng, robot), rng.normal(size=ns)
        q_obj, v_obj = rng.normal(size=3), rng.normal(size=3)
        rho = rng.normal(scale=0.1, size=2)
        tau = rng.normal(scale=0.5, size=joints)
        res = model.forward(q, tau, v=v, v_obj=v_obj, q_obj=q_obj, rho=rho,
                            f_obj=rng.normal(size=3))
        assert not res.singular
        # rows' rates along q(t) = q + t v + t^2/2 qdd, v(t) = v + t qdd (likewise the object),
        # differentiated at t = 0 by the five-point central stencil (error O(h^4))
        h = 1e-4
        rates = {}
        for t in (-2 * h, -h, h, 2 * h):
            rates[t] = row_rates(q + t * v + t * t / 2 * res.qdd, v + t * res.qdd,
                                 q_obj + t * v_obj + t * t / 2 * res.a_obj,
                                 v_obj + t * res.a_obj, rho, robot, scene)
        fd = (rates[-2 * h] - 8 * rates[-h] + 8 * rates[h] - rates[2 * h]) / (12 * h)
        scale = 1 + np.abs(res.qdd).max() + np.abs(res.a_obj).max() + np.abs(v).max() ** 2
        np.testing.assert_allclose(res.w, fd, rtol=0, atol=1e-8 * scale)


# ------------------------------------------------------------------------------------------
# Compiled C against CasADi's in-process evaluation
# ------------------------------------------------------------------------------------------
def _inputs_for(sig, model, rng, n):
    """Plausible random inputs for every generated function (a real K, one-hot link, ...)."""
    nl = model.n_links
    robot = model.robot
    per_link = {"link_mass": robot.mass, "link_length": robot.length,
                "link_inertia": robot.inertia, "link_com": robot.com}
    free = np.concatenate([[1.0], (rng.uniform(size=model.n_constraints - 1) < 0.7)])
    out = []
    for name, size in zip(sig.in_names, sig.in_sizes):
        if name == "K":
            a = model.parameters
        elif name in per_link and size == nl:  # derived_parameters
            a = np.asarray(per_link[name], float)
        elif name == "contact_link":
            a = np.eye(nl)[rng.integers(nl)]
        elif name == "side":
            a = np.array([rng.choice([-1.0, 1.0])])
        elif name in ("object_mass", "object_inertia", "link_com", "object_distance"):
            a = rng.uniform(0.05, 5.0, size)
        elif name == "free":  # held rows: the contact and some wheels
            a = free
        elif name == "free_lost":  # the same rows with the contact lost
            a = np.concatenate([[0.0], free[1:]])
        elif name == "regularization":
            a = np.zeros(1)
        elif name == "placed":  # contact_system: the object given (0) or placed from q (1)
            a = np.array([float(rng.integers(2))])
        elif name == "cs":  # bias_forces_cs: the links' cosines and sines, 2 x n_l by columns
            phi = rng.normal(size=(n, size // 2)) if n > 1 else rng.normal(size=size // 2)
            a = np.stack([np.cos(phi), np.sin(phi)], axis=-1).reshape(phi.shape[:-1] + (size,))
        elif name in ("q", "v", "tau", "q_obj", "v_obj", "f_obj", "link_pose", "link_twist",
                      "link_bias", "object_pose", "object_twist", "rho", "wheel_offset",
                      "lam_fixed", "contact_offset"):
            a = rng.normal(size=(n, size)) if n > 1 else rng.normal(size=size)
        else:  # a new input: make the test author decide what it should be
            raise AssertionError(f"no test input for {sig.name}({name})")
        out.append(np.ascontiguousarray(a, dtype=float))
    return out


@pytest.mark.parametrize("joints", SOME_JOINTS)
def test_compiled_agrees_with_casadi_in_process(joints, rng, random_robot):
    robot = random_robot(joints)
    model = snakecg.load(robot)
    assert model.backend.kind == "compiled", "no C compiler? the compiled backend is required"
    ca_backend = CasadiBackend(model.folder, model.manifest)
    names = [f["name"] for f in model.manifest["functions"]]
    assert set(names) == set(model.backend.signatures)
    for name in names:
        sig = model.backend.signatures[name]
        for n in (1, 4):
            args = _inputs_for(sig, model, rng, n)
            got = model.backend(name, n, args)
            ref = ca_backend(name, n, args)
            for oname, g, r in zip(sig.out_names, got, ref):
                assert g.shape == r.shape == (n, *sig.out_shapes[sig.out_names.index(oname)])
                assert np.all(np.isfinite(r)), f"{name}.{oname} not finite"
                scale = max(1.0, np.abs(r).max())
                np.testing.assert_allclose(g, r, rtol=0, atol=1e-12 * scale,
                                           err_msg=f"{name}.{oname} (n={n})")


@pytest.mark.parametrize("joints", SOME_JOINTS)
def test_contact_system_at_rest_is_contact_system_without_velocities(joints, rng,
                                                                     random_robot):
    """The at-rest variant equals contact_system with v = 0 and v_obj = 0 (placed and given
    objects), and forward gives the same answer through either: at rest, and with velocities
    of 1e-200 (which the core sends through the full function)."""
    robot = random_robot(joints)
    scene = snakecg.Scene(robot, scenario="wheels", kappa=float(rng.uniform(1, 200)),
                          contact_link=int(rng.integers(1, robot.n_links + 1)))
    model = snakecg.load(scene)
    full, rest = (model.backend.signatures[k] for k in ("contact_system",
                                                        "contact_system_at_rest"))
    n = 8
    args = dict(zip(full.in_names, _inputs_for(full, model, rng, n)))
    args["v"], args["v_obj"] = np.zeros(model.n_coordinates), np.zeros(3)
    args["placed"] = np.array([1.0])
    for placed in (0.0, 1.0):
        args["placed"] = np.array([placed])
        a = model.backend("contact_system", n, [args[k] for k in full.in_names])
        b = model.backend("contact_system_at_rest", n, [args[k] for k in rest.in_names])
        assert rest.out_names == full.out_names
        for oname, x, y in zip(full.out_names, a, b):
            np.testing.assert_allclose(y, x, rtol=0, atol=1e-13 * max(1.0, np.abs(x).max()),
                                       err_msg=f"{oname}, placed = {placed}")
    Q = random_q(rng, robot, 16)
    T = rng.normal(scale=0.3, size=(16, joints))
    at_rest = model.forward(Q, T)
    moving = model.forward(Q, T, v=np.full(model.n_coordinates, 1e-200))
    for field in ("qdd", "a_obj", "lam", "w", "norm_qdd", "norm_a_obj", "norm_lambda", "sr"):
        x, y = getattr(at_rest, field), getattr(moving, field)
        np.testing.assert_allclose(y, x, rtol=1e-12, atol=1e-15, err_msg=field)


@pytest.mark.parametrize("joints", (2,))
def test_load_with_casadi_backend_matches_compiled(joints, rng, random_robot):
    robot = random_robot(joints)
    a = snakecg.load(robot)
    b = snakecg.load(robot, backend="casadi")
    assert (a.backend_kind, b.backend_kind) == ("compiled", "casadi")
    Q = random_q(rng, robot, 6)
    V = rng.normal(size=Q.shape)
    for fa, fb in ((a.mass_matrix, b.mass_matrix), (a.link_jacobians, b.link_jacobians),
                   (a.link_poses, b.link_poses)):
        np.testing.assert_allclose(fa(Q), fb(Q), rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(a.bias_forces(Q, V), b.bias_forces(Q, V), rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(a.parameters, b.parameters, rtol=1e-15)


@pytest.mark.parametrize("joints", (1, 3, 6))
def test_batched_mass_matrix_sines_against_c_library(joints, rng, random_robot):
    """The batched ``mass_matrix`` computes the sines and cosines of a block of samples in its
    own vectorized loop (reduction by pi/2, polynomials; the C library above 8e5 rad): against
    the CasADi backend, whose sines are the C library's, for angles from 0.01 to 1e15 rad and
    batch sizes that end in a partial block."""
    robot = random_robot(joints)
    compiled = snakecg.load(robot)
    assert compiled.backend.kind == "compiled", "no C compiler? the compiled backend is required"
    reference = snakecg.load(robot, backend="casadi")
    for scale in (1e-2, 3.2, 40.0, 1e5, 7.9e5, 8.1e5, 1e15):
        for n in (1, 5, 37):
            Q = rng.uniform(-scale, scale, (n, robot.n_coordinates))
            ref = reference.mass_matrix(Q)
            np.testing.assert_allclose(compiled.mass_matrix(Q), ref, rtol=0,
                                       atol=4e-16 * np.abs(ref).max(),
                                       err_msg=f"angles up to {scale}, {n} samples")


# ------------------------------------------------------------------------------------------
# Batch semantics
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("joints", (1, 4))
def test_batch_equals_loop_of_single_calls(joints, rng, random_robot):
    robot = random_robot(joints)
    model = snakecg.load(robot)
    ns, nl, N = robot.n_coordinates, robot.n_links, 7
    Q, V = random_q(rng, robot, N), rng.normal(size=(N, ns))
    M = model.mass_matrix(Q)
    J = model.link_jacobians(Q)
    P = model.link_poses(Q)
    H = model.bias_forces(Q, V)
    assert (M.shape, J.shape, P.shape, H.shape) == (
        (N, ns, ns), (N, nl, 3, ns), (N, nl, 3), (N, ns))
    for i in range(N):
        np.testing.assert_array_equal(M[i], model.mass_matrix(Q[i]))
        np.testing.assert_array_equal(J[i], model.link_jacobians(Q[i]))
        np.testing.assert_array_equal(P[i], model.link_poses(Q[i]))
        np.testing.assert_array_equal(H[i], model.bias_forces(Q[i], V[i]))
    # one sample broadcasts against a batch; lists are accepted like arrays
    np.testing.assert_array_equal(model.bias_forces(Q[2], V), np.stack(
        [model.bias_forces(Q[2], v) for v in V]))
    np.testing.assert_array_equal(model.bias_forces(Q, V[3]), np.stack(
        [model.bias_forces(q, V[3]) for q in Q]))
    np.testing.assert_array_equal(model.mass_matrix(list(Q[0])), M[0])
    # a batch of one keeps its batch axis
    assert model.mass_matrix(Q[:1]).shape == (1, ns, ns)


def test_forward_batch_equals_loop(rng, random_robot):
    robot = random_robot(3)
    model = snakecg.load(snakecg.Scene(robot, scenario="wheels", kappa=50.0))
    N = 6
    Q = random_q(rng, robot, N)
    T = rng.normal(scale=0.3, size=(N, 3))
    batch = model.forward(Q, T)
    for i in range(N):
        one = model.forward(Q[i], T[i])
        for k in ("qdd", "a_obj", "lam", "w", "norm_lambda", "norm_a_obj", "norm_qdd", "sr"):
            np.testing.assert_allclose(getattr(batch, k)[i], getattr(one, k), rtol=1e-12,
                                       atol=1e-12, err_msg=k)
        assert batch.contact[i] == one.contact
        assert list(batch.wheel_state[i]) == list(one.wheel_state)


def test_batch_size_mismatch_and_bad_ranks_raise(rng):
    model = snakecg.load(snakecg.Robot(joints=2))
    with pytest.raises(snakecg.InputError, match=r"batch sizes differ \(q: 3, v: 4\)"):
        model.bias_forces(np.zeros((3, 5)), np.zeros((4, 5)))
    with pytest.raises(snakecg.InputError, match=r"q has shape \(2, 3, 5\), expected \(5,\) or "
                                                 r"\(N, 5\)"):
        model.mass_matrix(np.zeros((2, 3, 5)))
    with pytest.raises(snakecg.InputError, match=r"q has shape \(3, 4\), expected \(5,\)"):
        model.link_jacobians(np.zeros((3, 4)))
    scene = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))
    with pytest.raises(snakecg.InputError, match=r"batch sizes differ \(q: 2, tau: 3\)"):
        scene.forward(np.zeros((2, 5)), np.zeros((3, 2)))


# ------------------------------------------------------------------------------------------
# Bad input: InputError (a ValueError) naming the argument and the expected form
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("joints", [0, -1, 2.5, True, "3", None])
def test_bad_joint_count(joints):
    with pytest.raises(snakecg.InputError, match=r"joints must be an integer >= 1, got"):
        snakecg.Robot(joints=joints)


def test_input_error_is_value_error():
    assert issubclass(snakecg.InputError, ValueError)


def test_bad_q_shape_and_values():
    model = snakecg.load(snakecg.Robot(joints=2))
    expected = r"expected \(5,\) or \(N, 5\) = \(n_joints \+ 3,\) for a 2-joint robot"
    for bad, shape in (([0.0] * 4, r"\(4,\)"), ([0.0] * 6, r"\(6,\)"), (0.0, r"\(\)"),
                       (np.zeros((0, 5)), r"\(0, 5\)")):
        with pytest.raises(snakecg.InputError, match=rf"q has shape {shape}, {expected}"):
            model.mass_matrix(bad)
    with pytest.raises(snakecg.InputError, match=r"q must be finite, found nan at index \(0, 3\)"):
        model.mass_matrix([0, 0, 0, np.nan, 0])
    with pytest.raises(snakecg.InputError, match=r"q must be finite, found inf"):
        model.link_jacobians([[0, 0, 0, 0, 0], [0, 0, np.inf, 0, 0]])
    with pytest.raises(snakecg.InputError, match=r"v must be finite"):
        model.bias_forces(np.zeros(5), [0, 0, 0, 0, np.nan])
    with pytest.raises(snakecg.InputError, match=r"q must be numeric with shape \(5,\)"):
        model.mass_matrix(["a", 0, 0, 0, 0])
    scene = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))
    with pytest.raises(snakecg.InputError, match=r"tau has shape \(3,\), expected \(2,\) or "
                                                 r"\(N, 2\) \(one torque per joint"):
        scene.forward(np.zeros(5), np.zeros(3))


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"mass": 0.0}, r"mass must be positive finite, got 0\.0"),
        ({"mass": -1.0}, r"mass must be positive finite, got -1\.0"),
        ({"mass": (1.0, 1.0, -2.0)}, r"mass must be positive finite, got -2\.0"),
        ({"length": 0.0}, r"length must be positive finite, got 0\.0"),
        ({"length": float("nan")}, r"length must be positive finite, got nan"),
        ({"inertia": -0.1}, r"inertia must be positive finite"),
        ({"mass": (1.0, 2.0)}, r"mass has 2 values, expected one number or 3 \(= joints \+ 1, "
                               r"one per link\)"),
        ({"length": [0.1] * 4}, r"length has 4 values, expected one number or 3"),
        ({"com": (0.1, 0.1, 0.2), "length": 0.15}, r"com of link 3 is 0\.2 m, beyond its "
                                                    r"length 0\.15 m"),
        ({"mass": "heavy"}, r"mass must be a number or a list of 3 numbers, got 'heavy'"),
    ],
)
def test_bad_link_parameters(kwargs, message):
    with pytest.raises(snakecg.InputError, match=message):
        snakecg.Robot(joints=2, **kwargs)


def test_bad_link_parameters_reported_together():
    with pytest.raises(snakecg.InputError, match=r"mass must be positive.*; length has 2 values"):
        snakecg.Robot(joints=2, mass=0.0, length=(0.1, 0.1))


@pytest.mark.parametrize("link", [0, 4, -1, 1.0, True])
def test_unknown_contact_link(link):
    with pytest.raises(snakecg.InputError, match=rf"contact_link must be a link number 1\.\.3, "
                                                 rf"got {link!r}"):
        snakecg.Scene(snakecg.Robot(joints=2), contact_link=link)


def test_load_rejects_other_objects():
    with pytest.raises(snakecg.InputError, match=r"load\(\) takes a snakecg\.Robot, "
                                                 r"snakecg\.Scene, snakecg\.SpatialRobot or "
                                                 r"snakecg\.SpatialScene \(or a "
                                                 r"snakecg\.scenes\.GeneralScene\), "
                                                 r"got int"):
        snakecg.load(3)


def test_cli_input_error_one_line_exit_2():
    """``snakecg forward --joints 2 --q 0,0 --tau 0,0``: wrong q length."""
    proc = subprocess.run(
        [sys.executable, "-m", "snakecg.cli", "forward", "--joints", "2", "--q", "0,0",
         "--tau", "0,0"],
        capture_output=True, text=True, timeout=120,
    )
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.splitlines()
    assert len(lines) == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    assert lines[0].startswith("snakecg forward: error: q has shape (2,), expected (5,)")
    assert proc.stdout == ""


@pytest.mark.parametrize(
    "argv, message",
    [
        (["forward", "--joints", "0", "--q", "0", "--tau", "0"], "joints must be an integer >= 1"),
        (["forward", "--joints", "2", "--q", "0,0,0,x,0", "--tau", "0,0"],
         "--q must be numbers separated by commas"),
        (["forward", "--joints", "2", "--q", "0,0,0,0,0", "--tau", "0,0", "--contact-link", "7"],
         "contact_link must be a link number 1..3, got 7"),
        (["forward", "--joints", "two"], "argument --joints: invalid int value"),
    ],
)
def test_cli_errors_in_process(argv, message, capsys):
    from snakecg.cli import main

    try:
        status = main(argv)
    except SystemExit as exc:  # argparse's own usage errors
        status = exc.code
    err = capsys.readouterr().err
    assert status == 2
    assert len(err.splitlines()) == 1, err
    assert message in err
    assert "Traceback" not in err


# ------------------------------------------------------------------------------------------
# the matrix-structured (MX) composition used above SX_MAX_JOINTS, against the dense reference
def _reference_forward(ref, q, tau, v, v_obj):
    """All rows of an ideal-wheels scene held: forces and accelerations from the dense
    reference (tests/reference.py), written from eqs. (12)-(13)."""
    sys_ = ref.system(q, tau, v=v, v_obj=v_obj)
    lam = ref.solve_given(sys_, ["held"] * ref.nc)
    return sys_, ref.outcome(sys_, lam)


def _compare_composed(backend, sm, ref, rng, samples=3):
    from snakecg import kernels

    na, ns, nc = sm.n_joints, sm.n_coordinates, sm.n_constraints
    for _ in range(samples):
        q = np.concatenate([rng.normal(size=3), rng.uniform(-1.2, 1.2, na)])
        v = rng.normal(scale=0.3, size=ns)
        v_obj = rng.normal(scale=0.1, size=3)
        tau = rng.normal(scale=0.5, size=na)
        sys_, expect = _reference_forward(ref, q, tau, v, v_obj)
        common = dict(K=sm.parameters, contact_link=sm._contact_link, side=sm._side,
                      object_mass=sm._object_mass, object_inertia=sm._object_inertia,
                      rho=sys_["rho"], wheel_offset=sm._wheel_offset, q_obj=sys_["q_obj"],
                      free=np.ones(nc), lam_fixed=np.zeros(nc), regularization=np.zeros(1))
        out = kernels.call(backend, "constrained_dynamics", 1, q=q, v=v, tau=tau, v_obj=v_obj,
                           f_obj=np.zeros(3), **common)
        scale = max(1.0, np.abs(expect["lam"]).max())
        np.testing.assert_allclose(out["lam"][0, :, 0], expect["lam"], atol=1e-7 * scale)
        np.testing.assert_allclose(out["qdd"][0, :, 0], expect["qdd"],
                                   atol=1e-7 * max(1.0, np.abs(expect["qdd"]).max()))
        np.testing.assert_allclose(out["delassus"][0], sys_["Gc"],
                                   atol=1e-8 * np.abs(sys_["Gc"]).max())
        # eq. (17) and (22) at rest: the maps reproduce the reference's response to tau
        rest = {k: val for k, val in common.items()}
        maps = kernels.call(backend, "interaction_maps", 1, q=q, **rest)
        _, at_rest = _reference_forward(ref, q, tau, np.zeros(ns), np.zeros(3))
        np.testing.assert_allclose(maps["lam_from_tau"][0] @ tau, at_rest["lam"],
                                   atol=1e-7 * max(1.0, np.abs(at_rest["lam"]).max()))
        np.testing.assert_allclose(maps["qdd_from_tau"][0] @ tau, at_rest["qdd"],
                                   atol=1e-7 * max(1.0, np.abs(at_rest["qdd"]).max()))
        assert maps["pivot_ratio"][0, 0, 0] > 1e-12


def test_matrix_structured_composition_matches_reference(rng, random_robot, tmp_path):
    """The MX composition (linear-solve nodes, a loop for the pivots), rendered for three
    joints and evaluated by CasADi, against the dense reference: forces, accelerations and
    G_c of eqs. (12)-(14), and the maps of eqs. (17), (22)."""
    from reference import Reference
    from snakecg import artifacts
    from snakecg_derive.render import render_model, write_model

    folder = write_model(render_model(3, algebra="mx"), tmp_path)
    backend = CasadiBackend(folder, artifacts.verify_model_dir(folder, 3))
    scene = snakecg.Scene(random_robot(3), scenario="ideal_wheels")
    _compare_composed(backend, snakecg.load(scene), Reference(scene), rng)


def test_large_model_is_matrix_structured_and_matches_reference(rng, random_robot):
    """A 10-joint model (generated on demand, MX composition by the per-count choice recorded
    in its manifest), compiled, against the dense reference."""
    from reference import Reference

    scene = snakecg.Scene(random_robot(10), scenario="ideal_wheels")
    sm = snakecg.load(scene)
    assert sm.manifest["algebra"]["composed"] == "mx"
    _compare_composed(sm.backend, sm, Reference(scene), rng, samples=2)
