"""Benchmark: the cost of the `feasible` flag a sweep stores for every configuration.

    python benchmarks/bench_feasible.py [--quick] [--repeat R] [--json FILE]

Per scenario and joint count, on one chunk's worth of seeded samples (8192 configurations;
64 with bounded wheels), in one process with one C thread, side by side in one run:

* anchor: what a sweep computed per configuration before the flag, `model.extremes(q)` with
  its defaults and `model.com_polar(q)`;
* `snakecg.geometry.feasibility(model, q)` as the sweep now computes it;
* the same with the previous vector formulation of the point-to-segment distance and of the
  plate penetration (`einsum`, `linalg.norm`, stacked 2-vectors; kept below), which gives
  bit-identical results, to show what the component-wise form saves.

The median of `--repeat` runs (default 5) of each, interleaved, with the load average.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import time
from contextlib import contextmanager

os.environ.setdefault("SNAKECG_THREADS", "1")  # one C thread per process

import numpy as np  # noqa: E402

import snakecg  # noqa: E402
from snakecg import geometry  # noqa: E402
from snakecg.sweeps.plan import samples_plan  # noqa: E402


def _psd_vector(p, a, b):
    p, a, b = (np.asarray(x, float) for x in (p, a, b))
    d = b - a
    dd = np.einsum("...k,...k->...", d, d)
    t = np.einsum("...k,...k->...", p - a, d) / np.where(dd > 0, dd, 1.0)
    t = np.clip(np.where(dd > 0, t, 0.0), 0.0, 1.0)
    return np.linalg.norm(p - (a + t[..., None] * d), axis=-1)


def _penetration_vector(a, b, q_obj, side=geometry.OBJECT_SIDE):
    a, b, q_obj = (np.asarray(x, float) for x in (a, b, q_obj))
    c, psi = q_obj[..., :2], q_obj[..., 2]
    cs, sn = np.cos(psi), np.sin(psi)

    def local(p):
        d = p - c
        return np.stack([cs * d[..., 0] + sn * d[..., 1], -sn * d[..., 0] + cs * d[..., 1]], -1)

    la, lb = local(a), local(b)
    h = side / 2
    ts = [np.zeros(la.shape[:-1]), np.ones(la.shape[:-1])]
    d = lb - la
    with np.errstate(divide="ignore", invalid="ignore"):
        for k in (0, 1):
            ts.append(-la[..., k] / d[..., k])
        for s in (1.0, -1.0):
            ts.append(-(la[..., 0] - s * la[..., 1]) / (d[..., 0] - s * d[..., 1]))
    best = np.zeros(la.shape[:-1])
    for t in ts:
        t = np.clip(np.nan_to_num(t, nan=0.0, posinf=0.0, neginf=0.0), 0.0, 1.0)
        best = np.maximum(best, h - np.max(np.abs(la + t[..., None] * d), axis=-1))
    return best


@contextmanager
def vector_formulation():
    saved = geometry.point_segment_distance, geometry.object_penetration
    geometry.point_segment_distance, geometry.object_penetration = (_psd_vector,
                                                                    _penetration_vector)
    try:
        yield
    finally:
        geometry.point_segment_distance, geometry.object_penetration = saved


def _time(fn) -> float:
    t = time.perf_counter()
    fn()
    return time.perf_counter() - t


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="3 and 4 joints only")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--json", metavar="FILE")
    args = ap.parse_args()
    rows = []
    load0 = os.getloadavg()[0]
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"load {load0:.2f}")
    print(f"{'joints':>6} {'scenario':>13} {'configs':>7} {'extremes+com':>13} "
          f"{'feasibility':>12} {'ratio':>7} {'vector form':>12} {'speed-up':>9} "
          f"{'same flags':>10}")
    for joints in (3, 4) if args.quick else (3, 4, 6):
        for sc in snakecg.SCENARIOS:
            model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=joints), scenario=sc))
            n = 64 if sc == "wheels" else 8192
            q = samples_plan(joints, n, 1, sc, chunk=n).configurations(0)
            model.extremes(q[:8]), geometry.feasibility(model, q[:8])  # warm
            anchor, feas, vec = [], [], []
            for _ in range(args.repeat):
                anchor.append(_time(lambda: (model.extremes(q), model.com_polar(q))))
                feas.append(_time(lambda: geometry.feasibility(model, q)))
                with vector_formulation():
                    vec.append(_time(lambda: geometry.feasibility(model, q)))
            now = geometry.feasibility(model, q)
            with vector_formulation():
                before = geometry.feasibility(model, q)
            same = all(np.array_equal(getattr(now, f), getattr(before, f))
                       for f in ("self_distance", "penetration"))
            a, f, v = (float(np.median(x)) for x in (anchor, feas, vec))
            rows.append({"joints": joints, "scenario": sc, "configurations": n,
                         "extremes_com_s": a, "feasibility_s": f, "ratio": f / a,
                         "vector_form_s": v, "speedup": v / f, "bit_identical": same})
            print(f"{joints:>6} {sc:>13} {n:>7} {a:>12.4f}s {f:>11.4f}s {f / a:>6.1%} "
                  f"{v:>11.4f}s {v / f:>8.2f}x {str(same):>10}")
    load1 = os.getloadavg()[0]
    print(f"load {load0:.2f} -> {load1:.2f}")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump({"load": [load0, load1], "rows": rows}, fh, indent=1)


if __name__ == "__main__":
    main()
