"""Seed 002's findings that rest on readings recorded as data: the novelty claim against the
works its introduction reviews (``pick-claim-novelty``), and the claims for the arm's structure
against the test hardware (``pick-claim-structure``).

Each cited work is recorded as our reading of the text's words for it (``prior_work.cited`` in
data/papers/picker.toml), and the claim of novelty as its own reading (``novelty.reads_as``);
the domain ``prior_methods`` compares the two field by field. The verdict follows the reading,
never the words a description happens to hold; a reading not anchored in the printed text is
refused, naming the work.
"""

from __future__ import annotations

import hashlib
import re
import tomllib

import pytest

from analysis.audit import register as reg
from analysis.audit.context import Context, bespoke, context
from analysis.audit.papers.picker import checks, readings
from analysis.papers import load, load_file

SRC = (reg.data_dir() / "papers" / "picker.toml").read_text(encoding="utf-8")


def _copy(tmp_path, *edits):
    """The picker's paper file with ``(ref, old, new)`` replaced in the reading of work [ref]
    (ref None: anywhere in the file), loaded."""
    text = SRC
    for ref, old, new in edits:
        if ref is None:
            assert old in text, old
            text = text.replace(old, new, 1)
            continue
        head, sep, rest = text.partition(f"[[record.cited]]\n  ref = {ref}\n")
        block, sep2, tail = rest.partition("\n\n")
        assert sep and old in block, (ref, old)
        text = head + sep + block.replace(old, new, 1) + sep2 + tail
    digest = hashlib.sha256(text.encode()).hexdigest()[:12]  # load_file caches by path
    path = tmp_path / f"picker-{digest}.toml"
    path.write_text(text, encoding="utf-8")
    return load_file(path.resolve())


def _same(paper) -> dict[int, bool]:
    d = readings.prior_methods(paper)
    return dict(zip(d["key"].tolist(), d["same_method"].tolist(), strict=True))


def test_only_18_proposes_the_papers_method_and_every_reading_is_anchored():
    paper = load("picker")
    assert _same(paper) == {14: False, 15: False, 16: False, 17: False, 18: True}
    text = paper.record("prior_work").text
    cited = paper.record("prior_work")["cited"]
    assert sorted(c["ref"] for c in cited) == sorted(int(k) for k in re.findall(r"\[(\d+)\]", text) if 14 <= int(k) <= 18)  # noqa: E501
    for c in cited:  # the words the reading classifies are the paper's, verbatim
        assert c["quote"] in text and paper.record(f"references.{c['ref']}").type == "reference"


def test_the_verdict_follows_the_reading_not_the_words(tmp_path):
    # [16]'s description given every word the keyword check looked for: still not the method
    words = "並提出了一種基於旋量理論建立閉鏈級聯式機器人運動學方程的方法"
    quote16 = "簡化了具有任意自由度和任意構型的模塊化機器人的運動學建模過程"
    paper = _copy(tmp_path, (None, quote16 + ";", quote16 + words + ";"),
                  (16, quote16 + '"', quote16 + words + '"'))  # fmt: skip
    assert _same(paper)[16] is False
    # our reading of [17] as hybrid rather than parallel: it still proposes no method
    assert _same(_copy(tmp_path, (17, 'robot = "parallel"', 'robot = "hybrid"')))[17] is False
    # [18] read as a serial robot: no reviewed work proposes the method
    assert not any(_same(_copy(tmp_path, (18, 'robot = "hybrid"', 'robot = "serial"'))).values())


@pytest.mark.parametrize(("edit", "message"), [
    ((18, "並在此基礎上提出了", "並提出了"), r"cited \[18\]: the quote is not the text right after \[18\]"),  # noqa: E501
    ((15, "基於螺旋理論,提出", "提出"), r"cited \[15\]: the quote is not the text right after \[15\]"),  # noqa: E501
    ((14, 'robot = "parallel"', 'robot = "delta"'), r"cited \[14\]: robot = 'delta' not in"),
    ((14, "proposes_method = false", "proposes_method = 0"), r"cited \[14\]: proposes_method = 0 not in"),  # noqa: E501
    ((16, "beyond_print = ", "beyond = "), r"cited \[16\]: keys \['beyond', 'beyond_print'\]"),
    ((17, 'beyond_print = "The text', 'beyond_print = "  "\n  x = "The text'), r"cited \[17\]: keys \['x'\]"),  # noqa: E501
])  # fmt: skip
def test_a_reading_not_anchored_in_the_text_is_refused_naming_the_work(tmp_path, edit, message):
    with pytest.raises(ValueError, match=message):
        readings.prior_methods(_copy(tmp_path, edit))


def test_a_reading_that_clears_18_turns_the_register_red(tmp_path, monkeypatch):
    """With [18] read as another class, the novelty claim holds on the data: the register's
    counted row explains nothing, and the audit says so, naming the record."""
    paper = _copy(tmp_path, (18, 'robot = "hybrid"', 'robot = "serial"'))
    ctx = Context(paper, bespoke("picker", paper))
    monkeypatch.setattr(checks, "context", lambda _name: ctx)
    raw = tomllib.loads(reg.source_path("picker").read_text(encoding="utf-8"))
    found = reg.build(ctx, raw).findings
    assert any(f.startswith("explains nothing: pick-claim-novelty/abstract") and "(@novelty)" in f for f in found), found  # noqa: E501
    monkeypatch.undo()  # (before the real context computes the domain: it caches it)
    assert context("picker").domain("prior_methods")["same_method"].sum() == 1


def test_no_structure_claim_is_shown_or_measurable_by_the_test_hardware(tmp_path):
    d = readings.structure_claims(load("picker"))
    assert d["shown"].tolist() == [False] * 3 and d["measurable"].tolist() == [False] * 3
    assert {m for x in readings.test_devices(load("picker")) for m in x["measures"]} == {"marker position"}  # noqa: E501
    # an encoder readback on the prototype makes the stroke measurable, not the stiffness
    enc = _copy(tmp_path, (None, 'measures = []\n  beyond_print = "The prototype', 'measures = ["joint value"]\n  beyond_print = "The prototype'))  # noqa: E501
    assert readings.structure_claims(enc)["measurable"].tolist() == [False, True, False]
    # a property reported in a record of the paper is shown; a place that is none is refused
    shown = _copy(tmp_path, (None, 'reported_in = []\n  beyond_print = "A stiffness', 'reported_in = ["experiment"]\n  beyond_print = "A stiffness'))  # noqa: E501
    assert readings.structure_claims(shown)["shown"].tolist() == [True, False, False]
    nowhere = _copy(tmp_path, (None, 'reported_in = []\n  beyond_print = "A stiffness', 'reported_in = ["table9"]\n  beyond_print = "A stiffness'))  # noqa: E501
    with pytest.raises(ValueError, match="no record 'table9'"):
        readings.structure_claims(nowhere)


@pytest.mark.parametrize(("old", "new", "message"), [
    ('quote = "增加整個手臂的剛度"', 'quote = "增加整個手臂的強度"', r"'stiffness': the quote '增加整個手臂的強度' is not printed"),  # noqa: E501
    ('needs = ["force", "acceleration"]', 'needs = ["stress"]', r"'strength under vibration picking': needs \['stress'\]"),  # noqa: E501
    ('measures = ["marker position"]', 'measures = ["position"]', r"'three-dimensional coordinate measuring instrument': measures"),  # noqa: E501
])  # fmt: skip
def test_a_hardware_reading_not_anchored_in_the_text_is_refused(tmp_path, old, new, message):
    with pytest.raises(ValueError, match=message):
        readings.structure_claims(_copy(tmp_path, (None, old, new)))
