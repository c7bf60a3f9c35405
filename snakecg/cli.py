"""The ``snakecg`` command line: one sub-command per module in :mod:`snakecg.commands`.

Exit status: 0 success, 2 usage or input errors, 1 failures (a build that failed, ...).
Errors are printed on one line, without a traceback.
"""

from __future__ import annotations

import argparse
import sys
import warnings

from . import __version__
from .errors import InputError, SnakecgError

COMMANDS = ("generate", "show", "forward", "extremes", "reproduce", "optimize", "simulate")


class _Parser(argparse.ArgumentParser):
    """argparse, but usage errors are one line and exit with status 2."""

    def error(self, message):  # noqa: D401 - argparse API
        sys.stderr.write(f"{self.prog}: error: {message} (see {self.prog} --help)\n")
        raise SystemExit(2)


def build_parser() -> argparse.ArgumentParser:
    import importlib

    p = _Parser(
        prog="snakecg",
        description="Derive, generate and run the contact models of planar snake robots that "
        "push objects (Reyes & Ma 2017).",
        epilog="example: snakecg reproduce --out snakecg-output",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--version", action="version", version=f"snakecg {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name in COMMANDS:
        try:
            mod = importlib.import_module(f"snakecg.commands.{name}")
        except ModuleNotFoundError as exc:
            if exc.name == f"snakecg.commands.{name}":
                continue  # command not built yet
            raise
        mod.register(sub)
    return p


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "command", None):
        parser.print_help()
        return 2
    with warnings.catch_warnings():
        warnings.simplefilter("default")
        try:
            return int(args.run(args) or 0)
        except InputError as exc:
            sys.stderr.write(f"snakecg {args.command}: error: {_one_line(exc)}\n")
            return 2
        except SnakecgError as exc:
            sys.stderr.write(f"snakecg {args.command}: failed: {_one_line(exc)}\n")
            return 1
        except KeyboardInterrupt:
            sys.stderr.write(f"snakecg {args.command}: interrupted\n")
            return 130


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())
    return text or type(exc).__name__


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
