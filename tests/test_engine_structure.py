"""The shape of the runtime, checked on its sources: no import circle in ``snakecg/`` (lazy
imports included), ctypes in one binding module, and one C engine whose files share one
header of prototypes, one prefix and one integer type."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import snakecg

PACKAGE = Path(snakecg.__file__).resolve().parent
ENGINE = PACKAGE / "engine"


def _modules() -> dict[str, Path]:
    mods = {}
    for path in PACKAGE.rglob("*.py"):
        parts = ["snakecg", *path.relative_to(PACKAGE).with_suffix("").parts]
        if parts[-1] == "__init__":
            parts = parts[:-1]
        mods[".".join(parts)] = path
    return mods


def _import_graph() -> dict[str, set[str]]:
    """Every import of every module of snakecg (module level, function level, under
    TYPE_CHECKING: all of them), as edges to the snakecg modules named."""
    mods = _modules()
    graph: dict[str, set[str]] = {m: set() for m in mods}
    for name, path in mods.items():
        package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                    module = ".".join(base + ([node.module] if node.module else []))
                else:
                    module = node.module or ""
                # `from pkg import sub` imports the submodule; `from mod import name` the module
                targets = [f"{module}.{a.name}" if f"{module}.{a.name}" in mods else module
                           for a in node.names]
            else:
                continue
            graph[name] |= {t for t in targets if t in mods and t != name}
    return graph


def _cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """One import circle of ``graph`` (depth-first search), or None."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> list[str] | None:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph[node]):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def test_the_import_graph_finds_a_planted_circle():
    """The search itself: a circle through three modules is found, a chain is not."""
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": set()}) is None


def test_no_import_circle_in_snakecg():
    graph = _import_graph()
    assert len(graph) > 90  # every module was read
    assert "snakecg.model" in graph["snakecg"]
    cycle = _cycle(graph)
    assert cycle is None, "import circle: " + " -> ".join(cycle)


def test_feature_packages_never_import_the_facade():
    """analysis, optimize, simulate and shape import the engine, never snakecg.model (a
    SceneModel is recognised by snakecg.kinds)."""
    graph = _import_graph()
    features = [m for m in graph if m == "snakecg.analysis" or m.split(".")[:2] in (
        ["snakecg", "optimize"], ["snakecg", "simulate"], ["snakecg", "shape"])]
    assert len(features) > 20
    importers = sorted(m for m in features if "snakecg.model" in graph[m])
    assert importers == []


def test_the_engine_imports_nothing_above_it():
    """snakecg.engine is the low layer: its modules import only each other and the error
    types (the rules both engines share live in snakecg.engine.rules, not in the Python
    engine's modules)."""
    graph = _import_graph()
    engine = [m for m in graph if m == "snakecg.engine" or m.startswith("snakecg.engine.")]
    assert len(engine) >= 8
    upward = sorted((m, t) for m in engine for t in graph[m]
                    if not (t == "snakecg.engine" or t.startswith("snakecg.engine."))
                    and t not in ("snakecg", "snakecg.errors"))
    assert upward == []


def test_ctypes_is_imported_by_the_binding_only():
    users = []
    for name, path in _modules().items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
            if any(n.split(".")[0] == "ctypes" for n in names):
                users.append(name)
    assert sorted(set(users)) == ["snakecg.engine.binding"]


def _c_sources() -> dict[str, str]:
    return {p.name: p.read_text(encoding="utf-8") for p in sorted(ENGINE.glob("*.[ch]"))}


def test_every_c_file_is_compiled_and_includes_the_one_header():
    from snakecg.native import CORE_HEADERS, CORE_SOURCES

    sources = _c_sources()
    assert sorted(p.name for p in CORE_SOURCES) == sorted(n for n in sources if n.endswith(".c"))
    # engine.h and linalg.h, and a file's own header (what two files of one step share),
    # named after the C file that defines what it declares, included after engine.h
    own = sorted(n for n in sources if n.endswith(".h") and n not in ("engine.h", "linalg.h"))
    assert all(n[:-2] + ".c" in sources for n in own), own
    assert sorted(p.name for p in CORE_HEADERS) == sorted(["engine.h", "linalg.h", *own])
    for name, text in sources.items():
        if name.endswith(".c"):
            included = re.findall(r'^#include "([^"]+)"', text, re.M)
            assert included[:2] == ["snakecg_layout.h", "engine.h"], name
            assert set(included[2:]) <= set(own), name


def test_no_c_file_declares_a_function_of_another_file():
    """A prototype at file scope (a declaration ending in ``);``) belongs in engine.h."""
    declaration = re.compile(r"^(?:static\s+|extern\s+)?[A-Za-z_][\w \*]*\b(\w+)\s*\([^;{]*\)\s*;",
                             re.M)
    for name, text in _c_sources().items():
        if name.endswith(".c"):
            assert declaration.findall(text) == [], name


def test_one_prefix_and_one_integer_type():
    """Every function and type the C files define starts with sc_ (static helpers of one file
    may be unprefixed; SNAKECG_* are the model's generated symbols), and sc_int is the only
    integer typedef."""
    sources = _c_sources()
    typedefs = [m for text in sources.values()
                for m in re.findall(r"typedef\s+long\s+long\s+int\s+(\w+)\s*;", text)]
    assert typedefs == ["sc_int"]
    for name, text in sources.items():
        for old in ("sk_", "pc_", "op_", "geo_"):
            assert not re.search(rf"\b{old}\w+\s*\(", text), (name, old)
        for fn in re.findall(r"^(?:SC_INTERNAL\s+)?(?:int|void|double|sc_int)\s+\**(\w+)\s*\(",
                             text, re.M):
            assert fn.startswith(("sc_", "SNAKECG_")), (name, fn)


def test_engine_files_are_under_600_lines():
    for path in [*ENGINE.glob("*.[ch]"), *ENGINE.glob("*.py")]:
        lines = path.read_text(encoding="utf-8").count("\n")
        assert lines < 600, f"{path.name}: {lines} lines"


def test_no_per_model_state_outside_its_data():
    """No module keeps per-model state (a WeakKeyDictionary keyed by models) and no step
    stashes a key in a model's ``__dict__``: every workspace is the model's Data's."""
    for name, path in _modules().items():
        text = path.read_text(encoding="utf-8")
        assert "WeakKeyDictionary" not in text, name
        assert not re.search(r"model\.__dict__", text), name


def test_one_data_holds_the_workspaces_of_every_step():
    """forward, optimize and simulate leave their workspaces in ``model.data()`` and nothing
    on the model; ``create_data()`` is a new, empty one (one per thread)."""
    import numpy as np

    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels"))
    before = set(vars(model))
    q = np.array([0.0, 0.0, 0.0, 0.4, -0.3])
    model.forward(q, [0.1, -0.1])
    model.optimize(q, "max_sr", radius=1.0)
    model.simulate(q, [0.05, -0.05], 0.01)
    assert set(vars(model)) == before
    data = model.data()
    assert data is model.data()
    assert {"optimize.no_slide", "simulate.constants"} <= set(data.derived)
    assert len(data.simulation_pool) == 1
    other = model.create_data()
    assert other is not data and other.derived == {} and other.simulation_pool == []


def test_only_the_facade_layer_imports_the_facade():
    """snakecg.model is imported by the package's __init__ and the CLI layer (snakecg.cli,
    snakecg.commands) alone: figures, sweeps, export and reproduce load a scene they are given
    through snakecg.loading, which the facade fills when the package is imported."""
    graph = _import_graph()
    importers = sorted(m for m, targets in graph.items() if "snakecg.model" in targets)
    allowed = {"snakecg", "snakecg.cli"}
    assert [m for m in importers if m not in allowed
            and not m.startswith("snakecg.commands")] == []
    assert "snakecg" in importers  # the import graph sees the facade's importer


def test_the_loader_the_features_call_is_the_facades():
    import snakecg.loading

    assert snakecg.loading._LOADER == [snakecg.load]


def test_scene_model_methods_are_one_liners():
    """Every public method SceneModel defines itself is a call of a free function that takes
    the model (an import of that function aside), or is that function itself."""
    import inspect
    import textwrap

    from snakecg.model import SceneModel

    for name, fn in vars(SceneModel).items():
        if name.startswith("_") or not inspect.isfunction(fn) or fn.__qualname__.split(".")[0] \
                != "SceneModel":
            continue
        body = ast.parse(textwrap.dedent(inspect.getsource(fn))).body[0].body
        body = [s for s in body if not (isinstance(s, ast.Expr)
                                        and isinstance(s.value, ast.Constant))]  # docstring
        body = [s for s in body if not isinstance(s, (ast.Import, ast.ImportFrom))]
        assert len(body) <= 1 or name == "optimize", (name, len(body))
