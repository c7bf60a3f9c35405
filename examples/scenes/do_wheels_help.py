"""Do wheels help? The paper's question asked again on a wheel-less snake.

The same 3-joint snake pushes the same box touching the middle of its tail, with the
belly on Coulomb ground (mu = 0.3, no wheels), with bounded wheels (lateral mu = 0.3, free
along the link) and with ideal wheels. Over random configurations and torques on the input
ellipsoid (eq. 31), how often does the box move, and what is the mean slippage ratio?

    python examples/scenes/do_wheels_help.py [samples]
"""

from __future__ import annotations

import sys

import numpy as np

import snakecg
from snakecg.scenes import GeneralScene, Ground, SceneObject


def study(samples: int = 300, seed: int = 0) -> dict:
    robot = snakecg.Robot(joints=3)
    box = SceneObject(shape="box", size=(0.1, 0.1), mass=5.0, mu=0.2,
                      touching={"link": 1, "offset": 0.075, "side": "left"})
    rng = np.random.default_rng(seed)
    q = np.c_[np.zeros((samples, 3)), rng.uniform(-2.0, 2.0, (samples, 3))]
    out = {}
    for ground in ("coulomb", "wheels", "ideal_wheels"):
        # no wheel on the link that touches the box (the paper's assumption 4)
        per_link = tuple(Ground(model="frictionless" if (i == 0 and ground != "coulomb")
                                else ground, mu=0.3) for i in range(4))
        model = snakecg.load(GeneralScene(robot, ground=per_link, objects=(box,)))
        # torques on the input ellipsoid tau^T M_bar^-1 tau = 1 (eq. 31)
        M = model.mass_matrix(q)[:, 3:, 3:]
        u = rng.normal(size=(samples, 3))
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        tau = np.einsum("nij,nj->ni", np.linalg.cholesky(M), u)
        res = model.forward(q, tau)
        ok = res.status == 0
        out[ground] = {"answered": int(ok.sum()),
                       "box moves": float(np.mean(res.norm_a_obj[ok] > 1e-12)),
                       "mean sr": float(np.mean(res.sr[ok]))}
    return out


if __name__ == "__main__":
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 300
    for ground, row in study(n).items():
        print(f"{ground:13s} " + ", ".join(f"{k} {v:.3g}" for k, v in row.items()))
