"""The ``stl --dialect st|scl|plcopen-xml`` outputs: the program text and its interface map.

:func:`generate_st` builds the arm's program (:func:`analysis.plc.ir.build_program`, trig
``function`` by default: native ATAN and ACOS, a generated ATAN2) and prints it with
:mod:`.st` (``st``, ``scl``) or wraps the ST block in PLCopen XML TC6 0201 for CODESYS and
TwinCAT import (``plcopen-xml``, :func:`plcopen_xml`), validated against the schema model of
the PyPI package ``plcopen`` (:func:`validate_plcopen`). The map is JSON like MAP.json, with
the block's interface variables in place of addresses (there are none in ST).
"""

from __future__ import annotations

import dataclasses
import json
from xml.sax.saxutils import escape, quoteattr

from analysis.plc.ir import Program, build_program
from analysis.plc.st import block_name, emit_scl, emit_st

__all__ = ["ST_FAMILY", "generate_st", "interface_map", "plcopen_xml", "validate_plcopen"]

ST_FAMILY = ("st", "scl", "plcopen-xml")
"""The dialects printed from the structured IR (no addresses: the block's interface)."""

_TC6 = "http://www.plcopen.org/xml/tc6_0201"
_XHTML = "http://www.w3.org/1999/xhtml"


def interface_map(program: Program, fb: str, dialect: str, units, trig: str) -> dict:
    """The interface map (MAP.json schema of :func:`analysis.plc.memmap.map_document`, the
    interface variables ``FB.name`` in place of addresses): the inputs with their units, the
    outputs, every status code with its meaning, what the block does before its first call;
    and the block, its instance DB (SCL), its functions, the trigonometry and REAL."""
    from analysis.plc.generate import status_codes
    from analysis.plc.memmap import map_document

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
            "name": "S7-1200/S7-1500 (TIA Portal, SCL source)"
            if dialect == "scl"
            else "IEC 61131-3 runtime (CODESYS, TwinCAT, OpenPLC)",
            "limits": {},
            "source": "no fixed addresses: the block's interface",
        },
        arm=program.arm,
        branch=program.branch,
    )
    doc.update(
        {
            "block": fb,
            "instance_db": f"{fb}_DB" if dialect == "scl" else None,
            "functions": [f"IK_{s.name}" for s in program.subroutines],
            "trig": trig,
            "real": "REAL (IEEE binary32); pulses rounded half away from zero (eqs. 20-22)",
        }
    )
    return doc


def plcopen_xml(st_text: str, program: Program, fb: str, units) -> str:
    """PLCopen XML (TC6 0201) of the ST source: one POU per function (return type REAL,
    input variables) and the function block (inputs, outputs, static variables), each body
    the ST statements of :func:`~analysis.plc.st.emit_st`."""
    bodies = _st_bodies(st_text)

    def var(name, typ, doc=""):
        d = (
            f"<documentation><xhtml xmlns={quoteattr(_XHTML)}>{escape(doc)}</xhtml></documentation>"
            if doc
            else ""
        )
        return f'<variable name="{name}"><type><{typ}/></type>{d}</variable>'

    pous = []
    for s in program.subroutines:
        name = f"IK_{s.name}"
        iface = (
            "<interface><returnType><REAL/></returnType>"
            f"<inputVars>{''.join(var(n, 'REAL') for n in s.inputs)}</inputVars>"
            f"<localVars>{''.join(var(n, 'REAL') for n in (*s.outputs, *s.temps))}</localVars>"
            "</interface>"
        )
        pous.append(_pou(name, "function", iface, bodies[name]))
    outs = "".join(var(c, "DINT", "pulses") for c in program.outputs)
    outs += var("reachable", "BOOL") + var("status", "DINT", "status code (see the map)")
    ins = "".join(var(n, "REAL", u) for n, u in zip(program.inputs, units, strict=True))
    iface = (
        "<interface>"
        f"<inputVars>{ins}</inputVars>"
        f"<outputVars>{outs}</outputVars>"
        f"<localVars>{''.join(var(n, 'REAL') for n in program.work)}</localVars>"
        "</interface>"
    )
    pous.append(_pou(fb, "functionBlock", iface, bodies[fb]))
    return (
        '<?xml version="1.0" encoding="utf-8"?>\n'
        f'<project xmlns="{_TC6}">\n'
        '<fileHeader companyName="analysis" productName="analysis.plc" productVersion="0.1.0" '
        'creationDateTime="2016-05-01T00:00:00"/>\n'
        f'<contentHeader name="{fb}"><coordinateInfo>'
        '<fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld>'
        '<sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>\n'
        f"<types><dataTypes/><pous>\n{''.join(pous)}</pous></types>\n"
        "<instances><configurations/></instances>\n"
        "</project>\n"
    )


def _pou(name: str, kind: str, interface: str, body: str) -> str:
    return (
        f'<pou name="{name}" pouType="{kind}">{interface}'
        f"<body><ST><xhtml xmlns={quoteattr(_XHTML)}>{escape(body)}</xhtml></ST></body>"
        "</pou>\n"
    )


def _st_bodies(text: str) -> dict[str, str]:
    """The statement part of each POU of an ST source (after its last END_VAR)."""
    out, name, lines, in_decl = {}, None, [], False
    for ln in text.split("\n"):
        head = ln.split()
        if head[:1] in (["FUNCTION"], ["FUNCTION_BLOCK"]):
            name, lines, in_decl = head[1], [], True
        elif ln in ("END_FUNCTION", "END_FUNCTION_BLOCK"):
            out[name] = "\n".join(lines).strip("\n") + "\n"
            name = None
        elif name is not None:
            if ln.startswith("VAR"):
                in_decl = True
            elif ln == "END_VAR":
                in_decl, lines = False, []
            elif not in_decl:
                lines.append(ln[4:] if ln.startswith("    ") else ln)
    return out


def validate_plcopen(xml: str):
    """Parse ``xml`` into the TC6 0201 schema model of the PyPI package ``plcopen``
    (xsdata; unknown elements, attributes and unconvertible values refused) and check that
    every element and attribute the schema requires is present. Returns the
    ``plcopen.Project``; raises ValueError naming what is wrong."""
    from plcopen import Project
    from xsdata.exceptions import ParserError
    from xsdata.formats.dataclass.parsers import XmlParser
    from xsdata.formats.dataclass.parsers.config import ParserConfig

    config = ParserConfig(fail_on_unknown_properties=True, fail_on_unknown_attributes=True,
                          fail_on_converter_warnings=True)  # fmt: skip
    try:
        project = XmlParser(config=config).from_string(xml, Project)
    except (ParserError, Exception) as exc:  # xsdata raises several kinds
        raise ValueError(f"not PLCopen XML TC6 0201: {exc}") from None
    missing = list(_missing_required(project, "project"))
    if missing:
        raise ValueError(f"PLCopen XML lacks required {', '.join(missing[:5])}")
    return project


def _missing_required(obj, path: str):
    if isinstance(obj, list):
        for k, item in enumerate(obj):
            yield from _missing_required(item, f"{path}[{k}]")
        return
    if not dataclasses.is_dataclass(obj):
        return
    for f in dataclasses.fields(obj):
        value = getattr(obj, f.name)
        if f.metadata.get("required") and (value is None or value == []):
            yield f"{path}.{f.metadata.get('name', f.name)}"
        if value is not None and not isinstance(value, (str, int, float)):
            yield from _missing_required(value, f"{path}.{f.metadata.get('name', f.name)}")


def generate_st(
    dialect: str,
    branch: str | None = None,
    trig: str | None = None,
    arm=None,
    theta1_on_axis: float | None = None,
) -> tuple[str, str]:
    """Program text and map JSON for ``dialect`` in :data:`ST_FAMILY` (module docstring)."""
    from analysis.kinematics.arm import paper_arm

    if dialect not in ST_FAMILY:
        raise ValueError(f"dialect {dialect!r} is not one of {', '.join(ST_FAMILY)}")
    arm = arm if arm is not None else paper_arm()
    trig = trig or "function"
    prog = build_program(arm, branch, trig, theta1_on_axis=theta1_on_axis)
    units = arm.input_units
    first = arm.branches[0]
    fb = block_name(prog, first)
    st_text = emit_st(prog, units=units, default_branch=first)
    if dialect == "st":
        text = st_text
    elif dialect == "scl":
        text = emit_scl(prog, units=units, default_branch=first)
    else:
        text = plcopen_xml(st_text, prog, fb, units)
        validate_plcopen(text)
    mjson = json.dumps(interface_map(prog, fb, dialect, units, trig), indent=2) + "\n"
    return text, mjson
