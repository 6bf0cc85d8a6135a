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

from typing import ClassVar

import numpy as np

from analysis.kinematics.printing import Printer
from analysis.plc.ir import CMP, Program, Subroutine, flatten
from analysis.plc.memmap import MemoryMap, default_map
from analysis.plc.peephole import optimize_awl

__all__ = [
    "AwlPrinter",
    "S7200Printer",
    "allocate",
    "emit_s7200",
    "emit_s7200_subroutines",
    "emit_s7300",
    "fmt_real",
]

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
    mmap.check_end(mmap.work_base + 4 * len(program.work) - 1, "the work area")
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
class AwlPrinter(Printer):
    """S7-300/400 AWL: one method per IR instruction (:func:`~.ir.flatten`'s flat form)."""

    target = "the S7-300"
    control = ("mov", "seti", "jcmp", "jnotfinite", "jmp", "label", "set", "reset", "call")
    known_functions: ClassVar[dict[str, str]] = {
        "sqrt": "SQRT",
        "sin": "SIN",
        "cos": "COS",
        "atan": "ATAN",
        "acos": "ACOS",
    }
    infix: ClassVar[dict[str, str]] = {"add": "+R", "sub": "-R", "mul": "*R", "div": "/R"}
    compares: ClassVar[dict[str, str]] = {
        "<": "<R",
        "<=": "<=R",
        ">": ">R",
        ">=": ">=R",
        "==": "==R",
        "<>": "<>R",
    }

    def __init__(self, ctx: _Ctx, fc_numbers: dict[str, int], subs: dict[str, Subroutine]):
        self.ctx, self.fc_numbers, self.subs = ctx, fc_numbers, subs
        self.out: list[str] = []
        self.nlab = 0

    def print_code(self, code) -> list[str]:
        first = True
        for i in flatten(code):
            if i.op == "network":
                if not first:
                    self.out.append("")
                self.out += ["NETWORK", f"TITLE = {i.args[0]}"]
                first = False
                continue
            if i.comment:
                self.out.append(f"      // {i.comment}")
            self.doprint(i.op, i)
        return self.out

    # --- helpers ----------------------------------------------------------------------------
    def o(self, a) -> str:
        return self.ctx.opnd(a)

    def lab(self, name: str) -> str:
        if name not in self.ctx.labels:
            self.nlab += 1
            self.ctx.labels[name] = f"X{self.nlab:03d}"
        return self.ctx.labels[name]

    def ins(self, op: str, arg: str = "") -> None:
        self.out.append(f"      {op:<6}{arg}".rstrip())

    # --- values -----------------------------------------------------------------------------
    def _print_mov(self, i):
        self.ins("L", self.o(i.args[0]))
        self.ins("T", self.o(i.dst))

    def _print_infix(self, op, i):
        self.ins("L", self.o(i.args[0]))
        self.ins("L", self.o(i.args[1]))
        self.ins(self.infix[op])
        self.ins("T", self.o(i.dst))

    def _print_function(self, op, i):
        self.ins("L", self.o(i.args[0]))
        self.ins(self.known_functions[op])
        self.ins("T", self.o(i.dst))

    def _print_round(self, i):
        self.ins("L", self.o(i.args[0]))
        self.ins("RND")
        self.ins("T", self.o(i.dst))

    def _print_seti(self, i):
        self.ins("L", f"L#{int(i.args[0])}")
        self.ins("T", self.o(i.dst))

    # --- control ----------------------------------------------------------------------------
    def _print_jcmp(self, i):
        cmp, a, b, target = i.args
        self.ins("L", self.o(a))
        self.ins("L", self.o(b))
        self.ins(self.compares[cmp])
        self.ins("JC", self.lab(target))

    def _print_jnotfinite(self, i):
        a, target = i.args
        self.ins("L", self.o(a))
        self.ins("L", f"DW#16#{NAN_MASK:08X}")
        self.ins("AD")
        self.ins("L", f"DW#16#{NAN_MASK:08X}")
        self.ins("==D")
        self.ins("JC", self.lab(target))

    def _print_jmp(self, i):
        self.ins("JU", self.lab(i.args[0]))

    def _print_label(self, i):
        self.out.append(f"{self.lab(i.args[0])}: NOP   0")

    def _print_set(self, i):
        self.ins("SET")
        self.ins("S", self.o(i.dst))

    def _print_reset(self, i):
        self.ins("SET")
        self.ins("R", self.o(i.dst))

    def _print_call(self, i):
        name, ins_, outs = i.args
        if set(outs) & {a for a in ins_ if isinstance(a, str)}:
            # an FC gets references: an output aliasing an input would be overwritten
            raise ValueError(f"{i}: an output of CALL {name} is also an input")
        sub = self.subs[name]
        binds = [f"{p} := {self.o(a)}" for p, a in zip(sub.inputs, ins_, strict=True)]
        binds += [f"{p} := {self.o(a)}" for p, a in zip(sub.outputs, outs, strict=True)]
        self.ins("CALL", f"FC {self.fc_numbers[name]} ({', '.join(binds)})")


def _awl_body(
    code, ctx: _Ctx, fc_numbers: dict[str, int], sub_params: dict[str, Subroutine]
) -> list[str]:
    return AwlPrinter(ctx, fc_numbers, sub_params).print_code(code)


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


class S7200Printer(Printer):
    """S7-200 STL (Micro/WIN text): one method per IR instruction (the flat form)."""

    target = "the S7-200"
    control = ("mov", "seti", "jcmp", "jnotfinite", "jmp", "label", "set", "reset", "call")
    known_functions: ClassVar[dict[str, str]] = {"sqrt": "SQRT", "sin": "SIN", "cos": "COS"}
    infix: ClassVar[dict[str, str]] = {"add": "+R", "sub": "-R", "mul": "*R", "div": "/R"}
    compares: ClassVar[dict[str, str]] = {
        "<": "<",
        "<=": "<=",
        ">": ">",
        ">=": ">=",
        "==": "=",
        "<>": "<>",
    }

    def __init__(self, ctx: _Ctx, sbr: dict[str, int], w: _S200Writer):
        self.ctx, self.sbr, self.w = ctx, sbr, w
        self.nlab = 0

    def print_code(self, code) -> None:
        w = self.w
        for i in flatten(code):
            if i.op == "network":
                w.network(i.args[0])
                continue
            if i.op == "label":
                if not w.empty:
                    w.network()
                w.logic("LBL", str(self.lab(i.args[0])))
                continue
            if i.comment:
                w.lines.append(f"// {i.comment}")
            self.doprint(i.op, i)

    # --- helpers ----------------------------------------------------------------------------
    def lab(self, name: str) -> int:
        if name not in self.ctx.labels:
            self.ctx.labels[name] = self.nlab
            self.nlab += 1
        return self.ctx.labels[name]

    def o(self, a) -> str:
        return self.ctx.opnd(a, "E")

    # --- values -----------------------------------------------------------------------------
    def _print_mov(self, i):
        self.w.box("MOVR", f"{self.o(i.args[0])}, {self.o(i.dst)}")

    def _print_infix(self, op, i):
        """``d := a op b`` with the in-place two-operand instructions (module docstring)."""
        a, b = i.args
        w, o, mnem = self.w, self.o, self.infix[op]
        if i.dst == a:
            w.box(mnem, f"{o(b)}, {o(i.dst)}")
        elif i.dst == b and op in ("add", "mul"):
            w.box(mnem, f"{o(a)}, {o(i.dst)}")
        elif i.dst == b and op == "sub" and a == 0.0:
            w.box("*R", f"-1.0, {o(i.dst)}")
        elif i.dst == b and op == "sub":
            w.box("-R", f"{o(a)}, {o(i.dst)}")
            w.box("*R", f"-1.0, {o(i.dst)}")
        elif i.dst == b:
            raise ValueError(f"{i}: d = a / d has no in-place S7-200 form; use a temporary")
        else:
            w.box("MOVR", f"{o(a)}, {o(i.dst)}")
            w.box(mnem, f"{o(b)}, {o(i.dst)}")

    def _print_function(self, op, i):
        self.w.box(self.known_functions[op], f"{self.o(i.args[0])}, {self.o(i.dst)}")

    def _print_atan(self, i):
        raise ValueError(
            "the S7-200 has no ATAN/ACOS instruction: build the program with trig='subroutine'"
        )

    _print_acos = _print_atan

    def _print_round(self, i):
        self.w.box("ROUND", f"{self.o(i.args[0])}, {self.o(i.dst)}")

    def _print_seti(self, i):
        self.w.box("MOVD", f"{int(i.args[0])}, {self.o(i.dst)}")

    # --- control ----------------------------------------------------------------------------
    def _print_jcmp(self, i):
        cmp, a, b, target = i.args
        if cmp not in CMP:
            raise ValueError(f"unknown compare {cmp!r}")
        self.w.logic(f"LDR{self.compares[cmp]}", f"{self.o(a)}, {self.o(b)}")
        self.w.ins("JMP", str(self.lab(target)))

    def _print_jnotfinite(self, i):
        a, target = i.args
        w = self.w
        w.box("MOVD", f"{self.o(a)}, AC0")
        w.box("ANDD", f"16#{NAN_MASK:08X}, AC0")
        w.logic("LDD=", f"AC0, 16#{NAN_MASK:08X}")
        w.ins("JMP", str(self.lab(target)))

    def _print_jmp(self, i):
        self.w.box("JMP", str(self.lab(i.args[0])))

    def _print_set(self, i):
        self.w.box("S", f"{self.o(i.dst)}, 1")

    def _print_reset(self, i):
        self.w.box("R", f"{self.o(i.dst)}, 1")

    def _print_call(self, i):
        name, ins_, outs = i.args
        args = [f"SBR{self.sbr[name]}", *(self.o(a) for a in (*ins_, *outs))]
        self.w.box("CALL", ", ".join(args))


def _s200_body(code, ctx: _Ctx, sbr: dict[str, int], w: _S200Writer) -> None:
    S7200Printer(ctx, sbr, w).print_code(code)


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
