"""The problems of :mod:`snakecg.optimize` at one configuration: the all-held maps
(eqs. 17, 22, 24, 28, 29, 31), the constraint rows in ``z = (tau, t)`` (task, contact,
wheels, the input region), and the task as a bound on the contact force."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..solver import ABSENT, HELD, PIVOT_TOL, SLIDE_NEG, SLIDE_POS
from .fast import dot, matvec, one_sample_maps
from .query import Query
from .result import CONTACT, ELLIPSOID, FRICTION_MARGIN, NORMAL, joint_name, wheel_name
from .solvers import Problem

@dataclass
class Config:
    q: np.ndarray
    L: np.ndarray  # (n_c, n) lam = L tau (everything held)
    Xi: np.ndarray  # eq. 28
    Om: np.ndarray  # eq. 29
    N: np.ndarray  # input metric
    a_dir: np.ndarray  # (3,) a_obj = a_dir * lam_c
    k: float  # ||a_dir||^2 in the object's metric
    singular: bool
    widths: np.ndarray | None = None  # half-widths of the box rows (set per query)
    fl: dict | None = None  # the maps as lists of floats (:func:`floats`)


def floats(cfg: Config) -> dict:
    """The maps as lists of floats (for :mod:`snakecg.optimize.fast`), made once."""
    if cfg.fl is None:
        cfg.fl = {"L": cfg.L.tolist(), "Xi": cfg.Xi.tolist(), "Om": cfg.Om.tolist(),
                  "N": cfg.N.tolist()}
    return cfg.fl


def configs(model, qa: np.ndarray) -> list[Config]:
    n = qa.shape[0]
    if n == 1:  # one sample: the maps through preallocated buffers
        maps = one_sample_maps(model, qa[0])
        if maps is not None:
            L, A, Xi, Om, N, Io = maps
            fl = {"L": L.tolist(), "Xi": Xi.tolist(), "Om": Om.tolist(), "N": N.tolist()}
            ell = fl["L"][0]
            ll = dot(ell, ell)
            a_dir = [x / ll for x in matvec(A.tolist(), ell)] if ll > 0 else [0.0] * 3
            k = sum(i * a * a for i, a in zip(Io, a_dir))
            return [Config(q=qa[0], L=L, Xi=Xi, Om=Om, N=N, a_dir=np.array(a_dir), k=k,
                           singular=False, fl=fl)]
    state = np.where(model.present, HELD, ABSENT).astype(np.int8)
    mp = model.state_maps(qa, state)
    Io = np.array([model.scene.object_mass, model.scene.object_mass, model.scene.object_inertia])
    out = []
    for b in range(n):
        L = mp["lam_from_tau"][b]
        A = mp["a_obj_from_tau"][b]
        ell = L[0]
        ll = ell @ ell
        a_dir = A @ ell / ll if ll > 0 else np.zeros(3)
        out.append(Config(
            q=qa[b], L=L, Xi=mp["xi_tau"][b], Om=mp["omega_tau"][b],
            N=mp["input_metric"][b], a_dir=a_dir, k=float(a_dir @ (Io * a_dir)),
            singular=bool(mp["singular"][b]) if "singular" in mp
            else not mp["pivot_ratio"][b] > PIVOT_TOL,
        ))
    return out


def region_box(query: Query, cfg: Config) -> np.ndarray:
    """Half-widths of the box rows: the box limits, or the ellipsoid's bounding box, or both."""
    if cfg.widths is not None:
        return cfg.widths
    widths = np.full(cfg.N.shape[0], np.inf)
    if query.radius is not None:
        widths = query.radius * np.sqrt(np.diag(np.linalg.inv(cfg.N)))
    if query.tau_max is not None:
        widths = np.minimum(widths, query.tau_max)
    cfg.widths = widths
    return widths


def rows(model, query: Query, cfg: Config):
    """Empty row layout: task (0), contact (1), wheels (2 per row), box (2 per joint)."""
    n, nc = cfg.N.shape[0], model.n_constraints
    R = 2 + 2 * (nc - 1) + 2 * n
    A = np.zeros((R, n + 1))
    lba = np.full(R, -np.inf)
    uba = np.full(R, np.inf)
    names = [""] * R
    # box rows: tau_j + w_j t >= 0, w_j t - tau_j >= 0
    widths = region_box(query, cfg)
    box_name = [joint_name(j + 1) if query.tau_max is not None and
                (query.radius is None or query.tau_max[j] <= widths[j] * (1 + 1e-12))
                else ELLIPSOID for j in range(n)]
    base = 2 + 2 * (nc - 1)
    for j in range(n):
        for sgn, r in ((1.0, base + 2 * j), (-1.0, base + 2 * j + 1)):
            A[r, j] = sgn
            A[r, n] = widths[j]
            lba[r] = 0.0
            names[r] = box_name[j]
    return A, lba, uba, names


def stick_rows(model, cfg, A, lba, uba, names, L_h, slide_state=None, W_h=None):
    """Wheel rows: stick (``|lam_i| <= u_i t``) or the sliding sign condition on ``w_i``."""
    n = cfg.N.shape[0]
    for i in range(1, model.n_constraints):
        u = model.bounds[i]
        if not model.present[i] or not np.isfinite(u):
            continue
        r = 2 + 2 * (i - 1)
        s = HELD if slide_state is None else slide_state[i]
        if s == HELD:
            ub = u * (1 - FRICTION_MARGIN)
            A[r, :] = -L_h[i]
            A[r, n] += ub
            A[r + 1, :] = L_h[i]
            A[r + 1, n] += ub
            lba[r] = lba[r + 1] = 0.0
            names[r] = names[r + 1] = wheel_name(i)
        elif s == SLIDE_POS:  # force at +u, the wheel slides with w_i <= 0
            A[r, :] = -W_h[i]
            lba[r] = 0.0
            names[r] = wheel_name(i)
        elif s == SLIDE_NEG:
            A[r, :] = W_h[i]
            lba[r] = 0.0
            names[r] = wheel_name(i)


def scale_of(query, cfg):
    w = region_box(query, cfg)
    return np.append(w, 1.0)


def homog(M, c=None):
    """``[M, c]``: a map in ``tau`` extended to ``z = (tau, t)`` (offset ``c``, default 0)."""
    c = np.zeros(M.shape[0]) if c is None else c
    return np.hstack([M, c[:, None]])


@dataclass
class Answer:
    """One configuration's answer before the forward check; ``claim`` says what optimality
    the answer claims, for :mod:`snakecg.optimize.certificate`: ``("push", lam_lo, equal,
    lp)`` (the least-slip QP / strongest-push LP in ``tau``), ``("eigen",)`` (max_sr, every
    row held) or ``("state", problem, z)`` (max_sr, the winning wheel state's problem in
    ``z``)."""

    tau: np.ndarray
    status: str
    reason: str
    binding: tuple
    solver: str
    iterations: int
    expected: float | None  # the optimiser's objective value (checked against forward)
    states: np.ndarray | None = None  # assumed row states (max_sr with sliding)
    claim: tuple | None = None


def push_target(query, cfg):
    """The task as a bound on the contact force (``a_obj = a_dir lam_c``).

    Returns ``(lam_lo, equal, gain, structural)``: the task is ``lam_c >= lam_lo`` (``==``
    when ``equal``); ``gain`` converts ``lam_c`` into the task's acceleration (``d . a_obj``,
    or ``|a_obj|`` for a full acceleration); ``structural`` is ``(reason, binding)`` when no
    torque whatsoever can do the task."""
    a_dir = cfg.a_dir
    ax, ay, aa = a_dir.tolist()
    na = math.sqrt(ax * ax + ay * ay + aa * aa)
    if na == 0 or cfg.k <= 0:
        return None, False, 0.0, ("no torque accelerates the object at this configuration",
                                  (CONTACT,))
    nrm = [v / max(math.hypot(ax, ay), 1e-300) for v in (ax, ay)]
    if query.a_obj is not None:
        a = query.a_obj
        s0 = float(a_dir @ a) / (na * na)
        resid = np.linalg.norm(a - s0 * a_dir)
        if resid > 1e-6 * max(np.linalg.norm(a), 1e-300):
            return None, True, na, (
                f"a_obj = ({a[0]:.4g}, {a[1]:.4g}, {a[2]:.4g}) is not reachable: the object can "
                f"only accelerate along the contact normal n = ({nrm[0]:.4g}, {nrm[1]:.4g}), as "
                f"a_obj = lam_c * ({a_dir[0]:.4g}, {a_dir[1]:.4g}, {a_dir[2]:.4g}) with "
                f"lam_c >= 0", (NORMAL,))
        if s0 < 0:
            return None, True, na, (
                f"a_obj points against the contact normal n = ({nrm[0]:.4g}, {nrm[1]:.4g}): it "
                f"would need a pulling contact force; {CONTACT}", (CONTACT,))
        return s0, True, na, None
    d = query.direction
    gamma = dot(d.tolist(), (ax, ay, aa))
    if gamma <= 1e-9 * na:
        return None, False, gamma, (
            f"no torque accelerates the object along d = ({d[0]:.4g}, {d[1]:.4g}, {d[2]:.4g}): "
            f"the contact pushes only along its normal n = ({nrm[0]:.4g}, {nrm[1]:.4g}) and "
            f"d . n <= 0; {CONTACT}", (CONTACT,))
    lam_lo = None if query.a_min is None else query.a_min / gamma
    return lam_lo, False, gamma, None


def push_problem(model, query, cfg, *, lam_lo=None, equal=False, lp=False):
    n = cfg.N.shape[0]
    A, lba, uba, names = rows(model, query, cfg)
    Lh = homog(cfg.L)
    if lam_lo is not None:
        A[0] = Lh[0]
        lba[0] = lam_lo
        uba[0] = lam_lo if equal else np.inf
        names[0] = ""
    if lam_lo is None or lam_lo < 0:  # else implied by the task row
        A[1] = Lh[0]
        lba[1] = 0.0
        names[1] = CONTACT
    stick_rows(model, cfg, A, lba, uba, names, Lh)
    H = None
    g = np.zeros(n + 1)
    if lp:
        g[:n] = -cfg.L[0]
    else:
        H = np.zeros((n + 1, n + 1))
        H[:n, :n] = 2 * cfg.Xi
    lbx = np.full(n + 1, -np.inf)
    ubx = np.full(n + 1, np.inf)
    lbx[n] = ubx[n] = 1.0
    return Problem(H=H, g=g, A=A, lba=lba, uba=uba, lbx=lbx, ubx=ubx, names=names,
                    scale=scale_of(query, cfg))


