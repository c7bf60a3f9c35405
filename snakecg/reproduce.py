"""Reproduce the paper's case studies: Figures 4-6 and Table 2 (``snakecg reproduce``).

Every choice the paper leaves open is a named option here with the default documented in
``docs/reproduction.md``; nothing is fitted to the published numbers.

* Case study 1 (2 joints, Table 1, contact at the middle of link 1): maps over the torque
  plane of ``norm_a_obj``, ``norm_qdd`` and ``sr`` at the configuration of Fig. 4
  (``q = (0, 0, 0, -135 deg, -135 deg)``) for each kappa and scenario, with the input
  ellipsoid of eq. (31) drawn; the sweep over the 784 configurations with the extremes
  per configuration (CSV).
* Case study 2 (3 joints): the extremes over the 21,952 configurations of the joint grid
  as functions of the polar coordinates of the COM (Fig. 5), the best and worst shapes
  (Fig. 6) and Table 2 (worst/best of the per-configuration maximum of ``norm_a_obj`` and
  ``sr``), side by side with the paper.
"""

from __future__ import annotations

import csv
import io
import json
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ._files import atomic_path, write_text
from .analysis import com_polar, joint_grid
from .errors import InputError
from .progress import progress_bar
from .robot import SCENARIOS, Robot, Scene

__all__ = ["PAPER_TABLE2", "ReproduceOptions", "reproduce", "table2", "TABLE2_ROWS"]

#: Table 2 of Reyes & Ma 2017 (case study 2): scenario 1, 2, 3.
PAPER_TABLE2 = {
    "worst_norm_a_obj": (0.000763215, 0.00107454, 0.00107454),
    "best_norm_a_obj": (0.00785302, 0.00861168, 0.00861168),
    "worst_sr": (0.00138484, 0.00185713, 0.00185098),
    "best_sr": (0.0267348, 0.988638, 0.988643),
}
TABLE2_ROWS = {
    "worst_norm_a_obj": "Worst ||a_obj||^2",
    "best_norm_a_obj": "Best ||a_obj||^2",
    "worst_sr": "Worst sr",
    "best_sr": "Best sr",
}
SCENARIO_LABEL = {"frictionless": "Scenario 1 (frictionless)",
                  "wheels": "Scenario 2 (wheels, mu = 0.1)",
                  "ideal_wheels": "Scenario 3 (ideal wheels)"}
METRIC_LABEL = {
    "norm_a_obj": r"$\|\vec a_{obj}\|^2$",
    "norm_qdd": r"$\|\vec{\ddot q}_s\|^2$",
    "norm_lambda": r"$\|\vec\lambda\|^2$",
    "sr": "sr",
}
#: Maxima the figures and Table 2 use; with bounded wheels only these are refined by the local
#: search (the maximum of norm_qdd, in the CSV files, is the best of the sampled candidates).
REFINED = ("norm_a_obj", "sr", "norm_lambda")
METRIC_UNIT = {"norm_a_obj": r"kg m$^2$/s$^4$", "norm_qdd": r"kg m$^2$/s$^4$",
               "norm_lambda": r"N$^2$/kg", "sr": "-"}


@dataclass(frozen=True)
class ReproduceOptions:
    """The readings taken where the paper is silent (see docs/reproduction.md)."""

    out: Path = Path("snakecg-output")
    kappas_case1: tuple = (1.0, 10.0, 100.0)
    kappa_case2: float = 100.0
    fig4_joints_deg: tuple = (-135.0, -135.0)
    grid_lo_deg: float = -135.0
    grid_hi_deg: float = 135.0
    grid_step_deg: float = 10.0
    torque_grid: int = 181
    side: str = "left"
    object_distance: float = 0.05
    mu: float = 0.1
    wheel_samples: int | None = None
    formats: tuple = ("png", "svg")
    progress: bool = True


#: Largest torque grid of Fig. 4 (points per axis; the maps hold grid^2 forward results).
MAX_TORQUE_GRID = 1001
FORMATS = ("png", "svg", "pdf")


def check_options(opts: ReproduceOptions) -> None:
    """The options a user sets, checked before any computation or file (InputError)."""
    from ._inputs import integer, number

    number("kappa_case2", opts.kappa_case2, lo=0, lo_open=True)
    for k in opts.kappas_case1:
        number("kappas_case1", k, lo=0, lo_open=True)
    integer("torque_grid", opts.torque_grid, lo=11, hi=MAX_TORQUE_GRID,
            why=" points per axis (the limit: the Fig. 4 maps hold grid^2 results)")
    formats = opts.formats
    if isinstance(formats, str) or not formats or any(f not in FORMATS for f in formats):
        raise InputError(f"formats takes png, svg or pdf, got {formats!r:.60}")


@dataclass
class ReproduceReport:
    table2: dict = field(default_factory=dict)
    files: list = field(default_factory=list)
    timings: dict = field(default_factory=dict)


def _scene(joints: int, scenario: str, kappa: float, opts: ReproduceOptions) -> Scene:
    return Scene(Robot(joints=joints), scenario=scenario, kappa=kappa, mu=opts.mu,
                 side=opts.side, object_distance=opts.object_distance)


def _save(fig, out: Path, stem: str, opts: ReproduceOptions, report: ReproduceReport):
    for fmt in opts.formats:
        path = out / f"{stem}.{fmt}"
        with atomic_path(path) as tmp:  # unique temporary name, then os.replace
            fig.savefig(tmp, format=fmt, dpi=130 if fmt == "png" else None,
                        bbox_inches="tight")
        report.files.append(path)


def _write_text(path: Path, text: str, report: ReproduceReport):
    write_text(path, text)  # unique temporary name, then os.replace
    report.files.append(path)


# ------------------------------------------------------------------------------------------
# Case study 1
# ------------------------------------------------------------------------------------------
def torque_plane(model, q, n_grid: int, margin: float = 1.25):
    """Torque grid covering the ellipsoid ``tau^T N tau <= 1`` and the metrics on it."""
    N = model.maps(q)["input_metric"]
    half = margin * np.sqrt(np.diag(np.linalg.inv(N)))
    t1 = np.linspace(-half[0], half[0], n_grid)
    t2 = np.linspace(-half[1], half[1], n_grid)
    T1, T2 = np.meshgrid(t1, t2, indexing="xy")
    taus = np.stack([T1.ravel(), T2.ravel()], axis=1)
    res = model.forward(q, taus)
    grids = {m: getattr(res, m).reshape(T1.shape) for m in ("norm_a_obj", "norm_qdd", "sr")}
    grids["contact"] = res.contact.reshape(T1.shape)
    return t1, t2, grids, N


def _ellipse(N, n=400):
    a = np.linspace(0, 2 * np.pi, n)
    u = np.stack([np.cos(a), np.sin(a)])
    L = np.linalg.cholesky(N)
    return np.linalg.solve(L.T, u)


def case_study_1(opts: ReproduceOptions, report: ReproduceReport, load):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = opts.out
    q = np.array([0.0, 0.0, 0.0, *np.deg2rad(opts.fig4_joints_deg)])
    bar = progress_bar(len(opts.kappas_case1) * 3 + 3, "case study 1", enabled=opts.progress)
    for kappa in opts.kappas_case1:
        fig, axes = plt.subplots(3, 3, figsize=(13, 11.5), constrained_layout=True)
        for j, scenario in enumerate(SCENARIOS):
            model = load(_scene(2, scenario, kappa, opts))
            t1, t2, grids, N = torque_plane(model, q, opts.torque_grid)
            ell = _ellipse(N)
            for i, metric in enumerate(("norm_a_obj", "norm_qdd", "sr")):
                ax = axes[i, j]
                im = ax.imshow(grids[metric], origin="lower", aspect="auto", cmap="viridis",
                               extent=(t1[0], t1[-1], t2[0], t2[-1]),
                               vmin=0.0, vmax=1.0 if metric == "sr" else None)
                ax.plot(ell[0], ell[1], color="white", lw=1.2, ls="--",
                        label="input ellipsoid (31)")
                ax.contour(t1, t2, grids["contact"].astype(float), levels=[0.5], colors="red",
                           linewidths=0.8)
                ax.set_xlabel(r"$\tau_1$ [N m]")
                ax.set_ylabel(r"$\tau_2$ [N m]")
                ax.set_title(f"{METRIC_LABEL[metric]} — {SCENARIO_LABEL[scenario]}, "
                             f"$\\kappa$ = {kappa:g}", fontsize=9)
                cb = fig.colorbar(im, ax=ax, shrink=0.85)
                cb.set_label(f"{METRIC_LABEL[metric]} [{METRIC_UNIT[metric]}]")
            bar.update()
        axes[0, 0].legend(loc="upper right", fontsize=7)
        fig.suptitle(
            "Fig. 4 (case study 1): norms over the torque plane at q = (0, 0, 0, "
            f"{opts.fig4_joints_deg[0]:g}°, {opts.fig4_joints_deg[1]:g}°), "
            f"$\\kappa$ = {kappa:g}; dashed: input ellipsoid, red: contact lost/kept boundary",
            fontsize=11,
        )
        _save(fig, out, f"fig4_kappa{kappa:g}", opts, report)
        plt.close(fig)
    # sweep over the 784 configurations
    Q = joint_grid(2, opts.grid_lo_deg, opts.grid_hi_deg, opts.grid_step_deg)
    for scenario in SCENARIOS:
        model = load(_scene(2, scenario, opts.kappa_case2, opts))
        ex = model.extremes(Q, samples=opts.wheel_samples, refined=REFINED)
        r, a = com_polar(model, Q)
        _write_text(out / f"case1_sweep_{scenario}.csv",
                    _extremes_csv(Q, r, a, ex, model.n_joints), report)
        bar.update()
    bar.close()


def _extremes_csv(Q, radius, angle, ex, na) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    head = [f"q{j + 1}_deg" for j in range(na)] + ["com_radius_m", "com_angle_deg"]
    for m in ("norm_a_obj", "norm_qdd", "norm_lambda", "sr"):
        head += [f"max_{m}"] + [f"tau{j + 1}_at_max_{m}" for j in range(na)]
        head += [f"min_kept_{m}"] + [f"tau{j + 1}_at_min_kept_{m}" for j in range(na)]
    w.writerow(head)
    for k in range(Q.shape[0]):
        row = [f"{v:.1f}" for v in np.rad2deg(Q[k, 3:])]
        row += [f"{radius[k]:.6g}", f"{np.rad2deg(angle[k]):.4f}"]
        for m in ("norm_a_obj", "norm_qdd", "norm_lambda", "sr"):
            row += [f"{ex.max[m][k]:.9g}"] + [f"{t:.6g}" for t in ex.tau_max[m][k]]
            row += [f"{ex.min_kept[m][k]:.9g}"] + [f"{t:.6g}" for t in ex.tau_min_kept[m][k]]
        w.writerow(row)
    return buf.getvalue()


# ------------------------------------------------------------------------------------------
# Case study 2
# ------------------------------------------------------------------------------------------
def case_study_2(opts: ReproduceOptions, report: ReproduceReport, load):
    Q = joint_grid(3, opts.grid_lo_deg, opts.grid_hi_deg, opts.grid_step_deg)
    results = {}
    bar = progress_bar(3, "case study 2 (21,952 configurations)", enabled=opts.progress)
    for scenario in SCENARIOS:
        model = load(_scene(3, scenario, opts.kappa_case2, opts))
        chunks = []
        step = 2048
        for s in range(0, Q.shape[0], step):
            chunks.append(model.extremes(Q[s:s + step], samples=opts.wheel_samples,
                                         refined=REFINED, exact=True))  # wheels: exact
        ex = _concat_extremes(chunks)
        radius, angle = com_polar(model, Q)
        results[scenario] = (model, ex, radius, angle)
        _write_text(opts.out / f"case2_sweep_{scenario}.csv",
                    _extremes_csv(Q, radius, angle, ex, 3), report)
        bar.update()
    bar.close()
    return Q, results


def _concat_extremes(chunks):
    from .analysis import Extremes

    out = Extremes(method=chunks[0].method)
    for attr in ("max", "min", "tau_max", "tau_min", "min_kept", "tau_min_kept"):
        d = getattr(out, attr)
        for k in getattr(chunks[0], attr):
            d[k] = np.concatenate([getattr(c, attr)[k] for c in chunks], axis=0)
    return out


def table2(results) -> dict:
    """Table 2 from per-configuration maxima: worst = min over configurations, best = max."""
    t = {}
    for key in PAPER_TABLE2:
        kind, metric = key.split("_", 1)
        vals = []
        for scenario in SCENARIOS:
            ex = results[scenario][1]
            v = ex.max[metric]
            vals.append(float(v.min() if kind == "worst" else v.max()))
        t[key] = tuple(vals)
    return t


def table2_index(results) -> dict:
    """Index of the configuration attaining each Table 2 entry, per scenario."""
    idx = {}
    for key in PAPER_TABLE2:
        kind, metric = key.split("_", 1)
        idx[key] = tuple(
            int(np.argmin(results[s][1].max[metric]) if kind == "worst"
                else np.argmax(results[s][1].max[metric]))
            for s in SCENARIOS
        )
    return idx


def table2_text(t: dict) -> tuple[str, str, str]:
    """(terminal text, Markdown, CSV) of Table 2 beside the paper's values."""
    md = ["| Concept | " + " | ".join(
        f"{SCENARIO_LABEL[s]}: snakecg | paper | rel. diff." for s in SCENARIOS) + " |",
          "|---|" + "---|---|---|" * 3]
    rows_csv = [["concept", "scenario", "snakecg", "paper", "relative_difference"]]
    term = [f"{'Table 2':<20}" + "".join(f"{s:>36}" for s in SCENARIOS),
            f"{'':<20}" + "".join(f"{'snakecg':>12}{'paper':>12}{'rel.diff':>12}"
                                  for _ in SCENARIOS)]
    for key, label in TABLE2_ROWS.items():
        cells, tline = [], f"{label:<20}"
        for j, s in enumerate(SCENARIOS):
            ours, paper = t[key][j], PAPER_TABLE2[key][j]
            rel = (ours - paper) / paper
            cells.append(f"{ours:.6g} | {paper:.6g} | {rel:+.1%}")
            tline += f"{ours:>12.6g}{paper:>12.6g}{rel:>+12.1%}"
            rows_csv.append([key, s, f"{ours:.9g}", f"{paper:.9g}", f"{rel:.6f}"])
        md.append(f"| {label} | " + " | ".join(cells) + " |")
        term.append(tline)
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(rows_csv)
    return "\n".join(term), "\n".join(md) + "\n", buf.getvalue()


def figure5(Q, results, opts, report):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 3, figsize=(13, 13), subplot_kw={"projection": "polar"},
                             constrained_layout=True)
    for j, s in enumerate(SCENARIOS):
        _, ex, radius, angle = results[s]
        order = np.argsort(ex.max["sr"])
        for i, m in enumerate(("norm_lambda", "norm_a_obj", "sr")):
            ax = axes[i, j]
            vals = ex.max[m]
            o = np.argsort(vals)
            sc = ax.scatter(angle[o], radius[o], c=vals[o], s=3, cmap="viridis", linewidths=0,
                            rasterized=True)
            ax.set_title(f"max {METRIC_LABEL[m]} over (31)\n{SCENARIO_LABEL[s]}", fontsize=9)
            ax.set_rlabel_position(135)
            ax.tick_params(labelsize=7)
            cb = fig.colorbar(sc, ax=ax, shrink=0.7, pad=0.08)
            cb.set_label(f"{METRIC_LABEL[m]} [{METRIC_UNIT[m]}]", fontsize=8)
        del order
    fig.suptitle(
        "Fig. 5 (case study 2, 3 joints, "
        f"$\\kappa$ = {opts.kappa_case2:g}): per-configuration maxima over the input ellipsoid "
        "vs. polar coordinates of the snake's COM\n(radius |COM| [m] from the contact point, "
        "angle ∠COM from the contacting link's axis)", fontsize=11)
    _save(fig, opts.out, "fig5_polar", opts, report)
    plt.close(fig)


def draw_robot(ax, model, q, *, title="", tau=None):
    """Draw the snake (links, joints, COM) and the object for configuration ``q``."""
    import matplotlib.patches as mpatches

    poses = model.link_poses(q)
    r = model.robot
    for i, (x, y, phi) in enumerate(poses):
        e = np.array([np.cos(phi), np.sin(phi)])
        rear = np.array([x, y]) - r.com[i] * e
        front = rear + r.length[i] * e
        ax.plot([rear[0], front[0]], [rear[1], front[1]], "-", lw=5, solid_capstyle="round",
                color="tab:blue" if i else "tab:orange")
        ax.plot(*front, "o", color="k", ms=3)
    q_obj, rho, P = model.place_object(q)
    side = 0.1
    psi = q_obj[2]
    R = np.array([[np.cos(psi), -np.sin(psi)], [np.sin(psi), np.cos(psi)]])
    corner = q_obj[:2] + R @ np.array([-side / 2, -side / 2])
    ax.add_patch(mpatches.Rectangle(corner, side, side, angle=np.rad2deg(psi),
                                    rotation_point="xy", fc="0.8", ec="k"))
    ax.plot(*P, "r*", ms=8)
    com = model.com(q)
    ax.plot(*com, "kx", ms=7)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=8)
    ax.tick_params(labelsize=6)
    ax.set_xlabel("x [m]", fontsize=7)
    ax.set_ylabel("y [m]", fontsize=7)


def figure6(Q, results, opts, report):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    idx = table2_index(results)
    fig, axes = plt.subplots(2, 6, figsize=(18, 6.5), constrained_layout=True)
    for i, metric in enumerate(("norm_a_obj", "sr")):
        for j, s in enumerate(SCENARIOS):
            model = results[s][0]
            for k, kind in enumerate(("worst", "best")):
                ci = idx[f"{kind}_{metric}"][j]
                q = Q[ci]
                val = results[s][1].max[metric][ci]
                deg = ", ".join(f"{d:.0f}°" for d in np.rad2deg(q[3:]))
                draw_robot(axes[i, 2 * j + k], model, q,
                           title=f"{kind} {METRIC_LABEL[metric]} = {val:.4g}\n"
                                 f"{SCENARIO_LABEL[s]}\nq = ({deg})")
    fig.suptitle("Fig. 6 (case study 2): worst and best configurations for the object's "
                 "acceleration (top) and the slippage ratio (bottom); tail link orange, "
                 "contact *, snake COM x, object grey", fontsize=11)
    _save(fig, opts.out, "fig6_configurations", opts, report)
    plt.close(fig)


def _segments(model, Q):
    P = model.link_poses(Q)
    r = model.robot
    e = np.stack([np.cos(P[..., 2]), np.sin(P[..., 2])], -1)
    rear = P[..., :2] - np.asarray(r.com)[None, :, None] * e
    return rear, rear + np.asarray(r.length)[None, :, None] * e


def physically_feasible(model, Q) -> np.ndarray:
    """Configurations whose links neither cross each other nor enter the object (the paper's
    grid keeps all of them; this filter is one of the alternative readings)."""

    def cross(a, b):
        return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]

    rear, front = _segments(model, Q)
    nl = rear.shape[1]
    ok = np.ones(len(Q), bool)
    for i in range(nl):
        for j in range(i + 2, nl):
            p1, p2, p3, p4 = rear[:, i], front[:, i], rear[:, j], front[:, j]
            d1, d2 = cross(p4 - p3, p1 - p3), cross(p4 - p3, p2 - p3)
            d3, d4 = cross(p2 - p1, p3 - p1), cross(p2 - p1, p4 - p1)
            ok &= ~((d1 * d2 < 0) & (d3 * d4 < 0))
    q_obj, _, _ = model.place_object(Q)
    c, psi = q_obj[:, :2], q_obj[:, 2]
    h = 0.05
    for i in range(1, nl):
        for t in np.linspace(0.0, 1.0, 41):
            d = rear[:, i] * (1 - t) + front[:, i] * t - c
            lx = np.cos(psi) * d[:, 0] + np.sin(psi) * d[:, 1]
            ly = -np.sin(psi) * d[:, 0] + np.cos(psi) * d[:, 1]
            ok &= ~((np.abs(lx) < h - 1e-9) & (np.abs(ly) < h - 1e-9))
    return ok


def alternative_readings(opts: ReproduceOptions | None = None, *, load=None) -> str:
    """Table 2 entries of scenarios 1 and 3 under alternative readings (Markdown)."""
    from .model import load as default_load

    opts = opts or ReproduceOptions()
    load = load or default_load
    Q = joint_grid(3, opts.grid_lo_deg, opts.grid_hi_deg, opts.grid_step_deg)
    variants = [
        ("this reading (contact at mid link 1, kappa 100, object COM on the normal, exact max)",
         {}, None),
        ("contact at the tail end of link 1", {"contact_offset": 0.0}, None),
        ("contact at the front end of link 1", {"contact_offset": 0.15}, None),
        ("kappa = 50", {"kappa": 50.0}, None),
        ("kappa = 150", {"kappa": 150.0}, None),
        ("object on the right of link 1", {"side": "right"}, None),
        ("only shapes without self-crossing or object penetration", {}, "feasible"),
        ("max over 12 sampled torque directions instead of the exact max", {}, "sampled"),
    ]
    lines = ["| reading | S1 worst a_obj | S1 best a_obj | S1 worst sr | S1 best sr | "
             "S3 worst a_obj | S3 best a_obj | S3 worst sr | S3 best sr |",
             "|---|" + "---|" * 8]
    paper = ["paper"] + [f"{PAPER_TABLE2[k][j]:.4g}" for j in (0, 2)
                         for k in ("worst_norm_a_obj", "best_norm_a_obj", "worst_sr", "best_sr")]
    lines.append("| " + " | ".join(paper) + " |")
    for label, changes, mode in variants:
        cells = [label]
        for scenario in ("frictionless", "ideal_wheels"):
            base = dict(scenario=scenario, kappa=opts.kappa_case2, mu=opts.mu, side=opts.side,
                        object_distance=opts.object_distance)
            base.update(changes)
            model = load(Scene(Robot(joints=3), **base))
            mask = np.ones(len(Q), bool)
            if mode == "feasible":
                mask = physically_feasible(model, Q)
            if mode == "sampled":
                maps = model._maps(Q, len(Q), np.where(model.present, 1, 0).astype(np.int8))
                L = np.linalg.cholesky(maps["input_metric"])
                from .analysis import sphere_directions

                d = sphere_directions(3, 12)
                taus = np.einsum("bij,kj->bki", np.swapaxes(np.linalg.inv(L), -1, -2), d)
                res = model.forward(np.repeat(Q, 12, axis=0), taus.reshape(-1, 3))
                a = res.norm_a_obj.reshape(-1, 12).max(axis=1)
                srv = res.sr.reshape(-1, 12).max(axis=1)
            else:
                ex = model.extremes(Q)
                a, srv = ex.max["norm_a_obj"], ex.max["sr"]
            a, srv = a[mask], srv[mask]
            cells += [f"{a.min():.4g}", f"{a.max():.4g}", f"{srv.min():.4g}", f"{srv.max():.4g}"]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def reproduce(opts: ReproduceOptions | None = None, *, load=None, echo=print) -> ReproduceReport:
    """Run both case studies, write figures/CSV/Markdown into ``opts.out``, print Table 2."""
    from .model import load as default_load

    opts = opts or ReproduceOptions()
    check_options(opts)
    load = load or default_load
    out = Path(opts.out)
    if out.exists() and not out.is_dir():
        raise InputError(f"--out {str(out)!r} exists and is not a directory")
    out.mkdir(parents=True, exist_ok=True)
    opts = ReproduceOptions(**{**opts.__dict__, "out": out})
    report = ReproduceReport()
    t0 = time.perf_counter()
    for j in (2, 3):  # build/compile first so the timings below are the study itself
        load(Robot(joints=j))
    report.timings["models"] = time.perf_counter() - t0
    t1 = time.perf_counter()
    case_study_1(opts, report, load)
    report.timings["case_study_1"] = time.perf_counter() - t1
    t2 = time.perf_counter()
    Q, results = case_study_2(opts, report, load)
    t = table2(results)
    report.table2 = t
    term, md, csv_text = table2_text(t)
    _write_text(out / "table2.md", md, report)
    _write_text(out / "table2.csv", csv_text, report)
    figure5(Q, results, opts, report)
    figure6(Q, results, opts, report)
    report.timings["case_study_2"] = time.perf_counter() - t2
    report.timings["total"] = time.perf_counter() - t0
    summary = {"table2": {k: list(v) for k, v in t.items()},
               "paper_table2": {k: list(v) for k, v in PAPER_TABLE2.items()},
               "options": {k: (str(v) if isinstance(v, Path) else v)
                           for k, v in opts.__dict__.items()},
               "timings_s": report.timings}
    _write_text(out / "summary.json", json.dumps(summary, indent=2) + "\n", report)
    echo(term)
    echo(f"\nwrote {len(report.files)} files to {out}/: case study 1 in "
         f"{report.timings['case_study_1']:.1f} s, case study 2 in "
         f"{report.timings['case_study_2']:.1f} s (models ready in "
         f"{report.timings['models']:.1f} s)")
    return report
