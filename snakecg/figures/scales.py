"""Colour scales and titles of the metric panels: one rule for every figure that colours a
metric (the paper's Figs. 4 and 5, a sweep's polar figure).

* **Constant**: a panel whose values spread by less than :data:`CONSTANT_REL` of their
  magnitude (or :data:`CONSTANT_ULPS` units in the last place) holds rounding noise, not
  structure: it is drawn in one colour, and its colour bar has one tick, the value, and says
  ``constant 1.000``.
* **Narrow**: a spread below :data:`NARROW_REL` of the magnitude is drawn over the whole
  colour range (so that its structure shows), and the colour bar says so: the range and the
  spread in percent (``range 0.9896 to 1: 1 % spread, stretched``).
* **Bounds**: the slippage ratio lies in [0, 1] (eq. 30) and the squared norms are >= 0: no
  colour level, tick or bar end lies outside.
* **Titles** carry the symbol and the unit (:func:`metric_title`), never a code name.
* **Polar panels** name their radius rings beside the axes (:func:`polar_rings`), not on
  the data.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["METRIC_LABEL", "METRIC_UNIT", "CONSTANT_REL", "CONSTANT_ULPS", "NARROW_REL",
           "Scale", "metric_title", "colour_scale", "colorbar", "polar_rings"]

METRIC_LABEL = {
    "norm_a_obj": r"$\|\vec a_{obj}\|^2$",
    "norm_qdd": r"$\|\ddot q_s\|^2$",
    "norm_lambda": r"$\|\vec\lambda\|^2$",
    "sr": "sr",
}
METRIC_UNIT = {"norm_a_obj": r"kg m$^2$/s$^4$", "norm_qdd": r"kg m$^2$/s$^4$",
               "norm_lambda": r"N$^2$/kg", "sr": "–"}
#: The range each metric can take: sr in [0, 1] (eq. 30), the squared norms >= 0.
METRIC_BOUNDS = {"sr": (0.0, 1.0), "norm_a_obj": (0.0, math.inf),
                 "norm_qdd": (0.0, math.inf), "norm_lambda": (0.0, math.inf)}
#: Relative spread below which a panel is constant (rounding noise).
CONSTANT_REL = 1e-9
#: ... or a spread of at most this many units in the last place of the magnitude.
CONSTANT_ULPS = 8
#: Relative spread below which a panel's colours are said to be stretched.
NARROW_REL = 0.05
#: A data end within this fraction of a colour level's step beyond the round levels moves the
#: end level onto it (rather than adding a level a rounding error away).
MERGE_REL = 0.01


def metric_title(metric: str) -> str:
    """``$\\|\\vec\\lambda\\|^2$ [N$^2$/kg]``: the metric's symbol and unit."""
    return f"{METRIC_LABEL[metric]} [{METRIC_UNIT[metric]}]"


@dataclass
class Scale:
    """A panel's colours: ``norm`` and ``cmap`` for the plot, ``ticks`` and ``tick_labels``
    and ``label`` for its colour bar; ``kind`` is ``"constant"``, ``"narrow"``, ``"full"``
    or ``"empty"``; ``lo``/``hi`` the data's finite extremes (None when empty)."""

    norm: object
    cmap: object
    ticks: list
    tick_labels: list
    label: str
    kind: str
    lo: float | None
    hi: float | None


def _labels(ticks) -> list[str]:
    """The fewest significant digits (2 to 15) that give every tick within 1 % of the
    ticks' least spacing (so that neighbours never read alike or out of order)."""
    t = np.asarray(ticks, dtype=float)
    gaps = np.diff(np.sort(t))
    tol = 0.01 * float(gaps[gaps > 0].min()) if np.any(gaps > 0) else 0.0
    for digits in range(2, 16):
        out = [f"{x:.{digits}g}" for x in t]
        if all(abs(float(o) - x) <= tol for o, x in zip(out, t)) and len(set(out)) == len(out):
            return out
    return [repr(float(x)) for x in t]


def _is_constant(lo: float, hi: float) -> bool:
    mag = max(abs(lo), abs(hi))
    return hi - lo <= max(CONSTANT_REL * mag, CONSTANT_ULPS * math.ulp(mag))


def colour_scale(values, metric: str, *, levels: int | None = None, from_zero: bool = False,
                 cmap: str = "viridis") -> Scale:
    """The colour scale of a panel of ``metric`` over ``values`` (NaN and infinite entries,
    such as empty bins, are left out), by the rules of the module doc.

    ``levels``: None for a continuous scale, else about that many discrete colour levels
    (a :class:`~matplotlib.colors.BoundaryNorm`); ``from_zero``: the scale starts at 0 (the
    metric's lower bound) instead of the data's least value, so the colours show the spread
    relative to the magnitude (no stretching).
    """
    import matplotlib
    from matplotlib.colors import BoundaryNorm, ListedColormap, Normalize
    from matplotlib.ticker import MaxNLocator

    base = matplotlib.colormaps[cmap]
    title = metric_title(metric)
    bound_lo, bound_hi = METRIC_BOUNDS[metric]
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return Scale(Normalize(0.0, 1.0), base, [], [], f"{title}: no data", "empty", None,
                     None)
    lo, hi = float(v.min()), float(v.max())
    if _is_constant(lo, hi):
        value = 0.5 * (lo + hi)
        pad = max(abs(value), 1.0) * 1e-6  # far above the noise: every cell one colour
        vmin, vmax = max(value - pad, bound_lo), min(value + pad, bound_hi)
        if not vmin < vmax:
            vmin, vmax = value - pad, value + pad
        one = ListedColormap([base(0.5)])
        return Scale(Normalize(vmin, vmax), one, [value], [f"{value:#.4g}"],
                     f"{title}: constant {value:#.4g} (spread {hi - lo:.1e}, rounding)",
                     "constant", lo, hi)
    start = max(bound_lo, 0.0) if from_zero and math.isfinite(bound_lo) else lo
    spread = (hi - lo) / max(abs(lo), abs(hi))
    narrow = spread < NARROW_REL and not from_zero
    label = title
    if narrow:
        label = (f"{title}\nrange {lo:.4g} to {hi:.4g}: {100 * spread:.2g} % spread, "
                 "stretched")
    if levels is None:
        locator = MaxNLocator(nbins=6)
        ticks = [t for t in locator.tick_values(start, hi) if start <= t <= hi]
        norm = Normalize(start, hi)
        return Scale(norm, base, ticks, _labels(ticks), label, "narrow" if narrow else "full",
                     lo, hi)
    bounds = MaxNLocator(nbins=levels).tick_values(start, hi)
    bounds = np.unique(np.clip(bounds, bound_lo, bound_hi))
    # the data's ends beyond the round levels (the clip may have lifted the first one above
    # the data): a level of their own, or, within MERGE_REL of a level step (rounding, such
    # as a maximum of 1 + 1e-15), the end level moved onto them; a level of its own there
    # would take 16 digits to tell from its neighbour and print the rounding noise
    step = float(np.diff(bounds).min()) if len(bounds) > 1 else 0.0
    if bounds[0] > start:
        if bounds[0] - start <= MERGE_REL * step:
            bounds[0] = start
        else:
            bounds = np.r_[start, bounds]
    if bounds[-1] < hi:
        if hi - bounds[-1] <= MERGE_REL * step:
            bounds[-1] = hi
        else:
            bounds = np.r_[bounds, hi]
    norm = BoundaryNorm(bounds, base.N, clip=True)
    ticks = [float(b) for b in bounds]
    return Scale(norm, base, ticks, _labels(ticks), label, "narrow" if narrow else "full", lo,
                 hi)


def colorbar(fig, mappable, ax, scale: Scale, *, fontsize: float = 9, **kw):
    """The colour bar of a panel drawn with ``scale``: its ticks, tick labels and label."""
    cb = fig.colorbar(mappable, ax=ax, **kw)
    cb.set_ticks(scale.ticks)
    cb.set_ticklabels(scale.tick_labels)
    cb.set_label(scale.label, fontsize=fontsize)
    cb.ax.tick_params(labelsize=fontsize)
    return cb


def polar_rings(ax, r_max: float, *, fontsize: float = 9, unit: str = "m") -> list[float]:
    """Radius rings of a polar panel at round values below ``r_max``, named in one line below
    the panel instead of by labels on the data; returns the rings' radii."""
    from matplotlib.ticker import MaxNLocator

    rings = [float(r) for r in MaxNLocator(nbins=4).tick_values(0.0, r_max) if 0 < r < r_max]
    ax.set_rlim(0, r_max)
    ax.set_rticks(rings)
    ax.set_yticklabels([])
    ax.text(0.5, -0.13, "rings: radius " + ", ".join(_labels(rings)) + f" {unit}",
            transform=ax.transAxes, ha="center", va="top", fontsize=fontsize)
    return rings
