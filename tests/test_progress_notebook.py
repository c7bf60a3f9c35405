"""Progress in a notebook (standard error is no terminal there, but it is shown), model builds
reported by ``snakecg.load`` by default, and ``model.extremes`` in chunks with a bar, giving
exactly the numbers of the single call."""

from __future__ import annotations

import io
import sys
import types

import numpy as np
import pytest

import snakecg
import snakecg.robot_model
from snakecg import progress


@pytest.fixture
def fake_notebook(monkeypatch):
    """An IPython module whose shell has a kernel, as in Jupyter; stderr a non-terminal."""
    shell = types.SimpleNamespace(kernel=object(), config={"IPKernelApp": {}})
    monkeypatch.setitem(sys.modules, "IPython",
                        types.SimpleNamespace(get_ipython=lambda: shell))
    monkeypatch.delenv("SNAKECG_PROGRESS", raising=False)

    def stderr():  # pytest sets sys.stderr per phase: replace it inside the test itself
        err = io.StringIO()
        monkeypatch.setattr(sys, "stderr", err)
        return err

    return stderr


def test_off_a_terminal_and_outside_a_notebook_bars_are_off_and_steps_print(monkeypatch):
    monkeypatch.delenv("SNAKECG_PROGRESS", raising=False)
    err = io.StringIO()
    monkeypatch.setattr(sys, "stderr", err)
    shell = types.SimpleNamespace(config={})  # plain IPython in a terminal: no kernel
    monkeypatch.setitem(sys.modules, "IPython", types.SimpleNamespace(get_ipython=lambda: shell))
    assert not progress.in_notebook() and not progress.progress_enabled()
    progress.resolve(None)("compiling 13 C files")  # step lines go to every stream
    assert err.getvalue().endswith("compiling 13 C files\n")


def test_a_notebook_shows_steps_and_bars(fake_notebook, monkeypatch):
    err = fake_notebook()
    assert progress.in_notebook() and progress.progress_enabled()
    step = progress.resolve(None)
    step("compiling 13 C files")
    assert "compiling 13 C files" in err.getvalue()
    assert progress.resolve(False) is None
    import tqdm.notebook

    monkeypatch.setattr(tqdm.notebook, "IProgress", None)  # no ipywidgets: the text bar
    bar = progress.progress_bar(3, "sweep")
    bar.update(3)
    bar.close()
    assert "sweep" in err.getvalue()
    monkeypatch.setenv("SNAKECG_PROGRESS", "0")
    assert not progress.progress_enabled()


def test_load_reports_builds_by_default(fake_notebook, monkeypatch):

    fake_notebook()
    seen = []
    original = snakecg.robot_model._backend

    def spy(n_joints, prefer, progress=None):
        seen.append(progress)
        return original(n_joints, prefer, progress)

    monkeypatch.setattr(snakecg.robot_model, "_backend", spy)
    snakecg.load(snakecg.Robot(joints=1))
    snakecg.load(snakecg.Robot(joints=1), progress=False)
    assert callable(seen[0]) and seen[1] is None


def test_extremes_in_chunks_equal_one_call(monkeypatch, capsys, rng):
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels"))
    Q = np.zeros((300, 5))
    Q[:, 3:] = rng.uniform(-2.5, 2.5, (300, 2))
    monkeypatch.setenv("SNAKECG_PROGRESS", "0")
    whole = model.extremes(Q)
    monkeypatch.setenv("SNAKECG_PROGRESS", "1")
    chunked = model.extremes(Q)
    assert "extremes" in capsys.readouterr().err
    for attr in ("max", "min", "tau_max", "tau_min", "min_kept", "tau_min_kept"):
        a, b = getattr(whole, attr), getattr(chunked, attr)
        assert a.keys() == b.keys()
        for k in a:
            assert a[k].shape[0] == 300
            np.testing.assert_array_equal(a[k], b[k])
    assert chunked.method == whole.method
