"""``python -m analysis urdf``: an arm as URDF (:func:`analysis.kinematics.urdf.arm_urdf`).

``urdf --arm NAME|PATH [-o FILE] [--json]``: the arm by name (``data/arms``) or the path of a
description file (a user's own arm); the URDF on standard output, or written to ``FILE``
atomically (the old file stays whole on any error). With ``--json`` and ``-o`` a one-line
summary is printed instead of the sentence.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

__all__ = ["add_urdf", "cmd_urdf"]


def cmd_urdf(args: argparse.Namespace) -> int:
    """Write (or print) the URDF of ``--arm``."""
    from analysis.kinematics.urdf import arm_urdf

    if args.output is not None:
        from analysis.safe_io import check_paths, write_text_atomic

        check_paths(inputs=[], outputs=[args.output], make_parents=True)
    text = arm_urdf(args.arm)
    if args.output is None:
        print(text, end="")
        return 0
    write_text_atomic(args.output, text, make_parents=True)
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
        "--arm", default="grabber", help="arm name (list: arms) or a description file .toml"
    )
    p.add_argument("-o", "--output", type=Path, help="URDF file to write (default: stdout)")
    p.add_argument("--json", action="store_true", help="machine-readable summary and errors")
    p.set_defaults(func=cmd_urdf)
