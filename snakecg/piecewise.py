"""Exact extremes over the input ellipsoid for bounded wheels (the ``wheels`` scenario).

With bounded wheels the solution of the contact/wheel problem (``snakecg.solver``) is a
continuous, piecewise affine function of the torque: each *state* ``sigma`` (contact held or
lost, every wheel sticking or sliding either way) holds on a polyhedron ``R_sigma`` of
torques, on which ``lam``, ``w``, ``qdd`` and ``a_obj`` are affine in ``tau`` (eqs. 12-25 with
the sliding wheels' fixed forces ``+-mu m_i g``). In the whitened coordinates
``u = L^T tau`` (``N = B^T M_s^-1 B = L L^T``, eq. 31) the input boundary is the unit sphere
and each metric is, on a piece, a quadratic ``u^T A u + 2 g^T u + c`` (or, for ``sr``, a
ratio of two).

Method (exact, certified):

1. *Pieces*: starting from the states of a few directions solved by the package's forward
   solver, the pieces meeting the sphere are found by walking across their facets: a facet
   of ``R_sigma`` (one condition at equality) that meets the sphere inside ``R_sigma`` leads
   to the neighbouring state (that one row flipped). Whether a facet meets the sphere is
   decided exactly by the stationary points of a linear function on every face of
   ``R_sigma`` cut with the sphere (closed form). The sphere is connected, so the walk visits
   every piece with a non-empty patch on it. The walk's pieces and faces are kept for step 2
   (:mod:`snakecg.pieces`).
2. *Per piece*, the extremes of the quadratic on ``sphere ∩ R_sigma`` are attained at KKT
   points: for every set ``S`` of active conditions (``|S| < n_a``) the sphere cut by them is
   a smaller sphere ``u = u_0 + Z y, |y| = r``, on which the stationary points of
   ``y^T A_r y + 2 g_r^T y`` solve ``(A_r - mu I) y = -g_r``: the real eigenvalues of the
   ``2k x 2k`` linearization ``[[A_r, -I], [-g_r g_r^T / r^2, A_r]]`` (Gander, Golub and
   von Matt 1989), plus the "hard case" points built from the eigenvectors of ``A_r``. Every
   candidate inside ``R_sigma`` is evaluated; the best is the piece's extreme. The whole
   sphere is searched first, then the faces, fewest dimensions first; a face is skipped where
   a bound of the quadratic on it (its sphere's stationary values, then a bound on the face)
   cannot beat the best value found for the configuration (:mod:`snakecg.sphere_kkt`).
   Every step is one vectorized call over all (configuration, piece) pairs of a chunk: the
   faces that meet the sphere are kept as flat batches, one per ``|S|``.
3. ``sr = Omega / (Omega + Xi)``: Dinkelbach's iteration, ``t <- sr(u*)`` with ``u*`` the
   global maximiser of ``Omega - t (Omega + Xi)`` (step 2, skipping the pieces and faces
   whose bound stays below 0, the value at the current point), until that maximum is
   ``<= 0`` up to rounding, judged by the ratio at ``u*`` (``sr(u*) <= t + 1e-14``; the
   maximum itself is ``D (sr - t)``, and ``D`` may be tiny on a thin piece): a certificate
   that no torque on the boundary does better. For the minimum the certificate is often immediate: ``Omega - t (Omega + Xi) >=
   min Omega - t max (Omega + Xi)``, with both extremes known from step 2.
4. Every reported extreme is re-evaluated by the package's forward solver at the returned
   torque; ``certified`` is False where the two differ by more than 1e-7 (relative) or a
   Dinkelbach iteration did not close. A maximum is reported as the forward solver's value
   at its torque (the pieces' forms carry rounding of up to ~1e-8 on thin pieces).
"""

from __future__ import annotations

import numpy as np

from .engine.threads import pool, threads
from .pieces import all_states, explore, forms, primitives
from .solver import HELD
from .sphere_kkt import per_config, piece_extremes, quad

__all__ = ["face_kernel", "wheel_extremes"]

#: Faces per thread of one compiled call (a face costs about a microsecond).
FACES_PER_THREAD = 2048
#: Dinkelbach's iteration goes on while the ratio at the maximiser of ``Omega - t D`` beats
#: ``t`` by more than this (sr is in [0, 1]: an absolute tolerance, a few roundings).
SR_GAIN = 1e-14


def _chunk(model, qa, kernel):
    n = qa.shape[0]
    prim = primitives(model, qa)
    states = all_states(model)
    p, s, pc, fcs, rounds = explore(model, prim, qa, states, kernel)
    kept = states[s, 0] == HELD
    every = np.ones(len(p), bool)
    T = prim["T"]
    res = {"max": {}, "min": {}, "min_kept": {}, "u_max": {}, "u_min": {}, "u_min_kept": {}}
    fm = {m: forms(pc, prim, m) for m in ("norm_a_obj", "norm_qdd", "norm_lambda")}
    cond = pc["cond"]
    pair_u, pair_ok = {}, {}
    for m, (A, g, c) in fm.items():
        vmax, umax, vmin, umin = piece_extremes(cond, fcs, A, g, c, p, n, kept, kernel=kernel)
        pair_u[m + "_max"], pair_ok[m + "_max"] = umax, np.isfinite(vmax)
        pair_u[m + "_min"], pair_ok[m + "_min"] = umin, np.isfinite(vmin)
        res["max"][m], res["u_max"][m] = per_config(n, p, vmax, umax, every, True)
        res["min"][m], res["u_min"][m] = per_config(n, p, vmin, umin, every, False)
        res["min_kept"][m], res["u_min_kept"][m] = per_config(n, p, vmin, umin, kept, False)
    # sr = Omega / (Omega + Xi) on the kept pieces (0 where the contact is lost): Dinkelbach
    (Ao, go, co), (Aq, gq, cq) = fm["norm_a_obj"], fm["norm_qdd"]
    Ad, gd, cd = Ao + Aq, go + gq, co + cq
    closed = np.ones(n, bool)
    kp = np.flatnonzero(kept)
    has = np.zeros(n, bool)
    has[p[kp]] = True
    # starting ratios: sr at the extreme points of the norms found on the kept pieces
    pts = np.concatenate([pair_u[m][kp] for m in pair_u], axis=0)
    own = np.tile(kp, len(pair_u))
    ok = np.all(np.isfinite(pts), axis=1) & np.concatenate([pair_ok[m][kp] for m in pair_ok])
    pts, own = pts[ok], own[ok]
    om = quad(Ao[own], go[own], co[own], pts[:, None])[:, 0]
    dd = quad(Ad[own], gd[own], cd[own], pts[:, None])[:, 0]
    # D = Omega + Xi vanishes where the wheels brace the snake (a torque that moves nothing):
    # sr there is 0/0, a limit; such points only bound nothing. eps: the rounding level of D.
    d_scale = res["max"]["norm_qdd"] + res["max"]["norm_a_obj"]
    eps = 1e-12 * np.where(np.isfinite(d_scale) & (d_scale > 0), d_scale, 1.0)
    good = dd > 1e3 * eps[p[own]]
    pts, own, om, dd = pts[good], own[good], om[good], dd[good]
    sr0 = om / dd
    for largest in (True, False):
        t, u_best = per_config(n, p[own], sr0, pts, np.ones(len(own), bool), largest)
        t = np.clip(np.where(np.isfinite(t), t, 0.0 if largest else 1.0), 0.0, 1.0)
        done = ~has
        if not largest:
            # on the kept pieces Omega - t D >= min Omega - t max D (D = Omega + Xi, t >= 0):
            # where that bound is >= 0 up to rounding (typically t = 0: the object can be held
            # still) the certificate holds without another pass
            lb = res["min_kept"]["norm_a_obj"] - t * (res["max"]["norm_a_obj"]
                                                       + res["max"]["norm_qdd"])
            done |= np.isfinite(lb) & (lb >= -0.5 * eps)
        for _ in range(30):
            sel = kp[~done[p[kp]]]
            if sel.size == 0:
                break
            ps = p[sel]
            active = np.zeros(len(p), bool)
            active[sel] = True
            tp = t[p]
            # the max of sign * (Omega - t D): only where it can exceed 0, the value at the
            # current point (every pair's form, only the active pairs searched)
            sign = 1.0 if largest else -1.0
            A = sign * (Ao - tp[:, None, None] * Ad)
            g = sign * (go - tp[:, None] * gd)
            c = sign * (co - tp * cd)
            vmax, umax, _, _ = piece_extremes(cond, fcs, A, g, c, p, n, every,
                                              floor=np.zeros(n), kernel=kernel, active=active)
            vals, us = sign * vmax[sel], umax[sel]
            h, u = per_config(n, ps, vals, us, np.ones(len(sel), bool), largest)
            # the ratio at the maximiser (minimiser) of Omega - t D, from its own piece
            sv = vals if largest else -vals
            best = np.full(n, -np.inf)
            np.maximum.at(best, ps, np.where(np.isfinite(sv), sv, -np.inf))
            hit = np.flatnonzero((sv >= best[ps]) & np.isfinite(sv))
            sr_u = t.copy()
            uu = us[hit][:, None]
            d_u = quad(Ad[sel[hit]], gd[sel[hit]], cd[sel[hit]], uu)[:, 0]
            # (where D is at its rounding level, 0/0: no ratio, no gain)
            sr_u[ps[hit]] = np.where(d_u > 1e3 * eps[ps[hit]],
                                     quad(Ao[sel[hit]], go[sel[hit]], co[sel[hit]], uu)[:, 0]
                                     / np.maximum(d_u, 1e-300), t[ps[hit]])
            sr_u = np.clip(sr_u, 0.0, 1.0)  # Omega <= Omega + Xi
            active = np.zeros(n, bool)
            active[ps] = True
            # a gain is taken only where the forward solver confirms it at that torque (a
            # candidate may lie outside its piece by the feasibility tolerance, where the
            # piece's affine extension is not the map): its ratio there is the new t
            cand = np.flatnonzero(active & ~done & ((sr_u > t + SR_GAIN) if largest
                                                    else (sr_u < t - SR_GAIN)))
            if cand.size:
                fw = model.forward(qa[cand], np.einsum("nij,nj->ni", T[cand], u[cand]))
                sr_u[cand] = np.where(fw.contact & ~fw.singular, fw.sr, t[cand])
            # certificate: max (min) of Omega - t D over the boundary <= 0 up to rounding,
            # judged by the ratio at the maximiser (minimiser): Omega - t D = D (sr - t), and
            # D there may be tiny (a thin piece touching the sphere in a small cap), so a
            # rounding-sized Omega - t D can hide a gain of 1e-6 in sr
            gain = (sr_u - t) if largest else (t - sr_u)
            improve = active & ~done & (gain > SR_GAIN) & ((h > 0) if largest else (h < 0))
            t = np.where(improve, sr_u, t)
            u_best = np.where(improve[:, None], u, u_best)
            done |= active & ~improve
        closed &= done
        key = "max" if largest else "min_kept"
        res[key]["sr"] = np.where(has, np.clip(t, 0.0, 1.0), 0.0 if largest else np.nan)
        res["u_" + key]["sr"] = u_best
    lost_any = np.zeros(n, bool)
    lost_any[p[~kept]] = True
    res["min"]["sr"] = np.where(lost_any, 0.0, res["min_kept"]["sr"])
    # where the contact can be lost, sr = 0 there: any point of a lost piece
    _, u_lost = per_config(n, p, np.where(kept, np.nan, 0.0), pair_u["norm_qdd_min"],
                            ~kept & pair_ok["norm_qdd_min"], False)
    res["u_min"]["sr"] = np.where(lost_any[:, None], u_lost, res["u_min_kept"]["sr"])
    tau = {k: {m: np.einsum("nij,nj->ni", T, v) for m, v in res["u_" + k].items()}
           for k in ("max", "min", "min_kept")}
    return res, tau, closed, dict(pieces=len(p), rounds=rounds)


class _Kernel:
    """A model's :class:`~snakecg.engine.sphere.SphereKernel` with the candidates split over the
    package's threads."""

    def __init__(self, sphere):
        self._sphere = sphere
        self.cut, self.meets, self.pieces = sphere.cut, sphere.meets, sphere.pieces

    def candidates(self, pair, *args, **kwargs):
        return self._sphere.candidates(pair, *args, pool=pool(),
                                       workers=threads(len(pair), FACES_PER_THREAD), **kwargs)


def face_kernel(model):
    """The compiled faces and KKT candidates of ``model``'s library
    (:mod:`snakecg.engine.sphere`); None without a compiled core (NumPy's path then)."""
    core = getattr(model, "core", None)
    if core is None:
        return None
    return _Kernel(core.sphere)


def wheel_extremes(model, qa, chunk: int = 2048, compiled: bool = True):
    """Exact extremes of every metric for bounded wheels (see the module docstring).

    ``compiled``: the pieces, their faces and the KKT candidates in the model's compiled core
    where it has one (else, and with False, NumPy's; both find the same points).
    Returns an :class:`~snakecg.analysis.Extremes` with ``certified`` (N,) and ``pieces``
    (the number of (configuration, state) pieces meeting the sphere).
    """
    from .extremes_result import METRICS, Extremes

    n, na = qa.shape[0], model.n_joints
    ex = Extremes(method="wheels: exact piecewise solve (every wheel state meeting the input "
                         "boundary, KKT points of each piece, Dinkelbach for sr), certified "
                         "by the forward solver")
    kernel = face_kernel(model) if compiled else None
    parts = []
    for s0 in range(0, n, chunk):
        parts.append(_chunk(model, np.ascontiguousarray(qa[s0:s0 + chunk]), kernel))
    cert = np.concatenate([c for _, _, c, _ in parts])
    for key, tkey in (("max", "tau_max"), ("min", "tau_min"), ("min_kept", "tau_min_kept")):
        for m in METRICS:
            # the norms are sums of squares: rounding below 0 is clipped
            getattr(ex, key)[m] = np.maximum(
                np.concatenate([r[key][m] for r, _, _, _ in parts]), 0.0)
            getattr(ex, tkey)[m] = np.concatenate([t[key][m] for _, t, _, _ in parts])
    # certificate: the forward solver at the returned torques gives the same values
    for key, tkey in (("max", "tau_max"), ("min_kept", "tau_min_kept")):
        taus = np.stack([getattr(ex, tkey)[m] for m in METRICS], axis=1)  # (n, 4, na)
        res = model.forward(np.repeat(qa, len(METRICS), axis=0), taus.reshape(-1, na))
        for k, m in enumerate(METRICS):
            val = getattr(res, m).reshape(n, len(METRICS))[:, k]
            ref = getattr(ex, key)[m]
            scale = np.maximum(np.abs(ref), 1e-300)
            # (a contact-kept minimum may sit on the facet lam_c = 0, where the forward solver
            # reads the contact as lost: the values agree by continuity)
            bad = ~(np.abs(val - ref) <= 1e-7 * scale + 1e-12 * np.abs(ex.max[m]))
            cert &= ~bad
            if key == "max":  # the value reported is the forward solve's at the torque: the
                # pieces' forms carry rounding of up to ~1e-8 on thin pieces
                ex.max[m] = np.where(bad, ex.max[m], val)
    ex.certified = cert
    ex.pieces = sum(i["pieces"] for _, _, _, i in parts)
    return ex
