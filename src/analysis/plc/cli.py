"""``python -m analysis stl``: write the PLC program and its memory map (design.md).

``stl --dialect s7-200|s7-300 [--branch B] [--trig native|subroutine] [--layout IN.json]
[--no-motion] -o PROGRAM.awl --map MAP.json``. Exit 2 with a one-line reason on bad input.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from analysis.kinematics.arm import BRANCHES
from analysis.kinematics.params import load_table3
from analysis.plc.emit import allocate, emit_s7200, emit_s7300
from analysis.plc.ir import build_program
from analysis.plc.memmap import DIALECTS, MemoryMap, default_map
from analysis.plc.motion import motion_networks

__all__ = ["add_parser", "cmd_stl", "generate"]


def generate(
    dialect: str = "s7-300",
    branch: str = "front-up",
    trig: str | None = None,
    mmap: MemoryMap | None = None,
    params=None,
    motion: bool = True,
) -> tuple[str, str]:
    """Program text and MAP.json text for one dialect (the CLI's work, for tests/notebooks)."""
    if dialect not in DIALECTS:
        raise ValueError(f"dialect {dialect!r} is not one of {', '.join(DIALECTS)}")
    params = params or load_table3()
    trig = trig or ("native" if dialect == "s7-300" else "subroutine")
    if dialect == "s7-200" and trig == "native":
        raise ValueError("--trig native is not possible on the S7-200 (no ATAN/ACOS instruction)")
    mmap = (mmap or default_map(dialect)).with_dialect(dialect)
    prog = build_program(params, branch, trig)
    if dialect == "s7-300":
        text = emit_s7300(prog, mmap)
    else:
        text = emit_s7200(prog, mmap, motion=motion_networks(mmap) if motion else None)
    return text, mmap.to_json(allocate(prog, mmap))


def cmd_stl(args: argparse.Namespace) -> int:
    try:
        mmap = MemoryMap.from_json(args.layout) if args.layout else None
        text, mjson = generate(
            args.dialect,
            args.branch,
            args.trig,
            mmap,
            motion=not args.no_motion,
            params=load_table3(args.params) if getattr(args, "params", None) else None,
        )
        Path(args.output).write_text(text, encoding="utf-8", newline="")
        Path(args.map).write_text(mjson, encoding="utf-8")
    except (ValueError, OSError) as exc:
        print(f"stl: error: {exc}".replace("\n", " "), file=sys.stderr)
        return 2
    return 0


def add_parser(subparsers) -> None:
    """Register ``stl`` on the lead's ``analysis.app.cli`` subparsers."""
    p = subparsers.add_parser(
        "stl",
        help="generate the PLC program (S7-200 STL or S7-300 AWL) and its memory map",
        description="Generate the corrected IK program (Figures 3-6, eqs. 6-22) for a Siemens PLC.",
    )
    p.add_argument("--dialect", required=True, choices=DIALECTS)
    p.add_argument(
        "--branch",
        default="front-up",
        choices=BRANCHES,
        help="IK branch (default: the paper's front-up)",
    )
    p.add_argument(
        "--trig",
        choices=("native", "subroutine"),
        default=None,
        help="S7-300: native ATAN/ACOS (default) or the generated subroutines; "
        "S7-200: subroutine only",
    )
    p.add_argument(
        "--layout", type=Path, help="read the memory map (MAP.json format) instead of the default"
    )
    p.add_argument("--no-motion", action="store_true", help="S7-200: omit the PTO motion networks")
    p.add_argument("--params", type=Path, help="Table 3 CSV to use instead of data/table3.csv")
    p.add_argument("-o", "--output", required=True, type=Path, help="program file to write (.awl)")
    p.add_argument(
        "--map", required=True, type=Path, help="MAP.json to write (every input/output address)"
    )
    p.set_defaults(func=cmd_stl)


def main(argv=None) -> int:  # standalone: python -m analysis.plc.cli
    parser = argparse.ArgumentParser(prog="analysis")
    sub = parser.add_subparsers(dest="command", required=True)
    add_parser(sub)
    args = parser.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
