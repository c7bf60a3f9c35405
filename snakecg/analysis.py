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
* ``wheels``, up to 4 joints: exact, piece by piece (:mod:`snakecg.piecewise`): every wheel
  state meeting the boundary, the KKT points of each piece, Dinkelbach's iteration for ``sr``,
  certified per configuration (``Extremes.certified``).
* ``wheels``, 5 joints and more (or ``exact=False``): the map is piecewise affine (a wheel at
  its friction bound contributes a fixed force), so the metrics are not homogeneous.
  Candidates: the ideal-wheels eigenvectors (exact whenever no wheel reaches its bound there)
  and a dense set of boundary directions, all evaluated with the exact forward solver, then
  the best candidates refined by a local search on the boundary: lower bounds of the maxima,
  not certified.
"""

from __future__ import annotations


import numpy as np

from ._inputs import integer
from .errors import InputError
from .extremes_result import METRICS, Extremes, sphere_directions
from .forms_eig import Whitening as _Whitening
from .forms_eig import range_geig as _range_geig
from .forms_eig import signed as _signed

__all__ = ["Extremes", "extremes", "com_polar", "joint_grid", "METRICS", "sphere_directions"]

#: Keywords of :meth:`SceneModel.extremes` and their limits (larger values would take hours).
_EXTREMES_LIMITS = {"samples": (2, 100_000), "refine": (0, 1000), "starts": (1, 1000)}


def check_extremes_options(kwargs: dict) -> None:
    """The keywords of :meth:`SceneModel.extremes`, checked before any work."""
    allowed = {*_EXTREMES_LIMITS, "refined", "exact"}
    unknown = set(kwargs) - allowed
    if unknown:
        raise InputError(f"extremes() takes no keyword {sorted(unknown)[0]!r:.60} (it takes: "
                         f"{', '.join(sorted(allowed))})")
    for k, (lo, hi) in _EXTREMES_LIMITS.items():
        if k in kwargs:
            integer(k, kwargs[k], lo=lo, hi=hi, allow_none=(k == "samples"),
                    why=" (the limit)")
    if "exact" in kwargs and kwargs["exact"] is not None and not isinstance(kwargs["exact"], bool):
        raise InputError(f"exact must be True, False or None (exact bounded-wheel extremes, "
                         f"the default for up to 4 joints), got {kwargs['exact']!r:.60}")
    refined = kwargs.get("refined")
    if "refined" in kwargs and (isinstance(refined, str) or not isinstance(
            refined, (list, tuple, set, frozenset)) or not all(isinstance(m, str)
                                                               for m in refined)):
        raise InputError(f"refined must be a list of metric names (norm_a_obj, norm_qdd, "
                         f"norm_lambda, sr), got {refined!r:.60}")


def _forms(model, qa, *, contact: bool):
    """Quadratic forms of the metrics for every configuration with the contact kept/lost
    (the generated ``metric_forms``; eqs. 28, 29 and 31)."""
    from .solver import HELD, LOST

    state = np.where(model.present, HELD, 0).astype(np.int8)
    if not contact:
        state[0] = LOST
    out = model.state_forms(qa, state)
    forms = {
        "norm_a_obj": out["omega_tau"],
        "norm_qdd": out["xi_tau"],
        "norm_lambda": out["lambda_form_tau"],
    }
    return forms, out["input_metric"], out["contact_from_tau"], out


def _both_forms(model, qa):
    """``(kept, N, c, lost)``: :func:`_forms` with the contact kept and lost."""
    kept, N, c, _ = _forms(model, qa, contact=True)
    return kept, N, c, _forms(model, qa, contact=False)[0]


def _quadratic_extremes_numpy(model, qa, forms=None):
    """Exact extremes for linear scenarios (frictionless, ideal_wheels), numpy eigensolver
    (forms: :func:`_both_forms`'s, where taken)."""
    n, na = qa.shape[0], model.n_joints
    kept, N, c, lost = forms or _both_forms(model, qa)
    W = _Whitening(N)
    ex = Extremes(method="generalized eigenproblem per contact state (exact)")
    for m in ("norm_a_obj", "norm_qdd", "norm_lambda"):
        vk, Vk = W.geig(kept[m])
        vl, Vl = W.geig(lost[m]) if m != "norm_a_obj" else (np.zeros((n, na)), None)
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
        for d in (ex.max, ex.min, ex.min_kept):  # squared norms: rounding below 0 is clipped
            d[m] = np.maximum(d[m], 0.0)
    # slippage ratio: Rayleigh quotient of (Omega, Omega + Xi) on the kept half, 0 when lost.
    # Omega + Xi is only semidefinite where the wheels brace the snake (a torque direction
    # that moves nothing, and pushes nothing: Omega <= Omega + Xi), so the quotient is taken
    # on the range of Omega + Xi (rank-revealing, _range_geig), where it is defined.
    Omw = W.form(kept["norm_a_obj"])
    Dw = W.form(kept["norm_a_obj"] + kept["norm_qdd"])
    (vmax, Umax), (vmin, Umin) = _range_geig(Omw, Dw)
    for v_, u_, store_v, store_t in ((vmax, Umax, ex.max, ex.tau_max),
                                     (vmin, Umin, ex.min_kept, ex.tau_min_kept)):
        v = _signed((W.LinvT @ u_[:, :, None]), c, keep=True)[:, :, 0]
        norm = np.sqrt(np.einsum("bi,bij,bj->b", v, N, v))
        store_v["sr"] = np.clip(v_, 0.0, 1.0)
        store_t["sr"] = v / np.maximum(norm, 1e-300)[:, None]
    ex.min["sr"] = np.zeros(n)
    ex.tau_min["sr"] = -ex.tau_max["sr"]
    return ex


def _quadratic_extremes(model, qa):
    """Exact extremes for linear scenarios (frictionless, ideal_wheels).

    Uses the generated closed-form ``metric_extremes`` where the model has it (n_a <= 3) and
    numpy's batched eigensolver otherwise (and for samples with dependent rows).
    """
    if "metric_extremes" not in model.backend.signatures:
        forms = _both_forms(model, qa)
        return _at_torques(model, qa, _quadratic_extremes_numpy(model, qa, forms), forms)
    from .solver import HELD, LOST, PIVOT_TOL, _free_and_fixed

    n = qa.shape[0]
    state = np.where(model.present, HELD, 0).astype(np.int8)
    free_kept, _ = _free_and_fixed(state[None, :], model.bounds)
    state[0] = LOST
    free_lost, _ = _free_and_fixed(state[None, :], model.bounds)
    _, o = model.at_rest("metric_extremes", qa, free_kept[0], free_lost[0])
    c = o["contact_from_tau"][:, 0, :]

    def signed(t, keep):  # t: (n, na), flip so that c . t >= 0 (keep) or <= 0 (lose)
        s = np.einsum("bi,bi->b", c, t)
        flip = (s < 0) if keep else (s > 0)
        return np.where(flip[:, None], -t, t)

    ex = Extremes(method="generalized eigenproblem per contact state (exact, closed form)")
    # The forms are positive semidefinite; the closed form's smallest eigenvalue of a
    # rank-deficient form (one contact: Omega has rank 1) is exact only to ~1e-8 of the
    # largest (a double root of the cubic), so it is clipped at 0.
    for m in ("norm_a_obj", "norm_qdd", "norm_lambda"):
        vk, tk = np.maximum(o[f"{m}_kept"][:, :, 0], 0.0), o[f"tau_{m}_kept"]
        kmin, kmax = vk[:, 0], vk[:, 1]
        tk_min, tk_max = signed(tk[:, :, 0], True), signed(tk[:, :, 1], True)
        if m == "norm_a_obj":  # no contact, no push: the lost half gives exactly 0
            lmin = lmax = np.zeros(n)
            tl_min = tl_max = -tk_max
        else:
            vl, tl = np.maximum(o[f"{m}_lost"][:, :, 0], 0.0), o[f"tau_{m}_lost"]
            lmin, lmax = vl[:, 0], vl[:, 1]
            tl_min, tl_max = signed(tl[:, :, 0], False), signed(tl[:, :, 1], False)
        use_k = kmax >= lmax
        ex.max[m] = np.where(use_k, kmax, lmax)
        ex.tau_max[m] = np.where(use_k[:, None], tk_max, tl_max)
        use_k = kmin <= lmin
        ex.min[m] = np.where(use_k, kmin, lmin)
        ex.tau_min[m] = np.where(use_k[:, None], tk_min, tl_min if m != "norm_a_obj"
                                 else -tk_min)
        ex.min_kept[m] = kmin
        ex.tau_min_kept[m] = tk_min
    vs, ts = o["sr_kept"][:, :, 0], o["tau_sr_kept"]
    ex.max["sr"] = np.clip(vs[:, 1], 0.0, 1.0)
    ex.tau_max["sr"] = signed(ts[:, :, 1], True)
    ex.min_kept["sr"] = np.clip(vs[:, 0], 0.0, 1.0)
    ex.tau_min_kept["sr"] = signed(ts[:, :, 0], True)
    ex.min["sr"] = np.zeros(n)
    ex.tau_min["sr"] = -ex.tau_max["sr"]
    bad = ~(o["pivot_ratio_kept"][:, 0, 0] > PIVOT_TOL) | ~(o["pivot_ratio_lost"][:, 0, 0] >
                                                             PIVOT_TOL)
    for d in (ex.max, ex.min, ex.min_kept, ex.tau_max, ex.tau_min, ex.tau_min_kept):
        for k in d:
            bad |= ~np.all(np.isfinite(d[k].reshape(n, -1)), axis=1)
    if np.any(bad):  # dependent rows or a degenerate closed form: the regularised numpy path
        sub = np.flatnonzero(bad)
        again = _quadratic_extremes_numpy(model, np.ascontiguousarray(qa[sub]))
        for attr in ("max", "min", "min_kept", "tau_max", "tau_min", "tau_min_kept"):
            d, e = getattr(ex, attr), getattr(again, attr)
            for k in d:
                d[k][sub] = e[k]
    return _at_torques(model, qa, ex)


def _at_torques(model, qa, ex, forms=None):
    """Every extreme reported as its value at the returned torque. The largest sr: the exact
    forward solve's there (the closed form's eigenvalue is a root of a cubic with a double
    root at 0, Omega having rank one, good to ~1e-7 only; the eigensolver's is near
    rounding-level directions of Omega + Xi). The others: their forms' quotients there, where
    those differ from the eigenvalues by more than rounding (1e-14 of the largest value) and
    less than 1e-6. The cubic's roots are good to ~1e-8 only where one repeats, and without
    wheels ||qdd_s||^2 is 1 in every direction that loses the contact and in all but one that
    keeps it. The eigenvectors are good (any vector of a repeated root's space is one), and
    the quotient there to their error's square. A torque's contact state is its half of the
    ellipsoid (c . tau >= 0 keeps the contact). forms: :func:`_both_forms`'s, where taken."""
    kept, N, c, lost = forms or _both_forms(model, qa)
    scale = {m: 1e-14 * ex.max[m] for m in ("norm_a_obj", "norm_qdd", "norm_lambda")}
    for values, taus in ((ex.max, ex.tau_max), (ex.min, ex.tau_min),
                         (ex.min_kept, ex.tau_min_kept)):
        for m in ("norm_a_obj", "norm_qdd", "norm_lambda"):
            t, e = taus[m], values[m]
            K = np.where((np.einsum("bi,bi->b", c, t) >= 0)[:, None, None], kept[m], lost[m])
            v = np.einsum("bi,bij,bj->b", t, K, t) / np.einsum("bi,bij,bj->b", t, N, t)
            off = np.abs(v - e)  # (rounding, below 1e-14 of the largest value, kept as it is)
            ok = np.isfinite(v) & (off > scale[m]) & (off <= 1e-6 * np.maximum(1.0, e))
            values[m] = np.where(ok, np.maximum(v, 0.0), e)
    at = model.forward(qa, ex.tau_max["sr"])
    ok = at.contact & ~at.singular & np.isfinite(at.sr)
    ex.max["sr"] = np.where(ok, at.sr, ex.max["sr"])
    return ex


def _wheels_extremes(model, qa, samples: int, refine: int, starts: int = 4,
                     refined=METRICS):
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
        if refine and na >= 2 and m in refined:
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
        # (best is -inf where no start was answered: a configuration flagged by forward)
        better = vj > best + np.where(np.isfinite(best), 1e-15 * np.abs(best), 0.0)
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
    other = type(model)(model.scene.replace(scenario=scenario, wheel_links=model.scene.wheel_links,
                                              contact_offset=model.scene.contact_offset),
                        backend=model.backend_kind)
    return _quadratic_extremes(other, qa)


#: Largest joint count for which bounded-wheel extremes are solved exactly by default.
EXACT_WHEELS_MAX_JOINTS = 4


def extremes(model, q, *, samples: int | None = None, refine: int = 10,
             starts: int = 4, refined=METRICS, exact: bool | None = None) -> Extremes:
    """Best and worst ``norm_a_obj``, ``norm_qdd``, ``norm_lambda`` and ``sr`` over the
    input ellipsoid of eq. (31), with the torques attaining them (see the module docstring).

    ``q``: ``(n_s,)`` or ``(N, n_s)``. For ``wheels``: ``exact`` (default: ``n_a <= 4``)
    solves every piece of the piecewise-affine map exactly (:mod:`snakecg.piecewise`,
    certified per configuration in ``Extremes.certified``); otherwise ``samples`` boundary
    directions (default 64 for 2 joints, 160 for 3, 600 above), then ``refine`` rounds of
    pattern search from the ``starts`` best candidates of each maximum in ``refined`` (the
    other maxima and the minima are taken over the candidates): lower bounds of the maxima
    and upper bounds of the minima, not certified.
    """
    qa, batched = model.configurations(q)
    if exact is None:
        exact = model.n_joints <= EXACT_WHEELS_MAX_JOINTS
    if not isinstance(exact, (bool, np.bool_)):
        raise InputError(f"exact must be True, False or None (default), got {exact!r}")
    if samples is None:
        samples = {1: 2, 2: 64, 3: 160}.get(model.n_joints, 600)
    if not isinstance(samples, int) or samples < 2:
        raise InputError(f"samples must be an integer >= 2, got {samples!r}")
    bad = [m for m in refined if m not in METRICS]
    if bad:
        raise InputError(f"refined takes metric names from {METRICS}, got {bad[0]!r}")
    ex = _answered(model, qa, lambda sub: _solve(model, sub, exact, samples, refine, starts,
                                                  tuple(refined)))
    return ex if batched else ex._squeeze()


def extremes_of(model, q, chunk_rows: tuple[int, int], kwargs: dict):
    """:meth:`SceneModel.extremes`: :func:`extremes` of one configuration, or of a batch in
    chunks of rows (bounded working memory, a progress bar kept alive). ``chunk_rows``: the
    rows of one call with bounded wheels and in the closed-form scenarios."""
    from ._inputs import check_batch_memory
    from .progress import in_chunks

    check_extremes_options(kwargs)
    qa, batched = model._q(q)
    if not batched:
        return extremes(model, q, **kwargs)
    n = qa.shape[0]
    wheels = model.scene.scenario == "wheels"
    rows = chunk_rows[0] if wheels else chunk_rows[1]
    if n > rows:  # bounded working memory (kB per row inside one call): chunks of rows
        check_batch_memory("extremes", n, 8 * (24 + 24 * model.n_joints), what="results")
    # bounded wheels: chunks of 256 rows keep the progress bar alive; large batches solved
    # exactly go in chunks of chunk_rows[0] (vectorized over a chunk: faster)
    chunk = min(rows, 256) if wheels else rows
    exact = kwargs.get("exact")
    if exact is None:
        exact = model.n_joints <= EXACT_WHEELS_MAX_JOINTS
    if wheels and exact is True and n > rows:
        chunk = rows
    return in_chunks(lambda part: extremes(model, part, **kwargs), qa, chunk, "extremes",
                     always=n > rows)


def _solve(model, qa, exact, samples, refine, starts, refined):
    if model.scene.scenario == "wheels" and exact:
        from .piecewise import wheel_extremes

        ex = wheel_extremes(model, qa)
    elif model.scene.scenario == "wheels":
        ex = _wheels_extremes(model, qa, samples, refine, starts, refined)
        ex.certified = np.zeros(qa.shape[0], bool)
    else:
        ex = _quadratic_extremes(model, qa)
        ex.certified = np.ones(qa.shape[0], bool)
    return ex


def _answered(model, qa, solve) -> Extremes:
    """``solve(qa)`` on the configurations that can be answered; NaN, ``certified`` False and
    the cause in ``reason`` for the others. A configuration is screened by the forward solve
    at zero torque (a numerically singular mass matrix or a system that is not finite in
    float64 has no answer at any torque), and a numerical failure of a batch is retried one
    configuration at a time, so no LAPACK exception reaches the caller."""
    from .rows import NO_ANSWER, reason_of

    n = qa.shape[0]
    res = model.forward(qa, np.zeros((n, model.n_joints)))
    codes = res.raw[:, model.columns.status]
    why = np.array([reason_of(c) if c in NO_ANSWER else "" for c in codes], dtype=object)
    good = np.flatnonzero(why == "")
    parts = []
    if good.size:
        try:
            parts.append((good, solve(np.ascontiguousarray(qa[good]))))
        except np.linalg.LinAlgError:
            for i in good:
                try:
                    parts.append((np.array([i]), solve(np.ascontiguousarray(qa[i:i + 1]))))
                except np.linalg.LinAlgError as err:
                    why[i] = f"the linear algebra failed at this configuration ({err})"
    return _merge(n, model.n_joints, parts, why)


_FIELDS = ("max", "min", "min_kept", "tau_max", "tau_min", "tau_min_kept")


def _merge(n: int, na: int, parts, why) -> Extremes:
    """One :class:`Extremes` of ``n`` configurations from ``(indices, Extremes)`` parts; NaN
    where none answers (``why`` says why)."""
    ex = Extremes(method=parts[0][1].method if parts else "none (no configuration answered)")
    for attr in _FIELDS:
        d = getattr(ex, attr)
        for m in METRICS:
            d[m] = np.full((n, na) if attr.startswith("tau") else n, np.nan)
        for idx, part in parts:
            for m, v in getattr(part, attr).items():
                d[m][idx] = v
    ex.certified = np.zeros(n, bool)
    for idx, part in parts:
        ex.certified[idx] = part.certified
        ex.pieces += part.pieces
    # a value that is not finite, or a norm below 0 or sr outside [0, 1] (beyond rounding),
    # is no answer (min_kept is NaN where no torque keeps the contact)
    for attr in ("max", "min", "min_kept"):
        for m, v in getattr(ex, attr).items():
            tol = 1e-9 * np.abs(np.where(np.isfinite(ex.max[m]), ex.max[m], 0.0))
            with np.errstate(invalid="ignore"):
                impossible = (v < -tol) | (v > 1 + 1e-9 if m == "sr" else False)
                impossible |= np.isinf(v) | (np.isnan(v) & (attr != "min_kept"))
            for i in np.flatnonzero(impossible & (why == "")):
                why[i] = (f"{attr} {m} is not a possible value in float64 ({v[i]:.3g}): "
                          f"the configuration is too ill-conditioned to answer")
    lost = why != ""
    if np.any(lost):
        for attr in _FIELDS:
            for m in METRICS:
                getattr(ex, attr)[m][lost] = np.nan
        ex.certified[lost] = False
    ex.reason = why
    return ex


def com_polar(model, q):
    """Polar coordinates of the snake's COM w.r.t. the contact point (paper, Fig. 3).

    Returns ``(radius, angle)``: ``radius = |COM - P|`` (m) and ``angle`` (rad, in
    ``(-pi, pi]``) between the contacting link's axis ``e_k`` (pointing from its rear end to
    its front end) and ``COM - P``, positive counter-clockwise. Shapes ``()`` or ``(N,)``.
    """
    qa, batched = model.configurations(q)
    n = qa.shape[0]
    model._check_memory("com_polar", n, ["link_poses", "place_object"],
                        extra=3 * model.n_links + 12)
    poses = model.link_poses(qa)
    m = np.asarray(model.robot.mass)
    com = np.einsum("bik,i->bk", poses[:, :, :2], m) / m.sum()
    _, _, P = model.place(qa, n)
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
