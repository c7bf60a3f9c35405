"""Reductions of a sweep store, chunk by chunk (never the whole store in memory):
a Table-2-style summary and a Fig.-5-style polar figure of binned maxima."""

from __future__ import annotations

import math
import os
import uuid
from pathlib import Path

import numpy as np

from ..analysis import METRICS
from ..errors import InputError
from . import store as _store
from .plan import plan_from_meta

__all__ = ["summary", "figure", "read", "SUMMARY_SCHEMA"]

#: Version of the summary's JSON (``snakecg sweep --summary STORE --json``).
SUMMARY_SCHEMA = "snakecg.sweep.summary/1"


def _open(store):
    if not isinstance(store, (str, Path)) or not str(store).strip():
        raise InputError(f"store must be the path of a sweep store, got {store!r}")
    path = Path(store)
    if not (path / "zarr.json").is_file():
        raise InputError(f"{str(path)!r} is not a sweep store (no Zarr group there)")
    root = _store.open_existing(path, mode="r")
    meta = dict(root.attrs)["snakecg_sweep"]
    return root, meta, plan_from_meta(meta)


def _recorded(root, plan):
    """Indices of the chunks whose data is recorded complete."""
    return [int(i) for i in np.flatnonzero(root["chunk_digest"][:] != 0)]


def read(store) -> dict[str, np.ndarray]:
    """Every array of a (small) store in memory; configurations of chunks not computed yet
    are NaN. Also ``complete``: a boolean per configuration."""
    root, meta, plan = _open(store)
    out = {name: root[name][:] for name in _store.array_names()}
    complete = np.zeros(plan.size, dtype=bool)
    for i in _recorded(root, plan):
        start, stop = plan.chunk_range(i)
        complete[start:stop] = True
    out["complete"] = complete
    return out


def _entry(chunk, j, metric, start):
    return {
        "value": float(chunk[f"max_{metric}"][j]),
        "index": int(start + j),
        "q_deg": [float(x) for x in np.rad2deg(chunk["q"][j])],
        "tau": [float(x) for x in chunk[f"tau_max_{metric}"][j]],
        "com_radius": float(chunk["com_radius"][j]),
        "com_angle_deg": float(np.rad2deg(chunk["com_angle"][j])),
    }


def summary(store) -> dict:
    """Table 2 of the sweep: for every metric, the worst (smallest) and the best (largest)
    per-configuration maximum over the input ellipsoid, with the configuration attaining it
    (index, joint angles in degrees, torque, COM's polar coordinates). Computed chunk by
    chunk over the chunks written so far (``complete`` says whether that is all of them)."""
    root, meta, plan = _open(store)
    names = ["q", "com_radius", "com_angle"] + [f"{p}{m}" for m in METRICS
                                                  for p in ("max_", "tau_max_")]
    best: dict = {m: None for m in METRICS}
    worst: dict = {m: None for m in METRICS}
    chunks = _recorded(root, plan)
    counted = 0
    for i in chunks:
        start, stop = plan.chunk_range(i)
        data = _store.read_chunk(root, start, stop, names)
        counted += stop - start
        for m in METRICS:
            v = data[f"max_{m}"]
            if not np.any(np.isfinite(v)):
                continue
            hi, lo = int(np.nanargmax(v)), int(np.nanargmin(v))
            if best[m] is None or v[hi] > best[m]["value"]:
                best[m] = _entry(data, hi, m, start)
            if worst[m] is None or v[lo] < worst[m]["value"]:
                worst[m] = _entry(data, lo, m, start)
    scene = dict(meta["scene"])
    return {
        "schema": SUMMARY_SCHEMA,
        "store": str(store),
        "joints": meta["robot"]["joints"],
        "scenario": scene["scenario"], "kappa": scene["kappa"], "mu": scene["mu"],
        "configurations": plan.size,
        "summarized_configurations": counted,
        "chunks": plan.n_chunks, "completed_chunks": len(chunks),
        "complete": len(chunks) == plan.n_chunks,
        "metrics": {m: {"worst": worst[m], "best": best[m]} for m in METRICS},
    }


def summary_text(s: dict) -> str:
    """The summary as a terminal table."""
    lines = [f"{s['store']}: {s['joints']} joints, {s['scenario']}, kappa {s['kappa']:g}, "
             f"{s['summarized_configurations']:,} of {s['configurations']:,} configurations"
             + ("" if s["complete"] else f" (incomplete: {s['completed_chunks']} of "
                                         f"{s['chunks']} chunks)"),
             f"{'per-configuration max of':<26}{'worst':>14}  {'at q (deg)':<28}"
             f"{'best':>14}  at q (deg)"]
    for m, d in s["metrics"].items():
        if d["worst"] is None:
            lines.append(f"{m:<26}{'-':>14}")
            continue
        qw = ",".join(f"{x:g}" for x in d["worst"]["q_deg"])
        qb = ",".join(f"{x:g}" for x in d["best"]["q_deg"])
        lines.append(f"{m:<26}{d['worst']['value']:>14.6g}  {qw:<28}"
                     f"{d['best']['value']:>14.6g}  {qb}")
    return "\n".join(lines)


def figure(store, out=None, *, radius_bins: int = 24, angle_bins: int = 36) -> Path:
    """Fig. 5 of the sweep: for each metric, the largest per-configuration maximum in each
    bin of the COM's polar coordinates (|COM| from the contact point, angle from the
    contacting link's axis), drawn on polar axes. Written (atomically) to ``out``, default
    ``STORE-polar.png`` beside the store; the format follows the suffix (png, svg, pdf)."""
    root, meta, plan = _open(store)
    for name, v in (("radius_bins", radius_bins), ("angle_bins", angle_bins)):
        if isinstance(v, bool) or not isinstance(v, int) or v < 2:
            raise InputError(f"{name} must be an integer >= 2, got {v!r}")
    path = Path(store)
    out = Path(out) if out is not None else path.with_name(path.name.removesuffix(".zarr")
                                                            + "-polar.png")
    fmt = out.suffix.lower().lstrip(".")
    if fmt not in ("png", "svg", "pdf"):
        raise InputError(f"figure file {str(out)!r} must end in .png, .svg or .pdf")
    if not out.parent.is_dir():
        raise InputError(f"figure file {str(out)!r}: its folder does not exist")
    chunks = _recorded(root, plan)
    if not chunks:
        raise InputError(f"{str(store)!r} has no completed chunk yet; nothing to draw")
    rmax = 0.0
    for i in chunks:  # pass 1: the radius range
        start, stop = plan.chunk_range(i)
        rmax = max(rmax, float(np.nanmax(root["com_radius"][start:stop])))
    rmax = rmax * (1 + 1e-9) or 1.0
    grid = {m: np.full((angle_bins, radius_bins), -np.inf) for m in METRICS}
    for i in chunks:  # pass 2: binned maxima
        start, stop = plan.chunk_range(i)
        data = _store.read_chunk(root, start, stop,
                                 ["com_radius", "com_angle"] + [f"max_{m}" for m in METRICS])
        ri = np.clip((data["com_radius"] / rmax * radius_bins).astype(int), 0, radius_bins - 1)
        ai = np.clip(((data["com_angle"] + math.pi) / (2 * math.pi) * angle_bins).astype(int),
                     0, angle_bins - 1)
        for m in METRICS:
            v = data[f"max_{m}"]
            ok = np.isfinite(v)
            np.maximum.at(grid[m], (ai[ok], ri[ok]), v[ok])
    _draw(grid, rmax, meta, plan, out, fmt)
    return out


def _draw(grid, rmax, meta, plan, out: Path, fmt: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    angle_bins, radius_bins = next(iter(grid.values())).shape
    theta = np.linspace(-math.pi, math.pi, angle_bins + 1)
    radius = np.linspace(0.0, rmax, radius_bins + 1)
    fig, axes = plt.subplots(2, 2, figsize=(10, 10), subplot_kw={"projection": "polar"},
                             constrained_layout=True)
    for ax, m in zip(axes.ravel(), ("norm_lambda", "norm_a_obj", "sr", "norm_qdd")):
        vals = np.where(np.isfinite(grid[m]), grid[m], np.nan)
        mesh = ax.pcolormesh(theta, radius, np.ma.masked_invalid(vals).T, cmap="viridis",
                             shading="flat")
        ax.set_title(f"largest max {m} per bin", fontsize=10)
        ax.set_rlabel_position(135)
        ax.tick_params(labelsize=7)
        fig.colorbar(mesh, ax=ax, shrink=0.7, pad=0.08)
    scene = meta["scene"]
    fig.suptitle(f"{plan.size:,} configurations, {meta['robot']['joints']} joints, "
                 f"{scene['scenario']}, kappa = {scene['kappa']:g}: per-configuration maxima "
                 f"over the input ellipsoid,\nbinned over |COM| [m] from the contact point and "
                 f"the angle of COM from the contacting link's axis", fontsize=10)
    tmp = out.with_name(f".{out.name}.{uuid.uuid4().hex}.partial")
    try:
        fig.savefig(tmp, format=fmt, dpi=120 if fmt == "png" else None)
        os.replace(tmp, out)
    finally:
        plt.close(fig)
        tmp.unlink(missing_ok=True)
