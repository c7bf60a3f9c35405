"""Benchmark: extremes over the input ellipsoid and `snakecg reproduce`.

    python benchmarks/bench_extremes.py [--repeat 7] [--reproduce] [--exact-wheels [N]]
                                        [--no-sampled]

Prints, per scenario, the time of `model.extremes` over the 784 configurations of case study 1
(2 joints) and the 21,952 of case study 2 (3 joints), the best of `--repeat` runs after a warm
call, both through the compiled closed form (`metric_extremes`) and numpy's eigensolver; with
`--reproduce`, the wall time of the whole `snakecg reproduce` after the models are built.
Targets: 784 configurations under 5 ms, 21,952 under 60 ms (exact scenarios).

With `--exact-wheels`, the exact bounded-wheel extremes (`snakecg.piecewise`) of case study 2
(3 joints, kappa = 100, mu = 0.1; the first N of the 21,952 configurations, default all) on one
core, wall and CPU time, side by side in the same run with the anchor: a vectorized NumPy
evaluation of the same grid (numpy's batched eigensolver extremes of the ideal-wheel scene),
and the sampled method it replaced (`exact=False`; skipped with `--no-sampled`). One thread
(`SNAKECG_THREADS=1`, `OMP_NUM_THREADS=1`, `OPENBLAS_NUM_THREADS=1` unless set). Target: all
21,952 in 10 s on an idle core.
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
    ap.add_argument("--exact-wheels", type=int, nargs="?", const=21952, default=None,
                    metavar="N", help="time the exact bounded-wheel extremes on N configurations")
    ap.add_argument("--no-sampled", action="store_true",
                    help="with --exact-wheels: do not time the sampled method (exact=False)")
    args = ap.parse_args()
    if args.exact_wheels is not None:
        exact_wheels(args.exact_wheels, sampled=not args.no_sampled)
        return
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


def exact_wheels(count: int, sampled: bool = True) -> None:
    """Exact bounded-wheel extremes of case study 2 beside the NumPy anchor (one run)."""
    # one thread: the package's forward solver (read per call) and, if not yet loaded, BLAS
    for var in ("SNAKECG_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS"):
        os.environ.setdefault(var, "1")
    Q = joint_grid(3)[:count]
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0, mu=0.1)
    wheels = snakecg.load(scene)
    ideal = snakecg.load(scene.replace(scenario="ideal_wheels"))
    wheels.extremes(Q[:8])
    _quadratic_extremes_numpy(ideal, Q[:8])

    def timed(fn):
        w, c = time.perf_counter(), time.process_time()
        out = fn()
        return out, time.perf_counter() - w, time.process_time() - c

    load0 = os.getloadavg()[0]
    _, aw, ac = timed(lambda: _quadratic_extremes_numpy(ideal, Q))
    ex, ew, ec = timed(lambda: wheels.extremes(Q))
    rows = [("anchor: NumPy eigensolver (ideal)", aw, ac), ("exact bounded wheels", ew, ec)]
    if sampled:
        _, sw, sc = timed(lambda: wheels.extremes(Q, exact=False))
        rows.append(("sampled bounded wheels (exact=False)", sw, sc))
    print(f"load average {load0:.2f} -> {os.getloadavg()[0]:.2f}; {len(Q)} configurations, "
          f"{ex.pieces} pieces ({ex.pieces / len(Q):.1f} per configuration), "
          f"certified {np.mean(ex.certified):.4f}")
    print(f"{'':36} {'wall s':>8} {'CPU s':>8} {'CPU / anchor':>13}")
    for name, w, c in rows:
        print(f"{name:36} {w:8.2f} {c:8.2f} {c / ac:13.1f}")


if __name__ == "__main__":
    main()
