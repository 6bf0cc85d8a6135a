"""The command line: ``python -m analysis <command>``, one parser for everything a user can do.

Every command has ``--help`` with examples, exits 0 on success and 2 on bad input with one
line ``python -m analysis <command>: error: <reason>`` on stderr (with ``--json``: a JSON
object with ``"error"`` on stdout instead). Angles are degrees and lengths mm at this edge.
Outputs are written atomically (a temporary file, then a rename): an error never leaves a
half-written file, and an output may not be an input.

Imports are deferred to the command that needs them: answering one ``ik`` target loads
NumPy and the kinematics, not SymPy, pandas or Matplotlib.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Sequence
from pathlib import Path

__all__ = ["build_parser", "main"]

PROG = "python -m analysis"
EPILOG = """examples:
  python -m analysis ik 100 100 600 --json            Table 4 row 1, the paper's branch
  python -m analysis ik 100 100 600 --branch all      all four solutions
  python -m analysis fk 45 10.21 -155.13              joint angles (deg) -> point (mm)
  python -m analysis ik --input targets.csv --output solved.csv --branch all
  python -m analysis stl --dialect s7-200 -o ik.awl --map ik_map.json
  python -m analysis ik 250 0 100 --arm palletizer     another arm (see: arms)
  python -m analysis errata --check                    are the registers current?
  python -m analysis report --out build/report
"""


class UsageError(ValueError):
    """Bad input from the command line: reported on one line, exit status 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line on stderr, exit 2 (argparse's code)
        self.exit(2, f"{self.prog}: error: {message}\n")


class _Help(argparse.RawDescriptionHelpFormatter):
    pass


def _finite(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{text!r} is not a finite number")
    return value


def _arm(args: argparse.Namespace):
    """The arm of ``--arm`` (and ``--params``: a Table 3 file for the paper's arm)."""
    from analysis.kinematics.arm import Arm, load_arm

    if args.params:
        if args.arm != "grabber":
            raise UsageError("--params takes a Table 3 file: it applies to the paper's arm only")
        from analysis.kinematics.params import load_table3

        return Arm(load_table3(args.params))
    return load_arm(args.arm)


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--arm", default="grabber", help="arm (default: grabber, the paper's; list: arms)"
    )
    p.add_argument("--params", type=Path, help="a Table 3 CSV instead of data/table3.csv")


def _emit(args, doc: dict, text: str) -> None:
    print(json.dumps(doc) if getattr(args, "json", False) else text)


# --- fk --------------------------------------------------------------------------------------
def _cmd_fk(args: argparse.Namespace) -> int:
    import numpy as np

    from analysis.kinematics.arm import MAX_JOINT_DEG

    arm = _arm(args)
    if len(args.angles) != arm.n_joints:
        raise UsageError(
            f"{arm.name} has {arm.n_joints} joints: give {arm.n_joints} angles in degrees, "
            f"got {len(args.angles)}"
        )
    for j, a in enumerate(args.angles, 1):
        if abs(a) > MAX_JOINT_DEG:
            raise UsageError(
                f"theta{j} = {a:g} deg is beyond +-{MAX_JOINT_DEG:g} deg (ten turns): "
                "angles are in degrees"
            )
    p = arm.fk(np.radians(args.angles))
    p = np.where(p == 0, 0.0, p)  # no "-0.000"
    doc = {"arm": arm.name, "theta_deg": list(args.angles), "position_mm": p.tolist()}
    text = (
        f"theta = ({', '.join(f'{t:.2f}' for t in args.angles)}) deg -> "
        f"P = ({', '.join(f'{v:.3f}' for v in p)}) mm"
    )
    _emit(args, doc, text)
    return 0


# --- ik ------------------------------------------------------------------------------------------
def _cmd_ik(args: argparse.Namespace) -> int:
    if args.input is not None or args.output is not None:
        if args.target:
            raise UsageError("give either a target X Y Z or --input/--output, not both")
        if args.input is None or args.output is None:
            raise UsageError("batch mode needs both --input IN.csv and --output OUT.csv")
        from analysis.app.batch import solve_csv

        summary = solve_csv(
            _arm(args),
            args.input,
            args.output,
            branch=args.branch,
            tol=args.tol,
            theta1_on_axis=_axis(args),
            chunk_rows=args.chunk_rows,
            params=args.params,
        )
        text = (
            f"{summary['targets']} targets, {summary['solved']} solved, "
            + ", ".join(f"{n} {s}" for s, n in summary["status"].items() if s != "ok")
            + f" -> {summary['output']}"
        )
        if args.json:
            print(json.dumps(summary))
        else:
            print(text, file=sys.stderr)
        return 0
    arm = _arm(args)
    n, given = len(arm.inputs), len(args.target)
    if given != n:
        if n == 3:
            raise UsageError(
                f"give a target X Y Z (mm; got {given} of 3 coordinates), "
                "or --input IN.csv --output OUT.csv"
            )
        raise UsageError(
            f"{arm.name} takes {n} values ({', '.join(_input_labels(arm))}); got {given}"
        )
    return _ik_single(args, arm)


def _input_labels(arm) -> list[str]:
    return [f"{name} [{unit}]" for name, unit in zip(arm.inputs, arm.user_units, strict=True)]


def _nearest_pose_hint(arm, target) -> str:
    """The nearest orientation the arm can take at the target's position, as a command."""
    import numpy as np

    from analysis.studies.gr1 import project_orientation

    pose, turned = project_orientation(arm, np.asarray(target, dtype=float))
    words = [f"{v:g}" for v in pose[:3]] + [f"{math.degrees(v):.3f}" for v in pose[3:]]
    return (
        f"the nearest orientation it can take there is {math.degrees(float(turned)):.3f} deg "
        f"away: python -m analysis ik {' '.join(words)} --arm {arm.name} --branch all"
    )


def _axis(args) -> float | None:
    return None if args.theta1_on_axis is None else math.radians(args.theta1_on_axis)


def _ik_single(args: argparse.Namespace, arm) -> int:
    import numpy as np

    from analysis.kinematics.pulses import angles_to_pulses
    from analysis.kinematics.solution import OrientationError

    given = list(args.target)
    target = arm.from_user(given).tolist()
    names = arm.branch_names(args.branch or arm.branches[0])
    try:
        sols = arm.ik_all(target, theta1_on_axis=_axis(args), tol=args.tol, branches=names)
    except OrientationError as exc:
        # the library names the Python way to the nearest orientation; here, the command
        hint = arm.closed_form.PROJECTION_HINT
        raise UsageError(str(exc).replace(hint, _nearest_pose_hint(arm, target))) from None
    out = [
        {
            "branch": name,
            "theta_deg": np.degrees(theta).tolist(),
            "pulses": angles_to_pulses(theta, arm.params.pulses_per_rev).tolist(),
        }
        for name, theta in sols.items()
    ]
    units = arm.user_units
    if all(u == "mm" for u in units):
        lines = [f"target ({', '.join(f'{v:g}' for v in given)}) mm"]
    else:
        lines = [
            "pose "
            + ", ".join(f"{name} = {v:g} {u}"
                        for name, v, u in zip(arm.inputs, given, units, strict=True))
        ]  # fmt: skip
    for s in out:
        ang = ", ".join(f"{t:.2f}" for t in s["theta_deg"])
        pul = ", ".join(str(c) for c in s["pulses"])
        lines.append(f"  {s['branch']:<10} theta = ({ang}) deg   pulses = ({pul})")
    doc = {"target": given, "reachable": True, "solutions": out}
    if arm.name != "grabber":
        doc["arm"] = arm.name
    _emit(args, doc, "\n".join(lines))
    return 0


# --- stl ------------------------------------------------------------------------------------------
def _cmd_stl(args: argparse.Namespace) -> int:
    from analysis.app.safe_io import check_paths, write_many_atomic
    from analysis.plc.generate import generate
    from analysis.plc.memmap import MemoryMap

    check_paths(
        inputs=[p for p in (args.layout, args.params) if p],
        outputs=[args.output, args.map],
        make_parents=True,
    )
    arm = _arm(args)
    mmap = MemoryMap.from_json(args.layout) if args.layout else None
    text, mjson = generate(
        args.dialect,
        args.branch,
        args.trig,
        mmap,
        params=arm.params,
        motion=not args.no_motion,
        theta1_on_axis=_axis(args),
    )
    write_many_atomic({args.output: text, args.map: mjson}, newline="", make_parents=True)
    doc = {
        "program": str(args.output),
        "map": str(args.map),
        "dialect": args.dialect,
        "arm": arm.name,
        "branch": args.branch or arm.branches[0],
        "lines": text.count("\n"),
    }
    print(
        json.dumps(doc)
        if args.json
        else f"wrote {args.output} ({args.dialect}, {arm.name} {doc['branch']}, "
        f"{doc['lines']} lines) and {args.map}"
    )
    return 0


# --- errata ------------------------------------------------------------------------------------
def _cmd_errata(args: argparse.Namespace) -> int:
    from analysis.audit import register as reg

    papers = [args.paper] if args.paper else None
    if args.write:
        changed = reg.write_all(papers)
        print("\n".join(changed) or "up to date")
        return 0
    if args.check:
        stale = reg.check(papers)
        if stale:
            print(f"out of date: {', '.join(stale)} (run: {PROG} errata --write)", file=sys.stderr)
            return 1
        print("up to date")
        return 0
    print(reg.render_markdown(papers), end="")
    return 0


# --- arms ----------------------------------------------------------------------------------------
def _cmd_arms(args: argparse.Namespace) -> int:
    import tomllib

    from analysis.kinematics.description import load_description
    from analysis.paths import data_dir

    docs = []
    for path in sorted((data_dir() / "arms").glob("*.toml")):
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
        if "rows" not in raw:  # not a D-H description (the picker: dimensions only)
            docs.append(
                {
                    "name": path.stem,
                    "title": "dimensions only, no D-H rows (a closed-chain model)",
                    "paper": "",
                    "joints": [],
                    "parameters": {
                        k: {"value": v["value"], "unit": v["unit"], "status": v["status"]}
                        for k, v in raw.get("parameters", {}).items()
                        if isinstance(v.get("value"), (int, float))
                    },
                }
            )
            continue
        d = load_description(path.stem)
        docs.append(
            {
                "name": d.name,
                "title": d.title,
                "paper": d.paper,
                "joints": [j.name for j in d.joints],
                "parameters": {
                    k: {"value": p.value, "unit": p.unit, "status": p.status}
                    for k, p in d.parameters.items()
                },
            }
        )
    if args.json:
        print(json.dumps(docs))
        return 0
    for d in docs:
        params = ", ".join(
            f"{k} = {v['value']:g} {v['unit']}" + (" (assumed)" if v["status"] == "assumed" else "")
            for k, v in d["parameters"].items()
        )
        print(f"{d['name']:<11} {d['title']} ({len(d['joints'])} joints): {params}")
    return 0


# --- report ---------------------------------------------------------------------------------------
def _cmd_report(args: argparse.Namespace) -> int:
    from analysis.app.report import build_report

    index = build_report(args.out, notebooks=args.notebooks or None)
    print(index)
    return 0


def _add_fk(sub) -> None:
    """``fk``: joint angles -> end point."""
    p = sub.add_parser(
        "fk",
        help="joint angles (deg) -> end point (mm)",
        description="Forward kinematics: the end point of the chain (the paper's eq. 2).",
        epilog="example:\n  python -m analysis fk 45 10.21 -155.13 --json",
        formatter_class=_Help,
    )
    p.add_argument("angles", nargs="+", type=_finite, metavar="DEG", help="joint angles [deg]")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    _common(p)
    p.set_defaults(func=_cmd_fk)


def _add_ik(sub) -> None:
    """``ik``: one target or a CSV of them -> joint angles and pulses."""
    p = sub.add_parser(
        "ik",
        help="target (mm) -> joint angles (deg) and pulses",
        description="Closed-form IK (the paper's corrected eqs. 6-19) and stepper pulses "
        "(eqs. 20-22), for one target or a CSV of them (columns x_mm, y_mm, z_mm; the output "
        "has one row per target and branch, with reachable = the row is solved and status = "
        "ok, out-of-reach, inside-reach, base-axis, joint-limits).",
        epilog="examples:\n  python -m analysis ik 100 100 600 --json\n"
        "  python -m analysis ik 0 0 900 --theta1-on-axis 30\n"
        "  python -m analysis ik 300 100 50 0 90 10 --arm gr1 --branch all\n"
        "  python -m analysis ik --input targets.csv --output solved.csv --branch all",
        formatter_class=_Help,
    )
    p.add_argument(
        "target",
        nargs="*",
        type=_finite,
        metavar="X Y Z",
        help="target [mm]; for the GR-1 the pose X Y Z [mm] ALPHA BETA GAMMA [deg] (RPY)",
    )
    p.add_argument("--branch", help="IK branch, or 'all' (default: the arm's first, the paper's)")
    p.add_argument("--json", action="store_true", help="machine-readable output and errors")
    p.add_argument(
        "--input",
        type=Path,
        help="batch: CSV with columns x_mm, y_mm, z_mm (the GR-1: also alpha_deg, beta_deg, "
        "gamma_deg)",
    )
    p.add_argument("--output", type=Path, help="batch: output CSV (one row per target, branch)")
    p.add_argument(
        "--chunk-rows", type=int, default=100_000, help="batch: rows per chunk (memory bound)"
    )
    p.add_argument(
        "--theta1-on-axis",
        type=_finite,
        metavar="DEG",
        help="waist angle for targets on the base axis (else they are refused)",
    )
    p.add_argument(
        "--tol",
        type=_finite,
        default=1e-6,
        help="distance tolerance [mm] at the reach boundary and the base axis, 0 .. 1 "
        "(default 1e-06)",
    )
    _common(p)
    p.set_defaults(func=_cmd_ik)


def _add_stl(sub) -> None:
    """``stl``: the PLC program and its memory map."""
    p = sub.add_parser(
        "stl",
        help="generate the PLC program (S7-200 STL, S7-300 AWL, ST, SCL, PLCopen XML) and its map",
        description="Generate the corrected IK program for a Siemens PLC, from the arm's "
        "closed form (the paper's Figures 3-6 as they should be), and MAP.json naming every "
        "input and output address.",
        epilog="examples:\n  python -m analysis stl --dialect s7-200 -o ik.awl --map ik_map.json\n"
        "  python -m analysis stl --dialect s7-300 --arm palletizer -o pal.awl --map pal.json\n"
        "  python -m analysis stl --dialect st --arm gr1 -o gr1.st --map gr1.json",
        formatter_class=_Help,
    )
    p.add_argument(
        "--dialect",
        required=True,
        choices=("s7-200", "s7-300", "st", "scl", "plcopen-xml"),
        help="S7-200 STL, S7-300 AWL, IEC 61131-3 ST (CODESYS, TwinCAT, OpenPLC), Siemens SCL "
        "(TIA Portal, S7-1200/1500), or PLCopen XML of the ST block",
    )
    p.add_argument("--branch", help="IK branch (default: the arm's first, the paper's)")
    p.add_argument(
        "--trig",
        choices=("native", "subroutine", "function"),
        help="S7-300: native ATAN/ACOS (default) or the generated subroutines; "
        "S7-200: subroutine only; ST/SCL: function (default: ATAN2 a generated function on "
        "ATAN), native or subroutine",
    )
    p.add_argument("--layout", type=Path, help="memory map (MAP.json format) to use")
    p.add_argument("--no-motion", action="store_true", help="S7-200: omit the PTO motion networks")
    p.add_argument(
        "--theta1-on-axis", type=_finite, metavar="DEG", help="waist angle on the base axis"
    )
    p.add_argument("-o", "--output", required=True, type=Path, help="program file to write")
    p.add_argument("--map", required=True, type=Path, help="MAP.json to write")
    p.add_argument("--json", action="store_true", help="machine-readable summary and errors")
    _common(p)
    p.set_defaults(func=_cmd_stl)


def _add_errata(sub) -> None:
    """``errata``: show, check or write the registers."""
    p = sub.add_parser(
        "errata",
        help="the errata registers: show, --check, --write",
        description="The registers of every paper (data/errata/<paper>.csv) and the README "
        "block, generated from the audits.",
        epilog="examples:\n  python -m analysis errata --check\n"
        "  python -m analysis errata --paper grabber",
        formatter_class=_Help,
    )
    g = p.add_mutually_exclusive_group()
    g.add_argument("--check", action="store_true", help="exit 1 if a generated file is stale")
    g.add_argument("--write", action="store_true", help="rewrite the registers and README")
    p.add_argument(
        "--paper",
        help="only this paper's register (grabber, palletizer, picker, gr1); the README block "
        "lists every paper and is checked and written only without --paper",
    )
    p.set_defaults(func=_cmd_errata)


def _add_arms(sub) -> None:
    """``arms``: the arms and their parameters."""
    p = sub.add_parser(
        "arms",
        help="list the arms and their parameters",
        description="The arms described in data/arms/*.toml, with each parameter's value and "
        "whether it is printed in the paper or assumed.",
    )
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.set_defaults(func=_cmd_arms)


def _add_report(sub) -> None:
    """``report``: the report site."""
    p = sub.add_parser(
        "report",
        help="execute every notebook and build the report site",
        description="Execute every notebook fresh (the stored ones are not modified), collect "
        "the figures and build the report under --out.",
    )
    p.add_argument("--out", type=Path, default=Path("build/report"), help="output folder")
    p.add_argument("--notebooks", nargs="*", type=Path, help="only these notebooks")
    p.set_defaults(func=_cmd_report)


def build_parser() -> argparse.ArgumentParser:
    """The one parser of the command line."""
    parser = _Parser(
        prog=PROG,
        description="Audit of published robot-kinematics papers: kinematics, errata, PLC code.",
        epilog=EPILOG,
        formatter_class=_Help,
    )
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    _add_fk(sub)
    _add_ik(sub)
    _add_stl(sub)
    _add_errata(sub)
    _add_arms(sub)
    _add_report(sub)
    from analysis.app.cli_urdf import add_urdf  # the command's body: app/cli_urdf.py

    add_urdf(sub, _Help)
    return parser


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
    if isinstance(exc, UnreachableError) and target and max(abs(v) for v in target) <= 5:
        return " (coordinates are in mm: did you give metres?)"
    return ""


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    parser = build_parser()
    args = parser.parse_args(list(sys.argv[1:] if argv is None else argv))
    try:
        return int(args.func(args) or 0)
    except (ValueError, OSError) as exc:  # UsageError, UnreachableError, OutputError, ...
        if isinstance(exc, OSError):
            exc = ValueError(f"{getattr(exc, 'filename', '') or ''}: {exc.strerror or exc}")
        message = " ".join(str(exc).split()) + _hint(exc, args)
        if getattr(args, "json", False):
            doc = _error_doc(exc, args)
            doc["error"] = message
            print(json.dumps(doc))
        else:
            print(f"{PROG} {args.command}: error: {message}", file=sys.stderr)
        return 2
