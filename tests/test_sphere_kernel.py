"""The compiled faces and KKT candidates (snakecg/engine/sphere.c) against NumPy's path
(snakecg.sphere_kkt: QR cuts and the Gander-Golub-von Matt eigenvalue linearization) and
against dense sampling of each face's sphere; the exact bounded-wheel extremes by both paths."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import snakecg
from snakecg import sphere_kkt as sk
from snakecg.analysis import METRICS, joint_grid
from snakecg.piecewise import face_kernel, wheel_extremes


@pytest.fixture(scope="module")
def wheels():
    return snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels",
                                      kappa=100.0, mu=0.1))


@pytest.fixture(scope="module")
def kernel(wheels):
    k = face_kernel(wheels)
    assert k is not None, "the compiled model has no sphere kernel"
    return k


def _pieces(rng, P, m, na):
    """Random pieces: ``m`` normalized conditions, some slots unused (0 . u + 1)."""
    cond = rng.normal(size=(P, m, na + 1))
    cond[:, :, na] *= 0.6
    used = rng.uniform(size=(P, m)) < 0.8
    cond[~used] = 0.0
    cond[~used, na] = 1.0
    cond /= np.abs(cond).max(axis=2, keepdims=True)
    return cond, used


def _quadratics(rng, P, na):
    A = rng.normal(size=(P, na, na))
    A = A + np.swapaxes(A, 1, 2)
    g = rng.normal(size=(P, na))
    c = rng.normal(size=P)
    # hard cases: g = 0 (every eigenvector's point), repeated eigenvalues, g orthogonal to an
    # eigenvector of A
    A[0], g[0] = np.diag(np.arange(1.0, na + 1)), 0.0
    A[1] = np.eye(na) * 2.0
    ev, V = np.linalg.eigh(A[2])
    g[2] = V[:, 1:] @ rng.normal(size=na - 1)
    return A, g, c


@pytest.mark.parametrize("na", [2, 3, 4, 5])
def test_cut_matches_numpy(kernel, na):
    """Each face (conditions at equality cut with the unit sphere): the same faces in the same
    order, the same centre and radius, and the same plane (Z Z^T) as NumPy's QR cut."""
    rng = np.random.default_rng(na)
    cond, used = _pieces(rng, 300, 5, na)
    ref = sk.faces(cond, used, na)
    got = sk.faces(cond, used, na, kernel)
    assert len(ref) == len(got) == min(5, na - 1) + 1
    for a, b in zip(ref[1:], got[1:]):
        assert len(a.pair) > 0
        np.testing.assert_array_equal(a.pair, b.pair)
        np.testing.assert_array_equal(a.slots, b.slots)
        np.testing.assert_allclose(b.u0, a.u0, atol=1e-12)
        np.testing.assert_allclose(b.r, a.r, atol=1e-12)
        proj = np.swapaxes(a.Z, 1, 2)
        np.testing.assert_allclose(b.Z @ np.swapaxes(b.Z, 1, 2), a.Z @ proj, atol=1e-12)
        # orthonormal, orthogonal to the conditions, u0 on them
        k = b.Z.shape[2]
        np.testing.assert_allclose(np.swapaxes(b.Z, 1, 2) @ b.Z,
                                   np.broadcast_to(np.eye(k), (len(b.pair), k, k)), atol=1e-12)
        rows = cond[b.pair[:, None], b.slots]
        np.testing.assert_allclose(rows[:, :, :na] @ b.Z, 0.0, atol=1e-12)
        np.testing.assert_allclose(np.einsum("fsi,fi->fs", rows[:, :, :na], b.u0)
                                   + rows[:, :, na], 0.0, atol=1e-12)


@pytest.mark.parametrize("na", [2, 3, 4])
def test_meets_matches_numpy(kernel, na):
    rng = np.random.default_rng(10 + na)
    cond, used = _pieces(rng, 400, 6, na)
    d = rng.normal(size=na)
    d /= np.linalg.norm(d)
    for fc in sk.faces(cond, used, na)[1:]:
        ref = sk.feasible(cond[fc.pair], sk.linear_candidates(fc, d)).any(axis=1)
        got = sk.meets(cond, fc, d, kernel)
        assert ref.any() and not ref.all()
        np.testing.assert_array_equal(got, ref)


def _dense_face(fc, rows, A, g, c, count, rng):
    """The quadratic at ``count`` random points of each face sphere (F, count)."""
    F, k = len(rows), fc.Z.shape[2]
    y = rng.normal(size=(F, count, k))
    y *= fc.r[rows, None, None] / np.linalg.norm(y, axis=2, keepdims=True)
    u = fc.u0[rows, None, :] + y @ np.swapaxes(fc.Z[rows], 1, 2)
    q = fc.pair[rows]
    return sk.quad(A[q], g[q], c[q], u), u


@pytest.mark.parametrize("na", [2, 3, 4])
def test_candidates_match_numpy_and_dense_sampling(kernel, na):
    """Per face: the largest and smallest value over the stationary points (the extremes over
    the face's whole sphere) agree with NumPy's candidates to 1e-10 and bound a dense sample
    of the sphere, which comes within 1e-3 of them; the feasible extremes agree with NumPy's
    and are attained at the returned points, which lie on the face and satisfy the piece."""
    rng = np.random.default_rng(20 + na)
    P = 120
    cond, used = _pieces(rng, P, 4, na)
    A, g, c = _quadratics(rng, P, na)
    for level, fc in enumerate(sk.faces(cond, used, na)):
        rows = np.arange(len(fc.pair))
        q = fc.pair
        u = sk.quadratic_candidates(fc.u0, fc.Z, fc.r, A[q], g[q])
        v = sk.quad(A[q], g[q], c[q], u)
        feas = sk.feasible(cond[q], u)
        whole = level == 0
        vmax, umax, vmin, umin, hi, lo = kernel.candidates(
            q, None if whole else fc.u0, None if whole else fc.Z, None if whole else fc.r,
            A, g, c, cond, sk.FEAS_TOL, identity=whole)
        scale = np.abs(v).max(axis=1) + 1.0
        np.testing.assert_allclose(hi, v.max(axis=1), atol=1e-10 * scale.max())
        np.testing.assert_allclose(lo, v.min(axis=1), atol=1e-10 * scale.max())
        dense, _ = _dense_face(fc, rows, A, g, c, 4000 if fc.Z.shape[2] > 1 else 2, rng)
        assert np.all(dense.max(axis=1) <= hi + 1e-10 * scale)
        assert np.all(dense.min(axis=1) >= lo - 1e-10 * scale)
        if fc.Z.shape[2] == 2:  # a circle: the dense sample comes close to the extremes
            assert np.all(dense.max(axis=1) >= hi - 1e-3 * scale)
        # NumPy's candidates include the real parts of complex eigenvalues, points of the
        # sphere that are not stationary: only its stationary points count (the tangential
        # gradient of the quadratic on the face vanishes)
        grad = np.einsum("fij,fcj->fci", A[q], u) + g[q][:, None]
        gt = np.einsum("fik,fci->fck", fc.Z, grad)  # gradient in the face's coordinates
        y = np.einsum("fik,fci->fck", fc.Z, u - fc.u0[:, None])
        ny2 = np.maximum(np.sum(y * y, axis=2, keepdims=True), 1e-300)
        tang = gt - np.sum(gt * y, axis=2, keepdims=True) / ny2 * y
        stat = np.linalg.norm(tang, axis=2) <= 1e-6 * (np.linalg.norm(gt, axis=2) + 1.0)
        feas &= stat
        ref_max = np.where(feas, v, -np.inf).max(axis=1)
        ref_min = np.where(feas, v, np.inf).min(axis=1)
        has = np.isfinite(ref_max)
        assert has.any()
        np.testing.assert_allclose(vmax[has], ref_max[has], atol=1e-9 * scale.max())
        np.testing.assert_allclose(vmin[has], ref_min[has], atol=1e-9 * scale.max())
        # skipped faces (bounds within skip) return bounds enclosing the extremes; a skip
        # window no bound fits in changes nothing
        args = (q, None if whole else fc.u0, None if whole else fc.Z,
                None if whole else fc.r, A, g, c, cond, sk.FEAS_TOL)
        bmax, _, bmin, _, bhi, blo = kernel.candidates(*args, identity=whole,
                                                       skip=(np.inf, -np.inf))
        assert np.all(np.isneginf(bmax)) and np.all(np.isposinf(bmin))
        assert np.all(bhi >= hi) and np.all(blo <= lo)
        same = kernel.candidates(*args, identity=whole, skip=(-np.inf, np.inf))
        for x, y in zip(same, (vmax, umax, vmin, umin, hi, lo)):
            np.testing.assert_array_equal(x, y)
        for val, pt in ((vmax, umax), (vmin, umin)):
            ok = np.isfinite(val)
            np.testing.assert_allclose(sk.quad(A[q[ok]], g[q[ok]], c[q[ok]], pt[ok, None])[:, 0],
                                       val[ok], atol=1e-12 * scale.max())
            assert sk.feasible(cond[q[ok]], pt[ok, None]).all()
            off = pt[ok] - fc.u0[ok]
            np.testing.assert_allclose(np.linalg.norm(off, axis=1), fc.r[ok], atol=1e-12)


def test_candidates_refuse_bad_shapes(kernel):
    A = np.zeros((2, 3, 3))
    with pytest.raises(ValueError, match="per-pair"):
        kernel.candidates(np.zeros(1, int), None, None, None, A, np.zeros((2, 2)),
                          np.zeros(2), np.zeros((2, 1, 4)), 1e-9, identity=True)
    with pytest.raises(ValueError, match="pair index"):
        kernel.candidates(np.array([5]), None, None, None, A, np.zeros((2, 3)),
                          np.zeros(2), np.zeros((2, 1, 4)), 1e-9, identity=True)


def test_wheel_extremes_compiled_equal_numpy(wheels):
    """Case study 2's bounded wheels on 300 configurations of its grid: the compiled faces and
    candidates give the extremes of NumPy's path (to 1e-9 of each metric's scale; NumPy's
    hard-case points are the cruder ones), both certified by the forward solver."""
    qs = joint_grid(3)[::73]
    a = wheel_extremes(wheels, qs, compiled=False)
    b = wheel_extremes(wheels, qs, compiled=True)
    assert a.certified.all() and b.certified.all()
    assert a.pieces == b.pieces
    for key in ("max", "min", "min_kept"):
        for m in METRICS:
            x, y = getattr(a, key)[m], getattr(b, key)[m]
            np.testing.assert_array_equal(np.isnan(x), np.isnan(y))
            scale = 1.0 if m == "sr" else a.max[m]
            ok = ~np.isnan(x)
            assert np.all(np.abs(x[ok] - y[ok]) <= 1e-9 * scale[ok] if m != "sr"
                          else np.abs(x[ok] - y[ok]) <= 1e-9), (key, m)


def test_cut_combinations_are_numpys_order(kernel):
    """The slots of the faces come in itertools.combinations order per pair."""
    rng = np.random.default_rng(3)
    cond, used = _pieces(rng, 5, 4, 4)
    used[:] = True
    pair, slots, *_ = kernel.cut(cond, used, 2)
    combos = list(itertools.combinations(range(4), 2))
    for p in range(5):
        got = [tuple(s) for s in slots[pair == p]]
        assert got == [cmb for cmb in combos if cmb in got]


def test_pieces_match_numpy(wheels, kernel):
    """Each (configuration, state) pair's affine maps and conditions from the compiled core
    equal NumPy's (its masked solve of the held rows, eq. 16 with the sliding wheels' fixed
    forces) to rounding, for random pairs of every state; and the maps solve the held rows:
    G lam + Bt u = w with w = 0 on the held rows."""
    from snakecg.pieces import all_states, piece, primitives

    qs = joint_grid(3)[::211]
    prim = primitives(wheels, qs)
    states = all_states(wheels)
    rng = np.random.default_rng(5)
    p = rng.integers(0, len(qs), 2000)
    s = rng.integers(0, len(states), 2000)
    a = piece(prim, wheels.bounds, p, states[s])
    b = piece(prim, wheels.bounds, p, states[s], kernel)
    for key in ("lam", "w", "qdd", "a_obj"):
        for x, y in zip(a[key], b[key]):
            np.testing.assert_allclose(y, x, rtol=0, atol=1e-13 * np.abs(x).max())
    np.testing.assert_allclose(b["cond"], a["cond"], rtol=0, atol=1e-13)
    np.testing.assert_array_equal(b["flip"], a["flip"])
    used = a["flip"] >= 0
    np.testing.assert_array_equal(b["row"][used], a["row"][used])
    (Lam, _lam0), (W, w0) = b["lam"], b["w"]
    held = states[s] == 1
    G, Bt = prim["G"][p], prim["Bt"][p]
    np.testing.assert_allclose(W, G @ Lam + Bt, atol=1e-12)
    assert np.abs(np.where(held[:, :, None], W, 0.0)).max() < 1e-9
    assert np.abs(np.where(held, w0, 0.0)).max() < 1e-9
