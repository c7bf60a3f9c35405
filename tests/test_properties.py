"""Property-based tests (Hypothesis) of the runtime against a dense model written here.

Random robots (1-8 joints; per-link masses 0.01-100 kg, lengths 0.02-2 m, inertias
1e-5-1 kg m^2, COM anywhere on the link), random scenes (scenario, kappa 0.01-1000,
mu 0-10, contact link, side and offset, wheel sets and wheel offsets) and random states
(configuration, torques, velocities, external wrench on the object) are solved by
``SceneModel.forward`` and compared with

* an independent dense model (below; it shares no code with ``snakecg``, ``snakecg_derive``,
  ``snakecg.solver`` or ``tests/reference.py``): link kinematics in closed form from ``q``,
  ``M = sum J_i^T D_i J_i``, the constraint rows from the geometry, every rate
  (``Jdot v``, ``Adot V``, ``Mdot``) by the complex-step derivative, and the
  contact/wheel problem solved by enumerating every active set with the *full* KKT system
  ``[I -A^T; A_H 0] [a; lam] = [f - h; -Adot_H V]`` (no Delassus matrix), keeping the set whose
  complementarity conditions hold;
* physical laws: Newton-Euler for the whole snake + object (momentum and angular momentum
  rates equal the external forces: the wheels' lateral forces and the wrench on the object),
  the power balance ``dT/dt = tau . qdot_a + f_obj . v_obj`` (the held constraints do no work
  on velocities that respect them), the rows' accelerations from the dense rows, the bounds
  and sliding directions of the wheels, contact complementarity and ``sr`` in [0, 1].

Near-singular configurations (links folded onto each other, wheels that sit on the same
point so their rows coincide, wheel rows that make the contact row dependent as kappa grows)
must give finite numbers or raise the ``singular`` flag, never NaN without it.

Profiles: by default every test runs a modest, derandomized (seeded) set of examples so the
file takes well under a minute; ``SNAKECG_HYPOTHESIS_PROFILE=long`` runs many more random ones
(see docs/explanation/reliability.md). Joint counts 7 and 8 are generated once per session into the
session's cache (tests/conftest.py).
"""

from __future__ import annotations

import itertools
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, assume, event, given, note, settings
from hypothesis import strategies as st

import snakecg

# --------------------------------------------------------------------------------------------
# Hypothesis profiles (registered under our own names, applied per test, so other test files
# keep their own settings).
_PHASES = [Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink]  # no slow "explain"
settings.register_profile(
    "snakecg-default", max_examples=60, deadline=None, derandomize=True, database=None,
    phases=_PHASES, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
settings.register_profile(
    "snakecg-long", max_examples=1000, deadline=None, derandomize=False, phases=_PHASES,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
PROFILE_NAME = os.environ.get("SNAKECG_HYPOTHESIS_PROFILE", "default")
if PROFILE_NAME not in ("default", "long"):
    raise pytest.UsageError(
        f"SNAKECG_HYPOTHESIS_PROFILE must be 'default' or 'long', got {PROFILE_NAME!r}"
    )
PROFILE = settings.get_profile(f"snakecg-{PROFILE_NAME}")

G = 9.81


# --------------------------------------------------------------------------------------------
# Dense model (complex-safe so that rates come from the complex step)
def _perp(c, s):
    return np.array([-s, c])


class Dense:
    """The coupled snake + object of a Scene, written from the paper and docs/CONTEXT."""

    def __init__(self, scene: snakecg.Scene):
        r = scene.robot
        self.na, self.nl = r.joints, r.joints + 1
        self.ns, self.nc = r.joints + 3, r.joints + 2
        self.m = np.array(r.mass)
        self.l = np.array(r.length)
        self.I = np.array(r.inertia)
        self.c = np.array(r.com)
        self.k = scene.contact_link - 1
        self.sigma = 1.0 if scene.side == "left" else -1.0
        self.offset = scene.contact_offset
        self.dist = scene.object_distance
        self.m_obj = scene.kappa * self.m.mean()
        self.I_obj = scene.object_inertia
        self.woff = np.array(scene.wheel_offset)
        self.present = np.zeros(self.nc, bool)
        self.present[0] = True
        if scene.scenario != "frictionless":
            self.present[list(scene.wheel_links)] = True
        self.bound = np.full(self.nc, np.inf)
        if scene.scenario == "wheels":
            self.bound[1:] = scene.mu * self.m * scene.gravity

    # kinematics ------------------------------------------------------------------------------
    def angles(self, q):
        phi = [q[2]]
        for j in range(self.na):
            phi.append(phi[-1] + q[3 + j])
        return phi

    def rear_and_com(self, q):
        phi = self.angles(q)
        e = [np.array([np.cos(p), np.sin(p)]) for p in phi]
        rear = [np.array([q[0], q[1]]) - self.c[0] * e[0]]
        for i in range(self.nl - 1):
            rear.append(rear[i] + self.l[i] * e[i])
        com = [rear[i] + self.c[i] * e[i] for i in range(self.nl)]
        return phi, e, rear, com

    def phi_rows(self, dtype=float):
        """``S[j]``: d phi_j / d q (phi_j = theta + q_1 + ... + q_{j-1})."""
        S = np.zeros((self.nl, self.ns), dtype)
        S[:, 2] = 1
        for j in range(self.nl):
            S[j, 3:3 + j] = 1
        return S

    def jacobians(self, q):
        """``(n_l, 3, n_s)``: COM velocity and angular rate of each link = ``J_i qdot``."""
        phi, e, _, _ = self.rear_and_com(q)
        S = self.phi_rows(np.result_type(q, float))
        J = np.zeros((self.nl, 3, self.ns), dtype=S.dtype)
        for i in range(self.nl):
            J[i, 0, 0] = J[i, 1, 1] = 1  # (x, y) is the COM of link 1
            J[i, 2] = S[i]
            if i == 0:
                continue
            # COM_i = (x, y) + (l_1 - c_1) e_1 + sum_{1<j<i} l_j e_j + c_i e_i
            arms = [self.l[0] - self.c[0]] + [self.l[j] for j in range(1, i)] + [self.c[i]]
            for j, arm in enumerate(arms):
                J[i, :2] += arm * np.outer(_perp(np.cos(phi[j]), np.sin(phi[j])), S[j])
        return J

    @staticmethod
    def rate(fun, x, d, h=1e-30):
        """``d/dt fun(x + t d)`` at 0 by the complex step (exact to rounding)."""
        return np.imag(fun(np.asarray(x, float) + 1j * h * np.asarray(d, float))) / h

    def mass_matrix(self, q):
        J = self.jacobians(q)
        D = np.stack([np.diag([m, m, i]) for m, i in zip(self.m, self.I)])
        return np.einsum("iak,iab,ibl->kl", J, D, J)

    def bias(self, q, v):
        """``h_s = sum J_i^T D_i Jdot_i v`` and the links' ``Jdot_i v``."""
        J = self.jacobians(q)
        Jdv = self.rate(lambda x: np.einsum("iak,k->ia", self.jacobians(x), v), q, v)
        D = np.stack([np.diag([m, m, i]) for m, i in zip(self.m, self.I)])
        return np.einsum("iak,iab,ib->k", J, D, Jdv), Jdv

    # object and rows ---------------------------------------------------------------------------
    def place(self, q):
        phi, e, rear, _ = self.rear_and_com(q)
        k = self.k
        n = self.sigma * _perp(*e[k])
        P = rear[k] + self.offset * e[k]
        return np.array([*(P + self.dist * n), phi[k]]), np.array([0.0, -self.sigma * self.dist])

    def rows(self, x, rho):
        """``A(x)``, x = (q, q_obj): contact row (gap rate) and one wheel row per link."""
        q, qo = x[: self.ns], x[self.ns:]
        phi, e, rear, _ = self.rear_and_com(q)
        J = self.jacobians(q)
        S = self.phi_rows(J.dtype)
        A = np.zeros((self.nc, self.ns + 3), dtype=J.dtype)
        k = self.k
        n = self.sigma * _perp(*e[k])
        R_rho = np.array([np.cos(qo[2]) * rho[0] - np.sin(qo[2]) * rho[1],
                          np.sin(qo[2]) * rho[0] + np.cos(qo[2]) * rho[1]])
        d = qo[:2] + R_rho - rear[k]
        # gap = n . d ; d n/d phi_k = -sigma e_k ; r_k = COM_k - c_k e_k
        A[0, : self.ns] = (-self.sigma * (e[k] @ d) + self.sigma * self.c[k]) * S[k] \
            - n @ J[k, :2]
        A[0, self.ns:self.ns + 2] = n
        A[0, self.ns + 2] = n @ _perp(R_rho[0], R_rho[1])
        for i in range(self.nl):
            a_w = np.array([-np.sin(phi[i]), np.cos(phi[i]), self.woff[i]])
            A[1 + i, : self.ns] = a_w @ J[i]
        return A

    # the coupled system ------------------------------------------------------------------------
    def system(self, q, v, tau, v_obj, f_obj):
        q_obj, rho = self.place(q)
        x = np.concatenate([q, q_obj])
        V = np.concatenate([v, v_obj])
        M = self.mass_matrix(q)
        h, Jdv = self.bias(q, v)
        n = self.ns + 3
        I = np.zeros((n, n))
        I[: self.ns, : self.ns] = M
        I[self.ns:, self.ns:] = np.diag([self.m_obj, self.m_obj, self.I_obj])
        f = np.concatenate([np.concatenate([np.zeros(3), tau]) - h, f_obj])
        A = self.rows(x, rho)
        Adv = self.rate(lambda xx: self.rows(xx, rho) @ V, x, V)
        return dict(I=I, M=M, f=f, A=A, Adv=Adv, x=x, V=V, Jdv=Jdv, q_obj=q_obj, rho=rho)

    def candidates(self):
        """Every active set: per row "absent", contact held/lost, wheel held/slide+/slide-."""
        choices = []
        for r in range(self.nc):
            if not self.present[r]:
                choices.append(("absent",))
            elif r == 0:
                choices.append(("held", "lost"))
            elif np.isfinite(self.bound[r]):
                choices.append(("held", "slide+", "slide-"))
            else:
                choices.append(("held",))
        return list(itertools.product(*choices))

    def solve(self, sysd):
        """Enumerate the active sets; each is one full KKT solve; keep the one that satisfies
        the complementarity conditions (smallest violation)."""
        sets = self.candidates()
        acc, lam, w = self.kkt(sysd, sets)
        scale_l = np.maximum(1.0, np.abs(lam).max(axis=1))
        scale_w = np.maximum(1.0, np.abs(w).max(axis=1))
        viol = np.zeros(len(sets))
        for s, states in enumerate(sets):
            for r, st_ in enumerate(states):
                if st_ == "held" and r == 0:
                    viol[s] += max(-lam[s, 0], 0) / scale_l[s]
                elif st_ == "lost":
                    viol[s] += max(-w[s, 0], 0) / scale_w[s]
                elif st_ == "held" and np.isfinite(self.bound[r]):
                    viol[s] += max(abs(lam[s, r]) - self.bound[r], 0) / scale_l[s]
                elif st_ == "slide+":
                    viol[s] += max(w[s, r], 0) / scale_w[s]
                elif st_ == "slide-":
                    viol[s] += max(-w[s, r], 0) / scale_w[s]
        best = int(np.argmin(viol))
        return dict(qdd=acc[best, : self.ns], a_obj=acc[best, self.ns:], lam=lam[best],
                    w=w[best], states=sets[best], violation=viol[best])

    def kkt(self, sysd, sets):
        """Accelerations, forces and rows' accelerations for each active set in ``sets``:
        ``I a - A^T lam = f``; held rows ``A_r a = -Adot_r V``; other rows ``lam_r`` fixed."""
        I, f, A, Adv = sysd["I"], sysd["f"], sysd["A"], sysd["Adv"]
        n, nc = I.shape[0], self.nc
        K = np.zeros((len(sets), n + nc, n + nc))
        rhs = np.zeros((len(sets), n + nc))
        K[:, :n, :n] = I
        K[:, :n, n:] = -A.T
        rhs[:, :n] = f
        for s, states in enumerate(sets):
            for r, st_ in enumerate(states):
                if st_ == "held":
                    K[s, n + r, :n] = A[r]
                    rhs[s, n + r] = -Adv[r]
                else:
                    K[s, n + r, n + r] = 1.0
                    if st_ in ("slide+", "slide-"):
                        rhs[s, n + r] = (1 if st_ == "slide+" else -1) * self.bound[r]
        try:
            sol = np.linalg.solve(K, rhs[..., None])[..., 0]
        except np.linalg.LinAlgError:  # some active set holds dependent rows: least squares
            sol = np.stack([np.linalg.lstsq(Ks, r_, rcond=None)[0] for Ks, r_ in zip(K, rhs)])
        acc, lam = sol[:, :n], sol[:, n:]
        return acc, lam, acc @ A.T + Adv


# --------------------------------------------------------------------------------------------
# strategies
def log_uniform(lo, hi):
    return st.floats(np.log(lo), np.log(hi)).map(np.exp)


@st.composite
def scenes(draw, joints=st.integers(1, 8), scenarios=st.sampled_from(snakecg.SCENARIOS)):
    na = draw(joints)
    event(f"joints={na}")
    nl = na + 1
    length = draw(st.lists(log_uniform(0.02, 2.0), min_size=nl, max_size=nl))
    robot = snakecg.Robot(
        joints=na,
        mass=draw(st.lists(log_uniform(0.01, 100.0), min_size=nl, max_size=nl)),
        length=length,
        inertia=draw(st.lists(log_uniform(1e-5, 1.0), min_size=nl, max_size=nl)),
        com=[l_ * draw(st.floats(0.05, 0.95)) for l_ in length],
    )
    k = draw(st.integers(1, nl))
    others = [i for i in range(1, nl + 1) if i != k]
    wheels = draw(st.one_of(st.none(), st.lists(st.sampled_from(others), unique=True)
                            if others else st.none()))
    return snakecg.Scene(
        robot,
        scenario=draw(scenarios),
        kappa=draw(log_uniform(0.01, 1000.0)),
        mu=draw(st.one_of(log_uniform(1e-3, 10.0), log_uniform(1e-3, 10.0),
                          st.floats(0.0, 10.0), st.just(0.0))),
        contact_link=k,
        contact_offset=draw(st.floats(0.0, 1.0)) * length[k - 1],
        side=draw(st.sampled_from(["left", "right"])),
        wheel_links=None if wheels is None else tuple(wheels),
        wheel_offset=[l_ * draw(st.floats(-0.5, 0.5)) for l_ in length],
    )


def unit_floats(n):
    return st.lists(st.floats(-1.0, 1.0), min_size=n, max_size=n).map(np.array)


@st.composite
def states(draw, scene, moving=True):
    """Configuration (angles anywhere), torques, and a velocity that respects every present
    row (wheels roll, the contact neither opens nor closes), plus a wrench on the object."""
    r = scene.robot
    q = np.concatenate([draw(unit_floats(2)), np.pi * draw(unit_floats(r.joints + 1))])
    tau_scale = draw(log_uniform(1e-3, 1e2))
    tau = tau_scale * draw(unit_floats(r.joints))
    V = draw(unit_floats(r.joints + 6)) * draw(log_uniform(1e-3, 10.0)) if moving \
        else np.zeros(r.joints + 6)
    f_obj = draw(st.one_of(st.just(np.zeros(3)), unit_floats(3).map(lambda f: 10 * f)))
    return q, tau, V, f_obj


def project_velocity(dense: Dense, q, V):
    """The part of ``V = (v, v_obj)`` in the null space of the present rows at ``q``."""
    q_obj, rho = dense.place(q)
    A = dense.rows(np.concatenate([q, q_obj]), rho)[dense.present]
    _, s, vt = np.linalg.svd(A)
    rank = int(np.sum(s > 1e-12 * s.max()))
    N = vt[rank:].T
    return N @ (N.T @ V)


def load(scene):
    return snakecg.load(scene)


# --------------------------------------------------------------------------------------------
def cross2(a, b):
    """z-component of the cross product of planar vectors (last axis of size 2)."""
    a, b = np.asarray(a), np.asarray(b)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _m_norm(M, x):
    return float(np.sqrt(max(x @ M @ x, 0.0)))


def check_against_dense(scene, q, tau, V, f_obj, *, rtol):
    """Run forward and the dense model; assert agreement and the physical laws."""
    dense = Dense(scene)
    V = project_velocity(dense, q, V)
    v, v_obj = V[: dense.ns], V[dense.ns:]
    sm = load(scene)
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    note(f"runtime lam={res.lam} states={res.wheel_state} contact={res.contact}")
    event(f"{scene.scenario}, contact {'kept' if res.contact else 'lost'}"
          + (", sliding" if np.any(res.sliding) else ""))
    sysd = dense.system(q, v, tau, v_obj, f_obj)
    M, A = sysd["M"], sysd["A"]
    outputs = [res.qdd, res.a_obj, res.lam, res.w, res.sr, res.norm_qdd, res.norm_a_obj]
    assert all(np.all(np.isfinite(o)) for o in outputs) or res.singular
    # placement agrees (geometry of the contact)
    q_obj_rt, rho_rt, _ = sm.place_object(q)
    np.testing.assert_allclose(q_obj_rt, sysd["q_obj"], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(rho_rt, sysd["rho"], rtol=1e-12, atol=1e-14)

    ref = dense.solve(sysd)
    note(f"dense lam={ref['lam']} states={ref['states']} violation={ref['violation']}")
    assert ref["violation"] < 1e-8, "the dense enumeration found no KKT point"

    # --- agreement with the dense model ------------------------------------------------------
    # Both sides stop at a KKT point to ~1e-9 (relative); with a Delassus matrix of condition
    # number c, the forces of two such points may differ by ~1e-9 c. Random scenes have c well
    # below 1e3; the near-singular tests reach 1e9 and more (then only the laws are tight).
    I = sysd["I"]
    Gp = (A @ np.linalg.solve(I, A.T))[np.ix_(dense.present, dense.present)]
    ev = np.linalg.eigvalsh(Gp)
    cond = ev.max() / max(ev.min(), 1e-300 * ev.max())
    if cond < 1e15:
        rtol_agree = max(rtol, 1e-9 * cond)
    else:  # exactly dependent rows: A^T lam is still unique, see below
        rtol_agree = rtol
    lam_scale = max(1.0, np.abs(ref["lam"]).max(), np.abs(res.lam).max())
    # The generalized constraint force A^T lam is unique (the QP's objective is convex in lam
    # and strictly convex in A^T lam); lam itself only when the present rows are independent
    # (two wheels on one point share their force in any proportion).
    Iinv_sqrt = 1 / np.sqrt(np.diag(I))  # I is diagonal in the object block, M is not: use
    gen_rt, gen_ref = A.T @ res.lam, A.T @ ref["lam"]  # a diagonal scaling for the metric
    np.testing.assert_allclose(gen_rt * Iinv_sqrt, gen_ref * Iinv_sqrt, rtol=0,
                               atol=rtol_agree * lam_scale * np.abs(A * Iinv_sqrt).max())
    if cond < 1e12:
        np.testing.assert_allclose(res.lam, ref["lam"], rtol=0, atol=rtol_agree * lam_scale)
    else:
        event("dependent rows: forces compared through A^T lam only")
    a_ref = np.concatenate([ref["qdd"], ref["a_obj"]])
    a_rt = np.concatenate([res.qdd, res.a_obj])
    # accelerations compared in the kinetic-energy metric (scale-free across link sizes)
    force_scale = np.sqrt(np.sum(sysd["f"] ** 2 / np.diag(I))) + lam_scale * np.sqrt(
        np.sum((A**2).sum(axis=0) / np.diag(I)))
    assert _m_norm(I, a_rt - a_ref) <= rtol_agree * (force_scale + _m_norm(I, a_ref)) + 1e-300

    # --- physical laws, on the runtime's numbers only ----------------------------------------
    lam, w = res.lam, res.w
    # rows' accelerations: the dense rows applied to the runtime's accelerations
    w_dense = A @ a_rt + sysd["Adv"]
    w_scale = np.abs(A).sum(axis=1) * np.abs(a_rt).max() + np.abs(sysd["Adv"]) + 1.0
    present = dense.present
    np.testing.assert_allclose(w[present], w_dense[present], rtol=0,
                               atol=rtol * w_scale[present].max())
    tol_l, tol_w = 1e-7 * lam_scale, rtol * w_scale.max()
    # contact: lam_c >= 0, w_c >= 0 (no penetration), complementarity
    assert lam[0] >= -tol_l
    if res.contact:
        assert abs(w[0]) <= tol_w
    else:
        assert abs(lam[0]) <= tol_l and w[0] >= -tol_w and res.sr == 0.0
    # wheels: absent rows carry nothing; bounds; sliding opposes the row's acceleration
    for i, state in enumerate(res.wheel_state, start=1):
        if not present[i]:
            assert state == "none" and lam[i] == 0.0
            continue
        u = dense.bound[i]
        assert abs(lam[i]) <= u + tol_l
        if state == "stick":
            assert abs(w[i]) <= tol_w
        elif state == "slide+":
            assert lam[i] == pytest.approx(u, rel=1e-9) and w[i] <= tol_w
        elif state == "slide-":
            assert lam[i] == pytest.approx(-u, rel=1e-9) and w[i] >= -tol_w
        else:
            pytest.fail(f"wheel {i} present but in state {state!r}")
        if state != "stick":  # friction dissipates: lam w <= 0 (held rows: w = 0, above)
            assert lam[i] * w[i] <= u * tol_w
    assert 0.0 <= res.sr <= 1.0
    # norms of eqs. (26), (27)
    assert res.norm_qdd == pytest.approx(res.qdd @ M @ res.qdd, rel=1e-7, abs=1e-12)
    I_o = np.diag([dense.m_obj, dense.m_obj, dense.I_obj])
    assert res.norm_a_obj == pytest.approx(res.a_obj @ I_o @ res.a_obj, rel=1e-7, abs=1e-12)

    # Newton-Euler for snake + object: the wheels' lateral forces and f_obj are the only
    # external forces (the contact force is internal: equal, opposite, at one point)
    _, e, _, com = dense.rear_and_com(q)
    acc_links = np.einsum("iak,k->ia", dense.jacobians(q), res.qdd) + sysd["Jdv"]
    p_o = sysd["q_obj"][:2]
    F_ext = f_obj[:2].copy()
    L_ext = f_obj[2] + cross2(p_o, f_obj[:2])
    for i in range(1, dense.nc):
        if present[i]:
            n_i = _perp(*e[i - 1])
            point = com[i - 1] + dense.woff[i - 1] * e[i - 1]
            F_ext += lam[i] * n_i
            L_ext += cross2(point, lam[i] * n_i)
    F = dense.m @ acc_links[:, :2] + dense.m_obj * res.a_obj[:2]
    Ldot = (np.sum(dense.m * cross2(np.array(com), acc_links[:, :2])) + dense.I @ acc_links[:, 2]
            + dense.m_obj * cross2(p_o, res.a_obj[:2]) + dense.I_obj * res.a_obj[2])
    mom_scale = (np.sum(dense.m * np.abs(acc_links[:, :2]).max(axis=1))
                 + dense.m_obj * np.abs(res.a_obj[:2]).max() + np.abs(f_obj).sum()
                 + np.abs(lam).sum() + 1e-12)
    np.testing.assert_allclose(F, F_ext, rtol=0, atol=rtol * mom_scale)
    arm = 1.0 + max(np.abs(np.array(com)).max(), np.abs(p_o).max())
    ang_scale = arm * mom_scale + np.abs(dense.I @ acc_links[:, 2]).sum() \
        + dense.I_obj * abs(res.a_obj[2]) + abs(L_ext)
    assert abs(Ldot - L_ext) <= rtol * ang_scale

    # power balance: dT/dt = tau . qdot_a + f_obj . v_obj (held rows do no work on V)
    Mdot = dense.rate(dense.mass_matrix, q, v)
    dTdt = v @ M @ res.qdd + 0.5 * v @ Mdot @ v + v_obj @ I_o @ res.a_obj
    power_in = tau @ v[3:] + f_obj @ v_obj
    p_scale = (np.abs(v) @ np.abs(M) @ np.abs(res.qdd) + 0.5 * np.abs(v) @ np.abs(Mdot) @ np.abs(v)
               + np.abs(v_obj) @ np.abs(I_o) @ np.abs(res.a_obj) + np.abs(tau) @ np.abs(v[3:])
               + np.abs(f_obj) @ np.abs(v_obj)
               + 1e-9 * (1.0 + np.abs(sysd["V"]) @ np.abs(sysd["I"]) @ np.abs(sysd["V"])))
    assert abs(dTdt - power_in) <= rtol * p_scale
    return res, ref


# --------------------------------------------------------------------------------------------
# runtime vs dense model, all scenarios
@pytest.mark.parametrize("scenario", snakecg.SCENARIOS)
@PROFILE
@given(data=st.data())
def test_forward_matches_dense_model_and_laws(scenario, data):
    scene = data.draw(scenes(scenarios=st.just(scenario)))
    q, tau, V, f_obj = data.draw(states(scene))
    check_against_dense(scene, q, tau, V, f_obj, rtol=1e-6)


@PROFILE
@given(data=st.data(),
       target=st.sampled_from([0.25, 0.5, 0.8, 0.95, 0.99, 1.01, 1.05, 1.1, 1.3, 2.0, 4.0]))
def test_wheels_near_the_friction_bound(data, target):
    """Torques scaled so that, with every wheel held, the most loaded wheel needs ``target``
    times its friction bound mu m_i g: the active set then mixes sticking and sliding wheels."""
    scene = data.draw(scenes(scenarios=st.just("wheels")))
    dense = Dense(scene)
    assume(scene.mu > 0 and np.any(dense.present[1:]))
    q, tau_dir, _, _ = data.draw(states(scene, moving=False))
    zeros = np.zeros(3)
    sysd = dense.system(q, np.zeros(dense.ns), tau_dir, zeros, zeros)
    held = tuple("held" if p else "absent" for p in dense.present)
    _, lam, _ = dense.kkt(sysd, [held])
    wheels = dense.present.copy()
    wheels[0] = False
    load_ratio = np.max(np.abs(lam[0][wheels]) / dense.bound[wheels])
    assume(load_ratio > 1e-12)
    tau = tau_dir * target / load_ratio
    res, _ = check_against_dense(scene, q, tau, np.zeros(dense.ns + 3), zeros, rtol=1e-6)
    event("some wheel slides" if np.any(res.sliding) else "all wheels stick")


@PROFILE
@given(data=st.data(), scene=scenes(scenarios=st.just("frictionless")))
def test_frictionless_conserves_momentum_at_rest(data, scene):
    """Frictionless, no wrench on the object: total momentum and angular momentum of snake +
    object do not change, whatever the torques (the only external forces are absent)."""
    q, tau, _, _ = data.draw(states(scene, moving=False))
    res, _ = check_against_dense(scene, q, tau, np.zeros(scene.robot.joints + 6), np.zeros(3),
                                 rtol=1e-6)
    assert res.wheel_state.tolist() == ["none"] * scene.robot.n_links


@PROFILE
@given(data=st.data(), scene=scenes(joints=st.integers(1, 6)))
def test_batched_forward_equals_one_by_one(data, scene):
    """A batch of samples gives, sample by sample, what single calls give."""
    sm = load(scene)
    samples = [data.draw(states(scene)) for _ in range(3)]
    dense = Dense(scene)
    qs, taus, vs, vos = [], [], [], []
    for q, tau, V, _ in samples:
        V = project_velocity(dense, q, V)
        qs.append(q), taus.append(tau), vs.append(V[: dense.ns]), vos.append(V[dense.ns:])
    batch = sm.forward(np.array(qs), np.array(taus), v=np.array(vs), v_obj=np.array(vos))
    for j in range(3):
        one = sm.forward(qs[j], taus[j], v=vs[j], v_obj=vos[j])
        for name in ("qdd", "a_obj", "lam", "w", "sr", "norm_qdd", "norm_a_obj"):
            np.testing.assert_allclose(getattr(batch, name)[j], getattr(one, name),
                                       rtol=1e-12, atol=1e-12 * (1 + np.abs(one.lam).max()))
        assert batch.wheel_state[j].tolist() == one.wheel_state.tolist()
        assert bool(batch.contact[j]) == bool(one.contact)


# --------------------------------------------------------------------------------------------
# near-singular configurations: finite numbers or the `singular` flag, never NaN unflagged
def _assert_finite_or_flagged(res):
    outs = [res.qdd, res.a_obj, res.lam, res.w, res.sr, res.norm_qdd, res.norm_a_obj,
            res.norm_lambda]
    finite = all(np.all(np.isfinite(o)) for o in outs)
    assert finite or res.singular, f"non-finite result without the singular flag: {res}"
    return finite


SHARP = [0.0, 1e-14, -1e-12, 1e-9, -1e-6, 1e-3]


@PROFILE
@given(data=st.data(), scene=scenes(joints=st.integers(2, 6),
                                      scenarios=st.sampled_from(["wheels", "ideal_wheels"])),
       eps=st.sampled_from(SHARP), fold=st.sampled_from([0.0, np.pi, -np.pi]))
def test_coincident_wheels_flagged_or_finite(data, scene, eps, fold):
    """Joint j folded flat (q_j = 0) or back onto itself (q_j = +-pi), with the wheel of link j
    at its front end and the wheel of link j+1 at its rear end: both wheels sit on joint j, so
    their rows coincide (or are opposite) exactly at eps = 0 and nearly so for small eps."""
    r = scene.robot
    joints = [j for j in range(1, r.joints + 1) if scene.contact_link not in (j, j + 1)]
    assume(joints)
    j = data.draw(st.sampled_from(joints))  # joint between links j and j+1
    woff = list(scene.wheel_offset)
    woff[j - 1] = r.length[j - 1] - r.com[j - 1]
    woff[j] = -r.com[j]
    wheels = tuple(sorted(set(scene.wheel_links) | {j, j + 1}))
    scene = scene.replace(wheel_offset=tuple(woff), wheel_links=wheels)
    q, tau, _, _ = data.draw(states(scene, moving=False))
    q[2 + j] = fold + eps
    res = load(scene).forward(q, tau)
    finite = _assert_finite_or_flagged(res)
    event(f"eps={eps:g}: " + ("flagged" if res.singular else "not flagged"))
    if not res.singular:
        check_against_dense(scene, q, tau, np.zeros(r.joints + 6), np.zeros(3), rtol=1e-5)
    if eps == 0.0 and scene.scenario == "ideal_wheels":
        assert res.singular, "two identical held wheel rows must be flagged"
    if finite and res.singular:
        # The forces solve (G_c + r 1) lam = -b on the held rows with r = 1e-10 max diag G_c
        # (snakecg.solver): the held rows' accelerations are -r lam, tiny but not zero.
        dense = Dense(scene)
        sysd = dense.system(q, np.zeros(dense.ns), tau, np.zeros(3), np.zeros(3))
        A, I = sysd["A"], sysd["I"]
        g_max = np.max(np.diag(A @ np.linalg.solve(I, A.T)))
        held = np.array([bool(res.contact)] + [s == "stick" for s in res.wheel_state])
        bound = 2e-9 * (g_max * np.abs(res.lam).max() + np.abs(res.w).max() + 1.0)
        assert np.all(np.abs(res.w[held]) <= bound)


@PROFILE
@given(data=st.data(), scene=scenes(joints=st.integers(1, 6), scenarios=st.just("ideal_wheels")),
       kappa=st.sampled_from([1e3, 1e6, 1e9, 1e12]), eps=st.sampled_from(SHARP))
def test_wheel_rows_making_contact_dependent(data, scene, kappa, eps):
    """Contact at the rear end of link k and a wheel on link k-1 at its front end, links
    aligned: the snake part of the contact row is minus the wheel row, so only the object
    (mass kappa m) keeps the contact row independent; as kappa grows it becomes dependent."""
    r = scene.robot
    assume(scene.contact_link >= 2)
    k = scene.contact_link
    woff = list(scene.wheel_offset)
    woff[k - 2] = r.length[k - 2] - r.com[k - 2]
    wheels = tuple(sorted(set(scene.wheel_links) | {k - 1}))
    scene = scene.replace(kappa=kappa, contact_offset=0.0, wheel_offset=tuple(woff),
                          wheel_links=wheels, contact_link=k)
    q, tau, _, _ = data.draw(states(scene, moving=False))
    q[2 + k - 1] = eps  # joint k-1 between links k-1 and k
    res = load(scene).forward(q, tau)
    _assert_finite_or_flagged(res)
    event(f"kappa={kappa:g}: " + ("flagged" if res.singular else "not flagged"))
    if not res.singular:
        check_against_dense(scene, q, tau, np.zeros(r.joints + 6), np.zeros(3), rtol=1e-5)


@PROFILE
@given(data=st.data(), scene=scenes(joints=st.integers(2, 6)),
       eps=st.sampled_from(SHARP))
def test_folded_links(data, scene, eps):
    """Every joint at +-pi (+eps): the links lie on top of one another."""
    q, tau, _, _ = data.draw(states(scene, moving=False))
    signs = np.array(data.draw(st.lists(st.sampled_from([-1.0, 1.0]),
                                        min_size=scene.robot.joints,
                                        max_size=scene.robot.joints)))
    q[3:] = signs * np.pi + eps
    res = load(scene).forward(q, tau)
    event("flagged" if res.singular else "not flagged")
    if _assert_finite_or_flagged(res) and not res.singular:
        check_against_dense(scene, q, tau, np.zeros(scene.robot.joints + 6), np.zeros(3),
                            rtol=1e-5)


def test_exactly_dependent_rows_give_least_norm_forces():
    """Two ideal wheels on the same point of a straight snake: the rows are identical, the
    runtime flags the sample and splits the force evenly (the least-norm solution), and the
    result matches the dense model with the two wheels replaced by one."""
    robot = snakecg.Robot(joints=2)
    l, c = robot.length, robot.com
    scene = snakecg.Scene(robot, scenario="ideal_wheels", contact_link=1, kappa=10.0,
                          wheel_links=(2, 3), wheel_offset=(0.0, l[1] - c[1], -c[2]))
    q = np.array([0.1, -0.2, 0.3, 0.0, 0.0])
    tau = np.array([0.4, -0.7])
    res = load(scene).forward(q, tau)
    assert res.singular and np.all(np.isfinite(res.lam))
    # the split is set by a 1e-10 regularization: even to about cond * eps = 1e-6
    assert res.lam[2] == pytest.approx(res.lam[3], rel=1e-4)
    single = scene.replace(wheel_links=(2,), wheel_offset=(0.0, l[1] - c[1], 0.0))
    ref = Dense(single).solve(Dense(single).system(q, np.zeros(5), tau, np.zeros(3),
                                                   np.zeros(3)))
    assert res.lam[2] + res.lam[3] == pytest.approx(ref["lam"][2], rel=1e-6)
    np.testing.assert_allclose(res.qdd, ref["qdd"], rtol=1e-6, atol=1e-9)
