"""The documentation cannot rot: its examples run, its promises about the CLI hold, it builds.

* Every fenced ```` ```python ```` block of ``docs/*.md`` and ``README.md`` is executed; the
  blocks of one page run in order in one namespace (a page reads like one session), with the
  repository root as working directory (examples use ``examples/robot.toml``).
* Every ```` ```console ```` block is executed: each ``$ snakecg ...`` line runs the CLI in
  process and must exit 0; when the block shows output after a command, the actual output
  must match it — text token by token, numbers to a relative 1e-6. (``bash`` blocks are
  install commands and long runs, shown but not executed; the reproduction itself has its own
  tests.)
* The doctests of the modules that the API reference renders run too.
* The CLI behaviour that docs/reference/cli.md documents: exit statuses, one-line errors with a
  hint, ``--version``, an example in every command's help, the JSON schemas' fields, progress lines
  on every stream (bars on a terminal only).
* ``mkdocs build --strict`` succeeds (when MkDocs is installed; otherwise skipped, saying so),
  and the generated pages contain what the hooks promise.
"""

from __future__ import annotations

import doctest
import importlib
import io
import json
import math
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
PAGES = sorted(DOCS.rglob("*.md")) + [ROOT / "README.md"]

FENCE = re.compile(r"^(?P<indent>[ ]*)```(?P<info>[^\n`]*)\n(?P<body>.*?)^(?P=indent)```[ ]*$",
                   re.MULTILINE | re.DOTALL)


def fenced_blocks(path: Path, language: str) -> list[tuple[int, str]]:
    """``(line number, code)`` of every fenced block whose info string starts with
    ``language``."""
    text = path.read_text(encoding="utf-8")
    out = []
    for m in FENCE.finditer(text):
        info = m.group("info").strip().split()
        if info and info[0] == language:
            indent = len(m.group("indent"))
            body = "\n".join(line[indent:] for line in m.group("body").splitlines())
            out.append((text.count("\n", 0, m.start()) + 1, body))
    return out


def _rel(path: Path) -> str:
    return str(path.relative_to(ROOT))


# ------------------------------------------------------------------------------------------
# 1. python blocks
# ------------------------------------------------------------------------------------------
PYTHON_PAGES = [p for p in PAGES if fenced_blocks(p, "python")]


@pytest.mark.parametrize("page", PYTHON_PAGES, ids=_rel)
def test_python_blocks_run(page, monkeypatch):
    monkeypatch.chdir(ROOT)
    namespace = {"__name__": f"docs_{page.stem.replace('-', '_')}"}
    for line, code in fenced_blocks(page, "python"):
        try:
            exec(compile(code, f"{_rel(page)}:{line}", "exec"), namespace)  # noqa: S102
        except Exception as exc:
            raise AssertionError(
                f"the python block at {_rel(page)}:{line} failed: {type(exc).__name__}: {exc}"
            ) from exc


def test_the_docs_have_examples():
    """Guards the extraction itself: the pages that must carry runnable examples do."""
    names = {p.relative_to(DOCS).as_posix() if p.is_relative_to(DOCS) else p.name
             for p in PYTHON_PAGES}
    for required in ("README.md", "tutorials/getting-started.md", "tutorials/robot-to-result.md",
                     "explanation/model.md", "explanation/scenarios.md", "explanation/metrics.md",
                     "explanation/generated-code.md", "explanation/symbolic.md"):
        assert required in names, f"no ```python block found in {required}"


# ------------------------------------------------------------------------------------------
# 2. console blocks: `$ snakecg ...` lines run and, where output is shown, match it
# ------------------------------------------------------------------------------------------
def console_commands(page: Path) -> list[tuple[int, list[str], list[str]]]:
    """``(line, argv, expected output lines)`` of every ``$ snakecg`` command of a page."""
    out = []
    for line, body in fenced_blocks(page, "console"):
        current = None
        for k, text in enumerate(body.splitlines()):
            if text.startswith("$ "):
                argv = shlex.split(text[2:])
                assert argv[0] == "snakecg", f"{_rel(page)}:{line + k + 1}: not a snakecg command"
                current = (line + k + 1, argv[1:], [])
                out.append(current)
            elif current is not None:
                current[2].append(text)
    return out


CONSOLE = [(page, *cmd) for page in PAGES for cmd in console_commands(page)]

_NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?%?$")


def _tokens(text: str) -> list[str]:
    return re.sub(r"[\[\](),=]", " ", text).split()


def assert_output_matches(actual: str, expected: list[str], where: str) -> None:
    got, want = _tokens(actual), _tokens("\n".join(expected))
    assert len(got) == len(want), f"{where}: output differs from the docs:\n{actual}"
    for g, w in zip(got, want):
        if _NUMBER.match(w) and _NUMBER.match(g):
            gv, wv = float(g.rstrip("%")), float(w.rstrip("%"))
            ok = math.isclose(gv, wv, rel_tol=1e-6, abs_tol=1e-9 + 0.5 * 10 ** -_decimals(w))
            assert ok, f"{where}: {g} != {w} (documented)\n{actual}"
        else:
            assert g == w, f"{where}: {g!r} != {w!r} (documented)\n{actual}"


def _decimals(number: str) -> int:
    mantissa = re.split(r"[eE]", number.rstrip("%"))[0]
    return len(mantissa.split(".")[1]) if "." in mantissa else 0


@pytest.mark.parametrize("page, line, argv, expected", CONSOLE,
                         ids=[f"{_rel(p)}:{ln}" for p, ln, _, _ in CONSOLE])
def test_console_commands_run(page, line, argv, expected, monkeypatch, capsys):
    from snakecg.cli import main

    monkeypatch.chdir(ROOT)
    try:
        status = main(argv)
    except SystemExit as exc:  # --version and --help exit through argparse
        status = exc.code
    captured = capsys.readouterr()
    where = f"{_rel(page)}:{line}: snakecg {' '.join(argv)}"
    assert status == 0, f"{where}: exit {status}\n{captured.err}"
    if "--json" in argv:
        json.loads(captured.out)
    if expected:
        assert_output_matches(captured.out, expected, where)


# ------------------------------------------------------------------------------------------
# 3. doctests of the modules the API reference renders
# ------------------------------------------------------------------------------------------
_API_TEXT = (DOCS / "reference" / "api.md").read_text(encoding="utf-8")
API_NAMES = re.findall(r"^::: (snakecg[\w.]*)", _API_TEXT, re.MULTILINE) + [
    # entries the site hook renders once the module exists (docs/hooks/site.py)
    m for m in re.findall(r"<!--\s*snakecg-api:\s*([\w.]+)\s*-->", _API_TEXT)
    if (ROOT / Path(*m.split("."))).with_suffix(".py").is_file()
    or (ROOT / Path(*m.split(".")) / "__init__.py").is_file()
]


def _module_of(name: str) -> str:
    """The module part of a dotted API name (``snakecg.model.RobotModel`` -> ``snakecg.model``)."""
    parts = name.split(".")
    while parts:
        try:
            importlib.import_module(".".join(parts))
            return ".".join(parts)
        except ModuleNotFoundError:
            parts.pop()
    raise AssertionError(f"no module in {name}")


DOCTEST_MODULES = sorted({_module_of(n) for n in API_NAMES} | {"snakecg"})


@pytest.mark.parametrize("module", DOCTEST_MODULES)
def test_api_doctests(module, monkeypatch):
    monkeypatch.chdir(ROOT)
    mod = importlib.import_module(module)
    result = doctest.testmod(mod, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE,
                             verbose=False)
    assert result.failed == 0, f"{result.failed} doctest(s) of {module} failed"


# ------------------------------------------------------------------------------------------
# 4. the CLI promises of docs/reference/cli.md
# ------------------------------------------------------------------------------------------
def _subparsers():
    import argparse

    from snakecg.cli import build_parser

    parser = build_parser()
    (action,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return parser, action.choices


def test_every_command_help_has_an_example():
    parser, subs = _subparsers()
    assert "examples:" in parser.format_help()
    assert {"generate", "show", "forward"} <= set(subs)
    for name, sub in subs.items():
        text = sub.format_help()
        assert re.search(rf"^\s*(example:\s*)?snakecg {name}\b", text, re.MULTILINE), (
            f"snakecg {name} --help shows no example line"
        )
        for action in sub._actions:
            if action.option_strings and action.dest != "help":
                assert action.help, f"snakecg {name} {action.option_strings[0]} has no help"


def test_version_and_usage_errors(capsys):
    import snakecg
    from snakecg.cli import main

    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out.strip() == f"snakecg {snakecg.__version__}"
    for argv in (["no-such-command"], ["show", "--joints", "two"], ["forward", "--q", "0"]):
        with pytest.raises(SystemExit) as exc:
            main(argv)
        assert exc.value.code == 2
        err = capsys.readouterr().err
        assert len(err.splitlines()) == 1 and "--help" in err, err
    assert main([]) == 2 and "usage:" in capsys.readouterr().err


def test_input_errors_are_one_line_with_a_hint_exit_2(capsys):
    from snakecg.cli import main

    assert main(["show", "--joints", "1", "nothing"]) == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1
    assert err.startswith("snakecg show: error: unknown expression 'nothing'")
    assert "choose one of: M, M_expanded" in err and "(see snakecg show --help)" in err


def test_failures_exit_1(tmp_path, capsys):
    """A failure that is not the user's input (here: a file in the way of the output) exits 1
    with one line."""
    from snakecg.cli import main

    blocker = tmp_path / "file"
    blocker.write_text("")
    status = main(["generate", "--joints", "1", "--out", str(blocker / "sub")])
    err = capsys.readouterr().err
    assert status == 1, err
    # the progress of the work done before the failure, each line timed, then the failure
    *steps, last = err.splitlines()
    assert all(re.match(r"snakecg \[ *\d+\.\d s\] ", line) for line in steps), err
    assert "] generating the 1-joint model into " in steps[0], err
    assert re.search(r"] generating the 1-joint model into .*: failed after \d+\.\d s$",
                     steps[-1]), err
    assert last.startswith("snakecg generate: failed:"), err


def _documented_fields(section: str) -> set[str]:
    """Field names in the first column of the table under ``section`` in docs/reference/cli.md."""
    text = (DOCS / "reference" / "cli.md").read_text(encoding="utf-8")
    start = text.index(section)
    table = text[start:].split("\n\n", 3)
    rows = [r for block in table[1:3] for r in block.splitlines() if r.startswith("| `")]
    return {re.match(r"\| `([^`]+)`", r).group(1) for r in rows}


def test_forward_json_fields_are_documented(capsys):
    from snakecg.cli import main

    assert main(["forward", "--joints", "2", "--q", "0,0,0,-135deg,-135deg", "--tau", "0.1,0",
                 "--scenario", "wheels", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["schema"] == "snakecg.forward/1"
    assert set(out) == _documented_fields("### `snakecg forward --json`")


def test_show_json_fields_are_documented(capsys):
    from snakecg.cli import main

    assert main(["show", "--joints", "1", "J2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["schema"] == "snakecg.show/1"
    assert set(out) | set(out["expressions"][0]) == _documented_fields(
        "### `snakecg show --json`")


def test_generate_json_fields_are_documented(capsys):
    from snakecg.cli import main

    assert main(["generate", "--joints", "1", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["schema"] == "snakecg.generate/1" and out["backend"] in ("compiled", "casadi")
    assert set(out) == _documented_fields("### `snakecg generate --json`")


def test_progress_lines_on_every_stream_bars_on_a_terminal(monkeypatch):
    """docs/reference/cli.md: step lines on every stream, bars only on a terminal, and
    SNAKECG_PROGRESS=0 silences both."""
    from snakecg.commands._common import progress_reporter
    from snakecg.progress import progress_bar

    class Tty(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.delenv("SNAKECG_PROGRESS", raising=False)
    pipe = io.StringIO()
    progress_reporter(pipe)("compiling")
    assert pipe.getvalue().endswith("compiling\n")
    tty = Tty()
    step = progress_reporter(tty)
    step("compiling")
    assert tty.getvalue().endswith("compiling\n")
    quiet = io.StringIO()
    bar = progress_bar(4, "sweep", stream=quiet)
    bar.update(4)
    bar.close()
    assert quiet.getvalue() == ""
    tty = Tty()
    bar = progress_bar(4, "sweep", stream=tty)
    bar.update(2)
    bar.update(2)
    bar.refresh()  # tqdm redraws at most every 0.1 s on its own
    bar.close()
    assert "sweep" in tty.getvalue() and "4/4" in tty.getvalue()
    off = Tty()
    bar = progress_bar(4, "sweep", stream=off, enabled=False)
    bar.update(4)
    bar.close()
    assert off.getvalue() == ""
    monkeypatch.setenv("SNAKECG_PROGRESS", "0")
    assert progress_reporter(Tty()) is None


def test_cli_subprocess_stderr_is_clean():
    """In a pipe, a query prints its result and nothing on stderr (no progress, no noise)."""
    proc = subprocess.run(
        [sys.executable, "-m", "snakecg.cli", "show", "--joints", "1", "J1"],
        capture_output=True, text=True, timeout=120, cwd=ROOT,
    )
    assert proc.returncode == 0 and proc.stderr == "", proc.stderr
    assert proc.stdout.startswith("J_1 (eq. 3) =")


def test_show_lists_wide_matrices_entry_by_entry(monkeypatch, capsys):
    from snakecg.cli import main

    monkeypatch.setenv("COLUMNS", "60")
    assert main(["show", "--joints", "2", "M"]) == 0
    out = capsys.readouterr().out
    assert "5 x 5 matrix, symmetric" in out
    assert max(len(line) for line in out.splitlines()) <= 100
    assert re.search(r"^\[5,5\] = I.?3.? \+ c.?3", out, re.MULTILINE), out


# ------------------------------------------------------------------------------------------
# 5. the site builds, strictly, with the generated content
# ------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def built_site(tmp_path_factory):
    """The site built once, strictly, for the tests below (skipped without the docs extra)."""
    try:
        import material  # noqa: F401
        import mkdocs  # noqa: F401
        import mkdocstrings  # noqa: F401
    except ImportError as exc:
        if os.environ.get("CI"):  # CI installs the docs extra: a missing one is a failure
            pytest.fail(f"the docs extra is not installed ({exc.name}) but CI needs the site")
        pytest.skip(f"the docs extra is not installed ({exc.name}); pip install '.[docs]'")
    site = tmp_path_factory.mktemp("site") / "site"
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1"}
    proc = subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(site)],
        capture_output=True, text=True, timeout=900, cwd=ROOT, env=env,
    )
    assert proc.returncode == 0, proc.stderr[-4000:]
    return site


def test_mkdocs_build_strict(built_site):
    site = built_site
    symbolic = (site / "explanation" / "symbolic" / "index.html").read_text(encoding="utf-8")
    assert "snakecg-symbolic" not in symbolic, "a symbolic directive was not replaced"
    assert symbolic.count('class="arithmatex"') >= 10
    assert r"\beta_{1}" in symbolic and r"m_{\mathrm{tot}}" in symbolic
    # the operation-count table carries the manifests' numbers
    manifest = json.loads((ROOT / "generated" / "na2" / "manifest.json").read_text())
    ops = {f["name"]: f["operations"] for f in manifest["functions"]}
    assert f"{ops['constrained_dynamics']:,}" in symbolic
    cli = (site / "reference" / "cli" / "index.html").read_text(encoding="utf-8")
    assert "snakecg-cli" not in cli and "usage: snakecg forward" in cli
    api = (site / "reference" / "api" / "index.html").read_text(encoding="utf-8")
    assert 'id="snakecg.model.SceneModel.forward"' in api
    # the figures computed at build time are in the site and on their pages
    for rel in ("figures/reproduce/fig4_kappa100.png", "figures/reproduce/fig5_polar.png",
                "figures/reproduce/fig6_configurations.png", "figures/simulate/displacement.png",
                "figures/simulate/animation.gif"):
        assert (site / rel).stat().st_size > 10_000, rel
    reproduction = (site / "how-to" / "reproduction" / "index.html").read_text(encoding="utf-8")
    assert reproduction.count('src="../../figures/reproduce/') == 3
    assert 'src="../../figures/simulate/' in (site / "how-to" / "simulate" / "index.html") \
        .read_text("utf-8")


# ------------------------------------------------------------------------------------------
# 6. the site works offline: nothing loaded from elsewhere, formulas rendered in a browser
# ------------------------------------------------------------------------------------------
_LOADED = re.compile(  # what a browser fetches by itself: scripts, styles, fonts, images, frames
    r"<(?:script|img|iframe|source|embed)\b[^>]*\bsrc\s*=\s*[\"']?(?P<a>[^\"'\s>]+)"
    r"|<link\b[^>]*\bhref\s*=\s*[\"']?(?P<b>[^\"'\s>]+)"
    r"|url\(\s*[\"']?(?P<c>[^\"')\s]+)|@import\s+[\"'](?P<d>[^\"']+)", re.IGNORECASE)


def _external(ref: str) -> bool:
    return bool(re.match(r"^(https?:)?//", ref.strip(), re.IGNORECASE))


def test_site_loads_nothing_from_elsewhere(built_site):
    found = []
    for path in sorted(built_site.rglob("*")):
        if path.suffix not in (".html", ".css", ".js") or not path.is_file():
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        if path.suffix == ".js":  # a script may name URLs in strings; only its CSS-like loads
            refs = [m.group("c") or m.group("d") for m in _LOADED.finditer(text)
                    if m.group("c") or m.group("d")]
            refs = [r for r in refs if r.startswith(("http:", "https:"))]
        else:
            refs = [next(g for g in m.groups() if g) for m in _LOADED.finditer(text)]
        found += [f"{path.relative_to(built_site)}: {r}" for r in refs if _external(r)]
    link_tags = [m for m in re.findall(r"<link\b[^>]*>", (built_site / "index.html")
                 .read_text(encoding="utf-8"))]
    assert link_tags, "the pattern found no <link> at all: the check would be vacuous"
    assert not found, "the site loads files from elsewhere:\n" + "\n".join(found[:20])
    # the renderer is served with the site, with its licence
    assert (built_site / "assets" / "mathjax" / "tex-svg.js").stat().st_size > 1_000_000
    assert "Apache License" in (built_site / "assets" / "mathjax" / "LICENSE").read_text()
    model_page = built_site / "explanation" / "model" / "index.html"
    assert 'src="../../assets/mathjax/tex-svg.js"' in model_page.read_text(encoding="utf-8")


_PROBE = r"""
<script>
(function wait() {
  if (!(window.MathJax && MathJax.startup && MathJax.startup.promise)) {
    return setTimeout(wait, 50);
  }
  MathJax.startup.promise.then(function () {
    var items = [];
    Array.from(MathJax.startup.document.math).forEach(function (m) {
      var r = m.typesetRoot ? m.typesetRoot.getBoundingClientRect() : null;
      var block = m.typesetRoot ? m.typesetRoot.closest("div.arithmatex") : null;
      items.push({tex: m.math, display: m.display, rendered: !!(m.typesetRoot &&
                  m.typesetRoot.querySelector("svg")),
                  box: r ? [r.left + scrollX, r.top + scrollY, r.width, r.height] : null,
                  scrolls: block ? block.scrollWidth > block.clientWidth + 1 : false});
    });
    var raw = Array.prototype.some.call(document.querySelectorAll(".arithmatex"), function (e) {
      return /\\begin\{|\\\(|\\\[/.test(e.innerText);
    });
    var line = parseFloat(getComputedStyle(document.querySelector(".md-typeset p")).lineHeight);
    var out = document.createElement("pre");
    out.id = "snakecg-probe";
    out.textContent = JSON.stringify({items: items, raw: raw, line: line,
      pageWidth: document.documentElement.scrollWidth, viewport: innerWidth});
    document.body.appendChild(out);
  });
})();
</script>
"""


def _chromium():
    import shutil

    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    pytest.skip("no Chromium on this machine (Debian: apt-get install chromium; .ci/run "
                "installs it)")


@pytest.fixture(scope="module")
def site_server(built_site):
    import functools
    import http.server
    import threading

    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=str(built_site))
    handler.log_message = lambda *a, **k: None
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_address[1]}"
    server.shutdown()
    server.server_close()


def _browser(args, tmp_path):
    cmd = [_chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
           f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=20000", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=180)


def _probe(built_site, site_server, page, width, tmp_path):
    """Load ``page`` (a copy with the probe script) in headless Chromium; the probe's JSON."""
    html = (built_site / page / "index.html").read_text(encoding="utf-8")
    (built_site / page / "probe.html").write_text(html.replace("</body>", _PROBE + "</body>"),
                                                  encoding="utf-8")
    proc = _browser([f"--window-size={width},4000", "--dump-dom",
                     f"{site_server}/{page}/probe.html"], tmp_path)
    m = re.search(r'<pre id="snakecg-probe">(.*?)</pre>', proc.stdout, re.DOTALL)
    assert m, f"the page never finished typesetting:\n{proc.stderr[-2000:]}"
    import html as html_mod

    return json.loads(html_mod.unescape(m.group(1)))


def test_formulas_render_in_a_browser_offline(built_site, site_server, tmp_path):
    """Headless Chromium, no network but this machine: every formula of the model page is
    typeset, a matrix is drawn as a matrix (taller than a line, ink in its box on the
    screenshot), no raw TeX is left, and wide formulas scroll inside the page."""
    Image = pytest.importorskip("PIL.Image", reason="pillow (test extra) reads the screenshot")
    probe = _probe(built_site, site_server, "explanation/model", 1280, tmp_path)
    items = probe["items"]
    assert len(items) >= 30 and all(i["rendered"] for i in items)
    assert not probe["raw"], "raw TeX is visible"
    matrices = [i for i in items if "bmatrix" in i["tex"] and i["display"]]
    assert matrices
    tallest = max(matrices, key=lambda i: i["box"][3])
    assert tallest["box"][3] > 1.8 * probe["line"], tallest   # two rows, not one line of text
    shot = tmp_path / "model.png"
    _browser(["--window-size=1280,4000", f"--screenshot={shot}",
              f"{site_server}/explanation/model/probe.html"], tmp_path)
    import numpy as np

    with Image.open(shot) as im:
        x, y, w, h = (int(round(v)) for v in tallest["box"])
        ink = np.asarray(im.convert("L").crop((x, y, x + w, y + h))) < 110
    assert ink.mean() > 0.002, f"the matrix's box is blank on the screenshot ({ink.mean():.3%})"
    rows = np.flatnonzero(ink.any(axis=1))
    assert rows[-1] - rows[0] > 1.5 * probe["line"], "the drawn matrix is not taller than a line"
    # the symbolic page's wide matrices scroll in their block; the page itself does not
    sym = _probe(built_site, site_server, "explanation/symbolic", 900, tmp_path)
    assert any(i["scrolls"] for i in sym["items"])
    assert sym["pageWidth"] <= sym["viewport"]


# ------------------------------------------------------------------------------------------
# 7. Table 2 on the pages is the program's; wide tables and formulas scroll, never cut off
# ------------------------------------------------------------------------------------------
def _html_tables(page_html: str) -> list[list[list[str]]]:
    """Every ``<table>`` of a built page as rows of cell texts (tags dropped)."""
    import html as html_mod

    tables = []
    for body in re.findall(r"<table>(.*?)</table>", page_html, re.DOTALL):
        rows = []
        for row in re.findall(r"<tr>(.*?)</tr>", body, re.DOTALL):
            cells = re.findall(r"<t[hd][^>]*>(.*?)</t[hd]>", row, re.DOTALL)
            rows.append([html_mod.unescape(re.sub(r"<[^>]+>", "", c)).strip() for c in cells])
        tables.append(rows)
    return tables


def test_table2_on_the_pages_is_the_programs(built_site, tmp_path, capsys):
    """The home page's and the reproduction page's Table 2 are what ``snakecg reproduce``
    prints today, entry by entry: its values to the 6 digits shown, its paper values and
    relative differences, its marks on infeasible shapes and its feasible-only column. The
    command runs here on its own (case study 2 on its defaults; a coarse Fig. 4 grid, which
    Table 2 does not use)."""
    from snakecg.cli import main

    status = main(["reproduce", "--out", str(tmp_path / "out"), "--torque-grid", "11",
                   "--formats", "png", "--json"])
    captured = capsys.readouterr()
    assert status == 0, captured.err
    program = json.loads(captured.out)
    keys = ("worst_norm_a_obj", "best_norm_a_obj", "worst_sr", "best_sr")
    assert set(program["table2"]) == set(keys)
    for rel in ("index.html", "how-to/reproduction/index.html"):
        tables = [t for t in _html_tables((built_site / rel).read_text(encoding="utf-8"))
                  if t and t[0] and t[0][0] == "Concept"]
        assert len(tables) == 1, f"{rel}: {len(tables)} Table 2s"
        head, *rows = tables[0]
        assert len(head) == 13 and head[1].startswith("Scenario 1") and len(rows) == 4, head
        for key, row in zip(keys, rows):
            for j in range(3):
                ours, paper, diff, feasible_only = row[1 + 4 * j: 5 + 4 * j]
                value = program["table2"][key][j]
                infeasible = not program["table2_shape_feasible"][key][j]
                where = f"{rel}: {key}, scenario {j + 1}"
                assert ours.endswith("*") == infeasible, where
                assert float(ours.rstrip("*")) == float(f"{value:.6g}"), (where, ours, value)
                assert float(paper) == float(f"{program['paper_table2'][key][j]:.6g}"), where
                rel_diff = value / program["paper_table2"][key][j] - 1
                assert math.isclose(float(diff.rstrip("%").replace("−", "-")) / 100, rel_diff,
                                    abs_tol=0.0005 + 1e-12), (where, diff, rel_diff)
                assert float(feasible_only) == float(
                    f"{program['table2_feasible_only'][key][j]:.6g}"), where


def _shapes_table(site) -> dict:
    """The optimal-shapes page's table, ``{(scenario, metric, shapes): (continuous value,
    its angles, grid value, grid angles, grid marked infeasible, gain)}``."""
    html = (site / "how-to" / "shapes" / "index.html").read_text(encoding="utf-8")
    assert "snakecg-shapes-table" not in html, "the table directive was not replaced"
    tables = [t for t in _html_tables(html) if t and t[0][:2] == ["scenario", "maximised"]]
    assert len(tables) == 1, f"{len(tables)} shape tables"
    def angles(s):
        return tuple(float(x) for x in s.strip("()").split(","))

    out = {}
    for scenario, metric, shapes, value, q, grid, q_grid, gain in tables[0][1:]:
        key = (scenario.split()[0], "sr" if metric == "sr" else "a_obj", shapes)
        out[key] = (float(value), angles(q), float(grid.rstrip("*")), angles(q_grid),
                    grid.endswith("*"), float(gain.rstrip(" %")) / 100)
    return out


def test_optimal_shapes_table_is_the_packages(built_site):
    """The optimal-shapes page's table, computed at build time, against references outside
    the hook: scenario 1's sr (the top generalized eigenvalue of (Omega, Omega + Xi), eq. 30,
    by SciPy) over the paper's grid, and a SciPy search from the page's continuous optimum
    that finds nothing better; scenario 3's ||a_obj||^2 on the ellipsoid (SciPy's top
    eigenvalue of (Omega, N)) over the grid; scenario 3's sr at the straight shape against
    the closed-form plateau kappa / (kappa + 1 + 3 I / (m l^2)); scenario 2's sr with the
    package's API called directly (optimize_shape, and the extremes at that shape)."""
    import numpy as np
    import scipy.linalg as sla
    from scipy.optimize import minimize

    import snakecg
    from snakecg.analysis import joint_grid

    table = _shapes_table(built_site)
    assert len(table) == 12 and {k[0] for k in table} == {"1", "2", "3"}
    for (value, _, grid, _, _, gain) in table.values():
        assert value >= grid * (1 - 1e-12)  # the continuous optimum is never below the grid
        assert math.isclose(gain, value / grid - 1, rel_tol=0.06, abs_tol=1e-9)
    # what the page's prose says of the table: scenario 1's sr with the first joint at its
    # limit; the friction bounds do not bind ||a_obj||^2 (scenarios 2 and 3 agree), whose
    # grid best over all shapes is not physically possible
    assert table[("1", "sr", "all")][1][0] == -135.0
    for shapes in ("all", "feasible"):
        assert table[("2", "a_obj", shapes)][:2] == table[("3", "a_obj", shapes)][:2]
        assert table[("2", "a_obj", shapes)][4] == (shapes == "all")
    Q = joint_grid(3, -135.0, 135.0, 10.0)
    robot = snakecg.Robot(joints=3)

    def load(scenario):
        return snakecg.load(snakecg.Scene(robot, scenario=scenario, kappa=100))

    def top(A, B):
        return np.array([sla.eigh(a, b, eigvals_only=True)[-1] for a, b in zip(A, B)])

    # scenario 1, sr: Omega = k c^T c (rank one), so the sign of the top eigenvector keeps
    # the contact and the best sr at a shape is the top eigenvalue of (Omega, Omega + Xi)
    m1 = load("frictionless")
    maps = m1.maps(Q)
    sr = top(maps["omega_tau"], maps["omega_tau"] + maps["xi_tau"])
    best = int(np.argmax(sr))
    value, q_deg, grid, grid_deg, marked, _ = table[("1", "sr", "all")]
    assert float(f"{sr[best]:.8g}") == grid and not marked
    assert np.allclose(np.rad2deg(Q[best, 3:]), grid_deg)

    def neg_sr(qj):
        mp = m1.maps(np.concatenate([[0.0, 0.0, 0.0], qj])[None])
        return -top(mp["omega_tau"], mp["omega_tau"] + mp["xi_tau"])[0]

    lim = [(-0.75 * np.pi, 0.75 * np.pi)] * 3
    q_page = np.deg2rad(q_deg)
    assert math.isclose(-neg_sr(q_page), value, rel_tol=2e-7)
    for start in (q_page, Q[best, 3:]):
        found = minimize(neg_sr, start, method="L-BFGS-B", bounds=lim)
        assert -found.fun <= value * (1 + 1e-7), (start, found)
    assert table[("1", "sr", "feasible")][:2] == (value, q_deg)

    # scenario 3, ||a_obj||^2: the largest k lam_c^2 on tau^T N tau <= 1, Omega rank one
    m3 = load("ideal_wheels")
    maps = m3.maps(Q)
    a = top(maps["omega_tau"], maps["input_metric"])
    best = int(np.argmax(a))
    _, _, grid, grid_deg, marked, _ = table[("3", "a_obj", "all")]
    assert float(f"{a[best]:.8g}") == grid and marked  # its links cross / enter the object
    assert np.allclose(np.rad2deg(Q[best, 3:]), grid_deg)

    # scenario 3, sr: the straight snake on the closed-form plateau
    plateau = 100 / (100 + 1 + 3 * robot.inertia[0] / (robot.mass[0] * robot.length[0] ** 2))
    for shapes in ("all", "feasible"):
        value, q_deg, *_ = table[("3", "sr", shapes)]
        assert value == float(f"{plateau:.8g}") and np.allclose(q_deg, 0.0, atol=0.005)

    # scenario 2, sr: the API called here; a sliding wheel lifts it above the plateau
    m2 = load("wheels")
    res = m2.optimize_shape("max_sr", feasible=False)
    value, q_deg, *_ = table[("2", "sr", "all")]
    assert res.status == "optimal" and float(f"{res.value:.8g}") == value > plateau
    assert np.allclose(np.rad2deg(res.q[3:]), q_deg, atol=0.005)
    ex = m2.extremes(res.q[None], exact=True)
    assert math.isclose(float(ex.max["sr"][0]), value, rel_tol=1e-7)


def test_optimal_shapes_figures_are_built(built_site):
    page = (built_site / "how-to" / "shapes" / "index.html").read_text(encoding="utf-8")
    for name in ("max_sr.png", "max_a_obj.png"):
        assert (built_site / "figures" / "shapes" / name).stat().st_size > 10_000, name
        assert f'src="../../figures/shapes/{name}"' in page, name
    assert not (DOCS / "how-to" / "shapes").exists(), "hand-made figures are back in docs/"


_WIDE_PROBE = r"""
<script>
(function wait() {
  if (!(window.MathJax && MathJax.startup && MathJax.startup.promise) ||
      !document.querySelector(".md-typeset__scrollwrap")) {
    return setTimeout(wait, 50);
  }
  MathJax.startup.promise.then(function () {
    var art = document.querySelector("article.md-content__inner");
    var boxes = [];
    function box(r) { return [r.left + scrollX, r.top + scrollY, r.width, r.height]; }
    function check(kind, el, scroller, last) {
      var s = getComputedStyle(scroller), before = scroller.getBoundingClientRect();
      var wide = scroller.scrollWidth > scroller.clientWidth + 1;
      scroller.scrollLeft = scroller.scrollWidth;  // as far right as the reader can scroll
      var view = scroller.getBoundingClientRect(), end = last.getBoundingClientRect();
      var cut = [];  // an ancestor up to the article that hides what sticks out of it
      for (var c = scroller.parentElement; c && c !== art.parentElement; c = c.parentElement) {
        var o = getComputedStyle(c).overflowX;
        if ((o === "hidden" || o === "clip") && c.scrollWidth > c.clientWidth + 1) {
          cut.push(c.tagName + "." + c.className);
        }
      }
      boxes.push({kind: kind, wide: wide, overflowX: s.overflowX,
                  contentWidth: scroller.scrollWidth, visibleWidth: scroller.clientWidth,
                  view: box(view), end: box(end), cut: cut,
                  inColumn: before.left >= art.getBoundingClientRect().left - 20 &&
                            before.right <= art.getBoundingClientRect().right + 20});
    }
    document.querySelectorAll(".md-typeset table").forEach(function (t) {
      if (!/Scenario 1/.test(t.rows[0].textContent)) return;
      var cells = t.rows[t.rows.length - 1].cells;
      check("table2", t, t.closest(".md-typeset__scrollwrap") || t, cells[cells.length - 1]);
    });
    document.querySelectorAll(".md-typeset div.arithmatex").forEach(function (d) {
      var svg = d.querySelector("mjx-container svg");
      if (svg && d.scrollWidth > d.clientWidth + 1) check("formula", d, d, svg);
    });
    var out = document.createElement("pre");
    out.id = "snakecg-probe";
    out.textContent = JSON.stringify({boxes: boxes,
      pageWidth: document.documentElement.scrollWidth, viewport: innerWidth});
    document.body.appendChild(out);
  });
})();
</script>
"""


@pytest.mark.parametrize("page, kind", [("how-to/reproduction", "table2"), ("", "table2"),
                                        ("explanation/symbolic", "formula")])
def test_wide_tables_and_formulas_scroll_and_are_not_cut_off(built_site, site_server, tmp_path,
                                                             page, kind):
    """Headless Chromium at a width where Table 2 and the 2-joint matrices do not fit the
    column: each sits in a box that scrolls sideways (its content wider than its visible
    width), inside the text column, with no ancestor hiding what sticks out, and the page
    itself does not scroll sideways. Scrolled to its right end, the box shows the table's
    last column (the formula's right edge), and the screenshot has ink there."""
    Image = pytest.importorskip("PIL.Image", reason="pillow (test extra) reads the screenshot")
    import html as html_mod

    import numpy as np

    folder = built_site / page if page else built_site
    html = (folder / "index.html").read_text(encoding="utf-8")
    (folder / "wide.html").write_text(html.replace("</body>", _WIDE_PROBE + "</body>"),
                                      encoding="utf-8")
    url = f"{site_server}/{page + '/' if page else ''}wide.html"
    size = "--window-size=1024,12000"
    proc = _browser([size, "--dump-dom", url], tmp_path)
    m = re.search(r'<pre id="snakecg-probe">(.*?)</pre>', proc.stdout, re.DOTALL)
    assert m, f"the page never finished typesetting:\n{proc.stderr[-2000:]}"
    probe = json.loads(html_mod.unescape(m.group(1)))
    assert probe["pageWidth"] <= probe["viewport"], "the page scrolls sideways"
    boxes = [b for b in probe["boxes"] if b["kind"] == kind]
    assert boxes, f"no {kind} found on {page or 'the home page'}"
    wide = [b for b in boxes if b["wide"]]
    assert wide, f"at 1024 px no {kind} is wider than its box: the check would be vacuous"
    for b in wide:
        assert b["overflowX"] in ("auto", "scroll"), b
        assert b["inColumn"] and not b["cut"], b
        assert b["contentWidth"] > b["visibleWidth"], b
        vx, _, vw, _ = b["view"]
        ex, _, ew, _ = b["end"]
        assert vx - 1 <= ex + ew <= vx + vw + 1, f"the right end is out of reach: {b}"
    shot = tmp_path / "wide.png"
    _browser([size, f"--screenshot={shot}", url], tmp_path)
    b = max(wide, key=lambda b: b["contentWidth"])
    with Image.open(shot) as im:
        x, y, w, h = (round(v) for v in b["end"])
        x0, x1 = max(x, int(b["view"][0])), min(x + w, int(b["view"][0] + b["view"][2]))
        ink = np.asarray(im.convert("L").crop((x0, y, x1, y + h))) < 110
    assert ink.mean() > 0.002, f"the right end of the {kind} is blank on the screen: {b}"
