"""Seed 000's findings that rest on a reading of printed text (grabber-op-modes,
grabber-claim-navigation, grabber-ref-ik): each input of Table 2 and each cited entry is recorded
as our reading beside its printed row (``table2.devices``, ``references.N``), and the domains
decide from that data, never from the words a name happens to hold. A reading that is not the
printed row is refused, naming it; a reading changed turns the register red."""

from __future__ import annotations

import hashlib
import tomllib

import pytest

from analysis.audit import register as reg
from analysis.audit.context import Context, bespoke, context
from analysis.audit.papers.grabber import checks, listings
from analysis.papers import load, load_file

SRC = (reg.data_dir() / "papers" / "grabber.toml").read_text(encoding="utf-8")
SELECTOR = '''

  [[record.devices]]
  address = "I0.2"
  name = "手动/自动选择开关"
  device = "selector switch"
  selects = ["manual", "automatic"]
  beyond_print = "a test's selector"
'''


def _copy(tmp_path, *edits):
    text = SRC
    for old, new in edits:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    path = tmp_path / f"grabber-{hashlib.sha256(text.encode()).hexdigest()[:12]}.toml"
    path.write_text(text, encoding="utf-8")
    return load_file(path.resolve())


SB2 = '''  address = "I0.1"
  name = "停止按钮"
  device = "push button"'''


def _findings(tmp_path, monkeypatch, *edits):
    """The grabber's register over a copy of its paper file with ``edits`` (the domains read
    the copy), then the real context again."""
    paper = _copy(tmp_path, *edits)
    ctx = Context(paper, bespoke("grabber", paper))
    monkeypatch.setattr(checks, "context", lambda _name: ctx)
    monkeypatch.setattr(listings, "_paper", lambda: paper)
    raw = tomllib.loads(reg.source_path("grabber").read_text(encoding="utf-8"))
    found = reg.build(ctx, raw).findings
    modes = ctx.domain("claimed_modes")
    monkeypatch.undo()  # before the real context computes anything: it caches
    return found, modes


def test_every_printed_input_and_claimed_mode_has_its_reading():
    paper = load("grabber")
    devices = listings.input_devices(paper)
    assert [(d["address"], d["name"]) for d in devices] == [(a, n) for n, _c, a in paper.record("table2")["inputs"]]  # noqa: E501
    assert listings.claimed_modes(paper) == list(listings.MODES)
    d = context("grabber").domain
    assert not d("sensing_inputs")["senses"].any() and not d("claimed_modes")["selectable"].any()
    assert not d("ik_citations")["on_kinematics"].any()


def _unit_holds(paper, ref):
    from analysis.audit.kinds import check
    from analysis.audit.records import units

    ctx = Context(paper, bespoke("grabber", paper))
    u = next(u for u in units(paper) if u.ref == ref)
    return bool(check(u.spec, u.text, ctx)), ctx


def test_the_verdicts_follow_the_readings_not_the_names(tmp_path, monkeypatch):
    # SB2 read as a limit switch: Table 2 senses something, the navigation claim's check holds
    paper = _copy(tmp_path, (SB2, SB2.replace("push button", "limit switch")))
    monkeypatch.setattr(listings, "_paper", lambda: paper)
    monkeypatch.setattr(checks, "context", lambda _name: Context(paper, bespoke("grabber", paper)))
    assert _unit_holds(paper, "@novelty_navigation")[0]
    assert listings.census()["reference_inputs"] == 1
    # a selector added to Table 2 but read by no listing selects nothing: the verdict stands
    paper = _copy(tmp_path, *_SELECTOR_EDITS)
    ok, ctx = _unit_holds(paper, "@sec22_modes")
    modes = ctx.domain("claimed_modes")
    assert not ok and modes["mode_inputs"][0] == 1 and not modes["selectable"].any()
    monkeypatch.undo()


@pytest.mark.slow
def test_a_sensing_device_turns_the_register_red(tmp_path, monkeypatch):
    found, _ = _findings(tmp_path, monkeypatch, (SB2, SB2.replace("push button", "limit switch")))
    assert any(f.startswith("explains nothing: grabber-claim-navigation/introduction") and "(@novelty_navigation)" in f for f in found), found  # noqa: E501
    found, _ = _findings(tmp_path, monkeypatch, *_SELECTOR_EDITS)
    assert not any("grabber-op-modes" in f for f in found), found


_ROW = '["停止按钮", "SB2", "I0.1"]'
_SB2_TAIL = SRC[SRC.index(SB2) :].split("\n\n", 1)[0]
_SELECTOR_EDITS = (
    (_ROW, _ROW + ', ["手动/自动选择开关", "SA1", "I0.2"]'),
    (_SB2_TAIL, _SB2_TAIL + SELECTOR.rstrip("\n")),
)


@pytest.mark.parametrize(("old", "new", "message"), [
    ('name = "停止按钮"', 'name = "启动按钮"', r"input I0.1: '启动按钮' is not the printed row"),
    ('device = "push button"\n  selects = []\n  beyond_print = "Table 2 names it a stop',
     'device = "keypad"\n  selects = []\n  beyond_print = "Table 2 names it a stop', r"input I0.1: device 'keypad'"),  # noqa: E501
    ('mode = "cyclic", quote = "循环运行"', 'mode = "cyclic", quote = "循环模式"', r"'cyclic' \('循环模式'\) is not a mode"),  # noqa: E501
])  # fmt: skip
def test_a_reading_that_is_not_the_printed_row_is_refused(tmp_path, old, new, message):
    paper = _copy(tmp_path, (old, new))
    with pytest.raises(ValueError, match=message):
        listings.input_devices(paper)
        listings.claimed_modes(paper)


def test_a_cited_entry_read_as_kinematics_changes_the_verdict(tmp_path, monkeypatch):
    head = SRC[SRC.index('location = "reference [9]"') :].split("on_kinematics = false", 1)[0]
    paper = _copy(tmp_path, (head + "on_kinematics = false", head + "on_kinematics = true"))
    ctx = Context(paper, bespoke("grabber", paper))
    monkeypatch.setattr(checks, "context", lambda _name: ctx)
    assert ctx.domain("ik_citations")["on_kinematics"].tolist() == [False, False, True]
    monkeypatch.undo()
