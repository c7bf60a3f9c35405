"""The paper's Figures 4-6 drawn from computed data (``snakecg reproduce`` computes, this draws).

Every function takes plain NumPy data (no model), so a figure can be drawn in another process
while the next study computes, and writes each requested format atomically. Drawing is kept
cheap: the Agg and SVG backends directly (no pyplot state), fixed layouts instead of a layout
engine, images and meshes rasterized, one draw per format.

* :func:`figure4`: the metrics over the torque plane of case study 1, one figure per kappa;
  each panel has its own colour scale from 0 (the slippage ratio of scenario 1 stays below
  0.03).
* :func:`figure5`: per-configuration maxima against the polar coordinates of the COM, binned
  (the colour of a cell is the largest value of the configurations whose COM falls in it), on
  a few discrete levels between the data's extremes; cells whose largest value belongs to a
  physically infeasible shape are dotted.

Colour scales and titles follow :mod:`snakecg.figures.scales`: a panel constant to rounding
is drawn flat and says so, a narrow spread says it is stretched, sr stays within [0, 1], and
titles carry the symbol and the unit.
* :func:`figure6`: the worst and best shapes of Table 2, drawn to one scale; infeasible shapes
  (links crossing, or entering the object) are framed and labelled in red.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .scales import METRIC_LABEL, colorbar, colour_scale, metric_title, polar_rings

__all__ = ["Drawer", "Fig4Panel", "Shape", "figure4", "figure5", "figure6", "make_figure4",
           "make_figure5", "make_figure6", "write_figure", "METRIC_LABEL"]

SCENARIO_LABEL = {"frictionless": "Scenario 1 (frictionless)",
                  "wheels": "Scenario 2 (wheels, μ = 0.1)",
                  "ideal_wheels": "Scenario 3 (ideal wheels)"}
FONT = 10          # every text of the figures is at least 9 pt
PNG_DPI = 110


def _figure(width, height):
    """A figure outside pyplot (no global state, no GUI backend), Agg canvas attached."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    return fig


def write_figure(fig, stem: Path, formats) -> list[Path]:
    """Write ``fig`` as ``stem.<fmt>`` for each format, each file atomically (a uniquely
    named temporary file in the same folder, then ``os.replace``)."""
    from .._files import atomic_path

    written = []
    for fmt in formats:
        path = Path(f"{stem}.{fmt}")
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format=fmt, dpi=PNG_DPI if fmt == "png" else 100)
        written.append(path)
    return written


# ------------------------------------------------------------------------------------------
# Fig. 4
# ------------------------------------------------------------------------------------------
@dataclass
class Fig4Panel:
    """One scenario's torque plane: axes ``t1``, ``t2``, metric ``grids`` (``norm_a_obj``,
    ``norm_qdd``, ``sr``, ``contact``) and the input ellipsoid's outline ``ellipse`` (2, n)."""

    scenario: str
    t1: np.ndarray
    t2: np.ndarray
    grids: dict
    ellipse: np.ndarray


def figure4(panels, *, stem: Path, formats, **kw) -> list[Path]:
    """Draw :func:`make_figure4` and write it as ``stem.<fmt>``."""
    return write_figure(make_figure4(panels, **kw), stem, formats)


def make_figure4(panels: list[Fig4Panel], *, kappa: float, joints_deg, infeasible: str = ""):
    """Fig. 4 for one kappa: rows ``norm_a_obj``, ``norm_qdd``, ``sr``; one column per
    scenario. ``infeasible`` names why the configuration is not physically possible ("" when
    it is)."""
    from matplotlib.ticker import MaxNLocator

    fig = _figure(14.5, 12.5)
    # the torque plane depends on q and the robot only: every panel has the same axes
    axes = fig.subplots(3, len(panels), squeeze=False, sharex=True, sharey=True,
                        gridspec_kw=dict(left=0.06, right=0.94, bottom=0.05, top=0.87,
                                         wspace=0.30, hspace=0.25))
    for j, panel in enumerate(panels):
        extent = (panel.t1[0], panel.t1[-1], panel.t2[0], panel.t2[-1])
        for i, metric in enumerate(("norm_a_obj", "norm_qdd", "sr")):
            ax = axes[i, j]
            z = panel.grids[metric]
            scale = colour_scale(z, metric, from_zero=True)
            im = ax.imshow(z, origin="lower", aspect="auto", cmap=scale.cmap, norm=scale.norm,
                           extent=extent, interpolation="nearest", rasterized=True)
            ax.plot(panel.ellipse[0], panel.ellipse[1], color="white", lw=1.3, ls="--")
            ax.contour(panel.t1, panel.t2, panel.grids["contact"].astype(float), levels=[0.5],
                       colors="red", linewidths=1.0)
            if i == 2:
                ax.set_xlabel(r"$\tau_1$ [N m]", fontsize=FONT)
            if j == 0:
                ax.set_ylabel(r"$\tau_2$ [N m]", fontsize=FONT)
            ax.tick_params(labelsize=FONT - 1)
            ax.xaxis.set_major_locator(MaxNLocator(5))
            ax.label_outer()
            ax.set_title(f"{metric_title(metric)}\n{SCENARIO_LABEL[panel.scenario]}",
                         fontsize=FONT, y=1.0)  # a fixed place: no layout pass per draw
            colorbar(fig, im, ax, scale, fontsize=FONT - 1, fraction=0.08, pad=0.03)
    q = ", ".join(f"{d:g}°" for d in joints_deg)
    title = (f"Fig. 4 (case study 1, 2 joints): norms over the torque plane at q = (0, 0, 0, {q}),"
             f" $\\kappa$ = {kappa:g}\nwhite dashed: input ellipsoid (31); red: boundary between "
             "torques that keep and lose the contact; each colour scale spans its panel's range")
    fig.suptitle(title, fontsize=FONT + 2)
    if infeasible:
        fig.text(0.5, 0.915, f"This configuration is not physically feasible ({infeasible}); "
                 "the paper uses it, and so does this figure.", ha="center", color="firebrick",
                 fontsize=FONT + 1)
    return fig


# ------------------------------------------------------------------------------------------
# Fig. 5
# ------------------------------------------------------------------------------------------
ANGLE_BINS = 72    # 5 degrees
RADIUS_BINS = 24


def _binned_max(angle, radius, values, infeasible, r_max):
    """Largest value per (angle, radius) cell, and whether an infeasible shape attains it."""
    ia = np.clip(((angle + np.pi) / (2 * np.pi) * ANGLE_BINS).astype(int), 0, ANGLE_BINS - 1)
    ir = np.clip((radius / r_max * RADIUS_BINS).astype(int), 0, RADIUS_BINS - 1)
    cell = ia * RADIUS_BINS + ir
    order = np.lexsort((values, cell))          # by cell, then by value: the last is the max
    last = np.r_[cell[order][1:] != cell[order][:-1], True]
    top = order[last]
    z = np.full(ANGLE_BINS * RADIUS_BINS, np.nan)
    bad = np.zeros(ANGLE_BINS * RADIUS_BINS, bool)
    z[cell[top]] = values[top]
    bad[cell[top]] = infeasible[top]
    return z.reshape(ANGLE_BINS, RADIUS_BINS), bad.reshape(ANGLE_BINS, RADIUS_BINS)


def figure5(angle, radius, maxima, *, stem: Path, formats, **kw) -> list[Path]:
    """Draw :func:`make_figure5` and write it as ``stem.<fmt>``."""
    return write_figure(make_figure5(angle, radius, maxima, **kw), stem, formats)


def make_figure5(angle, radius, maxima: dict, *, infeasible, kappa: float,
                 feasible_only: bool = False):
    """Fig. 5: ``maxima[scenario][metric]`` (per configuration) against the COM's polar
    coordinates ``angle``, ``radius``; ``infeasible`` marks the shapes that are not physically
    possible (left out when ``feasible_only``)."""
    angle, radius = np.asarray(angle), np.asarray(radius)
    infeasible = np.asarray(infeasible, bool)
    keep = ~infeasible if feasible_only else np.ones(len(angle), bool)
    r_max = float(radius.max()) * 1.0001
    theta = np.linspace(-np.pi, np.pi, ANGLE_BINS + 1)
    rr = np.linspace(0.0, r_max, RADIUS_BINS + 1)
    tc, rc = np.meshgrid(0.5 * (theta[1:] + theta[:-1]), 0.5 * (rr[1:] + rr[:-1]), indexing="ij")
    scenarios = list(maxima)
    metrics = ("norm_lambda", "norm_a_obj", "sr")
    fig = _figure(4.6 * len(scenarios), 14.0)
    axes = fig.subplots(3, len(scenarios), squeeze=False, subplot_kw={"projection": "polar"},
                        gridspec_kw=dict(left=0.04, right=0.93, bottom=0.04, top=0.88,
                                         wspace=0.5, hspace=0.42))
    for j, s in enumerate(scenarios):
        for i, m in enumerate(metrics):
            ax = axes[i, j]
            z, bad = _binned_max(angle[keep], radius[keep], np.asarray(maxima[s][m])[keep],
                                 infeasible[keep], r_max)
            scale = colour_scale(z, m, levels=8)
            mesh = ax.pcolormesh(theta, rr, np.ma.masked_invalid(z).T, cmap=scale.cmap,
                                 norm=scale.norm, shading="flat", rasterized=True)
            if bad.any():
                ax.plot(tc[bad], rc[bad], ".", color="black", ms=2.0, alpha=0.7)
            ax.set_title(f"max {metric_title(m)} over (31)\n{SCENARIO_LABEL[s]}",
                         fontsize=FONT, pad=12)
            polar_rings(ax, r_max, fontsize=FONT - 1)
            ax.tick_params(labelsize=FONT - 1)
            ax.grid(alpha=0.4)
            colorbar(fig, mesh, ax, scale, fontsize=FONT - 1, shrink=0.78, pad=0.10)
    shown = "physically feasible shapes only" if feasible_only else (
        "every shape of the grid; black dots: the cell's largest value belongs to a shape whose "
        "links cross or enter the object")
    fig.suptitle(
        f"Fig. 5 (case study 2, 3 joints, $\\kappa$ = {kappa:g}): per-configuration maxima over "
        "the input ellipsoid against the polar coordinates of the snake's COM\n(radius [m] from "
        "the contact point, angle from the contacting link's axis); each cell shows the largest "
        f"value of the configurations whose COM lies in it ({ANGLE_BINS} × {RADIUS_BINS} cells)"
        f"\n{shown}", fontsize=FONT + 1)
    return fig


# ------------------------------------------------------------------------------------------
# Fig. 6
# ------------------------------------------------------------------------------------------
@dataclass
class Shape:
    """A configuration to draw: link ends ``rear``/``front`` (n_l, 2), the object's pose
    ``(x, y, psi)``, the contact point, the robot's COM, a ``title`` and ``infeasible`` (why
    the shape is not physically possible, "" when it is)."""

    rear: np.ndarray
    front: np.ndarray
    object_pose: np.ndarray
    contact: np.ndarray
    com: np.ndarray
    title: str
    infeasible: str = ""
    object_side: float = 0.1
    extra: dict = field(default_factory=dict)


def _object_corners(pose, side):
    c, psi = np.asarray(pose[:2]), pose[2]
    R = np.array([[np.cos(psi), -np.sin(psi)], [np.sin(psi), np.cos(psi)]])
    h = side / 2
    return np.array([c + R @ v for v in ([-h, -h], [h, -h], [h, h], [-h, h])])


def draw_shape(ax, shape: Shape, *, lw=4.0):
    """Links (tail orange, others blue), joints, the object (grey), contact (red star) and the
    robot's COM (black cross)."""
    from matplotlib.patches import Polygon

    ax.add_patch(Polygon(_object_corners(shape.object_pose, shape.object_side), closed=True,
                         fc="0.82", ec="0.2", lw=1.0, zorder=1))
    for i, (a, b) in enumerate(zip(shape.rear, shape.front)):
        ax.plot([a[0], b[0]], [a[1], b[1]], "-", lw=lw, solid_capstyle="round", zorder=2,
                color="tab:orange" if i == 0 else "tab:blue")
    joints = shape.front[:-1]
    ax.plot(joints[:, 0], joints[:, 1], "o", color="black", ms=3.5, zorder=3)
    ax.plot(*shape.contact, "*", color="red", ms=11, zorder=4)
    ax.plot(*shape.com, "x", color="black", ms=8, mew=2, zorder=4)


def figure6(rows, *, stem: Path, formats, **kw) -> list[Path]:
    """Draw :func:`make_figure6` and write it as ``stem.<fmt>``."""
    return write_figure(make_figure6(rows, **kw), stem, formats)


def make_figure6(rows: dict, *, feasible_only: bool = False):
    """Fig. 6: ``rows[scenario]`` is a list of :class:`Shape` (worst/best ``norm_a_obj``,
    worst/best ``sr``), drawn to one common scale."""
    scenarios = list(rows)
    n_col = max(len(v) for v in rows.values())
    pts = np.concatenate([np.concatenate([s.rear, s.front,
                                          _object_corners(s.object_pose, s.object_side)])
                          for v in rows.values() for s in v])
    lo, hi = pts.min(axis=0) - 0.03, pts.max(axis=0) + 0.03
    span = hi - lo
    cell_w = 3.6
    cell_h = cell_w * span[1] / span[0]
    fig = _figure(cell_w * n_col + 1.2, (cell_h + 1.35) * len(scenarios) + 1.0)
    axes = fig.subplots(len(scenarios), n_col, squeeze=False, sharex=True, sharey=True,
                        gridspec_kw=dict(left=0.07, right=0.99, bottom=0.05, top=0.90,
                                         wspace=0.06, hspace=0.45))
    for i, s in enumerate(scenarios):
        for k, shape in enumerate(rows[s]):
            ax = axes[i, k]
            draw_shape(ax, shape)
            ax.set_xlim(lo[0], hi[0])
            ax.set_ylim(lo[1], hi[1])
            ax.set_aspect("equal")
            ax.tick_params(labelsize=FONT - 1)
            ax.set_title(shape.title, fontsize=FONT, y=1.0)
            if shape.infeasible:
                for spine in ax.spines.values():
                    spine.set_edgecolor("firebrick")
                    spine.set_linewidth(2.5)
                ax.text(0.5, 0.02, f"infeasible: {shape.infeasible}", transform=ax.transAxes,
                        ha="center", va="bottom", color="firebrick", fontsize=FONT,
                        bbox=dict(fc="white", ec="none", alpha=0.8, pad=1.5))
            if k == 0:
                ax.set_ylabel(f"{SCENARIO_LABEL[s]}\ny [m]", fontsize=FONT)
            if i == len(scenarios) - 1:
                ax.set_xlabel("x [m]", fontsize=FONT)
            ax.label_outer()
    which = "among physically feasible shapes" if feasible_only else (
        "over every shape of the grid (red frame: links cross or enter the object)")
    fig.suptitle("Fig. 6 (case study 2): worst and best configurations of Table 2, " + which +
                 "\ntail link orange, joints black, contact red star, snake COM black cross, "
                 "object grey", fontsize=FONT + 1)
    return fig


# ------------------------------------------------------------------------------------------
# Drawing beside the computation
# ------------------------------------------------------------------------------------------
def _draw_task(name: str, kwargs: dict):
    """Run one figure function; return its files and the CPU time it took."""
    import time

    cpu = time.process_time()
    files = globals()[name](**kwargs)
    return files, time.process_time() - cpu


class Drawer:
    """Draws figures in ``jobs`` worker processes while the caller goes on computing, or in
    the calling process when ``jobs <= 1`` (or when no worker can be started).

    The workers are fresh interpreters (``spawn``) that import only this module: they do not
    run the caller's script again, whatever it guards, and inherit no threads. ``submit``
    queues a figure; ``finish`` waits for all and returns the files in submission order,
    re-raising a worker's error.
    """

    def __init__(self, jobs: int = 1):
        self.cpu = 0.0
        self._pool = None
        self._pending = []
        if jobs > 1:
            self._pool = _spawn_pool(jobs)

    @property
    def parallel(self) -> bool:
        return self._pool is not None

    def submit(self, name: str, **kwargs) -> None:
        if self._pool is None:
            files, cpu = _draw_task(name, kwargs)
            self.cpu += cpu
            self._pending.append(files)
        else:
            self._pending.append(self._pool.apply_async(_draw_task, (name, kwargs)))

    def finish(self) -> list[Path]:
        out = []
        for item in self._pending:
            if isinstance(item, list):
                out += item
            else:
                files, cpu = item.get()
                self.cpu += cpu
                out += files
        self._pending = []
        return out

    def close(self) -> None:
        if self._pool is not None:
            self._pool.terminate()
            self._pool.join()
            self._pool = None


def _spawn_pool(jobs: int):
    """A ``spawn`` pool whose workers do not import the caller's ``__main__``: the workers are
    started (all at once, by ``multiprocessing.Pool``) while ``__main__`` is a bare module, so
    an unguarded script that calls ``reproduce`` is not run again in each worker. ``None``
    when processes cannot be started here."""
    import multiprocessing
    import sys
    import types

    main = sys.modules.get("__main__")
    sys.modules["__main__"] = types.ModuleType("__main__")
    try:
        return multiprocessing.get_context("spawn").Pool(jobs)
    except (OSError, ImportError, RuntimeError):
        return None
    finally:
        if main is not None:
            sys.modules["__main__"] = main
