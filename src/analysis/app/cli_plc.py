"""``python -m analysis stl-run``: run a PLC program offline, from a shell.

::

    python -m analysis stl-run ik.awl --dialect s7-200 --set VD0=100.0 --set VD4=100.0 \\
        --set VD8=600.0 --read VD100:DINT --read V112.0:BOOL --json
    {"values": {"VD100": 500, "V112.0": true}}

``--dialect s7-200`` runs STEP 7-Micro/WIN STL (the text form, or a bare listing) on the
project's S7-200 evaluator (:class:`analysis.plc.stl_eval.S7200`); ``--dialect s7-300`` runs
AWL on awlsim (:class:`analysis.plc.runner.AwlRunner`). The ``--set`` values are written
before the first scan (what an HMI wrote before the CPU went to RUN), then ``--scans N``
scans run (default 1: the first scan, SM0.1 / OB100 included), then the ``--read``
addresses are read. Types: BOOL, BYTE, INT, DINT, REAL (and WORD, DWORD).

A value's type follows the address and the value: ``V116.0=1`` is a BOOL, ``VB120=3`` a
BYTE, ``VW0=-5`` an INT, ``VD0=100.0`` a REAL, ``VD0=100`` a DINT, or as given with a
suffix (``VD0=100:REAL``). On the S7-200 an integer written to a double word the program
reads only as a REAL is refused (it would store the integer's bit pattern: the paper's
``MOVD 100, VD0``, 1.4E-43 as a REAL); ``VD0=100:DINT`` writes those bits on purpose.
``nan``, ``inf`` and ``-inf`` are accepted for REALs (to test a program's guards); JSON
prints them as the strings "NaN", "Infinity", "-Infinity".

Exit status 0, or 2 with one line on stderr (``--json``: ``{"error": ...}`` on stdout) for
a program the CPU would not run (the line, block, network and statement), a bad address or
value, or a CPU that went to STOP (a NaN in a REAL compare: where).
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
from pathlib import Path

from analysis.app.cli_common import (
    HelpFormatter,
    UsageError,
    add_arm_options,
    add_mkdir,
    arm_from_args,
    finite,
    to_json,
    waist_angle,
)
from analysis.app.cli_plc_values import parse_read, parse_set
from analysis.escape import terminal
from analysis.plc.dialects import DIALECTS, printer_class

__all__ = ["add_stl", "add_stl_run", "cmd_stl", "parse_read", "parse_set", "run"]


def _json_value(v):
    if isinstance(v, float) and not math.isfinite(v):
        return "NaN" if math.isnan(v) else ("Infinity" if v > 0 else "-Infinity")
    return v


def _show(v) -> str:
    if isinstance(v, bool):
        return "1" if v else "0"
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else str(v)
    return str(v)


class _Refused(ValueError):
    """The CPU went to STOP: what was read before is reported too."""

    def __init__(self, message: str, values: dict) -> None:
        super().__init__(message)
        self.values = values


def run(
    program: str,
    dialect: str,
    sets: list[str],
    reads: list[str],
    scans: int = 1,
    cpu: str | None = None,
    source: str = "program",
) -> dict:
    """Run ``program`` (text) and return ``{"values": {address: value}}``.

    Raises ValueError (one line) for anything a user got wrong, and :class:`_Refused` when
    the CPU went to STOP.
    """
    if scans < 1:
        raise ValueError(f"--scans {scans}: at least one scan")
    if scans > 1_000_000:
        raise ValueError(f"--scans {scans}: at most 1,000,000 scans")
    cls = printer_class(dialect)
    if cpu is not None:
        cpu = cls.session_cpu(cpu)  # --cpu 224 means the CPU 224
    writes = [parse_set(s, dialect) for s in sets]
    wanted = [parse_read(r, dialect) for r in reads]
    if not wanted:
        raise ValueError("nothing to read: give at least one --read ADDRESS:TYPE")
    try:
        session = cls.session(program, cpu=cpu, source=source)
    except ValueError as exc:  # the program does not parse: say what was expected
        raise ValueError(f"{exc}{_dialect_hint(program, dialect)}") from None
    for addr, typ, v, explicit in writes:
        session.write(typ, addr, v, explicit)
    session.scan(scans)
    values = {a: session.read(t, a) for a, t in wanted}
    if session.fault is not None:
        raise _Refused(f"the CPU went to STOP: {session.fault}", values)
    return {"values": values}


_LOOKS_LIKE = (  # (dialect, a sign of its text): the first that matches names the guess
    ("plcopen-xml", re.compile(r"\A\s*(<\?xml|<project\b)")),
    ("s7-200", re.compile(r"^ORGANIZATION_BLOCK \w+:OB\d|^Network \d", re.M)),
    ("s7-300", re.compile(r"^ORGANIZATION_BLOCK OB\s*\d|^NETWORK\s*$", re.M)),
    ("st", re.compile(r"\A\s*\(\*|^\s*(PROGRAM|FUNCTION_BLOCK|VAR)\b", re.M)),
)


def _dialect_hint(text: str, dialect: str) -> str:
    """After a program's parse error: the dialect ``stl-run`` expected and, where the text
    looks like another one, that one (an ST file given as S7-200 STL fails on its first
    ``(*``)."""
    from analysis.plc.dialects import printer_class

    hint = f" (--dialect {dialect} expects {printer_class(dialect).title}"
    guess = next((d for d, sign in _LOOKS_LIKE if sign.search(text[:20_000])), None)
    if guess is not None and guess != dialect:
        hint += f"; this text looks like {printer_class(guess).title}: --dialect {guess}"
    return hint + ")"


def _read_program(args: argparse.Namespace) -> tuple[str, str]:
    """The program text and its name: a regular file or standard input, read at most the
    dialect's limit (:attr:`~analysis.plc.printer.PlcPrinter.max_program_bytes`, enforced
    while reading: a device, a FIFO or an endless stream never takes more), decoded as
    UTF-8 or else ANSI (cp1252)."""
    from analysis.safe_io import read_bytes

    limit = printer_class(args.dialect).max_program_bytes
    if str(args.program) == "-":
        stream = getattr(sys.stdin, "buffer", sys.stdin)
        raw = stream.read(limit + 1)
        raw = raw.encode("utf-8") if isinstance(raw, str) else raw
        if len(raw) > limit:
            raise ValueError(f"the program on standard input is longer than {limit:,} bytes, "
                             "the most read of one")  # fmt: skip
        return _decode(raw, "standard input"), "<stdin>"
    path = Path(args.program)
    return _decode(read_bytes(path, limit, "program"), str(path)), path.name


def _decode(raw: bytes, path: str) -> str:
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        text = raw.decode("cp1252", errors="strict") if _cp1252(raw) else None
        if text is None:
            raise ValueError(f"{path}: neither UTF-8 nor ANSI (cp1252) text") from None
    return text


def _cmd_stl_run(args: argparse.Namespace) -> int:
    if args.dialect in ("st", "plcopen-xml"):
        from analysis.plc.st_engine import EngineMissing

        try:
            return _cmd_stl_run_st(args)
        except EngineMissing as exc:  # not built, or built from other sources: one line
            raise ValueError(str(exc)) from None
    for opt in ("scenario", "trace", "map", "program_name", "start"):
        if getattr(args, opt) is not None:
            raise ValueError(f"--{opt.replace('_name', '')} applies to --dialect st and "
                             "plcopen-xml")  # fmt: skip
    text, source = _read_program(args)
    try:
        out = run(text, args.dialect, args.set or [], args.read or [], args.scans, args.cpu, source)
    except _Refused as exc:
        if args.json:
            print(
                json.dumps(
                    {
                        "error": " ".join(str(exc).split()),
                        "values": {k: _json_value(v) for k, v in exc.values.items()},
                    }
                )
            )
            return 2
        raise
    except Exception as exc:
        if type(exc).__module__.startswith("awlsim"):  # awlsim's own parse/run errors
            raise ValueError(f"awlsim: {exc}{_dialect_hint(text, args.dialect)}") from None
        raise
    if args.json:
        print(json.dumps({"values": {k: _json_value(v) for k, v in out["values"].items()}}))
    else:
        for a, t in (parse_read(r, args.dialect) for r in args.read):
            print(f"{a} = {_show(out['values'][a])} ({t})")
    return 0


def _cmd_stl_run_st(args: argparse.Namespace) -> int:
    """``--dialect st|plcopen-xml`` (:mod:`analysis.plc.machine.offline`)."""
    from analysis.plc.machine import offline
    from analysis.safe_io import check_paths, output_stream, read_table

    if args.cpu is not None:
        raise ValueError(f"--cpu applies to --dialect s7-200 (a {args.dialect} program names "
                         "no CPU)")  # fmt: skip
    if (args.scenario is None) != (args.trace is None):
        raise ValueError("--scenario and --trace go together (a scenario writes a trace)")
    if args.scenario is not None and (args.set or args.read or args.scans != 1):
        raise ValueError("--set, --read and --scans are for one scan; a scenario sets its "
                         "variables itself")  # fmt: skip
    inputs = [p for p in (args.program, args.scenario, args.map) if p and str(p) != "-"]
    if args.trace is not None:
        if str(args.trace) == "-" and args.json:
            raise ValueError("--json prints the summary on stdout, which --trace - writes the "
                             "trace to: give a trace file, or leave out --json")  # fmt: skip
        check_paths(inputs=inputs, outputs=[args.trace], make_parents=args.mkdir)
    text, _ = _read_program(args)
    mapdoc = _map(args.map) if args.map else None
    source = offline.load_source(text, args.dialect)
    if args.scenario is None:
        out = offline.one_scan(source, args.set or [], args.read or [], mapdoc=mapdoc,
                               program=args.program_name, start=args.start)  # fmt: skip
        if args.json:
            print(json.dumps({"values": {k: _json_value(v) for k, v in out["values"].items()}}))
        else:
            for k, v in out["values"].items():
                print(f"{k} = {_show(v)} ({out['types'][k]})")
        return 0
    table = read_table(args.scenario, required=("t_s", "name", "value"))
    outs, axes, run, types = offline.run_trace(
        source, table, cycle_s=args.cycle_ms / 1000.0, settle_s=args.settle_s, mapdoc=mapdoc,
        program=args.program_name, start=args.start)  # fmt: skip
    # --trace -: the CSV on stdout (output_stream), the summary on stderr
    with output_stream(args.trace, newline="", make_parents=args.mkdir) as fh:
        fh.write(offline.trace_csv(outs, axes, run, types))
    summary = {"trace": str(args.trace), "cycles": len(run.t), "cycle_ms": args.cycle_ms,
               "axes": [a.name for a in axes], "outputs": outs,
               "start": [a.start for a in axes]}  # fmt: skip
    if args.json:
        print(json.dumps(summary))
    else:
        print(f"wrote {args.trace} ({len(run.t)} cycles of {args.cycle_ms:g} ms, "
              f"{len(axes)} axes, {len(outs)} outputs)",
              file=sys.stderr if str(args.trace) == "-" else sys.stdout)  # fmt: skip
    return 0


def _map(path) -> dict:
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise ValueError(f"cannot read {path}: {exc.strerror}") from None
    if len(raw) > 16 * 1024 * 1024:
        raise ValueError(f"{path}: {len(raw)} bytes; a MAP.json is at most 16 MiB")
    try:
        doc = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ValueError(f"{path}: not JSON ({exc})") from None
    if not isinstance(doc, dict):
        raise ValueError(f"{path}: not a MAP.json (an object is expected)")
    return doc


def _cp1252(raw: bytes) -> bool:
    try:
        raw.decode("cp1252")
    except UnicodeDecodeError:
        return False
    return True


def add_stl_run(sub, parser_class=None, formatter_class=None) -> None:
    """Register ``stl-run`` on the subparsers ``sub`` (called by :mod:`analysis.app.cli`)."""
    p = sub.add_parser(
        "stl-run",
        help="run a PLC program offline (S7-200 STL on the evaluator, S7-300 AWL on awlsim)",
        description="Run a PLC program file: write --set values, run --scans scans, print "
        "the --read values. S7-200 STL (STEP 7-Micro/WIN text form) runs on the project's "
        "S7-200 evaluator, S7-300 AWL on awlsim; IEC 61131-3 ST (and the ST in a PLCopen XML "
        "file) on pyplcopen's ST engine, one scan or, with --scenario, cycle by cycle with "
        "one simulated axis per joint into a --trace.",
        epilog="examples:\n"
        "  python -m analysis stl --dialect s7-200 -o ik.awl --map ik.json\n"
        "  python -m analysis stl-run ik.awl --dialect s7-200 --set VD0=100.0 --set VD4=100.0"
        " --set VD8=600.0 --read VD100:DINT --read V112.0:BOOL --json\n"
        "  python -m analysis stl-run pal.awl --dialect s7-300 --set MD0=250.0 --set MD4=0.0"
        " --set MD8=100.0 --read MD100:DINT\n"
        "  python -m analysis stl --dialect st --arm gr1 -o gr1.st --map gr1.json\n"
        "  python -m analysis stl-run gr1.st --dialect st --map gr1.json --scenario s.csv"
        " --trace t.csv   # s.csv: t_s,name,value (0,Enable,TRUE ...)\n"
        "  python -m analysis stl-run gr1.st --dialect st --map gr1.json --scenario s.csv"
        " --trace t.csv --start 20,-10,30,0,45   # the axes at these joint values (deg) at"
        " power-up",
        **({"formatter_class": formatter_class} if formatter_class else {}),
    )
    p.add_argument("program", help="program file (- reads standard input)")
    engines = {name: cls for name, cls in DIALECTS.items() if cls.engine}
    p.add_argument(
        "--dialect",
        required=True,
        choices=tuple(engines),
        help="; ".join(f"{name}: {cls.title} on {cls.engine}" for name, cls in engines.items()),
    )
    p.add_argument(
        "--set",
        action="append",
        metavar="ADDR=VALUE",
        help="write before the first scan "
        "(e.g. VD0=100.0, V20.0=1, VW4=-5, VD8=7:DINT); repeatable",
    )
    p.add_argument(
        "--read",
        action="append",
        metavar="ADDR:TYPE",
        help="read after the last scan "
        "(TYPE: BOOL, BYTE, INT, DINT, REAL, WORD, DWORD); repeatable",
    )
    p.add_argument("--scans", type=int, default=1, help="scans to run (default 1)")
    p.add_argument("--cpu", help="the target CPU, whose memory the program gets: S7-200 (CPU 221, "
                   "222, 224, 224XP, 226; default CPU 224) or S7-300 (CPU 312, 314, 315-2 DP, "
                   "317-2 DP; default CPU 315-2 DP)")  # fmt: skip
    p.add_argument("--json", action="store_true", help='print {"values": {...}}')
    g = p.add_argument_group("ST and PLCopen XML on the ST engine (--dialect st|plcopen-xml)")
    g.add_argument("--scenario", metavar="SCENARIO.csv",
                   help="t_s,name,value rows: set a program variable at that time; the program "
                   "runs cycle by cycle with one simulated axis per joint")  # fmt: skip
    g.add_argument("--trace", metavar="TRACE.csv", help="one row per cycle: t_s, q1..qN, "
                   "v1..vN, then every output, then plc_q1..plc_qN, what the PLC reads of "
                   "each axis (written atomically)")  # fmt: skip
    g.add_argument("--cycle-ms", type=float, default=4.0, help="cycle time (default 4 ms)")
    g.add_argument("--settle-s", type=float, default=2.0,
                   help="run on after the last row (default 2 s)")  # fmt: skip
    g.add_argument("--map", metavar="MAP.json", help="the program's map (stl --map): its "
                   "axes' limits and home positions, its outputs")  # fmt: skip
    g.add_argument("--program", dest="program_name", metavar="NAME",
                   help="the PROGRAM to run (default: the only one)")  # fmt: skip
    g.add_argument("--mkdir", action="store_true", help="create the trace's directory")
    g.add_argument("--start", metavar="WHERE", help="where the axes stand at power-up: "
                   "power-up (default: as a machine is switched on, a reference-switch axis "
                   "2 s of its homing approach off home, a set axis on its mark), home (every "
                   "axis on its home position, its encoder reading it), or one position "
                   "per axis in deg or mm, comma-separated (q1,q2,...); until homed each "
                   "encoder reads a stale count (the trace's plc_q1..plc_qN)")  # fmt: skip
    p.set_defaults(func=_cmd_stl_run)


# --- stl: the program and its map (moved here from analysis.app.cli) ---------------------
def cmd_stl(args: argparse.Namespace) -> int:
    from analysis.plc.dialects import DIALECTS
    from analysis.plc.generate import generate
    from analysis.plc.memmap import MemoryMap
    from analysis.safe_io import check_paths, write_many_atomic

    extra = [p for p in (args.tags, args.gvl) if p]  # the machine's tag table and GVL
    outputs = [args.output, *([args.map] if args.map else []), *extra]
    if str(args.output) == "-" and (args.json or str(args.map) == "-"):
        raise UsageError("-o - writes the program to stdout: --json and --map - cannot share it")
    if str(args.map) == "-" and args.json:
        raise UsageError("--map - writes the map to stdout: --json cannot share it")
    arm = arm_from_args(args)
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
        theta1_on_axis=waist_angle(args),
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
        print(to_json(doc))
    else:
        also = f" and {args.map}" if args.map else " (no MAP.json: --map FILE writes it)"
        print(
            terminal(
                f"wrote {args.output} ({args.dialect}, {arm.name} {doc['branch']}, "
                f"{doc['lines']} lines){also}"
            ),
            file=sys.stderr if "-" in (str(args.output), str(args.map)) else sys.stdout,
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


def add_stl(sub) -> None:
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
        formatter_class=HelpFormatter,
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
    p.add_argument(
        "--tags",
        type=Path,
        metavar="TAGS.xlsx",
        help="st, scl, plcopen-xml: "
        "the machine's signals as a TIA Portal PLC tag table (Excel, import in the "
        "PLC tag editor)",
    )
    p.add_argument(
        "--gvl",
        type=Path,
        metavar="GVL.st",
        help="st, scl, plcopen-xml: the machine's signals as a CODESYS global variable list",
    )
    p.add_argument(
        "--no-motion",
        action="store_true",
        help="omit the motion: the S7-200's PTO "
        "networks; st, scl, plcopen-xml: the machine program (the IK block alone)",
    )
    p.add_argument(
        "--theta1-on-axis", type=finite, metavar="DEG", help="waist angle on the base axis"
    )
    p.add_argument(
        "-o", "--output", required=True, type=Path, help="program file to write; - for stdout"
    )
    p.add_argument("--map", type=Path, help="MAP.json to write (optional)")
    p.add_argument("--json", action="store_true", help="machine-readable summary and errors")
    add_mkdir(p)
    add_arm_options(p)
    p.set_defaults(func=cmd_stl)
