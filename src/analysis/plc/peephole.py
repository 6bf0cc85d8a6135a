"""Peephole optimisation of generated AWL: drop reloads of a value just stored, and stores
that are overwritten before anything reads them.

The S7-300 emitter (:func:`analysis.plc.emit.emit_s7300`) and the S7-200 translator
(:func:`analysis.plc.translate.translate_s7200`) write one AWL sequence per operation, each
loading its operands and storing its result:

.. code-block:: none

    *R                  # t3 := ...
    T     #T3
    L     #T3           # t8 := t3 + c
    L     -0.142003193
    +R
    T     #T8

A CPU (and awlsim, which interprets every instruction in Python) spends most of its scan on
these loads and transfers: 1,183 of the 2,022 instructions per target in the GR-1's translated
S7-200 program. Two rewrites remove the redundant ones, within straight-line code only:

1. **Reload.** ``T X`` immediately followed by ``L X`` of the same double word: the ``L X``
   is dropped if another ``L`` follows before anything reads ACCU2 (only ``T`` and
   one-operand instructions such as ``SQRT`` in between). After ``T X`` ACCU1 already holds
   X; ``L X`` would only copy ACCU1 into ACCU2, and the next ``L`` copies ACCU1 into ACCU2
   in either case, so from there on both accumulators are the same with or without it.
   ``L`` and ``T`` do not change the status word. Not applied when ``L X`` carries a label
   (a jump may arrive there with another value in ACCU1), nor to a byte or word (``T``
   stores only part of ACCU1).
2. **Dead store.** ``T X`` followed, before any instruction that could read X, by another
   ``T X`` (or a ``T`` covering all of X's bytes): the first is dropped. In between only
   ``L``/``T`` of other addresses and accumulator arithmetic or comparisons may occur; a
   label, a jump, a call, a block end or any other instruction ends the search and keeps the
   store.

Addresses are compared by bytes for ``M``/``MB``/``MW``/``MD`` and by name for ``#locals``;
constants are never memory; any other operand form (indirect, DB, periphery) counts as
possibly overlapping everything, so nothing is removed across it. Only lines between
``BEGIN`` and the block's ``END_...`` are code. Comments and blank lines are kept.

Why by hand: no library optimises S7 AWL (awlsim executes it, as is). The rewrites are the
two classic ones for an accumulator machine (redundant load after store, dead store in a
basic block); what makes them correct here is the two-accumulator ``L``/``T`` semantics
above. Proof that they change nothing observable: every generated program is run on awlsim
against its float32 model (:mod:`analysis.plc.model`), bit for bit, status and pulses, over
the seeded target sweeps (``tests/plc``), and ``tests/plc/test_peephole.py`` runs programs
before and after on awlsim and compares all of their memory.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass

__all__ = ["optimize_awl"]

_LINE = re.compile(
    r"^(?P<label>[A-Za-z_][A-Za-z0-9_]*:)?\s*(?P<op>[^\s/][^\s]*)?\s*(?P<arg>[^/]*?)\s*(//.*)?$"
)
_ABSOLUTE = re.compile(r"^(MB|MW|MD)\s*(\d+)$")
_WIDTH = {"MB": 1, "MW": 2, "MD": 4}
_CONSTANT = re.compile(r"^[-+]?(\d|L#|DW#16#|W#16#|B#16#|DINT#|REAL#|INT#)", re.IGNORECASE)

# instructions that read ACCU1 only (ACCU2 is neither read nor changed)
_UNARY = frozenset(
    {
        *("SQRT", "SQR", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "LN", "EXP", "ABS"),
        *("NEGR", "NEGD", "NEGI", "INVD", "INVI", "TRUNC", "RND", "RND+", "RND-"),
        *("DTR", "ITD", "DTB", "BTD", "ITB", "BTI"),
    }
)
# accumulator-only instructions: no memory operand, no jump, no block change
_ACCU_ONLY = _UNARY | {
    *("+R", "-R", "*R", "/R", "+D", "-D", "*D", "/D", "+I", "-I", "*I", "/I", "MOD"),
    *(f"{c}{t}" for c in ("==", "<>", "<", "<=", ">", ">=") for t in "RDI"),
    *("AD", "OD", "XOD", "AW", "OW", "XOW"),
}

_ANY = "any"


_DECLARATION = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)\s*:\s*([A-Za-z_]+)\s*;")
_DOUBLE_WORD = frozenset({"REAL", "DINT", "DWORD", "TIME"})


@dataclass(frozen=True)
class _Insn:
    index: int  # line number in the source
    label: bool
    op: str
    arg: str
    where: object  # _location(arg); a block parameter (#name of VAR_INPUT/OUTPUT/IN_OUT) is
    # _ANY: it may refer to any M address the caller passed
    double_word: bool  # the operand is 32 bits wide (what T stores of ACCU1 is all of it)


def _location(arg: str):
    """Where an operand is: ("#", name), ("M", (first byte, end)), None (a constant or no
    operand) or ``_ANY`` (a form this module does not analyse)."""
    arg = arg.strip()
    if not arg or _CONSTANT.match(arg):
        return None
    if re.fullmatch(r"#[A-Za-z_][A-Za-z0-9_]*", arg):
        return ("#", arg)
    m = _ABSOLUTE.match(arg)
    if m:
        first = int(m.group(2))
        return ("M", (first, first + _WIDTH[m.group(1)]))
    return _ANY


def _overlap(a, b) -> bool:
    if a is None or b is None:
        return False
    if _ANY in (a, b, a[0], b[0]):
        return True
    if a[0] != b[0]:
        return False
    if a[0] == "#":
        return a[1] == b[1]
    return a[1][0] < b[1][1] and b[1][0] < a[1][1]


def _covers(store, x) -> bool:
    """Whether writing ``store`` overwrites every byte of ``x``."""
    if store in (None, _ANY) or x in (None, _ANY) or _ANY in (store[0], x[0]) or store[0] != x[0]:
        return False
    if x[0] == "#":
        return store[1] == x[1]
    return store[1][0] <= x[1][0] and x[1][1] <= store[1][1]


def _code(lines: list[str]) -> list[_Insn]:
    """The instructions between each block's BEGIN and END_..., in order; the block's
    declarations (``name : TYPE;``) give the width of its ``#locals``."""
    out, inside, types, params, section = [], False, {}, set(), ""
    for n, line in enumerate(lines):
        text = line.strip()
        if not inside:
            if text == "BEGIN":
                inside = True
            elif text.startswith("VAR") or text == "END_VAR":
                section = text
            elif decl := _DECLARATION.match(text):
                types["#" + decl.group(1)] = decl.group(2).upper()
                if section != "VAR_TEMP":
                    params.add("#" + decl.group(1))
            continue
        if text.startswith("END_"):
            inside, types, params = False, {}, set()
            out.append(_Insn(n, True, "", "", _ANY, False))  # the block ends: a barrier
            continue
        if not text or text.startswith("//") or text == "NETWORK" or text.startswith("TITLE"):
            continue  # a network boundary changes neither the accumulators nor memory
        m = _LINE.match(text)
        if m is None or not m.group("op"):
            # a bare label ("X1:") or a line not understood: a barrier
            out.append(_Insn(n, True, "", "", _ANY, False))
            continue
        arg = m.group("arg")
        where = _location(arg)
        if where in (None, _ANY):
            wide = False
        elif where[0] == "#":
            wide = types.get(where[1]) in _DOUBLE_WORD
        else:
            wide = where[1][1] - where[1][0] == 4
        if where not in (None, _ANY) and where[1] in params:
            where = (_ANY, arg)  # reloads of it may go; stores to it stay (aliasing)
        out.append(_Insn(n, bool(m.group("label")), m.group("op").upper(), arg, where, wide))
    return out


def _accu2_overwritten(code: list[_Insn]) -> bool:
    """Whether ``code`` loads (overwriting ACCU2) before anything reads ACCU2: only ``T`` and
    one-operand instructions (ACCU1 only) may come first, with no label or jump."""
    for insn in code:
        if insn.label:
            return False
        if insn.op == "L":
            return True
        if insn.op != "T" and insn.op not in _UNARY:
            return False
    return False


def _dead_reloads(code: list[_Insn]) -> set[int]:
    dead = set()
    for k, (store, load) in enumerate(itertools.pairwise(code)):
        if (
            store.op == "T"
            and load.op == "L"
            and not load.label
            and load.where == store.where
            and store.double_word
            and _accu2_overwritten(code[k + 2 :])
        ):
            dead.add(load.index)
    return dead


def _dead_stores(code: list[_Insn]) -> set[int]:
    dead = set()
    for k, store in enumerate(code):
        x = store.where if store.op == "T" else None
        if x in (None, _ANY) or x[0] == _ANY:
            continue
        for nxt in code[k + 1 :]:
            if nxt.label:
                break
            where = nxt.where
            if nxt.op == "T":
                if _covers(where, x):
                    dead.add(store.index)
                    break
                if _overlap(where, x):
                    break
            elif nxt.op == "L" or nxt.op in _ACCU_ONLY:
                if _overlap(where, x):
                    break
            else:
                break
    return dead


def optimize_awl(text: str) -> str:
    """``text`` with the redundant reloads, then the dead stores, removed (module docstring).

    >>> src = "BEGIN\\n L 1.0\\n T MD 0\\n L MD 0\\n L 2.0\\n +R\\n T MD 0\\nEND_FUNCTION"
    >>> print(optimize_awl(src))
    BEGIN
     L 1.0
     L 2.0
     +R
     T MD 0
    END_FUNCTION
    """
    lines = text.split("\n")
    code = _code(lines)
    gone = _dead_reloads(code)
    gone |= _dead_stores([i for i in code if i.index not in gone])
    return "\n".join(line for n, line in enumerate(lines) if n not in gone)
