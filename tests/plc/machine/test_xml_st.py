"""The ST read back from PLCopen XML (analysis.plc.machine.xml_st), in both body forms a tool
writes: CODESYS' ``<xhtml>text</xhtml>`` and OpenPLC/Beremiz' ``<xhtml:p><![CDATA[...]]>``;
what it does not read is refused in one line."""

from __future__ import annotations

import re

import pytest

from analysis.kinematics.arm import paper_arm
from analysis.plc.generate import generate
from analysis.plc.machine.xml_st import st_from_plcopen
from analysis.plc.st_engine import program_variables


def _openplc_form(xml: str) -> str:
    """The same XML with every ST body as OpenPLC's editor writes it (CDATA in xhtml:p)."""
    from xml.sax.saxutils import unescape

    def body(m):
        return (
            '<ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml"><![CDATA['
            f"{unescape(m.group(1))}]]></xhtml:p></ST>"
        )

    return re.sub(r'<ST><xhtml xmlns="http://www.w3.org/1999/xhtml">(.*?)</xhtml></ST>', body, xml,
                  flags=re.S)  # fmt: skip


def test_both_body_forms_read_the_same(machine_engine):
    xml = generate(paper_arm(), "plcopen-xml").program
    codesys, openplc = st_from_plcopen(xml), st_from_plcopen(_openplc_form(xml))
    assert codesys == openplc and "<![CDATA[" in _openplc_form(xml)
    assert "Axis3" in program_variables(openplc, "MACHINE_GRABBER")


@pytest.mark.parametrize(
    ("change", "word"),
    [
        (lambda x: x.replace('pouType="program"', 'pouType="class"'), "pouType 'class'"),
        (lambda x: x.replace('<variable name="Start">', '<variable name="St art">'), "identifier"),
        (lambda x: x.replace("<project", "<projekt").replace("</project>", "</projekt>"), "root"),
        (lambda x: x[:-200], "not PLCopen XML"),
        (lambda x: '<!DOCTYPE p [<!ENTITY a "aaaa">]>' + x.split("?>", 1)[1], "not PLCopen XML"),
    ],
)
def test_refused(change, word):
    xml = generate(paper_arm(), "plcopen-xml").program
    with pytest.raises(ValueError, match=re.escape(word)):
        st_from_plcopen(change(xml))
