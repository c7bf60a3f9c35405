"""Committed artefacts are proven fresh: regenerating ``generated/`` gives the same bytes.

The comparison is only meaningful with the generator toolchain that produced the checked-in
files (the versions recorded in each manifest's ``tools``); with another SymPy/CasADi/Jinja2
the test fails and says to install the pinned test extra, rather than skipping silently.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from importlib import metadata
from pathlib import Path

import pytest
import sympy as sp

from snakecg_derive import FunctionSpec, derive_model
from snakecg_derive.render import CHECKED_IN_JOINTS, render_model, write_index, write_model

GENERATED = Path(__file__).parents[1] / "generated"


def _recorded_tools() -> dict[str, str]:
    return json.loads((GENERATED / "na1" / "manifest.json").read_text())["tools"]


def _require_pinned_toolchain() -> None:
    recorded = _recorded_tools()
    installed = {}
    for dist in recorded:
        try:
            installed[dist] = metadata.version(dist)
        except metadata.PackageNotFoundError:
            installed[dist] = "not installed"
    if installed != recorded:
        pytest.fail(
            f"generated/ was produced with {recorded}, but {installed} is installed; the "
            "byte-for-byte freshness check needs the same generator versions: "
            "pip install '.[test]' (it pins them)",
            pytrace=False,
        )


def _files(root: Path) -> dict[str, bytes]:
    """Every planar file under ``root`` (``spatial/`` has its own freshness test,
    tests/test_spatial_derive.py)."""
    return {
        p.relative_to(root).as_posix(): p.read_bytes()
        for p in sorted(root.rglob("*"))
        if p.is_file() and "__pycache__" not in p.parts
        and p.relative_to(root).parts[0] != "spatial"
    }


def test_checked_in_models_record_one_toolchain():
    tools = [json.loads((GENERATED / f"na{n}" / "manifest.json").read_text())["tools"]
             for n in CHECKED_IN_JOINTS]
    assert all(t == tools[0] for t in tools)
    assert set(tools[0]) == {"sympy", "casadi", "jinja2"}


def test_regenerated_models_are_byte_identical(tmp_path):
    """Render n_a = 1..6 and the index into a temporary folder (about 5 s); compare every
    file, and that no file is missing or extra on either side."""
    _require_pinned_toolchain()
    for n in CHECKED_IN_JOINTS:
        write_model(render_model(n), tmp_path)
    write_index(tmp_path)
    fresh, committed = _files(tmp_path), _files(GENERATED)
    assert sorted(fresh) == sorted(committed), "file lists differ; regenerate with: " \
        "python -m snakecg_derive --checked-in --out generated"
    stale = [name for name in committed if fresh[name] != committed[name]]
    assert not stale, (f"stale generated files {stale}; regenerate with: "
                       "python -m snakecg_derive --checked-in --out generated")


def test_spec_digest_is_deterministic_across_processes():
    """Same digest twice in this process, and in two processes with different hash seeds
    (catches argument orders built from sets), equal to the checked-in manifest's."""
    digest = derive_model(2).spec.digest()
    assert derive_model(2).spec.digest() == digest
    code = "from snakecg_derive import derive_model; print(derive_model(2).spec.digest())"
    for seed in ("1", "12345"):
        env = {**os.environ, "PYTHONHASHSEED": seed}
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                             env=env, timeout=300, check=True).stdout.strip()
        assert out == digest, f"digest differs with PYTHONHASHSEED={seed}"
    manifest = json.loads((GENERATED / "na2" / "manifest.json").read_text())
    assert manifest["spec_hash"] == digest


def test_check_closed_rejects_symbol_of_no_input():
    x, y, t = sp.symbols("x y t", real=True)
    ok = FunctionSpec(name="f", doc="", inputs=(("u", (x,), ""),),
                      outputs=(("out", sp.Matrix([x**2]), ""),))
    ok.check_closed()
    bad = FunctionSpec(name="g", doc="", inputs=(("u", (x,), ""),),
                       assignments=((t, 2 * x),),
                       outputs=(("out", sp.Matrix([t + y]), ""),))
    with pytest.raises(ValueError, match=r"function 'g': free symbols belong to no input: "
                                         r"output out uses \['y'\]"):
        bad.check_closed()
    bad_assignment = FunctionSpec(name="h", doc="", inputs=(("u", (x,), ""),),
                                  assignments=((t, x * y),),
                                  outputs=(("out", sp.Matrix([t]), ""),))
    with pytest.raises(ValueError, match=r"assignment t uses \['y'\]"):
        bad_assignment.check_closed()


# ------------------------------------------------------------------------------------------
# the generated C is strict C99 (as CasADi's own tests compile theirs: warnings are errors)
STRICT = ["-std=c99", "-Wall", "-pedantic", "-Werror", "-O2", "-fPIC"]


def _compiler() -> str:
    import shutil

    cc = shutil.which(os.environ.get("CC", "") or "cc") or shutil.which("gcc")
    if cc is None:
        pytest.fail("no C compiler: the strict-C99 check needs one (install gcc)", pytrace=False)
    return cc


@pytest.mark.parametrize("joints", [1, 3])
def test_checked_in_c_is_strict_c99(joints, tmp_path):
    """Every checked-in C file of na1 and na3 (unrolled SX composition) compiles with
    ``-std=c99 -Wall -pedantic -Werror``."""
    cc = _compiler()
    for src in sorted((GENERATED / f"na{joints}" / "c").glob("*.c")):
        res = subprocess.run([cc, *STRICT, "-c", str(src), "-o", str(tmp_path / "x.o")],
                             capture_output=True, text=True, timeout=600)
        assert res.returncode == 0, f"{src.name}:\n{res.stderr[-3000:]}"


def test_matrix_structured_c_is_strict_c99(tmp_path):
    """The matrix-structured (MX) composition used for large joint counts, rendered here for
    two joints, compiles with the same strict flags (CasADi's linear-solver and loop code)."""
    cc = _compiler()
    rendered = render_model(2, algebra="mx")
    assert rendered.manifest["algebra"]["composed"] == "mx"
    composed = [f for f in rendered.manifest["functions"] if f["algebra"] == "mx"]
    assert [f["name"] for f in composed] == ["constrained_dynamics", "interaction_maps",
                                             "metric_forms", "place_object", "contact_system",
                                             "contact_system_at_rest"]
    for name in ("constrained_dynamics", "interaction_maps", "metric_forms", "contact_system",
                 "contact_system_at_rest"):
        src = tmp_path / f"{name}.c"
        src.write_text(rendered.files[f"c/{name}.c"])
        res = subprocess.run([cc, *STRICT, "-c", str(src), "-o", str(tmp_path / "x.o")],
                             capture_output=True, text=True, timeout=600)
        assert res.returncode == 0, f"{name}.c:\n{res.stderr[-3000:]}"


@pytest.mark.parametrize("joints", [1, 3, 6])
def test_runtime_core_is_strict_c99(joints, tmp_path):
    """The runtime core (every C file of snakecg/engine) with the layout header written from a
    model's manifest compiles with the strict flags and -Wextra."""
    from snakecg.engine.layout import header
    from snakecg.native import CORE_SOURCES

    cc = _compiler()
    manifest = json.loads((GENERATED / f"na{joints}" / "manifest.json").read_text())
    (tmp_path / "snakecg_layout.h").write_text(header(manifest))
    for source in CORE_SOURCES:
        res = subprocess.run([cc, *STRICT, "-Wextra", "-I", str(tmp_path), "-c", str(source),
                              "-o", str(tmp_path / "core.o")], capture_output=True, text=True,
                             timeout=600)
        assert res.returncode == 0, f"{source.name}:\n{res.stderr[-3000:]}"
