#!/usr/bin/env python
"""How much of the generated mass matrix's time is its sines and cosines, and what the batched
mass matrix costs per configuration; prints two tables.

**C table.** For each checked-in joint count ``n_a`` asked for (default 3), in C, on the same
100,000 random configurations (uniform in [-pi, pi], as in bench_pipeline.py), best of 15
passes of CPU time (``CLOCK_PROCESS_CPUTIME_ID``), all in one process so that all see the same
load:

* **M per sample**: the generated ``mass_matrix`` called once per configuration (the C
  function itself, with its C library ``sincos`` calls: what the batched driver called before);
* **batched M**: the batched driver ``batch_mass_matrix`` on all of them in one call (sines and
  cosines of blocks of samples in one vectorized loop, then ``mass_matrix_sincos`` per
  sample);
* **sincos**: the ``n_a + 1`` calls ``sincos(theta)``, ``sincos(q_i)`` alone;
* **writing M**: storing the ``n_s^2`` doubles of every configuration's M and nothing else,
  the memory traffic that no evaluation of a batch avoids;
* **instructions** per configuration of the first two (``valgrind --tool=callgrind`` on one
  pass over 10,000 configurations, when valgrind is installed): independent of the load.

**Python table** (``--python``, one joint count): ``model.mass_matrix(Q)`` of the compiled
model with ``SNAKECG_THREADS=1`` for batches of 1,000 to 100,000 configurations, beside two
anchors timed in the same run: Pinocchio's ``pin.crba`` called from Python per configuration
(the snake as in bench_pipeline.py) and a dense NumPy evaluation of ``sum_i J_i^T D_i J_i``
vectorized over the batch; and ``np.empty(...).fill(0)`` of the output's size (the memory
floor).

Both are compiled with the compiler and ``-O2`` that ``snakecg`` uses. Usage:
``python benchmarks/bench_mass_trig.py [--joints 3,6] [--python]``.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from _machine import cpu_name  # benchmarks/_machine.py

ROOT = Path(__file__).resolve().parent.parent

_HARNESS = r"""
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
typedef long long casadi_int;
int %(symbol)s(const double** arg, double** res, casadi_int* iw, double* w, int mem);
int %(batch)s(casadi_int n, const double** arg, const casadi_int* stride, double** res);
static double now(void) {
  struct timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); return t.tv_sec + 1e-9 * t.tv_nsec;
}
/* one pass of each path in a function of its own, for counting instructions (callgrind) */
__attribute__((noinline)) void per_sample(int N, const double* Q, const double* K, double* out,
                                          int nq, int nM) {
  int i;
  for (i = 0; i < N; ++i) {
    const double* a[2]; double* r[1]; double w[%(nw)d]; casadi_int iw[%(niw)d];
    a[0] = Q + i * nq; a[1] = K; r[0] = out + i * nM;
    %(symbol)s(a, r, iw, w, 0);
  }
}
__attribute__((noinline)) void batched(int N, const double* Q, const double* K, double* out,
                                       int nq) {
  const double* a[2]; double* r[1]; casadi_int stride[2];
  a[0] = Q; a[1] = K; r[0] = out; stride[0] = nq; stride[1] = 0;
  %(batch)s(N, a, stride, r);
}
int main(int argc, char** argv) {
  const int N = argc > 1 ? 10000 : 100000, nq = %(nq)d, nK = %(nK)d, nM = nq * nq, na = %(na)d;
  double *Q = malloc(sizeof(double) * N * nq), *out = malloc(sizeof(double) * N * nM);
  double *cs = malloc(sizeof(double) * N * 2 * (na + 1)), K[%(nK)d], w[%(nw)d];
  casadi_int iw[%(niw)d];
  double *out2 = malloc(sizeof(double) * N * nM), diff = 0;
  double best_m = 1e9, best_t = 1e9, best_b = 1e9, best_w = 1e9, check = 0;
  int i, k, rep;
  srand(1);
  for (i = 0; i < N * nq; ++i) Q[i] = M_PI * (2.0 * rand() / RAND_MAX - 1.0);
  for (i = 0; i < nK; ++i) K[i] = 0.1 + 0.01 * i;
  if (argc > 1) {  /* "count": each path once, nothing timed */
    per_sample(N, Q, K, out, nq, nM);
    batched(N, Q, K, out2, nq);
    printf("%%g\n", out[N * nM - 1] + out2[N * nM - 1]);
    return 0;
  }
  for (rep = 0; rep < 15; ++rep) {
    double t = now();
    for (i = 0; i < N; ++i) {
      const double* a[2]; double* r[1];
      a[0] = Q + i * nq; a[1] = K; r[0] = out + i * nM;
      %(symbol)s(a, r, iw, w, 0);
    }
    t = now() - t; if (t < best_m) best_m = t;
    t = now();
    for (i = 0; i < N; ++i)
      for (k = 0; k <= na; ++k)
        sincos(Q[i * nq + 2 + k], cs + (i * (na + 1) + k) * 2, cs + (i * (na + 1) + k) * 2 + 1);
    t = now() - t; if (t < best_t) best_t = t;
    t = now();
    {
      const double* a[2]; double* r[1]; casadi_int stride[2];
      a[0] = Q; a[1] = K; r[0] = out2; stride[0] = nq; stride[1] = 0;
      if (%(batch)s(N, a, stride, r)) return 1;
    }
    t = now() - t; if (t < best_b) best_b = t;
    t = now();
    for (i = 0; i < N * nM; ++i) out2[i] = (double) i;
    t = now() - t; if (t < best_w) best_w = t;
    {
      const double* a[2]; double* r[1]; casadi_int stride[2];
      a[0] = Q; a[1] = K; r[0] = out2; stride[0] = nq; stride[1] = 0;
      if (%(batch)s(N, a, stride, r)) return 1;
    }
  }
  for (i = 0; i < N * nM; ++i) check += out[i];
  for (i = 0; i < N * 2 * (na + 1); ++i) check += cs[i];
  for (i = 0; i < N * nM; ++i) {
    double d = fabs(out[i] - out2[i]);
    if (d > diff) diff = d;
  }
  printf("%%.5f %%.5f %%.5f %%.5f %%g %%g\n", best_m / N * 1e6, best_t / N * 1e6,
         best_b / N * 1e6, best_w / N * 1e6, diff, check);
  return 0;
}
"""


def measure(joints: int, cc: str) -> tuple[float, float, float, float, float, dict]:
    import json

    folder = ROOT / "generated" / f"na{joints}"
    manifest = json.loads((folder / "manifest.json").read_text())
    (sig,) = [f for f in manifest["functions"] if f["name"] == "mass_matrix"]
    nq = manifest["n_coordinates"]
    with tempfile.TemporaryDirectory(prefix="bench-mass-trig-") as tmp:
        harness = Path(tmp) / "harness.c"
        harness.write_text(_HARNESS % {
            "symbol": sig["symbol"], "batch": f"{manifest['prefix']}batch_mass_matrix", "nq": nq, "nK": manifest["n_parameters"], "na": joints,
            "nw": sig["sz_w"] + 1, "niw": sig["sz_iw"] + 1})
        exe = Path(tmp) / "bench"
        subprocess.run([cc, "-O2", "-fPIC", "-o", str(exe), str(harness),
                        str(folder / "c" / "mass_matrix.c"), "-lm"], check=True)
        out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
        counts = {}
        if shutil.which("valgrind"):  # instructions per configuration: the load does not matter
            for fn in ("per_sample", "batched"):
                log = Path(tmp) / f"callgrind.{fn}"
                subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={log}",
                                f"--toggle-collect={fn}", str(exe), "count"], check=True,
                               capture_output=True)
                summary = [x for x in log.read_text().splitlines() if x.startswith("summary:")]
                counts[fn] = int(summary[0].split()[1]) / 10_000
    m_us, t_us, b_us, w_us, diff, _ = (float(x) for x in out.split())
    return m_us, t_us, b_us, w_us, diff, counts


def dense_mass_matrix(robot, Q: np.ndarray) -> np.ndarray:
    """``M = sum_i J_i^T diag(m_i, m_i, I_i) J_i`` (eq. 4) vectorized over the batch in NumPy,
    the Jacobians from the joint positions (the anchor; it shares nothing with snakecg)."""
    m, ln, inertia, c = (np.asarray(a, dtype=float) for a in (robot.mass, robot.length,
                                                              robot.inertia, robot.com))
    N, ns = Q.shape
    nl = ns - 2
    phi = Q[:, 2:2 + nl].copy()
    phi[:, 1:] = Q[:, 2:3] + np.cumsum(Q[:, 3:], axis=1)
    e = np.stack([np.cos(phi), np.sin(phi)], axis=-1)  # (N, nl, 2)
    rear = np.empty((N, nl, 2))
    rear[:, 0] = Q[:, :2] - c[0] * e[:, 0]
    for i in range(1, nl):
        rear[:, i] = rear[:, i - 1] + ln[i - 1] * e[:, i - 1]
    com = rear + c[None, :, None] * e
    pivots = np.concatenate([com[:, :1], rear[:, 1:]], axis=1)  # theta: COM 1; joint j: rear j+1
    M = np.zeros((N, ns, ns))
    for i in range(nl):
        Jv = np.zeros((N, 2, ns))
        Jv[:, 0, 0] = Jv[:, 1, 1] = 1.0
        d = com[:, i, None, :] - pivots[:, : i + 1]  # (N, i+1, 2)
        Jv[:, 0, 2: 3 + i] = -d[..., 1]
        Jv[:, 1, 2: 3 + i] = d[..., 0]
        M += m[i] * np.einsum("nki,nkj->nij", Jv, Jv)
        M[:, 2: 3 + i, 2: 3 + i] += inertia[i]
    return M


def python_table(joints: int, repeats: int = 7) -> None:
    """``model.mass_matrix(Q)`` against Pinocchio and NumPy anchors, one thread, one run."""
    os.environ["SNAKECG_THREADS"] = "1"
    import time

    import snakecg
    from bench_pipeline import pinocchio_snake  # benchmarks/bench_pipeline.py

    def best(fn) -> float:
        b = np.inf
        for _ in range(repeats):
            t0 = time.perf_counter()
            fn()
            b = min(b, time.perf_counter() - t0)
        return b

    robot = snakecg.Robot(joints=joints)
    model = snakecg.load(robot)
    assert model.backend.kind == "compiled"
    rng = np.random.default_rng(joints)
    Q = rng.uniform(-np.pi, np.pi, (100_000, robot.n_coordinates))
    np.testing.assert_allclose(model.mass_matrix(Q[:1000]), dense_mass_matrix(robot, Q[:1000]),
                               rtol=0, atol=1e-12)
    import pinocchio as pin

    pmodel = pinocchio_snake(robot)
    data = pmodel.createData()
    Qp = Q[:20_000]

    def crba() -> None:
        for q in Qp:
            pin.crba(pmodel, data, q)

    pin_us = best(crba) / len(Qp) * 1e6
    ns = robot.n_coordinates
    print(f"\nn_a = {joints}, SNAKECG_THREADS=1; pin.crba from Python per configuration:"
          f" {pin_us:.3f} µs (20,000 configurations)")
    print("| batch | model.mass_matrix µs/cfg | NumPy dense µs/cfg | writing M µs/cfg |"
          " pin.crba / model | NumPy / model |")
    print("|---:|---:|---:|---:|---:|---:|")
    for n in (1_000, 10_000, 100_000):
        q = Q[:n]
        model.mass_matrix(q)
        m_us = best(lambda: model.mass_matrix(q)) / n * 1e6
        d_us = best(lambda: dense_mass_matrix(robot, q)) / n * 1e6
        w_us = best(lambda: np.empty((n, ns, ns)).fill(0.0)) / n * 1e6
        print(f"| {n:,} | {m_us:.4f} | {d_us:.3f} | {w_us:.4f} | {pin_us / m_us:.0f} |"
              f" {d_us / m_us:.0f} |", flush=True)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    p.add_argument("--joints", default="3", help="comma-separated checked-in joint counts")
    p.add_argument("--python", action="store_true",
                   help="also time model.mass_matrix against pin.crba and NumPy (first count)")
    a = p.parse_args(argv)
    cc = os.environ.get("CC", "cc")
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"machine: {os.cpu_count()} CPUs, {cpu_name()}; Python {platform.python_version()};"
          f" {cc} -O2; load average {load}")
    print("| n_a | M per sample µs/cfg | batched M µs/cfg | sincos µs/cfg | writing M µs/cfg |"
          " sincos / M per sample | per sample / batched | instructions/cfg per sample |"
          " instructions/cfg batched |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    joints = [int(x) for x in a.joints.split(",")]
    for n in joints:
        m_us, t_us, b_us, w_us, diff, counts = measure(n, cc)
        if diff > 1e-12:
            raise SystemExit(f"batched and per-sample M differ by {diff:g} at n_a = {n}")
        ins = [f"{counts[k]:.0f}" if k in counts else "–" for k in ("per_sample", "batched")]
        print(f"| {n} | {m_us:.4f} | {b_us:.4f} | {t_us:.4f} | {w_us:.4f} | {t_us / m_us:.0%} |"
              f" {m_us / b_us:.2f} | {ins[0]} | {ins[1]} |", flush=True)
    if a.python:
        python_table(joints[0])
    print(f"load average at the end: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
