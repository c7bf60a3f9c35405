"""``snakecg.plot`` and ``snakecg plot``: what is drawn is where independent kinematics and the
dense reference solve (tests/reference.py) put it; the CLI writes a valid PNG atomically."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.figure import Figure
from reference import Reference

import snakecg
from snakecg.cli import main


def _by_gid(ax, gid):
    found = [a for a in ax.get_children() if a.get_gid() == gid]
    assert found, f"no artist with gid {gid!r}"
    return found


def _arrows(ax, gid):
    (qv,) = _by_gid(ax, gid)
    return (np.column_stack([qv.X, qv.Y]), np.column_stack([np.asarray(qv.U),
                                                            np.asarray(qv.V)]))


def _parallel(u, v, tol=1e-9):
    """u = s v with s > 0."""
    u, v = np.asarray(u, float), np.asarray(v, float)
    return abs(u[0] * v[1] - u[1] * v[0]) <= tol * np.hypot(*u) * np.hypot(*v) and u @ v > 0


@pytest.mark.parametrize("contact_link, side", [(1, "left"), (3, "right")])
def test_figure_coordinates_match_independent_kinematics_and_forces(contact_link, side, rng,
                                                                    random_robot):
    robot = random_robot(3)
    scene = snakecg.Scene(robot, scenario="wheels", mu=0.3, kappa=20,
                          contact_link=contact_link, side=side, wheel_offset=0.01)
    ref = Reference(scene)
    q = np.concatenate([rng.uniform(-0.2, 0.2, 2), rng.uniform(-np.pi, np.pi, 1),
                        rng.uniform(-1.5, 1.5, 3)])
    tau = rng.normal(scale=0.05, size=3)
    ax = snakecg.plot(scene, q, tau, ax=Figure().add_subplot())
    rear, e = ref.rear_ends(q)
    length = np.asarray(robot.length)
    for i in range(robot.n_links):
        (line,) = _by_gid(ax, f"link{i + 1}")
        np.testing.assert_allclose(line.get_xydata(), [rear[i], rear[i] + length[i] * e[i]],
                                   atol=1e-12)
    k = contact_link - 1
    phi = ref.angles(q)
    n = (1 if side == "left" else -1) * np.array([-np.sin(phi[k]), np.cos(phi[k])])
    P = rear[k] + scene.contact_offset * e[k]
    (obj,) = _by_gid(ax, "object")
    corners = obj.get_xy()[:4]
    np.testing.assert_allclose(corners.mean(axis=0), P + scene.object_distance * n, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(corners - corners.mean(axis=0), axis=1),
                               np.sqrt(2) * scene.object_distance, rtol=1e-12)
    at, vec = _arrows(ax, "contact_normal")
    np.testing.assert_allclose(at[0], P, atol=1e-12)
    assert _parallel(vec[0], n)
    # the wheels' rolling directions, at COM + wheel_offset along each wheeled link
    wheels = _by_gid(ax, "wheels")
    assert len(wheels) == len(scene.wheel_links)
    com = ref.link_poses(q)[:, :2]
    for line, i in zip(wheels, scene.wheel_links):
        xy = line.get_xydata()
        np.testing.assert_allclose(xy.mean(axis=0), com[i - 1] + 0.01 * e[i - 1], atol=1e-12)
        d = xy[1] - xy[0]
        assert abs(d[0] * e[i - 1][1] - d[1] * e[i - 1][0]) < 1e-12
    # forces and accelerations: the reference's forward solve, one scale per group
    sol = ref.solve(q, tau)
    lam = sol["lam"]
    at_c, f_c = _arrows(ax, "force_contact")
    at_w, f_w = _arrows(ax, "force_wheels")
    np.testing.assert_allclose(at_c[0], P, atol=1e-12)
    scale = f_c[0] @ n / lam[0] if abs(lam[0]) > 1e-9 else None
    for (pt, f), i in zip(zip(at_w, f_w), scene.wheel_links):
        lateral = np.array([-np.sin(phi[i - 1]), np.cos(phi[i - 1])])
        np.testing.assert_allclose(pt, com[i - 1] + 0.01 * e[i - 1], atol=1e-12)
        if scale is None:
            scale = f @ lateral / lam[i]
        np.testing.assert_allclose(f, scale * lam[i] * lateral, atol=1e-9 * abs(scale))
    np.testing.assert_allclose(f_c[0], scale * lam[0] * n, atol=1e-9 * abs(scale))
    longest = max(np.hypot(*v) for v in np.vstack([f_c, f_w]))
    assert longest == pytest.approx(0.6 * np.mean(length), rel=1e-12)
    at_o, a_o = _arrows(ax, "acc_object")
    np.testing.assert_allclose(at_o[0], P + scene.object_distance * n, atol=1e-12)
    if np.hypot(*sol["a_obj"][:2]) > 1e-9:
        assert _parallel(a_o[0], sol["a_obj"][:2], tol=1e-7)
    _, a_l = _arrows(ax, "acc_links")
    J = ref.jacobians(q)
    acc = np.einsum("iak,k->ia", J[:, :2], sol["qdd"])
    s = np.hypot(*a_l[0]) / np.hypot(*acc[0])
    np.testing.assert_allclose(a_l, s * acc, atol=1e-7 * s * np.abs(acc).max())
    title = ax.get_title()
    assert ("contact kept" if sol["contact"] else "contact lost") in title


def test_plot_without_torque_and_bad_input():
    scene = snakecg.Scene(snakecg.Robot(joints=2))  # frictionless: no wheels drawn
    ax = snakecg.plot(scene, [0, 0, 0, -2.356, -2.356], ax=Figure().add_subplot())
    assert not [a for a in ax.get_children() if a.get_gid() in ("wheels", "force_contact")]
    with pytest.raises(snakecg.InputError, match=r"q has shape \(4,\), expected \(5,\)"):
        snakecg.plot(scene, [0, 0, 0, 1], ax=Figure().add_subplot())
    with pytest.raises(snakecg.InputError, match="scene must be a snakecg.Scene"):
        snakecg.plot(snakecg.Robot(joints=2), [0] * 5)


def test_cli_writes_a_png_atomically(tmp_path, capsys):
    from PIL import Image

    out = tmp_path / "forces.png"
    assert main(["plot", "--joints", "3", "--q", "0,0,0,30deg,-45deg,60deg", "--tau",
                 "0.05,0,-0.02", "--scenario", "wheels", "--out", str(out)]) == 0
    with Image.open(out) as im:
        im.verify()
    with Image.open(out) as im:
        assert im.format == "PNG" and im.size[0] > 500 and im.size[1] > 400
    assert [p.name for p in tmp_path.iterdir()] == ["forces.png"]
    capsys.readouterr()
    assert main(["plot", "--joints", "3", "--q", "0,0,0,0,0,0", "--out",
                 str(tmp_path / "x.bmp")]) == 2
    err = capsys.readouterr().err
    assert "--out must end in .png, .pdf, .svg" in err and len(err.strip().splitlines()) == 1
