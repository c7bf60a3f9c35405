"""Ctrl-C during a long simulation, and the compiled calls that make it possible.

The compiled segments and whole runs (``core_integrate_segment``, ``core_run``) return to
Python after a wall-clock budget (``snakecg.engine.segment.PAUSE_AFTER``) and are called again
to go on where they stopped, so that Python can raise KeyboardInterrupt in between:

* a run whose every C call pauses after one step (or one chunk of samples) gives the same
  trajectory, bit for bit, as the run that never paused (the reference: the same run
  uninterrupted), events and samples included, on the whole-run path and the per-segment
  path (a held torque law);
* SIGINT sent to ``snakecg simulate`` inside a run that would go on for hours (a torque of
  1e20 N m) ends it with one line on standard error and exit status 130; sent to a Python
  process inside ``model.simulate`` it raises KeyboardInterrupt there.
"""

from __future__ import annotations

import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import snakecg
import snakecg.simulate.compiled as compiled

Q3 = np.array([0.0, 0.0, 0.0, 0.5, -0.6, 0.4])
TAU3 = np.array([0.05, 0.0, -0.02])
FIELDS = ("t", "q", "v", "q_obj", "v_obj", "lam", "qdd", "sr", "gap", "work_tau",
          "work_friction", "kinetic_energy")


@pytest.fixture(scope="module")
def wheels():
    return snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=10.0))


def _hard_push(sm, radius=4.0):
    """A push on the input ellipsoid (eq. 31) of radius 4: wheels break away and stick."""
    direction = np.array([1.0, 0.0, -0.4])
    N = sm.maps(Q3)["input_metric"]
    tau = radius * direction / np.sqrt(direction @ N @ direction)
    return tau if sm.forward(Q3, tau).contact else -tau


def _same_run(a, b):
    assert [(e.kind, e.row, e.t) for e in a.events] == [(e.kind, e.row, e.t) for e in b.events]
    for field in FIELDS:
        np.testing.assert_array_equal(getattr(a, field), getattr(b, field), err_msg=field)
    assert a.summary["status"] == b.summary["status"]
    assert a.summary["violation"] == b.summary["violation"]


@pytest.mark.parametrize("path", ["whole run", "segments"])
def test_paused_calls_give_the_uninterrupted_run(wheels, monkeypatch, path):
    tau = _hard_push(wheels)
    # (the push turns the contact link into the object within milliseconds: the contact
    # check records that and the run goes on, as it did before the check existed)
    kw = {"output_dt": 0.005, "geometry_check": "report"}
    if path == "segments":  # a held law: the Python loop, one compiled segment at a time
        kw["control_period"] = 0.05
        law = lambda t: tau * (1.0 - t)  # noqa: E731
    else:
        law = tau
    plain = wheels.simulate(Q3, law, 0.4, **kw)
    assert plain.events, "the case must have events"
    monkeypatch.setattr(compiled, "PAUSE_AFTER", 1e-12)  # every call stops after one step
    calls = []
    real_take = compiled.take

    def counting_take(model):
        ws = real_take(model)
        for key in ("_fn", "_run"):
            fn = ws.shared[key]
            ws.shared[key] = lambda address, fn=fn, key=key: calls.append(key) or fn(address)
        return ws

    monkeypatch.setattr(compiled, "take", counting_take)
    try:
        paused = wheels.simulate(Q3, law, 0.4, **kw)
    finally:
        wheels.data().simulation_pool.clear()  # no counting workspace left for later runs
    assert paused.summary["integrator"]["compiled_segments"]
    steps = plain.summary["integrator"]["rhs_evaluations"] // 12
    assert len(calls) > steps // 2, (len(calls), steps)  # it did stop and go on, many times
    _same_run(plain, paused)


def _ready_process(code: str, *args: str) -> subprocess.Popen:
    """``python -c code args`` with SIGINT at its default (Python installs its handler),
    started once it has printed its first line (imports done)."""
    proc = subprocess.Popen(
        [sys.executable, "-c", code, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        text=True, preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    assert proc.stdout.readline().strip() == "ready", proc.communicate(timeout=60)
    time.sleep(2.0)  # into the integration (the model is compiled already: see the callers)
    assert proc.poll() is None, proc.communicate()
    return proc


def test_sigint_ends_the_command_with_status_130(tmp_path):
    snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))  # compiled in the shared cache
    code = ("import sys; import snakecg.cli as cli; print('ready', flush=True); "
            "sys.exit(cli.main(sys.argv[1:]))")
    proc = _ready_process(code, "simulate", "--joints", "2", "--q", "0,0,0,0.3,0.3",
                          "--tau", "1e20,1e20", "--geometry-check", "report", "--no-figures", "--out", str(tmp_path / "o"))
    proc.send_signal(signal.SIGINT)
    try:
        _, err = proc.communicate(timeout=30)  # a hang guard: it ends well before
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    assert proc.returncode == 130, err
    assert err == "snakecg simulate: interrupted\n"
    assert not (tmp_path / "o").exists()


def test_sigint_raises_keyboard_interrupt_in_simulate():
    snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))
    code = """
import numpy as np, snakecg
sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))
print('ready', flush=True)
try:
    sm.simulate(np.array([0, 0, 0, 0.3, 0.3]), np.array([0.01, 0.0]), 1e4, geometry_check="report")
except KeyboardInterrupt:
    print('KeyboardInterrupt', flush=True)
else:
    print('finished', flush=True)
"""
    proc = _ready_process(code)
    proc.send_signal(signal.SIGINT)
    try:
        out, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    assert out.strip() == "KeyboardInterrupt", (out, err)
    assert proc.returncode == 0, err


def test_an_interrupt_while_a_dask_cluster_starts_prints_one_line():
    """A Ctrl-C that lands while `snakecg sweep` starts its local Dask cluster left the
    cluster half started, and distributed's exit hook then printed a 25-line traceback
    (AssertionError: Status.init) after the one line. Here such a cluster (one whose close
    raises that error) is registered, the command is interrupted, and the process ends with
    the one line and exit status 130; the hook still ran."""
    script = """
import sys, pathlib
from distributed.deploy.spec import SpecCluster
from distributed.core import Status
import snakecg, snakecg.cli

class HalfStarted:
    shutdown_on_close, status = True, Status.init
    def close(self, timeout=None):
        pathlib.Path(sys.argv[1]).write_text("closed")
        raise AssertionError(self.status)

held = HalfStarted()
SpecCluster._instances.add(held)
def interrupted(*args, **kwargs):
    raise KeyboardInterrupt
snakecg.load = interrupted
sys.exit(snakecg.cli.main(["forward", "--joints", "1", "--q", "0,0,0,0", "--tau", "0"]))
"""
    import tempfile
    from pathlib import Path

    mark = Path(tempfile.mkdtemp()) / "hook"
    p = subprocess.run([sys.executable, "-c", script, str(mark)], capture_output=True,
                       text=True, timeout=120)
    assert p.returncode == 130, p.stderr
    assert p.stderr.splitlines() == ["snakecg forward: interrupted"], p.stderr
    assert mark.read_text() == "closed"
