"""``max_sr``: the torque that maximises the slippage ratio (eq. 30) over the input region.

Every row held: the top generalized eigenvector of ``(Omega, Omega + Xi)`` (eqs. 28-30),
scaled to the largest magnitude the limits allow. Wheels allowed to slide: one convex problem
per wheel state (Charnes-Cooper form of the Rayleigh quotient on the state's affine map),
pruned by an exact upper bound, ranked by the exact forward solve (docs/optimize.md)."""

from __future__ import annotations

import itertools
import math

import numpy as np

from .. import kernels
from ..solver import ABSENT, HELD, PIVOT_TOL, SLIDE_NEG, SLIDE_POS, _free_and_fixed
from .fast import chol_solve, dot, quad, wheels
from .problems import Answer, floats, rows, scale_of, stick_rows
from .result import CONTACT, ELLIPSOID, SR_TIE, joint_name
from .solvers import _COLD, Problem, inside, solve_conic, solve_ipopt

def _max_scale(model, query, cfg, v):
    """Largest ``s > 0`` with ``s v`` inside every limit; and the limits that set it."""
    fl = floats(cfg)
    v = list(v)
    cands = []
    if query.radius is not None:
        cands.append((query.radius / math.sqrt(max(quad(fl["N"], v), 1e-300)), ELLIPSOID))
    if query.tau_max is not None:
        for j, m in enumerate(query.tau_max.tolist()):
            if abs(v[j]) > 0:
                cands.append((m / abs(v[j]), joint_name(j + 1)))
    L = fl["L"]
    for i, ub, name in wheels(model):
        li = dot(L[i], v)
        if abs(li) > 0:
            cands.append((ub / abs(li), name))
    s = min(c for c, _ in cands)
    binding = tuple(dict.fromkeys(nm for c, nm in cands if c <= s * (1 + 1e-9)))
    return s, binding


def _rank_one(cfg):
    """Top of the Rayleigh quotient when ``Omega = k l l^T`` (one frictionless contact,
    ``a_obj = a_dir lam_c``): ``sr = k c / (k c + 1)`` at ``v = Xi^-1 l``, ``c = l^T Xi^-1 l``
    (eqs. 28-30); None when ``Xi`` is not safely definite (the general eigensolve then)."""
    fl = floats(cfg)
    ell = fl["L"][0]
    v = chol_solve(fl["Xi"], ell)
    if v is None:
        return None
    c = dot(ell, v)
    if not c > 0:
        return None
    kc = cfg.k * c
    return kc / (kc + 1.0), v


def _top_rayleigh(Om, D):
    """Top generalized eigenpair of ``(Om, D)``, ``D`` positive semidefinite: restricted to
    the range of ``D`` (directions outside it move nothing, ``sr`` is 0/0 there)."""
    w, V = np.linalg.eigh(0.5 * (D + D.T))
    keep = w > 1e-12 * max(w[-1], 1e-300)
    Vr = V[:, keep] / np.sqrt(w[keep])
    C = Vr.T @ Om @ Vr
    lw, U = np.linalg.eigh(0.5 * (C + C.T))
    return float(lw[-1]), Vr @ U[:, -1]


def max_sr(model, query, cfg) -> Answer:
    n = cfg.N.shape[0]
    ell = cfg.L[0]
    if cfg.k <= 0 or not any(floats(cfg)["L"][0]):
        return Answer(np.zeros(n), "infeasible",
                      "no torque accelerates the object at this configuration (sr = 0 for "
                      "every torque)", (CONTACT,), "generalized eigenproblem", 0, None)
    # closed form (the cold re-solve of a failed certificate takes the general eigensolve)
    top = _rank_one(cfg) if _COLD.get() is None else None
    how = "generalized eigenproblem"
    if top is not None:
        lam, v = top
        how += " (rank-one closed form)"
    else:
        lam, v = _top_rayleigh(cfg.Om, cfg.Om + cfg.Xi)
        if ell @ v < 0:
            v = -v  # keep the contact: lam_c = L_c tau >= 0
        v = v.tolist()
    s, binding = _max_scale(model, query, cfg, v)
    best = Answer(np.array([s * x for x in v]), "optimal", "", binding, how, 0,
                  min(max(float(lam), 0.0), 1.0), claim=("eigen",))
    if query.slide.any():
        best = _max_sr_sliding(model, query, cfg, best)
    return best


def _slide_states(model, slide):
    choices = [(HELD,)]
    for i in range(1, model.n_constraints):
        if not model.present[i]:
            choices.append((ABSENT,))
        elif slide[i]:
            choices.append((HELD, SLIDE_POS, SLIDE_NEG))
        else:
            choices.append((HELD,))
    states = np.array(list(itertools.product(*choices)), dtype=np.int8)
    return states[1:]  # the first is "everything held", solved exactly above


def _state_maps(model, q, states):
    """Interaction maps of one configuration for many active sets, one compiled call."""
    S = states.shape[0]
    qa = q[None, :]
    q_obj, rho, _ = model.place(qa)
    free, lam_fixed = _free_and_fixed(states, model.bounds)
    f = np.ascontiguousarray
    outs = kernels.call(
        model.backend, "interaction_maps", S, q=f(q, dtype=float),
        **{k: model.scene_inputs[k] for k in ("K", "contact_link", "side", "object_mass",
                                              "object_inertia", "wheel_offset")},
        q_obj=f(q_obj[0]), rho=f(rho[0]), free=f(free, dtype=float),
        lam_fixed=f(lam_fixed, dtype=float), regularization=np.zeros(1))
    res = {}
    for name_, o in outs.items():
        res[name_] = o[:, :, 0] if o.shape[2] == 1 and name_.endswith("offset") else o
    res["pivot_ratio"] = outs["pivot_ratio"][:, 0, 0]
    return res


def _max_sr_sliding(model, query, cfg, stick: Answer) -> Answer:
    """Best wheel state (stick/slide+/slide- per allowed wheel), one convex problem each.

    States are solved best upper bound first and pruned against the best value so far; the
    candidates that beat the all-stick answer are then evaluated by one batched exact forward
    solve, which picks the winner (a state's optimum often lies on its boundary with another
    state, where the maps' rounding cannot separate them; ties keep the all-stick answer)."""
    n = cfg.N.shape[0]
    states = _slide_states(model, query.slide)
    mp = _state_maps(model, cfg.q, states)
    M = model.mass_matrix(cfg.q)
    Qh = np.concatenate([mp["qdd_from_tau"], mp["qdd_offset"][:, :, None]], axis=2)
    Xih = np.einsum("sai,ab,sbj->sij", Qh, M, Qh)
    Lh = np.concatenate([mp["lam_from_tau"], mp["lam_offset"][:, :, None]], axis=2)
    Wh = np.concatenate([mp["w_from_tau"], mp["w_offset"][:, :, None]], axis=2)
    ell = Lh[:, 0, :]
    # exact upper bound of sr on each state without its validity cone:
    # max k (l.z)^2 / (k (l.z)^2 + z^T Xi z) = k c / (k c + 1), c = l^T Xi^+ l
    pinv = np.linalg.pinv(Xih, rcond=1e-12, hermitian=True)
    c = np.einsum("si,sij,sj->s", ell, pinv, ell)
    ub = np.where(c > 0, cfg.k * c / (cfg.k * c + 1.0), 0.0)
    ub = np.where(mp["pivot_ratio"] > PIVOT_TOL, ub, -1.0)
    best_val = stick.expected
    solved = 0
    iters = 0
    cands = []  # (predicted sr, tau, binding, state) better than the all-stick answer
    outside = []  # states whose relaxed optimum leaves the ellipsoid: (value, s, prob, z)
    # phase 1: the linear relaxation (box rows; the ellipsoid's bounding box) of each state,
    # best upper bounds first; a relaxed optimum inside the region is the state's optimum
    for s in np.argsort(-ub):
        if ub[s] <= best_val + SR_TIE:
            break
        A, lba, uba, names = rows(model, query, cfg)
        A[0] = ell[s]
        lba[0] = uba[0] = 1.0
        stick_rows(model, cfg, A, lba, uba, names, Lh[s], states[s], Wh[s])
        lbx = np.full(n + 1, -np.inf)
        lbx[n] = 0.0
        prob = Problem(H=2 * Xih[s], g=np.zeros(n + 1), A=A, lba=lba, uba=uba, lbx=lbx,
                        ubx=np.full(n + 1, np.inf), names=names, scale=scale_of(query, cfg))
        sol = _solve_state(prob, cfg, best_val)
        solved += 1
        iters += sol.iterations
        if not sol.ok or sol.z[n] <= 0:
            continue  # the state is valid nowhere in the region
        z = sol.z
        val = _state_sr(cfg, Xih[s], ell[s], z)
        if not inside(query, cfg, z[:n] / z[n]):
            outside.append((val, s, prob, z))
        elif val > stick.expected + SR_TIE:
            best_val = max(best_val, val)
            cands.append((val, z[:n] / z[n], sol.binding, states[s], prob, z, prob))
    # phase 2: tighten the relaxation with tangent planes of the ellipsoid at the relaxed
    # optimum (Kelley's cutting planes, each a valid outer bound): most states then fall
    # below the best answer; IPOPT with the exact ellipsoid where the relaxation still beats it
    n_ipopt = 0
    for val, s, prob, z in sorted(outside, key=lambda o: -o[0]):
        if val <= best_val + SR_TIE:
            break
        cut = prob
        for _ in range(CUTS):
            cut = _with_tangent_cut(cut, cfg, query.radius, z)
            sol = _solve_state(cut, cfg, best_val)
            solved += 1
            if not sol.ok or sol.z[n] <= 0:
                break
            z = sol.z
            val = _state_sr(cfg, Xih[s], ell[s], z)
            if val <= best_val + SR_TIE or inside(query, cfg, z[:n] / z[n]):
                break
        if not sol.ok or sol.z[n] <= 0 or val <= best_val + SR_TIE:
            continue
        if inside(query, cfg, z[:n] / z[n]):  # the cut relaxation's optimum is feasible
            best_val = max(best_val, val)
            cands.append((val, z[:n] / z[n], sol.binding, states[s], prob, z, cut))
            continue
        prob.N, prob.r2 = cfg.N, query.radius**2
        tau = z[:n] / z[n]
        z0 = np.append(tau * query.radius / np.sqrt(tau @ cfg.N @ tau) * (1 - 1e-6), 1.0)
        sol = solve_ipopt(prob, z0 / (ell[s] @ z0) if ell[s] @ z0 > 0 else z0)
        n_ipopt += 1
        iters += sol.iterations
        if not sol.ok or sol.z[n] <= 0:
            continue
        z = sol.z
        val = _state_sr(cfg, Xih[s], ell[s], z)
        if val > stick.expected + SR_TIE:
            best_val = max(best_val, val)
            cands.append((val, z[:n] / z[n], sol.binding, states[s], prob, z, None))
    best = stick
    if cands:
        taus = np.array([c[1] for c in cands])
        fw = model.forward(np.repeat(cfg.q[None, :], len(cands), axis=0), taus)
        sliding = np.isin(fw.wheel_state, ("slide+", "slide-"))
        allowed = np.all(~sliding | query.slide[1:][None, :], axis=1)
        sr = np.where(fw.contact & allowed, fw.sr, -1.0)
        k = int(np.argmax(sr))
        if sr[k] > stick.expected + SR_TIE:
            _, tau, binding, state, prob, z, solved_prob = cands[k]
            if solved_prob is not None:  # the winner's QP again, its active set solved exactly
                sol = _solve_state(solved_prob, cfg, stick.expected, polish=True)
                solved += 1
                if sol.ok and sol.z[n] > 0:
                    z, tau, binding = sol.z, sol.z[:n] / sol.z[n], sol.binding
            if query.radius is not None:  # the exact region, for the certificate
                prob.N, prob.r2 = cfg.N, query.radius**2
            best = Answer(tau, "optimal", "", binding, "", 0, float(sr[k]), states=state,
                          claim=("state", prob, z))
    best.solver = (f"generalized eigenproblem; {len(states)} sliding wheel states: {solved} "
                   f"QPs, {n_ipopt} convex NLPs (ipopt)")
    best.iterations = iters
    return best


def _solve_state(prob: Problem, cfg, best_val: float, polish: bool = False):
    """A wheel state's QP ``min z^T Xi_h z`` s.t. ``l . z = 1`` and the state's cone (every
    other row is homogeneous), solved as the always-feasible ``min z^T Xi_h z - M l . z`` s.t.
    ``l . z <= 1`` and the cone: its solution is ``s z*`` with ``s = min(1, M / (2 m*))``
    (``m*`` the state's optimum), so ``z* = z / (l . z)`` exactly, and a state whose cone
    misses ``l . z > 0`` gives ``l . z = 0`` instead of an infeasible QP (a failed solve would
    cost a fresh solver). ``M`` is twice the value a state needs to beat ``best_val``. The
    states are compared on the solver's own answers; the winner is solved again with its
    active set polished (``polish``)."""
    ell = prob.A[0]
    m_ref = cfg.k * (1.0 / min(max(best_val, 1e-12), 1.0) - 1.0)
    M = 2.0 * min(max(m_ref, 1e-12), 1e12)
    lba = prob.lba.copy()
    lba[0] = -np.inf
    relaxed = Problem(H=prob.H, g=prob.g - M * ell, A=prob.A, lba=lba, uba=prob.uba,
                      lbx=prob.lbx, ubx=prob.ubx, names=prob.names, scale=prob.scale)
    sol = solve_conic(relaxed, polish=polish)
    if sol.ok:
        lz = ell @ sol.z
        if lz > 1e-9 * np.linalg.norm(ell) * np.linalg.norm(sol.z) and lz > 0:
            sol.z = sol.z / lz
        else:
            sol.ok = False
    return sol


#: Tangent-plane cuts of the ellipsoid tried per wheel state before IPOPT.
CUTS = 4


def _with_tangent_cut(prob: Problem, cfg, radius: float, z: np.ndarray) -> Problem:
    """``prob`` plus the ellipsoid's tangent plane at the radial projection of ``tau / t``:
    ``g . tau <= g . p t`` with ``p`` on the ellipsoid and ``g = N p`` (homogeneous)."""
    n = cfg.N.shape[0]
    tau = z[:n] / z[n]
    p = tau * radius / np.sqrt(tau @ cfg.N @ tau)
    g = cfg.N @ p
    row = np.append(-g, g @ p)
    return Problem(H=prob.H, g=prob.g, A=np.vstack([prob.A, row]),
                    lba=np.append(prob.lba, 0.0), uba=np.append(prob.uba, np.inf),
                    lbx=prob.lbx, ubx=prob.ubx, names=prob.names + [ELLIPSOID],
                    scale=prob.scale)


def _state_sr(cfg, Xih, ell, z):
    """sr at ``z = (tau, t)`` on a state's affine map: ``k / (k + z^T Xi_h z / (l . z)^2)``."""
    m = z @ Xih @ z / (ell @ z) ** 2
    return float(cfg.k / (cfg.k + m))


