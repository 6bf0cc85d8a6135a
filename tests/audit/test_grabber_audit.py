"""Seed 000's item audit: every printed statement re-derived, the file current.

``test_item_verdict[<id>]`` re-derives one audited item (those that hold included) and
checks the verdict recorded in ``data/errata/grabber_items.csv``.
"""

import csv

import pytest

from analysis.audit import grabber_audit as audit
from analysis.audit import register as reg
from analysis.paths import data_dir

ROWS = list(csv.DictReader((data_dir() / "errata" / "grabber_items.csv").open(encoding="utf-8")))


@pytest.mark.parametrize("row", [pytest.param(r, id=r["id"]) for r in ROWS])
def test_item_verdict(row):
    it = audit.item(row["id"])
    assert it.verdict == row["verdict"]
    assert it.verify(it.printed) == (it.verdict == "holds")
    assert row["check"] == it.check


def test_items_file_is_current():
    assert [dict(r) for r in ROWS] == audit.audit_table()


def test_coverage_counts():
    items = audit.audit()
    assert len(items) == len(ROWS) == 236
    assert all(it.verdict in ("holds", "wrong", "undecidable") for it in items)
    verdicts, _ = audit.coverage()
    assert int(verdicts.loc["wrong"].iloc[0]) == sum(it.verdict == "wrong" for it in items)
    assert reg.register("grabber")  # builds (and checks the coverage of wrong items)
