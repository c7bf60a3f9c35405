"""Benchmark of the optimal torque queries: ``SceneModel.optimize``.

1. Side by side in one run (n_a = 3, ``wheels``, warm, one configuration per call, each query
   and its anchor alternated configuration by configuration so that both see the same load):
   the whole public call (validation, maps, solve, certificate, forward check) against the
   direct solve of the same problem on ``SceneModel.maps`` from Python, maps call included:

   * ``max_sr`` (ellipsoid) against ``scipy.linalg.eigh`` of ``(Omega, Omega + Xi)``;
   * ``least_slip_push`` (box) against one qpOASES QP (``casadi.conic``, built once);
   * ``least_slip_push`` (ellipsoid) against Clarabel (its own Python API, a small SOCP);
   * ``strongest_push`` (box) against HiGHS (``scipy.optimize.linprog``);
   * ``strongest_push`` (ellipsoid) against Clarabel.

   Targets (medians): every query <= 0.1 ms.
2. Batches: 1,000 random configurations in one call per kind (n_a = 3, ``wheels``), with the
   default threads and with one (``SNAKECG_THREADS=1``), alternated over ``--runs`` runs.
   Target: <= 30 us per query.
3. Every kind at n_a = 3 and 6 (latency), and a sweep over the 784 configurations of the
   paper's case study 1 (n_a = 2) in one batched call per kind.

Push tasks are feasible by construction: the direction is the contact normal, and
``least_slip_push`` asks for half of the strongest push the same limits allow (computed
before timing). Wall-clock and thread CPU time are both reported: on a shared machine the
wall clock includes time the process waited for a core.

    python benchmarks/bench_optimize.py [--n 200] [--joints 3 6] [--runs 5]
                                        [--anchors-only | --batch-only | --kinds-only]
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time

import numpy as np

import snakecg
from snakecg.analysis import joint_grid

from _machine import cpu_name  # benchmarks/_machine.py

KINDS = {
    "max-sr, ellipsoid": dict(objective="max_sr"),
    "max-sr, box": dict(objective="max_sr", tau_max=0.2),
    "max-sr, sliding allowed, ellipsoid": dict(objective="max_sr", allow_slide=True),
    "max-sr, sliding allowed, box": dict(objective="max_sr", allow_slide=True, tau_max=0.2),
    "least-slip-push, box": dict(objective="least_slip_push", tau_max=0.3),
    "least-slip-push, ellipsoid": dict(objective="least_slip_push"),
    "strongest-push, box": dict(objective="strongest_push", tau_max=0.3),
    "strongest-push, ellipsoid": dict(objective="strongest_push"),
}
#: The batched kinds (section 2).
BATCH_KINDS = ("max-sr, ellipsoid", "least-slip-push, box", "least-slip-push, ellipsoid",
               "strongest-push, box", "strongest-push, ellipsoid")
TARGET_MS = 0.1
TARGET_BATCH_US = 30.0


def machine() -> str:
    cpu = cpu_name()
    load = os.getloadavg() if hasattr(os, "getloadavg") else ("?",)
    return (f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}, "
            f"load average {' '.join(f'{x:.2f}' for x in load)}")


def random_q(rng, na, n):
    return np.column_stack([rng.normal(size=(n, 2)), rng.uniform(-np.pi, np.pi, n),
                            rng.uniform(-2.35, 2.35, (n, na))])


def tasks(sm, Q, kw):
    """Per-configuration keyword arguments: the contact normal as direction and, for
    least-slip-push, half of the strongest push the same limits allow."""
    out = []
    limits = {k: v for k, v in kw.items() if k in ("tau_max", "radius")}
    for q in Q:
        if kw["objective"] == "max_sr":
            out.append(dict(kw))
            continue
        strong = sm.optimize(q, "strongest_push", **limits)
        d = strong.analysis.a_obj[:2] / np.linalg.norm(strong.analysis.a_obj[:2])
        k = dict(kw, direction=d)
        if kw["objective"] == "least_slip_push":
            k["a_min"] = 0.5 * strong.objective_value
        out.append(k)
    return out


def latency(sm, Q, kwargs):
    wall, cpu, status = [], [], {}
    for q, kw in zip(Q, kwargs):
        kw = dict(kw)
        objective = kw.pop("objective")
        t0, c0 = time.perf_counter(), time.thread_time()
        res = sm.optimize(q, objective, **kw)
        wall.append(time.perf_counter() - t0)
        cpu.append(time.thread_time() - c0)
        status[res.status] = status.get(res.status, 0) + 1
    ws = sorted(wall)
    return dict(median=statistics.median(wall) * 1e3, p90=ws[int(0.9 * (len(ws) - 1))] * 1e3,
                cpu=statistics.median(cpu) * 1e3, status=status)


# ------------------------------------------------------------------------------------------
# 1. side by side with the direct solves on the maps
# ------------------------------------------------------------------------------------------
def _anchor_solvers(sm):
    """The direct solves on ``maps`` (built once)."""
    import contextlib
    import io

    import casadi as ca
    from scipy.linalg import eigh
    from scipy.optimize import linprog

    n = sm.n_joints
    wheels = [i for i in range(1, sm.n_constraints)
              if sm.present[i] and np.isfinite(sm.bounds[i])]
    R = 1 + len(wheels)
    with contextlib.redirect_stdout(io.StringIO()):
        qp = ca.conic("anchor_qp", "qpoases", {"h": ca.Sparsity.dense(n, n),
                                               "a": ca.Sparsity.dense(R, n)},
                      {"printLevel": "none", "error_on_fail": False})
    u = np.array([sm.bounds[i] for i in wheels])

    def max_sr(q):
        mp = sm.maps(q)
        om = mp["omega_tau"]
        w, v = eigh(om, om + mp["xi_tau"])
        t = v[:, -1] * np.sign(mp["lam_from_tau"][0] @ v[:, -1])
        return w[-1], t / np.sqrt(t @ mp["input_metric"] @ t)

    def least_slip(q, d, a_min, tau_max):
        mp = sm.maps(q)
        L = mp["lam_from_tau"]
        A = np.vstack([np.append(d, 0.0) @ mp["a_obj_from_tau"], L[wheels]])
        lba = np.concatenate([[a_min], -u])
        uba = np.concatenate([[np.inf], u])
        r = qp(h=2 * mp["xi_tau"], g=np.zeros(n), a=A, lba=lba, uba=uba,
               lbx=-tau_max * np.ones(n), ubx=tau_max * np.ones(n))
        return np.array(r["x"]).ravel()

    def strongest(q, tau_max):
        mp = sm.maps(q)
        L = mp["lam_from_tau"]
        A = np.vstack([L[wheels], -L[wheels]])
        r = linprog(-L[0], A_ub=A, b_ub=np.concatenate([u, u]),
                    bounds=[(-tau_max, tau_max)] * n, method="highs")
        return r.x

    def clarabel_socp(q, d=None, a_min=None):
        """The ellipsoid's problem as a small SOCP for Clarabel: the least slip (with d,
        a_min) or the strongest push along the normal."""
        import clarabel
        import scipy.sparse as sp

        mp = sm.maps(q)
        L, N = mp["lam_from_tau"], mp["input_metric"]
        C = np.linalg.cholesky(N)  # tau^T N tau = |C^T tau|^2 <= 1
        rows = [-L[0]] + [L[i] for i in wheels] + [-L[i] for i in wheels]
        b = [0.0] + list(u) + list(u)
        if d is not None:
            rows[0] = -(np.append(d, 0.0) @ mp["a_obj_from_tau"])
            b[0] = -a_min
        A = np.vstack(rows + [np.zeros(n), -C.T])
        b = np.concatenate([b, [1.0], np.zeros(n)])
        cones = [clarabel.NonnegativeConeT(len(rows)), clarabel.SecondOrderConeT(n + 1)]
        settings = clarabel.DefaultSettings()
        settings.verbose = False
        if d is None:
            P, c = sp.csc_matrix((n, n)), -L[0]
        else:
            P, c = sp.csc_matrix(2 * np.triu(mp["xi_tau"])), np.zeros(n)
        return clarabel.DefaultSolver(P, c, sp.csc_matrix(A), b, cones, settings).solve()

    return max_sr, least_slip, strongest, clarabel_socp


def anchors(n: int) -> dict:
    """Median wall-clock and thread CPU time (ms) of each query and its anchor, alternated
    configuration by configuration; the count of certified answers."""
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels"))
    rng = np.random.default_rng(20171102)
    Q = random_q(rng, 3, n)
    a_max_sr, a_least, a_strong, a_socp = _anchor_solvers(sm)
    tau_max = 0.3
    box, ell = [], []
    for q in Q:  # the contact normal and half of the strongest push (not timed)
        for lim, out in ((dict(tau_max=tau_max), box), ({}, ell)):
            st = sm.optimize(q, "strongest_push", **lim)
            d = st.analysis.a_obj[:2] / np.linalg.norm(st.analysis.a_obj[:2])
            out.append((d, 0.5 * float(d @ st.analysis.a_obj[:2])))
    pairs = {
        "max_sr (ellipsoid) | scipy eigh on maps":
            (lambda k: sm.optimize(Q[k], "max_sr"), lambda k: a_max_sr(Q[k])),
        "least_slip_push (box) | qpOASES on maps":
            (lambda k: sm.optimize(Q[k], "least_slip_push", direction=box[k][0],
                                   a_min=box[k][1], tau_max=tau_max),
             lambda k: a_least(Q[k], box[k][0], box[k][1], tau_max)),
        "least_slip_push (ellipsoid) | Clarabel on maps":
            (lambda k: sm.optimize(Q[k], "least_slip_push", direction=ell[k][0],
                                   a_min=ell[k][1]),
             lambda k: a_socp(Q[k], ell[k][0], ell[k][1])),
        "strongest_push (box) | HiGHS on maps":
            (lambda k: sm.optimize(Q[k], "strongest_push", tau_max=tau_max),
             lambda k: a_strong(Q[k], tau_max)),
        "strongest_push (ellipsoid) | Clarabel on maps":
            (lambda k: sm.optimize(Q[k], "strongest_push"), lambda k: a_socp(Q[k])),
    }
    out = {}
    for name, (ours, theirs) in pairs.items():
        for k in range(min(5, n)):  # warm up
            ours(k)
            theirs(k)
        t_ours, t_theirs, c_ours, c_theirs, ok = [], [], [], [], 0
        for k in range(n):
            t0, c0 = time.perf_counter(), time.thread_time()
            res = ours(k)
            t1, c1 = time.perf_counter(), time.thread_time()
            theirs(k)
            t2, c2 = time.perf_counter(), time.thread_time()
            t_ours.append(t1 - t0)
            t_theirs.append(t2 - t1)
            c_ours.append(c1 - c0)
            c_theirs.append(c2 - c1)
            ok += res.status == "optimal" and bool(res.certificate.ok)
        med = [statistics.median(v) * 1e3 for v in (t_ours, t_theirs, c_ours, c_theirs)]
        out[name] = (*med, ok)
    return out


def print_anchors(n: int) -> None:
    print(f"# side by side: n_a = 3, wheels, {n} random configurations, alternated")
    print(f"# machine: {machine()}")
    print("| query | anchor | query ms (CPU) | anchor ms (CPU) | ratio (CPU) | target ms | "
          "certified |")
    print("|---|---|---|---|---|---|---|")
    for name, (ours, theirs, c_ours, c_theirs, ok) in anchors(n).items():
        query, anchor = name.split(" | ")
        verdict = "met" if ours <= TARGET_MS else "MISSED"
        print(f"| {query} | {anchor} | {ours:.4f} ({c_ours:.4f}) | {theirs:.4f} "
              f"({c_theirs:.4f}) | {ours / theirs:.2f} ({c_ours / c_theirs:.2f}) | "
              f"{TARGET_MS} ({verdict}) | {ok}/{n} |", flush=True)
    print(f"# machine at the end: {machine()}")


# ------------------------------------------------------------------------------------------
# 2. batches of 1,000 configurations
# ------------------------------------------------------------------------------------------
def batches(n: int, runs: int) -> None:
    """Section 2. The configurations have theta = 0 (random joints), so that the contact
    normal of the tail link is +y for all of them: the push tasks are the sweep's
    (``direction=(0, 1)``, ``a_min = 0.002``)."""
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels"))
    rng = np.random.default_rng(20171103)
    Q = random_q(rng, 3, n)
    Q[:, 2] = 0.0
    print(f"\n# batches: {n} configurations in one call, n_a = 3, wheels; us per query, "
          f"default threads ({os.cpu_count()} cores) and one thread (SNAKECG_THREADS=1), "
          f"alternated over {runs} runs")
    print(f"# machine: {machine()}")
    print("| query | default threads: median (runs) | one thread: median (runs) | "
          "statuses | target us |")
    print("|---|---|---|---|---|")
    given = os.environ.get("SNAKECG_THREADS")
    for name in BATCH_KINDS:
        kw = dict(KINDS[name])
        objective = kw.pop("objective")
        if objective == "least_slip_push":
            kw.update(direction=[0.0, 1.0], a_min=0.002)
        sm.optimize(Q[:10], objective, **kw)  # warm up
        times = {"default": [], "one": []}
        for _ in range(runs):
            for mode in ("default", "one"):
                if mode == "one":
                    os.environ["SNAKECG_THREADS"] = "1"
                elif given is None:
                    os.environ.pop("SNAKECG_THREADS", None)
                else:
                    os.environ["SNAKECG_THREADS"] = given
                t0 = time.perf_counter()
                res = sm.optimize(Q, objective, **kw)
                times[mode].append((time.perf_counter() - t0) / n * 1e6)
        if given is None:
            os.environ.pop("SNAKECG_THREADS", None)
        else:
            os.environ["SNAKECG_THREADS"] = given
        statuses = ", ".join(f"{s} {int(np.sum(res.status == s))}" for s in sorted(set(res.status)))
        med = {m: statistics.median(v) for m, v in times.items()}
        verdict = "met" if med["default"] <= TARGET_BATCH_US else "MISSED"
        runs_d = ", ".join(f"{t:.1f}" for t in times["default"])
        runs_1 = ", ".join(f"{t:.1f}" for t in times["one"])
        print(f"| {name} | {med['default']:.1f} ({runs_d}) | {med['one']:.1f} ({runs_1}) | "
              f"{statuses} | {TARGET_BATCH_US} ({verdict}) |", flush=True)
    print(f"# machine at the end: {machine()}")


# ------------------------------------------------------------------------------------------
# 3. every kind, and the case-study sweep
# ------------------------------------------------------------------------------------------
def every_kind(args) -> None:
    rng = np.random.default_rng(20171102)
    print(f"\n# bench_optimize: scenario {args.scenario}, {args.n} random configurations per "
          f"kind, warm queries")
    print(f"# machine: {machine()}")
    head = ("n_a", "query", "median ms", "p90 ms", "median CPU ms", "statuses")
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for na in args.joints:
        sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=na), scenario=args.scenario))
        Q = random_q(rng, na, args.n)
        for name, kw in KINDS.items():
            n = args.n if "sliding" not in name or na <= 3 else max(20, args.n // 5)
            kws = tasks(sm, Q[:n], kw)
            latency(sm, Q[:3], kws[:3])  # warm up
            r = latency(sm, Q[:n], kws)
            st = ", ".join(f"{k} {v}" for k, v in sorted(r["status"].items()))
            print(f"| {na} | {name} | {r['median']:.3f} | {r['p90']:.3f} | {r['cpu']:.3f} | "
                  f"{st} |", flush=True)
    sm2 = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario=args.scenario))
    grid = joint_grid(2)
    print(f"\n# sweep: {len(grid)} configurations of case study 1 (n_a = 2), one batched call")
    print("| query | wall s | CPU s | statuses |")
    print("|---|---|---|---|")
    for name, kw in KINDS.items():
        kw = dict(kw)
        objective = kw.pop("objective")
        if objective != "max_sr":
            kw["direction"] = [0.0, 1.0]  # the contact normal at theta = 0, contact link 1
        if objective == "least_slip_push":
            kw["a_min"] = 0.002
        sm2.optimize(grid[:2], objective, **kw)  # warm up
        t0, c0 = time.perf_counter(), time.process_time()
        res = sm2.optimize(grid, objective, **kw)
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
        st = ", ".join(f"{k} {int(np.sum(res.status == k))}" for k in sorted(set(res.status)))
        print(f"| {name} | {wall:.3f} | {cpu:.3f} | {st} |", flush=True)
    print(f"# machine at the end: {machine()}")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=200, help="configurations per kind and joint count")
    p.add_argument("--joints", type=int, nargs="+", default=[3, 6])
    p.add_argument("--scenario", default="wheels", choices=snakecg.SCENARIOS)
    p.add_argument("--batch", type=int, default=1000, help="configurations per batched call")
    p.add_argument("--runs", type=int, default=5, help="alternated runs of the batches")
    p.add_argument("--anchors-only", action="store_true",
                   help="only the side-by-side comparison with the direct solves on maps")
    p.add_argument("--batch-only", action="store_true", help="only the batches")
    p.add_argument("--kinds-only", action="store_true",
                   help="only every kind at each joint count and the sweep")
    args = p.parse_args(argv)
    only = args.anchors_only or args.batch_only or args.kinds_only
    if args.anchors_only or not only:
        print_anchors(args.n)
    if args.batch_only or not only:
        batches(args.batch, args.runs)
    if args.kinds_only or not only:
        every_kind(args)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
