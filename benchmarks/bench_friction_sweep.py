"""Robustness study: contact friction over a sweep of gaits and coefficients on the pegs row.

The scene is ``examples/scenes/pegs_row.toml`` with every peg's ``mu_contact`` set to each of
``--mu``, driven by the obstacle-aided locomotion page's serpenoid PD law (kp 10, kd 0.3,
phase lag 2 pi / 5) from the serpenoid's shape, with 15 gaits (amplitudes 0.3, 0.4, 0.5, 0.6,
0.7 rad x 0.5, 1, 1.5 Hz), ``--duration`` seconds each at ``dt = 1e-3``, one
``simulate_scene_batch`` per coefficient. Reported per coefficient: the runs completed, the
others' status and end, the batch's CPU time (``time.process_time``); the machine's load
before and after. Not a timed test: a study of how many runs the solve carries to the end.

    python benchmarks/bench_friction_sweep.py [--mu 0.3,0.6,1,1.5,2,3] [--duration 2]
        [--failures FILE.json]   (each stopped run's last state, gait and time, for replay)
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import time
from types import SimpleNamespace
from pathlib import Path

import numpy as np

from _machine import cpu_name

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "scenes" / "pegs_row.toml"
AMPLITUDES = (0.3, 0.4, 0.5, 0.6, 0.7)
FREQUENCIES = (0.5, 1.0, 1.5)


def model_at(mu):
    from snakecg.scenes import load_scene
    from snakecg.scenes.toml_reading import read_scene

    scene = read_scene(EXAMPLE)
    pegs = tuple(dataclasses.replace(o, mu_contact=mu) for o in scene.obstacles)
    return load_scene(dataclasses.replace(scene, obstacles=pegs))


def start():
    q0 = np.zeros(13)
    q0[3:] = 0.5 * np.sin(np.arange(10) * 2 * np.pi / 5)
    return q0


def gaits(model):
    from snakecg.simulate import serpenoid_controller

    return [(amp, fr, serpenoid_controller(model, amplitude=amp, frequency=fr,
                                           phase_lag=2 * np.pi / 5, kp=10.0, kd=0.3,
                                           tau_max=None))
            for amp in AMPLITUDES for fr in FREQUENCIES]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--mu", default="0.3,0.6,1,1.5,2,3")
    ap.add_argument("--duration", type=float, default=2.0)
    ap.add_argument("--failures", default=None,
                    help="write each stopped run's last state here (JSON)")
    args = ap.parse_args()
    from snakecg.scenes import simulate_scene_batch

    print(f"cpu: {cpu_name()}; load before: {os.getloadavg()[0]:.2f}; "
          f"SNAKECG_THREADS {os.environ.get('SNAKECG_THREADS', 'unset')}")
    total, done, stopped = 0, 0, []
    for mu in (float(m) for m in args.mu.split(",")):
        model = model_at(mu)
        laws = gaits(model)
        t = time.process_time()
        out = simulate_scene_batch(model, start(), args.duration, tau=[g for _, _, g in laws])
        cpu = time.process_time() - t
        ok = int(out.completed.sum())
        total, done = total + len(out), done + ok
        others = [f"{a:g} rad {f:g} Hz: {s} at {te:.3f} s" for (a, f, _), s, te, c in
                  zip(laws, out.status, out.t_end, out.completed) if not c]
        print(f"mu_contact {mu:g}: {ok} of {len(out)} completed, {cpu:.1f} CPU s")
        for line in others:
            print(f"    {line}")
        for (a, f, _), c, te in zip(laws, out.completed, out.t_end):
            if not c:
                stopped.append({"mu": mu, "amplitude": a, "frequency": f, "t_end": te})
    print(f"total: {done} of {total} completed; load after: {os.getloadavg()[0]:.2f}")
    if args.failures:
        rows = []
        for s in stopped:  # replayed one by one: the state of the step that stopped
            model = model_at(s["mu"])
            law = next(g for a, f, g in gaits(model)
                       if a == s["amplitude"] and f == s["frequency"])
            run = model.simulate(start(), args.duration, tau=law, dt=1e-3)
            q, v, te = np.asarray(run.q)[-1], np.asarray(run.v)[-1], float(run.t[-1])
            tau = law(te, SimpleNamespace(q=q, v=v))
            rows.append({**s, "status": run.status, "t": te, "q": q.tolist(),
                         "v": v.tolist(), "tau": np.asarray(tau).tolist()})
        Path(args.failures).write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
