"""Find, verify and (once) generate model folders; the only way up to ``snakecg_derive``.

Where a model folder ``na<N>/`` comes from, in order:

1. the package (``snakecg_generated``: the checked-in models, n_a = 1..6);
2. the user's cache, ``<cache>/models/<fingerprint>/na<N>/``, where ``<fingerprint>`` hashes
   the derivation's sources, templates and tool versions (so a new snakecg never loads a model
   an older one generated);
3. otherwise the generator is asked once (SymPy is imported only then) and the result is
   written atomically into the cache under a file lock.

The cache folder is ``$SNAKECG_CACHE_DIR`` if set (an absolute path), else the platform's
user cache folder (``~/.cache/snakecg`` on Linux), created with user-only permissions (0700);
an existing cache folder that belongs to another user or that other users may write is
refused. A folder is loaded only after every file's SHA-256 matches its manifest; a corrupted
cache entry is reported once and rebuilt. Nothing is read from the working directory: a
``snakecg_generated`` package that is found there (``''`` or the current folder on
``sys.path``) is ignored unless ``snakecg`` itself was imported from there.
"""

from __future__ import annotations

import hashlib
import importlib.machinery
import importlib.util
import json
import os
import shutil
import stat
import sys
import time
import warnings
from contextlib import contextmanager
from importlib import metadata
from pathlib import Path, PurePosixPath

from .errors import ArtifactError, BuildError, InputError

__all__ = [
    "cache_dir",
    "make_private_dir",
    "derive_fingerprint",
    "model_dir",
    "verify_model_dir",
    "MANIFEST_FORMAT",
    "max_joints",
    "held_lock",
    "lock_timeout",
]

MANIFEST_FORMAT = 1
_DEFAULT_MAX_JOINTS = 50
_reported: set[str] = set()


def max_joints() -> int:
    """Largest joint count generated on demand (``$SNAKECG_MAX_JOINTS``, default 50)."""
    raw = os.environ.get("SNAKECG_MAX_JOINTS")
    if raw is None:
        return _DEFAULT_MAX_JOINTS
    try:
        value = int(raw)
    except ValueError:
        raise InputError(f"SNAKECG_MAX_JOINTS must be a positive integer, got {raw!r}") from None
    if value < 1:
        raise InputError(f"SNAKECG_MAX_JOINTS must be a positive integer, got {raw!r}")
    return value


#: Seconds a process waits for a cache lock before it says who holds it (then keeps waiting).
LOCK_NOTICE_SECONDS = 5.0
_DEFAULT_LOCK_TIMEOUT = 1800.0


def lock_timeout() -> float:
    """Longest wait for a cache lock, in seconds (``$SNAKECG_LOCK_TIMEOUT``, default 1800)."""
    raw = os.environ.get("SNAKECG_LOCK_TIMEOUT")
    if raw is None:
        return _DEFAULT_LOCK_TIMEOUT
    try:
        value = float(raw)
    except ValueError:
        value = float("nan")
    if not value > 0 or value == float("inf"):
        raise InputError(f"SNAKECG_LOCK_TIMEOUT must be a positive number of seconds, got {raw!r}")
    return value


def _lock_owner(path: Path) -> str:
    try:
        data = json.loads(Path(str(path) + ".owner").read_text(encoding="utf-8"))
        since = time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(float(data["since"])))
        return f"process {int(data['pid'])} (since {since})"
    except (OSError, ValueError, KeyError, TypeError):
        return "another process"


@contextmanager
def held_lock(path: Path, what: str):
    """Hold the file lock ``path`` while doing ``what`` (a few words for messages).

    While another process holds it: after :data:`LOCK_NOTICE_SECONDS` one line says which
    process holds it and since when, and the wait goes on; after :func:`lock_timeout` seconds
    a :class:`BuildError` says how to free it. The holder's pid and start time are written
    beside the lock (``<lock>.owner``) for those messages.
    """
    from filelock import FileLock, Timeout

    limit = lock_timeout()
    lock = FileLock(str(path))
    start = time.monotonic()
    try:
        lock.acquire(timeout=min(LOCK_NOTICE_SECONDS, limit))
    except Timeout:
        warnings.warn(f"snakecg: waiting to {what}: the lock {path} is held by "
                      f"{_lock_owner(path)}; waiting up to {limit:g} s in all "
                      "(SNAKECG_LOCK_TIMEOUT)", RuntimeWarning, stacklevel=3)
        try:
            lock.acquire(timeout=max(0.0, limit - (time.monotonic() - start)))
        except Timeout:
            raise BuildError(
                f"gave up waiting {limit:g} s to {what}: the lock {path} is held by "
                f"{_lock_owner(path)}. If that process is stopped (Ctrl-Z), resume it (fg) or "
                "end it; or wait longer with SNAKECG_LOCK_TIMEOUT=<seconds>") from None
    owner = Path(str(path) + ".owner")
    try:
        try:
            tmp = owner.with_name(f"{owner.name}.tmp-{os.getpid()}")
            tmp.write_text(json.dumps({"pid": os.getpid(), "since": time.time()}))
            os.replace(tmp, owner)
        except OSError:  # a read-only folder: the lock still works, the notice is vaguer
            pass
        yield
    finally:
        try:
            owner.unlink()
        except OSError:
            pass
        lock.release()


def cache_dir() -> Path:
    """The user's snakecg cache folder (created with mode 0700; refused if others may write it)."""
    raw = os.environ.get("SNAKECG_CACHE_DIR")
    if raw:
        path = Path(raw).expanduser()
        if not path.is_absolute():
            raise InputError(
                f"SNAKECG_CACHE_DIR must be an absolute path, got {raw!r}"
                " (a relative path would make the cache depend on the working directory)"
            )
        error = InputError
    else:
        import platformdirs

        path = Path(platformdirs.user_cache_dir("snakecg", appauthor=False))
        error = ArtifactError
    make_private_dir(path, error=error)
    return path


def make_private_dir(path: Path, *, error=ArtifactError) -> Path:
    """Create ``path`` and its missing parents with mode 0700 and check that it is private.

    A folder that already exists is accepted if it belongs to the current user and neither
    its group nor other users may write it (a folder others can write could be made to hold
    a library or model that snakecg would then load).
    """
    missing = []
    p = path
    while not p.exists() and p != p.parent:
        missing.append(p)
        p = p.parent
    for d in reversed(missing):
        try:
            d.mkdir(mode=0o700)
        except FileExistsError:
            continue
        except OSError as exc:
            raise error(f"cannot create the cache folder {path}: {exc}"
                        " (set SNAKECG_CACHE_DIR to a folder you can write)") from None
        os.chmod(d, 0o700)  # independent of the umask
    try:
        st = path.stat()
    except OSError as exc:
        raise error(f"cannot create the cache folder {path}: {exc}") from None
    if not stat.S_ISDIR(st.st_mode):
        raise error(f"cache folder {path} exists and is not a directory")
    if hasattr(os, "getuid") and st.st_uid != os.getuid():
        raise error(
            f"cache folder {path} belongs to another user (uid {st.st_uid}); set"
            " SNAKECG_CACHE_DIR to a folder of your own"
        )
    if st.st_mode & (stat.S_IWGRP | stat.S_IWOTH):
        raise error(
            f"cache folder {path} is writable by other users (mode {stat.S_IMODE(st.st_mode):o});"
            " make it private (chmod go-w) or point SNAKECG_CACHE_DIR at a folder only you can"
            " write"
        )
    return path


def _working_dir_entries() -> set[str]:
    """``sys.path`` entries that stand for the working directory (unless snakecg lives there)."""
    try:
        cwd = Path.cwd().resolve()
    except OSError:  # the working directory was removed
        return set()
    home = Path(__file__).resolve().parent.parent  # the sys.path entry snakecg came from
    if home == cwd:
        return set()
    out = set()
    for entry in sys.path:
        try:
            if entry in ("", ".") or Path(entry).resolve() == cwd:
                out.add(entry)
        except (OSError, TypeError, ValueError):
            continue
    return out


def _find_spec(name: str):
    """``importlib.util.find_spec(name)``, skipping packages found in the working directory."""
    skip = _working_dir_entries()
    if not skip:
        return importlib.util.find_spec(name)
    path = [e for e in sys.path if e not in skip]
    for finder in sys.meta_path:
        if finder is importlib.machinery.PathFinder:
            spec = importlib.machinery.PathFinder.find_spec(name, path)
        else:
            find = getattr(finder, "find_spec", None)
            if find is None:
                continue
            try:
                spec = find(name, None)
            except (ImportError, AttributeError, TypeError, ValueError):
                continue
        if spec is not None:
            return spec
    return None


def _package_dir(name: str) -> Path | None:
    spec = _find_spec(name)
    if spec is None or not spec.origin or spec.origin in ("namespace", "built-in"):
        return None
    return Path(spec.origin).parent


def _derive_package() -> Path:
    root = _package_dir("snakecg_derive")
    if root is None:  # pragma: no cover - broken install
        raise BuildError("the generator package snakecg_derive is not installed")
    return root


def derive_fingerprint() -> str:
    """Hash of the derivation sources, templates and generator tool versions (no SymPy import)."""
    h = hashlib.sha256()
    root = _derive_package()
    for p in sorted(list(root.glob("*.py")) + list((root / "templates").glob("*.j2"))):
        h.update(p.name.encode())
        h.update(p.read_bytes())
    for dist in ("sympy", "casadi", "jinja2"):
        try:
            h.update(f"{dist}={metadata.version(dist)}".encode())
        except metadata.PackageNotFoundError:  # pragma: no cover
            h.update(f"{dist}=missing".encode())
    h.update(str(MANIFEST_FORMAT).encode())
    return h.hexdigest()


def _sha_file(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _safe_relative(name) -> bool:
    """A manifest file name: a plain relative path inside the folder (no ``..``, no root)."""
    if not isinstance(name, str) or not name or "\\" in name or "\0" in name:
        return False
    pp = PurePosixPath(name)
    return not pp.is_absolute() and all(part not in ("", ".", "..") for part in pp.parts)


def verify_model_dir(path: Path, n_joints: int | None = None) -> dict:
    """Read ``manifest.json`` and check every listed file's SHA-256; return the manifest.

    Raises :class:`ArtifactError` (naming the folder and the problem) for a missing or
    unreadable manifest, a manifest of another format or joint count, a file name that leaves
    the folder, or a file that is missing or does not match its hash.
    """
    mpath = path / "manifest.json"
    try:
        manifest = json.loads(mpath.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ArtifactError(f"{path}: no manifest.json (incomplete or foreign folder)") from None
    except (OSError, ValueError) as exc:
        raise ArtifactError(f"{path}: unreadable manifest.json ({exc})") from None
    if not isinstance(manifest, dict) or manifest.get("format") != MANIFEST_FORMAT:
        raise ArtifactError(f"{path}: manifest format is not {MANIFEST_FORMAT}")
    if n_joints is not None and manifest.get("n_joints") != n_joints:
        raise ArtifactError(
            f"{path}: manifest is for n_joints={manifest.get('n_joints')}, expected {n_joints}"
        )
    for key, kind in (("prefix", str), ("build_hash", str), ("functions", list),
                      ("n_joints", int)):
        if not isinstance(manifest.get(key), kind):
            raise ArtifactError(f"{path}: manifest has no valid {key!r}")
    problem = _function_set_problem(manifest, manifest["n_joints"])
    if problem:
        raise ArtifactError(f"{path}: manifest.json {problem}")
    files = manifest.get("files")
    if not isinstance(files, dict) or "model.py" not in files:
        raise ArtifactError(f"{path}: manifest lists no files")
    for name, digest in files.items():
        if not _safe_relative(name) or not isinstance(digest, str):
            raise ArtifactError(f"{path}: manifest lists an invalid file entry {name!r}")
        p = path / name
        if not p.is_file():
            raise ArtifactError(f"{path}: {name} is missing")
        if _sha_file(p) != digest:
            raise ArtifactError(f"{path}: {name} does not match its manifest hash")
    return manifest


def _well_formed(items) -> bool:
    return isinstance(items, list) and all(
        isinstance(i, dict) and isinstance(i.get("name"), str)
        and all(isinstance(i.get(k), int) and not isinstance(i.get(k), bool) and i[k] >= 0
                for k in ("rows", "cols"))
        for i in items)


def _function_set_problem(manifest: dict, n_joints: int) -> str | None:
    """Where the manifest's functions differ from the set the generator defines for
    ``n_joints`` (``snakecg_derive.catalog``), or are not well-formed signatures."""
    from snakecg_derive.catalog import function_names

    expected = list(function_names(n_joints))
    listed = [f.get("name") if isinstance(f, dict) else None for f in manifest["functions"]]
    if listed != expected:
        missing = [n for n in expected if n not in listed]
        extra = [str(n) for n in listed if n not in expected]
        parts = ([f"lacks {', '.join(missing)}"] if missing else []) + \
            ([f"has unknown {', '.join(extra)}"] if extra else [])
        return ("lists functions out of order" if not parts else " and ".join(parts)) + \
            f" (the generator defines {len(expected)} functions for {n_joints} joints)"
    prefix = manifest["prefix"]
    for f in manifest["functions"]:
        if f.get("symbol") != prefix + f["name"] or not _well_formed(f.get("inputs")) \
                or not _well_formed(f.get("outputs")):
            return f"has a damaged signature for {f['name']}"
    return None


def _packaged(n_joints: int) -> Path | None:
    root = _package_dir("snakecg_generated")
    if root is None:  # pragma: no cover - broken install
        return None
    p = root / f"na{n_joints}"
    return p if (p / "manifest.json").exists() else None


def _report_once(key: str, message: str) -> None:
    if key not in _reported:
        _reported.add(key)
        warnings.warn(message, RuntimeWarning, stacklevel=3)


def model_dir(n_joints: int, *, generate: bool = True, progress=None) -> tuple[Path, dict]:
    """Folder and verified manifest of the model for ``n_joints``, generating it if needed."""
    if isinstance(n_joints, bool) or not isinstance(n_joints, int) or n_joints < 1:
        raise InputError(f"joints must be an integer >= 1, got {n_joints!r}")
    limit = max_joints()
    if n_joints > limit:
        raise InputError(
            f"joints={n_joints} exceeds the generation limit of {limit} joints"
            " (raise it with SNAKECG_MAX_JOINTS if you accept the derivation and compile time)"
        )
    packaged = _packaged(n_joints)
    if packaged is not None:
        try:
            return packaged, verify_model_dir(packaged, n_joints)
        except ArtifactError as exc:
            _report_once(str(packaged), f"ignoring the packaged model: {exc}; regenerating")
    root = cache_dir() / "models" / derive_fingerprint()[:20]
    folder = root / f"na{n_joints}"
    if folder.exists():
        try:
            return folder, verify_model_dir(folder, n_joints)
        except ArtifactError as exc:
            _report_once(str(folder), f"corrupted cache entry, rebuilding: {exc}")
    if not generate:
        raise ArtifactError(f"no model for joints={n_joints} and generation is off")
    return _generate(n_joints, root, progress)


def regenerate(n_joints: int, folder: Path, problem, *, progress=None) -> tuple[Path, dict]:
    """Folder and manifest of the model for ``n_joints`` in place of ``folder`` (from
    :func:`model_dir`), whose manifest disagrees with its own hash-verified code
    (``problem``: the manifest is JSON and not itself hashed, so an edited signature passes
    :func:`verify_model_dir`): a cache entry is generated again, a packaged model is
    replaced by a cache entry. Reported once, in one line."""
    root = cache_dir() / "models" / derive_fingerprint()[:20]
    cached = root / f"na{n_joints}"
    if folder != cached:  # the packaged model: the cache entry, generated if needed
        _report_once(str(folder), f"ignoring the packaged model: {problem}; regenerating")
        if cached.exists():
            try:
                return cached, verify_model_dir(cached, n_joints)
            except ArtifactError:
                pass
        return _generate(n_joints, root, progress, discard=True)
    _report_once(str(folder), f"corrupted cache entry, rebuilding: {problem}")
    return _generate(n_joints, root, progress, discard=True)


def _generate(n_joints: int, root: Path, progress, *, discard: bool = False
              ) -> tuple[Path, dict]:
    make_private_dir(root)
    folder = root / f"na{n_joints}"
    with held_lock(root / f"na{n_joints}.lock", f"generate the {n_joints}-joint model"):
        if discard and folder.exists():  # verified, but its manifest lies: out of the way
            old = root / f".na{n_joints}.old-{os.getpid()}-{os.urandom(4).hex()}"
            os.replace(folder, old)
            shutil.rmtree(old, ignore_errors=True)
        if folder.exists():  # another process finished while we waited
            try:
                return folder, verify_model_dir(folder, n_joints)
            except ArtifactError:
                shutil.rmtree(folder, ignore_errors=True)
        # Leftovers of writers that were killed: only a lock holder writes here, so every
        # temporary folder of this joint count belongs to a dead process.
        for pattern in (f".na{n_joints}.tmp-*", f".na{n_joints}.old-*"):
            for stale in root.glob(pattern):
                shutil.rmtree(stale, ignore_errors=True)
        try:
            from snakecg_derive.render import render_model, write_model
        except ImportError as exc:  # pragma: no cover - broken install
            raise BuildError(f"cannot import the generator snakecg_derive: {exc}") from exc
        from .progress import stage

        with stage(progress, f"generating the {n_joints}-joint model (once; kept in the "
                   "cache)", f"generated the {n_joints}-joint model"):
            rendered = render_model(n_joints, progress=progress,
                                    max_joints=max_joints())
            write_model(rendered, root)
        return folder, verify_model_dir(folder, n_joints)
