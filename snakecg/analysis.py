"""Configuration analysis: extremes of the metrics over the input region, polar COM coordinates.

The input region is the ellipsoid of eq. (31), read as the torque's invariant norm
``tau^T B^T M_s^-1 B tau <= 1`` (the printed ``tau^T Mbar_s^-1 tau`` does not type-check:
``tau`` has ``n_a`` entries, ``M_s`` is ``n_s x n_s``). Extremes are taken over the
ellipsoid's boundary ``tau^T N tau = 1`` (``N = B^T M_s^-1 B``): the metrics are homogeneous
(quadratic or of degree 0) wherever the active set is fixed, so the boundary carries every
non-trivial extreme, and the minimum over the full ellipsoid would trivially be 0 at
``tau = 0``.

Method, per scenario:

* ``frictionless`` and ``ideal_wheels``: the map is linear on each of two half-spaces of
  torque directions: contact kept (``lam_c = c . tau >= 0``) and contact lost. Each metric is
  a quadratic form there (eqs. 26-29), and an even quadratic form takes the same extremes on
  the half of the ellipsoid as on the whole, so the extremes are the extreme generalized
  eigenvalues of ``(X, N)`` in each half (``(Omega, Omega + Xi)`` for ``sr``), with the
  eigenvector's sign chosen to keep (or lose) the contact. Exact.
* ``wheels``: the map is piecewise affine (a wheel at its friction bound contributes a fixed
  force), so the metrics are not homogeneous. Candidates: the ideal-wheels eigenvectors
  (exact whenever no wheel reaches its bound there) and a dense set of boundary directions,
  all evaluated with the exact forward solver, then the best candidates refined by a local
  search on the boundary. The tolerance is measured in the tests against much denser sampling
  and stated in docs/metrics.md.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .errors import InputError

__all__ = ["Extremes", "extremes", "com_polar", "joint_grid", "METRICS", "sphere_directions"]

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

    def _squeeze(self):
        for d in (self.max, self.min, self.tau_max, self.tau_min, self.min_kept,
                  self.tau_min_kept):
            for k in d:
                d[k] = d[k][0]
        return self


def _geig(X: np.ndarray, N: np.ndarray):
    """Generalized eigen-decomposition of symmetric ``X`` w.r.t. SPD ``N``, batched.

    Returns eigenvalues ``(B, n)`` ascending and eigenvectors ``(B, n, n)`` (columns),
    normalised so that ``v^T N v = 1``.
    """
    L = np.linalg.cholesky(N)
    Linv = np.linalg.inv(L)
    C = Linv @ X @ np.swapaxes(Linv, -1, -2)
    C = 0.5 * (C + np.swapaxes(C, -1, -2))
    vals, W = np.linalg.eigh(C)
    V = np.swapaxes(Linv, -1, -2) @ W
    return vals, V


def _signed(V: np.ndarray, c: np.ndarray, keep: bool) -> np.ndarray:
    """Flip columns of V so that ``c . v >= 0`` (keep) or ``<= 0`` (lose)."""
    s = np.einsum("bi,bij->bj", c, V)
    flip = (s < 0) if keep else (s > 0)
    return np.where(flip[:, None, :], -V, V)


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


def _forms(model, qa, *, contact: bool):
    """Quadratic forms of the metrics for every configuration with the contact kept/lost."""
    n = qa.shape[0]
    state = np.where(model.present, 1, 0).astype(np.int8)
    if not contact:
        state[0] = 2
    maps = model._maps(qa, n, state)
    N = maps["input_metric"]
    forms = {
        "norm_a_obj": maps["omega_tau"],
        "norm_qdd": maps["xi_tau"],
        "norm_lambda": maps["lambda_form_tau"],
    }
    c = maps["lam_from_tau"][:, 0, :]
    return forms, N, c, maps


def _quadratic_extremes(model, qa):
    """Exact extremes for linear scenarios (frictionless, ideal_wheels)."""
    n, na = qa.shape[0], model.n_joints
    kept, N, c, _ = _forms(model, qa, contact=True)
    lost, _, _, _ = _forms(model, qa, contact=False)
    ex = Extremes(method="generalized eigenproblem per contact state (exact)")
    for m in ("norm_a_obj", "norm_qdd", "norm_lambda"):
        vk, Vk = _geig(kept[m], N)
        vl, Vl = _geig(lost[m], N) if m != "norm_a_obj" else (np.zeros((n, na)), None)
        Vk_keep = _signed(Vk, c, keep=True)
        # max
        kmax, lmax = vk[:, -1], vl[:, -1]
        use_k = kmax >= lmax
        tmax = Vk_keep[:, :, -1].copy()
        if Vl is not None:
            Vl_lose = _signed(Vl, c, keep=False)
            tmax[~use_k] = Vl_lose[~use_k, :, -1]
        elif np.any(~use_k):  # a_obj: lost region gives 0 which only wins if kept max < 0
            tmax[~use_k] = -Vk_keep[~use_k, :, -1]
        ex.max[m] = np.where(use_k, kmax, lmax)
        ex.tau_max[m] = tmax
        # min
        kmin, lmin = vk[:, 0], vl[:, 0]
        use_k = kmin <= lmin
        tmin = Vk_keep[:, :, 0].copy()
        if Vl is not None:
            tmin[~use_k] = Vl_lose[~use_k, :, 0]
        else:
            tmin[~use_k] = -Vk_keep[~use_k, :, 0]  # pulling away: contact lost, a_obj = 0
        ex.min[m] = np.where(use_k, kmin, lmin)
        ex.tau_min[m] = tmin
        ex.min_kept[m] = kmin
        ex.tau_min_kept[m] = Vk_keep[:, :, 0]
    # slippage ratio: Rayleigh quotient of (Omega, Omega + Xi) on the kept half, 0 when lost.
    # Whiten with N first; Omega + Xi is only semidefinite where the wheels brace the snake
    # (a torque direction that moves nothing), so regularise relative to its largest eigenvalue.
    Om, Xi = kept["norm_a_obj"], kept["norm_qdd"]
    Linv = np.linalg.inv(np.linalg.cholesky(N))
    LinvT = np.swapaxes(Linv, -1, -2)
    Omw = Linv @ Om @ LinvT
    Dw = Linv @ (Om + Xi) @ LinvT
    Dw = 0.5 * (Dw + np.swapaxes(Dw, -1, -2))
    top = np.linalg.eigvalsh(Dw)[:, -1]
    Dw = Dw + (1e-12 * np.maximum(top, 1e-300))[:, None, None] * np.eye(na)
    vs, Us = _geig(Omw, Dw)
    Vs = _signed(LinvT @ Us, c, keep=True)
    norm = np.sqrt(np.einsum("bi,bij,bj->b", Vs[:, :, -1], N, Vs[:, :, -1]))
    ex.max["sr"] = np.clip(vs[:, -1], 0.0, 1.0)
    ex.tau_max["sr"] = Vs[:, :, -1] / norm[:, None]
    normin = np.sqrt(np.einsum("bi,bij,bj->b", Vs[:, :, 0], N, Vs[:, :, 0]))
    ex.min_kept["sr"] = np.clip(vs[:, 0], 0.0, 1.0)
    ex.tau_min_kept["sr"] = Vs[:, :, 0] / normin[:, None]
    ex.min["sr"] = np.zeros(n)
    ex.tau_min["sr"] = -ex.tau_max["sr"]
    return ex


def _wheels_extremes(model, qa, samples: int, refine: int, starts: int = 2):
    """Extremes for bounded wheels: exact candidates + dense boundary sampling + refinement."""
    n, na = qa.shape[0], model.n_joints
    ideal = _quadratic_extremes_for(model, qa, scenario="ideal_wheels")
    _, N, c, _ = _forms(model, qa, contact=True)
    L = np.linalg.cholesky(N)
    Linv_T = np.swapaxes(np.linalg.inv(L), -1, -2)  # tau = L^-T u maps the unit sphere
    dirs = sphere_directions(na, samples)
    cand = [np.einsum("bij,kj->bki", Linv_T, dirs)]  # (n, samples, na)
    for m in METRICS:
        cand.append(ideal.tau_max[m][:, None, :])
        cand.append(ideal.tau_min_kept[m][:, None, :])
    taus = np.concatenate(cand, axis=1)  # (n, K, na)
    K = taus.shape[1]
    res = model.forward(np.repeat(qa, K, axis=0), taus.reshape(n * K, na))
    vals = {m: getattr(res, m).reshape(n, K) for m in METRICS}
    kept = res.contact.reshape(n, K)
    ex = Extremes(method=f"wheels: ideal-wheel eigenvectors + {samples} boundary directions, "
                         f"exact forward solve, pattern search from the {starts} best of them "
                         f"({refine} rounds) for the maxima")
    rows = np.arange(n)
    for m in METRICS:
        imin = np.argmin(vals[m], axis=1)
        ex.min[m] = vals[m][rows, imin]
        ex.tau_min[m] = taus[rows, imin]
        vk = np.where(kept, vals[m], np.inf)
        ik = np.argmin(vk, axis=1)
        ex.min_kept[m] = vals[m][rows, ik]
        ex.tau_min_kept[m] = taus[rows, ik]
        k = min(starts, K)
        top = np.argsort(-vals[m], axis=1)[:, :k]  # (n, k) best starting points
        t0 = taus[rows[:, None], top]  # (n, k, na)
        v0 = vals[m][rows[:, None], top]
        if refine and na >= 2:
            t0, v0 = _pattern_search(model, qa, L, Linv_T, m, t0, v0, refine)
        j = np.argmax(v0, axis=1)
        ex.max[m] = v0[rows, j]
        ex.tau_max[m] = t0[rows, j]
    return ex


def _pattern_search(model, qa, L, Linv_T, metric, t0, v0, rounds: int):
    """Maximise ``metric`` on the ellipsoid boundary from ``k`` starts per configuration.

    Coordinates on the unit sphere ``u = L^T tau``; each round tries ``2 n_a`` moves along
    the tangent projections of the axes with a shrinking step, keeping improvements.
    """
    n, k, na = t0.shape
    LT = np.swapaxes(L, -1, -2)
    u = np.einsum("bij,bkj->bki", LT, t0)
    best = v0.copy()
    tau = t0.copy()
    step = 0.2
    qrep = np.repeat(qa, k * 2 * na, axis=0)
    for _ in range(rounds):
        moves = []
        for a in range(na):
            e = np.zeros(na)
            e[a] = 1.0
            t = e - np.sum(u * e, axis=2, keepdims=True) * u
            nt = np.linalg.norm(t, axis=2, keepdims=True)
            t = np.where(nt > 1e-12, t / np.maximum(nt, 1e-12), 0.0)
            moves += [u + step * t, u - step * t]
        cand = np.stack(moves, axis=2)  # (n, k, 2 na, na)
        cand /= np.linalg.norm(cand, axis=3, keepdims=True)
        taus = np.einsum("bij,bkmj->bkmi", Linv_T, cand)
        res = model.forward(qrep, taus.reshape(-1, na))
        v = getattr(res, metric).reshape(n, k, 2 * na)
        j = np.argmax(v, axis=2)
        vj = np.take_along_axis(v, j[..., None], axis=2)[..., 0]
        better = vj > best + 1e-15 * np.abs(best)
        best = np.where(better, vj, best)
        pick_u = np.take_along_axis(cand, j[..., None, None], axis=2)[:, :, 0]
        pick_t = np.take_along_axis(taus, j[..., None, None], axis=2)[:, :, 0]
        u = np.where(better[..., None], pick_u, u)
        tau = np.where(better[..., None], pick_t, tau)
        step *= 0.6
    return tau, best


def _quadratic_extremes_for(model, qa, scenario: str):
    """Quadratic extremes of the same robot/contact in another (linear) scenario."""
    if model.scene.scenario == scenario:
        return _quadratic_extremes(model, qa)
    from .model import SceneModel

    other = SceneModel(model.scene.replace(scenario=scenario, wheel_links=model.scene.wheel_links,
                                           contact_offset=model.scene.contact_offset))
    return _quadratic_extremes(other, qa)


def extremes(model, q, *, samples: int | None = None, refine: int = 6,
             starts: int = 2) -> Extremes:
    """Best and worst ``norm_a_obj``, ``norm_qdd``, ``norm_lambda`` and ``sr`` over the
    input ellipsoid of eq. (31), with the torques attaining them (see the module docstring).

    ``q``: ``(n_s,)`` or ``(N, n_s)``. For ``wheels``, ``samples`` boundary directions
    (default 64 for 2 joints, 120 for 3, 600 above), then ``refine`` rounds of pattern search
    from the ``starts`` best candidates of each maximum (the minima are taken over the
    candidates).
    """
    qa, batched = model._q(q)
    if model.scene.scenario == "wheels":
        if samples is None:
            samples = {1: 2, 2: 64, 3: 120}.get(model.n_joints, 600)
        if not isinstance(samples, int) or samples < 2:
            raise InputError(f"samples must be an integer >= 2, got {samples!r}")
        ex = _wheels_extremes(model, qa, samples, refine, starts)
    else:
        ex = _quadratic_extremes(model, qa)
    return ex if batched else ex._squeeze()


def com_polar(model, q):
    """Polar coordinates of the snake's COM w.r.t. the contact point (paper, Fig. 3).

    Returns ``(radius, angle)``: ``radius = |COM - P|`` (m) and ``angle`` (rad, in
    ``(-pi, pi]``) between the contacting link's axis ``e_k`` (pointing from its rear end to
    its front end) and ``COM - P``, positive counter-clockwise. Shapes ``()`` or ``(N,)``.
    """
    qa, batched = model._q(q)
    n = qa.shape[0]
    poses = model.link_poses(qa)
    m = np.asarray(model.robot.mass)
    com = np.einsum("bik,i->bk", poses[:, :, :2], m) / m.sum()
    _, _, P = model._place(qa, n)
    phi = poses[:, model.scene.contact_link - 1, 2]
    d = com - P
    e = np.stack([np.cos(phi), np.sin(phi)], axis=1)
    radius = np.linalg.norm(d, axis=1)
    angle = np.arctan2(e[:, 0] * d[:, 1] - e[:, 1] * d[:, 0], np.sum(e * d, axis=1))
    if batched:
        return radius, angle
    return radius[0], angle[0]


def joint_grid(n_joints: int, lo_deg: float = -135.0, hi_deg: float = 135.0,
               step_deg: float = 10.0) -> np.ndarray:
    """Configurations ``(N, n_s)`` with every joint on ``lo..hi`` every ``step`` degrees
    (x = y = theta = 0): the paper's grids (28 values per joint: 784 for 2 joints,
    21,952 for 3)."""
    vals = np.deg2rad(np.arange(lo_deg, hi_deg + 1e-9, step_deg))
    if len(vals) == 0:
        raise InputError("empty joint grid; check lo, hi and step")
    mesh = np.meshgrid(*([vals] * n_joints), indexing="ij")
    joints = np.stack([g.ravel() for g in mesh], axis=1)
    return np.hstack([np.zeros((joints.shape[0], 3)), joints])
