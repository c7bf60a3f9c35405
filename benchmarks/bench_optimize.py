"""Benchmark of the optimal torque queries: ``SceneModel.optimize``.

Warm query latency (one configuration per call, the whole public call: validation, maps,
solve, forward check), at random configurations, for every kind of query, at n_a = 3 and 6 in
the ``wheels`` scenario (the one with friction bounds, the hardest); then a sweep over the 784
configurations of the paper's case study 1 (n_a = 2, joints on -135..135 deg every 10 deg) in
one batched call per kind.

Push tasks are feasible by construction: the direction is the contact normal, and
``least_slip_push`` asks for half of the strongest push the limits allow (computed before
timing). Wall-clock and process CPU time are both reported: on a shared machine the wall
clock includes time the process waited for a core.

First, side by side in one run (n_a = 3, ``wheels``, warm, one configuration per call,
calls interleaved so that both see the same load), each public query against the direct solve
of the same problem on ``SceneModel.maps`` from Python (the anchor, maps call included):

* ``max_sr`` (ellipsoid) against ``scipy.linalg.eigh`` of ``(Omega, Omega + Xi)``;
* ``least_slip_push`` (box) against one qpOASES QP (``casadi.conic``, built once, hot-started
  as CasADi does by default) on the maps' rows;
* ``strongest_push`` (box) against HiGHS (``scipy.optimize.linprog``) on the maps' rows.

Targets of that comparison (medians): max_sr <= 0.1 ms, least_slip_push <= 0.25 ms,
strongest_push <= 0.3 ms, each faster than its anchor. Then the latency of every kind at
n_a = 3 and 6 (targets: under 1 ms for the QP kinds, under 20 ms for max-sr with sliding
wheels), and a sweep over the 784 configurations of case study 1 (under 2 s).

    python benchmarks/bench_optimize.py [--n 200] [--joints 3 6] [--anchors-only]
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
QP_KINDS = ("least-slip-push, box", "strongest-push, box")
NLP_KIND = "max-sr, sliding allowed, ellipsoid"


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
        t0, c0 = time.perf_counter(), time.process_time()
        res = sm.optimize(q, objective, **kw)
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
        status[res.status] = status.get(res.status, 0) + 1
    ws = sorted(wall)
    return dict(median=statistics.median(wall) * 1e3, p90=ws[int(0.9 * (len(ws) - 1))] * 1e3,
                cpu=statistics.median(cpu) * 1e3, status=status)


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

    return max_sr, least_slip, strongest


def anchors(n: int) -> dict:
    """Median wall-clock time (ms) of each query and its anchor, interleaved call by call."""
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels"))
    rng = np.random.default_rng(20171102)
    Q = random_q(rng, 3, n)
    a_max_sr, a_least, a_strong = _anchor_solvers(sm)
    tau_max = 0.3
    pushes = []
    for q in Q:  # the contact normal and half of the strongest push (not timed)
        st = sm.optimize(q, "strongest_push", tau_max=tau_max)
        d = st.analysis.a_obj[:2] / np.linalg.norm(st.analysis.a_obj[:2])
        pushes.append((d, 0.5 * float(d @ st.analysis.a_obj[:2])))
    pairs = {
        "max_sr (ellipsoid) | scipy eigh on maps":
            (lambda k: sm.optimize(Q[k], "max_sr"), lambda k: a_max_sr(Q[k])),
        "least_slip_push (box) | qpOASES on maps":
            (lambda k: sm.optimize(Q[k], "least_slip_push", direction=pushes[k][0],
                                   a_min=pushes[k][1], tau_max=tau_max),
             lambda k: a_least(Q[k], pushes[k][0], pushes[k][1], tau_max)),
        "strongest_push (box) | HiGHS on maps":
            (lambda k: sm.optimize(Q[k], "strongest_push", tau_max=tau_max),
             lambda k: a_strong(Q[k], tau_max)),
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


TARGETS = {"max_sr": 0.1, "least_slip_push": 0.25, "strongest_push": 0.3}


def print_anchors(n: int) -> None:
    print(f"# side by side: n_a = 3, wheels, {n} random configurations, interleaved")
    print(f"# machine: {machine()}")
    print("| query | anchor | query ms (CPU) | anchor ms (CPU) | ratio (CPU) | target ms | "
          "certified |")
    print("|---|---|---|---|---|---|---|")
    for name, (ours, theirs, c_ours, c_theirs, ok) in anchors(n).items():
        query, anchor = name.split(" | ")
        target = TARGETS[query.split()[0]]
        verdict = "met" if ours <= target and ours < theirs else "MISSED"
        print(f"| {query} | {anchor} | {ours:.3f} ({c_ours:.3f}) | {theirs:.3f} "
              f"({c_theirs:.3f}) | {ours / theirs:.2f} ({c_ours / c_theirs:.2f}) | "
              f"{target} ({verdict}) | {ok}/{n} |", flush=True)
    print(f"# machine at the end: {machine()}")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=200, help="configurations per kind and joint count")
    p.add_argument("--joints", type=int, nargs="+", default=[3, 6])
    p.add_argument("--scenario", default="wheels", choices=snakecg.SCENARIOS)
    p.add_argument("--anchors-only", action="store_true",
                   help="only the side-by-side comparison with the direct solves on maps")
    args = p.parse_args(argv)
    print_anchors(args.n)
    if args.anchors_only:
        return 0
    rng = np.random.default_rng(20171102)
    print(f"# bench_optimize: scenario {args.scenario}, {args.n} random configurations per "
          f"kind, warm queries")
    print(f"# machine: {machine()}")
    head = ("n_a", "query", "median ms", "p90 ms", "median CPU ms", "statuses")
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    results = {}
    for na in args.joints:
        sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=na), scenario=args.scenario))
        Q = random_q(rng, na, args.n)
        for name, kw in KINDS.items():
            n = args.n if "sliding" not in name or na <= 3 else max(20, args.n // 5)
            kws = tasks(sm, Q[:n], kw)
            latency(sm, Q[:3], kws[:3])  # warm up: solvers built, caches filled
            r = latency(sm, Q[:n], kws)
            results[(na, name)] = r
            st = ", ".join(f"{k} {v}" for k, v in sorted(r["status"].items()))
            print(f"| {na} | {name} | {r['median']:.3f} | {r['p90']:.3f} | {r['cpu']:.3f} | "
                  f"{st} |", flush=True)
    # sweep over the paper's case study 1 grid
    sm2 = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario=args.scenario))
    grid = joint_grid(2)
    print(f"\n# sweep: {len(grid)} configurations of case study 1 (n_a = 2), one batched call")
    print("| query | wall s | CPU s | statuses |")
    print("|---|---|---|---|")
    sweeps = {}
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
        sweeps[name] = wall
        st = ", ".join(f"{k} {int(np.sum(res.status == k))}" for k in sorted(set(res.status)))
        print(f"| {name} | {wall:.3f} | {cpu:.3f} | {st} |", flush=True)
    print(f"# machine at the end: {machine()}")
    if 3 in args.joints:
        ok_qp = all(results[(3, k)]["median"] < 1.0 for k in QP_KINDS)
        ok_nlp = results[(3, NLP_KIND)]["median"] < 20.0
        ok_sweep = all(v < 2.0 for v in sweeps.values())
        print(f"# targets (n_a = 3, medians): QP kinds < 1 ms {'met' if ok_qp else 'MISSED'}; "
              f"max-sr with sliding < 20 ms {'met' if ok_nlp else 'MISSED'}; "
              f"784-configuration sweeps < 2 s {'met' if ok_sweep else 'MISSED'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
