"""Progress on every stream (snakecg.progress): a generation or a compilation prints one line
when it starts and one when it ends, with its duration, whatever standard error is (here a
capture, as in a pipe, a log or a notebook's captured output); quiet only when asked
(``progress=False``, ``--quiet``, ``SNAKECG_PROGRESS=0``).

The compiler and the generator are replaced by quick stand-ins that write what the real ones
would (the compiled library's bytes are never loaded; the packaged model stands for a
generated one), so the lines are checked without a 15-60 s build.
"""

from __future__ import annotations

import os
import re
import shutil
import sys
from pathlib import Path

import pytest

from snakecg import artifacts, native, progress
from snakecg.errors import BuildError

LINE = re.compile(r"^snakecg \[ *\d+\.\d s\] (?P<msg>.*)$")


class _Captured:
    """Standard error as pytest captures it (no terminal): ``getvalue()`` so far."""

    def __init__(self, capsys):
        self.capsys, self.text = capsys, ""

    def getvalue(self) -> str:
        self.text += self.capsys.readouterr().err
        return self.text


@pytest.fixture
def stderr(capsys, monkeypatch):
    """Standard error not a terminal, progress not forced either way."""
    monkeypatch.delenv("SNAKECG_PROGRESS", raising=False)
    assert not sys.stderr.isatty()
    return _Captured(capsys)


@pytest.fixture
def fresh_cache(tmp_path, monkeypatch):
    cache = tmp_path / "cache"
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(cache))
    monkeypatch.setattr(artifacts, "_reported", set())
    monkeypatch.setattr(native, "_warned", set())
    return cache


def _messages(text: str) -> list[str]:
    lines = text.splitlines()
    assert all(LINE.match(ln) for ln in lines), lines
    return [LINE.match(ln).group("msg") for ln in lines]


def _fake_compiler(monkeypatch, fail_on=None):
    """``native._run`` writing the file after ``-o`` (a compile or the link), or failing on
    the command that names ``fail_on``."""
    def run(cmd):
        if fail_on is not None and any(fail_on in str(c) for c in cmd):
            raise BuildError(f"C compiler failed (exit 1): {' '.join(map(str, cmd))}",
                             command=cmd)
        Path(cmd[cmd.index("-o") + 1]).write_bytes(b"\0")

    monkeypatch.setattr(native, "_run", run)


def test_step_lines_go_to_every_stream_bars_only_to_a_terminal(stderr, monkeypatch):
    step = progress.resolve(None)
    assert callable(step) and not progress.progress_enabled()  # no terminal: no bars
    step("compiling")
    assert _messages(stderr.getvalue()) == ["compiling"]
    assert progress.resolve(False) is None
    monkeypatch.setenv("SNAKECG_PROGRESS", "0")
    assert progress.resolve(None) is None and progress.progress_reporter() is None


def test_stage_says_start_end_and_failure():
    said = []
    with progress.stage(said.append, "deriving", "derived"):
        pass
    assert said[0] == "deriving" and re.fullmatch(r"derived in \d+\.\d s", said[1])
    said.clear()
    with pytest.raises(ZeroDivisionError), progress.stage(said.append, "deriving", "derived"):
        1 / 0
    assert said[0] == "deriving" and re.fullmatch(r"deriving: failed after \d+\.\d s", said[1])
    with progress.stage(None, "x", "y"):  # quiet: nothing to call
        pass


def test_a_compile_prints_its_start_and_its_end_off_a_terminal(stderr, fresh_cache,
                                                               monkeypatch):
    _fake_compiler(monkeypatch)
    folder, manifest = artifacts.model_dir(1)
    lib = native.compile_model(folder, manifest, progress=progress.resolve(None))
    assert lib.is_file()
    said = _messages(stderr.getvalue())
    assert len(said) == 2, said
    assert re.fullmatch(r"compiling the 1-joint model: \d+ C files with \S+ -O2 \(once; the "
                        r"library is cached\)", said[0]), said[0]
    assert re.fullmatch(r"compiled the 1-joint model in \d+\.\d s", said[1]), said[1]
    # cached: nothing more to say
    native.compile_model(folder, manifest, progress=progress.resolve(None))
    assert len(_messages(stderr.getvalue())) == 2


def test_a_failed_compile_says_so(stderr, fresh_cache, monkeypatch):
    _fake_compiler(monkeypatch, fail_on="-shared")  # the link fails
    folder, manifest = artifacts.model_dir(1)
    with pytest.raises(BuildError):
        native.compile_model(folder, manifest, progress=progress.resolve(None))
    said = _messages(stderr.getvalue())
    assert said[0].startswith("compiling the 1-joint model")
    assert re.fullmatch(r"compiling the 1-joint model: failed after \d+\.\d s", said[1])


def test_a_generation_prints_its_start_and_its_end(stderr, fresh_cache, monkeypatch):
    import snakecg_derive.render as render

    packaged = artifacts._packaged(1)  # the installed snakecg_generated's folder
    assert packaged is not None and packaged.is_dir()
    monkeypatch.setattr(artifacts, "_packaged", lambda n: None)

    def render_model(n, *, progress=None, max_joints=None):
        progress("deriving the model of a 1-joint snake (SymPy)")
        return n

    def write_model(n, root):  # the packaged model stands for the generated one
        shutil.copytree(packaged, Path(root) / f"na{n}")

    monkeypatch.setattr(render, "render_model", render_model)
    monkeypatch.setattr(render, "write_model", write_model)
    artifacts.model_dir(1, progress=progress.resolve(None))
    said = _messages(stderr.getvalue())
    assert said[0] == "generating the 1-joint model (once; kept in the cache)"
    assert said[1] == "deriving the model of a 1-joint snake (SymPy)"
    assert re.fullmatch(r"generated the 1-joint model in \d+\.\d s", said[2]) and len(said) == 3


def test_quiet_silences_a_command_and_only_it(monkeypatch):
    import snakecg.commands.show as show
    from snakecg.cli import main

    monkeypatch.delenv("SNAKECG_PROGRESS", raising=False)
    seen = {}

    def run(args):
        seen["reporter"] = progress.progress_reporter()
        seen["env"] = os.environ.get("SNAKECG_PROGRESS")
        return 0

    monkeypatch.setattr(show, "run", run)
    assert main(["show", "--joints", "1", "--quiet", "M"]) == 0
    assert seen == {"reporter": None, "env": "0"}
    assert "SNAKECG_PROGRESS" not in os.environ  # restored after the command
    assert main(["show", "--joints", "1", "M"]) == 0
    assert callable(seen["reporter"])


def test_progress_false_prints_nothing(stderr, fresh_cache, monkeypatch):
    _fake_compiler(monkeypatch)
    folder, manifest = artifacts.model_dir(1)
    native.compile_model(folder, manifest, progress=progress.resolve(False))
    assert stderr.getvalue() == ""
