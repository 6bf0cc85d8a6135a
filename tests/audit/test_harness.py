"""The mutation harness over every object of analysis.audit.manifestations() (issue 30, item 3).

Per paper: tautologies, unrelated true statements, comments appended and single edits of the
correction (sign, index, digit, symbol, sin/cos, threshold), each held against the correction
with SymPy first, must fail ``verify``; for a ``holds`` row and for every printed record whose
own check passes, the same edits of the printed text must fail the check itself; every cause's
demonstration must fail once its corrections are printed. The counts are written to
build/audit-harness/<paper>.json (and printed by ``python -m analysis.audit.harness``): 0
tautologies and 0 non-equivalent texts accepted.
"""

from __future__ import annotations

import json

import pytest

from analysis.audit import harness
from analysis.audit import register as reg
from analysis.audit.context import context
from analysis.paths import build_dir

pytestmark = pytest.mark.slow


@pytest.mark.parametrize("paper", reg.available())
def test_harness_accepts_nothing_it_should_refuse(paper):
    r = reg.register(paper)
    report = harness.run_paper(r, context(paper), per_kind=2)
    objects = report.objects
    harness.run_records(r, context(paper), per_kind=2, report=report)  # the records that hold
    out = {**report.to_dict(), "manifestations": objects, "records": report.objects - objects}
    path = build_dir() / "audit-harness" / f"{paper}.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(out, indent=1, ensure_ascii=False), encoding="utf-8")
    assert out["manifestations"] == len(r.manifestations) > 0
    assert out["probes"] >= 10 * out["objects"], out["by_kind"]
    for kind in ("tautology", "unrelated", "comment", *harness.EDIT_KINDS):
        if kind not in ("symbol", "trig", "threshold", "index"):  # not every text has those
            assert out["by_kind"].get(kind, 0) > 0, kind
    assert not report.accepted, report.accepted[:5]
    assert not report.demonstrated_with_corrections, report.demonstrated_with_corrections
