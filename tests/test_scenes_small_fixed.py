"""The general scenes' inertia factor and Z = L^-1 A^T (scene_small.c's ``sc_inertia_factor``,
``sc_scene_z``) where the dense block is the snake's (n_s coordinates, up to 16): compiled
alone with the engine's flags for snakes of several sizes (the layout header's n_s), called
through ctypes, and checked against SciPy: L against ``scipy.linalg.cholesky``, g = L^-1 f and
Z against ``solve_triangular`` (to the condition number times rounding), on inertias with 0-2
objects (their diagonal tail) and 1-31 rows; the pivot rule (a pivot not above 1e-14 of the
largest diagonal entry refuses) on rank-deficient inertias; and the snake's unrolled block
against the general loops (the same file compiled with ``SC_GENERAL_ONLY``): its factor bit
for bit, its Z within rounding; Z's AVX copy bit for bit the code without it (``SC_NO_AVX``)."""

from __future__ import annotations

import ctypes
import subprocess

import numpy as np
import pytest
import scipy.linalg

from snakecg.native import CORE_FLAGS, ENGINE_DIR, find_compiler

LAYOUT = """#define SNAKECG_PREFIX t_
#define SNAKECG_CAT_(a, b) a##b
#define SNAKECG_CAT(a, b) SNAKECG_CAT_(a, b)
#define SNAKECG_EXPORT(name) SNAKECG_CAT(SNAKECG_PREFIX, name)
#define SNAKECG_NA {na}
#define SNAKECG_NS {ns}
#define SNAKECG_NL {nl}
#define SNAKECG_NC {nc}
"""
SHIM = """#include "scene_small.c"
/* L = chol(M), a = L^-1 f, Z = L^-1 A^T; returns the dense block's size t, or -1 refused */
int factor_z(sc_int n, sc_int m, const double *M, const double *f, double *L, double *a,
             const double *A, double *Z) {
  sc_int t;
  if (!sc_inertia_factor(n, M, f, 1e-14, L, a, &t)) return -1;
  sc_scene_z(n, m, t, L, A, Z);
  return (int)t;
}
"""
SIZES = (7, 13, 16, 17)  # n_s: 17 is past the unrolled block's 16 (the general loops)


def _build(tmp, ns, general):
    """general: 0 the file as the engine compiles it, 1 its general loops alone
    (SC_GENERAL_ONLY), 2 the unrolled block without its AVX copy (SC_NO_AVX)."""
    cc = find_compiler()
    assert cc is not None, "the engine needs a C compiler (cc, gcc or clang)"
    folder = tmp / f"ns{ns}-{general}"
    folder.mkdir()
    na = ns - 3
    (folder / "snakecg_layout.h").write_text(LAYOUT.format(na=na, ns=ns, nl=na + 1, nc=na + 2))
    (folder / "shim.c").write_text(SHIM)
    lib = folder / "libsmall.so"
    flags = [[], ["-DSC_GENERAL_ONLY"], ["-DSC_NO_AVX"]][general]
    subprocess.run([cc, *CORE_FLAGS, *flags, "-shared", "-I", str(folder), "-I", str(ENGINE_DIR),
                    str(folder / "shim.c"), "-o", str(lib), "-lm"], check=True,
                   capture_output=True)
    fn = ctypes.CDLL(str(lib)).factor_z
    fn.argtypes = [ctypes.c_longlong] * 2 + [ctypes.c_void_p] * 6
    fn.restype = ctypes.c_int

    def call(M, f, A):
        n, m = len(M), len(A)
        M, f, A = (np.ascontiguousarray(x, float) for x in (M, f, A))
        L, a, Z = np.zeros((n, n)), np.zeros(n), np.zeros((n, m))
        t = fn(n, m, M.ctypes.data, f.ctypes.data, L.ctypes.data, a.ctypes.data,
               A.ctypes.data, Z.ctypes.data)
        return t, np.tril(L), a, Z

    return call


@pytest.fixture(scope="module")
def libs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("small")
    return {(ns, general): _build(tmp, ns, general) for ns in SIZES for general in (0, 1, 2)}


def _inertia(rng, ns, no, cond):
    """A snake's dense M_s (condition about cond, scale 1e-3..1e3), then m, m, I per object."""
    Q, _ = np.linalg.qr(rng.normal(size=(ns, ns)))
    Ms = (Q * np.logspace(0, -np.log10(cond), ns)) @ Q.T * 10.0 ** rng.uniform(-3, 3)
    Ms = 0.5 * (Ms + Ms.T)
    n = ns + 3 * no
    M = np.zeros((n, n))
    M[:ns, :ns] = Ms
    M[ns:, ns:] = np.diag(rng.uniform(0.01, 10.0, 3 * no))
    return M


@pytest.mark.parametrize("ns", SIZES)
def test_factor_and_z_against_scipy(libs, ns):
    rng = np.random.default_rng(ns)
    for trial in range(60):
        no, m, cond = trial % 3, 1 + trial % 31, 10.0 ** rng.uniform(0, 6)
        M = _inertia(rng, ns, no, cond)
        f, A = rng.normal(size=len(M)), rng.normal(size=(m, len(M)))
        t, L, a, Z = libs[ns, 0](M, f, A)
        assert t == ns  # the objects' rows are the diagonal tail
        L_ref = scipy.linalg.cholesky(M, lower=True)
        a_ref = scipy.linalg.solve_triangular(L_ref, f, lower=True)
        Z_ref = scipy.linalg.solve_triangular(L_ref, A.T, lower=True)
        tol = 1e-14 * cond
        assert np.abs(L - L_ref).max() <= tol * np.abs(L_ref).max()
        assert np.abs(a - a_ref).max() <= tol * np.abs(a_ref).max()
        assert np.abs(Z - Z_ref).max() <= tol * np.abs(Z_ref).max()
        np.testing.assert_allclose(L @ L.T, M, rtol=0, atol=1e-14 * np.abs(M).max())


@pytest.mark.parametrize("ns", SIZES)
def test_unrolled_block_against_the_general_loops(libs, ns):
    """The factor (L, g) bit for bit the general loops'; Z within rounding of theirs (its
    sums grouped otherwise and times 1 / L_ii): 4 n_s ulps of Z's column scale times the
    condition's square root (Z's error bound, as L^-1's norm) at most."""
    rng = np.random.default_rng(100 + ns)
    for trial in range(90):
        cond = 10.0 ** rng.uniform(0, 8)
        M = _inertia(rng, ns, trial % 3, cond)
        f, A = rng.normal(size=len(M)), rng.normal(size=(1 + trial % 31, len(M)))
        fixed, general = libs[ns, 0](M, f, A), libs[ns, 1](M, f, A)
        assert fixed[0] == general[0]
        for x, y in zip(fixed[1:3], general[1:3]):
            assert x.tobytes() == y.tobytes()
        Z, Zg = fixed[3], general[3]
        scale = np.abs(Zg).max(axis=0)
        assert np.all(np.abs(Z - Zg) <= 4 * ns * 2.2e-16 * np.sqrt(cond) * scale)
        # the AVX copy (four of A's rows at a time, where the processor has it) bit for bit
        # the two-at-a-time code: each lane's operations are the same
        plain = libs[ns, 2](M, f, A)
        for x, y in zip(fixed, plain):
            assert np.asarray(x).tobytes() == np.asarray(y).tobytes()


@pytest.mark.parametrize("ns", SIZES)
def test_pivot_rule_against_its_threshold(libs, ns):
    """M = L0 diag(d) L0^T, L0 unit lower triangular with small entries: the factor's pivots
    are d to rounding (1e-16 of the largest); one pivot d_k at 0.3 or 3 times the rule's 1e-14
    of the largest diagonal entry refuses or passes; a coordinate without inertia refuses."""
    rng = np.random.default_rng(200 + ns)
    for trial in range(30):
        k = int(rng.integers(0, ns))
        L0 = np.eye(ns) + np.tril(rng.uniform(-0.1, 0.1, (ns, ns)), -1)
        d = rng.uniform(1.0, 2.0, ns)
        d[k] = 0.0
        big = np.max(np.diag((L0 * d) @ L0.T))
        d[k] = (0.3 if trial % 2 else 3.0) * 1e-14 * big
        M = np.zeros((ns + 3, ns + 3))
        M[:ns, :ns] = (L0 * d) @ L0.T
        M[ns:, ns:] = np.eye(3)
        f, A = rng.normal(size=ns + 3), rng.normal(size=(5, ns + 3))
        want = -1 if trial % 2 else ns
        assert libs[ns, 0](M, f, A)[0] == want
        assert libs[ns, 1](M, f, A)[0] == want
        M[:, k] = M[k, :] = 0.0  # a coordinate without inertia (not the diagonal tail: k < ns)
        if k < ns - 1:
            assert libs[ns, 0](M, f, A)[0] == -1
