"""Benchmark of the optimal shape queries: ``SceneModel.optimize_shape``.

One query is the whole public call with 8 starts: validation, the coarse grid scored by the
exact inner optimum (batched maps), up to 8 IPOPT runs (each first without the geometric
constraints, then with them where they are violated), the exact torque and forward check at
the answer. The first query of a kind also builds the NLP (CasADi's symbolic composition of
the generated functions and their derivatives): reported separately ("cold"); "warm" is the
median of the repeats. Wall clock and process CPU time are both given (on a shared machine
the wall clock includes waiting for a core; CPU time stands for one idle core).

The anchor, measured in the same run: the paper's method at n_a = 3, the exact extremes over
the 21,952 shapes of its joint grid (``model.extremes(joint_grid(3))``).

Targets: <= 1 s per query at n_a = 3 and <= 10 s at n_a = 8, 8 starts, one idle core.

    python benchmarks/bench_shape.py [--joints 3 8] [--repeat 3]
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time

import snakecg
from snakecg.analysis import joint_grid

from _machine import cpu_name  # benchmarks/_machine.py

KINDS = [
    ("max-sr", "frictionless", dict(objective="max_sr")),
    ("max-sr", "wheels", dict(objective="max_sr")),
    ("max-sr", "ideal_wheels", dict(objective="max_sr")),
    ("max-a-obj", "wheels", dict(objective="max_a_obj")),
    ("strongest-push, tau_max 0.3", "wheels", dict(objective="strongest_push", tau_max=0.3)),
    ("least-slip-push, a_y >= 0.005", "wheels",
     dict(objective="least_slip_push", direction=(0, 1), a_min=0.005)),
]


def machine() -> str:
    cpu = cpu_name()
    return f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}"


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg()) if hasattr(os, "getloadavg") else "?"


def timed(fn):
    w, c = time.perf_counter(), time.process_time()
    out = fn()
    return out, time.perf_counter() - w, time.process_time() - c


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--joints", type=int, nargs="+", default=[3, 8])
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args(argv)
    print(f"machine: {machine()}; load average at start {load()}")
    models = {}
    for na in args.joints:
        print(f"\nn_a = {na}: | query | scenario | status | value | cold s (CPU) "
              f"| warm median s (CPU) | load |")
        for label, scenario, kw in KINDS:
            key = (na, scenario)
            if key not in models:
                models[key] = snakecg.load(snakecg.Scene(snakecg.Robot(joints=na),
                                                         scenario=scenario, kappa=100.0))
            m = models[key]
            kw = dict(kw)
            objective = kw.pop("objective")
            res, w0, c0 = timed(lambda: m.optimize_shape(objective, **kw))
            walls, cpus = [], []
            for _ in range(args.repeat):
                res, w, c = timed(lambda: m.optimize_shape(objective, **kw))
                walls.append(w)
                cpus.append(c)
            print(f"| {label} | {scenario} | {res.status} | {res.value:.9g} | {w0:.2f} "
                  f"({c0:.2f}) | {statistics.median(walls):.2f} "
                  f"({statistics.median(cpus):.2f}) | {load()} |")
    if 3 in args.joints:
        m = models[(3, "ideal_wheels")]
        Q = joint_grid(3)
        _, w, c = timed(lambda: m.extremes(Q))
        print(f"\nanchor: extremes over the paper's {len(Q)}-shape grid (n_a = 3, "
              f"ideal_wheels): {w:.2f} s ({c:.2f} CPU); load {load()}")


if __name__ == "__main__":
    main()
