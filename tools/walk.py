"""The walk from an arm description to its PLC program (issue 28: "files, stops, returns").

    .venv/bin/python tools/walk.py [--depth 4] [--arm PATH] [--dialect s7-300]

Runs ``python -m analysis stl --arm PATH --dialect D -o FILE`` in this process under
:func:`sys.setprofile` and records every call into a function of ``src/analysis`` made
beneath the command's function (``cmd_stl``; ``_cmd_stl`` before the CLI split), up to
``--depth`` calls below it (deeper calls are the math namespaces evaluating a closed form:
thousands of steps that say nothing about the structure), leaving out the file I/O
(``safe_io``) that every command shares. Consecutive
calls within one file are one *stop*; a stop in a file the walk had already left is a
*return*. The description is a fresh copy of ``data/arms/grabber.toml`` of the version
walked (so it is read, not taken from a cache): ``PYTHONPATH=<old checkout>/src`` walks an
old version with its own data.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
WATCH = {
    ("description.py", "load_description"): "description read (load_description)",
    ("__init__.py", "closed_form"): "closed form looked up by name",
    ("__init__.py", "lookup"): "closed form looked up by name",
    ("loader.py", "closed_form_of"): "closed form picked (loader)",
    ("arm.py", "__post_init__"): "Params built and probed",
    ("params.py", "__post_init__"): "Params built (numbers)",
    ("arm.py", "__init__"): "Arm built",
    ("model.py", "__init__"): "Arm built",
    ("__init__.py", "probe"): "closed form recorded (probe)",
    ("emit.py", "allocate"): "work area allocated",
    ("s7200.py", "allocate"): "work area allocated",
    ("memmap.py", "check_program"): "work area checked (check_program)",
    ("memmap.py", "check_end"): "bounds checked (check_end)",
}
"""Calls counted anywhere beneath the command: how often one fact is resolved."""
COUNTS: dict[str, int] = {}


def walk(argv: list[str], depth: int, calls_only: bool = False) -> list[tuple[str, str]]:
    import analysis

    pkg = str(Path(analysis.__file__).resolve().parent)
    from analysis.app.cli import main

    calls: list[tuple[str, str, object]] = []
    level = [0]
    start = [None]
    COUNTS.clear()

    def prof(frame, event, arg):
        if event == "call":
            level[0] += 1
            f = frame.f_code.co_filename
            key = (Path(f).name, frame.f_code.co_name)
            if start[0] is not None and key in WATCH:
                COUNTS[WATCH[key]] = COUNTS.get(WATCH[key], 0) + 1
            if start[0] is None and frame.f_code.co_name in ("_cmd_stl", "cmd_stl"):
                start[0] = level[0]
            inside = f.startswith(pkg) and "safe_io" not in f
            if start[0] is not None and inside and 0 < level[0] - start[0] <= depth:
                calls.append((str(Path(f).relative_to(pkg)), frame.f_code.co_name, frame.f_code))
        elif event == "return":
            level[0] -= 1
            if start[0] is not None and level[0] < start[0]:
                start[0] = None

    sys.setprofile(prof)
    try:
        with contextlib.redirect_stdout(io.StringIO()):
            rc = main(argv)
    finally:
        sys.setprofile(None)
    if rc:
        raise SystemExit(f"the command failed ({rc})")
    if calls_only:
        reads = _property_codes()
        return [(f, fn) for f, fn, code in calls if not fn.startswith("<") and code not in reads]
    return [(f, fn) for f, fn, _ in calls]


def _property_codes() -> set:
    """The code of every property getter of the package's classes (a read of a fact the
    object holds, not a step of the walk)."""
    import functools

    out = set()
    for name, mod in list(sys.modules.items()):
        if not name.startswith("analysis") or mod is None:
            continue
        for cls in vars(mod).values():
            if isinstance(cls, type) and cls.__module__ == name:
                for attr in vars(cls).values():
                    if isinstance(attr, property) and attr.fget is not None:
                        out.add(attr.fget.__code__)
                    elif isinstance(attr, functools.cached_property):
                        out.add(attr.func.__code__)
    return out


def stops(calls):
    out = []
    for f, fn in calls:
        if out and out[-1][0] == f:
            out[-1][1].append(fn)
        else:
            out.append((f, [fn]))
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--depth", type=int, default=4)
    ap.add_argument("--dialect", default="s7-300")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--calls-only", action="store_true",
                    help="leave out comprehensions and property reads (facts an object holds)")
    args = ap.parse_args(argv)
    import analysis

    data = Path(analysis.__file__).resolve().parents[2] / "data"  # the walked version's data
    folder = Path(tempfile.mkdtemp())
    shutil.copy(data / "arms" / "grabber.toml", folder / "walk.toml")
    shutil.copy(data / "table3.csv", folder / "table3.csv")
    cmd = ["stl", "--arm", str(folder / "walk.toml"), "--dialect", args.dialect,
           "-o", str(folder / "out.awl"), "--map", str(folder / "out.json")]  # fmt: skip
    try:
        s = stops(walk(cmd, args.depth, args.calls_only))
    finally:
        shutil.rmtree(folder)
    seen, returns = set(), 0
    for i, (f, _) in enumerate(s):
        if f in seen and s[i - 1][0] != f:
            returns += 1
        seen.add(f)
    doc = {"depth": args.depth, "calls_only": args.calls_only, "files": len(seen),
           "stops": len(s), "returns": returns,
           "counts": dict(sorted(COUNTS.items())),
           "walk": [f"{f}: {', '.join(dict.fromkeys(fns))}" for f, fns in s]}  # fmt: skip
    if args.json:
        print(json.dumps(doc, indent=1))
    else:
        import analysis

        where = Path(analysis.__file__).parent
        print(f"{where}, depth {args.depth}: {len(seen)} files, {len(s)} stops, {returns} returns")
        for k, v in doc["counts"].items():
            print(f"  {v} x {k}")
        for line in doc["walk"]:
            print("  " + line[:160])
    return 0


if __name__ == "__main__":
    sys.exit(main())
