"""Find, verify and (once) generate model folders; the only way up to ``snakecg_derive``.

Where a model folder ``na<N>/`` comes from, in order:

1. the package (``snakecg_generated``: the checked-in models, n_a = 1..6);
2. the user's cache, ``<cache>/models/<fingerprint>/na<N>/``, where ``<fingerprint>`` hashes
   the derivation's sources, templates and tool versions (so a new snakecg never loads a model
   an older one generated);
3. otherwise the generator is asked once (SymPy is imported only then) and the result is
   written atomically into the cache under a file lock.

The cache folder is ``$SNAKECG_CACHE_DIR`` if set, else the platform's user cache folder
(``~/.cache/snakecg`` on Linux), created with user-only permissions. A folder is loaded only
after every file's SHA-256 matches its manifest; a corrupted cache entry is reported once
and rebuilt. Nothing is read from the working directory.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import warnings
import importlib.util
from importlib import metadata
from pathlib import Path

from .errors import ArtifactError, BuildError, InputError

__all__ = [
    "cache_dir",
    "derive_fingerprint",
    "model_dir",
    "verify_model_dir",
    "MANIFEST_FORMAT",
    "max_joints",
]

MANIFEST_FORMAT = 1
_DEFAULT_MAX_JOINTS = 30
_reported: set[str] = set()


def max_joints() -> int:
    """Largest joint count generated on demand (``$SNAKECG_MAX_JOINTS``, default 30)."""
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


def cache_dir() -> Path:
    """The user's snakecg cache folder (created, mode 0700)."""
    raw = os.environ.get("SNAKECG_CACHE_DIR")
    if raw:
        path = Path(raw).expanduser()
        if not path.is_absolute():
            raise InputError(
                f"SNAKECG_CACHE_DIR must be an absolute path, got {raw!r}"
                " (a relative path would make the cache depend on the working directory)"
            )
    else:
        import platformdirs

        path = Path(platformdirs.user_cache_dir("snakecg", appauthor=False))
    path.mkdir(parents=True, exist_ok=True, mode=0o700)
    return path


def _package_dir(name: str) -> Path | None:
    spec = importlib.util.find_spec(name)
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


def verify_model_dir(path: Path, n_joints: int | None = None) -> dict:
    """Read ``manifest.json`` and check every listed file's SHA-256; return the manifest."""
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
    files = manifest.get("files")
    if not isinstance(files, dict) or "model.py" not in files:
        raise ArtifactError(f"{path}: manifest lists no files")
    for name, digest in files.items():
        p = path / name
        if not p.is_file():
            raise ArtifactError(f"{path}: {name} is missing")
        if _sha_file(p) != digest:
            raise ArtifactError(f"{path}: {name} does not match its manifest hash")
    return manifest


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


def _generate(n_joints: int, root: Path, progress) -> tuple[Path, dict]:
    from filelock import FileLock

    root.mkdir(parents=True, exist_ok=True, mode=0o700)
    folder = root / f"na{n_joints}"
    with FileLock(str(root / f"na{n_joints}.lock")):
        if folder.exists():  # another process finished while we waited
            try:
                return folder, verify_model_dir(folder, n_joints)
            except ArtifactError:
                shutil.rmtree(folder, ignore_errors=True)
        try:
            from snakecg_derive.render import render_model, write_model
        except ImportError as exc:  # pragma: no cover - broken install
            raise BuildError(f"cannot import the generator snakecg_derive: {exc}") from exc
        rendered = render_model(n_joints, regen_out=str(root), progress=progress,
                                max_joints=max_joints())
        write_model(rendered, root)
    return folder, verify_model_dir(folder, n_joints)
