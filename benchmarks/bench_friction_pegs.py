"""Benchmark: contact friction over time, the pegs row with rough pegs against the same run
with frictionless pegs (the anchor), side by side in one run.

The scene is ``examples/scenes/pegs_row.toml`` with every peg's ``mu_contact`` set to each of
``--mu`` (0: the frictionless pegs, the anchor), driven by the obstacle-aided locomotion
page's serpenoid PD law from the serpenoid's shape for ``--duration`` seconds at
``dt = 1e-3``. Reported per coefficient: the run's status and end, simulated seconds per CPU
second (``time.process_time``, best of ``--repeat``, the runs of the coefficients taken in
turn in each round) and the ratio of its CPU time to the anchor's. Prints the machine's load
before and after.

    python benchmarks/bench_friction_pegs.py [--mu 0,0.3,0.6,1,1.5,2] [--duration 2]
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import time
from pathlib import Path

import numpy as np

from _machine import cpu_name

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "scenes" / "pegs_row.toml"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--mu", default="0,0.3,0.6,1,1.5,2")
    ap.add_argument("--duration", type=float, default=2.0)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    from snakecg.scenes import load_scene
    from snakecg.scenes.toml_reading import read_scene
    from snakecg.simulate import serpenoid_controller

    mus = [float(m) for m in args.mu.split(",")]
    if 0.0 not in mus:
        mus.insert(0, 0.0)
    print(f"cpu: {cpu_name()}; load before: {os.getloadavg()[0]:.2f}")
    scene = read_scene(EXAMPLE)
    q0 = np.zeros(13)
    q0[3:] = 0.5 * np.sin(np.arange(10) * 2 * np.pi / 5)
    models = {}
    for mu in mus:
        pegs = tuple(dataclasses.replace(o, mu_contact=mu) for o in scene.obstacles)
        models[mu] = load_scene(dataclasses.replace(scene, obstacles=pegs))
    best, runs = {mu: np.inf for mu in mus}, {}
    for _ in range(args.repeat):
        for mu, model in models.items():
            gait = serpenoid_controller(model, amplitude=0.5, frequency=1.0,
                                        phase_lag=2 * np.pi / 5, kp=10.0, kd=0.3, tau_max=None)
            t = time.process_time()
            runs[mu] = model.simulate(q0, args.duration, tau=gait, dt=1e-3)
            best[mu] = min(best[mu], time.process_time() - t)
    print(f"{'mu_contact':>10} {'status':>14} {'t_end':>7} {'sim s / CPU s':>14} {'x anchor':>9}")
    for mu in mus:
        run = runs[mu]
        print(f"{mu:>10g} {run.status:>14} {run.t[-1]:>7.3f} "
              f"{run.t[-1] / best[mu]:>14.1f} {best[mu] / best[0.0]:>9.2f}")
    print(f"load after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
