"""The command line: ``python -m analysis <command>``, one parser for everything a user can do.

Every command has ``--help`` with examples, exits 0 on success and 2 on bad input with one
line ``python -m analysis <command>: error: <reason>`` on stderr (with ``--json``: a JSON
object with ``"error"`` on stdout instead; JSON is always valid: no NaN or Infinity tokens,
and warnings never go to stdout). Angles are degrees and lengths mm at this edge; every
number is read and checked by :mod:`analysis.validate` (the same rules as in batch CSV
files; ``ik -1e3 0 600`` needs no ``--``). Outputs are written atomically (a temporary file,
then a rename): an error never leaves a half-written file or a directory it made, and an
output may not be an input, a device or a FIFO; ``-`` is standard input or output.
SIGINT, SIGTERM and SIGHUP end a command with one line and status 128 + the signal
(130 for Ctrl-C), removing its temporary files.

Imports are deferred to the command that needs them: answering one ``ik`` target loads
NumPy and the kinematics, not SymPy, pandas or Matplotlib.
"""

from __future__ import annotations

import argparse
import errno
import signal
import sys
from collections.abc import Sequence

from analysis.app.cli_audit import add_errata, add_report
from analysis.app.cli_common import PROG, HelpFormatter, Parser, to_json
from analysis.app.cli_kin import add_arms, add_fk, add_ik
from analysis.app.cli_play import add_play
from analysis.app.cli_plc import add_stl, add_stl_run
from analysis.app.cli_urdf import add_urdf

__all__ = ["build_parser", "main"]


EPILOG = """examples:
  python -m analysis ik 100 100 600 --json            Table 4 row 1, the paper's branch
  python -m analysis ik 100 100 600 --branch all      all four solutions
  python -m analysis fk 45 10.21 -155.13              joint angles (deg) -> point (mm)
  python -m analysis ik --input targets.csv --output solved.csv --branch all
  python -m analysis stl --dialect s7-200 -o ik.awl --map ik_map.json
  python -m analysis stl-run ik.awl --dialect s7-200 --set VD0=100.0 --read VD100:DINT
  python -m analysis ik 250 0 100 --arm palletizer     another arm (see: arms)
  python -m analysis ik --input - --output - < in.csv > out.csv    standard input and output
  python -m analysis errata --check                    are the registers current?
  python -m analysis report --out build/report
"""


def build_parser() -> argparse.ArgumentParser:
    """The one parser of the command line."""
    parser = Parser(
        prog=PROG,
        description="Audit of published robot-kinematics papers: kinematics, errata, PLC code.",
        epilog=EPILOG,
        formatter_class=HelpFormatter,
    )
    parser.add_argument("--version", action=_VersionAction, help="show the version and exit")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=Parser)

    add_fk(sub)  # analysis.app.cli_kin
    add_ik(sub)
    add_stl(sub)  # analysis.app.cli_plc
    add_stl_run(sub, formatter_class=HelpFormatter)
    add_errata(sub)  # analysis.app.cli_audit
    add_arms(sub)
    add_report(sub)
    add_urdf(sub, HelpFormatter)  # analysis.app.cli_urdf
    add_play(sub, HelpFormatter)  # analysis.app.cli_play
    return parser


class _VersionAction(argparse.Action):
    """``--version``: the installed package's version, looked up only when asked for."""

    def __init__(self, option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS,
                 help=None):  # fmt: skip
        super().__init__(option_strings, dest, nargs=0, default=default, help=help)

    def __call__(self, parser, namespace, values, option_string=None):
        print(f"{parser.prog} {_version()}")
        parser.exit(0)


def _version() -> str:
    """The installed package's version (pyproject.toml)."""
    from importlib import metadata

    try:
        return metadata.version("analysis")
    except metadata.PackageNotFoundError:  # pragma: no cover - run from a source tree
        return "unknown (not installed)"


_PARSER: list = []


def _parser() -> argparse.ArgumentParser:
    """The parser, built once per process (parsing keeps no state in it)."""
    if not _PARSER:
        _PARSER.append(build_parser())
    return _PARSER[0]


def _error_doc(exc: Exception, args) -> dict:
    from analysis.kinematics.arm import BaseAxisError, UnreachableError

    doc: dict = {"error": " ".join(str(exc).split())}
    if isinstance(exc, UnreachableError):
        doc.update(
            target=list(exc.target),
            reachable=False,
            status=exc.status.text,
            distance_mm=exc.distance_mm,
        )
    elif isinstance(exc, BaseAxisError):
        doc.update(target=list(exc.target), reachable=True, status="base-axis")
    return doc


def _hint(exc: Exception, args) -> str:
    """A second sentence where the likely mistake is the user's units or a missing flag."""
    from analysis.kinematics.arm import BaseAxisError, UnreachableError

    if isinstance(exc, BaseAxisError):
        return " (here: --theta1-on-axis DEG)"
    target = getattr(exc, "target", None)
    if isinstance(exc, UnreachableError) and target and max(abs(v) for v in target[:3]) <= 5:
        return " (coordinates are in mm: did you give metres?)"
    if "does not exist" in str(exc) and hasattr(args, "mkdir") and not args.mkdir:
        return " (--mkdir creates it)"
    return ""


class _Signal(BaseException):
    """SIGTERM or SIGHUP, raised where the program is, so that every ``with`` and ``finally``
    runs (temporary files removed) before the command ends with status 128 + the signal."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


def _raise_signal(signum, frame) -> None:
    raise _Signal(signum)


def _install_signals() -> dict:
    old = {}
    for sig in (signal.SIGTERM, signal.SIGHUP):
        try:
            old[sig] = signal.signal(sig, _raise_signal)
        except (ValueError, OSError):  # not the main thread
            pass
    return old


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    import warnings

    args = _parser().parse_args(list(sys.argv[1:] if argv is None else argv))
    if sys.stdout is None:  # started with standard output closed (>&-): no answer is lost
        sys.stdout = _ClosedStdout()
    if sys.stdin is None:  # started with standard input closed (<&-): `-` is refused in one line
        sys.stdin = _ClosedStdin()
    old = _install_signals()
    try:
        with warnings.catch_warnings():
            # a warning goes to stderr, never into stdout or JSON; none is expected from
            # validated input (tests/hostile holds every entry point to that)
            warnings.simplefilter("default")
            code = int(args.func(args) or 0)
            sys.stdout.flush()  # a full disk or a closed descriptor fails here, not at exit
            return code
    except (ValueError, OSError) as exc:  # UsageError, UnreachableError, OutputError, ...
        if isinstance(exc, BrokenPipeError):
            return _broken_pipe()
        if isinstance(exc, OSError):
            where = getattr(exc, "filename", None)
            exc = ValueError(f"{where}: {exc.strerror or exc}" if where else
                             f"cannot write the answer: {exc.strerror or exc}")  # fmt: skip
        message = " ".join(str(exc).split()) + _hint(exc, args)
        try:
            if not getattr(args, "json", False):
                raise OSError  # the message goes to stderr
            doc = _error_doc(exc, args)
            doc["error"] = message
            print(to_json(doc))
            sys.stdout.flush()
        except OSError:
            print(f"{PROG} {args.command}: error: {message}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"{PROG} {args.command}: interrupted (SIGINT)", file=sys.stderr)
        return 128 + signal.SIGINT
    except _Signal as exc:
        name = signal.Signals(exc.signum).name
        print(f"{PROG} {args.command}: terminated ({name})", file=sys.stderr)
        return 128 + exc.signum
    finally:
        for sig, handler in old.items():
            signal.signal(sig, handler)


class _ClosedStdout:
    """Standard output when the process started without one: every write fails, so a
    command whose answer cannot be written exits 2 instead of 0."""

    def write(self, text: str) -> int:
        raise OSError(errno.EBADF, "standard output is closed")

    def flush(self) -> None:
        pass


class _ClosedStdin:
    """Standard input when the process started without one: reading ``-`` (``ik --input -``,
    ``stl-run -``) is refused in one line instead of an AttributeError traceback."""

    closed = True

    def isatty(self) -> bool:
        return False

    def __getattr__(self, name: str):  # read, buffer, readline, fileno, ...
        raise ValueError("cannot read -: standard input is closed (<&-)")


def _broken_pipe() -> int:
    """The reader of stdout went away (``| head``): end quietly, as a shell tool does."""
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # pragma: no cover
        pass
    return 128 + signal.SIGPIPE
