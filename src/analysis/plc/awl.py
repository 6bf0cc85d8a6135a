"""S7-300/400 AWL (STEP 7 STL, English mnemonics): :class:`AwlPrinter`.

The S7-200 printer's shape (:class:`analysis.plc.s7200.S7200Printer`: a header, blocks,
networks, one method per flat IR instruction, labels per block) in AWL: ``L a``/``L b``/
``+R``/``T d``; ``RND`` (ties to even: see :mod:`.runner`); ``JC``/``JU``; the same bit
test with ``AD``/``==D``; no power flow; blocks ``FUNCTION FC n`` (the subroutines),
``OB 100`` (start-up), ``OB 1``; then the peephole pass (:func:`~.peephole.optimize_awl`).
"""

from __future__ import annotations

from typing import ClassVar

from analysis.plc.instr import CMP, Program, Subroutine
from analysis.plc.memmap import MemoryMap
from analysis.plc.peephole import optimize_awl
from analysis.plc.printer import Options, fmt_real
from analysis.plc.s7200 import NAN_MASK, S7200Printer

__all__ = ["AwlPrinter"]


class AwlPrinter(S7200Printer):
    """S7-300/400 AWL (module docstring): the S7-200 printer's shape, AWL's instructions."""

    name = "s7-300"
    title = "S7-300/400 AWL (STEP 7 STL)"
    trigs = ("native", "subroutine", "function")
    rounding = "half-even"
    engine = "awlsim"
    max_program_bytes = 1024 * 1024
    """awlsim parses 1 MiB of AWL in about 17 s and 125 MB here (the CPU 317's work memory
    is 1 MB): the bound of what one program may take."""
    target = "the S7-300"
    trig_reason = ""
    indent = "      "
    newline = "\n"
    exp_char = "e"
    startup_where = "OB100 (start-up)"
    known_functions: ClassVar[dict[str, str]] = {
        "sqrt": "SQRT",
        "sin": "SIN",
        "cos": "COS",
        "atan": "ATAN",
        "acos": "ACOS",
    }

    def __init__(
        self,
        mmap: MemoryMap,
        work: dict[str, int] | None = None,
        *,
        startup_target=None,
        extra_ob1: list[str] | None = None,
        optimize: bool = True,
    ) -> None:
        super().__init__(mmap, work, startup_target=startup_target)
        self.extra_ob1, self.optimize = extra_ob1, optimize

    def block(self, local: Subroutine | None) -> None:
        super().block(local)
        self.first = True

    def lab(self, name: str) -> str:
        if name not in self.labels:
            self.labels[name] = f"X{len(self.labels) + 1:03d}"
        return self.labels[name]

    # --- lines: no power flow -----------------------------------------------------------------
    def network(self, title: str = "") -> None:
        if not self.first:
            self.lines.append("")
        self.lines += ["NETWORK", f"TITLE = {self.text(title)}"]
        self.first = False

    def ins(self, op: str, arg: str = "") -> None:
        self.lines.append(f"      {op:<6}{arg}".rstrip())

    box = logic = ins

    def label(self, name: str) -> None:
        self.lines.append(f"{self.lab(name)}: NOP   0")

    # --- blocks -----------------------------------------------------------------------------------
    def header(self, program: Program) -> list[str]:
        return [
            self.comment(program.title),
            *(self.comment(n) for n in program.notes),
            self.comment(self.generated_by()),
            "",
        ]

    def subroutine_block(self, sub: Subroutine) -> None:
        self.block(sub)
        self.lines += [f"FUNCTION FC {sub.number} : VOID", f"TITLE = {self.text(sub.title)}"]
        for kw, names in (("VAR_INPUT", sub.inputs), ("VAR_OUTPUT", sub.outputs),
                          ("VAR_TEMP", sub.temps)):  # fmt: skip
            self.lines += [kw, *(f"  {n} : REAL;" for n in names), "END_VAR"]
        self.lines.append("BEGIN")
        self.body(sub.body)
        self.lines += ["END_FUNCTION", ""]

    def startup_block(self, program: Program) -> None:
        """OB100: the example target written on start-up (Figure 3), if one is given."""
        if self.startup_target is None:
            return
        self.lines += [
            "ORGANIZATION_BLOCK OB 100",
            "TITLE = " + program.cite("startup: the paper's example target (Fig. 3)"),
            "BEGIN",
        ]
        for name, v in zip(program.inputs, self.startup_target, strict=True):
            self.lines += [f"      L     {fmt_real(v)}", f"      T     {self.mmap.address(name)}"]
        self.lines += ["END_ORGANIZATION_BLOCK", ""]

    def main_block(self, program: Program) -> None:
        self.block(None)
        self.lines += ["ORGANIZATION_BLOCK OB 1", f"TITLE = {self.text(program.title)}", "BEGIN"]
        self.body(program.body)
        self.lines += [*(self.extra_ob1 or ()), "END_ORGANIZATION_BLOCK", ""]

    def doprint_program(self, program: Program) -> str:
        """The whole source: the FCs, OB100, OB1; then the peephole pass (``optimize``)."""
        self.subs = {s.name: s for s in program.subroutines}
        self.lines = self.header(program)
        for s in program.subroutines:
            self.subroutine_block(s)
        self.startup_block(program)
        self.main_block(program)
        text = self.newline.join(self.lines)
        return optimize_awl(text) if self.optimize else text

    # --- values -----------------------------------------------------------------------------------
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

    # --- control ----------------------------------------------------------------------------------
    def compare(self, op: str, a: str, b: str) -> None:
        """``L a``, ``L b``, ``<op>R``: the compare sets the RLO."""
        if op not in CMP:
            raise ValueError(f"unknown compare {op!r}")
        self.ins("L", a)
        self.ins("L", b)
        self.ins(f"{op}R")

    def _print_jcmp(self, i):
        cmp, a, b, target = i.args
        self.compare(cmp, self.o(a), self.o(b))
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
        self.ins("CALL", f"FC {sub.number} ({', '.join(binds)})")

    # --- the dialect's output ---------------------------------------------------------------------
    @classmethod
    def printer(cls, mmap, work, start, options: Options, arm) -> AwlPrinter:
        return cls(mmap, work, startup_target=start, optimize=options.optimize)

    @classmethod
    def session(cls, text: str, *, cpu: str | None = None, source: str = "program"):
        from analysis.plc.engines import AwlSession

        return AwlSession(text, cpu=cpu, source=source)

    @classmethod
    def awlsim_source(cls, text: str) -> str:
        return text
