"""Emitters: :class:`~.ir.Program` -> S7-200 STL (Micro/WIN text) and S7-300/400 AWL.

S7-200 (the paper's dialect; S7-200 System Manual, STL instructions)
    Two-operand in-place REAL math (``+R IN1, OUT``: OUT := OUT + IN1; ``-R``, ``/R``:
    OUT := OUT op IN1; ``*R``: OUT := IN1 * OUT), so ``d = a op b`` becomes ``MOVR a, d`` +
    ``op b, d``; ``d = a - d`` becomes ``-R a, d`` + ``*R -1.0, d`` (exact negation).
    Box instructions run on power flow, so each run of them starts with ``LD SM0.0``
    (always on; the paper writes it as "上电置1"). Compares are ``LDR<op>`` + ``JMP n``;
    the finiteness test is ``MOVD``/``ANDD 16#7F800000``/``LDD=`` on AC0 (DINT, no REAL
    compare). Subroutines are ``SUBROUTINE_BLOCK name:SBRn`` with ``#local`` names.
S7-300/400 (AWL, German mnemonics not used)
    ``L a``/``L b``/``+R``/``T d``; ``RND`` (ties to even: see notes in :mod:`.runner`);
    ``JC``/``JU``; the same bit test with ``AD``/``==D``; subroutines are FCs.
"""

from __future__ import annotations

import numpy as np

from analysis.plc.ir import CMP, Program, Subroutine
from analysis.plc.memmap import MemoryMap, default_map
from analysis.plc.peephole import optimize_awl

__all__ = ["allocate", "emit_s7200", "emit_s7200_subroutines", "emit_s7300", "fmt_real"]

NAN_MASK = 0x7F800000


def fmt_real(v: float, exp_char: str = "e") -> str:
    """A REAL literal with a decimal point, 9 significant digits of the float32 value."""
    v = float(np.float32(v))
    if v == 0:
        return "0.0"
    s = f"{v:.9g}"
    if "e" in s:
        m, e = s.split("e")
        if "." not in m:
            m += ".0"
        return f"{m}{exp_char}{int(e)}"
    return s if "." in s else s + ".0"


def allocate(program: Program, mmap: MemoryMap) -> dict[str, int]:
    """Byte offset of every work variable (4 bytes each from ``mmap.work_base``)."""
    end = mmap.work_base + 4 * len(program.work) - 1
    if end > 2047:
        raise ValueError(
            f"work area {mmap.work_base}..{end} ends beyond byte 2047; lower work_base"
        )
    return {name: mmap.work_base + 4 * i for i, name in enumerate(program.work)}


class _Ctx:
    def __init__(self, mmap: MemoryMap, work: dict[str, int], local: Subroutine | None):
        self.mmap, self.work, self.local = mmap, work, local
        self.labels: dict[str, str] = {}

    def opnd(self, a, exp_char="e") -> str:
        if isinstance(a, float):
            return fmt_real(a, exp_char)
        if self.local is not None:
            return f"#{a}"
        if a in self.work:
            return self.mmap.dword(self.work[a])
        return self.mmap.address(a)


# ---------------------------------------------------------------------- S7-300 / AWL
_AWL_CMP = {"<": "<R", "<=": "<=R", ">": ">R", ">=": ">=R", "==": "==R", "<>": "<>R"}
_AWL_ARITH = {"add": "+R", "sub": "-R", "mul": "*R", "div": "/R"}
_AWL_UNARY = {"sqrt": "SQRT", "sin": "SIN", "cos": "COS", "atan": "ATAN", "acos": "ACOS"}


def _awl_body(
    code, ctx: _Ctx, fc_numbers: dict[str, int], sub_params: dict[str, Subroutine]
) -> list[str]:
    out: list[str] = []
    nlab = 0

    def lab(name: str) -> str:
        nonlocal nlab
        if name not in ctx.labels:
            nlab += 1
            ctx.labels[name] = f"X{nlab:03d}"
        return ctx.labels[name]

    def ins(op: str, arg: str = "") -> None:
        out.append(f"      {op:<6}{arg}".rstrip())

    first = True
    for i in code:
        o = ctx.opnd
        if i.op == "network":
            if not first:
                out.append("")
            out.append("NETWORK")
            out.append(f"TITLE = {i.args[0]}")
            first = False
            continue
        if i.comment:
            out.append(f"      // {i.comment}")
        if i.op == "mov":
            ins("L", o(i.args[0]))
            ins("T", o(i.dst))
        elif i.op in _AWL_ARITH:
            ins("L", o(i.args[0]))
            ins("L", o(i.args[1]))
            ins(_AWL_ARITH[i.op])
            ins("T", o(i.dst))
        elif i.op in _AWL_UNARY:
            ins("L", o(i.args[0]))
            ins(_AWL_UNARY[i.op])
            ins("T", o(i.dst))
        elif i.op == "round":
            ins("L", o(i.args[0]))
            ins("RND")
            ins("T", o(i.dst))
        elif i.op == "seti":
            ins("L", f"L#{int(i.args[0])}")
            ins("T", o(i.dst))
        elif i.op == "jcmp":
            cmp, a, b, target = i.args
            ins("L", o(a))
            ins("L", o(b))
            ins(_AWL_CMP[cmp])
            ins("JC", lab(target))
        elif i.op == "jnotfinite":
            a, target = i.args
            ins("L", o(a))
            ins("L", f"DW#16#{NAN_MASK:08X}")
            ins("AD")
            ins("L", f"DW#16#{NAN_MASK:08X}")
            ins("==D")
            ins("JC", lab(target))
        elif i.op == "jmp":
            ins("JU", lab(i.args[0]))
        elif i.op == "label":
            out.append(f"{lab(i.args[0])}: NOP   0")
        elif i.op in ("set", "reset"):
            ins("SET")
            ins("S" if i.op == "set" else "R", o(i.dst))
        elif i.op == "call":
            name, ins_, outs = i.args
            if set(outs) & {a for a in ins_ if isinstance(a, str)}:
                # an FC gets references: an output aliasing an input would be overwritten
                raise ValueError(f"{i}: an output of CALL {name} is also an input")
            sub = sub_params[name]
            binds = [f"{p} := {o(a)}" for p, a in zip(sub.inputs, ins_, strict=True)]
            binds += [f"{p} := {o(a)}" for p, a in zip(sub.outputs, outs, strict=True)]
            ins("CALL", f"FC {fc_numbers[name]} ({', '.join(binds)})")
        else:
            raise ValueError(f"unknown IR op {i.op!r}")
    return out


def emit_s7300(
    program: Program,
    mmap: MemoryMap | None = None,
    *,
    startup_target=(100.0, 100.0, 600.0),
    extra_ob1: list[str] | None = None,
    optimize: bool = True,
) -> str:
    """S7-300/400 AWL source of ``program`` (FCs, OB100 with the Figure 3 target, OB1).

    Parameters
    ----------
    program : Program
    mmap : MemoryMap, optional
        Dialect must be "s7-300" (default map if omitted).
    startup_target : 3 floats or None
        Written to the inputs in OB100 (startup), like the paper's Figure 3 example
        (100, 100, 600) mm; None leaves the inputs alone.
    extra_ob1 : list of str, optional
        AWL lines appended to OB1.
    optimize : bool
        Remove reloads of a value just stored and stores overwritten before they are read
        (:func:`~.peephole.optimize_awl`): the same results in fewer instructions.
    """
    mmap = mmap or default_map("s7-300", program.inputs, len(program.outputs))
    mmap.check_program(program.inputs, program.outputs)
    if mmap.dialect != "s7-300":
        raise ValueError(f"emit_s7300 needs an s7-300 memory map, got {mmap.dialect!r}")
    work = allocate(program, mmap)
    fcn = {s.name: s.number for s in program.subroutines}
    subs = {s.name: s for s in program.subroutines}
    lines = [
        f"// {program.title}",
        *(f"// {n}" for n in program.notes),
        "// generated by analysis.plc (python -m analysis stl --dialect s7-300)",
        "",
    ]
    for s in program.subroutines:
        lines += [f"FUNCTION FC {s.number} : VOID", f"TITLE = {s.title}"]
        for kw, names in (
            ("VAR_INPUT", s.inputs),
            ("VAR_OUTPUT", s.outputs),
            ("VAR_TEMP", s.temps),
        ):
            lines += [kw, *(f"  {n} : REAL;" for n in names), "END_VAR"]
        lines.append("BEGIN")
        lines += _awl_body(s.body, _Ctx(mmap, work, s), fcn, subs)
        lines += ["END_FUNCTION", ""]
    if startup_target is not None:
        lines += [
            "ORGANIZATION_BLOCK OB 100",
            "TITLE = startup: the paper's example target (Fig. 3)",
            "BEGIN",
        ]
        for name, v in zip(program.inputs, startup_target, strict=True):
            lines += [f"      L     {fmt_real(v)}", f"      T     {mmap.address(name)}"]
        lines += ["END_ORGANIZATION_BLOCK", ""]
    lines += ["ORGANIZATION_BLOCK OB 1", f"TITLE = {program.title}", "BEGIN"]
    lines += _awl_body(program.body, _Ctx(mmap, work, None), fcn, subs)
    if extra_ob1:
        lines += extra_ob1
    lines += ["END_ORGANIZATION_BLOCK", ""]
    text = "\n".join(lines)
    return optimize_awl(text) if optimize else text


# ---------------------------------------------------------------------- S7-200 STL
_S2_CMP = {"<": "<", "<=": "<=", ">": ">", ">=": ">=", "==": "=", "<>": "<>"}
_S2_ARITH = {"add": "+R", "sub": "-R", "mul": "*R", "div": "/R"}
_S2_UNARY = {"sqrt": "SQRT", "sin": "SIN", "cos": "COS"}


class _S200Writer:
    """Writes networks; tracks whether power flow is known to be on (after LD SM0.0)."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.net = 0
        self.power = False
        self.empty = False

    def network(self, title: str = "") -> None:
        self.net += 1
        self.lines.append(f"Network {self.net}" + (f" // {title}" if title else ""))
        self.power = False
        self.empty = True

    def ins(self, op: str, arg: str = "") -> None:
        self.empty = False
        self.lines.append(f"{op:<7}{arg}".rstrip())

    def box(self, op: str, arg: str = "") -> None:
        if not self.power:
            self.ins("LD", "SM0.0")
            self.power = True
        self.ins(op, arg)

    def logic(self, op: str, arg: str = "") -> None:
        self.ins(op, arg)
        self.power = False


def _s200_body(code, ctx: _Ctx, sbr: dict[str, int], w: _S200Writer) -> None:
    nlab = 0

    def lab(name: str) -> int:
        nonlocal nlab
        if name not in ctx.labels:
            ctx.labels[name] = nlab
            nlab += 1
        return ctx.labels[name]

    def o(a) -> str:
        return ctx.opnd(a, "E")

    for i in code:
        if i.op == "network":
            w.network(i.args[0])
            continue
        if i.op == "label":
            if not w.empty:
                w.network()
            w.logic("LBL", str(lab(i.args[0])))
            continue
        if i.comment:
            w.lines.append(f"// {i.comment}")
        if i.op == "mov":
            w.box("MOVR", f"{o(i.args[0])}, {o(i.dst)}")
        elif i.op in _S2_ARITH:
            a, b = i.args
            op = _S2_ARITH[i.op]
            if i.dst == a:
                w.box(op, f"{o(b)}, {o(i.dst)}")
            elif i.dst == b and i.op in ("add", "mul"):
                w.box(op, f"{o(a)}, {o(i.dst)}")
            elif i.dst == b and i.op == "sub" and a == 0.0:
                w.box("*R", f"-1.0, {o(i.dst)}")
            elif i.dst == b and i.op == "sub":
                w.box("-R", f"{o(a)}, {o(i.dst)}")
                w.box("*R", f"-1.0, {o(i.dst)}")
            elif i.dst == b:
                raise ValueError(f"{i}: d = a / d has no in-place S7-200 form; use a temporary")
            else:
                w.box("MOVR", f"{o(a)}, {o(i.dst)}")
                w.box(op, f"{o(b)}, {o(i.dst)}")
        elif i.op in _S2_UNARY:
            w.box(_S2_UNARY[i.op], f"{o(i.args[0])}, {o(i.dst)}")
        elif i.op in ("atan", "acos"):
            raise ValueError(
                "the S7-200 has no ATAN/ACOS instruction: build the program with trig='subroutine'"
            )
        elif i.op == "round":
            w.box("ROUND", f"{o(i.args[0])}, {o(i.dst)}")
        elif i.op == "seti":
            w.box("MOVD", f"{int(i.args[0])}, {o(i.dst)}")
        elif i.op == "jcmp":
            cmp, a, b, target = i.args
            if cmp not in CMP:
                raise ValueError(f"unknown compare {cmp!r}")
            w.logic(f"LDR{_S2_CMP[cmp]}", f"{o(a)}, {o(b)}")
            w.ins("JMP", str(lab(target)))
        elif i.op == "jnotfinite":
            a, target = i.args
            w.box("MOVD", f"{o(a)}, AC0")
            w.box("ANDD", f"16#{NAN_MASK:08X}, AC0")
            w.logic("LDD=", f"AC0, 16#{NAN_MASK:08X}")
            w.ins("JMP", str(lab(target)))
        elif i.op == "jmp":
            w.box("JMP", str(lab(i.args[0])))
        elif i.op in ("set", "reset"):
            w.box("S" if i.op == "set" else "R", f"{o(i.dst)}, 1")
        elif i.op == "call":
            name, ins_, outs = i.args
            w.box("CALL", ", ".join([f"SBR{sbr[name]}", *(o(a) for a in (*ins_, *outs))]))
        else:
            raise ValueError(f"unknown IR op {i.op!r}")


def emit_s7200(
    program: Program,
    mmap: MemoryMap | None = None,
    *,
    startup_target=(100.0, 100.0, 600.0),
    motion: list[str] | None = None,
) -> str:
    """S7-200 STL (STEP 7-Micro/WIN text form) of ``program``.

    OB1 networks: the Figure 3 data acquisition on the first scan (``SM0.1``, REAL moves,
    unlike the paper's ``MOVD 100, VD0``), then the IK networks (Figures 4-6 corrected),
    then ``motion`` networks if given (see :mod:`.motion`). Subroutines follow OB1.
    """
    mmap = mmap or default_map("s7-200", program.inputs, len(program.outputs))
    mmap.check_program(program.inputs, program.outputs)
    if mmap.dialect != "s7-200":
        raise ValueError(f"emit_s7200 needs an s7-200 memory map, got {mmap.dialect!r}")
    if program.trig != "subroutine":
        raise ValueError(
            "the S7-200 has no ATAN/ACOS instruction: build the program with trig='subroutine'"
        )
    work = allocate(program, mmap)
    sbr = {s.name: s.number for s in program.subroutines}
    w = _S200Writer()
    w.lines += [
        "ORGANIZATION_BLOCK MAIN:OB1",
        f"TITLE={program.title}",
        *(f"// {n}" for n in program.notes),
        "// generated by analysis.plc (python -m analysis stl --dialect s7-200)",
        "BEGIN",
    ]
    if startup_target is not None:
        w.network("data acquisition (Fig. 3): example target on the first scan, as REALs")
        w.logic("LD", "SM0.1")
        w.power = True
        for name, v in zip(program.inputs, startup_target, strict=True):
            w.ins("MOVR", f"{fmt_real(v, 'E')}, {mmap.address(name)}")
    _s200_body(program.body, _Ctx(mmap, work, None), sbr, w)
    if motion:
        for line in motion:
            if line.startswith("Network "):
                w.network(line.split("// ", 1)[1] if "// " in line else "")
            else:
                w.lines.append(line)
    w.lines += ["END_ORGANIZATION_BLOCK"]
    for s in program.subroutines:
        w.lines += [f"SUBROUTINE_BLOCK {s.name}:SBR{s.number}", f"TITLE={s.title}"]
        for kw, names in (("VAR_INPUT", s.inputs), ("VAR_OUTPUT", s.outputs), ("VAR", s.temps)):
            w.lines += [kw, *(f"{n}:REAL;" for n in names), "END_VAR"]
        w.lines.append("BEGIN")
        w.net = 0
        _s200_body(s.body, _Ctx(mmap, work, s), sbr, w)
        w.lines.append("END_SUBROUTINE_BLOCK")
    return "\r\n".join(w.lines) + "\r\n"


def emit_s7200_subroutines(subs: list[Subroutine], mmap: MemoryMap | None = None) -> str:
    """S7-200 text of subroutine blocks only (e.g. to go with the paper's own OB1)."""
    mmap = mmap or default_map("s7-200")
    sbr = {s.name: s.number for s in subs}
    w = _S200Writer()
    for s in subs:
        w.lines += [f"SUBROUTINE_BLOCK {s.name}:SBR{s.number}", f"TITLE={s.title}"]
        for kw, names in (("VAR_INPUT", s.inputs), ("VAR_OUTPUT", s.outputs), ("VAR", s.temps)):
            w.lines += [kw, *(f"{n}:REAL;" for n in names), "END_VAR"]
        w.lines.append("BEGIN")
        w.net = 0
        _s200_body(s.body, _Ctx(mmap, {}, s), sbr, w)
        w.lines.append("END_SUBROUTINE_BLOCK")
    return "\r\n".join(w.lines) + "\r\n"
