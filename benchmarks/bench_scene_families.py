"""Study: the general scene's solve over its families at random configurations.

The benchmark's scene (``bench_scenes.scene_of``: a box and a disc touching the end links,
four pegs touching links, here on random sides) at random joint angles, with each ground
model and with Coulomb friction at the contacts (``mu_contact`` 0.3 on the objects and the
pegs); ``--radius`` gives the links capsules of that radius (self-contact possible, and
configurations whose bodies overlap refused per sample). Per family: ``--configurations``
configurations (angles uniform in +-``--amplitude`` rad, seed ``--seed``), ``--per`` torques
at each of 0.01, 0.1, 1 and 10 N m, one thread. Prints per family the time a sample, the
samples refused as overlapping, those not solved, the worst certificate of the solved ones,
the sweeps (mean, largest) and the dependent flags' counts (0 regular, 1 minimum-norm forces,
2 a basic solution of the face kept, 3 a near miss).

    python benchmarks/bench_scene_families.py [--joints 10] [--amplitude 1.0] [--radius 0]
        [--configurations 8] [--per 250] [--seed 2] [--families coulomb,anisotropic,...]
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from bench_scenes import scene_of  # benchmarks/bench_scenes.py

import snakecg
from snakecg.scenes import GeneralScene, Ground

GROUNDS = {"coulomb": Ground(model="coulomb", mu=0.3),
           "anisotropic": Ground(model="anisotropic", mu_forward=0.1, mu_backward=0.3,
                                 mu_lateral=0.5),
           "wheels": Ground(model="wheels", mu=0.3),
           "ideal_wheels": Ground(model="ideal_wheels"),
           "frictionless": Ground(model="frictionless"),
           "contact_friction": Ground(model="coulomb", mu=0.3)}


def family_scene(name: str, joints: int, q, radius: float, rng) -> GeneralScene:
    """The scene of family ``name`` at ``q``: the benchmark's (bench_scenes.scene_of) with
    its pegs on random sides."""
    sides = [1.0 if rng.random() < 0.5 else -1.0 for _ in range(4)]
    return scene_of(joints, q, ground=GROUNDS[name], sides=sides, radius=radius,
                    mu_contact=0.3 if name == "contact_friction" else None)


def study(name: str, a) -> str:
    rng = np.random.default_rng(a.seed)
    total, sweeps, flags = 0.0, [], np.zeros(4, int)
    refused = unsolved = 0
    worst = 0.0
    for _ in range(a.configurations):
        q = np.r_[0.0, 0.0, 0.0, rng.uniform(-a.amplitude, a.amplitude, a.joints)]
        model = snakecg.load(family_scene(name, a.joints, q, a.radius, rng))
        for scale in (0.01, 0.1, 1.0, 10.0):
            T = rng.normal(0, scale, (a.per, a.joints))
            t0 = time.perf_counter()
            res = model.forward(np.repeat(q[None], a.per, axis=0), T)
            total += time.perf_counter() - t0
            info = res._raw["info"]
            status = np.asarray(info["status"])
            overlap = status == 3
            refused += int(overlap.sum())
            solved = status == 0
            unsolved += int((~solved & ~overlap).sum())
            if solved.any():
                worst = max(worst, max(float(np.max(np.asarray(info[k])[solved]))
                                       for k in ("primal", "dual", "complementarity")))
                flags += np.bincount(np.asarray(info["dependent"])[solved].astype(int),
                                     minlength=4)[:4]
            sweeps.append(np.asarray(info["sweeps"])[~overlap])
    sw = np.concatenate(sweeps) if sweeps else np.zeros(1)
    n = a.configurations * 4 * a.per
    return (f"  {name:16s} {total / n * 1e6:9.1f} us  refused {refused:5d}  unsolved "
            f"{unsolved:3d}  worst certificate {worst:.1e}  sweeps mean {sw.mean():5.1f} "
            f"largest {sw.max():4.0f}  flags {flags.tolist()}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--joints", type=int, default=10)
    ap.add_argument("--amplitude", type=float, default=1.0)
    ap.add_argument("--radius", type=float, default=0.0)
    ap.add_argument("--configurations", type=int, default=8)
    ap.add_argument("--per", type=int, default=250)
    ap.add_argument("--seed", type=int, default=2)
    ap.add_argument("--families", default=",".join(GROUNDS))
    a = ap.parse_args()
    print(f"machine load {os.getloadavg()}; {a.joints} joints, angles in +-{a.amplitude} rad, "
          f"link radius {a.radius}, {a.configurations} configurations x 4 torque scales x "
          f"{a.per}, one thread")
    for name in a.families.split(","):
        if name not in GROUNDS:
            raise SystemExit(f"--families: {name!r} is not one of {', '.join(GROUNDS)}")
        print(study(name, a), flush=True)
    print(f"load after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
