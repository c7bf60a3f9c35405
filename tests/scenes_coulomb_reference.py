"""A reference for the searches over pieces with Coulomb friction at the contacts, written
apart from snakecg's pieces (snakecg/scenes/extremes*.py, optimize*.py, maps.py): every piece
of Coulomb's law (each frictional contact open, sticking, slipping either way; each bounded
wheel sticking or sliding either way) as affine maps of the torque, built by the dense solve
of its equations in (a, lam) (``test_scenes_contact_friction.piece_solution``, on rows from
the geometry reference) at the zero and unit torques, and its conditions checked densely on
many torques at once. Singular pieces are left out and counted."""

from __future__ import annotations

import itertools

import numpy as np

from snakecg.scenes.solve import BOX, FREE, UNILATERAL

from test_scenes_contact_friction import piece_solution, reference_problem


def piece_system(p, combo):
    """The piece's linear equations ``K x = rhs`` in ``x = (a, lam)``, as
    ``test_scenes_contact_friction.piece_solution`` writes them (kept apart here to solve
    the singular ones in the least-squares sense)."""
    M, f, A = p["M"], p["f"], p["A"]
    m, n = A.shape
    K = np.zeros((n + m, n + m))
    rhs = np.zeros(n + m)
    K[:n, :n], K[:n, n:], rhs[:n] = M, -A.T, f
    for b, s in zip(p["blocks"], combo):
        r, t = b["row"], b["tangent"]
        if s in ("held", "stick", "slip+", "slip-"):
            K[n + r, :n] = A[r]
        else:  # open, zero, a wheel at its bound
            K[n + r, n + r] = 1.0
            rhs[n + r] = {"+": b["p"], "-": -b["p"]}.get(s, 0.0)
        if t is None:
            continue
        if s == "stick":
            K[n + t, :n] = A[t]
        else:  # open: 0; slipping: lam_t + -mu lam_n = 0
            K[n + t, n + t] = 1.0
            if s != "open":
                K[n + t, n + r] = b["mu"] if s == "slip+" else -b["mu"]
    return K, rhs


def options(p, *, wheels_stick=False):
    """Every block's states (``coulomb_solutions``' words); ``wheels_stick``: bounded wheels
    sticking only (the optimal torques' pieces)."""
    out = []
    for b in p["blocks"]:
        if b["kind"] == FREE:
            out.append(["held"])
        elif b["kind"] == UNILATERAL:
            out.append(["open", "stick", "slip+", "slip-"] if b["tangent"] is not None
                       else ["held", "open"])
        elif b["kind"] == BOX:
            out.append(["zero"] if not b["p"] > 0 else ["stick"] if wheels_stick
                       else ["stick", "+", "-"])
        else:
            raise ValueError("polyhedral blocks only")
    return out


class Pieces:
    """Every regular piece at configuration ``q``: ``a = tau @ Xa.T + a0``, ``lam`` alike."""

    def __init__(self, model, q, *, wheels_stick=False):
        na = model.n_joints
        taus = np.vstack([np.zeros(na), np.eye(na)])
        probs = [reference_problem(model, q, t) for t in taus]
        self.p = p = probs[0]
        self.ns, self.na = model.n_coordinates, na
        self.M, self.A = p["M"], p["A"]
        n = self.M.shape[0]
        self.B = np.zeros((n, na))
        self.B[3:self.ns] = np.eye(na)
        self.Minv = np.linalg.inv(self.M)
        self.N = self.B.T @ self.Minv @ self.B  # eq. 31
        self.pieces, self.singular = [], 0
        for combo in itertools.product(*options(p, wheels_stick=wheels_stick)):
            xs = [piece_solution(pr, combo) for pr in probs]
            extra = {}
            if any(x is None for x in xs):
                xs, extra = self._family(probs, combo)
                if xs is None:
                    self.singular += 1
                    continue
            a0, l0 = xs[0]
            self.pieces.append({"combo": combo, "a0": a0, "l0": l0,
                                "Xa": np.array([x[0] - a0 for x in xs[1:]]).T,
                                "Xl": np.array([x[1] - l0 for x in xs[1:]]).T, **extra})
        self.object_rows = {c["row"] for c in p["contacts"] if "object" in (
            c["bodies"][0][0], c["bodies"][1][0])}

    def _family(self, probs, combo):
        """A singular piece whose forces are a line ``lam + z Zl`` with the accelerations
        determined (a box flush on a link, both corners sticking, sharing one friction):
        its least-norm solutions and ``Zl``; (None, {}) otherwise (counted singular)."""
        systems = [piece_system(pr, combo) for pr in probs]
        K = systems[0][0]
        n = probs[0]["M"].shape[0]
        _, sv, Vt = np.linalg.svd(K)
        null = Vt[sv <= 1e-10 * sv[0]].T
        if null.shape[1] != 1 or np.abs(null[:n]).max() > 1e-9:
            return None, {}
        xs = []
        for Ki, rhs in systems:
            x = np.linalg.lstsq(Ki, rhs, rcond=None)[0]
            if np.abs(Ki @ x - rhs).max() > 1e-9 * max(1.0, np.abs(rhs).max()):
                return None, {}  # inconsistent: no solution on this piece
            xs.append((x[:n], x[n:]))
        return xs, {"Zl": null[n:, 0]}

    def boundary(self, u):
        """Torques on the ellipsoid's boundary ``tau^T N tau = 1`` for unit vectors ``u``."""
        s, V = np.linalg.eigh(self.N)
        return u @ (V / np.sqrt(s)).T

    def solve(self, piece, taus):
        return taus @ piece["Xa"].T + piece["a0"], taus @ piece["Xl"].T + piece["l0"]

    def slacks(self, piece, taus):
        """Every condition of Coulomb's law (and the wheels' sets) on the piece as a value
        that is >= 0 where it holds, ``(K, c)``, with its scale ``(K, c)`` (the largest
        force, or the free motion's largest row acceleration)."""
        lam = taus @ piece["Xl"].T + piece["l0"]
        w = taus @ (self.A @ piece["Xa"]).T + self.A @ piece["a0"]
        F = np.maximum(1e-12, np.abs(lam).max(axis=1))
        W = np.maximum(1e-12, np.abs(taus @ (self.A @ self.Minv @ self.B).T).max(axis=1))
        vals, scales, zc = [], [], []
        Zl = piece.get("Zl", np.zeros(lam.shape[1]))

        def add(v, sc, z=0.0):
            vals.append(v)
            scales.append(sc)
            zc.append(z)

        for b, s in zip(self.p["blocks"], piece["combo"]):
            r, t = b["row"], b["tangent"]
            if b["kind"] == UNILATERAL:
                add(lam[:, r], F, Zl[r])
                add(w[:, r], W)
                if s == "stick" and t is not None:
                    add(b["mu"] * lam[:, r] - lam[:, t], F, b["mu"] * Zl[r] - Zl[t])
                    add(b["mu"] * lam[:, r] + lam[:, t], F, b["mu"] * Zl[r] + Zl[t])
                elif s == "slip+":
                    add(w[:, t], W)
                elif s == "slip-":
                    add(-w[:, t], W)
            elif b["kind"] == BOX and s == "stick":
                add(b["p"] - lam[:, r], F + b["p"], -Zl[r])
                add(b["p"] + lam[:, r], F + b["p"], Zl[r])
            elif s == "+":
                add(-w[:, r], W)
            elif s == "-":
                add(w[:, r], W)
        self._zc = np.array(zc)
        return np.array(vals).T.reshape(len(taus), -1), np.array(scales).T.reshape(
            len(taus), -1)

    def holds(self, piece, taus, tol=1e-9):
        """Where the piece meets every condition of Coulomb's law (and the wheels' sets);
        on a line of forces, for some point ``z`` of it (an interval per torque)."""
        v, sc = self.slacks(piece, taus)
        zc = self._zc
        if "Zl" not in piece:
            return np.all(v >= -tol * sc, axis=1)
        g = v + tol * sc  # g + zc z >= 0
        free = np.abs(zc) <= 1e-12
        ok = np.all(g[:, free] >= 0, axis=1)
        with np.errstate(divide="ignore"):
            lo = np.max(np.where(zc > 1e-12, -g / np.where(zc > 1e-12, zc, 1), -np.inf),
                        axis=1)
            hi = np.min(np.where(zc < -1e-12, g / np.where(zc < -1e-12, -zc, 1), np.inf),
                        axis=1)
        return ok & (lo <= hi)

    def kept(self, piece) -> bool:
        """Every contact of an object touching (not open) on this piece."""
        return not any(b["kind"] == UNILATERAL and b["row"] in self.object_rows
                       and s == "open" for b, s in zip(self.p["blocks"], piece["combo"]))

    def metrics(self, a, taus):
        """The paper's metrics of accelerations ``a`` (K, n) at torques ``taus``."""
        ns, M = self.ns, self.M
        qdd = a[:, :ns]
        out = {"norm_qdd": np.einsum("ki,ij,kj->k", qdd, M[:ns, :ns], qdd)}
        ao = a[:, ns:]
        out["norm_a_obj"] = np.einsum("ki,ij,kj->k", ao, M[ns:, ns:], ao)
        for j in range((M.shape[0] - ns) // 3):
            sl = slice(ns + 3 * j, ns + 3 * j + 3)
            out[f"norm_a_obj[{j + 1}]"] = np.einsum("ki,ij,kj->k", a[:, sl], M[sl, sl],
                                                     a[:, sl])
        d = a - taus @ (self.Minv @ self.B).T
        out["norm_lambda"] = np.einsum("ki,ij,kj->k", d, M, d)
        D = out["norm_a_obj"] + out["norm_qdd"]
        free = np.einsum("ki,ij,kj->k", taus, self.N, taus)
        out["sr"] = np.where(D > 1e-12 * free, out["norm_a_obj"] / np.where(D > 0, D, 1), 0.0)
        return out

    def extremes(self, taus):
        """Over every piece holding at each torque: ``{(attr, metric): (value, tau)}`` for
        the max, the min and the min over the pieces keeping every object contact."""
        best = {}
        for piece in self.pieces:
            ok = self.holds(piece, taus)
            if not ok.any():
                continue
            a, _ = self.solve(piece, taus[ok])
            vals = self.metrics(a, taus[ok])
            for m, v in vals.items():
                for attr, pick in (("max", np.argmax), ("min", np.argmin)) + (
                        (("min_kept", np.argmin),) if self.kept(piece) else ()):
                    i = int(pick(v))
                    old = best.get((attr, m))
                    if old is None or (v[i] > old[0] if attr == "max" else v[i] < old[0]):
                        best[(attr, m)] = (float(v[i]), taus[ok][i])
        return best

    def solutions_at(self, tau):
        """The distinct solutions (accelerations, metrics) of every piece holding at tau."""
        out = []
        for piece in self.pieces:
            if self.holds(piece, tau[None])[0]:
                a, _ = self.solve(piece, tau[None])
                if not any(np.abs(a[0] - b).max() <= 1e-7 * max(1.0, np.abs(a).max())
                           for b, _ in out):
                    out.append((a[0], {k: float(v[0]) for k, v in
                                       self.metrics(a, tau[None]).items()}))
        return out
