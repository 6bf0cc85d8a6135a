"""The registers of every paper, built from data/registers/, and the mutation harness.

``test_manifestation[<id>]``: the check rejects the printed text (a finding) or accepts it
(what holds), accepts the correction, and an uncertain row's readings differ in verdict; the
mutation harness over every row is tests/audit/test_harness.py.
``test_cause[<id>]``: the cause's demonstration holds on the printed texts and fails once they
are replaced by the corrections. The generated files are what the registers give; the cause set
is the one before issue 20 with each deliberate change listed in the register's [[change]].
"""

from __future__ import annotations

import csv
import re
import tomllib
from pathlib import Path

import pytest

from analysis import audit
from analysis.audit import register as reg
from analysis.audit import schema
from analysis.audit.context import context
from analysis.paths import data_dir

PAPERS = reg.available()
HERE = Path(__file__).parent


def _rows(kind: str):
    for p in PAPERS:
        for row in schema.read_rows(reg.register_path(p)):
            if bool(row["cause"]) == (kind == "manifestation"):
                yield pytest.param(p, row["id"], id=row["id"])


@pytest.mark.parametrize(("paper", "mid"), list(_rows("manifestation")))
def test_manifestation(paper, mid):
    m = reg.register(paper).manifestation(mid)
    if m.status == "holds":
        assert m.verify(m.checked), f"{mid}: what the paper prints fails its check"
    elif m.status == "uncertain":  # not an error: the ambiguity itself is what is shown
        _assert_ambiguous(paper, m)
    else:
        assert not m.holds(m.checked), f"{mid}: the printed text passes the check"
    assert m.verify(m.corrected), f"{mid}: the correction {m.corrected!r} fails its check"
    assert not m.verify("nonsense") and not m.verify(m.corrected + "  # note")


def _assert_ambiguous(paper, m):
    """An uncertain row proves its ambiguity (counting rule 5): at least two readings, each
    computed, that differ in verdict (what each implies), the correction one of them, and the
    cause names the lost records that would decide (type ``lost`` in the paper's data)."""
    assert len(m.readings) >= 2 and m.corrected in m.readings, m.id
    verdicts = [m.holds(t) for t in m.readings]
    assert len(set(verdicts)) == 2, f"{m.id}: the readings agree ({verdicts})"
    cause = reg.register(paper).cause(m.cause)
    paper_data = context(paper).paper
    assert cause.decided_by, f"{m.cause}: no lost data named that would decide"
    assert all(paper_data.record(r).type == "lost" for r in cause.decided_by), cause.decided_by


@pytest.mark.parametrize(("paper", "cid"), list(_rows("cause")))
def test_cause(paper, cid):
    cause = reg.register(paper).cause(cid)
    assert cause.demonstrate(), f"{cid}: the demonstration does not hold"
    if cause.status != "holds" and cause.manifestations:
        fixed = {m.id: m.corrected for m in cause.manifestations}
        assert not cause.demonstrate(fixed), f"{cid}: demonstrated with the corrections printed"
    if cause.status in schema.COUNTED:
        assert cause.severity in schema.SEVERITIES and cause.consequence


@pytest.mark.parametrize("paper", PAPERS)
def test_register_file_is_generated_and_valid(paper):
    path = reg.register_path(paper)
    assert path.read_text(encoding="utf-8") == reg.register(paper).csv_text()
    rows = schema.read_rows(path)
    assert {r["check"] for r in rows} >= {c.check for c in reg.register(paper).causes}


def test_items_table_is_the_register():
    """grabber_items.csv is generated from the register: one source, never disagreeing."""
    path = data_dir() / "errata" / "grabber_items.csv"
    with path.open(encoding="utf-8", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert rows == reg.items_table("grabber")
    status = {c.id: c.status for c in reg.register("grabber").causes}
    for row in rows:
        want = reg.VERDICT.get(status[row["id"].split("/")[0]], status[row["id"].split("/")[0]])
        assert row["verdict"] == want, row["id"]


def test_every_printed_cell_is_checked_once():
    """Every cell of the matrices and tables the holds rows expand is either a check that
    holds or a manifestation of a cause (seed 000)."""
    raw = tomllib.loads(reg.source_path("grabber").read_text(encoding="utf-8"))
    refs = [m.source for m in reg.register("grabber").manifestations]
    for c in raw["cause"]:
        for e in c.get("each", ()):
            for _, ref, _, _ in reg.each_cells(e, context("grabber").paper):
                assert refs.count(ref) == 1, ref


@pytest.mark.parametrize("paper", PAPERS)
def test_printed_texts_are_references_and_checks_never_hold_the_answer(paper):
    """A register refers to printed text (never retypes it), and no check spec contains the
    text it is to decide (a check cannot compare with the register's words)."""
    raw = tomllib.loads(reg.source_path(paper).read_text(encoding="utf-8"))
    for c in raw["cause"]:
        for m in c.get("manifestation", ()):
            p = m["printed"]
            parts = [p] if isinstance(p, str | dict) else p
            refs = [x if isinstance(x, str) else x.get("of", "@") for x in parts]
            assert all(isinstance(x, str) and x.startswith("@") for x in refs) or "order" in p, m
    for m in reg.register(paper).manifestations:  # the check in use: the row's or its record's
        spec = repr(m.spec)
        for text in (m.corrected, m.reading):
            assert not text or len(text) < 4 or text not in spec, m.id


def test_old_causes_are_all_accounted_for():
    """The causes before issue 20 (tests/audit/data/causes_before.csv): each is in the new
    registers with its status, or a deliberate [[change]] of its register says what became of
    it; and every change names a cause that existed."""
    with (HERE / "data" / "causes_before.csv").open(encoding="utf-8", newline="") as fh:
        rows = list(csv.DictReader(fh))
    before = [r for r in rows if not r["cause"]]
    for p in PAPERS:
        r = reg.register(p)
        now = {c.id: c.status for c in r.causes}
        changes = {ch["old"]: ch for ch in r.changes if "old" in ch}
        current = {c.id for c in r.causes} | {m.id for m in r.manifestations}
        for ch in (ch for ch in r.changes if "old" not in ch):  # a change of a current row
            assert ch["id"] in current and ch["why"].strip() and ch["issue"] >= 30, ch
        ids = {row["id"] for row in rows if row["paper"] == p}
        assert set(changes) <= ids, set(changes) - ids
        for row in (x for x in before if x["paper"] == p):
            ch = changes.get(row["id"])
            if ch is None:
                assert now.get(row["id"]) == row["status"], f"{row['id']}: lost or changed silently"
            else:
                assert ch["why"].strip()
                if "new" in ch:
                    target = ch["new"].split("/")[0]
                    assert target in now or ch["new"] in {m.id for m in r.manifestations}, ch
                if "status" in ch:
                    assert now[row["id"]] == ch["status"], ch


def test_manifestations_api():
    """analysis.audit.manifestations(): every manifestation of every register, the contract."""
    ms = list(audit.manifestations())
    assert len(ms) > 100
    for m in ms[:: max(1, len(ms) // 40)]:
        for attr in ("id", "cause", "status", "printed", "corrected"):
            assert isinstance(getattr(m, attr), str), attr
        assert m.status in schema.STATUSES and m.id.startswith(m.cause + "/")
        assert isinstance(m.verify(m.corrected), bool)
        assert m.verify("nonsense") is False


def test_counting_rule_is_one_for_every_paper():
    block = reg.render_markdown()
    assert schema.COUNTING_RULE[1] in block
    for p in PAPERS:
        r = reg.register(p)
        for c in r.causes:
            if c.status in schema.COUNTED:
                assert c.manifestations, f"{c.id}: a counted cause shows somewhere"
        assert r.summary.get("verdict") and r.summary.get("take_away"), p


def test_summary_has_a_headline_and_the_worst_consequence_in_numbers():
    """Every register's [summary]: a headline of at most 15 words (the front page's verdict at a
    glance) and the worst consequence with its numbers filled from the checks."""
    for p in PAPERS:
        s = reg.register(p).summary
        assert set(s) == set(schema.SUMMARY_KEYS), p
        assert len(s["headline"].split()) <= schema.HEADLINE_WORDS, p
        assert re.search(r"\d", s["worst"]) and "{" not in s["worst"], (p, s["worst"])


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"colour": "red"}, "unknown key 'colour'"),
        ({"headline": None}, "missing key 'headline'"),
        ({"headline": " ".join(["word"] * 16)}, "16 words, at most 15"),
        ({"headline": "Off by 180 degrees."}, "types a number"),
        ({"worst": "The arm misses by a lot."}, "names no computed number"),
        ({"verdict": ""}, "verdict must be a non-empty string"),
    ],
)
def test_summary_schema_refuses(change, message):
    raw = {"headline": "A short verdict.", "worst": "Off by {facts.x} mm.", "verdict": "v",
           "take_away": "t"} | change  # fmt: skip
    raw = {k: v for k, v in raw.items() if v is not None}
    with pytest.raises(ValueError, match=re.escape(message)):
        schema.check_summary("paper", raw)
    schema.check_summary("paper", {"headline": "A short verdict.", "worst": "{facts.x} mm",
                                   "verdict": "v", "take_away": "t"})  # fmt: skip


_TEMPLATE = re.compile(r"\{[A-Za-z_][\w.]*(?:\[[^\]{}]*\])*(?:![rsa])?(?::[^{}]*)?\}")
"""A replacement field of str.format left in a text ({facts.dims}, {printed.value:.2f})."""


@pytest.mark.parametrize("paper", PAPERS)
def test_every_template_is_rendered(paper):
    """No generated text keeps a '{...}' field: titles, evidence, consequences, what a row
    rests on, the alternatives, the summary, the register file and the README block."""
    r = reg.register(paper)
    texts = [*r.summary.values(), reg.render_markdown([paper])]
    for c in r.causes:
        texts += [c.title, c.evidence, c.consequence, *c.rests_on]
        for m in c.manifestations:
            texts += [m.evidence, *m.rests_on, *m.alternatives]
    left = sorted({f for t in texts for f in _TEMPLATE.findall(t)})
    assert not left, left
    generated = {k for row in r.rows() for k in (row["evidence"], row["rests_on"])}
    assert not [t for t in generated if _TEMPLATE.search(t)]


def test_the_claim_tolerance_is_a_column_appended_to_every_export(capsys):
    """The tolerance a max/min claim's check applies is in the CSV, the item table and
    ``errata --json`` (a column appended after ``check``: outside checks read the order), and
    it is the one the check computed on the correction."""
    import json

    from analysis.app.cli import main

    assert schema.COLUMNS[-2:] == ("check", "tolerance") and reg.ITEM_COLUMNS[-2:] == ("check", "tolerance")  # noqa: E501
    assert main(["errata", "--json"]) == 0
    exported = {r["id"]: r for rows in json.loads(capsys.readouterr().out).values() for r in rows}
    n = 0
    for paper in PAPERS:
        r = reg.register(paper)
        rows = {row["id"]: row for row in r.rows()}
        for m in r.manifestations:
            if m.id not in rows:  # a holds cause of more than 3 rows: the item table's
                continue
            assert exported[m.id]["tolerance"] == rows[m.id]["tolerance"], m.id
            if m.spec.get("kind") == "claim" and re.match(r"(max|min) ", m.corrected):
                assert rows[m.id]["tolerance"] == f"{m.result(m.corrected).values['tol']:.3g}", m.id
                n += 1
            else:
                assert rows[m.id]["tolerance"] == "", m.id
    assert n >= 20
    assert exported["grabber-claim-accuracy/claim"]["tolerance"] == "2.25e-05"  # 0.045: 5e-4 of it
    assert exported["pal-claim-unique/initial-pose"]["tolerance"] == "0.045"  # 90: half a unit


def test_what_decides_an_uncertain_row_says_whether_it_was_lost_or_never_printed(tmp_path):
    """A ``lost`` record's provenance: lost in extraction (location '(extraction) ...') or never
    printed ('(not printed) ...'); Figure 5's order rests on the program, which was never
    printed (grabber-fig5-order); an unknown provenance is refused, naming the record."""
    from analysis.papers import PROVENANCE, load, load_file, names

    for paper in names():
        for rec in load(paper).records.values():
            if rec.type == "lost":
                prov = rec.get("provenance", PROVENANCE[0])
                assert rec.location.startswith("(extraction)" if prov == PROVENANCE[0] else "(not printed)"), rec.id  # noqa: E501
    (rid,) = reg.register("grabber").cause("grabber-fig5-order").decided_by
    assert load("grabber").record(rid)["provenance"] == "not printed"
    src = (data_dir() / "papers" / "grabber.toml").read_text(encoding="utf-8")
    bad = tmp_path / "grabber.toml"
    bad.write_text(src.replace('"not printed"', '"misplaced"'), encoding="utf-8")
    with pytest.raises(ValueError, match=r"unprinted.program: provenance 'misplaced' not in"):
        load_file(bad.resolve())
