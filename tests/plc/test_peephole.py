"""The AWL peephole pass (analysis.plc.peephole): each rewrite where it is exact and nowhere
else, and programs before and after it leaving the same memory on awlsim."""

from __future__ import annotations

import itertools
import json

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from analysis.plc.peephole import optimize_awl


def _fc(body: str, decl: str = "VAR_TEMP\n  T1 : REAL;\n  T2 : REAL;\n  I1 : INT;\nEND_VAR") -> str:
    return f"FUNCTION FC 1 : VOID\n{decl}\nBEGIN\n{body}\nEND_FUNCTION"


def _body(text: str) -> list[str]:
    """The stripped lines between the first BEGIN and the END_... after it."""
    lines = [s.strip() for s in text.split("\n")]
    start = lines.index("BEGIN") + 1
    return lines[start : next(n for n in range(start, len(lines)) if lines[n].startswith("END_"))]


def _ops(*rows: str) -> str:
    return "\n".join(f"      {r}" for r in rows)


def test_a_reload_before_another_load_goes_and_the_overwritten_store_with_it():
    src = _fc(_ops("L #T1", "L 2.0", "*R", "T #T2", "L #T2", "L 1.0", "+R", "T #T2"))
    assert _body(optimize_awl(src)) == ["L #T1", "L 2.0", "*R", "L 1.0", "+R", "T #T2"]


def test_a_reload_goes_when_only_one_operand_instructions_come_before_the_next_load():
    src = _fc(_ops("T #T2", "L #T2", "SQRT", "T #T1", "L 3.0", "+R", "T #T1"))
    assert _body(optimize_awl(src)) == ["T #T2", "SQRT", "L 3.0", "+R", "T #T1"]


@pytest.mark.parametrize(
    ("rows", "why"),
    [
        (("T #T2", "L #T2", "*R", "T #T1"), "squares ACCU2 * ACCU1: the reload feeds ACCU2"),
        (("T #T2", "L #T2", "SQRT", "+R", "T #T1"), "ACCU2 read after a one-operand step"),
        (("T #T2", "L #T2", "SQRT", "T #T1"), "ACCU2 never overwritten here: it may be read"),
        (("T #T2", "X1: L #T2", "L 1.0", "+R", "T #T1"), "a jump may arrive at the reload"),
        (("T #I1", "L #I1", "L 1", "+I", "T #I1"), "an INT store keeps only ACCU1's low word"),
        (("T MW 4", "L MW 4", "L 1", "+I", "T MW 4"), "a word, not ACCU1's 32 bits"),
    ],
)
def test_a_reload_stays_where_it_changes_something(rows, why):
    src = _fc(_ops(*rows))
    assert optimize_awl(src) == src, why


@pytest.mark.parametrize(
    ("rows", "why"),
    [
        (("T MD 0", "L MW 2", "T MD 0"), "read in between (overlapping bytes)"),
        (("T MD 0", "L 1.0", "T MW 0"), "overwritten only in part"),
        (("T MD 0", "JC X1", "T MD 0"), "a jump: the store may be read on the other path"),
        (("T MD 0", "X1: L 1.0", "T MD 0"), "a label: another path may read it"),
        (("T MD 0", "CALL FC 2", "T MD 0"), "a call may read it"),
        (("T MD 0", "= M 0.1", "T MD 0"), "a bit operation"),
        (("T MD 0", "L DBD 0", "T MD 0"), "an operand form not analysed"),
        (("T #R", "L 1.0", "T #R"), "an FC parameter may refer to any address"),
    ],
)
def test_a_store_stays_unless_it_is_overwritten_unread(rows, why):
    src = _fc(_ops(*rows), decl="VAR_OUTPUT\n  R : REAL;\nEND_VAR")
    assert optimize_awl(src) == src, why


def test_declarations_comments_and_other_blocks_are_kept():
    src = (
        "// header: T MD 0\n"
        + _fc(_ops("// T MD 0", "L 1.0", "T MD 0", "", "L 2.0", "T MD 0"))
        + "\nORGANIZATION_BLOCK OB 1\nBEGIN\n      L 3.0\n      T MD 0\nEND_ORGANIZATION_BLOCK"
    )
    out = optimize_awl(src)
    assert out.count("\n") == src.count("\n") - 1  # one store gone, in FC 1 only
    assert "// header: T MD 0" in out and "      // T MD 0" in out
    assert out.endswith("      L 3.0\n      T MD 0\nEND_ORGANIZATION_BLOCK")


# --- on awlsim: random straight-line code and the generated programs -----------------------
awlsim = pytest.importorskip("awlsim")

from analysis.plc.memmap import MemoryMap, default_map  # noqa: E402
from analysis.plc.runner import AwlRunner  # noqa: E402

_MDS = [f"MD {4 * k}" for k in range(4)]
# chunks of straight-line code over four double words, with the patterns the pass rewrites
# (a store and its reload, a store and a later store) drawn often
_STEP = st.one_of(
    st.sampled_from([f"L {a}" for a in _MDS] + ["L 1.5", "L -0.25"]).map(lambda s: [s]),
    st.sampled_from([f"T {a}" for a in _MDS] + ["T MW 2", "T MB 5"]).map(lambda s: [s]),
    st.sampled_from(["+R", "-R", "*R", "/R", "SQRT", "ABS", "TAK"]).map(lambda s: [s]),
    st.sampled_from(["L MW 6", "L MB 1"]).map(lambda s: [s]),
    st.sampled_from(_MDS).map(lambda a: [f"T {a}", f"L {a}"]),
    st.sampled_from(_MDS).map(lambda a: [f"T {a}", "L 0.5", "*R", f"T {a}"]),
)


def _ob1(body: list[str]) -> str:
    return "ORGANIZATION_BLOCK OB 1\nBEGIN\n" + _ops(*body) + "\nEND_ORGANIZATION_BLOCK\n"


def _memory_after(body: list[str]) -> bytes:
    runner = AwlRunner(_ob1(body), default_map("s7-300"), first_scan=False)
    for k, a in enumerate(_MDS):
        runner.write_real(int(a.split()[1]), 1.0 + k / 4)
    runner.cycle()
    return bytes(runner.mem[:32])


@pytest.mark.slow
@settings(max_examples=60)
@given(st.lists(_STEP, min_size=3, max_size=16).map(lambda c: [*itertools.chain(*c)]))
@example(["L MD 4", "L MD 8", "T MD 0", "L MD 0", "+R", "T MD 12"])  # ACCU2 feeds +R
@example(["L 2.0", "T MD 0", "L MW 2", "L 1.0", "T MD 0", "TAK", "T MD 4"])  # read between
def test_random_straight_line_code_leaves_the_same_memory(body):
    assert _memory_after(_body(optimize_awl(_ob1(body)))) == _memory_after(body)


@pytest.mark.slow
@pytest.mark.parametrize("dialect", ["s7-200", "s7-300"])
def test_a_generated_program_leaves_the_same_memory_after_every_scan(dialect):
    """The GR-1 program (its S7-200 text translated), with and without the pass: the whole
    M area equal after each of 60 scans over the seeded pose sweep."""
    from analysis.audit.papers.gr1.thesis import gr1_arm
    from analysis.plc.generate import generate
    from analysis.plc.sweep import sweep_targets
    from analysis.plc.translate import translate_s7200

    arm = gr1_arm()
    text, map_json = generate(arm, dialect, "front-up", "subroutine")
    mmap = MemoryMap.from_dict(json.loads(map_json))
    if dialect == "s7-200":
        plain, optimized = (translate_s7200(text, optimize=o).awl for o in (False, True))
    else:
        plain, optimized = generate(arm, dialect, "front-up", "subroutine",
                                    optimize=False).program, text  # fmt: skip
    assert len(optimized.splitlines()) < len(plain.splitlines())
    targets = sweep_targets(arm)[list(arm.inputs)].to_numpy()[::19][:60]
    runs = [AwlRunner(src, mmap) for src in (plain, optimized)]
    for target in targets:
        for r in runs:
            for b, v in zip(mmap.inputs.values(), target, strict=True):
                r.write_real(b, float(v))
            r.cycle()
        assert bytes(runs[0].mem) == bytes(runs[1].mem)
    assert np.isfinite(targets).all()
