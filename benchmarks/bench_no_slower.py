"""This tree against another checkout of snakecg (the landed main), side by side, alternated.

Two worker processes, one importing snakecg from this tree and one from the checkout given
on the command line (``PYTHONPATH`` set to it, each with its own model cache), load the same
3-joint scene with bounded wheels and answer the same queries on the same inputs. The
controller asks them in turn, query by query, alternating which side goes first in every
round, and keeps each side's best time over the rounds. Queries:

* ``forward`` one sample (µs per call) and a batch of 1,000 (µs per sample);
* ``extremes`` one configuration (µs) and a batch of 200 (µs per configuration);
* ``simulate`` one run of 0.5 s (ms) and a batch of 8 runs of 0.2 s (ms per run);
* warm ``optimize`` ``least_slip_push`` and ``strongest_push`` with ``tau_max`` and with
  ``radius``, one configuration (µs) and a batch of 1,000 (µs per configuration);
* MuJoCo's ``mj_forward`` on the equivalent model of ``bench_core.py`` (µs, set ``qpos``,
  ``ctrl``, call, copy ``qacc``), in this tree's worker.

Usage: ``python benchmarks/bench_no_slower.py /path/to/main [--rounds 5]``.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
QUERIES = ("forward_1", "forward_1000", "extremes_1", "extremes_200", "simulate_1",
           "simulate_8", "lsp_tau_1", "lsp_radius_1", "sp_tau_1", "sp_radius_1",
           "lsp_tau_1000", "lsp_radius_1000", "sp_tau_1000", "sp_radius_1000")
UNITS = {"simulate_1": "ms", "simulate_8": "ms/run"}


def _best(fn, repeat: int, per: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best / per


def worker() -> None:
    """Answer queries on stdin, one JSON line each on stdout."""
    import numpy as np

    import snakecg
    from snakecg.simulate.batch import simulate_batch

    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels"),
                         progress=False)
    rng = np.random.default_rng(7)
    Q = np.column_stack([np.zeros((1000, 3)), rng.uniform(-2.0, 2.0, (1000, 3))])
    T = rng.normal(0, 0.3, (1000, 3))
    q, tau = Q[0].copy(), T[0].copy()
    d = np.array([1.0, 0.0])
    lsp = {"direction": d, "a_min": 1e-3}
    m = {}

    def forward_1():
        for i in range(2000):
            model.forward(q, tau)

    def opt(objective, n, **kw):
        if n == 1:
            def run():
                for i in range(200):
                    model.optimize(q, objective, **kw)
            return lambda: _best(run, 5, 200) * 1e6
        return lambda: _best(lambda: model.optimize(Q, objective, **kw), 3, 1000) * 1e6

    m["forward_1"] = lambda: _best(forward_1, 5, 2000) * 1e6
    m["forward_1000"] = lambda: _best(lambda: model.forward(Q, T), 5, 1000) * 1e6
    m["extremes_1"] = lambda: _best(lambda: model.extremes(q), 5, 1) * 1e6
    m["extremes_200"] = lambda: _best(lambda: model.extremes(Q[:200]), 3, 200) * 1e6
    m["simulate_1"] = lambda: _best(lambda: model.simulate(q, tau, 0.5), 3, 1) * 1e3
    m["simulate_8"] = lambda: _best(lambda: simulate_batch(model, Q[:8], T[:8], 0.2,
                                                           progress=False), 3, 8) * 1e3
    for n in (1, 1000):
        m[f"lsp_tau_{n}"] = opt("least_slip_push", n, tau_max=0.5, **lsp)
        m[f"lsp_radius_{n}"] = opt("least_slip_push", n, radius=1.0, **lsp)
        m[f"sp_tau_{n}"] = opt("strongest_push", n, tau_max=0.5)
        m[f"sp_radius_{n}"] = opt("strongest_push", n, radius=1.0)

    def mj():
        import mujoco

        sys.path.insert(0, str(HERE))
        from bench_core import MJCF

        mm = mujoco.MjModel.from_xml_string(MJCF)
        dd = mujoco.MjData(mm)
        qq = np.array([0.0, 0.0, 0.0, 0.3, -0.5, 0.4, 0.0, 0.0, 0.0])
        tt = np.array([0.05, 0.0, -0.02])

        def io():
            for _ in range(2000):
                dd.qpos[:] = qq
                dd.ctrl[:] = tt
                mujoco.mj_forward(mm, dd)
                dd.qacc.copy()

        return _best(io, 5, 2000) * 1e6

    m["mj_forward"] = mj
    for f in m.values():  # warm: every query once
        f()
    print(json.dumps({"ready": snakecg.__file__}), flush=True)
    for line in sys.stdin:
        name = line.strip()
        if not name:
            break
        print(json.dumps({name: m[name]()}), flush=True)


def _start(root: Path | None, cache: str):
    env = dict(os.environ, SNAKECG_CACHE_DIR=cache, SNAKECG_THREADS="1",
               SNAKECG_PROGRESS="0")
    if root is not None:
        env["PYTHONPATH"] = str(root)
    p = subprocess.Popen([sys.executable, __file__, "--worker"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, text=True, env=env)
    ready = json.loads(p.stdout.readline())["ready"]
    return p, ready


def _ask(p, name: str) -> float:
    p.stdin.write(name + "\n")
    p.stdin.flush()
    return json.loads(p.stdout.readline())[name]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("main", type=Path, help="the other checkout's root (its snakecg/ inside)")
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args(argv)
    tmp = tempfile.gettempdir()
    this_cache = os.environ.get("SNAKECG_CACHE_DIR", os.path.join(tmp, "snakecg-bench-this"))
    sides = {"main": _start(args.main.resolve(), os.path.join(tmp, "snakecg-bench-main")),
             "this": _start(None, this_cache)}
    for side, (_, path) in sides.items():
        print(f"{side}: {path}")
    if sides["main"][1] == sides["this"][1]:
        raise SystemExit("both workers import the same snakecg: give another checkout")
    best = {s: {} for s in sides}
    for r in range(args.rounds):
        order = ("main", "this") if r % 2 == 0 else ("this", "main")
        for name in QUERIES:
            for side in order:
                t = _ask(sides[side][0], name)
                best[side][name] = min(best[side].get(name, float("inf")), t)
    mj = min(_ask(sides["this"][0], "mj_forward") for _ in range(args.rounds))
    for p, _ in sides.values():
        p.stdin.write("\n")
        p.stdin.close()
        p.wait()
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"\n{args.rounds} alternated rounds, best of each; load average {load}\n")
    print("| query | unit | main | this | this / main |")
    print("|---|---|---:|---:|---:|")
    for name in QUERIES:
        a, b = best["main"][name], best["this"][name]
        unit = UNITS.get(name, "µs" if name.endswith("_1") else "µs/query")
        print(f"| {name} | {unit} | {a:.3f} | {b:.3f} | {b / a:.3f} |")
    print(f"| mj_forward (this run) | µs | | {mj:.3f} | |")
    return 0


if __name__ == "__main__":
    if "--worker" in sys.argv:
        worker()
    else:
        sys.exit(main())
