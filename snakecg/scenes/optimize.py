"""Optimal torques on a general scene (at rest): ``max_sr``, and ``least_slip_push`` /
``strongest_push`` of a chosen object, over the input region (the ellipsoid of eq. 31,
``tau^T N tau <= radius^2``, and/or the box ``|tau_j| <= tau_max_j``), with no ground set
of a link sliding (the paper's "every wheel sticking", on every ground model).

First, whether friction holds every torque of the region still
(:mod:`snakecg.scenes.friction_hold`: a friction set's size ``mu m g`` is constant, so the
torques it holds are not a cone): there nothing moves, every torque gives ``sr = 0`` (its
value where nothing moves) and ``d . a_o = 0``, so ``max_sr`` and ``strongest_push`` are
``optimal`` with 0 at the torque that needs the most friction, and ``least_slip_push`` is
``infeasible``.

The exact pieces: every contact held or open, every link's wheel or friction set sticking,
each object's own ground friction sticking or sliding. On a piece the maps are affine
(:mod:`snakecg.scenes.maps`) and, where no object slides, the task is convex: a quadratic
(``least_slip_push``: ``||qdd_s||^2``, eq. 26) or linear (``strongest_push``: ``d . a_o``)
objective under linear (contacts, push, box), second-order-cone (Coulomb sets) and ellipsoid
constraints, solved by IPOPT through CasADi to its KKT tolerance. The best piece, with every
piece either solved or proven infeasible, is the optimum: status ``optimal``. An object that
slides on the ground pushes back along its sliding direction ``theta``, a variable of the
piece: the problem is no longer convex, solved from a few starts: status ``local``.

``max_sr``: ``sr`` (eq. 30) is homogeneous of degree 0 on a piece with no fixed force, and
the set of torques that keep every link's set sticking is star-shaped about 0, so its
maximum is the largest ratio on the cone of the contact state: Dinkelbach's iteration on the
KKT points of the cone's faces (as :mod:`snakecg.scenes.extremes`; with objects that may
slide on the ground, these are the pieces where every object sticks, and IPOPT takes the
others, :func:`_max_sr`), then the torque scaled to the largest that keeps every limit
(where the held rows are dependent, by bisection on the scale with the forward solve:
:func:`_sticking_scale`). A state on which nothing moves (the
sticking sets lock the snake) has no ratio (0/0) and is left out. ``allow_slide=True`` also
searches the region's boundary with the forward solve: status ``local`` where a sliding
torque beats the sticking optimum, else ``stick_only`` (the sticking answer, not certified
against sliding pieces).

Every answer is checked by the compiled forward solve at its torque (the objective to 1e-6,
no link's set sliding): a disagreement is status ``failed`` with the reason.

Contacts with Coulomb friction (``mu_contact``) give their pieces four states each (open,
stick, slip either way: :mod:`snakecg.scenes.extremes_coulomb`), with linear conditions:
the pushes stay convex, ``max_sr``'s pieces stay cones. Coulomb's law may have several
solutions at a torque; the optimum is over every solution at every torque. Where the
forward solve at the optimum's torque meets another solution than the optimum's piece, the
piece's own solution is checked apart (:func:`piece_objective`: its conditions at ``tau``)
and the answer keeps its status with ``uniqueness`` ``several`` and the reason giving both
values; where the piece does not hold there it is ``failed``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .._inputs import short_repr
from ..errors import InputError
from ..limits import describe, resolve_tau_max
from .extremes import MOTION_FLOOR
from .friction_hold import friction_holds
from .extremes_coulomb import piece_conditions
from .maps import scene_problem, state_maps, whitening
from .metrics import state_name
from .optimize_pieces import solve_pieces
from .optimize_search import search
from .optimize_sr import max_sr_exact
from .optimize_task import CHECK_TOL, MARGIN, gauge
from .optimize_task import roles as block_roles
from .solve import DISC, FREE, HELD, SLIDE, SLIDE_NEG, SLIDE_POS, SPLIT, UNILATERAL, ZERO

__all__ = ["OBJECTIVES", "STATUSES", "SceneOptimizeResult", "optimize", "objective_of",
           "binding"]

OBJECTIVES = ("max_sr", "least_slip_push", "strongest_push")
STATUSES = ("optimal", "stick_only", "local", "infeasible", "failed")
#: A piece's conditions hold at a torque within this, in whitened torques (relative to their
#: size; the optimum lies on their boundary, solved by IPOPT to 1e-10).
PIECE_TOL = 1e-7


@dataclass
class SceneOptimizeResult:
    """The answer of :func:`optimize`: ``tau`` (n_a), ``status`` (:data:`STATUSES`),
    ``reason``, ``objective_value`` (sr, ``||qdd_s||^2`` or ``d . a_o``, read from the
    forward solve), ``object`` (1-based), ``binding`` (limits active at ``tau``),
    ``analysis`` (the forward :class:`~snakecg.scenes.metrics.SceneResult` at ``tau``),
    ``solver``, ``certificate`` (what was checked), ``limits``. With contact friction
    (``mu_contact``), ``uniqueness`` and ``solutions``: the forward solve's at ``tau``
    (:class:`~snakecg.scenes.metrics.SceneResult`), ``uniqueness`` ``several`` also where the
    optimum's own piece is a solution other than the forward solve's (the objective value is
    then the piece's, the reason says so); None on a scene without contact friction."""

    objective: str
    tau: np.ndarray
    status: str
    reason: str
    objective_value: float
    object: int
    binding: list
    analysis: object
    solver: str
    certificate: dict = field(default_factory=dict)
    limits: dict = field(default_factory=dict)
    uniqueness: object = None
    solutions: object = None

    @property
    def ok(self) -> bool:
        return self.status == "optimal"

    def to_dict(self) -> dict:
        """JSON-ready (no NaN: a missing value is None)."""
        def num(x):
            x = float(x)
            return x if np.isfinite(x) else None

        an = self.analysis.to_dict() if self.analysis is not None else None
        return {"objective": self.objective, "object": self.object, "status": self.status,
                "reason": self.reason, "objective_value": num(self.objective_value),
                "tau": [num(t) for t in self.tau], "binding": list(self.binding),
                "solver": self.solver, "certificate": self.certificate,
                "limits": self.limits, "analysis": an,
                **({"uniqueness": self.uniqueness, "solutions": self.solutions}
                   if self.uniqueness is not None else {})}


def _vector(name, v, sizes, what):
    try:
        arr = np.asarray(v, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InputError(f"{name} must be {what}, got {short_repr(v)}") from None
    if arr.size not in sizes or not np.all(np.isfinite(arr)):
        raise InputError(f"{name} must be {what}, got {short_repr(v)}")
    return arr


def _validate(model, objective, obj, tau_max, radius, direction, a_min, a_obj, allow_slide):
    na, no = model.n_joints, model.scene.n_objects
    problems = []
    if objective not in OBJECTIVES:
        raise InputError(f"objective must be one of {', '.join(OBJECTIVES)}, got "
                         f"{short_repr(objective)}")
    if no == 0:
        raise InputError(f"{objective} needs an object in the scene (sr and the pushes are "
                         f"about objects); this scene has none")
    if isinstance(obj, bool) or not isinstance(obj, (int, np.integer)) or not 1 <= obj <= no:
        problems.append(f"object must be an object number 1..{no}, got {short_repr(obj)}")
    tm, source = resolve_tau_max(model.robot, tau_max)
    if tm is not None:
        tm = _vector("tau_max", tm, (1, na), f"one positive number or {na} (N m per joint)")
        if np.any(tm <= 0):
            problems.append(f"tau_max must be > 0 (N m), got {short_repr(tau_max)}")
        tm = np.broadcast_to(tm, (na,)).copy()
    if radius is not None and not (isinstance(radius, (int, float, np.floating)) and
                                   not isinstance(radius, bool) and np.isfinite(radius)
                                   and radius > 0):
        problems.append(f"radius must be a number > 0 (eq. 31), got {short_repr(radius)}")
    if tm is None and radius is None:
        radius = 1.0
    d = None
    if direction is not None:
        d = _vector("direction", direction, (2, 3), "dx,dy or dx,dy,dalpha (not all 0)")
        if not np.any(d):
            problems.append("direction must not be all 0")
        else:
            d = np.r_[d, 0.0][:3] / np.linalg.norm(d)
    target = None if a_obj is None else _vector("a_obj", a_obj, (3,), "(a_x, a_y, alpha)")
    if objective == "least_slip_push":
        if (target is None) == (d is None and a_min is None):
            if target is None:
                problems.append("least_slip_push needs a task: direction and a_min, or a_obj")
            else:
                problems.append("least_slip_push takes either a_obj or direction and a_min")
        elif target is None and (d is None or a_min is None):
            problems.append("least_slip_push needs both direction and a_min")
        if a_min is not None and not (isinstance(a_min, (int, float, np.floating))
                                      and not isinstance(a_min, bool) and np.isfinite(a_min)
                                      and a_min > 0):
            problems.append(f"a_min must be a number > 0 (m/s^2), got {short_repr(a_min)}")
    elif objective == "strongest_push":
        if d is None:
            problems.append("strongest_push needs a direction (dx,dy or dx,dy,dalpha) on a "
                            "general scene")
        if a_min is not None or target is not None:
            problems.append("strongest_push takes no a_min or a_obj")
    elif direction is not None or a_min is not None or a_obj is not None:
        problems.append("max_sr takes no direction, a_min or a_obj")
    if allow_slide is not None and not isinstance(allow_slide, (bool, np.bool_)):
        problems.append(f"allow_slide must be None, True or False on a general scene, got "
                        f"{short_repr(allow_slide)}")
    if problems:
        raise InputError("; ".join(problems))
    return dict(objective=objective, object=int(obj), tau_max=tm, tau_max_from=source,
                radius=None if radius is None else float(radius), direction=d,
                a_min=None if a_min is None else float(a_min), a_obj=target,
                allow_slide=None if allow_slide is None else bool(allow_slide))


def optimize(model, q, objective="max_sr", *, object=1, tau_max="robot", radius=None,
             direction=None, a_min=None, a_obj=None, allow_slide=None):
    """The optimal joint torque for a task at configuration ``q`` (n_s,) of a general scene
    (see the module docstring). ``object``: the object (1-based) that ``direction``,
    ``a_min`` and ``a_obj`` refer to (``a_obj = (a_x, a_y, alpha)``; ``direction``
    ``(dx, dy)`` or ``(dx, dy, dalpha)``, normalized). ``tau_max``: the box (``"robot"``: the
    robot's effort limits; None: none); ``radius``: the ellipsoid (default 1 without a box).
    Returns a :class:`SceneOptimizeResult`."""
    ns = model.n_coordinates
    qa = _vector("q", q, (ns,), f"{ns} finite numbers = (n_joints + 3,) for a "
                                f"{model.n_joints}-joint robot (one configuration)")
    task = _validate(model, objective, object, tau_max, radius, direction, a_min, a_obj,
                     allow_slide)
    p = scene_problem(model, qa)
    limits = describe(tau_max=task["tau_max"], tau_max_from=task["tau_max_from"],
                      radius=task["radius"])
    roles = block_roles(p)
    sliding_objects = [b for b, (r, z) in enumerate(roles) if r == "object" and not z]
    if task["allow_slide"] is None:  # a snake on Coulomb or anisotropic ground moves by sliding
        task["allow_slide"] = any(r == "link" and not z and k in (DISC, SPLIT)
                                  for (r, z), k in zip(roles, p.kind))
    if task["allow_slide"] and task["a_obj"] is not None:
        raise InputError("a_obj (a full object acceleration) needs every link's set sticking "
                         "(allow_slide=False): with sliding links it is searched for, and an "
                         "equality is not met by a search; give direction and a_min instead")
    hold = friction_holds(p, task["radius"], task["tau_max"])
    if hold.holds:
        return _held(model, qa, p, task, hold, limits)
    tau, status, cert, solver = None, "infeasible", {}, ""
    if not task["allow_slide"] or (objective == "max_sr" and not sliding_objects):
        if objective == "max_sr":
            tau, status, cert, solver = _max_sr(model, qa, p, roles, task, sliding_objects)
        else:
            tau, status, cert = solve_pieces(p, roles, task, sliding_objects)
            solver = "IPOPT (CasADi) on every piece"
    res = _finish(model, qa, p, task, tau, status, cert, solver, limits)
    if task["allow_slide"]:
        t2, v2, count = search(model, p, task)
        how = (f"search of the region by {count} forward solves (every link free to slide) "
               f"and a pattern search")
        sign = -1.0 if objective == "least_slip_push" else 1.0
        if t2 is not None and (tau is None or not np.isfinite(res.objective_value)
                               or sign * (v2 - res.objective_value) > 1e-9 * max(1.0, abs(v2))):
            res = _finish(model, qa, p, task, t2, "local",
                          {"kind": "sampled, not certified", "ok": False, "value": v2,
                           "samples": count,
                           "reason": "a search: links may slide, the pieces are not "
                                     "polyhedra; not certified"}, how, limits)
        elif tau is not None and res.status == "optimal":
            res.status = "stick_only"
            res.reason = ("the optimum with every link's set sticking; no sliding torque "
                          "found by the search beats it, but sliding pieces are not certified")
            res.solver += "; " + how
        elif t2 is None and tau is None:
            res.reason = "no torque found by the search meets the task within the limits"
            res.status = "infeasible" if objective != "max_sr" else res.status
            res.solver = how
    return res


def _max_sr(model, qa, p, roles, task, sliding_objects):
    """``(tau, status, certificate, solver)`` of ``max_sr`` with every link's set sticking:
    the pieces where every object sticks are cones, solved exactly; where an object slides on
    the ground, the pieces are not convex (IPOPT, local) and the answer is their best where
    it beats the exact one."""
    tau, cert = max_sr_exact(p, roles, task)
    if tau is not None:
        tau = _sticking_scale(model, qa, tau, cert)
    status = "optimal" if tau is not None else "infeasible"
    solver = "Dinkelbach on the KKT points of every contact state's cone, scaled to the limits"
    if not sliding_objects:
        return tau, status, cert, solver
    t2, s2, c2 = solve_pieces(p, roles, task, sliding_objects, only_sliding=True)
    solver += "; IPOPT (CasADi) on every piece where an object slides on the ground"
    counts = {k: c2[k] for k in ("states", "solved", "infeasible", "unknown")}
    if t2 is not None and (tau is None or c2["value"] > cert["value"]):
        c2["sticking_pieces"] = {"value": cert["value"], "ok": cert["ok"]}
        return t2, s2, c2, solver
    if tau is None:
        c2["sticking_pieces"] = {"value": cert["value"], "ok": cert["ok"],
                                 "reason": cert.get("reason", "")}
        return None, s2, c2, solver
    cert["sliding_pieces"] = counts
    cert["ok"] = False
    cert["reason"] = ("the exact optimum of the pieces where every object sticks; the pieces "
                      "where an object slides on the ground are not convex: IPOPT's local "
                      f"optima ({counts['solved']} solved, {counts['infeasible']} "
                      f"infeasible, {counts['unknown']} not answered) do not beat it")
    return tau, "local", cert, solver


def _sticking_scale(model, qa, tau, cert):
    """``tau`` where the forward solve finds every link's set sticking there; else the largest
    sticking torque along its ray, by bisection on the scale (to 1e-12 of it) with the forward
    solve. The ray's sticking torques are an interval from 0 (forces scale with the torque, the
    sets are convex about 0) on which ``sr`` is the piece's. The scale to the limits reads the
    sets' forces from one member of the piece's forces; where the held rows are dependent
    (a box flush on a link and pegs, say), that member may pull at a contact, and the torque
    it allows then lets a link slide. A set at its boundary reads sticking while it slides by
    less than the solve's tolerance (relative to the largest set), which may already move sr:
    the ray's torques on the piece are those where sr is also the piece's (to 1e-9: its
    rounding on the piece is about 1e-13), read by the forward solve deep inside the piece."""
    inside = model.forward(qa, 1e-6 * tau)
    want = float(inside.sr) if inside.status == 0 else cert["value"]

    def sticks(t):
        an = model.forward(qa, t * tau)
        return (an.status == 0 and abs(float(an.sr) - want) <= 1e-3 * CHECK_TOL  # (rounding)
                and not any((g.get("link") or g.get("object")) and g["state"].startswith("slide")
                            for g in an.ground))

    if sticks(1.0):
        return tau
    lo, hi = 0.0, 1.0
    while hi - lo > 1e-12:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if sticks(mid) else (lo, mid)
    cert["scaled_by_forward"] = lo
    return tau * lo * (1 - MARGIN)


def _held(model, qa, p, task, hold, limits):
    """The answer where friction holds every torque of the region still
    (:mod:`snakecg.scenes.friction_hold`): nothing moves, so every torque gives ``sr = 0``
    (its convention where nothing moves) and ``d . a_o = 0``; a push of at least ``a_min``
    is infeasible. Checked by the forward solve at the torque that uses the most friction."""
    why = (f"friction holds every torque of the region still (at most {hold.fraction:.3g} "
           f"of a friction set's size is needed): nothing moves")
    cert = {"kind": "friction holds the region: every ground set balances every torque "
                    "of the region within its size", "ok": True, "fraction": hold.fraction,
            "value": 0.0, "unique": True}  # a = 0, the only solution (extremes' docstring)
    solver = "balance of the torques by the ground sets over the region (friction_holds)"
    target = task["a_obj"]
    moving = (task["objective"] == "least_slip_push"
              and (target is None or np.any(target != 0)))
    if moving:
        cert["reason"] = why + ", so no torque of the region moves the object"
        return _finish(model, qa, p, task, None, "infeasible", cert, solver, limits)
    cert["reason"] = why + {"max_sr": ": sr = 0 for every torque (0 where nothing moves)",
                            "strongest_push": ": every torque gives d . a_o = 0",
                            "least_slip_push": ": every torque gives a_o = 0 and "
                                               "norm_qdd = 0"}[task["objective"]]
    res = _finish(model, qa, p, dict(task, allow_slide=False), hold.tau, "optimal", cert,
                  solver, limits)
    return res


def objective_of(task, an, p, tau):
    """The task's objective read from a forward result ``an`` at ``tau``; sr is 0 where
    nothing moves (``|a|_M^2`` below ``MOTION_FLOOR`` of the free motion's ``tau^T N tau``,
    where the ratio is one of rounding errors)."""
    if task["objective"] == "max_sr":
        moving = float(an.norm_a_obj + an.norm_qdd) > MOTION_FLOOR * float(tau @ p.N @ tau)
        return float(an.sr) if moving else 0.0
    if task["objective"] == "least_slip_push":
        return float(an.norm_qdd)
    ao = np.asarray(an.a_obj)[task["object"] - 1]
    return float(task["direction"] @ ao)


def binding(p, task, tau, an) -> list:
    """The limits active at ``tau``: the ellipsoid, a joint's torque limit, a link's set at its
    boundary, a contact at zero force."""
    out = []
    if task["radius"] is not None and tau @ p.N @ tau >= task["radius"] ** 2 * (1 - 1e-6):
        out.append("input ellipsoid (eq. 31)")
    if task["tau_max"] is not None:
        for j in np.flatnonzero(np.abs(tau) >= task["tau_max"] * (1 - 1e-6)):
            out.append(f"torque limit on joint {j + 1}")
    lam = an._raw["lam"][0]
    for b, (k, par, lab) in enumerate(zip(p.kind, p.par, p.rows.labels)):
        r = p.start[b]
        if lab[0] in ("wheel", "ground") and gauge(k, par, lam[r:r + 2]) >= 1 - 1e-5:
            out.append(f"friction set of link {lab[1] + 1} at its boundary")
    return out


def _finish(model, qa, p, task, tau, status, cert, solver, limits):
    obj = task["object"]
    if tau is None:
        tau = np.zeros(p.n_a)
        an = model.forward(qa, tau)
        return SceneOptimizeResult(task["objective"], np.full(p.n_a, np.nan), status,
                                   cert.get("reason", "no piece admits the task within the "
                                                      "limits"), np.nan, obj, [], an, solver,
                                   cert, limits)
    an = model.forward(qa, tau)
    value = objective_of(task, an, p, tau)
    want = cert.get("value", value)
    reason = cert.get("reason", "")
    slid = [g for g in an.ground if g.get("link") and g["state"].startswith("slide")
            and not task["allow_slide"]]
    # contact friction: the piece's own solution at tau (Coulomb's law may have several)
    mine = piece_objective(p, task, cert["piece"], tau) if p.tangent and cert.get(
        "piece") is not None else None
    uniq, count = an.uniqueness, (int(an.solutions) if model.packed.friction else None)
    if "piece" in cert:
        cert["piece"] = piece_words(p, cert["piece"])
    if an.status != 0 and mine is None:
        status, reason = "failed", f"the forward solve did not answer at tau: {an.reason[0]}"
    elif slid:
        status, reason = "failed", (f"the forward solve finds the set of link "
                                    f"{slid[0]['link']} sliding at tau")
    elif abs(value - want) > CHECK_TOL * max(1.0, abs(want)) or an.status != 0:
        if mine is not None and abs(mine - want) <= CHECK_TOL * max(1.0, abs(want)):
            # the piece's solution holds at tau and attains the optimum: Coulomb's law has
            # another solution there, the one the forward solve picks (or none it finds)
            uniq = "several" if an.status == 0 else "not_certified"
            where = "(the piece's, in certificate['piece'], checked apart)"
            if an.status == 0:
                reason = (f"Coulomb's law has several solutions at tau: the optimum "
                          f"{want:.9g} is the objective of one of them {where}; the forward "
                          f"solve picks another one, of objective {value:.9g}")
            else:
                reason = (f"the optimum {want:.9g} is the objective of a solution of "
                          f"Coulomb's law at tau {where}; the forward solve finds none there")
            value = want
        else:
            status, reason = "failed", (f"the forward solve's objective {value:.9g} differs "
                                        f"from the piece's {want:.9g}")
    elif uniq is not None and uniq != "unique" and not cert.get("unique"):
        note = (f"the forward solve's solution at tau is one of {abs(count)} solutions of "
                f"Coulomb's law (uniqueness several); the optimum is its value"
                if uniq == "several" else "the forward solve does not certify that the "
                "solution of Coulomb's law at tau is unique (uniqueness not_certified)")
        reason = f"{reason}; {note}" if reason else note
    if cert.get("unique") and uniq is not None:
        uniq = "unique"
    return SceneOptimizeResult(task["objective"], tau, status, reason, value, obj,
                               binding(p, task, tau, an), an, solver, cert, limits,
                               uniq, count)


def piece_objective(p, task, piece, tau):
    """The task's objective on the piece ``piece`` (block state codes) at ``tau``, where the
    piece is a solution of Coulomb's law there (the contacts' conditions,
    :func:`~snakecg.scenes.extremes_coulomb.piece_conditions`, within ``PIECE_TOL`` in the
    whitened torques, every link's set sticking within ``1 + PIECE_TOL`` of its size); else
    None. Written from :func:`~snakecg.scenes.maps.state_maps`, apart from the search that
    found it."""
    if any(c == SLIDE for c in piece):  # an object sliding on the ground: angles unknown
        return None
    mp = state_maps(p, list(piece))
    lam = mp["lam_from_tau"] @ tau + mp["lam_offset"]
    qdd = mp["qdd_from_tau"] @ tau + mp["qdd_offset"]
    ao = np.einsum("ojk,k->oj", mp["a_obj_from_tau"], tau) + mp["a_obj_offset"]
    # the contacts' conditions in whitened torques (unit rows: a distance), the forces'
    # free directions (a family) projected out
    T = whitening(p)
    u = np.linalg.solve(T, tau)
    C, _ = piece_conditions(p, mp, list(piece), T, 0.0, ground=False)
    if C is None or np.any(C[:, :-1] @ u + C[:, -1] < -PIECE_TOL * max(1.0, np.linalg.norm(u))):
        return None
    for b, code in enumerate(piece):
        k, par, r = p.kind[b], p.par[b], p.start[b]
        if k != UNILATERAL and code == HELD and k != FREE and gauge(
                k, par, lam[r:r + 2]) > 1 + PIECE_TOL:
            return None
    if task["objective"] == "least_slip_push":
        return float(qdd @ p.M_s @ qdd)
    if task["objective"] == "strongest_push":
        return float(task["direction"] @ ao[task["object"] - 1])
    om = sum(float(ao[j] @ p.M[p.n_s + 3 * j:p.n_s + 3 * j + 3,
                               p.n_s + 3 * j:p.n_s + 3 * j + 3] @ ao[j]) for j in range(p.n_o))
    D = om + float(qdd @ p.M_s @ qdd)
    return om / D if D > MOTION_FLOOR * float(tau @ p.N @ tau) else 0.0


def piece_words(p, piece) -> list:
    """A piece's block states in ``maps``' words (contacts held/open, or with friction
    open/stick/slip+/slip-; ground sets stick/slide/none)."""
    out = []
    for b, c in enumerate(piece):
        if b in p.tangent:
            out.append({HELD: "stick", ZERO: "open", SLIDE_POS: "slip+", SLIDE_NEG: "slip-"}[c])
        else:
            out.append(state_name(p.kind[b], c))
    return out
