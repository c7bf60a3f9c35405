"""The coupled snake + object system of Reyes & Ma 2017, eqs. (8)-(31), as CasADi functions.

Built at generation time from the per-link functions of :mod:`.model` (link poses, Jacobians,
bias accelerations, ``M_s``, ``h_s``, the link-level contact and wheel rows); nothing here is
rendered into text and run. Notation follows the paper: ``A = [A_s, A_o] = [-J_s, G^T]``
(eq. 9), ``I = diag(M_s, I_obj)`` (eq. 12), ``G_c = A I^-1 A^T`` (eq. 14), the maps
``Phi_qdd_tau`` (eq. 22), ``Phi_qdd_f`` (23), ``Phi_a_tau`` (24), ``Phi_a_f`` (25), the forms
``Xi_tau`` (28) and ``Omega_tau`` (29) and the input metric ``B^T M_s^-1 B`` of eq. (31).

Constraint rows: row 0 is the contact, row ``1 + i`` the lateral wheel row of link ``i + 1``.
Which rows hold is an input (``free``: 1 = the row holds with equality and its force is solved
for; 0 = its force is fixed to ``lam_fixed``: 0 for a lost contact or a link without a wheel,
``+-mu m g`` for a sliding wheel), so one compiled function serves every scene and every active
set; the runtime picks the active set (``snakecg/solver.py``).

Two ways to carry the linear algebra (:class:`.algebra.Algebra`): ``"sx"`` unrolls every
factorization into scalar operations (fastest for a few joints); ``"mx"`` keeps the matrices,
so the generated code grows like ``n^2``. :func:`coupled_functions` builds every function in
one of them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca

from .algebra import Algebra
from .catalog import COUPLED_FUNCTIONS, EXTREMES_MAX_JOINTS

__all__ = ["Algebra", "coupled_functions", "COUPLED_FUNCTIONS", "EXTREMES_MAX_JOINTS"]


# ------------------------------------------------------------------------------------------
# the coupled system
# ------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class _Sizes:
    n_joints: int

    @property
    def n_links(self):
        return self.n_joints + 1

    @property
    def n_coordinates(self):
        return self.n_joints + 3

    @property
    def n_constraints(self):
        return self.n_links + 1


def _scene_inputs(alg: Algebra, sz: _Sizes) -> dict:
    nl = sz.n_links
    return {
        "contact_link": alg.sym("contact_link", nl),
        "side": alg.sym("side", 1),
        "object_mass": alg.sym("object_mass", 1),
        "object_inertia": alg.sym("object_inertia", 1),
        "q_obj": alg.sym("q_obj", 3),
        "rho": alg.sym("rho", 2),
        "wheel_offset": alg.sym("wheel_offset", nl),
        "free": alg.sym("free", sz.n_constraints),
        "lam_fixed": alg.sym("lam_fixed", sz.n_constraints),
        "regularization": alg.sym("regularization", 1),
    }


def _actuation(alg: Algebra, sz: _Sizes):
    # B = [0_{3 x n_a}; 1_{n_a}] of eq. (5): the joints are actuated, the base is not
    return ca.vertcat(alg.zeros(3, sz.n_joints), alg.eye(sz.n_joints))


def _link_rotations(q, nl):
    """``(cos phi_i, sin phi_i)`` of every link's absolute angle (``phi_1 = theta = q[2]``,
    ``phi_{i+1} = phi_i + q_i``) as products of the joints' rotations: one sine and cosine per
    coordinate, which the link functions compute too (shared after CSE), and none of a sum."""
    c, s = [ca.cos(q[2])], [ca.sin(q[2])]
    for i in range(1, nl):
        cj, sj = ca.cos(q[2 + i]), ca.sin(q[2 + i])
        c_prev, s_prev = c[-1], s[-1]
        c.append(c_prev * cj - s_prev * sj)
        s.append(s_prev * cj + c_prev * sj)
    return c, s


def _contact_rotation(c, s, contact_link):
    """The contact link's rotation ``(cos phi_k, sin phi_k)`` (one-hot ``contact_link``)."""
    return (ca.dot(contact_link, ca.vertcat(*c)), ca.dot(contact_link, ca.vertcat(*s)))


def _constraint_rows(fn, alg, sz, q, v, K, sc, v_obj, obj=None, poses=None, rotations=None,
                     at_rest=False):
    """Constraint matrix ``A = [-J_s, G^T]`` (eq. 9), ``Adot v`` (eq. 13), gap and ``s``.

    ``obj``: the object's ``(q_obj, rho, cos psi, sin psi)``; by default ``sc["q_obj"]``,
    ``sc["rho"]`` and the cosine and sine of ``q_obj[2]``. ``poses`` (``link_poses`` at
    ``q``) and ``rotations`` (:func:`_link_rotations`) when the caller has them already.
    ``at_rest``: ``v`` and ``v_obj`` are zero (the links' bias accelerations are not
    evaluated; ``Adot v`` is zero)."""
    nl, ns = sz.n_links, sz.n_coordinates
    contact_link = sc["contact_link"]
    if poses is None:
        poses = fn["link_poses"](q, K)
    c, s_ = rotations if rotations is not None else _link_rotations(q, nl)
    if obj is None:
        psi = sc["q_obj"][2]
        obj = (sc["q_obj"], sc["rho"], ca.cos(psi), ca.sin(psi))
    q_obj, rho, cos_psi, sin_psi = obj
    J = fn["link_jacobians"](q, K)
    bias = alg.zeros(3, nl) if at_rest else fn["link_bias_accelerations"](q, v, K)
    # eq. (10): the contact row uses the Jacobian J_* of the touching link (one-hot selection)
    J_k = alg.zeros(3, ns)
    for i in range(nl):
        J_k = J_k + contact_link[i] * J[3 * i: 3 * i + 3, :]
    pose_k = ca.mtimes(poses, contact_link)
    bias_k = ca.mtimes(bias, contact_link)
    com_k = ca.dot(K[3 * nl: 4 * nl], contact_link)
    c_k, s_k = _contact_rotation(c, s_, contact_link)
    a_link, g_obj, adv_c, gap, s = fn["contact_row_local_rotation"](
        pose_k, ca.mtimes(J_k, v), bias_k, com_k, q_obj, v_obj, rho, sc["side"],
        ca.vertcat(c_k, cos_psi), ca.vertcat(s_k, sin_psi))
    rows = [ca.horzcat(ca.mtimes(a_link, J_k), g_obj)]
    Adot_v = [adv_c]
    # one lateral wheel row per link (non-holonomic, eq. 13 with equality where it holds)
    for i in range(nl):
        J_i = J[3 * i: 3 * i + 3, :]
        a_w, adv_w = fn["wheel_row_local_rotation"](poses[:, i], ca.mtimes(J_i, v), bias[:, i],
                                                    sc["wheel_offset"][i], c[i], s_[i])
        rows.append(ca.horzcat(ca.mtimes(a_w, J_i), alg.zeros(1, 3)))
        Adot_v.append(adv_w)
    return ca.vertcat(*rows), ca.vertcat(*Adot_v), gap, s


def _masked_delassus(alg, Gc, free, regularization):
    """``G' = D G_c D + (1 - D) + r D`` with ``D = diag(free)``: factors and pivot ratio.

    The held rows keep eq. (14); a released row becomes an identity row (its force is fixed).
    ``r`` (``regularization``) is 0 normally; the runtime re-solves a flagged singular case
    with a tiny ``r``, which tends to the least-norm solution as ``r -> 0``.
    """
    D = ca.diag(free)
    Gp = ca.mtimes([D, Gc, D]) + ca.diag(1 - free) + regularization * D
    factors, d = alg.ldl(Gp, pivots=True)
    # pivot / diagonal: 1 for an independent row, -> 0 as a row becomes dependent on earlier ones
    pivot_ratio = ca.mmin(d / ca.diag(Gp))
    return factors, pivot_ratio


def _function(alg, name, inputs: dict, outputs: dict):
    outs = [ca.densify(o) for o in outputs.values()]
    if alg.kind == "sx":
        outs = ca.cse(outs)
    return ca.Function(alg.prefix + name, list(inputs.values()), outs, list(inputs),
                       list(outputs))


def constrained_dynamics(fn, alg: Algebra, sz: _Sizes) -> ca.Function:
    """Accelerations and constraint forces of snake + object for a given active set.

    Eq. (12) with the rows in ``free`` held (eq. 13 with equality), the other rows' forces
    fixed to ``lam_fixed``. ``lam`` solves ``G' lam_F = -(b_F + G_c lam_fixed)`` on the held
    rows (eq. 16), where ``G_c = A I^-1 A^T`` (eq. 14) and ``b = A I^-1 (f - p) + Adot v``;
    ``w = G_c lam + b`` are the rows' accelerations. Norms: eq. (26), (27), ``lam^T G_c lam``
    and the slippage ratio sr of eq. (30).
    """
    ns = sz.n_coordinates
    q, v = alg.sym("q", ns), alg.sym("v", ns)
    tau = alg.sym("tau", sz.n_joints)
    v_obj, f_obj = alg.sym("v_obj", 3), alg.sym("f_obj", 3)
    K = fn["K"]
    sc = _scene_inputs(alg, sz)
    A, Adot_v, gap, s = _constraint_rows(fn, alg, sz, q, v, K, sc, v_obj)
    M_s = fn["mass_matrix"](q, K)
    h_s = fn["bias_forces"](q, v, K)
    A_s, A_o = A[:, :ns], A[:, ns:]
    # eq. (12) without constraint forces, and M_s^-1 A_s^T for eq. (14), with one factorization
    M_factors, _ = alg.ldl(M_s)
    X = alg.solve(M_factors, ca.horzcat(ca.mtimes(_actuation(alg, sz), tau) - h_s, A_s.T))
    qdd_free, Minv_AsT = X[:, 0], X[:, 1:]
    I_obj = ca.vertcat(sc["object_mass"], sc["object_mass"], sc["object_inertia"])
    Iinv_AoT = ca.mtimes(ca.diag(1 / I_obj), A_o.T)
    # eq. (14): G_c = A I^-1 A^T, block-diagonal I = diag(M_s, I_obj)
    Gc = ca.mtimes(A_s, Minv_AsT) + ca.mtimes(A_o, Iinv_AoT)
    a_free = f_obj / I_obj
    # eq. (13) at zero constraint force: b = A I^-1 (f - p) + Adot v
    b = ca.mtimes(A_s, qdd_free) + ca.mtimes(A_o, a_free) + Adot_v
    free = sc["free"]
    lam_released = (1 - free) * sc["lam_fixed"]
    G_factors, pivot_ratio = _masked_delassus(alg, Gc, free, sc["regularization"])
    # eq. (16) on the held rows, with the released rows' forces fixed
    lam = alg.solve(G_factors, -free * (b + ca.mtimes(Gc, lam_released))) + lam_released
    w = ca.mtimes(Gc, lam) + b
    # eq. (18): the constraint forces back into eq. (12)
    qdd = qdd_free + ca.mtimes(Minv_AsT, lam)
    a_obj = a_free + ca.mtimes(Iinv_AoT, lam)
    norm_qdd = ca.mtimes([qdd.T, M_s, qdd])            # eq. (26)
    norm_a_obj = ca.dot(a_obj, I_obj * a_obj)          # eq. (27)
    norm_lambda = ca.mtimes([lam.T, Gc, lam])
    sr = norm_a_obj / ca.fmax(norm_a_obj + norm_qdd, 1e-300)   # eq. (30)
    inputs = {"q": q, "v": v, "tau": tau, "q_obj": sc["q_obj"], "v_obj": v_obj, "f_obj": f_obj,
              "K": K, **{k: sc[k] for k in ("contact_link", "side", "object_mass",
                                            "object_inertia", "rho", "wheel_offset", "free",
                                            "lam_fixed", "regularization")}}
    outputs = {"qdd": qdd, "a_obj": a_obj, "lam": lam, "w": w, "gap": gap, "s": s,
               "norm_lambda": norm_lambda, "norm_a_obj": norm_a_obj, "norm_qdd": norm_qdd,
               "sr": sr, "pivot_ratio": pivot_ratio, "delassus": Gc, "b": b}
    return _function(alg, "constrained_dynamics", inputs, outputs)


def contact_system(fn, alg: Algebra, sz: _Sizes) -> ca.Function:
    """The contact/wheel problem of one sample before any active set is chosen.

    Everything the complementarity solve needs, independent of which rows hold: the Delassus
    matrix ``G_c = A I^-1 A^T`` (eq. 14), the rows' accelerations at zero constraint force
    ``b = A I^-1 (f - p) + Adot v`` (eq. 13), the accelerations without constraint forces
    (eq. 12) and the maps of the constraint forces into them, ``M_s^-1 A_s^T`` and
    ``I_obj^-1 A_o^T`` (eq. 18), the mass matrix ``M_s`` (eq. 4, for the norm of eq. 26 and the
    conditioning), the gap and the contact coordinate ``s``. With these, every active set
    costs one small solve (``G_HH lam_H = -(b_H + G_HF lam_F)``, eq. 16): the runtime core
    (snakecg/core/forward.c) iterates the active set on them and evaluates nothing twice.
    """
    return _contact_system(fn, alg, sz, at_rest=False)


def contact_system_at_rest(fn, alg: Algebra, sz: _Sizes) -> ca.Function:
    """:func:`contact_system` at rest (``v = 0``, ``v_obj = 0``; no inputs ``v``, ``v_obj``):
    ``h_s`` (eq. 4) and ``Adot v`` (eq. 13) vanish, about a fifth of its operations at
    ``n_a = 3``. The paper's analysis is at rest, so the runtime core calls this for every
    sample whose velocities are zero."""
    return _contact_system(fn, alg, sz, at_rest=True)


def _contact_system(fn, alg, sz, *, at_rest: bool) -> ca.Function:
    ns = sz.n_coordinates
    q = alg.sym("q", ns)
    v = alg.zeros(ns, 1) if at_rest else alg.sym("v", ns)
    tau = alg.sym("tau", sz.n_joints)
    v_obj = alg.zeros(3, 1) if at_rest else alg.sym("v_obj", 3)
    f_obj = alg.sym("f_obj", 3)
    K = fn["K"]
    sc = _scene_inputs(alg, sz)
    contact_offset, object_distance = alg.sym("contact_offset", 1), alg.sym("object_distance", 1)
    placed = alg.sym("placed", 1)
    # the object given (placed = 0) or placed at the scene's contact from q (placed = 1, as
    # place_object; its orientation is then the contact link's, a product of rotations)
    poses, rotations = fn["link_poses"](q, K), _link_rotations(q, sz.n_links)
    p_obj, p_rho, _, (c_k, s_k) = _placement(fn, alg, sz, q, K, sc["contact_link"],
                                             contact_offset, object_distance, sc["side"],
                                             poses, rotations)
    given, psi = 1 - placed, sc["q_obj"][2]
    obj = (given * sc["q_obj"] + placed * p_obj, given * sc["rho"] + placed * p_rho,
           given * ca.cos(psi) + placed * c_k, given * ca.sin(psi) + placed * s_k)
    A, Adot_v, gap, s = _constraint_rows(fn, alg, sz, q, v, K, sc, v_obj, obj, poses,
                                         rotations, at_rest=at_rest)
    M_s = fn["mass_matrix"](q, K)
    h_s = alg.zeros(ns, 1) if at_rest else fn["bias_forces"](q, v, K)
    A_s, A_o = A[:, :ns], A[:, ns:]
    # eq. (12) without constraint forces, and M_s^-1 A_s^T, with one factorization
    M_factors, _ = alg.ldl(M_s)
    X = alg.solve(M_factors, ca.horzcat(ca.mtimes(_actuation(alg, sz), tau) - h_s, A_s.T))
    qdd_free, Minv_AsT = X[:, 0], X[:, 1:]
    I_obj = ca.vertcat(sc["object_mass"], sc["object_mass"], sc["object_inertia"])
    Iinv_AoT = ca.mtimes(ca.diag(1 / I_obj), A_o.T)
    Gc = ca.mtimes(A_s, Minv_AsT) + ca.mtimes(A_o, Iinv_AoT)       # eq. (14)
    a_free = f_obj / I_obj
    b = ca.mtimes(A_s, qdd_free) + ca.mtimes(A_o, a_free)           # eq. (13), lam = 0
    if not at_rest:
        b = b + Adot_v
    inputs = {"q": q, "v": v, "tau": tau, "q_obj": sc["q_obj"], "v_obj": v_obj, "f_obj": f_obj,
              "K": K, **{k: sc[k] for k in ("contact_link", "side", "object_mass",
                                            "object_inertia", "rho", "wheel_offset")},
              "contact_offset": contact_offset, "object_distance": object_distance,
              "placed": placed}
    if at_rest:
        del inputs["v"], inputs["v_obj"]
    outputs = {"M": M_s, "delassus": Gc, "b": b, "qdd_free": qdd_free, "a_obj_free": a_free,
               "qdd_from_lam": Minv_AsT, "a_obj_from_lam": Iinv_AoT, "gap": gap, "s": s}
    name = "contact_system_at_rest" if at_rest else "contact_system"
    return _function(alg, name, inputs, outputs)


def _at_rest_system(fn, alg, sz, q, K, sc):
    """What every at-rest function shares (``v = 0``: ``h_s`` and ``Adot v`` vanish):
    ``A = [A_s, A_o]`` (eq. 9), ``M_s``, ``M_s^-1 B`` and ``M_s^-1 A_s^T``, the object's
    inertia diagonal ``I_obj``, ``I_obj^-1 A_o^T`` and ``G_c = A I^-1 A^T`` (eq. 14)."""
    ns, na = sz.n_coordinates, sz.n_joints
    A, _, _, _ = _constraint_rows(fn, alg, sz, q, alg.zeros(ns, 1), K, sc, alg.zeros(3, 1),
                                  at_rest=True)
    M_s = fn["mass_matrix"](q, K)
    A_s, A_o = A[:, :ns], A[:, ns:]
    B = _actuation(alg, sz)
    M_factors, _ = alg.ldl(M_s)
    X = alg.solve(M_factors, ca.horzcat(B, A_s.T))
    I_obj = ca.vertcat(sc["object_mass"], sc["object_mass"], sc["object_inertia"])
    Iinv_AoT = ca.mtimes(ca.diag(1 / I_obj), A_o.T)
    Minv_AsT = X[:, na:]
    Gc = ca.mtimes(A_s, Minv_AsT) + ca.mtimes(A_o, Iinv_AoT)
    return {"A": A, "A_s": A_s, "A_o": A_o, "M_s": M_s, "B": B, "Minv_B": X[:, :na],
            "Minv_AsT": Minv_AsT, "I_obj": I_obj, "Iinv_AoT": Iinv_AoT, "Gc": Gc}


def _at_rest_inputs(sz, q, K, sc, *, lam_fixed=True):
    keys = ["contact_link", "side", "object_mass", "object_inertia", "q_obj", "rho",
            "wheel_offset", "free"] + (["lam_fixed"] if lam_fixed else []) + ["regularization"]
    return {"q": q, "K": K, **{k: sc[k] for k in keys}}


def interaction_maps(fn, alg: Algebra, sz: _Sizes) -> ca.Function:
    """The linear maps of the system at rest for a given active set.

    With ``v = 0`` every quantity is affine in ``(tau, f_obj)``: ``lam = lam_from_tau tau +
    lam_from_f_obj f_obj + lam_offset`` (eq. 17, the offset comes from fixed forces), and
    likewise ``qdd`` (eqs. 20, 22, 23), ``a_obj`` (eqs. 21, 24, 25) and the rows'
    accelerations ``w``. Also the quadratic forms of eqs. (28), (29) and ``lam^T G_c lam``
    in ``tau``, the input metric ``B^T M_s^-1 B`` of eq. (31) (corrected, see docs), the
    projectors of eqs. (14) and (19) and the Delassus matrix ``G_c``.
    """
    ns = sz.n_coordinates
    q, K = alg.sym("q", ns), fn["K"]
    sc = _scene_inputs(alg, sz)
    S = _at_rest_system(fn, alg, sz, q, K, sc)
    A, A_s, A_o, M_s, B = S["A"], S["A_s"], S["A_o"], S["M_s"], S["B"]
    Minv_B, Minv_AsT, I_obj, Iinv_AoT, Gc = (S["Minv_B"], S["Minv_AsT"], S["I_obj"],
                                             S["Iinv_AoT"], S["Gc"])
    free = sc["free"]
    D = ca.diag(free)
    lam_released = (1 - free) * sc["lam_fixed"]
    G_factors, pivot_ratio = _masked_delassus(alg, Gc, free, sc["regularization"])
    # eq. (14) restricted to the held rows: Phi_c = G'^-1 D A I^-1   (n_c x n)
    A_Iinv = ca.horzcat(Minv_AsT.T, Iinv_AoT.T)
    # (one solve for both right-hand sides; the second gives the fixed forces' offset)
    X = alg.solve(G_factors, ca.horzcat(ca.mtimes(D, A_Iinv),
                                        ca.mtimes([D, Gc, lam_released])))
    Phi_c = X[:, :ns + 3]
    # eq. (19): Phi_perp = 1 - A^T Phi_c
    Phi_perp = alg.eye(ns + 3) - ca.mtimes(A.T, Phi_c)
    # eq. (17): lam = -Phi_c f, f = (B tau, f_obj)
    Phi_lam_tau = -ca.mtimes(Phi_c[:, :ns], B)
    Phi_lam_f = -Phi_c[:, ns:]
    lam_offset = lam_released - X[:, ns + 3]
    Phi_qdd_tau = Minv_B + ca.mtimes(Minv_AsT, Phi_lam_tau)            # eq. (22)
    Phi_qdd_f = ca.mtimes(Minv_AsT, Phi_lam_f)                          # eq. (23)
    Phi_a_tau = ca.mtimes(Iinv_AoT, Phi_lam_tau)                        # eq. (24)
    Phi_a_f = ca.diag(1 / I_obj) + ca.mtimes(Iinv_AoT, Phi_lam_f)       # eq. (25)
    Xi_tau = ca.mtimes([Phi_qdd_tau.T, M_s, Phi_qdd_tau])               # eq. (28)
    Omega_tau = ca.mtimes([Phi_a_tau.T, ca.diag(I_obj), Phi_a_tau])     # eq. (29)
    inputs = _at_rest_inputs(sz, q, K, sc)
    outputs = {
        "lam_from_tau": Phi_lam_tau, "lam_from_f_obj": Phi_lam_f, "lam_offset": lam_offset,
        "qdd_from_tau": Phi_qdd_tau, "qdd_from_f_obj": Phi_qdd_f,
        "qdd_offset": ca.mtimes(Minv_AsT, lam_offset),
        "a_obj_from_tau": Phi_a_tau, "a_obj_from_f_obj": Phi_a_f,
        "a_obj_offset": ca.mtimes(Iinv_AoT, lam_offset),
        "w_from_tau": ca.mtimes(A_s, Minv_B) + ca.mtimes(Gc, Phi_lam_tau),
        "w_from_f_obj": ca.mtimes(A_o, ca.diag(1 / I_obj)) + ca.mtimes(Gc, Phi_lam_f),
        "w_offset": ca.mtimes(Gc, lam_offset),
        "xi_tau": Xi_tau, "omega_tau": Omega_tau,
        "lambda_form_tau": ca.mtimes([Phi_lam_tau.T, Gc, Phi_lam_tau]),
        "input_metric": ca.mtimes(B.T, Minv_B),                         # eq. (31)
        "projector_constrained": Phi_c, "projector_orthogonal": Phi_perp,
        "delassus": Gc, "pivot_ratio": pivot_ratio,
    }
    return _function(alg, "interaction_maps", inputs, outputs)


def _metric_forms(fn, alg, sz, q, K, sc, free):
    """Forms of the metrics in ``tau`` at rest for the held rows ``free`` (eqs. 28, 29, 31)."""
    S = _at_rest_system(fn, alg, sz, q, K, sc)
    G_factors, pivot_ratio = _masked_delassus(alg, S["Gc"], free, sc["regularization"])
    # eq. (17) with f_obj = 0: Phi_lam_tau = -G'^-1 D A_s M_s^-1 B
    Phi_lam_tau = -alg.solve(G_factors, ca.mtimes(ca.diag(free), ca.mtimes(S["A_s"],
                                                                           S["Minv_B"])))
    Phi_qdd_tau = S["Minv_B"] + ca.mtimes(S["Minv_AsT"], Phi_lam_tau)      # eq. (22)
    Phi_a_tau = ca.mtimes(S["Iinv_AoT"], Phi_lam_tau)                      # eq. (24)
    return {
        "omega_tau": ca.mtimes([Phi_a_tau.T, ca.diag(S["I_obj"]), Phi_a_tau]),   # eq. (29)
        "xi_tau": ca.mtimes([Phi_qdd_tau.T, S["M_s"], Phi_qdd_tau]),             # eq. (28)
        "lambda_form_tau": ca.mtimes([Phi_lam_tau.T, S["Gc"], Phi_lam_tau]),
        "input_metric": ca.mtimes(S["B"].T, S["Minv_B"]),                        # eq. (31)
        "contact_from_tau": Phi_lam_tau[0, :],
        "pivot_ratio": pivot_ratio,
    }


def metric_forms(fn, alg: Algebra, sz: _Sizes) -> ca.Function:
    """The quadratic forms of the metrics in ``tau`` at rest, for a given active set.

    A lean subset of ``interaction_maps`` for the extremes over the input ellipsoid:
    ``omega_tau`` (eq. 29), ``xi_tau`` (eq. 28), ``lambda_form_tau`` (``lam^T G_c lam``), the
    input metric ``B^T M_s^-1 B`` (eq. 31, corrected) and the contact row of
    ``lam_from_tau`` (its sign tells whether a torque keeps the contact).
    """
    q, K = alg.sym("q", sz.n_coordinates), fn["K"]
    sc = _scene_inputs(alg, sz)
    forms = _metric_forms(fn, alg, sz, q, K, sc, sc["free"])
    return _function(alg, "metric_forms", _at_rest_inputs(sz, q, K, sc, lam_fixed=False), forms)


# ------------------------------------------------------------------------------------------
# closed-form extremes over the input ellipsoid (eq. 31), n_a <= 3, scalar (SX) only
# ------------------------------------------------------------------------------------------
def _chol_small(A):
    """Lower Cholesky factor of a small SPD ``SX`` matrix."""
    n = A.shape[0]
    L = ca.SX(n, n)
    for j in range(n):
        s = A[j, j]
        for k in range(j):
            s = s - L[j, k] * L[j, k]
        L[j, j] = ca.sqrt(s)
        for i in range(j + 1, n):
            t = A[i, j]
            for k in range(j):
                t = t - L[i, k] * L[j, k]
            L[i, j] = t / L[j, j]
    return L


def _lower_inv(L):
    n = L.shape[0]
    Li = ca.SX(n, n)
    for i in range(n):
        Li[i, i] = 1 / L[i, i]
        for j in range(i):
            s = ca.SX(0)
            for k in range(j, i):
                s = s + L[i, k] * Li[k, j]
            Li[i, j] = -s / L[i, i]
    return Li


def _unit_or(v, fallback, scale):
    nv = ca.dot(v, v)
    return ca.if_else(nv > 1e-28 * scale, v / ca.sqrt(ca.fmax(nv, 1e-300)), fallback)


def _cross3(a, b):
    return ca.vertcat(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                      a[0] * b[1] - a[1] * b[0])


def _sym_eig_extremes(C):
    """Smallest and largest eigenpairs of a symmetric 1x1, 2x2 or 3x3 ``SX`` matrix in closed
    form (trigonometric solution of the characteristic cubic for 3x3):
    ``(l_min, l_max, v_min, v_max)`` with unit eigenvectors; a repeated eigenvalue gets any
    unit vector of its eigenspace."""
    n = C.shape[0]
    if n == 1:
        return C[0, 0], C[0, 0], ca.SX(1), ca.SX(1)
    scale = ca.sumsqr(C) + 1e-300
    if n == 2:
        a, b, c = C[0, 0], C[0, 1], C[1, 1]
        mean = (a + c) / 2
        r = ca.sqrt(((a - c) / 2) ** 2 + b ** 2)
        lmax = mean + r
        v1 = ca.vertcat(b, lmax - a)
        v2 = ca.vertcat(lmax - c, b)
        v = ca.if_else(ca.dot(v2, v2) > ca.dot(v1, v1), v2, v1)
        vmax = _unit_or(v, ca.vertcat(1, 0), scale)
        return mean - r, lmax, ca.vertcat(-vmax[1], vmax[0]), vmax
    qm = ca.trace(C) / 3
    p1 = C[0, 1] ** 2 + C[0, 2] ** 2 + C[1, 2] ** 2
    p2 = (C[0, 0] - qm) ** 2 + (C[1, 1] - qm) ** 2 + (C[2, 2] - qm) ** 2 + 2 * p1
    p = ca.sqrt(p2 / 6)
    Bm = (C - qm * ca.SX.eye(3)) / ca.fmax(p, 1e-300)
    r = ca.fmin(ca.fmax(ca.det(Bm) / 2, -1), 1)
    angle = ca.acos(r) / 3
    lmax = qm + 2 * p * ca.cos(angle)
    lmin = qm + 2 * p * ca.cos(angle + 2 * math.pi / 3)

    def eigvec(lam, fallback):
        R = C - lam * ca.SX.eye(3)
        r0, r1, r2 = R[0, :].T, R[1, :].T, R[2, :].T
        c01, c02, c12 = _cross3(r0, r1), _cross3(r0, r2), _cross3(r1, r2)
        n01, n02, n12 = ca.dot(c01, c01), ca.dot(c02, c02), ca.dot(c12, c12)
        v = ca.if_else(n01 >= n02, c01, c02)
        v = ca.if_else(n12 > ca.fmax(n01, n02), c12, v)
        return _unit_or(v, fallback, scale ** 2)

    # a vector orthogonal to the dominant row of C - lmax 1 (used when lmax is repeated)
    r0 = (C - lmax * ca.SX.eye(3))[0, :].T
    alt = _unit_or(_cross3(r0, ca.vertcat(0, 0, 1)),
                   _unit_or(_cross3(r0, ca.vertcat(0, 1, 0)), ca.vertcat(1, 0, 0), scale), scale)
    vmax = eigvec(lmax, alt)
    e = ca.if_else(ca.fabs(vmax[0]) < 0.5, ca.vertcat(1, 0, 0), ca.vertcat(0, 1, 0))
    perp = _unit_or(_cross3(vmax, e), ca.vertcat(0, 0, 1), 1)
    vmin = eigvec(lmin, perp)
    vmin = _unit_or(vmin - ca.dot(vmin, vmax) * vmax, perp, 1)
    return lmin, lmax, vmin, vmax


def metric_extremes(fn, alg: Algebra, sz: _Sizes) -> ca.Function:
    """Extreme values of the metrics over the boundary of the input ellipsoid (eq. 31), and the
    torques attaining them, for both contact states, in closed form (n_a <= 3).

    For a form ``X`` in ``tau`` and ``N = B^T M_s^-1 B = L L^T``, the extremes of
    ``tau^T X tau`` on ``tau^T N tau = 1`` are the extreme eigenvalues of ``L^-1 X L^-T``,
    attained at ``tau = L^-T u``. For sr, the generalized problem ``(Omega, Omega + Xi)``
    (eq. 30) is whitened twice. Outputs ``<metric>_<state>`` hold ``(l_min, l_max)`` and
    ``tau_<metric>_<state>`` the two torques as columns; the runtime signs them with
    ``contact_from_tau`` (the contact force per torque).
    """
    if alg.kind != "sx" or sz.n_joints > EXTREMES_MAX_JOINTS:
        raise ValueError(f"metric_extremes exists for n_a <= {EXTREMES_MAX_JOINTS} (SX) only")
    na = sz.n_joints
    q, K = alg.sym("q", sz.n_coordinates), fn["K"]
    sc = _scene_inputs(alg, sz)
    free_lost = alg.sym("free_lost", sz.n_constraints)
    kept = _metric_forms(fn, alg, sz, q, K, sc, sc["free"])
    lost = _metric_forms(fn, alg, sz, q, K, sc, free_lost)
    N = kept["input_metric"]                      # eq. (31): tau^T N tau <= 1
    Linv = _lower_inv(_chol_small(N))
    outputs = {}

    def extremes_of(X, label):
        C = ca.mtimes([Linv, X, Linv.T])
        lmin, lmax, vmin, vmax = _sym_eig_extremes((C + C.T) / 2)
        outputs[label] = ca.vertcat(lmin, lmax)
        outputs["tau_" + label] = ca.horzcat(ca.mtimes(Linv.T, vmin), ca.mtimes(Linv.T, vmax))

    for state, forms in (("kept", kept), ("lost", lost)):
        for metric, key in (("norm_a_obj", "omega_tau"), ("norm_qdd", "xi_tau"),
                            ("norm_lambda", "lambda_form_tau")):
            extremes_of(forms[key], f"{metric}_{state}")
    # eq. (30) on the kept half: (Omega, Omega + Xi), regularised where the wheels brace
    Omega = ca.mtimes([Linv, kept["omega_tau"], Linv.T])
    Den = ca.mtimes([Linv, kept["omega_tau"] + kept["xi_tau"], Linv.T])
    Den = (Den + Den.T) / 2 + 1e-12 * ca.trace(Den) * ca.SX.eye(na)
    LDinv = _lower_inv(_chol_small(Den))
    C = ca.mtimes([LDinv, Omega, LDinv.T])
    lmin, lmax, vmin, vmax = _sym_eig_extremes((C + C.T) / 2)
    taus = []
    for u in (vmin, vmax):
        t = ca.mtimes([Linv.T, LDinv.T, u])
        taus.append(t / ca.sqrt(ca.mtimes([t.T, N, t])))
    outputs["sr_kept"] = ca.vertcat(lmin, lmax)
    outputs["tau_sr_kept"] = ca.horzcat(*taus)
    outputs["contact_from_tau"] = kept["contact_from_tau"]
    outputs["pivot_ratio_kept"] = kept["pivot_ratio"]
    outputs["pivot_ratio_lost"] = lost["pivot_ratio"]
    inputs = _at_rest_inputs(sz, q, K, sc, lam_fixed=False)
    inputs = {**{k: v for k, v in inputs.items() if k != "regularization"},
              "free_lost": free_lost, "regularization": sc["regularization"]}
    return _function(alg, "metric_extremes", inputs, outputs)


def _placement(fn, alg, sz, q, K, contact_link, contact_offset, object_distance, side,
               poses=None, rotations=None):
    """The object placed at the contact (see :func:`place_object`): ``q_obj``, ``rho``, the
    contact point ``P`` and the contact link's rotation ``(cos phi_k, sin phi_k)``, which is
    the object's orientation. ``poses`` and ``rotations`` as in :func:`_constraint_rows`."""
    nl = sz.n_links
    if poses is None:
        poses = fn["link_poses"](q, K)
    if rotations is None:
        rotations = _link_rotations(q, nl)
    pose = ca.mtimes(poses, contact_link)
    com_k = ca.dot(K[3 * nl: 4 * nl], contact_link)
    c_k, s_k = _contact_rotation(*rotations, contact_link)
    e = ca.vertcat(c_k, s_k)
    n = side * ca.vertcat(-s_k, c_k)
    P = pose[:2] + (contact_offset - com_k) * e
    q_obj = ca.vertcat(P + object_distance * n, pose[2])
    rho = ca.vertcat(alg.zeros(1, 1), -side * object_distance)
    return q_obj, rho, P, (c_k, s_k)


def place_object(fn, alg: Algebra, sz: _Sizes) -> ca.Function:
    """Pose of the object and its contact point for a contact at ``contact_offset``.

    The contact point lies on link ``k`` (one-hot ``contact_link``) at ``contact_offset``
    from its rear end; the object's COM lies on the contact normal
    ``n = side (-sin phi_k, cos phi_k)`` at ``object_distance`` from it, and the object is
    aligned with the link (``psi = phi_k``), so ``rho = (0, -side * object_distance)``.
    """
    nl = sz.n_links
    q, K = alg.sym("q", sz.n_coordinates), fn["K"]
    contact_link = alg.sym("contact_link", nl)
    contact_offset = alg.sym("contact_offset", 1)
    object_distance = alg.sym("object_distance", 1)
    side = alg.sym("side", 1)
    q_obj, rho, P, _ = _placement(fn, alg, sz, q, K, contact_link, contact_offset,
                                  object_distance, side)
    inputs = {"q": q, "K": K, "contact_link": contact_link, "contact_offset": contact_offset,
              "object_distance": object_distance, "side": side}
    outputs = {"q_obj": q_obj, "rho": rho, "contact_point": P}
    return _function(alg, "place_object", inputs, outputs)


def coupled_functions(link_functions: dict, n_joints: int, n_parameters: int, *, prefix: str,
                      algebra: str = "sx") -> list[ca.Function]:
    """Every composed function for ``n_joints``, in manifest order (see
    :data:`COUPLED_FUNCTIONS`), from the per-link CasADi functions ``link_functions``."""
    alg = Algebra(algebra, prefix)
    sz = _Sizes(n_joints)
    fn = {**link_functions, "K": alg.sym("K", n_parameters)}
    out = [constrained_dynamics(fn, alg, sz), interaction_maps(fn, alg, sz),
           metric_forms(fn, alg, sz), place_object(fn, alg, sz), contact_system(fn, alg, sz),
           contact_system_at_rest(fn, alg, sz)]
    if n_joints <= EXTREMES_MAX_JOINTS:
        # closed-form eigenproblems: scalar code whatever the algebra of the others
        sx = Algebra("sx", prefix)
        out.append(metric_extremes({**link_functions, "K": sx.sym("K", n_parameters)}, sx, sz))
    return out
