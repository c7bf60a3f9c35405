"""Fuzzing the command line and the robot description files (issue #7).

Hypothesis builds malformed robot description files by applying several faults at once to a
valid one (missing keys, wrong types, zero, negative and non-finite numbers, lists of the
wrong length, unknown keys and tables, huge joint counts, bad scene values...). Each fault
knows the words the message must contain; faults whose detection needs a valid joint count
or robot only expect their words when those are valid. Every file goes through
``Scene.from_toml`` and ``snakecg forward --robot FILE``: one InputError / one line on
standard error, exit status 2, every problem named, no traceback.

Argument lists are fuzzed the same way (bad numbers, vectors of the wrong length, NaN and
infinity, unknown options and choices, missing or contradictory options). A fixed set of
them also runs through a real ``python -m snakecg.cli`` process.

Every option of every sub-command, read from the argparse parsers themselves (a new option is
covered without editing this file), takes a list of hostile values (empty, ``--`` as
``--opt=--``, NaN, infinities, 1e308, 5e-324, huge integers, text, unicode, 5000 characters;
a longer list in the ``slow`` variant): exit status 0, 1 or 2 with one line, never a
traceback, strict JSON with ``--json``. The reported attacks are replayed one by one.

``SNAKECG_HYPOTHESIS_PROFILE=long`` runs many more examples (docs/explanation/reliability.md).
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, event, given, settings
from hypothesis import strategies as st

import snakecg
import snakecg.artifacts
import snakecg.robot_model
from snakecg import cli

_PHASES = [Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink]
settings.register_profile(
    "snakecg-fuzz-default", max_examples=150, deadline=None, derandomize=True, database=None,
    phases=_PHASES, suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile(
    "snakecg-fuzz-long", max_examples=3000, deadline=None, derandomize=False, phases=_PHASES,
    suppress_health_check=[HealthCheck.too_slow],
)
PROFILE = settings.get_profile(
    "snakecg-fuzz-long" if os.environ.get("SNAKECG_HYPOTHESIS_PROFILE") == "long"
    else "snakecg-fuzz-default")


@pytest.fixture(autouse=True, scope="module")
def _default_limit():
    """The fuzz expects the default generation limit (50 joints)."""
    mp = pytest.MonkeyPatch()
    mp.delenv("SNAKECG_MAX_JOINTS", raising=False)
    yield
    mp.undo()


@pytest.fixture(scope="module")
def workdir(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("fuzz")


def run_cli(argv) -> tuple[int, str, str]:
    """``snakecg`` in this process: exit status, stdout, stderr (a traceback would propagate)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = cli.main(list(argv))
        except SystemExit as exc:  # argparse usage errors
            code = exc.code
    return code, out.getvalue(), err.getvalue()


def assert_one_line_error(code, err, fragments, prefix):
    assert code == 2, err
    assert "Traceback" not in err
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith(prefix), lines[0]
    for frag in fragments:
        assert frag in lines[0], f"{frag!r} not in {lines[0]!r}"


# ------------------------------------------------------------------------------------------
# a small TOML writer for the generated documents
def toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k} = {toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(v)


def toml_document(doc: dict) -> str:
    head, tables = [], []
    for key, value in doc.items():
        if isinstance(value, dict) and key in ("robot", "scene", "extras"):
            tables.append(f"[{key}]\n" + "".join(f"{k} = {toml_value(v)}\n"
                                                 for k, v in value.items()))
        else:
            head.append(f"{key} = {toml_value(value)}\n")
    return "".join(head) + "\n".join(tables)


# ------------------------------------------------------------------------------------------
# malformed robot files
POSITIVE = st.floats(0.01, 10.0)
NONPOSITIVE_OR_NONFINITE = st.sampled_from([0.0, -0.0, -1.0, -1e-9, math.nan, math.inf,
                                            -math.inf, 0])
LINK_KEYS = ("mass", "length", "inertia")


@st.composite
def malformed_files(draw):
    na = draw(st.integers(1, 6))
    nl = na + 1
    robot = {"joints": na, "name": "fuzzed"}
    for key in LINK_KEYS:
        robot[key] = draw(st.one_of(POSITIVE, st.lists(POSITIVE, min_size=nl, max_size=nl)))
    k = draw(st.integers(1, nl))
    scene = {"scenario": draw(st.sampled_from(snakecg.SCENARIOS)),
             "kappa": draw(st.floats(0.1, 100.0)), "mu": draw(st.floats(0.0, 1.0)),
             "contact_link": k, "side": draw(st.sampled_from(["left", "right"]))}
    doc = {"robot": robot, "scene": scene}

    slots = ["joints", *LINK_KEYS, "com", "robot_extra", "name", "top", "scenario", "kappa",
             "mu", "gravity", "contact_link", "side", "object_distance", "object_inertia",
             "wheel_links", "wheel_offset", "scene_extra", "contact_offset"]
    chosen = draw(st.lists(st.sampled_from(slots), min_size=1, max_size=6, unique=True))
    whole = draw(st.sampled_from([None, None, None, "robot_missing", "robot_not_table",
                                  "scene_not_table"]))
    if whole in ("robot_missing", "robot_not_table"):
        chosen = [s for s in chosen if s in ("top", "scenario", "kappa", "mu", "gravity",
                                             "side", "object_distance", "object_inertia",
                                             "scene_extra")]
    if whole == "scene_not_table":
        chosen = [s for s in chosen if s in ("joints", *LINK_KEYS, "com", "robot_extra",
                                             "name", "top")]
    robot_ok = whole not in ("robot_missing", "robot_not_table")
    count_ok = robot_ok and "joints" not in chosen
    robot_valid = robot_ok and not (set(chosen) & {"joints", *LINK_KEYS, "com", "robot_extra",
                                                  "name"})
    contact_ok = "contact_link" not in chosen
    expect: list[str] = []

    for slot in chosen:
        if slot == "joints":
            kind = draw(st.sampled_from(["missing", "type", "nonpositive", "huge"]))
            if kind == "missing":
                del robot["joints"]
                expect.append("missing key joints in [robot]")
            elif kind == "huge":
                robot["joints"] = draw(st.integers(51, 10**18))
                expect.append(f"joints={robot['joints']} exceeds the generation limit of 50")
            else:
                robot["joints"] = draw(st.sampled_from(["3", 2.5, True, [3], {"n": 3}])
                                       if kind == "type" else st.integers(-10**6, 0))
                expect.append("joints must be an integer >= 1")
        elif slot in LINK_KEYS:
            kind = draw(st.sampled_from(["scalar", "element", "length", "text", "type"]))
            if kind == "scalar":
                robot[slot] = draw(NONPOSITIVE_OR_NONFINITE)
                expect.append(f"{slot} must be positive finite")
            elif kind == "element":
                values = [1.0] * nl
                values[draw(st.integers(0, nl - 1))] = draw(NONPOSITIVE_OR_NONFINITE)
                robot[slot] = values
                expect.append(f"{slot} must be positive finite")
            elif kind == "length":
                n = draw(st.integers(0, 12).filter(lambda m: m != nl))
                robot[slot] = [0.5] * n
                if count_ok:
                    expect.append(f"{slot} has {n} values, expected one number or {nl}")
            elif kind == "text":
                robot[slot] = [1.0] * (nl - 1) + ["one"]
                expect.append(f"{slot} must hold numbers, got 'one'")
            else:
                robot[slot] = draw(st.sampled_from(["heavy", True, {"a": 1}]))
                expect.append(f"{slot} must be a number or a list")
        elif slot == "com":
            robot["com"] = 5.0  # beyond any length drawn (<= 10 only for scalars)
            robot["length"] = 1.0 if "length" not in chosen else robot["length"]
            if count_ok and "length" not in chosen:
                expect.append("com of link 1 is 5.0 m, beyond its length 1.0 m")
        elif slot == "robot_extra":
            robot["colour"] = "red"
            expect.append("unknown keys in [robot]: ['colour']")
        elif slot == "name":
            robot["name"] = 7
            expect.append("name must be a string, got 7")
        elif slot == "top":
            doc["extras"] = {"note": 1}
            expect.append("unknown tables or keys ['extras'] at the top level")
        elif slot == "scenario":
            scene["scenario"] = draw(st.sampled_from(["muddy", "", 3, "Wheels"]))
            expect.append("scenario must be one of frictionless, wheels, ideal_wheels")
        elif slot in ("kappa", "object_distance", "object_inertia"):
            scene[slot] = draw(st.sampled_from([0.0, -2.0, math.nan, math.inf, "big", False]))
            expect.append(f"{slot} must be")
        elif slot in ("mu", "gravity"):
            scene[slot] = draw(st.sampled_from([-0.5, -math.inf, math.nan, "x", [1.0]]))
            expect.append(f"{slot} must be")
        elif slot == "contact_link":
            bad = draw(st.sampled_from([0, -1, 1.5, True, "1", nl + 1, 10**6]))
            scene["contact_link"] = bad
            if isinstance(bad, int) and not isinstance(bad, bool) and bad > nl and not count_ok:
                pass  # the range is unknown without a valid joint count
            else:
                expect.append("contact_link must be a link number")
        elif slot == "side":
            scene["side"] = draw(st.sampled_from(["up", "", 0, 2, "LEFT"]))
            expect.append("side must be 'left' or 'right'")
        elif slot == "wheel_links":
            kind = draw(st.sampled_from(["type", "value", "contact"]))
            if kind == "type":
                scene["wheel_links"] = draw(st.sampled_from(["all", 3, {"a": 1}]))
                expect.append("wheel_links must be a list of link numbers")
            elif kind == "value":
                scene["wheel_links"] = [draw(st.sampled_from([0, -2, "two", 1.5]))]
                expect.append("wheel_links must be link numbers")
            elif contact_ok:
                scene["wheel_links"] = [k]
                expect.append(f"link {k} touches the object and cannot carry a wheel")
        elif slot == "wheel_offset":
            kind = draw(st.sampled_from(["nonfinite", "length"]))
            if kind == "nonfinite":
                scene["wheel_offset"] = draw(st.sampled_from([math.nan, math.inf]))
                expect.append("wheel_offset must be finite")
            else:
                scene["wheel_offset"] = [0.0] * (nl + 2)
                if count_ok:
                    expect.append(f"wheel_offset has {nl + 2} values")
        elif slot == "scene_extra":
            scene["friction_model"] = "coulomb"
            expect.append("unknown keys in [scene]: ['friction_model']")
        elif slot == "contact_offset":
            scene["contact_offset"] = 50.0
            if robot_valid and contact_ok:
                expect.append(f"contact_offset must lie on link {k}")
    if whole == "robot_missing":
        del doc["robot"]
        expect.append("missing [robot] table")
    elif whole == "robot_not_table":
        doc["robot"] = draw(st.sampled_from([3, "snake", [1, 2]]))
        expect.append("[robot] must be a table")
    elif whole == "scene_not_table":
        doc["scene"] = draw(st.sampled_from([5, "wheels", [1]]))
        expect.append("[scene] must be a table")
    return toml_document(doc), expect, (count_ok and "joints" not in chosen) and na


_counter = iter(range(10**9))


@PROFILE
@given(case=malformed_files())
def test_malformed_robot_files_api_and_cli(case, workdir):
    text, expect, na = case
    path = workdir / f"robot-{next(_counter)}.toml"
    path.write_text(text)
    event(f"{len(expect)} problems expected")
    if not expect:  # every chosen fault needed something another fault broke
        event("no detectable fault")
        return
    # Python API: one InputError naming every problem
    with pytest.raises(snakecg.InputError) as info:
        snakecg.Scene.from_toml(path)
    message = str(info.value)
    assert message.startswith(f"robot file {str(path)!r}: ")
    for frag in expect:
        assert frag in message, f"{frag!r} missing from {message!r}\n--- file ---\n{text}"
    # CLI: exit 2, one line, every problem named
    q = ",".join(["0"] * ((na or 2) + 3))
    tau = ",".join(["0.1"] * (na or 2))
    code, out, err = run_cli(["forward", "--robot", str(path), "--q", q, "--tau", tau])
    assert_one_line_error(code, err, expect, f"snakecg forward: error: robot file '{path}'")
    assert out == ""


# ------------------------------------------------------------------------------------------
# malformed argument lists
SCENE_FAULTS = {
    "--kappa": [("-1", "kappa must be > 0, got -1.0"), ("0", "kappa must be > 0"),
                ("nan", "kappa must be finite, got nan"), ("inf", "kappa must be finite")],
    "--mu": [("-0.25", "mu must be >= 0, got -0.25"), ("nan", "mu must be finite")],
    "--contact-link": [("0", "contact_link must be a link number 1.."),
                       ("99", "contact_link must be a link number 1.."),
                       ("-1", "contact_link must be a link number 1..")],
}
PARSE_FAULTS = [
    (["--joints", "x"], "argument --joints: invalid int value: 'x'"),
    (["--joints", "2.5"], "argument --joints: invalid int value: '2.5'"),
    (["--kappa", "heavy"], "argument --kappa: invalid float value: 'heavy'"),
    (["--mu", ""], "argument --mu: invalid float value: ''"),
    (["--contact-link", "1.5"], "argument --contact-link: invalid int value: '1.5'"),
    (["--side", "up"], "argument --side: invalid choice: 'up'"),
    (["--scenario", "muddy"], "argument --scenario: invalid choice: 'muddy'"),
    (["--frobnicate"], "unrecognized arguments: --frobnicate"),
    (["--q"], "argument --q: expected one argument"),
]


@st.composite
def bad_argvs(draw):
    na = draw(st.integers(1, 6))
    q = [draw(st.floats(-3.0, 3.0)) for _ in range(na + 3)]
    tau = [draw(st.floats(-1.0, 1.0)) for _ in range(na)]
    qtext = ",".join(f"{x:.6g}" for x in q)
    tautext = ",".join(f"{x:.6g}" for x in tau)
    base = ["forward", "--joints", str(na), f"--q={qtext}", f"--tau={tautext}"]
    kind = draw(st.sampled_from(["scene", "parse", "vector", "joints", "missing", "file"]))
    if kind == "scene":  # value problems are collected and reported together
        opts = draw(st.lists(st.sampled_from(sorted(SCENE_FAULTS)), min_size=1, max_size=3,
                             unique=True))
        extra, expect = [], []
        for opt in opts:
            value, frag = draw(st.sampled_from(SCENE_FAULTS[opt]))
            extra += [f"{opt}={value}"]
            expect.append(frag)
        return base + extra, expect, kind
    if kind == "parse":
        args, frag = draw(st.sampled_from(PARSE_FAULTS))
        pos = draw(st.integers(1, len(base)))
        argv = base[:pos] + args + base[pos:] if args != ["--q"] else base + args
        if pos < len(base) and base[pos - 1] in ("--joints",):
            argv = base + args  # do not split an option from its value
        return argv, [frag], kind
    if kind == "vector":
        which = draw(st.sampled_from(["q", "tau"]))
        size = na + 3 if which == "q" else na
        bad = draw(st.sampled_from(["short", "long", "nan", "inf", "text", "empty"]))
        if bad == "short":
            text = ",".join(["0"] * (size - 1))
            frag = (f"{which} has shape ({size - 1},), expected ({size},)" if size > 1
                    else f"argument --{which}: empty value")
        elif bad == "long":
            text = ",".join(["0"] * (size + 2))
            frag = f"{which} has shape ({size + 2},), expected ({size},)"
        elif bad in ("nan", "inf"):
            values = ["0"] * size
            values[draw(st.integers(0, size - 1))] = draw(st.sampled_from(
                [bad, "-" + bad, "1e999" if bad == "inf" else "nan"]))
            text = ",".join(values)
            frag = f"{which} must be finite"
        elif bad == "text":
            text = ",".join(["0"] * (size - 1) + [draw(st.sampled_from(["x", "1..2", "0x", "é"]))])
            frag = f"--{which} must be numbers separated by commas or spaces"
        else:
            text, frag = " , ", f"--{which} is empty"
        argv = [a for a in base if not a.startswith(f"--{which}=")] + [f"--{which}={text}"]
        return argv, [frag], kind
    if kind == "joints":
        value = draw(st.sampled_from(["0", "-3", str(10**12), "51", str(2**70)]))
        frag = ("joints must be an integer >= 1" if int(value) < 1
                else f"joints={value} exceeds the generation limit of 50 joints")
        return ["forward", "--joints", value, "--q=0", "--tau=0"], [frag], kind
    if kind == "missing":
        drop = draw(st.sampled_from(["--q", "--tau"]))
        return [a for a in base if not a.startswith(drop + "=")], \
            [f"the following arguments are required: {drop}"], kind
    bad_file = draw(st.sampled_from(["/nonexistent/robot.toml", "/"]))
    frag = "does not exist" if "nonexistent" in bad_file else "is a directory"
    return base + ["--robot", bad_file], [f"robot file {bad_file!r} {frag}"], kind


@PROFILE
@given(case=bad_argvs())
def test_malformed_argument_lists(case):
    argv, expect, kind = case
    event(f"{kind} ({len(expect)} problem{'s' if len(expect) > 1 else ''})")
    code, out, err = run_cli(argv)
    # argparse reports arguments no sub-command knows from the top-level parser
    prefix = "snakecg: error: " if "unrecognized arguments" in expect[0] else \
        "snakecg forward: error: "
    assert_one_line_error(code, err, expect, prefix)
    assert out == ""


OTHER_COMMANDS = [
    (["generate", "--joints", "0"], "snakecg generate: error: ", "--joints must be >= 1, got 0"),
    (["generate", "--joints", "51"], "snakecg generate: error: ",
     "exceeds the generation limit of 50 joints"),
    (["generate", "--joints", str(10**15)], "snakecg generate: error: ",
     "exceeds the generation limit of 50 joints"),
    (["generate", "--joints", "three"], "snakecg generate: error: ", "invalid int value"),
    (["show", "--joints", "0", "M"], "snakecg show: error: ", "--joints must be >= 1"),
    (["show", "--joints", "2", "nonsense"], "snakecg show: error: ", "unknown expression"),
    (["show", "--joints", "2", "--c", "nonsense"], "snakecg show: error: ", "unknown function"),
    (["optimize", "nope", "--joints", "2", "--q=0,0,0,0,0"], "snakecg optimize: error: ",
     "invalid choice: 'nope'"),
    (["simulate", "--joints", "2", "--q=0,0,0,0,0", "--tau=0,0", "--duration=-1"],
     "snakecg simulate: error: ", "argument --duration: must be >= 1e-09 (s), got '-1'"),
    (["frobnicate"], "snakecg: error: ", "invalid choice: 'frobnicate'"),
    (["forward", "--robot", "examples/robot.toml", "--joints", "2", "--q=0,0,0,0,0",
      "--tau=0,0"], "snakecg forward: error: ", "--joints 2 contradicts the robot file (3 joints)"),
]


@pytest.mark.parametrize("argv, prefix, frag", OTHER_COMMANDS,
                         ids=[" ".join(a[:3]) for a, _, _ in OTHER_COMMANDS])
def test_other_commands_refuse_bad_input(argv, prefix, frag, monkeypatch):
    monkeypatch.chdir(Path(__file__).resolve().parent.parent)
    code, out, err = run_cli(argv)
    assert_one_line_error(code, err, [frag], prefix)


def test_huge_joint_count_refused_quickly():
    """The limit is checked before anything is built: no per-link tuple of 10^15 numbers, no
    derivation; the limit is configurable."""
    import time

    t0 = time.perf_counter()
    code, _, err = run_cli(["forward", f"--joints={10**15}", "--q=0", "--tau=0"])
    assert code == 2 and "exceeds the generation limit of 50 joints" in err
    assert time.perf_counter() - t0 < 5.0


def test_generation_limit_is_configurable(monkeypatch):
    monkeypatch.setenv("SNAKECG_MAX_JOINTS", "4")
    code, _, err = run_cli(["forward", "--joints", "5", "--q=0,0,0,0,0,0,0,0", "--tau=0,0,0,0,0"])
    assert_one_line_error(code, err, ["joints=5 exceeds the generation limit of 4 joints",
                                      "SNAKECG_MAX_JOINTS"], "snakecg forward: error: ")
    monkeypatch.setenv("SNAKECG_MAX_JOINTS", "many")
    code, _, err = run_cli(["forward", "--joints", "2", "--q=0,0,0,0,0", "--tau=0,0"])
    assert_one_line_error(code, err, ["SNAKECG_MAX_JOINTS must be a positive integer, got "
                                      "'many'"], "snakecg forward: error: ")


# ------------------------------------------------------------------------------------------
# the real entry point (separate processes): a fixed sample of the fuzzed problems
REAL = [
    (["forward", "--joints", "2", "--q=0,0,0", "--tau=0,0"], "q has shape (3,)"),
    (["forward", "--joints", "2", "--q=0,0,0,0,0", "--tau=0,0", "--kappa=-1", "--mu=nan"],
     "kappa must be > 0, got -1.0; mu must be finite"),
    (["forward", f"--joints={10**12}", "--q=0", "--tau=0"], "exceeds the generation limit"),
    (["forward", "--joints", "x", "--q=0", "--tau=0"], "invalid int value: 'x'"),
    (["generate", "--joints", "51"], "exceeds the generation limit of 50 joints"),
]


@pytest.mark.parametrize("argv, frag", REAL, ids=[" ".join(a[:3]) for a, _ in REAL])
def test_real_process_exit_status_and_one_line(argv, frag, tmp_path):
    proc = subprocess.run([sys.executable, "-m", "snakecg.cli", *argv], capture_output=True,
                          text=True, timeout=300, cwd=tmp_path)
    assert proc.returncode == 2, proc.stderr
    assert "Traceback" not in proc.stderr and proc.stdout == ""
    assert len(proc.stderr.splitlines()) == 1 and frag in proc.stderr, proc.stderr


def test_real_process_malformed_file(tmp_path):
    path = tmp_path / "robot.toml"
    path.write_text('top = 1\n[robot]\njoints = 0\nmass = [-1, "x"]\ncolour = "red"\n'
                    '[scene]\nkappa = nan\nside = "up"\n')
    proc = subprocess.run([sys.executable, "-m", "snakecg.cli", "forward", "--robot", str(path),
                           "--q=0,0,0,0", "--tau=0"], capture_output=True, text=True,
                          timeout=300, cwd=tmp_path)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    (line,) = proc.stderr.splitlines()
    for frag in ("unknown keys in [robot]: ['colour']", "joints must be an integer >= 1, got 0",
                 "mass must hold numbers, got 'x' (link 2)",
                 "mass must be positive finite, got -1.0 (link 1)",
                 "unknown tables or keys ['top']", "kappa must be finite, got nan",
                 "side must be 'left' or 'right', got 'up'"):
        assert frag in line, (frag, line)
    assert re.match(r"snakecg forward: error: robot file '.*robot\.toml': ", line)


# ------------------------------------------------------------------------------------------
# every sub-command and every option: each draw breaks one to three options of a valid
# command line; the command must refuse it in one line, exit 2, before any model is
# generated or loaded and before anything is written
SCENE_OPTION_FAULTS = {
    "--joints": ["0", "-3", "x", "", "2.5", "51", str(2**70)],
    "--robot": ["", "/nonexistent/robot.toml", "/", "/dev/zero", "/dev/null"],
    "--scenario": ["muddy", "", "Wheels"],
    "--kappa": ["nan", "inf", "-1", "0", "1e400", "", "heavy", "-inf"],
    "--mu": ["nan", "-1", "inf", "", "x"],
    "--contact-link": ["0", "99", "-1", "1.5", ""],
    "--side": ["up", "", "LEFT"],
}
# wrong lengths: longer than any vector of the robots drawn (1-3 joints: at most 6 values)
VECTOR_FAULTS = ["", " , ", "nan", "x", "1e400", "0,0,0,0,0,0,0", "1,2,3,4,5,6,7,8,9,10,11,12",
                 "-inf"]
COMMAND_FAULTS = {
    "forward": {**SCENE_OPTION_FAULTS, "--q": VECTOR_FAULTS, "--tau": VECTOR_FAULTS,
                "--v": VECTOR_FAULTS},
    "optimize": {**SCENE_OPTION_FAULTS, "--q": VECTOR_FAULTS,
                 "--tau-max": ["", "-1", "0", "nan", "1e101", "1,2,3,4,5,6", "x"],
                 "--radius": ["0", "-1", "nan", "inf", "1e308", "", "x"],
                 "--direction": ["0,0", "1", "1,2,3,4", "nan,1", "", "1e400,0"],
                 "--a-min": ["-1", "nan", "1e308", "", "inf"],
                 "--a-obj": ["1,2", "nan,0,0", "1e101,0,0", ""],
                 "--allow-slide": ["nan", "inf", "0", "99", "1.5", "", "1e400", "-2"]},
    "simulate": {**SCENE_OPTION_FAULTS, "--q": VECTOR_FAULTS, "--tau": VECTOR_FAULTS,
                 "--v": VECTOR_FAULTS, "--v-obj": ["1,2", "nan,0,0", "", "1,2,3,4"],
                 "--duration": ["0", "-1", "nan", "inf", "", "1e400"],
                 "--controller": ["pid", ""],
                 "--a-min": ["-1", "nan", "1e308", "1"],
                 "--tau-max": ["0", "-1", "nan", "1e101", "0.1"],
                 "--control-period": ["0", "-1", "nan", "1e-12", "0.01"],
                 "--method": ["Euler", "", "rk45"],
                 "--rtol": ["0", "1e-20", "2", "nan", ""],
                 "--atol": ["0", "-1", "nan", ""],
                 "--stabilization": ["-1", "nan", "1e7", ""],
                 "--output-dt": ["0", "5e-324", "1e-9", "nan", "-1", ""],
                 "--out": [""], "--frames": ["0", "1", "1000000000", "x", ""],
                 # a time step is a general scene's (--scene); the paper's scene refuses any
                 "--dt": ["0", "-1", "nan", "2", "", "0.001"]},
    "reproduce": {"--out": [""], "--kappa": ["nan", "0", "-1", "inf", "x", ""],
                  "--torque-grid": ["10", "0", "100000000", "x", "", "-5"],
                  "--formats": ["", "gif", "png,jpg", " , "]},
    "generate": {"--joints": ["0", "-1", "51", "x", "", str(10**15)], "--out": [""]},
    "show": {"--joints": ["0", "-1", "x", ""]},
}
# options that are faults only in some combinations (the rest of the line is valid)
_CONDITIONAL = {("simulate", "--a-min", "1"), ("simulate", "--tau-max", "0.1"),
                ("simulate", "--control-period", "0.01")}


def _base(command, na, out):
    q = ",".join(["0"] * 3 + ["0.3"] * na)
    tau = ",".join(["0.01"] * na)
    return {
        "forward": ["forward", "--joints", str(na), f"--q={q}", f"--tau={tau}"],
        "optimize": ["optimize", "max-sr", "--joints", str(na), f"--q={q}"],
        "simulate": ["simulate", "--joints", str(na), f"--q={q}", f"--tau={tau}",
                     "--duration", "0.01", "--no-figures", "--out", out],
        "reproduce": ["reproduce", "--out", out],
        "generate": ["generate", "--joints", str(na), "--out", out],
        "show": ["show", "--joints", str(na), "M"],
    }[command]


@st.composite
def broken_command_lines(draw):
    command = draw(st.sampled_from(sorted(COMMAND_FAULTS)))
    faults = COMMAND_FAULTS[command]
    na = draw(st.integers(1, 3))
    opts = draw(st.lists(st.sampled_from(sorted(faults)), min_size=1, max_size=3, unique=True))
    chosen = {o: draw(st.sampled_from(faults[o])) for o in opts}
    # keep at least one unconditional fault
    if all((command, o, v) in _CONDITIONAL for o, v in chosen.items()):
        o = draw(st.sampled_from([o for o in sorted(faults) if o not in chosen]))
        chosen[o] = draw(st.sampled_from(
            [v for v in faults[o] if (command, o, v) not in _CONDITIONAL]))
    return command, na, chosen


def _apply(base, chosen):
    argv = list(base)
    for opt, value in chosen.items():
        # drop the option from the base (with its value)
        out, skip = [], False
        for i, a in enumerate(argv):
            if skip:
                skip = False
                continue
            if a == opt:
                skip = True
                continue
            if a.startswith(opt + "="):
                continue
            out.append(a)
        argv = out + [f"{opt}={value}"]
    return argv


@contextlib.contextmanager
def no_model_loaded():
    """Any generation, rendering, loading or study fails the test (the bad input must be
    refused before)."""
    import snakecg.reproduce as rep
    import snakecg_derive.inspection as inspect_mod
    import snakecg_derive.render as render

    def boom(*args, **kwargs):
        raise AssertionError("work started before the bad input was refused")

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(snakecg.robot_model, "_backend", boom)
        mp.setattr(snakecg.artifacts, "model_dir", boom)
        mp.setattr(render, "render_model", boom)
        mp.setattr(rep, "case_study_1", boom)
        mp.setattr(inspect_mod, "expression", boom)
        yield


@PROFILE
@given(case=broken_command_lines())
def test_every_command_and_option_refuses_bad_values(case, workdir):
    command, na, chosen = case
    event(command)
    out = workdir / f"out-{next(_counter)}"
    argv = _apply(_base(command, na, str(out)), chosen)
    with no_model_loaded():
        code, stdout, err = run_cli(argv)
    assert code == 2, (argv, code, err)
    assert "Traceback" not in err and stdout == "", (argv, err)
    lines = err.splitlines()
    assert len(lines) == 1, (argv, err)
    assert lines[0].startswith((f"snakecg {command}: error: ", "snakecg: error: ")), lines[0]
    assert not out.exists(), argv  # nothing written
    # the message names one of the broken options (or the library name of its value)
    names = set()
    for opt in chosen:
        names |= {opt, opt.lstrip("-").replace("-", "_"), opt.lstrip("-") + "0"}
    names |= {"robot file", "joints", "q0", "v0", "v_obj0"}
    assert any(n in lines[0] for n in names), (argv, lines[0])


# ------------------------------------------------------------------------------------------
# every option of every sub-command, read from the parsers themselves (a new option is
# covered without touching this file), with hostile values: exit status 0, 1 (a failure that
# is not the input's fault, one line) or 2 (one line), never a traceback, strict JSON with
# --json. Work that would take long once the values are accepted (a derivation, a sweep, a
# study, a shape search) is stopped where it starts: the values passed every check.
class WorkStarted(BaseException):
    """Raised where long work would start: every check before it passed."""


HOSTILE = ["", " ", "--", "nan", "-inf", "1e308", "5e-324", "-1", "0", str(10**40), "x",
           "\u00e9\u202e\u0301", "1" * 5000]
HOSTILE_SLOW = HOSTILE + [
    "inf", "-1e308", "1e400", "-0", "0x10", "1e-320", "3.5", "2", "1,2,3", "nan,nan",
    ",".join(["1e308"] * 6), "true", "/dev/zero", "/", "/nonexistent/x", "-", "1e-9", "1e6",
    "9" * 400, "\U0001f40d", "a" * 100_000, "0,0,0,0,0", "-135deg", "1e308deg",
]


def _parsers():
    """``{command: parser}`` of every installed sub-command."""
    parser = cli.build_parser()
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return dict(sub.choices)


def _options(parser):
    """``[(label, make)]``: ``make(value)`` gives the argument list that sets one option (or
    positional) of ``parser`` to ``value``."""
    out = []
    for action in parser._actions:
        if isinstance(action, argparse._HelpAction):
            continue
        if not action.option_strings:
            out.append((action.dest, ("positional", action.dest)))
        elif action.nargs == 0:  # flags: a value is an error
            out.append((action.option_strings[-1], ("flag", action.option_strings[-1])))
        else:
            out.append((action.option_strings[-1], ("option", action.option_strings[-1])))
    return out


POSITIONAL_BASE = {"optimize": "max-sr", "optimize-shape": "max-sr", "show": "M"}


def _base_line(command, out):
    """A valid, cheap command line of ``command`` (2 joints), writing under ``out``."""
    q = "--q=0,0,0,0.3,0.3"
    return {
        "generate": ["--joints", "2"],
        "show": ["--joints", "2"],
        "forward": ["--joints", "2", q, "--tau=0.01,0"],
        "reproduce": ["--out", str(out / "r")],
        "optimize": ["--joints", "2", q],
        "simulate": ["--joints", "2", q, "--tau=0.01,0", "--duration", "0.01",
                     "--no-figures", "--out", str(out / "s")],
        "export": ["--joints", "2", "--out", str(out / "e")],
        "plot": ["--joints", "2", q, "--out", str(out / "p.png")],
        "optimize-shape": ["--joints", "2"],
        "sweep": ["--joints", "2", "--out", str(out / "w.zarr")],
    }.get(command, [])


def _argv(command, parser, kind, name, value, out):
    """The base line of ``command`` with ``name`` set to ``value`` (``--opt=value``; a flag
    given a value; a positional replaced), ``--json`` added where the command has it."""
    base = _base_line(command, out)
    # drop the option from the base line (with its value)
    cleaned, skip = [], False
    for a in base:
        if skip:
            skip = False
            continue
        if kind != "positional" and a == name:
            skip = True
            continue
        if kind != "positional" and a.startswith(name + "="):
            continue
        cleaned.append(a)
    positional = POSITIONAL_BASE.get(command)
    if kind == "positional":
        positional = value
    argv = [command] + ([positional] if positional is not None else []) + cleaned
    if kind != "positional":
        argv.append(f"{name}={value}")
    if any("--json" in a.option_strings for a in parser._actions) and name != "--json":
        argv.append("--json")
    return argv


@contextlib.contextmanager
def long_work_stopped():
    """Derivations, sweeps, studies, shape searches and simulations raise WorkStarted."""
    import snakecg.model as model_mod
    import snakecg.reproduce as rep
    import snakecg.simulate as sim
    import snakecg.sweeps.run as sweeps_run
    import snakecg_derive.inspection as inspect_mod
    import snakecg_derive.render as render

    def started(*args, **kwargs):
        raise WorkStarted

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(render, "render_model", started)
        mp.setattr(rep, "reproduce", started)
        mp.setattr(sweeps_run, "sweep", started)
        mp.setattr(inspect_mod, "expression", started)
        mp.setattr(model_mod.SceneModel, "optimize_shape", started)
        real_simulate = sim.simulate

        def simulate(model, q0, tau, duration, **kw):  # short runs only (a hostile value
            if duration > 0.05 or (kw.get("atol") or 1) < 1e-30:  # may ask for hours)
                raise WorkStarted
            return real_simulate(model, q0, tau, duration, **kw)

        mp.setattr(sim, "simulate", simulate)
        yield


def _strict_json(text):
    def refuse(token):
        raise ValueError(f"non-strict JSON token {token}")

    return json.loads(text, parse_constant=refuse)


def check_hostile(command, parser, kind, name, value, out):
    """Run one hostile command line and check what a user sees."""
    argv = _argv(command, parser, kind, name, value, out)
    cwd = os.getcwd()
    os.chdir(out)  # a relative path among the values (`--out=x`) lands in the test's folder
    try:
        with long_work_stopped():
            code, stdout, err = run_cli(argv)
    except WorkStarted:
        return "accepted"
    finally:
        os.chdir(cwd)
    shown = [ln for ln in err.splitlines() if not ln.startswith("snakecg: warning: ")]
    where = (argv[:1] + [a[:80] for a in argv[1:]], code, err[:500])
    assert "Traceback" not in err, where
    assert code in (0, 1, 2), where
    if code == 2:
        assert len(shown) == 1, where
        assert shown[0].startswith((f"snakecg {command}: error: ", "snakecg: error: ")), where
        assert stdout == "", where
    elif code == 1:  # a failure said in one line, or a result whose status is not a success
        # (at most one line then, naming it: a simulation that stopped at a penetration)
        assert len(shown) <= 1, where
        assert (shown and ": failed: " in shown[0]) or stdout, where
    if code in (0, 1) and "--json" in argv and stdout.strip():
        _strict_json(stdout)
    return code


def _cases(values):
    for command, parser in sorted(_parsers().items()):
        for name, (kind, opt) in _options(parser):
            yield command, name, kind, values


def test_the_fuzz_reaches_every_command_and_option():
    """The table is the parsers': every sub-command, every option, and ``--opt=--``."""
    parsers = _parsers()
    assert set(parsers) >= {"generate", "show", "forward", "reproduce", "optimize",
                            "simulate", "export", "plot", "optimize-shape", "sweep"}
    for command, parser in parsers.items():
        assert _base_line(command, Path("/tmp")) or command in ("show", "generate"), command
        names = [n for n, _ in _options(parser)]
        assert len(names) >= 2, command
    assert "--" in HOSTILE


@pytest.mark.parametrize("command", sorted(_parsers()))
def test_every_option_takes_hostile_values(command, tmp_path):
    """Each option of ``command`` given every value of HOSTILE (one at a time, the rest of
    the line valid): one line and exit 2 when refused, never a traceback, strict JSON."""
    parser = _parsers()[command]
    seen = {}
    for i, (name, (kind, opt)) in enumerate(_options(parser)):
        for j, value in enumerate(HOSTILE):
            out = tmp_path / f"{i}-{j}"
            out.mkdir()
            seen[(name, value)] = check_hostile(command, parser, kind, opt, value, out)
    # `--opt=--` is refused by every option that takes a value
    for name, (kind, opt) in _options(parser):
        if kind == "option":
            assert seen[(name, "--")] == 2, (command, name)


@pytest.mark.slow
@pytest.mark.parametrize("command", sorted(_parsers()))
def test_every_option_takes_hostile_values_exhaustive(command, tmp_path):
    """The long list of hostile values (paths, devices, lists, huge and tiny numbers, long
    strings), one option at a time."""
    parser = _parsers()[command]
    options = _options(parser)
    for i, (name, (kind, opt)) in enumerate(options):
        for j, value in enumerate(HOSTILE_SLOW):
            out = tmp_path / f"{i}-{j}"
            out.mkdir()
            check_hostile(command, parser, kind, opt, value, out)


# the attacks that were reported, each reachable from the command line: one line, exit 2
REPORTED = [
    (["simulate", "--joints", "2", "--q=0,0,0,0,0", "--tau=0,0", "--duration=--"],
     "argument --duration: expected a value, got '--'"),
    (["plot", "--joints", "2", "--q=0,0,0,0,0", "--tau=--", "--out", "x.png"],
     "argument --tau: expected a value, got '--'"),
    (["simulate", "--joints", "2", "--q=0,0,0,0,0", "--tau=0,0", "--duration", "5e-324"],
     "argument --duration: must be >= 1e-09"),
    (["simulate", "--joints", "2", "--q=0,0,0,0,0", "--tau=1e151,0", "--no-figures"],
     "tau must have every entry within +-1e+150"),
    (["plot", "--joints", "2", "--q=1e308,0,0,0,0", "--out", "{tmp}/x.png"],
     "q places the drawing 1e+308 m from the origin"),
    (["export", "--joints", "1", "--out", ""], "argument --out: empty value"),
]


@pytest.mark.parametrize("argv, fragment", REPORTED, ids=[" ".join(a[:1] + a[-1:])
                                                          for a, _ in REPORTED])
def test_reported_attacks_are_refused_in_one_line(argv, fragment, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    code, out, err = run_cli(argv)
    assert code == 2 and "Traceback" not in err and out == "", err
    assert len(err.splitlines()) == 1 and fragment in err, err
    assert list(tmp_path.iterdir()) == []  # nothing written


# ------------------------------------------------------------------------------------------
# a general scene (--scene FILE): optimize's options broken one to three at a time against
# the scene (its joints, its objects), refused in one line before any model is loaded; the
# commands that do not take a general scene say so in one line
_SCENES = Path(__file__).resolve().parents[1] / "examples" / "scenes"
SCENE_FILE_FAULTS = {
    "--object": ["0", "3", "-1", "x", "", "1.5", str(2**70)],
    "--q": VECTOR_FAULTS,
    "--direction": ["0,0", "1", "1,2,3,4", "nan,1", "", "1e400,0"],
    "--a-min": ["-1", "nan", "1e308", "", "inf"],
    "--a-obj": ["1,2", "nan,0,0", "1e101,0,0", ""],
    "--tau-max": ["", "-1", "0", "nan", "1e101", "1,2,3,4,5,6", "x"],
    "--radius": ["0", "-1", "nan", "inf", "1e308", "", "x"],
    "--allow-slide": ["2,3", "0", "x", ""],
    "--joints": ["3", "2"],
    "--scenario": ["wheels"],
    "--kappa": ["10"],
}


@st.composite
def broken_scene_lines(draw):
    objective = draw(st.sampled_from(["max-sr", "least-slip-push", "strongest-push"]))
    base = ["optimize", objective, "--scene", str(_SCENES / "two_objects.toml"),
            "--q=0,0,0,0.6,-0.6,0.6", "--tau-max=2"]
    base += {"max-sr": [], "least-slip-push": ["--direction=0,1", "--a-min=0.1"],
             "strongest-push": ["--direction=0,1"]}[objective]
    opts = draw(st.lists(st.sampled_from(sorted(SCENE_FILE_FAULTS)), min_size=1, max_size=3,
                         unique=True))
    return objective, _apply(base, {o: draw(st.sampled_from(SCENE_FILE_FAULTS[o]))
                                    for o in opts})


@PROFILE
@given(case=broken_scene_lines())
def test_optimize_on_a_scene_file_refuses_bad_options(case):
    objective, argv = case
    event(objective)
    with no_model_loaded():
        code, stdout, err = run_cli(argv)
    assert code == 2, (argv, code, err)
    assert "Traceback" not in err and stdout == "", (argv, err)
    assert len(err.splitlines()) == 1 and err.startswith("snakecg"), (argv, err)


@pytest.mark.parametrize("command", ["sweep", "optimize-shape", "export"])
def test_commands_without_general_scenes_refuse_scene_files(command, tmp_path):
    line = {"sweep": ["sweep", *_base_line("sweep", tmp_path)],
            "optimize-shape": ["optimize-shape", "max-sr"],
            "export": ["export", "--out", str(tmp_path / "e")]}[command]
    line = [a for a in line if a not in ("--joints", "2")]
    with no_model_loaded():
        code, stdout, err = run_cli(line + ["--scene", str(_SCENES / "pegs.toml")])
    assert code == 2 and stdout == "" and "Traceback" not in err, (line, err)
    (msg,) = err.splitlines()
    assert "does not take a general scene yet (forward, optimize, plot and simulate do)" in msg, msg


def test_optimize_on_a_scene_file_prints_strict_json():
    code, stdout, err = run_cli(["optimize", "strongest-push", "--scene",
                                 str(_SCENES / "wall_push.toml"), "--q=0,0,0,0,0,0",
                                 "--direction=0,1", "--tau-max=2", "--json"])
    assert code == 1 and err == ""  # a search: 'local', not optimal
    out = _strict_json(stdout)
    assert out["status"] == "local" and out["object"] == 1 and out["objective_value"] > 0.1
    assert out["analysis"]["objects"][0]["a"][1] == pytest.approx(out["objective_value"])
    code, stdout, _ = run_cli(["optimize", "max-sr", "--scene",
                               str(_SCENES / "two_objects.toml"),
                               "--q=0,0,0,0.6,-0.6,0.6", "--json", "--allow-slide"])
    assert code in (0, 1)
    _strict_json(stdout)
