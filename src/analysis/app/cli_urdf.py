"""``python -m analysis urdf``: an arm as URDF (:func:`analysis.kinematics.urdf.arm_urdf`).

``urdf --arm NAME|PATH [-o FILE] [--mkdir] [--json]``: the arm by name (``data/arms``) or the
path of a description file (a user's own arm); the URDF on standard output (``-o -`` too), or
written to ``FILE`` atomically (the old file stays whole on any error; never over the
description or a table it read; a missing directory only with ``--mkdir``). With ``--json``
and ``-o`` a one-line summary is printed instead of the sentence.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

__all__ = ["add_urdf", "cmd_urdf"]


def cmd_urdf(args: argparse.Namespace) -> int:
    """Write (or print) the URDF of ``--arm``."""
    from analysis.kinematics.arm import load_arm
    from analysis.kinematics.urdf import arm_urdf
    from analysis.safe_io import check_paths, write_text_atomic

    arm = load_arm(args.arm)
    to_stdout = args.output is None or str(args.output) == "-"
    if not to_stdout:  # never over the description or a table it read; a directory on --mkdir
        check_paths(inputs=arm.input_files, outputs=[args.output], make_parents=args.mkdir)
    text = arm_urdf(arm)
    if to_stdout:
        print(text, end="")
        return 0
    write_text_atomic(args.output, text, make_parents=args.mkdir)
    joints = text.count("<joint ") - text.count('type="fixed"')
    doc = {"urdf": str(args.output), "arm": args.arm, "joints": joints}
    print(json.dumps(doc) if args.json else f"wrote {args.output} ({args.arm}, {joints} joints)")
    return 0


def add_urdf(sub, formatter_class) -> None:
    """Register ``urdf`` on the command line's subparsers."""
    p = sub.add_parser(
        "urdf",
        help="the arm as URDF (ROS, MoveIt, MuJoCo, Pinocchio)",
        description="The arm's kinematic tree as URDF (metres, radians): joints from the D-H "
        "rows or the screws, joint types and limits, every assumed value as a comment. A "
        "closed chain (the picker) is written as its open-chain equivalent with the closure "
        "stated.",
        epilog="examples:\n  python -m analysis urdf --arm gr1 -o gr1.urdf\n"
        "  python -m analysis urdf --arm ./my_arm.toml > my_arm.urdf",
        formatter_class=formatter_class,
    )
    p.add_argument(
        "--arm", default="grabber", help="arm name (list: arms) or a description file .toml "
        "(one that names a .py closed form runs that file's code)"
    )
    p.add_argument("-o", "--output", type=Path,
                   help="URDF file to write (default or -: stdout)")  # fmt: skip
    p.add_argument("--mkdir", action="store_true",
                   help="create the output's missing directories (without it a missing "
                   "directory is an error)")  # fmt: skip
    p.add_argument("--json", action="store_true", help="machine-readable summary and errors")
    p.set_defaults(func=cmd_urdf)
