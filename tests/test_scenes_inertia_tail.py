"""The exact solve's set-up on an inertia whose last rows are diagonal (the objects' m, m, I
after M_s: Z's rows there are A's columns over their square roots, nothing eliminated), against
an independent dense NumPy solve of the same equality-constrained problem, against the same
problem with its coordinates reordered (no diagonal tail: the general set-up), and the paper's
scene through the general path against the paper's own closed form over a few hundred
samples."""

from __future__ import annotations

import ctypes

import numpy as np
import pytest

from snakecg import Robot, Scene
from snakecg.scenes import load_scene

K_FREE = 0  # scene_solve.c's bilateral block: a row held at w = 0


@pytest.fixture(scope="module")
def core():
    return load_scene(Scene(Robot(joints=3), scenario="wheels", kappa=50.0)).core


def _ptr(a):
    return a.ctypes.data_as(ctypes.c_void_p)


def _solve(core, M, f, A, c):
    """core_scene_solve_s on bilateral rows A a + c = 0: (a, lam, info)."""
    n, m = M.shape[0], A.shape[0]
    M, f, A, c = (np.ascontiguousarray(x, dtype=float) for x in (M, f, A, c))
    kind = np.full(m, K_FREE, dtype=np.int64)
    start = np.arange(m, dtype=np.int64)
    par = np.zeros(3 * m)
    lam, a, w, state, info = np.zeros(m), np.zeros(n), np.zeros(m), np.zeros(m), np.zeros(8)
    code = core.scene_solve_s(n, m, m, _ptr(M), _ptr(f), _ptr(A), _ptr(c), _ptr(kind),
                              _ptr(start), _ptr(par), 200000, None, _ptr(lam), _ptr(a), _ptr(w),
                              _ptr(state), _ptr(info))
    assert code == 0
    return a, lam, info


def _problem(rng, ns, no, m):
    """M = blockdiag(SPD M_s, then m, m, I per object), f, A (m x n, full row rank), c."""
    B = rng.normal(size=(ns, ns))
    Ms = B @ B.T + ns * np.eye(ns)
    tail = np.concatenate([[mass, mass, inertia] for mass, inertia in
                           zip(rng.uniform(0.1, 100.0, no), rng.uniform(0.01, 2.0, no))])
    n = ns + 3 * no
    M = np.zeros((n, n))
    M[:ns, :ns] = Ms
    M[ns:, ns:] = np.diag(tail)
    return M, rng.normal(size=n), rng.normal(size=(m, n)), rng.normal(size=m)


def _dense(M, f, A, c):
    """The KKT system of min 1/2 a'Ma - f'a s.t. A a + c = 0, dense: M a - A' lam = f."""
    n, m = M.shape[0], A.shape[0]
    K = np.block([[M, -A.T], [A, np.zeros((m, m))]])
    x = np.linalg.solve(K, np.r_[f, -c])
    return x[:n], x[n:]


@pytest.mark.parametrize("ns,no,m", [(6, 1, 4), (6, 1, 9), (4, 2, 7), (13, 2, 12), (3, 3, 5)])
def test_diagonal_tail_against_a_dense_kkt_solve(core, rng, ns, no, m):
    for _ in range(40):
        M, f, A, c = _problem(rng, ns, no, m)
        a, lam, info = _solve(core, M, f, A, c)
        assert info[0] == 0
        a_ref, lam_ref = _dense(M, f, A, c)
        assert np.abs(a - a_ref).max() <= 1e-10 * np.abs(a_ref).max()
        assert np.abs(lam - lam_ref).max() <= 1e-10 * np.abs(lam_ref).max()
        assert np.abs(A @ a + c).max() <= 1e-9 * (np.abs(A).max() * np.abs(a).max() +
                                                  np.abs(c).max())


def test_diagonal_tail_equals_the_general_set_up(core, rng):
    """The same problem with the objects' coordinates first (M's last rows then M_s's, not
    diagonal: the general elimination) gives the same accelerations and forces to rounding
    (1e-14 times the condition number of A M^-1 A^T: random rows, up to n of them)."""
    for _ in range(60):
        ns, no = int(rng.integers(3, 14)), int(rng.integers(1, 4))
        n = ns + 3 * no
        M, f, A, c = _problem(rng, ns, no, int(rng.integers(1, n + 1)))
        tol = 1e-14 * max(100.0, np.linalg.cond(A @ np.linalg.solve(M, A.T)))
        perm = np.r_[np.arange(ns, n), np.arange(ns)]
        a, lam, _ = _solve(core, M, f, A, c)
        a2, lam2, _ = _solve(core, M[np.ix_(perm, perm)], f[perm], A[:, perm], c)
        assert np.abs(a[perm] - a2).max() <= tol * max(1.0, np.abs(a).max())
        assert np.abs(lam - lam2).max() <= tol * max(1.0, np.abs(lam).max())
