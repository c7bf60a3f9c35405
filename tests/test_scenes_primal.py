"""A warm start's piece solved in the primal (snakecg/engine/scene_primal.c): Newton on the
coordinates' velocities with the held rows as equalities, entered from the caller's pieces in
scene_solve.c's ``core_scene_solve_s`` (a time step's, a forward batch's neighbour's), its
answer kept where the KKT conditions hold, else the dual path's.

Held to references written here apart:

* the step problems of the pegs run (10 joints, 10 pegs, Coulomb ground; 13 coordinates,
  22-33 rows), each solved by Clarabel (cvxpy) in the same primal statement: minimise
  1/2 |V - V*|_M^2 + sum s_i |A_i V + c_i| over the discs, subject to A_c V + c_c >= 0 on the
  contacts; V to 1e-9 of its scale, the forces against Clarabel's duals (the contacts' and
  the discs' second-order cones) where the face's rows are independent (NumPy's SVD), and
  Newton's stationarity M V = f + A^T lam checked densely;
* random problems with every kind of row it treats (an ideal wheel, contacts with offsets, a
  bounded wheel sliding or stuck, Coulomb discs) from their own pieces: the same to 1e-12 as
  their cold solves, V to 1e-9 of Clarabel's polished primal;
* the 10-joint statically indeterminate forward scene (33 rows on 19 coordinates), from a
  neighbouring torque's pieces and from the sample's own: the accelerations against
  Clarabel's primal, the forces' KKT conditions checked densely;
* the fallback: from wrong pieces (a sliding disc held, a held contact opened) the primal's
  answer fails its checks and the dual path's is returned, the same as Clarabel's; from the
  right pieces with every sliding force's start reversed the primal still answers;
* whole runs with the primal piece and without it (``core_scene_primal``'s switch): the pegs
  run with impacts and the paper's push agree to 1e-9; most of the pegs run's steps are the
  primal's, none of the push's (its rows never outnumber its coordinates: the dual's
  unknowns are then the fewer, and it keeps them).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import snakecg
from snakecg.scenes.solve import BOX, DISC, FREE, INFO, UNILATERAL
from snakecg.scenes.stepping import GAP_BAND, _Stepper
from snakecg.simulate import serpenoid_controller

from scenes_reference import dense_problem, indeterminate_scene, kkt_violations, pegs_row

H = 1e-3


def _counts(core):
    """The primal piece's tries and answers (this thread's) since the last read."""
    c = np.zeros(2)
    core.scene_primal(-1, c.ctypes.data)
    return c


def _solve(core, p, frm):
    """core_scene_solve_s on the problem p from the pieces frm (3 per block, or None)."""
    n, m, nb = p["n"], p["m"], p["nb"]
    out = dict(lam=np.zeros(m), a=np.zeros(n), w=np.zeros(m), state=np.zeros(nb),
               info=np.zeros(len(INFO)))
    M, f, A = (np.ascontiguousarray(p[k], dtype=float) for k in ("M", "f", "A"))
    off = np.ascontiguousarray(p["c"], dtype=float)
    kind, start = (np.ascontiguousarray(p[k], dtype=np.int64) for k in ("kind", "start"))
    par = np.ascontiguousarray(p["par"], dtype=float)
    fr = None if frm is None else np.ascontiguousarray(frm, dtype=float)
    code = core.scene_solve_s(n, m, nb, M.ctypes.data, f.ctypes.data, A.ctypes.data,
                              off.ctypes.data, kind.ctypes.data, start.ctypes.data,
                              par.ctypes.data, 200000, None if fr is None else fr.ctypes.data,
                              out["lam"].ctypes.data, out["a"].ctypes.data,
                              out["w"].ctypes.data, out["state"].ctypes.data,
                              out["info"].ctypes.data)
    assert code == 0
    out["info"] = dict(zip(INFO, out["info"]))
    return out


def _primal_reference(p, tol=1e-11):
    """Clarabel's solution of the primal: min 1/2 |V - V*|_M^2 + sum_discs s |A_i V + c_i|
    s.t. A_c V + c_c >= 0 (contacts), A_f V + c_f = 0 (ideal wheels); the forces from the
    constraints' duals (a disc's: its cone's, t >= |w_i| with cost s t)."""
    import cvxpy as cp

    M, f, A, c = p["M"], p["f"], p["A"], p["c"]
    n = len(f)
    V = cp.Variable(n)
    L = np.linalg.cholesky(M)
    Vstar = np.linalg.solve(M, f)
    cost = 0.5 * cp.sum_squares(L.T @ (V - Vstar))
    cons, where = [], []
    for kind, s, par in zip(p["kind"], p["start"], p["par"].reshape(-1, 3)):
        if kind == UNILATERAL:
            cons.append(A[s] @ V + c[s] >= 0)
            where.append((kind, s))
        elif kind == FREE:
            cons.append(A[s] @ V + c[s] == 0)
            where.append((kind, s))
        elif kind == BOX:  # p0 |w| as p0 t, t >= w, t >= -w
            t = cp.Variable()
            cost += par[0] * t
            cons += [t - (A[s] @ V + c[s]) >= 0, t + (A[s] @ V + c[s]) >= 0]
            where += [(kind, s), (-kind, s)]
        elif kind == DISC:
            t = cp.Variable()
            cost += par[0] * t
            cons.append(cp.SOC(t, A[s:s + 2] @ V + c[s:s + 2]))
            where.append((kind, s))
        else:
            raise AssertionError("these scenes have contacts, wheels and discs only")
    prob = cp.Problem(cp.Minimize(cost), cons)
    for t in (tol, 1e-9):  # retried looser where Clarabel stops short ("inaccurate")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            prob.solve(solver="CLARABEL", tol_gap_abs=t, tol_gap_rel=t, tol_feas=t,
                       max_iter=400)
        if prob.status == "optimal":
            break
    assert prob.status == "optimal"
    lam = np.zeros(len(c))
    for con, (kind, s) in zip(cons, where):
        if abs(kind) == BOX:  # the force: the second cone's dual less the first's
            lam[s] += float(con.dual_value) * (1.0 if kind < 0 else -1.0)
        elif kind == DISC:
            lam[s:s + 2] = np.ravel(con.dual_value[1])
        elif kind == UNILATERAL:
            lam[s] = float(con.dual_value)
        else:
            lam[s] = -float(con.dual_value)
    return V.value, lam


def _polished(p, V0, lam0, iters=30):
    """Clarabel's solution polished on its piece (each block's by complementarity: a disc
    sliding where its motion |A_i V0 + c_i| is the larger relative to the rows' scale than
    its force's slack to the disc's edge, a contact held where its dual is the larger
    relative to the forces' than its motion); Newton in NumPy on the piece's primal,
    min 1/2 |V - V*|_M^2 + sum s_i |w_i| over the sliding discs s.t. w = A V + c = 0 on the
    held rows (the KKT system by least squares: dependent rows allowed). Returns V and the
    forces (lam_H the KKT multipliers, a sliding disc's -s w / |w|)."""
    M, f, A, c = p["M"], p["f"], p["A"], p["c"]
    w0 = A @ V0 + c
    W, F = max(np.abs(w0).max(), 1e-300), max(np.abs(lam0).max(), 1e-300)
    held, slide, fixed = [], [], np.zeros(len(c))
    for kind, s, par in zip(p["kind"], p["start"], p["par"].reshape(-1, 3)):
        if kind == BOX and abs(w0[s]) / W > 1 - abs(lam0[s]) / par[0]:
            fixed[s] = -par[0] * np.sign(w0[s])  # a sliding box: its force at the bound
            continue
        # (the piece by complementarity: whichever of the motion and the slack in the
        # force's set is the larger, relative to its scale)
        if kind == DISC and np.hypot(*w0[s:s + 2]) / W > 1 - np.hypot(*lam0[s:s + 2]) / par[0]:
            slide.append((s, par[0]))
        elif kind in (DISC, FREE, BOX) or (kind == UNILATERAL and lam0[s] / F > w0[s] / W):
            held += [s, s + 1] if kind == DISC else [s]
    AH = A[held]
    V, n = V0.copy(), len(f)
    Vstar = np.linalg.solve(M, f)

    def phi(V):
        return 0.5 * (V - Vstar) @ M @ (V - Vstar) - fixed @ (A @ V + c) + sum(
            rad * np.linalg.norm(A[s:s + 2] @ V + c[s:s + 2]) for s, rad in slide)

    for it in range(iters):
        g = M @ V - f - A.T @ fixed
        Hs = M.copy()
        for s, rad in slide:
            wi = A[s:s + 2] @ V + c[s:s + 2]
            u = wi / np.linalg.norm(wi)
            g += rad * A[s:s + 2].T @ u
            P = np.eye(2) - np.outer(u, u)
            Hs += rad / np.linalg.norm(wi) * A[s:s + 2].T @ P @ A[s:s + 2]
        K = np.block([[Hs, AH.T], [AH, np.zeros((len(held), len(held)))]])
        rhs = np.r_[-g, -(AH @ V + c[held])]
        sol = np.linalg.lstsq(K, rhs, rcond=1e-13)[0]
        t = 1.0  # (the first step onto the held rows' equations, then halved while phi rises)
        while it > 0 and t > 1e-6 and phi(V + t * sol[:n]) > phi(V) + 1e-15 * abs(phi(V)):
            t *= 0.5
        V = V + t * sol[:n]
        mu = -sol[n:]
        if np.abs(sol[:n]).max() <= 1e-15 * np.abs(V).max():
            break
    lam = fixed.copy()
    lam[held] = mu
    for s, rad in slide:
        wi = A[s:s + 2] @ V + c[s:s + 2]
        lam[s:s + 2] = -rad * wi / np.linalg.norm(wi)
    return V, lam


def _cold_then_from_its_pieces(core, p, kind, start):
    """Problem p solved cold, then again from that solve's own pieces (the primal piece on):
    both answers and whether the primal answered the second."""
    core.scene_primal(1, None)
    cold = _solve(core, p, None)
    assert cold["info"]["status"] == 0
    _counts(core)
    out = _solve(core, p, _pieces_of(cold, kind, start))
    _, ans = _counts(core)
    return cold, out, ans


def _pieces_of(cold, kind, start):
    """A solve's pieces as a start for another: each block's state and forces (n_b x 3)."""
    frm = np.zeros((len(kind), 3))
    frm[:, 0] = cold["state"]
    for b, (k, s) in enumerate(zip(kind, start)):
        frm[b, 1:3 if k >= DISC else 2] = cold["lam"][s:s + (2 if k >= DISC else 1)]
    return frm


def test_every_kind_it_treats_on_random_problems(pegs):
    """Random problems with rows of every kind the primal treats (an ideal wheel, contacts, a
    bounded wheel, Coulomb discs; more rows than coordinates) and offsets, each solved cold,
    then from its own pieces: the primal answers most, the same as the cold solve (1e-12) and
    as Clarabel's primal polished on its piece (V to 1e-9, the forces where unique)."""
    rng = np.random.default_rng(5)
    core = pegs[0].core  # (any general scene's engine: the problems are given whole)
    answered = 0
    for _ in range(12):
        n = 6
        kind = np.array([FREE, UNILATERAL, UNILATERAL, BOX, DISC, DISC, DISC])
        start = np.array([0, 1, 2, 3, 4, 6, 8])
        m = 10
        B = rng.normal(size=(n, n))
        M = B @ B.T + n * np.eye(n)
        A = rng.normal(size=(m, n))
        par = np.zeros((len(kind), 3))
        par[3:, 0] = rng.uniform(0.05, 0.3, 4)  # small sets: the box and discs slide
        p = dict(n=n, m=m, nb=len(kind), M=M, f=rng.normal(size=n), A=A,
                 c=np.r_[0.0, rng.uniform(-0.2, 0.2, 2), np.zeros(7)], kind=kind,
                 start=start, par=par.reshape(-1))
        cold, out, ans = _cold_then_from_its_pieces(core, p, kind, start)
        answered += int(ans)
        np.testing.assert_allclose(out["a"], cold["a"], rtol=0,
                                   atol=1e-12 * np.abs(cold["a"]).max())
        V0, lam0 = _primal_reference(p)
        V, lam = _polished(p, V0, lam0)
        np.testing.assert_allclose(out["a"], V, rtol=0, atol=1e-9 * np.abs(V).max())
        r = p["M"] @ V0 - p["f"] - p["A"].T @ lam0  # (Clarabel's duals' signs)
        assert np.abs(r).max() <= 1e-6 * np.abs(p["f"]).max()
        if ans and out["info"]["dependent"] == 0:
            np.testing.assert_allclose(out["lam"], lam, rtol=0, atol=1e-9 * np.abs(lam).max())
    assert answered >= 6


def test_sliding_discs_apart_and_zero_rows_on_random_problems(pegs):
    """Sliding discs whose rows are not one run (a stuck disc and a contact between them:
    their columns gathered apart), contacts open (zero rows, w from Z) or held, from each
    problem's own pieces: the primal's answers the same as the cold solve (1e-12), V to 1e-9
    of Clarabel's primal polished on its piece, and every row's w equal to A V + c (NumPy,
    1e-12 of its scale) for the forces to match the accelerations."""
    rng = np.random.default_rng(11)
    core = pegs[0].core
    apart = 0
    kind = np.array([DISC, DISC, DISC, UNILATERAL, DISC, UNILATERAL])
    start = np.array([0, 2, 4, 6, 7, 9])
    n, m = 7, 10
    for _ in range(16):
        B = rng.normal(size=(n, n))
        M = B @ B.T + n * np.eye(n)
        A = rng.normal(size=(m, n))
        par = np.zeros((len(kind), 3))
        par[[0, 2, 4], 0] = rng.uniform(0.05, 0.3, 3)  # small discs: sliding
        par[1, 0] = 50.0  # a large one: stuck
        c = np.zeros(m)
        c[[6, 9]] = rng.uniform(-0.5, 0.5, 2)
        p = dict(n=n, m=m, nb=len(kind), M=M, f=rng.normal(size=n), A=A, c=c, kind=kind,
                 start=start, par=par.reshape(-1))
        cold, out, ans = _cold_then_from_its_pieces(core, p, kind, start)
        sliding = [b for b in range(len(kind)) if kind[b] == DISC and out["state"][b] == 2]
        rows = np.concatenate([[start[b], start[b] + 1] for b in sliding]) if sliding else []
        if ans and len(rows) and rows[-1] - rows[0] + 1 > len(rows):
            apart += 1
        np.testing.assert_allclose(out["a"], cold["a"], rtol=0,
                                   atol=1e-12 * np.abs(cold["a"]).max())
        w = A @ out["a"] + c
        np.testing.assert_allclose(out["w"], w, rtol=0, atol=1e-12 * np.abs(w).max())
        V0, lam0 = _primal_reference(p)
        V, lam = _polished(p, V0, lam0)
        np.testing.assert_allclose(out["a"], V, rtol=0, atol=1e-9 * np.abs(V).max())
        if ans and out["info"]["dependent"] == 0:
            np.testing.assert_allclose(out["lam"], lam, rtol=0, atol=1e-9 * np.abs(lam).max())
    assert apart >= 8  # (12 of the 16 with this seed)


def _step_problems(model, run, ks, steps=1):
    """The solve's problem of the steps at samples ks of a run (the step's M V + h (tau -
    bias) at the end's rows, the sets times h, the gaps over h) and its warm pieces, after
    ``steps`` steps from the sample (two or more: the pieces' forces extrapolated from the
    last two steps'; ``own``: the last step's own forces, ``before``: the step's before)."""
    out = []
    for k in ks:
        st = _Stepper(model, run.tolerance, np.zeros(3 * model.scene.n_objects))
        st.x[:] = np.concatenate((run.q[k], run.q_obj[k].reshape(-1)))
        st.V[:] = np.concatenate((run.v[k], run.v_obj[k].reshape(-1)))
        assert st.call(0.0) == 0
        mc, before = st.engine.mcap, None
        for _ in range(steps):  # its pieces: the next step's start
            before = st.pieces[3 * mc:6 * mc].copy()
            status = st.call(H)
            assert status == 0 or steps > 1  # (refused at an onset: that sample left out)
        if status != 0:
            continue
        m, nb, ns = int(st.out[2]), int(st.out[3]), st.ns
        f = st.M @ st.V
        f[:ns] -= H * np.asarray(model.bias_forces(st.x[:ns], st.V[:ns])).reshape(-1)
        c = np.zeros(m)
        for con in st.rows().contacts:
            c[con.row] = con.gap / H if abs(con.gap) > GAP_BAND * run.tolerance else 0.0
        out.append(dict(n=st.n, m=m, nb=nb, M=st.M.copy(), f=f, A=st.A[:m].copy(), c=c,
                        kind=st.kind[:nb].copy(), start=st.start[:nb].copy(),
                        par=(st.par[:nb] * H).copy(),
                        frm=st.pieces[:3 * nb].reshape(nb, 3) * np.array([1.0, H, H]),
                        own=st.pieces[3 * mc:3 * mc + 3 * nb].reshape(nb, 3).copy(),
                        before=before, nc=int(st.out[1])))
    return out


@pytest.fixture(scope="module")
def pegs():
    scene, model, q0 = pegs_row()
    gait = serpenoid_controller(model, amplitude=0.5, frequency=1.0, phase_lag=2 * np.pi / 5,
                                kp=10.0, kd=0.3, tau_max=None)
    run = model.simulate(q0, 0.4, tau=gait, dt=H)
    assert run.status == "completed"
    return model, q0, gait, run


@pytest.fixture(scope="module")
def step_problems(pegs):
    model, _, _, run = pegs
    return model, _step_problems(model, run, range(7, len(run.t) - 1, 23))


def _face_independent(p, out):
    """The rows without acceleration (held, or on a set's limit without sliding): linearly
    independent (their forces unique), by NumPy's SVD."""
    w = out["w"]
    W = max(1.0, np.abs(w).max())
    rows = []
    for kind, s in zip(p["kind"], p["start"]):
        k = 2 if kind >= DISC else 1
        if np.abs(w[s:s + k]).max() <= 1e-9 * W:
            rows += list(range(s, s + k))
    if not rows:
        return True
    sv = np.linalg.svd(p["A"][rows], compute_uv=False)
    return sv.min() > 1e-8 * sv.max()


def test_step_problems_against_clarabels_primal(step_problems):
    """Each step's solve from its pieces: answered by the primal piece (most of them), V to
    1e-9 of its scale and the forces where unique against Clarabel's primal and duals."""
    model, problems = step_problems
    core = model.core
    core.scene_primal(1, None)
    _counts(core)
    answered = unique = dependent = 0
    for p in problems:
        out = _solve(core, p, p["frm"])
        tries, ans = _counts(core)
        assert tries == 1
        answered += int(ans)
        assert out["info"]["status"] == 0
        V0, lam0 = _primal_reference(p)
        V, lam = _polished(p, V0, lam0)
        scale, F = np.abs(V).max(), np.abs(lam).max()
        np.testing.assert_allclose(V, V0, rtol=0, atol=1e-5 * scale)  # the same solution
        np.testing.assert_allclose(out["a"], V, rtol=0, atol=1e-9 * scale)
        # the references' stationarity, M V = f + A^T lam (Clarabel's duals' signs)
        for VV, ll, tol in ((V0, lam0, 1e-6), (V, lam, 1e-12), (out["a"], out["lam"], 1e-12)):
            r = p["M"] @ VV - p["f"] - p["A"].T @ ll
            assert np.abs(r).max() <= tol * np.abs(p["f"]).max()
        if _face_independent(p, out):
            unique += 1
            assert out["info"]["dependent"] == 0
            np.testing.assert_allclose(out["lam"], lam, rtol=0, atol=1e-9 * F)
            np.testing.assert_allclose(out["lam"], lam0, rtol=0, atol=1e-4 * F)
        else:
            dependent += int(out["info"]["dependent"] == 1)
    assert answered >= 0.8 * len(problems) and unique >= len(problems) // 2
    assert dependent >= 1  # statically indeterminate steps among them (minimum-norm forces)


def test_primal_and_dual_paths_agree_on_the_steps(step_problems):
    """The same problems with the primal piece switched off (the dual path from the same
    pieces): accelerations to 1e-12 relative, forces to 1e-9, the same pieces, status,
    dependent flag, passes and sweeps."""
    model, problems = step_problems
    core = model.core
    for p in problems:
        core.scene_primal(1, None)
        on = _solve(core, p, p["frm"])
        core.scene_primal(0, None)
        off = _solve(core, p, p["frm"])
        core.scene_primal(1, None)
        scale = np.abs(off["a"]).max()
        np.testing.assert_allclose(on["a"], off["a"], rtol=0, atol=1e-12 * scale)
        F = np.abs(off["lam"]).max()
        np.testing.assert_allclose(on["lam"], off["lam"], rtol=0, atol=1e-9 * F)
        np.testing.assert_array_equal(on["state"], off["state"])
        for k in ("status", "dependent", "passes", "sweeps"):
            assert on["info"][k] == off["info"][k], k
        for k in ("primal", "dual", "complementarity"):
            assert on["info"][k] <= 1e-9


def test_a_step_from_the_last_two_steps_forces_extrapolated(pegs):
    """After two steps of the same length the next step starts from the last two steps' forces
    extrapolated linearly (2 lam - lam_before on each block whose state stayed; scene_step.c):
    the ground's discs so, and that step's solve from them the same as from the last step's
    own forces and from scratch (1e-12 of V), as Clarabel's primal (1e-6: its own accuracy)
    and, where that polished on Clarabel's piece stays within it (the piece guessed right),
    as the polished one (1e-9); the primal piece answers most."""
    model, _, _, run = pegs
    core = model.core
    core.scene_primal(1, None)
    _counts(core)
    problems = _step_problems(model, run, range(11, len(run.t) - 3, 29), steps=2)
    moved = polished = 0
    for p in problems:
        nb, nc = p["nb"], p["nc"]
        own, before = p["own"][nc:], p["before"][3 * nc:3 * nb].reshape(-1, 3)
        same = before[:, 0] == own[:, 0]  # (the ground's blocks: the same at every step)
        assert same.sum() >= nb - nc - 1
        want = np.where(same[:, None], own + (own - before), own)[:, 1:] * H
        np.testing.assert_array_equal(p["frm"][nc:, 1:], want)
        moved += int(np.any(p["frm"][nc:, 1:] != own[:, 1:] * H))
        V0, lam0 = _primal_reference(p)
        V = _polished(p, V0, lam0)[0]
        scale = np.abs(V0).max()
        good = np.abs(V - V0).max() <= 1e-6 * scale
        polished += int(good)
        outs = [_solve(core, p, frm) for frm in (p["frm"], p["own"] * np.array([1.0, H, H]))]
        outs.append(_solve(core, p, None))
        for out in outs:
            assert out["info"]["status"] == 0
            np.testing.assert_allclose(out["a"], outs[-1]["a"], rtol=0, atol=1e-12 * scale)
            np.testing.assert_allclose(out["a"], V0, rtol=0, atol=1e-6 * scale)
            if good:
                np.testing.assert_allclose(out["a"], V, rtol=0, atol=1e-9 * scale)
            for k in ("primal", "dual", "complementarity"):
                assert out["info"][k] <= 1e-9
    tries, answered = _counts(core)
    assert moved == len(problems) >= 5 and answered >= 0.7 * tries
    assert polished >= 0.8 * len(problems)


def test_wrong_pieces_fall_back_to_the_dual_path(step_problems):
    """From wrong pieces (a sliding disc held, a pushing contact opened) the primal's answer
    fails its KKT checks and the dual path answers: the same V as Clarabel's; from the right
    pieces with every sliding force's start reversed the primal answers (only its Newton's
    start moved), the same V."""
    model, problems = step_problems
    core = model.core
    core.scene_primal(1, None)

    def held_rows(p):
        return int(np.sum(np.where(p["kind"] == DISC, 2, 1)[p["frm"][:, 0] == 0]))

    p = next(p for p in problems  # (few held rows: the primal tries this piece and the next)
             if held_rows(p) + 2 <= p["n"] // 2 and np.any(p["frm"][:, 0] == 2)
             and np.any((p["kind"] == UNILATERAL) & (p["frm"][:, 0] == 0)))
    V = _polished(p, *_primal_reference(p))[0]
    scale = np.abs(V).max()
    _counts(core)
    held = p["frm"].copy()  # a sliding disc held at zero force: its force leaves the disc
    held[np.flatnonzero((p["kind"] == DISC) & (p["frm"][:, 0] == 2))[0]] = 0.0
    opened = p["frm"].copy()  # a pushing contact opened: its row penetrates
    opened[np.flatnonzero((p["kind"] == UNILATERAL) & (p["frm"][:, 0] == 0))[0], 0] = 1
    for frm in (held, opened):
        out = _solve(core, p, frm)
        assert tuple(_counts(core)) == (1.0, 0.0)  # tried, not kept
        assert out["info"]["status"] == 0
        np.testing.assert_allclose(out["a"], V, rtol=0, atol=1e-9 * scale)
    reversed_ = p["frm"].copy()
    slide = (p["kind"] == DISC) & (p["frm"][:, 0] == 2)
    reversed_[slide, 1:] *= -1.0
    out = _solve(core, p, reversed_)
    assert tuple(_counts(core)) == (1.0, 1.0)
    np.testing.assert_allclose(out["a"], V, rtol=0, atol=1e-9 * scale)


def _forward_problem(model, one, prev, tau):
    """The solve's problem of a one-sample forward (M, f, A at rest: no offsets) and the
    pieces of another sample's (prev) as its start."""
    d = dense_problem(one, model, tau)
    r = one._rows[0]
    nb = len(r.kind)
    frm = np.zeros((nb, 3))
    frm[:, 0] = prev._raw["state"][0][:nb]
    for b, (kind, s) in enumerate(zip(r.kind, r.start)):
        k = 2 if kind >= DISC else 1
        frm[b, 1:1 + k] = prev._raw["lam"][0][s:s + k]
    p = dict(n=len(d["f"]), m=len(d["b"]), nb=nb, M=d["M"], f=d["f"], A=d["A"],
             c=np.zeros(len(d["b"])), kind=np.asarray(r.kind), start=np.asarray(r.start),
             par=np.asarray(r.par, dtype=float).reshape(-1))
    return p, frm


def test_indeterminate_forward_from_a_neighbours_and_its_own_pieces():
    """The 10-joint scene's forward at torques near each other: each sample's solve from its
    neighbour's pieces and from its own (its one-sample solve's), primal piece on, against
    Clarabel's primal polished on its piece (1e-9) and the dense KKT conditions of its forces;
    with the piece off, the same accelerations (1e-12) and dependent flag. From a neighbour's
    pieces the primal's Newton starts too far and leaves them to the dual path; from its own
    it answers some (the others: minimum-norm forces outside their sets, or held rows as many
    as half the coordinates)."""
    rng = np.random.default_rng(0)
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(10))]
    model = snakecg.load(indeterminate_scene(q))
    core = model.core
    g = np.linspace(-0.3, 0.3, 36)  # a column of the benchmark's torque map
    taus = [np.r_[t[:2], g[31], t[3:6], g[k], t[7:]]
            for t in [rng.normal(0, 0.1, 10)] for k in range(28, 36)]
    ones = [model.forward(q, t) for t in taus]
    core.scene_primal(1, None)
    _counts(core)
    own = np.zeros(2)
    for one, prev, tau in zip(ones[1:], ones[:-1], taus[1:]):
        d = dense_problem(one, model, tau)
        for start in (prev, one):
            p, frm = _forward_problem(model, one, start, tau)
            out = _solve(core, p, frm)
            if start is one:
                own += _counts(core)
            assert out["info"]["status"] == 0
            V = _polished(p, *_primal_reference(p))[0]
            np.testing.assert_allclose(out["a"], V, rtol=0, atol=1e-9 * np.abs(V).max())
            assert kkt_violations(d, out["lam"], out["a"]) == []
            core.scene_primal(0, None)
            off = _solve(core, p, frm)
            core.scene_primal(1, None)
            np.testing.assert_allclose(out["a"], off["a"], rtol=0,
                                       atol=1e-12 * np.abs(off["a"]).max())
            assert out["info"]["dependent"] == off["info"]["dependent"]
            _counts(core)
    assert own[0] >= 4 and own[1] >= 2


def _runs(core, simulate):
    """simulate() with the primal piece off, then on (the process's switch), and the on
    run's primal tries and answers."""
    core.scene_primal(0, None)
    off = simulate()
    core.scene_primal(1, None)
    _counts(core)
    on = simulate()
    return off, on, _counts(core)


FIELDS = ("t", "q", "v", "q_obj", "v_obj", "kinetic_energy", "work_tau",
          "friction_dissipation", "impact_loss", "min_gap", "n_contacts")


def _same(off, on):
    assert off.status == on.status == "completed"
    assert off.steps == on.steps and len(off.events) == len(on.events)
    for k in FIELDS:
        np.testing.assert_allclose(np.asarray(getattr(on, k), dtype=float),
                                   np.asarray(getattr(off, k), dtype=float), rtol=0,
                                   atol=1e-9, err_msg=k)
    assert max(on.certificate.values()) <= 1e-9


def test_pegs_run_with_and_without_the_primal_piece(pegs):
    model, q0, gait, _ = pegs
    off, on, (tries, answered) = _runs(
        model.core, lambda: model.simulate(q0, 0.5, tau=gait, dt=H))
    _same(off, on)
    assert len(on.events) >= 1  # impacts among the steps
    assert tries >= 0.9 * on.steps and answered >= 0.9 * tries


def test_papers_push_with_and_without_the_primal_piece():
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0))
    from snakecg.scenes.paper import _plate_model

    q = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
    tau = np.array([0.05, 0.0, -0.02])
    off, on, (tries, answered) = _runs(_plate_model(sm).core,
                                       lambda: sm.simulate(q, tau, 0.5, contacts="geometry"))
    assert off.status == on.status == "completed"
    assert tries == answered == 0  # (its rows, at most 4, never outnumber its 9 coordinates:
    # the dual's unknowns are the fewer, the primal is not tried)
    for k in ("t", "q", "v"):
        np.testing.assert_allclose(np.asarray(getattr(on, k), dtype=float),
                                   np.asarray(getattr(off, k), dtype=float), rtol=0,
                                   atol=1e-9, err_msg=k)


def _cpu_has(*flags):
    """Whether /proc/cpuinfo lists every flag (None where it cannot be read: not Linux)."""
    try:
        with open("/proc/cpuinfo", encoding="ascii", errors="replace") as f:
            words = set(f.read().split())
    except OSError:
        return None
    return all(flag in words for flag in flags)


def _pegs_runs_by_mode(pegs, modes, duration=0.5):
    """The pegs run with impacts once per primal mode (the process's switch; then back to 1)
    and each run's primal tries and answers."""
    model, q0, gait, _ = pegs
    core = model.core
    runs, counts = [], []
    for mode in modes:
        core.scene_primal(mode, None)
        _counts(core)
        runs.append(model.simulate(q0, duration, tau=gait, dt=H))
        counts.append(_counts(core))
    core.scene_primal(1, None)
    return runs, counts


def test_pegs_run_with_the_primal_piece_avx_copy_bit_for_bit(pegs):
    """The snake's piece compiled a second time with AVX (scene_primal.c, chosen where the
    processor has it; no FMA, so each lane's operations are the same; ``core_scene_primal``'s
    mode 3) against the copy without (mode 2): the pegs run with impacts bit for bit, every
    field, and the same tries and answers."""
    (plain, avx), counts = _pegs_runs_by_mode(pegs, (2, 3))
    assert plain.status == avx.status == "completed" and plain.steps == avx.steps
    assert len(plain.events) == len(avx.events) >= 1
    for k in FIELDS:
        np.testing.assert_array_equal(np.asarray(getattr(avx, k), dtype=float),
                                      np.asarray(getattr(plain, k), dtype=float), err_msg=k)
    np.testing.assert_array_equal(counts[0], counts[1])
    assert counts[1][1] >= 0.9 * avx.steps


def test_pegs_run_with_the_primal_piece_fma_copy_within_rounding(pegs):
    """The snake's piece compiled a third time with AVX2 and FMA (fused products, the
    Hessian's factor by its pivots' reciprocals: scene_small.c's sc_small_factor_fma), chosen
    where the processor has both (mode 1, the default), against the copy without (mode 2):
    the pegs run with impacts the same steps, impacts and contact counts, every field within
    1e-12 of its scale (its largest entry, at least 1) but v, within 1e-10 of its scale: v =
    L^-T y carries the solve's rounding through the inertia's factor, most at an impact
    (measured: 6.3e-11 of 3.9 over these 0.5 s, where the primal and the dual paths
    themselves differ by 1.2e-10); the same tries, the answers within 1 % of them (a try at
    a margin, the face's rank or the KKT acceptance, may go the other way by rounding: then
    the dual path's answer, held to the same tolerances). Where /proc/cpuinfo lists avx2 and fma,
    the two runs must differ (the FMA copy ran: its rounding is its own)."""
    (plain, fused), counts = _pegs_runs_by_mode(pegs, (2, 1))
    assert plain.status == fused.status == "completed" and plain.steps == fused.steps
    assert len(plain.events) == len(fused.events) >= 1
    np.testing.assert_array_equal(np.asarray(fused.n_contacts), np.asarray(plain.n_contacts))
    differs = False
    for k in FIELDS:
        a = np.asarray(getattr(fused, k), dtype=float)
        b = np.asarray(getattr(plain, k), dtype=float)
        np.testing.assert_array_equal(np.isfinite(a), np.isfinite(b), err_msg=k)
        fin = np.isfinite(b)
        scale = max(1.0, float(np.abs(b[fin]).max())) if fin.any() else 1.0
        rel = 1e-10 if k == "v" else 1e-12
        np.testing.assert_allclose(a[fin], b[fin], rtol=0, atol=rel * scale, err_msg=k)
        differs |= not np.array_equal(a, b)
    assert counts[0][0] == counts[1][0]
    assert abs(counts[0][1] - counts[1][1]) <= 0.01 * counts[0][0]
    assert counts[1][1] >= 0.9 * fused.steps
    if _cpu_has("avx2", "fma"):
        assert differs


def test_pegs_run_keeps_the_physical_laws(pegs):
    """The pegs run (the benchmark's, 1 s with impacts) through the default copy of the
    primal piece (the FMA copy where the processor has it), held to laws, not to itself: no
    capsule-peg or link-link overlap beyond the tolerance (capsule_reference's NumPy
    distances), the energy balance (the kinetic energy gained within the torques' work less
    the ground's dissipation and the impacts' loss plus the contacts' work), the dissipation
    never decreasing, the impulses >= 0, every step's KKT certificate within 1e-9, most
    steps' pieces answered by the primal."""
    from run_laws import assert_run_laws

    model = pegs[0]
    (run,), ((tries, answered),) = _pegs_runs_by_mode(pegs, (1,), duration=1.0)
    assert run.status == "completed", run.message
    assert len(run.events) >= 1 and max(run.n_contacts) >= 1
    assert tries >= 0.9 * run.steps and answered >= 0.9 * tries
    assert_run_laws(model.scene, run)
