"""Simulation of a general scene over time: velocity-level time stepping on the scene's exact
solve (Moreau's midpoint-free scheme as in Stewart & Trinkle 1996, Anitescu & Potra 1997),
with contact onset found by root finding and inelastic impacts.

One step of length ``h`` from ``(x, V)`` (``x = (q, q_obj)``, ``V = (v, v_obj)``, the objects'
poses and twists in the world frame) solves

    min_{V+} 1/2 (V+ - V*)^T M (V+ - V*) + sum_k h sigma_{F_k}(A_k V+)
    s.t.  A_c V+ + g_c / h >= 0   (contacts: the gap stays >= 0 to first order)
          A_w V+ = 0              (ideal wheels)

with ``V* = V + h M^-1 (B tau - bias(q, v) + f_obj)`` and ``sigma_F`` the support function of
each ground friction set (a wheel's box, Coulomb's disc, the anisotropic split ellipse: the
sets of forces ``mu m_i g``, times ``h``: impulses). It is the rest problem of
:mod:`snakecg.scenes.solve` with ``a -> V+``, ``f -> M V*``, the sets' sizes times ``h`` and
the rows' offsets ``c = g_c / h`` (``core_scene_solve_b``): one exact solve for rest, steps and
impacts. Stick-slip and maximum dissipation come from it (a sliding block's impulse is on
its set's boundary, opposing the sliding velocity); a contact whose impulse would pull opens.

Then ``x+ = x + h V+``. Before the step is accepted the signed distance of every pair of
bodies that can touch (non-neighbour links, links with objects and obstacles, objects with
objects and obstacles: the engine's closest points, ``snakecg/engine/scene_geometry.c``) is
evaluated at ``x+``; where
one is below ``-tolerance`` the time it reaches ``-tolerance / 4`` along the step is found by
Brent's method on the distance of the interpolated state ``x + s h V+`` and the step is
taken again, shortened to it. A pair that comes within the tolerance with a closing velocity
gets an inelastic impact: the same solve with ``h = 0`` (no friction impulse, the ground's
forces being finite; ideal wheels take impulses) and the rows ``A V+ >= 0``, with its
certificate. The rows are found from the geometry at every step, so contact points slide along
edges and links and a box's corner can take over.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..errors import InputError
from .contacts import StateRows, place_objects
from .packing import scene_size
from .run_record import SceneEvent, SceneRun
from .solve import BOX, DISC, SPLIT, solve

__all__ = ["SceneState", "SceneEvent", "SceneRun", "simulate_scene"]

#: the shortest step (s) the root finding may ask for before the run stops (penetration)
H_MIN = 1e-9
#: at most this many steps per run
MAX_STEPS = 5_000_000
#: a contact closes with an impact when its normal velocity is below this (m/s)
IMPACT_SPEED = 1e-9
#: seconds of wall time between progress lines
PROGRESS_EVERY = 5.0


@dataclass
class SceneState:
    """What a feedback law ``tau(t, state)`` sees: ``t``, ``q``, ``v`` (n_s), ``q_obj``,
    ``v_obj`` (n_objects, 3)."""

    t: float
    q: np.ndarray
    v: np.ndarray
    q_obj: np.ndarray
    v_obj: np.ndarray


class _Stepper:
    """One run's state and the model's functions at a configuration."""

    def __init__(self, model, tol, f_obj):
        self.model, self.scene = model, model.scene
        self.ns, self.na, self.no = model.n_coordinates, model.n_joints, model.scene.n_objects
        self.n = self.ns + 3 * self.no
        self.tol = tol
        self.f_obj = f_obj
        self.engine = StateRows(model, tol)

    def geometry(self, q, qo):
        """The bodies' inertia and the rows at ``(q, qo)`` (the engine's, one call)."""
        rows, Mf, _ = self.engine.rows(q, qo)
        return Mf, rows

    def solve_rows(self, Mf, f, rows, h, gaps):
        """The velocity-level problem with the rows' sets scaled by ``h`` and contact offsets
        ``gaps / h`` (``h = 0``: an impact, offsets 0)."""
        A = rows.A if rows.A.size else np.zeros((0, self.n))
        m = A.shape[0]
        par = np.reshape(np.asarray(rows.par, dtype=float), (-1, 3)).copy()
        kind = np.asarray(rows.kind, dtype=np.int64)
        for k in range(len(kind)):
            if kind[k] in (BOX, DISC, SPLIT):
                par[k] *= h
        c = np.zeros(m)
        if h > 0:
            for cn in rows.contacts:
                c[cn.row] = cn.gap / h
        nb = len(kind)
        out = solve(self.model.core, Mf[None], f[None], A.reshape(1, m, self.n) if m else
                    np.zeros((1, 1, self.n)), np.array([m]),
                    kind.reshape(1, nb) if nb else np.full((1, 1), -1),
                    np.asarray(rows.start, dtype=np.int64).reshape(1, nb) if nb
                    else np.zeros((1, 1), dtype=np.int64),
                    par.reshape(1, nb, 3) if nb else np.zeros((1, 1, 3)), c=c[None] if m
                    else np.zeros((1, 1)))
        return {k: (v[0] if not isinstance(v, dict) else {a: b[0] for a, b in v.items()})
                for k, v in out.items()}


def _check_args(model, q0, v0, duration, dt, q_obj0, v_obj0, f_obj, tolerance):
    ns, no = model.n_coordinates, model.scene.n_objects
    problems = []

    def vec(name, value, shape, default):
        if value is None:
            return default
        arr = np.asarray(value, dtype=float) if not isinstance(value, (str, bytes)) else None
        if arr is None or arr.size != int(np.prod(shape)) or not np.all(np.isfinite(arr)):
            problems.append(f"{name} must be {int(np.prod(shape))} finite numbers "
                            f"(shape {shape}), got {value!r:.60}")
            return default
        return arr.reshape(shape).copy()

    q = vec("q0", q0, (ns,), np.zeros(ns))
    if q0 is None:
        problems.append(f"q0 is required: {ns} numbers (x, y, theta, q1..q{model.n_joints})")
    v = vec("v0", v0, (ns,), np.zeros(ns))
    vo = vec("v_obj0", v_obj0, (no, 3), np.zeros((no, 3)))
    fo = vec("f_obj", f_obj, (no, 3), np.zeros((no, 3)))
    qo = vec("q_obj0", q_obj0, (no, 3), None)
    for name, val, lo, hi in (("duration", duration, 0.0, 1e6), ("dt", dt, 1e-7, 1.0)):
        if not (isinstance(val, (int, float, np.floating)) and not isinstance(val, bool)
                and math.isfinite(val) and lo < val <= hi):
            problems.append(f"{name} must be a number in ({lo:g}, {hi:g}] (s), got {val!r:.60}")
    if tolerance is not None and not (isinstance(tolerance, (int, float)) and
                                      not isinstance(tolerance, bool) and 0 < tolerance < 0.01):
        problems.append(f"tolerance must be a number in (0, 0.01) (m), got {tolerance!r:.60}")
    if problems:
        raise InputError("simulate: " + "; ".join(problems))
    if isinstance(duration, (int, float)) and duration / dt > MAX_STEPS:
        raise InputError(f"simulate: duration / dt = {duration / dt:.3g} steps, more than "
                         f"{MAX_STEPS}; take a larger dt or a shorter run")
    return q, v, qo, vo, fo


def simulate_scene(model, q0, duration, *, v0=None, tau=None, dt=1e-3, q_obj0=None,
                   v_obj0=None, f_obj=None, tolerance=None, output_every=1,
                   progress=False) -> SceneRun:
    """Simulate the general scene of ``model`` (a :class:`~snakecg.scenes.model.
    GeneralSceneModel`) from ``q0`` (``v0``: default at rest) for ``duration`` seconds.

    ``tau``: joint torques, a constant ``(n_a,)``, a function ``tau(t)`` or a feedback law
    ``tau(t, state)`` (:class:`SceneState`; e.g. :class:`snakecg.simulate.SerpenoidPD`), held
    over each step; default zero. ``dt``: the step (s), shortened where a contact begins.
    ``q_obj0``/``v_obj0`` ``(n_objects, 3)``: the objects' poses and twists (default: placed by
    the scene, at rest); ``f_obj``: a constant wrench on every object. ``tolerance`` (m): the
    contact tolerance (default ``1e-5`` times the scene's size): contacts hold within it and
    nothing may penetrate beyond it. ``output_every``: keep every k-th step in the record.
    ``progress``: ``False`` (default) quiet, ``None`` a line on standard error every
    :data:`PROGRESS_EVERY` seconds of a long run (:func:`snakecg.progress.resolve`), or a
    ``progress(message)`` callable.
    """
    from ..progress import resolve
    from ..simulate.torques import check_tau, torque_law

    q, v, qo, vo, fo = _check_args(model, q0, v0, duration, dt, q_obj0, v_obj0, f_obj,
                                   tolerance)
    scene = model.scene
    tol = 1e-5 * scene_size(scene) if tolerance is None else float(tolerance)
    kind, law = torque_law(np.zeros(model.n_joints) if tau is None else tau, model.n_joints)
    st = _Stepper(model, tol, fo.reshape(-1))
    ns, n = st.ns, st.n
    if qo is None:
        qo = place_objects(scene, model.link_poses(q))
    x = np.concatenate([q, qo.reshape(-1)])
    V = np.concatenate([v, vo.reshape(-1)])
    rec = SceneRun.start(model, tol, dt)

    def torque(t, x, V):
        if kind == "constant":
            return law
        if kind == "time":
            return check_tau(law(t), model.n_joints, t)
        s = SceneState(t, x[:ns].copy(), V[:ns].copy(), x[ns:].reshape(-1, 3).copy(),
                       V[ns:].reshape(-1, 3).copy())
        return check_tau(law(t, s), model.n_joints, t)

    def min_gap(rows):  # the contacts' (every other pair is farther than the tolerance)
        return min((c.gap for c in rows.contacts), default=math.inf)

    try:
        Mf, rows = st.geometry(x[:ns], x[ns:].reshape(-1, 3))
    except InputError as exc:
        return rec.finish("penetration", 0.0, str(exc))
    t = 0.0
    tau_now = torque(t, x, V)
    rec.sample(t, x, V, tau_now, Mf, min_gap(rows), rows, None)
    nstep = 0
    report = resolve(progress)
    wall = time.perf_counter()
    while duration - t > 1e-9 * dt:  # (rounding of the sum of the steps is no step)
        if report is not None and time.perf_counter() - wall > PROGRESS_EVERY:
            wall = time.perf_counter()
            report(f"simulate: t = {t:.4g} s of {duration:g} s, {nstep} steps, "
                   f"{len(rec.events)} impacts")
        h = min(dt, duration - t)
        tau_now = torque(t, x, V)
        fgen = np.zeros(n)
        fgen[3:ns] = tau_now
        fgen[:ns] -= model.bias_forces(x[:ns], V[:ns])
        fgen[ns:] += st.f_obj
        for _ in range(60):
            f = Mf @ V + h * fgen
            out = st.solve_rows(Mf, f, rows, h, None)
            if out["info"]["status"] != 0:
                return rec.finish("not_converged", t, "the step's solve did not converge "
                                  f"at t = {t:.6g} s")
            Vp = out["a"]
            xp = x + h * Vp
            try:  # the next step's geometry; refused where a pair overlaps beyond tol
                geo = st.geometry(xp[:ns], xp[ns:].reshape(-1, 3))
                break
            except InputError as exc:
                refusal = str(exc)
            # bounding circles apart: no overlap (the pairs farther than that need no distance)
            bad = [(a, b, d) for a, b, d in st.engine.gaps(xp[:ns], xp[ns:], 2.0 * tol)
                   if d < -tol]
            if not bad:
                return rec.finish("penetration", t, refusal)
            # the time along the step where the first violating pair reaches -tol/4
            gaps0 = {(a, b): st.engine.gap(x[:ns], x[ns:], a, b) for a, b, _ in bad}
            s_hit = 1.0
            for a, b, d1 in bad:
                d0 = gaps0.get((a, b), math.inf)
                target = min(-0.25 * tol, 0.5 * (min(d0, tol) - tol))
                if not d0 > target:
                    s_hit = 0.0
                    break

                def dist(s, a=a, b=b, target=target):
                    xs = x + s * h * Vp
                    return st.engine.gap(xs[:ns], xs[ns:], a, b) - target

                s_hit = min(s_hit, brentq(dist, 0.0, 1.0, xtol=1e-12, rtol=1e-10))
            h = h * s_hit
            if h < H_MIN:
                a, b, d1 = min(bad, key=lambda r: r[2])
                return rec.finish("penetration", t,
                                  f"{scene.body_name(*a)} and {scene.body_name(*b)} would "
                                  f"penetrate by {-d1:.3g} m at t = {t:.6g} s (tolerance "
                                  f"{tol:.3g} m)", bodies=(a, b))
        else:
            return rec.finish("penetration", t, f"the step could not be kept within the "
                              f"contact tolerance at t = {t:.6g} s")
        rec.step_work(h, tau_now, Vp, out, rows)
        held = {(c.a, c.b) for c in rows.contacts}
        t += h
        x, V = xp, Vp
        nstep += 1
        Mf, rows = geo
        # inelastic impact where a new contact closes with a closing velocity (the contacts
        # of the step's rows are the step's solve's)
        new = [c for c in rows.contacts if (c.a, c.b) not in held]
        if new:
            vn = np.array([rows.A[c.row] @ V for c in new])
            if np.any(vn < -IMPACT_SPEED):
                imp = st.solve_rows(Mf, Mf @ V, rows, 0.0, None)
                if imp["info"]["status"] != 0:
                    return rec.finish("not_converged", t, "the impact's solve did not "
                                      f"converge at t = {t:.6g} s")
                V1 = imp["a"]
                rec.impact(t, V, V1, Mf, imp, rows, scene)
                V = V1
        if nstep % output_every == 0 or duration - t <= 1e-9 * dt:
            rec.sample(t, x, V, tau_now, Mf, min_gap(rows), rows, out)
    return rec.finish("completed", t, "")

