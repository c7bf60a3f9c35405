"""Compile a model's C into a shared library (once, cached) and call it on numpy arrays.

Two interchangeable backends evaluate the generated functions:

* :class:`CompiledBackend`: the C that CasADi emitted, compiled with the system C compiler
  (``$CC``, else ``cc``/``gcc``) at ``-O2`` into ``<cache>/build/<key>/model.so``, then
  called through ``ctypes`` on numpy buffers in place (no copies; one C loop over the batch);
* :class:`CasadiBackend`: CasADi's in-process virtual machine on the functions built by the
  generated ``model.py``, batched with ``Function.map``. Used when no compiler is present or
  compiling fails; the runtime says so once.

Both return, for a batch of ``n``, arrays of shape ``(n, rows, cols)`` per output.
"""

from __future__ import annotations

import ctypes
import hashlib
import importlib.util
import json
import os
import shutil
import subprocess
import tempfile
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

from .artifacts import cache_dir
from .errors import BuildError

__all__ = ["CompiledBackend", "CasadiBackend", "load_backend", "compile_model", "find_compiler"]

OPT_FLAGS = ["-O2", "-fPIC"]
LARGE_FLAGS = ["-fno-tree-pre", "-fno-code-hoisting"]
_warned: set[str] = set()


def find_compiler() -> str | None:
    cc = os.environ.get("CC")
    if cc:
        return shutil.which(cc) or (cc if os.path.isabs(cc) and os.access(cc, os.X_OK) else None)
    for name in ("cc", "gcc", "clang"):
        found = shutil.which(name)
        if found:
            return found
    return None


def _compiler_id(cc: str) -> str:
    try:
        out = subprocess.run([cc, "--version"], capture_output=True, text=True, timeout=30)
        return out.stdout.splitlines()[0] if out.stdout else cc
    except (OSError, subprocess.SubprocessError):
        return cc


def _build_key(manifest: dict, cc: str) -> str:
    h = hashlib.sha256()
    h.update(manifest["build_hash"].encode())
    h.update(json.dumps(manifest["files"], sort_keys=True).encode())
    h.update(_compiler_id(cc).encode())
    h.update(" ".join(OPT_FLAGS + LARGE_FLAGS).encode())
    return h.hexdigest()[:24]


def _run(cmd: list[str]) -> None:
    try:
        res = subprocess.run(cmd, capture_output=True, text=True)
    except OSError as exc:
        raise BuildError(f"could not run the C compiler: {exc}", command=cmd) from exc
    if res.returncode != 0:
        raise BuildError(
            f"C compiler failed (exit {res.returncode}): {' '.join(cmd)}\n{res.stderr.strip()}",
            command=cmd,
            stderr=res.stderr,
        )


def compile_model(folder: Path, manifest: dict, *, progress=None) -> Path:
    """Compile ``folder``'s C files into a cached shared library and return its path.

    Each function is its own translation unit; they compile in parallel and are linked into
    one library. The library is written under a temporary name and renamed into place,
    under a file lock, so a killed build never leaves a library that a later run would load.
    """
    from filelock import FileLock

    cc = find_compiler()
    if cc is None:
        raise BuildError("no C compiler found (set CC or install gcc)")
    key = _build_key(manifest, cc)
    out_dir = cache_dir() / "build" / f"na{manifest['n_joints']}-{key}"
    lib = out_dir / "model.so"
    stamp = out_dir / "model.so.sha256"
    if _library_ok(lib, stamp):
        return lib
    out_dir.mkdir(parents=True, exist_ok=True, mode=0o700)
    with FileLock(str(out_dir / "build.lock")):
        if _library_ok(lib, stamp):
            return lib
        step = progress or (lambda msg: None)
        sources = sorted(n for n in manifest["files"] if n.endswith(".c"))
        large = {f"c/{f['name']}.c" for f in manifest["functions"] if f.get("large")}
        tmp = Path(tempfile.mkdtemp(prefix="build-", dir=out_dir))
        try:
            step(f"compiling {len(sources)} C files with {Path(cc).name} -O2")

            def one(name: str) -> Path:
                obj = tmp / (Path(name).stem + ".o")
                flags = OPT_FLAGS + (LARGE_FLAGS if name in large else [])
                _run([cc, *flags, "-c", str(folder / name), "-o", str(obj)])
                return obj

            with ThreadPoolExecutor(max_workers=max(1, os.cpu_count() or 1)) as pool:
                objs = list(pool.map(one, sources))
            tmp_lib = tmp / "model.so"
            _run([cc, "-shared", *[str(o) for o in objs], "-o", str(tmp_lib), "-lm"])
            digest = hashlib.sha256(tmp_lib.read_bytes()).hexdigest()
            os.replace(tmp_lib, lib)
            tmp_stamp = tmp / "stamp"
            tmp_stamp.write_text(digest)
            os.replace(tmp_stamp, stamp)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    return lib


def _library_ok(lib: Path, stamp: Path) -> bool:
    if not (lib.is_file() and stamp.is_file()):
        return False
    try:
        return hashlib.sha256(lib.read_bytes()).hexdigest() == stamp.read_text().strip()
    except OSError:
        return False


class _Signature:
    def __init__(self, sig: dict):
        self.name = sig["name"]
        self.symbol = sig["symbol"]
        self.in_names = [i["name"] for i in sig["inputs"]]
        self.in_sizes = [i["rows"] * i["cols"] for i in sig["inputs"]]
        self.out_names = [o["name"] for o in sig["outputs"]]
        self.out_shapes = [(o["rows"], o["cols"]) for o in sig["outputs"]]


def _check_input(sig: _Signature, k: int, a: np.ndarray, n: int, size: int) -> None:
    """Internal contract: 1-D of ``size`` (broadcast) or C-contiguous ``(n, size)`` float64."""
    ok = a.dtype == np.float64 and a.flags.c_contiguous and (
        a.shape == (size,) or a.shape == (n, size)
    )
    if not ok:
        raise ValueError(
            f"{sig.name}: input {sig.in_names[k]!r} has shape {a.shape} and dtype {a.dtype},"
            f" expected float64 ({size},) or ({n}, {size})"
        )


class CompiledBackend:
    """Calls the compiled batched drivers ``<prefix>batch_<function>`` through ctypes."""

    kind = "compiled"

    def __init__(self, lib_path: Path, manifest: dict):
        self.path = lib_path
        self._lib = ctypes.CDLL(str(lib_path))
        self.prefix = manifest["prefix"]
        self.signatures = {s["name"]: _Signature(s) for s in manifest["functions"]}
        self._fns = {}
        for name in self.signatures:
            fn = getattr(self._lib, f"{self.prefix}batch_{name}")
            fn.argtypes = [
                ctypes.c_longlong,
                ctypes.POINTER(ctypes.c_void_p),
                ctypes.POINTER(ctypes.c_longlong),
                ctypes.POINTER(ctypes.c_void_p),
            ]
            fn.restype = ctypes.c_int
            self._fns[name] = fn

    def __call__(self, name: str, n: int, inputs: list[np.ndarray]) -> list[np.ndarray]:
        """Evaluate ``name`` on ``n`` samples.

        ``inputs[k]`` is float64 C-contiguous, either of size ``in_sizes[k]`` (broadcast) or
        of shape ``(n, in_sizes[k])``.
        """
        sig = self.signatures[name]
        n_in = len(sig.in_sizes)
        argp = (ctypes.c_void_p * n_in)()
        strides = (ctypes.c_longlong * n_in)()
        for k, (a, size) in enumerate(zip(inputs, sig.in_sizes)):
            _check_input(sig, k, a, n, size)
            argp[k] = a.ctypes.data
            strides[k] = 0 if a.ndim == 1 else size
        outs = [np.empty((n, c, r)) for (r, c) in sig.out_shapes]
        resp = (ctypes.c_void_p * len(outs))(*[o.ctypes.data for o in outs])
        status = self._fns[name](n, argp, strides, resp)
        if status != 0:
            raise BuildError(f"{name}: evaluation failed at sample {status - 1} (status {status})")
        return [o.transpose(0, 2, 1) for o in outs]


class CasadiBackend:
    """CasADi's in-process evaluation of the functions built by the generated ``model.py``."""

    kind = "casadi"

    def __init__(self, folder: Path, manifest: dict):
        spec = importlib.util.spec_from_file_location(
            f"snakecg_model_na{manifest['n_joints']}", folder / "model.py"
        )
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)  # verified against the manifest hash before loading
        self.signatures = {s["name"]: _Signature(s) for s in manifest["functions"]}
        self._fns = {f.name()[len(manifest["prefix"]):]: f for f in module.all_functions()}
        self._maps: dict[tuple[str, int], object] = {}

    def casadi_function(self, name: str):
        return self._fns[name]

    def __call__(self, name: str, n: int, inputs: list[np.ndarray]) -> list[np.ndarray]:
        sig = self.signatures[name]
        fn = self._fns[name]
        args = []
        for k, (a, size) in enumerate(zip(inputs, sig.in_sizes)):
            _check_input(sig, k, a, n, size)
            if a.ndim == 1:
                args.append(np.asarray(a, dtype=float).reshape(size, 1))
            else:
                args.append(np.asarray(a, dtype=float).reshape(n, size).T)
        if n == 1:
            res = fn.call(args)
        else:
            key = (name, n)
            if key not in self._maps:
                self._maps.clear() if len(self._maps) > 16 else None
                self._maps[key] = fn.map(n, "serial")
            res = self._maps[key].call(args)
        outs = []
        for r, (rows, cols) in zip(res, sig.out_shapes):
            # map() concatenates the samples' (rows, cols) blocks horizontally
            arr = np.asarray(r.full()).reshape(rows, cols, n, order="F")
            outs.append(np.ascontiguousarray(arr.transpose(2, 0, 1)))
        return outs


def load_backend(folder: Path, manifest: dict, *, prefer: str = "compiled", progress=None):
    """The compiled backend, or CasADi's in-process one (with one warning) if compiling fails."""
    if prefer not in ("compiled", "casadi"):
        raise ValueError(f"backend must be 'compiled' or 'casadi', got {prefer!r}")
    if prefer == "compiled" and os.environ.get("SNAKECG_BACKEND", "") != "casadi":
        try:
            return CompiledBackend(compile_model(folder, manifest, progress=progress), manifest)
        except BuildError as exc:
            key = f"{manifest['n_joints']}:{exc}"
            if key not in _warned:
                _warned.add(key)
                warnings.warn(
                    "snakecg: using CasADi's in-process evaluation (slower) because the C build "
                    f"failed: {exc}",
                    RuntimeWarning,
                    stacklevel=3,
                )
        except OSError as exc:
            warnings.warn(f"snakecg: cannot load the compiled model ({exc}); using CasADi",
                          RuntimeWarning, stacklevel=3)
    return CasadiBackend(folder, manifest)

