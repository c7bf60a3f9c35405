"""No code injection through paths.

A path chosen by the user (``snakecg generate --out``, ``SNAKECG_CACHE_DIR``) must never reach
executable generated text, and nothing rendered is executed when a model is loaded: the
no-compiler fallback deserializes CasADi's own format. Every hostile name below carries a
payload that would create a marker file if any line of it ran as Python.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from test_faults import reference_mass_matrix

import snakecg

ROOT = Path(__file__).resolve().parent.parent
PY = sys.executable

PAYLOAD = '__import__("pathlib").Path("PWNED").write_text("injected")'
HOSTILE = {
    "newline": f"out\n{PAYLOAD}\n#",
    "carriage return": f"out\r{PAYLOAD}\r#",
    "quotes": f"out'\"\"\"{PAYLOAD}\"\"\"'",
    "backslashes": f"out\\\\n{PAYLOAD}\\",
    "non-ASCII": f"ausgabe-\u00e4\u00f6\u00fc-\u86c7-\u2028{PAYLOAD}",
    "comment terminator": f"out*/ int x = 1; /*{PAYLOAD}",
}


def _env(**extra) -> dict:
    env = dict(os.environ)
    env.pop("SNAKECG_BACKEND", None)
    env.update(extra)
    return env


def _cli(args, *, cwd, env) -> subprocess.CompletedProcess:
    return subprocess.run([PY, "-m", "snakecg.cli", *args], capture_output=True, text=True,
                          cwd=cwd, env=env, timeout=600)


@pytest.mark.parametrize("kind", list(HOSTILE))
def test_generate_out_with_a_hostile_name_runs_no_code(kind, tmp_path):
    """``generate --out`` with a hostile folder name: the model is written there, the
    rendered files name no part of the path, and no line of the payload ever runs."""
    out = HOSTILE[kind]
    proc = _cli(["generate", "--joints", "1", "--out", out], cwd=tmp_path, env=_env())
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr
    assert not (tmp_path / "PWNED").exists()
    folder = tmp_path / out / "na1"
    assert (folder / "manifest.json").is_file()
    for path in folder.rglob("*"):
        if path.is_file():
            text = path.read_text(encoding="utf-8")
            assert PAYLOAD not in text, path.name
            assert out not in text, path.name


@pytest.mark.parametrize("kind", ["newline", "carriage return", "quotes", "non-ASCII"])
def test_hostile_cache_folder_runs_no_code_even_on_the_casadi_fallback(kind, tmp_path):
    """A hostile ``SNAKECG_CACHE_DIR`` for a model that is not checked in (7 joints: it is
    generated into the cache), loaded through CasADi's in-process backend because the
    compiler fails (``CC=/bin/false``): no code runs, and the numbers are right."""
    cache = tmp_path / HOSTILE[kind]
    script = (
        "import json, numpy as np, snakecg, warnings\n"
        "warnings.simplefilter('ignore')\n"
        "m = snakecg.load(snakecg.Robot(joints=7))\n"
        "q = np.linspace(-0.5, 0.6, 10)\n"
        "print(m.backend_kind)\n"
        "print(json.dumps(m.mass_matrix(q).tolist()))\n"
    )
    env = _env(SNAKECG_CACHE_DIR=str(cache), CC="/bin/false")
    for _ in range(2):  # the second run loads the cached entry
        proc = subprocess.run([PY, "-c", script], capture_output=True, text=True,
                              cwd=tmp_path, env=env, timeout=600)
        assert proc.returncode == 0, proc.stderr
        assert not (tmp_path / "PWNED").exists()
        kind_line, matrix = proc.stdout.splitlines()[-2:]
        assert kind_line == "casadi"
        M = np.array(json.loads(matrix))
        q = np.linspace(-0.5, 0.6, 10)
        assert np.allclose(M, reference_mass_matrix(snakecg.Robot(joints=7), q), atol=1e-12)
    for path in cache.rglob("*"):
        if path.is_file() and path.suffix in (".py", ".c", ".json", ".casadi"):
            assert PAYLOAD not in path.read_text(encoding="utf-8", errors="replace")
