"""Sweeps on Dask into Zarr (snakecg.sweep, `snakecg sweep`).

A local cluster of 2 worker processes on the loopback interface serves the module. The
reference is the package's in-process batch evaluation, ``model.extremes(Q)`` and
``model.com_polar(Q)`` on the same configurations built here independently (NumPy meshgrid);
the distributed, chunked, resumed path must reproduce it to 1e-12, and a run interrupted by a
killed process or a killed worker must end bit for bit equal to an uninterrupted one.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import distributed  # the sweep extra's dependencies are in the test extra too
import zarr

import snakecg
from snakecg.analysis import METRICS
from snakecg.cli import main
from snakecg.sweeps import read
from snakecg.sweeps.plan import joint_values

ROOT = Path(__file__).resolve().parents[1]
DEG = np.pi / 180


@pytest.fixture(scope="module")
def client():
    """2 worker processes on 127.0.0.1, started as snakecg.sweep starts its own."""
    from snakecg.sweeps.cluster import connect

    c, close = connect(workers=2)
    assert isinstance(c, distributed.Client)
    assert all(a.startswith("tcp://127.0.0.1:") for a in c.scheduler_info()["workers"])
    try:
        yield c
    finally:
        close()


def scene(scenario, joints=2):
    return snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario)


def mesh(*values):
    """Configurations (N, n_a + 3) of the Cartesian product, last joint fastest."""
    g = np.meshgrid(*values, indexing="ij")
    joints = np.stack([x.ravel() for x in g], axis=1)
    return np.hstack([np.zeros((joints.shape[0], 3)), joints])


def reference(sc, Q):
    model = snakecg.load(sc)
    ex = model.extremes(Q)
    radius, angle = model.com_polar(Q)
    out = {"q": Q[:, 3:], "com_radius": radius, "com_angle": angle}
    for m in METRICS:
        out[f"max_{m}"] = ex.max[m]
        out[f"tau_max_{m}"] = ex.tau_max[m]
        out[f"min_kept_{m}"] = ex.min_kept[m]
        out[f"tau_min_kept_{m}"] = ex.tau_min_kept[m]
    return out


def assert_matches(data, ref, tol=1e-12):
    assert data["complete"].all()
    for k, v in ref.items():
        scale = max(float(np.max(np.abs(v))), 1e-300)
        np.testing.assert_allclose(data[k], v, rtol=tol, atol=tol * scale, err_msg=k)


def assert_identical(a, b):
    for k in a:
        np.testing.assert_array_equal(a[k], b[k], err_msg=k)


# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("scenario", snakecg.SCENARIOS)
def test_grid_sweep_equals_model_extremes(client, tmp_path, scenario):
    """Every array of the store equals the in-process batch evaluation, per joint grid with
    its own range and step, chunks that do not divide the grid."""
    v1 = np.arange(-135, 136, 30) * DEG          # 10 values
    v2 = np.arange(-120, 121, 40) * DEG          # 7 values
    sc = scene(scenario)
    res = snakecg.sweep(sc, grid=[v1, v2], store=tmp_path / "s.zarr", client=client,
                        chunk=16, progress=False)
    assert (res.configurations, res.chunks, res.computed_chunks) == (70, 5, 5)
    data = read(tmp_path / "s.zarr")
    assert_matches(data, reference(sc, mesh(v1, v2)))
    attrs = dict(zarr.open_group(str(tmp_path / "s.zarr"), mode="r").attrs)
    assert attrs["complete"] is True and attrs["completed_chunks"] == 5
    assert attrs["snakecg_sweep"]["scene"]["scenario"] == scenario
    assert attrs["snakecg_sweep"]["version"] == snakecg.__version__


def test_samples_are_seeded_and_independent_of_the_chunking(client, tmp_path):
    sc = scene("ideal_wheels", joints=3)
    bounds = [(-1.0, 1.0), (-2.0, 0.5), (0.0, 2.3)]
    snakecg.sweep(sc, samples=300, seed=7, bounds=bounds, store=tmp_path / "a.zarr",
                  client=client, chunk=128, progress=False)
    snakecg.sweep(sc, samples=300, seed=7, bounds=bounds, store=tmp_path / "b.zarr",
                  client=client, chunk=100, progress=False)
    a, b = read(tmp_path / "a.zarr"), read(tmp_path / "b.zarr")
    np.testing.assert_array_equal(a["q"], b["q"])
    lo, hi = np.array(bounds).T
    assert np.all((a["q"] >= lo) & (a["q"] <= hi))
    # uniform: each joint's sample mean within 4 standard errors of the box's middle
    se = (hi - lo) / np.sqrt(12 * 300)
    assert np.all(np.abs(a["q"].mean(axis=0) - (lo + hi) / 2) < 4 * se)
    Q = np.hstack([np.zeros((300, 3)), a["q"]])
    assert_matches(a, reference(sc, Q))
    other = snakecg.sweep(sc, samples=300, seed=8, bounds=bounds, store=tmp_path / "c.zarr",
                          client=client, chunk=128, progress=False)
    assert other.configurations == 300
    assert not np.array_equal(read(tmp_path / "c.zarr")["q"], a["q"])


# ------------------------------------------------------------------------------------------
# Interruptions: the wheels grid of the paper for 2 joints (784 configurations), 49 chunks.
WHEELS_GRID = dict(grid=joint_values(-135, 135, 10), chunk=16)


@pytest.fixture(scope="module")
def uninterrupted(client, tmp_path_factory):
    path = tmp_path_factory.mktemp("sweep") / "whole.zarr"
    res = snakecg.sweep(scene("wheels"), store=path, client=client, progress=False,
                        **WHEELS_GRID)
    assert res.computed_chunks == res.chunks == 49
    return read(path)


def test_uninterrupted_wheels_sweep_equals_model_extremes(uninterrupted):
    v = np.arange(-135, 136, 10) * DEG
    assert_matches(uninterrupted, reference(scene("wheels"), mesh(v, v)))


def test_killed_sweep_resumes_with_identical_results(client, tmp_path, uninterrupted):
    import psutil

    store = tmp_path / "killed.zarr"
    argv = [sys.executable, "-m", "snakecg.cli", "sweep", "--joints", "2", "--scenario",
            "wheels", "--range", "135", "--step", "10", "--chunk", "16", "--workers", "2",
            "--out", str(store)]
    env = dict(os.environ, SNAKECG_PROGRESS="", PYTHONUNBUFFERED="1")
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True, env=env, cwd=ROOT, start_new_session=True)
    try:
        line = proc.stderr.readline()  # the first tenth is written
        assert "snakecg sweep:" in line and "%" in line, line
        family = [proc] + psutil.Process(proc.pid).children(recursive=True)
    finally:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait(timeout=30)
        proc.stderr.close()
    for p in family[1:]:  # the local cluster's processes we started go too
        try:
            p.kill()
        except psutil.NoSuchProcess:
            pass
    digests = zarr.open_group(str(store), mode="r")["chunk_digest"][:]
    done = int(np.count_nonzero(digests))
    assert 0 < done < 49, done
    res = snakecg.sweep(scene("wheels"), store=store, client=client, progress=False,
                        **WHEELS_GRID)
    assert res.reused_chunks >= done - 1 and res.reused_chunks + res.computed_chunks == 49
    assert res.computed_chunks >= 1
    assert_identical(read(store), uninterrupted)
    again = snakecg.sweep(scene("wheels"), store=store, client=client, progress=False,
                          **WHEELS_GRID)
    assert (again.computed_chunks, again.reused_chunks) == (0, 49)


def test_a_damaged_chunk_is_detected_and_computed_again(client, tmp_path, uninterrupted):
    store = tmp_path / "damaged.zarr"
    snakecg.sweep(scene("wheels"), store=store, client=client, progress=False, **WHEELS_GRID)
    # a chunk file of one array overwritten behind the sweep's back (its digest stays)
    root = zarr.open_group(str(store), mode="r+")
    root["max_sr"][16:32] = 0.5
    res = snakecg.sweep(scene("wheels"), store=store, client=client, progress=False,
                        **WHEELS_GRID)
    assert (res.computed_chunks, res.reused_chunks) == (1, 48)
    assert_identical(read(store), uninterrupted)


def test_killed_worker_the_sweep_completes_identically(client, tmp_path, uninterrupted):
    store = tmp_path / "worker.zarr"
    before = client.run(os.getpid)
    box = {}

    def run():
        try:
            box["res"] = snakecg.sweep(scene("wheels"), store=store, client=client,
                                       progress=False, **WHEELS_GRID)
        except BaseException as exc:  # noqa: BLE001 - reported below
            box["err"] = exc

    t = threading.Thread(target=run)
    t.start()
    victim = None
    deadline = time.monotonic() + 120
    while victim is None and time.monotonic() < deadline and t.is_alive():
        time.sleep(0.05)
        if not (store / "zarr.json").exists():
            continue
        done = np.count_nonzero(zarr.open_group(str(store), mode="r")["chunk_digest"][:])
        busy = [w for w, keys in client.processing().items() if keys]
        if done >= 2 and busy:
            victim = busy[0]
            os.kill(before[victim], signal.SIGKILL)
    t.join(timeout=300)
    assert victim is not None, "the sweep ended before a worker could be killed"
    assert "err" not in box, box.get("err")
    assert box["res"].computed_chunks == 49
    assert_identical(read(store), uninterrupted)
    after = client.run(os.getpid)
    assert before[victim] not in after.values()  # the worker was replaced by its nanny


# ------------------------------------------------------------------------------------------
def test_mismatched_store_is_refused_and_left_untouched(client, tmp_path, capsys):
    store = tmp_path / "m.zarr"
    sc = scene("frictionless")
    grid = joint_values(-90, 90, 30)
    snakecg.sweep(sc, grid=grid, store=store, client=client, chunk=10, progress=False)
    files = {p: p.stat().st_mtime_ns for p in store.rglob("*")}
    for kwargs, key in (
            ({"grid": grid, "chunk": 10, "scene": sc.replace(kappa=10.0)}, "scene"),
            ({"grid": grid, "chunk": 7, "scene": sc}, "chunk"),
            ({"grid": joint_values(-90, 90, 15), "chunk": 10, "scene": sc}, "configurations"),
            ({"samples": 49, "seed": 1, "chunk": 10, "scene": sc}, "configurations")):
        s = kwargs.pop("scene")
        with pytest.raises(snakecg.InputError, match="made with other arguments") as e:
            snakecg.sweep(s, store=store, client=client, progress=False, **kwargs)
        assert key in str(e.value)
    assert {p: p.stat().st_mtime_ns for p in store.rglob("*")} == files
    code = main(["sweep", "--joints", "2", "--scenario", "wheels", "--range", "90",
                 "--step", "30", "--chunk", "10", "--out", str(store),
                 "--scheduler", client.scheduler.address])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "other arguments" in err


def _one_line_error(capsys, argv, fragment):
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2, (argv, err)
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert err.startswith("snakecg sweep: error:") and fragment in err, err
    return err


def test_bad_arguments_are_one_line_errors_and_write_nothing(tmp_path, capsys, monkeypatch):
    from snakecg.sweeps import cluster

    monkeypatch.setattr(cluster, "CONNECT_TIMEOUT", 1.0)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a-file").write_text("x")
    (tmp_path / "plain-folder").mkdir()
    out = ["--out", "new.zarr"]
    cases = [
        (["--joints", "2", "--range=10:0"] + out, "zero points"),
        (["--joints", "2", "--step", "0"] + out, "step must be > 0"),
        (["--joints", "2", "--step", "10,10,10"] + out, "expected one or 2"),
        (["--joints", "2", "--range", "abc"] + out, "numbers of degrees"),
        (["--joints", "2", "--samples", "5"] + out, "--seed"),
        (["--joints", "2", "--seed", "5"] + out, "--samples"),
        (["--joints", "2", "--samples", "0", "--seed", "1"] + out, "samples must be"),
        (["--joints", "2", "--samples", "5", "--seed", "1", "--step", "5"] + out, "one of"),
        (["--joints", "3"] + out + ["--limit", "1000"], "exceed the limit of 1,000"),
        (["--joints", "2", "--chunk", "0"] + out, "chunk must be"),
        (["--joints", "2"] + out + ["--workers", "0"], "workers must be"),
        (["--joints", "2"] + out + ["--scheduler", "foo://host:1"], "unknown scheduler"),
        (["--joints", "2"] + out + ["--scheduler", "tcp://127.0.0.1:9"], "cannot reach"),
        (["--joints", "2", "--out", "a-file/new.zarr"], "does not exist"),
        (["--joints", "2", "--out", "a-file"], "is a file"),
        (["--joints", "2", "--out", "plain-folder"], "not a Zarr store"),
        (["--joints", "2", "--out", "missing/new.zarr"], "does not exist"),
        (["--joints", "2"], "--out STORE is required"),
        (["--summary", "plain-folder"], "not a sweep store"),
        (["--figure", "new.zarr"], "not a sweep store"),
        (["--summary", "x.zarr", "--joints", "2"], "read everything from the store"),
    ]
    for argv, fragment in cases:
        _one_line_error(capsys, ["sweep"] + argv, fragment)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a-file", "plain-folder"]
    assert list((tmp_path / "plain-folder").iterdir()) == []
    with pytest.raises(snakecg.InputError, match="grid of joint 2 has no values"):
        snakecg.sweep(scene("wheels"), grid=[[0.0], []], store=tmp_path / "g.zarr")
    with pytest.raises(snakecg.InputError, match="give grid or samples"):
        snakecg.sweep(scene("wheels"), grid=[0.0], samples=3, seed=1,
                      store=tmp_path / "g.zarr")
    assert not (tmp_path / "g.zarr").exists()


def test_cli_json_force_summary_and_figure(client, tmp_path, capsys):
    """The CLI on a running cluster (--scheduler): strict JSON, --force above the limit,
    the summary checked against NumPy on the in-memory reference, the figure rendered."""
    from PIL import Image

    store = tmp_path / "w.zarr"
    argv = ["sweep", "--joints", "2", "--scenario", "wheels", "--range=-135:135,-90:90",
            "--step", "20,30", "--chunk", "20", "--out", str(store), "--scheduler",
            client.scheduler.address, "--json"]
    _one_line_error(capsys, argv + ["--limit", "50"], "exceed the limit of 50")
    assert main(argv + ["--limit", "50", "--force"]) == 0
    out = json.loads(capsys.readouterr().out, parse_constant=pytest.fail)
    assert out["schema"] == "snakecg.sweep/1"
    assert (out["configurations"], out["chunks"], out["computed_chunks"]) == (98, 5, 5)
    v1, v2 = np.arange(-135, 136, 20) * DEG, np.arange(-90, 91, 30) * DEG
    ref = reference(scene("wheels"), mesh(v1, v2))

    assert main(["sweep", "--summary", str(store), "--json"]) == 0
    s = json.loads(capsys.readouterr().out, parse_constant=pytest.fail)
    assert s["complete"] and s["summarized_configurations"] == 98
    for m in METRICS:
        v = ref[f"max_{m}"]
        for kind, i in (("worst", int(np.argmin(v))), ("best", int(np.argmax(v)))):
            e = s["metrics"][m][kind]
            assert e["value"] == pytest.approx(v[i], rel=1e-12)
            assert e["index"] == i
            np.testing.assert_allclose(e["q_deg"], np.rad2deg(ref["q"][i]), atol=1e-9)
            np.testing.assert_allclose(e["tau"], ref[f"tau_max_{m}"][i], atol=1e-12)
    assert main(["sweep", "--summary", str(store)]) == 0
    text = capsys.readouterr().out
    assert "worst" in text and "sr" in text

    assert main(["sweep", "--figure", str(store)]) == 0
    png = Path(capsys.readouterr().out.strip())
    assert png == tmp_path / "w-polar.png"
    with Image.open(png) as im:
        assert im.size[0] > 600 and im.size[1] > 600
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".partial")]


def test_progress_lines_and_dask_bar(client, tmp_path, capsys):
    grid = joint_values(-135, 135, 30)
    snakecg.sweep(scene("frictionless"), grid=grid, store=tmp_path / "l.zarr", client=client,
                  chunk=10, progress="lines")
    err = [x for x in capsys.readouterr().err.splitlines() if "%" in x]
    assert len(err) == 10 and err[-1].startswith("snakecg sweep: 100% (10/10 chunks")
    snakecg.sweep(scene("frictionless"), grid=grid, store=tmp_path / "b.zarr", client=client,
                  chunk=10, progress="bar")
    time.sleep(0.5)  # the bar draws from the client's event loop
    assert "% Completed" in capsys.readouterr().err


def test_import_snakecg_does_not_import_dask():
    code = ("import sys, snakecg; assert 'distributed' not in sys.modules and 'zarr' not in "
            "sys.modules; snakecg.sweep; assert 'distributed' not in sys.modules")
    subprocess.run([sys.executable, "-c", code], check=True, cwd=ROOT)
