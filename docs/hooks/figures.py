"""MkDocs hook: the figures of the site, computed when the site is built.

* ``figures/reproduce/``: Figs. 4 (kappa = 100), 5 and 6 from a reduced ``snakecg reproduce``
  run (``REDUCED``: a coarser joint grid and torque grid than the full run, PNG only), so the
  pages show what the code computes today, not a picture that can go stale.
* ``figures/simulate/``: the figures and the animation of the push that the Simulation page's
  first example runs (``SIMULATION``).

The run takes seconds; its output is kept in the snakecg cache folder under a key made of the
package's sources, the checked-in generated models and this file, so a rebuild with nothing
changed (``mkdocs serve``, the second build of CI) reuses it. Pages refer to the files as
``figures/...``; ``mkdocs build --strict`` fails if one is missing.
"""

from __future__ import annotations

import hashlib
import logging
import os
import shutil
import tempfile
import time
from pathlib import Path

from mkdocs.structure.files import File

log = logging.getLogger("mkdocs.hooks.snakecg.figures")

#: The reduced reproduction: every joint on -135..135 deg every 30 deg (10^3 = 1,000 shapes of
#: case study 2 instead of 21,952), a 91 x 91 torque grid instead of 181 x 181, kappa = 100 only.
REDUCED = dict(kappas_case1=(100.0,), grid_step_deg=30.0, torque_grid=91, formats=("png",),
               progress=False, jobs=1)
REPRODUCE_FILES = ("fig4_kappa100.png", "fig5_polar.png", "fig6_configurations.png")
#: The Simulation page's first example (docs/simulate.md).
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
    from snakecg.reproduce import ReproduceOptions, reproduce

    reproduce(ReproduceOptions(out=folder, **REDUCED), echo=lambda *a: None)


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
    dest.parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=".figures-", dir=dest.parent))
    try:
        t = time.perf_counter()
        _reproduce(work / "reproduce")
        _simulate(work / "simulate")
        log.info("figures computed in %.1f s", time.perf_counter() - t)
        try:
            os.replace(work, dest)
        except OSError:  # another build finished first: use its copy
            shutil.rmtree(work, ignore_errors=True)
    except BaseException:
        shutil.rmtree(work, ignore_errors=True)
        raise


def on_files(files, config):
    from snakecg.artifacts import cache_dir

    root = Path(config.config_file_path).resolve().parent
    dest = cache_dir() / "docs-figures" / _key(root)
    wanted = [("reproduce", n) for n in REPRODUCE_FILES] + [("simulate", n)
                                                            for n in SIMULATE_FILES]
    if not all((dest / a / n).is_file() for a, n in wanted):
        _build(dest)
    for sub, name in wanted:
        files.append(File.generated(config, f"figures/{sub}/{name}",
                                    abs_src_path=str(dest / sub / name)))
    return files
