"""Benchmark: the whole `snakecg reproduce`, warm (models already compiled).

    python benchmarks/bench_reproduce.py [--repeat 3] [--json FILE]

Runs, side by side in one session and alternating, (a) the command as a user types it,
`snakecg reproduce --out DIR`, in a new process, and (b) the same run with the figures drawn
in the calling process (`ReproduceOptions(jobs=1)`) instead of in two worker processes. Each
run goes to a fresh folder. Prints per run the wall time of the process, the phases that
`summary.json` records (model loading, case study 1, case study 2, figures) and the CPU time
spent drawing, the CPU time of the whole run (the process and its workers: on an idle
2-core machine the wall time lies between half of it and all of it); and the load average before and after each run, since on a shared machine the
wall time depends on it. A first untimed run compiles the models if needed.

Target: warm `snakecg reproduce` in at most 20 s on an idle 2-core machine.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

INLINE = ("import sys; from pathlib import Path; "
          "from snakecg.reproduce import ReproduceOptions, reproduce; "
          "reproduce(ReproduceOptions(out=Path(sys.argv[1]), jobs=1, progress=False), "
          "echo=lambda *a: None)")


def run(kind: str, out: Path) -> dict:
    if kind == "cli":
        cmd = [sys.executable, "-m", "snakecg.cli", "reproduce", "--out", str(out)]
    else:
        cmd = [sys.executable, "-c", INLINE, str(out)]
    env = {**os.environ, "SNAKECG_PROGRESS": "0"}
    load0 = os.getloadavg()[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    # the process and its drawing workers (waited for by it, so counted here)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed:\n{proc.stderr[-3000:]}")
    timings = json.loads((out / "summary.json").read_text())["timings_s"]
    return {"kind": kind, "wall_s": wall, "cpu_s": cpu, "load_before": load0, "load_after": os.getloadavg()[0],
            **{k: timings.get(k) for k in ("models", "case_study_1", "case_study_2", "figures",
                                           "figures_drawing_cpu")}}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3, help="runs of each kind (default 3)")
    ap.add_argument("--json", metavar="FILE", help="also write the figures as JSON")
    args = ap.parse_args()
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}")
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench-reproduce-") as tmp:
        root = Path(tmp)
        run("cli", root / "warm-up")  # compiles the models on a fresh cache
        for k in range(args.repeat):
            for kind in ("cli", "inline"):
                r = run(kind, root / f"{kind}-{k}")
                rows.append(r)
                print(f"{kind:>6}: {r['wall_s']:6.1f} s wall, {r['cpu_s']:5.1f} s CPU (models {r['models']:.1f}, case 1 "
                      f"{r['case_study_1']:.1f}, case 2 {r['case_study_2']:.1f}, figures "
                      f"{r['figures']:.1f} in the main process, drawing "
                      f"{r['figures_drawing_cpu']:.1f} s CPU), load "
                      f"{r['load_before']:.1f} -> {r['load_after']:.1f}")
    for kind in ("cli", "inline"):
        walls = sorted(r["wall_s"] for r in rows if r["kind"] == kind)
        print(f"{kind:>6}: best {walls[0]:.1f} s, median {walls[len(walls) // 2]:.1f} s")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=2) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
