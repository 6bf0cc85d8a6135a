"""The AWL of each S7-200 statement, as a table: mnemonic (or its builder family) -> handler.

:func:`emit_statement` writes one statement's AWL into an :class:`~.emitter.Emitter` (the
block being translated): a comment with the S7-200 text, then the handler's instructions.
:data:`BY_OP` holds the handlers of single mnemonics, :data:`BY_BUILDER` those of whole
families of the evaluator's instruction table (:data:`analysis.plc.stl_eval.INSTRUCTIONS`:
contacts, compares, coils, moves, math ...); what neither holds is refused, naming the
mnemonic (:data:`NOT_TRANSLATED` says why for the instructions the evaluator runs and the
translation does not cover). The package docstring (:mod:`analysis.plc.translate`) gives the
mapping instruction by instruction.
"""

from __future__ import annotations

import re

from analysis.plc.stl_eval.operands import Operand
from analysis.plc.translate.layout import PLS_RECORDS

__all__ = ["BY_BUILDER", "BY_OP", "NOT_TRANSLATED", "emit_statement"]

_LOGIC = {
    "ANDB": "AW",
    "ORB": "OW",
    "XORB": "XOW",
    "ANDW": "AW",
    "ORW": "OW",
    "XORW": "XOW",
    "ANDD": "AD",
    "ORD": "OD",
    "XORD": "XOD",
}
_FUNC = {"SQRT": "SQRT", "LN": "LN", "EXP": "EXP", "SIN": "SIN", "COS": "COS", "TAN": "TAN"}
NOT_TRANSLATED = {
    "FOR": "FOR/NEXT loops are not translated",
    "NEXT": "FOR/NEXT loops are not translated",
    "STOP": "STOP is not translated",
    "BMB": "block moves are not translated",
    "BMW": "block moves are not translated",
    "BMD": "block moves are not translated",
    "SWAP": "SWAP is not translated",
    "MUL": "MUL is not translated",
    "DIV": "DIV is not translated",
    "INVB": "INVB is not translated",
    "INVW": "INVW is not translated",
    "INVD": "INVD is not translated",
    "INCB": "INCB/DECB (unsigned byte arithmetic) are not translated",
    "DECB": "INCB/DECB (unsigned byte arithmetic) are not translated",
    "BTI": "BTI is not translated",
    "ITB": "ITB is not translated",
    "WDR": "WDR is not translated",
    **{
        k: "shifts and rotates are not translated"
        for k in ("SLB SRB RLB RRB SLW SRW RLW RRW SLD SRD RLD RRD".split())
    },
}


def _contact(e, st, o) -> None:
    op = st.op
    base = {"LDI": "LD", "LDNI": "LDN", "AI": "A", "ANI": "AN", "OI": "O", "ONI": "ON"}.get(op, op)
    if base in ("LD", "LDN"):
        e.push()
        e.load_bit(o[0], base == "LDN", None)
    else:
        e.load_bit(o[0], base.endswith("N"), base[0])


def _compare(e, st, o) -> None:
    op = st.op
    m = re.match(r"^(LD|A|O)([BWDR])(.+)$", op)
    if m.group(1) == "LD":
        e.push()
    e.compare(m.group(2), m.group(3), o[0], o[1], None if m.group(1) == "LD" else m.group(1))


def _not_(e, st, o) -> None:
    e.i("AN", e.tos)
    e.i("=", e.tos)
    e.always = False


def _aeno(e, st, o) -> None:
    e.i("A", e.tos)
    e.i("A", e.bit(e.lay.eno))
    e.i("=", e.tos)
    e.always = False


def _edge(e, st, o) -> None:
    op = st.op
    edge = f"M {e.edge_base + e.n_edge // 8}.{e.n_edge % 8}"
    e.n_edge += 1
    if e.n_edge > 16:
        raise ValueError("more than 16 EU/ED in one block are not translated")
    e.i("A", e.tos)
    e.i("FP" if op == "EU" else "FN", edge)
    e.i("A", e.bit(e.lay.first_scan_done))  # no edge in the first scan
    e.i("=", e.tos)
    e.always = False


def _lps(e, st, o) -> None:
    keep = e.always
    e.push()
    e.always = keep


def _lrd_lpp(e, st, o) -> None:
    op = st.op
    e.i("A", e.stack[0])
    e.i("=", e.tos)
    e.always = e.always_stack[0]
    if op == "LPP":
        e.pop()


def _ald_old(e, st, o) -> None:
    op = st.op
    e.i("A", e.tos)
    e.i("A" if op == "ALD" else "O", e.stack[0])
    e.i("=", e.tos)
    e.always = False
    e.pop()


def _lds(e, st, o) -> None:
    n = o[0].value
    known = e.always_stack[n - 1]  # level n's "known on" flag, before the push
    e.i("A", e.stack[n - 1])
    e.i("=", e.bit(e.lay.cmp_scratch))
    e.push()
    e.i("A", e.bit(e.lay.cmp_scratch))
    e.i("=", e.tos)
    e.always = known


def _nop(e, st, o) -> None:
    pass


def _coil(e, st, o) -> None:
    e.i("A", e.tos)
    e.i("=", e.opnd(o[0]))


def _setreset(e, st, o) -> None:
    op = st.op
    first, n = o[0], int(o[1].value)
    for k in range(n):
        b = first.bit + k
        bit = Operand("bit", first.area, first.off + b // 8, b % 8, text=first.text)
        e.i("A", e.tos)
        e.i("S" if op.startswith("S") else "R", e.opnd(bit))


def _jmp(e, st, o) -> None:
    lab = f"J{o[0].value:03d}"
    if e.always:
        e.i("JU", lab)
    else:
        e.i("A", e.tos)
        e.i("JC", lab)


def _lbl(e, st, o) -> None:
    e.place(f"J{o[0].value:03d}")
    e.always = False


def _cret(e, st, o) -> None:
    e.i("A", e.tos)
    e.i("BEC")


def _end(e, st, o) -> None:
    e.i("A", e.tos)
    e.i("JC", "MEND")


def _move(e, st, o) -> None:
    op = st.op
    w = {"MOVB": "B", "MOVW": "W", "MOVD": "D", "MOVR": "D"}[op]

    def body(fail):
        e.i("L", e.opnd(o[0], w))
        e.i("T", e.opnd(o[1], w))

    e.box(body)


def _math(e, st, o) -> None:
    e.math(st, o)


def _func(e, st, o) -> None:
    op = st.op
    src, dst = e.opnd(o[0], "D"), e.opnd(o[1], "D")

    def body(fail):
        err = fail({1: True, 0: False, 2: False})
        if op == "EXP":  # EXP(-inf) = 0 without OV on awlsim: an illegal input here
            e.i("L", src)
            e.i("L", "DW#16#7F800000")
            e.i("AD")
            e.i("L", "DW#16#7F800000")
            e.i("==D")
            e.i("JC", err)
        e.i("L", src)
        e.i(_FUNC[op])
        e.i("JO", err)
        e.i("T", dst)
        e.math_status(True, dst, True)

    e.box(body)


def _logic(e, st, o) -> None:
    op = st.op
    w = {"B": "B", "W": "W", "D": "D"}[op[-1]]
    src, dst = e.opnd(o[0], w), e.opnd(o[1], w)

    def body(fail):
        e.i("L", dst)
        e.i("L", src)
        e.i(_LOGIC[op])
        e.i("T", dst)
        if e.tr.needs_sm1:
            e.i("L", dst)
            e.i("L", "L#0" if w == "D" else "0")
            e.i("==D" if w == "D" else "==I")
            e.sm1({0: "RLO"})

    e.box(body)


def _incdec(e, st, o) -> None:
    op = st.op
    w = {"W": "W", "D": "D"}[op[-1]]
    dst = e.opnd(o[0], w)

    def body(fail):
        e.i("L", dst)
        e.i("L", "L#1" if w == "D" else "1")
        e.i(("+" if op.startswith("INC") else "-") + ("D" if w == "D" else "I"))
        e.i("JO", fail({1: True, 0: False, 2: False}))
        e.i("T", dst)
        e.math_status(False, dst, w == "D")

    e.box(body)


def _round_trunc(e, st, o) -> None:
    op = st.op
    src, dst = e.opnd(o[0], "D"), e.opnd(o[1], "D")

    def body(fail):
        err = fail({1: True})  # not a valid REAL, or beyond DINT (S2M p.115)
        if op == "TRUNC":
            e.i("L", src)
            e.clear_ov()
            e.i("TRUNC")
            e.i("JO", err)
            e.i("T", dst)
        else:
            e.round(src, dst, err)
        e.sm1({1: False})

    e.box(body)


def _dtr_itd(e, st, o) -> None:
    op = st.op
    src = e.opnd(o[0], "D" if op == "DTR" else "W")
    dst = e.opnd(o[1], "D")

    def body(fail):
        e.i("L", src)
        e.i(op)
        e.i("T", dst)

    e.box(body)


def _dti(e, st, o) -> None:
    src, dst = e.opnd(o[0], "D"), e.opnd(o[1], "W")

    def body(fail):
        err = fail({1: True})
        e.i("L", src)
        e.i("L", "L#32767")
        e.i(">D")
        e.i("JC", err)
        e.i("L", src)
        e.i("L", "L#-32768")
        e.i("<D")
        e.i("JC", err)
        e.i("L", src)
        e.i("T", dst)

    e.box(body)


def _call(e, st, o) -> None:
    e.box(lambda fail: e.call(st, o))


def _pls(e, st, o) -> None:
    """PLS n: log what the SM registers hold (a record for the runner's pulse generator,
    :class:`analysis.plc.stl_eval.PtoChannel`, which runs after the scan) and mirror what the
    generator does at once: the enable bit cleared -> idle (SM66.5 if a train was running),
    set -> busy (the runner's model then decides: started, queued or overflow)."""
    ch = o[0].value
    lay = e.lay
    sm = lay.sm + 10 * ch
    count = f"MB {lay.pls_record(ch) - 2}"

    def body(fail):
        slots = [e.label() for _ in range(PLS_RECORDS)]
        full, logged, abort, done = e.label(), e.label(), e.label(), e.label()
        for k in range(PLS_RECORDS - 1):
            e.i("L", count)
            e.i("L", str(k))
            e.i("==I")
            e.i("JC", slots[k])
        e.i("L", count)
        e.i("L", str(PLS_RECORDS - 1))
        e.i("==I")
        e.i("JCN", full)
        for k, lab in enumerate(slots):
            r = lay.pls_record(ch, k)
            e.place(lab)
            regs = ((67, 0, "B"), (68, 2, "W"), (72, 4, "D"), (168, 8, "W"))
            for reg, off, w in regs:
                src, dst = f"M{w} {sm + reg}", f"M{w} {r + off}"
                e.i("L", src)
                e.i("T", dst)
            e.i("JU", logged)
        e.place(full)
        e.i("SET")
        e.i("S", f"M {lay.pls_record(ch) - 1}.0")  # more than PLS_RECORDS this scan
        e.i("JU", done)
        e.place(logged)
        e.i("L", count)
        e.i("L", "1")
        e.i("+I")
        e.i("T", count)
        e.i("A", f"M {sm + 67}.7")
        e.i("JCN", abort)
        e.i("A", f"M {sm + 67}.6")
        e.i("JC", done)
        e.i("SET")
        e.i("R", f"M {sm + 66}.7")
        e.i("JU", done)
        e.place(abort)
        e.i("AN", f"M {sm + 66}.7")
        e.i("S", f"M {sm + 66}.5")
        e.i("SET")
        e.i("S", f"M {sm + 66}.7")
        e.place(done)

    e.box(body)


BY_OP = {
    "NOT": _not_,
    "AENO": _aeno,
    "EU": _edge,
    "ED": _edge,
    "LPS": _lps,
    "LRD": _lrd_lpp,
    "LPP": _lrd_lpp,
    "ALD": _ald_old,
    "OLD": _ald_old,
    "LDS": _lds,
    "NOP": _nop,
    "JMP": _jmp,
    "LBL": _lbl,
    "CRET": _cret,
    "END": _end,
    "ROUND": _round_trunc,
    "TRUNC": _round_trunc,
    "DTR": _dtr_itd,
    "ITD": _dtr_itd,
    "DTI": _dti,
    "CALL": _call,
    "PLS": _pls,
}
BY_BUILDER = {
    "contact": _contact,
    "compare": _compare,
    "coil": _coil,
    "setreset": _setreset,
    "move": _move,
    "math_r": _math,
    "math_i": _math,
    "math_d": _math,
    "func": _func,
    "logic": _logic,
    "incdec": _incdec,
}


def emit_statement(e, st, classes, o, builder) -> None:
    """The AWL of statement ``st`` (its resolved operands ``o``, its builder family) into
    the emitter ``e``; ValueError for what is not translated."""
    op = st.op
    e.out.append(f"      // {st.text}")
    if op in NOT_TRANSLATED:
        raise ValueError(NOT_TRANSLATED[op])
    handler = BY_OP.get(op) or BY_BUILDER.get(builder)
    if handler is None:
        raise ValueError(f"{op} is not translated")
    handler(e, st, o)
