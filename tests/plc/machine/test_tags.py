"""The machine's signals as a TIA Portal PLC tag table and a CODESYS GVL (``stl --tags
--gvl``): the workbook TIA's tag editor imports (sheet "PLC Tags", its ten columns), read back
with openpyxl; every name and type held to the machine program as the ST engine compiled it."""

from __future__ import annotations

import re

import pytest
from tests.plc.machine.conftest import ARMS, machine

from analysis.app.cli import main
from analysis.plc.machine.tags import TIA_COLUMNS, codesys_gvl, signals
from analysis.plc.st_engine import program_variables

_TIA = {"Bool": "BOOL", "Int": "INT", "DInt": "DINT", "Real": "REAL"}


@pytest.mark.parametrize("arm", ARMS)
def test_tag_table_and_gvl(machine_engine, tmp_path, arm):
    from openpyxl import load_workbook

    _, spec, source, program, mapdoc = machine(arm)
    variables = program_variables(source, program)
    rc = main(["stl", "--arm", arm, "--dialect", "scl", "-o", str(tmp_path / "m.scl"),
               "--tags", str(tmp_path / "t.xlsx"), "--gvl", str(tmp_path / "g.st")])  # fmt: skip
    assert rc == 0
    ws = load_workbook(tmp_path / "t.xlsx")["PLC Tags"]
    rows = list(ws.iter_rows(values_only=True))
    assert rows[0] == TIA_COLUMNS
    for name, _, typ, address, *_ in rows[1:]:
        assert variables[name] == _TIA[typ], name
        assert re.fullmatch(r"%(I|Q)\d+\.[0-7]|%MD\d+|%MW\d+|%M\d+\.[0-7]", address), address
    assert len({r[3] for r in rows[1:]}) == len(rows) - 1  # every address once
    assert [r[0] for r in rows[1:]] == [n for n, *_ in signals(spec)]
    gvl = (tmp_path / "g.st").read_text("utf-8")
    assert gvl == codesys_gvl(spec)
    decls = re.findall(r"^    (\w+)(?: AT (%[IQ]X\d+\.\d))? : (\w+);", gvl, flags=re.M)
    assert [d[0] for d in decls] == [n for n, *_ in signals(spec)]
    assert all(variables[n] == t for n, _, t in decls)
    assert [s["name"] for s in mapdoc["machine"]["signals"]] == [n for n, *_ in signals(spec)]


def test_tags_need_the_machine(capsys, tmp_path):
    rc = main(["stl", "--dialect", "st", "--no-motion", "-o", str(tmp_path / "p.st"), "--tags",
               str(tmp_path / "t.xlsx")])  # fmt: skip
    assert rc == 2 and "--tags and --gvl are the machine program's" in capsys.readouterr().err
    assert not (tmp_path / "p.st").exists()
