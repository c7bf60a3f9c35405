"""Spellings the commands accept, and how they print the limits that bound an answer."""

from __future__ import annotations

import math

__all__ = ["objective_name", "limits_line"]


def objective_name(text: str) -> str:
    """An objective as the command line spells it (``max-sr``), from either spelling
    (``max-sr`` or ``max_sr``, as Python takes them); argparse then checks the choices."""
    return text.strip().replace("_", "-")


def _numbers(values) -> str:
    vals = [float(v) for v in values]
    if len(set(vals)) == 1:
        return f"{vals[0]:.6g}"
    return "(" + ", ".join(f"{v:.6g}" for v in vals) + ")"


_FROM = {"robot": "the robot's limits", "argument": "given",
         "paper": "the paper's range; the robot states none"}


def limits_line(limits: dict | None) -> str:
    """One line: the joint range, the torque box and the ellipsoid of an answer, with their
    sources (``snakecg.limits.describe``)."""
    if not limits:
        return "none recorded"
    parts = []
    if limits.get("joint_limits") is not None:
        lo = [math.degrees(p[0]) for p in limits["joint_limits"]]
        hi = [math.degrees(p[1]) for p in limits["joint_limits"]]
        rng = (f"{lo[0]:.4g}..{hi[0]:.4g} deg" if len(set(lo)) == 1 and len(set(hi)) == 1
               else ", ".join(f"{a:.4g}..{b:.4g}" for a, b in zip(lo, hi)) + " deg")
        parts.append(f"joints {rng} ({_FROM.get(limits.get('joint_limits_from'), '?')})")
    if limits.get("tau_max") is not None:
        parts.append(f"|tau_j| <= {_numbers(limits['tau_max'])} N m "
                     f"({_FROM.get(limits.get('tau_max_from'), '?')})")
    else:
        parts.append("no torque box")
    if limits.get("radius") is not None:
        parts.append(f"ellipsoid radius {limits['radius']:.6g} (eq. 31)")
    return "; ".join(parts)
