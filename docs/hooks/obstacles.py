"""MkDocs hook: the obstacle-aided locomotion page's figure and numbers, computed when the
site is built.

Two runs of ``examples/scenes/pegs_row.toml`` (2 s each, about 10 s of CPU together): the
snake among its pegs, and the same snake and gait on the same ground without them. The
figure (``figures/obstacles/com_paths.png``) draws both COM paths over the pegs with the
snake's outline at the start and at the end of each run; the directive
``<!-- snakecg-obstacle-aided -->`` on a line of its own is replaced by the table of their
numbers. The peg-friction study: the same run with the pegs' ``mu_contact`` at each of
``STUDY_MUS`` (a few seconds of CPU together); its figure
(``figures/obstacles/progress_mu.png``) draws the progress along the row against
``mu_contact`` and ``<!-- snakecg-obstacle-friction -->`` is replaced by its table. Kept in
the snakecg cache folder under a key made of the package's sources, the example and this
file, so a rebuild with nothing changed reuses it.
"""

from __future__ import annotations

import hashlib
import json
import logging
import re
import time
from pathlib import Path

from mkdocs.structure.files import File

log = logging.getLogger("mkdocs.hooks.snakecg.obstacles")

EXAMPLE = Path("examples") / "scenes" / "pegs_row.toml"
FIGURE = "com_paths.png"
STUDY_FIGURE = "progress_mu.png"
STUDY_MUS = (0.0, 0.1, 0.3, 0.6, 1.0, 1.5, 2.0)
RESULTS = "obstacles.json"
DURATION = 2.0
GAIT = dict(amplitude=0.5, frequency=1.0, phase_lag=1.2566370614359172, kp=10.0, kd=0.3)


def _key(root: Path) -> str:
    h = hashlib.sha256()
    sources = sorted(p for p in (root / "snakecg").rglob("*")
                     if p.suffix in (".py", ".c", ".h")) + [root / EXAMPLE, Path(__file__)]
    for path in sources:
        if path.is_file():
            h.update(path.relative_to(root).as_posix().encode()
                     if path.is_relative_to(root) else path.name.encode())
            h.update(path.read_bytes())
    return h.hexdigest()[:20]


def compute(root: Path, folder: Path) -> None:
    import numpy as np

    from snakecg.scenes import GeneralScene, load_scene
    from snakecg.scenes.contacts import link_ends
    from snakecg.scenes.toml_reading import read_scene
    from snakecg.simulate import serpenoid_controller

    scene = read_scene(root / EXAMPLE)
    free = GeneralScene(scene.robot, radius=scene.radius, ground=scene.ground)
    na = scene.robot.joints
    q0 = np.zeros(na + 3)
    q0[3:] = GAIT["amplitude"] * np.sin(np.arange(na) * GAIT["phase_lag"])
    rows, paths = [], {}
    for name, sc in (("among the pegs", scene), ("without the pegs", free)):
        model = load_scene(sc)
        gait = serpenoid_controller(model, tau_max=None, **GAIT)
        t = time.process_time()
        run = model.simulate(q0, DURATION, tau=gait, dt=1e-3)
        cpu = time.process_time() - t
        com = model.com(run.q)
        ends = [link_ends(sc, model.link_poses(run.q[i])) for i in (0, -1)]
        paths[name] = (com, ends)
        rows.append({"run": name, "status": run.status,
                     "progress": float(np.hypot(*(com[-1] - com[0]))),
                     "dx": float(com[-1, 0] - com[0, 0]), "dy": float(com[-1, 1] - com[0, 1]),
                     "impacts": len(run.events), "steps": run.steps,
                     "deepest": max(0.0, -float(np.min(run.min_gap))),
                     "tolerance": run.tolerance, "work": float(run.work_tau[-1]),
                     "friction": float(run.friction_dissipation[-1]),
                     "kkt": max(run.certificate.values()), "cpu": cpu})
    study = _friction_study(scene, q0)
    (folder / RESULTS).write_text(json.dumps({"rows": rows, "friction": study}, indent=1),
                                  encoding="utf-8")
    _figure(folder / FIGURE, scene, paths)
    _study_figure(folder / STUDY_FIGURE, study)


def _friction_study(scene, q0) -> list:
    """The example with the pegs' Coulomb coefficient at each of STUDY_MUS: the COM's
    progress along the row (from the first peg to the last), the run's status and figures."""
    import dataclasses

    import numpy as np

    from snakecg.scenes import load_scene
    from snakecg.simulate import serpenoid_controller

    centres = np.array([o.center for o in scene.obstacles])
    along = (centres[-1] - centres[0]) / np.hypot(*(centres[-1] - centres[0]))
    out = []
    for mu in STUDY_MUS:
        pegs = tuple(dataclasses.replace(o, mu_contact=mu) for o in scene.obstacles)
        model = load_scene(dataclasses.replace(scene, obstacles=pegs))
        gait = serpenoid_controller(model, tau_max=None, **GAIT)
        t = time.process_time()
        run = model.simulate(q0, DURATION, tau=gait, dt=1e-3)
        cpu = time.process_time() - t
        com = model.com(run.q)
        out.append({"mu": mu, "status": run.status, "t_end": float(run.t[-1]),
                    "progress": float((com[-1] - com[0]) @ along),
                    "dx": float(com[-1, 0] - com[0, 0]), "dy": float(com[-1, 1] - com[0, 1]),
                    "impacts": len(run.events), "work": float(run.work_tau[-1]),
                    "friction": float(run.friction_dissipation[-1]),
                    "kkt": max(run.certificate.values()), "cpu": cpu})
    return out


def _study_figure(path: Path, study: list) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 3.2))
    mus = [r["mu"] for r in study]
    ax.plot(mus, [1000 * r["progress"] for r in study], "o-", color="tab:blue")
    for r in study:
        if r["status"] != "completed":
            ax.annotate(r["status"], (r["mu"], 1000 * r["progress"]), fontsize=8)
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("the pegs' mu_contact")
    ax.set_ylabel("COM progress along the row (mm)")
    ax.set_title(f"{DURATION:g} s of the serpenoid gait among pegs of growing friction")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _figure(path: Path, scene, paths: dict) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 3.6))
    for o in scene.obstacles:
        ax.add_patch(plt.Circle(o.center, o.radius, color="0.55"))
    colours = {"among the pegs": "tab:blue", "without the pegs": "tab:orange"}
    for name, (com, ends) in paths.items():
        c = colours[name]
        ax.plot(com[:, 0], com[:, 1], color=c, lw=2, label=f"COM {name}")
        for k, e in enumerate(ends):
            xs = [e[0, 0, 0], *e[:, 1, 0]]
            ys = [e[0, 0, 1], *e[:, 1, 1]]
            ax.plot(xs, ys, color=c, lw=1, ls="--" if k == 0 else "-", alpha=0.7)
    xs = [e[:, :, 0] for _, (_, ends) in paths.items() for e in ends]
    ys = [e[:, :, 1] for _, (_, ends) in paths.items() for e in ends]
    ax.set_xlim(min(x.min() for x in xs) - 0.15, max(x.max() for x in xs) + 0.15)
    ax.set_ylim(min(y.min() for y in ys) - 0.15, max(y.max() for y in ys) + 0.15)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"{DURATION:g} s of the serpenoid gait: snake at the start (dashed) and end")
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _build(root: Path, dest: Path) -> None:
    """Compute into a fresh folder, then move it into place (atomic)."""
    from snakecg._files import atomic_dir

    with atomic_dir(dest) as work:
        t = time.perf_counter()
        log.info("obstacle-aided locomotion: two 2 s runs of the pegs-row example")
        compute(root, work)
        log.info("obstacle-aided locomotion: computed in %.1f s", time.perf_counter() - t)


_DEST: Path | None = None


def on_files(files, config):
    global _DEST
    from snakecg.artifacts import cache_dir

    root = Path(config.config_file_path).resolve().parent
    dest = _DEST = cache_dir() / "docs-obstacles" / _key(root)
    if not all((dest / n).is_file() for n in (RESULTS, FIGURE, STUDY_FIGURE)):
        _build(root, dest)
    for name in (FIGURE, STUDY_FIGURE):
        files.append(File.generated(config, f"figures/obstacles/{name}",
                                    abs_src_path=str(dest / name)))
    return files


def table(data: dict) -> str:
    """The Markdown table of the two runs, from ``obstacles.json``."""
    lines = ["| run | status | COM moved | (x, y) | impacts | deepest overlap (tolerance) | "
             "torques' work | friction dissipated | largest KKT residual | CPU |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in data["rows"]:
        lines.append(f"| {r['run']} | `{r['status']}` | {1000 * r['progress']:.1f} mm | "
                     f"({1000 * r['dx']:.1f}, {1000 * r['dy']:.1f}) mm | {r['impacts']} | "
                     f"{r['deepest']:.2g} m ({r['tolerance']:.2g} m) | {r['work']:.3g} J | "
                     f"{r['friction']:.3g} J | {r['kkt']:.1g} | {r['cpu']:.1f} s |")
    return "\n".join(lines) + "\n"


def study_table(data: dict) -> str:
    """The Markdown table of the peg-friction study, from ``obstacles.json``."""
    lines = ["| pegs' mu_contact | status | progress along the row | (x, y) | impacts | "
             "torques' work | friction dissipated | largest KKT residual | CPU |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in data["friction"]:
        lines.append(f"| {r['mu']:g} | `{r['status']}` | {1000 * r['progress']:.1f} mm | "
                     f"({1000 * r['dx']:.1f}, {1000 * r['dy']:.1f}) mm | {r['impacts']} | "
                     f"{r['work']:.3g} J | {r['friction']:.3g} J | {r['kkt']:.1g} | "
                     f"{r['cpu']:.2f} s |")
    return "\n".join(lines) + "\n"


DIRECTIVE = re.compile(r"^<!--\s*snakecg-obstacle-aided\s*-->\s*$", re.MULTILINE)
STUDY = re.compile(r"^<!--\s*snakecg-obstacle-friction\s*-->\s*$", re.MULTILINE)


def on_page_markdown(markdown, page, config, files):
    if "snakecg-obstacle-aided" in markdown:
        data = json.loads((_DEST / RESULTS).read_text(encoding="utf-8"))
        text = table(data)
        markdown = DIRECTIVE.sub(lambda m: text, markdown)
    if "snakecg-obstacle-friction" in markdown:
        data = json.loads((_DEST / RESULTS).read_text(encoding="utf-8"))
        text = study_table(data)
        markdown = STUDY.sub(lambda m: text, markdown)
    return markdown
