"""Atomic writes of output files (figures, CSV, JSON, trajectories).

Every file is written under a unique temporary name in its own folder (so two runs writing
into one folder never share a temporary file), flushed to disk and renamed onto its final
name with :func:`os.replace`: a reader sees the old file or the new one, never half of one,
and an interrupted run leaves no partial file under the final name.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

__all__ = ["atomic_path", "atomic_dir", "write_text", "write_bytes", "save_figure"]


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


#: Mode of the files written (what ``open`` would give under the process' umask).
_MODE = 0o666 & ~_umask()


@contextlib.contextmanager
def atomic_path(path) -> Iterator[Path]:
    """A unique temporary path beside ``path`` with the same suffix (so writers that infer
    the format from it, such as matplotlib and Pillow, keep working); renamed onto ``path``
    when the block ends without an exception, removed otherwise."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}.", suffix=f".tmp{path.suffix}",
                               dir=path.parent)
    os.close(fd)
    try:
        yield Path(tmp)
        with open(tmp, "rb+") as fh:
            os.fsync(fh.fileno())
        os.chmod(tmp, _MODE)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


@contextlib.contextmanager
def atomic_dir(path) -> Iterator[Path]:
    """A new temporary folder beside ``path`` (its parents made), renamed onto ``path`` when
    the block ends without an exception; removed otherwise, or when another writer's folder
    took the place first (the first complete folder stays: both hold the same content)."""
    import shutil

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{path.name}-", dir=path.parent))
    try:
        yield tmp
        try:
            os.replace(tmp, path)
        except OSError:  # another writer finished first: its copy stays
            shutil.rmtree(tmp, ignore_errors=True)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise


def write_text(path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)


def write_bytes(path, data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically."""
    with atomic_path(path) as tmp:
        tmp.write_bytes(data)
    return Path(path)


def save_figure(fig, path, fmt: str, dpi: int) -> Path:
    """Write a matplotlib figure to ``path`` atomically, in format ``fmt`` at ``dpi``."""
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format=fmt, dpi=dpi)
    return Path(path)
