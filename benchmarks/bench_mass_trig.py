#!/usr/bin/env python
"""How much of the generated mass matrix's time is its sines and cosines; prints a table.

For each checked-in joint count ``n_a`` asked for (default 3), in C, on the same random
configurations (uniform in [-pi, pi], as in bench_pipeline.py):

* **M**: the generated ``mass_matrix`` of ``generated/na<N>/c/mass_matrix.c`` called once per
  configuration (the C function itself: no Python, no batched driver);
* **sincos**: the ``n_a + 1`` calls ``sincos(theta)``, ``sincos(q_i)`` alone, which is what
  every generated kinematic function calls;
* their ratio.

Both are compiled with the compiler and ``-O2`` that ``snakecg`` uses and timed in one
process, alternating, best of several passes of CPU time (``CLOCK_PROCESS_CPUTIME_ID``), so
that both see the same load. Usage: ``python benchmarks/bench_mass_trig.py [--joints 3,6]``.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
from pathlib import Path

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
static double now(void) {
  struct timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); return t.tv_sec + 1e-9 * t.tv_nsec;
}
int main(void) {
  const int N = 100000, nq = %(nq)d, nK = %(nK)d, nM = nq * nq, na = %(na)d;
  double *Q = malloc(sizeof(double) * N * nq), *out = malloc(sizeof(double) * N * nM);
  double *cs = malloc(sizeof(double) * N * 2 * (na + 1)), K[%(nK)d], w[%(nw)d];
  casadi_int iw[%(niw)d];
  double best_m = 1e9, best_t = 1e9, check = 0;
  int i, k, rep;
  srand(1);
  for (i = 0; i < N * nq; ++i) Q[i] = M_PI * (2.0 * rand() / RAND_MAX - 1.0);
  for (i = 0; i < nK; ++i) K[i] = 0.1 + 0.01 * i;
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
  }
  for (i = 0; i < N * nM; ++i) check += out[i];
  for (i = 0; i < N * 2 * (na + 1); ++i) check += cs[i];
  printf("%%.5f %%.5f %%g\n", best_m / N * 1e6, best_t / N * 1e6, check);
  return 0;
}
"""


def measure(joints: int, cc: str) -> tuple[float, float]:
    import json

    folder = ROOT / "generated" / f"na{joints}"
    manifest = json.loads((folder / "manifest.json").read_text())
    (sig,) = [f for f in manifest["functions"] if f["name"] == "mass_matrix"]
    nq = manifest["n_coordinates"]
    with tempfile.TemporaryDirectory(prefix="bench-mass-trig-") as tmp:
        harness = Path(tmp) / "harness.c"
        harness.write_text(_HARNESS % {
            "symbol": sig["symbol"], "nq": nq, "nK": manifest["n_parameters"], "na": joints,
            "nw": sig["sz_w"] + 1, "niw": sig["sz_iw"] + 1})
        exe = Path(tmp) / "bench"
        subprocess.run([cc, "-O2", "-o", str(exe), str(harness),
                        str(folder / "c" / "mass_matrix.c"), "-lm"], check=True)
        out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    m_us, t_us, _ = (float(x) for x in out.split())
    return m_us, t_us


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--joints", default="3", help="comma-separated checked-in joint counts")
    a = p.parse_args(argv)
    cc = os.environ.get("CC", "cc")
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"machine: {os.cpu_count()} CPUs, {cpu_name()}; Python {platform.python_version()};"
          f" {cc} -O2; load average {load}")
    print("| n_a | M µs/cfg | sincos µs/cfg | sincos / M |")
    print("|---:|---:|---:|---:|")
    for n in (int(x) for x in a.joints.split(",")):
        m_us, t_us = measure(n, cc)
        print(f"| {n} | {m_us:.4f} | {t_us:.4f} | {t_us / m_us:.0%} |", flush=True)
    print(f"load average at the end: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
