"""Reproduce the paper's case studies: Figures 4-6 and Table 2 (``snakecg reproduce``).

Every choice the paper leaves open is a named option here with the default documented in
``docs/how-to/reproduction.md``; nothing is fitted to the published numbers.

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

import json
import os
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ._files import write_text
from .analysis import com_polar, joint_grid
from .errors import InputError
from .figures import paper as figures
from .geometry import INFEASIBLE_MARK, SELF_CLEARANCE, feasibility, link_segments
from .progress import progress_reporter, stage
from .robot import SCENARIOS, Robot, Scene
from .table2 import PAPER_TABLE2, TABLE2_ROWS, table2, table2_index, table2_text

__all__ = ["PAPER_TABLE2", "ReproduceOptions", "reproduce", "table2", "table2_index",
           "table2_text", "TABLE2_ROWS"]

#: Maxima the figures and Table 2 use; with bounded wheels only these are refined by the local
#: search (the maximum of norm_qdd, in the CSV files, is the best of the sampled candidates).
REFINED = ("norm_a_obj", "sr", "norm_lambda")


@dataclass(frozen=True)
class ReproduceOptions:
    """The readings taken where the paper is silent (see docs/how-to/reproduction.md)."""

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
    #: Table 2, Fig. 5 and Fig. 6 over physically feasible shapes only (links neither closer
    #: than ``clearance`` to each other nor inside the object). Off by default: the paper's grid
    #: includes every shape; the figures mark the infeasible ones either way.
    feasible_only: bool = False
    clearance: float = SELF_CLEARANCE
    #: Processes that draw the figures while the studies compute (None: up to 2, one per
    #: core; 1: draw in this process).
    jobs: int | None = None


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
    #: Per entry of ``table2``: whether its shape is physically possible; and the entries over
    #: the physically possible shapes only.
    table2_shape_feasible: dict = field(default_factory=dict)
    table2_feasible_only: dict = field(default_factory=dict)
    files: list = field(default_factory=list)
    feasible_count: int | None = None
    grid_count: int | None = None
    timings: dict = field(default_factory=dict)
    #: Prints a line per stage on standard error (None: quiet, ``progress=False``).
    progress: object = field(default=None, repr=False)

    def say(self, message: str) -> None:
        if self.progress is not None:
            self.progress(message)


def _scene(joints: int, scenario: str, kappa: float, opts: ReproduceOptions) -> Scene:
    return Scene(Robot(joints=joints), scenario=scenario, kappa=kappa, mu=opts.mu,
                 side=opts.side, object_distance=opts.object_distance)


@contextmanager
def _timed(report: ReproduceReport, key: str):
    """Add the wall and CPU time of the block to ``report.timings[key]`` / ``[key + "_cpu"]``."""
    wall, cpu = time.perf_counter(), time.process_time()
    try:
        yield
    finally:
        for k, v in ((key, time.perf_counter() - wall), (f"{key}_cpu", time.process_time() - cpu)):
            report.timings[k] = report.timings.get(k, 0.0) + v


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


def _infeasible_reason(f, k=None) -> str:
    """Why configuration ``k`` of a :class:`~snakecg.geometry.Feasibility` is not physically
    possible ("" when it is)."""
    cross = bool(np.asarray(f.self_intersecting)[() if k is None else k])
    enter = bool(np.asarray(f.penetrates_object)[() if k is None else k])
    reasons = (["links cross"] if cross else []) + (["a link enters the object"] if enter else [])
    return " and ".join(reasons)


def case_study_1(opts: ReproduceOptions, report: ReproduceReport, load, drawer=None):
    out = opts.out
    q = np.array([0.0, 0.0, 0.0, *np.deg2rad(opts.fig4_joints_deg)])
    for kappa in opts.kappas_case1:
        panels = []
        for scenario in SCENARIOS:
            model = load(_scene(2, scenario, kappa, opts))
            t1, t2, grids, N = torque_plane(model, q, opts.torque_grid)
            panels.append(figures.Fig4Panel(scenario, t1, t2, grids, _ellipse(N)))
        report.say(f"  Fig. 4 torque-plane maps, kappa = {kappa:g} ({opts.torque_grid}^2 "
                   "torques, 3 scenarios): done")
        why = _infeasible_reason(feasibility(model, q, clearance=opts.clearance))
        with _timed(report, "figures"):
            drawer.submit("figure4", panels=panels, kappa=kappa,
                          joints_deg=opts.fig4_joints_deg, stem=out / f"fig4_kappa{kappa:g}",
                          formats=opts.formats, infeasible=why)
    # sweep over the 784 configurations
    Q = joint_grid(2, opts.grid_lo_deg, opts.grid_hi_deg, opts.grid_step_deg)
    for scenario in SCENARIOS:
        model = load(_scene(2, scenario, opts.kappa_case2, opts))
        ex = model.extremes(Q, samples=opts.wheel_samples, refined=REFINED)
        r, a = com_polar(model, Q)
        _write_text(out / f"case1_sweep_{scenario}.csv",
                    _extremes_csv(Q, r, a, ex, model.n_joints), report)
        report.say(f"  extremes of the {len(Q):,} configurations, {scenario}: done")


def _extremes_csv(Q, radius, angle, ex, na) -> str:
    """The sweep's CSV text: one row per configuration (joint angles, polar COM, and per
    metric its maximum and least kept value with the attaining torques)."""
    head = [f"q{j + 1}_deg" for j in range(na)] + ["com_radius_m", "com_angle_deg"]
    cols = [np.rad2deg(Q[:, 3:]), np.asarray(radius)[:, None], np.rad2deg(angle)[:, None]]
    fmt = ["%.1f"] * na + ["%.6g", "%.4f"]
    for m in ("norm_a_obj", "norm_qdd", "norm_lambda", "sr"):
        head += [f"max_{m}"] + [f"tau{j + 1}_at_max_{m}" for j in range(na)]
        head += [f"min_kept_{m}"] + [f"tau{j + 1}_at_min_kept_{m}" for j in range(na)]
        cols += [ex.max[m][:, None], ex.tau_max[m], ex.min_kept[m][:, None], ex.tau_min_kept[m]]
        fmt += (["%.9g"] + ["%.6g"] * na) * 2
    table = np.concatenate([np.asarray(c, float).reshape(len(Q), -1) for c in cols], axis=1)
    row = ",".join(fmt)  # one %-format per row: the numbers contain no separator to quote
    return ",".join(head) + "\n" + "".join(row % tuple(r) + "\n" for r in table.tolist())


# ------------------------------------------------------------------------------------------
# Case study 2
# ------------------------------------------------------------------------------------------
def case_study_2(opts: ReproduceOptions, report: ReproduceReport, load):
    Q = joint_grid(3, opts.grid_lo_deg, opts.grid_hi_deg, opts.grid_step_deg)
    results = {}
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
        report.say(f"  extremes of the {len(Q):,} configurations, {scenario}: done")
    return Q, results


def _concat_extremes(chunks):
    from .analysis import Extremes

    out = Extremes(method=chunks[0].method)
    for attr in ("max", "min", "tau_max", "tau_min", "min_kept", "tau_min_kept"):
        d = getattr(out, attr)
        for k in getattr(chunks[0], attr):
            d[k] = np.concatenate([getattr(c, attr)[k] for c in chunks], axis=0)
    return out


def _formats_per_task(opts, drawer):
    """Each format in its own task when drawing in parallel (the last figures are on the
    critical path), all formats in one figure otherwise."""
    return [(f,) for f in opts.formats] if drawer.parallel else [tuple(opts.formats)]


def figure5(Q, results, opts, drawer, feas):
    model, _, radius, angle = results[SCENARIOS[0]]
    maxima = {s: {m: results[s][1].max[m] for m in ("norm_lambda", "norm_a_obj", "sr")}
              for s in SCENARIOS}
    for formats in _formats_per_task(opts, drawer):
        drawer.submit("figure5", angle=angle, radius=radius, maxima=maxima,
                      infeasible=~feas.feasible, kappa=opts.kappa_case2,
                      stem=opts.out / "fig5_polar", formats=formats,
                      feasible_only=opts.feasible_only)


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


def figure6(Q, results, opts, drawer, feas):
    idx = table2_index(results, feas.feasible if opts.feasible_only else None)
    rows = {}
    for j, s in enumerate(SCENARIOS):
        model, ex = results[s][0], results[s][1]
        picks = [(kind, metric, idx[f"{kind}_{metric}"][j])
                 for metric in ("norm_a_obj", "sr") for kind in ("worst", "best")]
        Qp = Q[[ci for _, _, ci in picks]]
        rear, front = link_segments(model.robot, model.link_poses(Qp))
        q_obj, _, contact = model.place_object(Qp)
        com = model.com(Qp)
        rows[s] = []
        for k, (kind, metric, ci) in enumerate(picks):
            deg = ", ".join(f"{d:.0f}°" for d in np.rad2deg(Q[ci, 3:]))
            why = _infeasible_reason(feas, ci)
            rows[s].append(figures.Shape(
                rear[k], front[k], q_obj[k], contact[k], com[k],
                title=f"{kind} {figures.METRIC_LABEL[metric]} = {ex.max[metric][ci]:.4g}"
                      f"{INFEASIBLE_MARK if why else ''}\nq = ({deg})",
                infeasible=why))
    for formats in _formats_per_task(opts, drawer):
        drawer.submit("figure6", rows=rows, stem=opts.out / "fig6_configurations",
                      formats=formats, feasible_only=opts.feasible_only)


def physically_feasible(model, Q, clearance: float = 0.0) -> np.ndarray:
    """Configurations whose links neither cross each other nor enter the object (the paper's
    grid keeps all of them; this filter is one of the alternative readings). See
    :mod:`snakecg.geometry`; ``clearance = 0`` counts only links that actually cross."""
    f = feasibility(model, Q, clearance=clearance)
    return ~(f.penetrates_object | (f.self_distance <= clearance))


def alternative_readings(opts: ReproduceOptions | None = None, *, load=None) -> str:
    """Table 2 entries of scenarios 1 and 3 under alternative readings (Markdown)."""
    from .loading import load as default_load

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
        ("only shapes whose links neither cross nor enter the object (clearance 0)", {},
         "feasible"),
        ("max over 12 sampled torque directions instead of the exact max", {}, "sampled"),
        ("max over a box grid of 15 torques per axis within the ellipsoid", {}, "grid15"),
        ("max over a box grid of 7 torques per axis over 1.25 x the ellipsoid's extent", {},
         "grid7"),
        ("input region tau^T (joint block of M_s)^-1 tau <= 1, exact max", {}, "joint_block"),
        ("input region tau^T tau <= 1, exact max", {}, "sphere"),
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
                maps = model.state_maps(Q, np.where(model.present, 1, 0).astype(np.int8))
                L = np.linalg.cholesky(maps["input_metric"])
                from .analysis import sphere_directions

                d = sphere_directions(3, 12)
                taus = np.einsum("bij,kj->bki", np.swapaxes(np.linalg.inv(L), -1, -2), d)
                res = model.forward(np.repeat(Q, 12, axis=0), taus.reshape(-1, 3))
                a = res.norm_a_obj.reshape(-1, 12).max(axis=1)
                srv = res.sr.reshape(-1, 12).max(axis=1)
            elif mode in ("grid15", "grid7", "joint_block", "sphere"):
                a, srv = _other_maximum(model, Q, mode)
            else:
                ex = model.extremes(Q)
                a, srv = ex.max["norm_a_obj"], ex.max["sr"]
            a, srv = a[mask], srv[mask]
            cells += [f"{a.min():.4g}", f"{a.max():.4g}", f"{srv.min():.4g}", f"{srv.max():.4g}"]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def _other_maximum(model, Q, mode):
    """Per-configuration maxima of ``norm_a_obj`` and ``sr`` (every row held: scenarios 1 and
    3) under another reading of eq. (31) or of the maximum: a box grid of torques
    (``grid15``: 15 per axis over the ellipsoid's extent; ``grid7``: 7 per axis over 1.25
    times it), keeping those inside the ellipsoid that push (lam_c >= 0); or the exact maximum
    over ``tau^T W tau <= 1`` with ``W`` the inverse of M_s's joint block (``joint_block``)
    or the identity (``sphere``). sr does not depend on the region (degree 0 in tau)."""
    import itertools

    maps = model.maps(Q)
    Om, Xi, N = maps["omega_tau"], maps["xi_tau"], maps["input_metric"]
    if mode in ("joint_block", "sphere"):
        W = (np.linalg.inv(model.mass_matrix(Q)[:, 3:, 3:]) if mode == "joint_block"
             else np.broadcast_to(np.eye(Om.shape[-1]), Om.shape))
        Li = np.linalg.inv(np.linalg.cholesky(W))
        a = np.linalg.eigvalsh(Li @ Om @ np.swapaxes(Li, -1, -2))[:, -1]
        return a, model.extremes(Q).max["sr"]
    k, margin = (15, 1.0) if mode == "grid15" else (7, 1.25)
    u = np.linspace(-1.0, 1.0, k)
    U = np.array(list(itertools.product(u, repeat=Om.shape[-1])))
    half = margin * np.sqrt(np.einsum("nii->ni", np.linalg.inv(N)))
    lam_c = maps["lam_from_tau"][:, 0, :]
    a, srv = np.empty(len(Q)), np.empty(len(Q))
    for lo in range(0, len(Q), 512):  # bounded memory: 512 configurations at a time
        sl = slice(lo, lo + 512)
        T = half[sl, None, :] * U[None]
        quad = lambda M: np.einsum("nki,nij,nkj->nk", T, M[sl], T)  # noqa: E731
        ok = (quad(N) <= 1 + 1e-12) & (np.einsum("nki,ni->nk", T, lam_c[sl]) >= 0)
        va, vq = quad(Om), quad(Xi)
        with np.errstate(invalid="ignore", divide="ignore"):
            vs = np.where(va + vq > 0, va / (va + vq), 0.0)
        a[sl] = np.where(ok, va, -np.inf).max(axis=1)
        srv[sl] = np.where(ok, vs, -np.inf).max(axis=1)
    return a, srv


def reproduce(opts: ReproduceOptions | None = None, *, load=None, echo=print) -> ReproduceReport:
    """Run both case studies, write figures/CSV/Markdown into ``opts.out``, print Table 2."""
    from .loading import load as default_load

    opts = opts or ReproduceOptions()
    check_options(opts)
    load = load or default_load
    out = Path(opts.out)
    if out.exists() and not out.is_dir():
        raise InputError(f"--out {str(out)!r} exists and is not a directory")
    out.mkdir(parents=True, exist_ok=True)
    opts = ReproduceOptions(**{**opts.__dict__, "out": out})
    report = ReproduceReport(progress=progress_reporter(prefix="snakecg reproduce")
                             if opts.progress else None)
    t0 = time.perf_counter()
    with stage(report.progress, "loading the 2- and 3-joint models",
               "loaded the 2- and 3-joint models"):
        for j in (2, 3):  # build/compile first so the timings below are the study itself
            load(Robot(joints=j))
    report.timings["models"] = time.perf_counter() - t0
    jobs = opts.jobs if opts.jobs is not None else min(2, os.cpu_count() or 1)
    drawer = figures.Drawer(jobs)
    try:
        _studies(opts, report, load, drawer)
    finally:
        drawer.close()
    report.timings["total"] = time.perf_counter() - t0
    summary = {"table2": {k: list(v) for k, v in report.table2.items()},
               "table2_shape_feasible": {k: list(v)
                                         for k, v in report.table2_shape_feasible.items()},
               "table2_feasible_only": {k: list(v)
                                        for k, v in report.table2_feasible_only.items()},
               "paper_table2": {k: list(v) for k, v in PAPER_TABLE2.items()},
               "feasible_shapes": report.feasible_count,
               "options": {k: (str(v) if isinstance(v, Path) else v)
                           for k, v in opts.__dict__.items()},
               "timings_s": report.timings}
    _write_text(out / "summary.json", json.dumps(summary, indent=2) + "\n", report)
    echo(_table_text(report, opts)[0])
    if opts.feasible_only:
        echo(f"(over the {report.feasible_count} physically feasible shapes of the "
             f"{report.grid_count} in the grid)")
    echo(f"\nwrote {len(report.files)} files to {out}/: case study 1 in "
         f"{report.timings['case_study_1']:.1f} s, case study 2 in "
         f"{report.timings['case_study_2']:.1f} s (models ready in "
         f"{report.timings['models']:.1f} s)")
    return report


def _table_text(report: ReproduceReport, opts: ReproduceOptions):
    """Table 2 as (terminal text, Markdown, CSV), entries of infeasible shapes marked, the
    feasible-only entries beside them."""
    return table2_text(report.table2, feasible=report.table2_shape_feasible or None,
                       feasible_only=report.table2_feasible_only or None,
                       clearance=opts.clearance)


def _studies(opts: ReproduceOptions, report: ReproduceReport, load, drawer) -> None:
    t1 = time.perf_counter()
    with stage(report.progress, "case study 1 (2 joints): Fig. 4 maps and the sweeps",
               "case study 1 done"):
        case_study_1(opts, report, load, drawer)
    report.timings["case_study_1"] = time.perf_counter() - t1
    t2 = time.perf_counter()
    with stage(report.progress, "case study 2 (3 joints): the extremes of every shape of the "
               "grid", "case study 2's extremes done"):
        Q, results = case_study_2(opts, report, load)
    with stage(report.progress, "Table 2, the shapes' feasibility and Figs. 4-6 (drawn in "
               f"{'parallel' if drawer.parallel else 'this process'})", "figures done"):
        _table_and_figures(opts, report, drawer, Q, results, t2)


def _table_and_figures(opts, report, drawer, Q, results, t2) -> None:
    out = opts.out
    feas = feasibility(results[SCENARIOS[0]][0], Q, clearance=opts.clearance)
    t = table2(results, feas.feasible if opts.feasible_only else None)
    report.table2 = t
    idx = table2_index(results, feas.feasible if opts.feasible_only else None)
    report.table2_shape_feasible = {k: tuple(bool(feas.feasible[i]) for i in v)
                                    for k, v in idx.items()}
    report.table2_feasible_only = table2(results, feas.feasible)
    report.feasible_count, report.grid_count = int(feas.feasible.sum()), len(Q)
    _, md, csv_text = _table_text(report, opts)
    _write_text(out / "table2.md", md, report)
    _write_text(out / "table2.csv", csv_text, report)
    with _timed(report, "figures"):
        figure5(Q, results, opts, drawer, feas)
        figure6(Q, results, opts, drawer, feas)
        report.files += drawer.finish()
    report.timings["figures_drawing_cpu"] = drawer.cpu
    report.timings["case_study_2"] = time.perf_counter() - t2
