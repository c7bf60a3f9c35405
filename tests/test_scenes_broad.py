"""The broad phase of a general scene's contacts (snakecg/engine/scene_broad.c: which bodies after
body a may touch it, as words of 64 bits for every body a at once, and the iteration over them
that scene_rows.c's contact_rows makes), compiled alone with the engine's flags (and once more
without its AVX path) and called through ctypes, against a brute-force NumPy loop over every
pair: the same pairs in the same order (bodies after a, neighbouring links skipped, bounding
circles not apart by more than twice the tolerance), for rows of pegs, random bodies, more than
64 bodies (several words of bits), circles exactly at the bound, and a body whose centre is not
a number (never apart, as the pair loop read it); with few bodies (at most 8) the table of pairs
that contact_rows makes once and tests pair by pair instead, against the same brute force. The
contacts and rows that follow are held against tests/scenes_rows_reference.py in
tests/test_scenes_rows.py."""

from __future__ import annotations

import ctypes
import subprocess

import numpy as np
import pytest

from snakecg.native import CORE_FLAGS, ENGINE_DIR, find_compiler

LAYOUT = """#define SNAKECG_PREFIX t_
#define SNAKECG_CAT_(a, b) a##b
#define SNAKECG_CAT(a, b) SNAKECG_CAT_(a, b)
#define SNAKECG_EXPORT(name) SNAKECG_CAT(SNAKECG_PREFIX, name)
#define SNAKECG_NA 10
#define SNAKECG_NS 13
#define SNAKECG_NL 11
#define SNAKECG_NC 12
"""
SHIM = """#include <stdlib.h>
#include "scene_broad.c"
/* every pair (a, b) that contact_rows would take, in its order, for a < nfirst: its count
 * (the circles laid out as scene_broad.h says: x's, y's, radii, each padded) */
long long pairs(sc_int nbody, sc_int nfirst, sc_int nl, const double *centre,
                const double *reach, double tol, long long *out) {
  const sc_int nw = sc_broad_words(nbody), pad = sc_broad_pad(nbody);
  uint64_t *near = (uint64_t *)malloc(sizeof(uint64_t) * (size_t)(nfirst * nw + 1)), bits;
  double *c = (double *)calloc((size_t)(3 * pad + 1), sizeof(double));
  sc_int a, b, w;
  long long k = 0;
  for (b = 0; b < nbody; ++b)
    c[b] = centre[2 * b], c[pad + b] = centre[2 * b + 1], c[2 * pad + b] = reach[b];
  sc_broad_masks(c, c + 2 * pad, tol, nfirst, nl, nbody, near);
  for (a = 0; a < nfirst; ++a)
    for (w = 0; w < nw; ++w)
      for (bits = near[a * nw + w]; bits;) {
        b = sc_broad_pop(&bits, 64 * w);
        out[2 * k] = a, out[2 * k + 1] = b, ++k;
      }
  free(near);
  free(c);
  return k;
}
"""

TABLE_SHIM = """#include <stdlib.h>
#include "scene_broad.c"
/* the pairs that contact_rows takes from the few bodies' table (sc_broad_pairs, then
 * sc_broad_near pair by pair), in its order: its count (the circles laid out as in pairs) */
long long table(sc_int nbody, sc_int nfirst, sc_int nl, const double *centre,
                const double *reach, double tol, long long *out) {
  const sc_int pad = sc_broad_pad(nbody);
  unsigned char pair[SC_BROAD_PAIRS][2];
  double far2[SC_BROAD_PAIRS], *c = (double *)calloc((size_t)(3 * pad + 1), sizeof(double));
  sc_int b, k, np;
  long long found = 0;
  for (b = 0; b < nbody; ++b)
    c[b] = centre[2 * b], c[pad + b] = centre[2 * b + 1], c[2 * pad + b] = reach[b];
  np = sc_broad_pairs(c + 2 * pad, tol, nfirst, nl, nbody, pair, far2);
  for (k = 0; k < np; ++k)
    if (sc_broad_near(c, pad, pair[k], far2[k]))
      out[2 * found] = pair[k][0], out[2 * found + 1] = pair[k][1], ++found;
  free(c);
  return found;
}
"""


@pytest.fixture(scope="module", params=["", "-DSC_NO_AVX"], ids=["as-built", "no-avx"])
def pairs(tmp_path_factory, request):
    """The engine's pairs, as built (AVX where the processor has it) and with SSE2 alone."""
    cc = find_compiler()
    assert cc is not None, "the engine needs a C compiler (cc, gcc or clang)"
    tmp = tmp_path_factory.mktemp("broad")
    (tmp / "snakecg_layout.h").write_text(LAYOUT)
    (tmp / "shim.c").write_text(SHIM)
    lib = tmp / "libbroad.so"
    flags = [request.param] if request.param else []
    subprocess.run([cc, *CORE_FLAGS, *flags, "-shared", "-I", str(tmp), "-I", str(ENGINE_DIR),
                    str(tmp / "shim.c"), "-o", str(lib), "-lm"], check=True,
                   capture_output=True)
    fn = ctypes.CDLL(str(lib)).pairs
    fn.argtypes = [ctypes.c_longlong] * 3 + [ctypes.c_void_p] * 2 + [ctypes.c_double,
                                                                     ctypes.c_void_p]
    fn.restype = ctypes.c_longlong

    def call(centre, reach, tol, nfirst, nl):
        centre = np.ascontiguousarray(centre, float)
        reach = np.ascontiguousarray(reach, float)
        out = np.zeros((nfirst * len(reach), 2), dtype=np.int64)
        k = fn(len(reach), nfirst, nl, centre.ctypes.data, reach.ctypes.data, tol,
               out.ctypes.data)
        return [tuple(p) for p in out[:k]]

    return call


def brute_force(centre, reach, tol, nfirst, nl):
    """Every pair a < b (a < nfirst; not two neighbouring links) whose circles are not apart."""
    out = []
    for a in range(nfirst):
        for b in range(a + 1, len(reach)):
            if b < nl and b - a < 2:
                continue
            dx, dy = centre[a] - centre[b]
            far = (reach[a] + reach[b] + 2 * tol) * (1 + 1e-9)
            if not dx * dx + dy * dy > far * far:
                out.append((a, b))
    return out


def test_a_snake_among_a_row_of_pegs(pairs):
    rng = np.random.default_rng(1)
    nl, npeg, tol = 11, 10, 1e-5
    for _ in range(200):  # a snake's links along a wavy line, pegs in a row beside it
        x = np.cumsum(rng.uniform(0.05, 0.1, nl))
        links = np.c_[x, 0.05 * np.sin(6 * x + rng.uniform(0, 6))]
        pegs = np.c_[np.linspace(0.0, 1.0, npeg) + rng.uniform(-0.02, 0.02, npeg),
                     rng.uniform(-0.06, 0.06, npeg)]
        centre = np.r_[links, pegs]
        reach = np.r_[rng.uniform(0.03, 0.06, nl), np.full(npeg, 0.02)]
        assert pairs(centre, reach, tol, nl, nl) == brute_force(centre, reach, tol, nl, nl)


@pytest.mark.parametrize("nbody", [1, 2, 3, 17, 63, 64, 65, 66, 130, 200])
def test_random_bodies_and_more_than_64(pairs, nbody):
    rng = np.random.default_rng(nbody)
    seen = 0
    for _ in range(20):
        centre = rng.uniform(-1.0, 1.0, (nbody, 2))
        reach = rng.uniform(0.0, 0.3, nbody)
        nl = int(rng.integers(0, nbody + 1))
        nfirst = int(rng.integers(0, nbody + 1))
        tol = 10.0 ** rng.uniform(-8, -2)
        got = pairs(centre, reach, tol, nfirst, nl)
        want = brute_force(centre, reach, tol, nfirst, nl)
        assert got == want
        seen += len(want)
    assert seen > 0 or nbody < 3  # (the test sees pairs that go on)


def test_circles_at_the_bound_and_not_a_number(pairs):
    tol = 1e-3
    reach = np.array([0.25, 0.5, 0.125, 0.5, 0.25])
    far = (0.25 + 0.5 + 2 * tol) * (1 + 1e-9)
    # body 1 exactly at the bound along x (dx^2 == far^2: not apart), body 3 just past it
    centre = np.array([[0.0, 0.0], [far, 0.0], [np.nan, 0.0], [-np.nextafter(far, 1.0), 0.0],
                       [0.0, 0.0]])
    want = brute_force(centre, reach, tol, 5, 0)
    assert (0, 1) in want and (0, 3) not in want and (0, 2) in want  # NaN: never apart
    assert pairs(centre, reach, tol, 5, 0) == want


@pytest.fixture(scope="module")
def table(tmp_path_factory):
    """The few bodies' table of pairs (at most SC_BROAD_FEW bodies) and its test."""
    cc = find_compiler()
    assert cc is not None, "the engine needs a C compiler (cc, gcc or clang)"
    tmp = tmp_path_factory.mktemp("table")
    (tmp / "snakecg_layout.h").write_text(LAYOUT)
    (tmp / "shim.c").write_text(TABLE_SHIM)
    lib = tmp / "libtable.so"
    subprocess.run([cc, *CORE_FLAGS, "-shared", "-I", str(tmp), "-I", str(ENGINE_DIR),
                    str(tmp / "shim.c"), "-o", str(lib), "-lm"], check=True,
                   capture_output=True)
    fn = ctypes.CDLL(str(lib)).table
    fn.argtypes = [ctypes.c_longlong] * 3 + [ctypes.c_void_p] * 2 + [ctypes.c_double,
                                                                     ctypes.c_void_p]
    fn.restype = ctypes.c_longlong

    def call(centre, reach, tol, nfirst, nl):
        centre = np.ascontiguousarray(centre, float)
        reach = np.ascontiguousarray(reach, float)
        out = np.zeros((max(1, nfirst * len(reach)), 2), dtype=np.int64)
        k = fn(len(reach), nfirst, nl, centre.ctypes.data, reach.ctypes.data, tol,
               out.ctypes.data)
        return [tuple(p) for p in out[:k]]

    return call


@pytest.mark.parametrize("nbody", range(1, 9))
def test_the_few_bodies_table_takes_the_same_pairs(table, nbody):
    """With at most 8 bodies contact_rows takes the pairs from a table made once and tests
    them one by one: the brute force's pairs in its order, for random bodies (some touching,
    some apart), with the circles exactly at the bound and a centre not a number."""
    rng = np.random.default_rng(100 + nbody)
    seen = 0
    for _ in range(200):
        centre = rng.uniform(-1.0, 1.0, (nbody, 2))
        reach = rng.uniform(0.0, 0.6, nbody)
        nl = int(rng.integers(0, nbody + 1))
        nfirst = int(rng.integers(0, nbody + 1))
        tol = 10.0 ** rng.uniform(-8, -2)
        want = brute_force(centre, reach, tol, nfirst, nl)
        assert table(centre, reach, tol, nfirst, nl) == want
        seen += len(want)
    assert seen > 0 or nbody < 3
    if nbody == 5:  # at the bound (not apart), just past it, and NaN (never apart)
        tol = 1e-3
        reach = np.array([0.25, 0.5, 0.125, 0.5, 0.25])
        far = (0.25 + 0.5 + 2 * tol) * (1 + 1e-9)
        centre = np.array([[0.0, 0.0], [far, 0.0], [np.nan, 0.0],
                           [-np.nextafter(far, 1.0), 0.0], [0.0, 0.0]])
        want = brute_force(centre, reach, tol, 5, 0)
        assert (0, 1) in want and (0, 3) not in want and (0, 2) in want
        assert table(centre, reach, tol, 5, 0) == want
