"""``stl --dialect st|scl|plcopen-xml``: the IK block and, beside it, the machine program
(:mod:`.program`), with the machine's part of MAP.json.

The IK block is printed by the dialect's printer (:func:`analysis.plc.generate.generate`; it
stays available on its own: ``stl --no-motion``); the machine program follows it in the same
source (ST, SCL) or as one more POU, ``pouType="program"``, in the PLCopen XML, whose
variables are the program's ``localVars`` and whose body is the same ST text.
"""

from __future__ import annotations

import json
import re

from analysis.escape import xml_attr
from analysis.plc.machine.program import STEPS, MachinePrinter, machine_name
from analysis.plc.machine.program_scl import SclMachinePrinter
from analysis.plc.machine.spec import MACHINE_INPUTS, MACHINE_OUTPUTS, machine_spec
from analysis.plc.machine.tags import signals
from analysis.plc.plcopen import formatted_text

__all__ = ["machine_map", "program_pou_xml", "with_machine"]

_ELEMENTARY = {"BOOL", "INT", "DINT", "REAL", "LREAL", "TIME"}


MACHINE_PRINTERS = {"st": MachinePrinter, "scl": SclMachinePrinter}
"""The machine program's printer per dialect (PLCopen XML carries the ST one)."""


def machine_text(spec, ik_block: str, dialect: str) -> str:
    """The machine program of ``spec`` calling IK block ``ik_block`` in ``dialect``."""
    return MACHINE_PRINTERS[dialect](spec, ik_block).text()


def machine_map(spec, ik_codes, dialect: str) -> dict:
    """The machine's part of MAP.json: its program, inputs and outputs with their units,
    every status code with its meaning and alarm text, each axis with its joint, unit, step,
    limits and homing (each value's provenance), the unit rule of the motion blocks."""
    name = machine_name(spec)
    inputs = {n: {"type": "BOOL"} for n in MACHINE_INPUTS}
    inputs.update(
        {
            n: {"type": "REAL", "unit": u}
            for n, u in zip(spec.targets, spec.target_units, strict=True)
        }
    )
    outputs = {n: {"type": "INT" if n == "Status" else "BOOL"} for n in MACHINE_OUTPUTS}
    outputs["AxisErrorID"] = {"type": "DINT", "meaning": "the first axis error's ID (0: none)"}
    axes = [
        {
            "axis": a.name,
            "joint": a.joint,
            "unit": a.unit,
            "per_pulse": a.per_pulse,
            "pulses_per_rev": a.pulses_per_rev,
            "limits": None if a.unlimited else [a.lower, a.upper],
            "max_velocity": a.max_velocity,
            "max_acceleration": a.max_acceleration,
            "max_jerk": a.max_jerk,
            "home": {"mode": a.home_mode, "position": a.home_position},
            "provenance": a.provenance,
        }
        for a in spec.axes
    ]
    return {
        "program": name,
        "instance_db": f"{name}_DB" if dialect == "scl" else None,
        "inputs": inputs,
        "outputs": outputs,
        "status_codes": {str(k): v for k, v in spec.status_codes(ik_codes).items()},
        "steps": STEPS,
        "axes": axes,
        "grip_dwell_s": spec.grip_dwell_s,
        "grip_dwell_status": "assumed: no paper prints the gripper's closing time",
        "signals": [
            {"name": n, "type": t, "address": a, "comment": c, "hmi_writes": w}
            for n, t, a, c, w in signals(spec)
        ],
        "motion_time_unit": {
            "variable": "MotionTimeUnit",
            "plc": 1.0,
            "rule": "every motion block's Velocity, Acceleration, Jerk is value * "
            "MotionTimeUnit**k: 1.0 (per second) on a PLC; stl-run writes the cycle time "
            "(the ST engine's axes take them per cycle)",
        },
    }


def _declarations(st_text: str, program: str) -> list[tuple[str, str, str | None]]:
    """(name, type, initial value) of each variable of PROGRAM ``program`` in ``st_text``."""
    body = st_text.split(f"PROGRAM {program}\n", 1)[1].split("\nEND_VAR", 1)[0]
    out = []
    for line in body.split("\n"):
        m = re.fullmatch(r"\s*(\w+) : (\w+)(?: := ([^;]+))?;", line)
        if m:
            out.append((m.group(1), m.group(2), m.group(3)))
    return out


def program_pou_xml(st_text: str, program: str) -> str:
    """The PLCopen XML POU (``pouType="program"``) of PROGRAM ``program`` in ``st_text``:
    its variables as ``localVars`` (elementary types as elements, the rest ``derived``),
    initial values as ``simpleValue``, the statements as the ST body."""

    def var(name, typ, init):
        t = f"<{typ}/>" if typ in _ELEMENTARY else f'<derived name="{xml_attr(typ)}"/>'
        i = f'<initialValue><simpleValue value="{xml_attr(init)}"/></initialValue>' if init else ""
        return f'<variable name="{xml_attr(name)}"><type>{t}</type>{i}</variable>'

    decls = "".join(var(*d) for d in _declarations(st_text, program))
    body = st_text.split(f"PROGRAM {program}\n", 1)[1].split("\nEND_VAR\n", 1)[1]
    body = body.rsplit("END_PROGRAM", 1)[0].strip("\n") + "\n"
    body = "\n".join(ln[4:] if ln.startswith("    ") else ln for ln in body.split("\n"))
    return (
        f'<pou name="{xml_attr(program)}" pouType="program"><interface><localVars>{decls}'
        f"</localVars></interface><body><ST>{formatted_text(body)}</ST></body></pou>\n"
    )


def with_machine(arm, dialect: str, ik, block: str):
    """The IK block's :class:`~analysis.plc.printer.Generated` ``ik`` (dialect st, scl or
    plcopen-xml) with the machine program beside it: after the IK block in ST and SCL, one
    more POU (``pouType="program"``) in the XML; MAP.json gains a ``machine`` section
    (:func:`machine_map`). ``block``: the IK function block's name."""
    from analysis.plc.plcopen import validate_plcopen
    from analysis.plc.printer import Generated

    spec = machine_spec(arm)
    doc = json.loads(ik.map)
    ik_codes = [int(k) for k in doc.get("status_codes", {})]
    if dialect == "plcopen-xml":
        pou = program_pou_xml(machine_text(spec, block, "st"), machine_name(spec))
        text = ik.program.replace("</pous>", pou + "</pous>", 1)
        validate_plcopen(text)
    else:
        text = ik.program.rstrip("\n") + "\n" + machine_text(spec, block, dialect)
    doc["machine"] = machine_map(spec, ik_codes, dialect)
    return Generated(text, json.dumps(doc, indent=2, ensure_ascii=False) + "\n", ik.files)
