"""Benchmark of the general scenes' forward solve, side by side with MuJoCo in one run.

* **scene**: an ``--joints`` (default 10) joint snake, 2 objects (a box and a disc touching
  links), 4 pegs touching links, Coulomb ground on every link (mu 0.3) and under the objects:
  ``model.forward(q, tau)`` on one sample from Python (best of ``--repeat`` rounds of
  ``--single`` calls; a call at the last call's q keeps its contacts, rows, inertia and Gram
  matrix, so the same calls are timed with nothing kept as well: q's first coordinate 0.0
  and -0.0 in turn) and batched (``--n`` samples, time per sample, one thread): unrelated
  torques at the benchmark's configuration (the batch finds the contacts, rows, inertia and
  Gram matrix once and keeps them for the samples at the same q), and the same torques each
  at its own configuration (q moved by 1e-10 per sample, within the contacts' tolerance:
  nothing kept);
* **where the time goes** in the batched figure (and the batch's mean Gauss-Seidel sweeps and
  active-set passes per sample): the engine's exact solve alone
  (``core_scene_solve`` on the same rows, inertia and forces, stacked), the engine's whole
  call (contacts, rows, solve, metrics: ``core_scene_forward``), and the rest (Python);
* **mj_forward**: MuJoCo's forward dynamics on the matched scene (capsule links on a planar
  base lying on a floor plane with gravity, box and cylinder objects on planar joints,
  cylinder pegs fixed to the world), bare ``mj_forward`` and with qpos and the applied
  forces set and qacc copied;
* **warm starts**: a batch's solves start from the last sample's pieces; the engine's call
  on a torque map (two joints' torques on a 36 x 36 grid, the others fixed) and on the random
  batch, against the same call with every sample cold (``chunk=1``), in one run;
* **paper**: the paper's scene (3 joints, wheels, kappa 100) through the general path and
  through today's path, single and batched (``--n`` samples and five times as many: the
  results' memory shows in the larger batch) (and a 64 x 64 map of two joint angles, warm
  against cold);
* **primal piece** (``--primal``): the warm batches (torque map, random batch) with a warm
  start's piece solved in the primal (scene_primal.c) and without it, alternated;
* **instructions** (``--instructions``, needs valgrind): machine instructions per sample
  inside the engine's call and inside its solve (callgrind's inclusive counts over a batch:
  the benchmark's at one q, 100 one-sample calls in a row at that q, the batch moved by
  1e-10 and the paper's), figures that do not depend on the machine's load;
* **long runs** (``--long-runs``): the scene at 8 random configurations, 500 torques at each
  of four scales, one thread: time a sample, the sweeps (mean, largest, above 150) and the
  worst certificate (the pieces read from the dual's barrier path after 150 sweeps).

    python benchmarks/bench_scenes.py [--joints 10] [--n 2000] [--single 300] [--repeat 3]
                                      [--instructions] [--primal] [--long-runs]

Prints a table and the machine's load average before and after.
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import numpy as np
from bench_core import best_of  # benchmarks/bench_core.py

import snakecg
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject


def scene_of(joints: int, q, *, ground=None, sides=(-1.0, 1.0, -1.0, 1.0), radius=0.0,
             mu_contact=None):
    """The benchmark's scene at q: a box and a disc touching the end links, four pegs of
    radius 0.03 touching links 2.. on ``sides`` (-1 right, 1 left), Coulomb ground (mu 0.3)
    unless ``ground`` is given; ``radius``: the links' capsules; ``mu_contact``: the objects'
    and pegs' own Coulomb coefficient at their contacts."""
    robot = snakecg.Robot(joints=joints)
    objects = (SceneObject(shape="box", size=(0.1, 0.08), mass=2.0, mu=0.2, mu_contact=mu_contact,
                           touching={"link": 1, "offset": 0.075, "side": "left"}),
               SceneObject(shape="disc", radius=0.04, mass=1.0, mu=0.2, mu_contact=mu_contact,
                           touching={"link": joints + 1, "offset": 0.075, "side": "right"}))
    P = snakecg.load(robot).link_poses(q)
    pegs = []
    for k, side in enumerate(sides):  # pegs touching links 2..
        x, y, phi = P[1 + (k * (joints - 1)) // 4]
        n = np.array([-np.sin(phi), np.cos(phi)]) * side
        c = np.array([x, y]) + (0.03 + radius) * n
        pegs.append(Obstacle(shape="peg", center=(float(c[0]), float(c[1])), radius=0.03,
                             mu_contact=mu_contact))
    return GeneralScene(robot, radius=radius,
                        ground=Ground(model="coulomb", mu=0.3) if ground is None else ground,
                        objects=objects, obstacles=tuple(pegs))


def mjcf(scene, P, obj_poses) -> str:
    """The matched MuJoCo scene (links from their COM poses at q, in world coordinates)."""
    r = scene.robot
    links, close = [], []
    for i in range(r.n_links):
        L = r.length[i]
        joint = ('<joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 1 0"/>'
                 '<joint type="hinge" axis="0 0 1"/>' if i == 0 else
                 '<joint type="hinge" axis="0 0 1" pos="-0.075 0 0"/>')
        pos = f"{P[0][0]} {P[0][1]} 0.01" if i == 0 else f"{L} 0 0"
        links.append(f'<body pos="{pos}">{joint}<geom type="capsule" size="0.01" '
                     f'fromto="{-L / 2} 0 0 {L / 2} 0 0" mass="{r.mass[i]}"/>')
        close.append("</body>")
    objs = []
    for j, o in enumerate(scene.objects):
        x, y, th = obj_poses[j]
        geom = (f'<geom type="box" size="{o.size[0] / 2} {o.size[1] / 2} 0.01" mass="{o.mass}"/>'
                if o.shape == "box" else
                f'<geom type="cylinder" size="{o.radius} 0.01" mass="{o.mass}"/>')
        objs.append(f'<body pos="{x} {y} 0.01" euler="0 0 {th}"><joint type="slide" '
                    f'axis="1 0 0"/><joint type="slide" axis="0 1 0"/><joint type="hinge" '
                    f'axis="0 0 1"/>{geom}</body>')
    pegs = "".join(f'<geom type="cylinder" pos="{o.center[0]} {o.center[1]} 0.02" '
                   f'size="{o.radius} 0.02"/>' for o in scene.obstacles)
    motors = "".join(f'<motor joint="{name}"/>' for name in [])
    return (f'<mujoco><option timestep="0.001" noslip_iterations="5"/>'
            f'<default><geom friction="0.3 0.005 0.0001" solref="0.002 1"/></default>'
            f'<worldbody><geom type="plane" size="5 5 0.1"/>{pegs}{"".join(links)}'
            f'{"".join(close)}{"".join(objs)}</worldbody>{motors}</mujoco>')


def _where(model, q, tau, n, repeat) -> tuple[float, float, dict]:
    """Per sample of a batch of n: the engine's whole call, its solve alone (on the same
    rows), and the solve's info of the first sample."""
    from snakecg.scenes.solve import solve

    res = model.forward(q, tau)
    rows, ns = res._rows[0], model.n_coordinates
    no = model.scene.n_objects
    M = np.zeros((n, ns + 3 * no, ns + 3 * no))
    M[:, :ns, :ns] = model.mass_matrix(q)
    for j, o in enumerate(model.scene.objects):
        M[:, ns + 3 * j + np.arange(3), ns + 3 * j + np.arange(3)] = [o.mass, o.mass,
                                                                       o.plate_inertia]
    f = np.zeros((n, ns + 3 * no))
    f[:, 3:ns] = tau
    A = np.repeat(rows.A[None], n, axis=0)
    args = (M, f, A, np.full(n, rows.A.shape[0]), np.repeat([rows.kind], n, axis=0),
            np.repeat([rows.start], n, axis=0), np.repeat([rows.par], n, axis=0))
    t_solve = best_of(lambda: solve(model.core, *args), repeat) / n
    Q, T = np.repeat(q[None], n, axis=0), np.repeat(tau[None], n, axis=0)
    # (every sample cold, as the stacked solve is: these samples are all the same, which a
    # warm start would answer from the first one's pieces)
    t_call = best_of(lambda: model._run(Q, T, model._zero_f, n, True, chunk=1), repeat) / n
    return t_call, t_solve, {k: float(v[0]) for k, v in res._raw["info"].items()}


def _warm_cold(model, name, Q, T, repeat) -> None:
    """The engine's call on a batch, its solves from the last sample's pieces (the forward's)
    and every sample cold, alternated; per sample, with the mean sweeps and passes."""
    from snakecg.scenes.model import WARM_CHUNK

    n, times = len(Q), {WARM_CHUNK: [], 1: []}
    for _ in range(repeat):
        for chunk, acc in times.items():
            acc.append(best_of(lambda: model._run(Q, T, model._zero_f, n, True, chunk=chunk),
                               1) / n)
    warm, cold = (model._run(Q, T, model._zero_f, n, True, chunk=c) for c in times)
    print(f"  {name} ({n}): warm {min(times[WARM_CHUNK]) * 1e6:.2f} us per sample (sweeps "
          f"{warm[:, 5].mean():.2f}, passes {warm[:, 6].mean():.2f}), cold "
          f"{min(times[1]) * 1e6:.2f} us (sweeps {cold[:, 5].mean():.2f}, passes "
          f"{cold[:, 6].mean():.2f}): {min(times[1]) / min(times[WARM_CHUNK]):.2f}x")


def _primal_on_off(model, name, Q, T, repeat) -> None:
    """The engine's warm batch with the warm start's piece solved in the primal
    (scene_primal.c) and without it (``core_scene_primal``'s switch), alternated; per sample,
    with the share of the samples the primal answered."""
    from snakecg.scenes.model import WARM_CHUNK

    core, n, counts = model.core, len(Q), np.zeros(2)
    times = {1: [], 0: []}
    for _ in range(repeat):
        for mode, acc in times.items():
            core.scene_primal(mode, None)
            acc.append(best_of(lambda: model._run(Q, T, model._zero_f, n, True,
                                                  chunk=WARM_CHUNK), 1) / n)
    core.scene_primal(1, counts.ctypes.data)
    model._run(Q, T, model._zero_f, n, True, chunk=WARM_CHUNK)
    core.scene_primal(1, counts.ctypes.data)
    print(f"  {name} ({n}), warm: primal piece {min(times[1]) * 1e6:.2f} us per sample "
          f"(answered {counts[1]:.0f} of {counts[0]:.0f} warm starts), without "
          f"{min(times[0]) * 1e6:.2f} us: {min(times[0]) / min(times[1]):.2f}x")


def _moved(Q, rng):
    """Each sample at its own configuration: q moved by 1e-10 (within the contacts'
    tolerance, the same contacts), so that a batch keeps nothing from one sample to the next."""
    return Q + 1e-10 * rng.standard_normal(Q.shape)


def _models(joints: int):
    """The benchmark's scene (its model, q, tau) and the paper's scene on the general path."""
    rng = np.random.default_rng(0)
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(joints))]
    scene = scene_of(joints, q)
    paper = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100)
    return (snakecg.load(scene), q, rng.normal(0, 0.1, joints),
            snakecg.load(GeneralScene.from_scene(paper)))


def _instructions_child(which: str, joints: int, n: int) -> None:
    """The work callgrind counts: one batch of n samples through the engine's call."""
    model, q, tau, paper = _models(joints)
    rng = np.random.default_rng(1)
    if which == "paper":
        model, q = paper, np.zeros(6)
        Q = np.c_[np.zeros((n, 3)), rng.uniform(-1.0, 1.0, (n, 3))]
        T = rng.normal(0, 0.05, (n, 3))
    else:
        Q, T = np.repeat(q[None], n, axis=0), rng.normal(0, 0.1, (n, joints))
        if which == "moved":
            Q = _moved(Q, rng)
        if which == "single":  # one-sample calls in a row at one q (the engine's kept rows)
            for t in T:
                model.forward(q, t)
            return
    model._run(Q, T, model._zero_f, n, True)


def bench_instructions(joints: int) -> None:
    """Instructions per sample of the engine's call and of its solve (callgrind, inclusive)."""
    import re
    import shutil
    import subprocess
    import sys
    import tempfile

    if not shutil.which("valgrind") or not shutil.which("callgrind_annotate"):
        print("instructions: valgrind is not installed (apt-get install valgrind)")
        return
    print("instructions per sample (callgrind, inclusive): the engine's call | its solve | the "
          "rest (contacts, rows, metrics)")
    for which, n in (("scene", 100), ("single", 100), ("moved", 100), ("paper", 2000)):
        with tempfile.TemporaryDirectory() as tmp:
            out = f"{tmp}/cg.out"
            subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                            sys.executable, __file__, "--_child", which, str(joints), str(n)],
                           check=True, capture_output=True)
            text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100",
                                   out], check=True, capture_output=True, text=True).stdout
        counts = []
        # the engine's call: libffi's inclusive count (callgrind attributes the exported
        # entry point's own count to its caller; the child makes no other foreign call of
        # note), its solve: sc_scene_solve_one's (the forward's per-sample call, the one
        # behind core_scene_solve_s) and sc_tiny_forward's (a tiny problem's, which the
        # forward calls first)
        for fns in (("ffi_call",), ("sc_scene_solve_one", "sc_tiny_forward")):
            total = 0.0
            for fn in fns:
                m = re.search(rf"^\s*([\d,]+) .*{fn}\b", text, re.M)
                total += int(m.group(1).replace(",", "")) / n if m else 0.0
            counts.append(total)
        print(f"  {which:5s} ({n} samples): {counts[0]:12,.0f} | {counts[1]:12,.0f} | "
              f"{counts[0] - counts[1]:10,.0f}")


def bench_long_runs(joints: int, configurations: int = 8, per_scale: int = 500) -> None:
    """The solve's long runs: the benchmark's scene at random joint angles (uniform in +-0.5
    rad, seed 0), torques at four scales (0.01 to 10 N m, per_scale each), one thread. On
    statically indeterminate faces the sweeps' forces drift; the pieces are then read once
    from the dual's barrier path. Prints the wall time, the sweeps (mean, largest, how many
    samples passed 150) and the certificates' worst."""
    rng = np.random.default_rng(0)
    total, sweeps, worst, unsolved = 0.0, [], 0.0, 0
    for _ in range(configurations):
        q = np.r_[0.0, 0.0, 0.0, rng.uniform(-0.5, 0.5, joints)]
        model = snakecg.load(scene_of(joints, q))
        for scale in (0.01, 0.1, 1.0, 10.0):
            T = rng.normal(0, scale, (per_scale, joints))
            Q = np.repeat(q[None], per_scale, axis=0)
            t0 = time.perf_counter()
            res = model.forward(Q, T)
            total += time.perf_counter() - t0
            info = res._raw["info"]
            sweeps.append(info["sweeps"])
            unsolved += int(np.sum(info["status"] != 0))
            worst = max(worst, max(float(np.nanmax(info[k]))
                                   for k in ("primal", "dual", "complementarity")))
    sw = np.concatenate(sweeps)
    print(f"long runs ({configurations} random configurations x 4 torque scales x {per_scale}, "
          f"one thread): {total / sw.size * 1e6:.1f} us a sample, sweeps mean {sw.mean():.1f}, "
          f"largest {sw.max():.0f}, above 150: {(sw > 150).sum()}; unsolved {unsolved}, worst "
          f"certificate {worst:.1e}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--joints", type=int, default=10)
    ap.add_argument("--n", type=int, default=2000)
    ap.add_argument("--single", type=int, default=300)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--instructions", action="store_true",
                    help="also instructions per sample (valgrind's callgrind)")
    ap.add_argument("--long-runs", action="store_true",
                    help="also the long runs' study (random configurations, four torque scales)")
    ap.add_argument("--primal", action="store_true",
                    help="also the warm batches with and without the primal piece")
    ap.add_argument("--_child", nargs=3, help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a._child:
        _instructions_child(a._child[0], int(a._child[1]), int(a._child[2]))
        return
    os.environ["SNAKECG_THREADS"] = "1"
    rng = np.random.default_rng(0)
    print(f"machine: {platform.processor() or platform.machine()}, load {os.getloadavg()}")
    na = a.joints
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(na))]
    scene = scene_of(na, q)
    model = snakecg.load(scene)
    tau = rng.normal(0, 0.1, na)
    res = model.forward(q, tau)
    t_call, t_solve, info = _where(model, q, tau, a.n, a.repeat)
    print(f"scene: {na} joints, {len(res.contacts)} contacts, {res._rows[0].A.shape[0]} rows, "
          f"status {res.status}, sweeps {info['sweeps']:.0f}, passes {info['passes']:.0f}, "
          f"dependent {info['dependent']:.0f}")
    t1 = best_of(lambda: [model.forward(q, tau) for _ in range(a.single)], a.repeat) / a.single
    Q = np.repeat(q[None], a.n, axis=0)
    T = rng.normal(0, 0.1, (a.n, na))
    tb = best_of(lambda: model.forward(Q, T), a.repeat) / a.n
    print(f"  snakecg forward, single:  {t1 * 1e6:10.1f} us")
    # one sample's cost depends on its pieces: the same single call over 50 unrelated torques
    ts = best_of(lambda: [model.forward(q, t) for t in T[:50]], a.repeat) / 50
    print(f"  snakecg forward, single, mean over 50 unrelated torques: {ts * 1e6:6.1f} us")
    # one-sample calls at the last call's q keep its rows: the same 50 with nothing kept (q's
    # first coordinate 0.0 and -0.0 in turn: the same numbers, other bytes)
    Q50 = [q.copy() for _ in range(50)]
    for qm in Q50[1::2]:
        qm[0] = -qm[0]
    assert all(qm[0] == 0.0 for qm in Q50)
    tq = best_of(lambda: [model.forward(qm, t) for qm, t in zip(Q50, T[:50])], a.repeat) / 50
    print(f"  snakecg forward, single, the same 50 with nothing kept (q[0] 0.0, -0.0 in turn): "
          f"{tq * 1e6:6.1f} us")
    print(f"  snakecg forward, batched: {tb * 1e6:10.1f} us per sample")
    Qm = _moved(Q, np.random.default_rng(2))
    tm_ = best_of(lambda: model.forward(Qm, T), a.repeat) / a.n
    moved = model.forward(Qm, T)
    print(f"  snakecg forward, batched, each sample at its own q (moved 1e-10): "
          f"{tm_ * 1e6:6.1f} us per sample (solved {np.mean(moved.status == 0):.0%})")
    inf = model.forward(Q, T)._raw["info"]
    print(f"    the batch's solves: mean sweeps {inf['sweeps'].mean():.1f}, mean active-set "
          f"passes {inf['passes'].mean():.2f}, dependent {np.mean(inf['dependent'] > 0):.0%}, "
          f"solved {np.mean(inf['status'] == 0):.0%}")
    print(f"    of which the engine's call {t_call * 1e6:.1f} us, its solve alone "
          f"{t_solve * 1e6:.1f} us (contacts, rows, metrics: {(t_call - t_solve) * 1e6:.1f} us)")
    g = np.linspace(-0.3, 0.3, 36)
    Tg = np.repeat(tau[None], g.size ** 2, axis=0)
    Tg[:, 2], Tg[:, 6] = np.repeat(g, g.size), np.tile(g, g.size)
    _warm_cold(model, "torque map 36 x 36", np.repeat(q[None], len(Tg), axis=0), Tg, a.repeat)
    _warm_cold(model, "random batch", Q, T, a.repeat)
    if a.primal:
        _primal_on_off(model, "torque map 36 x 36", np.repeat(q[None], len(Tg), axis=0), Tg,
                       a.repeat)
        _primal_on_off(model, "random batch", Q, T, a.repeat)
    try:
        import mujoco

        m = mujoco.MjModel.from_xml_string(mjcf(scene, model.link_poses(q),
                                                model.object_poses(q)))
        d = mujoco.MjData(m)
        mujoco.mj_forward(m, d)
        tm = best_of(lambda: [mujoco.mj_forward(m, d) for _ in range(a.single)],
                     a.repeat) / a.single
        qpos0 = d.qpos.copy()

        def full():
            d.qpos[:] = qpos0
            d.qfrc_applied[3:3 + na] = tau
            mujoco.mj_forward(m, d)
            return d.qacc.copy()

        tf = best_of(lambda: [full() for _ in range(a.single)], a.repeat) / a.single
        print(f"  mj_forward (bare, {d.ncon} contacts, MuJoCo {mujoco.__version__}): "
              f"{tm * 1e6:8.1f} us; with qpos, forces set and qacc copied: {tf * 1e6:8.1f} us")
    except ImportError:
        print("  mujoco not installed")
    paper = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100)
    old, new = snakecg.load(paper), snakecg.load(GeneralScene.from_scene(paper))
    Q = np.c_[np.zeros((a.n, 3)), rng.uniform(-1.0, 1.0, (a.n, 3))]
    T = rng.normal(0, 0.05, (a.n, 3))
    q0, t0 = Q[0].copy(), T[0].copy()
    Q5 = np.c_[np.zeros((5 * a.n, 3)), rng.uniform(-1.0, 1.0, (5 * a.n, 3))]
    T5 = rng.normal(0, 0.05, (5 * a.n, 3))
    for name, mdl in (("today's path", old), ("general path", new)):
        s = best_of(lambda: [mdl.forward(q0, t0) for _ in range(a.single)], a.repeat) / a.single
        b = best_of(lambda: mdl.forward(Q, T), a.repeat) / a.n
        b5 = best_of(lambda: mdl.forward(Q5, T5), a.repeat) / (5 * a.n)
        print(f"  paper scene, {name:13s}: single {s * 1e6:9.1f} us, batched "
              f"{b * 1e6:9.2f} us per sample ({5 * a.n} samples: {b5 * 1e6:.2f} us)")
    inf = new.forward(Q, T)._raw["info"]
    print(f"    general path's batch: mean sweeps {inf['sweeps'].mean():.1f}, mean active-set "
          f"passes {inf['passes'].mean():.2f}")
    t_call, t_solve, info = _where(new, q0, t0, a.n, a.repeat)
    print(f"    general path, of which the engine's call {t_call * 1e6:.2f} us, its solve alone "
          f"{t_solve * 1e6:.2f} us per sample (sweeps {info['sweeps']:.0f})")
    g = np.linspace(-1.0, 1.0, 64)
    Qg = np.c_[np.zeros((g.size ** 2, 3)), np.repeat(g, g.size), np.tile(g, g.size),
               np.full(g.size ** 2, 0.3)]
    _warm_cold(new, "paper, q map 64 x 64", Qg, np.tile([0.02, -0.01, 0.03], (len(Qg), 1)),
               a.repeat)
    if a.long_runs:
        bench_long_runs(na)
    if a.instructions:
        bench_instructions(na)
    print(f"load after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
