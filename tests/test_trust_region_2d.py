"""The engine's 2-D block minimiser (scene_block.h's ``sc_trust_region_2d``: min 1/2 x'Hx + g'x over
the unit disc, H 2 x 2 positive semidefinite), compiled alone with the engine's own flags and
called through ctypes, against an independent reference in mpmath at 50 digits: the interior
minimiser -H^+ g where it lies in the disc and g is in H's range, else the point
-(H + s I)^-1 g on the circle with s >= 0 found by bisection (Moré & Sorensen's conditions).
Random problems over twelve decades of scale, with spread and clustered eigenvalues,
singular H, g along an eigenvector and diagonal H, to rounding (1e-15 relative, a few units
of the double's precision on these well-conditioned problems)."""

from __future__ import annotations

import ctypes
import subprocess

import mpmath
import numpy as np
import pytest

from snakecg.native import CORE_FLAGS, ENGINE_DIR, find_compiler

mpmath.mp.dps = 50
SHIM = """#include <math.h>
#include "scene_block.h"
void tr2d(const double *H, const double *g, double *x) { sc_trust_region_2d(H, g, x); }
"""


@pytest.fixture(scope="module")
def tr2d(tmp_path_factory):
    cc = find_compiler()
    assert cc is not None, "the engine needs a C compiler (cc, gcc or clang)"
    tmp = tmp_path_factory.mktemp("tr2d")
    (tmp / "shim.c").write_text(SHIM)
    lib = tmp / "libtr2d.so"
    subprocess.run([cc, *CORE_FLAGS, "-shared", "-I", str(ENGINE_DIR), str(tmp / "shim.c"),
                    "-o", str(lib), "-lm"], check=True, capture_output=True)
    fn = ctypes.CDLL(str(lib)).tr2d
    fn.argtypes, fn.restype = [ctypes.c_void_p] * 3, None

    def call(H, g):
        H, g, x = np.ascontiguousarray(H, float), np.ascontiguousarray(g, float), np.zeros(2)
        fn(H.ctypes.data, g.ctypes.data, x.ctypes.data)
        return x

    return call


def _reference(H, g):
    """The minimiser in mpmath (50 digits) from H's own eigen-decomposition there."""
    Hm, gm = mpmath.matrix(H.tolist()), mpmath.matrix(g.tolist())
    h, V = mpmath.eigsy(Hm)
    order = sorted(range(2), key=lambda i: h[i])
    h = [max(h[i], mpmath.mpf(0)) for i in order]
    V = [V[:, i] for i in order]
    gp = [(V[i].T * gm)[0] for i in range(2)]
    tiny = mpmath.mpf(10) ** -30 * max(h[1], 1)
    if all(h[i] > tiny or abs(gp[i]) <= tiny for i in range(2)):
        y = [-gp[i] / h[i] if h[i] > tiny else mpmath.mpf(0) for i in range(2)]
        if y[0] ** 2 + y[1] ** 2 <= 1:
            return np.array([float(v) for v in V[0] * y[0] + V[1] * y[1]])

    def norm(s):
        return mpmath.sqrt(sum((gp[i] / (h[i] + s)) ** 2 for i in range(2)))

    gn = mpmath.sqrt(gp[0] ** 2 + gp[1] ** 2)
    lo, hi = max(mpmath.mpf(0), gn - h[1]), gn - h[0]
    for _ in range(220):  # |y(s)| decreasing in s: bisection to 1e-66 of the bracket
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if norm(mid) > 1 else (lo, mid)
    s = (lo + hi) / 2
    y = [-gp[i] / (h[i] + s) for i in range(2)]
    return np.array([float(v) for v in V[0] * y[0] + V[1] * y[1]])


def _problems(seed, count):
    rng = np.random.default_rng(seed)
    for k in range(count):
        t = rng.uniform(0.0, np.pi)
        V = np.eye(2) if k % 10 == 0 else np.array([[np.cos(t), -np.sin(t)],
                                                    [np.sin(t), np.cos(t)]])
        scale = 10.0 ** rng.uniform(-6, 6)
        kind = k % 5
        if kind == 0:  # spread eigenvalues
            h = np.sort(rng.uniform(0.05, 1.0, 2)) * scale
        elif kind == 1:  # clustered
            h = np.array([1.0, 1.0 + 10.0 ** rng.uniform(-6, -1)]) * scale
        elif kind == 2:  # singular (a null direction)
            h = np.array([0.0, rng.uniform(0.1, 1.0)]) * scale
        else:  # as the scenes' blocks: eigenvalues a few apart
            h = np.array([1.0, rng.uniform(2.0, 6.0)]) * scale
        H = V @ np.diag(h) @ V.T
        H = 0.5 * (H + H.T)
        g = rng.normal(size=2) * scale * 10.0 ** rng.uniform(-1.5, 1.5)
        if k % 7 == 3:  # g along an eigenvector (a singular H's null one: along its range
            g = V[:, 0 if kind == 2 else k % 2] * g[0]  # the null part is rounding: ill-posed)
        yield H, g


def test_minimiser_matches_mpmath_to_rounding(tr2d):
    worst, on_circle = 0.0, 0
    for H, g in _problems(11, 1500):
        x, ref = tr2d(H, g), _reference(H, g)
        err = np.linalg.norm(x - ref) / max(np.linalg.norm(ref), 1e-300)
        worst = max(worst, err)
        assert err <= 1e-15 or np.linalg.norm(x - ref) <= 2e-16, (H, g, x, ref)
        if abs(np.linalg.norm(ref) - 1.0) < 1e-12:
            on_circle += 1
            assert abs(np.linalg.norm(x) - 1.0) <= 1e-15  # the constraint held to rounding
    assert on_circle > 700  # both cases are exercised (the interior ones the rest)
    assert worst > 0.0  # (the comparison is of two computations, not one)


def test_interior_and_boundary_closed_forms(tr2d):
    """Diagonal H, cases solvable by hand: interior -g/h; g along a principal axis beyond the
    disc: x = -g/|g|; H = 0: x = -g/|g|; g = 0: x = 0."""
    np.testing.assert_allclose(tr2d(np.diag([4.0, 8.0]), np.array([1.0, -2.0])),
                               [-0.25, 0.25], rtol=1e-15)
    np.testing.assert_allclose(tr2d(np.diag([1.0, 3.0]), np.array([0.0, 5.0])), [0.0, -1.0],
                               atol=1e-16)
    np.testing.assert_allclose(tr2d(np.zeros((2, 2)), np.array([3.0, -4.0])), [-0.6, 0.8],
                               rtol=1e-15)
    np.testing.assert_array_equal(tr2d(np.diag([2.0, 5.0]), np.zeros(2)), [0.0, 0.0])
    # isotropic H = hI, |g| > h: s = |g| - h, x = -g/|g|
    np.testing.assert_allclose(tr2d(2.0 * np.eye(2), np.array([6.0, 8.0])), [-0.6, -0.8],
                               rtol=1e-15)
