"""Benchmark: the paper's 0.5 s push at n_a = 3, snakecg's ``simulate`` against MuJoCo's
``mj_step`` on the matched frictionless scene, side by side in one run.

The push is bench_simulate.py's (3 joints bent 30, -35, 25 degrees, contact link 1,
kappa = 10, frictionless ground, a constant torque on the paper's input ellipsoid, radius 1).
It turns the contact link against the plate within the first milliseconds, so snakecg runs
it with ``geometry_check="report"`` (the model's whole trajectory; the check is measured
by ``bench_simulate.py --check``), at its default settings (DOP853, rtol 1e-9, atol 1e-11),
output at the end only.

MuJoCo runs the matched model of tests/mujoco_scene.py (capsule links, frictionless
``condim 1`` contacts, ``solref = (2 timestep, 1)``, planar joints) with two objects:

* ``point``: today's contact model, a point fixed in the object against the contact link:
  the same dynamics as snakecg's, so its trajectory is comparable (``diff``);
* ``box``: the physical plate, which every link may touch: the link cannot sink into it,
  the plate turns on its edge instead, so its trajectory is another one (``diff`` then
  says how far the model's is from the physical one, not an error of either).

For each object and integrator (RK4, implicitfast) the time step is the largest of
``STEPS`` whose deepest contact over the whole run stays below snakecg's contact tolerance
(``snakecg.geometry.contact_tolerance``: 1e-6 of the longest link, 1.5e-7 m), measured on
every step. The figure is simulated seconds per CPU second (``time.process_time``, median
of ``--repeat`` runs): snakecg's whole ``simulate`` call; MuJoCo's ``mj_step`` in a Python
loop and in C (``mujoco.rollout``, one call for the whole run, states recorded every step).
``diff`` is the largest difference of the object's position and of the snake's COM at the
end against snakecg's run (m).

    python benchmarks/bench_simulate_mujoco.py [--repeat 5] [--joints 3]
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from snakecg.geometry import contact_tolerance

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))  # the matched model
from bench_simulate import _load, setup  # benchmarks/bench_simulate.py
from mujoco_scene import matched_scene  # tests/mujoco_scene.py

DURATION = 0.5
STEPS = (2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6, 2e-6, 1e-6)
INTEGRATORS = ("RK4", "implicitfast")
OBJECTS = ("point", "box")
LINK_RADIUS = 1e-6  # m: the point model touches the line to 2 r (1 - cos theta)


def cpu_median(fn, repeat: int):
    times, out = [], None
    for _ in range(repeat):
        t0 = time.process_time()
        out = fn()
        times.append(time.process_time() - t0)
    return statistics.median(times), out


def snakecg_run(sm, q0, tau, repeat: int):
    def run():
        return sm.simulate(q0, tau, DURATION, output_dt=DURATION, geometry_check="report")

    run()  # warm up
    return cpu_median(run, repeat)


def admissible_step(scene, q0, q_obj0, rho, tau, geometry, integrator, tol):
    """The largest step of STEPS whose deepest contact over the run stays below ``tol``,
    and that depth; (None, depth of the smallest) when none does."""
    depth = np.nan
    for dt in STEPS:
        mj = matched_scene(scene, timestep=dt, integrator=integrator,
                           object_geometry=geometry, rho=rho, link_radius=LINK_RADIUS)
        mj.set_state(q0, q_obj=q_obj0)
        depth = mj.run(tau, DURATION, [DURATION])["max_depth"]
        if depth < tol:
            return dt, depth
    return None, depth


def mujoco_timed(scene, q0, q_obj0, rho, tau, geometry, integrator, dt, repeat: int):
    """CPU seconds (median) of the run by mj_step in a Python loop and by mujoco.rollout,
    and the final state ``(q, q_obj, com)``."""
    import mujoco
    from mujoco import rollout

    mj = matched_scene(scene, timestep=dt, integrator=integrator, object_geometry=geometry,
                       rho=rho, link_radius=LINK_RADIUS)
    m, d = mj.model, mj.data
    n = round(DURATION / dt)

    def loop():
        mj.set_state(q0, q_obj=q_obj0)
        d.qfrc_applied[3:mj.ns] = tau
        for _ in range(n):
            mujoco.mj_step(m, d)
        return mj.q, mj.q_obj, mj.com()

    t_loop, final = cpu_median(loop, repeat)
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    mj.set_state(q0, q_obj=q_obj0)
    state0 = np.empty(mujoco.mj_stateSize(m, spec))
    mujoco.mj_getState(m, d, state0, spec)
    qfrc = np.zeros((1, 1, m.nv))
    qfrc[0, 0, 3:mj.ns] = tau

    def c_rollout():
        return rollout.rollout(m, d, state0[None], qfrc, nstep=n,
                               control_spec=mujoco.mjtState.mjSTATE_QFRC_APPLIED)

    c_rollout()
    t_c, (states, _) = cpu_median(c_rollout, repeat)
    # the rollout's final state agrees with the loop's (same steps)
    mujoco.mj_setState(m, d, states[0, -1], spec)
    mujoco.mj_forward(m, d)
    same = max(np.abs(mj.q - final[0]).max(), np.abs(mj.q_obj - final[1]).max())
    return t_loop, t_c, final, same


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--joints", type=int, default=3)
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    import mujoco

    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, MuJoCo {mujoco.__version__}; load average "
          f"before: {_load()}")
    sm, q0, tau = setup(args.joints, "frictionless", 1.0)
    scene = sm.scene
    q_obj0, rho, _ = sm.place_object(q0)
    tol = contact_tolerance(scene.robot)
    cpu, traj = snakecg_run(sm, q0, tau, args.repeat)
    moved = np.hypot(*(traj.q_obj[-1, :2] - traj.q_obj[0, :2]))
    print(f"{DURATION} s push at n_a = {args.joints}, frictionless, kappa = 10, tau = "
          f"{np.array2string(tau, precision=4)} N m; the object moves {moved * 1e3:.2f} mm; "
          f"contact tolerance {tol:.2g} m; simulated s per CPU s (median of {args.repeat})\n")
    header = (f"{'engine':<40} {'step (s)':>9} {'depth (m)':>9} {'sim s/CPU s':>11}"
              f" {'snakecg/x':>9} {'diff obj':>9} {'diff COM':>9}")
    print(header)
    print("-" * len(header))
    rate = DURATION / cpu
    print(f"{'snakecg simulate (DOP853)':<40} {'adaptive':>9} {'model':>9} {rate:>11.4g}"
          f" {1.0:>9.2f} {0.0:>9.1e} {0.0:>9.1e}")
    com_end = traj.com[-1]
    for geometry in OBJECTS:
        for integrator in INTEGRATORS:
            dt, depth = admissible_step(scene, q0, q_obj0, rho, tau, geometry, integrator, tol)
            name = f"MuJoCo {geometry} {integrator}"
            if dt is None:
                print(f"{name:<40} {'none':>9} {depth:>9.1e}  (no step of {STEPS[-1]:g} s or "
                      "more meets the tolerance)")
                continue
            t_loop, t_c, (_, q_obj, com), same = mujoco_timed(
                scene, q0, q_obj0, rho, tau, geometry, integrator, dt, args.repeat)
            d_obj = np.abs(q_obj[:2] - traj.q_obj[-1, :2]).max()
            d_com = np.abs(com - com_end).max()
            for kind, t in (("mj_step loop", t_loop), ("rollout", t_c)):
                r = DURATION / t
                print(f"{name + ', ' + kind:<40} {dt:>9.0e} {depth:>9.1e} {r:>11.4g}"
                      f" {rate / r:>9.2f} {d_obj:>9.1e} {d_com:>9.1e}")
            if same > 1e-12:
                print(f"    (the rollout's final state differs from the loop's by {same:.1e})")
    print(f"\nload average after: {_load()}")


if __name__ == "__main__":
    main()
