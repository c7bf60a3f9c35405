"""The command line on a spatial scene file (forward, optimize, plot --scene FILE) against
the library and the planar model: the example URDF read as a 3-D chain lying flat gives the
planar command's numbers; strict JSON; one-line refusals with exit status 2."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import snakecg
from snakecg.errors import InputError
from snakecg.spatial.scene_file import read_spatial_scene, spatial_scene_from_data

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples" / "spatial"


def _cli(*args, cwd=ROOT):
    return subprocess.run([sys.executable, "-m", "snakecg.cli", *args], capture_output=True,
                          text=True, cwd=cwd, timeout=600)


def _json(res):
    assert res.returncode in (0, 1), res.stderr
    return json.loads(res.stdout, parse_constant=lambda c: pytest.fail(f"{c} in the JSON"))


def test_forward_on_the_urdf_example_is_the_planar_command():
    """examples/spatial/from_urdf.toml (the example URDF, its yaw joints lying flat,
    ideal wheels): qdd's joint part, a_obj, the contact and wheel forces and the metrics equal
    the planar command's on the same URDF, to 1e-10."""
    q, tau = "0.1,-0.2,20deg,30deg,-45deg,60deg", "0.05,0,-0.02"
    sp = _json(_cli("forward", "--scene", str(EXAMPLES / "from_urdf.toml"), "--q", q,
                    "--tau", tau, "--json"))
    pl = _json(_cli("forward", "--robot", "examples/snake3.urdf", "--scenario", "ideal_wheels",
                    "--q", q, "--tau", tau, "--json"))
    assert sp["kind"] == "spatial" and sp["scenario"] == "ideal_wheels"
    nl = 4

    def close(a, b):
        a, b = np.asarray(a, float), np.asarray(b, float)
        return np.abs(a - b).max() <= 1e-10 * max(1.0, np.abs(b).max())

    assert close(sp["qdd"][6:], pl["qdd"][3:])
    assert close(sp["a_obj"], pl["a_obj"])
    assert close(sp["lam"][:nl + 1], pl["lam"])
    for k in ("norm_lambda", "norm_a_obj", "norm_qdd", "sr"):
        assert close(sp[k], pl[k]), k
    assert sp["wheel_state"] == pl["wheel_state"]


def test_forward_optimize_and_plot_on_the_yaw_pitch_example(tmp_path):
    """The library gives the same numbers as the command on examples/spatial/yaw_pitch.toml
    (the file read into the same SpatialScene as written in Python here), the optimize
    answer is optimal and inside the file's effort limits, the figure is written."""
    path = EXAMPLES / "yaw_pitch.toml"
    scene = read_spatial_scene(path)
    expected = snakecg.SpatialScene(
        snakecg.SpatialRobot(joints=3, effort_limits=[0.5, 2.0, 0.5]), scenario="wheels",
        mu=0.1, kappa=100.0, contact_link=4, side="left")
    assert scene == expected
    q = "0,0,0,-30deg,0,-30deg"
    out = _json(_cli("forward", "--scene", str(path), "--q", q, "--tau", "0.3,1,0.3", "--json"))
    qq = scene.robot.neutral()
    qq[7:] = np.deg2rad([-30, 0, -30])
    lib = snakecg.load(expected).forward(qq, [0.3, 1.0, 0.3])
    assert np.allclose(out["lam"], lib.lam, rtol=0, atol=1e-12)
    assert np.allclose(out["normal"], lib.normal, rtol=0, atol=1e-12)
    opt = _json(_cli("optimize", "strongest-push", "--scene", str(path), "--q", q, "--json"))
    assert opt["status"] == "optimal"
    assert all(abs(t) <= lim * (1 + 1e-9) for t, lim in zip(opt["tau"], (0.5, 2.0, 0.5)))
    fig = tmp_path / "snake.png"
    res = _cli("plot", "--scene", str(path), "--q", q, "--tau", "0.3,1,0.3", "--out", str(fig))
    assert res.returncode == 0, res.stderr
    assert fig.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("args, message", [
    (("optimize", "max-sr", "--a-obj", "1,0,0"), "--a-obj"),
    (("optimize", "max-sr", "--allow-slide"), "--allow-slide"),
    (("forward", "--tau", "0,0,0", "--q", "0,0,0,1"), "q has 4 numbers"),
    (("forward", "--tau", "0,0", ), "tau"),
    (("forward", "--tau", "0,0,0", "--q", "0,0,0,0,0,0,2,0,0,0"), "quaternion"),
    (("simulate", "--tau", "0,0,0", "--duration", "1"), "--scene"),
    (("forward", "--tau", "0,0,0", "--scenario", "wheels"), "drop --scenario"),
])
def test_refusals_are_one_line(args, message):
    path = str(EXAMPLES / "yaw_pitch.toml")
    full = list(args) + ["--scene", path]
    if "--q" not in full and args[0] != "simulate":
        full += ["--q", "0,0,0,0,0,0"]
    if args[0] == "simulate":
        full += ["--q", "0,0,0,0,0,0"]
    res = _cli(*full)
    assert res.returncode == 2, (res.stdout, res.stderr)
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0] and "Traceback" not in res.stderr


def test_scene_file_problems_are_collected():
    with pytest.raises(InputError, match=r"unknown tables \['object'\].*\[scene\] has unknown "
                                         r"keys \['friction'\]"):
        spatial_scene_from_data({"robot": {"joints": 2, "joint_axis": [0, 0, 1]},
                                 "scene": {"friction": 0.2}, "object": {}})
    with pytest.raises(InputError, match=r"\[robot\] file must end in .urdf or .xml"):
        spatial_scene_from_data({"robot": {"file": "snake.obj"}})
    with pytest.raises(InputError, match=r"\[scene\].*contact_link"):
        spatial_scene_from_data({"robot": {"joints": 2, "joint_axis": [0, 0, 1]},
                                 "scene": {"contact_link": 7}})


def test_robot_files_of_both_forms_on_the_planar_commands(tmp_path):
    """--robot takes an MJCF file: a planar chain (the paper's links as yaw hinges) gives the
    numbers of the paper's Table 1 robot; a 3-D chain is refused in one line that points at
    the spatial scene file."""
    inertial = '<inertial pos="0.075 0 0" mass="1" fullinertia="0.0002 0.002 0.002 0 0 0"/>'

    def chain(axis2):
        return (f'<mujoco><worldbody><body name="a"><freejoint/>{inertial}'
                f'<body name="b" pos="0.15 0 0"><joint name="h1" axis="0 0 1"/>{inertial}'
                f'<body name="c" pos="0.15 0 0"><joint name="h2" axis="{axis2}"/>{inertial}'
                '</body></body></body></worldbody></mujoco>')

    (tmp_path / "planar.xml").write_text(chain("0 0 1"))
    (tmp_path / "spatial.xml").write_text(chain("0 1 0"))
    q, tau = "0.1,-0.2,20deg,30deg,-45deg", "0.05,-0.02"
    common = ("--scenario", "wheels", "--q", q, "--tau", tau, "--json")
    mjcf = _json(_cli("forward", "--robot", str(tmp_path / "planar.xml"), *common))
    paper = _json(_cli("forward", "--joints", "2", *common))
    for k in ("qdd", "a_obj", "lam", "sr", "norm_qdd"):
        assert np.allclose(mjcf[k], paper[k], rtol=1e-12, atol=1e-12), k
    res = _cli("forward", "--robot", str(tmp_path / "spatial.xml"), "--q", q, "--tau", tau)
    assert res.returncode == 2
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and "a 3-D chain" in lines[0] and "--scene" in lines[0]
