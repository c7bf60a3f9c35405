"""Benchmark: extremes over the input ellipsoid and `snakecg reproduce`.

    python benchmarks/bench_extremes.py [--repeat 7] [--reproduce]

Prints, per scenario, the time of `model.extremes` over the 784 configurations of case study 1
(2 joints) and the 21,952 of case study 2 (3 joints), the best of `--repeat` runs after a warm
call, both through the compiled closed form (`metric_extremes`) and numpy's eigensolver; with
`--reproduce`, the wall time of the whole `snakecg reproduce` after the models are built.
Targets: 784 configurations under 5 ms, 21,952 under 60 ms (exact scenarios).
"""

from __future__ import annotations

import argparse
import os
import platform
import tempfile
import time
from pathlib import Path

import numpy as np

import snakecg
from snakecg.analysis import _quadratic_extremes_numpy, joint_grid


def best_of(fn, repeat):
    fn()
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times), float(np.median(times))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--reproduce", action="store_true", help="also time snakecg reproduce")
    args = ap.parse_args()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, {platform.processor() or ''}"
          f" load average {os.getloadavg()[0]:.2f}; numpy {np.__version__}")
    print(f"{'joints':>6} {'configs':>8} {'scenario':>13} {'best ms':>9} {'median ms':>10} "
          f"{'numpy best ms':>14}")
    for joints in (2, 3):
        Q = joint_grid(joints)
        for scenario in snakecg.SCENARIOS:
            model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario))
            best, med = best_of(lambda: model.extremes(Q),
                                args.repeat if scenario != "wheels" else 1)
            if scenario != "wheels":
                nbest, _ = best_of(lambda: _quadratic_extremes_numpy(model, Q), args.repeat)
                numpy_col = f"{nbest * 1e3:14.1f}"
            else:
                numpy_col = f"{'-':>14}"
            print(f"{joints:>6} {len(Q):>8} {scenario:>13} {best * 1e3:9.1f} {med * 1e3:10.1f}"
                  f" {numpy_col}")
    if args.reproduce:
        from snakecg.reproduce import ReproduceOptions, reproduce

        with tempfile.TemporaryDirectory() as tmp:
            report = reproduce(ReproduceOptions(out=Path(tmp), progress=False),
                               echo=lambda *a: None)
        t = report.timings
        print(f"snakecg reproduce: case study 1 {t['case_study_1']:.1f} s, case study 2 "
              f"{t['case_study_2']:.1f} s, total after the models are built "
              f"{t['case_study_1'] + t['case_study_2']:.1f} s (models ready in {t['models']:.1f} s)")


if __name__ == "__main__":
    main()
