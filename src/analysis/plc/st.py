"""IEC 61131-3 Structured Text and Siemens SCL printers of the PLC IR (:mod:`.ir`).

The same program as the S7 listings (:mod:`.s7200`, :mod:`.awl`), printed from the
*structured* IR (ST has no jumps): one ``FUNCTION_BLOCK`` per arm whose interface is the
program's: ``VAR_INPUT`` the closed form's inputs (REAL, mm or rad), ``VAR_OUTPUT`` the pulse
counts ``c1..cn`` (DINT), ``reachable`` (BOOL) and ``status`` (DINT,
:class:`~analysis.kinematics.status.Status` codes); the work values are its static ``VAR``.
Each printer makes the program's blocks (:class:`Pou`: the functions, then the function
block; :meth:`StPrinter.pous`) and prints each (:meth:`StPrinter.print_pou`); the PLCopen XML
printer (:mod:`.plcopen`) prints the same blocks as XML.

:class:`StPrinter` (``--dialect st``; CODESYS 3.5, TwinCAT 3, OpenPLC)
    IEC 61131-3 (3rd edition) text: typed literals (``REAL#...``: an untyped real literal
    is LREAL in IEC and in the ST engine the tests use, which would change the arithmetic),
    its own ATAN2 (``IK_ATAN2``, a ``FUNCTION``: the IEC standard library has ATAN, no
    ATAN2; built on ATAN and the quadrant selects of :func:`analysis.plc.approx.
    atan2_from_atan`, or with ``trig="subroutine"`` the S7-200's polynomial ATAN2/ACOS,
    bit for bit), ``IF``/``ELSE`` for the selects, ``RETURN`` after a refusal (status set,
    ``reachable := FALSE``, ``c1..cn`` left as they were). Statements are three-address
    assignments in the order of the closed form's recording, so every REAL operation rounds
    to binary32 where the S7 programs' do.
:class:`SclPrinter` (``--dialect scl``; TIA Portal, S7-1200/1500)
    A thin dialect of the ST text: an external source (``.scl``, "Generate blocks from
    source") with ``FUNCTION_BLOCK "IK_..."`` and ``{ S7_Optimized_Access := 'TRUE' }``,
    ``VERSION : 0.1``, ``BEGIN``, ``#`` before every local name, quoted block names, named
    parameters in calls, the function value assigned to ``#IK_ATAN2``, and the instance
    data block ``DATA_BLOCK "IK_..._DB"`` (optimized, ``NON_RETAIN``) after the FB.
    REAL (binary32) is chosen, not LREAL: it is the arithmetic the S7 programs, the float32
    model and the ST engine run, so the pulses are the ones the tests prove; LREAL exists on
    S7-1200 (firmware 2.0 and later) and S7-1500, only in optimized blocks.

Conditions never compare a NaN: the inputs are tested first with the quiet IEEE test
``x <> x`` (true only for NaN) and then ``ABS(x) > REAL#3.40282347E+38`` (inf), as
separate statements because IEC ``OR`` need not short-circuit; after that the closed forms
refuse before any value can overflow (the "huge" targets of the sweeps).

Pulse rounding: ``REAL_TO_DINT`` rounds to the nearest integer, but the tie rule is the
vendor's (IEC leaves it open; the ST engine rounds ties to even, CODESYS documents
``REAL_TO_INT(-1.5) = -2``). The block fixes the tie explicitly, so the count is the
S7-200 ``ROUND`` of eqs. 20-22 (halves away from zero) on every target: after
``c := REAL_TO_DINT(x)``, ``x - DINT_TO_REAL(c)`` is exact (|x| < 2^23) and is +-0.5 only on
a tie, which is then moved away from zero.

Why by hand: no Python library prints IEC 61131-3 ST or SCL from a program graph (blark,
PyPI, only parses TwinCAT ST); the printers follow :class:`analysis.kinematics.printing.
Printer` (a method per operation). Executed in ``make test`` on the ST engine of pyplcopen's
source distribution (:mod:`.st_engine`); SCL is held by golden files and by translating it
back to the ST text (:func:`scl_to_st`), which the engine compiles.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from typing import ClassVar

from analysis.escape import iec_identifier, plc_comment
from analysis.kinematics.status import Status
from analysis.plc.instr import CMP_OF, Cond, Instr, Program, Subroutine
from analysis.plc.mapdoc import interface_document
from analysis.plc.printer import Generated, Options, PlcPrinter, fmt_real

__all__ = [
    "Decl",
    "Pou",
    "SclPrinter",
    "StPrinter",
    "block_name",
    "emit_scl",
    "emit_st",
    "scl_to_st",
]

REAL_MAX = "3.40282347E+38"
"""The largest finite REAL (binary32), printed."""


def block_name(program: Program, default_branch: str | None = None) -> str:
    """``IK_<ARM>`` for the arm's default branch, ``IK_<ARM>_<BRANCH>`` for another."""
    name = f"IK_{program.arm}"
    if default_branch is not None and program.branch != default_branch:
        name += f"_{program.branch}"
    return iec_identifier(name).upper()  # IEC 61131-3 (analysis.escape): IK_ keeps it one


@dataclass(frozen=True)
class Decl:
    """A declared variable: the program's ``name``, its ``ident`` in the dialect (reserved
    words renamed), its IEC ``type`` (REAL, DINT, BOOL) and a ``note`` (unit, meaning)."""

    name: str
    ident: str
    type: str
    note: str = ""


@dataclass(frozen=True)
class Pou:
    """A program organisation unit as the ST-family printers print it: a ``function`` or a
    ``functionBlock`` (PLCopen's ``pouType``), its title, its variable sections in order
    (``input``, ``output``, ``temp``, ``static``: each a tuple of :class:`Decl`) and its
    statement lines (not indented)."""

    name: str
    kind: str
    title: str
    sections: tuple[tuple[str, tuple[Decl, ...]], ...]
    body: tuple[str, ...]


class StPrinter(PlcPrinter):
    """IEC 61131-3 ST of a :class:`~.instr.Program` (module docstring): one method per IR
    instruction of the structured form, each returning statement lines; one per block
    (:meth:`pous`, :meth:`print_pou`)."""

    name = "st"
    readable = True  # a PLC engineer reviews and maintains the ST, SCL and XML text
    engine = "pyplcopen's ST engine (cycle by cycle, simulated axes: analysis.plc.machine.offline)"
    title = "IEC 61131-3 ST (CODESYS, TwinCAT, OpenPLC)"
    trigs = ("function", "native", "subroutine")
    runtime = "IEC 61131-3 runtime (CODESYS, TwinCAT, OpenPLC)"
    target = "IEC 61131-3 ST"
    control = ("select", "refuse", "notfinite", "accept", "call", "network", "mov")
    known_functions: ClassVar[dict[str, str]] = {
        "sqrt": "SQRT",
        "sin": "SIN",
        "cos": "COS",
        "atan": "ATAN",
        "acos": "ACOS",
        "abs": "ABS",
    }
    infix: ClassVar[dict[str, str]] = {"add": "+", "sub": "-", "mul": "*", "div": "/"}
    indent = "    "
    types: ClassVar[dict[str, str]] = {"REAL": "REAL", "DINT": "DINT", "BOOL": "BOOL"}
    """IEC type -> the dialect's spelling."""
    count_note = "pulses (eqs. 20-22)"
    reachable_note = "TRUE: solved, c1..cn are its pulses"

    def __init__(self, function_names: dict[str, str] | None = None) -> None:
        self.function_names = dict(function_names or {})
        self.names: dict[str, str] = {}
        self.subs: dict[str, Subroutine] = {}

    # --- names and operands -------------------------------------------------------------------
    def ident(self, name: str) -> str:
        """The declared name of a variable (:meth:`declare`)."""
        return self.names.get(name, name)

    def declare(self, names) -> None:
        """Register the variables of one POU: each name as an IEC 61131-3 identifier
        (:func:`analysis.escape.iec_identifier`: reserved words get ``v_``), no two equal
        but for case (ST is case-insensitive)."""
        self.names = {}
        seen: set[str] = set()
        for n in names:
            out = iec_identifier(n)  # IEC 61131-3 identifier rule (analysis.escape)
            while out.upper() in seen:
                out = f"v_{out}"
            seen.add(out.upper())
            self.names[n] = out

    def var(self, name: str) -> str:
        """A use of variable ``name`` in a statement."""
        return self.ident(name)

    def lit(self, v: float) -> str:
        return f"REAL#{fmt_real(v, 'E')}"

    def o(self, a) -> str:
        return self.lit(a) if isinstance(a, float) else self.var(a)

    def compare(self, op: str, a: str, b: str) -> str:
        """``(a op b)``, ``=`` for equality (parenthesised: ST's NOT binds tighter)."""
        return f"({a} {'=' if op == '==' else op} {b})"

    def cond(self, c: Cond) -> str:
        """A condition: compares, ``NOT``, ``AND``, ``OR``."""
        if c.op in CMP_OF:
            return self.compare(CMP_OF[c.op], self.o(c.args[0]), self.o(c.args[1]))
        if c.op == "not":
            return f"NOT {self.cond(c.args[0])}"
        word = {"and": "AND", "or": "OR"}[c.op]
        return f"({self.cond(c.args[0])} {word} {self.cond(c.args[1])})"

    def call(self, name: str, sub: Subroutine, args) -> str:
        binds = ", ".join(f"{p} := {self.o(a)}" for p, a in zip(sub.inputs, args, strict=True))
        return f"{self.function_names[name]}({binds})"

    def text(self, text: str) -> str:
        """Text in a comment or a title: one line, no comment delimiter
        (:func:`analysis.escape.plc_comment`)."""
        return plc_comment(text)

    def comment(self, text: str) -> str:
        """A comment line (ST: ``(* *)``)."""
        return f"(* {self.text(text)} *)"

    def assign(self, dst: str, expr: str) -> str:
        return f"{self.var(dst)} := {expr};"

    # --- values -------------------------------------------------------------------------------
    def _print_infix(self, op: str, i: Instr) -> list[str]:
        a, b = i.args
        return [self.assign(i.dst, f"{self.o(a)} {self.infix[op]} {self.o(b)}")]

    def _print_function(self, op: str, i: Instr) -> list[str]:
        return [self.assign(i.dst, f"{self.known_functions[op]}({self.o(i.args[0])})")]

    def _print_neg(self, i: Instr) -> list[str]:
        return [self.assign(i.dst, f"-{self.o(i.args[0])}")]

    def _print_mov(self, i: Instr) -> list[str]:
        return [self.assign(i.dst, self.o(i.args[0]))]

    def _print_round(self, i: Instr) -> list[str]:
        """Eqs. 20-22: the nearest whole pulse, halves away from zero (module docstring)."""
        x, c = self.o(i.args[0]), self.var(i.dst)
        t = self.indent
        return [
            f"{c} := REAL_TO_DINT({x}); {self.comment('nearest; a tie moves away from zero:')}",
            f"IF ({x} - DINT_TO_REAL({c}) = {self.lit(0.5)}) AND ({x} > {self.lit(0.0)}) THEN",
            f"{t}{c} := {c} + 1;",
            f"ELSIF ({x} - DINT_TO_REAL({c}) = {self.lit(-0.5)}) AND ({x} < {self.lit(0.0)}) THEN",
            f"{t}{c} := {c} - 1;",
            "END_IF;",
        ]

    def _print_select(self, i: Instr) -> list[str]:
        cond, a, b = i.args
        t = self.indent
        return [
            f"IF {self.cond(cond)} THEN",
            f"{t}{self.assign(i.dst, self.o(a))}",
            "ELSE",
            f"{t}{self.assign(i.dst, self.o(b))}",
            "END_IF;",
        ]

    def _print_call(self, i: Instr) -> list[str]:
        name, ins, outs = i.args
        return [self.assign(outs[0], self.call(name, self.subs[name], ins))]

    # --- refusals -----------------------------------------------------------------------------
    def refusal(self, code: int) -> list[str]:
        t = self.indent
        return [
            f"{t}{self.comment(f'refused: {Status(code).text}; c1..cn keep their values')}",
            f"{t}{self.assign('status', str(code))}",
            f"{t}{self.assign('reachable', 'FALSE')}",
            f"{t}{self.assign('Error', 'TRUE')}",
            f"{t}{self.assign('ErrorID', str(code))}",
            f"{t}RETURN;",
        ]

    def _print_refuse(self, i: Instr) -> list[str]:
        cond, code = i.args
        return [f"IF {self.cond(cond)} THEN", *self.refusal(int(code)), "END_IF;"]

    def _print_notfinite(self, i: Instr) -> list[str]:
        a, code = self.o(i.args[0]), int(i.args[1])
        return [
            self.comment("NaN: the quiet IEEE test; then +-inf"),
            f"IF {a} <> {a} THEN",
            *self.refusal(code),
            "END_IF;",
            f"IF ABS({a}) > REAL#{REAL_MAX} THEN",
            *self.refusal(code),
            "END_IF;",
        ]

    def _print_accept(self, i: Instr) -> list[str]:
        return [self.assign("status", "0"), self.assign("reachable", "TRUE"),
                self.assign("Done", "TRUE")]  # fmt: skip

    def execute(self) -> list[str]:
        """PLCopen's Execute/Done/Busy/Error/ErrorID: the target is solved once, on Execute's
        rising edge; the outputs hold while Execute stays TRUE and clear when it falls (Busy
        is never TRUE: the block answers within its call)."""
        t, a = self.indent, self.assign
        return [
            self.comment("PLCopen Execute: solved on the rising edge; Done or Error (ErrorID = "
                         "status) hold while Execute is TRUE, cleared when it falls"),
            f"IF NOT {self.var('Execute')} THEN",
            *(f"{t}{x}" for x in (a("Done", "FALSE"), a("Busy", "FALSE"), a("Error", "FALSE"),
                                  a("ErrorID", "0"), a("ExecuteSeen", "FALSE"), "RETURN;")),
            "END_IF;",
            f"IF {self.var('ExecuteSeen')} THEN",
            f"{t}RETURN;",
            "END_IF;",
            a("ExecuteSeen", "TRUE"),
        ]  # fmt: skip

    # --- blocks -------------------------------------------------------------------------------
    def body(self, code) -> list[str]:
        out: list[str] = []
        for i in code:
            if i.op == "network":
                title = i.args[0].replace(
                    "(bit test: no REAL compare sees a NaN)", "(x <> x: NaN; ABS(x) > max: inf)"
                )
                out += ["", self.comment(title)]
                continue
            if i.comment:
                out.append(self.comment(i.comment))
            out += self.doprint(i.op, i)
        return out

    def decls(self, names, type_: str, note: str = "") -> tuple[Decl, ...]:
        return tuple(Decl(n, self.ident(n), type_, note) for n in names)

    def function_pou(self, sub: Subroutine) -> Pou:
        """A generated subroutine as a FUNCTION returning its one output (REAL)."""
        fname = self.function_names[sub.name]
        self.declare([*sub.inputs, *sub.outputs, *sub.temps])
        sections = (
            ("input", self.decls(sub.inputs, "REAL")),
            ("temp", self.decls((*sub.outputs, *sub.temps), "REAL")),
        )
        body = (*self.body(sub.body), self.return_value(fname, sub.outputs[0]))
        return Pou(fname, "function", sub.title, sections, body)

    def status_note(self, codes) -> str:
        return ", ".join(f"{k} {Status(k).text}" for k in codes)

    def block_pou(self, program: Program, fb: str, units) -> Pou:
        """The IK function block: the program's I/O as its interface, the work values its
        static variables."""
        codes = sorted({int(i.args[1]) for i in program.body if i.op in ("refuse", "notfinite")})
        plc = ("Execute", "Done", "Busy", "Error", "ErrorID", "ExecuteSeen")
        self.declare([*plc, *program.inputs, *program.outputs, "reachable", "status",
                      *program.work])  # fmt: skip
        ins = self.decls(["Execute"], "BOOL", "rising edge: solve the target")
        ins += tuple(
            Decl(n, self.ident(n), "REAL", u) for n, u in zip(program.inputs, units, strict=True)
        )
        outs = self.decls(["Done", "Busy", "Error"], "BOOL")
        outs += self.decls(["ErrorID"], "DINT", "the status of a refused target")
        outs += self.decls(program.outputs, "DINT", program.cite(self.count_note))
        outs += self.decls(["reachable"], "BOOL", self.reachable_note)
        outs += self.decls(["status"], "DINT", self.status_note([0, *codes]))
        static = self.decls(["ExecuteSeen"], "BOOL") + self.decls(program.work, "REAL")
        sections = (("input", ins), ("output", outs), ("static", static))
        body = (*self.execute(), *self.body(program.body))
        return Pou(fb, "functionBlock", program.title, sections, body)

    def pous(self, program: Program, fb: str, units) -> list[Pou]:
        """The program's blocks in order: its functions, then the IK function block."""
        self.subs = {s.name: s for s in program.subroutines}
        self.function_names = {s.name: f"IK_{s.name}" for s in program.subroutines}
        return [*(self.function_pou(s) for s in program.subroutines),
                self.block_pou(program, fb, units)]  # fmt: skip

    def var_section(self, kind: str, decls) -> list[str]:
        """``kind`` ... ``END_VAR`` with one declaration per line; the comments of the
        declarations go in one comment line before the section, never between two
        declarations: the ST engine (pyplcopen 0.21.0) fails to resolve an interface
        variable that a comment precedes (``sema_unknown_identifier`` at line 0)."""
        notes = "; ".join(f"{d.ident}: {d.note}" for d in decls if d.note)
        lines = [f"{self.indent}{d.ident} : {self.types[d.type]};" for d in decls]
        return [*([self.comment(notes)] if notes else []), kind, *lines, "END_VAR"] if lines else []

    def print_pou(self, pou: Pou) -> list[str]:
        """A POU as source lines (its header, sections, body and end)."""
        function = pou.kind == "function"
        out = (self.function_header if function else self.fb_header)(pou.name, pou.title)
        for kind, decls in pou.sections:
            out += self.var_section(self.keywords[kind], decls)
        out += self.begin()
        out += [self.indent + line if line else "" for line in pou.body]
        out += [self.end_function if function else self.end_fb, ""]
        return out

    # dialect words (SCL overrides)
    keywords: ClassVar[dict[str, str]] = {
        "input": "VAR_INPUT", "output": "VAR_OUTPUT", "temp": "VAR", "static": "VAR",
    }  # fmt: skip
    end_function, end_fb = "END_FUNCTION", "END_FUNCTION_BLOCK"

    def function_header(self, name: str, title: str) -> list[str]:
        return [self.comment(title), f"FUNCTION {name} : {self.types['REAL']}"]

    def fb_header(self, name: str, title: str) -> list[str]:
        return [self.comment(title), f"FUNCTION_BLOCK {name}"]

    def begin(self) -> list[str]:
        return []

    def return_value(self, fname: str, result: str) -> str:
        return f"{fname} := {self.var(result)};"

    def header(self, program: Program, fb: str, note: str) -> list[str]:
        return [*self.comment_block([program.title, *program.notes, note]), ""]

    def comment_block(self, lines) -> list[str]:
        """A comment of several lines (ST: one ``(* ... *)`` around them)."""
        return ["(*", *(f"   {self.text(n)}" for n in lines), "*)"]

    def doprint_program(self, program: Program, *, units, default_branch=None) -> str:
        """The whole source: the header comment, the functions, the function block."""
        fb = block_name(program, default_branch)
        pous = self.pous(program, fb, units)
        note = (
            f"generated by analysis.plc (python -m analysis stl --dialect {self.name}); "
            "REAL = IEEE binary32 throughout"
        )
        out = self.header(program, fb, note)
        for pou in pous:
            out += self.print_pou(pou)
        out += self.trailer(fb)
        return "\n".join(out).rstrip("\n") + "\n"

    def trailer(self, fb: str) -> list[str]:
        return []

    # --- the dialect's output ---------------------------------------------------------------------
    @classmethod
    def instance_db(cls, fb: str) -> str | None:
        return None

    @classmethod
    def generate(cls, arm, program, options: Options) -> Generated:
        """The source and its interface map (:func:`~.mapdoc.interface_document`)."""
        units, first = arm.input_units, arm.branches[0]
        fb = block_name(program, first)
        text = cls().doprint_program(program, units=units, default_branch=first)
        cls.check_text(text)
        doc = interface_document(program, fb, cls.name, units, program.trig, cls.runtime,
                                 cls.instance_db(fb))  # fmt: skip
        return Generated(text, json.dumps(doc, indent=2) + "\n")

    @classmethod
    def check_text(cls, text: str) -> None:
        """Refuse a text the dialect's own checker rejects (none for ST: executed in the
        tests on the ST engine)."""


class SclPrinter(StPrinter):
    """Siemens SCL for TIA Portal (S7-1200/1500): the ST text in SCL's dialect (module
    docstring)."""

    name = "scl"
    engine = None  # TIA Portal's SCL: no engine here (held by golden files and scl_to_st)
    title = "Siemens SCL (TIA Portal, S7-1200/1500)"
    runtime = "S7-1200/S7-1500 (TIA Portal, SCL source)"
    target = "Siemens SCL"
    types: ClassVar[dict[str, str]] = {"REAL": "Real", "DINT": "DInt", "BOOL": "Bool"}
    keywords: ClassVar[dict[str, str]] = {**StPrinter.keywords, "temp": "VAR_TEMP"}

    def var(self, name: str) -> str:
        return f"#{self.ident(name)}"

    def call(self, name: str, sub: Subroutine, args) -> str:
        return '"' + super().call(name, sub, args).replace("(", '"(', 1)

    def function_header(self, name: str, title: str) -> list[str]:
        return [
            f'FUNCTION "{name}" : {self.types["REAL"]}',
            f"TITLE = {self.text(title)}",
            "{ S7_Optimized_Access := 'TRUE' }",
            "VERSION : 0.1",
        ]

    def fb_header(self, name: str, title: str) -> list[str]:
        return [
            f'FUNCTION_BLOCK "{name}"',
            f"TITLE = {self.text(title)}",
            "{ S7_Optimized_Access := 'TRUE' }",
            "VERSION : 0.1",
        ]

    def begin(self) -> list[str]:
        return ["BEGIN"]

    def return_value(self, fname: str, result: str) -> str:
        return f"#{fname} := {self.var(result)};"

    def header(self, program: Program, fb: str, note: str) -> list[str]:
        lines = [
            program.title,
            *program.notes,
            note,
            "TIA Portal: add as external source, then Generate blocks from source; "
            f'the instance DB "{fb}_DB" follows the FB. REAL (32 bit) chosen, not LREAL: '
            "the arithmetic proven against awlsim, the float32 model and the ST engine",
        ]
        return [*self.comment_block(lines), ""]

    def comment_block(self, lines) -> list[str]:
        return [f"// {self.text(n)}" for n in lines]

    def trailer(self, fb: str) -> list[str]:
        return [
            f'DATA_BLOCK "{fb}_DB"',
            "{ S7_Optimized_Access := 'TRUE' }",
            "VERSION : 0.1",
            "NON_RETAIN",
            f'"{fb}"',
            "BEGIN",
            "END_DATA_BLOCK",
            "",
        ]

    @classmethod
    def instance_db(cls, fb: str) -> str | None:
        return f"{fb}_DB"


def _units(program: Program, units) -> tuple[str, ...]:
    units = tuple(units) if units is not None else ("",) * len(program.inputs)
    if len(units) != len(program.inputs):
        raise ValueError(f"{len(units)} units for the {len(program.inputs)} inputs")
    return units


def emit_st(program: Program, *, units=None, default_branch: str | None = None) -> str:
    """IEC 61131-3 ST of ``program``: the functions and ``FUNCTION_BLOCK IK_<ARM>``.

    ``units`` names each input's unit (comments); ``default_branch``: the arm's first
    branch, whose block is ``IK_<ARM>`` (others ``IK_<ARM>_<BRANCH>``)."""
    return StPrinter().doprint_program(
        program, units=_units(program, units), default_branch=default_branch
    )


def emit_scl(program: Program, *, units=None, default_branch: str | None = None) -> str:
    """Siemens SCL external source of ``program``: the functions, the FB and its instance DB."""
    return SclPrinter().doprint_program(
        program, units=_units(program, units), default_branch=default_branch
    )


def scl_to_st(text: str) -> str:
    """The ST text an SCL source of :func:`emit_scl` was printed from: SCL's dialect words
    undone line by line (``#``, quotes, block attributes, ``BEGIN``, the instance DB, the
    type spellings, ``//`` comments). A test holds this equal to :func:`emit_st`'s text
    but for the header, and the ST engine compiles it: the SCL printer adds nothing else."""
    lines = text.split("\n")
    if "DATA_BLOCK" in text:
        lines = lines[: next(k for k, ln in enumerate(lines) if ln.startswith("DATA_BLOCK"))]
    out = []
    for ln in lines:
        s = ln
        if s.startswith("//") or s.strip() in ("BEGIN", "VERSION : 0.1") or "S7_Optimized" in s:
            continue
        if s.startswith("TITLE = "):
            out.insert(len(out) - 1, f"(* {s[len('TITLE = ') :]} *)")
            continue
        s = re.sub(r'"(IK_\w+)"', r"\1", s)
        s = re.sub(r"(?<!\w)#(\w+)", r"\1", s)
        s = s.replace("VAR_TEMP", "VAR")
        s = re.sub(r": Real;", ": REAL;", s)
        s = re.sub(r": DInt;", ": DINT;", s)
        s = re.sub(r": Bool;", ": BOOL;", s)
        s = re.sub(r"^(FUNCTION \w+) : Real$", r"\1 : REAL", s)
        out.append(s)
    return "\n".join(out).strip("\n") + "\n"
