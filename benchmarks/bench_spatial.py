#!/usr/bin/env python
"""The spatial model against Pinocchio, side by side in one run; prints three tables.

**Mass matrix** of a 16-link chain (15 revolute joints about random axes on a free-flyer
base, random placements and links, seeded), per configuration, best of ``--repeat`` rounds of
CPU time (``process_time``/``CLOCK_PROCESS_CPUTIME_ID``: robust to the other work of a shared
machine), the rounds interleaved so that all see the same load:

* **snakecg batched**: ``model.mass_matrix(Q)`` of the compiled model, ``SNAKECG_THREADS=1``,
  batches of ``--batch`` configurations;
* **Pinocchio C++**: ``pinocchio::crba`` in a C++ driver written and compiled here with
  ``-O3 -DNDEBUG`` against the pip-installed Pinocchio's headers and library (``cmeel.prefix``
  of the ``pin`` wheel; Eigen from CasADi's wheel), on the same model and configurations, one
  call per configuration (``Convention::LOCAL``, its default, and ``WORLD``; the faster one is
  the anchor); its matrices are checked against snakecg's;
* **Pinocchio Python**: ``pin.crba(model, data, q)`` per configuration;
* **snakecg on two threads**: batches of ``8 --batch`` on every core by the wall clock
  (``SNAKECG_THREADS`` set to the core count), and split in two halves on two threads by hand, timed by
  each thread's own CPU time (``thread_time``): the slower thread's is the wall time on two
  free cores, a figure that the other jobs of a shared machine do not inflate.

**Cold build** of the 16-link model (``--cold``): derive + generate + compile into an empty
cache in a fresh process; wall time and CPU time (the process and its compilers).

**Growth** of the generated code with the link count (``--growth``): bytes of C and CasADi
operations of every generated function at 4, 8, 16 and 32 links, and the exponents
``log(size ratio) / log(2)`` of each doubling.

**Profile** (``--profile``): where the batched mass matrix's time goes: the generated C's
size, the Python call's overhead per batch, and the C driver's parts timed by a harness
compiled around the model's own generated file (the whole driver, the cosines and sines, the
block kernel; the rest is the gather of the inputs and the scatter of the outputs, with the
bytes written per configuration).

Usage: ``python benchmarks/bench_spatial.py [--repeat 5] [--batch 1024] [--cold] [--growth]
[--profile]``.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("SNAKECG_THREADS", "1")

import numpy as np  # noqa: E402

from _machine import cpu_name  # noqa: E402  (benchmarks/_machine.py)

ROOT = Path(__file__).resolve().parent.parent
N_LINKS = 16

_DRIVER = r"""
#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <cstdio>
#include <ctime>
#include <vector>
using namespace pinocchio;
static double now() { timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
                      return t.tv_sec + 1e-9 * t.tv_nsec; }
int main(int argc, char** argv) {
  FILE* f = std::fopen(argv[1], "rb");
  int nl, nq, nv, N, passes;
  if (std::fread(&nl, 4, 1, f) != 1 || std::fread(&N, 4, 1, f) != 1
      || std::fread(&passes, 4, 1, f) != 1) return 2;
  std::vector<double> p(nl * 10 + (nl - 1) * 15);
  if (std::fread(p.data(), 8, p.size(), f) != p.size()) return 2;
  Model m;
  const double* x = p.data();
  JointIndex j = 0;
  for (int i = 0; i < nl; ++i) {
    if (i == 0) j = m.addJoint(0, JointModelFreeFlyer(), SE3::Identity(), "base");
    else {
      Eigen::Matrix3d R; for (int k = 0; k < 9; ++k) R(k % 3, k / 3) = x[k];
      Eigen::Vector3d t(x[9], x[10], x[11]), a(x[12], x[13], x[14]); x += 15;
      j = m.addJoint(j, JointModelRevoluteUnaligned(a.normalized()), SE3(R, t),
                     "j" + std::to_string(i));
    }
    Eigen::Matrix3d I; I << x[4], x[7], x[8], x[7], x[5], x[9], x[8], x[9], x[6];
    m.appendBodyToJoint(j, Inertia(x[0], Eigen::Vector3d(x[1], x[2], x[3]), I),
                        SE3::Identity());
    x += 10;
  }
  nq = m.nq; nv = m.nv;
  std::vector<Eigen::VectorXd> qs(N, Eigen::VectorXd(nq));
  for (int k = 0; k < N; ++k) if (std::fread(qs[k].data(), 8, nq, f) != (size_t) nq) return 2;
  std::fclose(f);
  Data d(m);
  const Convention conv[2] = {Convention::LOCAL, Convention::WORLD};
  for (int c = 0; c < 2; ++c) {
    double best = 1e30;
    for (int r = 0; r < passes; ++r) {
      double t0 = now();
      for (int k = 0; k < N; ++k) crba(m, d, qs[k], conv[c]);
      best = std::min(best, (now() - t0) / N);
    }
    std::printf("%s %.6e\n", c == 0 ? "local" : "world", best);
  }
  crba(m, d, qs[N - 1], Convention::LOCAL);
  Eigen::MatrixXd M = d.M.selfadjointView<Eigen::Upper>();
  FILE* o = std::fopen(argv[2], "wb");
  std::fwrite(M.data(), 8, nv * nv, o);
  std::fclose(o);
  return 0;
}
"""


def robot(rng, n_links):
    import snakecg

    na = n_links - 1

    def inertia():
        a, b = rng.uniform(0.3, 1.0, 2)
        moments = np.array([a, b, rng.uniform(abs(a - b) + 0.05, a + b - 0.05)]) * 1e-2
        Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        I = Q @ np.diag(moments) @ Q.T
        return [I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]]

    return snakecg.SpatialRobot(
        joints=na, mass=rng.uniform(0.5, 2.0, n_links), com=rng.normal(0, 0.05, (n_links, 3)),
        inertia=[inertia() for _ in range(n_links)], joint_xyz=rng.normal(0, 0.15, (na, 3)),
        joint_rpy=rng.uniform(-np.pi, np.pi, (na, 3)), joint_axis=rng.normal(size=(na, 3)))


def _rpy(r, p, y):
    from snakecg.spatial.files import _rpy_matrix

    return _rpy_matrix(r, p, y)


def pinocchio_paths():
    import pinocchio

    prefix = Path(pinocchio.__file__).resolve()
    while prefix.name != "cmeel.prefix":  # the pin wheel's headers and library live there
        if prefix == prefix.parent:
            sys.exit("no cmeel.prefix above the pinocchio package: the C++ anchor needs the "
                     "pip-installed 'pin' wheel")
        prefix = prefix.parent
    import casadi

    eigen = Path(casadi.__file__).parent / "include" / "eigen3"
    return prefix, eigen


def build_driver(work: Path) -> Path:
    prefix, eigen = pinocchio_paths()
    src, exe = work / "crba_driver.cpp", work / "crba_driver"
    src.write_text(_DRIVER)
    cxx = os.environ.get("CXX", "c++")
    defs = ["-DBOOST_MPL_LIMIT_LIST_SIZE=30", "-DBOOST_MPL_LIMIT_VECTOR_SIZE=30",
            "-DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS", "-DBOOST_FUSION_INVOKE_MAX_ARITY=12"]
    cmd = [cxx, "-O3", "-DNDEBUG", "-std=c++17", *defs, f"-I{prefix / 'include'}",
           f"-I{eigen}", str(src), "-o", str(exe), f"-L{prefix / 'lib'}",
           "-lpinocchio_default", f"-Wl,-rpath,{prefix / 'lib'}"]
    print(f"compiling the Pinocchio driver: {' '.join(cmd[:4])} ... (a minute or two)",
          flush=True)
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        sys.exit(f"the C++ driver did not compile:\n{res.stderr[-3000:]}")
    return exe


def driver_input(r, Q, passes, path: Path) -> None:
    rows = []
    for i in range(r.n_links):
        if i > 0:
            j = i - 1
            R = _rpy(*r.joint_rpy[j])
            rows += list(R.ravel(order="F")) + list(r.joint_xyz[j]) + list(r.joint_axis[j])
        rows += [r.mass[i], *r.com[i], *r.inertia[i]]
    with open(path, "wb") as fh:
        np.array([r.n_links, len(Q), passes], dtype=np.int32).tofile(fh)
        np.array(rows, dtype=np.float64).tofile(fh)
        np.ascontiguousarray(Q, dtype=np.float64).tofile(fh)


def mass_matrix_table(args) -> None:
    import pinocchio as pin

    import snakecg
    from snakecg.spatial.files import _rpy_matrix

    rng = np.random.default_rng(30)
    r = robot(rng, N_LINKS)
    model = snakecg.load(r)
    pm = pin.Model()
    jid = pm.addJoint(0, pin.JointModelFreeFlyer(), pin.SE3.Identity(), "base")
    for i in range(r.n_links):
        if i > 0:
            a = np.array(r.joint_axis[i - 1])
            jid = pm.addJoint(jid, pin.JointModelRevoluteUnaligned(a / np.linalg.norm(a)),
                              pin.SE3(_rpy_matrix(*r.joint_rpy[i - 1]),
                                      np.array(r.joint_xyz[i - 1])), f"j{i}")
        xx, yy, zz, xy, xz, yz = r.inertia[i]
        pm.appendBodyToJoint(jid, pin.Inertia(r.mass[i], np.array(r.com[i]), np.array(
            [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])), pin.SE3.Identity())
    pd = pm.createData()
    Q = np.array([pin.randomConfiguration(pm, -np.pi * np.ones(pm.nq), np.pi * np.ones(pm.nq))
                  for _ in range(args.batch)])
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        exe = build_driver(work)
        driver_input(r, Q, 5, work / "in.bin")
        best = {"snakecg": np.inf, "cpp_local": np.inf, "cpp_world": np.inf, "python": np.inf}
        M = model.mass_matrix(Q)
        for rnd in range(args.repeat):
            t = time.process_time()
            for _ in range(args.calls):
                model.mass_matrix(Q)
            best["snakecg"] = min(best["snakecg"],
                                  (time.process_time() - t) / (args.calls * len(Q)))
            out = subprocess.run([str(exe), str(work / "in.bin"), str(work / "M.bin")],
                                 capture_output=True, text=True, check=True).stdout.split()
            best["cpp_local"] = min(best["cpp_local"], float(out[1]))
            best["cpp_world"] = min(best["cpp_world"], float(out[3]))
            t = time.process_time()
            for q in Q[:256]:
                pin.crba(pm, pd, q)
            best["python"] = min(best["python"], (time.process_time() - t) / 256)
            print(f"  round {rnd + 1}: " + ", ".join(f"{k} {v * 1e9:.0f} ns"
                                                    for k, v in best.items()), flush=True)
        Mc = np.fromfile(work / "M.bin").reshape(r.nv, r.nv, order="F")
    # every core (SNAKECG_THREADS set to the core count): wall time of batches of 8 x --batch
    os.environ["SNAKECG_THREADS"] = str(os.cpu_count() or 1)
    Qbig = np.concatenate([Q] * 8)
    wall = cpu_all = np.inf
    calls = max(1, args.calls // 8)
    for _ in range(args.repeat):
        t, c = time.perf_counter(), time.process_time()
        for _ in range(calls):
            model.mass_matrix(Qbig)
        wall = min(wall, (time.perf_counter() - t) / (calls * len(Qbig)))
        cpu_all = min(cpu_all, (time.process_time() - c) / (calls * len(Qbig)))
    # the batch split across two threads by hand (each half one call on one thread), each
    # thread's own CPU time: the slower one is the wall time on two free cores, whatever the
    # other jobs of a shared machine do
    os.environ["SNAKECG_THREADS"] = "1"
    halves = np.array_split(Qbig, 2)

    def half(Qh):
        t = time.thread_time()
        for _ in range(calls):
            model.mass_matrix(Qh)
        return time.thread_time() - t

    from concurrent.futures import ThreadPoolExecutor

    critical = np.inf
    with ThreadPoolExecutor(2) as pool:
        for _ in range(args.repeat):
            critical = min(critical, max(pool.map(half, halves)) / (calls * len(Qbig)))
    err = np.abs(Mc - M[-1]).max() / np.abs(Mc).max()
    cpp = min(best["cpp_local"], best["cpp_world"])
    print(f"\nmass matrix, {N_LINKS} links (n_v = {r.nv}), per configuration, best of "
          f"{args.repeat} rounds (CPU time); snakecg vs Pinocchio C++: {err:.1e} relative")
    print(f"{'':34}{'ns':>10}{'speed-up':>12}")
    print(f"{'snakecg batched (1 thread)':34}{best['snakecg'] * 1e9:10.0f}{'':>12}")
    print(f"{f'snakecg batched ({os.cpu_count()} threads, wall)':34}{wall * 1e9:10.0f}"
          f"{best['snakecg'] / wall:11.1f}x")
    print(f"{'  the same, CPU of all threads':34}{cpu_all * 1e9:10.0f}"
          f"   (wall x threads / CPU: {wall * (os.cpu_count() or 1) / cpu_all:.2f}; above 1: "
          "the cores were shared)")
    print(f"{'snakecg batched (2 threads, critical)':34}{critical * 1e9:10.0f}"
          f"{best['snakecg'] / critical:11.1f}x   (the slower thread's CPU time)")
    for key, label in (("cpp_local", "Pinocchio C++ crba (LOCAL)"),
                       ("cpp_world", "Pinocchio C++ crba (WORLD)"),
                       ("python", "Pinocchio pin.crba from Python")):
        print(f"{label:34}{best[key] * 1e9:10.0f}{best[key] / best['snakecg']:11.1f}x")
    print(f"targets: >= 2x the faster C++ call ({cpp / best['snakecg']:.1f}x on one thread), "
          f">= 10x pin.crba from Python ({best['python'] / best['snakecg']:.1f}x on one thread, "
          f"{best['python'] / wall:.1f}x on every core by the wall clock, "
          f"{best['python'] / critical:.1f}x on two threads by the slower one's CPU time)")


_HARNESS = r"""
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "mass_matrix.c"
static double now(void) { struct timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
                          return t.tv_sec + 1e-9 * t.tv_nsec; }
int main(void) {
  const int N = 1024, NQ = @NQ@, NK = @NK@, NA = @NA@, R = 30;
  double *Q = malloc(8 * N * NQ), *K = malloc(8 * NK), *M = malloc(8 * (size_t) N * @NV@ * @NV@);
  double *in = malloc(8 * 16 * NQ), *cq = malloc(8 * 16 * NA), *sq = malloc(8 * 16 * NA);
  double *out = malloc(8 * 16 * @NV@ * @NV@), best[3] = {1e9, 1e9, 1e9}, t;
  int i, r, k, e;
  for (i = 0; i < N * NQ; ++i) Q[i] = (rand() / (double) RAND_MAX - 0.5) * 6;
  for (i = 0; i < NK; ++i) K[i] = rand() / (double) RAND_MAX;
  for (i = 0; i < 16 * NQ; ++i) in[i] = Q[i];
  const casadi_real* arg[2] = {Q, K};
  casadi_int stride[2] = {NQ, 0};
  casadi_real* res[1] = {M};
  for (r = 0; r < R; ++r) {
    t = now(); @PREFIX@batch_mass_matrix(N, arg, stride, res); t = now() - t;
    if (t < best[0]) best[0] = t;
    t = now();
    for (k = 0; k < N / 16; ++k)
      for (e = 0; e < NA; ++e) snakecg_sincos_block(Q + 16 * e + k, cq + 16 * e, sq + 16 * e);
    t = now() - t;
    if (t < best[1]) best[1] = t;
    t = now();
    for (k = 0; k < N / 16; ++k) @PREFIX@mass_matrix_sincos_block(in, K, cq, sq, out);
    t = now() - t;
    if (t < best[2]) best[2] = t;
  }
  printf("%.6e %.6e %.6e %g\n", best[0] / N, best[1] / N, best[2] / N, M[1] + out[1]);
  return 0;
}
"""


def profile_table(args) -> None:
    """Where the time of the batched 16-link mass matrix goes: the generated code's size, the
    Python call's overhead per batch, and the C driver's parts (a harness compiled here
    around the model's own generated C file: the whole driver, the cosines and sines, the
    block kernel; the rest is the gather of the inputs and the scatter of the outputs)."""
    import json

    import snakecg
    from snakecg import kernels
    from snakecg.native import empty_pointers, int64s, pointers

    rng = np.random.default_rng(30)
    r = robot(rng, N_LINKS)
    model = snakecg.load(r)
    Q = rng.uniform(-np.pi, np.pi, (args.batch, r.nq))
    Q[:, 3:7] /= np.linalg.norm(Q[:, 3:7], axis=1, keepdims=True)
    src = Path(model.folder) / "c" / "mass_matrix.c"
    manifest = json.loads((Path(model.folder) / "manifest.json").read_text())
    ops = next(f["operations"] for f in manifest["functions"] if f["name"] == "mass_matrix")
    fn, K = model.backend._fns["mass_matrix"], model.parameters
    argp, strides = empty_pointers(2), int64s(2)
    argp[0], strides[0], argp[1], strides[1] = Q.ctypes.data, r.nq, K.ctypes.data, 0
    out = np.empty((len(Q), r.nv, r.nv))
    resp = pointers([out.ctypes.data])
    best = {"python": np.inf, "call": np.inf, "raw": np.inf}
    for _ in range(args.repeat * 4):
        for key, run in (("python", lambda: model.mass_matrix(Q)),
                         ("call", lambda: kernels.call(model.backend, "mass_matrix", len(Q),
                                                       q=Q, K=K)),
                         ("raw", lambda: fn(len(Q), argp, strides, resp))):
            t = time.process_time()
            run()
            best[key] = min(best[key], (time.process_time() - t) / len(Q))
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "mass_matrix.c").write_bytes(src.read_bytes())
        text = (_HARNESS.replace("@NQ@", str(r.nq)).replace("@NK@", str(len(K)))
                .replace("@NA@", str(r.joints)).replace("@NV@", str(r.nv))
                .replace("@PREFIX@", manifest["prefix"]))
        (work / "harness.c").write_text(text)
        cc = os.environ.get("CC", "cc")
        print(f"compiling the C harness around {src.name} ({cc} -O2) ...", flush=True)
        subprocess.run([cc, "-O2", "-I", str(work), str(work / "harness.c"), "-o",
                        str(work / "harness"), "-lm"], check=True, capture_output=True)
        driver, sincos, kernel = (float(x) for x in subprocess.run(
            [str(work / "harness")], capture_output=True, text=True,
            check=True).stdout.split()[:3])
    written = 8 * r.nv * r.nv
    print(f"\nprofile of the batched mass matrix, {N_LINKS} links, batches of {len(Q)} "
          f"(CPU time per configuration, best of the rounds)")
    print(f"  generated C of mass_matrix: {src.stat().st_size:,} bytes, {ops:,} CasADi "
          f"operations per configuration")
    print(f"  model.mass_matrix(Q)          {best['python'] * 1e9:8.0f} ns   (Python: "
          f"{(best['python'] - best['raw']) * 1e9:.0f} ns of it, "
          f"{(best['python'] - best['raw']) * len(Q) * 1e6:.1f} us per call)")
    print(f"  kernels.call                  {best['call'] * 1e9:8.0f} ns")
    print(f"  the C driver alone (ctypes)   {best['raw'] * 1e9:8.0f} ns")
    print(f"  C harness: whole driver       {driver * 1e9:8.0f} ns")
    print(f"    cosines and sines           {sincos * 1e9:8.0f} ns")
    print(f"    block kernel ({ops:,} ops)   {kernel * 1e9:8.0f} ns   "
          f"({ops / (kernel * 1e9):.1f} operations per ns)")
    print(f"    gather + scatter + rest     {(driver - sincos - kernel) * 1e9:8.0f} ns   "
          f"({written:,} bytes written per configuration: "
          f"{written / max(driver - sincos - kernel, 1e-12) / 1e9:.1f} GB/s)")


def cold_table() -> None:
    code = ("import snakecg, time\n"
            "t = time.time()\n"
            "snakecg.load(snakecg.SpatialRobot(joints=15), progress=lambda m: print("
            "f'{time.time() - t:6.1f} s  {m}', flush=True))\n"
            "print(f'{time.time() - t:6.1f} s  loaded', flush=True)\n")
    with tempfile.TemporaryDirectory() as cache:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t = time.perf_counter()
        subprocess.run([sys.executable, "-c", code], check=True,
                       env={**os.environ, "SNAKECG_CACHE_DIR": cache})
        wall = time.perf_counter() - t
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    print(f"\ncold derive + generate + compile, {N_LINKS} links: {wall:.1f} s wall, {cpu:.1f} s "
          f"CPU (Python and the compilers); load average {os.getloadavg()[0]:.1f}")


def growth_table() -> None:
    from snakecg_derive.spatial.render import render_spatial_model

    rows = {}
    for n in (4, 8, 16, 32):
        t = time.perf_counter()
        rendered = render_spatial_model(n)
        c_bytes = sum(len(v.encode()) for k, v in rendered.files.items() if k.endswith(".c"))
        ops = sum(f["operations"] or 0 for f in rendered.manifest["functions"])
        mm = next(f["operations"] for f in rendered.manifest["functions"]
                  if f["name"] == "mass_matrix")
        rows[n] = (c_bytes, ops, mm, time.perf_counter() - t)
        print(f"  rendered {n} links in {rows[n][3]:.1f} s", flush=True)
    print("\ngenerated code by link count (exponent of each doubling)")
    print(f"{'links':>6}{'C bytes':>12}{'exp':>6}{'operations':>12}{'exp':>6}"
          f"{'M ops':>9}{'exp':>6}")
    prev = None
    for n, (b, o, m, _) in rows.items():
        e = ["" if prev is None else f"{np.log2(x / y):.2f}" for x, y in
             zip((b, o, m), prev or (1, 1, 1))]
        print(f"{n:6d}{b:12d}{e[0]:>6}{o:12d}{e[1]:>6}{m:9d}{e[2]:>6}")
        prev = (b, o, m)
    n = np.log(list(rows))
    fit = np.polyfit(n, np.log([v[0] for v in rows.values()]), 1)[0]
    print(f"least-squares exponent of the C bytes over 4..32 links: {fit:.2f} (target <= 2.2)")


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--repeat", type=int, default=5, help="interleaved rounds (best is kept)")
    p.add_argument("--batch", type=int, default=1024, help="configurations per batch")
    p.add_argument("--calls", type=int, default=20, help="batched calls per round")
    p.add_argument("--cold", action="store_true", help="also time a cold build")
    p.add_argument("--growth", action="store_true", help="also measure the code's growth")
    p.add_argument("--profile", action="store_true",
                   help="also profile the batched mass matrix (Python, gather/scatter, kernel)")
    args = p.parse_args()
    print(f"machine: {cpu_name()}, {os.cpu_count()} cores, load average "
          f"{os.getloadavg()[0]:.1f}")
    mass_matrix_table(args)
    if args.profile:
        profile_table(args)
    print(f"load average at the end: {os.getloadavg()[0]:.1f}")
    if args.cold:
        cold_table()
    if args.growth:
        growth_table()


if __name__ == "__main__":
    main()
