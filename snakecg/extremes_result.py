"""What the extremes of the metrics over the input ellipsoid return (:class:`Extremes`), the
metrics they cover (:data:`METRICS`) and the quasi-uniform directions of the input sphere
that the sampled searches start from (:func:`sphere_directions`); shared by
:mod:`snakecg.analysis`, :mod:`snakecg.pieces` and :mod:`snakecg.piecewise`."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["Extremes", "METRICS", "sphere_directions"]

METRICS = ("norm_a_obj", "norm_qdd", "norm_lambda", "sr")


@dataclass
class Extremes:
    """Best and worst value of each metric over the boundary of the input ellipsoid.

    ``max[m]`` / ``min[m]`` are arrays ``(N,)`` (scalars for one configuration);
    ``tau_max[m]`` / ``tau_min[m]`` the torques ``(N, n_a)`` attaining them
    (``tau^T B^T M_s^-1 B tau = 1``). ``min_kept`` / ``tau_min_kept`` restrict the minimum
    to torques that keep the contact (the unrestricted minimum of ``norm_a_obj`` and ``sr``
    is 0: a torque that pulls away loses the contact).
    """

    max: dict = field(default_factory=dict)
    min: dict = field(default_factory=dict)
    tau_max: dict = field(default_factory=dict)
    tau_min: dict = field(default_factory=dict)
    min_kept: dict = field(default_factory=dict)
    tau_min_kept: dict = field(default_factory=dict)
    method: str = ""
    #: Per configuration: the values are certified exact (bounded wheels, n_a <= 4: every
    #: piece searched and the forward solver agrees at the returned torques); True for the
    #: exact linear scenarios.
    certified: object = None
    pieces: int = 0
    #: Per configuration: '' where answered, else why not, in one line (the values are NaN
    #: and ``certified`` False there: e.g. a numerically singular mass matrix).
    reason: object = None

    def _squeeze(self):
        for d in (self.max, self.min, self.tau_max, self.tau_min, self.min_kept,
                  self.tau_min_kept):
            for k in d:
                d[k] = d[k][0]
        if self.certified is not None:
            self.certified = self.certified[0]
        if self.reason is not None:
            self.reason = self.reason[0]
        return self


def sphere_directions(dim: int, count: int) -> np.ndarray:
    """Quasi-uniform unit vectors in R^dim (deterministic): a circle grid for dim 2, a
    Fibonacci sphere for dim 3, a seeded Gaussian sample otherwise."""
    if dim == 1:
        return np.array([[1.0], [-1.0]])
    if dim == 2:
        a = 2 * np.pi * np.arange(count) / count
        return np.stack([np.cos(a), np.sin(a)], axis=1)
    if dim == 3:
        i = np.arange(count) + 0.5
        z = 1 - 2 * i / count
        r = np.sqrt(1 - z * z)
        a = np.pi * (1 + 5**0.5) * i
        return np.stack([r * np.cos(a), r * np.sin(a), z], axis=1)
    rng = np.random.default_rng(12345)
    d = rng.standard_normal((count, dim))
    return d / np.linalg.norm(d, axis=1, keepdims=True)
