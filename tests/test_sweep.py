"""Sweeps on Dask into Zarr (snakecg.sweep, `snakecg sweep`).

A local cluster of 2 worker processes on the loopback interface (TLS, as snakecg.sweep starts
its own) serves the module; a plain-TCP cluster in threads stands for a cluster started by
hand for the --scheduler tests. The
reference is the package's in-process batch evaluation, ``model.extremes(Q)`` and
``model.com_polar(Q)`` on the same configurations built here independently (NumPy meshgrid);
the distributed, chunked, resumed path must reproduce it to 1e-12, and a run interrupted by a
killed process or a killed worker must end bit for bit equal to an uninterrupted one.
"""

from __future__ import annotations

import hashlib
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
import xxhash
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
    assert all(a.startswith("tls://127.0.0.1:") for a in c.scheduler_info()["workers"])
    try:
        yield c
    finally:
        close()


@pytest.fixture(scope="module")
def tcp_scheduler():
    """The address of a plain-TCP Dask scheduler with one worker thread, as a cluster started
    by hand with `dask scheduler` and `dask worker` (what --scheduler connects to)."""
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  protocol="tcp://", host="127.0.0.1",
                                  dashboard_address=None) as cluster:
        yield cluster.scheduler_address


def recorded(store) -> int:
    """Chunks whose digests are all recorded, read with Zarr."""
    d = zarr.open_group(str(store), mode="r")["chunk_digest"][:]
    return int(np.count_nonzero((d != 0).all(axis=1)))


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


def test_a_chunk_larger_than_a_block_equals_the_whole_batch():
    """A chunk is evaluated in blocks of BLOCK configurations (cache-sized): the arrays are
    bit for bit those of one batch evaluation of the whole chunk (the last block partial)."""
    from snakecg.geometry import feasibility
    from snakecg.sweeps.work import BLOCK, evaluate

    sc = scene("frictionless")
    rng = np.random.default_rng(3)
    n = 2 * BLOCK + 123
    Q = np.hstack([np.zeros((n, 3)), rng.uniform(-2.3, 2.3, (n, 2))])
    got = evaluate(snakecg.load(sc), Q)
    ref = reference(sc, Q)
    ref["feasible"] = feasibility(snakecg.load(sc), Q).feasible
    assert set(got) == set(ref)
    for k, v in ref.items():
        assert got[k].shape == np.shape(v) and got[k].flags.c_contiguous
        np.testing.assert_array_equal(got[k], v, err_msg=k)


# ------------------------------------------------------------------------------------------
# The default chunk: about CHUNK_SECONDS of single-core work at the documented per-configuration
# costs, rounded to the nearest 2^k or 3 * 2^k, at most 16 MiB of results; expected values
# worked out by hand from the documented table (e.g. 3-joint wheels: 1.5 s / 115 us = 13,043
# -> 12,288; 4-joint frictionless: 1.5 s / 16 us = 93,750, cap 16 MiB / 369 B = 45,467 ->
# 32,768; 1-joint wheels: 1.5 s / 7.2 us = 208,333, cap 16 MiB / 153 B = 109,655 -> 98,304).
WHEELS_COST_US = {1: 7.2, 2: 20, 3: 115, 4: 960, 5: 2700, 6: 3700}


@pytest.mark.parametrize("scenario,expected", [
    ("wheels", {1: 98304, 2: 65536, 3: 12288, 4: 1536, 5: 512, 6: 384, 8: 128, 10: 48}),
    ("frictionless", {1: 98304, 2: 65536, 3: 49152, 4: 32768, 5: 32768, 6: 24576,
                      8: 16384, 10: 8192}),
    ("ideal_wheels", {1: 98304, 2: 65536, 3: 49152, 4: 32768, 5: 32768, 6: 24576,
                      8: 16384, 10: 8192})])
def test_default_chunk_rule(scenario, expected):
    from snakecg.sweeps import default_chunk
    from snakecg.sweeps.plan import MAX_CHUNK_BYTES

    assert {n: default_chunk(scenario, n) for n in expected} == expected
    for n in range(1, 51):
        c = default_chunk(scenario, n)
        assert c >= 1 and c * (8 * (9 * n + 10) + 1) <= MAX_CHUNK_BYTES, n
    if scenario == "wheels":  # 1 to 2 s of single-core work at the measured costs, where
        for n, us in WHEELS_COST_US.items():  # the byte cap does not bind (1 joint)
            seconds = default_chunk(scenario, n) * us * 1e-6
            assert 1.0 <= seconds <= 2.0 if n > 1 else seconds < 1.0, n
    # at most 65,536 chunks: the 28^6 grid of 6-joint wheels in chunks of
    # ceil(481,890,304 / 65,536) = 7,354
    assert default_chunk("wheels", 6, 28 ** 6) == 7354
    assert default_chunk("wheels", 6, 10 ** 6) == 384
    with pytest.raises(snakecg.InputError, match="scenario must be one of"):
        default_chunk("wheel", 3)
    with pytest.raises(snakecg.InputError, match="n_joints must be an integer"):
        default_chunk("wheels", 0)


@pytest.mark.parametrize("chunk,size,workers,expected,chunks", [
    (1536, 24576, 2, 1536, 16),   # 16 chunks already: 8 per worker, a multiple of 2
    (1536, 4608, 2, 576, 8),      # 3 chunks -> 4 per worker, 8 of 576
    (1536, 10752, 4, 672, 16),    # 7 chunks -> 16 of 672
    (12288, 21952, 2, 3659, 6),   # 8 would be below 12288 / 4 = 3072: 7 -> down to 6
    (1536, 2000, 2, 500, 4),      # at most 2000 // 384 = 5 chunks -> 4
    (65536, 784, 2, 784, 1),      # less than a quarter chunk: one chunk
    (1536, 4608, 1, 1536, 3),     # one worker: the default as it is
    (1536, 1000, 1, 1000, 1)])
def test_spread_chunk(chunk, size, workers, expected, chunks):
    from snakecg.sweeps.plan import spread_chunk

    got = spread_chunk(chunk, size, workers)
    assert (got, -(-size // got)) == (expected, chunks)


def test_default_chunk_sweep_spreads_and_resumes_with_its_own_chunk(client, tmp_path,
                                                                    monkeypatch,
                                                                    uninterrupted):
    """A new store without chunk: the default spread over the 2 workers; resumed without
    chunk after the default changed (here: back to the real one), it keeps its own chunk and
    computes only the missing chunks; the data equal model.extremes either way."""
    from snakecg.sweeps import plan as plan_mod

    # a default of 64 configurations for 2-joint wheels (64 * 20 us): the 784 grid is 13
    # chunks, raised to a multiple of the 2 workers: 14 chunks of 784 / 14 = 56
    monkeypatch.setattr(plan_mod, "CHUNK_SECONDS", 64 * 20e-6)
    assert plan_mod.default_chunk("wheels", 2) == 64
    store = tmp_path / "d.zarr"
    grid = joint_values(-135, 135, 10)
    res = snakecg.sweep(scene("wheels"), grid=grid, store=store, client=client,
                        progress=False)
    assert (res.chunk, res.chunks, res.computed_chunks) == (56, 14, 14)
    root = zarr.open_group(str(store), mode="r+")
    assert root["max_sr"].chunks == (56,) and root["tau_max_sr"].chunks == (56, 2)
    assert root.attrs["snakecg_sweep"]["chunk"] == 56
    data = read(store)
    assert_identical(data, uninterrupted)
    v = np.arange(-135, 136, 10) * DEG
    assert_matches(data, reference(scene("wheels"), mesh(v, v)))
    # the bytes of results per configuration of the rule's memory cap
    per = sum(root[k].nbytes for k in root.array_keys()
              if k not in ("chunk_digest", "joint")) / 784
    assert per == plan_mod.result_bytes(2)
    for i in (0, 5, 13):
        root["chunk_digest"][i] = 0
    monkeypatch.undo()
    assert plan_mod.default_chunk("wheels", 2) == 65536
    res = snakecg.sweep(scene("wheels"), grid=grid, store=store, client=client,
                        progress=False)
    assert (res.chunk, res.computed_chunks, res.reused_chunks) == (56, 3, 11)
    assert_identical(read(store), uninterrupted)
    # an explicit other chunk is still refused
    with pytest.raises(snakecg.InputError, match="other arguments.*chunk"):
        snakecg.sweep(scene("wheels"), grid=grid, store=store, client=client, chunk=64,
                      progress=False)


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
            "--shared-store", "--out", str(store)]  # the workers write the data
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
    done = recorded(store)
    assert 0 < done < 49, done
    res = snakecg.sweep(scene("wheels"), store=store, client=client, progress=False,
                        **WHEELS_GRID)
    assert res.reused_chunks >= done - 1 and res.reused_chunks + res.computed_chunks == 49
    assert res.computed_chunks >= 1
    assert_identical(read(store), uninterrupted)
    again = snakecg.sweep(scene("wheels"), store=store, client=client, progress=False,
                          **WHEELS_GRID)
    assert (again.computed_chunks, again.reused_chunks) == (0, 49)
    # made with an explicit chunk, it resumes without one too (its own chunk size)
    again = snakecg.sweep(scene("wheels"), store=store, client=client, progress=False,
                          grid=WHEELS_GRID["grid"])
    assert (again.chunk, again.computed_chunks, again.reused_chunks) == (16, 0, 49)


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

    # chunks of 2 configurations: 392 tasks, so that the sweep lasts long enough to lose a
    # worker midway (a chunk of 16 takes a few milliseconds); the data do not depend on it
    grid = dict(WHEELS_GRID, chunk=2)

    def run():
        try:
            box["res"] = snakecg.sweep(scene("wheels"), store=store, client=client,
                                       progress=False, shared_store=True, **grid)
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
        done = recorded(store)
        busy = [w for w, keys in client.processing().items() if keys]
        if done >= 2 and busy:
            victim = busy[0]
            os.kill(before[victim], signal.SIGKILL)
    t.join(timeout=300)
    assert victim is not None, "the sweep ended before a worker could be killed"
    assert "err" not in box, box.get("err")
    assert box["res"].computed_chunks == 392
    assert_identical(read(store), uninterrupted)
    after = client.run(os.getpid)
    assert before[victim] not in after.values()  # the worker was replaced by its nanny


def test_workers_write_the_data_and_the_client_only_the_digests(client, tmp_path,
                                                                monkeypatch, uninterrupted):
    """shared_store=True: the workers write each chunk's data (this process never calls the
    data writer, it records the digests); False: this process writes everything; default,
    on this local cluster: the workers when they have a thread on every core. All stores
    equal the uninterrupted one bit for bit, hence model.extremes."""
    from snakecg.sweeps import store as store_mod

    calls = []
    real = store_mod.write_data
    monkeypatch.setattr(store_mod, "write_data",
                        lambda *a, **k: calls.append(a[1]) or real(*a, **k))
    res = snakecg.sweep(scene("wheels"), store=tmp_path / "w.zarr", client=client,
                        progress=False, shared_store=True, **WHEELS_GRID)
    assert res.computed_chunks == 49 and calls == []
    assert_identical(read(tmp_path / "w.zarr"), uninterrupted)
    res = snakecg.sweep(scene("wheels"), store=tmp_path / "c.zarr", client=client,
                        progress=False, shared_store=False, **WHEELS_GRID)
    assert res.computed_chunks == 49 and sorted(calls) == list(range(0, 784, 16))
    assert_identical(read(tmp_path / "c.zarr"), uninterrupted)
    calls.clear()
    snakecg.sweep(scene("wheels"), store=tmp_path / "d.zarr", client=client, progress=False,
                  **WHEELS_GRID)
    workers_write = sum(client.nthreads().values()) >= os.cpu_count()
    assert len(calls) == (0 if workers_write else 49)
    assert_identical(read(tmp_path / "d.zarr"), uninterrupted)
    # the digests recorded by this process are those of the files the workers wrote: the
    # documented digest, XXH3-64 of each array's chunk file as stored, low bit set
    for name in ("w.zarr", "c.zarr"):
        root = zarr.open_group(str(tmp_path / name), mode="r")
        for i in (0, 48):
            assert [int(x) for x in root["chunk_digest"][i]] == [
                _file_digest(tmp_path / name / k / "c" / str(i) / "0"
                             if k == "q" or k.startswith("tau_") else
                             tmp_path / name / k / "c" / str(i))
                for k in store_mod.array_names()]


def _file_digest(path) -> int:
    """The digest docs/how-to/sweep.md defines for a chunk file of a format-3 store."""
    return int.from_bytes(xxhash.xxh3_64(Path(path).read_bytes()).digest(), "little") | 1


def _documented_digest(arrays, start, stop, h) -> int:
    """The digest docs/how-to/sweep.md defines, from the arrays' bytes (copied, in the documented
    order) and the hash object ``h``."""
    for k in ("q", "com_radius", "com_angle",
              *(f"{p}{m}" for m in METRICS
                for p in ("max_", "tau_max_", "min_kept_", "tau_min_kept_")), "feasible"):
        part = arrays[k][start:stop]
        h.update((part.astype(np.uint8) if k == "feasible" else part).tobytes())
    return int.from_bytes(h.digest(), "little") | 1


def test_chunk_files_are_zarrs_own_encoding(tmp_path):
    """Every chunk is encoded here and handed to Zarr's store as bytes (the last, partial one
    padded with the fill value): every chunk file is byte for byte the file Zarr itself
    writes for the same values (Blosc-compressed in format 3 but for the torques), reads back
    equal through Zarr,
    and the digests returned are XXH3-64 of the files (2-D float, 1-D float with NaN, bool)."""
    from snakecg.sweeps import store as store_mod

    rng = np.random.default_rng(5)
    n, chunk, joints = 37, 16, 3
    arrays = {k: rng.normal(size=(n, joints)) if k == "q" or k.startswith("tau_")
              else rng.normal(size=n) for k in store_mod.array_names()}
    arrays["max_sr"][[3, 20]] = np.nan
    arrays["feasible"] = rng.random(n) < 0.5
    ours = store_mod.create(tmp_path / "ours.zarr", {"format": store_mod.FORMAT}, n, chunk,
                            joints)
    opened = store_mod.handles(ours)
    assert all(opened["specs"][k].blosc == (None if k.startswith("tau_") else
                                            ("lz4", 5, "bitshuffle"))
               for k in store_mod.array_names())
    theirs = store_mod.handles(store_mod.create(tmp_path / "theirs.zarr",
                                                {"format": store_mod.FORMAT}, n, chunk, joints))
    stored = dict(arrays, q=np.rad2deg(arrays["q"]))  # format 3 keeps degrees
    for i, (start, stop) in enumerate([(0, 16), (16, 32), (32, 37)]):
        part = {k: v[start:stop] for k, v in arrays.items()}
        got = store_mod.write_data(opened, start, stop, part)
        for k in store_mod.array_names():  # every chunk, also one of fill values only
            theirs[k].with_config({"write_empty_chunks": True})[start:stop] = \
                stored[k][start:stop]
        files = [tmp_path / "ours.zarr" / k / "c" / str(i) / ("0" if arrays[k].ndim == 2 else "")
                 for k in store_mod.array_names()]  # Path / "" is the path itself
        assert list(got) == [_file_digest(f) for f in files]
    for k in store_mod.array_names():
        files = sorted(p.relative_to(tmp_path / "ours.zarr" / k)
                       for p in (tmp_path / "ours.zarr" / k).rglob("*") if p.is_file())
        assert len(files) == 4, files  # zarr.json and three chunks
        for f in files:
            assert (tmp_path / "ours.zarr" / k / f).read_bytes() == \
                (tmp_path / "theirs.zarr" / k / f).read_bytes(), (k, f)
        np.testing.assert_array_equal(ours[k][:], stored[k], err_msg=k)


def test_digests_recorded_together_across_blocks_of_the_digest_array(tmp_path):
    """The digests of many chunks are written at once (one write per block of 4096 rows
    of chunk_digest, a row per chunk, one digest per array); the others stay 0."""
    from snakecg.sweeps import store as store_mod

    root = store_mod.create(tmp_path / "d.zarr", {"format": store_mod.FORMAT}, 9000, 1, 2)
    opened = store_mod.handles(root)
    k = len(store_mod.array_names())
    recorded_ = {i: tuple(range(d, d + k)) for i, d in
                 ((0, 3), (4095, 2**64 - k), (4096, 7), (8191, 11), (8999, 13))}
    store_mod.record(opened, recorded_)
    store_mod.record(opened, {})
    got = zarr.open_group(str(tmp_path / "d.zarr"), mode="r")["chunk_digest"][:]
    assert got.dtype == np.uint64 and got.shape == (9000, k)
    assert {int(i): tuple(int(x) for x in got[i])
            for i in np.flatnonzero(got.any(axis=1))} == recorded_


# ------------------------------------------------------------------------------------------
# Stores of earlier formats: tests/data/sweep-format2.zarr was made by the version before
# format 3 (2-joint frictionless, joints on -120..120 every 60 and -135, -45, 45, 135 degrees,
# chunks of 6: 20 configurations, 4 chunks, the last partial), raw chunks, one XXH3-64 per
# chunk of its values, joint angles in radians.
FORMAT2 = ROOT / "tests" / "data" / "sweep-format2.zarr"
FORMAT2_GRID = [np.deg2rad(np.arange(-120, 121, 60.0)), np.deg2rad([-135.0, -45, 45, 135])]


def old_store(tmp_path, fmt=2, feasible=True):
    """A copy of the format-2 store; ``fmt=1``: made a format-1 store (BLAKE2b-64 of the
    values, as the documented digest), ``feasible=False``: one made before the feasible flag
    (no feasible array, not in the digests)."""
    import shutil

    from snakecg.sweeps.plan import grid_plan
    from snakecg.sweeps.run import _meta

    path = tmp_path / f"format{fmt}.zarr"
    shutil.copytree(FORMAT2, path)
    root = zarr.open_group(str(path), mode="r+")
    # the robot's and the scene's description as this version writes them (a field added
    # to Robot or Scene since the store was made would refuse its resumption)
    now = _meta(scene("frictionless"), grid_plan(2, FORMAT2_GRID, "frictionless", 6), False,
                0.01)
    meta = dict(root.attrs["snakecg_sweep"])
    meta.update({k: now[k] for k in ("robot", "scene", "version")})
    root.attrs["snakecg_sweep"] = meta
    if fmt == 1:
        meta = dict(meta, format="snakecg.sweep/1")
        names = [k for k in meta["arrays"] if feasible or k != "feasible"]
        if not feasible:
            shutil.rmtree(path / "feasible")
            for k in ("feasibility", "feasible_only"):
                meta.pop(k)
        meta["arrays"] = names
        root.attrs.update({"snakecg_sweep": meta, "store_id": f"format-1-{feasible}"})
        values = {k: root[k][:] for k in names}
        root["chunk_digest"][:] = np.array(
            [_documented_digest(values, 6 * i, min(6 * i + 6, 20),
                                hashlib.blake2b(digest_size=8), names) for i in range(4)],
            dtype=np.uint64)
    return path


def _documented_digest(arrays, start, stop, h, names=None) -> int:
    """The digest docs/how-to/sweep.md defines for formats 1 and 2, from the arrays' bytes (copied,
    in the documented order) and the hash object ``h``."""
    for k in names or ("q", "com_radius", "com_angle",
                       *(f"{p}{m}" for m in METRICS
                         for p in ("max_", "tau_max_", "min_kept_", "tau_min_kept_")),
                       "feasible"):
        part = arrays[k][start:stop]
        h.update((part.astype(np.uint8) if k == "feasible" else part).tobytes())
    return int.from_bytes(h.digest(), "little") | 1


@pytest.mark.parametrize("fmt", [1, 2])
def test_stores_of_formats_1_and_2_are_read_verified_and_resumed(client, tmp_path, fmt):
    """A store of an earlier format is read (joint angles in radians, its own digests, now
    checked on every read) and equals the in-process reference on its grid; resumed with its
    own digest: a chunk whose data no longer matches and one without a digest are computed
    again, the others kept, the recorded digests are the documented ones; a reduction of a
    damaged one is refused."""
    from snakecg.sweeps import summary

    path = old_store(tmp_path, fmt)
    sc = scene("frictionless")
    ref = reference(sc, mesh(*FORMAT2_GRID))
    h = hashlib.blake2b(digest_size=8) if fmt == 1 else xxhash.xxh3_64()
    data = read(path)
    # the store was written by an earlier version, whose largest sr came from the closed
    # form (good to a few 1e-12); the values of today's in-process batch are forward's own
    assert_matches(data, ref, tol=1e-10)
    before = zarr.open_group(str(path), mode="r")["chunk_digest"][:]
    assert int(before[3]) == _documented_digest(data, 18, 20, h)
    assert summary(path)["summarized_configurations"] == 20
    root = zarr.open_group(str(path), mode="r+")
    root["chunk_digest"][1] = 0
    root["max_sr"][14] = 1.0  # chunk 2 damaged
    with pytest.raises(snakecg.InputError, match="chunk 2 .*does not match its recorded"):
        summary(path)
    res = snakecg.sweep(sc, grid=FORMAT2_GRID, store=path, client=client, progress=False)
    assert (res.chunk, res.computed_chunks, res.reused_chunks) == (6, 2, 2)
    again = read(path)
    kept = np.r_[0:6, 18:20]  # chunks 0 and 3: the old version's bytes, untouched
    assert_identical({k: v[kept] for k, v in again.items()},
                     {k: v[kept] for k, v in data.items()})
    assert_matches(again, ref, tol=1e-10)  # chunks 1 and 2 computed again, by today's code
    root = zarr.open_group(str(path), mode="r")
    assert root.attrs["snakecg_sweep"]["format"] == f"snakecg.sweep/{fmt}"
    after = root["chunk_digest"][:]
    np.testing.assert_array_equal(after[[0, 3]], before[[0, 3]])
    for c in (1, 2):
        h = hashlib.blake2b(digest_size=8) if fmt == 1 else xxhash.xxh3_64()
        assert int(after[c]) == _documented_digest(again, 6 * c, 6 * c + 6, h)


def test_a_format_1_store_without_the_feasible_flag_is_read(tmp_path, capsys):
    """A store made before the feasible flag (format 1, no feasible array, digests without
    it) is read and summarised verified; it cannot be filtered by feasibility."""
    from snakecg.sweeps import summary

    path = old_store(tmp_path, 1, feasible=False)
    data = read(path)
    assert "feasible" not in data
    assert_matches(data, reference(scene("frictionless"), mesh(*FORMAT2_GRID)), tol=1e-10)
    s = summary(path)
    assert s["feasible_configurations"] is None and s["summarized_configurations"] == 20
    _one_line_error(capsys, ["sweep", "--summary", str(path), "--feasible-only"],
                    "no feasible array")


def test_data_written_without_its_digest_is_computed_again(client, tmp_path, uninterrupted):
    """A sweep killed after a worker wrote a chunk's data but before the digest was recorded
    leaves that chunk's files (here some of them half old: garbage in two arrays) and a zero
    digest: resuming computes exactly those chunks again and ends identical."""
    store = tmp_path / "nodigest.zarr"
    snakecg.sweep(scene("wheels"), store=store, client=client, progress=False, **WHEELS_GRID)
    root = zarr.open_group(str(store), mode="r+")
    lost = [0, 7, 48]
    for i in lost:
        root["chunk_digest"][i] = 0
    root["max_sr"][7 * 16:8 * 16] = -1.0
    root["tau_max_sr"][0:16] = 3.0
    res = snakecg.sweep(scene("wheels"), store=store, client=client, progress=False,
                        verify=False, **WHEELS_GRID)
    assert (res.computed_chunks, res.reused_chunks) == (3, 46)
    assert_identical(read(store), uninterrupted)


def test_a_worker_never_writes_into_another_store(client, tmp_path):
    """shared_store=True on workers that see another store (or none) at the path: the
    chunk fails with the reason and the way out, and nothing is written."""
    from snakecg.sweeps import work
    from snakecg.sweeps.plan import grid_plan

    sc = scene("ideal_wheels")
    plan = grid_plan(2, [0.0, 0.5], "ideal_wheels", 2)
    snakecg.sweep(sc, grid=[0.0, 0.5], chunk=2, store=tmp_path / "a.zarr", client=client,
                  progress=False)
    before = read(tmp_path / "a.zarr")
    for path in (tmp_path / "a.zarr", tmp_path / "missing.zarr"):
        with pytest.raises(snakecg.SnakecgError, match="shared_store=False"):
            work.evaluate_and_write(sc, plan, 0, 0.01, str(path), "not-this-store")
    assert_identical(read(tmp_path / "a.zarr"), before)
    sid = zarr.open_group(str(tmp_path / "a.zarr"), mode="r").attrs["store_id"]
    d, n = work.evaluate_and_write(sc, plan, 1, 0.01, str(tmp_path / "a.zarr"), sid)
    assert n == 2 and list(d) == [int(x) for x in zarr.open_group(
        str(tmp_path / "a.zarr"), mode="r")["chunk_digest"][1]]
    with pytest.raises(snakecg.InputError, match="shared_store must be None"):
        snakecg.sweep(sc, store=tmp_path / "b.zarr", shared_store="yes")
    assert not (tmp_path / "b.zarr").exists()


# ------------------------------------------------------------------------------------------
def test_mismatched_store_is_refused_and_left_untouched(client, tmp_path, capsys,
                                                       tcp_scheduler):
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
                 "--scheduler", tcp_scheduler])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "other arguments" in err


def _one_line_error(capsys, argv, fragment):
    try:
        code = main(argv)
    except SystemExit as exc:  # refused while the command line is parsed
        code = exc.code
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
        (["--joints", "2"] + out + ["--scheduler", "ucx://host:1"], "unknown scheduler"),
        (["--joints", "2"] + out + ["--scheduler", "tls://host:1"], "certificates"),
        (["--joints", "2"] + out + ["--scheduler", "tcp://host"], "tcp://HOST:PORT"),
        (["--joints", "2"] + out + ["--scheduler", "tcp://127.0.0.1:9"], "cannot reach"),
        # sizes from the arguments, before any grid is made
        (["--joints", "2", "--step", "1e-9"] + out, "more than 100,000 values per joint"),
        (["--joints", "2", "--step", "1e-5"] + out, "more than 100,000 values per joint"),
        (["--joints", "2", "--step", "0.01"] + out, "exceed the limit of 10,000,000"),
        (["--joints", "6", "--step", "0.1", "--force"] + out, "too many for one store"),
        (["--joints", "3", "--samples", str(10**15), "--seed", "1", "--force"] + out,
         "too many for one store"),
        (["--joints", "2", "--range=-1e308:1e308", "--step", "1"] + out, "larger step"),
        (["--joints", "3", "--step", "1", "--chunk", "1", "--force"] + out,
         "chunk 1 is out of range"),
        (["--joints", "2", "--chunk", str(10**12), "--samples", str(10**9), "--seed", "1",
          "--force"] + out, "MiB of results"),
        (["--joints", "2"] + out + ["--workers", str(10**6)], "workers must be an integer"),
        (["--joints", "2", "--out", "a-file/new.zarr"], "does not exist"),
        (["--joints", "2", "--out", "a-file"], "is a file"),
        (["--joints", "2", "--out", "plain-folder"], "not a Zarr store"),
        (["--joints", "2", "--out", "missing/new.zarr"], "does not exist"),
        (["--joints", "2"], "--out STORE is required"),
        (["--summary", "plain-folder"], "not a sweep store"),
        (["--figure", "new.zarr"], "not a sweep store"),
        (["--summary", "x.zarr", "--joints", "2"], "read everything from the store"),
        (["--summary", "x.zarr", "--limit", "5"], "--limit describes a sweep to run"),
        (["--figure", "x.zarr", "--force"], "--force describes a sweep to run"),
        (["--summary", "x.zarr", "--shared-store"], "--shared-store describes a sweep"),
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


def test_cli_json_force_summary_and_figure(tcp_scheduler, tmp_path, capsys):
    """The CLI on a running cluster (--scheduler): strict JSON, --force above the limit,
    the summary checked against NumPy on the in-memory reference, the figure rendered."""
    from PIL import Image

    store = tmp_path / "w.zarr"
    argv = ["sweep", "--joints", "2", "--scenario", "wheels", "--range=-135:135,-90:90",
            "--step", "20,30", "--chunk", "20", "--out", str(store), "--scheduler",
            tcp_scheduler, "--json"]
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


# ------------------------------------------------------------------------------------------
# Feasible shapes: every store holds a boolean `feasible` per configuration; the reductions
# leave the infeasible ones out when asked. 3 joints, every 45 degrees: 343 shapes.
FEAS_VALUES = np.arange(-135, 136, 45) * DEG
FEAS_CLEARANCE = 0.02


@pytest.fixture(scope="module")
def feasible_store(client, tmp_path_factory):
    path = tmp_path_factory.mktemp("feasible") / "f.zarr"
    res = snakecg.sweep(scene("ideal_wheels", joints=3), grid=FEAS_VALUES, store=path,
                        client=client, chunk=100, progress=False, feasible=True,
                        clearance=FEAS_CLEARANCE)
    assert (res.configurations, res.chunks, res.feasible_only, res.clearance) == (
        343, 4, True, FEAS_CLEARANCE)
    return path


def test_feasible_array_equals_geometry_per_configuration(feasible_store):
    """Each configuration's stored flag is snakecg.geometry.feasibility of that one shape at
    the store's clearance (computed here one configuration at a time), and the clearance is
    recorded in the attributes."""
    from snakecg.geometry import feasibility

    model = snakecg.load(scene("ideal_wheels", joints=3))
    data = read(feasible_store)
    Q = mesh(FEAS_VALUES, FEAS_VALUES, FEAS_VALUES)
    one_by_one = np.array([bool(feasibility(model, q, clearance=FEAS_CLEARANCE).feasible)
                           for q in Q])
    assert data["feasible"].dtype == bool
    np.testing.assert_array_equal(data["feasible"], one_by_one)
    assert 0 < one_by_one.sum() < len(Q)  # both kinds on this grid
    np.testing.assert_array_equal(data["q"], Q[:, 3:])
    meta = dict(zarr.open_group(str(feasible_store), mode="r").attrs)["snakecg_sweep"]
    assert meta["feasibility"]["clearance"] == FEAS_CLEARANCE
    assert meta["feasible_only"] is True and "feasible" in meta["arrays"]


def _sampled_segments_check(model, q, points=1001):
    """Feasibility by brute force, independent of snakecg.geometry: every link sampled at
    `points` points; the least distance between the samples of non-adjacent links, and the
    deepest sample of a non-contacting link inside the 0.1 m square plate (object frame).
    Returns (least distance, deepest entry)."""
    poses = model.link_poses(q)
    r = model.robot
    e = np.stack([np.cos(poses[:, 2]), np.sin(poses[:, 2])], axis=1)
    rear = poses[:, :2] - np.asarray(r.com)[:, None] * e
    front = rear + np.asarray(r.length)[:, None] * e
    # the links form a chain: each joint is shared by two links
    for i in range(len(rear) - 1):
        shared = min(np.linalg.norm(a - b) for a in (rear[i], front[i])
                     for b in (rear[i + 1], front[i + 1]))
        assert shared < 1e-12, shared
    t = np.linspace(0.0, 1.0, points)[:, None]
    pts = [rear[i] + t * (front[i] - rear[i]) for i in range(len(rear))]
    least = np.inf
    for i in range(len(pts)):
        for j in range(i + 2, len(pts)):
            d = np.sqrt(((pts[i][:, None, :] - pts[j][None, :, :]) ** 2).sum(-1))
            least = min(least, float(d.min()))
    q_obj, _, _ = model.place_object(q)
    c, s = np.cos(q_obj[2]), np.sin(q_obj[2])
    deepest = 0.0
    for i, p in enumerate(pts):
        if i == model.scene.contact_link - 1:
            continue
        d = p - q_obj[:2]
        local = np.stack([c * d[:, 0] + s * d[:, 1], -s * d[:, 0] + c * d[:, 1]], axis=1)
        deepest = max(deepest, float(np.max(0.05 - np.max(np.abs(local), axis=1))))
    return least, deepest


def test_feasible_array_against_sampled_segments(feasible_store):
    """A handful of shapes, classified by a brute-force sampling of the links (no formula of
    snakecg.geometry): the stored flag agrees wherever the sampled margins are clear of the
    sampling error (link length / 1000)."""
    model = snakecg.load(scene("ideal_wheels", joints=3))
    data = read(feasible_store)
    Q = mesh(FEAS_VALUES, FEAS_VALUES, FEAS_VALUES)
    tol = 2 * max(model.robot.length) / 1000
    rng = np.random.default_rng(5)
    seen = {"crossing": 0, "inside": 0, "feasible": 0}
    for k in rng.permutation(len(Q)):
        if min(seen.values()) >= 3:
            break
        least, deepest = _sampled_segments_check(model, Q[k])
        if abs(least - FEAS_CLEARANCE) < tol or 0 < deepest < tol:
            continue  # too close to call by sampling
        feasible = least >= FEAS_CLEARANCE and deepest <= 0
        assert bool(data["feasible"][k]) == feasible, (np.rad2deg(Q[k, 3:]), least, deepest)
        kind = "feasible" if feasible else "crossing" if least < FEAS_CLEARANCE else "inside"
        seen[kind] += 1
    assert min(seen.values()) >= 3, seen


def _numpy_summary(ref, keep):
    """Worst and best per-configuration maxima over the configurations `keep`, by NumPy."""
    out = {}
    idx = np.flatnonzero(keep)
    for m in METRICS:
        v = ref[f"max_{m}"][idx]
        out[m] = {"worst": int(idx[np.argmin(v)]), "best": int(idx[np.argmax(v)])}
    return out


def _assert_summary(s, ref, expected, feasible):
    for m in METRICS:
        for kind in ("worst", "best"):
            i = expected[m][kind]
            e = s["metrics"][m][kind]
            assert e["index"] == i, (m, kind)
            assert e["value"] == pytest.approx(ref[f"max_{m}"][i], rel=1e-12)
            np.testing.assert_allclose(e["q_deg"], np.rad2deg(ref["q"][i]), atol=1e-9)
            np.testing.assert_allclose(e["tau"], ref[f"tau_max_{m}"][i], atol=1e-12)
            assert e["feasible"] is bool(feasible[i])


def test_feasible_only_summary_equals_numpy_over_the_feasible_subset(feasible_store, capsys):
    """The summary over feasible shapes is NumPy's argmin/argmax over the feasible subset of
    model.extremes(Q).max on the same grid (feasibility from snakecg.geometry in process);
    the store made with feasible=True filters by default, feasible=False gives every shape."""
    from snakecg.geometry import feasibility
    from snakecg.sweeps import summary

    sc = scene("ideal_wheels", joints=3)
    Q = mesh(FEAS_VALUES, FEAS_VALUES, FEAS_VALUES)
    ref = reference(sc, Q)
    ok = feasibility(snakecg.load(sc), Q, clearance=FEAS_CLEARANCE).feasible
    filtered, every = _numpy_summary(ref, ok), _numpy_summary(ref, np.ones(len(Q), bool))
    assert filtered != every  # the filter changes some entry on this grid

    s = summary(feasible_store)
    assert s["feasible_only"] is True and s["clearance"] == FEAS_CLEARANCE
    assert s["summarized_configurations"] == s["feasible_configurations"] == int(ok.sum())
    _assert_summary(s, ref, filtered, ok)
    assert main(["sweep", "--summary", str(feasible_store), "--feasible-only", "--json"]) == 0
    assert json.loads(capsys.readouterr().out, parse_constant=pytest.fail) == s

    s = summary(feasible_store, feasible=False)
    assert s["feasible_only"] is False and s["summarized_configurations"] == len(Q)
    assert s["feasible_configurations"] == int(ok.sum())
    _assert_summary(s, ref, every, ok)
    marked = any(not ok[every[m][k]] for m in METRICS for k in ("worst", "best"))
    from snakecg.sweeps.reduce import summary_text

    text = summary_text(s)
    assert ("* a shape that is not physically possible" in text) == marked
    assert main(["sweep", "--summary", str(feasible_store), "--every-shape", "--json"]) == 0
    assert json.loads(capsys.readouterr().out, parse_constant=pytest.fail) == s
    assert main(["sweep", "--summary", str(feasible_store)]) == 0
    assert "feasible shapes only, clearance 0.02 m" in capsys.readouterr().out


def test_feasible_only_figure_bins_the_feasible_subset(feasible_store, tmp_path):
    """The polar figure's bins over feasible shapes equal NumPy's binning of the feasible
    subset of the in-process reference; the figure is written."""
    from snakecg.geometry import feasibility
    from snakecg.sweeps import figure
    from snakecg.sweeps.reduce import binned_maxima

    sc = scene("ideal_wheels", joints=3)
    Q = mesh(FEAS_VALUES, FEAS_VALUES, FEAS_VALUES)
    ref = reference(sc, Q)
    ok = feasibility(snakecg.load(sc), Q, clearance=FEAS_CLEARANCE).feasible
    for only, keep in ((True, ok), (False, np.ones(len(Q), bool))):
        b = binned_maxima(feasible_store, radius_bins=6, angle_bins=8, feasible=only)
        assert b["binned_configurations"] == int(keep.sum())
        r, a = ref["com_radius"][keep], ref["com_angle"][keep]
        rmax = r.max()
        assert b["radius_max"] == pytest.approx(rmax, rel=1e-8)
        for m in METRICS:
            v = ref[f"max_{m}"][keep]
            want = np.full((8, 6), -np.inf)
            for k in range(len(v)):
                ri = min(int(r[k] / b["radius_max"] * 6), 5)
                ai = min(int((a[k] + np.pi) / (2 * np.pi) * 8), 7)
                want[ai, ri] = max(want[ai, ri], v[k])
            np.testing.assert_allclose(b["maxima"][m], want, rtol=1e-12, err_msg=m)
    png = figure(feasible_store, tmp_path / "f.png", feasible=True)
    assert png.stat().st_size > 10_000


def test_feasibility_of_a_plain_store_fingerprint_and_digest(client, tmp_path, capsys):
    """A store made without feasible=True keeps every shape by default, still holds the flag
    (at the default clearance, as `snakecg reproduce --feasible-only`) and filters when
    asked; resuming it with another feasibility choice is refused; a damaged flag is caught
    by the chunk's digest and computed again."""
    from snakecg.geometry import SELF_CLEARANCE, feasibility
    from snakecg.reproduce import ReproduceOptions
    from snakecg.sweeps import summary

    assert ReproduceOptions().clearance == SELF_CLEARANCE == 0.01
    store = tmp_path / "p.zarr"
    grid = joint_values(-135, 135, 30)
    sc = scene("frictionless")
    res = snakecg.sweep(sc, grid=grid, store=store, client=client, chunk=30, progress=False)
    assert (res.feasible_only, res.clearance) == (False, SELF_CLEARANCE)
    Q = mesh(grid, grid)
    ref = reference(sc, Q)
    ok = feasibility(snakecg.load(sc), Q).feasible
    assert 0 < ok.sum() < len(Q)
    whole = read(store)
    np.testing.assert_array_equal(whole["feasible"], ok)
    s = summary(store)
    assert s["feasible_only"] is False and s["summarized_configurations"] == len(Q)
    _assert_summary(s, ref, _numpy_summary(ref, np.ones(len(Q), bool)), ok)
    assert main(["sweep", "--summary", str(store), "--feasible-only", "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["feasible_only"] is True and s["clearance"] == SELF_CLEARANCE
    _assert_summary(s, ref, _numpy_summary(ref, ok), ok)

    for kwargs, key in (({"feasible": True}, "feasible_only"),
                        ({"feasible": True, "clearance": 0.02}, "feasibility")):
        with pytest.raises(snakecg.InputError, match="made with other arguments") as e:
            snakecg.sweep(sc, grid=grid, store=store, client=client, chunk=30,
                          progress=False, **kwargs)
        assert key in str(e.value)
    root = zarr.open_group(str(store), mode="r+")
    root["feasible"][30:60] = ~root["feasible"][30:60]
    res = snakecg.sweep(sc, grid=grid, store=store, client=client, chunk=30, progress=False)
    assert (res.computed_chunks, res.reused_chunks) == (1, 3)
    assert_identical(read(store), whole)


def test_bad_feasibility_arguments_are_one_line_errors(client, tmp_path, capsys,
                                                      monkeypatch, feasible_store):
    monkeypatch.chdir(tmp_path)
    out = ["--joints", "2", "--out", "new.zarr"]
    for argv, fragment in (
            (out + ["--feasible-only", "--clearance=-0.01"], "--clearance: must be >= 0"),
            (out + ["--feasible-only", "--clearance", "nan"], "finite"),
            (out + ["--feasible-only", "--clearance", "1cm"], "expected a distance"),
            (out + ["--clearance", "0.02"], "goes with --feasible-only"),
            (["--summary", str(feasible_store), "--clearance", "0.02"], "the store's"),
            (["--figure", str(feasible_store), "--feasible-only", "--clearance", "0"],
             "the store's"),
            (out + ["--every-shape"], "--every-shape goes with --summary or --figure"),
            (["--summary", str(feasible_store), "--every-shape", "--feasible-only"],
             "not allowed with")):
        _one_line_error(capsys, ["sweep"] + argv, fragment)
    assert list(tmp_path.iterdir()) == []
    sc = scene("wheels")
    for kwargs, fragment in (({"clearance": 0.02}, "clearance goes with feasible=True"),
                             ({"feasible": True, "clearance": -1.0}, "clearance must be"),
                             ({"feasible": True, "clearance": float("inf")}, "clearance must"),
                             ({"feasible": True, "clearance": True}, "clearance must"),
                             ({"feasible": "yes"}, "feasible must be True or False")):
        with pytest.raises(snakecg.InputError, match=fragment):
            snakecg.sweep(sc, grid=[0.0], store=tmp_path / "g.zarr", **kwargs)
    assert list(tmp_path.iterdir()) == []
    from snakecg.sweeps import summary

    with pytest.raises(snakecg.InputError, match="feasible must be True, False or None"):
        summary(feasible_store, feasible="yes")

