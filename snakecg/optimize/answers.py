"""The compiled query's answers as :class:`~snakecg.optimize.OptimizeResult`: codes to names,
numbers to reasons. Nothing numeric happens here: the solve, the certificate, the forward
solve at the answer and its check all ran in C (:mod:`snakecg.engine.optimal`)."""

from __future__ import annotations

import functools
import math

import numpy as np

from ..engine.optimal import (CERTIFICATE, CHECK, INFEASIBLE, METHOD, OPTIMAL, QP_STATUS,
                            REASON)
from ..forward import ForwardResult
from ..rows import reason_of
from ..solver import FORCE_LIMIT
from .result import (CONTACT, ELLIPSOID, NORMAL, TOLERANCE, Certificate, OptimizeResult,
                     joint_name, wheel_name)

__all__ = ["result"]

_STATUS = {OPTIMAL: "optimal", INFEASIBLE: "infeasible"}
_WHEEL = {0: "none", 1: "stick", 3: "slide+", 4: "slide-"}
_R = {v: k for k, v in REASON.items()}
_C = {v: k for k, v in CHECK.items()}
_RESIDUALS = ("stationarity", "primal_feasibility", "complementarity", "duality_gap")


@functools.lru_cache(maxsize=None)
def _fields(kernel):
    """Slices of the answer's fields and the binding names of this kernel's sizes."""
    na, nc = kernel.layout.n_joints, kernel.layout.n_constraints
    names = tuple([CONTACT, ELLIPSOID, NORMAL] + [joint_name(j + 1) for j in range(na)]
                  + [wheel_name(i) for i in range(1, nc)])
    off = {k: (o, o + s) for k, (o, s) in kernel.OUT.items()}
    return off, names


def _g(x):
    return f"{x:.4g}"


def _reason(query, row, off, binding, tol) -> str:
    code = _R[int(row[off["reason"][0]])]
    det = list(row[off["detail"][0]:off["detail"][1]])
    nrm = f"({_g(det[0])}, {_g(det[1])})"
    names = ", ".join(binding) if binding else "the limits"
    if code == "none":
        return ""
    if code == "singular":
        return ("dependent constraint rows at this configuration (singular Delassus matrix); "
                "the maps are not defined")
    if code == "no_push":
        return ("no torque accelerates the object at this configuration (sr = 0 for every "
                "torque)" if query.objective == "max_sr"
                else "no torque accelerates the object at this configuration")
    if code == "off_normal":
        a = query.a_obj
        return (f"a_obj = ({_g(a[0])}, {_g(a[1])}, {_g(a[2])}) is not reachable: the object can "
                f"only accelerate along the contact normal n = {nrm}, as a_obj = lam_c * "
                f"({_g(det[2])}, {_g(det[3])}, {_g(det[4])}) with lam_c >= 0")
    if code == "against_normal":
        return (f"a_obj points against the contact normal n = {nrm}: it would need a pulling "
                f"contact force; {CONTACT}")
    if code == "direction":
        d = query.direction if query.direction is not None else np.array(det[2:5])
        return (f"no torque accelerates the object along d = ({_g(d[0])}, {_g(d[1])}, "
                f"{_g(d[2])}): the contact pushes only along its normal n = {nrm} and "
                f"d . n <= 0; {CONTACT}")
    if code == "out_of_reach":
        what = "|a_obj|" if query.a_obj is not None else "the acceleration along d"
        return (f"{what} must reach {det[6]:.6g} m/s^2 but is at most {det[7]:.6g} m/s^2 "
                f"within the limits with every wheel sticking; binding: {names}")
    if code == "no_strong_push":
        return ("no torque within the limits pushes the object along d without a wheel "
                f"sliding; binding: {names}")
    if code == "solver":
        return f"solver failure: {QP_STATUS.get(int(det[5]), 'unknown')}"
    if code == "within_reach":
        return (f"solver failure ({QP_STATUS.get(int(det[5]), 'unknown')}) although the task "
                f"is within reach")
    if code == "certificate":
        kind = CERTIFICATE[int(row[off["certificate"][0]])]
        again = (" after the general eigenproblem" if row[off["resolved"][0]] else "")
        return f"optimality certificate ({kind}) fails{again}: {_residuals(row, off, tol)}"
    if code == "not_finite":  # the forward solve at zero torque's reason, when it has one
        why = reason_of(det[1])
        return why or (f"the optimizer's torque is not finite or beyond +-{FORCE_LIMIT:.0e} "
                       f"(max |tau| = {det[0]:.3g}): the configuration is too ill-conditioned "
                       f"to answer")
    if code == "unanswerable":
        return reason_of(det[1]) or ("the system at this configuration is not usable in "
                                     "float64 (a non-finite map): no answer")
    if code == "no_answer":
        return reason_of(det[1])
    return f"forward check: {_check(query, row, off)}"


def _residuals(row, off, tol) -> str:
    """The residuals out of their tolerances (``tol``: the four, in the order of
    ``_RESIDUALS``, as the compiled call used them)."""
    bad = []
    for name, t in zip(_RESIDUALS, tol):
        v = float(row[off[name][0]])
        if not math.isnan(v) and not abs(v) <= t:
            bad.append(f"{name} {v:.3g} > {t:.0e}")
    return "; ".join(bad)


def _check(query, row, off) -> str:
    code = _C[int(row[off["check"][0]])]
    c = list(row[off["check_detail"][0]:off["check_detail"][1]])
    if code == "tau_max":
        return f"|tau_{int(c[0]) + 1}| = {c[1]:.6g} exceeds tau_max = {c[2]:.6g}"
    if code == "ellipsoid":
        return f"tau^T N tau = {c[0]:.6g} exceeds radius^2 = {c[1]:.6g}"
    if code == "separates":
        return "the contact separates at tau"
    if code == "slides":
        return (f"the wheel on link {int(c[0])} slides ({_WHEEL[int(c[1])]}) although the "
                f"optimiser kept it within its friction bound")
    if code == "objective":
        return (f"objective {c[0]:.9g} from the forward solve differs from the optimiser's "
                f"{c[1]:.9g}")
    if code == "a_obj":
        return f"a_obj misses the requested {query.a_obj.tolist()} by {c[0]:.3g}"
    return f"d . a_obj = {c[0]:.6g} < a_min = {c[1]:.6g}"


def _solver(row, off) -> str:
    return _describe(int(row[off["method"][0]]), int(row[off["states"][0]]),
                     int(row[off["states_solved"][0]]), int(row[off["qp_solves"][0]]),
                     int(row[off["newton_steps"][0]]))


@functools.lru_cache(maxsize=4096)
def _describe(m, states, solved, qps, newton) -> str:
    """The methods of flags ``m`` (and the counts of the sliding-wheel search) in words."""
    if m & (METHOD["rank_one"] | METHOD["eigen"]):
        text = ("generalized eigenproblem (rank-one closed form)" if m & METHOD["rank_one"]
                else "generalized eigenproblem (Jacobi rotations)")
        if m & METHOD["states"]:
            text += f"; {states} sliding wheel states: {solved} solved, {qps} QPs"
            if m & METHOD["scale"]:
                text += f", the ellipsoid by its multiplier ({newton} Newton steps)"
        return text
    parts = []
    if m & METHOD["closed_ellipsoid"]:
        parts.append("closed form (ellipsoid)")
    if m & (METHOD["qp"] | METHOD["lp"]):
        kinds = [k for k in ("qp", "lp") if m & METHOD[k]]
        text = "dual active set" + (" (LP)" if kinds == ["lp"] else " (QP, LP)"
                                    if len(kinds) == 2 else "")
        if m & METHOD["secular"]:
            text += ", ellipsoid multiplier (secular equation)"
        parts.append(text)
    if m & METHOD["tie_break"]:
        parts.append("least-slip tie-break")
    if m & METHOD["diagnosis"]:
        parts.append("diagnosis by the strongest push")
    return "; ".join(parts) or "structure"


_CERT_FIELDS = ("certificate", "certified", "stationarity", "primal_feasibility",
                "complementarity", "duality_gap", "resolved")


def _certificate(row, off, status, tol) -> Certificate:
    return _certificate_of([row[off[k][0]] for k in _CERT_FIELDS], status, tol)


def _certificate_of(fields, status, tol) -> Certificate:
    """The certificate of the answer's fields (kind, certified, the four residuals,
    resolved)."""
    kind, ok, st, pf, co, gap, resolved = fields
    kind = CERTIFICATE[int(kind)]
    if kind == "none":
        return Certificate("none", False, reason=f"no optimality claim: {status}")
    ok = bool(ok)
    gap = None if math.isnan(gap) else gap
    reason = ""
    if not ok:
        reason = "; ".join(f"{name} {v:.3g} > {t:.0e}" for name, v, t in zip(
            _RESIDUALS, (st, pf, co, gap), tol) if v is not None and not abs(v) <= t)
    return Certificate(kind, ok, st, pf, co, gap, tol[0], bool(resolved), reason)


@functools.lru_cache(maxsize=4096)
def _names(names, codes) -> tuple:
    return tuple(names[c] for c in codes)


def _one(query, row, off, names, tol):
    """status, reason, binding, solver, iterations, certificate, wheel states of one answer
    (``row``: its fields before the forward row, as a list of floats)"""
    status = _STATUS.get(int(row[off["status"][0]]), "failed")
    b0 = off["binding"][0]
    binding = _names(names, tuple(int(c) for c in row[b0:b0 + int(row[off["n_binding"][0]])]))
    states = row[off["wheel_states"][0]:off["wheel_states"][1]]
    assumed = (None if states[0] < 0
               else np.array([_WHEEL[int(s)] for s in states[1:]]))
    return (status, _reason(query, row, off, binding, tol) if status != "optimal" else "",
            binding, _solver(row, off),
            int(row[off["qp_solves"][0]] + row[off["newton_steps"][0]]),
            _certificate(row, off, status, tol), assumed)


def result(model, query, kernel, out: np.ndarray, batched: bool, elapsed: float,
           tol=tuple(TOLERANCE[k] for k in _RESIDUALS)):
    """The :class:`OptimizeResult` of the answers ``out`` (one row per configuration);
    ``tol``: the certificate's tolerances the compiled call used."""
    off, names = _fields(kernel)
    f0, f1 = off["forward"]
    if not batched:
        row = out[0, :f0].tolist()
        status, reason, binding, solver, iters, cert, assumed = _one(query, row, off, names, tol)
        analysis = ForwardResult(out[0, f0:f1].copy(), model.columns)
        return OptimizeResult(
            objective=query.objective, tau=analysis.tau.copy(), status=status, reason=reason,
            objective_value=row[off["objective_value"][0]], binding=binding,
            analysis=analysis, solver=solver, iterations=iters, time=elapsed,
            wheel_states_assumed=assumed, certificate=cert)
    # a batch: the same per row, with the repeated patterns (statuses, binding limits,
    # methods) worded once each
    n = out.shape[0]
    code = out[:, off["status"][0]].astype(np.intp)
    status = np.array(["optimal", "infeasible", "failed"], dtype=object)[np.minimum(code, 2)]
    b0 = off["binding"][0]
    nb = out[:, off["n_binding"][0]].astype(np.intp)
    width = int(nb.max(initial=0))
    pattern = np.column_stack([nb, out[:, b0:b0 + width]]).astype(np.intp)
    uniq, inv = np.unique(pattern, axis=0, return_inverse=True)
    words = [_names(names, tuple(u[1:1 + u[0]].tolist())) for u in uniq]
    binding = [words[i] for i in inv.ravel().tolist()]
    how = out[:, [off[k][0] for k in ("method", "states", "states_solved", "qp_solves",
                                      "newton_steps")]].astype(np.int64)
    uniq, inv = np.unique(how, axis=0, return_inverse=True)
    words = [_describe(*u.tolist()) for u in uniq]
    solver = np.array(words, dtype=object)[inv.ravel()]
    reason = np.full(n, "", dtype=object)
    for i in np.flatnonzero(code != OPTIMAL).tolist():
        reason[i] = _reason(query, out[i, :f0].tolist(), off, binding[i], tol)
    fields = out[:, [off[k][0] for k in ("certificate", "certified", "stationarity",
                                         "primal_feasibility", "complementarity",
                                         "duality_gap", "resolved")]].tolist()
    certificate = [_certificate_of(f, st, tol) for f, st in zip(fields, status.tolist())]
    first_state = out[:, off["wheel_states"][0]]
    assumed = [None] * n
    for i in np.flatnonzero(first_state >= 0).tolist():
        assumed[i] = _one(query, out[i, :f0].tolist(), off, names, tol)[6]
    analysis = ForwardResult(np.ascontiguousarray(out[:, f0:f1]), model.columns)
    return OptimizeResult(
        objective=query.objective, tau=analysis.tau.copy(), status=status, reason=reason,
        objective_value=out[:, off["objective_value"][0]].copy(), binding=binding,
        analysis=analysis, solver=solver,
        iterations=(out[:, off["qp_solves"][0]] + out[:, off["newton_steps"][0]]).astype(int),
        time=np.full(n, elapsed / max(n, 1)), wheel_states_assumed=assumed,
        certificate=certificate)
