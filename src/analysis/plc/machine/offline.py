"""``stl-run --dialect st|plcopen-xml``: run an ST program (or the ST inside a PLCopen XML
file) on the ST engine, offline (issue 29 item 3, a contract).

- With ``--scenario S.csv`` (header ``t_s,name,value``; each row sets a program variable at
  that time, a BOOL as TRUE/FALSE, a number by :func:`analysis.validate.number_problem`'s
  rule, a REAL also ``nan``, ``inf``, ``-inf`` on purpose): the program runs cycle by cycle
  (``cycle_s``) until the last row's time plus ``settle_s``, with one simulated axis per
  joint (MAP.json's ``machine.axes``: limits, software limits, a ``switch`` axis' reference
  switch at its home position) or, without a map, per AXIS_REF variable of the program (its
  switch at 0); the trace has one row per cycle: ``t_s``, ``q1..qN`` (deg or mm), ``v1..vN``
  (per second), then every output of the program by name (MAP.json's ``machine.outputs``;
  without a map, every scalar variable the PROGRAM declares itself, not those of the block
  instances inside it, that the scenario does not write), then ``plc_q1..plc_qN``: what the
  PLC reads (each axis' encoder: a stale count until the axis is homed).
- Where the axes stand at power-up (``start``, :func:`parse_start`): ``power-up`` (the
  default) as a machine is switched on, as the scenarios' plant has it
  (:func:`analysis.plc.machine.plant.power_up_axis`: a ``switch`` axis two seconds of its
  homing approach off home, a ``set`` axis on its mark, every encoder reading a stale count),
  so Home does real work; ``home``: every axis on its home position, read exactly (a machine
  already homed, as ``stl-run`` ran before the option); or one physical position per axis
  in joint units (deg or mm, comma-separated), each encoder again stale. Without a map
  nothing is known of the axes' limits or homes: ``power-up`` and ``home`` put them at 0.
  ``AxisN.PowerOK`` (FALSE, then TRUE) is the simulated drive's power feedback: losing it is
  an axis error (:data:`analysis.plc.st_engine.POWER_OK`).
- Without a scenario: one scan, ``--set NAME=VALUE`` before it, ``--read NAME`` after it.
- A source without a PROGRAM (the IK block on its own) runs through a generated PROGRAM that
  calls its function block with its inputs (a rising edge of its Execute in every scan) and
  copies its outputs (today's IK sweep).

Every user error raises ValueError with one line: an unknown variable, a time going
backwards, a program that does not compile (its line and column), an engine fault (which, at
which cycle).
"""

from __future__ import annotations

import math
import re

from analysis import validate
from analysis.plc.machine.checks import PLC_COLUMN

__all__ = [
    "MAX_CYCLES",
    "MAX_ROWS",
    "START_MODES",
    "load_source",
    "one_scan",
    "parse_scenario",
    "run_trace",
    "trace_csv",
]

MAX_ROWS = 100_000
"""The most scenario rows read."""
MAX_CYCLES = 1_000_000
"""The longest run (cycles): 66 minutes at 4 ms."""
START_MODES = ("power-up", "home")
"""``stl-run --start``'s words (module docstring); the first is the default."""

_INTS = {
    "SINT": (-(2**7), 2**7 - 1),
    "INT": (-(2**15), 2**15 - 1),
    "DINT": (-(2**31), 2**31 - 1),
    "LINT": (-(2**63), 2**63 - 1),
    "USINT": (0, 2**8 - 1),
    "UINT": (0, 2**16 - 1),
    "UDINT": (0, 2**32 - 1),
    "ULINT": (0, 2**64 - 1),
    "BYTE": (0, 2**8 - 1),
    "WORD": (0, 2**16 - 1),
    "DWORD": (0, 2**32 - 1),
    "LWORD": (0, 2**64 - 1),
}
_REALS = {"REAL": 3.4028234663852886e38, "LREAL": 1.7976931348623157e308}
SCALARS = ("BOOL", *_INTS, *_REALS)


def load_source(text: str, dialect: str) -> str:
    """The ST text of a program file: as it is (``st``) or assembled from the XML's POUs."""
    if dialect == "plcopen-xml":
        from analysis.plc.machine.xml_st import st_from_plcopen

        return st_from_plcopen(text)
    return text


def _pous(source: str, kind: str) -> list[str]:
    from analysis.plc.st_engine import blank_comments

    return re.findall(rf"(?im)^\s*{kind}\s+(\w+)", blank_comments(source))


def _harness(source: str, fb: str) -> tuple[str, str]:
    """A PROGRAM calling function block ``fb`` with its inputs, copying its outputs."""
    from analysis.plc.st_engine import blank_comments

    text = blank_comments(source)
    m = re.search(rf"(?is)^\s*FUNCTION_BLOCK\s+{fb}\b(.*?)END_FUNCTION_BLOCK", text, flags=re.M)
    decl = {}
    for section in ("VAR_INPUT", "VAR_OUTPUT"):
        body = re.findall(rf"(?is)\b{section}\b(.*?)\bEND_VAR\b", m.group(1))
        decl[section] = re.findall(r"(\w+)\s*:\s*(\w+)", body[0]) if body else []
    name = "STL_RUN_HARNESS"
    execute = [n for n, _ in decl["VAR_INPUT"] if n.lower() == "execute"]
    ins = [(n, t) for n, t in decl["VAR_INPUT"] if n not in execute]
    lines = [f"PROGRAM {name}", "VAR"]
    lines += [f"    {n} : {t};" for n, t in ins + decl["VAR_OUTPUT"]]
    lines += [f"    block : {fb};", "END_VAR"]
    call = ", ".join(f"{n} := {n}" for n, _ in ins)
    if execute:  # a PLCopen block: a rising edge of Execute in every scan
        lines += [f"block({execute[0]} := FALSE, {call});",
                  f"block({execute[0]} := TRUE, {call});"]  # fmt: skip
    else:
        lines += [f"block({call});"]
    lines += [f"{n} := block.{n};" for n, _ in decl["VAR_OUTPUT"]]
    return source + "\n" + "\n".join([*lines, "END_PROGRAM", ""]), name


def pick_program(source: str, program: str | None, mapdoc: dict | None) -> tuple[str, str]:
    """(source, PROGRAM name): the one asked for, MAP.json's machine program, the only
    PROGRAM, or a harness around the only function block when there is no PROGRAM."""
    programs = _pous(source, "PROGRAM")
    want = program or ((mapdoc or {}).get("machine") or {}).get("program")
    if want:
        found = [p for p in programs if p.lower() == want.lower()]
        if not found:
            raise ValueError(
                f"no PROGRAM {want} in the source (programs: {', '.join(programs) or 'none'})"
            )
        return source, found[0]
    if len(programs) == 1:
        return source, programs[0]
    if programs:
        raise ValueError(
            f"the source has {len(programs)} programs ({', '.join(programs)}): "
            "name one with --program"
        )
    blocks = _pous(source, "FUNCTION_BLOCK")
    if len(blocks) != 1:
        raise ValueError(
            "the source has no PROGRAM and "
            f"{'no' if not blocks else len(blocks)} function blocks: nothing to "
            "run"
        )
    return _harness(source, blocks[0])


def parse_value(text: str, typ: str, what: str) -> float:
    """A value for a variable of type ``typ`` (module docstring), as the driver stores it."""
    v = text.strip(" \t")
    if typ == "BOOL":
        word = v.upper()
        if word not in ("TRUE", "FALSE"):
            raise ValueError(f"{what}: a BOOL is TRUE or FALSE, not {v!r}")
        return 1.0 if word == "TRUE" else 0.0
    if typ in _REALS and v.lower().lstrip("+-") in ("nan", "inf", "infinity"):
        return float(v)
    problem = validate.number_problem(v)
    if problem:
        raise ValueError(f"{what}: {problem}")
    if typ in _REALS:
        x = float(v)
        if abs(x) > _REALS[typ]:
            raise ValueError(f"{what}: {v} is beyond the largest {typ} ({_REALS[typ]:.7g})")
        return x
    if typ in _INTS:
        if not re.fullmatch(r"[+-]?[0-9]+", v):
            raise ValueError(f"{what}: a {typ} is a whole number, not {v!r}")
        lo, hi = _INTS[typ]
        if not lo <= int(v) <= hi:
            raise ValueError(f"{what}: {v} is outside the {typ} range {lo}..{hi}")
        return float(int(v))
    raise ValueError(f"{what}: a {typ} variable is not written from outside")


def _variable(variables: dict[str, str], name: str, program: str, what: str) -> tuple[str, str]:
    lower = {k.lower(): k for k in variables}
    key = lower.get(name.strip().lower())
    if key is None:
        near = ", ".join(list(variables)[:8])
        raise ValueError(f"{what}: {name.strip()!r} is not a variable of {program} ({near}, ...)")
    return key, variables[key]


def parse_scenario(table: dict, variables: dict[str, str], program: str):
    """Rows (t_s, name, value) of a scenario table (``t_s,name,value`` as text columns),
    each checked: a finite time not going backwards, a variable of the program, a value of
    its type. ValueError naming the row."""
    t_col, n_col, v_col = (list(table[c]) for c in ("t_s", "name", "value"))
    if len(t_col) > MAX_ROWS:
        raise ValueError(f"the scenario has {len(t_col)} rows: at most {MAX_ROWS}")
    rows, last = [], 0.0
    for k, (t, n, v) in enumerate(zip(t_col, n_col, v_col, strict=True)):
        where = f"scenario row {k + 1}"
        problem = validate.number_problem(t.strip(" \t"))
        if problem:
            raise ValueError(f"{where}: t_s {problem}")
        ts = float(t)
        if ts < 0:
            raise ValueError(f"{where}: t_s = {t.strip()} is before 0")
        if ts < last:
            raise ValueError(
                f"{where}: t_s = {t.strip()} goes back in time (the row before is at {last:g} s)"
            )
        last = ts
        name, typ = _variable(variables, n, program, where)
        if typ not in SCALARS:
            raise ValueError(f"{where}: {name} is a {typ}, not a value a scenario writes")
        rows.append((ts, name, parse_value(v, typ, f"{where}: {name}")))
    return rows


def _axis_rows(variables: dict[str, str], mapdoc: dict | None) -> list[dict]:
    """Each axis: name, joint, unit, limits per second, software limits, home mode and
    position (MAP.json's; without a map every AXIS_REF, no software limits, a reference
    switch at 0, limits that only bound homing blocks)."""
    machine = (mapdoc or {}).get("machine") or {}
    if not machine.get("axes"):
        return [{"name": n, "joint": n, "unit": "", "v": 1e6, "a": 1e9, "j": 1e12,
                 "limits": None, "mode": "switch", "home": 0.0, "known": False}
                for n, t in variables.items() if t == "AXIS_REF"]  # fmt: skip
    out = []
    for a in machine["axes"]:
        lim = a.get("limits")
        out.append({"name": a["axis"], "joint": str(a.get("joint", a["axis"])),
                    "unit": str(a.get("unit", "")), "v": float(a["max_velocity"]),
                    "a": float(a["max_acceleration"]), "j": float(a["max_jerk"]),
                    "limits": None if lim is None else (float(lim[0]), float(lim[1])),
                    "mode": a["home"].get("mode"), "home": float(a["home"]["position"]),
                    "known": True})  # fmt: skip
    return out


def parse_start(text: str | None, rows: list[dict]) -> tuple[float, ...] | str:
    """``--start`` (module docstring): one of :data:`START_MODES` (None: the first), or one
    physical position per axis in joint units, each finite and inside its software limits.
    ValueError naming the value and the limit."""
    text = START_MODES[0] if text is None else text.strip()
    if text.lower() in START_MODES:
        return text.lower()
    cells = text.split(",")
    names = ", ".join(r["name"] for r in rows) or "none"
    if len(cells) == 1 and validate.number_problem(cells[0].strip(" \t")):
        raise ValueError(f"--start {text!r}: {' or '.join(START_MODES)}, or one position per "
                         f"axis in deg or mm, comma-separated ({names})")  # fmt: skip
    if len(cells) != len(rows):
        raise ValueError(f"--start {text!r}: {len(cells)} positions for {len(rows)} axes "
                         f"({names})")  # fmt: skip
    out = []
    for r, cell in zip(rows, cells, strict=True):
        problem = validate.number_problem(cell.strip(" \t"))
        if problem:
            raise ValueError(f"--start: {r['joint']} {problem}")
        q, lim = float(cell), r["limits"]
        if lim is not None and not lim[0] <= q <= lim[1]:
            raise ValueError(f"--start: {r['joint']} = {q:g} {r['unit']} is outside its "
                             f"limits {lim[0]:g}..{lim[1]:g} {r['unit']}")  # fmt: skip
        out.append(q)
    return tuple(out)


def _axes(variables: dict[str, str], mapdoc: dict | None, start: str | None = None):
    """One :class:`~analysis.plc.st_engine.SimAxis` per axis (:func:`_axis_rows`), standing
    where ``start`` says (:func:`parse_start`)."""
    from analysis.plc.machine.plant import placed, power_up_axis
    from analysis.plc.st_engine import SimAxis

    rows = _axis_rows(variables, mapdoc)
    where = parse_start(start, rows)
    out = []
    for k, r in enumerate(rows):
        switch = r["home"] if r["mode"] == "switch" else None
        if isinstance(where, tuple):
            pos = placed(k, where[k], r["mode"], r["home"], r["limits"])
        elif where == "power-up" and r["known"]:
            pos = power_up_axis(k, r["mode"], r["home"], r["v"], r["limits"])
        else:  # home, or nothing known of the axis
            pos = (r["home"], r["home"], switch)
        lo, hi = r["limits"] or (None, None)
        out.append(SimAxis(r["name"], r["v"], r["a"], r["j"], lo, hi, *pos))
    return out


def _outputs(source, program, variables, written, mapdoc) -> list[str]:
    from analysis.plc.st_engine import CYCLE_VARIABLE, TIME_UNIT_VARIABLE

    machine = (mapdoc or {}).get("machine") or {}
    if machine.get("outputs"):
        return [
            _variable(variables, n, "the program", "MAP.json output")[0] for n in machine["outputs"]
        ]
    skip = {w.lower() for w in written} | {TIME_UNIT_VARIABLE.lower(), CYCLE_VARIABLE.lower()}
    declared = {n.lower() for n in _declared(source, program)}
    return [n for n, t in variables.items()
            if t in SCALARS and n.lower() in declared and n.lower() not in skip]  # fmt: skip


def _declared(source: str, program: str) -> list[str]:
    """The names PROGRAM ``program`` declares in its own VAR sections, in order (not the
    variables of the block instances inside it, which the engine lists too)."""
    from analysis.plc.st_engine import blank_comments

    text = blank_comments(source)
    m = re.search(rf"(?is)^\s*PROGRAM\s+{re.escape(program)}\b(.*?)\bEND_PROGRAM\b", text,
                  flags=re.M)  # fmt: skip
    if not m:
        return []
    sections = re.findall(r"(?is)\bVAR\w*\b(.*?)\bEND_VAR\b", m.group(1))
    return [n for body in sections for n in re.findall(r"(?m)(\w+)\s*:\s*\w", body)]


def run_trace(
    source: str,
    table: dict,
    *,
    cycle_s: float,
    settle_s: float,
    mapdoc: dict | None = None,
    program: str | None = None,
    start: str | None = None,
):
    """Run a scenario table (:func:`parse_scenario`), the axes standing where ``start`` says
    (:func:`parse_start`); returns (header, axes, run, output types)."""
    from analysis.plc.machine.run import schedule
    from analysis.plc.st_engine import program_variables, run_machine

    if not (0.0005 <= cycle_s <= 1.0):
        raise ValueError(f"--cycle-ms {cycle_s * 1e3:g}: between 0.5 and 1000 ms")
    if not (0.0 <= settle_s <= 3600.0):
        raise ValueError(f"--settle-s {settle_s:g}: between 0 and 3600 s")
    from analysis.plc.st_engine import POWER_OK

    source, name = pick_program(source, program, mapdoc)
    variables = program_variables(source, name)
    axes = _axes(variables, mapdoc, start)
    drives = {f"{a.name}.{POWER_OK}": "BOOL" for a in axes}  # the drives' power feedback
    rows = parse_scenario(table, {**variables, **drives}, name)
    writes, n = schedule(rows, cycle_s, settle_s)
    if n > MAX_CYCLES:
        raise ValueError(
            f"the scenario runs {n} cycles (last row at {rows[-1][0]:g} s + "
            f"{settle_s:g} s at {cycle_s * 1e3:g} ms): at most {MAX_CYCLES}"
        )
    outs = _outputs(source, name, variables, {n for _, n, _ in rows}, mapdoc)
    clash = {PLC_COLUMN.format(k + 1).lower() for k in range(len(axes))} & {o.lower() for o in outs}
    if clash:
        raise ValueError(f"the output {sorted(clash)[0]} has the name of the trace's column "
                         "of what the PLC reads: rename it")  # fmt: skip
    run = run_machine(source, name, axes, writes, outs, cycle_s=cycle_s, n_cycles=n)
    return [v for v in outs], axes, run, {n: variables[n] for n in outs}


def _fmt(x: float) -> str:
    if not math.isfinite(x):
        return "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf")
    return repr(float(x)) if x != int(x) or abs(x) >= 1e15 else str(int(x))


def trace_csv(outs, axes, run, types) -> str:
    """The trace (module docstring): BOOL outputs as TRUE/FALSE, numbers in full; what the
    PLC reads of each axis last (:data:`PLC_COLUMN`)."""
    n = len(axes)
    head = ["t_s", *(f"q{k + 1}" for k in range(n)), *(f"v{k + 1}" for k in range(n)), *outs,
            *(PLC_COLUMN.format(k + 1) for k in range(n))]  # fmt: skip
    lines = [",".join(head)]
    bools = [types[o] == "BOOL" for o in outs]
    for k in range(len(run.t)):
        cells = [
            _fmt(round(run.t[k], 9)),
            *(_fmt(x) for x in run.q[k]),
            *(_fmt(x) for x in run.v[k]),
        ]
        for b, x in zip(bools, run.values[k], strict=True):
            cells.append(("TRUE" if x else "FALSE") if b else _fmt(x))
        cells += [_fmt(x) for x in run.pos[k]] if n else []
        lines.append(",".join(cells))
    return "\n".join(lines) + "\n"


def one_scan(source: str, sets, reads, *, mapdoc=None, program=None, start=None) -> dict:
    """One scan: ``sets`` (``NAME=VALUE``) written before it, ``reads`` (``NAME`` or
    ``NAME:TYPE``) after it, the axes standing where ``start`` says (:func:`parse_start`);
    ``{"values": {name: value}}``."""
    from analysis.plc.st_engine import program_variables, run_machine

    source, name = pick_program(source, program, mapdoc)
    variables = program_variables(source, name)
    writes = []
    for s in sets:
        var, sep, value = s.partition("=")
        if not sep:
            raise ValueError(f"--set {s!r}: expected NAME=VALUE (e.g. TargetX=100.0)")
        key, typ = _variable(variables, var, name, f"--set {s!r}")
        writes.append((0, key, parse_value(value, typ, f"--set {s!r}")))
    if not reads:
        raise ValueError("nothing to read: give at least one --read NAME")
    wanted = []
    for r in reads:
        var, _, typ = r.partition(":")
        key, real = _variable(variables, var, name, f"--read {r!r}")
        if typ and typ.strip().upper() != real:
            raise ValueError(f"--read {r!r}: {key} is a {real}, not {typ.strip().upper()}")
        if real not in SCALARS:
            raise ValueError(f"--read {r!r}: {key} is a {real}, not a scalar")
        wanted.append((key, real))
    run = run_machine(
        source, name, _axes(variables, mapdoc, start), writes, [k for k, _ in wanted], n_cycles=1
    )
    values = {}
    for k, (key, typ) in enumerate(wanted):
        x = float(run.values[0, k])
        values[key] = bool(x) if typ == "BOOL" else (x if typ in _REALS else int(x))
    return {"values": values, "types": dict(wanted)}
