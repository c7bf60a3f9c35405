"""Faults in generation, compilation and the cache (issue #7).

* Atomic writes: a writer killed (SIGKILL) at every step of ``write_model`` and of
  ``compile_model`` leaves nothing that a later run would load, and the later run succeeds.
  The kill points are reached deterministically: a child process forks one grandchild per
  kill point; the grandchild patches file operations *in itself only* so that the k-th one
  sends it SIGKILL. A real generation (7 joints) is also killed from outside at two moments.
* Concurrency: two real processes generating (7 joints) and compiling (1 joint) the same
  model in a fresh cache both succeed and leave one valid artefact.
* A corrupted, truncated or foreign cache entry (model folder or compiled library) is
  detected, reported once and rebuilt; a tampered ``model.py`` is never executed; manifest
  entries cannot point outside their folder.
* The cache folder is private (0700, owner only) and absolute; nothing is loaded from the
  working directory.
* No compiler, a failing one or one that writes nothing: CasADi's in-process evaluation with
  one warning that carries the compiler's command and stderr; the numbers do not change.
* No pickle, marshal, shelve or eval anywhere in the runtime.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import signal
import stat
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

ROOT = Path(__file__).resolve().parent.parent
PY = sys.executable
TIMEOUT = 600


def packaged(n: int) -> Path:
    """The installed package's model folder (never a cache entry)."""
    folder = artifacts._package_dir("snakecg_generated") / f"na{n}"
    artifacts.verify_model_dir(folder, n)
    return folder


def rendered_from_package(n: int):
    """The RenderedModel of the packaged model (what render_model(n) produces, tested fresh
    by test_generated_fresh.py), without running the SymPy derivation."""
    from snakecg_derive.render import RenderedModel

    folder = packaged(n)
    manifest_text = (folder / "manifest.json").read_text(encoding="utf-8")
    manifest = json.loads(manifest_text)
    files = {name: (folder / name).read_text(encoding="utf-8") for name in manifest["files"]}
    files["manifest.json"] = manifest_text
    return RenderedModel(n, files, manifest)


def run_child(script: str, *args, env=None, cwd=None, timeout=TIMEOUT):
    return subprocess.run([PY, "-c", script, *map(str, args)], capture_output=True, text=True,
                          env=env, cwd=cwd, timeout=timeout)


def child_env(cache: Path, **extra) -> dict:
    env = dict(os.environ)
    env["SNAKECG_CACHE_DIR"] = str(cache)
    env.pop("SNAKECG_BACKEND", None)
    env.update({k: str(v) for k, v in extra.items()})
    return env


@pytest.fixture
def fresh_cache(tmp_path, monkeypatch):
    """An empty private cache for this test (in this process and its children)."""
    cache = tmp_path / "cache"
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(cache))
    monkeypatch.setattr(artifacts, "_reported", set())
    monkeypatch.setattr(native, "_warned", set())
    return cache


def reference_mass_matrix(robot: snakecg.Robot, q) -> np.ndarray:
    """M = sum J_i^T diag(m, m, I) J_i from the closed-form link kinematics (independent)."""
    n, ns = robot.n_links, robot.n_coordinates
    phi = q[2] + np.concatenate([[0.0], np.cumsum(q[3:])])
    S = np.zeros((n, ns))
    S[:, 2] = 1
    for j in range(n):
        S[j, 3:3 + j] = 1
    M = np.zeros((ns, ns))
    for i in range(n):
        J = np.zeros((3, ns))
        J[0, 0] = J[1, 1] = 1
        J[2] = S[i]
        if i:
            arms = [robot.length[0] - robot.com[0], *robot.length[1:i], robot.com[i]]
            for j, arm in enumerate(arms):
                J[:2] += arm * np.outer([-np.sin(phi[j]), np.cos(phi[j])], S[j])
        M += J.T @ np.diag([robot.mass[i], robot.mass[i], robot.inertia[i]]) @ J
    return M


# ------------------------------------------------------------------------------------------
# atomic writes: kill write_model at every step
KILL_WRITER = r'''
import builtins, json, os, signal, sys
from pathlib import Path
import snakecg_derive.render as render

spec = json.loads(Path(sys.argv[1]).read_text())
rendered = render.RenderedModel(spec["n_joints"], spec["files"], spec["manifest"])
base = Path(sys.argv[2])
log = []
k = 1
while k < 1000:
    root = base / f"k{k:03d}"
    pid = os.fork()
    if pid == 0:  # grandchild: dies at its k-th file operation
        count = [0]
        def point():
            count[0] += 1
            if count[0] == k:
                os.kill(os.getpid(), signal.SIGKILL)
        real_open = builtins.open
        class HalfWriter:  # writes half, flushes, may die, writes the rest
            def __init__(self, fh):
                self.fh = fh
            def write(self, text):
                h = len(text) // 2
                self.fh.write(text[:h]); self.fh.flush(); point()
                n = self.fh.write(text[h:]); point()
                return n
            def __getattr__(self, name):
                return getattr(self.fh, name)
            def __enter__(self):
                return self
            def __exit__(self, *exc):
                return self.fh.__exit__(*exc)
        def patched_open(*a, **kw):
            point()
            return HalfWriter(real_open(*a, **kw))
        render.open = patched_open  # shadows the builtin inside render only
        for name in ("fsync", "replace", "rename", "chmod", "mkdir"):
            real = getattr(os, name)
            def wrapped(*a, _real=real, **kw):
                point()
                out = _real(*a, **kw)
                point()
                return out
            setattr(os, name, wrapped)
        render.write_model(rendered, root)
        os._exit(0)
    _, status = os.waitpid(pid, 0)
    killed = os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGKILL
    log.append([k, "killed" if killed else "exit %d" % os.WEXITSTATUS(status)])
    if not killed:
        break
    k += 1
print(json.dumps(log))
'''


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork to reach every kill point")
def test_write_model_killed_at_every_step_leaves_nothing_loadable(tmp_path, monkeypatch):
    from snakecg_derive.render import write_model

    rendered = rendered_from_package(1)
    spec = tmp_path / "rendered.json"
    spec.write_text(json.dumps({"n_joints": 1, "files": rendered.files,
                                "manifest": rendered.manifest}))
    base = tmp_path / "kills"
    proc = run_child(KILL_WRITER, spec, base)
    assert proc.returncode == 0, proc.stderr
    log = json.loads(proc.stdout)
    kills = [k for k, how in log if how == "killed"]
    assert log[-1][1] == "exit 0"  # the last grandchild ran past every kill point
    assert len(kills) >= 5 * len(rendered.files)  # open, 2 half-writes, fsync per file, ...
    complete = 0
    for k in kills:
        root = base / f"k{k:03d}"
        visible = sorted(p.name for p in root.iterdir() if not p.name.startswith(".")) \
            if root.exists() else []
        assert visible in ([], ["na1"]), (k, visible)
        if visible:  # renamed into place: complete and identical
            complete += 1
            artifacts.verify_model_dir(root / "na1", 1)
            for name, text in rendered.files.items():
                assert (root / "na1" / name).read_text(encoding="utf-8") == text
        # a later writer succeeds over whatever the killed one left
        final = write_model(rendered, root)
        artifacts.verify_model_dir(final, 1)
    assert 0 < complete < len(kills)  # kills landed both before and after the rename


def test_generate_recovers_from_a_killed_writer(fresh_cache, monkeypatch):
    """A writer killed mid-file in the cache leaves a hidden temporary folder: the loader
    never looks at it, reports nothing, regenerates the model and removes the leftover."""
    monkeypatch.setattr(artifacts, "_packaged", lambda n: None)
    root = artifacts.cache_dir() / "models" / artifacts.derive_fingerprint()[:20]
    root.mkdir(parents=True)
    stale = root / ".na1.tmp-killed"
    (stale / "c").mkdir(parents=True)
    (stale / "model.py").write_text("raise SystemExit('half-written model loaded')\n")
    with pytest.raises(ArtifactError, match=r"no model for joints=1 and generation is off"):
        artifacts.model_dir(1, generate=False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        folder, manifest = artifacts.model_dir(1)
    # nothing to report: no corrupted entry existed, the leftover is not an entry
    assert [str(w.message) for w in caught if "snakecg" in str(w.filename)
            or "corrupted" in str(w.message)] == []
    assert folder == root / "na1" and manifest["n_joints"] == 1
    assert not stale.exists()
    assert [p.name for p in root.iterdir() if p.name.startswith(".na1")] == []


# ------------------------------------------------------------------------------------------
# atomic builds: kill compile_model at every step
KILL_COMPILER = r'''
import json, os, signal, sys
from pathlib import Path
import snakecg.artifacts as artifacts
import snakecg.native as native

folder, manifest = artifacts.model_dir(1)
base = Path(sys.argv[1])
log = []
k = 1
while k < 100:
    pid = os.fork()
    if pid == 0:
        os.environ["SNAKECG_CACHE_DIR"] = str(base / f"k{k:02d}")
        count = [0]
        def point():
            count[0] += 1
            if count[0] == k:
                os.kill(os.getpid(), signal.SIGKILL)
        real_run = native._run
        def run(cmd):
            if "-shared" in cmd:  # the link step (objects are compiled in parallel before)
                point(); real_run(cmd); point()
            else:
                real_run(cmd)
        native._run = run
        real_replace, real_unlink = os.replace, os.unlink
        def replace(*a, **kw):
            point(); real_replace(*a, **kw); point()
        def unlink(path, *a, **kw):
            stamp = str(path).endswith("model.so.sha256")
            if stamp:
                point()
            real_unlink(path, *a, **kw)
            if stamp:
                point()
        os.replace, os.unlink = replace, unlink
        native.compile_model(folder, manifest)
        os._exit(0)
    _, status = os.waitpid(pid, 0)
    killed = os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGKILL
    log.append([k, "killed" if killed else "exit %d" % os.WEXITSTATUS(status)])
    if not killed:
        break
    k += 1
print(json.dumps(log))
'''


# A long study (a compile killed at each of its steps in turn, about 6-9 min on a 2-core
# machine): run with -m slow.
@pytest.mark.slow
@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork to reach every kill point")
@pytest.mark.skipif(native.find_compiler() is None, reason="no C compiler on this machine")
def test_compile_killed_at_every_step_then_rebuilt(tmp_path, monkeypatch):
    base = tmp_path / "kills"
    proc = run_child(KILL_COMPILER, base, env=child_env(tmp_path / "unused"))
    assert proc.returncode == 0, proc.stderr
    log = json.loads(proc.stdout)
    kills = [k for k, how in log if how == "killed"]
    assert log[-1][1] == "exit 0" and len(kills) >= 6, log
    folder, manifest = artifacts.model_dir(1)
    robot = snakecg.Robot(joints=1, mass=(1.0, 2.0), length=(0.3, 0.2))
    q = np.array([0.1, -0.2, 0.4, 1.1])
    M_ref = reference_mass_matrix(robot, q)
    trusted_before = 0
    for k in kills:
        cache = base / f"k{k:02d}"
        monkeypatch.setenv("SNAKECG_CACHE_DIR", str(cache))
        monkeypatch.setattr(native, "_warned", set())
        (out_dir,) = (cache / "build").iterdir()
        lib, stamp = out_dir / "model.so", out_dir / "model.so.sha256"
        trusted = native._library_ok(lib, stamp)
        leftover = lib.exists() and not trusted
        trusted_before += trusted
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            path = native.compile_model(folder, manifest)
        reports = [w for w in caught if "corrupted or incomplete" in str(w.message)]
        assert len(reports) == (1 if leftover else 0), (k, [str(w.message) for w in caught])
        assert path == lib and native._library_ok(lib, stamp)
        if not trusted:  # a rebuild (under the lock) removes killed builds' temporary folders
            assert list(out_dir.glob("build-*")) == []
        backend = native.CompiledBackend(path, manifest)
        (K_full,) = backend("derived_parameters", 1, [np.asarray(robot.mass), np.asarray(
            robot.length), np.asarray(robot.inertia), np.asarray(robot.com)])
        (M,) = backend("mass_matrix", 1, [q, np.ascontiguousarray(K_full[0, :, 0])])
        np.testing.assert_allclose(M[0], M_ref, rtol=1e-12, atol=1e-14)
    assert 0 < trusted_before < len(kills)


# ------------------------------------------------------------------------------------------
# a real generation killed from outside, then two processes generating at once
LOAD7 = r'''
import json, sys
import numpy as np
import snakecg
robot = snakecg.Robot(joints=7, mass=[1.0 + 0.1 * i for i in range(8)], length=0.2)
model = snakecg.load(robot, progress=lambda msg: print("PROGRESS", msg, flush=True))
q = np.linspace(-1.0, 1.0, 10)
print(json.dumps({"M": model.mass_matrix(q).tolist(), "folder": str(model.folder),
                  "backend": model.backend_kind,
                  "lib": str(getattr(model.backend, "path", ""))}), flush=True)
'''


def _kill_when(env, marker: str, delay: float) -> list[str]:
    """Start LOAD7, SIGKILL it ``delay`` s after it prints a line containing ``marker``."""
    proc = subprocess.Popen([PY, "-c", LOAD7], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, env=env)
    seen = []
    try:
        for line in proc.stdout:
            seen.append(line.strip())
            if marker in line:
                time.sleep(delay)
                break
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=TIMEOUT)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == -signal.SIGKILL, (seen, proc.stderr.read())
    proc.stdout.close()
    proc.stderr.close()
    return seen


def _no_half_written_model(cache: Path) -> None:
    for folder in cache.glob("models/*/na7"):
        artifacts.verify_model_dir(folder, 7)  # raises on anything partial


def test_generation_killed_then_two_processes_generate_at_once(fresh_cache):
    env = child_env(fresh_cache)
    # killed while CasADi emits the C (the rendered files are about to be written) ...
    seen = _kill_when(env, "emitting C", 0.3)
    assert any("deriving" in s for s in seen)
    _no_half_written_model(fresh_cache)
    # ... and while the freshly written model is being compiled
    seen = _kill_when(env, "compiling", 0.5)
    _no_half_written_model(fresh_cache)
    # two processes at once on what the killed runs left
    procs = [subprocess.Popen([PY, "-c", LOAD7], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              text=True, env=env) for _ in range(2)]
    outs = [p.communicate(timeout=TIMEOUT) for p in procs]
    results = []
    for p, (out, err) in zip(procs, outs):
        assert p.returncode == 0, err
        assert "Traceback" not in err and "corrupted" not in err, err
        results.append(json.loads(out.strip().splitlines()[-1]))
    assert results[0] == results[1]
    assert results[0]["backend"] == ("compiled" if native.find_compiler() else "casadi")
    models = list(fresh_cache.glob("models/*/na7"))
    assert [str(m) for m in models] == [results[0]["folder"]]
    artifacts.verify_model_dir(models[0], 7)
    assert list(fresh_cache.glob("models/*/.na7.*")) == []  # no temporary folders left
    builds = list(fresh_cache.glob("build/na7-*"))
    assert len(builds) == 1 and list(builds[0].glob("build-*")) == []
    robot = snakecg.Robot(joints=7, mass=[1.0 + 0.1 * i for i in range(8)], length=0.2)
    np.testing.assert_allclose(np.array(results[0]["M"]),
                               reference_mass_matrix(robot, np.linspace(-1.0, 1.0, 10)),
                               rtol=1e-12, atol=1e-13)


COMPILE1 = r'''
import json, sys, time
import snakecg.artifacts as artifacts, snakecg.native as native
folder, manifest = artifacts.model_dir(1)
start = float(sys.argv[1])
while time.time() < start:  # both processes enter compile_model together
    time.sleep(0.005)
lib = native.compile_model(folder, manifest)
ok = native._library_ok(lib, lib.with_name("model.so.sha256"))
print(json.dumps({"lib": str(lib), "ok": ok}))
'''


@pytest.mark.skipif(native.find_compiler() is None, reason="no C compiler on this machine")
def test_two_processes_compile_at_once(fresh_cache):
    env = child_env(fresh_cache)
    start = time.time() + 2.0
    procs = [subprocess.Popen([PY, "-c", COMPILE1, repr(start)], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, env=env) for _ in range(2)]
    outs = [p.communicate(timeout=TIMEOUT) for p in procs]
    for p, (_, err) in zip(procs, outs):
        assert p.returncode == 0, err
    res = [json.loads(out) for out, _ in outs]
    assert res[0] == res[1] and res[0]["ok"]
    (build,) = (fresh_cache / "build").iterdir()
    assert sorted(p.name for p in build.iterdir()) == ["build.lock", "model.so",
                                                       "model.so.sha256"]


# ------------------------------------------------------------------------------------------
# corrupted, truncated and foreign cache entries
def _cached_copy_of_package(n: int, monkeypatch) -> Path:
    """The packaged model copied into the cache as if it had been generated there (and the
    package hidden), so that the cache path of the loader is exercised without SymPy."""
    monkeypatch.setattr(artifacts, "_packaged", lambda n_: None)
    root = artifacts.cache_dir() / "models" / artifacts.derive_fingerprint()[:20]
    root.mkdir(parents=True)
    shutil.copytree(packaged(n), root / f"na{n}")
    return root / f"na{n}"


def _edit_manifest(folder: Path, change) -> None:
    p = folder / "manifest.json"
    m = json.loads(p.read_text())
    change(m)
    p.write_text(json.dumps(m))


CORRUPTIONS = {
    "truncated C file": (lambda f: (f / "c" / "mass_matrix.c").write_text(
        (f / "c" / "mass_matrix.c").read_text()[:1000]), r"c/mass_matrix\.c does not match"),
    "missing file": (lambda f: (f / "c" / "link_poses.c").unlink(), r"c/link_poses\.c is missing"),
    "manifest hash mismatch": (lambda f: _edit_manifest(
        f, lambda m: m["files"].update({"model.py": "0" * 64})), r"model\.py does not match"),
    "truncated manifest": (lambda f: (f / "manifest.json").write_text(
        (f / "manifest.json").read_text()[:200]), r"unreadable manifest\.json"),
    "empty manifest": (lambda f: (f / "manifest.json").write_text(""),
                       r"unreadable manifest\.json"),
    "no manifest": (lambda f: (f / "manifest.json").unlink(), r"no manifest\.json"),
    "other joint count": (lambda f: _edit_manifest(f, lambda m: m.update({"n_joints": 3})),
                          r"manifest is for n_joints=3, expected 1"),
    "other format": (lambda f: _edit_manifest(f, lambda m: m.update({"format": 99})),
                     r"manifest format is not 1"),
    "entry outside the folder": (lambda f: _edit_manifest(
        f, lambda m: m["files"].update({"../../../etc/passwd": "0" * 64})),
        r"invalid file entry '\.\./\.\./\.\./etc/passwd'"),
    "absolute entry": (lambda f: _edit_manifest(
        f, lambda m: m["files"].update({"/etc/hostname": "0" * 64})),
        r"invalid file entry '/etc/hostname'"),
}


@pytest.mark.parametrize("kind", list(CORRUPTIONS))
def test_corrupted_model_entry_detected_and_reported_once(kind, fresh_cache, monkeypatch):
    corrupt, message = CORRUPTIONS[kind]
    folder = _cached_copy_of_package(1, monkeypatch)
    assert artifacts.model_dir(1, generate=False)[0] == folder  # intact: loaded
    corrupt(folder)
    with pytest.raises(ArtifactError, match=message):
        artifacts.verify_model_dir(folder, 1)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for _ in range(3):
            with pytest.raises(ArtifactError, match=r"generation is off"):
                artifacts.model_dir(1, generate=False)
    reports = [str(w.message) for w in caught if "corrupted cache entry" in str(w.message)]
    assert len(reports) == 1 and re.search(message, reports[0]), reports


def test_corrupted_model_entry_is_rebuilt(fresh_cache, monkeypatch):
    folder = _cached_copy_of_package(1, monkeypatch)
    (folder / "c" / "mass_matrix.c").write_text("int broken;\n")
    with pytest.warns(RuntimeWarning, match=r"corrupted cache entry, rebuilding: .*"
                                            r"c/mass_matrix\.c does not match its manifest hash"):
        rebuilt, manifest = artifacts.model_dir(1)
    assert rebuilt == folder
    artifacts.verify_model_dir(folder, 1)
    assert (folder / "c" / "mass_matrix.c").read_text() == \
        (packaged(1) / "c" / "mass_matrix.c").read_text()


def test_model_py_with_a_recomputed_hash_is_never_executed(fresh_cache, monkeypatch, tmp_path):
    """Even a model.py whose manifest hash was recomputed to match is never run: CasADi's
    in-process backend loads the serialized functions, not the rendered Python."""
    folder = _cached_copy_of_package(1, monkeypatch)
    marker = tmp_path / "executed"
    (folder / "model.py").write_text(f"open({str(marker)!r}, 'w').write('ran')\n")

    def rehash(m):
        m["files"]["model.py"] = artifacts._sha_file(folder / "model.py")
    _edit_manifest(folder, rehash)
    monkeypatch.setattr(snakecg.robot_model, "_BACKENDS", {})
    model = snakecg.load(snakecg.Robot(joints=1), backend="casadi")
    q = np.array([0.1, -0.2, 0.3, 0.7])
    M = model.mass_matrix(q)
    assert np.allclose(M, reference_mass_matrix(snakecg.Robot(joints=1), q), atol=1e-12)
    assert not marker.exists()


def test_tampered_model_py_is_never_executed(fresh_cache, monkeypatch, tmp_path):
    """A model.py that does not match its manifest is refused before anything loads the
    folder."""
    folder = _cached_copy_of_package(1, monkeypatch)
    marker = tmp_path / "executed"
    (folder / "model.py").write_text(f"open({str(marker)!r}, 'w').write('ran')\n")
    monkeypatch.setattr(snakecg.robot_model, "_BACKENDS", {})
    monkeypatch.setattr(artifacts, "_generate", lambda *a: (_ for _ in ()).throw(
        ArtifactError("regeneration disabled in this test")))
    with pytest.warns(RuntimeWarning, match=r"model\.py does not match"):
        with pytest.raises(ArtifactError, match="regeneration disabled"):
            snakecg.load(snakecg.Robot(joints=1), backend="casadi")
    assert not marker.exists()


@pytest.mark.parametrize("backend", ["compiled", "casadi"])
def test_manifest_signature_that_disagrees_with_the_code_is_rebuilt(backend, fresh_cache,
                                                                    monkeypatch):
    """The manifest is JSON, not hashed itself: an edit that keeps it valid JSON and leaves
    the files' hashes alone never sizes the output buffers of the compiled drivers (they
    would write past their ends): the functions' own signatures are compared on loading, and
    the model folder is then generated again (docs/explanation/reliability.md), reported once in one
    line. The rebuilt model's mass matrix obeys the physics: M_xx = M_yy = m_1 + m_2."""
    if backend == "compiled" and native.find_compiler() is None:
        pytest.skip("no C compiler on this machine")
    folder = _cached_copy_of_package(1, monkeypatch)

    def shrink(m):
        (sig,) = [f for f in m["functions"] if f["name"] == "mass_matrix"]
        sig["outputs"][0]["rows"] -= 1
    _edit_manifest(folder, shrink)
    artifacts.verify_model_dir(folder, 1)  # the files still match their hashes
    monkeypatch.setattr(snakecg.robot_model, "_BACKENDS", {})
    robot = snakecg.Robot(joints=1, mass=(2.0, 3.0))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = snakecg.load(robot, backend=backend)
    lines = [str(w.message) for w in caught if "rebuilding" in str(w.message)]
    assert len(lines) == 1 and "\n" not in lines[0], lines
    assert re.search(r"corrupted cache entry, rebuilding: .*the generated functions do not "
                     r"match manifest\.json of the model for joints=1: mass_matrix output "
                     r"'\w+' is 4x4, the manifest says 3x4", lines[0]), lines[0]
    M = model.mass_matrix(np.array([0.1, -0.2, 0.3, 0.4]))
    assert M[0, 0] == pytest.approx(5.0) and M[1, 1] == pytest.approx(5.0)
    rows = {f["name"]: f["outputs"][0]["rows"] for f in
            json.loads((folder / "manifest.json").read_text())["functions"]}
    assert rows["mass_matrix"] == 4  # the folder was generated again
    # a second load in a fresh process state: the repaired folder, no new report
    monkeypatch.setattr(snakecg.robot_model, "_BACKENDS", {})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        snakecg.load(robot, backend=backend)
    assert not [w for w in caught if "rebuilding" in str(w.message)]


@pytest.fixture(scope="module")
def compiled_cache(tmp_path_factory):
    """A cache holding the compiled 1-joint model (built once for the module)."""
    if native.find_compiler() is None:
        pytest.skip("no C compiler on this machine")
    cache = tmp_path_factory.mktemp("compiled-cache")
    mp = pytest.MonkeyPatch()
    mp.setenv("SNAKECG_CACHE_DIR", str(cache))
    try:
        folder, manifest = artifacts.model_dir(1)
        native.compile_model(folder, manifest)
    finally:
        mp.undo()
    return cache


@pytest.mark.parametrize("damage", ["truncated library", "wrong checksum", "foreign library",
                                    "missing checksum"])
def test_corrupted_library_detected_reported_once_and_rebuilt(damage, fresh_cache,
                                                              compiled_cache):
    shutil.copytree(compiled_cache, fresh_cache)
    folder, manifest = artifacts.model_dir(1)
    lib = native.compile_model(folder, manifest)
    assert str(lib).startswith(str(fresh_cache))
    stamp = lib.with_name("model.so.sha256")
    good = lib.read_bytes()
    if damage == "truncated library":
        lib.write_bytes(good[: len(good) // 3])
    elif damage == "wrong checksum":
        stamp.write_text("0" * 64)
    elif damage == "foreign library":  # a valid shared library, but not this model's
        import _ctypes

        lib.write_bytes(Path(_ctypes.__file__).read_bytes())
    else:
        stamp.unlink()
    assert not native._library_ok(lib, stamp)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        again = native.compile_model(folder, manifest)
        native.compile_model(folder, manifest)
    reports = [w for w in caught if "corrupted or incomplete" in str(w.message)]
    assert len(reports) == 1 and str(lib) in str(reports[0].message)
    assert again == lib and native._library_ok(lib, stamp)
    backend = native.CompiledBackend(lib, manifest)
    casadi = native.CasadiBackend(folder, manifest)
    robot = snakecg.Robot(joints=1)
    K = snakecg.load(robot, backend="casadi").parameters
    q = np.array([0.3, -0.1, 0.7, -1.2])
    np.testing.assert_allclose(backend("mass_matrix", 1, [q, K])[0],
                               casadi("mass_matrix", 1, [q, K])[0], rtol=1e-13)


# ------------------------------------------------------------------------------------------
# the cache folder
def _mode(p: Path) -> int:
    return stat.S_IMODE(p.stat().st_mode)


def test_cache_folder_created_private(tmp_path, monkeypatch):
    cache = tmp_path / "a" / "b" / "cache"
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(cache))
    old = os.umask(0o000)  # even with a permissive umask
    try:
        assert artifacts.cache_dir() == cache
    finally:
        os.umask(old)
    for p in (tmp_path / "a", tmp_path / "a" / "b", cache):
        assert _mode(p) == 0o700, (p, oct(_mode(p)))


@pytest.mark.skipif(native.find_compiler() is None, reason="no C compiler on this machine")
def test_cache_subfolders_private(fresh_cache):
    folder, manifest = artifacts.model_dir(1)
    lib = native.compile_model(folder, manifest)
    for p in (fresh_cache, fresh_cache / "build", lib.parent):
        assert _mode(p) == 0o700, (p, oct(_mode(p)))


@pytest.mark.parametrize("raw", ["relative/cache", "./cache", "cache", "../cache"])
def test_relative_cache_dir_refused(raw, monkeypatch):
    monkeypatch.setenv("SNAKECG_CACHE_DIR", raw)
    with pytest.raises(InputError, match=rf"SNAKECG_CACHE_DIR must be an absolute path, got "
                                         rf"'{re.escape(raw)}'"):
        artifacts.cache_dir()


def test_shared_cache_dir_refused(tmp_path, monkeypatch):
    cache = tmp_path / "shared"
    cache.mkdir()
    os.chmod(cache, 0o777)
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(cache))
    with pytest.raises(InputError, match=r"is writable by other users \(mode 777\)"):
        artifacts.cache_dir()
    os.chmod(cache, 0o755)  # readable by others is fine: only writing matters
    assert artifacts.cache_dir() == cache


@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() != 0,
                    reason="creating a folder owned by another user needs root")
def test_cache_dir_of_another_user_refused(tmp_path, monkeypatch):
    cache = tmp_path / "theirs"
    cache.mkdir(mode=0o700)
    os.chown(cache, 12345, 12345)
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(cache))
    with pytest.raises(InputError, match=r"belongs to another user \(uid 12345\)"):
        artifacts.cache_dir()


def test_cache_dir_that_cannot_be_created(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(blocker / "cache"))
    with pytest.raises(InputError, match=r"cannot create the cache folder .*file/cache: .*"
                                         r"set SNAKECG_CACHE_DIR to a folder you can write"):
        artifacts.cache_dir()


def test_cache_dir_that_is_a_file_refused(tmp_path, monkeypatch):
    p = tmp_path / "file"
    p.write_text("")
    monkeypatch.setenv("SNAKECG_CACHE_DIR", str(p))
    with pytest.raises(InputError, match=r"exists and is not a directory"):
        artifacts.cache_dir()


WHICH_MODEL = r'''
import snakecg, snakecg.artifacts as a
print(a.model_dir(2)[0])
model = snakecg.load(snakecg.Robot(joints=2), backend="casadi")
print(model.folder)
'''


def test_working_directory_is_never_searched(tmp_path, fresh_cache):
    """A ``snakecg_generated`` package and loose ``na2/`` folders in the working directory
    (complete, self-consistent, but foreign: their model.py leaves a marker when imported)
    are ignored; ``python -c`` puts the working directory first on sys.path."""
    cwd = tmp_path / "work"
    marker = tmp_path / "foreign-model-imported"
    for where in (cwd / "snakecg_generated" / "na2", cwd / "na2", cwd / "generated" / "na2"):
        shutil.copytree(packaged(2), where)
        model_py = where / "model.py"
        model_py.write_text(f"open({str(marker)!r}, 'w').write('x')\n" + model_py.read_text())
        _edit_manifest(where, lambda m: m["files"].update(
            {"model.py": __import__("hashlib").sha256(model_py.read_bytes()).hexdigest()}))
        artifacts.verify_model_dir(where, 2)  # a valid folder in its own right
    (cwd / "snakecg_generated" / "__init__.py").write_text("")
    proc = run_child(WHICH_MODEL, env=child_env(fresh_cache), cwd=cwd)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.split()
    assert lines[0] == lines[1] == str(packaged(2)), proc.stdout
    assert not marker.exists()


# ------------------------------------------------------------------------------------------
# no C compiler, a failing one, one that writes nothing
FORWARD2 = r'''
import json, warnings
import numpy as np
import snakecg
warnings.simplefilter("default")
scene = snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels", kappa=20.0, mu=0.3)
model = snakecg.load(scene)
again = snakecg.load(scene.replace(kappa=5.0))
robot = snakecg.load(snakecg.Robot(joints=2))
res = model.forward([0.1, 0.2, 0.3, -0.9, 0.6], [0.4, -0.2])
print(json.dumps({"backend": [model.backend_kind, again.backend_kind, robot.backend_kind],
                  "lam": res.lam.tolist(), "qdd": res.qdd.tolist()}))
'''


def _compiler_script(tmp_path, body: str) -> Path:
    p = tmp_path / "fake-cc"
    p.write_text("#!/bin/sh\n" + body)
    p.chmod(0o755)
    return p


COMPILERS = {
    "missing": (lambda tmp: tmp / "no" / "such" / "cc",
                r"the C compiler CC='[^']*/no/such/cc' was not found or is not executable"),
    "failing": (lambda tmp: _compiler_script(tmp, 'echo "fake-cc: error: cannot compile $*" >&2\n'
                                                  "exit 1\n"),
                r"C compiler failed \(exit 1\): \S*fake-cc -O2 -fPIC -c \S+\.c -o \S+\.o\s+"
                r"fake-cc: error: cannot compile -O2 -fPIC -c"),
    "silent": (lambda tmp: _compiler_script(tmp, "exit 0\n"),
               r"(wrote no library|C compiler)"),
}


@pytest.mark.parametrize("kind", list(COMPILERS))
def test_compiler_problems_fall_back_to_casadi_with_one_warning(kind, tmp_path, fresh_cache,
                                                               snakecg_cache_dir):
    make_cc, message = COMPILERS[kind]
    cc = make_cc(tmp_path)
    good = run_child(FORWARD2, env=child_env(Path(snakecg_cache_dir)))
    assert good.returncode == 0, good.stderr
    bad = run_child(FORWARD2, env=child_env(fresh_cache, CC=cc))
    assert bad.returncode == 0, bad.stderr
    assert "Traceback" not in bad.stderr
    warned = [line for line in bad.stderr.splitlines() if "RuntimeWarning" in line]
    assert len(warned) == 1, bad.stderr
    assert "using CasADi's in-process evaluation (slower) because the C build failed" in warned[0]
    assert re.search(message, bad.stderr), bad.stderr
    out_good, out_bad = json.loads(good.stdout), json.loads(bad.stdout)
    assert out_bad["backend"] == ["casadi"] * 3
    if native.find_compiler() is not None:
        assert out_good["backend"] == ["compiled"] * 3
    np.testing.assert_allclose(out_bad["lam"], out_good["lam"], rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(out_bad["qdd"], out_good["qdd"], rtol=1e-12, atol=1e-14)
    assert not list(fresh_cache.glob("build/*/model.so"))  # nothing half-built to load later


def test_build_error_carries_command_and_stderr(tmp_path, fresh_cache, monkeypatch):
    cc = COMPILERS["failing"][0](tmp_path)
    monkeypatch.setenv("CC", str(cc))
    folder, manifest = artifacts.model_dir(1)
    with pytest.raises(snakecg.BuildError) as info:
        native.compile_model(folder, manifest)
    err = info.value
    assert err.command[0] == str(cc) and "-c" in err.command
    assert "fake-cc: error: cannot compile" in err.stderr
    assert " ".join(err.command) in str(err)


def test_cli_forward_with_failing_compiler(tmp_path, fresh_cache, snakecg_cache_dir):
    cc = COMPILERS["failing"][0](tmp_path)
    args = ["-m", "snakecg.cli", "forward", "--joints", "2", "--q", "0,0,0,30deg,-40deg",
            "--tau", "0.1,-0.2", "--scenario", "wheels", "--json"]
    good = subprocess.run([PY, *args], capture_output=True, text=True, timeout=TIMEOUT,
                          env=child_env(Path(snakecg_cache_dir)))
    bad = subprocess.run([PY, *args], capture_output=True, text=True, timeout=TIMEOUT,
                         env=child_env(fresh_cache, CC=cc))
    assert good.returncode == bad.returncode == 0, bad.stderr
    assert bad.stderr.count("using CasADi's in-process evaluation") == 1, bad.stderr
    assert "fake-cc: error: cannot compile" in bad.stderr and "Traceback" not in bad.stderr
    a, b = json.loads(good.stdout), json.loads(bad.stdout)
    np.testing.assert_allclose(b["lam"], a["lam"], rtol=1e-12, atol=1e-14)


# ------------------------------------------------------------------------------------------
# no pickle, marshal, shelve or eval of cached data
FORBIDDEN = [r"\bimport pickle\b", r"\bpickle\.", r"\bcPickle\b", r"\bmarshal\b", r"\bshelve\b",
             r"\bdill\b", r"\bjoblib\b", r"(?<![\w.])eval\(", r"allow_pickle\s*=\s*True",
             r"\bliteral_eval\b"]


def test_no_pickle_or_eval_in_the_runtime():
    """Cached data is JSON (manifests), SHA-256 text (library stamps), C and CasADi's own
    serialization. Nothing rendered is executed, neither at run time nor when generating:
    the generator builds the CasADi functions in Python (derive/build.py, derive/coupled.py),
    so there is no ``exec`` and no ``compile`` of source text anywhere."""
    offenders = []
    execs = []
    for pkg in ("snakecg", "derive"):
        for path in sorted((ROOT / pkg).rglob("*.py")):
            text = path.read_text(encoding="utf-8")
            for pattern in FORBIDDEN:
                for m in re.finditer(pattern, text):
                    offenders.append(f"{path.relative_to(ROOT)}: {m.group(0)}")
            execs += [f"{path.relative_to(ROOT)}: {m.group(0)}"
                      for m in re.finditer(r"(?<![\w.])(exec|compile)\(", text)]
    assert offenders == []
    assert execs == []
    loader = (ROOT / "snakecg" / "native.py").read_text()
    # the no-compiler fallback deserializes CasADi's data format; it imports no generated code
    assert "exec_module" not in loader and "importlib" not in loader
    assert "Function.deserialize" in loader


def test_missing_serialized_function_is_an_artifact_error(tmp_path):
    """A model folder whose manifest lacks one function's ``.casadi`` file is refused on
    loading with an ArtifactError naming the function, for CasADi's in-process backend (the
    problem used to be dropped, and the first call of the function raised a bare KeyError)."""
    folder = tmp_path / "na1"
    shutil.copytree(packaged(1), folder)
    manifest = json.loads((folder / "manifest.json").read_text())
    del manifest["files"]["casadi/mass_matrix.casadi"]
    (folder / "casadi" / "mass_matrix.casadi").unlink()
    with pytest.raises(ArtifactError, match=r"mass_matrix has no serialized CasADi function"):
        native.CasadiBackend(folder, manifest)
