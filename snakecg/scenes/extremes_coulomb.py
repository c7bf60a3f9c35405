"""Coulomb friction at a general scene's contacts in the searches over pieces
(:mod:`snakecg.scenes.extremes`, :mod:`snakecg.scenes.optimize`): each frictional contact's
four states, the exact conditions under which a piece holds, and the solutions of Coulomb's
law that the pieces give at one torque.

A frictional contact is open, sticking, or slipping either way (``maps``' ``state``). On a
piece every output is affine in the torques (:func:`snakecg.scenes.maps.state_maps`), and
the piece is a solution of Coulomb's law at ``tau`` exactly where its linear conditions hold
(:func:`contact_conditions`): the piece's region is a polyhedron in the torques, a cone
where no fixed force acts. Unlike the frictionless case, the regions of two pieces may
overlap with different accelerations: Coulomb's problem may have several solutions at one
torque (and none at some: then no piece holds there). A search over every piece then covers
every pair (torque, solution): its maximum is the largest value over every solution at every
torque, and :class:`PieceSolutions` says, at a returned torque, how many distinct solutions
the pieces give and what each one's value is, so that an answer on such a torque is flagged,
never picked silently.

Where a piece's equations are singular (contacts whose rows depend on each other: a box
flush on a link, both corners sticking, shares one friction between its two tangent rows)
its forces are a family ``lam + lam_null z`` (:func:`snakecg.scenes.maps.state_maps`), and
the piece holds at a torque where some ``z`` meets every condition: the conditions in
``(u, z)`` are projected onto ``u`` by Fourier-Motzkin elimination of ``z``, exactly (at
most ``MAX_ROWS`` rows). Where the accelerations themselves form a family (``a_null`` not 0)
or the elimination would pass ``MAX_ROWS``, the piece keeps the least-norm member's
conditions and the count at a torque it holds is marked incomplete (negative, as
``forward``'s ``solutions``).
"""

from __future__ import annotations

import numpy as np

from .solve import BOX, HELD, SLIDE_NEG, SLIDE_POS, UNILATERAL, ZERO

__all__ = ["contact_conditions", "contact_choices", "PieceSolutions", "DISTINCT",
           "count_words", "normalized", "piece_conditions", "force_family", "ROW_FLOOR",
           "MAX_ROWS"]

#: Two solutions are distinct where their accelerations differ by more than this, relative
#: to the largest (the forward solve's enumeration counts them so).
DISTINCT = 1e-7


def contact_conditions(p, b, code) -> list:
    """The conditions of contact block ``b`` (``p``: :class:`~snakecg.scenes.maps.Problem`)
    in state ``code``, each a linear form ``>= 0`` of the piece's forces and row
    accelerations: a list of terms ``(key, row, coefficient)``, ``key`` ``"lam"`` or ``"w"``.
    A frictionless contact: held ``lam_n >= 0``, open ``w_n >= 0``. A contact with Coulomb
    friction (``p.tangent``): open ``w_n >= 0``; stick ``mu lam_n -+ lam_t >= 0`` (the cone,
    which implies ``lam_n >= 0``); slip+ ``lam_n >= 0`` and ``w_t >= 0`` (its friction,
    ``-mu lam_n``, tied to the normal force by the piece); slip- ``lam_n >= 0`` and
    ``w_t <= 0``. With the piece's equations (``w_n = 0`` where touching, ``w_t = 0`` where
    sticking, the forces 0 where open) these are Coulomb's law exactly."""
    r, t = p.start[b], p.tangent.get(b)
    if code == ZERO:
        return [[("w", r, 1.0)]]
    if t is None:
        return [[("lam", r, 1.0)]]
    if code == HELD:
        mu = p.mu[b]
        return [[("lam", r, mu), ("lam", t, -1.0)], [("lam", r, mu), ("lam", t, 1.0)]]
    return [[("lam", r, 1.0)], [("w", t, 1.0 if code == SLIDE_POS else -1.0)]]


#: A condition whose coefficients in the torque are below this, relative to the largest
#: coefficient of the maps it is made of, is constant in the torque: on such a piece the force
#: (or acceleration) it reads is 0 for every torque, and its coefficients are rounding (a
#: free object held by one sticking contact, say), whose direction would be noise.
ROW_FLOOR = 1e-10


def normalized(C, scale, tol):
    """Conditions ``C[:, :-1] u + C[:, -1] >= 0`` with unit coefficient rows; ``scale``
    (per row) the size of the maps each is made of. A row constant in ``u``
    (:data:`ROW_FLOOR`) is dropped where its constant is ``>= -tol scale`` (always true);
    None where one is negative (no torque meets it: the piece is empty)."""
    nrm = np.linalg.norm(C[:, :-1], axis=1)
    keep = nrm > ROW_FLOOR * scale
    if np.any(~keep & (C[:, -1] < -tol * np.maximum(scale, 1.0))):
        return None
    return C[keep] / nrm[keep, None]


#: Rows of a piece's conditions at most after eliminating its forces' free directions.
MAX_ROWS = 4000


def _eliminate(C, scale, k):
    """Fourier-Motzkin: the rows ``[C_u | C_z | c]`` (``k`` columns of ``z``) of ``C_u u + C_z
    z + c >= 0`` projected onto ``u`` (some ``z`` exists): ``(rows, scale)``, or None where
    the rows would pass :data:`MAX_ROWS`."""
    for _ in range(k):
        j = C.shape[1] - 2  # the last column of z
        cz = C[:, j]
        small = np.abs(cz) <= ROW_FLOOR * scale
        pos, neg = np.flatnonzero(~small & (cz > 0)), np.flatnonzero(~small & (cz < 0))
        if len(pos) * len(neg) + np.sum(small) > MAX_ROWS:
            return None
        rows = [C[small]]
        sc = [scale[small]]
        if pos.size and neg.size:
            P, N = C[pos], C[neg]
            # -cz_n * row_p + cz_p * row_n: z_j cancels, both weights > 0
            comb = (-N[None, :, j:j + 1] * P[:, None, :] + P[:, None, j:j + 1] * N[None])
            rows.append(comb.reshape(-1, C.shape[1]))
            sc.append((-N[None, :, j] * scale[pos, None] + P[:, None, j] * scale[None, neg])
                      .ravel())
        C = np.delete(np.vstack(rows), j, axis=1)
        scale = np.concatenate(sc)
    return C, scale


def force_family(p, mp):
    """``(lam_null, exact)``: the free directions of a piece's forces (``lam + lam_null z``
    meets its equations for every ``z``; no column where they are determined) and whether
    the accelerations are determined (else no column, ``exact`` False)."""
    Z = mp["lam_null"]
    if not Z.shape[1]:
        return Z, True
    # (a_null = M^-1 D_H^T null, null orthonormal: of the size of M^-1 A where not 0)
    if np.abs(mp["a_null"]).max() <= 1e-9 * np.abs(p.Minv).max() * max(1.0,
                                                                         np.abs(p.A).max()):
        return Z, True
    return Z[:, :0], False


def piece_conditions(p, mp, state, T, tol, *, ground=True):
    """The conditions under which a piece (``state``, its maps ``mp``) is a solution, as rows
    ``[a | b]`` of ``a . u + b >= 0`` in the whitened torques ``u`` (``tau = T u``), unit
    ``a``: each contact's (:func:`contact_conditions`) and, with ``ground``, each bounded
    wheel's (sticking: ``|lam| <=`` its bound; sliding either way: against its force). Where
    the forces are a family (:func:`~snakecg.scenes.maps.state_maps`' ``lam_null``) the rows
    are projected onto ``u``. Returns ``(rows or None where no torque meets them, exact)``:
    ``exact`` False where the accelerations are a family or the projection is too large
    (then the least-norm forces' rows)."""
    L, l0 = mp["lam_from_tau"] @ T, mp["lam_offset"]
    W, w0 = mp["w_from_tau"] @ T, mp["w_offset"]
    Z, exact = force_family(p, mp)
    nz = Z.shape[1]
    lin = {"lam": (L, l0, Z[:, :nz]), "w": (W, w0, np.zeros((len(w0), nz)))}
    big = {key: max(1e-300, np.abs(X).max(initial=0.0), np.abs(x).max(initial=0.0))
           for key, (X, x, _) in lin.items()}
    rows, scale = [], []

    def add(terms):
        rows.append(sum(c * np.r_[lin[key][0][i], lin[key][2][i], lin[key][1][i]]
                        for key, i, c in terms))
        scale.append(max(big[key] * abs(c) for key, _, c in terms))

    for b, code in enumerate(state):
        kd, r = p.kind[b], p.start[b]
        if kd == UNILATERAL:
            for terms in contact_conditions(p, b, code):
                add(terms)
        elif ground and kd == BOX and code == HELD:
            for sgn in (1.0, -1.0):  # bound -+ lam >= 0
                add([("lam", r, -sgn)])
                rows[-1][-1] += p.par[b][0]
                scale[-1] = max(scale[-1], p.par[b][0])
        elif ground and kd == BOX and code in (SLIDE_POS, SLIDE_NEG):  # the force opposes w
            add([("w", r, -1.0 if code == SLIDE_POS else 1.0)])
    C = np.array(rows).reshape(-1, T.shape[1] + nz + 1)
    scale = np.array(scale)
    if nz:
        got = _eliminate(C, scale, nz)
        if got is None:  # too many rows: the least-norm forces' conditions
            return piece_conditions(p, dict(mp, lam_null=Z[:, :0]), state, T, tol,
                                    ground=ground)[0], False
        C, scale = got
    return normalized(C, scale, tol), exact


def contact_choices(p, b) -> tuple:
    """The states contact block ``b`` takes: held or open; with Coulomb friction stick, open,
    slip+ or slip-."""
    return (HELD, ZERO, SLIDE_POS, SLIDE_NEG) if b in p.tangent else (HELD, ZERO)


def count_words(k: int) -> str:
    """A count of solutions in words (``forward``'s ``uniqueness``)."""
    return "unique" if k == 1 else "several" if abs(k) >= 2 else "not_certified"


class PieceSolutions:
    """The solutions of Coulomb's law that a list of pieces gives at a torque.

    ``conds[i]``: piece ``i``'s conditions ``C u + c >= 0`` as rows ``[C | c]`` (normalized,
    whitened torques ``u``); ``accel[i]``: ``(P, p0)`` with the accelerations (snake and
    objects) ``P u + p0``; ``forms[i]``: ``{metric: (A, g, c)}``, the value ``u^T A u + 2 g^T
    u + c``; ``singular[i]``: its equations are singular (its forces one member of a
    family). ``tol``: the conditions' feasibility tolerance."""

    def __init__(self, conds, accel, forms, singular, tol):
        self.conds, self.accel, self.forms = conds, accel, forms
        self.singular, self.tol = singular, tol

    def at(self, u, floor):
        """``(count, values)``: the number of distinct solutions at ``u`` (1 unique; ``k >=
        2`` several; ``-k`` where a singular piece holds there, so that others may exist;
        0 where no piece holds) and, per solution, ``{metric: value}`` (``sr`` 0 where
        ``norm_a_obj + norm_qdd`` is below ``floor``)."""
        seen, values, partial = [], [], False
        for i, C in enumerate(self.conds):
            if not np.all(C[:, :-1] @ u + C[:, -1] >= -self.tol):
                continue
            partial |= bool(self.singular[i])
            P, p0 = self.accel[i]
            a = P @ u + p0
            scale = max(1.0, np.abs(a).max())
            if any(np.abs(a - b).max() <= DISTINCT * scale for b in seen):
                continue
            seen.append(a)
            vals = {m: float(u @ A @ u + 2 * g @ u + c) for m, (A, g, c) in
                    self.forms[i].items()}
            if "norm_a_obj" in vals and "norm_qdd" in vals:
                D = vals["norm_a_obj"] + vals["norm_qdd"]
                vals["sr"] = vals["norm_a_obj"] / D if D > floor else 0.0
            values.append(vals)
        k = len(seen)
        return (-k if partial and k else k), values
