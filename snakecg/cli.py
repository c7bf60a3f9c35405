"""The ``snakecg`` command line: one sub-command per module in :mod:`snakecg.commands`.

Exit status: 0 success, 2 usage or input errors, 1 failures (a build that failed, a file
that cannot be written, ...). Errors are printed on one line of standard error, with a hint,
never with a traceback; warnings likewise. Progress goes to standard error: a line when a
generation, a compilation or a stage of work starts and one when it ends, on every stream;
bars only on a terminal; ``--quiet`` (or ``SNAKECG_PROGRESS=0``) silences it. The reference
in docs/reference/cli.md is generated from :func:`build_parser`.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
import warnings

from ._version import __version__
from .errors import InputError, SnakecgError

COMMANDS = ("generate", "show", "forward", "reproduce", "optimize", "simulate")
#: Toolkit commands (C export, configuration plots, optimal shapes, sweeps on Dask).
COMMANDS += ("export", "plot", "optimize_shape", "sweep")


#: What argparse must read as a value, not an option: negative numbers and number lists
#: (``--tau -0.1,0``, ``--q -1,0,0,-135deg``, ``--a-min -inf`` to be refused as a value).
_NEGATIVE_VALUE = re.compile(r"^-(?:\d|\.\d|inf|nan)", re.IGNORECASE)


class _Parser(argparse.ArgumentParser):
    """argparse, but usage errors are one line and exit with status 2, and values that
    start with a minus sign (``--tau -0.1,0``) are values, not unknown options."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_VALUE

    def error(self, message):  # noqa: D401 - argparse API
        sys.stderr.write(f"{self.prog}: error: {message} (see {self.prog} --help)\n")
        raise SystemExit(2)

    def _get_values(self, action, arg_strings):
        # `--opt=--`: argparse drops the '--' and hands the option an empty list, which no
        # `type` ever sees (every sub-command's parser is this class, so this covers all)
        if action.option_strings and "--" in arg_strings:
            raise argparse.ArgumentError(action, "expected a value, got '--'")
        return super()._get_values(action, arg_strings)


def build_parser() -> argparse.ArgumentParser:
    """The parser of ``snakecg`` with every sub-command that is installed."""
    import importlib

    p = _Parser(
        prog="snakecg",
        description="Derive, generate and run the contact models of planar snake robots that "
        "push objects (Reyes & Ma 2017).",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--version", action="version", version=f"snakecg {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    examples = []
    for name in COMMANDS:
        try:
            mod = importlib.import_module(f"snakecg.commands.{name}")
        except ModuleNotFoundError as exc:
            if exc.name == f"snakecg.commands.{name}":
                continue  # command not built yet
            raise
        mod.register(sub)
        sub.choices[name.replace("_", "-")].add_argument(
            "--quiet", action="store_true",
            help="no progress on standard error (model builds, stages, bars)")
        examples.append(_first_example(sub.choices[name.replace("_", "-")]))
    p.epilog = ("examples:\n" + "".join(f"  {e}\n" for e in examples if e)
                + "\nRun 'snakecg COMMAND --help' for a command's options and examples.\n"
                "Exit status: 0 success, 2 usage or input error, 1 failure.")
    return p


def _first_example(parser: argparse.ArgumentParser) -> str:
    """The first example line of a sub-command's epilog (``example: ...`` or a list)."""
    for line in (parser.epilog or "").splitlines():
        line = line.strip()
        if line.startswith("example:"):
            line = line[len("example:"):].strip()
        if line.startswith("snakecg "):
            return line.split("  #")[0].rstrip()
    return ""


def _format_warning(message, category, filename, lineno, line=None):
    return f"snakecg: warning: {' '.join(str(message).split())}\n"


def main(argv=None) -> int:
    try:
        parser = build_parser()  # imports every sub-command: a Ctrl-C may land here too
        args = parser.parse_args(argv)
    except KeyboardInterrupt:
        sys.stderr.write("snakecg: interrupted\n")
        return 130
    if not getattr(args, "command", None):
        parser.print_help(sys.stderr)
        return 2
    command = f"snakecg {args.command}"
    hint = f"(see {command} --help)"
    saved_format = warnings.formatwarning
    saved_progress = os.environ.get("SNAKECG_PROGRESS")
    if getattr(args, "quiet", False):  # for this command, and the processes it starts
        os.environ["SNAKECG_PROGRESS"] = "0"
    with warnings.catch_warnings():
        warnings.simplefilter("default")
        warnings.formatwarning = _format_warning
        try:
            return int(args.run(args) or 0)
        except InputError as exc:
            sys.stderr.write(f"{command}: error: {_one_line(exc)} {hint}\n")
            return 2
        except SnakecgError as exc:
            sys.stderr.write(f"{command}: failed: {_one_line(exc)}\n")
            return 1
        except BrokenPipeError:
            # the reader went away (e.g. `snakecg show --c ... | head`): stop quietly
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            return 1
        except OSError as exc:
            sys.stderr.write(f"{command}: failed: {_one_line(exc)}\n")
            return 1
        except KeyboardInterrupt:
            sys.stderr.write(f"{command}: interrupted\n")
            _quiet_cluster_close()
            return 130
        finally:
            warnings.formatwarning = saved_format
            if saved_progress is None:
                os.environ.pop("SNAKECG_PROGRESS", None)
            else:
                os.environ["SNAKECG_PROGRESS"] = saved_progress


def _quiet_cluster_close() -> None:
    """An interrupt can land while a local Dask cluster starts: distributed's own exit hook
    then closes it half started and prints a traceback (an AssertionError on its status)
    after the one line. The hook still runs, without the traceback."""
    import atexit

    spec = sys.modules.get("distributed.deploy.spec")
    close = getattr(spec, "close_clusters", None)
    if close is None:
        return

    def quietly():
        try:
            close()
        except Exception:  # noqa: BLE001 - a half-started cluster's close; the process ends
            pass

    atexit.unregister(close)
    atexit.register(quietly)


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())
    return text or type(exc).__name__


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
