"""Benchmark of the interaction analysis: ``SceneModel.forward`` batched and single.

For a 3-joint snake in the ``ideal_wheels`` and ``wheels`` scenarios, at rest:

* batched ``forward`` over N (configuration, torque) pairs, norms and sr included (the whole
  public call: validation, object placement, active-set iterations, result);
* one ``forward`` call from Python (latency: median and 90th percentile);
* the same equations written as a vectorized numpy program (einsum / batched ``solve`` over
  the batch, the same primal-dual active-set iteration), checked against the runtime and
  timed, and the ratio numpy / runtime.

Targets: batched < 2 us per pair (ideal_wheels), single call < 50 us.

    python benchmarks/bench_interaction.py [--n 100000] [--repeat 3]
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time

import numpy as np

import snakecg

from _machine import cpu_name  # benchmarks/_machine.py

JOINTS = 3
SCENARIOS = ("ideal_wheels", "wheels")


# ------------------------------------------------------------------------------------------
# the same equations in vectorized numpy (eqs. 3-30 at rest)
# ------------------------------------------------------------------------------------------
class NumpyInteraction:
    """Vectorized numpy forward analysis of a scene at rest (v = 0, f_obj = 0)."""

    def __init__(self, scene: snakecg.Scene):
        r = scene.robot
        self.na, self.nl, self.ns = r.joints, r.joints + 1, r.joints + 3
        self.nc = self.nl + 1
        nl, ns = self.nl, self.ns
        self.m = np.array(r.mass)
        self.I = np.array(r.inertia)
        self.l = np.array(r.length)
        self.c = np.array(r.com)
        # COM_i = (x, y) + sum_j coef_ij e_j  (rear end of link 1 at (x, y) - c_1 e_1)
        coef = np.zeros((nl, nl))
        for i in range(nl):
            coef[i, :i] = self.l[:i]
            coef[i, i] += self.c[i]
            coef[i, 0] -= self.c[0]
        self.coef = coef
        # d phi_j / d q: theta moves every link, q_k the links after joint k
        dphi = np.zeros((nl, ns))
        dphi[:, 2] = 1.0
        for k in range(self.na):
            dphi[k + 1:, 3 + k] = 1.0
        self.dphi = dphi
        self.k = scene.contact_link - 1
        self.sigma = scene.side_sign
        self.s = scene.contact_offset
        self.dist = scene.object_distance
        self.m_obj = scene.kappa * self.m.mean()
        self.io = np.array([self.m_obj, self.m_obj, scene.object_inertia])
        self.woff = np.array(scene.wheel_offset)
        present = np.zeros(self.nc, bool)
        present[0] = True
        if scene.scenario != "frictionless":
            present[list(scene.wheel_links)] = True
        self.present = present
        self.bounds = np.full(self.nc, np.inf)
        if scene.scenario == "wheels":
            self.bounds[1:] = scene.mu * self.m * scene.gravity
        self.B = np.vstack([np.zeros((3, self.na)), np.eye(self.na)])
        self.M_rot = np.einsum("i,ik,il->kl", self.I, dphi, dphi)

    def __call__(self, q, tau, max_iter=30):
        N, _nl, ns, nc = len(q), self.nl, self.ns, self.nc
        phi = q[:, 2:3] + np.concatenate([np.zeros((N, 1)), np.cumsum(q[:, 3:], axis=1)], 1)
        e = np.stack([np.cos(phi), np.sin(phi)], axis=-1)  # (N, nl, 2)
        perp = np.stack([-e[..., 1], e[..., 0]], axis=-1)
        com = q[:, None, :2] + np.einsum("ij,njd->nid", self.coef, e)
        # link Jacobians of the COM positions (N, nl, 2, ns)
        Jp = np.einsum("ij,njd,jk->nidk", self.coef, perp, self.dphi)
        Jp[:, :, 0, 0] += 1.0
        Jp[:, :, 1, 1] += 1.0
        M = np.einsum("i,nidk,nidl->nkl", self.m, Jp, Jp) + self.M_rot
        # contact: gradient of the gap n^T (P - r_k) at the touching placement
        k = self.k
        n_k = self.sigma * perp[:, k]
        JP = Jp[:, k] + (self.s - self.c[k]) * perp[:, k, :, None] * self.dphi[k]
        A = np.zeros((N, nc, ns + 3))
        A[:, 0, :ns] = -np.einsum("nd,ndk->nk", n_k, JP)
        A[:, 0, ns:ns + 2] = n_k  # object COM on the normal: no moment arm
        # wheels: lateral velocity of the wheel point of every link
        A[:, 1:, :ns] = (np.einsum("nid,nidk->nik", perp, Jp)
                         + self.woff[None, :, None] * self.dphi[None])
        As, Ao = A[:, :, :ns], A[:, :, ns:]
        rhs = np.concatenate([np.broadcast_to(self.B, (N, ns, self.na)),
                              np.swapaxes(As, 1, 2)], axis=2)
        X = np.linalg.solve(M, rhs)
        MinvB, MinvAsT = X[:, :, :self.na], X[:, :, self.na:]
        Gc = As @ MinvAsT + np.einsum("nrd,d,nsd->nrs", Ao, 1 / self.io, Ao)
        qdd0 = np.einsum("nka,na->nk", MinvB, tau)
        b = np.einsum("nrk,nk->nr", As, qdd0)
        # primal-dual active set (1 held, 2 lost, 3 slide+, 4 slide-, 0 absent)
        state = np.where(self.present, 1, 0)[None].repeat(N, 0)
        lam = np.zeros((N, nc))
        w = np.zeros((N, nc))
        active = np.arange(N)
        ub = self.bounds
        for _ in range(max_iter):
            if active.size == 0:
                break
            st = state[active]
            G, bb = Gc[active], b[active]
            free = (st == 1).astype(float)
            lf = np.where(st == 3, ub, 0.0) - np.where(st == 4, ub, 0.0)
            lf = np.where(np.isfinite(lf), lf, 0.0)
            D = free[:, :, None] * free[:, None, :]
            Gp = G * D + np.eye(nc) * (1 - free)[:, None, :]
            rhs = -free * (bb + np.einsum("nrs,ns->nr", G, lf))
            la = np.linalg.solve(Gp, rhs[..., None])[..., 0] + lf
            wa = np.einsum("nrs,ns->nr", G, la) + bb
            lam[active], w[active] = la, wa
            tl = 1e-9 * np.maximum(1, np.abs(la).max(1, keepdims=True))
            tw = 1e-9 * np.maximum(1, np.abs(wa).max(1, keepdims=True))
            new = st.copy()
            c0 = new[:, 0]
            c0[(st[:, 0] == 1) & (la[:, 0] < -tl[:, 0])] = 2
            c0[(st[:, 0] == 2) & (wa[:, 0] < -tw[:, 0])] = 1
            s1, l1, w1, n1 = st[:, 1:], la[:, 1:], wa[:, 1:], new[:, 1:]
            n1[(s1 == 1) & (l1 > ub[1:] + tl)] = 3
            n1[(s1 == 1) & (l1 < -ub[1:] - tl)] = 4
            n1[(s1 == 3) & (w1 > tw)] = 1
            n1[(s1 == 4) & (w1 < -tw)] = 1
            changed = np.any(new != st, axis=1)
            state[active] = new
            active = active[changed]
        qdd = qdd0 + np.einsum("nkr,nr->nk", MinvAsT, lam)
        a_obj = np.einsum("nrd,nr->nd", Ao, lam) / self.io
        norm_qdd = np.einsum("nk,nkl,nl->n", qdd, M, qdd)
        norm_a_obj = np.einsum("nd,d,nd->n", a_obj, self.io, a_obj)
        norm_lambda = np.einsum("nr,nrs,ns->n", lam, Gc, lam)
        contact = state[:, 0] == 1
        sr = np.where(contact, norm_a_obj / np.maximum(norm_a_obj + norm_qdd, 1e-300), 0.0)
        return dict(qdd=qdd, a_obj=a_obj, lam=lam, w=w, contact=contact, state=state,
                    norm_qdd=norm_qdd, norm_a_obj=norm_a_obj, norm_lambda=norm_lambda, sr=sr,
                    com=com)


# ------------------------------------------------------------------------------------------
def samples(rng, n):
    q = np.column_stack([rng.normal(size=(n, 2)), rng.uniform(-np.pi, np.pi, n),
                         rng.uniform(-2.35, 2.35, (n, JOINTS))])
    d = rng.normal(size=(n, JOINTS))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    tau = d * np.exp(rng.uniform(np.log(0.01), np.log(2.0), (n, 1)))
    return q, tau


def one_pass(sm, q, tau):
    """The generated functions alone: object placement and one ``constrained_dynamics`` pass
    with every row held (what the runtime costs without its active-set glue)."""
    n = len(q)
    q_obj, rho, _ = sm.backend("place_object", n, [
        q, sm.parameters, sm._contact_link, np.array([sm.scene.contact_offset]),
        np.array([sm.scene.object_distance]), sm._side])
    q_obj = np.ascontiguousarray(q_obj[:, :, 0])
    rho = np.ascontiguousarray(rho[:, :, 0])
    free = sm.present.astype(float)
    if n == 1:
        q, tau, q_obj, rho = q[0], tau[0], q_obj[0], rho[0]
    return sm.backend("constrained_dynamics", n, [
        q, np.zeros(sm.n_coordinates), tau, q_obj, np.zeros(3), np.zeros(3), sm.parameters,
        sm._contact_link, sm._side, sm._object_mass, sm._object_inertia, rho,
        sm._wheel_offset, free, np.zeros(sm.n_constraints), np.zeros(1)])


def best_of(fn, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def machine() -> str:
    cpu = cpu_name()
    return f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}, numpy {np.__version__}"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=100_000, help="batch size (pairs)")
    p.add_argument("--repeat", type=int, default=3, help="best of this many batched runs")
    p.add_argument("--single", type=int, default=2000, help="single calls timed")
    args = p.parse_args(argv)
    rng = np.random.default_rng(20170903)
    q, tau = samples(rng, args.n)
    print(f"# bench_interaction: n_a = {JOINTS}, N = {args.n}, best of {args.repeat}")
    print(f"# machine: {machine()}")
    rows = []
    for scenario in SCENARIOS:
        scene = snakecg.Scene(snakecg.Robot(joints=JOINTS), scenario=scenario)
        sm = snakecg.load(scene)
        ref = NumpyInteraction(scene)
        sm.forward(q[:16], tau[:16])  # warm up (load, first-call costs)
        t_rt, res = best_of(lambda: sm.forward(q, tau), args.repeat)
        t_np, out = best_of(lambda: ref(q, tau), max(1, args.repeat - 1))
        # agreement of the numpy program with the runtime
        dev = max(
            float(np.abs(out[k] - getattr(res, k)).max() / max(1.0, np.abs(getattr(res, k)).max()))
            for k in ("qdd", "a_obj", "lam", "norm_qdd", "norm_a_obj", "norm_lambda", "sr"))
        assert np.array_equal(out["contact"], res.contact), "numpy and runtime disagree on contact"
        # the generated C alone: placement + one all-held constrained_dynamics pass
        t_c, _ = best_of(lambda: one_pass(sm, q, tau), args.repeat)
        one = (q[:1], tau[:1])
        t_c1 = min(best_of(lambda: one_pass(sm, *one), 1)[0] for _ in range(200))
        # single calls
        lat = []
        m = min(args.single, args.n)
        for i in range(m):
            t0 = time.perf_counter()
            sm.forward(q[i], tau[i])
            lat.append(time.perf_counter() - t0)
        lat_sorted = sorted(lat)
        rows.append(dict(
            scenario=scenario,
            batched=t_rt / args.n * 1e6,
            numpy=t_np / args.n * 1e6,
            ratio=t_np / t_rt,
            single_med=statistics.median(lat) * 1e6,
            single_p90=lat_sorted[int(0.9 * (m - 1))] * 1e6,
            c_pass=t_c / args.n * 1e6,
            c_single=t_c1 * 1e6,
            lost=100 * (1 - res.contact.mean()),
            sliding=100 * np.mean(np.any(res.sliding, axis=1)),
            dev=dev,
            backend=sm.backend.kind,
        ))
    head = ("scenario", "batched us/pair", "C one pass us/pair", "numpy us/pair",
            "numpy/runtime", "single median us", "single p90 us", "C one pass single us",
            "lost %", "sliding %", "max rel dev")
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        print(f"| {r['scenario']} | {r['batched']:.2f} | {r['c_pass']:.2f} | {r['numpy']:.2f} | "
              f"{r['ratio']:.1f}x | {r['single_med']:.1f} | {r['single_p90']:.1f} | "
              f"{r['c_single']:.1f} | {r['lost']:.0f} | {r['sliding']:.0f} | {r['dev']:.1e} |")
    print(f"# backend: {rows[0]['backend']}; targets: batched < 2 us/pair (ideal_wheels), "
          f"single < 50 us")
    ok = rows[0]["batched"] < 2.0 and all(r["single_med"] < 50.0 for r in rows)
    print(f"# targets {'met' if ok else 'MISSED'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
