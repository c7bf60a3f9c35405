"""The general solve compiled for tiny problems (snakecg/engine/scene_tiny.c: one-row blocks,
at most 6 rows, its set-up unrolled for the snake with 0-2 objects), both its copies (mode 1:
with FMA where the processor has AVX2 and FMA; mode 2: without): random problems of every
one-row kind against an independent dense NumPy enumeration of the pieces, and the same
problems with the tiny path switched off (``core_scene_tiny``), which must give the same
status, dependent flag, passes, pieces and certificate and the same accelerations to 1e-12
(not bit for bit: the tiny path factors by L D L^T with reciprocals, the general path by
Cholesky); then the paper's scene through the general path, its batched forward and its push,
both ways, and against the paper's own closed form."""

from __future__ import annotations

import ctypes
import itertools

import numpy as np
import pytest

import snakecg
from snakecg import Robot, Scene
from snakecg.scenes import GeneralScene, load_scene

K_FREE, K_UNILATERAL, K_BOX = 0, 1, 2  # scene_solve.c's block kinds
STATUS, DEPENDENT, PASSES, SWEEPS, DEFECT = 0, 1, 6, 5, 7  # info fields


@pytest.fixture(scope="module")
def core():
    return load_scene(Scene(Robot(joints=3), scenario="wheels", kappa=50.0)).core


def _ptr(a):
    return None if a is None else a.ctypes.data_as(ctypes.c_void_p)


def _tiny(core, mode):
    """Switch the tiny path (1 on, 0 off); returns (tried, answered) since the last call."""
    counts = np.zeros(2)
    core.scene_tiny(mode, counts.ctypes.data)
    return counts


def _solve(core, M, f, A, c, kind, par, start_from=None):
    """core_scene_solve_s on one-row blocks: (a, lam, w, state, info)."""
    n, m = M.shape[0], A.shape[0]
    M, f, A, par = (np.ascontiguousarray(x, dtype=float) for x in (M, f, A, par))
    c = None if c is None else np.ascontiguousarray(c, dtype=float)
    kind = np.ascontiguousarray(kind, dtype=np.int64)
    start = np.arange(m, dtype=np.int64)
    lam, a, w, state, info = np.zeros(m), np.zeros(n), np.zeros(m), np.zeros(m), np.zeros(8)
    code = core.scene_solve_s(n, m, m, _ptr(M), _ptr(f), _ptr(A), _ptr(c), _ptr(kind),
                              _ptr(start), _ptr(par), 200000, _ptr(start_from), _ptr(lam),
                              _ptr(a), _ptr(w), _ptr(state), _ptr(info))
    assert code == 0
    return a, lam, w, state, info


def _problem(rng, ns):
    """A snake's dense inertia (ns coordinates) and 0-2 objects' diagonal rows, 1-6 rows of
    random kinds (a box's bound zero now and then), offsets or none, a start or none."""
    no = int(rng.integers(0, 3))
    B = rng.normal(size=(ns, ns))
    n = ns + 3 * no
    M = np.zeros((n, n))
    M[:ns, :ns] = B @ B.T + rng.uniform(0.05, ns) * np.eye(ns)
    for j in range(no):
        mass, inertia = rng.uniform(0.1, 10.0), rng.uniform(0.01, 2.0)
        M[ns + 3 * j + np.arange(3), ns + 3 * j + np.arange(3)] = [mass, mass, inertia]
    m = min(int(rng.integers(1, 7)), n)
    kind = rng.integers(0, 3, m)
    par = np.zeros(3 * m)
    par[0::3] = np.where(rng.random(m) < 0.1, 0.0, rng.uniform(0.05, 3.0, m))
    c = rng.normal(size=m) if rng.random() < 0.5 else None
    start = None
    if rng.random() < 0.6:  # the caller's pieces: held, zero, a box at +p or -p
        start = np.zeros(3 * m)
        start[0::3] = rng.choice([0, 1, 3, 4], m)
        start[1::3] = rng.normal(size=m)
    return M, rng.normal(size=n) * rng.uniform(0.1, 10.0), rng.normal(size=(m, n)), c, kind, \
        par, start


def _enumerate(M, f, A, c, kind, par, tol=1e-9):
    """The accelerations of the piece whose KKT conditions hold, by dense KKT solves of every
    piece: a free row held; a contact held (lam >= 0) or open (lam = 0, w >= 0); a box held
    (|lam| <= p) or at +p (w <= 0) or -p (w >= 0), a box of bound 0 at zero force."""
    m, n = A.shape
    c = np.zeros(m) if c is None else c
    choices = [("held",) if k == K_FREE else ("held", "zero") if k == K_UNILATERAL else
               ("zero",) if par[3 * i] == 0 else ("held", "+", "-") for i, k in enumerate(kind)]
    for pick in itertools.product(*choices):
        held = [i for i in range(m) if pick[i] == "held"]
        lam = np.array([0.0 if p in ("held", "zero") else par[3 * i] * (1 if p == "+" else -1)
                        for i, p in enumerate(pick)])
        K = np.block([[M, -A[held].T], [A[held], np.zeros((len(held), len(held)))]])
        x = np.linalg.solve(K, np.r_[f + A.T @ lam, -c[held]])
        lam[held] = x[n:]
        a = x[:n]
        w = A @ a + c
        F, W = max(1.0, np.abs(lam).max()), max(1.0, np.abs(w).max())
        ok = True
        for i in range(m):
            if kind[i] == K_UNILATERAL:
                ok &= lam[i] >= -tol * F if pick[i] == "held" else w[i] >= -tol * W
            elif kind[i] == K_BOX and pick[i] == "held":
                ok &= abs(lam[i]) <= par[3 * i] * (1 + tol)
            elif pick[i] in ("+", "-"):
                ok &= w[i] <= tol * W if pick[i] == "+" else w[i] >= -tol * W
        if ok:
            return a
    raise AssertionError("no piece satisfies the KKT conditions")


@pytest.mark.parametrize("mode", [1, 2])  # the FMA copy (where the processor has it), plain
@pytest.mark.parametrize("ns", [6, 5])  # the model's snake (set-up unrolled) and another size
def test_random_tiny_problems_against_the_pieces_and_the_general_path(core, rng, ns, mode):
    """400 random problems: the tiny path's accelerations against the enumerated pieces (1e-9
    of their scale, the problems' conditioning), and against the general path (the tiny path
    switched off) to 1e-12, with the same status, flags, passes, pieces and certificate."""
    _tiny(core, mode)
    answers = []
    for _ in range(400):
        problem = _problem(rng, ns)
        answers.append((problem, _solve(core, *problem)))
    tried, answered = _tiny(core, 0)
    try:
        for problem, (a, lam, w, state, info) in answers:
            M, f, A, c, kind, par, _ = problem
            a_ref = _enumerate(M, f, A, c, kind, par)
            assert info[STATUS] == 0
            assert np.abs(a - a_ref).max() <= 1e-9 * max(1.0, np.abs(a_ref).max())
            g_a, g_lam, g_w, g_state, g_info = _solve(core, *problem)
            assert g_info[[STATUS, DEPENDENT, SWEEPS, PASSES, DEFECT]].tolist() == \
                info[[STATUS, DEPENDENT, SWEEPS, PASSES, DEFECT]].tolist()
            assert np.array_equal(g_state, state)
            assert np.abs(g_a - a).max() <= 1e-12 * max(1.0, np.abs(g_a).max())
            assert np.abs(g_lam - lam).max() <= 1e-12 * max(1.0, np.abs(g_lam).max())
            assert np.abs(g_w - w).max() <= 1e-12 * max(1.0, np.abs(g_w).max())
            assert np.abs(g_info[2:5] - info[2:5]).max() <= 1e-12  # the certificate
            assert max(info[2:5]) <= 1e-9
        assert _tiny(core, 0)[0] == 0  # (switched off: nothing tried)
    finally:
        _tiny(core, 1)
    assert tried == 400 and answered >= 300  # the tiny path answered most of them


def test_left_to_the_general_path(core, rng):
    """What the tiny path does not treat goes to the general path, which answers it: rows
    dependent (a statically indeterminate piece: dependent flag, minimum-norm forces), more
    than 6 rows (not tried)."""
    M, f, A, _, _, _, _ = _problem(rng, 6)
    A = np.r_[A[:1], A[:1], rng.normal(size=(1, M.shape[0]))]  # the first row twice
    kind, par = np.array([K_FREE, K_FREE, K_UNILATERAL]), np.zeros(9)
    _tiny(core, 1)
    _, lam, _, _, info = _solve(core, M, f, A, None, kind, par)
    assert _tiny(core, 1).tolist() == [1.0, 0.0]
    assert info[STATUS] == 0 and info[DEPENDENT] == 1 and info[DEFECT] == 1
    assert lam[0] == pytest.approx(lam[1], rel=1e-12)  # the minimum-norm split
    a7 = _solve(core, M, f, rng.normal(size=(7, M.shape[0])), None, np.zeros(7, int),
                np.zeros(21))[4]
    assert a7[STATUS] == 0 and _tiny(core, 1).tolist() == [0.0, 0.0]  # 7 rows: not tried


@pytest.mark.parametrize("mode", [1, 2])
@pytest.mark.parametrize("scenario", ["wheels", "frictionless", "ideal_wheels"])
def test_paper_scene_general_path_with_and_without_the_tiny_path(rng, scenario, mode):
    """300 samples of each of the paper's scenarios through the general path, batched and one
    at a time, with the tiny path (either copy) and without: the same status, passes and
    pieces, the accelerations to 1e-12 (not bit for bit: the factors differ); against the
    paper's own closed form to 1e-12, the metrics too (1e-12 of the sample's norms)."""
    scene = Scene(Robot(joints=3), scenario=scenario, kappa=100.0, mu=0.1)
    old, new = snakecg.load(scene), load_scene(scene)
    Q = np.c_[rng.normal(0.0, 0.3, (300, 3)), rng.uniform(-1.0, 1.0, (300, 3))]
    T = rng.normal(0.0, 0.05, (300, 3))
    _tiny(new.core, mode)
    try:  # (the solver's arrays, solved again, read under each switch)
        on = new.forward(Q, T)
        single_on = [new.forward(Q[s], T[s]) for s in range(0, 300, 10)]
        counts = _tiny(new.core, 0)
        assert on._raw is not None
        off = new.forward(Q, T)
        single = [new.forward(Q[s], T[s]) for s in range(0, 300, 10)]
        assert off._raw is not None
    finally:
        _tiny(new.core, 1)
    o = old.forward(Q, T)
    assert counts[1] >= 0.9 * counts[0] > 0  # the tiny path answered these
    assert np.all(on.status == 0) and np.all(off.status == 0)
    assert np.array_equal(on._raw["state"], off._raw["state"])
    for key in ("status", "dependent", "sweeps", "passes", "rank_defect"):
        assert np.array_equal(on._raw["info"][key], off._raw["info"][key]), key
    for key in ("primal", "dual", "complementarity"):
        assert np.abs(on._raw["info"][key] - off._raw["info"][key]).max() <= 1e-12, key
    scale = max(1.0, np.abs(o.qdd).max())
    assert np.abs(on.qdd - off.qdd).max() <= 1e-12 * scale
    assert np.abs(on.qdd - o.qdd).max() <= 1e-12 * scale
    assert np.abs(on.sr - o.sr).max() <= 1e-12
    norms = o.norm_qdd + o.norm_a_obj + o.norm_lambda
    for key in ("norm_qdd", "norm_a_obj", "norm_lambda"):
        assert np.all(np.abs(getattr(on, key) - getattr(o, key)) <= 1e-12 * norms), key
    for s, r, r_on in zip(range(0, 300, 10), single, single_on):
        assert np.abs(r.qdd - on.qdd[s]).max() <= 1e-12 * scale
        assert np.abs(r_on.qdd - on.qdd[s]).max() <= 1e-12 * scale


def test_paper_push_with_and_without_the_tiny_path():
    """The paper's push through the general stepping (contacts from geometry), 0.5 s, with the
    tiny path and without: the same steps and contact counts, the states to 1e-10."""
    sm = snakecg.load(Scene(Robot(joints=3), scenario="wheels", kappa=100.0))
    q = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
    tau = np.array([0.05, 0.0, -0.02])
    core = load_scene(GeneralScene.from_scene(Scene(Robot(joints=3), scenario="wheels",
                                                    kappa=100.0))).core
    _tiny(core, 1)
    on = sm.simulate(q, tau, 0.5, contacts="geometry")
    counts = _tiny(core, 0)
    try:
        off = sm.simulate(q, tau, 0.5, contacts="geometry")
    finally:
        _tiny(core, 1)
    assert counts[1] >= 0.9 * counts[0] >= 450  # (one solve a step, most through the path)
    assert on.status == off.status and on.steps == off.steps
    assert np.array_equal(on.n_contacts, off.n_contacts)
    for key in ("q", "v", "q_obj", "v_obj"):
        a, b = np.asarray(getattr(on, key)), np.asarray(getattr(off, key))
        assert np.abs(a - b).max() <= 1e-10 * max(1.0, np.abs(b).max()), key
