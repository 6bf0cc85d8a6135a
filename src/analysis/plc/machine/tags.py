"""The machine's signals as the PLC's own tags: a TIA Portal PLC tag table and a CODESYS global
variable list, written beside MAP.json (``stl --tags``, ``stl --gvl``).

One assignment (:func:`signals`), from the machine's contract (:mod:`.spec`): the push buttons,
the stop circuit and the gripper's valve are wired (inputs %I0.0.., outputs %Q0.0..); the
targets, Status and AxisErrorID are HMI values (memory %M from byte 100). Both files carry the
same names, types, addresses and comments.

- TIA Portal (V15 and later): the workbook that the PLC tag editor's *Import* reads and its
  *Export* writes, one sheet "PLC Tags" with the columns ``Name, Path, Data Type, Logical
  Address, Comment, Hmi Visible, Hmi Accessible, Hmi Writeable, Typeobject ID, Version ID``
  (the TIA Portal online help, "Importing and exporting PLC tags"); written with openpyxl.
  The machine FB is then called in OB1 as ``"MACHINE_<ARM>_DB"(Enable := "Enable", ...)``.
- CODESYS: a GVL (``{attribute 'qualified_only'}``, ``VAR_GLOBAL``) with the wired signals at
  ``%IX``/``%QX`` addresses and the HMI values without one; a task copies them into the
  machine program's variables (``MACHINE_<ARM>.Enable := GVL_<ARM>.Enable;``), shown in the
  file's header comment.

Names and comments are the contract's and the arm description's own (identifiers and
ASCII text); nothing from outside is embedded unchecked: a comment is cleaned of ``*)`` and
line breaks in one place (:func:`_text`).
"""

from __future__ import annotations

import io
import re

from analysis.escape import plc_comment
from analysis.plc.machine.spec import MACHINE_INPUTS, MachineSpec

__all__ = ["TIA_COLUMNS", "codesys_gvl", "machine_files", "signals", "tia_tag_table"]

TIA_COLUMNS = ("Name", "Path", "Data Type", "Logical Address", "Comment", "Hmi Visible",
               "Hmi Accessible", "Hmi Writeable", "Typeobject ID", "Version ID")  # fmt: skip
"""The columns of TIA Portal's PLC tag table workbook (sheet "PLC Tags")."""

_COMMENT = {
    "Enable": "power the axes (switch)",
    "Home": "home every axis (push button, rising edge)",
    "Start": "latch the target and move (push button, rising edge)",
    "StopOK": "stop circuit, normally closed: FALSE or a broken wire stops every axis",
    "Reset": "clear a stop or an axis error (push button, rising edge)",
    "Grip": "close the gripper (TRUE) or open it",
    "Homed": "every axis homed (lamp)",
    "Busy": "homing, moving or gripping (lamp)",
    "Done": "the last command completed (lamp)",
    "Error": "a command was refused or a fault is latched (lamp); Status says which",
    "Gripper": "gripper valve",
    "Status": "0 ok, 1-7 the IK's refusal, 100-104 the machine's (MAP.json: the alarm texts)",
    "AxisErrorID": "the first axis error's ID (0: none)",
    "GripperClosed": "the gripper has closed (after the dwell)",
}


def _text(s: str) -> str:
    """A comment on one line, without the ST comment's delimiters (analysis.escape)."""
    return plc_comment(s)


def signals(spec: MachineSpec) -> list[tuple[str, str, str | None, str, bool]]:
    """(name, IEC type, address or None, comment, written by the HMI) for every signal."""
    out = []
    for k, name in enumerate(MACHINE_INPUTS):
        out.append((name, "BOOL", f"%I0.{k}", _COMMENT[name], False))
    for k, name in enumerate(("Homed", "Busy", "Done", "Error", "Gripper")):
        out.append((name, "BOOL", f"%Q0.{k}", _COMMENT[name], False))
    byte = 100
    for name, unit in zip(spec.targets, spec.target_units, strict=True):
        out.append((name, "REAL", f"%MD{byte}", f"target, {unit}", True))
        byte += 4
    out.append(("Status", "INT", f"%MW{byte}", _COMMENT["Status"], False))
    out.append(("AxisErrorID", "DINT", f"%MD{byte + 2}", _COMMENT["AxisErrorID"], False))
    out.append(("GripperClosed", "BOOL", f"%M{byte + 6}.0", _COMMENT["GripperClosed"], False))
    return out


_TIA_TYPE = {"BOOL": "Bool", "INT": "Int", "DINT": "DInt", "REAL": "Real"}


def tia_tag_table(spec: MachineSpec, table: str | None = None) -> bytes:
    """The TIA Portal PLC tag table workbook (module docstring) as bytes."""
    from openpyxl import Workbook

    from analysis.plc.machine.program import machine_name

    table = table or f"{machine_name(spec)}_tags"
    wb = Workbook()
    ws = wb.active
    ws.title = "PLC Tags"
    ws.append(list(TIA_COLUMNS))
    for name, typ, address, comment, writable in signals(spec):
        ws.append([name, table, _TIA_TYPE[typ], address, _text(comment), "True", "True",
                   "True" if writable else "False", "", ""])  # fmt: skip
    buf = io.BytesIO()
    wb.save(buf)
    return buf.getvalue()


def _codesys_address(address: str) -> str | None:
    """%I0.3 -> %IX0.3, %Q0.1 -> %QX0.1; memory values get no address in CODESYS."""
    m = re.fullmatch(r"%([IQ])(\d+\.\d)", address)
    return f"%{m.group(1)}X{m.group(2)}" if m else None


def codesys_gvl(spec: MachineSpec) -> str:
    """The CODESYS GVL (module docstring)."""
    from analysis.plc.machine.program import machine_name

    program = machine_name(spec)
    gvl = "GVL_" + program[len("MACHINE_") :]
    rows = signals(spec)
    copy_in = [f"{program}.{n} := {gvl}.{n};" for n, _, _, _, _ in rows if n in
               (*MACHINE_INPUTS, *spec.targets)]  # fmt: skip
    copy_out = [f"{gvl}.{n} := {program}.{n};" for n, _, _, _, _ in rows if n not in
                (*MACHINE_INPUTS, *spec.targets)]  # fmt: skip
    head = [
        f"(* {gvl}: the signals of {program} ({_text(spec.title)}), generated by analysis.plc",
        "   (python -m analysis stl --dialect st --gvl FILE). Add as a global variable list",
        f"   named {gvl}; in the task, before and after calling {program}:",
        *(f"     {line}" for line in copy_in),
        f"     {program}();",
        *(f"     {line}" for line in copy_out),
        "*)",
        "{attribute 'qualified_only'}",
        "VAR_GLOBAL",
    ]
    decl = []
    for name, typ, address, comment, _ in rows:
        at = _codesys_address(address)
        where = f" AT {at}" if at else ""
        decl.append(f"    {name}{where} : {typ}; (* {_text(comment)} *)")
    return "\n".join([*head, *decl, "END_VAR", ""])


def machine_files(arm, dialect: str, no_motion: bool, tags=None, gvl=None) -> dict:
    """``stl --tags/--gvl``: {path: content} of the files asked for; ValueError where the
    dialect or ``--no-motion`` has no machine."""
    from analysis.plc.machine.spec import machine_spec

    if dialect not in ("st", "scl", "plcopen-xml") or no_motion:
        raise ValueError(
            f"--tags and --gvl are the machine program's signals (--dialect st, "
            f"scl or plcopen-xml without --no-motion), not {dialect}'s"
        )
    spec = machine_spec(arm)
    out = {}
    if tags is not None:
        out[tags] = tia_tag_table(spec)
    if gvl is not None:
        out[gvl] = codesys_gvl(spec)
    return out
