"""The optimal-torque tasks of a general scene where the links may slide (Coulomb or
anisotropic ground, or ``allow_slide``): a search of the input region by the compiled forward
solve (:class:`~snakecg.scenes.extremes_bounds.Sampler`), then a pattern search from the best
samples. The answer is attained (the forward solve's own value at ``tau``) but not certified:
status ``local`` (see :mod:`snakecg.scenes.optimize`)."""

from __future__ import annotations

import numpy as np

from ..extremes_result import sphere_directions
from .extremes import whitening
from .extremes_bounds import Sampler

__all__ = ["search", "DIRECTIONS", "RADII", "ROUNDS"]

#: sr is taken where ``|a|_M^2`` is at least this fraction of the free motion's.
MOTION_FLOOR = 1e-8
#: Directions of the region's boundary sampled, radii per direction, pattern-search rounds.
DIRECTIONS, RADII, ROUNDS = 1500, 16, 60


def _region_scale(p, task, taus):
    """The largest ``t`` per row with ``t tau`` in the region."""
    s = np.full(len(taus), np.inf)
    if task["radius"] is not None:
        n = np.sqrt(np.maximum(np.einsum("ki,ij,kj->k", taus, p.N, taus), 1e-300))
        s = np.minimum(s, task["radius"] / n)
    if task["tau_max"] is not None:
        with np.errstate(divide="ignore"):
            s = np.minimum(s, np.min(task["tau_max"] / np.abs(taus), axis=1))
    return s


def _score(p, task, vals):
    """The value to minimise per sample (inf where the task is not met)."""
    ok = vals["_ok"]
    if task["objective"] == "max_sr":
        # sr where the system moves: |a|^2 at least MOTION_FLOOR of the free motion's (below,
        # sr is a ratio of rounding errors)
        moving = vals["_D"] >= MOTION_FLOOR * vals["_free"]
        return np.where(ok, -np.where(moving, vals["sr"], 0.0), np.inf)
    j = task["object"] - 1
    ao = vals["_a"][:, p.n_s + 3 * j:p.n_s + 3 * j + 3]
    push = ao @ task["direction"]
    if task["objective"] == "strongest_push":
        return np.where(ok, -push, np.inf)
    return np.where(ok & (push >= task["a_min"]), vals["norm_qdd"], np.inf)


def search(model, p, task, starts: int = 4):
    """``(tau, value, samples)``: the best torque found (None where no sample meets the
    task) and its objective (sr, ``||qdd_s||^2`` or ``d . a_o``)."""
    sampler = Sampler(model, p)
    T = whitening(p)
    dirs = sphere_directions(p.n_a, DIRECTIONS) @ T.T
    dirs *= _region_scale(p, task, dirs)[:, None]
    radii = (np.arange(1, RADII + 1) / RADII) ** 2 if task["objective"] == "least_slip_push" \
        else np.array([1.0])
    taus = (radii[:, None, None] * dirs[None]).reshape(-1, p.n_a)
    score = _score(p, task, sampler(taus))
    order = np.argsort(score)[:starts]
    order = order[np.isfinite(score[order])]
    if order.size == 0:
        return None, np.nan, sampler.count
    x, fx = taus[order].copy(), score[order].copy()
    size = np.sqrt(np.max(np.einsum("ki,ij,kj->k", dirs, p.N, dirs)))
    step = 0.1
    eye = np.linalg.cholesky(np.linalg.inv(p.N))  # moves of unit N-norm along its axes
    moves = np.vstack([eye.T, -eye.T]) * size
    for _ in range(ROUNDS):
        cand = (x[:, None, :] + step * moves[None]).reshape(-1, p.n_a)
        cand *= np.minimum(_region_scale(p, task, cand), 1.0)[:, None]
        sc = _score(p, task, sampler(cand)).reshape(len(x), -1)
        k = np.argmin(sc, axis=1)
        better = sc[np.arange(len(x)), k] < fx - 1e-15 * np.abs(fx)
        x[better] = cand.reshape(len(x), -1, p.n_a)[better, k[better]]
        fx[better] = sc[better, k[better]]
        if not better.any():
            step *= 0.5
            if step < 1e-9:
                break
    i = int(np.argmin(fx))
    value = -fx[i] if task["objective"] != "least_slip_push" else fx[i]
    return x[i], float(value), sampler.count
