"""Static reading and a minimal float32 evaluation of the paper's S7-200 STL (Figures 3-6).

This is an audit aid, not a PLC simulator: it parses the listings of
:data:`analysis.papers.grabber.FIGURE_STL`, finds operands that are not S7-200 addresses, traces
which V-memory double words each instruction reads and writes (def-use), and evaluates
the straight-line REAL arithmetic with the S7-200 semantics of ``../shared/stl_reference.md``
(1.1: ``op IN1, OUT`` works in place, ``OUT := OUT op IN1``; 1.2: MOVD copies bits, MOVR
copies a REAL, SIN/COS take radians, ROUND rounds halves away from zero; 1.3: REAL is
IEEE-754 single precision, big-endian). Power flow (LD/LPS/LRD/LPP/AENO) is taken as
always on. ``CALL ARCTAN`` / ``CALL ARCCOS`` follow Siemens' "Arcusfunctions" library
(results in radians). Execution on awlsim is the PLC helper's job (``analysis.plc``).
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass

import numpy as np

__all__ = [
    "Instr",
    "defs_uses",
    "dint",
    "evaluate",
    "invalid_operands",
    "parse_stl",
    "real",
    "real_from_bits",
    "real_memory",
]

_ADDR = re.compile(r"^VD\d+$")
_CONST_REAL = re.compile(r"^[+-]?\d+\.\d*(E[+-]?\d+)?$", re.IGNORECASE)
_CONST_INT = re.compile(r"^[+-]?\d+$")
_LOGIC = {"LD", "LPS", "LRD", "LPP", "AENO"}


@dataclass(frozen=True)
class Instr:
    """One STL instruction: mnemonic, operands, source line, uncertainty flag (``// ?``)."""

    op: str
    args: tuple[str, ...]
    line: int
    uncertain: bool


def parse_stl(text: str) -> list[Instr]:
    """Parse a listing of :data:`analysis.papers.grabber.FIGURE_STL` into instructions.

    Comments (``// ...``) are dropped; a comment starting with ``?`` marks the line as
    uncertain. ``CALL ARCTAN, A, B`` becomes ``Instr("CALL ARCTAN", (A, B))``.
    """
    out = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        code, _, comment = raw.partition("//")
        code = code.strip()
        if not code:
            continue
        op, _, rest = code.partition(" ")
        args = tuple(a.strip() for a in rest.split(",") if a.strip())
        if op == "CALL":  # "CALL ARCTAN, IN, OUT" (also accepted without the first comma)
            parts = [a for a in re.split(r"[,\s]+", rest.strip()) if a]
            op, args = f"CALL {parts[0]}", tuple(parts[1:])
        out.append(Instr(op, args, lineno, comment.strip().startswith("?")))
    return out


def invalid_operands(instrs: list[Instr]) -> list[tuple[Instr, str]]:
    """Operands that are neither a VD address, a REAL/INT constant nor a contact symbol."""
    bad = []
    for ins in instrs:
        if ins.op in _LOGIC:
            continue
        for a in ins.args:
            if not (_ADDR.match(a) or _CONST_REAL.match(a) or _CONST_INT.match(a)):
                bad.append((ins, a))
    return bad


def defs_uses(ins: Instr) -> tuple[set[str], set[str]]:
    """(written, read) V addresses of one instruction (in-place ops read their OUT too)."""
    if ins.op in _LOGIC or not ins.args:
        return set(), set()
    src, out = ins.args[0], ins.args[-1]
    reads = set() if (_CONST_REAL.match(src) or _CONST_INT.match(src)) else {src}
    if ins.op in ("+R", "-R", "*R", "/R"):
        reads.add(out)
    return {out}, reads


def real_from_bits(bits: int) -> float:
    """The REAL a 32-bit pattern denotes (S7 REAL = IEEE-754 single, big-endian)."""
    return struct.unpack(">f", struct.pack(">I", bits & 0xFFFFFFFF))[0]


def _bits_from_real(x: float) -> int:
    return struct.unpack(">I", struct.pack(">f", np.float32(x)))[0]


def evaluate(
    instrs: list[Instr],
    memory: dict[str, int] | None = None,
    *,
    aliases: dict[str, str] | None = None,
) -> dict[str, int]:
    """Run straight-line STL on a V-memory image of 32-bit words; returns the new image.

    Parameters
    ----------
    instrs : list of Instr
        From :func:`parse_stl`.
    memory : dict, optional
        ``{"VD0": bits, ...}``; unset addresses read as 0 (bits). Use
        :func:`real_memory` to build it from REAL values.
    aliases : dict, optional
        Operand substitutions, e.g. ``{"VDD0": "VD12"}`` to try a reading of Figure 6.

    Raises ``ValueError`` naming the instruction for unknown mnemonics or operands.
    """
    mem = dict(memory or {})
    aliases = aliases or {}

    def val(a: str) -> np.float32:
        a = aliases.get(a, a)
        if _CONST_REAL.match(a):
            return np.float32(float(a))
        if _ADDR.match(a):
            return np.float32(real_from_bits(mem.get(a, 0)))
        raise ValueError(f"operand {a!r} is not a VD address or REAL constant")

    def store(a: str, x) -> None:
        a = aliases.get(a, a)
        if not _ADDR.match(a):
            raise ValueError(f"cannot write to operand {a!r}")
        mem[a] = _bits_from_real(x)

    with np.errstate(all="ignore"):
        for ins in instrs:
            op, args = ins.op, ins.args
            if op in _LOGIC:
                continue
            if op == "MOVD":  # bit copy, no conversion (stl_reference 1.2)
                src = aliases.get(args[0], args[0])
                mem[aliases.get(args[1], args[1])] = (
                    int(src) & 0xFFFFFFFF if _CONST_INT.match(src) else mem.get(src, 0)
                )
            elif op == "MOVR":
                store(args[1], val(args[0]))
            elif op in ("+R", "-R", "*R", "/R"):
                a, b = val(args[1]), val(args[0])  # OUT := OUT op IN1
                r = {"+R": a + b, "-R": a - b, "*R": b * a, "/R": a / b}[op]
                store(args[1], np.float32(r))
            elif op in ("SIN", "COS"):
                store(
                    args[1],
                    np.float32(np.sin(val(args[0])) if op == "SIN" else np.cos(val(args[0]))),
                )
            elif op == "CALL ARCTAN":
                store(args[-1], np.float32(np.arctan(val(args[0]))))
            elif op == "CALL ARCCOS":
                store(args[-1], np.float32(np.arccos(val(args[0]))))
            elif op == "ROUND":  # REAL -> DINT, halves away from zero
                x = float(val(args[0]))
                mem[aliases.get(args[1], args[1])] = (
                    int(np.copysign(np.floor(abs(x) + 0.5), x)) & 0xFFFFFFFF
                )
            else:
                raise ValueError(f"line {ins.line}: unsupported instruction {op!r}")
    return mem


def real_memory(**values: float) -> dict[str, int]:
    """A memory image holding REALs, e.g. ``real_memory(VD0=100.0, VD4=100.0)``."""
    return {k: _bits_from_real(v) for k, v in values.items()}


def dint(mem: dict[str, int], addr: str) -> int:
    """Read a DINT (two's complement) from a memory image."""
    v = mem.get(addr, 0) & 0xFFFFFFFF
    return v - (1 << 32) if v & 0x80000000 else v


def real(mem: dict[str, int], addr: str) -> float:
    """Read a REAL from a memory image."""
    return real_from_bits(mem.get(addr, 0))
