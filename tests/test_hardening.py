"""Hardening: bad values refused at the boundary before any work, strict JSON, robot files
that are not regular files, empty option values, atomic writes, bounded memory.

Each fault class of docs/explanation/reliability.md ("Bad input", "Output", "Files written",
"Memory") has its cases here; the fuzz tests (tests/test_cli_fuzz.py) add random combinations over
every sub-command and option.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import snakecg
import snakecg.artifacts
import snakecg.robot_model
from snakecg import InputError, Robot, Scene, cli

ROOT = Path(__file__).resolve().parent.parent


def run_cli(argv) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = cli.main(list(argv))
        except SystemExit as exc:
            code = exc.code
    return code, out.getvalue(), err.getvalue()


def refused(argv, *fragments, prefix=None):
    """Run the CLI; assert exit 2, one line on stderr naming ``fragments``, no stdout."""
    code, out, err = run_cli(argv)
    assert code == 2, (argv, code, err)
    assert "Traceback" not in err and out == "", (out, err)
    lines = err.splitlines()
    assert len(lines) == 1, err
    prefix = prefix or f"snakecg {argv[0]}: error: "
    assert lines[0].startswith(prefix), lines[0]
    for frag in fragments:
        assert frag in lines[0], (frag, lines[0])
    return lines[0]


def strict_loads(text: str):
    """json.loads that fails on NaN, Infinity and -Infinity (RFC 8259)."""
    def bad(name):
        raise ValueError(f"non-standard JSON constant {name}")
    return json.loads(text, parse_constant=bad)


@pytest.fixture
def no_model(monkeypatch):
    """Fail the test if anything generates, renders or loads a model (the input must be
    refused before)."""

    def boom(*args, **kwargs):
        raise AssertionError("a model was loaded before the bad input was refused")

    monkeypatch.setattr(snakecg.robot_model, "_backend", boom)
    monkeypatch.setattr(snakecg.artifacts, "model_dir", boom)
    import snakecg_derive.render as render

    monkeypatch.setattr(render, "render_model", boom)


# ------------------------------------------------------------------------------------------
# integers beyond float range, complex numbers, wrong types: InputError, never a traceback
def test_integers_beyond_float_range():
    with pytest.raises(InputError, match=r"mass must be positive finite, got 1000.*\(401 "
                                         r"characters\)"):
        Robot(joints=2, mass=10**400)
    with pytest.raises(InputError, match=r"kappa must be finite, got 1000"):
        Scene(Robot(joints=2), kappa=10**400)
    with pytest.raises(InputError, match=r"joints=1000.* exceeds the generation limit"):
        Robot(joints=10**400)
    with pytest.raises(InputError, match=r"\(link 3\)"):
        Robot(joints=2, length=[0.1, 0.1, 10**400])


def test_robot_file_with_a_400_digit_mass(tmp_path, no_model):
    path = tmp_path / "robot.toml"
    path.write_text("[robot]\njoints = 2\nmass = 1" + "0" * 400 + "\n")
    with pytest.raises(InputError, match="mass must be positive finite"):
        Robot.from_toml(path)
    line = refused(["forward", "--robot", str(path), "--q=0,0,0,0,0", "--tau=0,0"],
                   "mass must be positive finite", "(401 characters)")
    assert len(line) < 400  # the value is cut, not printed in full


def test_wrong_types_at_the_python_boundary(tmp_path):
    with pytest.raises(InputError, match="path must be the path of a robot description"):
        Scene.from_toml(None)
    with pytest.raises(InputError, match="path must be the path"):
        Robot.from_toml(3)
    with pytest.raises(InputError, match=r"unknown keyword overrides \['colour'\]"):
        Scene.from_toml(ROOT / "examples" / "robot.toml", colour="red")
    with pytest.raises(InputError, match=r"Scene.replace: unknown fields \['kapa'\]"):
        Scene(Robot(joints=2)).replace(kapa=3)
    with pytest.raises(InputError, match="backend must be 'compiled' or 'casadi', got 'x'"):
        snakecg.load(Robot(joints=2), backend="x")
    with pytest.raises(InputError, match="progress must be None, False or a callable"):
        snakecg.load(Robot(joints=2), progress=3)


def test_complex_arrays_are_refused_not_truncated():
    scene = Scene(Robot(joints=2), scenario="wheels")
    model = snakecg.load(scene)
    q = np.zeros(5, dtype=complex)
    q[3] = 0.5 + 1e-3j
    with pytest.raises(InputError, match="q must be real, got a complex array"):
        model.mass_matrix(q)
    with pytest.raises(InputError, match="tau must be real"):
        model.forward(np.zeros(5), np.array([0.1 + 1j, 0.0]))
    with pytest.raises(InputError, match="direction must be real"):
        model.optimize(np.zeros(5), "strongest_push", direction=np.array([0, 1 + 1j]))
    with pytest.raises(InputError, match="q0 must be real"):
        model.simulate(q, [0.0, 0.0], 0.01)
    # the real part alone is accepted, so the refusal is about the imaginary part
    assert model.mass_matrix(q.real).shape == (5, 5)


def test_finite_but_absurd_values_refused_with_the_limit():
    model = snakecg.load(Scene(Robot(joints=2), scenario="wheels"))
    q = [0, 0, 0, 0.5, -0.8]
    with pytest.raises(InputError, match=r"radius must be at most 1e\+100"):
        model.optimize(q, radius=1e308)
    with pytest.raises(InputError, match=r"a_min must be at most 1e\+100"):
        model.optimize(q, "least_slip_push", direction=[0, 1], a_min=1e308)
    with pytest.raises(InputError, match=r"output_dt = 4.94066e-324 s gives inf output "
                                         r"samples over 0.5 s, above the limit of 1e\+06"):
        model.simulate(q, [0.0, 0.0], 0.5, output_dt=5e-324)
    with pytest.raises(InputError, match=r"gives 5e\+08 output samples"):
        model.simulate(q, [0.0, 0.0], 0.5, output_dt=1e-9)
    with pytest.raises(InputError, match=r"rtol must be from 2.22e-14"):
        model.simulate(q, [0.0, 0.0], 0.5, rtol=1e-20)
    with pytest.raises(InputError, match=r"refine must be at most 1000"):
        model.extremes(q, refine=10**6)
    with pytest.raises(InputError, match=r"extremes\(\) takes no keyword 'sample'"):
        model.extremes(q, sample=10)


def test_huge_push_direction_gives_the_same_push_as_the_unit_one():
    """``--direction 1e200,1e200`` once read as d = (0, 0, 0) ("infeasible"); only the
    direction matters, so it must give exactly what (1, 1) gives."""
    model = snakecg.load(Scene(Robot(joints=3), scenario="ideal_wheels"))
    q = [0, 0, 0, math.radians(30), math.radians(-45), math.radians(60)]
    huge = model.optimize(q, "strongest_push", direction=[1e200, 1e200], tau_max=0.3)
    unit = model.optimize(q, "strongest_push", direction=[1, 1], tau_max=0.3)
    assert huge.status == unit.status == "optimal"
    assert huge.objective_value == pytest.approx(unit.objective_value, rel=1e-9)
    # d . a_obj with d = (1, 1, 0)/sqrt(2), recomputed from the forward analysis
    a = huge.analysis.a_obj
    assert huge.objective_value == pytest.approx((a[0] + a[1]) / math.sqrt(2), rel=1e-9)
    assert huge.objective_value > 0


# ------------------------------------------------------------------------------------------
# the command line: the cases of the issue, each refused up front in one line
Q2 = "--q=0,0,0,0.5,-0.8"
Q3 = "--q=0,0,0,30deg,-45deg,60deg"

CITED = [
    (["optimize", "max-sr", "--joints", "3", Q3, "--scenario", "wheels", "--allow-slide=nan"],
     "--allow-slide takes link numbers 1..4"),
    (["optimize", "max-sr", "--joints", "3", Q3, "--scenario", "wheels", "--allow-slide=inf"],
     "--allow-slide takes link numbers"),
    (["optimize", "max-sr", "--joints", "3", Q3, "--scenario", "wheels",
      "--allow-slide=1e400"], "--allow-slide takes link numbers"),
    (["optimize", "max-sr", "--joints", "3", Q3, "--radius=1e308"],
     "argument --radius: must be <= 1e+100 (the limit)"),
    (["optimize", "max-sr", "--joints", "3", Q3, "--radius=nan"],
     "argument --radius: expected a finite number"),
    (["optimize", "least-slip-push", "--joints", "3", Q3, "--direction", "0,1",
      "--a-min=1e308"], "argument --a-min: must be <= 1e+100 (m/s^2) (the limit)"),
    (["simulate", "--joints", "2", Q2, "--tau=0.05,-0.02", "--output-dt=5e-324"],
     "--output-dt = 4.94066e-324 s gives inf output samples over 0.5 s, above the limit"),
    (["simulate", "--joints", "2", Q2, "--tau=0.05,-0.02", "--output-dt=1e-9"],
     "gives 5e+08 output samples over 0.5 s, above the limit of 1e+06"),
    (["simulate", "--joints", "2", Q2, "--tau=0.05,-0.02", "--frames=1000000000"],
     "argument --frames: must be at most 2000"),
    (["reproduce", "--torque-grid=100000000"], "argument --torque-grid: must be at most 1001"),
    (["reproduce", "--kappa", "nan"], "argument --kappa: expected a finite number"),
    (["forward", "--joints", "10", "--q", "0,0,0,0,0", "--tau", "0,0"],
     "q has shape (5,), expected (13,)"),
    (["forward", "--robot", "", "--q=0", "--tau=0"], "argument --robot: empty value"),
    (["forward", "--joints", "2", Q2, "--tau=0,0", "--v", ""], "argument --v: empty value"),
    (["generate", "--joints", "1", "--out", ""], "argument --out: empty value"),
    (["simulate", "--joints", "2", Q2, "--tau=0,0", "--out", ""], "argument --out: empty value"),
    (["reproduce", "--out", ""], "argument --out: empty value"),
    (["optimize", "strongest-push", "--joints", "2", Q2, "--direction", ""],
     "argument --direction: empty value"),
]


@pytest.mark.parametrize("argv, fragment", CITED, ids=[" ".join(c[0][:1] + c[0][-1:])
                                                        for c in CITED])
def test_cited_cases_refused_before_any_work(argv, fragment, no_model, tmp_path,
                                             monkeypatch):
    monkeypatch.chdir(tmp_path)
    t0 = time.perf_counter()
    refused(argv, fragment)
    assert time.perf_counter() - t0 < 5.0
    assert list(tmp_path.iterdir()) == []  # nothing written (no output folder either)


def test_reproduce_bad_kappa_computes_and_writes_nothing(tmp_path, monkeypatch):
    import snakecg.reproduce as rep

    monkeypatch.setattr(rep, "case_study_1", lambda *a: pytest.fail("computed before refusing"))
    out = tmp_path / "out"
    refused(["reproduce", "--kappa", "nan", "--out", str(out)], "--kappa")
    refused(["reproduce", "--kappa", "-1", "--out", str(out)], "--kappa: must be > 0")
    assert not out.exists()
    with pytest.raises(InputError, match="kappa_case2 must be > 0"):
        rep.reproduce(rep.ReproduceOptions(out=out, kappa_case2=-1.0))
    assert not out.exists()


def test_out_that_is_a_file_refused_before_work(tmp_path, no_model):
    f = tmp_path / "file"
    f.write_text("keep")
    refused(["simulate", "--joints", "2", Q2, "--tau=0,0", "--out", str(f)],
            "exists and is not a directory")
    refused(["reproduce", "--out", str(f / "sub")], "is not a directory")
    assert f.read_text() == "keep"


def test_option_combinations_checked_before_loading(no_model):
    refused(["simulate", "--joints", "2", Q2, "--tau=0,0", "--a-min", "1"],
            "--a-min applies to --controller least-slip-push only")
    refused(["simulate", "--joints", "2", Q2, "--tau=0,0", "--controller", "least-slip-push",
             "--a-min", "1"], "give either --tau or --controller, not both")
    refused(["optimize", "max-sr", "--joints", "2", Q2, "--a-min", "1"],
            "--a-min do(es) not apply to max-sr")
    refused(["optimize", "least-slip-push", "--joints", "2", Q2], "needs a task")
    refused(["optimize", "max-sr", "--joints", "2", Q2, "--tau-max", "0.1,0.1,1"],
            "tau_max has shape (3,)")


# ------------------------------------------------------------------------------------------
# negative numbers in list options
def test_negative_values_after_a_space(capsys):
    base = ["forward", "--joints", "2", "--scenario", "wheels", "--json"]
    code, a, err = run_cli(base + ["--q", "-0.1,0,0,-135deg,-135deg", "--tau", "-0.1,0"])
    assert code == 0, err
    code, b, _ = run_cli(base + ["--q=-0.1,0,0,-135deg,-135deg", "--tau=-0.1,0"])
    assert code == 0 and strict_loads(a)["qdd"] == strict_loads(b)["qdd"]
    assert strict_loads(a)["tau"] == [-0.1, 0.0] and strict_loads(a)["q"][0] == -0.1
    code, c, err = run_cli(["optimize", "strongest-push", "--joints", "2", "--scenario",
                            "ideal_wheels", "--q", "-1,0,0,0.5,-0.8", "--direction", "-1,0",
                            "--tau-max", "0.2", "--json"])
    assert code in (0, 1) and strict_loads(c)["task"]["direction"] == [-1.0, 0.0], err
    # a negative value that is an option error stays one: -inf is refused as a value
    refused(["optimize", "least-slip-push", "--joints", "2", "--q", "-1,0,0,0,0",
             "--direction", "0,1", "--a-min", "-inf"], "argument --a-min")


# ------------------------------------------------------------------------------------------
# strict JSON
def test_forward_json_overflow_is_refused_and_nonfinite_values_are_null_with_a_flag(capsys):
    # a torque whose norms would overflow is refused up front (one line, exit 2, no JSON)
    code, out, err = run_cli(["forward", "--joints", "2", "--q", "0,0,0,0.5,-0.8",
                              "--tau=1e200,0", "--scenario", "wheels", "--json"])
    assert code == 2 and out == "" and len(err.splitlines()) == 1 and "tau" in err
    # whatever non-finite number reaches the JSON writer is printed as null and listed
    from snakecg.commands._common import print_json

    found = print_json({"norm_qdd": float("inf"), "lam": [1.0, float("nan")], "ok": 2.0})
    data = strict_loads(capsys.readouterr().out)  # NaN/Infinity would raise
    assert sorted(found) == ["lam[1]", "norm_qdd"] == sorted(data["nonfinite"])
    assert data["norm_qdd"] is None and data["lam"] == [1.0, None] and data["ok"] == 2.0
    # a finite result has the flag set and no list
    code, out, _ = run_cli(["forward", "--joints", "2", "--q", "0,0,0,0.5,-0.8",
                            "--tau=0.1,0", "--scenario", "wheels", "--json"])
    data = strict_loads(out)
    assert code == 0 and data["finite"] is True and "nonfinite" not in data


def test_every_json_output_is_strict(tmp_path):
    cases = [
        ["forward", "--joints", "1", "--q=0,0,0,0.3", "--tau=0.05", "--json"],
        ["optimize", "max-sr", "--joints", "2", "--q=0,0,0,-135deg,-135deg", "--scenario",
         "wheels", "--json"],
        ["optimize", "least-slip-push", "--joints", "2", "--q=0,0,0,-135deg,-135deg",
         "--direction", "0,1", "--a-min", "1e90", "--tau-max", "0.1", "--json"],
        ["simulate", "--joints", "1", "--q=0,0,0,0.3", "--tau=0.01", "--duration", "0.02",
         "--no-figures", "--out", str(tmp_path / "sim"), "--json"],
        ["generate", "--joints", "1", "--out", str(tmp_path / "gen"), "--json"],
        ["show", "--joints", "1", "M", "--json"],
    ]
    for argv in cases:
        code, out, err = run_cli(argv)
        assert code in (0, 1), (argv, err)
        data = strict_loads(out)
        assert isinstance(data, dict) and data.get("schema", "").startswith("snakecg."), argv
    summary = strict_loads((tmp_path / "sim" / "summary.json").read_text())
    assert summary["schema"] == "snakecg.simulate/1"


def test_reproduce_json_schema(tmp_path, monkeypatch):
    """The summary as strict JSON (the study itself is replaced by a stand-in whose report
    holds a non-finite timing; tests/test_reproduce.py runs the real one)."""
    import snakecg.reproduce as rep

    def fake(opts, echo=print, load=None):
        echo("table 2 ...")
        r = rep.ReproduceReport(table2={k: (1.0, 2.0, math.nan) for k in rep.PAPER_TABLE2},
                                files=[opts.out / "table2.md"], timings={"total": math.inf})
        return r

    monkeypatch.setattr(rep, "reproduce", fake)
    code, out, err = run_cli(["reproduce", "--out", str(tmp_path), "--json"])
    assert code == 0 and "table 2" in err  # the human-readable report goes to stderr
    data = strict_loads(out)
    assert data["schema"] == "snakecg.reproduce/1"
    assert data["paper_table2"]["best_sr"] == list(rep.PAPER_TABLE2["best_sr"])
    assert data["table2"]["best_sr"] == [1.0, 2.0, None]
    assert data["timings_s"]["total"] is None
    assert "table2.best_sr[2]" in data["nonfinite"] and "timings_s.total" in data["nonfinite"]
    assert data["options"] == {"kappa": 100.0, "torque_grid": 181,
                               "formats": ["png", "svg"], "alternatives": False}
    # every field is documented in docs/reference/cli.md (nonfinite is the common convention)
    text = (ROOT / "docs" / "reference" / "cli.md").read_text(encoding="utf-8")
    section = text[text.index("### `snakecg reproduce --json`"):]
    section = section[:section.index("\n## ") if "\n## " in section else None]
    import re

    documented = set(re.findall(r"^\| `([a-z_0-9]+)` \|", section, re.MULTILINE))
    assert set(data) - {"nonfinite"} == documented


# ------------------------------------------------------------------------------------------
# robot files
def test_devices_fifos_and_large_files_refused_without_reading(tmp_path, no_model):
    with pytest.raises(InputError, match="'/dev/zero' is a device"):
        Robot.from_toml("/dev/zero")
    fifo = tmp_path / "robot.fifo"
    os.mkfifo(fifo)
    result = {}

    def read():
        try:
            Scene.from_toml(fifo)
        except InputError as exc:
            result["error"] = str(exc)

    t = threading.Thread(target=read, daemon=True)
    t.start()
    t.join(10)
    if t.is_alive():  # unblock the reader before failing
        with open(fifo, "w"):
            pass
        pytest.fail("reading a FIFO blocked")
    assert "is a FIFO; expected a regular TOML file" in result["error"]
    big = tmp_path / "big.toml"
    big.write_text("[robot]\njoints = 2\n" + "# padding\n" * 120_000)
    with pytest.raises(InputError, match=r"has 1200019 bytes, above the limit of 1048576"):
        Robot.from_toml(big)
    refused(["forward", "--robot", "/dev/zero", "--q=0,0,0,0,0", "--tau=0,0"], "is a device")


def test_utf8_bom_accepted(tmp_path):
    text = "[robot]\njoints = 2\nmass = [1.0, 2.0, 3.0]\n[scene]\nkappa = 7\n"
    plain, bom = tmp_path / "plain.toml", tmp_path / "bom.toml"
    plain.write_text(text, encoding="utf-8")
    bom.write_bytes(b"\xef\xbb\xbf" + text.encode())
    assert Scene.from_toml(bom) == Scene.from_toml(plain)
    assert Scene.from_toml(bom).robot.mass == (1.0, 2.0, 3.0)
    assert Scene.from_toml(bom).kappa == 7.0


def test_error_lines_bounded(tmp_path):
    keys = 60_000
    path = tmp_path / "keys.toml"
    path.write_text("[robot]\njoints = 2\n" + "".join(f"k{i} = 1\n" for i in range(keys)))
    assert path.stat().st_size < 1 << 20
    with pytest.raises(InputError) as info:
        Robot.from_toml(path)
    message = str(info.value)
    assert f"and {keys - 4} more" in message and len(message) < 600
    many = tmp_path / "many.toml"  # 31 links with a COM beyond the length: 31 problems
    many.write_text("[robot]\njoints = 30\nlength = 0.1\ncom = 0.5\n")
    with pytest.raises(InputError) as info:
        Robot.from_toml(many)
    message = str(info.value)
    assert message.count("beyond its length") == 20 and "; and 11 more problems" in message
    line = refused(["forward", "--robot", str(path), "--q=0,0,0,0,0", "--tau=0,0"],
                   f"and {keys - 4} more")
    assert len(line) < 700


# ------------------------------------------------------------------------------------------
# atomic writes with unique temporary names
def _writer(args):
    folder, tag, rounds = args
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from snakecg.figures import write_figure
    from snakecg.reproduce import ReproduceReport, _write_text

    report = ReproduceReport()
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, int(tag)])
    for i in range(rounds):
        _write_text(Path(folder) / "table2.md", f"run {tag} round {i}\n" * 200, report)
        report.files += write_figure(fig, Path(folder) / "fig", ("png", "svg"))
    return len(report.files)


def test_two_writers_into_one_folder_both_succeed(tmp_path):
    """reproduce's writers once shared a fixed `.name.tmp`: two runs into one folder failed.
    Two processes now write the same files 15 times each: no error, every final file whole,
    no temporary file left."""
    import multiprocessing as mp

    with mp.get_context("spawn").Pool(2) as pool:
        counts = pool.map(_writer, [(str(tmp_path), "1", 15), (str(tmp_path), "2", 15)])
    assert counts == [45, 45]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig.png", "fig.svg", "table2.md"]
    text = (tmp_path / "table2.md").read_text()
    assert len(set(text.splitlines())) == 1 and len(text.splitlines()) == 200
    from PIL import Image

    with Image.open(tmp_path / "fig.png") as im:
        im.load()
    assert (tmp_path / "fig.svg").read_text().rstrip().endswith("</svg>")


def test_failed_write_keeps_the_old_file_and_leaves_no_temporary(tmp_path):
    from snakecg._files import atomic_path, write_text

    target = tmp_path / "summary.json"
    write_text(target, "old\n")
    with pytest.raises(RuntimeError), atomic_path(target) as tmp:
        tmp.write_text("half")
        raise RuntimeError("disk full")
    assert target.read_text() == "old\n" and [p.name for p in tmp_path.iterdir()] == [
        "summary.json"]
    assert (target.stat().st_mode & 0o777) == (0o666 & ~_umask())


def _umask():
    m = os.umask(0o022)
    os.umask(m)
    return m


def test_two_simulations_into_one_folder(tmp_path):
    out = tmp_path / "sim"
    argv = [sys.executable, "-m", "snakecg.cli", "simulate", "--joints", "1",
            "--q=0,0,0,0.3", "--tau=0.01", "--duration", "0.05", "--frames", "4",
            "--out", str(out), "--json", "--geometry-check", "off"]
    procs = [subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              cwd=tmp_path) for _ in range(2)]
    results = [p.communicate(timeout=600) for p in procs]
    for p, (o, e) in zip(procs, results):
        assert p.returncode == 0, e
        assert strict_loads(o)["status"] == "completed (geometry not checked)"
    names = sorted(p.name for p in out.iterdir())
    assert names == ["animation.gif", "displacement.png", "energy.png", "forces.png",
                     "slippage.png", "summary.json", "trajectory.npz"]
    data = np.load(out / "trajectory.npz")
    assert data["t"][-1] == pytest.approx(0.05)
    strict_loads((out / "summary.json").read_text())


# ------------------------------------------------------------------------------------------
# bounded memory: large batches in chunks, or refused with the memory needed
def test_forward_in_chunks_equals_one_call(monkeypatch, rng):
    """The reference path (the CasADi backend, and the samples the compiled core marks) works
    in chunks of CHUNK_ROWS rows; chunks give the same answers as the compiled core's one
    call. The compiled core also splits a batch over threads (PARALLEL_MIN rows each)."""
    import snakecg.forward as forward_mod

    scene = Scene(Robot(joints=2), scenario="wheels")
    model = snakecg.load(scene)
    n = 53
    q = np.column_stack([np.zeros((n, 3)), rng.uniform(-2.5, 2.5, (n, 2))])
    tau = rng.uniform(-0.2, 0.2, (n, 2))
    whole = model.forward(q, tau)
    monkeypatch.setattr(forward_mod, "CHUNK_ROWS", 7)
    monkeypatch.setattr(forward_mod, "PARALLEL_MIN", 5)
    monkeypatch.setenv("SNAKECG_THREADS", "3")
    threaded = model.forward(q, tau)
    np.testing.assert_array_equal(threaded.raw, whole.raw)
    chunked = snakecg.load(scene, backend="casadi").forward(q, tau)
    for k in ("qdd", "a_obj", "lam", "w", "norm_lambda", "norm_a_obj", "norm_qdd", "sr",
              "conditioning", "tau"):
        np.testing.assert_allclose(getattr(chunked, k), getattr(whole, k), rtol=1e-12,
                                   atol=1e-14, err_msg=k)
    np.testing.assert_array_equal(chunked.wheel_state, whole.wheel_state)
    np.testing.assert_array_equal(chunked.contact, whole.contact)
    # one sample broadcast against a chunked batch
    one = model.forward(q[0], tau)
    np.testing.assert_allclose(one.qdd[5], model.forward(q[0], tau[5]).qdd, rtol=1e-12,
                               atol=1e-14)


def test_extremes_in_chunks_equal_one_call(monkeypatch, rng):
    import snakecg.model as model_mod

    model = snakecg.load(Scene(Robot(joints=2), scenario="frictionless"))
    q = np.column_stack([np.zeros((12, 3)), rng.uniform(-2.5, 2.5, (12, 2))])
    whole = model.extremes(q)
    monkeypatch.setattr(model_mod, "CLOSED_FORM_CHUNK_ROWS", 5)
    chunked = model.extremes(q)
    for attr in ("max", "min", "tau_max", "tau_min"):
        for k, v in getattr(whole, attr).items():
            np.testing.assert_allclose(getattr(chunked, attr)[k], v, rtol=1e-12, atol=1e-15)


def test_too_large_a_batch_refused_with_the_memory_needed(monkeypatch):
    model = snakecg.load(Scene(Robot(joints=2)))
    monkeypatch.setenv("SNAKECG_MAX_MEMORY", "16M")
    q = np.zeros((200_000, 5))
    with pytest.raises(InputError, match=r"forward: a batch of 200000 rows needs about "
                                         r"0\.0\d+ GB .* split it into batches of at most "
                                         r"\d+ rows"):
        model.forward(q, [0.1, 0.0])
    monkeypatch.setenv("SNAKECG_MAX_MEMORY", "lots")
    with pytest.raises(InputError, match="SNAKECG_MAX_MEMORY must be a positive size"):
        model.forward(q, [0.1, 0.0])


def test_large_forward_batch_peak_memory_is_bounded(monkeypatch):
    """400 000 rows: the peak allocation stays within the results (~270 B a row) plus one
    chunk's working memory, instead of growing with the whole batch's solver state."""
    import tracemalloc

    model = snakecg.load(Scene(Robot(joints=2), scenario="wheels"))
    n = 400_000
    q = np.zeros((n, 5))
    q[:, 3], q[:, 4] = 0.5, -0.8
    tau = np.array([0.1, 0.0])
    model.forward(q[:10], tau)  # warm up
    tracemalloc.start()
    res = model.forward(q, tau)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    result_bytes = res.raw.nbytes
    assert peak < result_bytes + 150 * 2**20, (peak / 2**20, result_bytes / 2**20)
    assert np.allclose(res.qdd, res.qdd[0])  # every row the same configuration


# ------------------------------------------------------------------------------------------
# the Python API: every public function and argument against a list of bad values
BAD_VALUES = [None, "x", "", 10**400, -10**400, math.nan, math.inf, 1e308, 1 + 2j,
              np.complex128(1 + 1j), [1, 2], [[1]], {}, True, object(),
              np.array([1 + 1j] * 5), [10**400] * 5, np.zeros((0, 5)), np.zeros((2, 2, 5)),
              -1, 0, 2.5]


def _api_calls(sc, m, rm):
    q, tau = np.zeros(5), np.zeros(2)
    calls = {
        "Robot(joints)": lambda b: Robot(joints=b),
        "Robot(mass)": lambda b: Robot(joints=2, mass=b),
        "Robot(com)": lambda b: Robot(joints=2, com=b),
        "Robot(name)": lambda b: Robot(joints=2, name=b),
        "Scene(robot)": lambda b: Scene(b),
        "Scene.from_toml": lambda b: Scene.from_toml(b),
        "Robot.from_toml": lambda b: Robot.from_toml(b),
        "Scene.replace": lambda b: sc.replace(kappa=b),
        "load": lambda b: snakecg.load(b),
        "load(backend)": lambda b: snakecg.load(sc, backend=b),
        "load(progress)": lambda b: snakecg.load(sc, progress=b),
        "mass_matrix": lambda b: rm.mass_matrix(b),
        "link_jacobians": lambda b: rm.link_jacobians(b),
        "link_poses": lambda b: rm.link_poses(b),
        "bias_forces(q)": lambda b: rm.bias_forces(b, q),
        "bias_forces(v)": lambda b: rm.bias_forces(q, b),
        "com": lambda b: rm.com(b),
        "place_object": lambda b: m.place_object(b),
        "forward(q)": lambda b: m.forward(b, tau),
        "forward(tau)": lambda b: m.forward(q, b),
        "maps(q)": lambda b: m.maps(b),
        "maps(contact)": lambda b: m.maps(q, contact=b),
        "maps(wheel_state)": lambda b: m.maps(q, wheel_state=b),
        "extremes(q)": lambda b: m.extremes(b),
        "com_polar": lambda b: m.com_polar(b),
        "optimize(q)": lambda b: m.optimize(b),
        "optimize(objective)": lambda b: m.optimize(q, b),
        "optimize(tau_max)": lambda b: m.optimize(q, tau_max=b),
        "optimize(radius)": lambda b: m.optimize(q, radius=b),
        "optimize(direction)": lambda b: m.optimize(q, "strongest_push", direction=b),
        "optimize(a_min)": lambda b: m.optimize(q, "least_slip_push", direction=[0, 1], a_min=b),
        "optimize(a_obj)": lambda b: m.optimize(q, "least_slip_push", a_obj=b),
        "optimize(allow_slide)": lambda b: m.optimize(q, allow_slide=b),
        "simulate(q0)": lambda b: m.simulate(b, tau, 0.01),
        "simulate(tau)": lambda b: m.simulate(q, b, 0.01),
        "simulate(duration)": lambda b: m.simulate(q, tau, b),
        "simulate(v0)": lambda b: m.simulate(q, tau, 0.01, v0=b),
    }
    for k in ("scenario", "kappa", "mu", "gravity", "contact_link", "contact_offset", "side",
              "object_distance", "object_inertia", "wheel_links", "wheel_offset"):
        calls[f"Scene({k})"] = (lambda k: lambda b: Scene(Robot(joints=2), **{k: b}))(k)
    for k in ("v", "v_obj", "f_obj", "max_iter"):
        calls[f"forward({k})"] = (lambda k: lambda b: m.forward(q, tau, **{k: b}))(k)
    for k in ("samples", "refine", "starts", "refined"):
        calls[f"extremes({k})"] = (lambda k: lambda b: m.extremes(q, **{k: b}))(k)
    for k in ("v_obj0", "f_obj", "control_period", "method", "rtol", "atol", "max_step",
              "fixed_step", "stabilization", "output_dt", "max_events"):
        calls[f"simulate({k})"] = (lambda k: lambda b: m.simulate(q, tau, 0.01, **{k: b}))(k)
    return calls


def test_public_functions_refuse_bad_values_with_input_error(tmp_path, monkeypatch):
    """Each public function and argument gets 22 bad values (None, text, integers beyond
    float range, NaN, infinity, 1e308, complex numbers and arrays, wrong shapes, booleans,
    other objects...): each call succeeds (a value that is valid there) or raises InputError;
    any other exception is a failure."""
    import signal

    monkeypatch.chdir(tmp_path)  # string values must not name files of the repository
    sc = Scene(Robot(joints=2), scenario="wheels")
    m, rm = snakecg.load(sc), snakecg.load(Robot(joints=2))
    calls = _api_calls(sc, m, rm)

    def slow(*args):
        raise TimeoutError("took more than 20 s")

    failures, refused_count, cases = [], 0, 0
    old = signal.signal(signal.SIGALRM, slow)
    try:
        for name, call in calls.items():
            for bad in BAD_VALUES:
                cases += 1
                signal.alarm(20)
                try:
                    call(bad)
                except InputError:
                    refused_count += 1
                except Exception as exc:  # noqa: BLE001 - what the test looks for
                    failures.append(f"{name} <- {bad!r:.40}: {type(exc).__name__}: {exc!s:.80}")
                finally:
                    signal.alarm(0)
    finally:
        signal.signal(signal.SIGALRM, old)
    assert cases == len(calls) * len(BAD_VALUES) and len(calls) >= 65
    assert not failures, f"{len(failures)} of {cases} cases:\n" + "\n".join(failures)
    assert refused_count > 0.8 * cases  # nearly all of them are bad everywhere


# ------------------------------------------------------------------------------------------
# a full disk: a small file system mounted for the test (root with mount rights only)
@pytest.fixture
def small_fs(tmp_path):
    mnt = tmp_path / "small"
    mnt.mkdir()
    try:
        proc = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=96k", "tmpfs", str(mnt)],
                              capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired) as exc:
        pytest.skip(f"cannot mount a small file system here: {exc}")
    if proc.returncode != 0:
        pytest.skip(f"cannot mount a small file system here: {proc.stderr.strip()}")
    try:
        yield mnt
    finally:
        subprocess.run(["umount", str(mnt)], capture_output=True, timeout=30)


def test_disk_full_is_a_clean_failure_without_partial_files(small_fs):
    out = small_fs / "run"
    code, stdout, err = run_cli(["simulate", "--joints", "2", "--q=0,0,0,0.5,-0.6",
                                 "--tau=0.05,-0.02", "--duration", "0.05", "--frames", "20",
                                 "--out", str(out), "--geometry-check", "report"])
    assert code == 1 and "Traceback" not in err, err
    (line,) = err.splitlines()
    assert line.startswith("snakecg simulate: failed: cannot write to --out") and \
        "No space left on device" in line, line
    # whatever was written is whole; no temporary file is left behind
    names = sorted(p.name for p in out.iterdir())
    assert not [n for n in names if ".tmp" in n], names
    if "summary.json" in names:
        strict_loads((out / "summary.json").read_text())
    if "trajectory.npz" in names:
        assert np.load(out / "trajectory.npz")["t"][-1] == pytest.approx(0.05)
    assert "animation.gif" not in names or (out / "animation.gif").stat().st_size > 0


def _nbytes(x) -> int:
    if isinstance(x, dict):
        return sum(_nbytes(v) for v in x.values())
    if isinstance(x, (tuple, list)):
        return sum(_nbytes(v) for v in x)
    return np.asarray(x).nbytes


BATCHED = {  # method: (call on a batch q, the arrays its rows produce: result or working)
    "mass_matrix": (lambda m, q: m.mass_matrix(q), lambda m, q: m.mass_matrix(q)),
    "link_jacobians": (lambda m, q: m.link_jacobians(q), lambda m, q: m.link_jacobians(q)),
    "link_poses": (lambda m, q: m.link_poses(q), lambda m, q: m.link_poses(q)),
    "bias_forces": (lambda m, q: m.bias_forces(q, q), lambda m, q: m.bias_forces(q, q)),
    "com": (lambda m, q: m.com(q), lambda m, q: m.link_poses(q)),
    "place_object": (lambda m, q: m.place_object(q), lambda m, q: m.place_object(q)),
    "maps": (lambda m, q: m.maps(q), lambda m, q: m.maps(q)),
    "com_polar": (lambda m, q: m.com_polar(q),
                  lambda m, q: (m.link_poses(q), m.place_object(q))),
    "optimize": (lambda m, q: m.optimize(q), lambda m, q: m.maps(q)),
}


@pytest.mark.parametrize("method", sorted(BATCHED))
def test_every_batched_method_estimates_its_memory_first(method, monkeypatch, rng):
    """Every batched method of the model refuses, before any evaluation, a batch whose
    arrays (measured here: the nbytes of what a small batch returns or holds, scaled) would
    exceed SNAKECG_MAX_MEMORY, with the method and the limit named; a batch a few times below
    the limit is evaluated. (549 MB came back against a 256 MB limit; maps and com_polar
    raised numpy's MemoryError.)"""
    model = snakecg.load(Scene(Robot(joints=2), scenario="wheels"))
    call, held = BATCHED[method]
    small = np.column_stack([np.zeros((8, 3)), rng.uniform(-1.0, 1.0, (8, 2))])
    per_row = _nbytes(held(model, small)) / len(small)
    limit = 4 << 20
    monkeypatch.setenv("SNAKECG_MAX_MEMORY", str(limit))
    big = int(1.05 * limit / per_row) + 1
    q = np.zeros((big, 5))
    q[:, 3:] = 0.3

    def boom(*a, **k):
        raise AssertionError("evaluated before the memory check")

    with monkeypatch.context() as mp:
        mp.setattr(model, "_named", boom)
        with pytest.raises(InputError, match=rf"{method}: a batch of {big} rows needs about "
                                             r".* above the limit of 0\.00391 GB"):
            call(model, q)
    ok = max(2, int(limit / (4 * per_row)))
    if method != "optimize":  # (a solve per row: the refusal above is what is tested)
        call(model, q[:ok])


def test_simulate_checks_its_inputs_as_forward_does():
    """The ranges forward refuses are refused by simulate too, before any work: torques and
    wrenches above 1e150, velocities above 1e75 (the norms would overflow float64; 1e151
    ran until killed), and a duration outside 1e-9..1e6 s (5e-324 divided by zero); a
    torque law that returns such a torque stops the run with a SimulationError."""
    from snakecg.simulate.records import SimulationError

    model = snakecg.load(Scene(Robot(joints=2)))
    q = [0.0, 0.0, 0.0, 0.3, 0.3]
    for kw, words in (({"tau": [1e151, 0.0]}, r"tau must have every entry within \+-1e\+150"),
                      ({"v0": [0, 0, 0, 1e76, 0]}, r"v must have every entry within \+-1e\+75"),
                      ({"v_obj0": [0, -1e80, 0]}, r"v_obj must have every entry within"),
                      ({"f_obj": [0, 0, 2e150]}, r"f_obj must have every entry within"),
                      ({"duration": 5e-324}, r"duration must be from 1e-09 to 1e\+06 s"),
                      ({"duration": 1e7}, r"duration must be from 1e-09 to 1e\+06 s")):
        args = {"tau": [0.01, 0.0], "duration": 0.01, **kw}
        with pytest.raises(InputError, match=words):
            model.simulate(q, args.pop("tau"), args.pop("duration"), **args)
    with pytest.raises(SimulationError, match=r"torques within \+-1e\+150 N m"):
        model.simulate(q, lambda t: [1e200, 0.0], 0.01)
    for argv, words in ((["--tau=1e151,0"], "tau must have every entry within"),
                        (["--tau=0.01,0", "--duration=5e-324"], "must be >= 1e-09 (s)"),
                        (["--tau=0.01,0", "--v=0,0,0,1e80,0"], "v must have every entry")):
        code, out, err = run_cli(["simulate", "--joints", "2", "--q=0,0,0,0.3,0.3", *argv])
        assert code == 2 and len(err.splitlines()) == 1 and words in err, err


def test_atomic_dir_moves_a_complete_folder_or_nothing(tmp_path):
    """snakecg._files.atomic_dir: the folder appears whole, or not at all after an error;
    a second writer that finishes later leaves the first complete folder in place."""
    from snakecg._files import atomic_dir

    dest = tmp_path / "sub" / "built"
    with pytest.raises(RuntimeError):
        with atomic_dir(dest) as work:
            (work / "a.txt").write_text("half")
            raise RuntimeError("interrupted")
    assert not dest.exists() and list((tmp_path / "sub").iterdir()) == []
    with atomic_dir(dest) as work:
        (work / "a.txt").write_text("first")
    with atomic_dir(dest) as work:
        (work / "a.txt").write_text("second")
    assert (dest / "a.txt").read_text() == "first"
    assert [p.name for p in (tmp_path / "sub").iterdir()] == ["built"]
