"""The engine's L D L^T without pivoting (linalg.h's ``sc_ldl_factor`` / ``sc_ldl_solve``: one
division per pivot, none in the solve; the general scenes' angle Newton factors its matrix with
it where every pivot stays above 1e-8 of the largest diagonal entry), compiled alone with the
engine's own flags and called through ctypes, against NumPy and SciPy: the solution of random
positive definite systems against ``numpy.linalg.solve`` (to the condition number times
rounding), the pivots against SciPy's Cholesky factor (d_j = L_jj^2), and the rule the angle
Newton applies (its smallest pivot against 1e-8 of the largest diagonal entry) on matrices
that are rank-deficient or nearly so, where it must refuse (the caller then pivots)."""

from __future__ import annotations

import ctypes
import subprocess

import numpy as np
import pytest
import scipy.linalg

from snakecg.native import CORE_FLAGS, ENGINE_DIR, find_compiler

SHIM = """typedef long long int sc_int; /* as engine.h, which includes linalg.h */
#define SC_UNROLL
#include "linalg.h"
/* A (n x n, symmetric) factored as the angle Newton does; y := A^-1 y; d (n) the pivots */
void ldl(sc_int n, const double *A, double *L, double *d, double *dinv, double *work,
         double *y) {
  sc_ldl_factor(n, A, n, 0, L, n, d, dinv, 0, 0.0, work);
  sc_ldl_solve(n, L, n, dinv, y);
}
"""


@pytest.fixture(scope="module")
def ldl(tmp_path_factory):
    cc = find_compiler()
    assert cc is not None, "the engine needs a C compiler (cc, gcc or clang)"
    tmp = tmp_path_factory.mktemp("ldl")
    (tmp / "shim.c").write_text(SHIM)
    lib = tmp / "libldl.so"
    subprocess.run([cc, *CORE_FLAGS, "-shared", "-I", str(ENGINE_DIR), str(tmp / "shim.c"),
                    "-o", str(lib), "-lm"], check=True, capture_output=True)
    fn = ctypes.CDLL(str(lib)).ldl
    fn.argtypes, fn.restype = [ctypes.c_longlong] + [ctypes.c_void_p] * 6, None

    def call(A, b):
        n = len(A)
        A = np.ascontiguousarray(A, float)
        L, d, dinv, work = np.zeros((n, n)), np.zeros(n), np.zeros(n), np.zeros(n)
        y = np.array(b, float)
        fn(n, A.ctypes.data, L.ctypes.data, d.ctypes.data, dinv.ctypes.data, work.ctypes.data,
           y.ctypes.data)
        return y, d

    return call


def _spd(rng, n, cond):
    """A random symmetric positive definite matrix of condition number cond."""
    Q, _ = np.linalg.qr(rng.normal(size=(n, n)))
    return (Q * np.logspace(0, -np.log10(cond), n)) @ Q.T * 10.0 ** rng.uniform(-6, 6)


def test_solves_positive_definite_systems_as_numpy(ldl, rng):
    worst = 0.0
    for _ in range(300):
        n = int(rng.integers(1, 31))
        cond = 10.0 ** rng.uniform(0, 8)
        A = _spd(rng, n, cond)
        A = 0.5 * (A + A.T)
        b = rng.normal(size=n)
        y, d = ldl(A, b)
        ref = np.linalg.solve(A, b)
        worst = max(worst, np.abs(y - ref).max() / (np.abs(ref).max() * cond))
        chol = scipy.linalg.cholesky(A, lower=True)
        np.testing.assert_allclose(d, np.diag(chol) ** 2, rtol=1e-12 * cond, atol=0)
    assert worst < 1e-13


def test_refuses_rank_deficient_matrices_by_the_angle_newton_rule(ldl, rng):
    """Rank r < n (A = B B^T, B n x r) and pivots down to 1e-12 of the largest: the smallest
    pivot falls below 1e-8 of the largest diagonal entry (the caller's test); full-rank
    matrices of condition number at most 1e4 stay above it."""
    for _ in range(200):
        n = int(rng.integers(2, 21))
        r = int(rng.integers(1, n))
        B = rng.normal(size=(n, r))
        A = B @ B.T
        if rng.uniform() < 0.5:  # nearly dependent rather than exactly
            A += 1e-12 * np.abs(A).max() * np.eye(n)
        _, d = ldl(A, rng.normal(size=n))
        assert not np.all(d > 1e-8 * np.diag(A).max()), (n, r)
        A = _spd(rng, n, 10.0 ** rng.uniform(0, 4))
        A = 0.5 * (A + A.T)
        _, d = ldl(A, rng.normal(size=n))
        assert np.all(d > 1e-8 * np.diag(A).max())
