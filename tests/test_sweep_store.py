"""The sweep store as read back (snakecg/sweeps/store.py, chunks.py, reduce.py): xarray reads
it, every read is verified against the recorded digests and bounded, a damaged or edited
store is refused on one line naming what is damaged, and a store in use waits.

One small store serves the module: the 2-joint frictionless scene on a 5 x 4 grid, chunks of
6 (4 chunks, the last partial), swept on an in-process cluster (threads; no listener).
Values are checked against the package's own `forward`/`extremes` and against the
independent dense model of tests/reference.py (written from the paper, sharing no code).
"""

from __future__ import annotations

import json
import re
import shutil
import struct
import threading
import time
from pathlib import Path

import distributed
import numpy as np
import pytest
import xxhash
import zarr

import snakecg
from snakecg.cli import main
from snakecg.sweeps import figure, read, summary
from snakecg.sweeps.store import array_names

GRID_DEG = [np.arange(-120, 121, 60.0), np.array([-135.0, -45, 45, 135])]
GRID = [np.deg2rad(g) for g in GRID_DEG]
SCENE = snakecg.Scene(snakecg.Robot(joints=2), scenario="frictionless")


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as c:
        yield c


@pytest.fixture(scope="module")
def made(client, tmp_path_factory):
    path = tmp_path_factory.mktemp("store") / "s.zarr"
    res = snakecg.sweep(SCENE, grid=GRID, store=path, client=client, chunk=6, progress=False)
    assert (res.configurations, res.chunks) == (20, 4)
    return path


@pytest.fixture
def store(made, tmp_path):
    """A fresh copy of the module's store, to damage."""
    path = tmp_path / "s.zarr"
    shutil.copytree(made, path)
    return path


def _file(store: Path, name: str, index: int) -> Path:
    two_d = name == "q" or name.startswith("tau_")
    return store / name / "c" / str(index) / "0" if two_d else store / name / "c" / str(index)


# ------------------------------------------------------------------------------------------
def test_xarray_opens_the_store_with_dimensions_degrees_and_units(made):
    """xarray.open_zarr gives a Dataset: dimensions configuration and joint, the joint
    angles as a coordinate in degrees (exactly the grid's), units in the attributes; its
    values at a few grid points equal model.extremes/forward and the independent reference
    evaluated at the stored torques."""
    import xarray as xr
    from reference import Reference

    ds = xr.open_zarr(made)  # consolidated metadata: no warning, one read
    assert ds.sizes["configuration"] == 20 and ds.sizes["joint"] == 2
    assert list(ds["joint"].values) == [1, 2]
    assert "q" in ds.coords and ds["q"].dims == ("configuration", "joint")
    assert ds["q"].attrs["units"] == "degree"
    g = np.meshgrid(*GRID_DEG, indexing="ij")
    np.testing.assert_array_equal(ds["q"].values, np.stack([x.ravel() for x in g], axis=1))
    units = {"max_sr": "1", "max_norm_a_obj": "kg m2 s-4", "tau_max_sr": "N m",
             "com_radius": "m", "com_angle": "rad"}
    for name, unit in units.items():
        assert ds[name].attrs["units"] == unit, name
    assert ds["tau_max_sr"].dims == ("configuration", "joint")
    assert ds["max_sr"].dims == ("configuration",) and ds["feasible"].dtype == bool

    model = snakecg.load(SCENE)
    ref = Reference(SCENE)
    for i in (0, 7, 13, 19):
        q = np.concatenate([[0.0, 0.0, 0.0], np.deg2rad(ds["q"].values[i])])
        ex = model.extremes(q[None, :])
        for m in ("sr", "norm_a_obj", "norm_qdd", "norm_lambda"):
            stored = float(ds[f"max_{m}"].values[i])
            assert stored == pytest.approx(float(ex.max[m][0]), rel=1e-12, abs=1e-300)
            tau = ds[f"tau_max_{m}"].values[i]
            # the stored maximum is the metric at the stored torque, by forward and by the
            # dense reference (enumerated active sets, written from the paper)
            assert stored == pytest.approx(getattr(model.forward(q, tau), m), rel=1e-9)
            assert stored == pytest.approx(ref.solve(q, tau)[m], rel=1e-7, abs=1e-12)


def test_the_compression_is_stated_and_the_digest_covers_the_files(made):
    """The arrays are Blosc-LZ4 with bit shuffling but for the torques (raw: they do not
    compress), as Zarr reads them itself, and each recorded digest is XXH3-64 of the chunk
    file as stored: the compressed bytes where compressed."""
    root = zarr.open_group(str(made), mode="r")
    for name in array_names():
        meta = json.loads((made / name / "zarr.json").read_text())
        if name.startswith("tau_"):
            assert [c["name"] for c in meta["codecs"]] == ["bytes"], name
            continue
        assert [c["name"] for c in meta["codecs"]] == ["bytes", "blosc"], name
        assert meta["codecs"][1]["configuration"]["cname"] == "lz4"
        assert meta["codecs"][1]["configuration"]["shuffle"] == "bitshuffle"
    digests = root["chunk_digest"][:]
    assert root["chunk_digest"].attrs["arrays"] == list(array_names())
    for i in range(4):
        for k, name in enumerate(array_names()):
            data = _file(made, name, i).read_bytes()
            want = int.from_bytes(xxhash.xxh3_64(data).digest(), "little") | 1
            assert int(digests[i, k]) == want, (name, i)


# ------------------------------------------------------------------------------------------
# Damage: every class the store can suffer, each refused on one line (exit 2) by --summary
# and --figure, and by read(), naming the array and the chunk (or the attribute).
def _refused(capsys, store, fragment):
    for argv in (["sweep", "--summary", str(store)], ["sweep", "--figure", str(store)]):
        code = main(argv)
        err = capsys.readouterr().err
        assert code == 2 and err.count("\n") == 1 and "Traceback" not in err, (argv, err)
        assert fragment in err, (argv, err)
    with pytest.raises(snakecg.InputError, match=re.escape(fragment)):
        read(store)


@pytest.mark.parametrize("name", [*array_names()])
def test_a_flipped_byte_in_any_chunk_file_is_refused(store, capsys, name):
    """One byte of one chunk file changed (the issue's case: max_sr's best value became
    1.67e305 with complete: true): the file no longer matches its digest."""
    f = _file(store, name, 1)
    data = bytearray(f.read_bytes())
    data[len(data) // 2] ^= 0x10
    f.write_bytes(bytes(data))
    _refused(capsys, store, f"array {name}, chunk 1 (configurations from 6) does not match "
                            f"its recorded digest")


@pytest.mark.parametrize("name", ["q", "max_sr", "tau_max_sr", "feasible"])
def test_a_truncated_chunk_file_is_refused(store, capsys, name):
    f = _file(store, name, 2)
    f.write_bytes(f.read_bytes()[:7])
    _refused(capsys, store, f"array {name}, chunk 2")


def test_a_missing_chunk_file_is_refused(store, capsys):
    _file(store, "com_angle", 3).unlink()
    _refused(capsys, store, "array com_angle, chunk 3 (configurations from 18) has no file")


def test_a_truncated_digest_table_is_refused(store, capsys):
    f = store / "chunk_digest" / "c" / "0" / "0"
    f.write_bytes(f.read_bytes()[:-3])
    _refused(capsys, store, "array chunk_digest, chunk 0 (configurations from 0) is "
                            "truncated")


@pytest.mark.parametrize("name", ["q", "max_sr", "feasible", "chunk_digest", "joint"])
def test_a_missing_array_metadata_is_refused(store, capsys, name):
    (store / name / "zarr.json").unlink()
    _refused(capsys, store, f"array {name} (its zarr.json) is missing")


def test_array_metadata_edited_or_unreadable_is_refused(store, capsys):
    meta = json.loads((store / "max_sr" / "zarr.json").read_text())
    meta["chunk_grid"]["configuration"]["chunk_shape"] = [7]
    (store / "max_sr" / "zarr.json").write_text(json.dumps(meta))
    _refused(capsys, store, "array max_sr")
    (store / "max_sr" / "zarr.json").write_text("{not json")
    _refused(capsys, store, "array max_sr (its zarr.json) cannot be read")


@pytest.mark.parametrize("edit,fragment", [
    (lambda m: m.update(chunk=0), "chunk is 0, expected an integer >= 1"),
    (lambda m: m.update(chunk=-3), "chunk is -3"),
    (lambda m: m.update(chunk="six"), "chunk is 'six'"),
    (lambda m: m.pop("chunk"), "chunk is missing"),
    (lambda m: m.update(chunk=7), "n_chunks is 4, but the configurations and the chunk make"),
    (lambda m: m.update(chunk=7, n_chunks=3), "array q is not laid out"),
    (lambda m: m.update(n_configurations=21), "n_configurations is 21"),
    (lambda m: m["robot"].update(joints=0), "robot.joints is 0"),
    (lambda m: m["configurations"].update(kind="mesh"), "configurations.kind is 'mesh'"),
    (lambda m: m["configurations"]["joint_values"].pop(), "joint_values is not 2 lists"),
    (lambda m: m["configurations"].update(joint_values=[[0.0], [1e400]]),
     "joint_values is not 2 lists"),
    (lambda m: m.update(arrays=["q"]), "snakecg_sweep.arrays is ['q']"),
    (lambda m: m.update(format="snakecg.sweep/9"), "format is 'snakecg.sweep/9'")])
def test_edited_attributes_are_refused_naming_the_attribute(store, capsys, edit, fragment):
    doc = json.loads((store / "zarr.json").read_text())
    edit(doc["attributes"]["snakecg_sweep"])
    (store / "zarr.json").write_text(json.dumps(doc))
    _refused(capsys, store, fragment)


def _blosc_frame(nbytes: int, payload: bytes) -> bytes:
    """A Blosc 1 frame header (version 2, LZ4's format, flags: shuffled, type size 8)
    claiming ``nbytes`` of values, followed by ``payload``."""
    body = struct.pack("<BBBBIII", 2, 1, 0x01, 8, nbytes, 1 << 16, 16 + len(payload))
    return body + payload


def _record(store: Path, name: str, index: int) -> None:
    """Record the digest of the file now there (an attacker who rewrites a chunk can
    rewrite its digest too: the bound must not depend on the digest)."""
    root = zarr.open_group(str(store), mode="r+")
    k = list(array_names()).index(name)
    row = root["chunk_digest"][index]
    data = _file(store, name, index).read_bytes()
    row[k] = int.from_bytes(xxhash.xxh3_64(data).digest(), "little") | 1
    root["chunk_digest"][index] = row


def test_decompression_bombs_are_refused_before_expanding(store, capsys):
    """A chunk file that would expand beyond its chunk: a Blosc frame claiming 4 GB of
    values, and a 10 GB file (sparse), both with their digests recorded; and the array's
    codec edited to zlib with a zlib bomb in the file. None is decompressed or read beyond
    a chunk's size: each is refused on one line."""
    import zlib

    f = _file(store, "max_sr", 0)
    f.write_bytes(_blosc_frame(0xFFFFFFF0, b"\0" * 16))
    _record(store, "max_sr", 0)
    _refused(capsys, store, "array max_sr, chunk 0 (configurations from 0) claims "
                            "4,294,967,280 bytes of values, a chunk has 48")
    with open(f, "wb") as out:  # 10 GB, sparse: nothing is written to the disk
        out.truncate(10 * 10**9)
    _refused(capsys, store, "array max_sr, chunk 0 (configurations from 0) is longer than "
                            "a chunk can be")
    meta = json.loads((store / "max_sr" / "zarr.json").read_text())
    meta["codecs"][1] = {"name": "gzip", "configuration": {"level": 9}}
    (store / "max_sr" / "zarr.json").write_text(json.dumps(meta))
    f.write_bytes(zlib.compress(b"\0" * 10**8, 9))  # 100 MB in about 100 kB
    _refused(capsys, store, "array max_sr")


def test_an_intact_store_reads_and_its_summary_is_verified(made, capsys):
    """The control: the module's store reads back (each chunk checked) and its summary
    equals NumPy's over the in-process reference."""
    Q = np.hstack([np.zeros((20, 3)), np.stack(
        [x.ravel() for x in np.meshgrid(*GRID, indexing="ij")], axis=1)])
    ex = snakecg.load(SCENE).extremes(Q)
    data = read(made)
    np.testing.assert_array_equal(data["q"], Q[:, 3:])
    s = summary(made)
    assert s["complete"] and s["metrics"]["sr"]["best"]["value"] == pytest.approx(
        ex.max["sr"].max(), rel=1e-12)
    best = int(np.argmax(ex.max["sr"]))  # the grid's degrees, exactly
    assert s["metrics"]["sr"]["best"]["q_deg"] == [GRID_DEG[0][best // 4],
                                                   GRID_DEG[1][best % 4]]
    assert figure(made, made.parent / "f.png").stat().st_size > 10_000


# ------------------------------------------------------------------------------------------
def test_a_store_in_use_waits_for_the_other_sweep(client, tmp_path, capsys):
    """While another sweep holds the store (its lock beside it), a sweep into it says so
    and waits, writing nothing; once free it runs. Two sweeps creating one store at once
    both succeed: one computes every chunk, the other finds them complete."""
    from filelock import FileLock

    path = tmp_path / "busy.zarr"
    lock = FileLock(str(tmp_path / ".busy.zarr.lock"))
    lock.acquire()
    box = {}
    t = threading.Thread(target=lambda: box.update(r=snakecg.sweep(
        SCENE, grid=GRID, store=path, client=client, chunk=6, progress="lines")))
    t.start()
    deadline = time.monotonic() + 60
    err = ""
    while "in use by another sweep" not in err and time.monotonic() < deadline:
        time.sleep(0.1)
        err += capsys.readouterr().err
    assert "in use by another sweep; waiting for it to finish" in err
    assert not path.exists() and t.is_alive()
    lock.release()
    t.join(timeout=120)
    assert box["r"].computed_chunks == 4

    both = tmp_path / "both.zarr"
    results, errors = [], []

    def run():
        try:
            results.append(snakecg.sweep(SCENE, grid=GRID, store=both, client=client,
                                         chunk=6, progress=False))
        except BaseException as exc:  # noqa: BLE001 - reported below
            errors.append(exc)

    threads = [threading.Thread(target=run) for _ in range(2)]
    for th in threads:
        th.start()
    for th in threads:
        th.join(timeout=120)
    assert errors == []
    assert sorted((r.computed_chunks, r.reused_chunks) for r in results) == [(0, 4), (4, 0)]
    np.testing.assert_array_equal(read(both)["max_sr"], read(path)["max_sr"])


def test_out_of_range_grid_values_are_refused(tmp_path):
    """grid=[0, 10**400] (an integer beyond float's range) and such bounds or clearance are
    refused with the argument named, not an OverflowError."""
    for kwargs, fragment in (({"grid": [0, 10**400]}, "grid must be"),
                             ({"grid": [[0.0], [0, 10**400]]}, "grid must be"),
                             ({"samples": 5, "seed": 1, "bounds": [0, 10**400]},
                              "bounds must be"),
                             ({"grid": [0.0], "feasible": True, "clearance": 10**400},
                              "clearance must be")):
        with pytest.raises(snakecg.InputError, match=fragment):
            snakecg.sweep(SCENE, store=tmp_path / "g.zarr", **kwargs)
    assert list(tmp_path.iterdir()) == []
