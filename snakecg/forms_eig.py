"""Extreme Rayleigh quotients of batched symmetric forms (the metrics' quadratic forms in
the torque, :mod:`snakecg.analysis`): whitening by a positive definite metric, and the
quotient of two forms on the range of a semidefinite one (rank-revealing)."""

from __future__ import annotations

import numpy as np

__all__ = ["Whitening", "range_geig", "signed", "RANK_TOL"]


def _tri_inv(L: np.ndarray) -> np.ndarray:
    """Inverse of batched lower-triangular matrices (explicit for n <= 4, else numpy)."""
    n = L.shape[-1]
    if n > 4:
        return np.linalg.inv(L)
    Li = np.zeros_like(L)
    d = 1.0 / np.diagonal(L, axis1=-2, axis2=-1)
    for i in range(n):
        Li[:, i, i] = d[:, i]
        for j in range(i):
            s = np.zeros(L.shape[0])
            for k in range(j, i):
                s += L[:, i, k] * Li[:, k, j]
            Li[:, i, j] = -s * d[:, i]
    return Li


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-300)


def _eigh_small(C: np.ndarray, vectors: bool = True):
    """Batched symmetric eigendecomposition, ascending: closed form for n <= 2 (vectorized,
    faster than ``numpy.linalg.eigh`` on many tiny matrices), numpy otherwise."""
    n = C.shape[-1]
    if not vectors and n > 2:
        return np.linalg.eigvalsh(C), None
    if n == 1:
        return C[:, :, 0].copy(), np.ones_like(C)
    if n == 2:
        a, b, c = C[:, 0, 0], C[:, 0, 1], C[:, 1, 1]
        mean, r = 0.5 * (a + c), np.hypot(0.5 * (a - c), b)
        vals = np.stack([mean - r, mean + r], axis=1)
        lam = vals[:, 1]
        v1 = np.stack([b, lam - a], axis=1)
        v2 = np.stack([lam - c, b], axis=1)
        use2 = np.linalg.norm(v2, axis=1) > np.linalg.norm(v1, axis=1)
        vmax = _unit(np.where(use2[:, None], v2, v1))
        vmax = np.where((r > 0)[:, None], vmax, np.array([1.0, 0.0]))
        vmin = np.stack([-vmax[:, 1], vmax[:, 0]], axis=1)
        return vals, np.stack([vmin, vmax], axis=2)
    return np.linalg.eigh(C)


class Whitening:
    """``N = L L^T``: maps forms to ``L^-1 X L^-T`` and eigenvectors back (``v^T N v = 1``)."""

    def __init__(self, N: np.ndarray):
        self.N = N
        self.Linv = _tri_inv(np.linalg.cholesky(N))
        self.LinvT = np.swapaxes(self.Linv, -1, -2)

    def form(self, X: np.ndarray) -> np.ndarray:
        C = self.Linv @ X @ self.LinvT
        return 0.5 * (C + np.swapaxes(C, -1, -2))

    def geig(self, X: np.ndarray):
        vals, W = _eigh_small(self.form(X))
        return vals, self.LinvT @ W


#: Eigenvalues of ``Omega + Xi`` (whitened) below this fraction of the largest are its null
#: space: the forms carry rounding of ~1e-13 of the largest at 30 joints (a quotient of two
#: rounding errors would mean nothing), and a torque direction moving the snake this little
#: carries no meaningful sr.
RANK_TOL = 1e-10


def range_geig(Om: np.ndarray, D: np.ndarray):
    """Largest and smallest Rayleigh quotient ``u^T Om u / u^T D u`` of batched symmetric
    ``Om``, ``D`` (``D`` positive semidefinite, ``Om`` zero on its null space) over the
    range of ``D``: ``((vmax, umax), (vmin, umin))`` with ``u^T D u = 1``.

    Rank-revealing: ``D = U diag(d) U^T`` (eigh); the directions with ``d <= RANK_TOL
    max d`` are ``D``'s null space, where the quotient is 0/0 and means nothing (a torque that
    moves nothing). On the others, ``C = S^-1/2 U^T Om U S^-1/2``; the null directions get the
    eigenvalue -1 in ``C`` (decoupled: below every quotient, which lies in [0, 1] for sr), so
    the smallest real quotient is the first eigenvalue above -1/2."""
    n, k = D.shape[0], D.shape[-1]
    d, U = np.linalg.eigh(0.5 * (D + np.swapaxes(D, -1, -2)))
    top = np.maximum(d[:, -1:], 1e-300)
    keep = d > RANK_TOL * top
    sinv = np.where(keep, 1.0 / np.sqrt(np.where(keep, d, 1.0)), 0.0)
    P = U * sinv[:, None, :]  # (n, k, k): columns U_j / sqrt(d_j), 0 for the null space
    C = np.swapaxes(P, -1, -2) @ Om @ P
    C = 0.5 * (C + np.swapaxes(C, -1, -2))
    C = C - np.where(keep, 0.0, 1.0)[:, :, None] * np.eye(k)  # -1 on the null directions
    vals, Y = np.linalg.eigh(C)
    V = P @ Y
    rows = np.arange(n)
    imax = np.full(n, k - 1)
    imin = np.argmax(vals > -0.5, axis=1)
    none = ~np.any(keep, axis=1)  # D = 0: nothing moves at all; no quotient
    vmax, vmin = vals[rows, imax], vals[rows, imin]
    vmax = np.where(none, np.nan, vmax)
    vmin = np.where(none, np.nan, vmin)
    return (vmax, V[rows, :, imax]), (vmin, V[rows, :, imin])


def signed(V: np.ndarray, c: np.ndarray, keep: bool) -> np.ndarray:
    """Flip columns of V so that ``c . v >= 0`` (keep) or ``<= 0`` (lose)."""
    s = np.einsum("bi,bij->bj", c, V)
    flip = (s < 0) if keep else (s > 0)
    return np.where(flip[:, None, :], -V, V)
