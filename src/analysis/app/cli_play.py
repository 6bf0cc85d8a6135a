"""``python -m analysis play``: a machine run (the trace ``stl-run --trace`` writes) as a page
that plays it in a browser with no kernel and no network (issue 31 item 3).

``play TRACE.csv --arm NAME|PATH -o FILE.html [--frames K] [--title TEXT] [--mkdir] [--json]``:
the trace read strictly for the arm (:func:`analysis.app.arm3d_trace.read_trace`: refused in
one line naming row, column and limit), drawn by
:func:`~analysis.app.arm3d_trace.machine_run_figure` (the arm, its joint axes and tool frame
at K times, a time slider, play / pause, the outputs under the title) into one HTML file
with plotly.js inside (about 5 MB: the page opens offline, from a file, anywhere), written
atomically (never over the trace or the description; ``-o -`` writes it to standard output).

Why a command and not only the API: a run made from a shell (``stl-run``) is looked at from
a shell too, by someone who has no Jupyter open; the same figure as notebook 09's.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

__all__ = ["add_play", "cmd_play"]

MAX_FRAMES = 400
"""The most animation frames a page plays (:func:`analysis.app.arm3d.trajectory_figure`)."""


def cmd_play(args: argparse.Namespace) -> int:
    """Write the page that plays ``args.trace`` for ``--arm``."""
    from analysis.app.arm3d import CONFIG
    from analysis.app.arm3d_trace import machine_run_figure, read_trace
    from analysis.kinematics.arm import load_arm
    from analysis.safe_io import check_paths, write_text_atomic

    if not 2 <= args.frames <= MAX_FRAMES:
        raise ValueError(f"--frames {args.frames}: between 2 and {MAX_FRAMES}")
    if len(args.title) > 200:
        raise ValueError(f"--title has {len(args.title)} characters: at most 200")
    arm = load_arm(args.arm)
    to_stdout = str(args.output) == "-"
    if not to_stdout:  # never over the trace or the description; a directory on --mkdir
        check_paths(inputs=[args.trace, *arm.input_files], outputs=[args.output],
                    make_parents=args.mkdir)  # fmt: skip
    run = read_trace(args.trace, arm)
    title = args.title or f"{arm.description.title}: {Path(args.trace).name}"
    fig = machine_run_figure(arm, run, title=title, frames=args.frames)
    # plotly writes the figure as JSON inside a script (its own escaping of "</"), and the
    # title as text; plotly.js inlined: nothing is fetched when the page opens
    page = fig.to_html(include_plotlyjs=True, full_html=True, auto_play=False,
                       config=CONFIG, div_id="machine-run")  # fmt: skip
    if to_stdout:
        print(page, end="")
        return 0
    write_text_atomic(args.output, page, make_parents=args.mkdir)
    doc = {"html": str(args.output), "arm": arm.name, "cycles": len(run.t),
           "seconds": float(run.t[-1] - run.t[0]), "frames": len(fig.frames)}  # fmt: skip
    print(json.dumps(doc) if args.json else
          f"wrote {args.output} ({arm.name}: {len(run.t)} cycles, {doc['seconds']:.2f} s, "
          f"{len(fig.frames)} frames; opens offline in a browser)")  # fmt: skip
    return 0


def add_play(sub, formatter_class) -> None:
    """Register ``play`` on the command line's subparsers."""
    p = sub.add_parser(
        "play",
        help="a machine run (stl-run --trace) as a page that plays it",
        description="A machine run, the trace stl-run --trace writes, played in a 3D view: "
        "the arm with its joint axes and tool frame at K times spread over the run, a time "
        "slider, play and pause, and the program's outputs (Status, Busy, Done, Homed, the "
        "gripper) under the title. One HTML file with plotly.js inside: it opens offline.",
        epilog="examples:\n  python -m analysis play t.csv --arm gr1 -o run.html"
        "   # t.csv: from stl-run ... --trace t.csv",
        formatter_class=formatter_class,
    )
    p.add_argument(
        "trace",
        type=Path,
        metavar="TRACE.csv",
        help="the trace (stl-run --dialect st --scenario S.csv --trace TRACE.csv)",
    )
    p.add_argument(
        "--arm",
        default="grabber",
        help="the arm the run moved: name (list: "
        "arms) or description file; its joints must be the trace's",
    )
    p.add_argument(
        "-o", "--output", type=Path, required=True, help="HTML file to write (-: stdout)"
    )
    p.add_argument(
        "--frames",
        type=int,
        default=61,
        help=f"animation frames, spread over the run (2 .. {MAX_FRAMES}; default 61)",
    )
    p.add_argument("--title", default="", help="the page's title (default: arm and file)")
    p.add_argument("--mkdir", action="store_true", help="create the output's missing directories")
    p.add_argument("--json", action="store_true", help="machine-readable summary and errors")
    p.set_defaults(func=cmd_play)  # fmt: skip
