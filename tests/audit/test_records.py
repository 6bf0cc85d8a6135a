"""Every printed record checked and every failure explained (issue 30, item 1).

The four papers: no record fails without a cause that explains it, no counted cause names only
records whose checks pass, no printed record lacks a check. The example paper written for the
purpose (tests/audit/example: a D-H table, a matrix with a wrong sign, a table with a wrong
cell, a false claim) is reported before any cause is written; its register explains it; a cause
deleted or a printed symbol changed turns the audit red, naming the record.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from analysis.audit import harness, records
from analysis.audit import register as reg
from analysis.audit.context import Context, bespoke, context
from analysis.papers import load, names

EXAMPLE = Path(__file__).parent / "example"


@pytest.mark.parametrize("paper", names())
def test_every_printed_record_is_checked_and_explained(paper):
    r = reg.register(paper)
    assert not r.findings, "\n".join(r.findings)
    n = r.record_counts
    assert n["units"] > 0 and n["pass"] + n["fail"] == n["units"] and n["explained"] == n["fail"]


def test_the_example_paper_is_reported_before_any_cause_is_written():
    r = reg.audit_file(EXAMPLE / "paper.toml")
    assert r.findings == (
        "unexplained: example eq. 2 row 1 col 2 (@A2[1,2]): the printed cell differs from the product",  # noqa: E501
        "unexplained: example Table 2 row 3 y_mm (@fk_table[3].y_mm): the printed cell differs from its recomputation",  # noqa: E501
        "unexplained: example sec. 3 (@reach): the claim does not hold",
    )
    assert r.record_counts["pass"] > 50  # the D-H trig cells, A1, T2, the other Table 2 cells


def test_the_example_register_explains_it_and_each_cause_is_needed():
    path = EXAMPLE / "register.toml"
    r = reg.audit_file(EXAMPLE / "paper.toml", path)
    assert r.findings == ()
    assert all(c.demonstrate() for c in r.causes)
    rep = harness.run_paper(r, Context(load_example(), bespoke("example", load_example())))
    assert rep.objects == 3 and not rep.accepted and not rep.demonstrated_with_corrections
    raw = tomllib.loads(path.read_text(encoding="utf-8"))
    for k, cause in enumerate(raw["cause"]):  # delete one cause: its record is unexplained again
        less = {"cause": raw["cause"][:k] + raw["cause"][k + 1 :]}  # (the summary names them)
        ctx = Context(load_example(), bespoke("example", load_example()))
        found = reg.build(ctx, less).findings
        assert len(found) == 1 and found[0].startswith("unexplained: example"), (cause["id"], found)


def test_a_cause_naming_a_record_that_holds_explains_nothing():
    raw = {"cause": [{
        "id": "ex-a1", "status": "error", "kind": "sign", "severity": "cosmetic",
        "consequence": "none", "title": "A1 is wrong",
        "manifestation": [{"id": "c", "printed": "@A1[1,2]", "corrected": "sin(theta1)"}],
    }]}  # fmt: skip
    ctx = Context(load_example(), bespoke("example", load_example()))
    found = reg.build(ctx, raw).findings
    assert any(f.startswith("explains nothing: ex-a1/c names example eq. 1 row 1 col 2") for f in found)  # noqa: E501


def load_example():
    from analysis.papers import load_file

    return load_file((EXAMPLE / "paper.toml").resolve())


@pytest.mark.parametrize(("paper", "record", "old", "new"), [
    ("palletizer", "eq2", 'lhs = "L4p"', 'lhs = "L3p"'),  # a holds record's symbol (issue 30)
    ("grabber", "eq7", "L2*cos(theta2)", "L3*cos(theta2)"),
    ("gr1", "4.2-c3", "a2**2 - a3**2", "a2**2 - a4**2"),
])
def test_a_printed_symbol_changed_in_a_record_that_holds_turns_red(tmp_path, paper, record, old, new):  # noqa: E501
    src = (reg.data_dir() / "papers" / f"{paper}.toml").read_text(encoding="utf-8")
    head, _, rest = src.partition(f'id = "{record}"\n')
    body, sep, tail = rest.partition("[[record]]")
    assert old in body, (record, old)
    copy = tmp_path / f"{paper}.toml"
    copy.write_text(head + f'id = "{record}"\n' + body.replace(old, new, 1) + sep + tail, encoding="utf-8")  # noqa: E501
    r = reg.audit_file(copy, reg.source_path(paper))
    assert any(f"(@{record}" in f for f in r.findings), r.findings


def test_units_split_as_their_checks_decide():
    us = {u.ref: u for u in records.units(load("grabber"))}
    assert "@eq12[2,2]" in us and "@table4[1].theta2_deg" in us and "@accuracy" in us
    assert us["@table4[8].theta2_deg"].text == "无解"
    pal = {u.ref for u in records.units(load("palletizer"))}
    assert {"@eq3#1", "@eq3#2", "@eq3#3"} <= pal


def test_errata_reports_the_example_paper(capsys):
    from analysis.app.cli import main

    code = main(["errata", "--paper-file", str(EXAMPLE / "paper.toml")])
    out = capsys.readouterr().out
    assert code == 1 and out.count("unexplained: example") == 3, out
    code = main(["errata", "--paper-file", str(EXAMPLE / "paper.toml"),
                 "--register", str(EXAMPLE / "register.toml")])  # fmt: skip
    assert (code, capsys.readouterr().out.strip()) == (0, "explained")


def test_each_never_drops_a_cell():
    """A holds cause's [[cause.each]] whose check a cell fails (here a typo: A1's cells held
    against A2's product) is an error naming the cell, not a cause with fewer rows."""
    path = reg.source_path("grabber")
    raw = tomllib.loads(path.read_text(encoding="utf-8"))
    cause = next(c for c in raw["cause"] if c["id"] == "grabber-matrices-hold")
    cause["each"] = [{"matrix": "A1", "check": {"kind": "matrix", "product": ["A2"]}}]
    raw["cause"] = [cause]
    cell = r"unexplained: grabber sec\. 1\.2 A_1 row 1 col 1 \(@A1\[1,1\]\)"
    with pytest.raises(ValueError, match=cell):
        reg.build(context("grabber"), raw)
    cause["each"] = [{"matrix": "A1"}]  # the record's own check: every cell a row
    built = reg.build(context("grabber"), raw)
    assert len(built.cause("grabber-matrices-hold").manifestations) == 16
