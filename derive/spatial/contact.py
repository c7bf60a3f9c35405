"""The paper's contact problem for a spatial snake lying on the ground, as CasADi functions
with the planar model's layout (:mod:`snakecg_derive.coupled`).

``contact_system`` and ``contact_system_at_rest`` take and give exactly what the planar ones
do (the same input and output names; ``q`` and ``v`` are the spatial configuration and
velocity), so that the runtime core's complementarity solve (snakecg/core/forward.c) runs
on them unchanged. Built at generation time from the spatial chain's own functions
(``link_poses``, ``link_jacobians``, ``mass_matrix``, ``bias_forces``, ``kinematic_map``);
nothing here is rendered into text and run.

The ground is the plane ``z = 0`` (world ``z`` up); the object lies on it and moves in it
(pose ``q_obj = (x, y, psi)``, twist ``(vx, vy, omega_z)``, inertia ``diag(m, m, I_zz)``).
Each link's *heading* is its frame's ``x`` axis projected on the ground, ``e``, and its edge
runs along ``e`` from the frame origin. Rows, in order (``n_c = 3 n_l + 1``):

* row 0, the **contact**: the gap ``g = n . (P - o_k)`` of the object's point ``P`` (``rho``
  in the object frame) from the edge of link ``k`` (one-hot ``contact_link``), ``n = side
  (-e_y, e_x)``; the row is ``gdot`` on ``(v, v_obj)``, ``s = e . (P - o_k)`` the contact
  coordinate along the edge;
* rows ``1..n_l``, the **wheels**: the velocity of the link's point ``c_i + wheel_offset_i
  x_i`` (``c_i`` its COM, ``x_i`` its frame's x axis) along the lateral direction ``(-e_y, e_x, 0)``;
* rows ``n_l + 1..2 n_l``, the **ground**: the vertical velocity of each link's COM
  (bilateral: the snake stays on the ground); the row's force is the link's normal force;
* rows ``2 n_l + 1..3 n_l``, the link's **pitch** on the ground: ``d_i (w_i x x_i)_z``, the
  rate of the height of the link's axis ``x_i`` scaled by ``d_i = L_i / (2 sqrt 3)`` (``L_i``
  the link's length: the distance to its next joint, the last link's that of the one before).

The ground and pitch rows of a link are its lying capsule's line contact: the bottom line of
the link along its axis through the COM, held on the ground (its height and its slope), free
to roll about its own axis, as a cylinder on a flat floor is. With both rows at the same
scale they are the half sum and half difference of the vertical velocities at the two Gauss
points ``c_i +- d_i x_i``: the least-norm forces of the rows (the solve's choice where rows
depend on each other) are then those of a uniformly stiff ground along equally long links
(two-point Gauss quadrature is exact for the line's linear load), and the ground row's force
is the sum of the two, the link's normal force.

Every row is ``A(q, q_obj) (v, v_obj)``; its ``Adot v`` is the derivative of ``A`` along the
motion, ``d/dq (A V) G(q) v + d/dq_obj (A V) v_obj`` with ``qdot = G(q) v`` (the kinematic
map), taken by CasADi's algorithmic differentiation of the same expressions (one forward-mode
directional derivative). A chain of yaw
joints lying flat is the planar snake: these rows are then the planar rows (eqs. 8-13 of
Reyes & Ma 2017) and the ground rows carry the weight.
"""

from __future__ import annotations

import casadi as ca

from ..algebra import Algebra
from .symbols import SpatialSymbols

__all__ = ["CONTACT_FUNCTIONS", "contact_functions"]

#: Up to this many links the linear algebra is unrolled into scalars (faster for small
#: chains); beyond, it keeps its matrices.
SX_MAX_LINKS = 4
#: The composed functions, in manifest order after the chain's own.
CONTACT_FUNCTIONS = ("contact_system", "contact_system_at_rest")


def _link_com(K, s: SpatialSymbols, i: int):
    """COM of link ``i`` (from 0) in its frame: ``K``'s ``link_com`` block."""
    nl = s.n_links
    return K[nl + 3 * i: nl + 3 * i + 3]


def _support_offset(K, s: SpatialSymbols, i: int):
    """``d_i = L_i / (2 sqrt 3)``: the Gauss points' distance from the COM along the link
    (``L_i = |joint_xyz|`` of the link's next joint; the last link: of the joint before)."""
    nl = s.n_links
    j = min(i, nl - 2)
    t = K[10 * nl + 3 * j: 10 * nl + 3 * j + 3]
    return ca.sqrt(ca.dot(t, t)) / (2 * 3 ** 0.5)


def _heading(R):
    """The link's heading on the ground, ``e = (R_x0, R_y0) / |.|``."""
    hx, hy = R[0, 0], R[1, 0]
    r = ca.sqrt(hx * hx + hy * hy)
    return hx / r, hy / r


def _rows(fn, s: SpatialSymbols, q, K, q_obj, rho, sc):
    """``A`` (``n_c x (n_v + 3)``), the gap and ``s`` at ``(q, q_obj)``, with ``rho`` the
    object's contact point in its frame."""
    nl, nv = s.n_links, s.nv
    pos, rot = fn["link_poses"](q, K)
    J = fn["link_jacobians"](q, K)
    V = ca.SX.sym("V", nv)  # only to read the rows off their velocities
    Vo = ca.SX.sym("Vo", 3)

    def point(i, local):
        R = rot[:, 3 * i: 3 * i + 3]
        d = ca.mtimes(R, local)
        Ji = J[6 * i: 6 * i + 6, :]
        w = ca.mtimes(Ji[3:, :], V)
        return pos[:, i] + d, ca.mtimes(Ji[:3, :], V) + ca.cross(w, d), R, w

    # the contact: the edge of the selected link
    ok = ca.mtimes(pos, sc["contact_link"])
    Rk = sum(sc["contact_link"][i] * rot[:, 3 * i: 3 * i + 3] for i in range(nl))
    wk = sum(sc["contact_link"][i] * ca.mtimes(J[6 * i + 3: 6 * i + 6, :], V) for i in range(nl))
    vk = sum(sc["contact_link"][i] * ca.mtimes(J[6 * i: 6 * i + 3, :], V) for i in range(nl))
    ex, ey = _heading(Rk)
    side = sc["side"]
    cp, sp_ = ca.cos(q_obj[2]), ca.sin(q_obj[2])
    P = ca.vertcat(q_obj[0] + cp * rho[0] - sp_ * rho[1], q_obj[1] + sp_ * rho[0] + cp * rho[1])
    Pdot = ca.vertcat(Vo[0] - Vo[2] * (sp_ * rho[0] + cp * rho[1]),
                      Vo[1] + Vo[2] * (cp * rho[0] - sp_ * rho[1]))
    # e turns with the link: edot = (I - e e^T) hdot_xy / |h_xy|, hdot = w x h
    hx, hy = Rk[0, 0], Rk[1, 0]
    r = ca.sqrt(hx * hx + hy * hy)
    hd = ca.cross(wk, Rk[:, 0])
    t = (hd[0] * ex + hd[1] * ey)
    edx, edy = (hd[0] - ex * t) / r, (hd[1] - ey * t) / r
    dx, dy = P[0] - ok[0], P[1] - ok[1]
    gap = side * (-ey * dx + ex * dy)
    s_along = ex * dx + ey * dy
    gdot = side * (-edy * dx + edx * dy) + side * (-ey * (Pdot[0] - vk[0]) + ex * (Pdot[1] - vk[1]))
    rows = [gdot]
    for i in range(nl):  # the wheels
        c = _link_com(K, s, i)
        R = rot[:, 3 * i: 3 * i + 3]
        hx, hy = _heading(R)
        local = c + ca.vertcat(sc["wheel_offset"][i], 0, 0)
        _, vel, _, _ = point(i, local)
        rows.append(-hy * vel[0] + hx * vel[1])
    for i in range(nl):  # the ground
        _, vel, _, _ = point(i, _link_com(K, s, i))
        rows.append(vel[2])
    for i in range(nl):  # the pitch of each link's axis on the ground
        _, _, R, w = point(i, _link_com(K, s, i))
        rows.append(_support_offset(K, s, i) * ca.cross(w, R[:, 0])[2])
    Vall = ca.vertcat(V, Vo)
    A = ca.jacobian(ca.vertcat(*rows), Vall)  # the rows are linear in the velocities
    return A, gap, s_along


def _system(fn, s: SpatialSymbols, *, at_rest: bool, prefix: str) -> ca.Function:
    nl, nq, nv, na = s.n_links, s.nq, s.nv, s.n_joints
    K = ca.SX.sym("K", len(s.parameters))
    q = ca.SX.sym("q", nq)
    v = ca.SX(nv, 1) if at_rest else ca.SX.sym("v", nv)
    tau = ca.SX.sym("tau", na)
    q_obj = ca.SX.sym("q_obj", 3)
    v_obj = ca.SX(3, 1) if at_rest else ca.SX.sym("v_obj", 3)
    f_obj = ca.SX.sym("f_obj", 3)
    sc = {"contact_link": ca.SX.sym("contact_link", nl), "side": ca.SX.sym("side", 1),
          "object_mass": ca.SX.sym("object_mass", 1),
          "object_inertia": ca.SX.sym("object_inertia", 1), "rho": ca.SX.sym("rho", 2),
          "wheel_offset": ca.SX.sym("wheel_offset", nl)}
    contact_offset = ca.SX.sym("contact_offset", 1)
    object_distance = ca.SX.sym("object_distance", 1)
    placed = ca.SX.sym("placed", 1)
    # the object placed at the contact from q (placed = 1): on the edge of link k at
    # contact_offset, its COM at object_distance along the normal, aligned with the link
    pos, rot = fn["link_poses"](q, K)
    ok = ca.mtimes(pos, sc["contact_link"])
    Rk = sum(sc["contact_link"][i] * rot[:, 3 * i: 3 * i + 3] for i in range(nl))
    ex, ey = _heading(Rk)
    side = sc["side"]
    nx, ny = -side * ey, side * ex
    Px, Py = ok[0] + contact_offset * ex, ok[1] + contact_offset * ey
    p_obj = ca.vertcat(Px + object_distance * nx, Py + object_distance * ny, ca.atan2(ey, ex))
    p_rho = ca.vertcat(0, -side * object_distance)
    given = 1 - placed
    # the rows as functions of the object's pose (placed: its value is put in afterwards)
    qo, rh = ca.SX.sym("qo", 3), ca.SX.sym("rh", 2)
    A, gap, s_along = _rows(fn, s, q, K, qo, rh, sc)
    Vall = ca.vertcat(v, v_obj)
    if at_rest:
        Adot_v = ca.SX(A.shape[0], 1)
    else:
        # one directional derivative (forward mode) along (qdot, q_obj dot) = (G(q) v, v_obj)
        AV = ca.mtimes(A, Vall)
        G = fn["kinematic_map"](q)
        Adot_v = ca.jtimes(AV, ca.vertcat(q, qo), ca.vertcat(ca.mtimes(G, v), v_obj))
    obj = given * q_obj + placed * p_obj
    rho = given * sc["rho"] + placed * p_rho
    A, gap, s_along, Adot_v = (ca.substitute(x, ca.vertcat(qo, rh), ca.vertcat(obj, rho))
                               for x in (A, gap, s_along, Adot_v))
    M = fn["mass_matrix"](q, K)
    h = fn["bias_forces"](q, v, K)  # at rest: gravity alone
    inputs = {"q": q, "v": v, "tau": tau, "q_obj": q_obj, "v_obj": v_obj, "f_obj": f_obj,
              "K": K, **sc, "contact_offset": contact_offset,
              "object_distance": object_distance, "placed": placed}
    if at_rest:
        del inputs["v"], inputs["v_obj"]
    # the scalar part (rows, M, h) as one SX function; the linear algebra in the algebra of
    # the chain's size: unrolled scalars for a few links, matrices (CasADi's ldl solve, a loop
    # in the C) beyond, so that the code grows like n^2 and not like n^3
    terms = ca.Function("terms", list(inputs.values()), [M, h, A, Adot_v, gap, s_along])
    alg = Algebra("sx" if nl <= SX_MAX_LINKS else "mx", prefix)
    args = {k: alg.sym(k, x.shape[0], x.shape[1]) for k, x in inputs.items()}
    M, h, A, Adot_v, gap, s_along = terms(*args.values())
    A_s, A_o = A[:, :nv], A[:, nv:]
    B = ca.vertcat(alg.zeros(6, na), alg.eye(na))
    M_factors, _ = alg.ldl(M)
    X = alg.solve(M_factors, ca.horzcat(ca.mtimes(B, args["tau"]) - h, A_s.T))
    qdd_free, Minv_AsT = X[:, 0], X[:, 1:]
    I_obj = ca.vertcat(args["object_mass"], args["object_mass"], args["object_inertia"])
    Iinv_AoT = ca.mtimes(ca.diag(1 / I_obj), A_o.T)
    Gc = ca.mtimes(A_s, Minv_AsT) + ca.mtimes(A_o, Iinv_AoT)       # eq. (14)
    a_free = args["f_obj"] / I_obj
    b = ca.mtimes(A_s, qdd_free) + ca.mtimes(A_o, a_free) + Adot_v  # eq. (13), lam = 0
    outputs = {"M": M, "delassus": Gc, "b": b, "qdd_free": qdd_free, "a_obj_free": a_free,
               "qdd_from_lam": Minv_AsT, "a_obj_from_lam": Iinv_AoT, "gap": gap, "s": s_along}
    outs = [ca.densify(o) for o in outputs.values()]
    if alg.kind == "sx":
        outs = ca.cse(outs)
    name = "contact_system_at_rest" if at_rest else "contact_system"
    return ca.Function(prefix + name, list(args.values()), outs, list(args), list(outputs))


def contact_functions(built: dict, s: SpatialSymbols, prefix: str) -> list[ca.Function]:
    """:data:`CONTACT_FUNCTIONS` from the chain's built functions (``built``: name -> SX
    function without the prefix)."""
    return [_system(built, s, at_rest=False, prefix=prefix),
            _system(built, s, at_rest=True, prefix=prefix)]


#: What each composed function computes (its doc in the manifest and the record).
CONTACT_DOCS = {
    "contact_system": "The contact problem of one state before any active set (the planar "
                      "model's layout): M, the Delassus matrix G_c = A I^-1 A^T (eq. 14), "
                      "b = A I^-1 (f - p) + Adot v (eq. 13), the accelerations without "
                      "constraint forces and the maps of the forces into them (eq. 18), the "
                      "gap and s. Rows: contact, a lateral wheel row per link, a ground row "
                      "per link (its normal force), a pitch row per link (its axis's slope on "
                      "the ground).",
    "contact_system_at_rest": "contact_system at rest (v = 0, v_obj = 0).",
}
