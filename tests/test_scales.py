"""Colour scales and titles of the metric panels (snakecg.figures.scales), checked on real
data by reading the colour bars (limits, ticks, labels) and the titles, not pixels:

* a panel constant to rounding: the 4-joint ideal-wheels maxima of ||lambda||^2 are 1 to
  within 1e-14 (every shape's best torque loads the rows to the ellipsoid's norm);
* a 1 % spread: the 3-joint ideal-wheels maxima of ||lambda||^2, 0.990 to 1;
* sr data: the 2-joint wheels maxima of sr reach 0.987, and sr lies in [0, 1] (eq. 30).
"""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.analysis import com_polar, joint_grid
from snakecg.figures import paper
from snakecg.figures.scales import CONSTANT_REL, NARROW_REL, colour_scale

CODE_NAMES = ("norm_lambda", "norm_a_obj", "norm_qdd", "max_sr")


def _study(joints, scenario, step):
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario))
    Q = joint_grid(joints, -135, 135, step)
    ex = model.extremes(Q)
    radius, angle = com_polar(model, Q)
    return {m: ex.max[m] for m in ("norm_lambda", "norm_a_obj", "sr", "norm_qdd")}, \
        np.asarray(angle), np.asarray(radius)


@pytest.fixture(scope="module")
def constant():
    return _study(4, "ideal_wheels", 45)


@pytest.fixture(scope="module")
def narrow():
    return {s: _study(3, s, 30) for s in snakecg.SCENARIOS}


@pytest.fixture(scope="module")
def wheels2():
    return _study(2, "wheels", 10)


def _meshes(fig):
    return [c for ax in fig.axes if ax.name == "polar" for c in ax.collections
            if c.get_array() is not None]


def _bar(mesh):
    cb = mesh.colorbar
    labels = [t.get_text() for t in cb.ax.get_yticklabels()]
    return cb, list(cb.get_ticks()), labels, cb.ax.get_ylabel()


def test_the_data_are_what_the_rules_are_tried_on(constant, narrow, wheels2):
    lam = constant[0]["norm_lambda"]
    assert np.ptp(lam) < CONSTANT_REL * lam.max() and lam.max() == pytest.approx(1.0)
    lam3 = narrow["ideal_wheels"][0]["norm_lambda"]
    assert 0.005 < np.ptp(lam3) / lam3.max() < NARROW_REL
    assert 0.98 < wheels2[0]["sr"].max() <= 1.0


def test_a_constant_panel_is_flat_and_says_constant(constant):
    """The sweep's polar figure over the 4-joint ideal-wheels maxima: the ||lambda||^2 panel
    is one colour, its bar has one tick, 1.000, and says constant; the others vary."""
    from snakecg.sweeps.reduce import _polar_figure

    maxima, angle, radius = constant
    r_max = float(radius.max()) * 1.0001
    grid = {m: paper._binned_max(angle, radius, v, np.zeros(len(v), bool), r_max)[0]
            for m, v in maxima.items()}
    meta = {"robot": {"joints": 4}, "scene": {"scenario": "ideal_wheels", "kappa": 100.0}}
    fig = _polar_figure(grid, r_max, meta, f"{len(angle):,} configurations")
    meshes = _meshes(fig)
    assert len(meshes) == 4
    lam = meshes[0]
    cb, ticks, labels, label = _bar(lam)
    assert ticks == [pytest.approx(1.0, abs=1e-12)] and labels == ["1.000"]
    assert "constant 1.000" in label
    colours = lam.to_rgba(lam.get_array().compressed())
    assert len(np.unique(colours, axis=0)) == 1  # flat: noise of 1e-14 shows no bands
    assert lam.axes.get_title().startswith(r"largest max $\|\vec\lambda\|^2$ [N$^2$/kg]")
    for mesh in meshes[1:]:  # ||a_obj||^2, sr, ||qdd||^2 vary: several ticks, no "constant"
        _, ticks, _, label = _bar(mesh)
        assert len(ticks) >= 3 and "constant" not in label
    import matplotlib.pyplot as plt

    plt.close(fig)


def test_a_one_percent_spread_says_it_is_stretched(narrow):
    """Fig. 5 on the 3-joint maxima: scenario 3's ||lambda||^2 (a 1 % spread) keeps its
    colours over its range and its bar states the range and the stretch; scenario 1's (an
    80 % spread) does not need to."""
    s0 = narrow["frictionless"]
    maxima = {s: narrow[s][0] for s in snakecg.SCENARIOS}
    fig = paper.make_figure5(s0[1], s0[2], maxima, infeasible=np.zeros(len(s0[1]), bool),
                             kappa=100)
    meshes = _meshes(fig)
    assert len(meshes) == 9
    by = {(m.axes.get_title().splitlines()[1]): m for m in meshes if "lambda" in
          m.axes.get_title()}
    ideal = by["Scenario 3 (ideal wheels)"]
    cb, ticks, labels, label = _bar(ideal)
    data = ideal.get_array().compressed()
    lo, hi = float(data.min()), float(data.max())
    spread = (hi - lo) / hi
    assert f"range {lo:.4g} to {hi:.4g}: {100 * spread:.2g} % spread, stretched" in label
    assert ticks[0] <= lo and hi <= ticks[-1] and (ticks[-1] - ticks[0]) < 2 * (hi - lo)
    assert len(set(labels)) == len(labels)  # every tick readable apart
    assert [float(t) for t in labels] == pytest.approx(ticks, abs=0.01 * np.diff(ticks).min())
    _, _, _, label1 = _bar(by["Scenario 1 (frictionless)"])
    assert "stretched" not in label1 and "constant" not in label1


def test_sr_bars_stop_at_one(wheels2, narrow):
    """sr lies in [0, 1]: no colour level or bar end beyond, in Fig. 5, in a sweep's figure
    and on Fig. 4's torque planes."""
    s = narrow["wheels"]
    maxima = {sc: narrow[sc][0] for sc in snakecg.SCENARIOS}
    fig = paper.make_figure5(s[1], s[2], maxima, infeasible=np.zeros(len(s[1]), bool),
                             kappa=100)
    for mesh in _meshes(fig):
        if not mesh.axes.get_title().startswith("max sr"):
            continue
        cb, ticks, _, label = _bar(mesh)
        assert 0.0 <= mesh.norm.vmin and mesh.norm.vmax <= 1.0, (mesh.norm.vmin, mesh.norm.vmax)
        assert 0.0 <= min(ticks) and max(ticks) <= 1.0 and cb.ax.get_ylim()[1] <= 1.0
        assert label.startswith("sr [–]")
    scale = colour_scale(wheels2[0]["sr"], "sr", levels=8)
    assert scale.norm.boundaries[-1] <= 1.0 and scale.norm.boundaries[0] >= 0.0
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels"))
    from snakecg.reproduce import _ellipse, torque_plane

    q = np.array([0, 0, 0, np.radians(-135), np.radians(-135)])
    t1, t2, grids, N = torque_plane(model, q, 41)
    fig4 = paper.make_figure4([paper.Fig4Panel("wheels", t1, t2, grids, _ellipse(N))],
                              kappa=100, joints_deg=(-135, -135))
    sr_image = [im for ax in fig4.axes for im in ax.get_images()][2]
    assert sr_image.norm.vmin == 0.0 and sr_image.norm.vmax <= 1.0
    assert max(sr_image.colorbar.get_ticks()) <= 1.0


def test_titles_carry_symbols_and_units_and_rings_sit_off_the_data(narrow):
    s0 = narrow["frictionless"]
    maxima = {s: narrow[s][0] for s in snakecg.SCENARIOS}
    fig = paper.make_figure5(s0[1], s0[2], maxima, infeasible=np.zeros(len(s0[1]), bool),
                             kappa=100)
    polar = [ax for ax in fig.axes if ax.name == "polar"]
    units = {"lambda": "[N$^2$/kg]", "a_{obj}": "[kg m$^2$/s$^4$]", "sr": "sr [–]"}
    for ax in polar:
        title = ax.get_title()
        assert sum(sym in title and unit in title for sym, unit in units.items()) == 1, title
        # no radius label on the disc: the rings are named below the panel
        assert all(not t.get_text() for t in ax.get_yticklabels())
        rings = [t.get_text() for t in ax.texts if t.get_text().startswith("rings: radius")]
        assert len(rings) == 1 and rings[0].endswith(" m")
        assert ax.texts[0].get_position()[1] < 0  # below the axes, in axes coordinates
    texts = [t.get_text() for t in fig.findobj(lambda a: hasattr(a, "get_text"))]
    texts += [c.ax.get_ylabel() for c in (m.colorbar for m in _meshes(fig))]
    assert not any(name in t for t in texts for name in CODE_NAMES)


def test_fig5_tick_labels_carry_no_rounding_noise():
    """Fig. 5 as ``snakecg reproduce`` draws it (3 joints, kappa 100): with wheels the maxima
    of ||lambda||^2 reach 1 + 2e-15 (rounding above the ellipsoid's norm, 1), just beyond the
    round level 1. Every colour bar's labels read as short decimals (at most 6 significant
    digits, no 0.9700000000000001), apart from each other, each within 1 % of the least
    tick spacing of its tick, and the bar covers the data."""
    import re

    import matplotlib.pyplot as plt

    from snakecg.analysis import com_polar, joint_grid

    Q = joint_grid(3, -135, 135, 45)
    maxima = {}
    for s in snakecg.SCENARIOS:
        model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario=s, kappa=100))
        ex = model.extremes(Q)
        maxima[s] = {m: ex.max[m] for m in ("norm_lambda", "norm_a_obj", "sr")}
    assert maxima["wheels"]["norm_lambda"].max() > 1.0  # the rounding the labels must hide
    radius, angle = com_polar(model, Q)
    fig = paper.make_figure5(np.asarray(angle), np.asarray(radius), maxima,
                             infeasible=np.zeros(len(Q), bool), kappa=100)
    meshes = _meshes(fig)
    assert len(meshes) == 9
    for mesh in meshes:
        cb, ticks, labels, _ = _bar(mesh)
        assert len(ticks) >= 3 and len(set(labels)) == len(labels), labels
        for text in labels:  # significant digits of the mantissa
            assert len(re.sub(r"[^0-9]", "", text.split("e")[0]).strip("0")) <= 6, labels
        assert [float(t) for t in labels] == pytest.approx(
            ticks, abs=0.01 * np.diff(ticks).min()), labels
        data = mesh.get_array().compressed()
        assert ticks[0] <= data.min() and data.max() <= ticks[-1]
    plt.close(fig)
