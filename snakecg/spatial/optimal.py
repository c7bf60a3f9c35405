"""Optimal joint torques for a spatial snake lying on the ground (the planar
:meth:`~snakecg.SceneModel.optimize`'s tasks, at rest), from the maps of one active set
(:mod:`snakecg.spatial.queries`).

Every task keeps the contact and, in the ``wheels`` scenario, every wheel within its
friction bound ``|lam_i| <= mu N_i`` (``N_i`` the link's solved normal force, affine in
``tau``: a pitch torque moves the weight between the links). In that state — the contact
kept, the wheels held, the ground and pitch rows held — ``qdd``, ``a_obj`` and every force
are linear in ``tau`` on the ground, so:

* ``max_sr``: ``sr`` is of degree 0 in ``tau``; its largest value over all torque directions
  keeping the contact is the largest generalized eigenvalue of ``(Omega, Omega + Xi)``
  (exact); every region (box, ellipsoid) and the friction bounds (which hold at a small
  enough scale: ``N_i`` at rest is the weight) contain a multiple of that direction. The
  answer is the largest such multiple (the strongest of the best pushes).
* ``strongest_push``: the largest ``d . a_obj`` (linear) and ``least_slip_push``: the least
  ``||qdd||^2`` (a positive semidefinite quadratic) with ``d . a_obj >= a_min``, under the
  linear conditions (contact force >= 0, friction bounds) and the box and/or the ellipsoid:
  convex problems, solved by IPOPT (through CasADi) to a KKT point, which is the global
  optimum; ``least_slip_push`` is infeasible exactly when the strongest push reaches less
  than ``a_min``.

``status`` is ``"optimal"`` only when the solver converged and the exact forward solve at
the answer confirms the assumed state (contact kept, wheels sticking) and the value (to
1e-6 relative); ``"infeasible"`` for a push that the limits cannot give (``tau`` the
strongest push); ``"failed"`` otherwise, with the reason.
"""

from __future__ import annotations

import time

import numpy as np

from ..errors import InputError
from ..optimize.query import Query, _finite_vector, _is_number
from ..optimize.result import (CONTACT, ELLIPSOID, FRICTION_MARGIN, OBJECTIVES, OptimizeResult,
                               joint_name, wheel_name)
from .queries import StateMaps, _held, metric_forms, screen

__all__ = ["optimize"]

#: Relative agreement of the forward solve with the solver's value.
CHECK_TOL = 1e-6
#: A constraint with a slack below this (relative) is binding.
ACTIVE = 1e-6


def _validate(model, objective, tau_max, radius, direction, a_min, a_obj, allow_slide):
    if not isinstance(objective, str) or objective.replace("-", "_") not in OBJECTIVES:
        raise InputError(f"objective must be one of {', '.join(OBJECTIVES)} (dashes "
                         f"allowed), got {objective!r:.60}")
    objective = objective.replace("-", "_")
    na = model.n_joints
    source = "argument"
    if isinstance(tau_max, str) and tau_max == "robot":
        e = model.scene.robot.effort_limits
        tau_max, source = (None, None) if e is None else (np.array(e, dtype=float), "robot")
    elif tau_max is not None:
        if np.ndim(tau_max) == 0 and _is_number(tau_max):
            tau_max = np.full(na, float(tau_max))
        tau_max = _finite_vector("tau_max", tau_max, (na,), f"a positive number or {na} "
                                 "positive numbers (N m), one per joint, 'robot' or None")
        if np.any(tau_max <= 0):
            raise InputError(f"tau_max must be positive (N m), got {tau_max.tolist()}")
    if radius is not None:
        if not _is_number(radius) or not np.isfinite(radius) or radius <= 0:
            raise InputError(f"radius must be a positive number (the ellipsoid "
                             f"tau^T B^T M^-1 B tau <= radius^2 of eq. 31), got {radius!r:.60}")
        radius = float(radius)
    if tau_max is None and radius is None:
        radius = 1.0
    given = {k for k, v in (("direction", direction), ("a_min", a_min)) if v is not None}
    allowed = {"max_sr": set(), "least_slip_push": {"direction", "a_min"},
               "strongest_push": {"direction"}}[objective]
    if given - allowed:
        raise InputError(f"{', '.join(sorted(given - allowed))} do(es) not apply to objective "
                         f"{objective!r} (it takes: {', '.join(sorted(allowed)) or 'no task'})")
    if a_obj is not None:
        raise InputError("a_obj does not apply to a spatial scene (the contact pushes along "
                         "its normal only); give direction and a_min")
    if allow_slide not in (False, None):
        raise InputError("allow_slide does not apply to a spatial scene: every wheel stays "
                         "within its friction bound")
    d = None
    if direction is not None:
        d = _finite_vector("direction", direction, (2, 3), "(dx, dy) or (dx, dy, dalpha): "
                           "the direction of the object's acceleration, world frame")
        if not np.linalg.norm(d) > 0:
            raise InputError("direction must be non-zero")
        d = np.r_[d, 0.0] if d.shape[0] == 2 else d
        d = d / np.linalg.norm(d)
    if objective == "least_slip_push":
        if d is None or a_min is None:
            raise InputError("least_slip_push needs a task: direction=(dx, dy) and a_min "
                             "(m/s^2)")
        if not _is_number(a_min) or not np.isfinite(a_min) or a_min < 0:
            raise InputError(f"a_min must be a number >= 0 (m/s^2), got {a_min!r:.60}")
        a_min = float(a_min)
    return Query(objective, tau_max, radius, d, a_min, None,
                 np.zeros(model.n_constraints, bool), None if tau_max is None else source)


class _Problem:
    """The linear maps of the all-held state at one configuration, and its constraints
    ``F tau + f >= 0`` (the contact force, both sides of each friction bound)."""

    def __init__(self, model, S: StateMaps, i: int, maps, query: Query):
        sc = model.scene
        nl = model.n_links
        self.N, self.M = S.N[i], S.M[i]
        Lam, lam0 = maps["Lam"][i], maps["lam0"][i]
        self.Q, self.A, self.c = maps["Q"][i], maps["A"][i], Lam[0]
        rows, consts, names = [Lam[0]], [0.0], [CONTACT]
        if sc.scenario == "wheels":
            k = 1.0 - FRICTION_MARGIN
            for w in sc.wheel_links:
                Nr, N0 = Lam[nl + w], lam0[nl + w]
                for sgn in (1.0, -1.0):  # mu N (1 - margin) -+ lam_w >= 0
                    rows.append(sc.mu * k * Nr - sgn * Lam[w])
                    consts.append(sc.mu * k * N0 - sgn * lam0[w])
                    names.append(wheel_name(w))
        self.F, self.f, self.names = np.array(rows), np.array(consts), names
        self.tau_max, self.radius = query.tau_max, query.radius
        if query.direction is not None:
            self.d = query.direction
        else:  # the contact normal, from the link to the object
            T = model.robot_model.link_poses(S.q[i])[sc.contact_link - 1]
            e = T[:2, 0] / np.linalg.norm(T[:2, 0])
            self.d = np.array([-e[1], e[0], 0.0]) * sc.side_sign
        # the torque's scale: the largest |tau| in the region
        sizes = []
        if self.tau_max is not None:
            sizes.append(float(np.max(self.tau_max)))
        if self.radius is not None:
            sizes.append(self.radius / np.sqrt(np.linalg.eigvalsh(self.N)[0]))
        self.s = min(sizes)

    def scale_limit(self, u):
        """The largest ``t`` with ``t u`` in the region and the constraints, and what binds."""
        t, why = np.inf, []
        if self.tau_max is not None:
            with np.errstate(divide="ignore"):
                lim = self.tau_max / np.abs(u)
            j = int(np.argmin(lim))
            t, why = lim[j], [joint_name(j + 1)]
        if self.radius is not None:
            te = self.radius / np.sqrt(u @ self.N @ u)
            t, why = (te, [ELLIPSOID]) if te < t else (t, why)
        g = self.F @ u
        for r in range(1, len(self.f)):  # the friction bounds: f_r + t g_r >= 0
            if g[r] < 0 and -self.f[r] / g[r] < t:
                t, why = -self.f[r] / g[r], [self.names[r]]
        return t, why


def _ipopt(P: _Problem, objective: str, a_min=None):
    """``(tau, solver status, iterations)`` of the convex problem, scaled to ``|u| ~ 1``."""
    import casadi as ca

    na = P.N.shape[0]
    u = ca.SX.sym("u", na)
    g_push = P.s * (P.A.T @ P.d)
    gn = max(np.linalg.norm(g_push), 1e-300)
    push = ca.dot(ca.DM(g_push / gn), u)
    if objective == "strongest_push":
        f = -push
    else:
        X = P.s ** 2 * (P.Q.T @ P.M @ P.Q)
        X = 0.5 * (X + X.T) / max(np.abs(X).max(), 1e-300)
        f = ca.mtimes([u.T, ca.DM(X), u])
    Fs = P.F * P.s
    fs = np.maximum(np.abs(Fs).max(axis=1), np.abs(P.f))
    fs = np.where(fs > 0, fs, 1.0)
    g = [ca.mtimes(ca.DM(Fs / fs[:, None]), u) + ca.DM(P.f / fs)]
    lbg = [np.zeros(len(P.f))]
    if P.radius is not None:
        Nn = P.s ** 2 * P.N / P.radius ** 2
        g.append(1.0 - ca.mtimes([u.T, ca.DM(Nn), u]))
        lbg.append([0.0])
    if objective == "least_slip_push":
        g.append(push - a_min / gn)
        lbg.append([0.0])
    ub = np.full(na, np.inf) if P.tau_max is None else P.tau_max / P.s
    solver = ca.nlpsol("push", "ipopt", {"x": u, "f": f, "g": ca.vertcat(*g)},
                       {"print_time": False, "ipopt": {"print_level": 0, "sb": "yes",
                                                       "tol": 1e-12,
                                                       "constr_viol_tol": 1e-12}})
    sol = solver(x0=np.zeros(na), lbx=-ub, ubx=ub, lbg=np.concatenate(lbg), ubg=np.inf)
    st = solver.stats()
    return np.array(sol["x"]).ravel() * P.s, st["return_status"], int(st["iter_count"])


def _linear_constraints(P: _Problem, objective: str, a_min):
    """Every linear constraint as ``C tau >= r``: the contact and friction rows, the box,
    and the push's ``d . a_obj >= a_min``."""
    C, r = [P.F], [-P.f]
    if P.tau_max is not None:
        eye = np.eye(len(P.tau_max))
        C += [eye, -eye]
        r += [-P.tau_max, -P.tau_max]
    if objective == "least_slip_push":
        C.append((P.A.T @ P.d)[None])
        r.append([a_min])
    return np.vstack(C), np.concatenate(r)


def _polish(P: _Problem, objective: str, tau, a_min=None):
    """The interior-point answer made exact on its active set (an equality-constrained
    problem solved directly): kept when it is feasible and no worse; the ellipsoid (not
    linear) active: the answer as it is."""
    if P.radius is not None and np.sqrt(tau @ P.N @ tau) >= P.radius * (1 - ACTIVE):
        return tau
    C, r = _linear_constraints(P, objective, a_min)
    size = np.abs(C).max(axis=1) * max(np.abs(tau).max(), 1e-300) + np.abs(r)
    act = np.flatnonzero(C @ tau - r <= ACTIVE * size)
    na = len(tau)
    if objective == "strongest_push":
        if act.size == 0 or np.linalg.matrix_rank(C[act]) < na:
            return tau
        new = np.linalg.lstsq(C[act], r[act], rcond=None)[0]
        better = P.d @ P.A @ new >= P.d @ P.A @ tau - 1e-12 * abs(P.d @ P.A @ tau)
    else:
        X = P.Q.T @ P.M @ P.Q
        Ca = C[act]
        K = np.block([[2 * X, -Ca.T], [Ca, np.zeros((len(act), len(act)))]])
        sol = np.linalg.lstsq(K, np.r_[np.zeros(na), r[act]], rcond=1e-14)[0]
        new = sol[:na]
        better = new @ X @ new <= tau @ X @ tau * (1 + 1e-12) + 1e-300
    feasible = np.all(C @ new - r >= -1e-12 * size)
    return new if better and feasible else tau


def _value(objective, r, P):
    if objective == "max_sr":
        return float(r.sr)
    if objective == "strongest_push":
        return float(P.d @ r.a_obj)
    return float(r.norm_qdd)


def _binding(P: _Problem, tau):
    out = []
    if P.tau_max is not None:
        out += [joint_name(j + 1) for j in np.flatnonzero(np.abs(tau) >= P.tau_max * (1 - ACTIVE))]
    if P.radius is not None and np.sqrt(tau @ P.N @ tau) >= P.radius * (1 - ACTIVE):
        out.append(ELLIPSOID)
    slack = P.F @ tau + P.f
    size = np.abs(P.F).max(axis=1) * np.abs(tau).max() + np.abs(P.f)
    for r in np.flatnonzero(slack <= ACTIVE * np.maximum(size, 1e-300)):
        if P.names[r] not in out:
            out.append(P.names[r])
    return out


def _one(model, S, i, maps, query, sr_ex):
    """``(tau, status, reason, value, binding, solver, iterations)`` of configuration i."""
    P = _Problem(model, S, i, maps, query)
    q = S.q[i]
    obj = query.objective
    if obj == "max_sr":
        u = sr_ex[i]
        if not np.all(np.isfinite(u)) or not np.any(u):
            return np.zeros(model.n_joints), "failed", "no torque moves the snake", np.nan, [], \
                "generalized eigenvector of (Omega, Omega + Xi)", 0
        t, why = P.scale_limit(u)
        tau = t * u
        solver, iters, ok_status = "generalized eigenvector of (Omega, Omega + Xi) (exact)", 0, \
            "Solve_Succeeded"
    else:
        tau, ok_status, iters = _ipopt(P, "strongest_push")
        tau = _polish(P, "strongest_push", tau)
        solver = ("IPOPT (CasADi) on the convex problem of the all-held state, its active set "
                  "solved exactly")
        if obj == "least_slip_push":
            best = P.d @ P.A @ tau
            if ok_status == "Solve_Succeeded" and best < query.a_min * (1 - CHECK_TOL):
                r = model.forward(q, tau)
                return tau, "infeasible", (f"the strongest push the limits allow gives "
                                           f"d . a_obj = {best:.6g} m/s^2 < a_min = "
                                           f"{query.a_min:.6g}"), _value(obj, r, P), \
                    _binding(P, tau), solver, iters
            if ok_status == "Solve_Succeeded":
                tau, ok_status, more = _ipopt(P, obj, query.a_min)
                tau = _polish(P, obj, tau, query.a_min)
                iters += more
        why = _binding(P, tau)
    r = model.forward(q, tau)
    value = _value(obj, r, P)
    if ok_status != "Solve_Succeeded":
        return tau, "failed", f"the solver stopped: {ok_status}", value, why, solver, iters
    if r.singular:
        return tau, "failed", r.reason, value, why, solver, iters
    stick = model.scene.scenario != "wheels" or all(
        r.wheel_state[w - 1] == "stick" for w in model.scene.wheel_links)
    if not (r.contact or not np.any(tau)) or not stick:
        return tau, "failed", ("the forward solve at the answer does not keep the contact and "
                               "every wheel sticking"), value, why, solver, iters
    want = {"max_sr": lambda: float(np.clip(
        (tau @ maps_form(maps, i, "a") @ tau) / max(tau @ maps_form(maps, i, "aq") @ tau,
                                                    1e-300), 0, 1)),
            "strongest_push": lambda: float(P.d @ P.A @ tau),
            "least_slip_push": lambda: float(tau @ P.Q.T @ P.M @ P.Q @ tau)}[obj]()
    if not abs(value - want) <= CHECK_TOL * max(abs(want), abs(value), 1e-12):
        return tau, "failed", (f"the forward solve gives {value:.9g}, the maps {want:.9g}"), \
            value, why, solver, iters
    return tau, "optimal", "", value, why, solver, iters


def maps_form(maps, i, which):
    """``Omega`` (``"a"``) or ``Omega + Xi`` (``"aq"``) of configuration ``i``."""
    return maps["forms"]["norm_a_obj"][i] + (maps["forms"]["norm_qdd"][i] if which == "aq"
                                             else 0.0)


def optimize(model, q, objective: str = "max_sr", *, tau_max="robot", radius=None,
             direction=None, a_min=None, a_obj=None, allow_slide=False) -> OptimizeResult:
    """The optimal joint torque for a task at configuration ``q`` (``(n_q,)`` or
    ``(N, n_q)``, lying on the ground, at rest): ``"max_sr"``, ``"strongest_push"`` (along
    ``direction``, default the contact normal) or ``"least_slip_push"`` (``direction`` and
    ``a_min``), with the planar :meth:`~snakecg.SceneModel.optimize`'s limits (``tau_max``:
    a box, default the robot's effort limits; ``radius``: the ellipsoid of eq. 31 with the
    spatial ``M``; neither: ``radius = 1``). See the module for the methods and the status."""
    t0 = time.perf_counter()
    query = _validate(model, objective, tau_max, radius, direction, a_min, a_obj, allow_slide)
    qa, batched = model.configurations(q)
    S = StateMaps(model, qa)
    S.q = qa
    forms, c, maps, residual = metric_forms(S, _held(model, True, model.scene.has_wheels))
    maps["forms"] = forms
    sr_tau = None
    if query.objective == "max_sr":
        from .queries import linear_extremes

        ex, _ = linear_extremes(model, S, wheels=model.scene.has_wheels)
        sr_tau = ex.tau_max["sr"]
    rows = []
    why = screen(model, qa, residual)
    for i in range(S.n):
        if why[i]:
            r = model.forward(qa[i], np.zeros(model.n_joints))
            rows.append((np.full(model.n_joints, np.nan), "failed", why[i], np.nan, [],
                         "", 0, r))
            continue
        out = _one(model, S, i, maps, query, sr_tau)
        rows.append(out + (model.forward(qa[i], out[0]),))
    elapsed = (time.perf_counter() - t0) / S.n
    pick = lambda k: [r[k] for r in rows]  # noqa: E731
    if batched:
        analysis = model.forward(qa, np.nan_to_num(np.array(pick(0))))
        res = OptimizeResult(query.objective, np.array(pick(0)), np.array(pick(1), object),
                             np.array(pick(2), object), np.array(pick(3), float), pick(4),
                             analysis, np.array(pick(5), object), np.array(pick(6)),
                             np.full(S.n, elapsed))
    else:
        r = rows[0]
        res = OptimizeResult(query.objective, r[0], r[1], r[2], r[3], r[4], r[7], r[5], r[6],
                             elapsed)
    res._query = query
    return res
