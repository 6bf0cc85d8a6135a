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
import json
import math
import re
import signal
import sys
import time
from collections.abc import Sequence
from pathlib import Path

from analysis.escape import terminal

__all__ = ["build_parser", "main"]

PROG = "python -m analysis"
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


class UsageError(ValueError):
    """Bad input from the command line: reported on one line, exit status 2."""


# argparse takes an argument that starts with "-" for an option unless it looks like a
# negative number, and its test knows no exponent: "-1e3" was "unrecognized arguments". Here
# anything that starts like a number (a digit or a point after the minus, or inf/nan) is a
# value; analysis.validate then decides whether it is one. No option starts that way.
_NEGATIVE_NUMBER = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message: str) -> None:  # one line on stderr, exit 2 (argparse's code)
        self.exit(2, f"{self.prog}: error: {message}\n")


class _Help(argparse.RawDescriptionHelpFormatter):
    pass


def _finite(text: str) -> float:
    """A number given on the command line (:func:`analysis.validate.parse_real`: ASCII
    digits, no underscores, finite)."""
    from analysis.validate import InvalidValue, parse_real

    try:
        return parse_real(text)
    except InvalidValue as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _tolerance(text: str) -> float:
    from analysis.validate import InvalidValue, tolerance_mm

    try:
        return tolerance_mm(_finite(text), "--tol")
    except InvalidValue as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _whole(text: str) -> int:
    value = _finite(text)
    if value != int(value):
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number")
    return int(value)


def _json(doc) -> str:
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

    return json.dumps(clean(doc), allow_nan=False, ensure_ascii=False)


class _Progress:
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


def _arm(args: argparse.Namespace):
    """The arm of ``--arm`` (and ``--params``: a Table 3 file for the paper's arm)."""
    from analysis.kinematics.arm import load_arm

    if args.params:
        if args.arm != "grabber":
            raise UsageError("--params takes a Table 3 file: it applies to the paper's arm only")
        from analysis.kinematics.params import load_table3

        table3 = load_table3(args.params)
        return load_arm("grabber").with_(**table3, pulses_per_rev=table3.pulses_per_rev)
    return load_arm(args.arm)


def _common(p: argparse.ArgumentParser) -> None:
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


def _emit(args, doc: dict, text: str) -> None:
    print(_json(doc) if getattr(args, "json", False) else text)


def _mkdir_flag(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--mkdir",
        action="store_true",
        help="create the output's missing directories (without it a missing directory is an "
        "error; they are removed again if the command fails)",
    )


# --- fk --------------------------------------------------------------------------------------
def _cmd_fk(args: argparse.Namespace) -> int:

    from analysis.kinematics.arm import MAX_JOINT_DEG

    arm = _arm(args)
    units = arm.joint_user_units
    if len(args.angles) != arm.n_joints:
        what = (
            "angles in degrees"
            if set(units) == {"deg"}
            else "values ("
            + ", ".join(f"{n} [{u}]" for n, u in zip(arm.joint_names, units, strict=True))
            + ")"
        )
        raise UsageError(
            f"{arm.name} has {arm.n_joints} joints: give {arm.n_joints} {what}, "
            f"got {len(args.angles)}"
        )  # fmt: skip
    for j, (a, u) in enumerate(zip(args.angles, units, strict=True), 1):
        if u == "deg" and abs(a) > MAX_JOINT_DEG:
            raise UsageError(
                f"theta{j} = {a:g} deg is beyond +-{MAX_JOINT_DEG:g} deg (ten turns): "
                "angles are in degrees"
            )
    if set(units) == {"deg"}:
        hint = _radians_hint(args.angles)
        if hint:
            print(f"{PROG} fk: note: {hint}", file=sys.stderr)
    from analysis.kinematics.pose import fk_document, fk_sentence

    doc = fk_document(arm, args.angles)  # the full pose: the explorer's FK line shows it too
    _emit(args, doc, fk_sentence(doc))
    return 0


def _radians_hint(angles: Sequence[float]) -> str:
    """A hint when joint angles look like radians typed where degrees belong (as ``ik``
    hints at metres): every angle within +-pi, and some with a fractional part."""
    if angles and all(abs(a) <= math.pi + 1e-9 for a in angles) and any(
        a != round(a) for a in angles
    ):
        deg = ", ".join(f"{math.degrees(a):.2f}" for a in angles)
        return (
            "the angles are taken in degrees; all lie within +-pi, as radians would: "
            f"in degrees those are ({deg})"
        )
    return ""


# --- ik ------------------------------------------------------------------------------------------
def _cmd_ik(args: argparse.Namespace) -> int:
    if args.input is not None or args.output is not None:
        if args.target:
            raise UsageError("give either a target X Y Z or --input/--output, not both")
        if args.input is None or args.output is None:
            raise UsageError("batch mode needs both --input IN.csv and --output OUT.csv")
        if args.json and str(args.output) == "-":
            raise UsageError("--json prints the summary on stdout, which --output - writes the "
                             "CSV to: give an output file, or leave out --json")  # fmt: skip
        from analysis.app.batch import solve_csv

        progress = _Progress("ik")
        summary = solve_csv(
            _arm(args),
            args.input,
            args.output,
            branch=args.branch,
            tol=args.tol,
            theta1_on_axis=_axis(args),
            chunk_rows=args.chunk_rows,
            params=args.params,
            strict=args.strict,
            delimiter=args.delimiter,
            make_dirs=args.mkdir,
            progress=lambda n: progress.update(f"{n:,} targets"),
        )
        progress.done()
        text = (
            f"{summary['targets']} targets, {summary['solved']} solved"
            + "".join(f", {n} {s}" for s, n in summary["status"].items() if s != "ok")
            + f" -> {summary['output']}"
        )
        if args.json:
            print(_json(summary))
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

    from analysis.audit.papers.gr1.thesis import project_orientation

    pose, turned = project_orientation(arm, np.asarray(target, dtype=float))
    words = [f"{v:g}" for v in pose[:3]] + [f"{math.degrees(v):.3f}" for v in pose[3:]]
    return (
        f"the nearest orientation it can take there is {math.degrees(float(turned)):.3f} deg "
        f"away: python -m analysis ik {' '.join(words)} --arm {arm.name} --branch all"
    )


def _axis(args) -> float | None:
    """The waist angle on the base axis [rad]: the degrees given, reduced exactly to
    (-180, 180] first (:func:`analysis.validate.reduce_deg`; 3600 deg is 0 deg)."""
    if args.theta1_on_axis is None:
        return None
    from analysis.validate import reduce_deg

    return math.radians(reduce_deg(args.theta1_on_axis))


def _ik_single(args: argparse.Namespace, arm) -> int:

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
    revolute = set(arm.joint_units) == {"rad"}
    out = []
    for name, theta in sols.items():
        values = (arm.joints_to_user(theta) + 0.0).tolist()  # degrees | mm; no "-0.00"
        sol = {"branch": name}
        if revolute:
            sol["theta_deg"] = values
        else:
            sol |= {"joint_values": values, "joint_units": list(arm.joint_user_units)}
        out.append({**sol, "pulses": arm.pulses(theta).tolist()})
    missing = _missing_branches(arm, target, names, sols, args)
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
        pul = ", ".join(str(c) for c in s["pulses"])
        if revolute:
            ang = "theta = (" + ", ".join(f"{t:.2f}" for t in s["theta_deg"]) + ") deg"
        else:
            ang = "q = (" + ", ".join(
                f"{t:.2f} {u}" for t, u in zip(s["joint_values"], arm.joint_user_units,
                                               strict=True)) + ")"  # fmt: skip
        lines.append(f"  {s['branch']:<10} {ang}   pulses = ({pul})")
    for m in missing:
        lines.append(f"  {m['branch']:<10} no solution: {m['status']} ({m['reason']})")
    if len(names) > 1:
        lines.append(
            f"{arm.name} has {len(arm.branches)} branches; {len(out)} of the {len(names)} "
            f"requested solve this target"
        )
    doc = {"target": given, "reachable": True, "solutions": out}
    if arm.name != "grabber":
        doc["arm"] = arm.name
    if len(names) > 1:
        doc["branches"] = len(arm.branches)
        doc["missing"] = missing
    _emit(args, doc, "\n".join(lines))
    return 0


def _missing_branches(arm, target, names, sols, args) -> list[dict]:
    """Why each requested branch without a solution has none: its own status
    (:attr:`IKSolutions.branch_status`: the target's refusal, the branch's own, such as the
    GR-1's back wrist out of reach, or the joint limits) with the closed form's reason, or
    for the joint limits the angles that cross them."""
    import numpy as np

    from analysis.kinematics.status import Status

    missing = [b for b in names if b not in sols]
    if not missing:
        return []
    one = arm.solve(target, missing, tol=args.tol, theta1_on_axis=_axis(args))
    free = arm.solve(target, missing, tol=args.tol, theta1_on_axis=_axis(args), limits=False)
    out = []
    for k, b in enumerate(missing):
        status = Status(int(one.branch_status[k]))
        if status == Status.JOINT_LIMITS:
            crossed = []
            for q, lim, name, unit in zip(
                free.theta[k], arm.limits, arm.joint_names, arm.joint_units, strict=True
            ):
                if lim is not None and not (lim[0] <= q <= lim[1]):
                    if unit == "rad":
                        crossed.append(f"{name} = {np.degrees(q):.2f} deg outside "
                                       f"[{np.degrees(lim[0]):g}, {np.degrees(lim[1]):g}] deg")
                    else:
                        crossed.append(f"{name} = {q:.3f} mm outside [{lim[0]:g}, "
                                       f"{lim[1]:g}] mm")  # fmt: skip
            reason = "; ".join(crossed) or "outside the joint limits"
        else:
            message, _ = arm.closed_form.refusal(
                status, target, arm.params, tol=args.tol, distance=float(one.outside_mm)
            )
            reason = " ".join(message.split())
        out.append({"branch": b, "status": status.text, "reason": reason})
    return out


# --- stl ------------------------------------------------------------------------------------------
def _cmd_stl(args: argparse.Namespace) -> int:
    from analysis.plc.dialects import DIALECTS
    from analysis.plc.generate import generate
    from analysis.plc.memmap import MemoryMap
    from analysis.safe_io import check_paths, write_many_atomic

    extra = [p for p in (args.tags, args.gvl) if p]  # the machine's tag table and GVL
    outputs = [args.output, *([args.map] if args.map else []), *extra]
    if str(args.output) == "-" and (args.json or str(args.map) == "-"):
        raise UsageError("-o - writes the program to stdout: --json and --map - cannot share it")
    arm = _arm(args)
    check_paths(  # no output may be an input: the description, its tables, --params, --layout
        inputs=[*arm.input_files, *(p for p in (args.layout, args.params) if p)],
        outputs=outputs,
        make_parents=args.mkdir,
    )
    mmap = _layout(args.layout, MemoryMap) if args.layout else None
    cpu = None
    if args.cpu is not None:
        from analysis.plc.memmap import cpu_name

        if not DIALECTS[args.dialect].addresses:
            raise UsageError(
                f"--cpu applies to --dialect s7-200 and s7-300 (a {args.dialect} program "
                "names no addresses)"
            )
        cpu = cpu_name(args.cpu, args.dialect)  # checked at generation: the map's areas
    text, mjson = generate(
        arm,
        args.dialect,
        args.branch,
        args.trig,
        mmap,
        motion=not args.no_motion,
        theta1_on_axis=_axis(args),
        cpu=cpu,
    )
    files = {p: c for p, c in ((args.output, text), (args.map, mjson)) if p and str(p) != "-"}
    if extra:
        from analysis.plc.machine.tags import machine_files

        files.update(machine_files(arm, args.dialect, args.no_motion, args.tags, args.gvl))
    if files:
        write_many_atomic(files, newline="", make_parents=args.mkdir)
    for p, c in ((args.output, text), (args.map, mjson)):
        if p is not None and str(p) == "-":
            sys.stdout.write(c)
            sys.stdout.flush()
    doc = {
        "program": str(args.output),
        "map": None if args.map is None else str(args.map),
        "dialect": args.dialect,
        "arm": arm.name,
        "branch": args.branch or arm.branches[0],
        "lines": text.count("\n"),
    }
    if DIALECTS[args.dialect].addresses:
        doc["cpu"] = json.loads(mjson)["target_cpu"]["name"]
    if args.json:
        print(_json(doc))
    else:
        also = f" and {args.map}" if args.map else " (no MAP.json: --map FILE writes it)"
        print(
            terminal(
                f"wrote {args.output} ({args.dialect}, {arm.name} {doc['branch']}, "
                f"{doc['lines']} lines){also}"
            ),
            file=sys.stderr if str(args.output) == "-" else sys.stdout,
        )
    return 0


def _layout(path: Path, MemoryMap):
    """``--layout L.json``, checked at the boundary: a JSON object, read by the memory map's
    own parser; anything it cannot take is one line naming the file."""
    try:
        doc = json.loads(Path(path).read_text(encoding="utf-8"))
    except json.JSONDecodeError as exc:
        raise UsageError(f"{path}: not valid JSON ({exc})") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise UsageError(f"cannot read {path}: {getattr(exc, 'strerror', None) or exc}") from None
    if not isinstance(doc, dict):
        raise UsageError(
            f"{path}: a memory map is a JSON object (MAP.json format), not {type(doc).__name__}"
        )
    try:
        return MemoryMap.from_json(path)
    except (KeyError, TypeError, AttributeError, IndexError) as exc:
        raise UsageError(f"{path}: not a memory map ({type(exc).__name__}: {exc})") from None
    except ValueError as exc:
        raise UsageError(f"{path}: {exc}" if str(path) not in str(exc) else str(exc)) from None


# --- errata ------------------------------------------------------------------------------------
def _cmd_errata(args: argparse.Namespace) -> int:
    from analysis.audit import register as reg

    papers = [args.paper] if args.paper else None
    if args.paper and args.paper not in reg.available():
        reg.register(args.paper)  # raises, naming the papers
    progress = _Progress("errata")
    # --check is answered from the cache of the generated files' digests when no input changed
    # (under 1 s); reg.check builds the registers only when it must
    if not (args.check and reg.check_is_cached(papers)):
        for i, paper in enumerate(papers or reg.available(), 1):  # built once, cached
            progress.update(f"building the register of {paper} ({i}/{len(papers or reg.available())})")  # noqa: E501
            if args.write or args.check or not args.json:
                reg.register(paper)
    progress.done()
    if args.write:
        changed = reg.write_all(papers)
        if args.json:
            print(_json({"changed": changed}))
        else:
            print("\n".join(changed) or "up to date")
        return 0
    if args.check:
        stale = reg.check(papers)
        if args.json:
            print(_json({"up_to_date": not stale, "stale": stale}))
        elif stale:
            print(f"out of date: {', '.join(stale)} (run: {PROG} errata --write)", file=sys.stderr)
        else:
            print("up to date")
        return 1 if stale else 0
    if args.json:
        print(_json({p: reg.load(p).to_dict(orient="records") for p in papers or reg.available()}))
        return 0
    print(reg.render_markdown(papers), end="")
    return 0


# --- arms ----------------------------------------------------------------------------------------
def _cmd_arms(args: argparse.Namespace) -> int:
    from analysis.kinematics.catalog import describe_arm, list_arms

    docs = [describe_arm(a) for a in args.arm] if args.arm else list_arms()
    if args.json:
        print(_json(docs))
        return 0
    for d in docs:
        if "error" in d:
            print(terminal(f"{d['name']:<11} not loadable: {d['error']}"))
            continue
        params = ", ".join(
            f"{k} = {v['value']:g} {v['unit']}" + (" (assumed)" if v["status"] == "assumed" else "")
            for k, v in d["parameters"].items()
        )
        print(terminal(f"{d['name']:<11} {d['title']} ({len(d['joints'])} joints): {params}"))
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
        help="joint values (deg | mm) -> the tool's full pose",
        description="Forward kinematics from the arm's chain (its D-H rows, any serial chain; "
        "a closed chain's closed form): the tool point [mm] and orientation (RPY [deg] in the "
        "convention ik takes; --json adds the rotation matrix), every joint (a closed "
        "chain's passive ones too: joint_states) and the target ik takes for this pose.",
        epilog="examples:\n  python -m analysis fk 45 10.21 -155.13 --json\n"
        "  python -m analysis fk 30 40 -60 -70 10 --arm gr1",
        formatter_class=_Help,
    )
    p.add_argument(
        "angles", nargs="+", type=_finite, metavar="VALUE",
        help="joint values [deg, or mm for a prismatic joint] (a note on stderr when angles "
        "look like radians)",
    )  # fmt: skip
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
        "ok, out-of-reach, inside-reach, base-axis, joint-limits, invalid; a row whose numbers "
        "are bad is 'invalid', its reason in the last column, and the batch goes on: --strict "
        "stops at the first). '-' reads standard input or writes standard output.",
        epilog="examples:\n  python -m analysis ik 100 100 600 --json\n"
        "  python -m analysis ik 0 0 900 --theta1-on-axis 30\n"
        "  python -m analysis ik 300 100 50 0 90 10 --arm gr1 --branch all\n"
        "  python -m analysis ik --input targets.csv --output solved.csv --branch all\n"
        "  python -m analysis ik -1e3 0 600                 (a leading minus needs no --)",
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
        "gamma_deg); - for stdin",
    )
    p.add_argument(
        "--output", type=Path, help="batch: output CSV (one row per target, branch); - for stdout"
    )
    p.add_argument(
        "--chunk-rows", type=_whole, default=100_000, help="batch: rows per chunk (memory bound)"
    )
    p.add_argument(
        "--strict", action="store_true",
        help="batch: stop at the first bad row (default: mark it 'invalid' and go on)",
    )  # fmt: skip
    p.add_argument(
        "--delimiter", choices=(",", ";", "\t", "|"), metavar="CHAR",
        help="batch: the input's field separator (default: sniffed from the header: , ; tab |)",
    )  # fmt: skip
    _mkdir_flag(p)
    p.add_argument(
        "--theta1-on-axis",
        type=_finite,
        metavar="DEG",
        help="waist angle for targets on the base axis (else they are refused)",
    )
    p.add_argument(
        "--tol",
        type=_tolerance,
        default=1e-6,
        help="distance tolerance [mm] at the reach boundary and the base axis, 0 .. 1 "
        "(default 1e-06)",
    )
    _common(p)
    p.set_defaults(func=_cmd_ik)


def _add_stl(sub) -> None:
    """``stl``: the PLC program and its memory map (the dialects: the registry's)."""
    from analysis.plc.dialects import DIALECTS

    p = sub.add_parser(
        "stl",
        help="generate the PLC program (S7-200 STL, S7-300 AWL, ST, SCL, PLCopen XML) and its map",
        description="Generate the corrected IK program for a Siemens PLC, from the arm's "
        "closed form (the paper's Figures 3-6 as they should be), and MAP.json naming every "
        "input and output address.",
        epilog="examples:\n  python -m analysis stl --dialect s7-200 -o ik.awl --map ik_map.json\n"
        "  python -m analysis stl --dialect s7-300 --arm palletizer -o pal.awl --map pal.json\n"
        "  python -m analysis stl --dialect st --arm gr1 -o gr1.st --map gr1.json\n"
        "  python -m analysis stl --dialect s7-300 -o -          the program on stdout",
        formatter_class=_Help,
    )
    p.add_argument(
        "--dialect",
        required=True,
        choices=tuple(DIALECTS),
        help="; ".join(f"{name}: {cls.title}" for name, cls in DIALECTS.items()),
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
    p.add_argument(
        "--cpu",
        metavar="NAME",
        help="S7 target CPU whose memory limits the program and MAP.json are checked "
        "against (S7-200: CPU 221, 222, 224, 224XP, 226, default CPU 224; S7-300: CPU 312, "
        "314, 315-2 DP, 317-2 DP, default CPU 315-2 DP; e.g. --cpu 224XP)",
    )
    p.add_argument("--tags", type=Path, metavar="TAGS.xlsx", help="st, scl, plcopen-xml: "
                   "the machine's signals as a TIA Portal PLC tag table (Excel, import in the "
                   "PLC tag editor)")
    p.add_argument("--gvl", type=Path, metavar="GVL.st", help="st, scl, plcopen-xml: the "
                   "machine's signals as a CODESYS global variable list")
    p.add_argument("--no-motion", action="store_true", help="omit the motion: the S7-200's PTO "
                   "networks; st, scl, plcopen-xml: the machine program (the IK block alone)")
    p.add_argument(
        "--theta1-on-axis", type=_finite, metavar="DEG", help="waist angle on the base axis"
    )
    p.add_argument(
        "-o", "--output", required=True, type=Path, help="program file to write; - for stdout"
    )
    p.add_argument("--map", type=Path, help="MAP.json to write (optional)")
    p.add_argument("--json", action="store_true", help="machine-readable summary and errors")
    _mkdir_flag(p)
    _common(p)
    p.set_defaults(func=_cmd_stl)


def _add_errata(sub) -> None:
    """``errata``: show, check or write the registers."""
    p = sub.add_parser(
        "errata",
        help="the errata registers: show, --check, --write",
        description="The registers of every paper (data/errata/<paper>.csv) and the README "
        "block, generated from data/registers/<paper>.toml.",
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
    p.add_argument(
        "--json", action="store_true",
        help="machine-readable: the register rows, or {up_to_date, stale} with --check, "
        "{changed} with --write",
    )  # fmt: skip
    p.set_defaults(func=_cmd_errata)


def _add_arms(sub) -> None:
    """``arms``: the arms and their parameters."""
    p = sub.add_parser(
        "arms",
        help="list the arms and their parameters",
        description="The arms described in data/arms/*.toml (or the description files given "
        "with --arm), with each parameter's value and whether it is printed in the paper or "
        "assumed; a description that does not load is listed with the reason.",
    )
    p.add_argument("--arm", action="append", metavar="NAME|PATH", default=[],
                   help="list this arm (a name or a description file; repeatable) instead; "
                   "a description that names a .py closed form runs that file's code")  # fmt: skip
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
    from analysis.app.cli_plc import add_stl_run
    parser = _Parser(
        prog=PROG,
        description="Audit of published robot-kinematics papers: kinematics, errata, PLC code.",
        epilog=EPILOG,
        formatter_class=_Help,
    )
    parser.add_argument("--version", action=_VersionAction, help="show the version and exit")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    _add_fk(sub)
    _add_ik(sub)
    _add_stl(sub)
    add_stl_run(sub, formatter_class=_Help)  # analysis.app.cli_plc (issue 22)
    _add_errata(sub)
    _add_arms(sub)
    _add_report(sub)
    from analysis.app.cli_urdf import add_urdf  # the command's body: app/cli_urdf.py

    add_urdf(sub, _Help)
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
            print(_json(doc))
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


def _broken_pipe() -> int:
    """The reader of stdout went away (``| head``): end quietly, as a shell tool does."""
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # pragma: no cover
        pass
    return 128 + signal.SIGPIPE
