"""Benchmark of the simulation: a 0.5 s push with a constant torque.

For each joint count (3, 6, 10) and scenario: the snake starts at rest in a bent shape
(joint angles cycling through 30, -35, 25 degrees), touching the object (kappa = 10) with
link 1; the torque is fixed on the paper's input ellipsoid (eq. 31) scaled by ``radius``,
``tau^T B^T M_s^-1 B tau = radius^2``, along the pattern (1, 0, -0.4, 1, 0, -0.4, ...), with the
sign that keeps the contact at t = 0: radius 1 is the paper's region (the object moves a few
mm in 0.5 s), radius 4 a hard push (centimetres, wheels breaking away).

Accuracy is the largest position error (m) of every link COM and of the object at the end,
against a reference run at rtol = 1e-13, atol = 1e-15. For each tolerance the table gives the
wall-clock time of ``model.simulate`` (median of ``--repeat`` runs, output at the end only,
model already loaded and compiled), the error and the number of right-hand-side evaluations;
``target`` marks the loosest tolerance that reaches 1e-6 m (the target: under 0.2 s
at n_a = 3), ``default`` the default settings (rtol 1e-9, atol 1e-11, Baumgarte 10 1/s).

    python benchmarks/bench_simulate.py [--joints 3 6 10] [--radius 1 4]
        [--repeat 5]

``--compare`` prints instead, for each case at the default settings (output at the end),
the compiled segments against solve_ivp in the same run: simulated seconds per CPU second
(``time.process_time``, median of ``--repeat`` runs) of the whole ``model.simulate`` call and
of its segment integrations alone (``summary["integrator"]["segment_cpu_s"]``; the rest is
the Python event handling, the setup and the assembly of the trajectory), of the whole call
with the default 400 output samples, of the compiled call followed by the first read of its
``summary`` (computed on first access), the largest position difference between the two and
the compiled run's error against the reference.

    python benchmarks/bench_simulate.py --compare --joints 3 [--repeat 20]

These pushes turn the contact link against the object, which it enters within the first
milliseconds (docs/how-to/simulate.md, the contact check): every run here integrates the whole push
with ``geometry_check="report"`` (the check finds it, then the integration goes on as
without it). ``--check`` measures the check itself where it runs throughout: a push that
stays physical (a symmetric W of 4 joints pushing with its middle link, or of 2 joints),
each call with the check (``"stop"``) against the same call without it (``"off"``),
alternated, CPU time per call (median of ``--repeat``), output at the end and with the
default 400 samples.

    python benchmarks/bench_simulate.py --check [--repeat 200]
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time

import numpy as np

import snakecg

DURATION = 0.5
ACCURACY = 1e-6  # m
RTOLS = (1e-5, 1e-6, 1e-7, 1e-8, 1e-10)
SCENARIOS = ("frictionless", "wheels", "ideal_wheels")
CHECK = "report"  # the contact check finds the link in the object at once, then reports only


def setup(joints: int, scenario: str, radius: float = 1.0):
    scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, kappa=10.0)
    sm = snakecg.load(scene)
    pattern_q = np.deg2rad([30.0, -35.0, 25.0])
    q0 = np.concatenate([[0.0, 0.0, 0.0], np.resize(pattern_q, joints)])
    direction = np.resize([1.0, 0.0, -0.4], joints)
    N = sm.maps(q0)["input_metric"]
    tau = radius * direction / np.sqrt(direction @ N @ direction)
    if not sm.forward(q0, tau).contact:
        tau = -tau
    return sm, q0, tau


def positions(sm, traj) -> np.ndarray:
    """Link COM positions and the object position at the end (m)."""
    P = sm.link_poses(traj.q[-1])[:, :2]
    return np.vstack([P, traj.q_obj[-1, :2]])


def timed(fn, repeat: int):
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def case(joints: int, radius: float, scenario: str, repeat: int) -> None:
    sm, q0, tau = setup(joints, scenario, radius)
    sm.simulate(q0, tau, 0.01, geometry_check=CHECK)  # warm up (first calls, imports)
    ref = sm.simulate(q0, tau, DURATION, rtol=1e-13, atol=1e-15, output_dt=DURATION,
                      geometry_check=CHECK)
    p_ref = positions(sm, ref)
    moved = np.hypot(*(ref.q_obj[-1, :2] - ref.q_obj[0, :2]))

    def measure(name, **kw):
        t, traj = timed(lambda: sm.simulate(q0, tau, DURATION, geometry_check=CHECK, **kw),
                        repeat)
        return name, t, np.abs(positions(sm, traj) - p_ref).max(), traj

    rows = [measure(f"rtol {rtol:.0e}", rtol=rtol, atol=rtol * 1e-2, output_dt=DURATION)
            for rtol in RTOLS]
    ok = [r for r in rows if r[2] <= ACCURACY]
    target = ok[0][0] if ok else None
    rows += [measure("default", output_dt=DURATION),
             measure("default, no Baumgarte", stabilization=0.0, output_dt=DURATION),
             measure("default, 400 output samples")]
    for name, t, err, traj in rows:
        note = "target" if name == target else ""
        if name == "default":
            note = "default" + (" (meets 1e-6 m)" if err <= ACCURACY else "")
        print(f"{joints:>3} {radius:>2g} {scenario:<13} {name:<27} {t:>9.4f} {err:>10.2e}"
              f" {traj.summary['integrator']['rhs_evaluations']:>6} {len(traj.events):>6}"
              f"  {note}")
    kinds = sorted({e.kind for e in ref.events})
    print(f"    object moved {moved * 1e3:.1f} mm; events in the reference: "
          f"{', '.join(kinds) or 'none'} ({len(ref.events)})\n")


def cpu_timed(fn, repeat: int):
    """Median CPU seconds of ``fn()`` over ``repeat`` runs, with the median of its segment
    integrations' CPU seconds, the median CPU seconds of the call and the first read of its
    summary together, and the last result."""
    times, seg, full, out = [], [], [], None
    for _ in range(repeat):
        t0 = time.process_time()
        out = fn()
        t1 = time.process_time()
        summary = out.summary
        full.append(time.process_time() - t0)
        times.append(t1 - t0)
        seg.append(summary["integrator"]["segment_cpu_s"])
    return statistics.median(times), statistics.median(seg), statistics.median(full), out


def compare(joints: int, radius: float, scenario: str, repeat: int) -> None:
    sm, q0, tau = setup(joints, scenario, radius)
    for integrator in ("scipy", "compiled"):
        sm.simulate(q0, tau, 0.01, integrator=integrator, geometry_check=CHECK)  # warm up
    ref = sm.simulate(q0, tau, DURATION, rtol=1e-13, atol=1e-15, output_dt=DURATION,
                      integrator="scipy", geometry_check=CHECK)
    p_ref = positions(sm, ref)
    res, full = {}, {}
    for integrator in ("scipy", "compiled"):
        res[integrator] = cpu_timed(lambda i=integrator: sm.simulate(
            q0, tau, DURATION, output_dt=DURATION, integrator=i, geometry_check=CHECK),
            repeat)
        full[integrator] = cpu_timed(lambda i=integrator: sm.simulate(
            q0, tau, DURATION, integrator=i, geometry_check=CHECK), repeat)[0]
    (ts, ss, _, a), (tc, sc, tcs, b) = res["scipy"], res["compiled"]
    fs, fc = full["scipy"], full["compiled"]
    diff = np.abs(positions(sm, a) - positions(sm, b)).max()
    err = np.abs(positions(sm, b) - p_ref).max()
    print(f"{joints:>3} {radius:>2g} {scenario:<13} {len(b.events):>6}"
          f" {DURATION / ts:>9.0f} {DURATION / tc:>9.0f} {ts / tc:>6.1f}"
          f" {DURATION / ss:>9.0f} {DURATION / sc:>9.0f} {ss / sc:>6.1f}"
          f" {DURATION / fs:>9.0f} {DURATION / fc:>9.0f} {fs / fc:>6.1f}"
          f" {DURATION / tcs:>9.0f} {diff:>9.1e} {err:>9.1e}")


def _load() -> str:
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def _machine() -> None:
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}; load average before: {_load()}")


def main_compare(args) -> None:
    _machine()
    print(f"{DURATION} s push, default settings (DOP853, rtol 1e-9, atol 1e-11); simulated s per"
          f" CPU s (median of {args.repeat}): call = whole simulate call, output at the end; seg"
          " = its segment integrations alone; 400 = whole call with the default 400 output"
          " samples; +summary = compiled call and the first read of its summary; diff ="
          " compiled vs scipy, error = compiled vs rtol 1e-13 (largest link/object position at"
          " the end, m)\n")
    header = (f"{'n_a':>3} {'r':>2} {'scenario':<13} {'events':>6} {'call:scipy':>9}"
              f" {'compiled':>9} {'x':>6} {'seg:scipy':>9} {'compiled':>9} {'x':>6}"
              f" {'400:scipy':>9} {'compiled':>9} {'x':>6} {'+summary':>9} {'diff':>9}"
              f" {'error':>9}")
    print(header)
    print("-" * len(header))
    for joints in args.joints:
        for radius in args.radius:
            for scenario in args.scenarios:
                compare(joints, radius, scenario, args.repeat)
    print(f"\nload average after: {_load()}")


def main_check(args) -> None:
    """The contact check's cost where it runs throughout (a push that stays physical)."""
    _machine()
    print(f"{DURATION} s symmetric push (contact link in the middle), default settings; CPU ms "
          f"per simulate call (median of {args.repeat}, check and no check alternated)\n")
    header = (f"{'n_a':>3} {'scenario':<13} {'output':<11} {'off (ms)':>9} {'stop (ms)':>9}"
              f" {'overhead':>9} {'samples':>7} {'status':<10}")
    print(header)
    print("-" * len(header))
    shapes = {2: ([60.0, 60.0], [-0.05, -0.05]), 4: ([30.0, 40.0, 40.0, 30.0],
                                                      [0.05, 0.02, 0.02, 0.05])}
    for joints, (q_deg, tau) in shapes.items():
        for scenario in args.scenarios:
            scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, kappa=10.0,
                                  contact_link=joints // 2 + 1)
            sm = snakecg.load(scene)
            q0 = np.r_[0.0, 0.0, 0.0, np.deg2rad(q_deg)]
            for output in (DURATION, None):
                times = {"off": [], "stop": []}
                for mode in ("off", "stop"):  # warm up
                    sm.simulate(q0, tau, DURATION, output_dt=output, geometry_check=mode)
                for _ in range(args.repeat):
                    for mode in ("off", "stop"):
                        t0 = time.process_time()
                        traj = sm.simulate(q0, tau, DURATION, output_dt=output,
                                           geometry_check=mode)
                        times[mode].append(time.process_time() - t0)
                off, on = (statistics.median(times[m]) for m in ("off", "stop"))
                print(f"{joints:>3} {scenario:<13} {'end' if output else '400 samples':<11}"
                      f" {off * 1e3:>9.3f} {on * 1e3:>9.3f} {on / off - 1:>+9.1%}"
                      f" {traj.n_samples:>7} {traj.summary['status']:<10}")
    print(f"\nload average after: {_load()}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--joints", type=int, nargs="+", default=[3, 6, 10])
    ap.add_argument("--scenarios", nargs="+", default=list(SCENARIOS), choices=SCENARIOS)
    ap.add_argument("--radius", type=float, nargs="+", default=[1.0, 4.0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--compare", action="store_true",
                    help="compiled segments vs solve_ivp, simulated s per CPU s")
    ap.add_argument("--check", action="store_true",
                    help="the contact check's cost on a push that stays physical")
    args = ap.parse_args()
    if args.compare:
        main_compare(args)
        return
    if args.check:
        main_check(args)
        return
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}")
    print(f"{DURATION} s push, constant torque on the input ellipsoid x radius r, kappa = 10; "
          "error = largest link/object position error at the end (m)\n")
    header = (f"{'n_a':>3} {'r':>2} {'scenario':<13} {'settings':<27} {'time (s)':>9}"
              f" {'error (m)':>10} {'rhs':>6} {'events':>6}  note")
    print(header)
    print("-" * len(header))
    for joints in args.joints:
        for radius in args.radius:
            for scenario in args.scenarios:
                case(joints, radius, scenario, args.repeat)


if __name__ == "__main__":
    main()
