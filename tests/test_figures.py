"""snakecg.figures: readable panels (text sizes, colour scales), the binned Fig. 5 against a
plain loop, and the same pictures whether drawn in worker processes or in this one."""

from __future__ import annotations

import numpy as np
import pytest

from snakecg.figures import paper as figures


def _texts(fig):
    from matplotlib.text import Text

    return [t for t in fig.findobj(Text) if t.get_text().strip() and t.get_visible()]


def _panels(rng, n=41):
    t = np.linspace(-0.1, 0.1, n)
    out = []
    for s, top in (("frictionless", 0.026), ("wheels", 0.99), ("ideal_wheels", 0.98)):
        g = {m: rng.uniform(0, 1, (n, n)) for m in ("norm_a_obj", "norm_qdd")}
        g["sr"] = rng.uniform(0, top, (n, n))
        g["contact"] = np.add.outer(t, 0 * t) > 0
        a = np.linspace(0, 2 * np.pi, 50)
        out.append(figures.Fig4Panel(s, t, t, g, 0.08 * np.stack([np.cos(a), np.sin(a)])))
    return out


def test_figure4_scales_per_panel_and_text_at_least_9pt(rng):
    panels = _panels(rng)
    fig = figures.make_figure4(panels, kappa=100, joints_deg=(-135, -135),
                               infeasible="links cross")
    images = [im for ax in fig.axes for im in ax.get_images()]
    assert len(images) == 9
    # the sr panels (last row) span their own data: scenario 1's 0.026 is not squeezed into 0-1
    sr_images = images[6:9]  # axes are row-major: the third row is sr
    for im, p in zip(sr_images, panels):
        assert im.get_clim() == pytest.approx((0.0, p.grids["sr"].max()))
    sizes = [t.get_fontsize() for t in _texts(fig)]
    assert min(sizes) >= 9
    assert any("not physically feasible" in t.get_text() for t in _texts(fig))


def test_binned_max_matches_a_loop(rng):
    n = 3000
    angle = rng.uniform(-np.pi, np.pi, n)
    radius = rng.uniform(0, 0.2, n)
    values = rng.normal(size=n)
    bad = rng.random(n) < 0.3
    z, marked = figures._binned_max(angle, radius, values, bad, 0.2)
    ref = np.full_like(z, np.nan)
    ref_bad = np.zeros_like(marked)
    for k in range(n):
        a = min(int((angle[k] + np.pi) / (2 * np.pi) * figures.ANGLE_BINS), figures.ANGLE_BINS - 1)
        r = min(int(radius[k] / 0.2 * figures.RADIUS_BINS), figures.RADIUS_BINS - 1)
        if np.isnan(ref[a, r]) or values[k] > ref[a, r]:
            ref[a, r], ref_bad[a, r] = values[k], bad[k]
    np.testing.assert_array_equal(np.isnan(z), np.isnan(ref))
    np.testing.assert_array_equal(z[~np.isnan(z)], ref[~np.isnan(ref)])
    np.testing.assert_array_equal(marked, ref_bad)


def test_figure5_levels_span_the_data_and_text_at_least_9pt(rng):
    n = 4000
    angle, radius = rng.uniform(-np.pi, np.pi, n), rng.uniform(0, 0.22, n)
    maxima = {s: {"norm_lambda": 0.99 + 0.01 * rng.random(n), "norm_a_obj": rng.random(n),
                  "sr": rng.random(n)} for s in ("frictionless", "wheels", "ideal_wheels")}
    fig = figures.make_figure5(angle, radius, maxima, infeasible=rng.random(n) < 0.2, kappa=100)
    meshes = [c for ax in fig.axes for c in ax.collections if hasattr(c, "norm")
              and c.get_array() is not None and ax.name == "polar"]
    assert len(meshes) == 9
    for mesh in meshes:
        levels = mesh.norm.boundaries
        data = mesh.get_array().compressed()
        assert levels[0] <= data.min() and data.max() <= levels[-1]
        assert 4 <= len(levels) <= 12   # a few discrete bands, not a continuous speckle
    assert min(t.get_fontsize() for t in _texts(fig)) >= 9


def _shape(infeasible=""):
    rear = np.array([[0.0, 0.0], [0.15, 0.0], [0.3, 0.0], [0.45, 0.0]])
    front = rear + [0.15, 0.0]
    return figures.Shape(rear, front, np.array([0.075, 0.05, 0.0]), np.array([0.075, 0.0]),
                         np.array([0.3, 0.0]), title="best sr = 0.98\nq = (0°, 0°, 0°)",
                         infeasible=infeasible)


def test_figure6_marks_infeasible_shapes_in_red_and_text_at_least_9pt():
    rows = {"wheels": [_shape(), _shape("a link enters the object")]}
    fig = figures.make_figure6(rows)
    texts = _texts(fig)
    assert min(t.get_fontsize() for t in texts) >= 9
    red = [t for t in texts if "infeasible" in t.get_text() and t.get_text() != fig._suptitle
           .get_text()]
    assert len(red) == 1 and red[0].axes is fig.axes[1]
    assert fig.axes[1].spines["left"].get_edgecolor()[:3] != fig.axes[0].spines["left"] \
        .get_edgecolor()[:3]


def test_drawing_in_workers_gives_the_same_picture(tmp_path):
    rows = {"wheels": [_shape(), _shape("links cross")]}
    files = {}
    for jobs in (1, 2):
        d = tmp_path / f"jobs{jobs}"
        d.mkdir()
        drawer = figures.Drawer(jobs)
        try:
            assert drawer.parallel == (jobs > 1)
            drawer.submit("figure6", rows=rows, stem=d / "fig6", formats=("png",))
            files[jobs] = drawer.finish()
        finally:
            drawer.close()
        assert drawer.cpu > 0
    assert [p.name for p in files[1]] == [p.name for p in files[2]] == ["fig6.png"]
    assert files[1][0].read_bytes() == files[2][0].read_bytes()
    assert not list(tmp_path.rglob("*.tmp"))   # atomic writes leave no temporary file
