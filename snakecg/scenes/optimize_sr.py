"""``max_sr`` on a general scene where no fixed force acts (no object's own ground friction):
the exact optimum with every link's set sticking (see :mod:`snakecg.scenes.optimize`)."""

from __future__ import annotations

import numpy as np

from .extremes import FEAS_TOL, MOTION_FLOOR, best_on_pieces, piece_faces, quadratics
from .maps import state_maps, whitening
from .optimize_task import MARGIN, contact_states, gauge
from .extremes_coulomb import piece_conditions

__all__ = ["max_sr_exact", "motionless", "scale_to_limits"]

#: Dinkelbach's iteration stops when the ratio gains less than this (sr is in [0, 1]).
SR_GAIN = 1e-14


def scale_to_limits(p, roles, task, tau, lam_from_tau) -> float:
    """The largest ``t`` with ``t tau`` inside the region and every link's set sticking (the
    forces ``t lam_from_tau tau`` within their sets)."""
    t = np.inf
    if task["radius"] is not None:
        t = min(t, task["radius"] / np.sqrt(max(tau @ p.N @ tau, 1e-300)))
    if task["tau_max"] is not None:
        big = np.abs(tau) > 0
        t = min(t, float(np.min(task["tau_max"][big] / np.abs(tau[big]), initial=np.inf)))
    lam = lam_from_tau @ tau
    for b, ((role, zero), k, par) in enumerate(zip(roles, p.kind, p.par)):
        if role != "contact" and not zero:
            g = gauge(k, par, lam[p.start[b]:p.start[b] + 2])
            if g > 0:
                t = min(t, 1.0 / g)
    return t


def motionless(f) -> bool:
    """Whether nothing moves on a state for any torque: its motion ``|a_o|^2 + |qdd_s|^2``
    (the quadratic forms ``f`` of :func:`~snakecg.scenes.extremes.quadratics`, whitened
    torques: the free motion's is 1) below :data:`MOTION_FLOOR`."""
    return np.linalg.eigvalsh(f["norm_a_obj"][0] + f["norm_qdd"][0]).max() <= MOTION_FLOOR


def max_sr_exact(p, roles, task):
    """``(tau, certificate)``: the largest sr with every link's set sticking, or ``(None,
    certificate)`` when no torque moves an object."""
    T = whitening(p)
    states = contact_states(p, roles)
    conds, forms, lams, pieces = [], [], [], []
    locked = 0
    for st in states:
        mp = state_maps(p, st)
        f = quadratics(p, mp, T, ())
        # a state on which nothing moves (the sticking sets lock the snake and the objects):
        # sr is 0 there by its convention, not a ratio of rounding errors; left out
        if motionless(f):
            locked += 1
            continue
        # the contacts' conditions (no fixed force: homogeneous, a cone)
        C, _ = piece_conditions(p, mp, st, T, FEAS_TOL, ground=False)
        if C is None:
            continue
        conds.append(C)
        forms.append(f)
        lams.append(mp["lam_from_tau"])
        pieces.append([int(c) for c in st])
    cert = {"kind": "Dinkelbach on the KKT points of every contact state's cone (every "
                    "link's set sticking)", "states": len(states), "locked": locked,
            "rounds": 0, "ok": False, "value": 0.0}
    if not conds:
        cert["reason"] = ("with every link's set sticking nothing moves (the sets lock the "
                          "snake): no sticking torque moves an object")
        return None, cert
    faces = piece_faces(conds, p.n_a)

    def ratio(i, u):  # u on the unit sphere: the free motion's norm is 1
        Ao, Aq = forms[i]["norm_a_obj"][0], forms[i]["norm_qdd"][0]
        om, D = u @ Ao @ u, u @ (Ao + Aq) @ u
        return om / D if D > MOTION_FLOOR else 0.0

    t, best, rounds = 0.0, None, 0
    for rounds in range(1, 61):
        comb = [tuple(f["norm_a_obj"][j] - t * (f["norm_a_obj"][j] + f["norm_qdd"][j])
                      for j in range(3)) for f in forms]
        _, u, i = best_on_pieces(conds, comb, faces, 1)
        if u is None:
            break
        r = ratio(i, u)
        if best is not None and not r > t + SR_GAIN:
            break
        t, best = max(r, t), (i, u)
    cert.update(rounds=rounds, ok=best is not None, value=float(t))
    if best is None or not t > 0:
        cert["reason"] = "no torque within the limits moves an object with every link sticking"
        return None, cert
    i, u = best
    cert["piece"] = pieces[i]
    tau = T @ u
    s = scale_to_limits(p, roles, task, tau, lams[i])
    return tau * s * (1 - MARGIN), cert
