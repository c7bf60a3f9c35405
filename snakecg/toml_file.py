"""Reading a robot description file safely: a regular file of bounded size, UTF-8 (a BOM is
allowed), parsed as TOML, every problem an :class:`InputError` that names the file."""

from __future__ import annotations

from pathlib import Path

from ._inputs import short_repr as _r
from .errors import InputError

__all__ = ["MAX_FILE_BYTES", "checked_path", "read_bytes", "read_toml"]

#: Largest robot description file read (bytes): a description is a few hundred bytes.
MAX_FILE_BYTES = 1 << 20


def checked_path(path) -> Path:
    """``path`` as a Path; anything but a non-empty str or os.PathLike is refused."""
    import os

    if isinstance(path, bytes) or not isinstance(path, (str, os.PathLike)):
        raise InputError(f"path must be the path of a robot description file (str or "
                         f"os.PathLike), got {_r(path)}")
    p = Path(path)
    if str(path) == "":
        raise InputError("path is empty; give the path of a robot description file")
    return p


def read_bytes(path, *, where: str = "robot file", kind: str = "TOML") -> tuple[Path, bytes]:
    """``(path, its bytes)``: a regular file of at most MAX_FILE_BYTES, read once (``where``
    starts the messages, ``kind`` names the expected file).

    Devices (``/dev/zero``), FIFOs and sockets are refused before they are opened, so a read
    can neither run out of memory nor block.
    """
    import os
    import stat

    p = checked_path(path)
    where = f"{where} {str(p)!r}"
    try:
        st = os.stat(p)
    except FileNotFoundError:
        raise InputError(f"{where} does not exist") from None
    except (OSError, ValueError) as exc:
        raise InputError(f"{where} cannot be read: {exc}") from None
    if stat.S_ISDIR(st.st_mode):
        raise InputError(f"{where} is a directory, expected a {kind} file")
    if not stat.S_ISREG(st.st_mode):
        what = ("a FIFO" if stat.S_ISFIFO(st.st_mode) else
                "a device" if stat.S_ISCHR(st.st_mode) or stat.S_ISBLK(st.st_mode) else
                "a socket" if stat.S_ISSOCK(st.st_mode) else "not a regular file")
        raise InputError(f"{where} is {what}; expected a regular {kind} file")
    if st.st_size > MAX_FILE_BYTES:
        raise InputError(f"{where} has {st.st_size} bytes, above the limit of "
                         f"{MAX_FILE_BYTES} bytes for a robot description")
    try:
        flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
        fd = os.open(p, flags)
        with os.fdopen(fd, "rb") as fh:
            if not stat.S_ISREG(os.fstat(fh.fileno()).st_mode):  # replaced meanwhile
                raise InputError(f"{where} is not a regular file; expected a {kind} file")
            data = fh.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise InputError(f"{where} cannot be read: {exc}") from None
    if len(data) > MAX_FILE_BYTES:
        raise InputError(f"{where} has more than {MAX_FILE_BYTES} bytes, the limit for a "
                         f"robot description")
    return p, data


def read_toml(path) -> dict:
    """The parsed file: a regular file of at most MAX_FILE_BYTES (:func:`read_bytes`), UTF-8
    (a BOM is allowed)."""
    try:
        import tomllib
    except ModuleNotFoundError:  # pragma: no cover - Python 3.10
        import tomli as tomllib
    p, data = read_bytes(path)
    where = f"robot file {str(p)!r}"
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]  # a UTF-8 byte order mark, as some editors write
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"{where} cannot be read: it is not UTF-8 text ({exc.reason} at "
                         f"byte {exc.start})") from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{where} is not valid TOML: {exc}") from None
    except RecursionError:
        raise InputError(f"{where} is not valid TOML: nested too deeply") from None
