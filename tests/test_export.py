"""``snakecg export``: the C library compiles with ``cc -std=c99 -Wall`` and computes what the
runtime computes.

References: the dense NumPy mass matrix of tests/reference.py and the runtime's forward
solve (``SceneModel.forward``) at a torque where every row holds; the header's sizes against
the manifest.
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess

import numpy as np
import pytest
from reference import Reference

import snakecg
from snakecg.casadi_api import parameter_names
from snakecg.cli import main
from snakecg.export import export_library

CC = shutil.which("cc") or shutil.which("gcc")
pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler (cc) on this machine")
FLAGS = ["-O1", "-std=c99", "-Wall"]


def _write_robot(path, robot, scenario):
    def arr(v):
        return "[" + ", ".join(repr(float(x)) for x in v) + "]"

    path.write_text(
        f'[robot]\nname = "exported"\njoints = {robot.joints}\nmass = {arr(robot.mass)}\n'
        f"length = {arr(robot.length)}\ninertia = {arr(robot.inertia)}\n"
        f"com = {arr(robot.com)}\n\n[scene]\nscenario = \"{scenario}\"\nkappa = 20.0\n"
        f"contact_link = 2\nside = \"right\"\n")


def _run_example(folder, q, tau):
    argv = [str(folder / "example")] + [",".join(repr(float(x)) for x in v) for v in (q, tau)]
    out = subprocess.run(argv, capture_output=True, text=True, check=True)
    return {line.split()[0]: np.array([float(x) for x in line.split()[1:]])
            for line in out.stdout.splitlines()}


def _own_warnings(stderr: str) -> list[str]:
    """Compiler diagnostics about the files written by the export itself (not CasADi's C)."""
    return [ln for ln in stderr.splitlines()
            if re.match(r"^(main\.c|robot_params\.[ch]|snakecg_na\d+\.[ch]):\d+", ln)]


def test_exported_library_builds_with_make_and_matches_the_runtime(tmp_path, rng, random_robot):
    robot = random_robot(2)
    toml = tmp_path / "robot.toml"
    _write_robot(toml, robot, "ideal_wheels")
    out = tmp_path / "lib"
    assert main(["export", "--robot", str(toml), "--out", str(out)]) == 0
    assert not list(out.rglob("*.tmp")) and not list(out.rglob(".*"))
    if shutil.which("make") is None:
        pytest.skip("make is not installed")
    res = subprocess.run(["make", "-C", str(out), f"CC={CC}", "CFLAGS=" + " ".join(FLAGS)],
                         capture_output=True, text=True, check=False)
    assert res.returncode == 0, res.stderr[-3000:]
    assert _own_warnings(res.stderr) == []
    scene = snakecg.Scene.from_toml(toml)
    model = snakecg.load(scene)
    ref = Reference(scene)
    for _ in range(2):
        q = rng.uniform(-1, 1, robot.n_coordinates)
        tau = rng.normal(scale=0.05, size=robot.joints)
        got = _run_example(out, q, tau)
        if got["active_set_valid"][0] != 1:  # at rest lam is linear in tau: the other sign
            tau = -tau                        # keeps the contact (ideal wheels never slide)
            got = _run_example(out, q, tau)
        assert got["active_set_valid"][0] == 1
        ns = robot.n_coordinates
        M = got["M"].reshape(ns, ns, order="F")
        np.testing.assert_allclose(M, model.mass_matrix(q), rtol=1e-13, atol=1e-15)
        np.testing.assert_allclose(M, ref.mass_matrix(q), rtol=1e-9, atol=1e-12)
        fw = model.forward(q, tau)
        assert fw.contact and set(fw.wheel_state) <= {"stick", "none"}
        for k in ("qdd", "a_obj", "lam", "w"):
            scale = max(1.0, np.abs(getattr(fw, k)).max())
            np.testing.assert_allclose(got[k], getattr(fw, k), rtol=0, atol=1e-11 * scale)
        assert got["sr"][0] == pytest.approx(float(fw.sr), rel=1e-11)
        q_obj, _, P = model.place_object(q)
        np.testing.assert_allclose(got["q_obj"], q_obj, atol=1e-14)
        np.testing.assert_allclose(got["contact_point"], P, atol=1e-14)


def test_header_sizes_and_baked_parameters_follow_the_manifest(tmp_path, random_robot):
    robot = random_robot(1)
    scene = snakecg.Scene(robot, scenario="wheels", mu=0.3)
    model = snakecg.load(scene)
    files = export_library(scene, tmp_path / "x", source="test")
    header = (tmp_path / "x" / "snakecg_na1.h").read_text()
    defines = dict(re.findall(r"^#define (\w+) (\S+)$", header, re.MULTILINE))
    man = model.manifest
    assert int(defines["SNAKECG_NA1_N_PARAMETERS"]) == man["n_parameters"]
    assert int(defines["SNAKECG_NA1_N_COORDINATES"]) == robot.n_coordinates
    for sig in man["functions"]:
        up = sig["symbol"].upper()
        for k, i in enumerate(sig["inputs"]):
            assert int(defines[f"{up}_IN_{i['name'].upper()}"]) == k
            assert int(defines[f"{up}_SIZE_IN_{i['name'].upper()}"]) == i["rows"] * i["cols"]
        for k, o in enumerate(sig["outputs"]):
            assert int(defines[f"{up}_SIZE_OUT_{o['name'].upper()}"]) == o["rows"] * o["cols"]
        assert f"int {sig['symbol']}_eval(" in header
    for k, name in enumerate(parameter_names(1)):
        assert int(defines[f"SNAKECG_NA1_K_{name.upper()}"]) == k
    params = (tmp_path / "x" / "robot_params.c").read_text()
    body = params.split("robot_K[")[1].split("};")[0]
    K = [float(x) for x in re.findall(r"^\s*([-+0-9.eE]+),? /\*", body, re.MULTILINE)]
    assert K == model.parameters.tolist()  # exact: repr round-trips
    bound = re.search(r"scene_wheel_bound\[\d+\] = \{([^}]*)\}", params).group(1)
    # row 0 the contact; the contact link carries no wheel (assumption 4): no bound on it
    want = [math.inf] + [0.0 if i == scene.contact_link else 0.3 * m * scene.gravity
                         for i, m in enumerate(robot.mass, start=1)]
    got = [math.inf if x.strip() == "INFINITY" else float(x) for x in bound.split(",")]
    assert got == pytest.approx(want, rel=1e-15)
    # compiles standalone with one cc call, -std=c99 -Wall, no warnings in the wrapper code
    srcs = [str(f) for f in files if f.suffix == ".c"]
    exe = tmp_path / "example"
    res = subprocess.run([CC, *FLAGS, "-I", str(tmp_path / "x"), *srcs, "-o", str(exe), "-lm"],
                         capture_output=True, text=True, cwd=tmp_path / "x", check=False)
    assert res.returncode == 0, res.stderr[-3000:]
    assert _own_warnings(res.stderr) == []
    got = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout
    M = np.array([float(x) for x in got.splitlines()[0].split()[1:]]).reshape(4, 4, order="F")
    q0 = np.array([0.0, 0.0, 0.0, np.radians(30)])  # the example's default configuration
    np.testing.assert_allclose(M, model.mass_matrix(q0), rtol=1e-13, atol=1e-15)


def test_export_refuses_a_file_as_folder(tmp_path, capsys):
    f = tmp_path / "file"
    f.write_text("x")
    assert main(["export", "--joints", "1", "--out", str(f)]) == 2
    err = capsys.readouterr().err
    assert "is not a directory" in err and len(err.strip().splitlines()) == 1


def test_export_refuses_an_empty_folder_name(tmp_path, capsys, monkeypatch):
    """``--out ''`` wrote every file into the working directory; the docs say it is refused
    (the API too)."""
    from snakecg.export import export_library

    monkeypatch.chdir(tmp_path)
    for value in ("", "  "):
        with pytest.raises(SystemExit) as info:  # refused by the parser
            main(["export", "--joints", "1", "--out", value])
        assert info.value.code == 2
        err = capsys.readouterr().err
        assert "argument --out: empty value" in err and len(err.splitlines()) == 1
    for value, words in (("", "out must name a folder"), (None, "out must be a folder path"),
                         (3, "out must be a folder path")):
        with pytest.raises(snakecg.InputError, match=words):
            export_library(snakecg.Scene(snakecg.Robot(joints=1)), value)
    assert list(tmp_path.iterdir()) == []


def test_the_build_hint_is_shell_quoted(tmp_path, capsys):
    """The printed ``make -C DIR`` hint, read back by a POSIX shell's rules (shlex), names the
    folder exactly, whatever characters it holds."""
    import shlex

    out = tmp_path / "my snake $(touch pwned) 'x'"
    assert main(["export", "--joints", "1", "--out", str(out)]) == 0
    hint = capsys.readouterr().out.splitlines()[-1]
    words = shlex.split(hint)
    assert words[:3] == ["build:", "make", "-C"] and words[3] == str(out)
    assert words[4:] == ["run:", str(out / "example")]
