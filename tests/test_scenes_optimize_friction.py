"""Optimal torques on general scenes with Coulomb friction at the contacts (``mu_contact``),
held against references written apart from snakecg's pieces:

* the pushes (``strongest_push``, ``least_slip_push``) against cvxpy (Clarabel), one conic
  problem per Coulomb state of the contacts (open; stick: both rows still, ``|lam_t| <= mu
  lam_n``; slip either way: the normal row still, ``lam_t = -+ mu lam_n``, the tangent row
  accelerating that way) in the variables (tau, a, lam) on rows from the geometry reference,
  every wheel sticking;
* ``max_sr`` against a brute-force circle of directions (2 joints) over every piece of the
  dense reference (tests/scenes_coulomb_reference.py) and SciPy's SLSQP polishing the best
  ones under the piece's conditions;
* where Coulomb's law has several solutions at the optimum, the reference's solutions there;
* the command line on a frictional scene file: strict JSON.
"""

from __future__ import annotations

import contextlib
import dataclasses
import io
import itertools
import json

import numpy as np
import pytest
import scipy.optimize

import snakecg
from snakecg.scenes.solve import BOX, FREE, UNILATERAL

from scenes_coulomb_reference import Pieces
from scenes_reference import POLYHEDRAL, small_scenes
from test_scenes_contact_friction import reference_problem

cp = pytest.importorskip("cvxpy")


def frictional(rng, count, *, joints=None, max_contacts=3):
    out = []
    while len(out) < count:
        for model0, q, res in small_scenes(rng, 4, POLYHEDRAL, object_friction=False,
                                           need_object=True):
            if len(out) >= count or len(res.contacts) > max_contacts or (
                    joints is not None and model0.n_joints != joints):
                continue
            mu = float(rng.choice([0.2, 0.5, 1.0, 2.0]))
            out.append((snakecg.load(dataclasses.replace(model0.scene, mu_contact=mu)), q))
    return out


def clarabel_push(model, q, objective, d, a_min=None, radius=1.0):
    """The best push over every Coulomb state of the contacts, every wheel sticking."""
    na, ns = model.n_joints, model.n_coordinates
    p = reference_problem(model, q, np.zeros(na))
    A, M = p["A"], p["M"]
    n, m = M.shape[0], A.shape[0]
    N = np.linalg.inv(M[:ns, :ns])[3:, 3:]
    Lc = np.linalg.cholesky(N)
    B = np.zeros((n, na))
    B[3:ns] = np.eye(na)
    opts = [["open", "stick", "slip+", "slip-"] if b["kind"] == UNILATERAL and b["tangent"]
            is not None else ["held", "open"] if b["kind"] == UNILATERAL else ["-"]
            for b in p["blocks"]]
    best = None
    for combo in itertools.product(*opts):
        tau, a, lam = cp.Variable(na), cp.Variable(n), cp.Variable(m)
        cons = [M @ a == B @ tau + A.T @ lam, cp.norm(Lc.T @ tau) <= radius]
        used = set()
        for b, s in zip(p["blocks"], combo):
            r, t = b["row"], b["tangent"]
            used.add(r)
            if b["kind"] == FREE:
                cons.append(A[r] @ a == 0)
            elif b["kind"] == BOX:
                cons += [A[r] @ a == 0, cp.abs(lam[r]) <= b["p"] * (1 - 1e-7)]
            elif s == "held":
                cons += [A[r] @ a == 0, lam[r] >= 0]
            elif s == "open":
                cons += [lam[r] == 0, A[r] @ a >= 0] + ([lam[t] == 0] if t is not None
                                                         else [])
            elif s == "stick":
                cons += [A[r] @ a == 0, A[t] @ a == 0, cp.abs(lam[t]) <= b["mu"] * lam[r]]
            else:
                sg = 1.0 if s == "slip+" else -1.0
                cons += [A[r] @ a == 0, lam[r] >= 0, lam[t] == -sg * b["mu"] * lam[r],
                         sg * (A[t] @ a) >= 0]
            if t is not None:
                used.add(t)
        assert used == set(range(m))
        ao = a[ns:ns + 3]
        if objective == "strongest_push":
            prob = cp.Problem(cp.Maximize(d @ ao), cons)
        else:
            cons.append(d @ ao >= a_min)
            Ls = np.linalg.cholesky(M[:ns, :ns])
            prob = cp.Problem(cp.Minimize(cp.sum_squares(Ls.T @ a[:ns])), cons)
        prob.solve(solver="CLARABEL", tol_gap_abs=1e-10, tol_gap_rel=1e-10, tol_feas=1e-10)
        if prob.status == "optimal":
            v = prob.value
            if best is None or (v > best if objective == "strongest_push" else v < best):
                best = v
    return best


def test_pushes_against_clarabel_over_every_coulomb_state():
    rng = np.random.default_rng(20261208)
    pushed = several = 0
    for model, q in frictional(rng, 8):
        d = rng.normal(size=2)
        d = np.r_[d / np.linalg.norm(d), 0.0]
        ref = clarabel_push(model, q, "strongest_push", d)
        got = model.optimize(q, "strongest_push", direction=d[:2], tau_max=None)
        assert got.status == "optimal", got.reason
        assert got.objective_value == pytest.approx(ref, rel=1e-5, abs=1e-8)
        several += got.uniqueness == "several"
        if ref > 1e-6:
            pushed += 1
            a_min = 0.5 * ref
            ref2 = clarabel_push(model, q, "least_slip_push", d, a_min=a_min)
            got2 = model.optimize(q, "least_slip_push", direction=d[:2], a_min=a_min,
                                  tau_max=None)
            assert got2.status == "optimal", got2.reason
            assert got2.objective_value == pytest.approx(ref2, rel=1e-5, abs=1e-10)
            if got2.uniqueness == "unique":  # the forward solve's own push meets a_min
                assert d @ got2.analysis.a_obj[0] >= a_min * (1 - 1e-6)
    print(pushed, several)
    assert pushed >= 3


def _sr_piece(ref, piece, tau):
    a, _ = ref.solve(piece, tau[None])
    return ref.metrics(a, tau[None])["sr"][0]


def test_max_sr_against_a_brute_force_circle_and_slsqp():
    rng = np.random.default_rng(20261209)
    checked = 0
    for model, q in frictional(rng, 8, joints=2):
        got = model.optimize(q, "max_sr", tau_max=None)
        ref = Pieces(model, q, wheels_stick=True)
        th = np.linspace(0, 2 * np.pi, 20000, endpoint=False)
        # sr is of degree 0 and the contacts' conditions are cones: small torques (the
        # wheels stick there) on every direction
        taus = 1e-3 * ref.boundary(np.stack([np.cos(th), np.sin(th)], axis=1))
        grid, starts = 0.0, []
        for piece in ref.pieces:
            ok = ref.holds(piece, taus)
            if not ok.any():
                continue
            a, _ = ref.solve(piece, taus[ok])
            v = ref.metrics(a, taus[ok])["sr"]
            i = int(np.argmax(v))
            grid = max(grid, v[i])
            starts.append((v[i], piece, taus[ok][i]))
        polished = grid
        step = 2 * np.pi / len(th)
        for _, piece, t0 in sorted(starts, key=lambda s: -s[0])[:6]:
            # in whitened torques u (tau = 1e-3 boundary(u)): a finer circle near the start,
            # then SLSQP on |u| = 1 under the piece's conditions
            s_, V = np.linalg.eigh(ref.N)
            u0 = np.sqrt(s_) * (V.T @ t0) / 1e-3
            c0 = np.arctan2(u0[1], u0[0]) + np.linspace(-step, step, 20001)
            tt = 1e-3 * ref.boundary(np.stack([np.cos(c0), np.sin(c0)], axis=1))
            ok = ref.holds(piece, tt)
            if ok.any():
                a, _ = ref.solve(piece, tt[ok])
                polished = max(polished, ref.metrics(a, tt[ok])["sr"].max())

            def tau_of(u):
                return 1e-3 * ref.boundary(u[None])[0]

            cons = [{"type": "eq", "fun": lambda u: u @ u - 1.0},
                    {"type": "ineq", "fun": lambda u, pc=piece: (
                        lambda v, sc: v / sc)(*ref.slacks(pc, tau_of(u)[None]))[0]}]
            sol = scipy.optimize.minimize(lambda u, pc=piece: -_sr_piece(ref, pc, tau_of(u)),
                                          u0, method="SLSQP", constraints=cons,
                                          options={"ftol": 1e-15, "maxiter": 500})
            if sol.success and ref.holds(piece, tau_of(sol.x)[None], tol=1e-8)[0]:
                polished = max(polished, -sol.fun)
        if grid <= 1e-9:
            assert got.status == "infeasible" or got.objective_value <= 1e-9
            continue
        assert got.status == "optimal", got.reason
        assert got.objective_value >= grid - 1e-9
        assert got.objective_value == pytest.approx(polished, abs=1e-6)
        # the value is one of the reference's solutions at the returned torque
        sols = ref.solutions_at(got.tau)
        assert any(abs(s[1]["sr"] - got.objective_value) <= 1e-6 for s in sols)
        if got.uniqueness == "several" and ref.singular == 0:
            assert len(sols) >= 2
        checked += 1
    assert checked >= 5


def test_several_solutions_at_the_optimum_are_flagged_with_the_reference_s_count():
    """A torque where Coulomb's law has two solutions: the reference finds them; the
    optimum's reason and uniqueness say so (never one picked silently)."""
    rng = np.random.default_rng(0)
    seen = 0
    for model, q in frictional(rng, 12, joints=2, max_contacts=4):
        ref = Pieces(model, q)
        for obj, kw in (("max_sr", {}), ("strongest_push", {"direction": [1.0, 0.0]})):
            got = model.optimize(q, obj, tau_max=None, **kw)
            if got.status != "optimal":
                continue
            sols = ref.solutions_at(got.tau)
            ns = model.n_coordinates
            values = [s[1]["sr"] if obj == "max_sr" else s[0][ns] for s in sols]
            # the optimum is the value of one of the reference's solutions at its torque
            assert any(abs(v - got.objective_value) <= 1e-6 for v in values), (values, got)
            if got.uniqueness == "several":
                seen += 1
                assert len(sols) >= 2 or ref.singular > 0
                assert "solutions" in got.reason
            elif got.uniqueness == "unique" and ref.singular == 0:
                assert len(sols) == 1
    assert seen >= 1


def test_command_line_on_a_frictional_scene_is_strict_json(tmp_path):
    from snakecg import cli

    scene = tmp_path / "rough.toml"
    scene.write_text("""[robot]
joints = 3
length = 0.15
mass = 1.0
inertia = 0.002

[ground]
model = "wheels"
mu = 0.3

[contacts]
mu = 0.5

[[object]]
shape = "box"
size = [0.08, 0.06]
mass = 1.5
touching = { link = 1, offset = 0.075, side = "left" }
""")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = cli.main(["optimize", "max-sr", "--scene", str(scene), "--q",
                         "0,0,0,0.6,-0.6,0.6", "--json"])

    def refuse(name):
        raise ValueError(f"not strict JSON: {name}")

    d = json.loads(out.getvalue(), parse_constant=refuse)
    assert code == (0 if d["status"] == "optimal" else 1)
    assert d["status"] == "optimal" and 0 < d["objective_value"] <= 1
    assert d["uniqueness"] in ("unique", "several", "not_certified")
    assert all(c["mu"] == 0.5 for c in d["analysis"]["contacts"])
