"""Robot description files and robot/scene arguments: every problem in one clear message.

Each documented problem has its message checked word for word (the fuzz in
test_cli_fuzz.py checks many combinations); files that are not TOML at all, missing or
unreadable are reported without a traceback; joint counts beyond the generation limit are
refused before anything is built, with the (configurable) limit in the message.
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np
import pytest

import snakecg
from snakecg import InputError, Robot, Scene

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(autouse=True)
def _default_limit(monkeypatch):
    monkeypatch.delenv("SNAKECG_MAX_JOINTS", raising=False)


def write(tmp_path, text: str, name="robot.toml") -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_example_file():
    scene = Scene.from_toml(ROOT / "examples" / "robot.toml")
    assert scene.robot == Robot(joints=3, mass=1.0, length=0.15, inertia=0.002,
                                joint_limits=(-2.6, 2.6), effort_limits=1.0)
    assert scene.robot.name == "table1-three-joints"
    assert (scene.scenario, scene.kappa, scene.mu, scene.contact_link, scene.side) == \
        ("wheels", 100.0, 0.1, 1, "left")
    assert scene.wheel_links == (2, 3, 4)
    assert Robot.from_toml(ROOT / "examples" / "robot.toml") == scene.robot


GOOD_ROBOT = "[robot]\njoints = 2\n"

# (file text, the exact words of the one problem)
SINGLE_PROBLEMS = [
    ("", "missing [robot] table"),
    ("robot = 3\n", "[robot] must be a table, got 3"),
    ("[robot]\nmass = 1.0\n", "missing key joints in [robot]"),
    ("[robot]\njoints = \"2\"\n", "joints must be an integer >= 1, got '2'"),
    ("[robot]\njoints = 2.0\n", "joints must be an integer >= 1, got 2.0"),
    ("[robot]\njoints = true\n", "joints must be an integer >= 1, got True"),
    ("[robot]\njoints = 0\n", "joints must be an integer >= 1, got 0"),
    ("[robot]\njoints = -4\n", "joints must be an integer >= 1, got -4"),
    ("[robot]\njoints = 51\n", "joints=51 exceeds the generation limit of 50 joints (raise it "
                              "with SNAKECG_MAX_JOINTS if you accept the derivation and "
                              "compile time)"),
    ("[robot]\njoints = 9223372036854775807\n", "joints=9223372036854775807 exceeds the "
                                                "generation limit of 50 joints"),
    (GOOD_ROBOT + "mass = 0\n", "mass must be positive finite, got 0.0"),
    (GOOD_ROBOT + "mass = -1.5\n", "mass must be positive finite, got -1.5"),
    (GOOD_ROBOT + "length = nan\n", "length must be positive finite, got nan"),
    (GOOD_ROBOT + "inertia = inf\n", "inertia must be positive finite, got inf"),
    (GOOD_ROBOT + "inertia = -inf\n", "inertia must be positive finite, got -inf"),
    (GOOD_ROBOT + "mass = [1, 0, -2]\n",
     "mass must be positive finite, got 0.0 (link 2), -2.0 (link 3)"),
    (GOOD_ROBOT + "length = [0.1, 0.2]\n",
     "length has 2 values, expected one number or 3 (= joints + 1, one per link)"),
    (GOOD_ROBOT + "length = []\n", "length has 0 values, expected one number or 3"),
    (GOOD_ROBOT + "mass = [1, \"two\", 3]\n", "mass must hold numbers, got 'two' (link 2)"),
    (GOOD_ROBOT + "mass = \"heavy\"\n", "mass must be a number or a list of 3 numbers, "
                                       "got 'heavy'"),
    (GOOD_ROBOT + "mass = {a = 1}\n", "mass must be a number or a list of 3 numbers, "
                                     "got {'a': 1}"),
    (GOOD_ROBOT + "length = 0.1\ncom = [0.05, 0.2, 0.05]\n",
     "com of link 2 is 0.2 m, beyond its length 0.1 m"),
    (GOOD_ROBOT + "name = 5\n", "name must be a string, got 5"),
    (GOOD_ROBOT + "colour = \"red\"\n",
     "unknown keys in [robot]: ['colour'] (allowed: ['com', 'effort_limits', 'inertia', "
     "'joint_limits', 'joints', 'length', 'mass', 'name'])"),
    (GOOD_ROBOT + "joint_limits = [1.0, -1.0]\n",
     "joint_limits must hold pairs lower < upper (rad): lower 1 >= upper -1"),
    (GOOD_ROBOT + "joint_limits = [[-1.0, 1.0]]\n",
     "joint_limits has 1 pair(s), expected one pair or 2 (one per joint)"),
    (GOOD_ROBOT + "effort_limits = [1.0, 0.0]\n",
     "effort_limits must be positive finite torques (N m), got 0.0 (joint 2)"),
    (GOOD_ROBOT + "effort_limits = [1.0, 2.0, 3.0]\n",
     "effort_limits has 3 value(s), expected one number or 2 (one per joint)"),
    ("version = 2\n" + GOOD_ROBOT, "unknown tables or keys ['version'] at the top level "
                                   "(expected the tables [robot] and [scene])"),
    (GOOD_ROBOT + "[scen]\nkappa = 1\n", "unknown tables or keys ['scen'] at the top level"),
    ("scene = 1\n" + GOOD_ROBOT, "[scene] must be a table, got 1"),
    (GOOD_ROBOT + "[scene]\nfriction = 1\n", "unknown keys in [scene]: ['friction'] (allowed: "),
    (GOOD_ROBOT + "[scene]\nscenario = \"ice\"\n",
     "scenario must be one of frictionless, wheels, ideal_wheels (got 'ice')"),
    (GOOD_ROBOT + "[scene]\nkappa = 0\n", "kappa must be > 0, got 0"),
    (GOOD_ROBOT + "[scene]\nkappa = nan\n", "kappa must be finite, got nan"),
    (GOOD_ROBOT + "mass = 10\n[scene]\nkappa = 1e308\n",
     "kappa * mean link mass = inf (object mass) is not finite"),
    (GOOD_ROBOT + "[scene]\nmu = -0.1\n", "mu must be >= 0, got -0.1"),
    (GOOD_ROBOT + "[scene]\nmu = \"low\"\n", "mu must be a number, got 'low'"),
    (GOOD_ROBOT + "[scene]\ngravity = -9.81\n", "gravity must be >= 0, got -9.81"),
    (GOOD_ROBOT + "[scene]\ncontact_link = 4\n", "contact_link must be a link number 1..3, got 4"),
    (GOOD_ROBOT + "[scene]\ncontact_link = 1.0\n",
     "contact_link must be a link number 1..3, got 1.0"),
    (GOOD_ROBOT + "[scene]\ncontact_offset = 0.5\n",
     "contact_offset must lie on link 1: 0..0.15 m from its rear end, got 0.5"),
    (GOOD_ROBOT + "[scene]\nside = \"above\"\n", "side must be 'left' or 'right', got 'above'"),
    (GOOD_ROBOT + "[scene]\nobject_distance = 0\n", "object_distance must be > 0, got 0"),
    (GOOD_ROBOT + "[scene]\nobject_inertia = -1\n", "object_inertia must be > 0, got -1"),
    (GOOD_ROBOT + "[scene]\nwheel_links = \"all\"\n",
     "wheel_links must be a list of link numbers, got 'all'"),
    (GOOD_ROBOT + "[scene]\nwheel_links = [0, 4]\n",
     "wheel_links must be link numbers 1..3, got 0, 4"),
    (GOOD_ROBOT + "[scene]\nwheel_links = [1, 2]\n",
     "link 1 touches the object and cannot carry a wheel (assumption 4); remove it from "
     "wheel_links"),
    (GOOD_ROBOT + "[scene]\nwheel_offset = [0, 0]\n",
     "wheel_offset has 2 values, expected one number or 3"),
    (GOOD_ROBOT + "[scene]\nwheel_offset = nan\n", "wheel_offset must be finite, got nan"),
]


@pytest.mark.parametrize("text, words", SINGLE_PROBLEMS,
                         ids=[w[:40] for _, w in SINGLE_PROBLEMS])
def test_one_problem_named_exactly(text, words, tmp_path):
    path = write(tmp_path, text)
    with pytest.raises(InputError) as info:
        Scene.from_toml(path)
    message = str(info.value)
    assert message.startswith(f"robot file {str(path)!r}: ")
    assert words in message
    assert message.count(";") == words.count(";")  # exactly one problem


def test_every_problem_listed_at_once(tmp_path):
    text = """
notes = "x"
[robot]
joints = 3
mass = [1, -1, "a", 2]
length = 0.15
inertia = [0.002, 0.002, 0.002]
com = 0.2
colour = "blue"

[scene]
scenario = "sand"
kappa = -5
mu = nan
contact_link = 9
side = "up"
wheel_links = [1, 2]
speed = 3
"""
    path = write(tmp_path, text)
    with pytest.raises(InputError) as info:
        Scene.from_toml(path)
    problems = str(info.value).split(": ", 1)[1].split("; ")
    expected = [
        "unknown keys in [robot]: ['colour']",
        "mass must hold numbers, got 'a' (link 3)",
        "mass must be positive finite, got -1.0 (link 2)",
        "inertia has 3 values, expected one number or 4",
        "com of link 1 is 0.2 m, beyond its length 0.15 m",
        "unknown tables or keys ['notes']",
        "unknown keys in [scene]: ['speed']",
        "scenario must be one of frictionless, wheels, ideal_wheels (got 'sand')",
        "kappa must be > 0, got -5",
        "mu must be finite, got nan",
        "contact_link must be a link number 1..4, got 9",
        "side must be 'left' or 'right', got 'up'",
    ]
    for words in expected:
        assert sum(words in p for p in problems) == 1, (words, problems)
    assert len(problems) == len(expected) + 3  # com of links 2..4 as well


def test_robot_from_toml_ignores_the_scene_table(tmp_path):
    path = write(tmp_path, GOOD_ROBOT + "[scene]\nkappa = -1\n")
    assert Robot.from_toml(path) == Robot(joints=2)
    with pytest.raises(InputError, match="kappa must be > 0"):
        Scene.from_toml(path)


def test_keyword_overrides_are_validated_with_the_file(tmp_path):
    path = write(tmp_path, GOOD_ROBOT + "[scene]\nside = \"up\"\n")
    with pytest.raises(InputError, match=r"kappa must be > 0, got -1\.0; side must be"):
        Scene.from_toml(path, kappa=-1.0)
    assert Scene.from_toml(path, side="right").side == "right"


@pytest.mark.parametrize("content, words", [
    (b"[robot\njoints = 2\n", "is not valid TOML"),
    (b"[robot]\njoints = 2\njoints = 3\n", "is not valid TOML"),
    (b"[robot]\nname = \"unterminated\n", "is not valid TOML"),
    (b"\x00\x01\x02\xff\xfe binary", "cannot be read"),
    ("[robot]\njoints = 2\n".encode("utf-16"), "cannot be read"),
    (b"a = " + b"[" * 100_000 + b"]" * 100_000 + b"\n", "is not valid TOML"),
])
def test_not_toml(content, words, tmp_path):
    path = tmp_path / "robot.toml"
    path.write_bytes(content)
    with pytest.raises(InputError, match=rf"robot file '.*robot\.toml' {words}"):
        Scene.from_toml(path)


def test_missing_and_directory(tmp_path):
    with pytest.raises(InputError, match=r"robot file '.*nope\.toml' does not exist"):
        Robot.from_toml(tmp_path / "nope.toml")
    with pytest.raises(InputError, match=r"is a directory, expected a TOML file"):
        Robot.from_toml(tmp_path)


def test_unreadable_file(tmp_path):
    """An OS error other than a missing file (here: a path through a regular file, which fails
    for every user, root included) is reported as unreadable, not as a traceback."""
    path = write(tmp_path, GOOD_ROBOT)
    with pytest.raises(InputError, match=r"cannot be read"):
        Robot.from_toml(path / "robot.toml")


# ------------------------------------------------------------------------------------------
# the Python API
def test_robot_arguments_all_problems_at_once():
    with pytest.raises(InputError) as info:
        Robot(joints=0, mass=[1.0, -1.0, math.nan], length="long", inertia=[1e-3, 0.0],
              com=[0.1, None], name=None)
    message = str(info.value)
    assert message.startswith("invalid robot: ")
    for words in ("joints must be an integer >= 1, got 0",
                  "mass must be positive finite, got -1.0 (link 2), nan (link 3)",
                  "length must be a number or a list of numbers, got 'long'",
                  "inertia must be positive finite, got 0.0 (link 2)",
                  "com must hold numbers, got None (link 2)",
                  "name must be a string, got None"):
        assert words in message, (words, message)


def test_many_bad_values_are_counted_not_all_quoted():
    with pytest.raises(InputError, match=r"mass must be positive finite, got -1\.0 \(link 1\), "
                                         r"-1\.0 \(link 2\), -1\.0 \(link 3\), -1\.0 "
                                         r"\(link 4\) and 6 more"):
        Robot(joints=9, mass=[-1.0] * 10)


def test_numpy_values_accepted():
    r = Robot(joints=np.int64(2), mass=np.array([1.0, 2.0, 3.0]), length=np.float32(0.2))
    assert r.joints == 2 and type(r.joints) is int
    assert r.mass == (1.0, 2.0, 3.0) and r.length == pytest.approx((0.2,) * 3)
    s = Scene(r, contact_link=np.int64(2), wheel_links=np.array([1, 3]), kappa=np.float64(3))
    assert s.contact_link == 2 and s.wheel_links == (1, 3) and s.kappa == 3.0


def test_scene_arguments_all_problems_at_once():
    with pytest.raises(InputError) as info:
        Scene(Robot(joints=2), scenario="mud", kappa=math.inf, mu=-1, gravity="g",
              contact_link=0, side=None, object_distance=-1, object_inertia=0,
              wheel_links=[7], wheel_offset=[0.0, math.nan, 0.0])
    message = str(info.value)
    for words in ("scenario must be one of", "kappa must be finite, got inf",
                  "mu must be >= 0, got -1", "gravity must be a number, got 'g'",
                  "contact_link must be a link number 1..3, got 0",
                  "side must be 'left' or 'right', got None",
                  "object_distance must be > 0, got -1", "object_inertia must be > 0, got 0",
                  "wheel_links must be link numbers 1..3, got 7",
                  "wheel_offset must be finite, got nan (link 2)"):
        assert words in message, (words, message)
    assert message.count("; ") == 9  # ten problems


def test_huge_joint_count_refused_before_anything_is_built():
    t0 = time.perf_counter()
    with pytest.raises(InputError, match=r"joints=1000000000000 exceeds the generation limit "
                                          r"of 50 joints"):
        Robot(joints=10**12)  # a per-link tuple of 10^12 floats would never finish
    assert time.perf_counter() - t0 < 1.0


def test_generation_limit_is_configurable(monkeypatch):
    monkeypatch.setenv("SNAKECG_MAX_JOINTS", "40")
    assert Robot(joints=35).n_links == 36
    monkeypatch.setenv("SNAKECG_MAX_JOINTS", "3")
    with pytest.raises(InputError, match=r"joints=4 exceeds the generation limit of 3 joints"):
        Robot(joints=4)
    for bad in ("0", "-1", "x", "2.5"):
        monkeypatch.setenv("SNAKECG_MAX_JOINTS", bad)
        with pytest.raises(InputError, match=rf"SNAKECG_MAX_JOINTS must be a positive integer, "
                                             rf"got '{bad}'"):
            Robot(joints=2)


def test_load_refuses_beyond_the_limit_without_generating(monkeypatch, tmp_path):
    """A robot made under a higher limit is still refused by load() (no derivation)."""
    robot = Robot(joints=12)
    monkeypatch.setenv("SNAKECG_MAX_JOINTS", "8")
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(tmp_path / "cache"))
    t0 = time.perf_counter()
    with pytest.raises(InputError, match=r"joints=12 exceeds the generation limit of 8 joints"):
        snakecg.load(robot)
    assert time.perf_counter() - t0 < 5.0
    assert not (tmp_path / "cache" / "models").exists()
