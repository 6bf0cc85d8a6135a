"""Loading an S7-200 program: every block, instruction, operand and call checked for one CPU.

:func:`load_program` parses the text (:mod:`.syntax`), lays out each block's locals in L
memory (IN, IN_OUT, OUT, TEMP in order; bits packed into bytes, other types from the next
byte [manualshelf p.324]) and resolves every operand (:mod:`.operands`) against the
instruction table (:mod:`.instructions`). Anything the CPU would not run is refused with the
line, the block, the network and the statement (:class:`~.syntax.StlError`); what loads
runs on :class:`~.cpu.S7200`.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

from analysis.plc.memmap import CPUS, DEFAULT_CPU
from analysis.plc.stl_eval.instructions import INSTRUCTIONS, REFUSED_OPS
from analysis.plc.stl_eval.operands import TYPES, Operand, Resolver
from analysis.plc.stl_eval.syntax import Block, Program, StlError, Stmt, parse_program

__all__ = ["Library", "Loaded", "Pou", "layout", "load_program"]


@dataclass(frozen=True)
class Library:
    """A library subroutine (e.g. Siemens' "Arcusfunctions" ARCTAN): REAL inputs, REAL
    outputs, computed by ``fn`` (float64, rounded to REAL). Micro/WIN links libraries into
    the program; the paper calls ARCTAN and ARCCOS without listing them."""

    inputs: tuple[str, ...]
    outputs: tuple[str, ...]
    fn: Callable
    source: str


@dataclass
class Pou:
    block: Block
    frame: dict  # local name -> (type, byte, bit)
    params: list  # (section, name, type, byte, bit)
    size: int
    code: list  # compiled: list of (stmt, classes, operands, builder)
    labels: dict


def layout(block: Block) -> tuple[dict, list, int]:
    """L memory of a block's locals: IN, IN_OUT, OUT, TEMP in order; bits packed into
    bytes, other types from the next byte (manualshelf p.324)."""
    order = {"IN": 0, "IN_OUT": 1, "OUT": 2, "TEMP": 3}
    frame, params = {}, []
    byte, bit = 0, None  # bit: next free bit in the current bit byte, or None
    sizes = {"BYTE": 1, "WORD": 2, "INT": 2, "DWORD": 4, "DINT": 4, "REAL": 4}
    last = -1
    for v in block.vars:
        if order[v.section] < last:
            raise StlError(
                f"{v.section} declared after a later section (order: VAR_INPUT, VAR_IN_OUT, "
                "VAR_OUTPUT, VAR)",
                line=v.line,
                block=block.label,
            )
        last = order[v.section]
        if v.name in frame:
            raise StlError(f"local {v.name} declared twice", line=v.line, block=block.label)
        if v.type == "BOOL":
            if bit is None or bit == 8:
                bit, bbyte = 0, byte
                byte += 1
            frame[v.name] = ("BOOL", bbyte, bit)
            bit += 1
        elif v.type in sizes:
            bit = None
            frame[v.name] = (v.type, byte, 0)
            byte += sizes[v.type]
        else:
            raise StlError(
                f"local {v.name}: type {v.type} is not one of {', '.join(TYPES)}",
                line=v.line,
                block=block.label,
            )
        if v.section != "TEMP":
            params.append((v.section, v.name, *frame[v.name]))
        if byte > 64:
            raise StlError(
                f"the locals need {byte} bytes of L memory; the S7-200 has 64 per block",
                line=v.line,
                block=block.label,
            )
    if block.kind == "OB" and params:
        raise StlError(
            "the main program has no parameters (only VAR / VAR_TEMP locals)",
            line=block.line,
            block=block.label,
        )
    return frame, params, byte


def load_program(
    text: str | Program,
    *,
    symbols: dict[str, str] | None = None,
    libraries: dict[str, Library] | None = None,
    cpu: str | None = None,
    source: str = "program",
):
    """Parse and check a program (every instruction, operand and call), ready to run.

    Returns a :class:`Loaded` that :class:`S7200` runs. Raises :class:`StlError` naming the
    line, the block, the network and the statement for anything the CPU would not run.
    """
    prog = (
        text if isinstance(text, Program) else parse_program(text, symbols=symbols, source=source)
    )
    return Loaded(prog, dict(libraries or {}), CPUS[cpu or DEFAULT_CPU["s7-200"]])


class Loaded:
    """A checked program: blocks compiled to operand descriptors for one CPU."""

    def __init__(self, prog: Program, libraries: dict[str, Library], cpu) -> None:
        if cpu.dialect != "s7-200":
            raise ValueError(f"{cpu.name} is not an S7-200 CPU")
        self.program, self.libraries, self.cpu = prog, libraries, cpu
        self.pous: dict[str, Pou] = {}
        for b in prog.blocks:
            frame, params, size = layout(b)
            key = f"{b.kind}{b.number}"
            if key in self.pous:
                raise StlError(f"{key} defined twice", line=b.line, block=b.label)
            self.pous[key] = Pou(b, frame, params, size, [], {})
        self.names = {p.block.name.upper(): k for k, p in self.pous.items() if k[:3] == "SBR"}
        for pou in self.pous.values():
            self._compile(pou)

    def sbr_key(self, name: str) -> str | None:
        u = name.upper()
        if u in self.names:
            return self.names[u]
        m = re.fullmatch(r"SBR_?(\d+)", u)
        if m and f"SBR{int(m.group(1))}" in self.pous:
            return f"SBR{int(m.group(1))}"
        return None

    def _compile(self, pou: Pou) -> None:
        b = pou.block
        res = Resolver(self.cpu, b, pou.frame)
        fors = []
        for idx, st in enumerate(b.code):

            def err(msg, st=st):
                return StlError(msg, line=st.line, block=b.label, network=st.network, text=st.text)

            op = st.op
            if op in REFUSED_OPS:
                raise err(f"{op}: {REFUSED_OPS[op]}")
            if op not in INSTRUCTIONS:
                hint = ""
                for k in ("CALL", "ROUND", "MOVR", "MOVD"):
                    if op.startswith(k) and op != k:
                        hint = f" (a space is missing: {k} {op[len(k) :]}...?)"
                raise err(f"unknown instruction {op}{hint}")
            classes, builder, _ = INSTRUCTIONS[op]
            if op == "CALL":
                pou.code.append((st, (), self._call_operands(st, res, err), builder))
                continue
            if len(st.args) != len(classes):
                raise err(
                    f"{op} takes {len(classes)} operand(s), {len(st.args)} given"
                    + (" (a comma is missing?)" if len(st.args) < len(classes) else "")
                )
            opnds = []
            for a, cls in zip(st.args, classes, strict=True):
                if cls == "n":
                    try:
                        v = int(a)
                    except ValueError:
                        raise err(f"operand {a!r} must be a whole number") from None
                    lim = {
                        "LDS": (1, 8),
                        "PLS": (0, 1),
                        "JMP": (0, 255),
                        "LBL": (0, 255),
                        "NOP": (0, 255),
                    }[op]
                    if not lim[0] <= v <= lim[1]:
                        raise err(f"{op} {a}: the operand is {lim[0]}..{lim[1]}")
                    opnds.append(Operand("num", value=v, text=a))
                    continue
                try:
                    opnds.append(res.operand(a, cls))
                except ValueError as exc:
                    raise err(str(exc)) from None
            if op in ("S", "R", "SI", "RI"):
                n = opnds[1]
                if n.kind != "const" or not 1 <= int(n.value) <= 255:
                    raise err(f"{op}: the number of bits is a constant 1..255")
            if op in ("BMB", "BMW", "BMD"):
                n = opnds[2]
                if n.kind == "const" and not 1 <= int(n.value) <= 255:
                    raise err(f"{op}: N is 1..255")
            if op == "LBL":
                if opnds[0].value in pou.labels:
                    raise err(f"label {opnds[0].value} defined twice in {b.label}")
                pou.labels[opnds[0].value] = idx
            if op == "FOR":
                fors.append(idx)
            if op == "NEXT":
                if not fors:
                    raise err("NEXT without FOR")
                fors.pop()
            if op == "END" and b.kind != "OB":
                raise err("END (conditional end) is for the main program; a subroutine uses CRET")
            if op == "CRET" and b.kind == "OB":
                raise err("CRET returns from a subroutine; the main program uses END")
            pou.code.append((st, classes, opnds, builder))
        if fors:
            st = b.code[fors[-1]]
            raise StlError(
                "FOR without NEXT", line=st.line, block=b.label, network=st.network, text=st.text
            )
        if len(fors) > 8:
            raise StlError("FOR loops nest 8 deep at most", block=b.label)
        for st, _, opnds, builder in pou.code:
            if builder == "jump" and opnds[0].value not in pou.labels:
                raise StlError(
                    f"JMP {opnds[0].value}: no LBL {opnds[0].value} in {b.label} (a jump "
                    "stays within its block)",
                    line=st.line,
                    block=b.label,
                    network=st.network,
                    text=st.text,
                )

    def _call_operands(self, st: Stmt, res: Resolver, err):
        if not st.args:
            raise err("CALL needs a subroutine (CALL SBR0 or CALL name, parameters...)")
        target, actuals = st.args[0], st.args[1:]
        key = self.sbr_key(target)
        if key is None:
            lib = self.libraries.get(target.upper()) or self.libraries.get(target)
            if lib is None:
                raise err(f"subroutine {target} is not defined in this program")
            params = [("IN", n, "REAL", 0, 0) for n in lib.inputs] + [
                ("OUT", n, "REAL", 0, 0) for n in lib.outputs
            ]
        else:
            params = self.pous[key].params
        if len(actuals) != len(params):
            names = ", ".join(f"{s} {n}:{t}" for s, n, t, _, _ in params) or "none"
            raise err(f"{target} takes {len(params)} parameter(s) ({names}), {len(actuals)} given")
        ops = []
        for a, (section, name, typ, _, _) in zip(actuals, params, strict=True):
            cls = {
                "BOOL": "x",
                "BYTE": "b",
                "WORD": "w",
                "INT": "i",
                "DWORD": "d",
                "DINT": "l",
                "REAL": "r",
            }[typ]
            if section != "IN":
                cls += ">"
            try:
                ops.append(res.operand(a, cls))
            except ValueError as exc:
                raise err(f"parameter {name} ({section} {typ}): {exc}") from None
        return (key, target, params, ops)
