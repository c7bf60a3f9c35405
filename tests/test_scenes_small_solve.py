"""The exact solve of small general scenes (scene_small.c's set-up: the inertia's Cholesky on
its dense block, Z and G compiled per row count up to 8): problems with a diagonal tail and
1 to 10 rows against an independent dense NumPy KKT solve; small contact problems (a contact,
bounded wheel rows) against an independent enumeration of every piece by dense KKT solves,
including samples whose first pass fails and hands over to the next; and the paper's three
scenarios through the general path against the paper's own closed form, to 1e-12."""

from __future__ import annotations

import ctypes
import itertools

import numpy as np
import pytest

import snakecg
from snakecg import Robot, Scene
from snakecg.scenes import load_scene

K_FREE, K_UNILATERAL, K_BOX = 0, 1, 2  # scene_solve.c's block kinds
S_HELD, S_ZERO = 0, 1  # its states (state_out: 3 / 4 a box sliding at +p / -p)
STATUS, PASSES = 0, 6  # info fields (snakecg.scenes.solve.INFO)


@pytest.fixture(scope="module")
def core():
    return load_scene(Scene(Robot(joints=3), scenario="wheels", kappa=50.0)).core


def _ptr(a):
    return None if a is None else a.ctypes.data_as(ctypes.c_void_p)


def _solve(core, M, f, A, c, kind, par, start_from=None):
    """core_scene_solve_s on 1-D blocks (one row each): (a, lam, w, state, info)."""
    n, m = M.shape[0], A.shape[0]
    M, f, A, c, par = (np.ascontiguousarray(x, dtype=float) for x in (M, f, A, c, par))
    kind = np.ascontiguousarray(kind, dtype=np.int64)
    start = np.arange(m, dtype=np.int64)
    lam, a, w, state, info = np.zeros(m), np.zeros(n), np.zeros(m), np.zeros(m), np.zeros(8)
    code = core.scene_solve_s(n, m, m, _ptr(M), _ptr(f), _ptr(A), _ptr(c), _ptr(kind),
                              _ptr(start), _ptr(par), 200000, _ptr(start_from), _ptr(lam),
                              _ptr(a), _ptr(w), _ptr(state), _ptr(info))
    assert code == 0
    return a, lam, w, state, info


def _problem(rng, ns, no, m):
    """M = blockdiag(SPD M_s, then m, m, I per object), f, A (m x n), c."""
    B = rng.normal(size=(ns, ns))
    Ms = B @ B.T + ns * np.eye(ns)
    tail = np.concatenate([[mass, mass, inertia] for mass, inertia in
                           zip(rng.uniform(0.1, 100.0, no), rng.uniform(0.01, 2.0, no))])
    n = ns + 3 * no
    M = np.zeros((n, n))
    M[:ns, :ns] = Ms
    M[ns:, ns:] = np.diag(tail)
    return M, rng.normal(size=n), rng.normal(size=(m, n)), rng.normal(size=m)


def _equality(M, f, A, c, held, fixed):
    """min 1/2 a'Ma - (f + A_F' lam_F)'a s.t. A_H a + c_H = 0, dense: (a, lam)."""
    n, m = M.shape[0], A.shape[0]
    lam = np.zeros(m)
    lam[list(fixed)] = list(fixed.values())
    g = f + A.T @ lam
    H = np.asarray(held, dtype=int)
    K = np.block([[M, -A[H].T], [A[H], np.zeros((H.size, H.size))]])
    x = np.linalg.solve(K, np.r_[g, -c[H]])
    lam[H] = x[M.shape[0]:]
    return x[:n], lam


def _enumerate(M, f, A, c, kind, par, tol=1e-9):
    """The KKT point of the dual over every piece: a contact held (w = 0, lam >= 0) or open
    (lam = 0, w >= 0); a box held (w = 0, |lam| <= p) or at +p (w <= 0) or -p (w >= 0).
    Returns (a, lam) of the one piece that satisfies its conditions (a, w unique)."""
    m = A.shape[0]
    choices = [("held", "zero") if k == K_UNILATERAL else ("held", "+", "-") for k in kind]
    found = []
    for pick in itertools.product(*choices):
        held = [i for i in range(m) if pick[i] == "held"]
        fixed = {i: (0.0 if pick[i] == "zero" else par[3 * i] * (1 if pick[i] == "+" else -1))
                 for i in range(m) if pick[i] != "held"}
        a, lam = _equality(M, f, A, c, held, fixed)
        w = A @ a + c
        F, W = max(1.0, np.abs(lam).max()), max(1.0, np.abs(w).max())
        ok = True
        for i in range(m):
            if kind[i] == K_UNILATERAL:
                ok &= lam[i] >= -tol * F if pick[i] == "held" else w[i] >= -tol * W
            elif pick[i] == "held":
                ok &= abs(lam[i]) <= par[3 * i] * (1 + tol)
            else:
                ok &= w[i] <= tol * W if pick[i] == "+" else w[i] >= -tol * W
        if ok:
            found.append((a, lam))
    assert found, "no piece satisfies the KKT conditions"
    return found[0]


@pytest.mark.parametrize("m", [1, 2, 3, 4, 5, 6, 7, 8, 10])
def test_rows_counted_by_the_compiler_against_a_dense_kkt_solve(core, rng, m):
    """Bilateral rows, 1 to 10 of them (Z and G compiled for m up to 8, the general loops
    beyond), on inertias with a diagonal tail of one or two objects."""
    for _ in range(30):
        ns, no = int(rng.integers(3, 8)), int(rng.integers(1, 3))
        M, f, A, c = _problem(rng, ns, no, m)
        if m > M.shape[0]:
            continue
        a, lam, w, _, info = _solve(core, M, f, A, c, np.full(m, K_FREE), np.zeros(3 * m))
        assert info[STATUS] == 0
        a_ref, lam_ref = _equality(M, f, A, c, list(range(m)), {})
        cond = max(100.0, np.linalg.cond(A @ np.linalg.solve(M, A.T)))
        assert np.abs(a - a_ref).max() <= 1e-14 * cond * np.abs(a_ref).max()
        assert np.abs(lam - lam_ref).max() <= 1e-14 * cond * np.abs(lam_ref).max()
        assert np.abs(w).max() <= 1e-12 * cond * max(1.0, np.abs(c).max())


def _contact_problem(rng):
    """The paper's shape of problem: 6 snake coordinates and one object's 3, a contact row
    (on both) and three bounded wheel rows (on the snake), random."""
    M, f, A, c = _problem(rng, 6, 1, 4)
    A[1:, 6:] = 0.0
    kind = np.array([K_UNILATERAL, K_BOX, K_BOX, K_BOX])
    par = np.zeros(12)
    par[3::3] = rng.uniform(0.05, 2.0, 3)
    return M, f, A, c, kind, par


def test_small_contact_problems_against_every_piece_enumerated(core, rng):
    """200 random problems of the paper's shape, cold and from a wrong start, against the
    enumeration; among them samples whose first pass fails (a contact pulling, a wheel force
    beyond its bound) and whose answer comes from a later pass."""
    handed = 0
    for _ in range(200):
        M, f, A, c, kind, par = _contact_problem(rng)
        a_ref, lam_ref = _enumerate(M, f, A, c, kind, par)
        wrong = np.zeros(12)  # every block held at zero force: a start to switch from
        for start in (None, wrong):
            a, lam, w, state, info = _solve(core, M, f, A, c, kind, par, start)
            assert info[STATUS] == 0
            scale = max(1.0, np.abs(a_ref).max())
            assert np.abs(a - a_ref).max() <= 1e-12 * scale
            assert np.abs(lam - lam_ref).max() <= 1e-12 * max(1.0, np.abs(lam_ref).max())
            assert np.abs(w - (A @ a_ref + c)).max() <= 1e-12 * max(1.0, np.abs(c).max())
            assert max(info[2:5]) <= 1e-9  # the certificate
            for i, code in enumerate(state):  # the pieces reported: a box sliding at +-p,
                if code in (3, 4):  # an open contact at zero force
                    assert lam_ref[i] == pytest.approx(par[3 * i] * (1 if code == 3 else -1))
                elif code == S_ZERO:
                    assert abs(lam_ref[i]) <= 1e-12 * max(1.0, np.abs(lam_ref).max())
            handed += info[PASSES] > 1
    assert handed >= 20  # the hand-over from a failed first pass was exercised


@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
def test_paper_scenarios_general_path_against_their_own_path(rng, scenario):
    """300 samples of each of the paper's scenarios through the general path (9 coordinates,
    4-5 rows), batched and one at a time, against the paper's closed form, to 1e-12."""
    scene = Scene(Robot(joints=3), scenario=scenario, kappa=100.0, mu=0.1)
    old, new = snakecg.load(scene), load_scene(scene)
    Q = np.c_[rng.normal(0.0, 0.3, (300, 3)), rng.uniform(-1.0, 1.0, (300, 3))]
    T = rng.normal(0.0, 0.05, (300, 3))
    o, b = old.forward(Q, T), new.forward(Q, T)
    assert np.all(b.status == 0)
    scale = max(1.0, np.abs(o.qdd).max())
    assert np.abs(b.qdd - o.qdd).max() <= 1e-12 * scale
    assert np.abs(b.a_obj[:, 0] - o.a_obj).max() <= 1e-12 * max(1.0, np.abs(o.a_obj).max())
    assert np.abs(b.sr - o.sr).max() <= 1e-12
    for s in range(0, 300, 5):
        r = new.forward(Q[s], T[s])
        assert np.abs(r.qdd - o.qdd[s]).max() <= 1e-12 * scale
        assert abs(r.sr - o.sr[s]) <= 1e-12
