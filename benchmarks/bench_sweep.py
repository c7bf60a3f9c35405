"""Benchmark: sweeps on Dask into Zarr (`snakecg.sweep`).

    python benchmarks/bench_sweep.py [--part cost,scaling,overhead,grid4,size] [--quick]
                                     [--budget SECONDS] [--json FILE] [--chunk N]
                                     [--repeat R] [--joints N] [--seconds S]
                                     [--variants tls-lz4,tls-raw,tcp-raw]

* cost: per-configuration CPU cost of `model.extremes` + `com_polar` in one process (one C
  thread), per scenario and joint count 2..6 (the bounded-wheels scenario on a small batch),
  and from it core-hours of the 28^4, 28^5 and 28^6 grids;
* scaling: the same bounded-wheels sweep on a local cluster of 1 worker and of 2 workers,
  alternated `--repeat` times (4 joints, 32,768 seeded samples: 30-45 s on one idle
  worker), the ratio of the medians; the chunk is the sweep's default for the cluster
  (`--chunk` to fix it); the tail is the time from the first worker's last task's end to
  the last one's (one worker idle), from Dask's task stream;
* overhead: at the default chunk size (`snakecg.sweeps.default_chunk`), a warm 1-worker
  cluster's `sweep` (at least 8 chunks, about `--seconds` of work) against the same chunks
  evaluated in this process one after the other, right before and right after it
  (scheduling, serialization, Zarr writes and the digests are the difference), `--repeat`
  rounds and their median; 3 joints for bounded wheels and 4 for the others, or `--joints`;
* grid4: the 28^4 = 614,656 grid of each scenario on 2 workers; the bounded-wheels one
  stops after `--budget` seconds (default 300) and is extrapolated from the chunks written
  (the store is resumable: rerun to finish it);
* size: the bytes on disk of the 28^3 grid of each scenario and of the 28^4 frictionless
  grid, compressed (the store's default) and raw.

Variants (`--variants`, scaling and overhead; each round runs them one after the other, each
on its own cluster): `tls-lz4` is what `snakecg.sweep` does (the local cluster with TLS,
Blosc-LZ4 chunks); `tls-raw` the same with raw chunks; `tcp-raw` the previous release's
setting (plain TCP, raw chunks), the anchor of the change. Only the benchmark can choose them.

Every figure comes with the load average it was measured under.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import tempfile
import threading
import time
from pathlib import Path

os.environ.setdefault("SNAKECG_THREADS", "1")  # one C thread per process: compare like with like

import numpy as np  # noqa: E402

import snakecg  # noqa: E402
from snakecg.sweeps.plan import default_chunk, joint_values, samples_plan  # noqa: E402
from snakecg.sweeps.work import evaluate  # noqa: E402


def load_avg() -> float:
    return round(os.getloadavg()[0], 2)


def scene(joints, scenario):
    return snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario)


def cost(quick: bool) -> dict:
    """Seconds of CPU per configuration, in one process."""
    out = {}
    print(f"{'joints':>6} {'scenario':>13} {'configs':>8} {'us/config':>10} {'load':>5}")
    for joints in (2, 3, 4) if quick else (2, 3, 4, 5, 6):
        for sc in snakecg.SCENARIOS:
            model = snakecg.load(scene(joints, sc))
            n = (64 if joints <= 4 else 32) if sc == "wheels" else 8192
            plan = samples_plan(joints, n, 1, sc, chunk=n)
            q = plan.configurations(0)
            evaluate(model, q[:8])  # warm
            t0, c0 = time.perf_counter(), time.process_time()
            evaluate(model, q)
            cpu = (time.process_time() - c0) / n
            wall = (time.perf_counter() - t0) / n
            out[f"{joints}/{sc}"] = {"cpu_s": cpu, "wall_s": wall, "n": n, "load": load_avg()}
            print(f"{joints:>6} {sc:>13} {n:>8} {cpu * 1e6:>10.1f} {load_avg():>5}", flush=True)
    print("\ncore-hours of a 28^n grid at these costs (per scenario and kappa):")
    for sc in snakecg.SCENARIOS:
        for joints in (4, 5, 6):
            key = f"{joints}/{sc}"
            if key in out:
                ch = 28 ** joints * out[key]["cpu_s"] / 3600
                out[key]["grid28_core_hours"] = ch
                print(f"  28^{joints} {sc:>13}: {ch:12.4g} core-hours")
    return out


def kernel_seconds() -> float:
    """System CPU seconds of this process so far (all its threads)."""
    return os.times().system


def timed_sweep(sc, store, **kw) -> float:
    t = time.perf_counter()
    timed_sweep.last = snakecg.sweep(sc, store=store, progress=False, **kw)
    return time.perf_counter() - t


def tail_seconds(stream) -> float:
    """From Dask's task stream: the last task's end minus the earliest of the workers' last
    task ends (the time one worker sat idle at the end of the sweep)."""
    last = {}
    for t in stream:
        for s in t["startstops"]:
            if s["action"] == "compute":
                last[t["worker"]] = max(last.get(t["worker"], 0.0), s["stop"])
    return max(last.values()) - min(last.values()) if len(last) > 1 else 0.0


SHIPPED_COMPRESSION = None


def use_variant(variant: str) -> None:
    """Make the next local cluster and new stores of ``variant`` (see the module doc)."""
    from snakecg.sweeps import chunks, cluster

    global SHIPPED_COMPRESSION
    if SHIPPED_COMPRESSION is None:
        SHIPPED_COMPRESSION = chunks.COMPRESSION, cluster._security
    compression, security = SHIPPED_COMPRESSION
    if variant not in ("tls-lz4", "tls-raw", "tcp-raw"):
        raise SystemExit(f"unknown variant {variant!r}")
    chunks.COMPRESSION = compression if variant.endswith("lz4") else None
    cluster._security = security if variant.startswith("tls") else (lambda: None)


class local_client:
    """A local cluster as `snakecg.sweep` starts it (`workers=`), kept across calls."""

    def __init__(self, workers, variant="tls-lz4"):
        from snakecg.sweeps.cluster import connect

        use_variant(variant)
        self.client, self.close = connect(workers=workers)
        self.protocol = self.client.scheduler.address.split("://")[0]


def scaling(tmp: Path, quick: bool, chunk: int | None = None, repeat: int = 1,
            variants=("tls-lz4",)) -> dict:
    """1 worker against 2, ``repeat`` rounds alternating (the VM's speed drifts between runs:
    the medians of alternated runs compare like with like)."""
    from distributed import get_task_stream

    joints, n = (3, 2048) if quick else (4, 32768)  # >= 30 s on one idle worker (1 ms each)
    sc = scene(joints, "wheels")
    out = {(v, w): [] for v in variants for w in (1, 2)}
    for r, workers, variant in ((r, w, v) for r in range(repeat) for w in (1, 2)
                                for v in variants):
        lc = local_client(workers, variant)
        client = lc.client
        try:
            # warm: every worker loads the model before the clock starts
            timed_sweep(sc, tmp / f"warm{workers}-{r}-{variant}.zarr",
                        samples=4 * workers, seed=0, chunk=1, client=client)
            la = load_avg()
            w0, c0 = client.run(time.process_time), time.process_time()
            with get_task_stream(client) as ts:
                t = timed_sweep(sc, tmp / f"scale{workers}-{r}-{variant}.zarr",
                                samples=n, seed=1, chunk=chunk, client=client)
            used = timed_sweep.last.chunk
            tail = tail_seconds(ts.data)
            # CPU seconds of this process (scheduler, client, nannies and whatever Zarr
            # writes it does) and of the workers, during the sweep
            cpu_here = time.process_time() - c0
            w1 = client.run(time.process_time)
            cpu_workers = sum(w1[a] - w0[a] for a in w1 if a in w0)
            out[(variant, workers)].append({"seconds": t, "load_before": la,
                                 "load_after": load_avg(), "cpu_client_s": cpu_here,
                                 "cpu_workers_s": cpu_workers, "chunk": used,
                                 "tail_s": tail})
            print(f"  {variant} {workers} worker(s): {n} configurations ({joints} "
                  f"joints, wheels, "
                  f"chunks of {used}) in {t:.1f} s, load {la} -> {load_avg()}; CPU: "
                  f"workers {cpu_workers:.1f} s, this process {cpu_here:.2f} s; "
                  f"tail {tail:.2f} s", flush=True)
        finally:
            lc.close()
    result = {}
    for v in variants:
        med = {w: float(np.median([x["seconds"] for x in out[(v, w)]])) for w in (1, 2)}
        result[v] = {"1": out[(v, 1)], "2": out[(v, 2)], "speedup": med[1] / med[2],
                     "median_s": med}
        print(f"  {v}: speed-up 2 workers / 1 (medians of {repeat}): "
              f"{med[1] / med[2]:.2f}x ({med[1]:.1f} s / {med[2]:.1f} s)")
    return result


def overhead(tmp: Path, quick: bool, joints: int | None = None, repeat: int = 3,
             seconds: float = 8.0, variants=("tls-lz4",), scenarios=None) -> dict:
    """Wall time of a warm 1-worker sweep against the same chunks evaluated in this process
    one after the other (the plain loop, run right before and right after each sweep: their
    mean is the anchor, so a drift of the machine's speed weighs on both alike), ``repeat``
    rounds, the median of the rounds' ratios; and the CPU time of the sweep's processes
    (worker and this one) against the loop's. The difference is scheduling, serialization,
    the Zarr writes and the digests. The sweep has at least 8 default chunks and about
    ``seconds`` of single-core work (at :func:`configuration_seconds`), so that what a sweep
    costs once (creating the store, the last chunk's write) counts as in a sweep of that
    length; that part is reported apart too: the sweep's wall time outside its tasks (one
    worker runs them one after the other; from Dask's task stream), and the tasks' own
    slowdown against the loop (the calling process writes the chunks on the other core)."""
    from snakecg.sweeps.plan import configuration_seconds

    out = {}
    for sc_name, nj in (("wheels", 3), ("frictionless", 4), ("ideal_wheels", 4)):
        if scenarios and sc_name not in scenarios:
            continue
        nj = joints or nj
        sc = scene(nj, sc_name)
        chunk = default_chunk(sc_name, nj)
        per_chunk = chunk * configuration_seconds(sc_name, nj)
        chunks = 4 if quick else max(8, round(seconds / per_chunk))
        n = chunk * chunks
        plan = samples_plan(nj, n, 2, sc_name, chunk=chunk)
        model = snakecg.load(sc)
        evaluate(model, plan.configurations(0)[:8])  # warm

        def loop(plan=plan, model=model):
            t, c = time.perf_counter(), time.process_time()
            for i in range(plan.n_chunks):
                evaluate(model, plan.configurations(i))
            return time.perf_counter() - t, time.process_time() - c

        rounds = {v: [] for v in variants}
        for r in range(repeat):
            for variant in variants:
                lc = local_client(1, variant)
                client = lc.client
                try:
                    timed_sweep(sc, tmp / f"warm-{sc_name}-{r}-{variant}.zarr", samples=2,
                                seed=0, chunk=1, client=client)
                    rounds[variant].append(_overhead_round(
                        client, loop, sc, tmp / f"ovh-{sc_name}-{r}-{variant}.zarr", n, chunk))
                finally:
                    lc.close()
                x = rounds[variant][-1]
                print(f"  {variant} {sc_name:>13} ({nj} joints, {chunks} chunks of {chunk}): "
                      f"sweep {x['dask_s']:.2f} s, plain loop {x['in_process_runs_s'][0]:.2f} s "
                      f"before and {x['in_process_runs_s'][1]:.2f} s after: overhead "
                      f"{100 * x['overhead']:+.1f} % (outside the tasks "
                      f"{x['outside_tasks_s']:.2f} s, tasks {100 * x['task_slowdown']:+.1f} "
                      f"%); CPU: worker {x['cpu_worker_s']:.2f} s + this process "
                      f"{x['cpu_client_s']:.2f} s against {x['cpu_loop_s']:.2f} s: "
                      f"{100 * x['cpu_overhead']:+.1f} % (in the kernel "
                      f"{x['cpu_kernel_s']:.2f} s); store {x['store_mb']:.1f} MB; load "
                      f"{x['load']} -> {x['load_after']}", flush=True)
        out[sc_name] = {"joints": nj, "chunk": chunk, "chunks": chunks, "configurations": n}
        for variant in variants:
            med = {k: float(np.median([x[k] for x in rounds[variant]]))
                   for k in ("overhead", "outside_tasks_s", "task_slowdown", "cpu_overhead",
                             "store_mb")}
            out[sc_name][variant] = {"rounds": rounds[variant], "median": med}
            print(f"  {variant} {sc_name:>13}: median of {repeat}: overhead "
                  f"{100 * med['overhead']:+.1f} % (outside the tasks "
                  f"{med['outside_tasks_s']:.2f} s, tasks {100 * med['task_slowdown']:+.1f} "
                  f"%), CPU {100 * med['cpu_overhead']:+.1f} %, store {med['store_mb']:.1f} MB",
                  flush=True)
    return out


def _dir_mb(path: Path) -> float:
    return sum(f.stat().st_size for f in path.rglob("*") if f.is_file()) / 1e6


def _overhead_round(client, loop, sc, store, n, chunk) -> dict:
    """One round: the plain loop, the sweep, the plain loop."""
    from distributed import get_task_stream

    la = load_avg()
    before, cpu_before = loop()
    w0, c0 = client.run(time.process_time), time.process_time()
    k0 = client.run(kernel_seconds), kernel_seconds()
    with get_task_stream(client) as ts:
        dask = timed_sweep(sc, store, samples=n, seed=2, chunk=chunk, client=client)
    cpu_here = time.process_time() - c0
    w1, k1 = client.run(time.process_time), client.run(kernel_seconds)
    cpu_worker = sum(w1[a] - w0[a] for a in w1 if a in w0)
    # of which in the kernel (writing the files, moving the results)
    kernel = kernel_seconds() - k0[1] + sum(k1[a] - k0[0][a] for a in k1 if a in k0[0])
    after, cpu_after = loop()
    tasks = sum(s["stop"] - s["start"] for t in ts.data for s in t["startstops"]
                if s["action"] == "compute")
    inproc, cpu_loop = (before + after) / 2, (cpu_before + cpu_after) / 2
    return {
        "dask_s": dask, "task_s": tasks, "in_process_runs_s": [before, after],
        "overhead": dask / inproc - 1,
        "outside_tasks_s": dask - tasks, "task_slowdown": tasks / inproc - 1,
        # CPU seconds: the worker and this process (scheduler, client, nanny, Zarr writes
        # when it writes) against the plain loop's
        "cpu_worker_s": cpu_worker, "cpu_client_s": cpu_here, "cpu_loop_s": cpu_loop,
        "cpu_overhead": (cpu_worker + cpu_here) / cpu_loop - 1, "cpu_kernel_s": kernel,
        "store_mb": _dir_mb(store), "load": la, "load_after": load_avg()}


def size(tmp: Path) -> dict:
    """Bytes on disk of the paper's grids, compressed (the default) and raw, 2 workers."""
    out = {}
    grid = joint_values(-135, 135, 10)
    for joints, sc_name in ((3, "frictionless"), (3, "ideal_wheels"), (3, "wheels"),
                            (4, "frictionless")):
        for variant in ("tls-lz4", "tls-raw"):
            lc = local_client(2, variant)
            try:
                store = tmp / f"size-{joints}-{sc_name}-{variant}.zarr"
                t = timed_sweep(scene(joints, sc_name), store, grid=grid, client=lc.client)
            finally:
                lc.close()
            mb = _dir_mb(store)
            out[f"{joints}/{sc_name}/{variant}"] = {"mb": mb, "seconds": t}
            print(f"  28^{joints} {sc_name:>13} {variant}: {mb:8.1f} MB ({t:.1f} s)",
                  flush=True)
            shutil.rmtree(store, ignore_errors=True)
    return out


def grid4(tmp: Path, budget: float) -> dict:
    out = {}
    grid = joint_values(-135, 135, 10)
    for sc_name in ("frictionless", "ideal_wheels", "wheels"):
        sc = scene(4, sc_name)
        store = tmp / f"grid4-{sc_name}.zarr"
        la = load_avg()
        t = time.perf_counter()
        if sc_name != "wheels":
            snakecg.sweep(sc, grid=grid, store=store, workers=2, progress=False)
            wall = time.perf_counter() - t
            out[sc_name] = {"seconds": wall, "load": la, "complete": True}
            print(f"  28^4 {sc_name:>13}: {wall:.1f} s on 2 workers (cluster start and model "
                  f"loads included), load {la} -> {load_avg()}", flush=True)
            continue
        lc = local_client(2)
        client = lc.client
        box = {}

        def run():
            try:
                snakecg.sweep(sc, grid=grid, store=store, client=client, progress=False)
            except Exception as exc:  # noqa: BLE001 - cancelled at the budget
                box["err"] = exc

        th = threading.Thread(target=run, daemon=True)
        th.start()
        th.join(timeout=budget)
        import zarr

        root = zarr.open_group(str(store), mode="r")
        done = int(np.count_nonzero(root["chunk_digest"][:]))
        meta = root.attrs["snakecg_sweep"]
        wall = time.perf_counter() - t
        lc.close()
        th.join(timeout=60)
        configs = done * meta["chunk"]
        rate = configs / wall
        est = meta["n_configurations"] / rate if rate else float("inf")
        out[sc_name] = {"seconds": wall, "chunks_done": done, "chunks": meta["n_chunks"],
                        "configurations_done": configs, "rate_per_s": rate,
                        "estimated_seconds": est, "load": la,
                        "complete": done == meta["n_chunks"]}
        print(f"  28^4 {sc_name:>13}: {done} of {meta['n_chunks']} chunks ({configs:,} "
              f"configurations) in {wall:.0f} s on 2 workers: {rate:.0f} configurations/s, "
              f"the whole grid in about {est / 3600:.2f} h; load {la} -> {load_avg()}",
              flush=True)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--part", default="cost,scaling,overhead,grid4")
    ap.add_argument("--quick", action="store_true", help="smaller runs (3-joint scaling, ...)")
    ap.add_argument("--budget", type=float, default=300.0,
                    help="seconds for the bounded-wheels 28^4 sweep (default 300)")
    ap.add_argument("--json", metavar="FILE", help="also write the figures as JSON")
    ap.add_argument("--chunk", type=int, default=None,
                    help="scaling: configurations per chunk (default: the sweep's default)")
    ap.add_argument("--joints", type=int, default=None,
                    help="overhead: joints of all three scenarios (default 3 for bounded "
                    "wheels, 4 for the others)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="scaling: alternated rounds of 1 and 2 workers; overhead: rounds of "
                    "loop, sweep, loop (default 3)")
    ap.add_argument("--scenarios", default=None,
                    help="overhead: comma-separated scenarios (default all three)")
    ap.add_argument("--variants", default="tls-lz4",
                    help="scaling, overhead: comma-separated among tls-lz4 (what sweeps do), "
                    "tls-raw, tcp-raw (the previous release), run one after the other in "
                    "each round")
    ap.add_argument("--seconds", type=float, default=8.0,
                    help="overhead: single-core seconds of work per sweep, at least 8 "
                    "chunks (default 8)")
    args = ap.parse_args()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python "
          f"{platform.python_version()}, load average {load_avg()}")
    results = {"cores": os.cpu_count()}
    tmp = Path(tempfile.mkdtemp(prefix="bench-sweep-"))
    try:
        for part in args.part.split(","):
            print(f"\n== {part}")
            if part == "cost":
                results[part] = cost(args.quick)
            elif part == "scaling":
                results[part] = scaling(tmp, args.quick, args.chunk, args.repeat,
                                        tuple(args.variants.split(",")))
            elif part == "overhead":
                results[part] = overhead(tmp, args.quick, args.joints, args.repeat,
                                         args.seconds, tuple(args.variants.split(",")),
                                         args.scenarios and args.scenarios.split(","))
            elif part == "size":
                results[part] = size(tmp)
            elif part == "grid4":
                results[part] = grid4(tmp, args.budget)
            else:
                raise SystemExit(f"unknown part {part!r}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=2) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
