"""``python -m analysis fk``, ``ik`` (one target or a CSV of them) and ``arms``: the commands
of the kinematics (:mod:`analysis.app.cli` builds the parser)."""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Sequence
from pathlib import Path

from analysis.app.cli_common import (
    PROG,
    HelpFormatter,
    Progress,
    UsageError,
    add_arm_options,
    add_mkdir,
    arm_from_args,
    emit,
    finite,
    to_json,
    tolerance,
    waist_angle,
    whole,
)
from analysis.escape import terminal

__all__ = ["add_arms", "add_fk", "add_ik", "cmd_arms", "cmd_fk", "cmd_ik"]


def cmd_fk(args: argparse.Namespace) -> int:

    from analysis.kinematics.arm import MAX_JOINT_DEG

    arm = arm_from_args(args)
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
    emit(args, doc, fk_sentence(doc))
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


def cmd_ik(args: argparse.Namespace) -> int:
    if args.input is not None or args.output is not None:
        if args.target:
            raise UsageError("give either a target X Y Z or --input/--output, not both")
        if args.input is None or args.output is None:
            raise UsageError("batch mode needs both --input IN.csv and --output OUT.csv")
        if args.json and str(args.output) == "-":
            raise UsageError("--json prints the summary on stdout, which --output - writes the "
                             "CSV to: give an output file, or leave out --json")  # fmt: skip
        from analysis.app.batch import solve_csv

        progress = Progress("ik")
        summary = solve_csv(
            arm_from_args(args),
            args.input,
            args.output,
            branch=args.branch,
            tol=args.tol,
            theta1_on_axis=waist_angle(args),
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
            + ("" if summary["pulses"] else " (no drive given: no pulse columns)")
        )
        if args.json:
            print(to_json(summary))
        else:
            print(text, file=sys.stderr)
        return 0
    arm = arm_from_args(args)
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


def _ik_single(args: argparse.Namespace, arm) -> int:

    from analysis.kinematics.joints import NO_DRIVE
    from analysis.kinematics.solution import OrientationError

    given = list(args.target)
    target = arm.from_user(given).tolist()
    names = arm.branch_names(args.branch or arm.branches[0])
    try:
        sols = arm.ik_all(target, theta1_on_axis=waist_angle(args), tol=args.tol, branches=names)
    except OrientationError as exc:
        # the library names the Python way to the nearest orientation; here, the command
        hint = arm.closed_form.PROJECTION_HINT
        raise UsageError(str(exc).replace(hint, _nearest_pose_hint(arm, target))) from None
    revolute = set(arm.joint_units) == {"rad"}
    out = []
    for name, theta in sols.items():
        values = (arm.joints_to_user(theta) + 0.0).tolist()  # degrees | mm; no "-0.00"
        sol = {"branch": name, "status": "ok"}
        if revolute:
            sol["theta_deg"] = values
        else:
            sol |= {"joint_values": values, "joint_units": list(arm.joint_user_units)}
        # one shape: "pulses" is the drive's whole counts, or null where no drive is given
        out.append({**sol, "pulses": arm.pulses(theta).tolist() if arm.has_drive else None})
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
        pul = ("pulses = (" + ", ".join(str(c) for c in s["pulses"]) + ")" if arm.has_drive
               else f"pulses: {NO_DRIVE}")  # fmt: skip
        if revolute:
            ang = "theta = (" + ", ".join(f"{t:.2f}" for t in s["theta_deg"]) + ") deg"
        else:
            ang = "q = (" + ", ".join(
                f"{t:.2f} {u}" for t, u in zip(s["joint_values"], arm.joint_user_units,
                                               strict=True)) + ")"  # fmt: skip
        lines.append(f"  {s['branch']:<10} {ang}   {pul}")
    for m in missing:
        lines.append(f"  {m['branch']:<10} no solution: {m['status']} ({m['reason']})")
    if len(names) > 1:
        lines.append(
            f"{arm.name} has {len(arm.branches)} branches; {len(out)} of the {len(names)} "
            f"requested solve this target"
        )
    # one shape for every arm and --branch: the arm, each requested branch with its status
    doc = {"arm": arm.name, "target": given, "reachable": True, "solutions": out,
           "branches": len(arm.branches), "missing": missing}  # fmt: skip
    emit(args, doc, "\n".join(lines))
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
    one = arm.solve(target, missing, tol=args.tol, theta1_on_axis=waist_angle(args))
    free = arm.solve(target, missing, tol=args.tol, theta1_on_axis=waist_angle(args), limits=False)
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


def cmd_arms(args: argparse.Namespace) -> int:
    from analysis.kinematics.catalog import describe_arm, list_arms

    if args.toml:
        if len(args.arm) != 1 or args.json:
            raise UsageError("--toml prints one arm's description: give one --arm (no --json)")
        from analysis.kinematics.description import description_toml

        print(description_toml(args.arm[0]), end="")
        return 0
    docs = [describe_arm(a) for a in args.arm] if args.arm else list_arms()
    if args.json:
        print(to_json(docs))
        return 0
    for d in docs:
        if "error" in d:
            print(terminal(f"{d['name']:<11} not loadable: {d['error']}"))
            continue
        params = ", ".join(
            f"{k} = {v['value']:g} {v['unit']}" + (" (assumed)" if v["status"] == "assumed" else "")
            for k, v in d["parameters"].items()
        )
        drive = ", no drive given" if d.get("pulses_per_rev", ()) is None else ""
        print(terminal(f"{d['name']:<11} {d['title']} ({len(d['joints'])} joints{drive}): "
                       f"{params}"))  # fmt: skip
    return 0


def add_fk(sub) -> None:
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
        formatter_class=HelpFormatter,
    )
    p.add_argument(
        "angles", nargs="+", type=finite, metavar="VALUE",
        help="joint values [deg, or mm for a prismatic joint] (a note on stderr when angles "
        "look like radians)",
    )  # fmt: skip
    p.add_argument("--json", action="store_true", help="machine-readable output")
    add_arm_options(p)
    p.set_defaults(func=cmd_fk)


def add_ik(sub) -> None:
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
        "  python -m analysis ik 336.804 194.454 -4.425 -60 80 90 --arm gr1 --branch all\n"
        "  python -m analysis ik --input targets.csv --output solved.csv --branch all\n"
        "  python -m analysis ik -100 100 600               (a leading minus needs no --)",
        formatter_class=HelpFormatter,
    )
    p.add_argument(
        "target",
        nargs="*",
        type=finite,
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
        "--chunk-rows", type=whole, default=100_000, help="batch: rows per chunk (memory bound)"
    )
    p.add_argument(
        "--strict", action="store_true",
        help="batch: stop at the first bad row (default: mark it 'invalid' and go on)",
    )  # fmt: skip
    p.add_argument(
        "--delimiter", choices=(",", ";", "\t", "|"), metavar="CHAR",
        help="batch: the input's field separator (default: sniffed from the header: , ; tab |)",
    )  # fmt: skip
    add_mkdir(p)
    p.add_argument(
        "--theta1-on-axis",
        type=finite,
        metavar="DEG",
        help="waist angle for targets on the base axis (else they are refused)",
    )
    p.add_argument(
        "--tol",
        type=tolerance,
        default=1e-6,
        help="distance tolerance [mm] at the reach boundary and the base axis, 0 .. 1 "
        "(default 1e-06)",
    )
    add_arm_options(p)
    p.set_defaults(func=cmd_ik)


def add_arms(sub) -> None:
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
    p.add_argument("--toml", action="store_true",
                   help="print the --arm's description as TOML (a URDF's: the description it "
                   "is converted to, without a drive, which a URDF does not give: add "
                   "pulses_per_rev to each [[joints]] entry for a PLC program)")  # fmt: skip
    p.set_defaults(func=cmd_arms)
