"""The cache repairs itself, and no wait is silent.

* a manifest whose function list was emptied or lost an entry is checked against the set the
  generator defines for that joint count and rebuilt once, with one line saying why;
* a foreign library whose checksum stamp was recomputed is rebuilt (the model runs compiled),
  not kept on the slow CasADi path;
* a process waiting for a lock held by a stopped process says who holds it (pid, since when)
  after a few seconds and gives up after ``SNAKECG_LOCK_TIMEOUT`` with a clear error;
* a cache that cannot be written, without its compiled library, falls back to CasADi with one
  warning.
"""

from __future__ import annotations

import hashlib
import json
import os
import signal
import subprocess
import sys
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

import snakecg
from snakecg import artifacts, native
from snakecg.errors import ArtifactError, InputError
from snakecg_derive.catalog import function_names
from test_faults import child_env

PY = sys.executable
TIMEOUT = 900


@pytest.fixture
def fresh_cache(tmp_path, monkeypatch):
    cache = tmp_path / "cache"
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(cache))
    monkeypatch.delenv("SNAKECG_BACKEND", raising=False)
    monkeypatch.setattr(artifacts, "_reported", set())
    monkeypatch.setattr(native, "_warned", set())
    # models loaded here (a CasADi fallback among them) must not serve later tests
    monkeypatch.setattr(snakecg.robot_model, "_BACKENDS", {})
    return cache



def _edit_manifest(folder: Path, edit) -> None:
    path = folder / "manifest.json"
    m = json.loads(path.read_text())
    edit(m)
    path.write_text(json.dumps(m, indent=2))


@pytest.mark.parametrize("damage, reason", [
    (lambda m: m.update(functions=[]), "lacks derived_parameters"),
    (lambda m: m.update(functions=[f for f in m["functions"] if f["name"] != "mass_matrix"]),
     "lacks mass_matrix"),
    (lambda m: m["functions"].reverse(), "out of order"),
    (lambda m: m["functions"][4].update(outputs="M"), "damaged signature for mass_matrix"),
])
def test_damaged_function_list_is_rebuilt_once(fresh_cache, monkeypatch, damage, reason):
    """A cached one-joint model (the packaged one is hidden) whose manifest lost functions is
    rebuilt on the next load: one warning naming what was wrong, then a model whose mass
    matrix is the two-link one of test_derive (M_xx = m_1 + m_2)."""
    monkeypatch.setattr(artifacts, "_packaged", lambda n: None)
    folder, manifest = artifacts.model_dir(1)
    assert [f["name"] for f in manifest["functions"]] == list(function_names(1))
    _edit_manifest(folder, damage)
    with pytest.raises(ArtifactError, match=reason):
        artifacts.verify_model_dir(folder, 1)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        folder2, manifest2 = artifacts.model_dir(1)
        artifacts.model_dir(1)
    lines = [str(w.message) for w in caught if "rebuilding" in str(w.message)]
    assert len(lines) == 1 and reason in lines[0] and "\n" not in lines[0]
    assert folder2 == folder
    assert [f["name"] for f in manifest2["functions"]] == list(function_names(1))
    robot = snakecg.Robot(joints=1, mass=(2.0, 3.0))
    M = native.CasadiBackend(folder2, manifest2)
    from snakecg import kernels

    K = kernels.call(M, "derived_parameters", 1, link_mass=robot.mass, link_length=robot.length,
                     link_inertia=robot.inertia, link_com=robot.com)["K"][0, :, 0]
    mm = kernels.call(M, "mass_matrix", 1, q=np.zeros(4), K=K)["M"][0]
    assert mm[0, 0] == pytest.approx(5.0) and mm[1, 1] == pytest.approx(5.0)


def test_catalog_matches_every_checked_in_manifest():
    """``snakecg show`` and the cache check read the catalog; it lists exactly the functions
    of every checked-in model, metric_extremes only up to three joints."""
    root = Path(__file__).parents[1] / "generated"
    for n in range(1, 7):
        m = json.loads((root / f"na{n}" / "manifest.json").read_text())
        assert [f["name"] for f in m["functions"]] == list(function_names(n))
        assert ("metric_extremes" in function_names(n)) == (n <= 3)


def test_show_lists_the_functions_of_the_requested_joint_count():
    out5 = subprocess.run([PY, "-m", "snakecg.cli", "show", "--joints", "5"],
                          capture_output=True, text=True, timeout=TIMEOUT)
    out2 = subprocess.run([PY, "-m", "snakecg.cli", "show", "--joints", "2"],
                          capture_output=True, text=True, timeout=TIMEOUT)
    assert out5.returncode == 0 and out2.returncode == 0, out5.stderr + out2.stderr
    listed5 = out5.stdout.strip().splitlines()[-1].split()
    listed2 = out2.stdout.strip().splitlines()[-1].split()
    assert listed5 == list(function_names(5)) and "metric_extremes" not in listed5
    assert listed2 == list(function_names(2)) and "metric_extremes" in listed2


FOREIGN_C = "int snakecg_foreign(void) { return 42; }\n"


def test_foreign_library_with_recomputed_checksum_is_rebuilt(fresh_cache, tmp_path):
    """Replace the cached library of the one-joint model with a foreign one and recompute its
    stamp: the next process says so once, rebuilds it and runs compiled, with the same M."""
    code = ("import json, snakecg, numpy as np; "
            "m = snakecg.load(snakecg.Robot(joints=1)); "
            "print(json.dumps({'kind': m.backend_kind, 'lib': str(m.backend.path), "
            "'M': m.mass_matrix(np.array([0, 0, 0.3, -0.4])).tolist()}))")
    first = subprocess.run([PY, "-c", code], capture_output=True, text=True, timeout=TIMEOUT,
                           env=child_env(fresh_cache))
    assert first.returncode == 0, first.stderr
    info = json.loads(first.stdout)
    assert info["kind"] == "compiled"
    lib = Path(info["lib"])
    src = tmp_path / "foreign.c"
    src.write_text(FOREIGN_C)
    subprocess.run([native.find_compiler(), "-shared", "-fPIC", str(src), "-o", str(lib)],
                   check=True, timeout=TIMEOUT)
    (lib.parent / "model.so.sha256").write_text(hashlib.sha256(lib.read_bytes()).hexdigest())
    second = subprocess.run([PY, "-c", code], capture_output=True, text=True, timeout=TIMEOUT,
                            env=child_env(fresh_cache))
    assert second.returncode == 0, second.stderr
    again = json.loads(second.stdout)
    assert again["kind"] == "compiled", second.stderr
    assert second.stderr.count("does not belong to this model") == 1, second.stderr
    assert "rebuilding it" in second.stderr and "Traceback" not in second.stderr
    np.testing.assert_allclose(again["M"], info["M"], rtol=1e-14)
    third = subprocess.run([PY, "-c", code], capture_output=True, text=True, timeout=TIMEOUT,
                           env=child_env(fresh_cache))
    assert third.returncode == 0 and "does not belong" not in third.stderr, third.stderr


HOLDER = r"""
import sys, time
from pathlib import Path
from snakecg import artifacts
with artifacts.held_lock(Path(sys.argv[1]), "hold the lock for a test"):
    print("held", flush=True)
    time.sleep(600)
"""


def test_stopped_lock_holder_is_named_and_the_wait_is_bounded(fresh_cache):
    """A generator stopped with SIGSTOP holds the lock of the 7-joint model: a second process
    says after a few seconds which pid holds it and since when, keeps waiting, and gives up
    after SNAKECG_LOCK_TIMEOUT with one clear line (exit 1, no traceback, nothing generated)."""
    env = child_env(fresh_cache)
    fingerprint = subprocess.run(
        [PY, "-c", "from snakecg import artifacts; print(artifacts.derive_fingerprint()[:20])"],
        capture_output=True, text=True, timeout=TIMEOUT, env=env, check=True).stdout.strip()
    root = fresh_cache / "models" / fingerprint
    root.mkdir(parents=True, mode=0o700)
    os.chmod(fresh_cache, 0o700)
    os.chmod(fresh_cache / "models", 0o700)
    holder = subprocess.Popen([PY, "-c", HOLDER, str(root / "na7.lock")], env=env,
                              stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        os.kill(holder.pid, signal.SIGSTOP)
        t0 = time.monotonic()
        waiter = subprocess.run(
            [PY, "-m", "snakecg.cli", "generate", "--joints", "7"], capture_output=True,
            text=True, timeout=TIMEOUT, env=child_env(fresh_cache, SNAKECG_LOCK_TIMEOUT=9))
        waited = time.monotonic() - t0
    finally:
        os.kill(holder.pid, signal.SIGKILL)
        holder.wait(timeout=60)
    err = waiter.stderr
    assert waiter.returncode != 0 and "Traceback" not in err, err
    assert f"is held by process {holder.pid} (since " in err, err
    assert "waiting up to 9 s" in err and "gave up waiting 9 s" in err, err
    assert "SNAKECG_LOCK_TIMEOUT" in err and "resume it" in err
    assert 9 <= waited < 120
    assert not (root / "na7").exists()


def test_lock_timeout_is_validated(monkeypatch):
    for bad in ("0", "-1", "soon", "inf", "nan"):
        monkeypatch.setenv("SNAKECG_LOCK_TIMEOUT", bad)
        with pytest.raises(InputError, match="SNAKECG_LOCK_TIMEOUT must be a positive number"):
            artifacts.lock_timeout()
    monkeypatch.setenv("SNAKECG_LOCK_TIMEOUT", "2.5")
    assert artifacts.lock_timeout() == 2.5


def test_unwritable_cache_without_library_falls_back_once(fresh_cache, monkeypatch):
    """The library's folder cannot be created (what a read-only file system gives): the
    model is served by CasADi with one warning, and its M matches the compiled model's."""
    def read_only(path, *, error=ArtifactError):
        raise error(f"cannot create the cache folder {path}: [Errno 30] Read-only file system")

    robot = snakecg.Robot(joints=2)
    q = np.array([0.1, -0.2, 0.3, 0.5, -0.7])
    monkeypatch.setattr(native, "make_private_dir", read_only)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        m = snakecg.load(robot)
        snakecg.load(robot)
    lines = [str(w.message) for w in caught if "CasADi" in str(w.message)]
    assert m.backend_kind == "casadi"
    assert len(lines) == 1 and "Read-only file system" in lines[0] and "\n" not in lines[0]
    monkeypatch.undo()
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(fresh_cache))
    from snakecg import kernels

    compiled = native.CompiledBackend(native.compile_model(m.folder, m.manifest), m.manifest)
    M = kernels.call(compiled, "mass_matrix", 1, q=q, K=m.parameters)["M"][0]
    np.testing.assert_allclose(m.mass_matrix(q), M, rtol=1e-13)


def test_free_lock_is_taken_at_once(fresh_cache):
    """An uncontended lock is taken at once and leaves no owner file behind."""
    path = fresh_cache / "x.lock"
    fresh_cache.mkdir(mode=0o700)
    t0 = time.monotonic()
    with artifacts.held_lock(path, "test"):
        owner = json.loads(Path(str(path) + ".owner").read_text())
        assert owner["pid"] == os.getpid()
    assert time.monotonic() - t0 < artifacts.LOCK_NOTICE_SECONDS
    assert not Path(str(path) + ".owner").exists()
