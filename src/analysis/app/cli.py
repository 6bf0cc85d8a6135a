"""Command line: ``python -m analysis <command>`` (contract in design.md).

Every command has ``--help``, exits 0 on success and 2 on bad input with a one-line
reason on stderr. Angles are degrees and lengths mm at this edge.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from analysis.kinematics.arm import (
    BRANCHES,
    DEFAULT_TOL_MM,
    Arm,
    BaseAxisError,
    Status,
    UnreachableError,
    as_points,
)
from analysis.kinematics.params import load_table3
from analysis.kinematics.pulses import angles_to_pulses

__all__ = ["main"]

INPUT_COLUMNS = ("x_mm", "y_mm", "z_mm")
OUTPUT_COLUMNS = (
    "branch",
    "reachable",
    "theta1_deg",
    "theta2_deg",
    "theta3_deg",
    "c1",
    "c2",
    "c3",
    "status",
)
_STATUS_TEXT = {
    Status.OK: "ok",
    Status.OUT_OF_REACH: "out-of-reach",
    Status.INSIDE_REACH: "inside-inner-reach",
    Status.BASE_AXIS: "base-axis",
}


class UsageError(ValueError):
    """Bad input from the command line: reported on stderr, exit status 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line on stderr, exit 2 (argparse's own code)
        self.exit(2, f"{self.prog}: error: {message}\n")


def _finite(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text!r} is not a finite number")
    return value


def _arm(args: argparse.Namespace) -> Arm:
    return Arm(load_table3(args.params) if args.params else load_table3())


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument("--params", type=Path, help="Table 3 CSV to use instead of data/table3.csv")


# --- fk ------------------------------------------------------------------------------
def _cmd_fk(args: argparse.Namespace) -> int:
    arm = _arm(args)
    theta_deg = [args.t1, args.t2, args.t3]
    p = arm.fk(np.radians(theta_deg))
    if args.json:
        print(json.dumps({"theta_deg": theta_deg, "position_mm": p.tolist()}))
    else:
        print(
            f"theta = ({', '.join(f'{t:.2f}' for t in theta_deg)}) deg -> "
            f"P = ({', '.join(f'{v:.3f}' for v in p)}) mm"
        )
    return 0


# --- ik ------------------------------------------------------------------------------
def _branches(name: str) -> tuple[str, ...]:
    return BRANCHES if name == "all" else (name,)


def _cmd_ik(args: argparse.Namespace) -> int:
    if args.input is not None or args.output is not None:
        if args.x is not None:
            raise UsageError("give either a target X Y Z or --input/--output, not both")
        if args.input is None or args.output is None:
            raise UsageError("batch mode needs both --input IN.csv and --output OUT.csv")
        return _ik_batch(args)
    given = [v for v in (args.x, args.y, args.z) if v is not None]
    if len(given) != 3:
        raise UsageError(
            f"give a target X Y Z (mm; got {len(given)} of 3 coordinates), "
            "or --input IN.csv --output OUT.csv"
        )
    return _ik_single(args)


def _ik_single(args: argparse.Namespace) -> int:
    arm = _arm(args)
    target = [args.x, args.y, args.z]
    t1_axis = None if args.theta1_on_axis is None else math.radians(args.theta1_on_axis)
    sols = arm.ik_all(target, theta1_on_axis=t1_axis, tol=args.tol, branches=_branches(args.branch))
    ppr = arm.params.pulses_per_rev
    out = []
    for name, theta in sols.items():
        out.append(
            {
                "branch": name,
                "theta_deg": np.degrees(theta).tolist(),
                "pulses": angles_to_pulses(theta, ppr).tolist(),
            }
        )
    if args.json:
        print(json.dumps({"target": target, "reachable": True, "solutions": out}))
    else:
        print(f"target ({', '.join(f'{v:g}' for v in target)}) mm")
        for s in out:
            ang = ", ".join(f"{t:.2f}" for t in s["theta_deg"])
            pul = ", ".join(str(c) for c in s["pulses"])
            print(f"  {s['branch']:<10} theta = ({ang}) deg   pulses = ({pul})")
    return 0


def _read_targets(path: Path) -> pd.DataFrame:
    try:
        df = pd.read_csv(path, dtype=str, keep_default_na=False)
    except FileNotFoundError:
        raise UsageError(f"{path}: no such file") from None
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise UsageError(f"{path}: not a readable CSV ({str(exc).splitlines()[0]})") from None
    missing = [c for c in INPUT_COLUMNS if c not in df.columns]
    if missing:
        raise UsageError(
            f"{path}: missing column(s) {', '.join(missing)} (have: {', '.join(df.columns)})"
        )
    for col in INPUT_COLUMNS:
        values = pd.to_numeric(df[col].str.strip(), errors="coerce")
        bad = values.isna() | ~np.isfinite(values.to_numpy(dtype=float, na_value=np.nan))
        if bad.any():
            i = int(np.flatnonzero(bad.to_numpy())[0])
            raise UsageError(
                f"{path} line {i + 2} column {col}: {df[col].iloc[i]!r} is not a finite number"
            )
        df[col] = values.astype(float)
    return df


def _ik_batch(args: argparse.Namespace) -> int:
    arm = _arm(args)
    df = _read_targets(args.input)
    p = as_points(df[list(INPUT_COLUMNS)].to_numpy())
    t1_axis = None if args.theta1_on_axis is None else math.radians(args.theta1_on_axis)
    sol = arm.solve(p, _branches(args.branch), theta1_on_axis=t1_axis, tol=args.tol)
    n, nb = sol.ok.shape
    # one output row per target and branch, targets in input order
    theta = sol.theta.reshape(n * nb, 3)
    ok = sol.ok.reshape(n * nb)
    pulses = np.zeros((n * nb, 3), dtype=np.int64)
    if ok.any():
        pulses[ok] = angles_to_pulses(theta[ok], arm.params.pulses_per_rev)
    base = df.rename(columns={c: f"input_{c}" for c in df.columns if c in OUTPUT_COLUMNS})
    out = base.loc[base.index.repeat(nb)].reset_index(drop=True)
    out["branch"] = list(sol.branches) * n
    out["reachable"] = np.repeat(sol.reachable, nb)
    deg = np.degrees(theta)
    # unsolved rows stay empty (masked), never NaN text
    for j in range(3):
        out[f"theta{j + 1}_deg"] = pd.arrays.FloatingArray(np.where(ok, deg[:, j], 0.0), ~ok)
    for j in range(3):
        out[f"c{j + 1}"] = pd.arrays.IntegerArray(pulses[:, j], ~ok)
    out["status"] = [_STATUS_TEXT[Status(s)] for s in np.repeat(sol.status, nb)]
    out["reachable"] = out["reachable"].map({True: "true", False: "false"})
    args.output.parent.mkdir(parents=True, exist_ok=True)
    out.to_csv(args.output, index=False, float_format="%.10g")
    n_ok = int(sol.ok.any(axis=-1).sum())
    print(
        f"{n} targets, {n_ok} solved, {int((~sol.reachable).sum())} unreachable, "
        f"{int((sol.status == Status.BASE_AXIS).sum())} on the base axis -> {args.output}",
        file=sys.stderr,
    )
    return 0


# --- report ----------------------------------------------------------------------------
def _cmd_report(args: argparse.Namespace) -> int:
    from analysis.app.report import build_report

    index = build_report(args.out, notebooks=args.notebooks or None)
    print(index)
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="python -m analysis", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    p = sub.add_parser("fk", help="joint angles (deg) -> end point (mm), eq. 2")
    for name in ("t1", "t2", "t3"):
        p.add_argument(name, type=_finite, metavar=name.upper(), help=f"theta{name[1]} in degrees")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    _common(p)
    p.set_defaults(func=_cmd_fk)

    p = sub.add_parser(
        "ik",
        help="target (mm) -> joint angles (deg) and pulses, eqs. 6-22",
        description="Closed-form IK (corrected eqs. 6-19) and pulses (eqs. 20-22).",
    )
    p.add_argument("x", nargs="?", type=_finite, metavar="X", help="target x in mm")
    p.add_argument("y", nargs="?", type=_finite, metavar="Y", help="target y in mm")
    p.add_argument("z", nargs="?", type=_finite, metavar="Z", help="target z in mm")
    p.add_argument(
        "--branch",
        default="front-up",
        choices=[*BRANCHES, "all"],
        help="IK branch (default front-up, the paper's)",
    )
    p.add_argument("--json", action="store_true", help="machine-readable output (single target)")
    p.add_argument("--input", type=Path, help="batch: CSV with columns x_mm,y_mm,z_mm")
    p.add_argument("--output", type=Path, help="batch: output CSV (one row per target and branch)")
    p.add_argument(
        "--theta1-on-axis",
        type=_finite,
        metavar="DEG",
        help="waist angle to use for targets on the base axis (else they have no solution)",
    )
    p.add_argument(
        "--tol",
        type=_finite,
        default=DEFAULT_TOL_MM,
        help="distance tolerance in mm at the reach boundary and base axis "
        f"(default {DEFAULT_TOL_MM:g})",
    )
    _common(p)
    p.set_defaults(func=_cmd_ik)

    try:  # the PLC generator registers `stl` when it is installed (analysis.plc)
        from analysis.plc.cli import add_parser as _add_stl
    except ImportError:
        _add_stl = None
    if _add_stl is not None:
        _add_stl(sub)

    p = sub.add_parser(
        "errata",
        add_help=False,
        help="the errata register: --check, --write, --write-readme (see errata --help)",
    )
    p.set_defaults(func=None)  # dispatched in main() before parsing

    p = sub.add_parser(
        "report", help="execute every notebook, export figures and build/report/index.html"
    )
    p.add_argument(
        "--out",
        type=Path,
        default=Path("build/report"),
        help="output folder (default build/report)",
    )
    p.add_argument(
        "--notebooks",
        nargs="*",
        type=Path,
        help="only these notebooks (default: all in notebooks/)",
    )
    p.set_defaults(func=_cmd_report)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv[:1] == [
        "errata"
    ]:  # its options belong to analysis.audit.register, passed through whole
        from analysis.audit import register as errata

        return errata.main(argv[1:])
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except (UsageError, UnreachableError, BaseAxisError, ValueError, FileNotFoundError) as exc:
        message = " ".join(str(exc).split())
        if isinstance(exc, BaseAxisError):
            message += " (here: --theta1-on-axis DEG)"
        print(f"{parser.prog} {args.command}: error: {message}", file=sys.stderr)
        return 2
