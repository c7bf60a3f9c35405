"""MkDocs hook: the optimal-shapes page's table and figures, computed when the site is built.

* ``<!-- snakecg-shapes-table -->`` on a line of its own is replaced by the table of case
  study 2 (3 joints, Table 1, kappa = 100): for every scenario, objective (``max_sr``,
  ``max_a_obj``) and shape set (every shape; only shapes without self-intersection or object
  penetration), the continuous optimum of ``model.optimize_shape`` on its defaults (8
  starts) and the best point of the paper's 21,952-shape grid (every joint on -135..135 deg
  every 10 deg) by ``model.extremes`` over the grid (exact, every wheel state: the same
  constraint set as the continuous problem), followed by one sentence of what was computed
  (statuses, the largest KKT residual, the time). No number of the table is typed into the
  page.
* ``figures/shapes/max_sr.png`` and ``max_a_obj.png``: top row, the continuous optimum with
  the geometric constraints; bottom row, the grid's best with every shape kept.

The computation takes a few seconds once the 3-joint model is compiled; its output is kept in
the snakecg cache folder under a key made of the package's sources (Python and C), the
checked-in 3-joint generated model and this file, so a rebuild with nothing changed reuses it.
"""

from __future__ import annotations

import hashlib
import json
import logging
import re
import time
from pathlib import Path

from mkdocs.structure.files import File

log = logging.getLogger("mkdocs.hooks.snakecg.shapes")

#: Case study 2's scene (the reproduction's defaults) and the paper's grid.
KAPPA = 100.0
GRID_DEG = (-135.0, 135.0, 10.0)
SCENARIOS = (("frictionless", "1 (frictionless)"), ("wheels", "2 (wheels, μ = 0.1)"),
             ("ideal_wheels", "3 (ideal wheels)"))
#: objective of optimize_shape -> (the extremes' metric, its label in the table, in titles)
OBJECTIVES = {"max_sr": ("sr", "sr", "sr"),
              "max_a_obj": ("norm_a_obj", r"$\lVert a_{obj}\rVert^2$", "|a_obj|^2")}
SHAPE_SETS = (("all", False), ("feasible", True))
FIGURES = tuple(f"{objective}.png" for objective in OBJECTIVES)
RESULTS = "shapes.json"


def _key(root: Path) -> str:
    h = hashlib.sha256()
    sources = sorted(p for p in (root / "snakecg").rglob("*")
                     if p.suffix in (".py", ".c", ".h")) + sorted(
        (root / "generated" / "na3").glob("*")) + [Path(__file__)]
    for path in sources:
        if path.is_file():
            h.update(path.relative_to(root).as_posix().encode())
            h.update(path.read_bytes())
    return h.hexdigest()[:20]


def _deg(q) -> list:
    import numpy as np

    return [float(d) + 0.0 for d in np.round(np.rad2deg(np.asarray(q, float)), 6)]


def _why(f, k) -> str:
    reasons = (["links cross"] if bool(f.self_intersecting[k]) else []) + (
        ["a link enters the object"] if bool(f.penetrates_object[k]) else [])
    return " and ".join(reasons)


def compute(folder: Path) -> None:
    """Every row of the table into ``folder/shapes.json`` and both figures beside it."""
    import numpy as np

    import snakecg
    from snakecg.analysis import joint_grid
    from snakecg.geometry import feasibility

    Q = joint_grid(3, *GRID_DEG)
    rows, shapes = [], {}
    for scenario, label in SCENARIOS:
        model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario,
                                           kappa=KAPPA))
        t = time.perf_counter()
        ex = model.extremes(Q, refined=tuple(m for m, _, _ in OBJECTIVES.values()),
                            exact=True)
        feas = feasibility(model, Q)
        log.info("optimal shapes: scenario %s, the %s shapes of the grid in %.1f s", label,
                 f"{len(Q):,}", time.perf_counter() - t)
        for objective, (metric, _, _) in OBJECTIVES.items():
            values = np.asarray(ex.max[metric], float)
            for shape_set, feasible in SHAPE_SETS:
                t = time.perf_counter()
                res = model.optimize_shape(objective, feasible=feasible)
                seconds = time.perf_counter() - t
                masked = np.where(feas.feasible, values, -np.inf) if feasible else values
                g = int(np.nanargmax(np.where(np.isnan(masked), -np.inf, masked)))
                cert = res.certificate
                rows.append({
                    "scenario": scenario, "objective": objective, "shapes": shape_set,
                    "status": res.status, "value": float(res.value), "q_deg": _deg(res.q[3:]),
                    "kkt": max(float(cert[k]) for k in
                               ("stationarity", "primal_infeasibility", "complementarity")),
                    "seconds": seconds, "starts": len(res.starts),
                    "grid_value": float(values[g]), "grid_q_deg": _deg(Q[g, 3:]),
                    "grid_infeasible": _why(feas, g)})
                log.info("optimal shapes: scenario %s, %s, %s shapes: %s %.8g (%.1f s); "
                         "grid %.8g", label, objective, shape_set, res.status, res.value,
                         seconds, values[g])
                if feasible:
                    shapes[(objective, scenario, "top")] = (model, res.q, rows[-1], "")
                else:
                    shapes[(objective, scenario, "bottom")] = (model, Q[g], rows[-1],
                                                               _why(feas, g))
    (folder / RESULTS).write_text(json.dumps({"grid_deg": GRID_DEG, "kappa": KAPPA,
                                              "grid_shapes": len(Q), "rows": rows}, indent=1),
                                  encoding="utf-8")
    for objective in OBJECTIVES:
        _figure(folder / f"{objective}.png", objective, shapes)


def _figure(path: Path, objective: str, shapes: dict) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from snakecg.reproduce import draw_robot

    title = OBJECTIVES[objective][2]
    fig, axes = plt.subplots(2, 3, figsize=(13, 8), constrained_layout=True)
    fig.suptitle(f"Best shapes for {title} (3 joints, kappa = {KAPPA:g}): top, the continuous "
                 "optimum with the geometric constraints; bottom, the best of the "
                 "21,952-shape grid (every shape kept)", fontsize=10)
    for j, (scenario, label) in enumerate(SCENARIOS):
        for i, (row, what) in enumerate((("top", "continuous optimum"),
                                         ("bottom", "best of the paper's grid"))):
            model, q, r, why = shapes[(objective, scenario, row)]
            value = r["value"] if row == "top" else r["grid_value"]
            angles = r["q_deg"] if row == "top" else r["grid_q_deg"]
            deg = ", ".join(f"{d:.1f}°" if row == "top" else f"{d:.0f}°" for d in angles)
            draw_robot(axes[i, j], model, q,
                       title=f"{what}, scenario {label}\n{title} = {value:.6g}, q = ({deg})"
                             + (f"\n* not physically possible: {why}" if why else ""))
            if why:
                for spine in axes[i, j].spines.values():
                    spine.set_color("red")
                    spine.set_linewidth(2)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _build(dest: Path) -> None:
    """Compute into a fresh folder, then move it into place (atomic)."""
    from snakecg._files import atomic_dir

    with atomic_dir(dest) as work:
        t = time.perf_counter()
        log.info("optimal shapes: computing the table and figures of how-to/shapes.md "
                 "(12 continuous optima, the paper's grid in 3 scenarios)")
        compute(work)
        log.info("optimal shapes: computed in %.1f s", time.perf_counter() - t)


_DEST: Path | None = None  # the folder of this build's table and figures


def on_files(files, config):
    global _DEST
    from snakecg.artifacts import cache_dir

    root = Path(config.config_file_path).resolve().parent
    dest = _DEST = cache_dir() / "docs-shapes" / _key(root)
    if not all((dest / n).is_file() for n in (RESULTS, *FIGURES)):
        _build(dest)
    for name in FIGURES:
        files.append(File.generated(config, f"figures/shapes/{name}",
                                    abs_src_path=str(dest / name)))
    return files


def _num(v: float) -> str:
    return f"{v:.8g}"


def table(data: dict) -> str:
    """The Markdown table and the sentence under it, from ``shapes.json``."""
    labels = dict(SCENARIOS)
    head = ("| scenario | maximised | shapes | continuous optimum | joint angles (°) | "
            "best grid point | joint angles (°) | gain |")
    lines = [head, "|---|---|---|---|---|---|---|---|"]
    for r in data["rows"]:
        cont = ", ".join(f"{d:.2f}" for d in r["q_deg"])
        grid = ", ".join(f"{d:.0f}" for d in r["grid_q_deg"])
        mark = "*" if r["grid_infeasible"] else ""
        gain = 100 * (r["value"] / r["grid_value"] - 1)
        status = "" if r["status"] == "optimal" else f" ({r['status']})"
        lines.append(f"| {labels[r['scenario']]} | {OBJECTIVES[r['objective']][1]} | "
                     f"{r['shapes']} | {_num(r['value'])}{status} | ({cont}) | "
                     f"{_num(r['grid_value'])}{mark} | ({grid}) | {gain:+.2g} % |")
    rows = data["rows"]
    statuses = sorted({r["status"] for r in rows})
    said = (f'every continuous optimum is `"{statuses[0]}"`' if len(statuses) == 1 else
            "statuses: " + ", ".join(f'`"{s}"` ({sum(r["status"] == s for r in rows)})'
                                     for s in statuses))
    starts = sorted({r["starts"] for r in rows})
    note = (f"Computed when this page was built: {len(rows)} runs of `model.optimize_shape` "
            f"on its defaults ({'/'.join(map(str, starts))} starts), and `model.extremes` "
            f"over the {data['grid_shapes']:,} shapes of the grid in each scenario; {said}, "
            f"with KKT residuals at most {max(r['kkt'] for r in rows):.1g}; the optima took "
            f"{min(r['seconds'] for r in rows):.2f}–{max(r['seconds'] for r in rows):.2f} s "
            "each.")
    if any(r["grid_infeasible"] for r in rows):
        from snakecg.geometry import infeasible_footnote

        note += " \\" + infeasible_footnote() + "."
    return "\n".join(lines) + "\n\n" + note + "\n"


SHAPES_TABLE = re.compile(r"^<!--\s*snakecg-shapes-table\s*-->\s*$", re.MULTILINE)


def on_page_markdown(markdown, page, config, files):
    """``<!-- snakecg-shapes-table -->``: the table of this build's computation."""
    if "snakecg-shapes-table" in markdown:
        data = json.loads((_DEST / RESULTS).read_text(encoding="utf-8"))
        text = table(data)
        markdown = SHAPES_TABLE.sub(lambda m: text, markdown)
    return markdown
