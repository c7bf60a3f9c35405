"""Benchmark of the runtime core: one ``forward`` call from Python and batched ``forward``,
side by side with MuJoCo's ``mj_forward`` on an equivalent model, in one run.

For a 3-joint snake (the paper's Table 1 robot, kappa = 100) at rest, in each scenario:

* **single**: ``model.forward(q, tau)`` from Python on one sample (validation, the compiled
  per-sample solve, the result object), best of ``--repeat`` rounds of ``--single`` calls,
  cycling through 64 random (configuration, torque) pairs;
* **batched**: ``model.forward(Q, T)`` on ``--n`` pairs with ``SNAKECG_THREADS=1``, time per
  pair (best of ``--repeat``);
* **mj_forward**: MuJoCo's whole forward dynamics on the same bodies and joints (the snake's
  four capsule links on a planar base, the 5 kg object as a planar box touching link 2,
  actuated joints, no gravity), from Python: set ``qpos`` and ``ctrl``, ``mj_forward``, copy
  ``qacc``; and the bare ``mj_forward`` call. MuJoCo has no lateral-only wheel constraint, so
  its model has the contact and the bodies but not the wheels: it does less than the
  ``wheels`` scenarios.

* **threads** (``--threads``): batched ``forward`` per pair on 1 and on 2 threads for batch
  sizes from 128 to 65,536 (``wheels``), the data behind the default of ``SNAKECG_THREADS``
  (threads only from ``PARALLEL_MIN`` samples per thread on).
* **instructions** (``--instructions``, needs valgrind): machine instructions per batched
  pair inside the C core (callgrind's inclusive count of the per-sample solve over 20,000
  pairs), a figure that does not depend on the machine's load or clock.

    python benchmarks/bench_core.py [--n 100000] [--single 20000] [--repeat 5] [--threads]
                                    [--instructions]

Prints a table and the machine's load average before and after.
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import numpy as np

from _machine import cpu_name  # benchmarks/_machine.py

os.environ.setdefault("SNAKECG_THREADS", "1")

import snakecg  # noqa: E402  (after SNAKECG_THREADS)

SCENARIOS = ("frictionless", "wheels", "ideal_wheels")

MJCF = """
<mujoco model="snake3">
  <option timestep="0.001" gravity="0 0 0"/>
  <default><geom contype="1" conaffinity="1" friction="0.5 0.005 0.0001"/></default>
  <worldbody>
    <body name="link1" pos="0 0 0.02">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="y" type="slide" axis="0 1 0"/>
      <joint name="theta" type="hinge" axis="0 0 1"/>
      <geom type="capsule" fromto="0.01 0 0 0.14 0 0" size="0.01" mass="1"/>
      <body name="link2" pos="0.15 0 0">
        <joint name="q1" type="hinge" axis="0 0 1"/>
        <geom type="capsule" fromto="0.01 0 0 0.14 0 0" size="0.01" mass="1"/>
        <body name="link3" pos="0.15 0 0">
          <joint name="q2" type="hinge" axis="0 0 1"/>
          <geom type="capsule" fromto="0.01 0 0 0.14 0 0" size="0.01" mass="1"/>
          <body name="link4" pos="0.15 0 0">
            <joint name="q3" type="hinge" axis="0 0 1"/>
            <geom type="capsule" fromto="0.01 0 0 0.14 0 0" size="0.01" mass="1"/>
          </body>
        </body>
      </body>
    </body>
    <body name="object" pos="0.225 0.06 0.02">
      <joint name="ox" type="slide" axis="1 0 0"/>
      <joint name="oy" type="slide" axis="0 1 0"/>
      <joint name="opsi" type="hinge" axis="0 0 1"/>
      <geom type="box" size="0.05 0.05 0.01" mass="5"/>
    </body>
  </worldbody>
  <actuator>
    <motor joint="q1"/><motor joint="q2"/><motor joint="q3"/>
  </actuator>
</mujoco>
"""


def best_of(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def bench_snakecg(scenario, n, single, repeat, rng):
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=100)
    model = snakecg.load(scene)
    Q = np.zeros((n, 6))
    Q[:, 3:] = rng.uniform(-2.3, 2.3, (n, 3))
    T = rng.normal(0.0, 0.05, (n, 3))
    qs, ts = [Q[i].copy() for i in range(64)], [T[i].copy() for i in range(64)]
    fwd = model.forward
    res = fwd(Q, T)
    marked = int(np.count_nonzero(res.raw[:, model.columns.status]))

    def singles():
        for k in range(single):
            fwd(qs[k & 63], ts[k & 63])

    singles()  # warm-up: the first round after loading runs slower on this kind of VM
    t_single = best_of(singles, repeat) / single
    t_batch = best_of(lambda: fwd(Q, T, out=res), repeat) / n
    return t_single, t_batch, marked


def bench_mujoco(single, repeat):
    try:
        import mujoco
    except ImportError:
        return None
    m = mujoco.MjModel.from_xml_string(MJCF)
    d = mujoco.MjData(m)
    q = np.array([0.0, 0.0, 0.0, 0.3, -0.5, 0.4, 0.0, 0.0, 0.0])
    tau = np.array([0.05, 0.0, -0.02])
    d.qpos[:] = q
    d.ctrl[:] = tau
    mujoco.mj_forward(m, d)
    ncon = int(d.ncon)

    def io():
        for _ in range(single):
            d.qpos[:] = q
            d.ctrl[:] = tau
            mujoco.mj_forward(m, d)
            d.qacc.copy()

    def bare():
        for _ in range(single):
            mujoco.mj_forward(m, d)

    io()  # warm-up, as for snakecg
    return best_of(io, repeat) / single, best_of(bare, repeat) / single, ncon, mujoco.__version__


def bench_threads(repeat, rng):
    from snakecg import forward as forward_mod

    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100))
    print(f"\nthreads (wheels; PARALLEL_MIN = {forward_mod.PARALLEL_MIN} samples per thread)")
    print("| batch | 1 thread µs/pair | 2 threads µs/pair | speed-up |")
    print("|---:|---:|---:|---:|")
    saved = forward_mod.PARALLEL_MIN
    forward_mod.PARALLEL_MIN = 1  # measure both at every size
    try:
        for n in (128, 512, 2048, 8192, 65536):
            Q = np.zeros((n, 6))
            Q[:, 3:] = rng.uniform(-2.3, 2.3, (n, 3))
            T = rng.normal(0.0, 0.05, (n, 3))
            res = model.forward(Q, T)
            times = []
            for k in ("1", "2"):
                os.environ["SNAKECG_THREADS"] = k
                rounds = max(1, 20000 // n)
                times.append(best_of(lambda: [model.forward(Q, T, out=res)
                                              for _ in range(rounds)], repeat) / (rounds * n))
            print(f"| {n} | {times[0] * 1e6:.3f} | {times[1] * 1e6:.3f} |"
                  f" {times[0] / times[1]:.2f} |")
    finally:
        forward_mod.PARALLEL_MIN = saved
        os.environ["SNAKECG_THREADS"] = "1"


def _instructions_child(scenario: str, n: int) -> None:
    """The work callgrind counts: one batched forward of ``n`` random pairs."""
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=100)
    model = snakecg.load(scene)
    rng = np.random.default_rng(0)
    Q = np.zeros((n, 6))
    Q[:, 3:] = rng.uniform(-2.3, 2.3, (n, 3))
    T = rng.normal(0.0, 0.05, (n, 3))
    model.forward(Q, T)


def bench_instructions(n: int = 20000) -> None:
    """Instructions per pair of the per-sample solve (callgrind, inclusive), per scenario."""
    import re
    import shutil
    import subprocess
    import sys
    import tempfile

    if not shutil.which("valgrind") or not shutil.which("callgrind_annotate"):
        print("\ninstructions: valgrind is not installed (apt-get install valgrind)")
        return
    print(f"\ninstructions per pair in the C core (callgrind, {n} pairs, inclusive solve_one)")
    print("| scenario | instructions per pair |")
    print("|---|---:|")
    for sc in SCENARIOS:
        with tempfile.TemporaryDirectory() as tmp:
            out = f"{tmp}/cg.out"
            subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                            sys.executable, __file__, "--_child", sc, str(n)],
                           check=True, capture_output=True)
            text = subprocess.run(["callgrind_annotate", "--inclusive=yes", out], check=True,
                                  capture_output=True, text=True).stdout
        m = re.search(r"^\s*([\d,]+) .*:solve_one\b", text, re.M)
        count = int(m.group(1).replace(",", "")) / n if m else float("nan")
        print(f"| {sc} | {count:,.0f} |")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=100_000, help="batch size (pairs)")
    p.add_argument("--single", type=int, default=20_000, help="single calls per round")
    p.add_argument("--repeat", type=int, default=5, help="best of this many rounds")
    p.add_argument("--threads", action="store_true", help="also 1 vs 2 threads per batch size")
    p.add_argument("--instructions", action="store_true",
                   help="also instructions per batched pair (valgrind's callgrind)")
    p.add_argument("--_child", nargs=2, help=argparse.SUPPRESS)
    a = p.parse_args(argv)
    if a._child:
        _instructions_child(a._child[0], int(a._child[1]))
        return 0
    rng = np.random.default_rng(0)
    load0 = os.getloadavg()
    print(f"machine: {cpu_name()}, {os.cpu_count()} cores, Python {platform.python_version()},"
          f" numpy {np.__version__}, SNAKECG_THREADS={os.environ['SNAKECG_THREADS']}")
    print(f"load average before: {load0[0]:.2f} {load0[1]:.2f} {load0[2]:.2f}")
    mj = bench_mujoco(a.single, a.repeat)
    print("| scenario | single forward µs | batched µs/pair | marked for the reference path |"
          " mj_forward + I/O µs | bare mj_forward µs |")
    print("|---|---:|---:|---:|---:|---:|")
    for sc in SCENARIOS:
        t1, tb, marked = bench_snakecg(sc, a.n, a.single, a.repeat, rng)
        mjs = (f"{mj[0] * 1e6:.2f} | {mj[1] * 1e6:.2f}" if mj else "n/a | n/a")
        print(f"| {sc} | {t1 * 1e6:.2f} | {tb * 1e6:.3f} | {marked} of {a.n} | {mjs} |")
    if mj:
        print(f"MuJoCo {mj[3]}, {mj[2]} contact(s) in the model's configuration")
    if a.threads:
        bench_threads(a.repeat, rng)
    if a.instructions:
        bench_instructions()
    load1 = os.getloadavg()
    print(f"load average after: {load1[0]:.2f} {load1[1]:.2f} {load1[2]:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
