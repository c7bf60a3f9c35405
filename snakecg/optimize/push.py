"""The push tasks: ``least_slip_push`` (a convex QP, eq. 26) and ``strongest_push`` (an
LP), every wheel sticking; with the ellipsoid of eq. (31) both become convex QCQPs, solved
exactly through the ellipsoid's multiplier (:func:`~snakecg.optimize.solvers.solve_ellipsoid`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .box_push import solve_box_push
from .problems import Answer, push_problem, push_target
from .query import Query
from .result import ELLIPSOID, FRICTION_MARGIN
from .solvers import _COLD, inside, solve_conic, solve_ellipsoid

@dataclass
class _Strongest:
    ok: bool
    lam: float  # the largest contact force
    tau: np.ndarray
    binding: tuple
    solver: str
    iterations: int
    status: str
    unique: bool  # no other torque reaches ``lam``


def _strongest_lam(model, query, cfg) -> _Strongest:
    """Largest contact force ``lam_c`` within the limits with every wheel sticking."""
    n = cfg.N.shape[0]
    ell = cfg.L[0]
    if query.tau_max is None:
        # the ellipsoid alone: tau = r N^-1 l / sqrt(l^T N^-1 l) (closed form, unique)
        Ni = np.linalg.solve(cfg.N, ell)
        tau = query.radius * Ni / np.sqrt(ell @ Ni)
        Lw = cfg.L[1:] @ tau
        u = model.bounds[1:]
        if np.all(~np.isfinite(u) | (np.abs(Lw) <= u * (1 - FRICTION_MARGIN))):
            return _Strongest(True, float(ell @ tau), tau, (ELLIPSOID,),
                             "closed form (ellipsoid)", 0, "", True)
    if query.radius is None and _COLD.get() is None:  # box only: posed directly in tau
        sol = solve_box_push(model, query, cfg, lp=True)
        if sol is not None:
            tau = sol.z[:n]
            return _Strongest(True, float(ell @ tau), tau, sol.binding, sol.solver,
                              sol.iterations, sol.status, sol.unique)
    prob = push_problem(model, query, cfg, lp=True)
    sol = solve_conic(prob)
    iters, solver, unique = sol.iterations, sol.solver, sol.unique
    if query.radius is not None and sol.ok and not inside(query, cfg, sol.z[:n]):
        sol = solve_ellipsoid(query, cfg, prob, sol.z[:n] @ cfg.N @ sol.z[:n])
        iters += sol.iterations
        solver = sol.solver
        # a linear objective on a strictly convex active constraint: a single maximiser
        unique = True
    if not sol.ok:
        return _Strongest(False, 0.0, np.zeros(n), (), solver, iters, sol.status, False)
    tau = sol.z[:n]
    return _Strongest(True, float(ell @ tau), tau, sol.binding, solver, iters, sol.status,
                      unique)


def _least_slip(model, query, cfg, lam_lo, equal):
    """min tau^T Xi tau s.t. lam_c >= lam_lo (== if equal), limits, wheels sticking."""
    n = cfg.N.shape[0]
    if query.radius is None and _COLD.get() is None:  # box only: posed directly in tau
        sol = solve_box_push(model, query, cfg, lam_lo=lam_lo, equal=equal)
        if sol is not None:
            return sol, sol.solver, sol.iterations
    prob = push_problem(model, query, cfg, lam_lo=lam_lo, equal=equal)
    sol = solve_conic(prob)
    solver, iters = sol.solver, sol.iterations
    if sol.ok and not inside(query, cfg, sol.z[:n]):
        sol = solve_ellipsoid(query, cfg, prob, sol.z[:n] @ cfg.N @ sol.z[:n])
        solver = sol.solver
        iters += sol.iterations
    return sol, solver, iters


def least_slip_push(model, query, cfg) -> Answer:
    n = cfg.N.shape[0]
    lam_lo, equal, gain, structural = push_target(query, cfg)
    if structural is not None:
        reason, binding = structural
        return Answer(np.zeros(n), "infeasible", reason, binding, "structure", 0, None)
    sol, solver, iters = _least_slip(model, query, cfg, lam_lo, equal)
    if sol.ok:
        tau = sol.z[:n]
        return Answer(tau, "optimal", "", sol.binding, solver, iters, float(tau @ cfg.Xi @ tau),
                      claim=("push", lam_lo, equal, False))
    # diagnose: the strongest push the limits allow, and what limits it
    st = _strongest_lam(model, query, cfg)
    iters += st.iterations
    lam_max, tau, binding, solver2 = st.lam, st.tau, st.binding, st.solver
    if not st.ok:
        return Answer(np.zeros(n), "failed", f"solver failure: {sol.status}; {st.status}", (),
                      solver, iters, None)
    if lam_max >= lam_lo * (1 - 1e-7):
        return Answer(np.zeros(n), "failed",
                      f"solver failure ({sol.status}) although the task is within reach",
                      (), solver, iters, None)
    want = np.linalg.norm(query.a_obj) if query.a_obj is not None else query.a_min
    what = "|a_obj|" if query.a_obj is not None else "the acceleration along d"
    names = ", ".join(binding) if binding else "the limits"
    reason = (f"{what} must reach {want:.6g} m/s^2 but is at most {gain * lam_max:.6g} m/s^2 "
              f"within the limits with every wheel sticking; binding: {names}")
    return Answer(tau, "infeasible", reason, binding, f"{solver}; diagnosis {solver2}", iters,
                   None)


def strongest_push(model, query, cfg) -> Answer:
    n = cfg.N.shape[0]
    if query.direction is None:
        # default: straight along the contact normal
        query = Query(query.objective, query.tau_max, query.radius,
                      cfg.a_dir / max(np.linalg.norm(cfg.a_dir), 1e-300), None, None,
                      query.slide)
    _, _, gamma, structural = push_target(query, cfg)
    if structural is not None:
        reason, binding = structural
        return Answer(np.zeros(n), "infeasible", reason, binding, "structure", 0, 0.0)
    st = _strongest_lam(model, query, cfg)
    lam_max, tau, binding, solver, iters = st.lam, st.tau, st.binding, st.solver, st.iterations
    if not st.ok:
        return Answer(tau, "failed", f"solver failure: {st.status}", (), solver, iters, None)
    if lam_max <= 0:
        return Answer(np.zeros(n), "infeasible",
                      "no torque within the limits pushes the object along d without a wheel "
                      f"sliding; binding: {', '.join(binding) or 'the limits'}", binding,
                      solver, iters, 0.0)
    # ties (a degenerate LP optimum): among the strongest pushes, the least snake motion
    if not st.unique:
        sol, s2, it2 = _least_slip(model, query, cfg, lam_max * (1 - 1e-9), False)
        iters += it2
        if sol.ok:
            tau = sol.z[:n]
            solver += f"; least-slip tie-break {s2}"
    return Answer(tau, "optimal", "", binding, solver, iters, float(gamma * (cfg.L[0] @ tau)),
                  claim=("push", None, False, True))


