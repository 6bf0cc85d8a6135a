"""Hostile S7-200 programs through ``stl-run`` (issue 27 item 5: bounded work, and the
pointer traceback of its list): the S7-200 evaluator must end every scan, answer one line
for an operand nested thousands deep, and refuse a program no S7-200 could hold before it
takes the memory.

Each class is a property over generated programs (Hypothesis, a few examples each): loops
that never end (a JMP back, a FOR whose body resets its index, FOR loops nested up to the
CPU's 8 levels; in OB1 or in a called subroutine; with or without WDR in the body), pointer
operands nested 2 to 20,000 deep, programs past the statement and text limits. A loop that
ran on (the fix reverted) would hang the test: :func:`deadline` turns that into a failure
naming the class. The expected line of the watchdog (the jump back that went over the budget)
is computed from the generated text, not read from the evaluator.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from analysis.plc.stl_eval import S7200, StlError, load_program
from analysis.plc.stl_eval.cpu import MAX_SCAN_FACTOR, WATCHDOG_STATEMENTS
from analysis.plc.stl_eval.syntax import MAX_PROGRAM_CHARS, MAX_STATEMENTS

from .registry import cli
from .strategies import deadline

BUDGET = 20_000
"""A small watchdog for the API examples (the command line keeps the default)."""


def _program(ob1: list[str], sbr: list[str] | None = None) -> tuple[str, int]:
    """Program text with OB1 (and SBR0) bodies; returns (text, line of OB1's first body
    line)."""
    head = ["ORGANIZATION_BLOCK MAIN:OB1", "TITLE=hostile", "BEGIN", "Network 1"]
    lines = [*head, *ob1, "END_ORGANIZATION_BLOCK"]
    if sbr is not None:
        lines += ["SUBROUTINE_BLOCK LOOP:SBR0", "TITLE=", "BEGIN", "Network 1", *sbr]
        lines += ["END_SUBROUTINE_BLOCK"]
    return "\n".join(lines) + "\n", len(head) + 1


@st.composite
def endless_loops(draw):
    """(program text, the line of the jump back that the watchdog must name, WDR?)."""
    kind = draw(st.sampled_from(["jmp", "for-reset", "nested-for"]))
    pad = [f"MOVW {k}, VW{200 + 2 * k}" for k in range(draw(st.integers(0, 5)))]
    wdr = draw(st.booleans())
    label = draw(st.integers(0, 255))
    body = ["LD SM0.0", *pad, *(["WDR"] if wdr else [])]
    if kind == "jmp":
        loop = [f"LBL {label}", *body, f"JMP {label}"]
        closing = len(loop) - 1
    elif kind == "for-reset":  # the body resets the index: NEXT never passes FINAL
        loop = ["LD SM0.0", "FOR VW0, 1, 10", *body, "MOVW 1, VW0", "NEXT"]
        closing = len(loop) - 1
    else:  # nested FOR loops: 32767^depth iterations, the innermost NEXT goes over first
        depth = draw(st.integers(2, 8))
        loop = ["LD SM0.0"] + [f"FOR VW{2 * k}, 1, 32767" for k in range(depth)]
        loop += body
        closing = len(loop)
        loop += ["NEXT"] * depth
    in_sbr = draw(st.booleans())
    if in_sbr:
        text, _ = _program(["LD SM0.0", "CALL SBR0"], loop)
        first = text.splitlines().index("Network 1", 6) + 2  # SBR0's first body line
    else:
        text, first = _program(loop)
    return text, first + closing, wdr


@settings(max_examples=12, deadline=None)
@given(case=endless_loops())
def test_a_scan_that_never_ends_stops_at_the_watchdog_naming_the_jump(case):
    text, line, wdr = case
    cpu = S7200(load_program(text), watchdog=BUDGET)
    with deadline(30, "an endless loop", "no watchdog?"):
        cpu.scan()
    assert cpu.fault is not None and cpu.stopped
    msg = str(cpu.fault)
    assert msg.startswith(f"watchdog at line {line} ("), msg
    assert "\n" not in msg
    if wdr:  # WDR retriggers the watchdog, up to MAX_SCAN_FACTOR budgets
        assert f"{MAX_SCAN_FACTOR} x {BUDGET:,} statements" in msg
    cpu.scan(3)  # the CPU stays in STOP
    assert str(cpu.fault) == msg


@pytest.mark.slow  # three scans of a million statements (about 2 s)
def test_the_issue_reproductions_stop_on_the_command_line(tmp_path):
    """Issue 27's three: LBL 0 / LD SM0.0 / JMP 0; a FOR whose body resets its index; nested
    FOR loops (21 minutes a scan before). The default watchdog, through stl-run."""
    cases = {
        "jmp": (["LBL 0", "LD SM0.0", "JMP 0"], 7),
        "for": (["LD SM0.0", "FOR VW0, 1, 10", "MOVW 1, VW0", "NEXT"], 8),
        "nested": (["LD SM0.0", *[f"FOR VW{2 * k}, 1, 32767" for k in range(8)],
                    "INCW VW100", *["NEXT"] * 8], 15),
    }  # fmt: skip
    for name, (body, line) in cases.items():
        path = tmp_path / f"{name}.awl"
        path.write_text(_program(body)[0])
        with deadline(60, name, "no watchdog?"):
            out = cli("stl-run", str(path), "--dialect", "s7-200", "--read", "VW0:INT")
        assert out.code == 2, (name, out.stderr)
        want = f"the CPU went to STOP: watchdog at line {line} (MAIN (OB1), network 1): "
        assert want in out.message, out.message
        assert f"within {WATCHDOG_STATEMENTS:,} statements" in out.message, out.message
        assert "Traceback" not in out.stderr and len(out.stderr.strip().splitlines()) == 1


def test_a_loop_that_ends_in_time_is_not_stopped():
    """The watchdog is a bound, not a guess: a loop of fewer statements than the budget
    runs to its end (FOR 1..1000 of 4 statements: 4,000 < 20,000)."""
    text, _ = _program(["LD SM0.0", "FOR VW0, 1, 1000", "LD SM0.0", "INCD VD4", "NEXT"])
    cpu = S7200(load_program(text), watchdog=BUDGET)
    cpu.scan(2)
    assert cpu.fault is None and cpu.read("DINT", "VD4") == 2000


@settings(max_examples=8, deadline=None)
@given(depth=st.integers(2, 20_000), where=st.sampled_from(["in", "out"]))
def test_a_pointer_nested_deep_is_refused_in_one_line(depth, where):
    """``**..*VD0``: S7-200 pointers are one level (*VDn, *ACn, *LDn); a RecursionError
    traceback before the fix."""
    ptr = "*" * depth + "VD0"
    stmt = f"MOVD {ptr}, VD4" if where == "in" else f"MOVD VD4, {ptr}"
    text, first = _program(["LD SM0.0", stmt])
    with pytest.raises(StlError) as exc:
        load_program(text)
    msg = str(exc.value)
    assert "\n" not in msg and len(msg) < 400, msg
    assert msg.startswith(f"line {first + 1} (MAIN (OB1), network 1)")
    assert "a pointer to a pointer is no S7-200 operand" in msg


@pytest.mark.slow  # parses 65,537 statements
def test_programs_no_s7200_could_hold_are_refused_before_they_take_the_memory(tmp_path):
    """Past :data:`MAX_STATEMENTS` statements: refused at the statement past the limit;
    past :data:`MAX_PROGRAM_CHARS` characters: refused before the text is split."""
    n = MAX_STATEMENTS + 1
    text, first = _program(["LD SM0.0", *["MOVR VD0, VD4"] * (n - 1)])
    with pytest.raises(StlError, match=f"line {first + n - 1} .*more than {MAX_STATEMENTS:,}"):
        load_program(text)
    big = tmp_path / "big.awl"
    big.write_text(_program(["LD SM0.0", "MOVR VD0, VD4 // " + "x" * MAX_PROGRAM_CHARS])[0])
    out = cli("stl-run", str(big), "--dialect", "s7-200", "--read", "VD0:DINT")
    # stl-run reads at most the limit (analysis.safe_io's bounded read), naming it
    assert out.code == 2 and f"larger than {MAX_PROGRAM_CHARS:,} bytes" in out.message
    assert len(out.stderr.strip().splitlines()) == 1
