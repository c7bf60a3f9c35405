"""Reductions of a sweep store, chunk by chunk (never the whole store in memory):
a Table-2-style summary and a Fig.-5-style polar figure of binned maxima, over every shape
or over the physically feasible ones (the store's ``feasible`` array)."""

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

__all__ = ["summary", "figure", "binned_maxima", "read", "SUMMARY_SCHEMA"]

#: Version of the summary's JSON (``snakecg sweep --summary STORE --json``).
SUMMARY_SCHEMA = "snakecg.sweep.summary/1"


def _path(store) -> Path:
    if not isinstance(store, (str, Path)) or not str(store).strip():
        raise InputError(f"store must be the path of a sweep store, got {store!r}")
    return Path(store)


def _open(store):
    """``(reader, meta, plan)`` of a store: its attributes, metadata and digest table
    checked (:class:`~.store.Reader`; a damaged store is refused, saying what is damaged)."""
    path = _path(store)
    if not (path / "zarr.json").is_file():
        raise InputError(f"{str(path)!r} is not a sweep store (no Zarr group there)")
    root = _store.open_existing(path, mode="r")
    meta = dict(root.attrs)["snakecg_sweep"]
    plan = plan_from_meta(meta, str(path))
    return _store.Reader(path, root, plan, meta), meta, plan


def _has_feasible(meta) -> bool:
    return "feasible" in meta.get("arrays", ())


def _feasible_only(store, meta, feasible) -> bool:
    """Whether a reduction leaves infeasible shapes out: ``feasible`` if given, else the
    store's choice (``snakecg.sweep(feasible=...)``)."""
    if feasible is None:
        return bool(meta.get("feasible_only", False))
    if not isinstance(feasible, bool):
        raise InputError(f"feasible must be True, False or None (the store's choice), "
                         f"got {feasible!r}")
    if feasible and not _has_feasible(meta):
        raise InputError(f"{str(store)!r} has no feasible array (it was made by an older "
                         f"snakecg); sweep into a new store to leave infeasible shapes out")
    return feasible


def _clearance(meta):
    return meta.get("feasibility", {}).get("clearance")


def _recorded(reader):
    """Indices of the chunks whose data is recorded complete."""
    return [int(i) for i in np.flatnonzero(reader.recorded())]


def read(store) -> dict[str, np.ndarray]:
    """Every array of a (small) store in memory, each chunk checked against its digests
    (a damaged store is refused); configurations of chunks not computed yet are NaN
    (``feasible``: false). ``q`` in radians whatever the store's format: the joint angles
    the configurations were computed at (format 3 stores them in degrees, checked here to
    be exactly those of the store's grid or samples). Also ``complete``: a boolean per
    configuration."""
    reader, _, plan = _open(store)
    out = {}
    for name in reader.names:
        spec = reader.specs[name]
        out[name] = np.full((plan.size, *spec.row), spec.fill, dtype=spec.dtype.newbyteorder("="))
    complete = np.zeros(plan.size, dtype=bool)
    for i in _recorded(reader):
        start, stop = plan.chunk_range(i)
        data = reader.chunk(i)
        data["q"] = reader.q_rad(data, plan.joint_angles(start, stop), i)
        for name, v in data.items():
            out[name][start:stop] = v
        complete[start:stop] = True
    out["complete"] = complete
    return out


def _entry(chunk, j, metric, start):
    feasible = chunk.get("feasible")
    return {
        "value": float(chunk[f"max_{metric}"][j]),
        "index": int(start + j),
        "q_deg": [float(x) for x in chunk["q_deg"][j]],
        "tau": [float(x) for x in chunk[f"tau_max_{metric}"][j]],
        "com_radius": float(chunk["com_radius"][j]),
        "com_angle_deg": float(np.rad2deg(chunk["com_angle"][j])),
        "feasible": None if feasible is None else bool(feasible[j]),
    }


def summary(store, *, feasible=None) -> dict:
    """Table 2 of the sweep: for every metric, the worst (smallest) and the best (largest)
    per-configuration maximum over the input ellipsoid, with the configuration attaining it
    (index, joint angles in degrees, torque, COM's polar coordinates, whether the shape is
    feasible). Computed chunk by chunk over the chunks written so far (``complete`` says
    whether that is all of them).

    ``feasible``: True leaves out the shapes that are not physically possible (the store's
    ``feasible`` array, at the clearance recorded when it was made), False keeps every shape
    (the paper's reading), None (default) follows the store (``snakecg.sweep(feasible=...)``).
    """
    reader, meta, plan = _open(store)
    only = _feasible_only(store, meta, feasible)
    has = _has_feasible(meta)
    names = ["q", "com_radius", "com_angle"] + [f"{p}{m}" for m in METRICS
                                                  for p in ("max_", "tau_max_")]
    names += ["feasible"] if has else []
    sim = _SimulationTally(meta.get("simulation"))
    names += list(sim.names)
    best: dict = {m: None for m in METRICS}
    worst: dict = {m: None for m in METRICS}
    chunks = _recorded(reader)
    counted = n_feasible = 0
    for i in chunks:
        start, stop = plan.chunk_range(i)
        data = reader.chunk(i, names)
        data["q_deg"] = reader.q_deg(data)
        keep = data["feasible"] if has else np.ones(stop - start, dtype=bool)
        n_feasible += int(np.count_nonzero(keep))
        counted += int(np.count_nonzero(keep)) if only else stop - start
        for m in METRICS:
            v = np.where(keep, data[f"max_{m}"], np.nan) if only else data[f"max_{m}"]
            if not np.any(np.isfinite(v)):
                continue
            hi, lo = int(np.nanargmax(v)), int(np.nanargmin(v))
            if best[m] is None or v[hi] > best[m]["value"]:
                best[m] = _entry(data, hi, m, start)
            if worst[m] is None or v[lo] < worst[m]["value"]:
                worst[m] = _entry(data, lo, m, start)
        sim.add(data, keep if only else np.ones(stop - start, dtype=bool), start)
    scene = dict(meta["scene"])
    out = {
        "schema": SUMMARY_SCHEMA,
        "store": str(store),
        "joints": meta["robot"]["joints"],
        "scenario": scene["scenario"], "kappa": scene["kappa"], "mu": scene["mu"],
        "configurations": plan.size,
        "summarized_configurations": counted,
        "feasible_only": only,
        "clearance": _clearance(meta),
        "feasible_configurations": n_feasible if has else None,
        "chunks": plan.n_chunks, "completed_chunks": len(chunks),
        "complete": len(chunks) == plan.n_chunks,
        "metrics": {m: {"worst": worst[m], "best": best[m]} for m in METRICS},
    }
    if sim.spec:
        out["simulation"] = sim.result()
    return out


class _SimulationTally:
    """The summary of a store's simulated pushes (:mod:`.simulation`), chunk by chunk: how
    the runs ended, and the completed run that moved the object farthest."""

    def __init__(self, spec):
        from .simulation import SIM_ARRAYS, STATUS_CODES

        self.spec = spec
        self.names = SIM_ARRAYS if spec else ()
        self.codes = {v: k for k, v in STATUS_CODES.items()}
        self.counts = {k: 0 for k in STATUS_CODES}
        self.farthest = None

    def add(self, data, keep, start):
        if not self.spec:
            return
        status = data["sim_status"]
        for code, name in self.codes.items():
            self.counts[name] += int(np.count_nonzero(keep & (status == code)))
        dist = np.hypot(data["sim_object_dx"], data["sim_object_dy"])
        dist = np.where(keep & (status == 0) & np.isfinite(dist), dist, -np.inf)
        if dist.size and np.isfinite(dist.max()):
            j = int(np.argmax(dist))
            if self.farthest is None or dist[j] > self.farthest["distance"]:
                self.farthest = {
                    "distance": float(dist[j]), "index": start + j,
                    "q_deg": [float(x) for x in data["q_deg"][j]],
                    "object_displacement": [float(data[f"sim_object_{k}"][j])
                                            for k in ("dx", "dy", "dpsi")],
                    "com_displacement": [float(data[f"sim_com_{k}"][j]) for k in ("dx", "dy")],
                    "sr_mean": _finite_or_none(data["sim_sr_mean"][j])}

    def result(self) -> dict:
        return {"duration": self.spec["duration"], "tau": self.spec["tau"],
                "status_counts": self.counts, "farthest_push": self.farthest}


def _finite_or_none(x):
    return float(x) if np.isfinite(x) else None


def summary_text(s: dict) -> str:
    """The summary as a terminal table."""
    which = ""
    if s.get("feasible_only"):
        which = f" (feasible shapes only, clearance {s['clearance']:g} m)"
    elif s.get("feasible_configurations") is not None:
        which = f" ({s['feasible_configurations']:,} of them feasible)"
    lines = [f"{s['store']}: {s['joints']} joints, {s['scenario']}, kappa {s['kappa']:g}, "
             f"{s['summarized_configurations']:,} of {s['configurations']:,} configurations"
             + which
             + ("" if s["complete"] else f" (incomplete: {s['completed_chunks']} of "
                                         f"{s['chunks']} chunks)"),
             f"{'per-configuration max of':<26}{'worst':>14}  {'at q (deg)':<28}"
             f"{'best':>14}  at q (deg)"]
    marked = False

    def at(e):
        nonlocal marked
        q = ",".join(f"{x:g}" for x in e["q_deg"])
        if e.get("feasible") is False:
            marked = True
            return q + " *"  # geometry.INFEASIBLE_MARK
        return q

    for m, d in s["metrics"].items():
        if d["worst"] is None:
            lines.append(f"{m:<26}{'-':>14}")
            continue
        lines.append(f"{m:<26}{d['worst']['value']:>14.6g}  {at(d['worst']):<28}"
                     f"{d['best']['value']:>14.6g}  {at(d['best'])}")
    if marked:
        from ..geometry import infeasible_footnote

        lines.append(f"{infeasible_footnote(s['clearance'])}; --feasible-only leaves them out")
    sim = s.get("simulation")
    if sim:
        ended = ", ".join(f"{n} {k}" for k, n in sim["status_counts"].items() if n)
        lines.append(f"pushes of {sim['duration']:g} s with tau = "
                     f"({', '.join(f'{t:g}' for t in sim['tau'])}) N m: {ended or 'none yet'}")
        f = sim["farthest_push"]
        if f is not None:
            sr = "-" if f["sr_mean"] is None else f"{f['sr_mean']:.4g}"
            lines.append(f"  farthest completed push: {f['distance']:.6g} m at q (deg) "
                         f"{','.join(f'{x:g}' for x in f['q_deg'])} (mean sr {sr})")
    return "\n".join(lines)


def figure(store, out=None, *, radius_bins: int = 24, angle_bins: int = 36,
           feasible=None) -> Path:
    """Fig. 5 of the sweep: for each metric, the largest per-configuration maximum in each
    bin of the COM's polar coordinates (|COM| from the contact point, angle from the
    contacting link's axis), drawn on polar axes. Written (atomically) to ``out``, default
    ``STORE-polar.png`` beside the store; the format follows the suffix (png, svg, pdf).
    ``feasible``: as in :func:`summary` (True: feasible shapes only)."""
    path = _path(store)
    out = Path(out) if out is not None else path.with_name(path.name.removesuffix(".zarr")
                                                            + "-polar.png")
    fmt = out.suffix.lower().lstrip(".")
    if fmt not in ("png", "svg", "pdf"):
        raise InputError(f"figure file {str(out)!r} must end in .png, .svg or .pdf")
    if not out.parent.is_dir():
        raise InputError(f"figure file {str(out)!r}: its folder does not exist")
    b = binned_maxima(store, radius_bins=radius_bins, angle_bins=angle_bins,
                      feasible=feasible)
    size = b["configurations"]
    which = (f"{b['binned_configurations']:,} feasible configurations (clearance "
             f"{b['clearance']:g} m) of {size:,}" if b["feasible_only"]
             else f"{size:,} configurations")
    _draw(b["maxima"], b["radius_max"], b["meta"], which, out, fmt)
    return out


def binned_maxima(store, *, radius_bins: int = 24, angle_bins: int = 36,
                  feasible=None) -> dict:
    """What :func:`figure` draws: ``maxima[m]`` ``(angle_bins, radius_bins)``, the largest
    per-configuration maximum of metric ``m`` in each bin (``-inf`` for an empty bin); the
    angle bins split -pi..pi evenly, the radius bins 0..``radius_max`` (just above the
    largest |COM| of the configurations binned). Also ``binned_configurations``,
    ``configurations``, ``feasible_only``, ``clearance`` and the store's ``meta``."""
    reader, meta, plan = _open(store)
    only = _feasible_only(store, meta, feasible)
    for name, v in (("radius_bins", radius_bins), ("angle_bins", angle_bins)):
        if isinstance(v, bool) or not isinstance(v, int) or v < 2:
            raise InputError(f"{name} must be an integer >= 2, got {v!r}")
    chunks = _recorded(reader)
    if not chunks:
        raise InputError(f"{str(store)!r} has no completed chunk yet; nothing to draw")
    rmax, shown = 0.0, 0
    for i in chunks:  # pass 1: the radius range
        data = reader.chunk(i, ["com_radius", "feasible"] if only else ["com_radius"])
        r = data["com_radius"]
        if only:
            r = r[data["feasible"]]
        shown += r.size
        if r.size:
            rmax = max(rmax, float(np.nanmax(r)))
    if not shown:
        raise InputError(f"{str(store)!r} has no feasible configuration in its completed "
                         f"chunks; nothing to draw with feasible shapes only")
    rmax = rmax * (1 + 1e-9) or 1.0
    grid = {m: np.full((angle_bins, radius_bins), -np.inf) for m in METRICS}
    for i in chunks:  # pass 2: binned maxima
        data = reader.chunk(i, ["com_radius", "com_angle"] + [f"max_{m}" for m in METRICS]
                            + (["feasible"] if only else []))
        ri = np.clip((data["com_radius"] / rmax * radius_bins).astype(int), 0, radius_bins - 1)
        ai = np.clip(((data["com_angle"] + math.pi) / (2 * math.pi) * angle_bins).astype(int),
                     0, angle_bins - 1)
        for m in METRICS:
            v = data[f"max_{m}"]
            ok = np.isfinite(v) & data["feasible"] if only else np.isfinite(v)
            np.maximum.at(grid[m], (ai[ok], ri[ok]), v[ok])
    return {"maxima": grid, "radius_max": rmax, "binned_configurations": shown,
            "configurations": plan.size, "feasible_only": only, "clearance": _clearance(meta),
            "meta": meta}


def _draw(grid, rmax, meta, which: str, out: Path, fmt: str) -> None:
    import matplotlib.pyplot as plt

    fig = _polar_figure(grid, rmax, meta, which)
    tmp = out.with_name(f".{out.name}.{uuid.uuid4().hex}.partial")
    try:
        fig.savefig(tmp, format=fmt, dpi=120 if fmt == "png" else None)
        os.replace(tmp, out)
    finally:
        plt.close(fig)
        tmp.unlink(missing_ok=True)


def _polar_figure(grid, rmax, meta, which: str):
    """The figure :func:`figure` writes: one polar panel per metric, colour scales and titles
    by :mod:`snakecg.figures.scales`."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..figures.scales import colorbar, colour_scale, metric_title, polar_rings

    angle_bins, radius_bins = next(iter(grid.values())).shape
    theta = np.linspace(-math.pi, math.pi, angle_bins + 1)
    radius = np.linspace(0.0, rmax, radius_bins + 1)
    fig, axes = plt.subplots(2, 2, figsize=(10, 10.5), subplot_kw={"projection": "polar"},
                             constrained_layout=True)
    for ax, m in zip(axes.ravel(), ("norm_lambda", "norm_a_obj", "sr", "norm_qdd")):
        vals = np.where(np.isfinite(grid[m]), grid[m], np.nan)
        scale = colour_scale(vals, m)  # flat when constant, a stretch said, sr within [0, 1]
        mesh = ax.pcolormesh(theta, radius, np.ma.masked_invalid(vals).T, cmap=scale.cmap,
                             norm=scale.norm, shading="flat")
        ax.set_title(f"largest max {metric_title(m)} per bin", fontsize=10)
        polar_rings(ax, rmax, fontsize=8)
        ax.tick_params(labelsize=7)
        colorbar(fig, mesh, ax, scale, fontsize=8, shrink=0.7, pad=0.08)
    scene = meta["scene"]
    fig.suptitle(f"{which}, {meta['robot']['joints']} joints, "
                 f"{scene['scenario']}, kappa = {scene['kappa']:g}:\nper-configuration maxima "
                 f"over the input ellipsoid, binned over |COM| [m] from the contact point\nand "
                 f"the angle of COM from the contacting link's axis", fontsize=10)
    return fig
