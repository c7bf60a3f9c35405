"""Griffe extension (used by mkdocstrings, see mkdocs.yml): Sphinx roles in docstrings.

The code's docstrings use Sphinx-style roles (``:class:`~snakecg.Robot```,
``:func:`snakecg.analysis.extremes```) that Markdown would print literally. They become code
spans: ``~`` keeps the last component, as in Sphinx.
"""

from __future__ import annotations

import re

import griffe

ROLE = re.compile(
    r":(?:py:)?(?:class|func|meth|mod|attr|data|exc|obj):`(?P<tilde>~?)(?P<target>[^`]+)`"
)


def _code(m: re.Match) -> str:
    target = m.group("target")
    return f"`{target.rsplit('.', 1)[-1] if m.group('tilde') else target}`"


class RstRoles(griffe.Extension):
    def on_instance(self, *, obj, **kwargs) -> None:
        if obj.docstring is not None and ":`" in obj.docstring.value:
            obj.docstring.value = ROLE.sub(_code, obj.docstring.value)
