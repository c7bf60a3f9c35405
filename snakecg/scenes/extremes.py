"""Extremes of the metrics of a general scene over the input ellipsoid (eq. 31), the paper's
definition: the boundary ``tau^T N tau = 1`` with ``N = B^T M_s^-1 B``, in whitened
coordinates ``u = L^T tau`` (``N = L L^T``) the unit sphere. The metrics: ``norm_lambda``,
``norm_a_obj`` (summed over the objects) and each object's ``norm_a_obj[j]`` (1-based),
``norm_qdd`` and ``sr`` (eqs. 26-30).

Two methods, chosen per configuration:

* **exact pieces** where every block is a 1-D set (contacts, bounded and ideal wheels,
  frictionless or size-0 ground): the solution is piecewise affine in ``tau``; each state
  (every contact held or open, every bounded wheel sticking or sliding either way) holds on
  a polyhedron, where the maps are affine (:mod:`snakecg.scenes.maps`) and every metric a
  quadratic. The extremes of a quadratic on ``sphere ∩ polyhedron`` are at KKT points: for
  every set of active conditions the sphere cut by them, and the stationary points of the
  quadratic on it (closed form, :mod:`snakecg.sphere_kkt`). Every state is enumerated, so the
  answer is exact; ``sr`` by Dinkelbach's iteration on ``Omega - t (Omega + Xi)`` over the
  same pieces, closed when no piece beats ``t``. Every value is re-evaluated by the compiled
  forward solve at its torque (``certified`` False where they differ by more than 1e-7).
* **certified bounds** elsewhere (Coulomb and anisotropic sets: the pieces are not
  polyhedra): a branch and bound on a cover of the sphere, the compiled forward solve at
  every cell's centre, with the accelerations' Lipschitz bound in the inertia metric
  (:mod:`snakecg.scenes.extremes_bounds`): ``max`` is the best value attained (at
  ``tau_max``), ``bound_max`` a certified upper bound (``min``/``bound_min`` the same
  below), to the absolute ``gap`` (every norm lies in [0, 1] on the boundary: the free
  motion's norm is 1) or until ``budget`` solves are spent; what the certificate leaves out
  is said there (``sr`` where the system barely moves, ``|a|_M^2`` below ``gap``: its bounds
  hold at every other torque; ``min_kept``).

Contacts with Coulomb friction (``mu_contact``) add their four states to the exact pieces
(open, stick, slip either way: :mod:`snakecg.scenes.extremes_coulomb`, whose conditions are
Coulomb's law exactly), at most ``MAX_STATES`` states. Coulomb's problem may have several
solutions at a torque: the pieces' regions then overlap, and every extreme is over every
solution at every torque of the boundary (the largest value any solution attains). At each
returned torque ``solutions[attr][m]`` counts the distinct solutions the pieces give there
(1: unique; ``k >= 2``: the value is one of them, and the forward solve, which picks one,
agrees when it meets any of them; ``-k``: a singular piece holds there, so the count may be
incomplete), and ``uniqueness`` says in one line which extremes have more than one. Where the
pieces are not enumerated (Coulomb or anisotropic ground, more than ``MAX_STATES`` states,
``exact=False``) there is no Lipschitz bound (no Gauss principle), so the extremes are
**sampled**, not certified: the forward solve at ``budget`` directions, with the bounds 1 and
0 that hold for every solution (every force dissipates) and the forward solve's own count of
solutions at each returned torque.

Before any of these, a configuration where friction holds every torque of the ellipsoid still
(:mod:`snakecg.scenes.friction_hold`: the ground sets balance every torque within their
sizes) is answered exactly: nothing moves, every object's norm, ``norm_qdd`` and ``sr`` are
0 and ``norm_lambda`` is 1 on the whole boundary. With contact friction ``a = 0`` is then the
only solution: ``a^T M a = a^T B tau + w^T lam``, the balancing ground forces make
``a^T B tau`` at most the ground's dissipation ``-w_g^T lam_g``, and the contacts' forces
dissipate, so ``a^T M a <= 0``.

``min_kept`` (every method): the minimum over the torques that keep every contact of every
object touching (held; with friction, sticking or slipping), equal to ``min`` when no object
is touched.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from ..extremes_result import Extremes, sphere_directions
from ..sphere_kkt import _cut, quadratic_candidates
from .maps import scene_problem, state_maps, whitening
from .extremes_bounds import Sampler, bounds
from .extremes_coulomb import PieceSolutions, contact_choices, piece_conditions
from .friction_hold import friction_holds
from .solve import BOX, DISC, FREE, HELD, SLIDE_NEG, SLIDE_POS, SPLIT, UNILATERAL, ZERO

__all__ = ["SceneExtremes", "extremes", "metric_names", "whitening", "quadratics", "piece_faces",
           "best_on_pieces"]

#: States enumerated at most by the exact method (more: certified bounds instead).
MAX_STATES = 2048
#: Feasibility tolerance of a candidate point (normalized conditions).
FEAS_TOL = 1e-9
#: The forward solve at an exact extreme's torque agrees to this (absolute: on the boundary
#: every norm and sr lie in [0, 1]), or not certified.
AGREE = 1e-7
#: Below this ``|a|_M^2`` (the free motion's is 1) the system does not move: sr is 0 there.
MOTION_FLOOR = 1e-12


@dataclass
class SceneExtremes(Extremes):
    """:class:`~snakecg.extremes_result.Extremes` of a general scene, with the certificate's
    bounds: ``bound_max[m]`` >= every value of ``m`` on the ellipsoid's boundary and
    ``bound_min[m]`` <= every value (equal to ``max``/``min`` where exact); ``gap[m]`` the
    gap of the two pairs (absolute: on the boundary every norm and sr lie in [0, 1]);
    ``samples``: forward solves spent. ``solutions[attr][m]`` (attr ``max``, ``min``,
    ``min_kept``): the distinct solutions of Coulomb's law at that extreme's torque (1
    unique, ``k >= 2`` several, ``-k`` maybe more, 0 unknown; 1 without contact friction);
    ``uniqueness``: '' or one line naming the extremes whose torque has more than one."""

    bound_max: dict = field(default_factory=dict)
    bound_min: dict = field(default_factory=dict)
    gap: dict = field(default_factory=dict)
    samples: object = 0
    solutions: dict = field(default_factory=dict)
    uniqueness: object = ""

    def _squeeze(self):
        super()._squeeze()
        for d in (self.bound_max, self.bound_min, self.gap):
            for k in d:
                d[k] = d[k][0]
        for d in self.solutions.values():
            for k in d:
                d[k] = d[k][0]
        if isinstance(self.samples, np.ndarray):
            self.samples = self.samples[0]
            self.uniqueness = self.uniqueness[0]
        if isinstance(self.method, list):
            self.method = self.method[0]
        return self


def metric_names(n_objects: int) -> tuple:
    """``norm_a_obj``, ``norm_qdd``, ``norm_lambda``, ``sr`` and ``norm_a_obj[j]`` per object."""
    return ("norm_a_obj", "norm_qdd", "norm_lambda", "sr") + tuple(
        f"norm_a_obj[{j + 1}]" for j in range(n_objects))


def _polyhedral(p) -> bool:
    return all(k in (FREE, UNILATERAL, BOX) or (k == DISC and not par[0] > 0)
               or (k == SPLIT and not (par[2] > 0 and (par[0] > 0 or par[1] > 0)))
               for k, par in zip(p.kind, p.par))


def _block_states(p):
    out = []
    for b, (k, par) in enumerate(zip(p.kind, p.par)):
        if k == UNILATERAL:
            out.append(contact_choices(p, b))
        elif k == FREE:
            out.append((HELD,))
        elif k == BOX:
            out.append((HELD, SLIDE_POS, SLIDE_NEG) if par[0] > 0 else (ZERO,))
        else:
            out.append((ZERO,))
    return out


def extremes(model, q, *, gap: float = 1e-3, budget: int = 100_000,
             exact: bool | None = None) -> SceneExtremes:
    """Best and worst of every metric over the input ellipsoid's boundary (eq. 31), with the
    torques attaining them and a certificate (see the module docstring).

    ``q``: ``(n_s,)`` or ``(N, n_s)``. ``exact``: None (default) answers a configuration
    where friction holds every torque exactly, enumerates the exact pieces where every block
    is a 1-D set and bounds the rest; False always bounds. ``gap``: the
    absolute gap at which the bounds stop (every norm and sr lie in [0, 1] there);
    ``budget``: forward solves allowed per configuration for the bounds."""
    ns = model.n_coordinates
    if not (isinstance(gap, (int, float)) and not isinstance(gap, bool) and 0 < gap < 1):
        raise InputError(f"gap must be a number in (0, 1) (the bounds' absolute gap), got "
                         f"{gap!r:.60}")
    if isinstance(budget, bool) or not isinstance(budget, (int, np.integer)) or not (
            100 <= budget <= 10**8):
        raise InputError(f"budget must be an integer in 100..1e8 (forward solves per "
                         f"configuration), got {budget!r:.60}")
    if exact not in (None, False, True):
        raise InputError(f"exact must be None, True or False, got {exact!r:.60}")
    try:
        qa = np.asarray(q, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"q must be numbers, shape ({ns},) or (N, {ns}), got {q!r:.60}") \
            from None
    batched = qa.ndim == 2
    if qa.ndim not in (1, 2) or qa.shape[-1] != ns or not np.all(np.isfinite(qa)):
        raise InputError(f"q has shape {qa.shape}, expected ({ns},) or (N, {ns}) = "
                         f"(n_joints + 3,) finite numbers for a {model.n_joints}-joint robot")
    qa = qa.reshape(-1, ns)
    names = metric_names(model.scene.n_objects)
    parts = []
    for s in range(qa.shape[0]):
        try:
            p = scene_problem(model, qa[s])
        except InputError as exc:
            if not batched:
                raise
            parts.append(_none(names, model.n_joints, str(exc)))
            continue
        hold = friction_holds(p, radius=1.0) if exact is not False else None
        if hold is not None and hold.holds:
            parts.append(_held(model, p, names, hold))
            continue
        if exact is not False and _polyhedral(p):
            n_states = int(np.prod([len(x) for x in _block_states(p)]))
            if n_states <= MAX_STATES:
                parts.append(_exact(model, p, names))
                continue
            if exact:
                raise InputError(f"exact: {n_states} states at this configuration (more than "
                                 f"{MAX_STATES}); use exact=None for " + (
                                     "sampled values (with contact friction they are not "
                                     "certified)" if p.tangent else "certified bounds"))
            if p.tangent:
                parts.append(_sampled(model, p, names, budget, f"contact friction and "
                                      f"{n_states} pieces (more than {MAX_STATES})"))
                continue
        elif exact:
            raise InputError("exact=True needs every block to be a 1-D set (contacts, wheels, "
                             "ideal wheels, frictionless ground); this scene has Coulomb or "
                             "anisotropic sets: use exact=None for " + (
                                 "sampled values (with contact friction they are not "
                                 "certified)" if p.tangent else "certified bounds"))
        elif p.tangent:
            parts.append(_sampled(model, p, names, budget, "contact friction with exact=False"
                                  if exact is False else "contact friction on Coulomb or "
                                  "anisotropic ground sets (the pieces are not polyhedra)"))
            continue
        parts.append(_bounds(model, p, names, gap, budget))
    ex = _stack(parts, names)
    return ex if batched else ex._squeeze()


def _none(names, na, why):
    ex = SceneExtremes(method="none")
    for attr in ("max", "min", "min_kept", "bound_max", "bound_min", "gap"):
        for m in names:
            getattr(ex, attr)[m] = np.nan
    for attr in ("tau_max", "tau_min", "tau_min_kept"):
        for m in names:
            getattr(ex, attr)[m] = np.full(na, np.nan)
    ex.certified, ex.reason, ex.samples = False, why, 0
    return ex


def _stack(parts, names):
    ex = SceneExtremes(method=[x.method for x in parts])
    for attr in ("max", "min", "min_kept", "bound_max", "bound_min", "gap", "tau_max",
                 "tau_min", "tau_min_kept"):
        for m in names:
            getattr(ex, attr)[m] = np.array([getattr(x, attr)[m] for x in parts])
    ex.certified = np.array([bool(x.certified) for x in parts])
    ex.reason = np.array([x.reason for x in parts], dtype=object)
    ex.samples = np.array([x.samples for x in parts])
    ex.uniqueness = np.array([x.uniqueness for x in parts], dtype=object)
    for attr in ("max", "min", "min_kept"):
        ex.solutions[attr] = {m: np.array([x.solutions.get(attr, {}).get(m, 0) for x in parts])
                              for m in names}
    ex.pieces = int(sum(x.pieces for x in parts))
    return ex


def _held(model, p, names, hold) -> SceneExtremes:
    """Friction holds every torque of the ellipsoid still
    (:mod:`snakecg.scenes.friction_hold`): ``a = 0`` for every torque, so on the boundary
    every object's norm, ``norm_qdd`` and ``sr`` are 0 and ``norm_lambda = |a_free|_M^2 = 1``,
    exactly; the torque reported for each is the one that uses the most friction, where the
    forward solve checks the values."""
    ex = SceneExtremes(method=f"friction holds every torque of the ellipsoid still (at most "
                              f"{hold.fraction:.3g} of a friction set's size is needed): "
                              f"nothing moves", pieces=0)
    for m in names:
        v = 1.0 if m == "norm_lambda" else 0.0
        for attr in ("max", "min", "min_kept"):
            getattr(ex, attr)[m] = v
            getattr(ex, "tau_" + attr)[m] = hold.tau.copy()
    ex = _check(model, p, ex, names)  # (a = 0 the only solution: the module's docstring)
    for m in names:  # the exact values, not the forward solve's rounding of them
        ex.max[m] = ex.bound_max[m] = ex.min[m]
    return ex


# ---------------------------------------------------------------- exact pieces
def quadratics(p, mp, T, names):
    """Every metric of the state's maps as ``(A, g, c)`` in ``u``: ``u^T A u + 2 g^T u + c``."""
    ns, no = p.n_s, p.n_o
    P = np.vstack([mp["qdd_from_tau"], mp["a_obj_from_tau"].reshape(3 * no, p.n_a)]) @ T
    p0 = np.r_[mp["qdd_offset"], mp["a_obj_offset"].ravel()]
    Pf = p.Minv @ p.B @ T  # the free accelerations (at f_obj = 0)
    out = {}

    def form(X, x0, W):
        return X.T @ W @ X, X.T @ W @ x0, float(x0 @ W @ x0)

    out["norm_qdd"] = form(P[:ns], p0[:ns], p.M_s)
    tot = [np.zeros((P.shape[1], P.shape[1])), np.zeros(P.shape[1]), 0.0]
    for j in range(no):
        sl = slice(ns + 3 * j, ns + 3 * j + 3)
        f = form(P[sl], p0[sl], p.M[sl, sl])
        out[f"norm_a_obj[{j + 1}]"] = f
        tot = [tot[0] + f[0], tot[1] + f[1], tot[2] + f[2]]
    out["norm_a_obj"] = tuple(tot)
    out["norm_lambda"] = form(P - Pf, p0, p.M)
    return out


def _conditions(p, mp, state, T):
    """The state's validity ``a . u + b >= 0`` as rows ``[a | b]``, normalized (None where
    empty), and whether they are exact
    (:func:`~snakecg.scenes.extremes_coulomb.piece_conditions`)."""
    return piece_conditions(p, mp, state, T, FEAS_TOL)


def piece_faces(C, na):
    """``(state index, u0, Z, r)`` of every face of every state's polyhedron cut with the
    sphere, grouped by the cut's dimension ``k`` (dict ``k -> arrays``)."""
    groups = {}
    for i, Ci in enumerate(C):
        m = Ci.shape[0]
        for s in range(0, min(m, na - 1) + 1):
            for S in itertools.combinations(range(m), s):
                groups.setdefault(s, []).append((i, S))
    out = {}
    for s, items in groups.items():
        idx = np.array([i for i, _ in items])
        if s == 0:
            u0 = np.zeros((len(items), na))
            Z = np.broadcast_to(np.eye(na), (len(items), na, na)).copy()
            r = np.ones(len(items))
        else:
            a = np.array([C[i][list(S), :-1] for i, S in items])
            b = np.array([C[i][list(S), -1] for i, S in items])
            with np.errstate(divide="ignore", invalid="ignore"):  # parallel conditions
                u0, Z, r, valid = _cut(a, b, na)
            valid &= np.isfinite(r) & np.all(np.isfinite(u0), axis=1)
            idx, u0, Z, r = idx[valid], u0[valid], Z[valid], r[valid]
        if idx.size:
            out[na - s] = (idx, u0, Z, r)
    return out


def best_on_pieces(C, forms, faces, sign):
    """The largest (sign 1) or smallest (-1) value of each state's quadratic on its piece
    of the sphere: (value, u, state) over every state."""
    best, bu, bs = -np.inf, None, -1
    for k, (idx, u0, Z, r) in faces.items():
        A = np.array([forms[i][0] for i in idx]) * sign
        g = np.array([forms[i][1] for i in idx]) * sign
        c = np.array([forms[i][2] for i in idx]) * sign
        pts = quadratic_candidates(u0, Z, r, A, g)  # (F, K, na)
        vals = np.einsum("fki,fij,fkj->fk", pts, A, pts) + 2 * np.einsum("fki,fi->fk", pts,
                                                                          g) + c[:, None]
        mc = max(Ci.shape[0] for Ci in C)
        Cp = np.zeros((len(C), mc, pts.shape[2] + 1))
        Cp[:, :, -1] = 1.0
        for i, Ci in enumerate(C):
            Cp[i, :Ci.shape[0]] = Ci
        cf = Cp[idx]
        slack = np.einsum("fmi,fki->fkm", cf[:, :, :-1], pts) + cf[:, None, :, -1]
        ok = np.all(slack >= -FEAS_TOL, axis=2) & np.isfinite(vals)
        vals = np.where(ok, vals, -np.inf)
        j = np.unravel_index(np.argmax(vals), vals.shape)
        if vals[j] > best:
            best, bu, bs = vals[j], pts[j], idx[j[0]]
    return sign * best, bu, bs


def _exact(model, p, names) -> SceneExtremes:
    na = p.n_a
    T = whitening(p)
    states = list(itertools.product(*_block_states(p)))
    conds, forms, kept, accel, singular = [], [], [], [], []
    kept_blocks = [b for b, lab in enumerate(p.rows.labels) if lab[0] == "contact" and "object"
                   in (p.rows.contacts[lab[1]].a[0], p.rows.contacts[lab[1]].b[0])]
    for st in states:
        mp = state_maps(p, st)
        C, exact_rows = _conditions(p, mp, st, T)
        if C is None:
            continue
        conds.append(C)
        forms.append(quadratics(p, mp, T, names))
        # kept: every contact of an object touching (held; with friction sticking or slipping)
        kept.append(all(st[b] != ZERO for b in kept_blocks))
        if p.tangent:  # the solutions' accelerations at a torque (Coulomb: maybe several)
            accel.append((np.vstack([mp["qdd_from_tau"], mp["a_obj_from_tau"].reshape(
                3 * p.n_o, na)]) @ T, np.r_[mp["qdd_offset"], mp["a_obj_offset"].ravel()]))
            singular.append(not exact_rows)
    kept = np.array(kept)
    faces = piece_faces(conds, na)
    ex = SceneExtremes(method=f"exact pieces ({len(conds)} states, KKT points of every face "
                              f"on the sphere; sr by Dinkelbach's iteration)", pieces=len(conds))
    pts = []
    for m in names:
        if m == "sr":
            continue
        fm = [f[m] for f in forms]
        for attr, sign, sel in (("max", 1, None), ("min", -1, None), ("min_kept", -1, kept)):
            use_faces = faces if sel is None else _restrict(faces, sel)
            v, u, _ = best_on_pieces(conds, fm, use_faces, sign) if use_faces else \
                (np.nan, np.full(na, np.nan), -1)
            getattr(ex, attr)[m] = max(float(v), 0.0) if np.isfinite(v) else np.nan
            getattr(ex, "tau_" + attr)[m] = T @ u if u is not None else np.full(na, np.nan)
            if u is not None:
                pts.append(u)
    _dinkelbach(ex, conds, forms, faces, kept, T, pts)
    sols = PieceSolutions(conds, accel, forms, singular, FEAS_TOL) if p.tangent else None
    return _check(model, p, ex, names, sols, T)


def _restrict(faces, sel):
    out = {}
    for k, (idx, u0, Z, r) in faces.items():
        keep = sel[idx]
        if keep.any():
            out[k] = (idx[keep], u0[keep], Z[keep], r[keep])
    return out


def _dinkelbach(ex, conds, forms, faces, kept, T, pts):
    """sr = Omega / D (D = Omega + Xi) on the pieces: Dinkelbach's iteration from the ratios
    at the norms' extreme points, for the max, min and min_kept."""
    def value(i, u, key):
        A, g, c = forms[i][key]
        return u @ A @ u + 2 * g @ u + c

    for attr, sign, sel in (("max", 1, None), ("min", -1, None), ("min_kept", -1, kept)):
        use = faces if sel is None else _restrict(faces, sel)
        if not use:
            ex.__dict__[attr]["sr"], ex.__dict__["tau_" + attr]["sr"] = np.nan, T @ np.full(
                T.shape[0], np.nan)
            continue
        # start: the extreme points of the norms, ratio evaluated on a piece that holds them
        t, u_best = (0.0 if sign > 0 else 1.0), None
        for u in pts:
            for i in range(len(conds)):
                if sel is not None and not sel[i]:
                    continue
                if np.all(conds[i][:, :-1] @ u + conds[i][:, -1] >= -FEAS_TOL):
                    D = value(i, u, "norm_a_obj") + value(i, u, "norm_qdd")
                    r = value(i, u, "norm_a_obj") / D if D > MOTION_FLOOR else 0.0
                    if u_best is None or sign * r > sign * t:
                        t, u_best = r, u
                    break
        for _ in range(60):
            comb = [tuple(f["norm_a_obj"][j] - t * (f["norm_a_obj"][j] + f["norm_qdd"][j])
                          for j in range(3)) for f in forms]
            h, u, i = best_on_pieces(conds, comb, use, sign)
            if u is None:
                break
            D = value(i, u, "norm_a_obj") + value(i, u, "norm_qdd")
            r = value(i, u, "norm_a_obj") / D if D > MOTION_FLOOR else t
            if not sign * (r - t) > 1e-14:
                break
            t, u_best = r, u
        getattr(ex, attr)["sr"] = float(np.clip(t, 0.0, 1.0))
        getattr(ex, "tau_" + attr)["sr"] = T @ u_best if u_best is not None else \
            np.full(T.shape[0], np.nan)


def _check(model, p, ex, names, sols=None, T=None):
    """Re-evaluate every extreme by the compiled forward solve at its torque; the max is
    reported as the forward solve's value; certified where all agree. With contact friction
    (``sols``: :class:`~snakecg.scenes.extremes_coulomb.PieceSolutions`) the pieces give
    every solution of Coulomb's law at the torque: where they give several, the extreme is
    the value of one of them (kept, flagged in ``solutions`` and ``uniqueness``), and the
    forward solve agrees when it meets any of them."""
    sampler = Sampler(model, p)
    taus, keys = [], []
    for attr in ("max", "min", "min_kept"):
        ex.solutions[attr] = {}
        for m in names:
            t = getattr(ex, "tau_" + attr)[m]
            ex.solutions[attr][m] = 1  # Gauss's principle: one solution
            if t is not None and np.all(np.isfinite(t)):
                taus.append(t)
                keys.append((attr, m))
    vals = sampler(np.array(taus).reshape(-1, p.n_a))
    ok, several = True, []
    for i, (attr, m) in enumerate(keys):
        got, want = vals[m][i], getattr(ex, attr)[m]
        if m == "sr" and vals["_D"][i] < MOTION_FLOOR:  # nothing moves: sr is 0 by convention
            got = 0.0
        agree = bool(vals["_ok"][i] and abs(got - want) <= AGREE)  # the free motion's is 1
        if sols is not None:
            k, each = sols.at(np.linalg.solve(T, taus[i]), MOTION_FLOOR)
            ex.solutions[attr][m] = k
            if abs(k) >= 2 or k < 0:
                several.append(f"{attr}[{m}]")
            if not agree and abs(k) >= 2 and vals["_ok"][i]:
                # the forward solve met another solution: the extreme is one of them
                agree = any(abs(v[m] - got) <= AGREE for v in each)
                if agree:
                    continue
        ok &= agree
        if attr == "max" and vals["_ok"][i]:
            ex.max[m] = float(got)
    for m in names:
        for attr in ("max", "min", "min_kept"):
            if not np.isfinite(getattr(ex, attr)[m]):
                getattr(ex, attr)[m] = np.nan
        ex.bound_max[m], ex.bound_min[m], ex.gap[m] = ex.max[m], ex.min[m], 0.0
    ex.certified = ok
    ex.reason = "" if ok else ("the forward solve at a returned torque differs from the "
                               "pieces' value by more than 1e-7")
    if several:
        ex.uniqueness = (f"Coulomb's law has several solutions (or a singular piece) at the "
                         f"torque of {', '.join(several)}: each such extreme is over every "
                         f"solution at every torque, attained by one of them (see solutions)")
    ex.samples = sampler.count
    return ex


# ---------------------------------------------------------------- certified bounds
def _bounds(model, p, names, gap, budget) -> SceneExtremes:
    na = p.n_a
    T = whitening(p)
    sampler = Sampler(model, p)
    best, bmax, bmin, closed, why = bounds(sampler, names, T, gap, budget)
    if best is None:
        ex = _none(names, na, why)
        ex.samples = sampler.count
        return ex
    ex = SceneExtremes(method="certified bounds: branch and bound on a cover of the sphere "
                              "(accelerations 1-Lipschitz in the inertia metric), the compiled "
                              "forward solve at every cell's centre; sr's bounds hold where "
                              f"|a|_M^2 >= {gap:g} (the free motion's is 1): below, the system "
                              "barely moves and sr, 0/0 in the limit, is left out")
    for m in names:
        for attr in ("max", "min", "min_kept"):
            v, u = best[(attr, m)]
            ok = u is not None and np.isfinite(v)
            getattr(ex, attr)[m] = v if ok else np.nan
            getattr(ex, "tau_" + attr)[m] = T @ u if ok else np.full(na, np.nan)
        ex.bound_max[m] = min(max(bmax[m], ex.max[m]), 1.0)
        ex.bound_min[m] = max(min(bmin[m], ex.min[m]), 0.0)
        ex.gap[m] = max(ex.bound_max[m] - ex.max[m], ex.min[m] - ex.bound_min[m])
    for attr in ("max", "min", "min_kept"):  # Gauss's principle: one solution
        ex.solutions[attr] = {m: 1 for m in names}
    ex.certified = closed and all(ex.gap[m] <= gap for m in names)
    ex.reason = "" if ex.certified else (why or f"the bounds did not close to {gap:g}") + \
        "; bound_max and bound_min still hold"
    ex.samples = sampler.count
    return ex


# ---------------------------------------------------------------- sampled (contact friction)
#: Samples per forward call of the sampled extremes.
SAMPLE_CHUNK = 4096


def _sampled(model, p, names, budget, why) -> SceneExtremes:
    """Contact friction where the pieces are not enumerated (``why``): ``budget`` directions
    of the sphere (quasi-uniform), the forward solve at each. Coulomb's problem has no Gauss
    principle, so the accelerations are not 1-Lipschitz in the torques and the cells of the
    certified bounds do not apply: ``max``/``min`` are the forward solve's values at their
    torques, not certified. ``bound_max`` 1 and ``bound_min`` 0 hold for every solution:
    every force dissipates (``w^T lam <= 0``: a contact's normal force is complementary to
    its row, its friction opposes its slip, a ground set's force is its maximal
    dissipation), so ``|a|_M^2 = a^T f + w^T lam <= a^T M a_free`` gives ``|a|_M <= 1`` and
    ``|a - a_free|_M^2 <= 1 - |a|_M^2`` on the boundary."""
    na = p.n_a
    T = whitening(p)
    sampler = Sampler(model, p)
    u = sphere_directions(na, int(budget))
    best = {(attr, m): (-np.inf if attr == "max" else np.inf, -1, 0)
            for attr in ("max", "min", "min_kept") for m in names}
    unsolved = 0
    for lo in range(0, len(u), SAMPLE_CHUNK):
        vals = sampler(u[lo:lo + SAMPLE_CHUNK] @ T.T)
        ok = vals["_ok"]
        unsolved += int(np.sum(~ok))
        for m in names:
            v = np.asarray(vals[m], dtype=float)
            for attr, w in (("max", np.where(ok, v, -np.inf)), ("min", np.where(ok, v, np.inf)),
                            ("min_kept", np.where(ok & vals["_kept"], v, np.inf))):
                i = int(np.argmax(w) if attr == "max" else np.argmin(w))
                if (w[i] > best[(attr, m)][0]) if attr == "max" else (w[i] < best[(attr, m)][0]):
                    best[(attr, m)] = (float(w[i]), lo + i, int(vals["_solutions"][i]))
    ex = SceneExtremes(method=f"sampled, not certified: {why}; the forward solve at "
                              f"{len(u)} directions of the sphere")
    several = []
    for attr in ("max", "min", "min_kept"):
        ex.solutions[attr] = {}
        for m in names:
            v, i, k = best[(attr, m)]
            found = i >= 0 and np.isfinite(v)
            getattr(ex, attr)[m] = v if found else np.nan
            getattr(ex, "tau_" + attr)[m] = T @ u[i] if found else np.full(na, np.nan)
            ex.solutions[attr][m] = k if found else 0
            if found and k != 1:
                several.append(f"{attr}[{m}]")
    for m in names:
        ex.bound_max[m], ex.bound_min[m] = 1.0, 0.0
        ex.gap[m] = max(1.0 - ex.max[m], ex.min[m]) if np.isfinite(ex.max[m]) else np.nan
    ex.certified = False
    ex.reason = ("with contact friction the sampled values are attained but not certified "
                 "(no Lipschitz bound: Coulomb's problem may have several solutions); "
                 "bound_max 1 and bound_min 0 hold" +
                 (f"; {unsolved} samples not answered by the forward solve" if unsolved else ""))
    if several:
        ex.uniqueness = (f"the forward solve's solution at the torque of {', '.join(several)} "
                         f"is not certified unique (see solutions: its count of Coulomb "
                         f"solutions there): each such value is the one the forward solve "
                         f"picks")
    ex.samples = sampler.count
    return ex
