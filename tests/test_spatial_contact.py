"""The spatial contact problem (``contact_system``, ``contact_system_at_rest``) against
independent references: a dense NumPy model built from Pinocchio's M, h, joint Jacobians and
classical accelerations, rigid-body kinematics written here; the planar model (a chain of
yaw joints lying flat is the planar snake); free fall (the ground rows' accelerations at zero
force)."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg

pin = pytest.importorskip("pinocchio")

from test_spatial_references import pinocchio_chain, random_robot, rel


def _call(model, name, **inputs):
    f = model.casadi_function(name)
    out = f.call({k: np.asarray(inputs[k], dtype=float) for k in f.name_in()})
    return {k: np.array(v) for k, v in out.items()}


def _scene_inputs(model, rng, link):
    nl = model.n_links
    onehot = np.zeros(nl)
    onehot[link] = 1.0
    return {"K": model.parameters, "contact_link": onehot, "side": rng.choice([-1.0, 1.0]),
            "object_mass": rng.uniform(0.5, 3), "object_inertia": rng.uniform(0.01, 0.1),
            "wheel_offset": rng.uniform(-0.05, 0.05, nl), "contact_offset": 0.1,
            "object_distance": 0.2}


def _skew(a):
    return np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])


def _reference(robot, q, v, tau, q_obj, v_obj, f_obj, rho, sc):
    """G_c, b, gap and s from Pinocchio's quantities and the rows written out here."""
    pm = pinocchio_chain(robot)
    pd = pm.createData()
    nv, nl = pm.nv, robot.n_links
    M = pin.crba(pm, pd, q)
    M = np.triu(M) + np.triu(M, 1).T
    h = pin.rnea(pm, pd, q, v, np.zeros(nv))
    pin.computeJointJacobians(pm, pd, q)
    pin.forwardKinematics(pm, pd, q, v, np.zeros(nv))
    LWA = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
    links = []
    for i in range(nl):
        jid = i + 1
        J = pin.getJointJacobian(pm, pd, jid, LWA)
        acc = pin.getClassicalAcceleration(pm, pd, jid, LWA)
        vel = pin.getVelocity(pm, pd, jid, LWA)
        R, o = pd.oMi[jid].rotation, pd.oMi[jid].translation
        links.append((J, acc.linear, acc.angular, vel.linear, vel.angular, R, o))

    def point(i, local):
        J, a_o, al, v_o, w, R, o = links[i]
        d = R @ local
        Jp = J[:3] - _skew(d) @ J[3:]
        return o + d, Jp, v_o + np.cross(w, d), a_o + np.cross(al, d) + np.cross(w, np.cross(w, d))

    def heading(i):
        """e, edot, eddot of the link's x axis projected on the ground, normalised."""
        _, _, al, _, w, R, _ = links[i]
        hv = R[:, 0]
        hd = np.cross(w, hv)
        hdd = np.cross(al, hv) + np.cross(w, hd)
        x, xd, xdd = hv[:2], hd[:2], hdd[:2]
        r = np.linalg.norm(x)
        e = x / r
        P = np.eye(2) - np.outer(e, e)
        rd = e @ xd
        ed = P @ xd / r
        Pd = -(np.outer(ed, e) + np.outer(e, ed))
        edd = (Pd @ xd + P @ xdd) / r - P @ xd * rd / r**2
        return e, ed, edd

    rows, adot = [], []
    k = int(np.argmax(sc["contact_link"]))
    e, ed, edd = heading(k)
    J, a_o, _, v_o, _, R, o = links[k]
    side = sc["side"]
    perp = lambda x: np.array([-x[1], x[0]])
    n, nd, ndd = side * perp(e), side * perp(ed), side * perp(edd)
    psi, wo = q_obj[2], v_obj[2]
    Rz = np.array([[np.cos(psi), -np.sin(psi)], [np.sin(psi), np.cos(psi)]])
    P = q_obj[:2] + Rz @ rho
    Pd = v_obj[:2] + wo * perp(Rz @ rho)
    Pdd = -wo**2 * (Rz @ rho)
    d, dd, ddd = P - o[:2], Pd - v_o[:2], Pdd - a_o[:2]
    gap, s = n @ d, e @ d
    # gdot = nd . d + n . dd, linear in (v, v_obj): its row from J, and gddot at vdot = 0
    Jo = J[:3, :]
    Jw = J[3:, :]
    hv = R[:, 0]
    r = np.linalg.norm(hv[:2])
    # d(edot)/dv: edot = (I - e e^T) (w x h)_xy / r, w = Jw v
    dh = -_skew(hv) @ Jw  # (w x h) = -h x w
    de = (np.eye(2) - np.outer(e, e)) @ dh[:2] / r
    dn = side * np.vstack([-de[1], de[0]])
    a_snake = d @ dn - n @ Jo[:2]
    g_obj = np.r_[n, n @ perp(Rz @ rho)]
    rows.append(np.r_[a_snake, g_obj])
    adot.append(ndd @ d + 2 * nd @ dd + n @ ddd)
    mass = robot.mass
    for i in range(nl):  # wheels
        ei, edi, _ = heading(i)
        local = np.array(robot.com[i]) + sc["wheel_offset"][i] * np.array([1.0, 0, 0])
        _, Jp, vp, ap = point(i, local)
        lat, latd = perp(ei), perp(edi)
        rows.append(np.r_[lat @ Jp[:2], 0, 0, 0])
        adot.append(lat @ ap[:2] + latd @ vp[:2])
    for i in range(nl):  # ground
        _, Jp, vp, ap = point(i, np.array(robot.com[i]))
        rows.append(np.r_[Jp[2], 0, 0, 0])
        adot.append(ap[2])
    for i in range(nl):  # pitch: half the difference of the Gauss points' vertical velocities
        L = np.linalg.norm(robot.joint_xyz[min(i, nl - 2)])
        d = L / (2 * np.sqrt(3)) * np.array([1.0, 0, 0])
        ends = [point(i, np.array(robot.com[i]) + sgn * d) for sgn in (1, -1)]
        rows.append(np.r_[(ends[0][1][2] - ends[1][1][2]) / 2, 0, 0, 0])
        adot.append((ends[0][3][2] - ends[1][3][2]) / 2)
    A = np.array(rows)
    A_s, A_o = A[:, :nv], A[:, nv:]
    I_obj = np.array([sc["object_mass"], sc["object_mass"], sc["object_inertia"]])
    S = np.vstack([np.zeros((6, robot.joints)), np.eye(robot.joints)])
    qdd_free = np.linalg.solve(M, S @ tau - h)
    Minv_AsT = np.linalg.solve(M, A_s.T)
    G = A_s @ Minv_AsT + A_o @ np.diag(1 / I_obj) @ A_o.T
    b = A_s @ qdd_free + A_o @ (f_obj / I_obj) + np.array(adot)
    return {"M": M, "delassus": G, "b": b, "qdd_free": qdd_free, "qdd_from_lam": Minv_AsT,
            "gap": gap, "s": s}, mass


@pytest.mark.parametrize("joints", (1, 3, 5))
def test_contact_system_against_pinocchio(rng, joints):
    """Random axes, placements, masses and inertias, a random state with velocities and a
    given object: M, G_c, b, the free accelerations, M^-1 A^T, the gap and s to 1e-12 (five
    joints: the linear algebra as matrices, not unrolled)."""
    robot = random_robot(rng, joints + 1)
    model = snakecg.load(robot)
    for _ in range(3):
        q = robot.neutral()
        q[:3] = rng.normal(size=3)
        quat = rng.normal(size=4)
        q[3:7] = quat / np.linalg.norm(quat)
        q[7:] = rng.uniform(-1.5, 1.5, joints)
        v = rng.normal(size=robot.nv)
        tau = rng.normal(size=joints)
        q_obj, v_obj, f_obj = rng.normal(size=3), rng.normal(size=3), rng.normal(size=3)
        rho = rng.normal(size=2) * 0.2
        sc = _scene_inputs(model, rng, int(rng.integers(robot.n_links)))
        out = _call(model, "contact_system", q=q, v=v, tau=tau, q_obj=q_obj, v_obj=v_obj,
                    f_obj=f_obj, rho=rho, placed=0.0, **sc)
        ref, _ = _reference(robot, q, v, tau, q_obj, v_obj, f_obj, rho, sc)
        for key, value in ref.items():
            assert rel(np.ravel(out[key]), np.ravel(value)) <= 1e-12, key
        rest = _call(model, "contact_system_at_rest", q=q, tau=tau, q_obj=q_obj, f_obj=f_obj,
                     rho=rho, placed=0.0, **sc)
        ref0, _ = _reference(robot, q, 0 * v, tau, q_obj, 0 * v_obj, f_obj, rho, sc)
        for key, value in ref0.items():
            assert rel(np.ravel(rest[key]), np.ravel(value)) <= 1e-12, key


def _flat(planar: snakecg.Robot) -> snakecg.SpatialRobot:
    """The planar snake as a chain of yaw joints lying flat: every link frame at the link's
    rear end, x along the link, z up, the COMs on the ground."""
    l, c = np.array(planar.length), np.array(planar.com)
    return snakecg.SpatialRobot(joints=planar.joints, mass=planar.mass,
                                com=[(ci, 0, 0) for ci in c],
                                inertia=[(0.3 * I, 0.7 * I, I, 0, 0, 0) for I in planar.inertia],
                                joint_xyz=[(l[j], 0, 0) for j in range(planar.joints)],
                                joint_axis=(0, 0, 1))


def _embed(planar, qs, vs):
    """Spatial q, v and E (v = E v_s at rest) of a planar state (the base frame at link 1's
    rear end)."""
    c1 = planar.com[0]
    x, y, th = qs[:3]
    ct, st = np.cos(th), np.sin(th)
    q = np.r_[x - c1 * ct, y - c1 * st, 0, 0, 0, np.sin(th / 2), np.cos(th / 2), qs[3:]]
    nv, ns = planar.joints + 6, planar.n_coordinates
    E = np.zeros((nv, ns))
    R2 = np.array([[ct, -st], [st, ct]])
    E[:2, :3] = R2.T @ np.array([[1, 0, c1 * st], [0, 1, -c1 * ct]])
    E[5, 2] = 1
    E[6:, 3:] = np.eye(planar.joints)
    return q, E @ vs, E


@pytest.mark.parametrize("velocities", (False, True))
def test_flat_yaw_chain_is_the_planar_problem(rng, velocities):
    """Case study 2's robot with its joints turned to yaw, lying flat: the contact and wheel
    rows' G_c and b, the maps of their forces, M, the gap and s are the planar model's
    (to 1e-12); the ground and pitch rows are uncoupled from them and their accelerations at
    zero force are free fall (-g, no pitch)."""
    planar = snakecg.Robot(joints=3)
    scene = snakecg.Scene(robot=planar, scenario="ideal_wheels")
    pm = snakecg.load(scene)
    sm = snakecg.load(_flat(planar))
    nc = planar.n_links + 1
    si = {k: np.asarray(v, dtype=float) for k, v in pm.scene_inputs.items()}
    for _ in range(3):
        qs = np.r_[rng.normal(size=3), np.deg2rad(rng.uniform(-100, 100, 3))]
        vs = rng.normal(size=6) if velocities else np.zeros(6)
        tau, f_obj = rng.normal(size=3), rng.normal(size=3)
        q, v, E = _embed(planar, qs, vs)
        common = {"tau": tau, "q_obj": np.zeros(3), "f_obj": f_obj, "rho": np.zeros(2),
                  "placed": 1.0}
        if velocities:
            vo = rng.normal(size=3)
            po = _call(pm, "contact_system", q=qs, v=vs, v_obj=vo, **common, **si)
            so = _call(sm, "contact_system", q=q, v=v, v_obj=vo, **common,
                       **{**si, "K": sm.parameters})
        else:
            po = _call(pm, "contact_system_at_rest", q=qs, **common, **si)
            so = _call(sm, "contact_system_at_rest", q=q, **common,
                       **{**si, "K": sm.parameters})
        G, b = so["delassus"], so["b"].ravel()
        assert rel(G[:nc, :nc], po["delassus"]) <= 1e-12
        assert rel(b[:nc], po["b"].ravel()) <= 1e-12
        assert np.abs(G[:nc, nc:]).max() <= 1e-14 * np.abs(G).max()
        nl = planar.n_links
        assert np.abs(b[nc:nc + nl] + 9.81).max() <= 1e-12 * 9.81  # the ground rows fall
        assert np.abs(b[nc + nl:]).max() <= 1e-12 * 9.81  # the links fall without pitching
        assert rel(E.T @ so["M"] @ E, po["M"]) <= 1e-12
        assert rel(so["qdd_from_lam"][:, :nc], E @ po["qdd_from_lam"]) <= 1e-12
        assert rel(so["a_obj_from_lam"][:, :nc], po["a_obj_from_lam"]) <= 1e-12
        assert abs(so["gap"] - po["gap"]) <= 1e-12 and abs(so["s"] - po["s"]) <= 1e-12


def test_contact_system_at_rest_against_mujoco(rng):
    """At rest, G_c and b from MuJoCo's mass matrix (mj_fullM), its point Jacobians (mj_jac)
    and its gravity forces (qfrc_bias), in MuJoCo's own velocity coordinates (G_c and b do
    not depend on them), with the rows written out here: to 1e-12."""
    from test_spatial_references import mujoco_chain

    robot = random_robot(rng, 4)
    mujoco, mm = mujoco_chain(robot)
    md = mujoco.MjData(mm)
    model = snakecg.load(robot)
    nl, nv = robot.n_links, robot.nv
    perp = lambda x: np.array([-x[1], x[0]])  # noqa: E731
    for _ in range(3):
        q = robot.neutral()
        quat = rng.normal(size=4)
        q[3:7] = quat / np.linalg.norm(quat)
        q[:3] = rng.normal(size=3)
        q[7:] = rng.uniform(-1.5, 1.5, robot.joints)
        tau = rng.normal(size=robot.joints)
        q_obj, f_obj, rho = rng.normal(size=3), rng.normal(size=3), rng.normal(size=2) * 0.2
        sc = _scene_inputs(model, rng, int(rng.integers(nl)))
        out = _call(model, "contact_system_at_rest", q=q, tau=tau, q_obj=q_obj, f_obj=f_obj,
                    rho=rho, placed=0.0, **sc)
        md.qpos[:] = np.r_[q[:3], q[6], q[3:6], q[7:]]
        md.qvel[:] = 0.0
        mujoco.mj_forward(mm, md)
        M = np.zeros((nv, nv))
        try:
            mujoco.mj_fullM(mm, md, M)  # MuJoCo 4: (model, data, dst)
        except TypeError:
            mujoco.mj_fullM(mm, M, md.qM)  # MuJoCo 3: (model, dst, qM)

        def jac(i, local):
            R, o = md.xmat[i + 1].reshape(3, 3), md.xpos[i + 1]
            jp, jr = np.zeros((3, nv)), np.zeros((3, nv))
            mujoco.mj_jac(mm, md, jp, jr, o + R @ local, i + 1)
            return jp, jr, R, o

        rows = []
        k = int(np.argmax(sc["contact_link"]))
        jo, jr, R, o = jac(k, np.zeros(3))
        h = R[:, 0]
        r = np.linalg.norm(h[:2])
        e = h[:2] / r
        n = sc["side"] * perp(e)
        psi = q_obj[2]
        Rz = np.array([[np.cos(psi), -np.sin(psi)], [np.sin(psi), np.cos(psi)]])
        d = q_obj[:2] + Rz @ rho - o[:2]
        de = (np.eye(2) - np.outer(e, e)) @ (-_skew(h) @ jr)[:2] / r  # edot = de v
        dn = sc["side"] * np.vstack([-de[1], de[0]])
        rows.append(np.r_[d @ dn - n @ jo[:2], n, n @ perp(Rz @ rho)])
        for i in range(nl):
            c = np.array(robot.com[i])
            jp, _, Ri, _ = jac(i, c + np.array([sc["wheel_offset"][i], 0, 0]))
            ei = Ri[:2, 0] / np.linalg.norm(Ri[:2, 0])
            rows.append(np.r_[perp(ei) @ jp[:2], 0, 0, 0])
        for i in range(nl):
            jp, _, _, _ = jac(i, np.array(robot.com[i]))
            rows.append(np.r_[jp[2], 0, 0, 0])
        for i in range(nl):  # pitch: the Gauss points' vertical velocities, half difference
            L = np.linalg.norm(robot.joint_xyz[min(i, nl - 2)])
            off = np.array([L / (2 * np.sqrt(3)), 0, 0])
            jf, _, _, _ = jac(i, np.array(robot.com[i]) + off)
            jb, _, _, _ = jac(i, np.array(robot.com[i]) - off)
            rows.append(np.r_[(jf[2] - jb[2]) / 2, 0, 0, 0])
        A = np.array(rows)
        A_s, A_o = A[:, :nv], A[:, nv:]
        I_obj = np.array([sc["object_mass"], sc["object_mass"], sc["object_inertia"]])
        S = np.vstack([np.zeros((6, robot.joints)), np.eye(robot.joints)])
        G = A_s @ np.linalg.solve(M, A_s.T) + A_o @ np.diag(1 / I_obj) @ A_o.T
        b = A_s @ np.linalg.solve(M, S @ tau - md.qfrc_bias) + A_o @ (f_obj / I_obj)
        assert rel(out["delassus"], G) <= 1e-12
        assert rel(out["b"].ravel(), b) <= 1e-12
