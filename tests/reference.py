"""Independent dense numpy reference of the coupled snake + object system (Reyes & Ma 2017).

Written from the paper (eqs. 3-30) and the conventions of docs/CONTEXT, sharing no code with
``snakecg`` or ``snakecg_derive``: it reads only the plain numbers of a :class:`snakecg.Scene`
(masses, lengths, offsets...). Every derivative is taken numerically from *positions*:

* link kinematics: rear ends ``r_1 = (x, y) - c_1 e_1``, ``r_{i+1} = r_i + l_i e_i``, COM
  ``r_i + c_i e_i``, ``phi_{j+1} = phi_j + q_j``; the link Jacobians ``J_i`` (eq. 3) by the
  complex-step derivative of the COM poses (exact to rounding), ``Jdot_i v`` by a fourth-order
  central difference of ``J_i(q + h v) v``;
* ``M_s = sum J_i^T D_i J_i`` with ``D_i = diag(m_i, m_i, I_i)``; ``h_s = sum J_i^T D_i Jdot_i v``
  (planar bodies have no gyroscopic term);
* the contact row is the gradient of the gap function ``g = n^T (P - r_k)`` (``P`` the object's
  contact point, ``n = sigma (-sin phi_k, cos phi_k)``) with respect to ``(q, q_obj)``; a wheel
  row is ``n_i^T`` times the Jacobian of the wheel point ``COM_i + w_i e_i``; ``Adot v`` by
  central differences of ``A(x + h V) V``;
* the contact/wheel problem is solved by brute-force enumeration of every active set with a
  dense least-norm solve and a KKT check, or by scipy's bounded least squares (BVLS) on the
  equivalent box QP ``min 1/2 lam^T G_c lam + b^T lam``.
"""

from __future__ import annotations

import itertools

import numpy as np

__all__ = ["Reference", "STATES"]

#: Row states of the reference (strings, unlike the runtime's integer codes).
STATES = ("absent", "held", "lost", "slide+", "slide-")


def _complex_step(fun, x, h=1e-30):
    """Jacobian of a real-analytic ``fun`` at ``x`` by the complex step (exact to rounding)."""
    x = np.asarray(x, dtype=float)
    cols = []
    for j in range(x.size):
        xc = x.astype(complex)
        xc[j] += 1j * h
        cols.append(np.imag(np.ravel(fun(xc))) / h)
    return np.stack(cols, axis=-1)


def _directional_rate(fun, x, d, h=1e-3):
    """``d/dt fun(x + t d)`` at ``t = 0``, fourth-order central difference."""
    if not np.any(d):
        return np.zeros_like(np.asarray(fun(x), dtype=float))
    f = lambda t: np.asarray(fun(x + t * d), dtype=float)  # noqa: E731
    return (-f(2 * h) + 8 * f(h) - 8 * f(-h) + f(-2 * h)) / (12 * h)


class Reference:
    """Dense reference of a scene: ``solve(q, tau, ...)`` and the dense pieces of eq. (12)."""

    def __init__(self, scene):
        r = scene.robot
        self.na = r.joints
        self.nl = r.joints + 1
        self.ns = r.joints + 3
        self.nc = self.nl + 1
        self.mass = np.array(r.mass, float)
        self.length = np.array(r.length, float)
        self.link_inertia = np.array(r.inertia, float)
        self.com_dist = np.array(r.com, float)
        self.kappa = float(scene.kappa)
        self.m_obj = self.kappa * self.mass.mean()  # m_obj = kappa m, m = mean link mass
        self.I_obj_rot = float(scene.object_inertia)
        self.sigma = 1.0 if scene.side == "left" else -1.0
        self.k = scene.contact_link - 1
        self.contact_offset = float(scene.contact_offset)
        self.object_distance = float(scene.object_distance)
        self.scenario = scene.scenario
        self.wheel_offset = np.array(scene.wheel_offset, float)
        self.present = np.zeros(self.nc, bool)
        self.present[0] = True
        if scene.scenario != "frictionless":
            for i in scene.wheel_links:
                self.present[i] = True
        self.bounds = np.full(self.nc, np.inf)
        if scene.scenario == "wheels":
            self.bounds[1:] = scene.mu * self.mass * scene.gravity

    # --- kinematics (complex-safe) ------------------------------------------------------------
    def angles(self, q):
        q = np.asarray(q)
        return q[2] + np.concatenate([np.zeros(1, dtype=q.dtype), np.cumsum(q[3:])])

    def rear_ends(self, q):
        phi = self.angles(q)
        e = np.stack([np.cos(phi), np.sin(phi)], axis=1)
        r = [np.array([q[0], q[1]]) - self.com_dist[0] * e[0]]
        for i in range(self.nl - 1):
            r.append(r[-1] + self.length[i] * e[i])
        return np.array(r), e

    def link_poses(self, q):
        """``(n_l, 3)``: COM ``x, y`` and angle ``phi`` of every link."""
        r, e = self.rear_ends(q)
        com = r + self.com_dist[:, None] * e
        return np.concatenate([com, self.angles(q)[:, None]], axis=1)

    def jacobians(self, q):
        """``(n_l, 3, n_s)`` link Jacobians of eq. (3), COM twist = ``J_i qdot``."""
        return _complex_step(self.link_poses, q).reshape(self.nl, 3, self.ns)

    def jdot_v(self, q, v):
        """``(n_l, 3)``: ``Jdot_i v`` (the links' bias accelerations)."""
        q, v = np.asarray(q, float), np.asarray(v, float)
        return _directional_rate(lambda x: np.einsum("ijk,k->ij", self.jacobians(x), v), q, v)

    def link_inertias(self):
        return np.array([np.diag([m, m, i]) for m, i in zip(self.mass, self.link_inertia)])

    def mass_matrix(self, q):
        J = self.jacobians(q)
        return np.einsum("iak,iab,ibl->kl", J, self.link_inertias(), J)

    def bias_forces(self, q, v):
        J = self.jacobians(q)
        return np.einsum("iak,iab,ib->k", J, self.link_inertias(), self.jdot_v(q, v))

    # --- object and constraint rows ---------------------------------------------------------
    def place_object(self, q):
        """Object pose, ``rho`` and world contact point of the scene's default placement."""
        r, e = self.rear_ends(np.asarray(q, float))
        phi = self.angles(np.asarray(q, float))[self.k]
        n = self.sigma * np.array([-np.sin(phi), np.cos(phi)])
        P = r[self.k] + self.contact_offset * e[self.k]
        p_o = P + self.object_distance * n
        return np.array([p_o[0], p_o[1], phi]), np.array([0.0, -self.sigma * self.object_distance]), P

    def gap(self, x, rho):
        """Gap ``n^T (P - r_k)`` as a function of ``x = (q, q_obj)`` (complex-safe)."""
        q, qo = x[: self.ns], x[self.ns:]
        r, e = self.rear_ends(q)
        phi = self.angles(q)[self.k]
        n = self.sigma * np.array([-np.sin(phi), np.cos(phi)])
        c, s = np.cos(qo[2]), np.sin(qo[2])
        P = np.array([qo[0] + c * rho[0] - s * rho[1], qo[1] + s * rho[0] + c * rho[1]])
        return n @ (P - r[self.k])

    def wheel_point(self, q, i):
        poses = self.link_poses(q)
        phi = poses[i, 2]
        return poses[i, :2] + self.wheel_offset[i] * np.array([np.cos(phi), np.sin(phi)])

    def rows(self, x, rho):
        """Constraint matrix ``A`` (n_c x (n_s + 3)), eq. (9): contact, then a wheel per link."""
        x = np.asarray(x, float)
        q = x[: self.ns]
        A = np.zeros((self.nc, self.ns + 3))
        A[0] = _complex_step(lambda xx: np.atleast_1d(self.gap(xx, rho)), x)[0]
        for i in range(self.nl):
            phi = self.angles(q)[i]
            n_i = np.array([-np.sin(phi), np.cos(phi)])
            Jw = _complex_step(lambda qq: self.wheel_point(qq, i), q)
            A[1 + i, : self.ns] = n_i @ Jw
        return A

    def rows_dot_v(self, x, V, rho):
        """``Adot v`` of eq. (13): the rate of ``A(x(t)) V`` along ``xdot = V``."""
        x, V = np.asarray(x, float), np.asarray(V, float)
        return _directional_rate(lambda xx: self.rows(xx, rho) @ V, x, V)

    # --- the coupled system -----------------------------------------------------------------
    def system(self, q, tau, v=None, v_obj=None, f_obj=None, q_obj=None, rho=None):
        """Dense pieces of eq. (12)-(13): ``I, A, Adot v, f, p, G_c, b``."""
        q = np.asarray(q, float)
        tau = np.asarray(tau, float)
        v = np.zeros(self.ns) if v is None else np.asarray(v, float)
        v_obj = np.zeros(3) if v_obj is None else np.asarray(v_obj, float)
        f_obj = np.zeros(3) if f_obj is None else np.asarray(f_obj, float)
        if q_obj is None:
            q_obj, rho, _ = self.place_object(q)
        x = np.concatenate([q, q_obj])
        V = np.concatenate([v, v_obj])
        M = self.mass_matrix(q)
        I_obj = np.diag([self.m_obj, self.m_obj, self.I_obj_rot])
        n = self.ns + 3
        I = np.zeros((n, n))
        I[: self.ns, : self.ns] = M
        I[self.ns:, self.ns:] = I_obj
        B = np.vstack([np.zeros((3, self.na)), np.eye(self.na)])  # eq. (5)
        f = np.concatenate([B @ tau, f_obj])
        p = np.concatenate([self.bias_forces(q, v), np.zeros(3)])
        A = self.rows(x, rho)
        Adv = self.rows_dot_v(x, V, rho)
        Iinv = np.linalg.inv(I)
        Gc = A @ Iinv @ A.T
        b = A @ Iinv @ (f - p) + Adv
        return dict(I=I, M=M, I_obj=I_obj, B=B, A=A, Adv=Adv, f=f, p=p, Gc=Gc, b=b,
                    x=x, V=V, q_obj=q_obj, rho=rho, gap=self.gap(x, rho))

    def outcome(self, sys_, lam):
        """Accelerations, row accelerations and norms (eqs. 26, 27, 30) for forces ``lam``."""
        a = np.linalg.solve(sys_["I"], sys_["f"] - sys_["p"] + sys_["A"].T @ lam)
        qdd, a_obj = a[: self.ns], a[self.ns:]
        w = sys_["A"] @ a + sys_["Adv"]
        norm_qdd = qdd @ sys_["M"] @ qdd
        norm_a_obj = a_obj @ sys_["I_obj"] @ a_obj
        tot = norm_a_obj + norm_qdd
        return dict(qdd=qdd, a_obj=a_obj, lam=lam, w=w, norm_qdd=norm_qdd,
                    norm_a_obj=norm_a_obj, norm_lambda=lam @ sys_["Gc"] @ lam,
                    sr=norm_a_obj / tot if tot > 0 else 0.0)

    def choices(self):
        out = []
        for r in range(self.nc):
            if not self.present[r]:
                out.append(("absent",))
            elif r == 0:
                out.append(("held", "lost"))
            elif np.isfinite(self.bounds[r]):
                out.append(("held", "slide+", "slide-"))
            else:
                out.append(("held",))
        return out

    def solve_given(self, sys_, states):
        """Forces for a given active set: held rows ``w = 0`` (least-norm if dependent)."""
        Gc, b = sys_["Gc"], sys_["b"]
        lam = np.zeros(self.nc)
        for r, s in enumerate(states):
            if s == "slide+":
                lam[r] = self.bounds[r]
            elif s == "slide-":
                lam[r] = -self.bounds[r]
        H = np.array([s == "held" for s in states])
        if H.any():
            rhs = -(b[H] + Gc[np.ix_(H, ~H)] @ lam[~H])
            lam[H] = np.linalg.lstsq(Gc[np.ix_(H, H)], rhs, rcond=1e-12)[0]
        return lam

    def kkt_violation(self, lam, w, states, scale_lam=1.0, scale_w=1.0):
        """Sum of the KKT violations of an active set (0 for the solution)."""
        v = 0.0
        for r, s in enumerate(states):
            u = self.bounds[r]
            if s == "held" and r == 0:
                v += max(-lam[0], 0) / scale_lam
            elif s == "lost":
                v += max(-w[0], 0) / scale_w
            elif s == "held" and np.isfinite(u):
                v += max(abs(lam[r]) - u, 0) / scale_lam
            elif s == "slide+":
                v += max(w[r], 0) / scale_w
            elif s == "slide-":
                v += max(-w[r], 0) / scale_w
        return v

    def solve_enumerate(self, sys_):
        """Brute force: every active set, keep the one satisfying the KKT conditions."""
        best = None
        for states in itertools.product(*self.choices()):
            lam = self.solve_given(sys_, states)
            w = sys_["Gc"] @ lam + sys_["b"]
            sl = max(1.0, np.abs(lam).max())
            sw = max(1.0, np.abs(w).max())
            viol = self.kkt_violation(lam, w, states, sl, sw)
            if best is None or viol < best[0]:
                best = (viol, lam, states)
        return best[1], list(best[2]), best[0]

    def solve_bvls(self, sys_):
        """The box QP ``min 1/2 lam^T G_c lam + b^T lam`` by scipy's BVLS (G_c restricted to the
        present rows must be positive definite)."""
        from scipy.optimize import lsq_linear

        P = self.present
        G = sys_["Gc"][np.ix_(P, P)]
        b = sys_["b"][P]
        L = np.linalg.cholesky(G)
        lo = np.where(np.arange(self.nc)[P] == 0, 0.0, -self.bounds[P])
        hi = self.bounds[P]
        res = lsq_linear(L.T, -np.linalg.solve(L, b), bounds=(lo, hi), method="bvls",
                         tol=1e-14, lsmr_tol=None)
        lam = np.zeros(self.nc)
        lam[P] = res.x
        return lam

    def states_of(self, lam, w):
        """Row states read off a solution, and each row's margin (distance from ambiguity)."""
        states, margins = [], []
        for r in range(self.nc):
            if not self.present[r]:
                states.append("absent")
                margins.append(np.inf)
            elif r == 0:
                states.append("held" if lam[0] > w[0] else "lost")
                margins.append(max(lam[0], w[0]))
            else:
                u = self.bounds[r]
                if np.isfinite(u) and abs(w[r]) > u - abs(lam[r]):
                    states.append("slide+" if lam[r] > 0 else "slide-")
                else:
                    states.append("held")
                margins.append(max(u - abs(lam[r]), abs(w[r])))
        return states, np.array(margins)

    def solve(self, q, tau, *, v=None, v_obj=None, f_obj=None, q_obj=None, rho=None,
              method="enumerate"):
        """Everything :meth:`snakecg.SceneModel.forward` returns, as a dict, plus the system."""
        sys_ = self.system(q, tau, v, v_obj, f_obj, q_obj, rho)
        if method == "enumerate":
            lam, chosen, viol = self.solve_enumerate(sys_)
        elif method == "bvls":
            lam, viol = self.solve_bvls(sys_), 0.0
        else:
            raise ValueError(method)
        out = self.outcome(sys_, lam)
        states, margins = self.states_of(lam, out["w"])
        out.update(states=states, margins=margins, kkt_violation=viol, system=sys_)
        out["contact"] = states[0] == "held"
        if not out["contact"]:
            out["sr"] = 0.0  # convention: no interaction, no slippage ratio (eq. 30)
        return out


# --- at rest, many torques at once (for dense sampling of the input boundary) ---------------
def rest_maps(ref, q):
    """The reference's system at rest as maps of ``tau``: ``b = Bmap tau`` (the rows' free
    accelerations), ``G_c``, ``I^-1 A^T``, ``I^-1 B``, ``M``, ``I_obj`` and ``N = B^T M^-1 B``."""
    s0 = ref.system(q, np.zeros(ref.na))
    Iinv = np.linalg.inv(s0["I"])
    B = np.vstack([s0["B"], np.zeros((3, ref.na))])
    return dict(G=s0["Gc"], Bmap=s0["A"] @ Iinv @ B, IAt=Iinv @ s0["A"].T, IB=Iinv @ B,
                M=s0["M"], I_obj=s0["I_obj"], N=s0["B"].T @ np.linalg.solve(s0["M"], s0["B"]),
                ns=ref.ns)


def solve_rest_batch(ref, maps, taus):
    """Exact contact/wheel solution at rest for many torques ``(K, n_a)``: every active set
    of the reference (dense solves, vectorized), keeping the one that satisfies the KKT
    conditions (relative tolerance). Returns norms, ``sr`` (0 when lost), ``contact``."""
    G, Bm = maps["G"], maps["Bmap"]
    taus = np.atleast_2d(taus)
    b = taus @ Bm.T  # (K, nc)
    K, nc = b.shape
    best_v = np.full(K, np.inf)
    lam_best = np.zeros((K, nc))
    kept = np.zeros(K, bool)
    for states in itertools.product(*ref.choices()):
        lam = np.zeros((K, nc))
        for r, s in enumerate(states):
            if s == "slide+":
                lam[:, r] = ref.bounds[r]
            elif s == "slide-":
                lam[:, r] = -ref.bounds[r]
        H = np.array([s == "held" for s in states])
        if H.any():
            rhs = -(b[:, H] + lam[:, ~H] @ G[np.ix_(H, ~H)].T)
            lam[:, H] = np.linalg.solve(G[np.ix_(H, H)], rhs.T).T
        w = lam @ G.T + b
        scale = np.maximum(np.abs(lam).max(axis=1), 1e-300)
        wscale = np.maximum(np.abs(w).max(axis=1), 1e-300)
        v = np.zeros(K)
        for r, s in enumerate(states):
            u = ref.bounds[r]
            if s == "held" and r == 0:
                v += np.maximum(-lam[:, 0], 0) / scale
            elif s == "lost":
                v += np.maximum(-w[:, 0], 0) / wscale
            elif s == "held" and np.isfinite(u):
                v += np.maximum(np.abs(lam[:, r]) - u, 0) / scale
            elif s == "slide+":
                v += np.maximum(w[:, r], 0) / wscale
            elif s == "slide-":
                v += np.maximum(-w[:, r], 0) / wscale
        better = v < best_v
        best_v = np.where(better, v, best_v)
        lam_best[better] = lam[better]
        kept = np.where(better, states[0] == "held", kept)
    acc = taus @ maps["IB"].T + lam_best @ maps["IAt"].T
    ns = maps["ns"]
    qdd, a_obj = acc[:, :ns], acc[:, ns:]
    nq = np.einsum("ki,ij,kj->k", qdd, maps["M"], qdd)
    na = np.einsum("ki,ij,kj->k", a_obj, maps["I_obj"], a_obj)
    nl = np.einsum("ki,ij,kj->k", lam_best, G, lam_best)
    sr = np.where(kept, na / np.maximum(na + nq, 1e-300), 0.0)
    return dict(norm_qdd=nq, norm_a_obj=na, norm_lambda=nl, sr=sr, contact=kept,
                lam=lam_best, kkt=best_v)
