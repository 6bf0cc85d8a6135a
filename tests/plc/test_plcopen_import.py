"""The PLCopen XML imported the way OpenPLC Editor / Beremiz read it (issue 29 item 5), and
executed from the XML itself on the ST engine.

How Beremiz loads a project (read in its source, ``plcopen/plcopen.py`` ``LoadProjectXML`` and
``xmlclass/xmlclass.py`` ``GenerateAnyInfos``; described here, not copied): a CDATA section
that is not inside an ``xhtml:p`` element is wrapped in one, and every ``formattedText`` (a
POU's ``<body><ST>``, a variable's ``<documentation>``) is read as the text of its first child
``p`` in the XHTML namespace; the project is parsed against the TC6 0201 schema. A body in
CODESYS' form ``<xhtml xmlns=...>text</xhtml>`` has no such ``p``: it would import as nothing.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm
from analysis.plc.generate import generate
from analysis.plc.plcopen import validate_plcopen

TC6 = "{http://www.plcopen.org/xml/tc6_0201}"
XHTML = "{http://www.w3.org/1999/xhtml}"
SECTIONS = {"inputVars": "VAR_INPUT", "outputVars": "VAR_OUTPUT", "localVars": "VAR"}
KINDS = {"function": "FUNCTION", "functionBlock": "FUNCTION_BLOCK"}


def beremiz_text(formatted) -> str:
    """A formattedText as Beremiz reads it: the text of its first ``xhtml:p`` (IndexError,
    as there, if it has none)."""
    return formatted.findall(f"{XHTML}p")[0].text or ""


def beremiz_import(xml: str) -> list[tuple[str, str, list, str]]:
    """The POUs as Beremiz loads them: (name, kind, [(section, name, type)], body)."""
    wrapped = re.sub(r"(?<!<xhtml:p>)<!\[CDATA\[", "<xhtml:p><![CDATA[", xml)
    wrapped = re.sub(r"]]>(?!</xhtml:p>)", "]]></xhtml:p>", wrapped)
    assert wrapped == xml, "a CDATA section outside xhtml:p (Beremiz would rewrite it)"
    root = ET.fromstring(xml)
    pous = []
    for pou in root.iter(f"{TC6}pou"):
        decls = []
        for section in pou.find(f"{TC6}interface"):
            for var in section.iter(f"{TC6}variable"):
                (typ,) = list(var.find(f"{TC6}type"))
                decls.append((section.tag[len(TC6) :], var.get("name"), typ.tag[len(TC6) :]))
                doc = var.find(f"{TC6}documentation")
                if doc is not None:
                    beremiz_text(doc)  # documentation is formatted text too
        body = beremiz_text(pou.find(f"{TC6}body/{TC6}ST"))
        pous.append((pou.get("name"), pou.get("pouType"), decls, body))
    return pous


def st_source(pous) -> str:
    """The ST program those POUs are (what an IEC 61131-3 runtime compiles)."""
    out = []
    for name, kind, decls, body in pous:
        ret = [t for s, _, t in decls if s == "returnType"]
        out.append(f"{KINDS[kind]} {name}" + (" : REAL" if kind == "function" else ""))
        for section, keyword in SECTIONS.items():
            lines = [f"    {n} : {t};" for s, n, t in decls if s == section]
            if lines:
                out += [keyword, *lines, "END_VAR"]
        out += [body, f"END_{KINDS[kind]}", ""]
        assert not ret
    return "\n".join(out)


@pytest.mark.parametrize("name", ["grabber", "palletizer", "gr1", "picker"])
def test_beremiz_reads_every_body_and_document(name):
    """Every POU's body and every documentation has the ``xhtml:p`` Beremiz reads, the
    interface declares every name the body uses (the grabber's ``v_d``, ``v_s``), and the
    file validates against the TC6 0201 schema model."""
    xml = generate(load_arm(name), "plcopen-xml").program
    validate_plcopen(xml)
    pous = beremiz_import(xml)
    assert [p[1] for p in pous].count("functionBlock") == 1
    for _, _, decls, body in pous:
        assert body.strip()
        declared = {n.upper() for _, n, _ in decls}
        assigned = {m.upper() for m in re.findall(r"^\s*(\w+) :=", body, re.M)}
        assert assigned <= declared | {p[0].upper() for p in pous}, assigned - declared


def test_the_grabber_imported_as_beremiz_does_runs_as_the_st(request):
    """The IK block read from the XML the Beremiz way computes, on the ST engine, what the
    ST dialect's text computes: the same counts and statuses on the Table 4 targets and
    beyond the reach."""
    from analysis.plc import st_engine
    from analysis.plc.targets import table4_targets
    from analysis.plc.verify import reference_pulses

    try:
        st_engine.engine_path()
    except st_engine.EngineMissing as exc:
        pytest.skip(str(exc))
    arm = load_arm("grabber")
    xml = generate(arm, "plcopen-xml", motion=False).program
    st = generate(arm, "st", motion=False).program
    targets = np.vstack([table4_targets(), [[5000.0, 0.0, 0.0], [0.0, 0.0, 900.0]]])
    runs = []
    for source in (st_source(beremiz_import(xml)), st):
        res, _ = st_engine.sweep(source, "IK_GRABBER", ["px", "py", "pz"], 3, targets)
        runs.append((res.pulses.tolist(), res.status.tolist()))
    assert runs[0] == runs[1]
    pulses, ok, status, _ = reference_pulses(arm, targets)  # Python, float64
    assert runs[0][1] == status.tolist()
    assert np.array_equal(np.array(runs[0][0])[ok], pulses[ok])
