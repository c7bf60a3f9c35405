"""The push tasks (and ``max_sr`` with objects sliding on the ground) of a general scene, piece
by piece, by IPOPT through CasADi (see :mod:`snakecg.scenes.optimize`).

On a piece, with the objects' sliding directions ``theta_b`` as variables, every quantity
is ``X(tau, theta) = X_tau tau + X_0 + sum_b (cos theta_b C_b + sin theta_b S_b)``: the maps
of :mod:`snakecg.scenes.maps` with the sliding forces superposed (they enter linearly)."""

from __future__ import annotations

import numpy as np

from .extremes import quadratics
from .extremes_coulomb import contact_conditions, force_family
from .maps import state_maps, whitening
from .optimize_sr import motionless
from .optimize_task import IPOPT_TOL, MARGIN, contact_states
from .solve import BOX, DISC, HELD, SLIDE, SPLIT, UNILATERAL, ZERO

__all__ = ["solve_pieces"]

#: A condition constant on a piece holds within this (relative to its value, plus absolute).
CONSTANT_TOL = 1e-9

_SUCCESS = ("Solve_Succeeded",)
_INFEASIBLE = ("Infeasible_Problem_Detected",)
_ACCEPTABLE = ("Solved_To_Acceptable_Level",)


def _affine(p, st):
    """``{name: (X_tau, X_0, [(C_b, S_b)])}`` for ``a`` (qdd and objects), ``lam`` and ``w``
    of state ``st`` (sliding blocks superposed)."""
    slides = [b for b, c in enumerate(st) if c == SLIDE]
    base = [ZERO if c == SLIDE else c for c in st]
    m0 = state_maps(p, base)

    def vec(mp):
        return {"a": np.r_[mp["qdd_offset"], mp["a_obj_offset"].ravel()],
                "lam": mp["lam_offset"], "w": mp["w_offset"]}

    def mat(mp):
        return {"a": np.vstack([mp["qdd_from_tau"],
                                mp["a_obj_from_tau"].reshape(3 * p.n_o, p.n_a)]),
                "lam": mp["lam_from_tau"], "w": mp["w_from_tau"]}

    v0, X = vec(m0), mat(m0)
    extra = {k: [] for k in v0}
    for b in slides:
        st_b = list(base)
        st_b[b] = SLIDE
        vc = vec(state_maps(p, st_b, {b: 0.0}))
        vs = vec(state_maps(p, st_b, {b: np.pi / 2}))
        for k in v0:
            extra[k].append((vc[k] - v0[k], vs[k] - v0[k]))
    # a family of forces (a box flush on a link, both corners sticking): lam + Z z
    Z = force_family(p, m0)[0] if not slides else np.zeros((len(v0["lam"]), 0))
    return {k: (X[k], v0[k], extra[k]) for k in v0}, slides, Z


def _build(p, roles, task, st, start, relax=0.0):
    import casadi as ca

    aff, slides, Z = _affine(p, st)
    opti = ca.Opti()
    tau = opti.variable(p.n_a)
    th = opti.variable(len(slides)) if slides else None

    def ex(name):
        X, x0, extra = aff[name]
        out = ca.mtimes(ca.DM(X), tau) + ca.DM(x0)
        for i, (C, S) in enumerate(extra):
            out = out + ca.cos(th[i]) * ca.DM(C) + ca.sin(th[i]) * ca.DM(S)
        return out

    empty = []  # a condition constant in the unknowns that fails: the piece has no point

    def sub(g, lo=0.0, eq=None):
        """``g >= lo`` (or ``g == eq``); Opti takes no constant condition: one that does not
        depend on the unknowns on this piece (a contact force 0 whatever the torque, a push
        the held object cannot make) is checked here instead."""
        if not g.is_constant():
            opti.subject_to(g == eq if eq is not None else g >= lo)
            return
        v = np.asarray(g if isinstance(g, ca.DM) else ca.evalf(g), float).ravel()
        gap = np.abs(v - np.ravel(eq)) if eq is not None else lo - v
        if np.any(gap > CONSTANT_TOL * (1.0 + np.abs(v))):
            empty.append(True)

    a, lam, w = ex("a"), ex("lam"), ex("w")
    if Z.shape[1]:  # the forces' free directions: any member of the family will do
        lam = lam + ca.mtimes(ca.DM(Z), opti.variable(Z.shape[1]))
    keep = 1 - MARGIN
    for b, (code, (role, zero), k, par) in enumerate(zip(st, roles, p.kind, p.par)):
        r = p.start[b]
        if k == UNILATERAL:  # Coulomb's conditions where the contact has friction
            lin = {"lam": lam, "w": w}
            for terms in contact_conditions(p, b, code):
                sub(sum(c * lin[key][i] for key, i, c in terms))
        elif code == HELD and not zero and k == BOX:
            sub(lam[r], -par[0] * keep)
            sub(-lam[r], -par[0] * keep)
        elif code == HELD and not zero and k == DISC:
            sub((par[0] * keep) ** 2 - lam[r] ** 2 - lam[r + 1] ** 2)
        elif code == HELD and not zero and k == SPLIT:
            s = opti.variable()
            opti.subject_to(s >= 0)
            for sgn, semi in ((1.0, par[1]), (-1.0, par[0])):
                if semi > 0:
                    opti.subject_to(s >= sgn * lam[r] / semi)
                else:
                    sub(-sgn * lam[r])
            opti.subject_to(s ** 2 + (lam[r + 1] / par[2]) ** 2 <= keep ** 2)
        elif code == SLIDE:  # the object slides against its friction: a_lin = -s (cos, sin)
            i = slides.index(b)
            j = p.rows.labels[b][1]
            ax, ay = a[p.n_s + 3 * j], a[p.n_s + 3 * j + 1]
            c, sn = ca.cos(th[i]), ca.sin(th[i])
            opti.subject_to(ax * sn - ay * c == 0)
            opti.subject_to(ax * c + ay * sn <= 0)
    if task["radius"] is not None:
        opti.subject_to(ca.bilin(ca.DM(p.N), tau, tau) <= task["radius"] ** 2)
    if task["tau_max"] is not None:
        opti.subject_to(opti.bounded(-ca.DM(task["tau_max"]), tau, ca.DM(task["tau_max"])))
    j = task["object"] - 1
    ao = a[p.n_s + 3 * j:p.n_s + 3 * j + 3]
    qdd = a[:p.n_s]
    norm_qdd = ca.bilin(ca.DM(p.M_s), qdd, qdd)
    if task["objective"] == "least_slip_push":
        if task["a_obj"] is not None and not slides:  # on the range of the torque's map
            _equal_on_range(sub, ao, aff["a"][0][p.n_s + 3 * j:p.n_s + 3 * j + 3],
                            aff["a"][1][p.n_s + 3 * j:p.n_s + 3 * j + 3],
                            np.asarray(task["a_obj"], float))
        elif task["a_obj"] is not None:
            sub(ao, eq=np.asarray(task["a_obj"], float))
        else:
            sub(ca.dot(ca.DM(task["direction"]), ao), task["a_min"])
        f = norm_qdd
    elif task["objective"] == "strongest_push":
        f = -ca.dot(ca.DM(task["direction"]), ao)
    else:
        om = 0
        for jj in range(p.n_o):
            aj = a[p.n_s + 3 * jj:p.n_s + 3 * jj + 3]
            Ij = p.M[p.n_s + 3 * jj:p.n_s + 3 * jj + 3, p.n_s + 3 * jj:p.n_s + 3 * jj + 3]
            om = om + ca.bilin(ca.DM(Ij), aj, aj)
        # sr is 0/0 where nothing moves: the ratio is taken where the motion is above a
        # floor (1e-8 of the free motion's largest norm in the region)
        free = task["radius"] ** 2 if task["radius"] is not None else float(
            task["tau_max"] @ np.abs(p.N) @ task["tau_max"])
        sub(om + norm_qdd, 1e-8 * free)
        f = -om / (om + norm_qdd)
    opti.minimize(f)
    tau0, th0 = start
    opti.set_initial(tau, tau0)
    if slides:
        opti.set_initial(th, th0[:len(slides)])
    # a push that no torque changes on this piece (the object held by the others): its value
    # is a constant, exact wherever the piece is feasible
    Xa = aff["a"][0][p.n_s + 3 * j:p.n_s + 3 * j + 3]
    constant = (task["objective"] == "strongest_push" and not slides
                and np.abs(task["direction"] @ Xa).max() <= 1e-12 * max(1.0, np.abs(Xa).max()))
    opti.solver("ipopt", {"print_time": False, "ipopt.print_level": 0, "ipopt.sb": "yes",
                          "ipopt.tol": IPOPT_TOL, "ipopt.max_iter": 1000,
                          "ipopt.bound_relax_factor": relax})
    return opti, tau, f, bool(slides), constant, bool(empty)


def _equal_on_range(sub, x, X, x0, target):
    """``x = X tau + x0 == target`` as ``rank X`` equations in ``tau`` (the rows of ``X``'s
    range, by its SVD) and the rest, which no torque changes, checked as constants: a full
    object acceleration asked of fewer joints than its three entries is otherwise an
    overconstrained NLP (IPOPT has too few degrees of freedom, CasADi warns at every
    build)."""
    import casadi as ca

    U, S, _ = np.linalg.svd(X)
    r = int(np.sum(S > 1e-12 * S.max())) if S.size and S.max() > 0 else 0
    if r:
        sub(ca.mtimes(ca.DM(U[:, :r].T), x - ca.DM(target)), eq=np.zeros(r))
    if r < len(target):
        sub(ca.DM(U[:, r:].T @ (x0 - target)), eq=np.zeros(len(target) - r))


def _starts(p, task, st, rng):
    """Initial points: a small torque along each axis (convex pieces: one is enough), and
    sliding directions against the push (or around the circle)."""
    n_sl = sum(1 for c in st if c == SLIDE)
    d = task["direction"]
    base = -np.arctan2(d[1], d[0]) if d is not None else 0.0
    scale = 1e-3 if task["radius"] is None else 1e-3 * task["radius"]
    t0 = np.linalg.solve(np.linalg.cholesky(p.N).T, rng.normal(size=p.n_a)) * scale
    if n_sl == 0:  # convex: the second start only where IPOPT does not finish the first
        return [(t0, np.zeros(0)), (-10 * t0, np.zeros(0))]
    return [(t0, np.full(n_sl, base + np.pi + off)) for off in (0.0, np.pi / 2, -np.pi / 2)]


#: An object sliding on the ground is tried in each of SECTORS sectors of its direction.
SECTORS = 8
#: Pieces with more objects sliding are not relaxed (SECTORS ** k linear programs).
MAX_SLIDES_RELAXED = 2


def _lp_empty(p, task, st) -> bool:
    """Whether a relaxation of the piece has no point, by linear programs (HiGHS): the linear
    conditions in ``(tau, z, c, s)`` (the contacts', the bounded wheels' bounds, the push's
    ``d . a_o >= a_min`` or ``a_o = a_obj``, the torque box), with the ellipsoid widened to
    its bounding box and each sticking set to a polygon around it (a disc to its octagon, a
    split ellipse to its box). An object sliding on the ground (``(c, s) = (cos theta, sin
    theta)``, its acceleration along ``-(c, s)``) is tried in each of :data:`SECTORS`
    sectors of ``theta``: ``(c, s)`` in the hull of the sector's arc, its acceleration in the
    opposite sector (one LP per sector, per pair of sectors for two objects). Every
    relaxation contains the piece; where all of them are empty, so is the piece: where IPOPT
    cannot tell (a piece without interior, a non-convex piece), this says infeasible."""
    import itertools

    from scipy.optimize import linprog

    aff, slides, Z = _affine(p, st)
    if len(slides) > MAX_SLIDES_RELAXED:
        return False
    na, nz, k = p.n_a, Z.shape[1], len(slides)
    nx = na + nz + 2 * k

    def lin(name):  # quantity = X x + x0 in x = (tau, z, c_1, s_1, ..)
        X, x0, extra = aff[name]
        cols = [X, Z if name == "lam" else np.zeros((len(x0), nz))]
        for C, S in extra:
            cols += [C[:, None], S[:, None]]
        return np.hstack(cols), x0

    forms = {"lam": lin("lam"), "w": lin("w")}
    Xa, a0 = lin("a")
    G, h = [], []  # G x + h >= 0
    for b, code in enumerate(st):
        kd, r, par = p.kind[b], p.start[b], p.par[b]
        if kd == UNILATERAL:
            for terms in contact_conditions(p, b, code):
                G.append(sum(c * forms[key][0][i] for key, i, c in terms))
                h.append(sum(c * forms[key][1][i] for key, i, c in terms))
            continue
        if code != HELD or (kd not in (BOX, DISC, SPLIT)) or max(par) <= 0:
            continue
        (Xl, l0) = forms["lam"]
        if kd == BOX:  # |lam| <= par[0]
            rows = [(np.array([1.0]), par[0]), (np.array([-1.0]), par[0])]
        elif kd == DISC:  # the octagon around the disc: |u . lam| <= par[0] on 8 axes
            rows = [(np.array(u), par[0]) for u in ((1, 0), (-1, 0), (0, 1), (0, -1))]
            rows += [(np.array(u) / np.sqrt(2), par[0]) for u in ((1, 1), (1, -1), (-1, 1),
                                                                  (-1, -1))]
        else:  # the split ellipse's box: -par[0] <= lam_t <= par[1], |lam_n| <= par[2]
            rows = [(np.array([1.0, 0.0]), par[1]), (np.array([-1.0, 0.0]), par[0]),
                    (np.array([0.0, 1.0]), par[2]), (np.array([0.0, -1.0]), par[2])]
        for u, bound in rows:  # bound - u . lam >= 0
            G.append(-(u @ Xl[r:r + len(u)]))
            h.append(bound - u @ l0[r:r + len(u)])
    j = task["object"] - 1
    Xo, ao0 = Xa[p.n_s + 3 * j:p.n_s + 3 * j + 3], a0[p.n_s + 3 * j:p.n_s + 3 * j + 3]
    eq = None
    if task["objective"] == "least_slip_push":
        if task["a_obj"] is not None:
            eq = (Xo, task["a_obj"] - ao0)
        else:
            G.append(task["direction"] @ Xo)
            h.append(task["direction"] @ ao0 - task["a_min"])
    hi = np.full(na, np.inf)
    if task["radius"] is not None:  # the ellipsoid's bounding box
        hi = task["radius"] * np.sqrt(np.diag(np.linalg.inv(p.N)))
    if task["tau_max"] is not None:
        hi = np.minimum(hi, task["tau_max"])
    bounds = [(-v, v) for v in hi] + [(None, None)] * nz + [(-1.0, 1.0)] * (2 * k)
    half = np.pi / SECTORS
    for sectors in itertools.product(range(SECTORS), repeat=k):
        G2, h2 = list(G), list(h)
        for i, (b, sec) in enumerate(zip(slides, sectors)):
            cs = na + nz + 2 * i  # the columns of (c, s)
            o = p.n_s + 3 * p.rows.labels[b][1]  # the object's linear acceleration
            lo, mid, up = (2 * sec) * half, (2 * sec + 1) * half, (2 * sec + 2) * half
            for ang, sg in ((lo, 1.0), (up, -1.0)):  # (c, s) inside the wedge [lo, up]
                e = np.zeros(nx)
                e[cs], e[cs + 1] = -sg * np.sin(ang), sg * np.cos(ang)
                G2.append(e)
                h2.append(0.0)
                # the acceleration in the opposite wedge: -a inside [lo, up]
                G2.append(-(-sg * np.sin(ang) * Xa[o] + sg * np.cos(ang) * Xa[o + 1]))
                h2.append(-(-sg * np.sin(ang) * a0[o] + sg * np.cos(ang) * a0[o + 1]))
            e = np.zeros(nx)  # beyond the arc's chord: c cos(mid) + s sin(mid) >= cos(half)
            e[cs], e[cs + 1] = np.cos(mid), np.sin(mid)
            G2.append(e)
            h2.append(-np.cos(half))
        A = np.array(G2).reshape(-1, nx)
        res = linprog(np.zeros(nx), A_ub=-A if len(A) else None,
                      b_ub=np.array(h2) if len(A) else None,
                      A_eq=None if eq is None else eq[0], b_eq=None if eq is None else eq[1],
                      bounds=bounds, method="highs")
        if res.status != 2:  # a point (or not proven empty): the piece may have one
            return False
    return True


def _locked(p, st) -> bool:
    """Whether nothing moves on piece ``st`` (no object sliding) for any torque
    (:func:`~snakecg.scenes.optimize_sr.motionless`), as
    :func:`~snakecg.scenes.optimize_sr.max_sr_exact` leaves such states out. ``max_sr``'s
    pieces ask for motion above 1e-8 of the free motion's: such a piece is empty (IPOPT
    cannot say so: its constraint is not convex)."""
    if any(c == SLIDE for c in st):
        return False
    return motionless(quadratics(p, state_maps(p, st), whitening(p), ()))


def solve_pieces(p, roles, task, sliding_objects, only_sliding=False):
    """``(tau, status, certificate)``: the best piece's torque; ``optimal`` where every piece
    is convex and solved or proven infeasible. ``only_sliding``: the pieces where an object
    slides on the ground alone (``max_sr``: the others are cones, solved exactly by
    :func:`~snakecg.scenes.optimize_sr.max_sr_exact`; IPOPT's absolute tolerances would
    take their ratio to torques near 0, where every condition holds within them)."""
    rng = np.random.default_rng(0)
    states = contact_states(p, roles, sliding_objects)
    if only_sliding:
        states = [st for st in states if any(c == SLIDE for c in st)]
    best, solved, infeasible, unknown, nonconvex = None, 0, 0, 0, False
    for st in states:
        if task["objective"] == "max_sr" and _locked(p, st):
            infeasible += 1  # nothing moves on it: below the task's motion floor
            continue
        outcome = None
        starts = _starts(p, task, st, rng)
        # a degenerate piece (no interior) may need IPOPT's own relaxation of the bounds
        # (1e-8): the last try; the forward solve checks the answer at the end
        tries = [(s0, 0.0) for s0 in starts] + [(starts[0], 1e-8)]
        for start, relax in tries:
            opti, tau, f, has_slide, constant, empty = _build(p, roles, task, st, start,
                                                              relax)
            nonconvex |= has_slide or task["objective"] == "max_sr"
            if empty:  # a condition that no torque changes fails on it
                outcome = "infeasible" if outcome in (None, "unknown") else outcome
                break
            try:
                sol = opti.solve()
                stat = sol.stats()["return_status"]
                val, t = float(sol.value(f)), np.atleast_1d(sol.value(tau)).astype(float)
            except RuntimeError:
                stat = opti.stats()["return_status"]
                val, t = np.inf, None
            if stat in _SUCCESS or (constant and stat in _ACCEPTABLE):
                outcome = "solved"
                if best is None or val < best[0]:
                    best = (val, t, st)
                if not has_slide and task["objective"] != "max_sr":
                    break  # a convex piece: its KKT point is its optimum
            elif stat in _INFEASIBLE and outcome in (None, "unknown"):
                outcome = "infeasible"
                if not has_slide:
                    break
            elif outcome is None:
                outcome = "unknown"
            if relax == 0.0 and outcome != "unknown" and start is starts[-1]:
                break
        if outcome == "unknown" and _lp_empty(p, task, st):
            outcome = "infeasible"  # IPOPT did not say, a relaxation's LPs prove it
        solved += outcome == "solved"
        infeasible += outcome == "infeasible"
        unknown += outcome == "unknown"
    cert = {"kind": "KKT of every piece (IPOPT)" + (", non-convex pieces (objects sliding "
                                                     "on the ground): local" if nonconvex
                                                     else ", convex pieces"),
            "states": len(states), "solved": solved, "infeasible": infeasible,
            "unknown": unknown, "ok": best is not None and not nonconvex and unknown == 0}
    if best is None:
        if unknown == 0:
            cert["reason"] = ("every piece is infeasible: no torque within the limits does "
                              "the task with every link's set sticking")
            return None, "infeasible", cert
        cert["reason"] = f"no piece solved ({unknown} not answered by IPOPT)"
        return None, "failed", cert
    value = best[0]
    cert["piece"] = [int(c) for c in best[2]]
    cert["value"] = {"least_slip_push": value, "strongest_push": -value,
                     "max_sr": -value}[task["objective"]]
    if cert["ok"]:
        return best[1], "optimal", cert
    cert["reason"] = ("pieces with an object sliding on the ground are not convex: a local "
                      "optimum" if nonconvex else f"{unknown} pieces not answered by IPOPT")
    return best[1], "local", cert
