"""PLCopen XML (TC6 0201) of the ST program: a printer of its own, and the schema check.

:class:`PlcopenXmlPrinter` (``--dialect plcopen-xml``) prints the ST printer's blocks
(:meth:`~analysis.plc.st.StPrinter.pous`) as PLCopen XML: one ``<pou>`` per function (return
type REAL, input variables) and the function block (inputs, outputs, static variables), each
body the ST statements. :func:`validate_plcopen` parses a text into the TC6 0201 schema model
of the PyPI package ``plcopen`` (xsdata) and checks every required element and attribute; the
generator refuses what does not validate.

Formatted text (a body, a variable's documentation) is written as
``<xhtml:p><![CDATA[...]]></xhtml:p>`` (:func:`formatted_text`), the prefix declared on the
project: OpenPLC Editor and Beremiz read a ``formattedText`` as the text of its first
``xhtml:p`` element (Beremiz ``xmlclass.GenerateAnyInfos``; a bare CDATA they wrap in one
when loading), so CODESYS' ``<xhtml xmlns=...>text</xhtml>`` imports there as nothing, while
CODESYS and TwinCAT take any XHTML content, ``xhtml:p`` included.
"""

from __future__ import annotations

import dataclasses
from typing import ClassVar

from analysis.escape import xml_attr, xml_cdata
from analysis.plc.instr import Program
from analysis.plc.st import Pou, StPrinter, block_name

__all__ = ["PlcopenXmlPrinter", "validate_plcopen"]

_TC6 = "http://www.plcopen.org/xml/tc6_0201"
_XHTML = "http://www.w3.org/1999/xhtml"


def formatted_text(text: str) -> str:
    """PLCopen ``formattedText`` content both tools read (module docstring)."""
    return f"<xhtml:p><![CDATA[{xml_cdata(text)}]]></xhtml:p>"


class PlcopenXmlPrinter(StPrinter):
    """PLCopen XML TC6 0201 of the ST blocks (module docstring)."""

    name = "plcopen-xml"
    engine = "pyplcopen's ST engine, the ST read from the XML (analysis.plc.machine.xml_st)"
    title = "PLCopen XML (TC6 0201) of the ST block (CODESYS, TwinCAT import)"
    target = "PLCopen XML"
    count_note = "pulses"
    reachable_note = ""
    sections: ClassVar[dict[str, str]] = {
        "input": "inputVars", "output": "outputVars", "temp": "localVars", "static": "localVars",
    }  # fmt: skip

    def status_note(self, codes) -> str:
        return "status code (see the map)"

    def text(self, text: str) -> str:
        """A comment's text as in ST, and no ``]]>`` (it ends a CDATA section)."""
        out = super().text(text)
        while "]]>" in out:
            out = out.replace("]]>", "]] >")
        return out

    def variable(self, name: str, typ: str, doc: str = "") -> str:
        d = (
            f"<documentation>{formatted_text(doc)}</documentation>"
            if doc
            else ""
        )
        return f'<variable name="{xml_attr(name)}"><type><{typ}/></type>{d}</variable>'

    def interface(self, pou: Pou) -> str:
        parts = ["<returnType><REAL/></returnType>"] if pou.kind == "function" else []
        for kind, decls in pou.sections:
            tag = self.sections[kind]
            inner = "".join(self.variable(d.ident, d.type, d.note) for d in decls)
            parts.append(f"<{tag}>{inner}</{tag}>")
        return f"<interface>{''.join(parts)}</interface>"

    def print_pou(self, pou: Pou) -> str:
        body = "\n".join(pou.body).strip("\n") + "\n"
        doc = getattr(self, "about", {}).get(pou.name)
        doc = f"<documentation>{formatted_text(doc)}</documentation>" if doc else ""
        return (
            f'<pou name="{xml_attr(pou.name)}" pouType="{pou.kind}">{self.interface(pou)}'
            f"<body><ST>{formatted_text(body)}</ST></body>{doc}"
            "</pou>\n"
        )

    def doprint_program(self, program: Program, *, units, default_branch=None) -> str:
        fb = block_name(program, default_branch)
        # the header the ST text opens with: the block's documentation here
        self.about = {fb: "\n".join(self.text(n) for n in (program.title, *program.notes))}
        pous = "".join(self.print_pou(p) for p in self.pous(program, fb, units))
        return (
            '<?xml version="1.0" encoding="utf-8"?>\n'
            f'<project xmlns="{_TC6}" xmlns:xhtml="{_XHTML}">\n'
            '<fileHeader companyName="analysis" productName="analysis.plc" productVersion="0.1.0" '
            'creationDateTime="2016-05-01T00:00:00"/>\n'
            f'<contentHeader name="{xml_attr(fb)}"><coordinateInfo>'
            '<fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld>'
            '<sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>\n'
            f"<types><dataTypes/><pous>\n{pous}</pous></types>\n"
            "<instances><configurations/></instances>\n"
            "</project>\n"
        )

    @classmethod
    def check_text(cls, text: str) -> None:
        validate_plcopen(text)


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
