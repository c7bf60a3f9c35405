"""The count of Coulomb solutions that ``forward`` reports with contact friction (its
``solutions`` and ``uniqueness``), held against a dense NumPy enumeration written apart from
the engine's (``snakecg/engine/scene_friction_states.c``), at (near) zero torque, at ordinary
torques, and under a scaling of the whole problem.

The reference solves every piece's equations in (a, lam) densely
(``scenes_coulomb_reference.piece_system``), keeps a piece where Coulomb's conditions (and
the wheels' sets) hold within ``TOL`` of its own scales, and merges two solutions whose
accelerations agree within ``SAME`` of its own floor. Its scales are the problem's data, not
the answer: the force that would stop each row's free acceleration alone and the wheels'
bounds (forces), the rows' free accelerations and what a force of that scale gives on its own
row (row accelerations), and the largest coordinate acceleration a force of that scale gives
on any one row (accelerations, in plain coordinates, where the engine works in the inertia's
metric). At a torque of 1e-16 on a scene whose wheels' bounds are of order 1, every
solution's accelerations are ~1e-16: one solution at the data's resolution.
"""

from __future__ import annotations

import dataclasses
import itertools

import numpy as np
import pytest

import snakecg
from snakecg.scenes.solve import BOX, UNILATERAL

from scenes_coulomb_reference import options, piece_system
from scenes_reference import POLYHEDRAL, small_scenes
from test_scenes_contact_friction import reference_problem

TOL = 1e-9    # a condition holds within this of its scale
SAME = 1e-7   # two solutions are one within this of the accelerations' floor


def reference_count(p):
    """(distinct solutions, singular pieces) of Coulomb's law on the dense problem ``p``."""
    M, f, A = p["M"], p["f"], p["A"]
    m, n = A.shape
    MiA = np.linalg.solve(M, A.T)             # a force 1 on row i: accelerations MiA[:, i]
    a_free = np.linalg.solve(M, f)
    own = np.einsum("ij,ji->i", A, MiA)       # row i's acceleration per unit of its force
    free = A @ a_free
    bounds = [abs(b["p"]) for b in p["blocks"] if b["kind"] == BOX]
    F = max([float(np.max(np.abs(free) / own))] + bounds)
    F = F if F > 0 else 1.0
    W = max(float(np.abs(free).max()), float(own.max()) * F)
    W = W if W > 0 else 1.0
    floor = max(float(np.abs(a_free).max()), float(np.abs(MiA).max()) * F)
    sols, singular = [], 0
    for combo in itertools.product(*options(p)):
        K, rhs = piece_system(p, combo)
        sv = np.linalg.svd(K, compute_uv=False)
        if sv[-1] <= 1e-12 * sv[0]:
            singular += 1
            continue
        x = np.linalg.solve(K, rhs)
        a, lam = x[:n], x[n:]
        w = A @ a
        ok = True
        for b, s in zip(p["blocks"], combo):
            r, t = b["row"], b["tangent"]
            if b["kind"] == UNILATERAL:
                ok &= lam[r] >= -TOL * F and w[r] >= -TOL * W
                if s == "stick" and t is not None:
                    ok &= abs(lam[t]) <= b["mu"] * lam[r] + TOL * F
                elif s == "slip+":
                    ok &= w[t] >= -TOL * W
                elif s == "slip-":
                    ok &= w[t] <= TOL * W
            elif b["kind"] == BOX and b["p"] > 0:
                if s == "stick":
                    ok &= abs(lam[r]) <= b["p"] + TOL * F
                elif s == "+":  # the force +p: the row slides back
                    ok &= w[r] <= TOL * W
                elif s == "-":
                    ok &= w[r] >= -TOL * W
        if ok and not any(np.abs(a - a2).max() <= SAME * max(floor, np.abs(a).max(),
                                                               np.abs(a2).max())
                          for a2 in sols):
            sols.append(a)
    return len(sols), singular


def frictional(seed, count, models=POLYHEDRAL, *, pushes=False):
    """``count`` small scenes with contact friction (pegs or objects touching the links, no
    object rubbing the ground), each with a random torque direction; ``pushes``: an object
    in each, up to 4 contacts, no direction (tests/test_scenes_optimize_friction.py's)."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        for model0, q, res in small_scenes(rng, 4, models, object_friction=False,
                                           need_object=pushes):
            if (len(out) >= count or len(res.contacts) > (4 if pushes else 3)
                    or not model0.scene.objects + model0.scene.obstacles):
                continue
            mu = float(rng.choice([0.2, 0.5, 1.0, 2.0]))
            model = snakecg.load(dataclasses.replace(model0.scene, mu_contact=mu))
            out.append((model, q, None if pushes else rng.normal(size=model.n_joints)))
    return out


def scaled(model, k):
    """The model with every ground coefficient times k (the wheels' bounds scale with k)."""
    sc = model.scene
    grounds = sc.ground if isinstance(sc.ground, tuple) else (sc.ground,)
    grounds = tuple(dataclasses.replace(g, mu=g.mu * k, mu_forward=g.mu_forward * k,
                                        mu_backward=g.mu_backward * k,
                                        mu_lateral=g.mu_lateral * k) for g in grounds)
    return snakecg.load(dataclasses.replace(
        sc, ground=grounds if isinstance(sc.ground, tuple) else grounds[0]))


@pytest.mark.parametrize("size", [0.0, 1e-300, 1e-16, 1e-12])
def test_the_count_at_near_zero_torque_is_the_reference_s(size):
    """At a torque of 0, 1e-300, 1e-16, 1e-12 the solutions' accelerations (~ the torque) are
    one at the wheels' bounds' scale: rounding between the pieces' solutions is not counted
    as several solutions."""
    compared = 0
    for model, q, u in frictional(20261211, 24):
        tau = size * u
        res = model.forward(q, tau)
        count, singular = reference_count(reference_problem(model, q, tau))
        if singular:  # (a family of solutions the engine cannot count: negated)
            assert abs(res.solutions) == count, (size, res.solutions, count)
            continue
        assert res.solutions == count, (size, res.solutions, count)
        assert res.uniqueness == ("unique" if count == 1 else "several")
        compared += 1
    assert compared >= 8, compared


def _counts(model, q, taus):
    """The engine's counts at each torque (one batched forward solve)."""
    return np.atleast_1d(model.forward(np.tile(q, (len(taus), 1)), taus).solutions)


def test_the_count_at_ordinary_torques_is_the_reference_s():
    """At ordinary torques (scales 0.1-5, 24 directions a scene) the floor changes nothing:
    each count is the reference's, several solutions included."""
    rng = np.random.default_rng(7)
    compared = several = 0
    for model, q, _ in frictional(20261212, 30):
        taus = rng.normal(size=(24, model.n_joints)) * rng.choice([0.1, 1.0, 5.0], (24, 1))
        for tau, got in zip(taus, _counts(model, q, taus)):
            count, singular = reference_count(reference_problem(model, q, tau))
            assert got == count if not singular else abs(got) == count, (got, count)
            compared += not singular
            several += count >= 2
    assert compared >= 300 and several >= 3, (compared, several)


def test_the_count_does_not_move_when_the_problem_is_scaled():
    """Torques and the ground's coefficients (so the wheels' bounds) times 1e-6 or 1e6: the
    same problem in other units, the same count; without bounded wheels the torques alone,
    down to 1e-300. Each count the reference's at the unit scale."""
    rng = np.random.default_rng(8)
    several = 0
    for models, scales in ((POLYHEDRAL, (1e-6, 1e6)),
                           (("frictionless", "ideal_wheels"), (1e-300, 1e-16, 1e6))):
        for model, q, _ in frictional(20261213, 30, models=models):
            taus = rng.normal(size=(48, model.n_joints))
            base = _counts(model, q, taus)
            for k in scales:
                other = scaled(model, k) if models == POLYHEDRAL else model
                np.testing.assert_array_equal(_counts(other, q, k * taus), base, err_msg=k)
            for tau, got in zip(taus, base):
                count, singular = reference_count(reference_problem(model, q, tau))
                assert got == count if not singular else abs(got) == count, (got, count)
                several += count >= 2
    assert several >= 5, several


def test_a_strongest_push_of_zero_at_about_zero_torque_counts_the_reference_s_solutions():
    """``optimize`` reports the forward solve's count at its optimum: where the strongest push
    is 0 at a torque of ~1e-12 or less, that count is the reference's (one solution there,
    where rounding between the pieces' solutions was counted as 64)."""
    seen = 0
    for model, q, _ in frictional(5, 4, pushes=True):
        for d in ([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]):
            got = model.optimize(q, "strongest_push", direction=d, tau_max=None)
            if got.status != "optimal" or not np.abs(got.tau).max() < 1e-9:
                continue
            count, singular = reference_count(reference_problem(model, q, got.tau))
            if singular:
                continue
            assert abs(got.objective_value) <= 1e-9
            assert got.uniqueness == ("unique" if count == 1 else "several"), (
                got.uniqueness, count)
            seen += 1
    assert seen >= 2, seen
