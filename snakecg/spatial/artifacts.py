"""Find, verify, generate (once) and compile spatial model folders.

As the planar models (:mod:`snakecg.artifacts`, :mod:`snakecg.native`): the package's
``snakecg_generated/spatial/na<N>/`` first, else the user cache's
``<cache>/spatial/<fingerprint>/na<N>/``, generated once under a file lock (SymPy is imported
only then); every file is checked against the manifest's SHA-256 before use. The C compiles
into ``<cache>/build/spatial-na<N>-chain-<key>/model.so``, and is called through the same
batched drivers and backends; the contact problem (``contact_system``) with the runtime
core's complementarity solve (``forward.c``) compiles into a second library on the first
spatial scene.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import tempfile
from concurrent.futures import ThreadPoolExecutor
from importlib import metadata
from pathlib import Path

from .. import native
from ..engine.binding import Library
from ..artifacts import (_package_dir, _report_once, _safe_relative, _sha_file, _well_formed,
                         cache_dir, held_lock, make_private_dir)
from ..errors import ArtifactError, BuildError, InputError

__all__ = ["spatial_model_dir", "verify_spatial_dir", "load_spatial_backend",
           "SpatialCompiledBackend", "spatial_fingerprint"]

MANIFEST_FORMAT = 1
#: Straight-line code of the spatial functions: -O2, with the two passes that are superlinear
#: on large straight-line code off for the large ones (as the planar models).
OPT_FLAGS = ["-O2", "-fPIC"]


def _derive_root() -> Path:
    root = _package_dir("snakecg_derive")
    if root is None:  # pragma: no cover - broken install
        raise BuildError("the generator package snakecg_derive is not installed")
    return root


def spatial_fingerprint() -> str:
    """Hash of the spatial generator's sources, the shared builder and the tool versions."""
    root = _derive_root()
    h = hashlib.sha256()
    files = (sorted((root / "spatial").glob("*.py")) + sorted((root / "spatial" / "templates")
                                                              .glob("*.j2"))
             + [root / "build.py", root / "sample_c.py", root / "spec.py",
                root / "templates" / "batch.c.j2"])
    for p in files:
        h.update(p.name.encode())
        h.update(p.read_bytes())
    for dist in ("sympy", "casadi", "jinja2"):
        try:
            h.update(f"{dist}={metadata.version(dist)}".encode())
        except metadata.PackageNotFoundError:  # pragma: no cover
            h.update(f"{dist}=missing".encode())
    h.update(f"spatial-{MANIFEST_FORMAT}".encode())
    return h.hexdigest()


def verify_spatial_dir(path: Path, n_joints: int) -> dict:
    """The folder's manifest after checking its kind, sizes, function set and every file's
    SHA-256; :class:`ArtifactError` naming the folder and the problem otherwise."""
    from snakecg_derive.spatial.catalog import SPATIAL_MODEL_FUNCTIONS as SPATIAL_FUNCTIONS

    try:
        manifest = json.loads((path / "manifest.json").read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ArtifactError(f"{path}: no manifest.json (incomplete or foreign folder)") from None
    except (OSError, ValueError) as exc:
        raise ArtifactError(f"{path}: unreadable manifest.json ({exc})") from None
    if not isinstance(manifest, dict) or manifest.get("format") != MANIFEST_FORMAT \
            or manifest.get("kind") != "spatial":
        raise ArtifactError(f"{path}: not a spatial model manifest of format {MANIFEST_FORMAT}")
    if manifest.get("n_joints") != n_joints:
        raise ArtifactError(f"{path}: manifest is for n_joints={manifest.get('n_joints')}, "
                            f"expected {n_joints}")
    functions = manifest.get("functions")
    names = [f.get("name") if isinstance(f, dict) else None for f in functions or []]
    if names != list(SPATIAL_FUNCTIONS):
        raise ArtifactError(f"{path}: manifest lists functions {names}, expected "
                            f"{list(SPATIAL_FUNCTIONS)}")
    prefix = manifest.get("prefix")
    for f in functions:
        if f.get("symbol") != f"{prefix}{f['name']}" or not _well_formed(f.get("inputs")) \
                or not _well_formed(f.get("outputs")):
            raise ArtifactError(f"{path}: manifest has a damaged signature for {f['name']}")
    files = manifest.get("files")
    if not isinstance(files, dict) or "model.py" not in files:
        raise ArtifactError(f"{path}: manifest lists no files")
    for name, digest in files.items():
        if not _safe_relative(name) or not isinstance(digest, str):
            raise ArtifactError(f"{path}: manifest lists an invalid file entry {name!r}")
        if not (path / name).is_file():
            raise ArtifactError(f"{path}: {name} is missing")
        if _sha_file(path / name) != digest:
            raise ArtifactError(f"{path}: {name} does not match its manifest hash")
    return manifest


def spatial_model_dir(n_joints: int, *, progress=None) -> tuple[Path, dict]:
    """Folder and verified manifest of the spatial model with ``n_joints`` joints."""
    if isinstance(n_joints, bool) or not isinstance(n_joints, int) or n_joints < 1:
        raise InputError(f"joints must be an integer >= 1, got {n_joints!r}")
    root = _package_dir("snakecg_generated")
    if root is not None and (root / "spatial" / f"na{n_joints}" / "manifest.json").exists():
        packaged = root / "spatial" / f"na{n_joints}"
        try:
            return packaged, verify_spatial_dir(packaged, n_joints)
        except ArtifactError as exc:
            _report_once(str(packaged), f"ignoring the packaged model: {exc}; regenerating")
    base = cache_dir() / "spatial" / spatial_fingerprint()[:20]
    folder = base / f"na{n_joints}"
    if folder.exists():
        try:
            return folder, verify_spatial_dir(folder, n_joints)
        except ArtifactError as exc:
            _report_once(str(folder), f"corrupted cache entry, rebuilding: {exc}")
    make_private_dir(base)
    with held_lock(base / f"na{n_joints}.lock",
                   f"generate the {n_joints}-joint spatial model"):
        if folder.exists():
            try:
                return folder, verify_spatial_dir(folder, n_joints)
            except ArtifactError:
                shutil.rmtree(folder, ignore_errors=True)
        for pattern in (f".na{n_joints}.tmp-*", f".na{n_joints}.old-*"):
            for stale in base.glob(pattern):
                shutil.rmtree(stale, ignore_errors=True)
        from snakecg_derive.spatial.render import render_spatial_model, write_spatial_model

        write_spatial_model(render_spatial_model(n_joints + 1, progress=progress), base)
        return folder, verify_spatial_dir(folder, n_joints)


#: The engine's files that a spatial scene's library compiles in (the per-state system and
#: the complementarity solve) and the headers they include.
CORE_FILES = ("contact.c", "forward.c", "engine.h", "linalg.h")


def core_manifest(manifest: dict) -> dict:
    """The spatial manifest in the runtime core's terms (snakecg/engine/layout.py): ``n_s`` is
    ``n_v``, the rows are the contact, a wheel, a ground and a pitch row per link."""
    return {**manifest, "n_coordinates": manifest["nv"],
            "n_constraints": 3 * manifest["n_links"] + 1}


def _core_sources(manifest: dict) -> tuple[dict[str, bytes], str]:
    from ..engine.layout import header

    here = native.ENGINE_DIR
    return {name: (here / name).read_bytes() for name in CORE_FILES}, \
        header(core_manifest(manifest))


#: The two libraries of a spatial model: the chain's functions (``load(robot)``), and the
#: contact problem with the runtime core's solve (compiled on the first ``load(scene)``, so
#: that a chain alone does not wait for it).
PARTS = ("chain", "contact")


def _part(manifest: dict, part: str) -> dict:
    """The manifest restricted to the functions of one library."""
    from snakecg_derive.spatial.catalog import SPATIAL_CONTACT_FUNCTIONS

    keep = [f for f in manifest["functions"]
            if (f["name"] in SPATIAL_CONTACT_FUNCTIONS) == (part == "contact")]
    return {**manifest, "functions": keep}


def _build_key(manifest: dict, cc: str, part: str) -> str:
    h = hashlib.sha256()
    h.update(manifest["build_hash"].encode())
    h.update(part.encode())
    if part == "contact":
        core, layout = _core_sources(manifest)
        for name, text in core.items():
            h.update(name.encode() + hashlib.sha256(text).digest())
        h.update(layout.encode())
        h.update(" ".join(native.CORE_FLAGS).encode())
    h.update(json.dumps(manifest["files"], sort_keys=True).encode())
    h.update(native._compiler_id(cc).encode())
    h.update(" ".join(OPT_FLAGS + native.LARGE_FLAGS).encode())
    return h.hexdigest()[:24]


def compile_spatial(folder: Path, manifest: dict, *, progress=None, part: str = "chain") -> Path:
    """Compile the C files of one library (:data:`PARTS`; in parallel) into a cached shared
    library, atomically under a file lock; :class:`BuildError` with the command and stderr
    when it fails."""
    cc = native.find_compiler()
    if cc is None:
        raise native._no_compiler()
    key = _build_key(manifest, cc, part)
    out_dir = cache_dir() / "build" / f"spatial-na{manifest['n_joints']}-{part}-{key}"
    lib, stamp = out_dir / "model.so", out_dir / "model.so.sha256"
    if native._library_ok(lib, stamp):
        return lib
    make_private_dir(out_dir)
    with held_lock(out_dir / "build.lock",
                   f"compile the {manifest['n_joints']}-joint spatial model"):
        if native._library_ok(lib, stamp):
            return lib
        for stale in out_dir.glob("build-*"):
            shutil.rmtree(stale, ignore_errors=True)
        sources = sorted(f"c/{f['name']}.c" for f in _part(manifest, part)["functions"])
        large = {f"c/{f['name']}.c" for f in manifest["functions"] if f.get("large")}
        tmp = Path(tempfile.mkdtemp(prefix="build-", dir=out_dir))
        try:
            (progress or (lambda m: None))(f"compiling {len(sources)} C files with "
                                           f"{Path(cc).name} -O2")

            def one(name: str) -> Path:
                obj = tmp / (Path(name).stem + ".o")
                flags = OPT_FLAGS + (native.LARGE_FLAGS if name in large else [])
                native._run([cc, *flags, "-c", str(folder / name), "-o", str(obj)])
                return obj

            core, layout = _core_sources(manifest) if part == "contact" else ({}, "")
            (tmp / "snakecg_layout.h").write_text(layout, encoding="utf-8")
            for name, text in core.items():
                (tmp / (name if name.endswith(".h") else f"snakecg_core_{name}")).write_bytes(text)

            def one_core(name: str) -> Path:
                obj = tmp / f"snakecg_core_{Path(name).stem}.o"
                native._run([cc, *native.CORE_FLAGS, "-I", str(tmp), "-c",
                             str(tmp / f"snakecg_core_{name}"), "-o", str(obj)])
                return obj

            sources.sort(key=lambda n: -(folder / n).stat().st_size)
            with ThreadPoolExecutor(max_workers=max(1, os.cpu_count() or 1)) as pool:
                jobs = [pool.submit(one, name) for name in sources]
                jobs += [pool.submit(one_core, name) for name in core if name.endswith(".c")]
                objs = sorted((j.result() for j in jobs), key=lambda o: o.name)
            tmp_lib = tmp / "model.so"
            native._run([cc, "-shared", *map(str, objs), "-o", str(tmp_lib), "-lm"])
            digest = hashlib.sha256(tmp_lib.read_bytes()).hexdigest()
            stamp.unlink(missing_ok=True)
            os.replace(tmp_lib, lib)
            (tmp / "stamp").write_text(digest)
            os.replace(tmp / "stamp", stamp)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    return lib


class SpatialCompiledBackend(native.CompiledBackend):
    """The compiled batched drivers of a spatial chain; :meth:`contact` the library of its
    contact problem with the runtime core's solve (compiled on first use)."""

    def __init__(self, lib_path: Path, manifest: dict, *, folder: Path | None = None,
                 part: str = "chain", progress=None):  # noqa: D107 - as CompiledBackend
        self.path = lib_path
        self.prefix = manifest["prefix"]
        self._lib = Library(lib_path, self.prefix)
        mine = _part(manifest, part)
        self.signatures = {s["name"]: native._Signature(s) for s in mine["functions"]}
        self._fns = {name: self._lib.batch(name) for name in self.signatures}
        native._check_signatures(lib_path, manifest, native._library_problems(self._lib, mine))
        self.core = None
        if part == "contact":
            from ..engine import Core

            self.core = Core.forward_library(self._lib, core_manifest(manifest))
        self._folder, self._manifest, self._contact = folder, manifest, None

    def contact(self, progress=None) -> SpatialCompiledBackend:
        """The contact problem's library (``contact_system``, the runtime core's
        ``core_forward`` as ``.core``), compiled once and cached."""
        if self._contact is None:
            lib = compile_spatial(self._folder, self._manifest, progress=progress,
                                  part="contact")
            self._contact = SpatialCompiledBackend(lib, self._manifest, part="contact")
        return self._contact


def load_spatial_backend(folder: Path, manifest: dict, *, prefer: str = "compiled",
                         progress=None):
    """The compiled backend, or CasADi's in-process one (one warning) when compiling fails."""
    if prefer == "compiled" and os.environ.get("SNAKECG_BACKEND", "") != "casadi":
        try:
            return SpatialCompiledBackend(compile_spatial(folder, manifest, progress=progress),
                                          manifest, folder=folder)
        except (BuildError, ArtifactError, OSError, AttributeError) as exc:
            _report_once(f"spatial{manifest['n_joints']}:{exc}",
                         "snakecg: using CasADi's in-process evaluation (slower) for the "
                         f"spatial model because the C build failed: {native._one_line(exc)}")
    return native.CasadiBackend(folder, manifest)
