"""MkDocs hook: the CLI reference, generated from the CLI itself.

The directive ``<!-- snakecg-cli: reference -->`` on a line of its own is replaced by the
``--help`` text of ``snakecg`` and of every sub-command that ``snakecg.cli.build_parser()``
registers (commands that are not installed yet simply do not appear). Help is formatted at a
fixed width so the page does not depend on the terminal that builds it.
"""

from __future__ import annotations

import argparse
import os
import re

from mkdocs.exceptions import PluginError

DIRECTIVE = re.compile(r"^<!--\s*snakecg-cli:\s*(?P<body>.*?)\s*-->\s*$", re.MULTILINE)
WIDTH = 90


def on_page_markdown(markdown, page, config, files):
    if "snakecg-cli:" not in markdown:
        return markdown

    def replace(m: re.Match) -> str:
        if m.group("body") != "reference":
            raise PluginError(f"{page.file.src_uri}: unknown directive "
                              f"'snakecg-cli: {m.group('body')}' (known: reference)")
        return reference()

    return DIRECTIVE.sub(replace, markdown)


def _help(parser: argparse.ArgumentParser) -> str:
    saved = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = str(WIDTH)  # argparse reads the width from COLUMNS
    try:
        return parser.format_help().rstrip()
    finally:
        if saved is None:
            os.environ.pop("COLUMNS", None)
        else:
            os.environ["COLUMNS"] = saved


def reference() -> str:
    from snakecg.cli import build_parser

    parser = build_parser()
    subs = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    if len(subs) != 1:
        raise PluginError("snakecg.cli.build_parser() has no sub-commands")
    out = ["## `snakecg`", "", "```text", _help(parser), "```", ""]
    for name, sub in subs[0].choices.items():
        out += [f"## `snakecg {name}`", "", "```text", _help(sub), "```", ""]
    return "\n".join(out)
