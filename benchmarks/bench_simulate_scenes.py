"""Benchmark: a general scene over time, snakecg's time stepping against MuJoCo's ``mj_step``
on the matched scene, side by side in one run.

The scene is ``examples/scenes/pegs_row.toml``: a 10-joint snake (capsule links, radius
0.02 m) among 10 pegs on an isotropic Coulomb ground (mu 0.1), driven by the serpenoid PD law
of the obstacle-aided locomotion page (amplitude 0.5 rad, 1 Hz, phase lag 2 pi / 5, kp 10,
kd 0.3) from the serpenoid's shape, for ``--duration`` seconds (default 2).

* **snakecg**: ``model.simulate`` at ``dt = 1e-3`` (velocity-level steps on the exact solve,
  contact onset by root finding); its penetration bound is its contact tolerance (1e-5 of the
  scene's size), held on every step. The run's loop is the engine's (``scene_run.c``, the
  serpenoid PD law evaluated in C); beside it the same law as a callable of the caller's own
  (the loop returns to Python for the torque at every step), the exact solve's share of the
  engine's step and the figure the rest of the step would reach were the solve free; the
  same run with every step's solve from scratch (``SNAKECG_SCENE_COLD_START=1``: the anchor
  of the warm start, each step's solve started from the last step's pieces); and a
  batch of 8 runs (gait amplitudes) in one ``simulate_scene_batch`` call.
* **the paper's push**: ``model.simulate(..., contacts="geometry")`` of the paper's 3-joint
  scene (kappa 100, q0 = (0, 0, 0, 30, -45, 60) deg, tau = (0.05, 0, -0.02) N m, 0.5 s), as
  times real time, the first call in the process apart (imports, the plate model's load),
  and from scratch.
* **MuJoCo**: ``mj_step`` on tests/mujoco_pegs.py's matched model (COM
  spheres on a condim-3 floor, noslip 10, frictionless capsule-peg contacts, solref
  ``(2 timestep, 1)``) at the time steps of ``STEPS``; reported: the deepest capsule-peg or
  capsule-capsule overlap over the run, the speed, and the largest time step whose overlap
  stays within snakecg's tolerance (the ratio is taken there). The torque is the same law,
  held over 1 ms: evaluated in Python once per millisecond, the millisecond's steps in one
  ``mj_step(..., nstep)`` call (no Python per step). The overlap is measured on a second,
  identical run, step by step, outside the timing.

The figure is simulated seconds per CPU second (``time.process_time``, best of
``--repeat``). Prints the machine's load before and after.

    python benchmarks/bench_simulate_scenes.py [--duration 2] [--repeat 2] [--primal]

``--primal``: instead, the pegs row's run and the paper's push with each warm step's piece
solved in the primal (scene_primal.c) and without it, alternated in one process.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))  # the matched MuJoCo model (tests/mujoco_pegs.py)

from snakecg.scenes import load_scene  # noqa: E402
from snakecg.scenes.stepping import SceneState  # noqa: E402
from snakecg.scenes.toml_reading import read_scene  # noqa: E402
from snakecg.simulate import serpenoid_controller  # noqa: E402

STEPS = (1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5)
COLD = "SNAKECG_SCENE_COLD_START"


@contextlib.contextmanager
def cold_start():
    """Every step's solve from scratch (not from the last step's pieces) inside."""
    old = os.environ.get(COLD)
    os.environ[COLD] = "1"
    try:
        yield
    finally:
        if old is None:
            del os.environ[COLD]
        else:
            os.environ[COLD] = old


def setup():
    scene = read_scene(ROOT / "examples" / "scenes" / "pegs_row.toml")
    model = load_scene(scene)
    q0 = np.zeros(13)
    q0[3:] = 0.5 * np.sin(np.arange(10) * 2 * np.pi / 5)
    gait = serpenoid_controller(model, amplitude=0.5, frequency=1.0, phase_lag=2 * np.pi / 5,
                                kp=10.0, kd=0.3, tau_max=None)
    return scene, model, q0, gait


def run_mujoco(scene, model, q0, gait, ts, duration, measure: bool):
    """CPU seconds (``measure`` False: the timed run, nothing but the law and mj_step) or the
    deepest overlap over every step (``measure`` True, the same run), and the COM at the
    end."""
    from mujoco_pegs import MatchedPegs

    mj = MatchedPegs(scene, timestep=ts)
    mj.set_state(q0)
    hold = max(1, int(round(1e-3 / ts)))
    n = int(round(duration / ts))
    depth = 0.0
    none = np.zeros((0, 3))
    t0 = time.process_time()
    if not measure:  # the law once per hold, the hold's steps in one call (mj_step's nstep)
        for k in range(0, n, hold):
            q, v = mj.state()
            mj.step(gait(k * ts, SceneState(k * ts, q, v, none, none)), min(hold, n - k))
    else:
        for k in range(n):
            if k % hold == 0:
                q, v = mj.state()
                tau = gait(k * ts, SceneState(k * ts, q, v, none, none))
            mj.step(tau)
            depth = max(depth, mj.peg_depth())
    cpu = time.process_time() - t0
    return depth if measure else cpu, model.com(mj.state()[0])


def solve_share(model, run) -> float:
    """The exact solve's share of the engine's step: the step (from the last step's pieces, as
    in a run), and the solve alone on the same problem from the same pieces
    (core_scene_solve_s), timed from one state of the run, 2000 times each."""
    from snakecg.scenes.solve import INFO
    from snakecg.scenes.stepping import GAP_BAND, _Stepper

    h = 1e-3
    st = _Stepper(model, run.tolerance, np.zeros(3 * model.scene.n_objects))
    k = len(run.t) // 2
    st.x[:] = np.concatenate((run.q[k], run.q_obj[k].reshape(-1)))
    st.V[:] = np.concatenate((run.v[k], run.v_obj[k].reshape(-1)))
    st.call(0.0)
    st.call(h)  # the pieces of this step: the start of the next
    # (by name: an accepted step swaps the stepper's buffers of the rows at x and at its end)
    keep = ("x", "V", "M", "A", "par", "out", "kind", "start", "pieces")
    saved, nfrom = [getattr(st, name).copy() for name in keep], st.args.nfrom
    m, nb, ns, n = int(st.out[2]), int(st.out[3]), st.ns, st.n
    f = st.M @ st.V  # no torque: M V - h bias(q, v)
    f[:ns] -= h * np.asarray(model.bias_forces(st.x[:ns], st.V[:ns])).reshape(-1)
    par = st.par[:nb] * h
    off = np.zeros(m)
    for c in st.rows().contacts:
        off[c.row] = c.gap / h if abs(c.gap) > GAP_BAND * run.tolerance else 0.0
    start = st.pieces[:3 * nb].reshape(nb, 3) * np.array([1.0, h, h])
    w, lam, a = np.zeros(m), np.zeros(m), np.zeros(n)
    state, info = np.zeros(nb), np.zeros(len(INFO))
    kind, rstart, A = st.kind[:nb].copy(), st.start[:nb].copy(), st.A[:m].copy()
    args = (n, m, nb, st.M.ctypes.data, f.ctypes.data, A.ctypes.data, off.ctypes.data,
            kind.ctypes.data, rstart.ctypes.data, par.ctypes.data, 200000, start.ctypes.data,
            lam.ctypes.data, a.ctypes.data, w.ctypes.data, state.ctypes.data, info.ctypes.data)
    fn = model.core.scene_solve_s
    t0 = time.process_time()
    for _ in range(2000):
        fn(*args)
    t_solve = time.process_time() - t0
    t_step = 0.0
    for _ in range(2000):
        for name, src in zip(keep, saved):
            getattr(st, name)[...] = src
        st.args.nfrom = nfrom
        t0 = time.process_time()
        st.call(h)
        t_step += time.process_time() - t0
    if not np.allclose(a, st.Vp, rtol=0, atol=1e-9 * max(1.0, np.abs(a).max())):
        raise RuntimeError("the solve alone is not the step's problem")
    return t_solve / t_step


def batch(model, q0, duration, repeat) -> None:
    """8 runs (gait amplitudes 0.3 .. 0.65) in one simulate_scene_batch call."""
    from snakecg.scenes import simulate_scene_batch

    gaits = [serpenoid_controller(model, amplitude=amp, frequency=1.0,
                                  phase_lag=2 * np.pi / 5, kp=10.0, kd=0.3, tau_max=None)
             for amp in np.linspace(0.3, 0.65, 8)]
    best = np.inf
    for _ in range(repeat):
        t0 = time.process_time()
        out = simulate_scene_batch(model, q0, duration, tau=gaits)
        best = min(best, time.process_time() - t0)
    print(f"  batch of 8 runs: {8 * duration / best:8.3f} simulated s per CPU s "
          f"({int(out.completed.sum())} completed, SNAKECG_THREADS "
          f"{os.environ.get('SNAKECG_THREADS', 'unset')})")


def paper_push(repeat) -> None:
    """The paper's push with contacts from geometry, times real time (CPU)."""
    import snakecg

    q = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
    tau = np.array([0.05, 0.0, -0.02])
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0))
    t0 = time.process_time()
    run = sm.simulate(q, tau, 0.5, contacts="geometry")
    first = time.process_time() - t0
    best, cold = np.inf, np.inf
    for _ in range(max(repeat, 20)):
        t0 = time.process_time()
        sm.simulate(q, tau, 0.5, contacts="geometry")
        best = min(best, time.process_time() - t0)
        with cold_start():
            t0 = time.process_time()
            sm.simulate(q, tau, 0.5, contacts="geometry")
            cold = min(cold, time.process_time() - t0)
    print(f"the paper's push (3 joints, contacts='geometry', 0.5 s): {run.status}, "
          f"{run.steps} steps, {0.5 / best:.0f} x real time ({best * 1e3:.2f} ms; the model's "
          f"first call, the plate model's load with it, {first * 1e3:.0f} ms); every solve "
          f"from scratch: {0.5 / cold:.0f} x real time")
    from snakecg.scenes.paper import _plate_model

    plate = _plate_model(sm)
    steps = np.inf
    for _ in range(max(repeat, 20)):
        t0 = time.process_time()
        prun = plate.simulate(q, 0.5, tau=tau)
        steps = min(steps, time.process_time() - t0)
    share = solve_share(plate, prun)
    # the stepping is part of the run: a noisy minimum above the run's is capped by it
    rest = best - share * min(steps, best)
    free = f"{0.5 / rest:.0f} x real time" if rest > 0 else "not resolved in this run (noise)"
    print(f"  of it the stepping {steps * 1e3:.2f} ms, the exact solve {100 * share:.0f} % of "
          f"a step; were the solve free: {free}")


def primal_on_off(model, q0, gait, duration, repeat) -> None:
    """The pegs row's run and the paper's push with each step's warm start solved in the
    primal (scene_primal.c) and without it (``core_scene_primal``'s switch), alternated."""
    import snakecg
    from snakecg.scenes.paper import _plate_model

    q = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
    tau = np.array([0.05, 0.0, -0.02])
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0))
    sm.simulate(q, tau, 0.5, contacts="geometry")
    plate = _plate_model(sm).core
    pegs, push = {1: np.inf, 0: np.inf}, {1: np.inf, 0: np.inf}
    counts = np.zeros(2)
    for _ in range(repeat):
        for mode in (1, 0):
            model.core.scene_primal(mode, None)
            plate.scene_primal(mode, None)
            t0 = time.process_time()
            model.simulate(q0, duration, tau=gait, dt=1e-3)
            pegs[mode] = min(pegs[mode], time.process_time() - t0)
            for _ in range(10):
                t0 = time.process_time()
                sm.simulate(q, tau, 0.5, contacts="geometry")
                push[mode] = min(push[mode], time.process_time() - t0)
    model.core.scene_primal(1, counts.ctypes.data)
    model.simulate(q0, duration, tau=gait, dt=1e-3)
    model.core.scene_primal(1, counts.ctypes.data)
    plate.scene_primal(1, None)
    print(f"the warm step's piece in the primal, and without (alternated, best of {repeat}): "
          f"pegs row {duration / pegs[1]:.1f} against {duration / pegs[0]:.1f} simulated s "
          f"per CPU s ({pegs[0] / pegs[1]:.2f}x; the primal answered {counts[1]:.0f} of "
          f"{counts[0]:.0f} warm starts); the paper's push {0.5 / push[1]:.0f} against "
          f"{0.5 / push[0]:.0f} x real time ({push[0] / push[1]:.2f}x)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--duration", type=float, default=2.0)
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--primal", action="store_true",
                    help="only the runs with and without the primal piece, alternated")
    a = ap.parse_args()
    print(f"machine: {platform.processor() or platform.machine()}, load {os.getloadavg()}")
    scene, model, q0, gait = setup()
    if a.primal:
        primal_on_off(model, q0, gait, a.duration, a.repeat)
        print(f"load after: {os.getloadavg()}")
        return
    best, run = np.inf, None
    for _ in range(a.repeat):
        t0 = time.process_time()
        run = model.simulate(q0, a.duration, tau=gait, dt=1e-3)
        best = min(best, time.process_time() - t0)
    com = model.com(run.q)
    worst = max(0.0, -float(np.min(run.min_gap)))
    print(f"snakecg: {run.status}, {run.steps} steps, {len(run.events)} impacts, deepest "
          f"overlap {worst:.3g} m (tolerance {run.tolerance:.3g} m), COM moved "
          f"{np.hypot(*(com[-1] - com[0])):.4f} m")
    print(f"  {a.duration / best:8.3f} simulated s per CPU s ({best / run.steps * 1e3:.3f} ms "
          f"per step), the law in the engine's loop")
    cold = np.inf
    with cold_start():
        for _ in range(a.repeat):
            t0 = time.process_time()
            model.simulate(q0, a.duration, tau=gait, dt=1e-3)
            cold = min(cold, time.process_time() - t0)
    print(f"  {a.duration / cold:8.3f} simulated s per CPU s, every step's solve from scratch "
          f"({COLD}=1: the anchor; the warm start {cold / best:.2f}x)")
    caller = np.inf
    for _ in range(a.repeat):
        t0 = time.process_time()
        model.simulate(q0, a.duration, tau=lambda t, state: gait(t, state), dt=1e-3)
        caller = min(caller, time.process_time() - t0)
    print(f"  {a.duration / caller:8.3f} simulated s per CPU s, the law a callable of the "
          "caller's own (Python at every step)")
    share = solve_share(model, run)
    print(f"  the exact solve's share of the engine's step: {100 * share:.0f} %; were it free: "
          f"{a.duration / (best * (1 - share)):.1f} simulated s per CPU s")
    batch(model, q0, a.duration, a.repeat)
    paper_push(a.repeat)
    try:
        import mujoco
    except ImportError:
        print("MuJoCo: not installed")
        return
    print(f"MuJoCo {mujoco.__version__} mj_step (matched scene, nstep per 1 ms hold):")
    chosen = None
    for ts in STEPS:
        depth, com_mj = run_mujoco(scene, model, q0, gait, ts, a.duration, True)
        cpu, _ = run_mujoco(scene, model, q0, gait, ts, a.duration, False)
        ok = depth <= run.tolerance
        if ok and chosen is None:
            chosen = (ts, cpu)
        print(f"  timestep {ts:7.1e} s: {a.duration / cpu:8.3f} simulated s per CPU s, "
              f"deepest overlap {depth:.3g} m{' (within)' if ok else ''}, COM end differs "
              f"from snakecg's by {np.hypot(*(com_mj - com[-1])):.4f} m")
    if chosen:
        print(f"speed ratio at MuJoCo's largest step within the bound ({chosen[0]:.1e} s): "
              f"snakecg / MuJoCo = {chosen[1] / best:.3f}")
    print(f"load after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
