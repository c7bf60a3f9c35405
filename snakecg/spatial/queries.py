"""The paper's queries on a spatial snake lying on the ground: the maps of one active set, and
the extremes of the metrics over the input ellipsoid (eq. 31 with the spatial ``M``).

**The maps of a state.** At rest at a configuration ``q`` the generated
``contact_system_at_rest`` gives ``M``, the Delassus matrix ``G_c``, ``b(tau)``, the free
accelerations and the maps of the forces into them; ``b`` and the free accelerations are
affine in ``tau``, so ``n_a + 1`` evaluations (``tau = 0`` and the unit torques, one batched
call) give them exactly. For an active set (the contact kept or lost, the wheels held or
absent, the ground and pitch rows always held) the held forces are
``lam_H = -G_HH^+ b_H`` (the least-norm ones where ground rows depend on each other, as in
the forward solve), affine in ``tau``: ``lam = Lam tau + lam_0``, and so are ``qdd`` and
``a_obj``. On the ground the weight is held by the ground rows alone: ``lam_0`` has no
contact or wheel part and ``qdd_0 = a_0 = 0``. A configuration whose links do not all lie
flat (axes horizontal, COMs at one height, to 1e-9), or that the forward solve does not
answer at zero torque, is not answered (NaN, with the reason).

**Extremes** (:func:`extremes`), as the planar engine does (:mod:`snakecg.analysis`):

* ``frictionless`` and ``ideal_wheels``: the map is linear on each of two half-spaces of
  torque directions (contact kept: ``c . tau >= 0``; lost), each metric a quadratic form
  there, so the extremes are the extreme generalized eigenvalues of ``(X, N)``,
  ``N = B^T M^-1 B`` (``(Omega, Omega + Xi)`` for ``sr``, on the range of ``Omega + Xi``),
  the eigenvector's sign chosen to keep or lose the contact. Exact; ``certified`` where the
  forward solve at every returned torque gives the value and the contact state (to 1e-8).
* ``wheels`` (bounds ``mu N_i`` with the solved normal forces: affine in ``tau``, not
  homogeneous): candidates (the all-stick state's eigenvectors and boundary directions)
  through the exact forward solve, then a pattern search on the boundary for the maxima:
  lower bounds of the maxima and upper bounds of the minima, not certified.
"""

from __future__ import annotations

import numpy as np

from .. import kernels
from ..analysis import _pattern_search
from ..errors import InputError
from ..extremes_result import METRICS, Extremes, sphere_directions
from ..forms_eig import Whitening, range_geig, signed
from .ground import NOT_ON_GROUND

__all__ = ["StateMaps", "state_maps", "extremes", "NOT_ON_GROUND"]

#: Relative size of the held forces' pseudo-inverse cut (the forward solve's pivot ratio).
RCOND = 1e-10
#: Relative residual of gravity's motion at zero torque above which q is not on the ground.
GROUND_TOL = 1e-9
#: Relative agreement of the forward solve with a returned extreme (the certificate).
CERTIFY_TOL = 1e-8


class StateMaps:
    """The at-rest problem of a batch of configurations, affine in ``tau``: ``M`` ``(n, nv,
    nv)``, ``G`` ``(n, nc, nc)``, ``b0`` ``(n, nc)`` and ``Bb`` ``(n, nc, na)`` with ``b =
    b0 + Bb tau``, ``q0``, ``Bq`` likewise for the free accelerations, ``Kq`` ``(n, nv, nc)``,
    ``Ka`` ``(n, 3, nc)``, the object's inertia ``I_obj`` (3,), and ``N = B^T M^-1 B``."""

    def __init__(self, model, qa: np.ndarray):
        n, na, nc = qa.shape[0], model.n_joints, model.n_constraints
        taus = np.concatenate([np.zeros((1, na)), np.eye(na)])  # tau = 0, e_1 .. e_na
        k = na + 1
        inputs = {name: value for name, value in model.scene_inputs.items()}
        o = kernels.call(model.backend, "contact_system_at_rest", n * k,
                         q=np.repeat(kernels.at_origin(qa)[0], k, axis=0),
                         tau=np.tile(taus, (n, 1)),
                         q_obj=np.zeros(3), f_obj=np.zeros(3), rho=np.zeros(2), placed=[1.0],
                         **inputs)
        shape = lambda a: a.reshape(n, k, *a.shape[1:])  # noqa: E731
        b, qf = shape(o["b"][:, :, 0]), shape(o["qdd_free"][:, :, 0])
        self.n, self.na, self.nc, self.nl = n, na, nc, model.n_links
        self.M = shape(o["M"])[:, 0]
        self.G = shape(o["delassus"])[:, 0]
        self.b0, self.Bb = b[:, 0], np.swapaxes(b[:, 1:] - b[:, :1], 1, 2)
        self.q0, self.Bq = qf[:, 0], np.swapaxes(qf[:, 1:] - qf[:, :1], 1, 2)
        self.Kq = shape(o["qdd_from_lam"])[:, 0]
        self.Ka = shape(o["a_obj_from_lam"])[:, 0]
        sc = model.scene
        self.I_obj = np.array([sc.object_mass, sc.object_mass, sc.object_inertia])
        Minv = np.linalg.inv(self.M)
        self.N = 0.5 * (Minv[:, 6:, 6:] + np.swapaxes(Minv[:, 6:, 6:], 1, 2))


def state_maps(model, qa) -> StateMaps:
    return StateMaps(model, qa)


def held_forces(S: StateMaps, held: np.ndarray):
    """``(Lam (n, nc, na), lam0 (n, nc))`` of the active set ``held`` (bool ``(nc,)``): the
    least-norm forces of the held rows, zero on the others."""
    H = np.flatnonzero(held)
    Lam = np.zeros((S.n, S.nc, S.na))
    lam0 = np.zeros((S.n, S.nc))
    for i in range(S.n):
        P = np.linalg.pinv(S.G[i][np.ix_(H, H)], rcond=RCOND, hermitian=True)
        Lam[i, H] = -P @ S.Bb[i, H]
        lam0[i, H] = -P @ S.b0[i, H]
    return Lam, lam0


def metric_forms(S: StateMaps, held: np.ndarray):
    """The metrics' quadratic forms in ``tau`` of the active set ``held`` (eqs. 26-29 with
    the spatial tensors), the contact force's row ``c`` (``lam_c = c . tau``), the maps
    themselves, and each configuration's residual at zero torque relative to its scale
    (above :data:`GROUND_TOL`: not on the ground)."""
    Lam, lam0 = held_forces(S, held)
    nl = S.nl
    Q = S.Bq + S.Kq @ Lam  # qdd = Q tau (+ q0')
    A = S.Ka @ Lam  # a_obj = A tau
    P = slice(0, nl + 1)  # the contact and the wheels: the rows of ||lambda||^2
    GP = S.G[:, P, P]
    X = {"norm_qdd": np.swapaxes(Q, 1, 2) @ S.M @ Q,
         "norm_a_obj": np.swapaxes(A, 1, 2) @ (S.I_obj[:, None] * A),
         "norm_lambda": np.swapaxes(Lam[:, P], 1, 2) @ GP @ Lam[:, P]}
    X = {k: 0.5 * (v + np.swapaxes(v, 1, 2)) for k, v in X.items()}
    q0 = S.q0 + np.einsum("bij,bj->bi", S.Kq, lam0)
    a0 = np.einsum("bij,bj->bi", S.Ka, lam0)
    weight = np.maximum(np.abs(lam0).max(axis=1), 1e-300)
    residual = np.maximum.reduce([np.abs(lam0[:, P]).max(axis=1) / weight,
                                  np.abs(q0).max(axis=1) * np.abs(S.M).max(axis=(1, 2))
                                  / weight, np.abs(a0).max(axis=1) * S.I_obj[0] / weight])
    return X, Lam[:, 0], {"Lam": Lam, "lam0": lam0, "Q": Q, "A": A}, residual


def _held(model, contact: bool, wheels: bool) -> np.ndarray:
    """Rows held: the contact (if kept), the wheels (if held), the ground and pitch rows."""
    nl = model.n_links
    held = np.zeros(model.n_constraints, bool)
    held[0] = contact
    if wheels:
        held[list(model.scene.wheel_links)] = True
    held[nl + 1:] = True
    return held


def linear_extremes(model, S: StateMaps, wheels: bool):
    """Exact extremes of a linear scenario (wheels held or absent): ``(Extremes, residual)``."""
    n = S.n
    kept, c, _, res_k = metric_forms(S, _held(model, True, wheels))
    lost, _, _, res_l = metric_forms(S, _held(model, False, wheels))
    W = Whitening(S.N)
    ex = Extremes(method="generalized eigenproblem per contact state (exact)")
    for m in ("norm_a_obj", "norm_qdd", "norm_lambda"):
        vk, Vk = W.geig(kept[m])
        vl, Vl = W.geig(lost[m])
        Vk, Vl = signed(Vk, c, keep=True), signed(Vl, c, keep=False)
        use = vk[:, -1] >= vl[:, -1]
        ex.max[m] = np.where(use, vk[:, -1], vl[:, -1])
        ex.tau_max[m] = np.where(use[:, None], Vk[:, :, -1], Vl[:, :, -1])
        use = vk[:, 0] <= vl[:, 0]
        ex.min[m] = np.where(use, vk[:, 0], vl[:, 0])
        ex.tau_min[m] = np.where(use[:, None], Vk[:, :, 0], Vl[:, :, 0])
        ex.min_kept[m], ex.tau_min_kept[m] = vk[:, 0], Vk[:, :, 0]
        for d in (ex.max, ex.min, ex.min_kept):  # squared norms: rounding below 0 clipped
            d[m] = np.maximum(d[m], 0.0)
    # sr: the quotient of (Omega, Omega + Xi) on the kept half, 0 where the contact is lost
    (vmax, umax), (vmin, umin) = range_geig(W.form(kept["norm_a_obj"]),
                                            W.form(kept["norm_a_obj"] + kept["norm_qdd"]))
    for v_, u_, store_v, store_t in ((vmax, umax, ex.max, ex.tau_max),
                                     (vmin, umin, ex.min_kept, ex.tau_min_kept)):
        t = signed(W.LinvT @ u_[:, :, None], c, keep=True)[:, :, 0]
        norm = np.sqrt(np.einsum("bi,bij,bj->b", t, S.N, t))
        store_v["sr"] = np.clip(v_, 0.0, 1.0)
        store_t["sr"] = t / np.maximum(norm, 1e-300)[:, None]
    ex.min["sr"] = np.zeros(n)
    ex.tau_min["sr"] = -ex.tau_max["sr"]
    return ex, np.maximum(res_k, res_l)


def _sampled_extremes(model, qa, S: StateMaps, samples: int, refine: int, starts: int):
    """Bounded wheels: the all-stick eigenvectors and ``samples`` boundary directions through
    the exact forward solve, a pattern search from the ``starts`` best for each maximum."""
    n, na = S.n, S.na
    stick, residual = linear_extremes(model, S, wheels=True)
    L = np.linalg.cholesky(S.N)
    Linv_T = np.swapaxes(np.linalg.inv(L), -1, -2)
    cand = [np.einsum("bij,kj->bki", Linv_T, sphere_directions(na, samples))]
    for m in METRICS:
        cand += [stick.tau_max[m][:, None], stick.tau_min_kept[m][:, None]]
    taus = np.concatenate(cand, axis=1)
    K = taus.shape[1]
    res = model.forward(np.repeat(qa, K, axis=0), taus.reshape(n * K, na))
    vals = {m: np.nan_to_num(getattr(res, m).reshape(n, K), nan=-np.inf) for m in METRICS}
    kept = res.contact.reshape(n, K)
    ex = Extremes(method=f"wheels (bounds mu N_i): all-stick eigenvectors + {samples} boundary "
                         f"directions through the exact forward solve, pattern search from "
                         f"the {starts} best ({refine} rounds) for the maxima: bounds, not "
                         f"certified")
    rows = np.arange(n)
    for m in METRICS:
        low = np.where(np.isfinite(vals[m]), vals[m], np.inf)
        i = np.argmin(low, axis=1)
        ex.min[m], ex.tau_min[m] = low[rows, i], taus[rows, i]
        lk = np.where(kept, low, np.inf)
        i = np.argmin(lk, axis=1)
        ex.min_kept[m], ex.tau_min_kept[m] = lk[rows, i], taus[rows, i]
        top = np.argsort(-vals[m], axis=1)[:, :min(starts, K)]
        t0, v0 = taus[rows[:, None], top], vals[m][rows[:, None], top]
        if refine and na >= 2:
            t0, v0 = _pattern_search(model, qa, L, Linv_T, m, t0, v0, refine)
        j = np.argmax(v0, axis=1)
        ex.max[m], ex.tau_max[m] = v0[rows, j], t0[rows, j]
    ex.certified = np.zeros(n, bool)
    return ex, residual


def _certify(model, qa, ex: Extremes) -> np.ndarray:
    """Per configuration: the forward solve at every returned torque gives the value."""
    n = qa.shape[0]
    ok = np.ones(n, bool)
    for attr, tattr in (("max", "tau_max"), ("min", "tau_min"), ("min_kept", "tau_min_kept")):
        for m in METRICS:
            r = model.forward(qa, np.ascontiguousarray(getattr(ex, tattr)[m]))
            v, want = getattr(r, m), getattr(ex, attr)[m]
            scale = np.maximum(np.abs(ex.max[m]), 1e-300)
            ok &= ~r.singular & (np.abs(v - want) <= CERTIFY_TOL * scale)
    return ok


def screen(model, qa, residual) -> np.ndarray:
    """Per configuration ``""``, or why it is not answered: not on the ground, or a state
    that the forward solve does not answer at zero torque (its reason: e.g. ground rows
    nearly but not exactly dependent), where no torque is answered either."""
    why = np.array(["" if r <= GROUND_TOL else NOT_ON_GROUND for r in residual], dtype=object)
    at_rest = model.forward(qa, np.zeros((qa.shape[0], model.n_joints)))  # (flags lifted q)
    for i in np.flatnonzero(at_rest.singular & (why == "")):
        why[i] = at_rest.reason[i]
    return why


def extremes(model, q, *, samples: int | None = None, refine: int = 10,
             starts: int = 4) -> Extremes:
    """Best and worst ``norm_a_obj``, ``norm_qdd``, ``norm_lambda`` and ``sr`` over the
    boundary of the input ellipsoid ``tau^T B^T M^-1 B tau = 1`` (eq. 31, spatial ``M``) at
    rest, with the torques attaining them: :class:`~snakecg.analysis.Extremes`, as the
    planar :meth:`~snakecg.SceneModel.extremes`. ``q``: ``(n_q,)`` or ``(N, n_q)``, lying
    on the ground. Exact and certified in ``frictionless`` and ``ideal_wheels``; in
    ``wheels`` ``samples`` boundary directions (default 64 for 2 joints, 160 for 3, 600
    above) and ``refine`` rounds of pattern search: bounds, not certified (see the module).
    A configuration that cannot be answered is NaN with its ``reason``."""
    for name, value, lo in (("refine", refine, 0), ("starts", starts, 1)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < lo:
            raise InputError(f"{name} must be an integer >= {lo}, got {value!r:.60}")
    if samples is None:
        samples = {1: 2, 2: 64, 3: 160}.get(model.n_joints, 600)
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 2:
        raise InputError(f"samples must be an integer >= 2, got {samples!r:.60}")
    qa, batched = model.configurations(q)
    S = StateMaps(model, qa)
    if model.scene.scenario == "wheels":
        ex, residual = _sampled_extremes(model, qa, S, int(samples), int(refine), int(starts))
    else:
        ex, residual = linear_extremes(model, S, wheels=model.scene.has_wheels)
        ex.certified = _certify(model, qa, ex)
    why = screen(model, qa, residual)
    for m in METRICS:  # a value that is not finite (but min_kept: NaN where nothing keeps it)
        for attr in ("max", "min"):
            lost = ~np.isfinite(getattr(ex, attr)[m]) & (why == "")
            why[lost] = f"{attr} {m} is not finite: the configuration is too ill-conditioned"
    for attr in ("max", "min", "min_kept", "tau_max", "tau_min", "tau_min_kept"):
        for v in getattr(ex, attr).values():
            v[why != ""] = np.nan
    ex.certified = np.asarray(ex.certified) & (why == "")
    ex.reason = why
    return ex if batched else ex._squeeze()
