"""analysis.plc.runner.sweep: a fresh CPU per call, and with ANALYSIS_AWLSIM_MEMO an identical
call's result read back instead of executed, equal to what awlsim computes."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("awlsim")

from analysis.plc.emit import emit_s7300
from analysis.plc.ir import build_program
from analysis.plc.memmap import default_map
from analysis.plc.runner import MEMO_ENV, AwlRunner, sweep

pytestmark = pytest.mark.slow  # seconds per test: run first (tests/conftest.py)

TARGETS = np.array([[100.0, 100.0, 600.0], [0.0, 0.0, 2000.0], [np.nan, 0.0, 0.0]])


@pytest.fixture(scope="module")
def program():
    from analysis.kinematics.arm import paper_arm

    return emit_s7300(build_program(paper_arm(), "front-up", "native")), default_map("s7-300")


def _equal(a, b) -> bool:
    return all(
        np.array_equal(getattr(a, k), getattr(b, k)) for k in ("pulses", "reachable", "status")
    )


def test_without_the_memo_every_call_executes(program, monkeypatch, tmp_path):
    monkeypatch.delenv(MEMO_ENV, raising=False)
    src, mmap = program
    first, second = (sweep(src, mmap, TARGETS, sentinel=-1) for _ in range(2))
    assert first.source == second.source == "awlsim"
    assert not list(tmp_path.iterdir())
    reference = AwlRunner(src, mmap).solve(TARGETS, sentinel=-1)
    assert _equal(first.result, reference) and not first.stopped
    assert first.result.status.tolist() == [0, 1, 6]  # solved, out of reach, not finite


def test_an_identical_call_reads_the_result_and_any_change_executes(program, monkeypatch, tmp_path):
    monkeypatch.setenv(MEMO_ENV, str(tmp_path / "memo"))
    src, mmap = program
    ran = sweep(src, mmap, TARGETS, sentinel=-1)
    read = sweep(src, mmap, TARGETS, sentinel=-1)
    assert (ran.source, read.source) == ("awlsim", "memo")
    assert _equal(ran.result, read.result) and read.stopped == ran.stopped
    assert read.result.pulses.dtype == np.int64 and read.result.reals is None
    # whatever determines the result is in the key
    changed = {
        "targets": sweep(src, mmap, TARGETS[:2], sentinel=-1),
        "sentinel": sweep(src, mmap, TARGETS, sentinel=-2),
        "program": sweep(src.replace("600.0", "500.0"), mmap, TARGETS, sentinel=-1),
        "reals": sweep(src, mmap, TARGETS, sentinel=-1, reals=(200,)),
    }
    assert {k: v.source for k, v in changed.items()} == dict.fromkeys(changed, "awlsim")
    assert changed["sentinel"].result.pulses[1].tolist() == [-2, -2, -2]
    assert sweep(src, mmap, TARGETS, sentinel=-1, reals=(200,)).result.reals.shape == (3, 1)
    assert len(list((tmp_path / "memo").glob("*.npz"))) == 5
    assert not list((tmp_path / "memo").glob("*.tmp"))


def test_an_unreadable_memo_file_is_executed_again(program, monkeypatch, tmp_path):
    monkeypatch.setenv(MEMO_ENV, str(tmp_path))
    src, mmap = program
    ran = sweep(src, mmap, TARGETS, sentinel=-1)
    (stored,) = tmp_path.glob("*.npz")
    stored.write_bytes(stored.read_bytes()[:100])  # e.g. a run killed mid-write elsewhere
    again = sweep(src, mmap, TARGETS, sentinel=-1)
    assert again.source == "awlsim" and _equal(again.result, ran.result)
    assert sweep(src, mmap, TARGETS, sentinel=-1).source == "memo"
