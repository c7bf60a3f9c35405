"""With Coulomb friction at the contacts, ``dependent`` 0 promises that the forces are the only
ones Coulomb's law allows with the answered accelerations. Held against SciPy's linear
programs (HiGHS) on rows built apart from the engine
(``test_scenes_contact_friction.reference_problem``): at the engine's accelerations a, every
force lam with M a = f + A^T lam that Coulomb's law and the wheels' bounds allow at w = A a is
a linear set (a normal force >= 0, zero where its contact opens; |lam_t| <= mu lam_n, equal to
-mu lam_n sign(w_t) where it slips; a wheel's force within its bound, at it against its
sliding). Its width along random directions is zero exactly where the forces are unique.
"""

from __future__ import annotations


import numpy as np
import pytest
from scipy.optimize import linprog

from snakecg.scenes.solve import BOX, FREE

from test_scenes_contact_friction import frictional_cases, reference_problem

TOL = 1e-9  # a row's acceleration zero within this of the rows' scale (the engine's too)


def force_set(p, a):
    """The linear set of forces at accelerations a: (A_eq, b_eq, A_ub, b_ub, bounds)."""
    M, f, A = p["M"], p["f"], p["A"]
    m = A.shape[0]
    w = A @ a
    W = max(1e-12, np.abs(A @ np.linalg.solve(M, f)).max(), np.abs(w).max())
    eq, rhs, ub, bounds = [A.T], [M @ a - f], [], [(None, None)] * m

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
    A_ub = np.array(ub) if ub else None
    b_ub = np.zeros(len(ub)) if ub else None
    return np.vstack(eq), np.concatenate(rhs), A_ub, b_ub, bounds


def width(p, a, rng, directions=3):
    """The set's largest width along random unit directions (None where it is empty to
    HiGHS, or unbounded), and the scale of its forces."""
    A_eq, b_eq, A_ub, b_ub, bounds = force_set(p, a)
    m = p["A"].shape[0]
    out, F = 0.0, 0.0
    for _ in range(directions):
        c = rng.normal(size=m)
        c /= np.linalg.norm(c)
        ends = []
        for sign in (1.0, -1.0):
            r = linprog(sign * c, A_ub=A_ub, b_ub=b_ub, A_eq=A_eq, b_eq=b_eq, bounds=bounds,
                        method="highs")
            if r.status != 0:
                return None, F
            ends.append(c @ r.x)
            F = max(F, np.abs(r.x).max())
        out = max(out, abs(ends[0] - ends[1]))
    return out, F


@pytest.fixture(scope="module")
def samples():
    return frictional_cases(20261206, 60)


def test_dependent_is_zero_exactly_where_coulomb_allows_one_force(samples):
    """0: one force (the set a point); 2: a family that Coulomb's piece has beyond the
    inner solve's rows (a contact sticking at its cone's edge, for example), met at least
    once; 1: the inner solve's rows dependent (a family, or a point where the sets pin it)."""
    rng = np.random.default_rng(7)
    seen = {"unique": 0, "family": 0, "flag 2": 0}
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
        assert family == (res.dependent != 0) or res.dependent == 1, (res.dependent, wd, F)
        seen["flag 2"] += res.dependent == 2
    print(seen)
    assert seen["unique"] >= 300 and seen["family"] >= 10 and seen["flag 2"] >= 1, seen
