"""C text shared by the exported C libraries (:mod:`snakecg.export`,
:mod:`snakecg.spatial.export`): identifiers checked, free text made safe for a comment, the
stack limit of work arrays."""

from __future__ import annotations

import re

from .errors import InputError

__all__ = ["STACK_LIMIT", "c_comment", "c_ident"]

_IDENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
#: Work arrays larger than this (in doubles) are allocated with malloc instead of the stack.
STACK_LIMIT = 32768


def c_ident(text: str, what: str) -> str:
    """``text`` when it is a C identifier; else InputError (the model folder is damaged)."""
    if not isinstance(text, str) or not _IDENT.match(text):
        raise InputError(f"{what} {text!r} is not a C identifier; the model folder is damaged")
    return text


def c_comment(text: str) -> str:
    """Free text made safe for a C comment (no comment terminator, printable ASCII)."""
    safe = "".join(ch if 32 <= ord(ch) < 127 else "?" for ch in str(text))
    return safe.replace("*/", "* /").replace("/*", "/ *")
