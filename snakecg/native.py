"""Compile a model's C into a shared library (once, cached) and call it on numpy arrays.

Two interchangeable backends evaluate the generated functions:

* :class:`CompiledBackend`: the C that CasADi emitted, compiled with the system C compiler
  (``$CC``, else ``cc``/``gcc``) at ``-O2`` into ``<cache>/build/<key>/model.so``, then
  called through ``ctypes`` on numpy buffers in place (no copies; one C loop over the batch);
* :class:`CasadiBackend`: CasADi's in-process virtual machine on the functions deserialized
  from CasADi's own serialization (``casadi/*.casadi``, hash-checked; nothing generated is
  executed), batched with ``Function.map``. Used when no compiler is present or
  compiling fails; the runtime says so once.

Both return, for a batch of ``n``, arrays of shape ``(n, rows, cols)`` per output.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import tempfile
import time
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

from .artifacts import cache_dir, held_lock, make_private_dir
from .bound import BoundFunction
from .engine.binding import Library, empty_pointers, int64s, pointers
from .engine.threads import PARALLEL_MIN as _PARALLEL_MIN
from .engine.threads import pool, threads
from .errors import ArtifactError, BuildError

__all__ = [
    "CompiledBackend",
    "CasadiBackend",
    "BoundFunction",
    "load_backend",
    "compile_model",
    "find_compiler",
]

OPT_FLAGS = ["-O2", "-fPIC"]
LARGE_FLAGS = ["-fno-tree-pre", "-fno-code-hoisting"]
#: Generated functions evaluated once per scene (the scene's constants), not per sample: they
#: compile at -O1, which at 50 joints takes 4 s of CPU instead of 12 s for a function that
#: runs once per `load`.
SETUP_FUNCTIONS = frozenset({"derived_parameters"})
SETUP_FLAGS = ["-O1", "-fPIC"]
#: The runtime core's own C files (small loops over the model's sizes, known when compiling):
#: -O3 unrolls and vectorizes them, about 5 % of a batched `forward`
#: (docs/reference/performance.md).
CORE_FLAGS = ["-O3", "-fPIC"]
_warned: set[str] = set()
#: The engine compiled into every model's library (fixed C files of the runtime, each named
#: after the step it does; snakecg/engine/engine.h lists what each defines).
ENGINE_DIR = Path(__file__).resolve().parent / "engine"
CORE_SOURCES = tuple(ENGINE_DIR / name
                     for name in ("contact.c", "forward.c", "rows.c", "integrate.c", "events.c",
                                  "run.c", "geometry.c", "sphere.c", "pieces.c", "maps.c", "qp.c",
                                  "certificate.c", "optimal.c", "max_sr.c", "push.c",
                                  "wheel_states.c", "scene_sets.c", "scene_min_norm.c",
                                  "scene_piece.c",
                                  "scene_primal.c", "scene_rescue.c", "scene_barrier.c",
                                  "scene_kkt.c", "scene_small.c", "scene_tiny.c",
                                  "scene_tiny_setup.c", "scene_solve.c", "scene_diag.c",
                                  "scene_block.c", "scene_geometry.c", "scene_place.c",
                                  "scene_rows.c", "scene_inputs.c", "scene_broad.c",
                                  "scene_metrics.c", "scene_work.c", "scene_step.c",
                                  "scene_run.c", "scene_friction.c", "scene_friction_states.c",
                                  "scene_family.c"))
#: Its headers: engine.h (the types and prototypes), linalg.h (the small dense linear algebra),
#: and a file's own (what two files of one step share), named after the C file defining it.
CORE_HEADERS = (ENGINE_DIR / "engine.h", ENGINE_DIR / "linalg.h",
                *(p.with_suffix(".h") for p in CORE_SOURCES if p.with_suffix(".h").exists()))
#: Up to this batch size the outputs of a compiled call share one buffer (see CompiledBackend).
_SMALL_BATCH = 64


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


def _core_sources(manifest: dict) -> tuple[dict[str, bytes], str]:
    """The runtime core's C files (snakecg/engine/*.c) by name and its layout header."""
    from .engine.layout import header

    return ({p.name: p.read_bytes() for p in (*CORE_SOURCES, *CORE_HEADERS)},
            header(manifest))


def _build_key(manifest: dict, cc: str) -> str:
    h = hashlib.sha256()
    h.update(manifest["build_hash"].encode())
    core, layout = _core_sources(manifest)
    for name, text in core.items():
        h.update(name.encode() + hashlib.sha256(text).digest())
    h.update(layout.encode())
    h.update(json.dumps(manifest["files"], sort_keys=True).encode())
    h.update(_compiler_id(cc).encode())
    h.update(" ".join(OPT_FLAGS + LARGE_FLAGS + sorted(SETUP_FUNCTIONS) + SETUP_FLAGS
                      + CORE_FLAGS).encode())
    return h.hexdigest()[:24]


#: Lines of the compiler's stderr quoted in an error message (all of it is in ``.stderr``).
_STDERR_LINES = 40


def _run(cmd: list[str]) -> None:
    try:
        res = subprocess.run(cmd, capture_output=True, text=True, errors="replace")
    except OSError as exc:
        raise BuildError(f"could not run the C compiler: {exc}; command: {' '.join(cmd)}",
                         command=cmd) from exc
    if res.returncode != 0:
        lines = res.stderr.strip().splitlines()
        shown = "\n".join(lines[-_STDERR_LINES:])
        if len(lines) > _STDERR_LINES:
            shown = f"[... {len(lines) - _STDERR_LINES} earlier lines]\n{shown}"
        raise BuildError(
            f"C compiler failed (exit {res.returncode}): {' '.join(cmd)}\n{shown}",
            command=cmd,
            stderr=res.stderr,
        )


def _no_compiler() -> BuildError:
    cc = os.environ.get("CC")
    if cc:
        return BuildError(f"the C compiler CC={cc!r} was not found or is not executable"
                          " (set CC to a working compiler, or unset it to use cc/gcc/clang)",
                          command=[cc])
    return BuildError("no C compiler found (set CC or install gcc)")


def compile_model(folder: Path, manifest: dict, *, progress=None, rebuild: bool = False) -> Path:
    """Compile ``folder``'s C files into a cached shared library and return its path.

    Each function is its own translation unit; they compile in parallel and are linked into
    one library. The library is written under a temporary name and renamed into place,
    under a file lock, so a killed build never leaves a library that a later run would load.
    ``rebuild`` replaces a cached library that matched its checksum but not the model.
    """
    cc = find_compiler()
    if cc is None:
        raise _no_compiler()
    key = _build_key(manifest, cc)
    out_dir = cache_dir() / "build" / f"na{manifest['n_joints']}-{key}"
    lib = out_dir / "model.so"
    stamp = out_dir / "model.so.sha256"
    if not rebuild and _library_ok(lib, stamp):
        return lib
    make_private_dir(out_dir)
    with held_lock(out_dir / "build.lock", f"compile the {manifest['n_joints']}-joint model"):
        if rebuild:
            stamp.unlink(missing_ok=True)
            lib.unlink(missing_ok=True)
        if _library_ok(lib, stamp):
            return lib
        if lib.exists() or stamp.exists():
            _report_once(str(lib), f"snakecg: the cached library {lib} is corrupted or"
                         " incomplete (it does not match its checksum); rebuilding it")
        # Leftovers of builds that were killed: only the lock holder builds here.
        for stale in out_dir.glob("build-*"):
            shutil.rmtree(stale, ignore_errors=True)
        step = progress or (lambda msg: None)
        sources = sorted(n for n in manifest["files"] if n.endswith(".c"))
        large = {f"c/{f['name']}.c" for f in manifest["functions"] if f.get("large")}
        tmp = Path(tempfile.mkdtemp(prefix="build-", dir=out_dir))
        what = f"the {manifest['n_joints']}-joint model"
        t_start = time.perf_counter()
        try:
            step(f"compiling {what}: {len(sources)} C files with {Path(cc).name} -O2 (once; "
                 "the library is cached)")

            def one(name: str) -> Path:
                obj = tmp / (Path(name).stem + ".o")
                if Path(name).stem in SETUP_FUNCTIONS:
                    flags = SETUP_FLAGS
                else:
                    flags = OPT_FLAGS + (LARGE_FLAGS if name in large else [])
                _run([cc, *flags, "-c", str(folder / name), "-o", str(obj)])
                return obj

            core, layout = _core_sources(manifest)
            (tmp / "snakecg_layout.h").write_text(layout, encoding="utf-8")
            for name, text in core.items():  # the header under its own name (#include)
                target = name if name.endswith(".h") else f"snakecg_core_{name}"
                (tmp / target).write_bytes(text)

            def one_core(name: str) -> Path:
                obj = tmp / f"snakecg_core_{Path(name).stem}.o"
                _run([cc, *CORE_FLAGS, "-I", str(tmp), "-c", str(tmp / f"snakecg_core_{name}"),
                      "-o", str(obj)])
                return obj

            # largest first, so that the long compiles of a large model start at once and
            # the small files fill the gaps (the wall time is not bound by a late large file)
            jobs = [(len(core[name]), one_core, name) for name in core if name.endswith(".c")]
            jobs += [((folder / name).stat().st_size, one, name) for name in sources]
            jobs.sort(key=lambda job: -job[0])
            with ThreadPoolExecutor(max_workers=max(1, os.cpu_count() or 1)) as pool:
                futures = [pool.submit(fn, name) for _, fn, name in jobs]
                objs = sorted((f.result() for f in futures), key=lambda o: o.name)
            tmp_lib = tmp / "model.so"
            link = [cc, "-shared", *[str(o) for o in objs], "-o", str(tmp_lib), "-lm"]
            _run(link)
            if not tmp_lib.is_file():
                raise BuildError(f"the C compiler wrote no library: {' '.join(link)}",
                                 command=link)
            digest = hashlib.sha256(tmp_lib.read_bytes()).hexdigest()
            # the stamp goes first and comes back last: a library is trusted only with it
            stamp.unlink(missing_ok=True)
            os.replace(tmp_lib, lib)
            tmp_stamp = tmp / "stamp"
            tmp_stamp.write_text(digest)
            os.replace(tmp_stamp, stamp)
            step(f"compiled {what} in {time.perf_counter() - t_start:.1f} s")
        except BaseException:
            step(f"compiling {what}: failed after {time.perf_counter() - t_start:.1f} s")
            raise
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    return lib


def _report_once(key: str, message: str) -> None:
    if key not in _warned:
        _warned.add(key)
        warnings.warn(message, RuntimeWarning, stacklevel=4)


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
        self.out_offsets = [0]
        for r, c in self.out_shapes:
            self.out_offsets.append(self.out_offsets[-1] + r * c)


def _signature_problems(sig: dict, n_in: int, n_out: int, size_in, size_out) -> list[str]:
    """Where a manifest signature disagrees with the code's own (n_in, n_out, shapes)."""
    out = []
    if n_in != len(sig["inputs"]) or n_out != len(sig["outputs"]):
        return [f"{sig['name']} has {n_in} inputs and {n_out} outputs, the manifest says "
                f"{len(sig['inputs'])} and {len(sig['outputs'])}"]
    for kind, items, size in (("input", sig["inputs"], size_in),
                              ("output", sig["outputs"], size_out)):
        for k, item in enumerate(items):
            actual = size(k)
            if actual != (item["rows"], item["cols"]):
                out.append(f"{sig['name']} {kind} {item['name']!r} is {actual[0]}x{actual[1]}, "
                           f"the manifest says {item['rows']}x{item['cols']}")
    return out


class ManifestMismatch(ArtifactError):
    """The manifest's function signatures disagree with its own hash-verified code (the
    manifest was edited or damaged): the model folder is regenerated
    (:func:`snakecg.artifacts.regenerate`)."""


def _check_signatures(where, manifest: dict, problems: list[str]) -> None:
    """The buffers are sized from the manifest: refuse code whose functions have other shapes
    (a manifest edited or damaged without breaking its JSON would otherwise make the compiled
    drivers write past the ends of the output arrays)."""
    if problems:
        shown = "; ".join(problems[:3]) + (f" (and {len(problems) - 3} more)"
                                           if len(problems) > 3 else "")
        raise ManifestMismatch(
            f"{where}: the generated functions do not match manifest.json of the model for "
            f"joints={manifest.get('n_joints')}: {shown}. The model folder is damaged: "
            "reinstall snakecg, or delete the snakecg cache folder (SNAKECG_CACHE_DIR)"
        )


def _library_problems(lib, manifest: dict) -> list[str]:
    """Compare the manifest with CasADi's own signature functions in the compiled library."""
    problems = []
    for sig in manifest["functions"]:
        sym = sig["symbol"]
        try:
            n_in, n_out, size_in, size_out = lib.signature(sym)
        except AttributeError:
            problems.append(f"{sym} is not in the library")
            continue
        problems += _signature_problems(sig, n_in, n_out, size_in, size_out)
    return problems


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
    """Calls the compiled batched drivers ``<prefix>batch_<function>`` (bound in
    :mod:`snakecg.engine.binding`)."""

    kind = "compiled"

    def __init__(self, lib_path: Path, manifest: dict):
        self.path = lib_path
        self.prefix = manifest["prefix"]
        self._lib = Library(lib_path, self.prefix)
        self.signatures = {s["name"]: _Signature(s) for s in manifest["functions"]}
        self._fns = {name: self._lib.batch(name) for name in self.signatures}
        _check_signatures(lib_path, manifest, _library_problems(self._lib, manifest))
        from .engine import Core

        self.core = Core(self._lib, manifest)
        """The runtime core's ``core_forward`` (snakecg.engine), compiled into the library."""

    def __call__(self, name: str, n: int, inputs: list[np.ndarray]) -> list[np.ndarray]:
        """Evaluate ``name`` on ``n`` samples.

        ``inputs[k]`` is float64 C-contiguous, either of size ``in_sizes[k]`` (broadcast) or
        of shape ``(n, in_sizes[k])``.
        """
        sig = self.signatures[name]
        n_in = len(sig.in_sizes)
        argp = empty_pointers(n_in)
        strides = int64s(n_in)
        # Reading an array's address (``a.ctypes.data``) costs about 1 us, as much as the C call
        # for one sample, so broadcast (1-D) inputs are packed into one buffer and small
        # batches get one output buffer: one address lookup each instead of one per array.
        shared = []
        for k, (a, size) in enumerate(zip(inputs, sig.in_sizes)):
            _check_input(sig, k, a, n, size)
            if a.ndim == 1:
                shared.append(k)
            else:
                argp[k] = a.ctypes.data
                strides[k] = size
        if shared:
            packed = np.concatenate([inputs[k] for k in shared])  # alive until the call returns
            base, off = packed.ctypes.data, 0
            for k in shared:
                argp[k] = base + 8 * off
                off += sig.in_sizes[k]
        if n <= _SMALL_BATCH:
            buf = np.empty(n * sig.out_offsets[-1])
            base = buf.ctypes.data
            resp = pointers(base + 8 * n * o for o in sig.out_offsets[:-1])
            outs = [buf[n * o: n * (o + r * c)].reshape(n, c, r)
                    for o, (r, c) in zip(sig.out_offsets, sig.out_shapes)]
        else:
            outs = [np.empty((n, c, r)) for (r, c) in sig.out_shapes]
            resp = pointers(o.ctypes.data for o in outs)
        if threads(n, _PARALLEL_MIN) > 1:
            status = self._parallel(name, n, argp, strides, resp, sig)
        else:
            status = self._fns[name](n, argp, strides, resp)
        if status != 0:
            raise BuildError(f"{name}: evaluation failed at sample {status - 1} (status {status})")
        return [o.transpose(0, 2, 1) for o in outs]

    def _parallel(self, name, n, argp, strides, resp, sig) -> int:
        """Split a large batch into contiguous chunks evaluated on several threads.

        ctypes releases the GIL during the call and every driver call allocates its own work
        arrays, so the chunks run truly in parallel (``SNAKECG_THREADS``; one thread by default:
        :mod:`snakecg.engine.threads`).
        """
        workers = threads(n, _PARALLEL_MIN)
        bounds = np.linspace(0, n, workers + 1).astype(np.int64)
        n_in, n_out = len(sig.in_sizes), len(sig.out_shapes)
        nnz = [r * c for r, c in sig.out_shapes]
        jobs = []
        for lo, hi in zip(bounds[:-1], bounds[1:]):
            if hi <= lo:
                continue
            a = pointers((argp[k] or 0) + 8 * int(lo) * strides[k] for k in range(n_in))
            r = pointers(resp[k] + 8 * int(lo) * nnz[k] for k in range(n_out))
            jobs.append((int(lo), int(hi - lo), a, r))
        fn = self._fns[name]
        results = list(pool().map(lambda j: (j[0], fn(j[1], j[2], strides, j[3])), jobs))
        for lo, status in results:
            if status != 0:
                return status + lo if status > 0 else status
        return 0


class CasadiBackend:
    """CasADi's in-process evaluation of the generated functions, deserialized from
    ``casadi/<name>.casadi`` (CasADi's data format, hash-checked; never executed)."""

    kind = "casadi"
    core = None  # no compiled runtime core: forward takes the reference path

    def __init__(self, folder: Path, manifest: dict):
        import casadi as ca

        self.signatures = {s["name"]: _Signature(s) for s in manifest["functions"]}
        self._fns = {}
        problems = []
        for sig in manifest["functions"]:
            # CasADi's serialization, hash-checked by verify_model_dir; data, never executed.
            rel = f"casadi/{sig['name']}.casadi"
            if rel not in manifest["files"]:
                problems.append(f"{sig['name']} has no serialized CasADi function")
                continue
            try:
                f = ca.Function.deserialize((folder / rel).read_text(encoding="utf-8"))
            except (OSError, RuntimeError, UnicodeDecodeError) as exc:
                problems.append(f"{rel} cannot be deserialized ({exc})")
                continue
            self._fns[sig["name"]] = f
        self._maps: dict[tuple[str, int], object] = {}
        for sig in manifest["functions"]:
            f = self._fns.get(sig["name"])
            if f is None:
                continue
            problems += _signature_problems(
                sig, f.n_in(), f.n_out(), lambda k, f=f: (f.size1_in(k), f.size2_in(k)),
                lambda k, f=f: (f.size1_out(k), f.size2_out(k)))
        _check_signatures(folder / "casadi", manifest, problems)

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


def _load_fresh(lib: Path, manifest: dict) -> CompiledBackend:
    """Load a just rebuilt library through a new name: the dynamic loader would otherwise
    hand back the library of that path that this process loaded before."""
    link = lib.with_name(f".load-{os.getpid()}-{os.urandom(4).hex()}.so")
    try:
        os.link(lib, link)
    except OSError:
        shutil.copyfile(lib, link)
    try:
        backend = CompiledBackend(link, manifest)
    finally:
        link.unlink(missing_ok=True)
    backend.path = lib
    return backend


def load_backend(folder: Path, manifest: dict, *, prefer: str = "compiled", progress=None):
    """The compiled backend, or CasADi's in-process one (with one warning) if compiling fails.

    A cached library that matches its checksum but not the model (a foreign library whose
    checksum was recomputed, a library missing a function) is rebuilt once, with one line
    saying why; only if that fails too does the model fall back to CasADi. A cache that
    cannot be written (read-only) falls back with one warning.
    """
    if prefer not in ("compiled", "casadi"):
        raise ValueError(f"backend must be 'compiled' or 'casadi', got {prefer!r}")
    if prefer == "compiled" and os.environ.get("SNAKECG_BACKEND", "") != "casadi":
        try:
            lib = compile_model(folder, manifest, progress=progress)
            try:
                return CompiledBackend(lib, manifest)
            except (OSError, AttributeError, ArtifactError) as exc:
                # rebuilt from the verified C; reported once it loads (a library rebuilt
                # that still disagrees shows the manifest is wrong: ManifestMismatch)
                backend = _load_fresh(compile_model(folder, manifest, progress=progress,
                                                    rebuild=True), manifest)
                _report_once(
                    f"{lib}:foreign",
                    f"snakecg: the cached library {lib} does not belong to this model "
                    f"({_one_line(exc)}); rebuilding it")
                return backend
        except ManifestMismatch:  # the library built from the verified C disagrees too:
            raise                 # the manifest is wrong, the model folder is regenerated
        except BuildError as exc:
            _report_once(
                f"{manifest['n_joints']}:{exc}",
                "snakecg: using CasADi's in-process evaluation (slower) because the C build "
                f"failed: {exc}",
            )
        except ArtifactError as exc:  # the cache cannot be written (read-only, full, ...)
            _report_once(
                f"{manifest['n_joints']}:cache:{exc}",
                "snakecg: using CasADi's in-process evaluation (slower) because the compiled "
                f"library cannot be built in the cache: {_one_line(exc)}",
            )
        except (OSError, AttributeError) as exc:  # dlopen failed, or a symbol is missing
            _report_once(
                f"{manifest['n_joints']}:load:{exc}",
                f"snakecg: using CasADi's in-process evaluation (slower) because the compiled "
                f"model cannot be loaded: {_one_line(exc)}",
            )
    return CasadiBackend(folder, manifest)


def _one_line(exc) -> str:
    text = " ".join(str(exc).split())
    return text if len(text) <= 300 else text[:297] + "..."

