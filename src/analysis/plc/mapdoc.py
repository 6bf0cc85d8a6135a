"""MAP.json: what a generated program's map says, for every dialect (one schema, :data:`SCHEMA`).

:func:`map_document` writes it for any dialect: every input with its unit, every output,
every status code the program writes with its meaning, every memory range the program uses
(work areas included), the start-up behaviour and the target CPU with its limits. For the S7
dialects (:func:`s7_document`) the addresses are the program's, and :func:`program_addresses`
finds every memory operand in the program text (checked against the target CPU); for ST, SCL
and PLCopen XML (:func:`interface_document`) they are the block's interface variables.

MAP.json keys (``schema`` ``analysis.plc.map/2``; the first four are the contract of
design.md and unchanged):

``dialect``
    ``s7-200``, ``s7-300``, ``st``, ``scl`` or ``plcopen-xml``.
``inputs``, ``outputs``
    name -> address (S7) or interface variable (ST/SCL).
``units``
    ``{"inputs": "...", "outputs": "..."}``, one line each naming every signal's unit.
``signals``
    name -> ``{"address", "type", "unit", "direction", "meaning"}`` (``joint`` and
    ``pulses_per_rev`` for the counts, ``codes`` for the status word).
``status_codes``
    code (as text) -> ``{"name", "meaning"}``, for every code the program can write.
``memory``
    every range the program reads or writes, in address order: ``{"range", "area",
    "first", "last", "use"}`` (``use`` names the signal, the work variable or what the
    area is for; "program-internal" where nothing more is known).
``work``
    work variable -> address (the IK's REAL temporaries).
``startup``
    what the program does on its first scan, in words, per item.
``target_cpu``
    ``{"name", "limits": {area: "first-last"}, "source"}``; for ST/SCL the runtime.
"""

from __future__ import annotations

import re

from analysis.kinematics.status import Status
from analysis.plc.instr import status_codes

__all__ = [
    "SCHEMA",
    "SM_USES",
    "interface_document",
    "map_document",
    "program_addresses",
    "ranges",
    "s7_document",
    "startup_values",
    "status_meanings",
]

SCHEMA = "analysis.plc.map/2"


def status_meanings() -> dict[int, tuple[str, str]]:
    """Status code -> (name, one-sentence meaning), for every code a program can write."""
    meaning = {
        Status.OK: "solved: c1..cn hold the pulse counts, the reach flag is on",
        Status.OUT_OF_REACH: "the target is farther than the arm reaches; outputs unchanged",
        Status.INSIDE_REACH: "the target is nearer than the inner reach radius; outputs unchanged",
        Status.BASE_AXIS: "the target is on the waist axis, where the waist angle is "
        "undefined; outputs unchanged",
        Status.JOINT_LIMITS: "reachable, but the branch's angles are outside the joint "
        "limits; outputs unchanged",
        Status.DEGENERATE: "the closed form's own singular case (e.g. the wrist on the "
        "shoulder); outputs unchanged",
        Status.INVALID: "an input is NaN or infinite (bit test, no REAL compare); outputs "
        "unchanged",
        Status.ORIENTATION: "an orientation this arm cannot take (a 5-DOF arm's missing "
        "freedom); outputs unchanged",
    }
    return {int(s): (s.text, meaning[s]) for s in Status}


def map_document(
    dialect: str,
    *,
    inputs: dict[str, str],
    outputs: dict[str, str],
    units: dict[str, str],
    output_facts: dict[str, dict] | None = None,
    status_codes=(),
    memory: list[dict] | None = None,
    work: dict[str, str] | None = None,
    startup: dict[str, str] | None = None,
    target_cpu: dict | None = None,
    arm: str | None = None,
    branch: str | None = None,
) -> dict:
    """MAP.json content for any dialect (the keys in the module docstring).

    ``inputs``/``outputs`` map each name to its address (S7) or interface variable (ST,
    SCL, PLCopen XML); ``units`` gives every input's unit ("mm", "deg" or "rad");
    ``status_codes`` the codes the program writes. Raises ValueError for an input without a
    unit, a unit outside mm/deg/rad, or an unknown status code.
    """
    meanings = status_meanings()
    for k in inputs:
        if units.get(k) not in ("mm", "deg", "rad"):
            raise ValueError(f"input {k}: unit {units.get(k)!r} is not mm, deg or rad")
    codes = sorted({int(c) for c in status_codes})
    for c in codes:
        if c not in meanings:
            raise ValueError(f"status code {c} has no meaning in analysis.kinematics.status")
    facts = output_facts or {}
    signals: dict = {}
    for k, a in inputs.items():
        signals[k] = {
            "address": a,
            "type": "REAL",
            "unit": units[k],
            "direction": "input",
            "meaning": f"target {k} [{units[k]}], written by the HMI",
        }
    counts = [k for k in outputs if re.fullmatch(r"c\d+", k)]
    for k in counts:
        signals[k] = {
            "address": outputs[k],
            "type": "DINT",
            "unit": "pulses",
            "direction": "output",
            "meaning": "pulse count of joint "
            + str(facts.get(k, {}).get("joint", k[1:]))
            + " (eqs. 20-22); unchanged when the target is refused",
            **facts.get(k, {}),
        }
    if "reachable" in outputs:
        signals["reachable"] = {
            "address": outputs["reachable"],
            "type": "BOOL",
            "unit": "",
            "direction": "output",
            "meaning": "on when status = 0 (c1..cn valid); motion starts only with it on",
        }
    if "status" in outputs:
        signals["status"] = {
            "address": outputs["status"],
            "type": "DINT",
            "unit": "code",
            "direction": "output",
            "meaning": "why the target was solved or refused (status_codes)",
            "codes": [str(c) for c in codes],
        }
    by_unit: dict[str, list[str]] = {}
    for k in inputs:
        by_unit.setdefault(units[k], []).append(k)
    doc = {
        "schema": SCHEMA,
        "dialect": dialect,
        **({"arm": arm} if arm else {}),
        **({"branch": branch} if branch else {}),
        "inputs": dict(inputs),
        "outputs": dict(outputs),
        "units": {
            "inputs": "; ".join(f"{', '.join(v)}: {u} (REAL)" for u, v in by_unit.items()),
            "outputs": f"{', '.join(counts)}: pulses (DINT); reachable: BOOL; status: DINT "
            "code (status_codes)",
        },
        "signals": signals,
        "status_codes": {
            str(c): {"name": meanings[c][0], "meaning": meanings[c][1]} for c in codes
        },
    }
    if memory is not None:
        doc["memory"] = memory
    if work:
        doc["work"] = dict(work)
    doc["startup"] = dict(startup or {})
    doc["startup"].setdefault(
        "inputs", "not written by the program: it computes from what the inputs hold"
    )
    if target_cpu is not None:
        doc["target_cpu"] = target_cpu
    return doc


# ------------------------------------------------------------------------------------------
# the memory a program text uses
_S7200_OPND = re.compile(
    r"(?<![#\w&*])(?P<area>SM|AC|V|M|I|Q|S|L)(?P<w>[BWD]?)(?P<n>\d+)(?:\.(?P<bit>[0-7]))?(?![\w.])"
)
_S7300_OPND = re.compile(
    r"(?<![#\w])(?P<area>M|I|Q)(?P<w>[BWD]?)\s*(?P<n>\d+)(?:\.(?P<bit>[0-7]))?(?![\w.])"
)
_WIDTH = {"": 1, "B": 1, "W": 2, "D": 4}


def program_addresses(text: str, dialect: str) -> list[tuple[str, int, int, str]]:
    """Every memory operand ``text`` names: ``(area, first byte, last byte, operand)``, one
    per distinct operand (``AC`` by register number).

    Comments (``//``) are ignored; S7-200 subroutine locals (``#name``) are reported as one
    L range, LB0 up to the largest local frame of any subroutine (each call level has its
    own 64 bytes).
    """
    pat = _S7200_OPND if dialect == "s7-200" else _S7300_OPND
    found: dict[str, tuple[str, int, int, str]] = {}
    sizes = {"BOOL": 0, "BYTE": 1, "WORD": 2, "INT": 2, "DWORD": 4, "DINT": 4, "REAL": 4}
    local_bytes = frame = bits = 0
    for raw in text.splitlines():
        line = raw.split("//", 1)[0].strip()
        if not line:
            continue
        if dialect == "s7-200":
            if line.startswith(("SUBROUTINE_BLOCK", "ORGANIZATION_BLOCK", "INTERRUPT_BLOCK")):
                frame = bits = 0
            m = re.fullmatch(r"(\w+)\s*:\s*(\w+)\s*;?", line)
            if m and m.group(2).upper() in sizes:  # a VAR declaration: its L bytes
                size = sizes[m.group(2).upper()]
                if size == 0:
                    bits += 1
                    frame += bits % 8 == 1
                else:
                    frame += size
                local_bytes = max(local_bytes, frame)
                continue
        if line.startswith(("TITLE", "Network", "NETWORK", "FUNCTION", "ORGANIZATION", "VAR")):
            continue
        parts = line.split(None, 1)
        if len(parts) < 2 or parts[0].startswith(("END_", "DATA_BLOCK")):
            continue
        for m in pat.finditer(parts[1]):
            area, n = m.group("area"), int(m.group("n"))
            text_ = m.group(0).replace(" ", "")
            if area == "AC":
                found[text_] = ("AC", n, n, text_)
                continue
            if m.group("bit") is None and not m.group("w"):
                continue  # "M 12" without width or bit is not a memory operand
            width = 1 if m.group("bit") is not None else _WIDTH[m.group("w")]
            found[text_] = (area, n, n + width - 1, text_)
    if local_bytes:
        found["#locals"] = ("L", 0, local_bytes - 1, "#locals")
    return sorted(found.values(), key=lambda t: (_AREA_ORDER.get(t[0], 99), t[1], t[2], t[3]))


SM_USES = {
    "SM0.0": "always on",
    "SM0.1": "first scan only",
    "SM0.3": "first scan after power-up",
    "SM0.5": "1 s clock (0.5 s on, 0.5 s off)",
    "SM1.0": "result zero",
    "SM1.1": "overflow or illegal value",
    "SM1.2": "result negative",
    "SM1.3": "division by zero",
}
"""What the S7-200's common SM bits are (S7-200 System Manual, Appendix D, SMB0/SMB1)."""

_AREA_ORDER = {a: k for k, a in enumerate(("V", "M", "I", "Q", "SM", "S", "L", "AC"))}


def ranges(addresses, groups: dict[str, tuple[str, str]]) -> list[dict]:
    """Merge operands into ranges: overlapping or adjacent bytes of the same group
    (``groups``: operand -> (group key, label)) become one range, labelled with its members."""
    out: list[dict] = []
    for area, first, last, opnd in addresses:
        key, label = groups.get(opnd, ("internal", "program-internal"))
        prev = out[-1] if out else None
        if (
            prev is not None
            and prev["area"] == area
            and prev["_key"] == key
            and first <= prev["last"] + 1
        ):
            prev["last"] = max(prev["last"], last)
            prev["_members"].append(opnd)
            if label not in prev["_labels"]:
                prev["_labels"].append(label)
            continue
        out.append(
            {
                "area": area,
                "first": first,
                "last": last,
                "_key": key,
                "_labels": [label],
                "_members": [opnd],
            }
        )
    for r in out:
        a, f, l_ = r["area"], r["first"], r["last"]
        members = r.pop("_members")
        if len(members) == 1 and not members[0].startswith("#"):
            r["range"] = members[0]
        elif a == "AC":
            r["range"] = f"AC{f}" if f == l_ else f"AC{f}-AC{l_}"
        else:
            r["range"] = f"{a}B{f}" if f == l_ else f"{a}B{f}-{a}B{l_}"
        labels = r.pop("_labels")
        key = r.pop("_key")
        r["use"] = (
            f"{key}: " + ", ".join(labels)
            if key in ("inputs", "outputs", "work")
            else "; ".join(labels)
        )
    return [{k: r[k] for k in ("range", "area", "first", "last", "use")} for r in out]


# ------------------------------------------------------------------------------------------
# the start-up, and the documents of the two kinds of dialect
def startup_values(arm, program, startup_target) -> tuple[float, ...] | None:
    """What the first scan writes into the inputs: nothing (None), the closed form's example
    (``"paper"``: Figure 3's (100, 100, 600) mm for the grabber) or these values (in the
    inputs' units; as many as the program has inputs)."""
    if startup_target is None:
        return None
    if isinstance(startup_target, str):
        if startup_target != "paper":
            raise ValueError(f"startup_target {startup_target!r}: expected 'paper' or numbers")
        start = arm.startup_target
        if start is None:
            raise ValueError(f"arm {arm.name} names no example target (STARTUP_TARGET)")
    else:
        start = tuple(float(v) for v in startup_target)
    if len(start) != len(program.inputs):
        raise ValueError(
            f"startup_target has {len(start)} values; the program has {len(program.inputs)} "
            f"inputs ({', '.join(program.inputs)})"
        )
    return start


def _startup_doc(where: str, program, start, units, motion: str | None) -> dict[str, str]:
    doc = {}
    if start is None:
        doc["inputs"] = (
            "not written: the program computes from whatever the inputs hold (an HMI's value "
            "survives a restart only where the CPU retains that memory)"
        )
    else:
        vals = ", ".join(
            f"{k} = {v:g} {units[k]}" for k, v in zip(program.inputs, start, strict=True)
        )
        doc["inputs"] = (
            f"written on {where} with the example target {vals} (the paper's Figure 3): a "
            "value the HMI wrote before the restart is overwritten"
        )
    doc["outputs"] = (
        "c1..cn keep their value until the first scan that solves a target; status and the "
        "reach flag are written on every scan"
    )
    if motion:
        doc["motion"] = motion
    return doc


def s7_document(arm, program, text: str, mmap, work: dict[str, int], start, *, where: str,
                uses: dict[str, str], motion: str | None) -> dict:  # fmt: skip
    """The MAP.json of an S7 program ``text`` laid out by ``mmap`` (with its work area
    ``work``): ``where`` the first scan writes the start-up target ``start``, ``uses`` what
    the addresses beyond the I/O and work area are for, ``motion`` what the motion networks
    do at start-up (None: the program has none)."""
    units = dict(zip(arm.inputs, arm.input_units, strict=True))
    joints = arm.description.joints
    ppr = arm.params.pulses_per_rev
    outputs = {
        f"c{j + 1}": {"joint": joints[j].name, "pulses_per_rev": ppr[j]}
        for j in range(len(program.outputs))
    }
    return mmap.document(
        text,
        units=units,
        outputs=outputs,
        status_codes=status_codes(program),
        work=work,
        uses=uses,
        startup=_startup_doc(where, program, start, units, motion),
        arm=arm.name,
        branch=program.branch,
    )


def interface_document(program, fb: str, dialect: str, units, trig: str, runtime: str,
                       instance_db: str | None) -> dict:  # fmt: skip
    """The interface map of an ST-family block (the MAP.json schema, the interface
    variables ``FB.name`` in place of addresses): the inputs with their units, the outputs,
    every status code with its meaning, what the block does before its first call; and the
    block, its instance DB (SCL), its functions, the trigonometry and REAL."""
    doc = map_document(
        dialect,
        inputs={n: f"{fb}.{n}" for n in program.inputs},
        outputs={n: f"{fb}.{n}" for n in (*program.outputs, "reachable", "status")},
        units=dict(zip(program.inputs, units, strict=True)),
        status_codes=status_codes(program),
        startup={
            "inputs": "the caller passes them on every call; the block keeps no inputs",
            "outputs": "0 / FALSE until the first call; a refused call leaves c1..cn as they were",
        },
        target_cpu={
            "name": runtime,
            "limits": {},
            "source": "no fixed addresses: the block's interface",
        },
        arm=program.arm,
        branch=program.branch,
    )
    doc.update(
        {
            "block": fb,
            "instance_db": instance_db,
            "functions": [f"IK_{s.name}" for s in program.subroutines],
            "trig": trig,
            "real": "REAL (IEEE binary32); pulses rounded half away from zero (eqs. 20-22)",
        }
    )
    return doc
