"""Reading STEP 7-Micro/WIN's text form of an S7-200 program (the ``.awl`` export).

The layout (no official grammar exists: this follows Micro/WIN's exports as third-party
tools read them, and the project's generator)::

    ORGANIZATION_BLOCK MAIN:OB1
    TITLE=...
    VAR_TEMP ... END_VAR            (optional: the main program's TEMP locals)
    BEGIN
    Network 1 // title
    // comment
    LD     I0.0
    =      Q0.0
    END_ORGANIZATION_BLOCK
    SUBROUTINE_BLOCK NAME:SBR0
    TITLE=...
    VAR_INPUT  X:REAL;  END_VAR      (also VAR_IN_OUT, VAR_OUTPUT, VAR / VAR_TEMP)
    BEGIN
    Network 1
    ...
    END_SUBROUTINE_BLOCK
    INTERRUPT_BLOCK NAME:INT0 ... END_INTERRUPT_BLOCK

A listing without any block line is read as the main program (a network copied out of the
editor). Comments are ``//`` to the end of the line; ``TITLE=`` lines are titles. Operands
are split at commas; ``symbol:address`` (the export's symbolic form, e.g.
``Always_On:SM0.0``) keeps the address. Everything here is syntax: what an operand means
and whether an instruction exists is decided in :mod:`.loader`, which reports errors
with the line, the block and the network (:class:`StlError`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

__all__ = [
    "MAX_PROGRAM_CHARS",
    "MAX_STATEMENTS",
    "Block",
    "Program",
    "StlError",
    "Stmt",
    "Var",
    "clip",
    "parse_program",
]

MAX_STATEMENTS = 65_536
"""More statements than any S7-200 CPU's program memory holds (the largest, the CPU 226, has
24 KB without run-mode edit (secondary: a distributor's summary of the data sheets) and
every instruction takes at least a byte): a longer text is refused at the statement past it,
so memory stays bounded (about 2 kB a statement once loaded)."""
MAX_PROGRAM_CHARS = 8 * 1024 * 1024
"""The longest program text read (a program of :data:`MAX_STATEMENTS` with comments is far
shorter)."""

_BLOCK = re.compile(
    r"^(ORGANIZATION_BLOCK|SUBROUTINE_BLOCK|INTERRUPT_BLOCK)\s+([^\s:]+)\s*:\s*(OB|SBR|INT)\s*(\d+)\s*$",
    re.IGNORECASE,
)
_END_BLOCK = {
    "END_ORGANIZATION_BLOCK": "OB",
    "END_SUBROUTINE_BLOCK": "SBR",
    "END_INTERRUPT_BLOCK": "INT",
}
_SECTIONS = {
    "VAR_INPUT": "IN",
    "VAR_IN_OUT": "IN_OUT",
    "VAR_INOUT": "IN_OUT",
    "VAR_OUTPUT": "OUT",
    "VAR": "TEMP",
    "VAR_TEMP": "TEMP",
}
_NETWORK = re.compile(r"^NETWORK(?:\s+(\d+))?\s*(?://\s*(.*))?$", re.IGNORECASE)
_DECL = re.compile(r"^([A-Za-z_\u0080-\uffff][\w\u0080-\uffff]*)\s*:\s*([A-Za-z]+)\s*;?\s*$")


def clip(s: str, n: int = 60) -> str:
    """``s`` shortened to about ``n`` characters for a message (its start and end kept, the
    length said): a hostile operand of thousands of characters stays one readable line."""
    if len(s) <= n:
        return s
    return f"{s[: n - 20]}...{s[-12:]} ({len(s):,} characters)"


def _clip_words(message: str) -> str:
    return re.sub(r"\S{81,}", lambda m: clip(m.group(), 80), message)


class StlError(ValueError):
    """An S7-200 program that cannot be run as written: names the line, the block, the
    network and the statement."""

    def __init__(
        self,
        message: str,
        *,
        line: int | None = None,
        block: str | None = None,
        network: int | None = None,
        text: str | None = None,
    ) -> None:
        message = _clip_words(message)
        text = clip(text, 80) if text else text
        self.reason, self.line, self.block, self.network, self.text = (
            message,
            line,
            block,
            network,
            text,
        )
        where = []
        if line is not None:
            where.append(f"line {line}")
        ctx = ", ".join(x for x in (block, f"network {network}" if network else None) if x)
        head = " ".join(where) + (f" ({ctx})" if ctx else "")
        stmt = f" {text!r}" if text else ""
        super().__init__(
            f"{head}:{stmt} {message}" if head else f"{stmt.strip()} {message}".strip()
        )


@dataclass(frozen=True)
class Stmt:
    """One instruction as written: mnemonic (upper case), operands (as written, symbols
    resolved), the source line, the network number and the text."""

    op: str
    args: tuple[str, ...]
    line: int
    network: int
    text: str


@dataclass(frozen=True)
class Var:
    """A local variable: section (IN, IN_OUT, OUT, TEMP), name, type, declaration line."""

    section: str
    name: str
    type: str
    line: int


@dataclass
class Block:
    """A program organisation unit: the main program (OB), a subroutine (SBR) or an
    interrupt routine (INT)."""

    kind: str
    name: str
    number: int
    line: int
    title: str = ""
    vars: list[Var] = field(default_factory=list)
    code: list[Stmt] = field(default_factory=list)

    @property
    def label(self) -> str:
        """How errors name the block: ``MAIN (OB1)``, ``ATAN2 (SBR1)``."""
        return f"{self.name} ({self.kind}{self.number})"


@dataclass
class Program:
    """A parsed program: its blocks in source order."""

    blocks: list[Block]
    source: str = "program"

    @property
    def main(self) -> Block:
        return next(b for b in self.blocks if b.kind == "OB")

    def subroutines(self) -> list[Block]:
        return [b for b in self.blocks if b.kind == "SBR"]


def _split_operands(rest: str) -> list[str]:
    out = [a.strip() for a in rest.split(",")] if rest.strip() else []
    return out


def _resolve_symbol(a: str, symbols: dict[str, str]) -> str:
    if a in symbols:
        return symbols[a]
    # the export's "symbol:address" (and "#local:LD0"): keep the address part
    if ":" in a and not a.startswith(("'", '"')):
        name, _, addr = a.rpartition(":")
        if a.startswith("#"):
            return name  # "#X:LD0" -> "#X" (the local's own name decides its address)
        return addr.strip()
    return a


def parse_program(
    text: str, *, symbols: dict[str, str] | None = None, source: str = "program"
) -> Program:
    """Parse Micro/WIN text into blocks of statements (no semantics: :mod:`.loader`).

    Parameters
    ----------
    text : str
        The program (CRLF or LF). Without block lines, the whole text is the main program.
    symbols : dict, optional
        Global symbol -> address (the symbol table is not part of the export), e.g.
        ``{"上电置1": "SM0.0"}`` for the paper's figures.
    source : str
        Name of the program in messages.

    Raises
    ------
    StlError
        A line outside a block, an unterminated block or VAR section, a malformed
        declaration, a block header that is not ``NAME:OBn/SBRn/INTn``.
    """
    if len(text) > MAX_PROGRAM_CHARS:
        raise StlError(
            f"the program is {len(text):,} characters long; at most {MAX_PROGRAM_CHARS:,} are "
            f"read (no S7-200 holds more than {MAX_STATEMENTS:,} statements)"
        )
    lines = text.splitlines()
    reader = _Reader(dict(symbols or {}), lines)
    for lineno, raw in enumerate(lines, 1):
        reader.line(lineno, raw)
    return reader.program(source)


class _Reader:
    """The state of :func:`parse_program` while it reads the lines: the blocks so far, the
    open block, its VAR section (``"CODE"`` after BEGIN) and the network number."""

    def __init__(self, symbols: dict[str, str], lines: list[str]) -> None:
        self.symbols = symbols
        self.n_lines = len(lines)
        self.blocks: list[Block] = []
        self.cur: Block | None = None
        self.section: str | None = None
        self.net = 0
        self.n_statements = 0
        self.has_blocks = any(_BLOCK.match(ln.split("//", 1)[0].strip()) for ln in lines)
        if not self.has_blocks:
            self.cur = Block("OB", "MAIN", 1, 1)
            self.blocks.append(self.cur)
            self.section = "CODE"

    def line(self, lineno: int, raw: str) -> None:
        code = raw.split("//", 1)[0].strip()
        if not code:
            return
        cur = self.cur
        if code.upper().startswith("TITLE"):
            if cur is not None and code.upper().replace(" ", "").startswith("TITLE="):
                cur.title = code.split("=", 1)[1].strip()
                return
        m = _BLOCK.match(code)
        if m:
            self.begin_block(m, lineno, code)
            return
        up = code.upper()
        if up in _END_BLOCK:
            self.end_block(up, lineno, code)
            return
        if cur is None:
            raise StlError(
                "outside a block (ORGANIZATION_BLOCK, SUBROUTINE_BLOCK or INTERRUPT_BLOCK)",
                line=lineno,
                text=code,
            )
        if self.section != "CODE":
            self.declaration(up, lineno, code)
            return
        n = _NETWORK.match(code)
        if n and (n.group(1) or code.upper() == "NETWORK" or n.group(2) is not None):
            self.net = int(n.group(1)) if n.group(1) else self.net + 1
            return
        if up == "BEGIN" and not self.has_blocks:
            return
        mm = re.match(r"^(\S+)\s*(.*)$", code)
        op, rest = mm.group(1).upper(), mm.group(2)
        args = tuple(_resolve_symbol(a, self.symbols) for a in _split_operands(rest))
        self.n_statements += 1
        if self.n_statements > MAX_STATEMENTS:
            raise StlError(
                f"more than {MAX_STATEMENTS:,} statements: no S7-200 CPU's program memory "
                "holds this program",
                line=lineno,
                block=cur.label,
            )
        cur.code.append(Stmt(op, args, lineno, self.net, code))

    def begin_block(self, m, lineno: int, code: str) -> None:
        cur = self.cur
        if cur is not None and self.has_blocks:
            raise StlError(
                f"a new block begins before END_{_kind_word(cur.kind)} of {cur.label}",
                line=lineno,
                text=code,
            )
        kind = m.group(3).upper()
        if (
            (kind == "OB" and m.group(1).upper() != "ORGANIZATION_BLOCK")
            or (kind == "SBR" and m.group(1).upper() != "SUBROUTINE_BLOCK")
            or (kind == "INT" and m.group(1).upper() != "INTERRUPT_BLOCK")
        ):
            raise StlError(f"{m.group(1)} cannot be {kind}{m.group(4)}", line=lineno, text=code)
        self.cur = Block(kind, m.group(2), int(m.group(4)), lineno)
        self.blocks.append(self.cur)
        self.section, self.net = None, 0

    def end_block(self, up: str, lineno: int, code: str) -> None:
        cur = self.cur
        if cur is None or not self.has_blocks:
            raise StlError("END of a block that was not begun", line=lineno, text=code)
        if _END_BLOCK[up] != cur.kind:
            raise StlError(f"{cur.label} ends with {code}", line=lineno, text=code)
        if self.section not in (None, "CODE"):
            raise StlError(f"{cur.label}: VAR section not closed by END_VAR", line=lineno)
        self.cur, self.section = None, None

    def declaration(self, up: str, lineno: int, code: str) -> None:
        """A line before BEGIN: a VAR section keyword, END_VAR, BEGIN or a declaration."""
        cur, section = self.cur, self.section
        if up in _SECTIONS:
            if section not in (None,):
                raise StlError(f"{up} inside another VAR section", line=lineno, block=cur.label)
            self.section = _SECTIONS[up]
            return
        if up == "END_VAR":
            if section is None:
                raise StlError("END_VAR without a VAR section", line=lineno, block=cur.label)
            self.section = None
            return
        if up == "BEGIN":
            if section is not None:
                raise StlError(
                    "BEGIN inside a VAR section (END_VAR missing)", line=lineno, block=cur.label
                )
            self.section = "CODE"
            return
        if section is None:
            raise StlError(
                "expected a VAR section or BEGIN before the code",
                line=lineno,
                block=cur.label,
                text=code,
            )
        d = _DECL.match(code)
        if not d:
            raise StlError(
                "a declaration is 'name:TYPE;' (e.g. X:REAL;)",
                line=lineno,
                block=cur.label,
                text=code,
            )
        cur.vars.append(Var(section, d.group(1), d.group(2).upper(), lineno))

    def program(self, source: str) -> Program:
        cur, blocks = self.cur, self.blocks
        if cur is not None and self.has_blocks:
            raise StlError(
                f"{cur.label} is not closed (END_{_kind_word(cur.kind)} missing)",
                line=self.n_lines,
            )
        if not blocks:
            raise StlError("no program: the text has no ORGANIZATION_BLOCK and no instructions")
        obs = [b for b in blocks if b.kind == "OB"]
        if len(obs) != 1:
            raise StlError(f"a program has one ORGANIZATION_BLOCK (main program); found {len(obs)}")
        return Program(blocks, source)


def _kind_word(kind: str) -> str:
    return {"OB": "ORGANIZATION_BLOCK", "SBR": "SUBROUTINE_BLOCK", "INT": "INTERRUPT_BLOCK"}[kind]
