"""The PLC program's instructions: what :func:`analysis.plc.ir.build_program` writes and every
printer of :mod:`analysis.plc.dialects` reads (the instruction set is described in
:mod:`analysis.plc.ir`).

:class:`Instr`, :class:`Cond`, :class:`Subroutine` and :class:`Program` are the structured
code; :func:`flatten` turns it into jumps only (the S7 listings); :func:`status_codes` names
the status codes a program writes. Nothing here depends on how a program is built, so the
printers (and the dialect registry) sit below the lowering.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from analysis.kinematics.ops import OPS
from analysis.kinematics.status import Status
from analysis.kinematics.trace import Graph

__all__ = [
    "CMP",
    "Cond",
    "Instr",
    "Program",
    "Subroutine",
    "flatten",
    "names",
    "status_codes",
    "uncited",
]

CMP = ("<", "<=", ">", ">=", "==", "<>")
"""The compares of the flat form (``jcmp``), as the op table's symbols plus ``<>``."""
CMP_OF = {op: OPS[op].symbol for op in OPS if OPS[op].kind == "compare"}
"""A condition's compare (op table name: ``lt`` ...) -> its symbol (``<`` ...)."""
_NOT = {"<": ">=", "<=": ">", ">": "<=", ">=": "<", "==": "<>", "<>": "=="}


@dataclass(frozen=True)
class Cond:
    """A condition: a compare (``op`` in lt le gt ge eq, ``args`` two operands) or a logic
    operation (``and``, ``or``: two conditions; ``not``: one)."""

    op: str
    args: tuple

    def operands(self):
        """Variable names and constants the condition reads, in order."""
        for a in self.args:
            if isinstance(a, Cond):
                yield from a.operands()
            else:
                yield a


@dataclass(frozen=True)
class Instr:
    op: str
    dst: str | None = None
    args: tuple = ()
    comment: str = ""


@dataclass(frozen=True)
class Subroutine:
    """A generated subroutine: S7-200 ``SUBROUTINE_BLOCK name:SBRn``, S7-300 ``FC n``."""

    name: str
    number: int
    inputs: tuple[str, ...]
    outputs: tuple[str, ...]
    temps: tuple[str, ...]
    body: tuple[Instr, ...]
    title: str


@dataclass(frozen=True)
class Program:
    """The IK program: OB1 body, subroutines, I/O and work variable names."""

    body: tuple[Instr, ...]
    subroutines: tuple[Subroutine, ...]
    work: tuple[str, ...]
    arm: str
    branch: str
    trig: str
    title: str
    inputs: tuple[str, ...] = ("px", "py", "pz")
    outputs: tuple[str, ...] = ("c1", "c2", "c3")
    notes: tuple[str, ...] = field(default=())
    graph: Graph | None = field(default=None, compare=False, repr=False)
    cites: bool = True
    """Whether the program's texts may cite the paper (equations, figures, tables): the
    paper's own arm; a user's arm on the same closed form gets its texts without them."""

    def cite(self, text: str) -> str:
        """``text`` as this program may say it (:attr:`cites`; :func:`uncited`)."""
        return text if self.cites else uncited(text)

    def variables(self) -> set[str]:
        return {a for i in self.body for a in names(i)}


def names(i: Instr):
    """Variable names an instruction (structured or flat) reads or writes."""
    if i.dst is not None:
        yield i.dst
    if i.op == "call":
        yield from i.args[1]
        yield from i.args[2]
    elif i.op == "jcmp":
        yield from (a for a in i.args[1:3] if isinstance(a, str))
    elif i.op in ("jnotfinite", "notfinite"):
        yield i.args[0]
    elif i.op in ("select", "refuse"):
        for a in i.args:
            if isinstance(a, Cond):
                yield from (b for b in a.operands() if isinstance(b, str))
            elif isinstance(a, str):
                yield a
    elif i.op == "mov" or i.op in OPS:
        yield from (a for a in i.args if isinstance(a, str))


def flatten(code) -> tuple[Instr, ...]:
    """Structured code with jumps only (module docstring), for the S7 listings.

    ``select d c a b``: ``mov d b``, jump past ``mov d a`` unless c; ``abs d a``: ``mov d a``
    and ``d := 0 - a`` unless a >= 0; ``refuse c k``: jump to k's refusal if c;
    ``notfinite a k``: ``jnotfinite a``; ``accept``: status 0, reach flag on, jump to the
    end, then one refusal block per code (status k, reach flag off)."""
    out: list[Instr] = []
    count = 0

    def label() -> str:
        nonlocal count
        count += 1
        return f"@{count}"

    def jump_if(c: Cond, target: str, value: bool) -> None:
        """Jump to ``target`` if ``c`` is ``value`` (short-circuit and/or/not)."""
        if c.op in CMP_OF:
            cmp = CMP_OF[c.op] if value else _NOT[CMP_OF[c.op]]
            out.append(Instr("jcmp", None, (cmp, c.args[0], c.args[1], target)))
        elif c.op == "not":
            jump_if(c.args[0], target, not value)
        elif (c.op == "or") == value:  # or -> true, and -> false: either operand decides
            jump_if(c.args[0], target, value)
            jump_if(c.args[1], target, value)
        else:  # or -> false, and -> true: both operands must agree
            skip = label()
            jump_if(c.args[0], skip, not value)
            jump_if(c.args[1], target, value)
            out.append(Instr("label", None, (skip,)))

    for i in code:
        if i.op == "select":
            cond, a, b = i.args
            skip = label()
            out.append(Instr("mov", i.dst, (b,)))
            jump_if(cond, skip, False)
            out.append(Instr("mov", i.dst, (a,)))
            out.append(Instr("label", None, (skip,)))
        elif i.op == "abs":
            skip = label()
            out.append(Instr("mov", i.dst, i.args))
            out.append(Instr("jcmp", None, (">=", i.args[0], 0.0, skip)))
            out.append(Instr("sub", i.dst, (0.0, i.args[0])))
            out.append(Instr("label", None, (skip,)))
        elif i.op == "neg":
            out.append(Instr("sub", i.dst, (0.0, i.args[0]), i.comment))
        elif i.op == "refuse":
            jump_if(i.args[0], f"@refuse{int(i.args[1])}", True)
        elif i.op == "notfinite":
            out.append(Instr("jnotfinite", None, (i.args[0], f"@refuse{int(i.args[1])}")))
        elif i.op == "accept":
            end = label()
            out.append(Instr("seti", "status", (0,)))
            out.append(Instr("set", "reachable"))
            out.append(Instr("jmp", None, (end,)))
            out.append(
                Instr(
                    "network",
                    None,
                    ("refused: status code, reach flag off, c1..cn unchanged, no motion",),
                )
            )
            for k in i.args[0]:
                out.append(Instr("label", None, (f"@refuse{k}",)))
                out.append(Instr("seti", "status", (k,), Status(k).text))
                out.append(Instr("reset", "reachable"))
                out.append(Instr("jmp", None, (end,)))
            out.append(Instr("label", None, (end,)))
        else:
            out.append(i)
    return tuple(out)


_CITATION = re.compile(r"\b(?:eqs?|Figs?|Figures?|sec|Tables?|seed)\b\.?\s*[0-9]", re.I)


def uncited(text: str) -> str:
    """``text`` without its citations of a paper: every parenthesised part that cites an
    equation, a figure, a section or a table, and ``the paper's``.

    >>> uncited("theta1 = atan2(Py, Px) (eq. 6; Fig. 4); the base axis")
    'theta1 = atan2(Py, Px); the base axis'
    >>> uncited("theta1 = atan2(py, px) (sec. 4.2 prints arctan(py/px)); the base axis")
    'theta1 = atan2(py, px); the base axis'
    """
    out, depth, start, pieces = [], 0, 0, []
    for k, c in enumerate(text):
        if c == "(":
            if depth == 0:
                pieces.append(text[start:k])
                start = k
            depth += 1
        elif c == ")" and depth:
            depth -= 1
            if depth == 0:
                group = text[start : k + 1]
                pieces.append("" if _CITATION.search(group) else group)
                start = k + 1
    pieces.append(text[start:])
    out = "".join(pieces).replace("the paper's ", "the ")
    return re.sub(r"\s+([;:,.])", r"\1", re.sub(r"\s{2,}", " ", out)).strip()


def status_codes(program: Program) -> list[int]:
    """The status codes ``program`` writes: 0, and every refusal's (``accept``'s list in the
    structured IR, ``seti status k`` once flattened)."""
    codes = {0}
    for i in program.body:
        if i.op == "accept":
            codes |= {int(k) for k in i.args[0]}
        elif i.op in ("refuse", "notfinite"):
            codes.add(int(i.args[1]))
        elif i.op == "seti" and i.dst == "status":
            codes.add(int(i.args[0]))
    return sorted(codes)
