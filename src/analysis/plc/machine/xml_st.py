"""The ST source held in a PLCopen XML (TC6 0201) file, for the ST engine: ``stl-run
--dialect plcopen-xml`` executes the XML itself, not the ST it was printed from.

Every ``<pou>`` becomes its ST declaration: ``pouType`` function (with its ``returnType``),
functionBlock or program; each interface section its VAR section (``inputVars`` VAR_INPUT,
``outputVars`` VAR_OUTPUT, ``inOutVars`` VAR_IN_OUT, ``localVars`` VAR, ``tempVars``
VAR_TEMP); a variable's type an elementary element (``<REAL/>``) or ``<derived name=.../>``,
its ``initialValue/simpleValue``; the body the text of ``<body><ST>``, in either form a tool
writes it: CODESYS' ``<xhtml xmlns="http://www.w3.org/1999/xhtml">text</xhtml>`` or
OpenPLC/Beremiz' ``<xhtml:p><![CDATA[text]]></xhtml:p>``. The XML is parsed with defusedxml
(no entities, no external references) and bounded in size.
"""

from __future__ import annotations

import re

__all__ = ["MAX_XML_BYTES", "st_from_plcopen"]

MAX_XML_BYTES = 16 * 1024 * 1024
"""The largest PLCopen XML read (16 MiB; a generated machine program is about 100 kB)."""

_SECTIONS = {
    "inputVars": "VAR_INPUT",
    "outputVars": "VAR_OUTPUT",
    "inOutVars": "VAR_IN_OUT",
    "localVars": "VAR",
    "tempVars": "VAR_TEMP",
}
_KINDS = {"function": "FUNCTION", "functionBlock": "FUNCTION_BLOCK", "program": "PROGRAM"}
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


def _children(el, name: str):
    return [c for c in el if _local(c.tag) == name]


def _child(el, name: str):
    found = _children(el, name)
    return found[0] if found else None


def _ident(name: str | None, what: str) -> str:
    if not name or not _NAME.fullmatch(name):
        raise ValueError(f"PLCopen XML: {what} {name!r} is not an IEC 61131-3 identifier")
    return name


def _type(type_el, where: str) -> str:
    inner = list(type_el) if type_el is not None else []
    if len(inner) != 1:
        raise ValueError(f"PLCopen XML: {where} has no single type")
    t = inner[0]
    if _local(t.tag) == "derived":
        return _ident(t.get("name"), f"{where}'s type")
    return _ident(_local(t.tag), f"{where}'s type")


def _variable(v, pou: str) -> str:
    name = _ident(v.get("name"), f"a variable of {pou}")
    typ = _type(_child(v, "type"), f"{pou}.{name}")
    init = _child(v, "initialValue")
    value = ""
    if init is not None:
        simple = _child(init, "simpleValue")
        if simple is None or simple.get("value") is None:
            raise ValueError(f"PLCopen XML: {pou}.{name}: only a simpleValue initial value is read")
        text = simple.get("value")
        if any(c in text for c in ";\n\r") or "(*" in text:
            raise ValueError(
                f"PLCopen XML: {pou}.{name}: initial value {text!r} is not one literal"
            )
        value = f" := {text}"
    return f"    {name} : {typ}{value};"


def _body(pou_el, pou: str) -> str:
    body = _child(pou_el, "body")
    st = _child(body, "ST") if body is not None else None
    if st is None:
        raise ValueError(f"PLCopen XML: POU {pou} has no ST body (only ST is executed)")
    return "".join(st.itertext()).strip("\n")


def _pou(p) -> str:
    kind = p.get("pouType")
    name = _ident(p.get("name"), "a POU name")
    if kind not in _KINDS:
        raise ValueError(
            f"PLCopen XML: POU {name} has pouType {kind!r} (function, functionBlock or program)"
        )
    head = f"{_KINDS[kind]} {name}"
    iface = _child(p, "interface")
    lines = []
    if iface is not None:
        ret = _child(iface, "returnType")
        if kind == "function":
            head += f" : {_type(ret, f'{name} return')}"
        for section in iface:
            word = _SECTIONS.get(_local(section.tag))
            if word is None:
                if _local(section.tag) in ("returnType", "documentation"):
                    continue
                raise ValueError(
                    f"PLCopen XML: {name}: interface section {_local(section.tag)} is not read"
                )
            decls = [_variable(v, name) for v in _children(section, "variable")]
            if decls:
                lines += [word, *decls, "END_VAR"]
    end = "END_" + _KINDS[kind]
    return "\n".join([head, *lines, _body(p, name), end, ""])


def st_from_plcopen(xml: str | bytes) -> str:
    """The ST source of every POU of a PLCopen XML document (module docstring); ValueError
    naming what is not read."""
    from defusedxml import ElementTree
    from defusedxml.common import DefusedXmlException

    size = len(xml.encode("utf-8") if isinstance(xml, str) else xml)
    if size > MAX_XML_BYTES:
        raise ValueError(f"PLCopen XML of {size} bytes: at most {MAX_XML_BYTES} are read")
    try:
        root = ElementTree.fromstring(xml)
    except (ElementTree.ParseError, DefusedXmlException) as exc:
        raise ValueError(f"not PLCopen XML: {exc}") from None
    if _local(root.tag) != "project":
        raise ValueError(f"not PLCopen XML: the root is <{_local(root.tag)}>, not <project>")
    pous = [p for p in root.iter() if _local(p.tag) == "pou"]
    if not pous:
        raise ValueError("PLCopen XML: no POU")
    return "\n".join(_pou(p) for p in pous)
