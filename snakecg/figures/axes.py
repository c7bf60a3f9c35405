"""What every planar drawing shares: its colours, the length of its force and acceleration
arrows, and the frame of its axes."""

from __future__ import annotations

import numpy as np

__all__ = ["COLORS", "frame"]

#: Colours of the drawing (matplotlib's tab palette).
COLORS = {"snake": "tab:blue", "contact_link": "tab:orange", "object": "0.82",
          "normal": "tab:red", "wheel": "0.15", "force": "tab:purple", "acc": "tab:green"}


def _scale(vectors, target):
    big = max((float(np.hypot(*v)) for v in vectors), default=0.0)
    return (target / big, big) if big > 0 else (0.0, 0.0)


def frame(ax, tips, margin: float) -> None:
    """Limits around every point of ``tips`` (arrays of 2-D points) with ``margin`` of their
    extent, equal axes in metres, a light grid."""
    pts = np.concatenate([np.asarray(t).reshape(-1, 2) for t in tips])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = margin * float(max(hi - lo)) + 1e-3
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.grid(True, lw=0.3, alpha=0.5)
