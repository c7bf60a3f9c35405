"""With Coulomb friction at the contacts, ``dependent`` 0 promises that the forces are the only
ones Coulomb's law allows with the answered accelerations, 1 that they are a family's
minimum-norm member, and 2 that they are one member of a family whose minimum-norm one was not
found. Held on rows built apart from the engine
(``test_scenes_contact_friction.reference_problem``): at the engine's accelerations a, every
force lam with M a = f + A^T lam that Coulomb's law and the ground's sets allow at w = A a is
a convex set (a normal force >= 0, zero where its contact opens; |lam_t| <= mu lam_n, equal to
-mu lam_n sign(w_t) where it slips; a wheel's force within its bound, at it against its
sliding; a Coulomb disc's inside it, at -r w/|w| where its link slides). Its width along
random directions is zero exactly where the forces are unique: SciPy's linear programs (HiGHS)
where the sets are polyhedral (random small scenes), a conic program (cvxpy with Clarabel)
with the ground's discs (the 10-joint benchmark scene). Its minimum-norm member, a conic
program too (cvxpy with Clarabel), is the engine's forces wherever the flag is 1.
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np
import pytest
from scipy.optimize import linprog

import snakecg
from snakecg.scenes.solve import BOX, DISC, FREE, UNILATERAL

from scenes_reference import indeterminate_scene
from test_scenes_contact_friction import engine_forces, frictional_cases, reference_problem

TOL = 1e-9  # a row's acceleration zero within this of the rows' scale (the engine's too)


def force_set(p, a):
    """The set of forces at accelerations a: linear equations (A_eq, b_eq), inequalities
    (A_ub lam <= 0), bounds per row, and discs ``(rows, radius)`` (|lam[rows]| <= radius)."""
    M, f, A = p["M"], p["f"], p["A"]
    m = A.shape[0]
    w = A @ a
    W = max(1e-12, np.abs(A @ np.linalg.solve(M, f)).max(), np.abs(w).max())
    eq, rhs, ub, bounds, discs = [A.T], [M @ a - f], [], [(None, None)] * m, []

    def row(pairs):
        r = np.zeros(m)
        for j, c in pairs:
            r[j] += c
        return r

    for b in p["blocks"]:
        r, t = b["row"], b["tangent"]
        moves = abs(w[r]) > TOL * W
        if b["kind"] == FREE:
            continue
        if b["kind"] == DISC:  # inside, or at -r w/|w| where the link slides
            wd = w[r:r + 2]
            if np.abs(wd).max() > TOL * W:
                for i, v in enumerate(-b["p"] * wd / np.linalg.norm(wd)):
                    bounds[r + i] = (v, v)
            else:
                discs.append(([r, r + 1], b["p"]))
            continue
        if b["kind"] == BOX:
            if not b["p"] > 0:
                bounds[r] = (0.0, 0.0)
            elif moves:  # sliding: its force at the bound, against the sliding
                bounds[r] = (-b["p"],) * 2 if w[r] > 0 else (b["p"],) * 2
            else:
                bounds[r] = (-b["p"], b["p"])
            continue
        bounds[r] = (0.0, 0.0) if moves else (0.0, None)  # UNILATERAL
        if t is None:
            continue
        if moves:
            bounds[t] = (0.0, 0.0)
        elif abs(w[t]) > TOL * W:  # slips: lam_t = -mu lam_n sign(w_t)
            eq.append(row([(t, 1.0), (r, b["mu"] * np.sign(w[t]))])[None])
            rhs.append([0.0])
        else:  # sticks: inside the cone
            ub += [row([(t, 1.0), (r, -b["mu"])]), row([(t, -1.0), (r, -b["mu"])])]
    return np.vstack(eq), np.concatenate(rhs), np.array(ub).reshape(-1, m), bounds, discs


def _ends_linear(sets, c):
    """min and max of c . lam over a polyhedral set (HiGHS), or None."""
    A_eq, b_eq, A_ub, bounds, _ = sets
    ends = []
    for sign in (1.0, -1.0):
        r = linprog(sign * c, A_ub=A_ub if len(A_ub) else None,
                    b_ub=np.zeros(len(A_ub)) if len(A_ub) else None, A_eq=A_eq, b_eq=b_eq,
                    bounds=bounds, method="highs")
        if r.status != 0:
            return None
        ends.append(r.x)
    return ends


def _conic(sets):
    """The set as cvxpy's variable and constraints (its discs as second-order cones)."""
    import cvxpy as cp

    A_eq, b_eq, A_ub, bounds, discs = sets
    lam = cp.Variable(A_eq.shape[1])
    cons = [A_eq @ lam == b_eq] + ([A_ub @ lam <= 0] if len(A_ub) else [])
    for i, (lo, hi) in enumerate(bounds):
        cons += ([lam[i] >= lo] if lo is not None else []) + ([lam[i] <= hi] if hi is not None
                                                               else [])
    cons += [cp.norm(lam[rows]) <= radius for rows, radius in discs]
    return lam, cons


def _solve(objective, cons, tol):
    import cvxpy as cp

    prob = cp.Problem(cp.Minimize(objective), cons)
    with warnings.catch_warnings():  # ("may be inaccurate": the status says it)
        warnings.simplefilter("ignore", UserWarning)
        prob.solve(solver="CLARABEL", tol_gap_abs=tol, tol_gap_rel=tol, tol_feas=tol)
    return prob.status


def _ends_conic(sets, c):
    """min and max of c . lam over a set with discs (cvxpy, Clarabel), or None."""
    lam, cons = _conic(sets)
    ends = []
    for sign in (1.0, -1.0):
        if _solve(sign * c @ lam, cons, 1e-10) not in ("optimal", "optimal_inaccurate"):
            return None  # (the latter: its tolerances not all met to 1e-10, far inside the
        ends.append(lam.value)  # widths' margins)
    return ends


def min_norm(p, a):
    """The set's minimum-norm member (cvxpy, Clarabel), or None where the program did not
    reach its tolerances."""
    import cvxpy as cp

    lam, cons = _conic(force_set(p, a))
    return lam.value if _solve(cp.sum_squares(lam), cons, 1e-12) == "optimal" else None


def engine_lam(res, p):
    """Every force of the engine's answer as the reference's lam: the contacts' (matched by
    bodies and point), then the ground's rows in the reference's block order."""
    lam = engine_forces(res, p)
    ground = iter(res.ground)
    for b in p["blocks"]:
        if b["kind"] != UNILATERAL:
            f = np.atleast_1d(next(ground)["force"])
            lam[b["row"]:b["row"] + len(f)] = f
    assert not np.isnan(lam).any()
    return lam


def width(p, a, rng, directions=3):
    """The set's largest width along random unit directions (None where a program found it
    empty or failed), and the scale of its forces."""
    sets = force_set(p, a)
    ends_of = _ends_conic if sets[4] else _ends_linear
    m = p["A"].shape[0]
    out, F = 0.0, 0.0
    for _ in range(directions):
        c = rng.normal(size=m)
        c /= np.linalg.norm(c)
        ends = ends_of(sets, c)
        if ends is None:
            return None, F
        F = max(F, *(np.abs(x).max() for x in ends))
        out = max(out, abs(c @ (ends[0] - ends[1])))
    return out, F


@pytest.fixture(scope="module")
def samples():
    return frictional_cases(20261206, 60)


def test_dependent_is_zero_exactly_where_coulomb_allows_one_force(samples):
    """0: one force (the set a point); 1: a family (or a point that the sets pin while the
    rows are dependent), the forces its minimum-norm member; 2: a family whose minimum-norm
    member was not found (none on these samples)."""
    rng = np.random.default_rng(7)
    seen = {"unique": 0, "family": 0, "minimum norm": 0}
    for model, q, tau in samples:
        res = model.forward(q, tau)
        if res.status != 0:
            continue
        p = reference_problem(model, q, tau)
        a = np.r_[res.qdd, np.ravel(res.a_obj)]
        wd, F = width(p, a, rng)
        assert wd is not None, "the engine's accelerations admit no Coulomb forces"
        F = max(F, 1.0)
        assert wd <= 1e-7 * F or wd >= 1e-5 * F, (wd, F)  # (rounding, or a family)
        family = wd >= 1e-5 * F
        seen["family" if family else "unique"] += 1
        assert res.dependent in ((1,) if family else (0, 1)), (res.dependent, wd, F)
        if res.dependent == 1:
            ref = min_norm(p, a)
            if ref is not None:
                lam = engine_lam(res, p)
                assert np.abs(lam - ref).max() <= 1e-8 * F, (np.abs(lam - ref).max(), F)
                seen["minimum norm"] += 1
    print(seen)
    assert seen["unique"] >= 300 and seen["family"] >= 10 and seen["minimum norm"] >= 10, seen


def test_on_coulomb_ground_a_family_s_forces_are_its_minimum_norm_member():
    """The 10-joint benchmark scene with contact friction (pegs and objects at mu 0.3) on
    Coulomb ground: its discs are free unknowns where their links stick. At six random
    configurations (200 torques each, 94 % flagged 1: nearly every one is a family), every
    sample flagged 0 is a point (a conic program's width below 1e-7 of the forces' scale),
    none is flagged 2, and the forces of 60 flagged 1 are the family's minimum-norm member
    (a conic program's, to 1e-6 of their scale: Clarabel's own accuracy on these)."""
    rng = np.random.default_rng(0)
    seen = {"minimum norm": 0, "point": 0}
    for _ in range(6):
        q = np.r_[0.0, 0.0, 0.0, rng.uniform(-1.0, 1.0, 10)]
        model = snakecg.load(dataclasses.replace(indeterminate_scene(q, 10), mu_contact=0.3))
        T = rng.normal(0.0, 0.1, (200, 10))
        res = model.forward(np.repeat(q[None], len(T), axis=0), T)
        dep = np.asarray(res.dependent)
        assert np.all(np.asarray(res.status) == 0)
        assert not np.any(dep == 2), np.flatnonzero(dep == 2)
        for i in [*np.flatnonzero(dep == 0), *np.flatnonzero(dep == 1)[:10]]:
            p = reference_problem(model, q, T[i])
            r = model.forward(q, T[i])
            a = np.r_[r.qdd, np.ravel(r.a_obj)]
            if dep[i] == 0:
                wd, F = width(p, a, rng, directions=2)
                assert wd is not None, "the engine's accelerations admit no Coulomb forces"
                assert wd <= 1e-7 * max(F, 1.0), (i, wd, F)
                seen["point"] += 1
                continue
            ref = min_norm(p, a)
            if ref is None:
                continue
            lam = engine_lam(r, p)
            F = max(1.0, np.abs(ref).max())
            assert np.abs(lam - ref).max() <= 1e-6 * F, (i, np.abs(lam - ref).max(), F)
            seen["minimum norm"] += 1
    assert seen["minimum norm"] >= 30 and seen["point"] >= 8, seen


def test_a_family_unbounded_along_an_ideal_wheel_gets_its_minimum_norm_member():
    """An ideal wheel's lateral force is free: a family through it is unbounded (HiGHS finds
    c . lam unbounded along random directions) while its minimum-norm member is one point.
    On the random small scenes of seed 13 (ideal wheels among the ground models) every such
    sample (15) is flagged 1 and its forces are that member (Clarabel's, to 1e-9 of their
    scale; before, forces 3.0 off on a scale of 3.7)."""
    rng = np.random.default_rng(13)
    unbounded = 0
    for model, q, tau in frictional_cases(13, 60):
        ground = model.scene.ground
        if not any(g.model == "ideal_wheels" for g in
                   (ground if isinstance(ground, tuple) else (ground,))):
            continue
        res = model.forward(q, tau)
        if res.status != 0:
            continue
        p = reference_problem(model, q, tau)
        a = np.r_[res.qdd, np.ravel(res.a_obj)]
        A_eq, b_eq, A_ub, bounds, _ = force_set(p, a)
        c = rng.normal(size=A_eq.shape[1])
        if all(linprog(sign * c, A_ub=A_ub if len(A_ub) else None,
                       b_ub=np.zeros(len(A_ub)) if len(A_ub) else None, A_eq=A_eq, b_eq=b_eq,
                       bounds=bounds, method="highs").status != 3 for sign in (1.0, -1.0)):
            continue  # (3: unbounded, so feasible)
        unbounded += 1
        assert res.dependent == 1, res.dependent
        ref = min_norm(p, a)
        assert ref is not None
        F = max(1.0, np.abs(ref).max())
        assert np.abs(engine_lam(res, p) - ref).max() <= 1e-9 * F
    assert unbounded >= 10, unbounded
