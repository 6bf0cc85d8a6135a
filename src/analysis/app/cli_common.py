"""What every command of :mod:`analysis.app.cli` shares: the parser and help classes, the
number readers of the command line (:mod:`analysis.validate`), JSON that is always valid, the
progress line, and the ``--arm``/``--params``/``--mkdir`` options with the arm they select."""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
import time
from pathlib import Path

__all__ = ["PROG", "HelpFormatter", "Parser", "Progress", "UsageError", "add_arm_options",
           "add_mkdir", "arm_from_args", "emit", "finite", "to_json", "tolerance",
           "waist_angle", "whole"]  # fmt: skip


PROG = "python -m analysis"


class UsageError(ValueError):
    """Bad input from the command line: reported on one line, exit status 2."""


# argparse takes an argument that starts with "-" for an option unless it looks like a
# negative number, and its test knows no exponent: "-1e3" was "unrecognized arguments". Here
# anything that starts like a number (a digit or a point after the minus, or inf/nan) is a
# value; analysis.validate then decides whether it is one. No option starts that way.
_NEGATIVE_NUMBER = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


class Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message: str) -> None:  # one line on stderr, exit 2 (argparse's code)
        self.exit(2, f"{self.prog}: error: {message}\n")


class HelpFormatter(argparse.RawDescriptionHelpFormatter):
    pass


def finite(text: str) -> float:
    """A number given on the command line (:func:`analysis.validate.parse_real`: ASCII
    digits, no underscores, finite)."""
    from analysis.validate import InvalidValue, parse_real

    try:
        return parse_real(text)
    except InvalidValue as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def tolerance(text: str) -> float:
    from analysis.validate import InvalidValue, tolerance_mm

    try:
        return tolerance_mm(finite(text), "--tol")
    except InvalidValue as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def whole(text: str) -> int:
    value = finite(text)
    if value != int(value):
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number")
    return int(value)


def to_json(doc) -> str:
    """JSON text that is always valid: a non-finite float (which no validated input yields)
    becomes null instead of the invalid token NaN or Infinity."""

    def clean(v):
        if isinstance(v, float) and not math.isfinite(v):
            return None
        if isinstance(v, dict):
            return {k: clean(x) for k, x in v.items()}
        if isinstance(v, (list, tuple)):
            return [clean(x) for x in v]
        return v

    text = json.dumps(clean(doc), allow_nan=False, ensure_ascii=False)
    # A file name that is no UTF-8 reaches us with lone surrogates (os.fsdecode); written as
    # they are, stdout would hold bytes that are no UTF-8. As \uDCxx escapes (what
    # ensure_ascii writes for them) the JSON is UTF-8, and json.loads + os.fsencode give the
    # name's bytes back. Outside strings JSON has no surrogate to replace.
    return _SURROGATE.sub(lambda m: f"\\u{ord(m.group(0)):04x}", text)


_SURROGATE = re.compile("[\ud800-\udfff]")


class Progress:
    """Progress on stderr for work that takes over a second, on a terminal only (a log or a
    pipe gets the final summary alone): ``update(text)`` rewrites one line."""

    def __init__(self, what: str) -> None:
        self.what, self.start, self.shown = what, time.monotonic(), False
        self.tty = sys.stderr.isatty()

    def update(self, text: str) -> None:
        if self.tty and time.monotonic() - self.start >= 1.0:
            sys.stderr.write(f"\r{self.what}: {text} ({time.monotonic() - self.start:.0f} s)\033[K")
            sys.stderr.flush()
            self.shown = True

    def done(self) -> None:
        if self.shown:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()


def arm_from_args(args: argparse.Namespace):
    """The arm of ``--arm`` (and ``--params``: a Table 3 file for the paper's arm)."""
    from analysis.kinematics.arm import load_arm

    if args.params:
        if args.arm != "grabber":
            raise UsageError("--params takes a Table 3 file: it applies to the paper's arm only")
        from analysis.kinematics.params import load_table3

        table3 = load_table3(args.params)
        return load_arm("grabber").with_(**table3, pulses_per_rev=table3.pulses_per_rev)
    return load_arm(args.arm)


def add_arm_options(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--arm",
        default="grabber",
        metavar="NAME|PATH",
        help="arm: a name (default: grabber, the paper's; list: arms) or the path of a "
        "description file (*.toml), anywhere on disk; a description that names a .py "
        "closed form (next to it) runs that file's code: load only descriptions you trust "
        "as you would run their scripts",
    )
    p.add_argument("--params", type=Path, help="a Table 3 CSV instead of data/table3.csv")


def emit(args, doc: dict, text: str) -> None:
    print(to_json(doc) if getattr(args, "json", False) else text)


def add_mkdir(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--mkdir",
        action="store_true",
        help="create the output's missing directories (without it a missing directory is an "
        "error; they are removed again if the command fails)",
    )


def waist_angle(args) -> float | None:
    """The waist angle on the base axis [rad]: the degrees given, reduced exactly to
    (-180, 180] first (:func:`analysis.validate.reduce_deg`; 3600 deg is 0 deg)."""
    if args.theta1_on_axis is None:
        return None
    from analysis.validate import reduce_deg

    return math.radians(reduce_deg(args.theta1_on_axis))
