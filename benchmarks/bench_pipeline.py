#!/usr/bin/env python
"""Benchmark of the derive -> generated -> snakecg pipeline; prints a table.

For each joint count ``n_a`` (default 2, 3, 6, 10, 20):

* **cold pipeline**: a new process with an empty ``SNAKECG_CACHE_DIR`` derives the model
  (SymPy), renders it (Jinja2 -> CasADi functions -> CasADi's C), writes it and compiles the
  C into the shared library. For the checked-in joint counts (<= 6) generation is forced with
  ``render_model``/``write_model`` into a temporary folder; above, it is the path ``load()``
  takes (``artifacts.model_dir``, which writes into the cache). Reported: SymPy derivation,
  render + build + emit C + write, C compilation, and the process's wall time (interpreter
  start and imports included);
* **M operation count**: CasADi operations of the generated ``mass_matrix`` (manifest) against
  the planar composite-rigid-body count ``3 n^2 + 20 n + 1`` with ``n = n_a + 1`` bodies;
* **cached load**: a new process runs ``import snakecg; snakecg.load(snakecg.Robot(joints=N))``
  with the cache filled by the cold run; ``load()`` alone (timed inside), import + load, and the
  process's wall time; best of three processes;
* **batched evaluation**: ``mass_matrix`` and ``link_jacobians`` on ``N`` random configurations
  in one call, time per configuration (best of several calls; public API, validation and
  output reshaping included);
* **Pinocchio**: ``pin.crba`` called from Python in a loop on the same snake (see
  tests/test_pinocchio.py), time per call, and its ratio to snakecg's batched ``M``.

Usage: ``python benchmarks/bench_pipeline.py [--quick] [--joints 2,3] [--json FILE]``.
The machine is shown with the results; numbers on a shared machine vary by tens of percent.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

from _machine import cpu_name  # benchmarks/_machine.py

JOINTS = (2, 3, 6, 10, 20)
CHECKED_IN_MAX = 6

TARGETS = {
    "cold_na10_s": 30.0,
    "cached_load_s": 0.3,
    "batched_M_na3_us": 0.5,
    "ops_ratio_na20": 1.5,
}

_COLD = r"""
import json, shutil, sys, tempfile, time
t0 = time.perf_counter()
from snakecg_derive.render import render_model, write_model
from snakecg import artifacts
from snakecg.native import compile_model
t_import = time.perf_counter() - t0
n, checked_in_max = int(sys.argv[1]), int(sys.argv[2])
marks = {}
def progress(msg):
    marks.setdefault(msg.split()[0], time.perf_counter())
t1 = time.perf_counter()
if n <= checked_in_max:
    # forced generation: the packaged model would otherwise be used
    rendered = render_model(n, progress=progress)
    scratch = tempfile.mkdtemp(prefix="bench-model-")
    folder = write_model(rendered, scratch)
    manifest = artifacts.verify_model_dir(folder, n)
else:
    folder, manifest = artifacts.model_dir(n, progress=progress)
t2 = time.perf_counter()
compile_model(folder, manifest)
t3 = time.perf_counter()
if n <= checked_in_max:
    shutil.rmtree(scratch, ignore_errors=True)
ops = {f["name"]: f["operations"] for f in manifest["functions"]}
print(json.dumps({
    "import": t_import, "derive": marks["building"] - t1, "render": t2 - marks["building"],
    "compile": t3 - t2, "in_process": t3 - t0, "ops": ops,
}))
"""

_LOAD = r"""
import json, sys, time
t0 = time.perf_counter()
import snakecg
t1 = time.perf_counter()
steps = []  # load() reports generation or compilation steps: then it was not a cached load
model = snakecg.load(snakecg.Robot(joints=int(sys.argv[1])), progress=steps.append)
t2 = time.perf_counter()
assert model.backend_kind == "compiled", model.backend_kind
print(json.dumps({"import": t1 - t0, "load": t2 - t1, "steps": steps}))
"""


def _children_cpu() -> float:
    """CPU seconds (user + system) of the waited-for child processes and their children."""
    try:
        import resource
    except ImportError:  # pragma: no cover - not on POSIX
        return float("nan")
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _python(code: str, *args: str, env: dict) -> tuple[dict, float]:
    """Run ``code`` in a new interpreter; its JSON result with ``cpu`` (CPU seconds of the
    process and the compilers it ran: about what the wall time is on an idle machine, times
    the parallelism) added, and the wall time."""
    cpu0, t0 = _children_cpu(), time.perf_counter()
    proc = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True,
                          env=env)
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        raise SystemExit(f"benchmark subprocess failed:\n{proc.stderr}")
    out = json.loads(proc.stdout.strip().splitlines()[-1])
    out["cpu"] = _children_cpu() - cpu0
    return out, wall


def crba_count(joints: int) -> int:
    n = joints + 1
    return 3 * n * n + 20 * n + 1


def _best_time(fn, repeats: int) -> float:
    best = np.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def pinocchio_snake(robot):
    """The snake as a Pinocchio tree: PX, PY, RZ root, then one RZ per joint."""
    import pinocchio as pin

    m, l, inertia, c = (np.asarray(a) for a in (robot.mass, robot.length, robot.inertia,
                                                 robot.com))
    model = pin.Model()
    model.gravity = pin.Motion.Zero()
    parent = 0
    for name, joint in (("x", pin.JointModelPX()), ("y", pin.JointModelPY()),
                        ("theta", pin.JointModelRZ())):
        parent = model.addJoint(parent, joint, pin.SE3.Identity(), name)
    model.appendBodyToJoint(parent, pin.Inertia(m[0], np.zeros(3), np.diag([inertia[0]] * 3)),
                            pin.SE3.Identity())
    for i in range(1, robot.n_links):
        offset = l[0] - c[0] if i == 1 else l[i - 1]
        parent = model.addJoint(parent, pin.JointModelRZ(),
                                pin.SE3(np.eye(3), np.array([offset, 0.0, 0.0])), f"q{i}")
        model.appendBodyToJoint(parent, pin.Inertia(m[i], np.array([c[i], 0.0, 0.0]),
                                                    np.diag([inertia[i]] * 3)),
                                pin.SE3.Identity())
    return model


def bench_evaluation(joints: int, n_samples: int, repeats: int) -> dict:
    import snakecg

    robot = snakecg.Robot(joints=joints)
    model = snakecg.load(robot)
    rng = np.random.default_rng(joints)
    Q = rng.uniform(-np.pi, np.pi, (n_samples, robot.n_coordinates))
    model.mass_matrix(Q[:10])
    out = {
        "N": n_samples,
        "M_us": _best_time(lambda: model.mass_matrix(Q), repeats) / n_samples * 1e6,
        "J_us": _best_time(lambda: model.link_jacobians(Q), repeats) / n_samples * 1e6,
    }
    try:
        import pinocchio as pin
    except ImportError:
        out["pin_us"] = None
        return out
    pmodel = pinocchio_snake(robot)
    data = pmodel.createData()
    Qp = Q[: min(n_samples, 20000)]
    # sanity: same M as snakecg (full matrix; crba may fill the upper triangle only)
    Mp = pin.crba(pmodel, data, Qp[0])
    Mp = np.triu(Mp) + np.triu(Mp, 1).T
    assert np.allclose(Mp, model.mass_matrix(Qp[0]), rtol=1e-12, atol=1e-14)

    def loop():
        for q in Qp:
            pin.crba(pmodel, data, q)

    out["pin_us"] = _best_time(loop, repeats) / len(Qp) * 1e6
    return out


def c_size_table(joints) -> int:
    """Generated C per joint count (rendered in this process, nothing compiled): total bytes,
    the largest file, the composition chosen, the render time; and the growth exponent
    between successive counts (``log(size ratio) / log(n ratio)``)."""
    import math

    from snakecg_derive.render import render_model

    print(f"machine: {machine()}")
    print(f"{'n_a':>4} {'algebra':>7} {'C MB':>8} {'largest':>26} {'render s':>9} {'growth':>7}")
    prev = None
    for n in joints:
        t0 = time.perf_counter()
        r = render_model(n, max_joints=max(joints))
        dt = time.perf_counter() - t0
        sizes = {k: len(v.encode()) for k, v in r.files.items() if k.endswith(".c")}
        total = sum(sizes.values())
        big = max(sizes, key=sizes.get)
        growth = "" if prev is None else \
            f"{math.log(total / prev[1]) / math.log(n / prev[0]):.2f}"
        print(f"{n:>4} {r.manifest['algebra']['composed']:>7} {total / 1e6:>8.2f} "
              f"{big[2:] + f' {sizes[big] / 1e6:.2f}':>26} {dt:>9.1f} {growth:>7}", flush=True)
        prev = (n, total)
    return 0


def machine() -> str:
    cpu = cpu_name()
    load = os.getloadavg() if hasattr(os, "getloadavg") else ("?",)
    return (f"{os.cpu_count()} CPUs, {cpu}; Python {platform.python_version()}; "
            f"load average {', '.join(f'{x:.2f}' for x in load)}")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true",
                   help="joint counts 2, 3, 6 and smaller batches (about a minute)")
    p.add_argument("--joints", help="comma-separated joint counts (default 2,3,6,10,20)")
    p.add_argument("--json", metavar="FILE", help="also write the figures as JSON")
    p.add_argument("--c-size", metavar="N,N", nargs="?", const="10,20,30,50",
                   help="only render (no compile) and print the generated C size, render time "
                   "and composition (sx/mx) per joint count (default 10,20,30,50)")
    a = p.parse_args(argv)
    if a.c_size:
        return c_size_table(tuple(int(x) for x in a.c_size.split(",")))
    joints = (tuple(int(x) for x in a.joints.split(",")) if a.joints
              else (2, 3, 6) if a.quick else JOINTS)
    repeats = 3 if a.quick else 7
    cache = tempfile.mkdtemp(prefix="snakecg-bench-cache-")
    # this process evaluates with the cache the subprocesses fill (set before any load)
    os.environ["SNAKECG_CACHE_DIR"] = cache
    env = dict(os.environ)
    print(f"machine: {machine()}")
    print(f"cache: {cache} (fresh; deleted at the end)\n", flush=True)
    rows = []
    try:
        for n in joints:
            print(f"n_a = {n}: cold pipeline ...", end=" ", flush=True)
            cold, cold_wall = _python(_COLD, str(n), str(CHECKED_IN_MAX), env=env)
            print(f"{cold_wall:.1f} s; cached load ...", end=" ", flush=True)
            loads = [_python(_LOAD, str(n), env=env) for _ in range(3)]
            rebuilt = sorted({m for x, _ in loads for m in x["steps"]})
            if rebuilt:  # e.g. derive/ edited during the run (new cache fingerprint)
                print(f"\n  warning: the 'cached' load did work: {rebuilt}", flush=True)
                loads = [_python(_LOAD, str(n), env=env) for _ in range(3)]
            print("evaluation ...", flush=True)
            samples = 100_000 if n <= 6 else 20_000 if n <= 10 else 10_000
            if a.quick:
                samples //= 5
            ev = bench_evaluation(n, samples, repeats)
            rows.append({
                "joints": n,
                "cold": cold, "cold_wall": cold_wall,
                "ops_M": cold["ops"]["mass_matrix"], "crba": crba_count(n),
                "load": min(x["load"] for x, _ in loads),
                "import_load": min(x["import"] + x["load"] for x, _ in loads),
                "load_wall": min(w for _, w in loads),
                **ev,
            })
    finally:
        shutil.rmtree(cache, ignore_errors=True)
    print(f"\nmachine at the end: {machine()}\n")
    _print_table(rows)
    _print_targets(rows)
    if a.json:
        with open(a.json, "w") as fh:
            json.dump({"machine": machine(), "rows": rows}, fh, indent=2)
    return 0


def _print_table(rows) -> None:
    head = ("n_a", "derive s", "render s", "compile s", "cold wall s", "cold CPU s", "M ops",
            "3n²+20n+1",
            "ratio", "load ms", "imp+load ms", "wall ms", "N", "M µs/cfg", "J µs/cfg",
            "crba µs", "crba/M")
    lines = []
    for r in rows:
        c = r["cold"]
        pin_us = r["pin_us"]
        lines.append((
            str(r["joints"]), f"{c['derive']:.2f}", f"{c['render']:.2f}", f"{c['compile']:.2f}",
            f"{r['cold_wall']:.1f}", f"{c['cpu']:.1f}", str(r["ops_M"]), str(r["crba"]),
            f"{r['ops_M'] / r['crba']:.2f}", f"{r['load'] * 1e3:.0f}",
            f"{r['import_load'] * 1e3:.0f}", f"{r['load_wall'] * 1e3:.0f}", str(r["N"]),
            f"{r['M_us']:.3f}", f"{r['J_us']:.3f}",
            "-" if pin_us is None else f"{pin_us:.3f}",
            "-" if pin_us is None else f"{pin_us / r['M_us']:.1f}",
        ))
    widths = [max(len(h), *(len(x[i]) for x in lines)) for i, h in enumerate(head)]
    fmt = " | ".join(f"{{:>{w}}}" for w in widths)
    print("| " + fmt.format(*head) + " |")
    print("|" + "|".join("-" * (w + 1) + ":" for w in widths) + "|")
    for x in lines:
        print("| " + fmt.format(*x) + " |")


def _print_targets(rows) -> None:
    by = {r["joints"]: r for r in rows}
    print("\ntargets:")

    def say(ok, text):
        print(f"  [{'met' if ok else 'NOT met'}] {text}")

    if 10 in by:
        say(by[10]["cold_wall"] < TARGETS["cold_na10_s"],
            f"n_a = 10 cold pipeline {by[10]['cold_wall']:.1f} s < {TARGETS['cold_na10_s']:g} s"
            f" (CPU {by[10]['cold']['cpu']:.1f} s over {os.cpu_count()} cores)")
    worst = max(rows, key=lambda r: r["load"])
    say(worst["load"] < TARGETS["cached_load_s"],
        f"cached load() <= {worst['load'] * 1e3:.0f} ms (n_a = {worst['joints']}) "
        f"< {TARGETS['cached_load_s'] * 1e3:.0f} ms; with import "
        f"{max(r['import_load'] for r in rows) * 1e3:.0f} ms")
    if 3 in by:
        say(by[3]["M_us"] < TARGETS["batched_M_na3_us"],
            f"batched M at n_a = 3: {by[3]['M_us']:.3f} µs < {TARGETS['batched_M_na3_us']} µs")
    with_pin = [r for r in rows if r["pin_us"] is not None]
    if with_pin:
        slow = [r["joints"] for r in with_pin if r["M_us"] >= r["pin_us"]]
        say(not slow, "batched M faster than pin.crba in a Python loop at every n_a"
            + (f" (not at n_a = {slow})" if slow else ""))
    else:
        print("  [skipped] Pinocchio comparison: pinocchio not installed (pip install pin)")
    if 20 in by:
        r = by[20]
        say(r["ops_M"] <= TARGETS["ops_ratio_na20"] * r["crba"],
            f"M operations at n_a = 20: {r['ops_M']} = {r['ops_M'] / r['crba']:.2f} x "
            f"(3n²+20n+1 = {r['crba']}) <= {TARGETS['ops_ratio_na20']}x")


if __name__ == "__main__":
    sys.exit(main())
