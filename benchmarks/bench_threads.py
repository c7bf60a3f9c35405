"""Benchmark of the thread rule (snakecg.engine.threads): threads never cost time.

* **default vs one thread**: batched ``model.mass_matrix(Q)`` at ``--joints`` (default 20)
  joints on ``--n`` configurations, with the default threads (``SNAKECG_THREADS`` unset) and
  with ``SNAKECG_THREADS=1``, alternated, in ``--runs`` runs in a row (best of ``--repeat``
  calls each): the default must never be slower than one thread.
* **where a split pays** (``SNAKECG_THREADS=2``): the same per configuration on 1 and 2
  threads for batch sizes from 1,024 to 65,536, the split forced at every size; the
  threshold ``PARALLEL_MIN`` (samples per thread) is where two threads start to pay on an
  idle machine. On a machine whose second core is busy they do not pay at any size, which is
  why one thread is the default.

    python benchmarks/bench_threads.py [--joints 20] [--n 20000] [--runs 5] [--repeat 5]

Prints tables and the machine's load average before and after.
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import numpy as np

from _machine import cpu_name  # benchmarks/_machine.py

import snakecg
from snakecg import native
from snakecg.engine import threads as threads_mod


def best_of(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def _with_threads(value: str | None, fn):
    saved = os.environ.get("SNAKECG_THREADS")
    if value is None:
        os.environ.pop("SNAKECG_THREADS", None)
    else:
        os.environ["SNAKECG_THREADS"] = value
    try:
        return fn()
    finally:
        if saved is None:
            os.environ.pop("SNAKECG_THREADS", None)
        else:
            os.environ["SNAKECG_THREADS"] = saved


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--joints", type=int, default=20)
    p.add_argument("--n", type=int, default=20000)
    p.add_argument("--runs", type=int, default=5)
    p.add_argument("--repeat", type=int, default=5)
    a = p.parse_args()
    load0 = os.getloadavg()
    print(f"machine: {cpu_name()}, {os.cpu_count()} cores, Python {platform.python_version()},"
          f" numpy {np.__version__}")
    print(f"load average before: {load0[0]:.2f} {load0[1]:.2f} {load0[2]:.2f}")
    model = snakecg.load(snakecg.Robot(joints=a.joints))
    rng = np.random.default_rng(0)
    Q = rng.uniform(-2.0, 2.0, (a.n, a.joints + 3))
    model.mass_matrix(Q)  # warm-up

    def per_config():
        return best_of(lambda: model.mass_matrix(Q), a.repeat) / a.n * 1e6

    print(f"\nbatched M, {a.joints} joints, {a.n} configurations (µs per configuration; "
          f"default threads: {threads_mod.asked_threads() if 'SNAKECG_THREADS' in os.environ else 1})")
    print("| run | default | one thread | default / one |")
    print("|---:|---:|---:|---:|")
    worst = 0.0
    for run in range(1, a.runs + 1):
        t_default = _with_threads(None, per_config)
        t_one = _with_threads("1", per_config)
        worst = max(worst, t_default / t_one)
        print(f"| {run} | {t_default:.3f} | {t_one:.3f} | {t_default / t_one:.3f} |")
    print(f"largest ratio default / one thread over {a.runs} runs: {worst:.3f}")

    print(f"\nwhere a split pays (SNAKECG_THREADS=2, split forced; the default threshold is "
          f"{threads_mod.PARALLEL_MIN} configurations per thread)")
    print("| batch | 1 thread µs/config | 2 threads µs/config | speed-up |")
    print("|---:|---:|---:|---:|")
    saved = native._PARALLEL_MIN
    native._PARALLEL_MIN = 1
    try:
        for n in (1024, 4096, 16384, 65536):
            Qn = rng.uniform(-2.0, 2.0, (n, a.joints + 3))
            rounds = max(1, 20000 // n)

            def timed(Qn=Qn, rounds=rounds):
                return best_of(lambda: [model.mass_matrix(Qn) for _ in range(rounds)],
                               a.repeat) / (rounds * len(Qn)) * 1e6
            t1 = _with_threads("1", timed)
            t2 = _with_threads("2", timed)
            print(f"| {n} | {t1:.3f} | {t2:.3f} | {t1 / t2:.2f} |")
    finally:
        native._PARALLEL_MIN = saved
    load1 = os.getloadavg()
    print(f"load average after: {load1[0]:.2f} {load1[1]:.2f} {load1[2]:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
