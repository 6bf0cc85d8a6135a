"""S7-200 STL (STEP 7-Micro/WIN text), the paper's dialect: :class:`S7200Printer`.

S7-200 System Manual, STL instructions: two-operand in-place REAL math (``+R IN1, OUT``:
OUT := OUT + IN1; ``-R``, ``/R``: OUT := OUT op IN1; ``*R``: OUT := IN1 * OUT), so ``d = a op
b`` becomes ``MOVR a, d`` + ``op b, d``; ``d = a - d`` becomes ``-R a, d`` + ``*R -1.0, d``
(exact negation). Box instructions run on power flow, so each run of them starts with ``LD
SM0.0`` (always on; the paper writes it as "上电置1"). Compares are ``LDR<op>`` + ``JMP n``;
the finiteness test is ``MOVD``/``ANDD 16#7F800000``/``LDD=`` on AC0 (DINT, no REAL
compare). Blocks: ``ORGANIZATION_BLOCK MAIN:OB1`` (the first-scan network, the IK networks,
the motion networks) and ``SUBROUTINE_BLOCK name:SBRn`` with ``#local`` names.

The printer prints the flat form of the IR (:func:`~analysis.plc.instr.flatten`). Addresses
come from a :class:`~analysis.plc.memmap.MemoryMap` and the work area allocated once
(:func:`allocate`). :class:`analysis.plc.awl.AwlPrinter` (S7-300 AWL) has its shape.
"""

from __future__ import annotations

import json
from typing import ClassVar

from analysis.escape import one_line
from analysis.plc.instr import CMP, Program, Subroutine, flatten
from analysis.plc.mapdoc import s7_document, startup_values
from analysis.plc.memmap import MemoryMap, default_map
from analysis.plc.printer import Generated, Options, PlcPrinter, fmt_real
from analysis.plc.stl_eval.syntax import MAX_PROGRAM_CHARS

__all__ = ["NAN_MASK", "S7200Printer", "allocate"]

NAN_MASK = 0x7F800000
"""The exponent bits of a REAL: all ones for inf and NaN (the finiteness bit test)."""


def allocate(program: Program, mmap: MemoryMap) -> dict[str, int]:
    """Byte offset of every work variable (4 bytes each from ``mmap.work_base``), checked
    against the target CPU's memory (ValueError naming the CPU and the limit)."""
    mmap.check_end(mmap.work_base + 4 * len(program.work) - 1, "the work area")
    return {name: mmap.work_base + 4 * i for i, name in enumerate(program.work)}


class S7200Printer(PlcPrinter):
    """S7-200 STL (module docstring): the program's blocks, one method per IR instruction of
    the flat form, power flow tracked (``LD SM0.0`` before a run of box instructions)."""

    name = "s7-200"
    title = "S7-200 STL (STEP 7-Micro/WIN text, the paper's dialect)"
    trigs = ("subroutine",)
    addresses = True
    engine = "the project's S7-200 evaluator"
    max_program_bytes = MAX_PROGRAM_CHARS  # the evaluator's own limit
    target = "the S7-200"
    newline = "\r\n"
    exp_char = "E"
    startup_where = "the first scan (SM0.1)"
    control = ("mov", "seti", "jcmp", "jnotfinite", "jmp", "label", "set", "reset", "call")
    known_functions: ClassVar[dict[str, str]] = {"sqrt": "SQRT", "sin": "SIN", "cos": "COS"}
    infix: ClassVar[dict[str, str]] = {"add": "+R", "sub": "-R", "mul": "*R", "div": "/R"}

    def __init__(
        self,
        mmap: MemoryMap,
        work: dict[str, int] | None = None,
        *,
        startup_target=None,
        motion: list[str] | None = None,
    ) -> None:
        self.mmap, self.work = mmap, dict(work or {})
        self.startup_target, self.motion = startup_target, motion
        self.subs: dict[str, Subroutine] = {}
        self.lines: list[str] = []
        self.block(None)

    trig_reason = "no ATAN/ACOS instruction"
    indent = ""

    # --- state of one block ---------------------------------------------------------------------
    def block(self, local: Subroutine | None) -> None:
        """Start a block: ``local`` is the subroutine whose ``#locals`` it names (None: OB1);
        networks, labels and the power flow start afresh."""
        self.local = local
        self.labels: dict[str, int | str] = {}
        self.net = 0
        self.power = False
        self.empty = False

    # --- operands and labels ----------------------------------------------------------------------
    def o(self, a) -> str:
        """An operand: a REAL literal, a ``#local``, a work double word or an I/O address."""
        if isinstance(a, float):
            return fmt_real(a, self.exp_char)
        if self.local is not None:
            return f"#{a}"
        if a in self.work:
            return self.mmap.dword(self.work[a])
        return self.mmap.address(a)

    def lab(self, name: str) -> str:
        if name not in self.labels:
            self.labels[name] = str(len(self.labels))
        return self.labels[name]

    # --- lines ------------------------------------------------------------------------------------
    def network(self, title: str = "") -> None:
        self.net += 1
        title = self.text(title)
        self.lines.append(f"Network {self.net}" + (f" // {title}" if title else ""))
        self.power = False
        self.empty = True

    def ins(self, op: str, arg: str = "") -> None:
        self.empty = False
        self.lines.append(f"{op:<7}{arg}".rstrip())

    def box(self, op: str, arg: str = "") -> None:
        """A box instruction: runs on power flow, so ``LD SM0.0`` first unless it is on."""
        if not self.power:
            self.ins("LD", "SM0.0")
            self.power = True
        self.ins(op, arg)

    def logic(self, op: str, arg: str = "") -> None:
        self.ins(op, arg)
        self.power = False

    def text(self, text: str) -> str:
        """Text in a title or a comment: one line (an S7 comment or title ends with its
        line; :func:`analysis.escape.one_line`)."""
        return one_line(text)

    def comment(self, text: str) -> str:
        return f"// {self.text(text)}"

    def label(self, name: str) -> None:
        """A jump target: ``LBL n`` begins a network of its own."""
        if not self.empty:
            self.network()
        self.logic("LBL", self.lab(name))

    # --- blocks -----------------------------------------------------------------------------------
    def generated_by(self) -> str:
        return f"generated by analysis.plc (python -m analysis stl --dialect {self.name})"

    def body(self, code) -> None:
        """Print ``code`` (structured or flat IR) into the current block."""
        for i in flatten(code):
            if i.op == "network":
                self.network(i.args[0])
                continue
            if i.op == "label":
                self.label(i.args[0])
                continue
            if i.comment:
                self.lines.append(self.indent + self.comment(i.comment))
            self.doprint(i.op, i)

    def header(self, program: Program) -> list[str]:
        return [
            f"TITLE={self.text(program.title)}",
            *(self.comment(n) for n in program.notes),
            self.comment(self.generated_by()),
        ]

    def main_block(self, program: Program) -> None:
        """OB1: the first-scan target (Figure 3, as REALs, unlike the paper's ``MOVD 100,
        VD0``), the IK networks (Figures 4-6 corrected), then the motion networks if any."""
        self.block(None)
        self.lines += ["ORGANIZATION_BLOCK MAIN:OB1", *self.header(program), "BEGIN"]
        if self.startup_target is not None:
            self.network(
                program.cite(
                    "data acquisition (Fig. 3): example target on the first scan, as REALs"
                )
            )
            self.logic("LD", "SM0.1")
            self.power = True
            for name, v in zip(program.inputs, self.startup_target, strict=True):
                self.ins("MOVR", f"{fmt_real(v, self.exp_char)}, {self.mmap.address(name)}")
        self.body(program.body)
        for line in self.motion or ():
            if line.startswith("Network "):
                self.network(line.split("// ", 1)[1] if "// " in line else "")
            else:
                self.lines.append(line)
        self.lines.append("END_ORGANIZATION_BLOCK")

    def subroutine_block(self, sub: Subroutine) -> None:
        self.block(sub)
        self.lines += [
            f"SUBROUTINE_BLOCK {sub.name}:SBR{sub.number}",
            f"TITLE={self.text(sub.title)}",
        ]
        for kw, names in (("VAR_INPUT", sub.inputs), ("VAR_OUTPUT", sub.outputs),
                          ("VAR", sub.temps)):  # fmt: skip
            self.lines += [kw, *(f"{n}:REAL;" for n in names), "END_VAR"]
        self.lines.append("BEGIN")
        self.body(sub.body)
        self.lines.append("END_SUBROUTINE_BLOCK")

    def check_program(self, program: Program) -> None:
        """Refuse a map that is not this dialect's or does not name the program's I/O, and a
        program whose trigonometry the dialect cannot print."""
        self.mmap.check_program(program.inputs, program.outputs)
        if self.mmap.dialect != self.name:
            raise ValueError(f"emit_{self.name.replace('-', '')} needs an {self.name} memory "
                             f"map, got {self.mmap.dialect!r}")  # fmt: skip
        if program.trig not in self.trigs:
            raise ValueError(
                "the S7-200 has no ATAN/ACOS instruction: build the program with trig='subroutine'"
            )

    def doprint_program(self, program: Program) -> str:
        """The whole source: OB1, then the subroutines (:meth:`check_program` first)."""
        self.subs = {s.name: s for s in program.subroutines}
        self.lines = []
        self.main_block(program)
        for s in program.subroutines:
            self.subroutine_block(s)
        return self.newline.join(self.lines) + self.newline

    def doprint_subroutines(self, subs) -> str:
        """The subroutine blocks alone (e.g. to go with the paper's own OB1)."""
        self.subs = {s.name: s for s in subs}
        self.lines = []
        for s in subs:
            self.subroutine_block(s)
        return self.newline.join(self.lines) + self.newline

    # --- values -----------------------------------------------------------------------------------
    def _print_mov(self, i):
        self.box("MOVR", f"{self.o(i.args[0])}, {self.o(i.dst)}")

    def _print_infix(self, op, i):
        """``d := a op b`` with the in-place two-operand instructions (module docstring)."""
        a, b = i.args
        o, mnem = self.o, self.infix[op]
        if i.dst == a:
            self.box(mnem, f"{o(b)}, {o(i.dst)}")
        elif i.dst == b and op in ("add", "mul"):
            self.box(mnem, f"{o(a)}, {o(i.dst)}")
        elif i.dst == b and op == "sub" and a == 0.0:
            self.box("*R", f"-1.0, {o(i.dst)}")
        elif i.dst == b and op == "sub":
            self.box("-R", f"{o(a)}, {o(i.dst)}")
            self.box("*R", f"-1.0, {o(i.dst)}")
        elif i.dst == b:
            raise ValueError(f"{i}: d = a / d has no in-place S7-200 form; use a temporary")
        else:
            self.box("MOVR", f"{o(a)}, {o(i.dst)}")
            self.box(mnem, f"{o(b)}, {o(i.dst)}")

    def _print_function(self, op, i):
        self.box(self.known_functions[op], f"{self.o(i.args[0])}, {self.o(i.dst)}")

    def emptyPrinter(self, op, *args, **kwargs):
        if op in ("atan", "acos"):
            raise ValueError(
                f"{self.target} has no ATAN/ACOS instruction: build the program with "
                "trig='subroutine'"
            )
        return super().emptyPrinter(op, *args, **kwargs)

    def _print_round(self, i):
        self.box("ROUND", f"{self.o(i.args[0])}, {self.o(i.dst)}")

    def _print_seti(self, i):
        self.box("MOVD", f"{int(i.args[0])}, {self.o(i.dst)}")

    # --- control ----------------------------------------------------------------------------------
    def compare(self, op: str, a: str, b: str) -> None:
        """``LDR<op> a, b`` (``=`` for equality): the compare contact."""
        if op not in CMP:
            raise ValueError(f"unknown compare {op!r}")
        self.logic(f"LDR{'=' if op == '==' else op}", f"{a}, {b}")

    def _print_jcmp(self, i):
        cmp, a, b, target = i.args
        self.compare(cmp, self.o(a), self.o(b))
        self.ins("JMP", self.lab(target))

    def _print_jnotfinite(self, i):
        a, target = i.args
        self.box("MOVD", f"{self.o(a)}, AC0")
        self.box("ANDD", f"16#{NAN_MASK:08X}, AC0")
        self.logic("LDD=", f"AC0, 16#{NAN_MASK:08X}")
        self.ins("JMP", self.lab(target))

    def _print_jmp(self, i):
        self.box("JMP", self.lab(i.args[0]))

    def _print_set(self, i):
        self.box("S", f"{self.o(i.dst)}, 1")

    def _print_reset(self, i):
        self.box("R", f"{self.o(i.dst)}, 1")

    def _print_call(self, i):
        name, ins_, outs = i.args
        args = [f"SBR{self.subs[name].number}", *(self.o(a) for a in (*ins_, *outs))]
        self.box("CALL", ", ".join(args))

    # --- the dialect's output ---------------------------------------------------------------------
    @classmethod
    def printer(cls, mmap, work, start, options: Options, arm) -> S7200Printer:
        """The printer :meth:`generate` prints with: the motion networks of an arm of the
        grabber's machine (:func:`.motion.supports`: Table 2's I/O) unless ``options.motion``
        is off."""
        from analysis.plc.motion import motion_networks, supports

        with_motion = options.motion and supports(arm)
        printer = cls(mmap, work, startup_target=start,
                      motion=motion_networks(arm, mmap, work) if with_motion else None)  # fmt: skip
        printer.arm = arm
        return printer

    def uses(self) -> tuple[dict[str, str], str | None]:
        """What the program's addresses beyond its I/O and work area are for, and what its
        motion networks do at start-up (None without them)."""
        uses = {"AC0": "finiteness test of the inputs (exponent bits, no REAL compare)"}
        if not self.motion:
            return uses, None
        from analysis.plc.motion import MOTION_STARTUP, motion_uses

        return {**uses, **motion_uses(self.arm, self.mmap, self.work)}, MOTION_STARTUP

    @classmethod
    def generate(cls, arm, program, options: Options) -> Generated:
        """The program text and MAP.json (:func:`~.mapdoc.s7_document`)."""
        mmap = options.mmap or default_map(cls.name, program.inputs, len(program.outputs))
        mmap = mmap.with_dialect(cls.name)
        if options.cpu is not None:
            mmap = mmap.with_cpu(options.cpu)
        start = startup_values(arm, program, options.startup_target)
        work = allocate(program, mmap)  # the work area: allocated and checked once
        printer = cls.printer(mmap, work, start, options, arm)
        printer.check_program(program)
        text = printer.doprint_program(program)
        uses, motion = printer.uses()
        doc = s7_document(arm, program, text, mmap, work, start, where=printer.startup_where,
                          uses=uses, motion=motion)  # fmt: skip
        if printer.motion:
            from analysis.plc.motion import machine_document

            doc["machine"] = machine_document(arm, mmap)
        return Generated(text, json.dumps(doc, indent=2, ensure_ascii=False) + "\n")

    @classmethod
    def session(cls, text: str, *, cpu: str | None = None, source: str = "program"):
        from analysis.plc.engines import S7200Session

        return S7200Session(text, cpu=cpu, source=source)

    @classmethod
    def awlsim_source(cls, text: str) -> str:
        """The AWL awlsim runs for this program text: the project's translation
        (:mod:`.translate`)."""
        from analysis.plc.translate import translate_s7200

        return translate_s7200(text).awl
