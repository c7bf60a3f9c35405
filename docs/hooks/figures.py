"""MkDocs hook: the figures and Table 2 of the site, computed when the site is built.

* ``figures/reproduce/``: Figs. 4 (kappa = 100), 5 and 6 from a ``snakecg reproduce`` run
  (``SITE_RUN``, PNG only). Case study 2 (Figs. 5, 6 and Table 2) runs on the command's
  defaults, the full 10-degree joint grid, so the pages show what ``snakecg reproduce``
  computes; only case study 1 is reduced (kappa = 100 alone, a coarser torque grid for Fig. 4).
* Table 2: the directive ``<!-- snakecg-table2 -->`` on a line of its own is replaced by the
  Markdown table that the same run wrote (``table2.md``, made by ``snakecg.table2``), with
  its footnotes (the caption is left to the page's own text). No number of Table 2 is typed
  into a page. ``<!-- snakecg-alternatives -->``: the
  table of ``snakecg reproduce --alternatives`` (``alternatives.md``), from the same defaults.
* ``figures/simulate/``: the figures and the animation of the push that the Simulation page's
  first example runs (``SIMULATION``).

The runs take seconds to a minute; their output is kept in the snakecg cache folder under a
key made of the package's sources, the checked-in generated models and this file, so a
rebuild with nothing changed (``mkdocs serve``, the second build of CI) reuses it. Pages
refer to the files as ``figures/...``; ``mkdocs build --strict`` fails if one is missing.
"""

from __future__ import annotations

import hashlib
import logging
import re
import time
from pathlib import Path

from mkdocs.structure.files import File

log = logging.getLogger("mkdocs.hooks.snakecg.figures")

#: The site's reproduction: case study 2 on the defaults of ``snakecg reproduce`` (every joint
#: on -135..135 deg every 10 deg, 21,952 shapes), so Figs. 5, 6 and Table 2 are the command's;
#: case study 1 at kappa = 100 only, on a 91 x 91 torque grid instead of 181 x 181.
SITE_RUN = dict(kappas_case1=(100.0,), torque_grid=91, formats=("png",), progress=False, jobs=1)
REPRODUCE_FILES = ("fig4_kappa100.png", "fig5_polar.png", "fig6_configurations.png",
                   "table2.md", "alternatives.md")
#: The Simulation page's first example (docs/how-to/simulate.md).
SIMULATION = dict(joints=4, scenario="wheels", kappa=10.0, mu=0.1, contact_link=3,
                  q_deg=(30.0, 40.0, 40.0, 30.0), tau=(0.05, 0.02, 0.02, 0.05), duration=0.5)
SIMULATE_FILES = ("displacement.png", "slippage.png", "forces.png", "animation.gif")


def _key(root: Path) -> str:
    h = hashlib.sha256()
    sources = sorted((root / "snakecg").rglob("*.py")) + sorted(
        (root / "generated").glob("na[23]/manifest.json")) + [Path(__file__)]
    for path in sources:
        h.update(path.relative_to(root).as_posix().encode())
        h.update(path.read_bytes())
    return h.hexdigest()[:20]


def _reproduce(folder: Path) -> None:
    from snakecg._files import write_text
    from snakecg.reproduce import ReproduceOptions, alternative_readings, reproduce

    opts = ReproduceOptions(out=folder, **SITE_RUN)
    reproduce(opts, echo=lambda *a: None)
    # the table of `snakecg reproduce --alternatives`, on the command's defaults
    write_text(folder / "alternatives.md", alternative_readings(opts))


def _simulate(folder: Path) -> None:
    import numpy as np

    import snakecg
    from snakecg.simulate import save_figures

    s = SIMULATION
    scene = snakecg.Scene(snakecg.Robot(joints=s["joints"]), scenario=s["scenario"],
                          kappa=s["kappa"], mu=s["mu"], contact_link=s["contact_link"])
    q0 = np.array([0.0, 0.0, 0.0, *np.deg2rad(s["q_deg"])])
    traj = snakecg.load(scene).simulate(q0, list(s["tau"]), s["duration"])
    save_figures(traj, folder, frames=40)


def _build(dest: Path) -> None:
    """Compute every figure into a fresh folder, then move it into place (atomic)."""
    from snakecg._files import atomic_dir

    with atomic_dir(dest) as work:
        t = time.perf_counter()
        _reproduce(work / "reproduce")
        _simulate(work / "simulate")
        log.info("figures computed in %.1f s", time.perf_counter() - t)


_DEST: Path | None = None  # the folder of this build's figures and Table 2


def on_files(files, config):
    global _DEST
    from snakecg.artifacts import cache_dir

    root = Path(config.config_file_path).resolve().parent
    dest = _DEST = cache_dir() / "docs-figures" / _key(root)
    wanted = [("reproduce", n) for n in REPRODUCE_FILES] + [("simulate", n)
                                                            for n in SIMULATE_FILES]
    if not all((dest / a / n).is_file() for a, n in wanted):
        _build(dest)
    for sub, name in wanted:
        if name.endswith(".md"):
            continue  # read by on_page_markdown, not a page of the site
        files.append(File.generated(config, f"figures/{sub}/{name}",
                                    abs_src_path=str(dest / sub / name)))
    return files


ALTERNATIVES = re.compile(r"^<!--\s*snakecg-alternatives\s*-->\s*$", re.MULTILINE)
TABLE2 = re.compile(r"^<!--\s*snakecg-table2\s*-->\s*$", re.MULTILINE)


def on_page_markdown(markdown, page, config, files):
    """``<!-- snakecg-table2 -->``: Table 2 of this build's run with its footnotes (its caption
    is left to the page); ``<!-- snakecg-alternatives -->``: the alternatives table."""
    if "snakecg-alternatives" in markdown:
        text = (_DEST / "reproduce" / "alternatives.md").read_text(encoding="utf-8")
        markdown = ALTERNATIVES.sub(lambda m: text.rstrip("\n") + "\n", markdown)
    if "snakecg-table2" in markdown:
        text = (_DEST / "reproduce" / "table2.md").read_text(encoding="utf-8")
        table, _, rest = text.partition("\n\n")
        notes = rest.rstrip("\n").rpartition("\n\n")[0]
        markdown = TABLE2.sub(lambda m: f"{table}\n\n{notes}\n", markdown)
    return markdown
