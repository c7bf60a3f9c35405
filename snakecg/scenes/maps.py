"""The linear maps of a general scene at rest for a fixed contact/ground state (eqs. 17,
22-25, 28, 29 of the paper, taken with any set of constraint rows).

At a configuration the rows ``A`` (the engine's: :class:`~snakecg.scenes.contacts.StateRows`)
split, for a given state of every block, into *held* rows ``H`` (a contact held, an ideal
wheel, a wheel or friction set sticking: ``w_H = A_H a = 0``) and rows with a *fixed* force
``lam_F`` (a contact that opens: 0; a wheel sliding either way: ``+-mu m g``; a Coulomb or
anisotropic set sliding at a given point of its boundary). Then, with ``I`` the bodies'
inertia (snake and objects), ``f = B tau + E f_obj`` (eq. 12) and
``G_HH = A_H I^-1 A_H^T`` (eq. 14)::

    lam_H = -G_HH^-1 A_H I^-1 (f + A_F^T lam_F)              (eq. 17)
    a     = I^-1 (f + A_H^T lam_H + A_F^T lam_F)              (eqs. 18, 22-25)

affine in ``tau`` (and ``f_obj``). A contact with Coulomb friction adds its tangent row: held
where it sticks, its force 0 where it is open, and where it slips its normal row held with the
force acting along ``A_n -+ mu A_t`` (the friction tied to the normal force), so that
``A_H I^-1 D_H^T`` (``D_H`` the held rows' force directions) replaces ``G_HH``, no longer
symmetric. Where the held rows are dependent (statically indeterminate) ``G_HH^-1`` is the
pseudo-inverse: the minimum-norm forces, flagged ``singular``. :func:`scene_problem` builds
one configuration's inertia, input map and rows;
:func:`state_maps` the maps of one state; :func:`maps` checks a user's state and calls both.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .contacts import StateRows
from .solve import BOX, DISC, FREE, HELD, SLIDE, SLIDE_NEG, SLIDE_POS, SPLIT, UNILATERAL, ZERO

__all__ = ["Problem", "scene_problem", "state_maps", "maps", "boundary_point", "block_names",
           "whitening", "PINV_RCOND"]

#: Relative cut-off of the held rows' pseudo-inverse (singular values of ``G_HH`` below it
#: times the largest are its null space: dependent rows).
PINV_RCOND = 1e-10

_SIZE = {FREE: 1, UNILATERAL: 1, BOX: 1, DISC: 2, SPLIT: 2}


class Problem:
    """One configuration of a general scene at rest: ``M`` (n x n) the bodies' inertia,
    ``B`` (n x n_a) the torques' map and ``E`` (n x 3 n_o) the objects' wrenches' map into
    the generalized force, the rows (``rows``: :class:`~snakecg.scenes.contacts.Rows`), the
    objects' poses, and the sizes."""

    def __init__(self, model, q):
        na, ns, no = model.n_joints, model.n_coordinates, model.scene.n_objects
        qa = np.asarray(q, dtype=float).reshape(1, ns)
        model.check_base(qa[0])
        state_rows = StateRows(model)
        self.rows, M, self.obj_poses = state_rows.rows(qa[0])
        n = ns + 3 * no
        m, A = len(self.rows.A), self.rows.A
        #: a frictional contact's block -> its tangent row (after the m rows), and its mu
        self.tangent, self.mu = {}, {}
        fric = [c.row for c in self.rows.contacts if c.mu > 0]
        if fric:  # (the engine's tangent rows: after the m rows, contact k's at m + k)
            A = np.vstack([A, state_rows.A[m + np.array(fric)]])
            for j, k in enumerate(fric):
                self.tangent[k], self.mu[k] = m + j, float(self.rows.contacts[k].mu)
        self.M, self.M_s = M, M[:ns, :ns].copy()
        self.B = np.zeros((n, na))
        self.B[3:ns] = np.eye(na)
        self.E = np.zeros((n, 3 * no))
        self.E[ns:] = np.eye(3 * no)
        self.q = qa[0]
        self.n, self.n_s, self.n_a, self.n_o = n, ns, na, no
        self.A = A
        self.kind = list(self.rows.kind)
        self.start = list(self.rows.start)
        self.par = [tuple(map(float, p)) for p in self.rows.par]
        self.Minv = np.linalg.inv(M)
        self.Minv = 0.5 * (self.Minv + self.Minv.T)
        self.G = self.A @ self.Minv @ self.A.T  # eq. 14 (every row)
        #: the input metric N = B^T M_s^-1 B (eq. 31)
        self.N = self.B.T @ self.Minv @ self.B
        try:  # (the input ellipsoid's whitening, every query's first step: whitening below)
            np.linalg.cholesky(self.N)
        except np.linalg.LinAlgError:
            raise InputError("q: at this configuration the input metric N = B^T M_s^-1 B "
                             "(eq. 31) is not numerically positive definite: the robot's "
                             "masses, lengths and inertias span too many orders of magnitude "
                             "(the links' m l^2 against their inertias) for double precision; "
                             "rescale the robot") from None

    @property
    def n_blocks(self) -> int:
        return len(self.kind)

    def block_rows(self, b: int) -> np.ndarray:
        return self.start[b] + np.arange(_SIZE[self.kind[b]])


def scene_problem(model, q) -> Problem:
    """The :class:`Problem` of one configuration ``q`` (n_s,) of a general scene model."""
    return Problem(model, q)


def whitening(p: Problem) -> np.ndarray:
    """``T`` with ``tau = T u``: the whitened torques ``u = L^T tau`` (``N = L L^T``, eq. 31),
    in which the input ellipsoid is the unit ball."""
    L = np.linalg.cholesky(p.N)
    return np.linalg.inv(L).T


def boundary_point(kind: int, par, angle: float) -> np.ndarray:
    """The force on the boundary of a Coulomb disc (``DISC``: radius ``par[0]``) or split
    ellipse (``SPLIT``: semi-axes ``par[0]`` backward (lam_t < 0), ``par[1]`` forward,
    ``par[2]`` across) at the parametric ``angle`` (rad): ``(s cos angle, s_n sin angle)``."""
    c, s = np.cos(angle), np.sin(angle)
    if kind == DISC:
        return par[0] * np.array([c, s])
    return np.array([(par[0] if c < 0 else par[1]) * c, par[2] * s])


def _fixed_force(kind, par, code, angle):
    if code == ZERO:
        return np.zeros(_SIZE[kind])
    if kind == BOX:
        return np.array([par[0] if code == SLIDE_POS else -par[0]])
    return boundary_point(kind, par, angle)


def state_maps(p: Problem, state, angles=None) -> dict:
    """The affine maps of problem ``p`` for the block states ``state`` (solver codes,
    :mod:`snakecg.scenes.solve`; ``HELD`` for a held contact, an ideal wheel or a sticking
    set) and, for a ``DISC``/``SPLIT`` block sliding (``SLIDE``), ``angles[b]`` its point on
    the set's boundary (:func:`boundary_point`). Every map is ``X_from_tau`` (a matrix) plus
    ``X_offset`` (the fixed forces' part), and ``X_from_f_obj``."""
    angles = {} if angles is None else angles
    held, fixed_rows, lam_F, tied = [], [], [], []
    for b, code in enumerate(state):
        rows = p.block_rows(b)
        t = p.tangent.get(b)
        if t is not None:  # a frictional contact: open, stick, slip either way
            if code == HELD:
                held.extend([rows[0], t])
            elif code == ZERO:
                fixed_rows.extend([rows[0], t])
                lam_F.extend([0.0, 0.0])
            else:  # slip+ (w_t > 0): lam_t = -mu lam_n; slip-: +mu lam_n
                held.append(rows[0])
                tied.append((rows[0], t, -p.mu[b] if code == SLIDE_POS else p.mu[b]))
        elif code == HELD:
            held.extend(rows.tolist())
        else:
            fixed_rows.extend(rows.tolist())
            lam_F.extend(_fixed_force(p.kind[b], p.par[b], code, angles.get(b, 0.0)).tolist())
    H = np.array(held, dtype=int)
    F = np.array(fixed_rows, dtype=int)
    lam_F = np.array(lam_F, dtype=float)
    A, Mi = p.A, p.Minv
    AH, AF = A[H], A[F]
    # the held rows' forces act along D = A_H, a slipping contact's along its normal row plus
    # its tangent row times the tied coefficient (-+ mu)
    DH = AH.copy()
    for r, t, k in tied:
        DH[held.index(r)] += k * A[t]
    # the applied generalized force in (tau, f_obj, 1): f = B tau + E f_obj + A_F^T lam_F
    inputs = np.hstack([p.B, p.E, (AF.T @ lam_F)[:, None]])
    singular, null = False, np.zeros((H.size, 0))
    if H.size:  # A_H a = 0 with a = M^-1 (f + D_H^T lam_H) (D_H = A_H where nothing is tied)
        GHD = AH @ Mi @ DH.T
        _, s, Vt = np.linalg.svd(GHD)
        singular = bool(s.size and s[-1] <= PINV_RCOND * s[0])
        lamH = -np.linalg.pinv(GHD, rcond=PINV_RCOND, hermitian=not tied) @ (AH @ Mi @ inputs)
        if singular:  # the forces' family: lam_H + null z, GHD null = 0
            null = Vt[s <= PINV_RCOND * s[0]].T
    else:
        lamH = np.zeros((0, inputs.shape[1]))
    a = Mi @ (inputs + DH.T @ lamH)  # eq. 18
    lam = np.zeros((A.shape[0], inputs.shape[1]))
    lam[H] = lamH
    lam[F, -1] = lam_F
    for r, t, k in tied:
        lam[t] = k * lam[r]
    lam_null = np.zeros((A.shape[0], null.shape[1]))
    lam_null[H] = null
    for r, t, k in tied:
        lam_null[t] = k * lam_null[r]
    w = A @ a
    na, no, ns = p.n_a, p.n_o, p.n_s

    def split(X):
        return X[..., :na], X[..., na:na + 3 * no], X[..., -1]

    out = {}
    for name, X in (("qdd", a[:ns]), ("lam", lam), ("w", w)):
        out[f"{name}_from_tau"], out[f"{name}_from_f_obj"], out[f"{name}_offset"] = split(X)
    ao = a[ns:].reshape(no, 3, a.shape[1])
    out["a_obj_from_tau"], out["a_obj_from_f_obj"], out["a_obj_offset"] = split(ao)
    Q = out["qdd_from_tau"]
    out["xi_tau"] = Q.T @ p.M_s @ Q  # eq. 28
    Io = [p.M[ns + 3 * j:ns + 3 * j + 3, ns + 3 * j:ns + 3 * j + 3] for j in range(no)]
    each = np.array([out["a_obj_from_tau"][j].T @ Io[j] @ out["a_obj_from_tau"][j]
                     for j in range(no)]).reshape(no, na, na)
    out["omega_tau_each"] = each  # eq. 29, per object
    out["omega_tau"] = each.sum(axis=0)
    Lt = lam[:, :na]
    out["lambda_form_tau"] = Lt.T @ p.G @ Lt
    out["input_metric"] = p.N  # eq. 31
    out["delassus"] = p.G  # eq. 14
    out["singular"] = singular
    # where singular: every force lam + lam_null z meets the piece's equations; a_null the
    # accelerations' change per z (0 where only the forces are indeterminate)
    out["lam_null"], out["a_null"] = lam_null, Mi @ DH.T @ null
    out["state"] = np.array(state, dtype=int)
    return out


def block_names(p: Problem, scene) -> list:
    """One line per block: what it is (``contact link 2 - obstacle 1``, ``ground link 3
    (coulomb)``, ``ground object 1``)."""
    from .metrics import _KIND_NAMES

    out = []
    for kd, label in zip(p.kind, p.rows.labels):
        if label[0] == "contact":
            c = p.rows.contacts[label[1]]
            fric = f" (mu {c.mu:g})" if c.mu > 0 else ""
            out.append(f"contact {scene.body_name(*c.a)} - {scene.body_name(*c.b)}{fric}")
        elif label[0] == "object_ground":
            out.append(f"ground {scene.body_name('object', label[1])} ({_KIND_NAMES[kd]})")
        else:
            out.append(f"ground link {label[1] + 1} ({_KIND_NAMES[kd]})")
    return out


_WORDS = {UNILATERAL: {"held": HELD, "open": ZERO},
          FREE: {"held": HELD, "stick": HELD},
          BOX: {"stick": HELD, "slide+": SLIDE_POS, "slide-": SLIDE_NEG, "none": ZERO},
          DISC: {"stick": HELD, "none": ZERO},
          SPLIT: {"stick": HELD, "none": ZERO}}

#: a contact with friction (its pair's mu > 0): open, stick (normal and tangent rows held),
#: slip+ / slip- (the second body sliding along +tangent / -tangent on the first: w_t > 0,
#: friction -mu lam_n / w_t < 0, +mu lam_n)
_FRICTION_WORDS = {"open": ZERO, "stick": HELD, "slip+": SLIDE_POS, "slip-": SLIDE_NEG}


def _parse_state(p: Problem, names, state):
    """Solver codes and sliding angles of a user's state (one entry per block)."""
    nb = p.n_blocks
    if state is None:
        return [HELD] * nb, {}
    if isinstance(state, (str, bytes)) or not isinstance(state, (list, tuple)):
        raise InputError(f"state must be None or a list of {nb} block states (one per block: "
                         f"{'; '.join(names) or 'none at this configuration'}), got "
                         f"{state!r:.80}")
    if len(state) != nb:
        raise InputError(f"state must list {nb} block states (one per block: "
                         f"{'; '.join(names) or 'none at this configuration'}), got "
                         f"{len(state)}")
    codes, angles, problems = [], {}, []
    for b, s in enumerate(state):
        kd = p.kind[b]
        words = _FRICTION_WORDS if b in p.tangent else _WORDS[kd]
        if kd in (DISC, SPLIT) and not isinstance(s, str):
            try:
                ang = float(s[1]) if isinstance(s, (list, tuple)) and len(s) == 2 \
                    and s[0] == "slide" else float("nan")
            except (TypeError, ValueError):
                ang = float("nan")
            if np.isfinite(ang):
                codes.append(SLIDE)
                angles[b] = ang
                continue
        if isinstance(s, str) and s in words:
            codes.append(words[s])
            continue
        extra = " or ('slide', angle in rad)" if kd in (DISC, SPLIT) else ""
        problems.append(f"state[{b}] ({names[b]}) must be one of {', '.join(words)}{extra}, "
                        f"got {s!r:.40}")
        codes.append(HELD)
    if problems:
        raise InputError("; ".join(problems))
    return codes, angles


def maps(model, q, *, state=None) -> dict:
    """The linear maps of a general scene at configuration ``q`` (n_s,) for a given state of
    every block (default: every contact held, every wheel and friction set sticking).

    ``state``: one entry per block, in the order of ``maps(q)["blocks"]`` (the contacts, then
    the ground under each link, then the objects' ground friction, as ``forward`` lists
    them): ``"held"``/``"open"`` for a contact, ``"stick"``/``"slide+"``/``"slide-"`` for a
    bounded wheel, ``"held"`` for an ideal wheel, ``"stick"`` or ``("slide", angle)`` for a
    Coulomb or anisotropic set (sliding at :func:`boundary_point` ``angle``). A contact whose
    pair has Coulomb friction (``mu_contact``; its name ends in ``(mu ...)``) is ``"open"``,
    ``"stick"`` (its normal and tangent rows held; the default) or ``"slip+"``/``"slip-"``
    (its normal row held, its second body sliding along +/- its tangent on the first, the
    friction force ``-/+ mu lam_n`` along the tangent): each piece keeps every output affine
    in the torques.

    Keys: ``qdd_from_tau`` (n_s, n_a, eq. 22), ``qdd_from_f_obj`` (eq. 23), ``a_obj_from_tau``
    (n_o, 3, n_a, per object, eq. 24), ``a_obj_from_f_obj`` (eq. 25), ``lam_from_tau``,
    ``lam_from_f_obj`` (m rows, eq. 17; with contact friction the frictional contacts'
    tangent rows after them, ``tangent_rows`` naming each contact's, -1 where none),
    ``w_from_tau``, ``w_from_f_obj`` (the rows' accelerations), each with its ``*_offset``
    (the fixed forces' part: ``X = X_from_tau tau + X_from_f_obj f_obj + X_offset``); the
    forms of the homogeneous part: ``xi_tau`` (eq. 28),
    ``omega_tau`` (eq. 29, summed over objects) and ``omega_tau_each``, ``lambda_form_tau``
    (``lam^T G lam``); ``input_metric`` (``B^T M_s^-1 B``, eq. 31), ``delassus`` (``G``,
    eq. 14); ``singular`` (dependent held rows: minimum-norm forces), ``lam_null`` (every
    force ``lam + lam_null z`` meets the piece's equations) and ``a_null`` (the accelerations'
    change per ``z``: 0 where only the forces are indeterminate); ``state`` (codes) and
    ``blocks`` (names)."""
    ns = model.n_coordinates
    try:
        qa = np.asarray(q, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"q must be numbers, shape ({ns},) = (n_joints + 3,), got "
                         f"{q!r:.60}") from None
    if qa.shape != (ns,) or not np.all(np.isfinite(qa)):
        raise InputError(f"q must be {ns} finite numbers, shape ({ns},) = (n_joints + 3,) for "
                         f"a {model.n_joints}-joint robot (maps of a general scene take one "
                         f"configuration), got shape {qa.shape}")
    p = scene_problem(model, qa)
    names = block_names(p, model.scene)
    codes, angles = _parse_state(p, names, state)
    out = state_maps(p, codes, angles)
    out["blocks"] = names
    if p.tangent:
        out["tangent_rows"] = np.array([p.tangent.get(b, -1) for b in range(p.n_blocks)])
    return out
