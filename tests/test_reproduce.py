"""Reproduction of the paper (issue #4): Table 2 against the published values, the paper's
qualitative claims, and the figure files.

Tolerances per Table 2 entry are those stated in docs/how-to/reproduction.md; they are what the
documented reading achieves, not a fit (no constant is tuned to the published numbers).
"""

from __future__ import annotations

import csv
import io
import re
from contextlib import redirect_stderr

import numpy as np
import pytest

import snakecg
from snakecg.analysis import joint_grid
from snakecg.reproduce import PAPER_TABLE2, ReproduceOptions, reproduce, table2

# |relative difference| allowed per entry: (scenario 1, scenario 2, scenario 3).
# Best sr: a few percent (the slippage ratio is independent of the input ellipsoid's scale);
# the acceleration extremes depend on how the paper sampled the input region (docs).
TOLERANCE = {
    "best_sr": (0.03, 0.01, 0.01),
    "worst_sr": (0.15, 0.05, 0.15),
    "best_norm_a_obj": (0.15, 0.25, 0.25),
    "worst_norm_a_obj": (0.80, 0.40, 0.40),
}


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """The reproduction, with its progress on a captured standard error (not a terminal):
    ``report.stderr``."""
    out = tmp_path_factory.mktemp("reproduce")
    lines = []
    opts = ReproduceOptions(out=out, formats=("png", "svg"), torque_grid=41)
    err = io.StringIO()
    with redirect_stderr(err):
        report = reproduce(opts, echo=lines.append)
    report.stderr = err.getvalue()
    return out, report, "\n".join(lines)


def test_every_stage_says_when_it_starts_and_ends_off_a_terminal(run):
    """Standard error is a StringIO here (no terminal): each stage still prints its start
    and its end with the duration, and sub-steps as they finish, in order."""
    _, report, _ = run
    lines = report.stderr.splitlines()
    assert lines and all(re.match(r"snakecg reproduce \[ *\d+\.\d s\] ", ln) for ln in lines)
    said = [ln.split("] ", 1)[1] for ln in lines]
    for start, done in [("loading the 2- and 3-joint models", "loaded the 2- and 3-joint "
                         "models in "),
                        ("case study 1 (2 joints)", "case study 1 done in "),
                        ("case study 2 (3 joints)", "case study 2's extremes done in "),
                        ("Table 2, the shapes' feasibility and Figs. 4-6", "figures done in ")]:
        i = next(k for k, m in enumerate(said) if m.startswith(start))
        j = next(k for k, m in enumerate(said) if m.startswith(done))
        assert i < j and re.search(r" in \d+\.\d s$", said[j]), (start, said)
    for scenario in snakecg.SCENARIOS:
        assert f"  extremes of the 21,952 configurations, {scenario}: done" in said
    assert sum(m.startswith("  Fig. 4 torque-plane maps, kappa = ") for m in said) == 3


def test_table2_within_documented_tolerance_of_the_paper(run):
    _, report, _ = run
    for key, tol in TOLERANCE.items():
        for j, scenario in enumerate(snakecg.SCENARIOS):
            ours, paper = report.table2[key][j], PAPER_TABLE2[key][j]
            assert abs(ours - paper) / paper <= tol[j], (key, scenario, ours, paper)


def test_table2_files_and_terminal_output(run):
    out, report, text = run
    rows = list(csv.DictReader((out / "table2.csv").open()))
    assert len(rows) == 12
    for row in rows:
        key, scenario = row["concept"], row["scenario"]
        j = snakecg.SCENARIOS.index(scenario)
        assert float(row["paper"]) == pytest.approx(PAPER_TABLE2[key][j])
        assert float(row["snakecg"]) == pytest.approx(report.table2[key][j], rel=1e-8)
    md = (out / "table2.md").read_text()
    table = [ln for ln in md.splitlines() if ln.startswith("|")]
    assert len(table) == 6 and "Best sr" in md
    assert all(ln.count("|") == 14 for ln in table)  # concept + 3 x (4 columns)
    assert "Worst ||a_obj||^2" in text and "rel.diff" in text and "feas. only" in text
    # one convention: the entries of infeasible shapes carry *, the footnote says what it
    # means, in the terminal table, table2.md (escaped) and table2.csv (shape_feasible)
    footnote = "* a shape that is not physically possible (links closer than 0.01 m or " \
               "inside the object)"
    assert footnote in text and "\\" + footnote in md
    for row in rows:
        key, j = row["concept"], snakecg.SCENARIOS.index(row["scenario"])
        feasible = report.table2_shape_feasible[key][j]
        assert row["shape_feasible"] == ("true" if feasible else "false")
        assert float(row["feasible_only"]) == pytest.approx(
            report.table2_feasible_only[key][j], rel=1e-8)
        entry = f"{report.table2[key][j]:.6g}"
        assert (entry + "*" in text) == (not feasible)
        assert (entry + "\\*" in md) == (not feasible)
    # the caption says plainly that the paper's ||a_obj||^2 rows are not reproducible
    assert "||a_obj||^2 rows are not reproducible from its Table 1" in text
    assert "‖a_obj‖² rows are not reproducible from its Table 1" in md


def _inside_plate_or_crossing(q_deg, clearance=0.01, n=600):
    """Independent of snakecg.geometry: the links of Table 1 (0.15 m, joint angles added up)
    sampled at ``n`` points each; the 0.1 m plate on the left of link 1, touching the middle
    of its face. (True/False: whether the shape is physically impossible)."""
    phi = np.concatenate([[0.0], np.cumsum(np.radians(q_deg))])
    e = np.stack([np.cos(phi), np.sin(phi)], axis=1)
    rear = np.concatenate([[[0.0, 0.0]], np.cumsum(0.15 * e, axis=0)[:-1]])
    t = np.linspace(0.0, 1.0, n)[:, None]
    pts = [rear[i] + 0.15 * t * e[i] for i in range(4)]
    for i in range(4):
        for j in range(i + 2, 4):
            d = np.linalg.norm(pts[i][:, None, :] - pts[j][None, :, :], axis=2).min()
            if d < clearance:
                return True
    normal = np.array([-np.sin(phi[0]), np.cos(phi[0])])
    centre = rear[0] + 0.075 * e[0] + 0.05 * normal
    for i in range(1, 4):
        rel = pts[i] - centre
        if np.any((np.abs(rel @ e[0]) < 0.05 - 1e-9) & (np.abs(rel @ normal) < 0.05 - 1e-9)):
            return True
    return False


def test_table2_marks_and_feasible_only_entries_agree_with_an_independent_geometry(run):
    """The marks and the feasible-only column, checked on the sweep CSV with the links and the
    plate sampled point by point: a marked entry's shape is impossible, an unmarked one's
    possible; a feasible-only entry is attained by a possible shape, and every shape that
    does better is impossible."""
    out, report, _ = run
    for j, scenario in enumerate(snakecg.SCENARIOS):
        with (out / f"case2_sweep_{scenario}.csv").open() as fh:
            rows = list(csv.DictReader(fh))
        q = np.array([[float(r[f"q{k}_deg"]) for k in (1, 2, 3)] for r in rows])
        for key in ("worst_norm_a_obj", "best_norm_a_obj", "worst_sr", "best_sr"):
            kind, metric = key.split("_", 1)
            v = np.array([float(r[f"max_{metric}"]) for r in rows])
            sign = 1.0 if kind == "worst" else -1.0  # order: best first
            at = int(np.argmin(sign * v))
            assert _inside_plate_or_crossing(q[at]) == (not report.table2_shape_feasible[key][j])
            f_value = report.table2_feasible_only[key][j]
            f_at = int(np.argmin(np.abs(v - f_value)))
            assert v[f_at] == pytest.approx(f_value, rel=1e-8)
            assert not _inside_plate_or_crossing(q[f_at]), (scenario, key, q[f_at])
            # (the CSV holds 9 significant digits: ties within them are not "better")
            better = np.flatnonzero(sign * (v - f_value) < -1e-8 * abs(f_value))
            assert all(_inside_plate_or_crossing(q[b]) for b in better), (scenario, key)


def test_table2_entries_follow_from_the_sweep_csv(run):
    """Table 2 = min/max over configurations of the per-configuration maxima in the CSV."""
    out, report, _ = run
    for j, scenario in enumerate(snakecg.SCENARIOS):
        with (out / f"case2_sweep_{scenario}.csv").open() as fh:
            rows = list(csv.DictReader(fh))
        assert len(rows) == 28**3
        a = np.array([float(r["max_norm_a_obj"]) for r in rows])
        sr = np.array([float(r["max_sr"]) for r in rows])
        assert a.min() == pytest.approx(report.table2["worst_norm_a_obj"][j], rel=1e-6)
        assert sr.max() == pytest.approx(report.table2["best_sr"][j], rel=1e-6)


def test_passive_wheels_raise_sr_sharply_but_barely_change_the_push(run):
    """Paper: wheels have 'little impact on the acceleration, but a significant one on
    decreasing the slippage' (Table 2, Fig. 5)."""
    _, report, _ = run
    s1, s2, s3 = (report.table2["best_sr"][j] for j in range(3))
    assert s3 > 30 * s1 and s2 > 30 * s1
    a1, a2, a3 = (report.table2["best_norm_a_obj"][j] for j in range(3))
    assert max(a2, a3) / a1 < 1.5
    # per configuration: the sr gain dwarfs the change in the object's acceleration
    scene = dict(robot=snakecg.Robot(joints=3), kappa=100.0)
    Q = joint_grid(3)[::7]
    ex1 = snakecg.load(snakecg.Scene(scenario="frictionless", **scene)).extremes(Q)
    ex3 = snakecg.load(snakecg.Scene(scenario="ideal_wheels", **scene)).extremes(Q)
    sr_gain = np.median(ex3.max["sr"] / ex1.max["sr"])
    push_change = np.median(ex3.max["norm_a_obj"] / ex1.max["norm_a_obj"])
    assert sr_gain > 20 and 0.8 < push_change < 1.5


def test_tau2_far_from_the_object_barely_moves_it_without_wheels():
    """Paper, Fig. 4 discussion: tau_2 has almost no effect on the object's acceleration."""
    q = np.array([0, 0, 0, *np.deg2rad([-135, -135])])
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario="frictionless"))
    maps = model.maps(q)
    extent = np.sqrt(np.diag(np.linalg.inv(maps["input_metric"])))
    Io = np.diag([model.scene.object_mass] * 2 + [model.scene.object_inertia])
    col = [maps["a_obj_from_tau"][:, j] * extent[j] for j in range(2)]
    effect = [c @ Io @ c for c in col]
    assert effect[1] < 0.05 * effect[0]


def test_sr_vanishes_where_the_contact_is_lost():
    q = np.array([0, 0, 0, *np.deg2rad([-135, -135])])
    for scenario in snakecg.SCENARIOS:
        model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario=scenario))
        rng = np.random.default_rng(4)
        res = model.forward(q, rng.normal(scale=0.05, size=(400, 2)))
        assert (~res.contact).sum() > 50 and res.contact.sum() > 50
        assert np.all(res.sr[~res.contact] == 0.0)
        assert np.all(res.norm_a_obj[~res.contact] < 1e-20)


def test_table2_recomputed_from_results_matches(run):
    """``table2`` is a pure reduction: recompute it from fresh extremes on a sub-grid."""
    Q = joint_grid(3)[::97]
    results = {}
    for s in snakecg.SCENARIOS:
        m = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario=s))
        results[s] = (m, m.extremes(Q), None, None)
    t = table2(results)
    for j, s in enumerate(snakecg.SCENARIOS):
        assert t["best_sr"][j] == pytest.approx(results[s][1].max["sr"].max())


def test_figures_written_and_readable(run):
    Image = pytest.importorskip("PIL.Image", reason="pillow (test extra) reads the PNGs")
    out, _, _ = run
    names = ["fig4_kappa1", "fig4_kappa10", "fig4_kappa100", "fig5_polar", "fig6_configurations"]
    for name in names:
        png = out / f"{name}.png"
        svg = out / f"{name}.svg"
        assert png.stat().st_size > 10_000 and svg.stat().st_size > 10_000
        with Image.open(png) as im:
            im.load()
            assert im.size[0] > 800 and im.size[1] > 400
            # not a blank canvas: many distinct colours
            assert len(im.convert("RGB").getcolors(maxcolors=1 << 20) or []) > 50
        assert svg.read_text(errors="ignore").lstrip().startswith("<?xml")
    for s in snakecg.SCENARIOS:
        with (out / f"case1_sweep_{s}.csv").open() as fh:
            assert sum(1 for _ in fh) == 784 + 1


def test_object_inertia_and_distance_drop_out_with_the_com_on_the_normal():
    """docs/how-to/reproduction.md: with the object's COM on the contact normal the contact force
    passes through it, so neither its rotational inertia nor the distance changes a metric."""
    Q = joint_grid(3)[::331]
    robot = snakecg.Robot(joints=3)
    ref = snakecg.load(snakecg.Scene(robot, scenario="ideal_wheels")).extremes(Q)
    for change in ({"object_inertia": 5.0}, {"object_distance": 0.2}):
        other = snakecg.load(snakecg.Scene(robot, scenario="ideal_wheels", **change)).extremes(Q)
        for m in ("norm_a_obj", "sr", "norm_qdd"):
            np.testing.assert_allclose(other.max[m], ref.max[m], rtol=1e-9)


# ------------------------------------------------------------------------------------------
# Feasibility of shapes (Table 2 option, marks in the figures)
# ------------------------------------------------------------------------------------------
class _Max:
    def __init__(self, mx):
        self.max = mx


def _sweep(out, scenario):
    with (out / f"case2_sweep_{scenario}.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    return {m: np.array([float(r[f"max_{m}"]) for r in rows]) for m in ("norm_a_obj", "sr")}


def _sampled_feasible(model, q, clearance, n=400):
    """Brute force: links sampled at n points; non-adjacent pairs farther than the clearance,
    no sample of a non-contacting link strictly inside the 0.1 m plate."""
    P = model.link_poses(q)
    r = model.robot
    t = np.linspace(0, 1, n)[:, None]
    pts = []
    for i, (x, y, phi) in enumerate(P):
        e = np.array([np.cos(phi), np.sin(phi)])
        rear = np.array([x, y]) - r.com[i] * e
        pts.append(rear + t * r.length[i] * e)
    for i in range(len(pts)):
        for j in range(i + 2, len(pts)):
            d = np.sqrt(((pts[i][:, None] - pts[j][None]) ** 2).sum(-1)).min()
            if d < clearance:
                return False
    q_obj = model.place_object(q)[0]
    c, psi = q_obj[:2], q_obj[2]
    R = np.array([[np.cos(psi), np.sin(psi)], [-np.sin(psi), np.cos(psi)]])
    for i in range(1, len(pts)):
        local = (pts[i] - c) @ R.T
        if np.any(np.max(np.abs(local), axis=1) < 0.05 - 1e-6):
            return False
    return True


def test_feasible_only_table2_is_the_reduction_over_feasible_shapes(run):
    from snakecg.geometry import SELF_CLEARANCE, feasibility
    from snakecg.reproduce import table2_index

    out, report, _ = run
    Q = joint_grid(3)
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3)))
    mask = feasibility(model, Q).feasible
    assert report.feasible_count == mask.sum() and report.grid_count == len(Q)
    assert 0.5 * len(Q) < mask.sum() < len(Q)   # many shapes of the paper's grid are not possible
    results = {s: (model, _Max(_sweep(out, s)), None, None) for s in snakecg.SCENARIOS}
    full, feasible = table2(results), table2(results, mask)
    idx = table2_index(results, mask)
    for j, s in enumerate(snakecg.SCENARIOS):
        v = results[s][1].max
        assert feasible["best_sr"][j] == pytest.approx(v["sr"][mask].max(), rel=1e-12)
        assert feasible["worst_norm_a_obj"][j] == pytest.approx(v["norm_a_obj"][mask].min())
        assert full["best_sr"][j] == pytest.approx(report.table2["best_sr"][j], rel=1e-8)
        # the feasible worst can only be higher, the feasible best only lower
        assert feasible["worst_sr"][j] >= full["worst_sr"][j]
        assert feasible["best_norm_a_obj"][j] <= full["best_norm_a_obj"][j]
        for key in idx:  # the attaining shapes are possible by brute-force sampling
            assert _sampled_feasible(model, Q[idx[key][j]], SELF_CLEARANCE)
    # Fig. 6's "best ||a_obj||^2" of scenarios 2 and 3 passes through the object (issue seen
    # by users): the unfiltered table picks it, and the brute force agrees it is infeasible
    unfiltered = table2_index(results)
    for j in (1, 2):
        q = Q[unfiltered["best_norm_a_obj"][j]]
        assert not mask[unfiltered["best_norm_a_obj"][j]]
        assert not _sampled_feasible(model, q, SELF_CLEARANCE)


def test_summary_records_feasible_count_and_options(run):
    import json

    out, report, _ = run
    summary = json.loads((out / "summary.json").read_text())
    assert summary["feasible_shapes"] == report.feasible_count
    assert summary["options"]["feasible_only"] is False
    assert set(summary["timings_s"]) >= {"models", "case_study_1", "case_study_2", "figures"}


@pytest.mark.slow
def test_no_reading_tried_reproduces_the_paper_a_obj_rows():
    """What Table 2's caption states: among the alternative readings of the input region and
    of the maximum (snakecg reproduce --alternatives), none brings the four ||a_obj||^2
    entries of scenarios 1 and 3 within 15 % of the published values together, while the
    readings of the region leave sr unchanged (degree 0 in tau)."""
    from snakecg.reproduce import alternative_readings

    text = alternative_readings()
    rows = [r.split(" | ") for r in text.splitlines()[3:]]
    paper = [PAPER_TABLE2[k][j] for j in (0, 2) for k in ("worst_norm_a_obj",
                                                          "best_norm_a_obj")]
    cols = (1, 2, 5, 6)  # S1 worst/best a_obj, S3 worst/best a_obj
    for row in rows:
        label = row[0].lstrip("| ")
        got = [float(row[c]) for c in cols]
        worst_miss = max(abs(g / p - 1) for g, p in zip(got, paper))
        assert worst_miss > 0.15, (label, got)
    this = rows[0]
    for row in rows:
        if row[0].lstrip("| ").startswith("input region"):
            assert [row[c] for c in (3, 4, 7)] == [this[c] for c in (3, 4, 7)]
