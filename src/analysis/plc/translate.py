"""Translate the S7-200 STL subset used here (and by the paper) into AWL for awlsim.

awlsim implements S7-300/400 semantics; the S7-200 is a different machine (boolean logic
stack instead of an RLO, two-operand in-place math, V memory). This translator maps the
subset literally, instruction by instruction, so that executing the translation shows what
the S7-200 text computes:

=====================  ======================================================================
S7-200                 AWL
=====================  ======================================================================
V/VB/VW/VD n           M/MB/MW/MD n (same byte offsets)
SM0.0, "上电置1"        always on (the paper's symbol "power-on set 1" is read as SM0.0)
SM0.1                  first scan (a bit cleared at the end of the first OB1 cycle)
SM n / SMB / SMD n     M (1024 + n) (PTO control bytes etc., so tests can inspect them)
AC0..AC3               MD 1600..1612
logic stack            M bits per POU (top of stack + 8 levels; LPS/LRD/LPP/ALD/OLD)
LD/A/O/N, =, S/R       A/O on the TOS bit, = / S / R
LDR<op> a, b           L a; L b; <op>R; = TOS; JUO -> CPU STOP (NaN in a REAL compare
                       stops an S7-200: the translation sets the STOP bit and ends OB1)
AENO                   TOS := TOS AND NOT OV (ENO = 0 after an overflow/illegal value)
MOVR/MOVD/MOVW/MOVB    L; T (integer constants as L#n / DW#16#..)
+R -R *R /R IN1, OUT   L OUT; L IN1; op; T OUT (OUT := OUT op IN1)
SQRT/SIN/COS... IN,OUT L IN; op; T OUT
ROUND IN, OUT          exact S7-200 rule (TRUNC, then +-1 if |fraction| >= 0.5: halves away
                       from zero), not RND (ties to even)
TRUNC/DTR/ITD          TRUNC/DTR/ITD
ANDD/ORD               AD/OD
JMP n / LBL n          JC Jn / Jn: NOP 0
CALL SBRn|NAME, args   CALL FC n+1 (IN..., IN_OUT..., OUT... by position), by value:
                       copied through scratch MDs (an AWL FC gets references)
PLS n                  no PTO hardware: logs the pulse count SMD72/SMD82 and clears the idle
                       bit SM66.7/SM76.7 (a test sets it again to model "train done")
=====================  ======================================================================

Box instructions run only with power flow: unless the translator knows the TOS is the
always-on SM0.0, each box is wrapped in ``A TOS; JCN skip``.

The AWL then goes through :func:`analysis.plc.peephole.optimize_awl` (``optimize=False``
keeps it literal): ``MOVR a, b`` followed by ``+R c, b`` becomes ``L a; L c; +R; T b``
instead of ``L a; T b; L b; L c; +R; T b``. Only the AWL that awlsim runs changes, not the
S7-200 text, and nothing observable does (the module's docstring says why).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from analysis.plc.peephole import optimize_awl

__all__ = ["SM_BASE", "STOP_BIT", "Translation", "translate_s7200"]

SM_BASE = 1024
AC_BASE = 1600
I_BASE = 1800  # process image inputs I n.b -> M (1800 + n).b (tests write them)
Q_BASE = 1810  # process image outputs Q n.b -> M (1810 + n).b (tests read them)
LOGIC_BASE = 1700  # 4 bytes per POU: TOS + stack, edge bits
ROUND_SCRATCH = 1680  # MD1680 DINT, MD1684 REAL, MD1688 REAL (bytes 1680..1691)
FIRST_SCAN_DONE = (1696, 0)
STOP_BIT = (1696, 1)
CALL_SCRATCH = 1900  # 16 bytes per POU: CALL parameters passed by value (4 double words)
PLS_LOG = 1660  # MD1660 channel 0 count, MD1664 channel 1; MW1672/1674 number of PLS

_BOX_ARITH = {
    "+R": "+R",
    "-R": "-R",
    "*R": "*R",
    "/R": "/R",
    "+D": "+D",
    "*D": "*D",
    "-D": "-D",
    "/D": "/D",
    "ANDD": "AD",
    "ORD": "OD",
    "XORD": "XOD",
}
_BOX_UNARY = {
    "SQRT": "SQRT",
    "SIN": "SIN",
    "COS": "COS",
    "TAN": "TAN",
    "LN": "LN",
    "EXP": "EXP",
    "TRUNC": "TRUNC",
    "DTR": "DTR",
    "ITD": "ITD",
}
_CMP = {"=": "==", "<>": "<>", "<": "<", "<=": "<=", ">": ">", ">=": ">="}
_STACK_OPS = {"LPS", "LRD", "LPP", "ALD", "OLD", "LDS"}
ALWAYS = {"SM0.0", "上电置1"}


@dataclass
class _Pou:
    kind: str  # "OB" or "SBR"
    name: str
    number: int
    inputs: list[str] = field(default_factory=list)
    inouts: list[str] = field(default_factory=list)
    outputs: list[str] = field(default_factory=list)
    temps: list[str] = field(default_factory=list)
    types: dict[str, str] = field(default_factory=dict)
    code: list[tuple[int, str, list[str]]] = field(default_factory=list)  # (line no, op, args)


@dataclass(frozen=True)
class Translation:
    """AWL text plus what the translation had to assume."""

    awl: str
    notes: tuple[str, ...]


def _split_args(rest: str) -> list[str]:
    return [a.strip() for a in rest.split(",") if a.strip()] if rest.strip() else []


def _parse(text: str) -> list[_Pou]:
    pous: list[_Pou] = []
    cur: _Pou | None = None
    section = None
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = raw.split("//", 1)[0].strip()
        if not line or line.startswith("TITLE="):
            continue
        m = re.match(r"^(ORGANIZATION_BLOCK|SUBROUTINE_BLOCK)\s+(\w+):(OB|SBR)(\d+)$", line)
        if m:
            cur = _Pou("OB" if m.group(3) == "OB" else "SBR", m.group(2), int(m.group(4)))
            pous.append(cur)
            section = None
            continue
        if line in ("END_ORGANIZATION_BLOCK", "END_SUBROUTINE_BLOCK"):
            cur = None
            continue
        if cur is None:
            raise ValueError(f"line {lineno}: {raw.strip()!r} outside a block")
        if line in ("VAR_INPUT", "VAR_IN_OUT", "VAR_OUTPUT", "VAR", "VAR_TEMP"):
            section = line
            continue
        if line == "END_VAR":
            section = None
            continue
        if line == "BEGIN":
            section = "CODE"
            continue
        if section and section != "CODE":
            name, typ = (s.strip().rstrip(";") for s in line.split(":", 1))
            {"VAR_INPUT": cur.inputs, "VAR_IN_OUT": cur.inouts, "VAR_OUTPUT": cur.outputs}.get(
                section, cur.temps
            ).append(name)
            cur.types[name] = typ
            continue
        if re.match(r"^Network\s+\d+", line, re.I):
            cur.code.append((lineno, "NETWORK", []))
            continue
        m = re.match(r"^(\S+)\s*(.*)$", line)
        op, rest = m.group(1).upper(), m.group(2)
        if op.startswith("CALL") and op != "CALL":  # the paper's "CALLARCTAN,"
            rest = op[4:] + rest
            op = "CALL"
        if op.startswith("ROUND") and op != "ROUND":  # the paper's "ROUNDVD122, VD122"
            rest = op[5:] + rest
            op = "ROUND"
        cur.code.append((lineno, op, _split_args(rest)))
    return pous


class _Emitter:
    def __init__(self, pou: _Pou, index: int, sbrs: dict[str, _Pou], notes: list[str]) -> None:
        self.pou, self.sbrs, self.notes = pou, sbrs, notes
        base = LOGIC_BASE + 4 * index
        self.tos = f"M {base}.0"
        self.stack = [f"M {base + (k + 1) // 8}.{(k + 1) % 8}" for k in range(8)]
        self.edge_base = base + 2
        self.call_base = CALL_SCRATCH + 16 * index
        self.n_edge = 0
        self.uses_stack = any(op in _STACK_OPS for _, op, _ in pou.code)
        self.always = False
        self.always_stack: list[bool] = [False] * 8
        self.out: list[str] = []
        self.n_skip = 0
        self.nan_used = False

    # --- operands ----------------------------------------------------------------------
    def opnd(self, a: str, width: str = "D") -> str:
        a = a.strip()
        if a.startswith("#"):
            return a
        m = re.match(r"^(SM|V|AC|I|Q)([BWD]?)(\d+)(?:\.(\d))?$", a.upper())
        if m:
            area, w, n, bit = m.group(1), m.group(2), int(m.group(3)), m.group(4)
            n += {"I": I_BASE, "Q": Q_BASE}.get(area, 0)
            if area == "AC":
                return f"MD {AC_BASE + 4 * n}"
            if area == "SM":
                if a.upper() == "SM0.0":
                    raise AssertionError("SM0.0 handled by the caller")
                n += SM_BASE
            return f"M {n}.{bit}" if bit is not None else f"M{w} {n}"
        if re.match(r"^-?\d+\.\d*(E[-+]?\d+)?$", a, re.I) or re.match(r"^-?\d+E[-+]?\d+$", a, re.I):
            return a.replace("E", "e")
        m = re.match(r"^16#([0-9A-F]+)$", a, re.I)
        if m:
            return {"B": f"B#16#{m.group(1)}", "W": f"W#16#{m.group(1)}"}.get(
                width, f"DW#16#{m.group(1)}"
            )
        if re.match(r"^-?\d+$", a):
            return f"L#{a}" if width == "D" else a
        if a.upper().startswith("VDD"):  # the paper's Figure 6 prints "VDD0"
            raise ValueError(
                f"operand {a!r} is not a valid S7-200 address (printed as such in the paper)"
            )
        raise ValueError(f"operand {a!r} not in the translated subset")

    # --- logic stack -----------------------------------------------------------------------
    def i(self, op: str, arg: str = "") -> None:
        self.out.append(f"      {op:<6}{arg}".rstrip())

    def push(self) -> None:
        if self.uses_stack:
            for k in range(7, 0, -1):
                self.i("A", self.stack[k - 1])
                self.i("=", self.stack[k])
            self.i("A", self.tos)
            self.i("=", self.stack[0])
            self.always_stack = [self.always, *self.always_stack[:-1]]

    def pop(self) -> None:
        if self.uses_stack:
            for k in range(7):
                self.i("A", self.stack[k + 1])
                self.i("=", self.stack[k])
            self.always_stack = [*self.always_stack[1:], False]

    def bit_src(self, a: str) -> str:
        return self.first_scan() if a.upper() == "SM0.1" else self.opnd(a)

    def first_scan(self) -> str:
        return "FIRST"

    def load_bit(self, a: str, negate: bool, combine: str | None) -> None:
        """Load bit a (or its negation) and combine into TOS with A/O, or set TOS."""
        if a.upper() in ALWAYS or a in ALWAYS:
            if combine is None:
                self.i("SET")
                self.i("=", self.tos)
                self.always = not negate
                if negate:
                    self.i("CLR")
                    self.i("=", self.tos)
                return
            src_expr = None
        else:
            src_expr = a
        if combine is not None:
            self.i("A", self.tos)
        op = {None: "A", "A": "A", "O": "O"}[combine]
        if src_expr is None:  # combining with always-on: A SM0.0 = unchanged, O SM0.0 = 1
            if combine == "O":
                self.i("SET")
        elif src_expr.upper() == "SM0.1":
            self.i(op + ("" if negate else "N"), f"M {FIRST_SCAN_DONE[0]}.{FIRST_SCAN_DONE[1]}")
        else:
            self.i(op + ("N" if negate else ""), self.opnd(src_expr))
        self.i("=", self.tos)
        self.always = False

    def compare(self, kind: str, cmp: str, a: str, b: str, combine: str | None) -> None:
        real = kind == "R"
        w = "B" if kind == "B" else "D"
        self.i("L", self.opnd(a, w))
        self.i("L", self.opnd(b, w))
        self.i(_CMP[cmp] + {"R": "R", "D": "D", "B": "I"}[kind])
        scratch = self.tos if combine is None else f"M {FIRST_SCAN_DONE[0]}.7"
        self.i("=", scratch)
        if real:
            self.i("JUO", "NAN")
            self.nan_used = True
        if combine is not None:
            self.i("A", self.tos)
            self.i(combine, scratch)
            self.i("=", self.tos)
        self.always = False

    def box_begin(self) -> str | None:
        if self.always:
            return None
        self.n_skip += 1
        lbl = f"S{self.n_skip:03d}"
        self.i("A", self.tos)
        self.i("JCN", lbl)
        return lbl

    def box_end(self, lbl: str | None) -> None:
        if lbl:
            self.out.append(f"{lbl}: NOP   0")

    # --- instructions ---------------------------------------------------------------------
    def emit(self, lineno: int, op: str, args: list[str]) -> None:
        where = f"{self.pou.name} line {lineno}: {op} {', '.join(args)}"
        self.out.append(f"      // {op} {', '.join(args)}".rstrip())
        if op == "NETWORK":
            self.always = False
            return
        if op in ("LD", "LDN"):
            self.push()
            self.load_bit(args[0], op == "LDN", None)
        elif op in ("A", "AN", "O", "ON"):
            self.load_bit(args[0], op.endswith("N"), op[0])
        elif m := re.match(r"^(LD|A|O)([RDB])(=|<>|<=|>=|<|>)$", op):
            if m.group(1) == "LD":
                self.push()
            self.compare(
                m.group(2), m.group(3), args[0], args[1], None if m.group(1) == "LD" else m.group(1)
            )
        elif op == "NOT":
            self.i("AN", self.tos)
            self.i("=", self.tos)
            self.always = False
        elif op == "AENO":
            self.i("A", self.tos)
            self.i("AN", "OV")
            self.i("=", self.tos)
            self.always = False
        elif op in ("EU", "ED"):
            edge = f"M {self.edge_base + self.n_edge // 8}.{self.n_edge % 8}"
            self.n_edge += 1
            self.i("A", self.tos)
            self.i("FP" if op == "EU" else "FN", edge)
            self.i("=", self.tos)
            self.always = False
        elif op == "LPS":
            keep = self.always
            self.push()
            self.always = keep
        elif op in ("LRD", "LPP"):
            self.i("A", self.stack[0])
            self.i("=", self.tos)
            self.always = self.always_stack[0]
            if op == "LPP":
                self.pop()
        elif op in ("ALD", "OLD"):
            self.i("A", self.tos)
            self.i("A" if op == "ALD" else "O", self.stack[0])
            self.i("=", self.tos)
            self.always = False
            self.pop()
        elif op in ("=", "S", "R"):
            n = int(args[1]) if len(args) > 1 else 1
            m = re.match(r"^(SM|V|Q|M|I)(\d+)\.(\d)$", args[0].upper())
            if not m:
                raise ValueError(f"{where}: bit operand expected")
            byte, bit = int(m.group(2)), int(m.group(3))
            for k in range(n):
                b = bit + k
                addr = args[0][: -len(f"{m.group(2)}.{m.group(3)}")] + f"{byte + b // 8}.{b % 8}"
                self.i("A", self.tos)
                self.i(op, self.q_or_opnd(addr))
        elif op == "JMP":
            if self.always:
                self.i("JU", f"J{int(args[0]):03d}")
            else:
                self.i("A", self.tos)
                self.i("JC", f"J{int(args[0]):03d}")
        elif op == "LBL":
            self.out.append(f"J{int(args[0]):03d}: NOP   0")
            self.always = False
        elif op == "CRET":
            self.i("A", self.tos)
            self.i("BEC")
        else:
            lbl = self.box_begin()
            self.box(where, op, args)
            self.box_end(lbl)

    def q_or_opnd(self, a: str) -> str:
        return self.opnd(a)

    def box(self, where: str, op: str, args: list[str]) -> None:
        o = self.opnd
        if op in ("MOVR", "MOVD", "MOVW", "MOVB"):
            w = {"MOVR": "D", "MOVD": "D", "MOVW": "W", "MOVB": "B"}[op]
            self.i("L", o(args[0], w))
            self.i("T", o(args[1], w))
        elif op in _BOX_ARITH:
            self.i("L", o(args[1]))
            self.i("L", o(args[0]))
            self.i(_BOX_ARITH[op])
            self.i("T", o(args[1]))
        elif op in _BOX_UNARY:
            self.i("L", o(args[0]))
            self.i(_BOX_UNARY[op])
            self.i("T", o(args[1]))
        elif op == "ROUND":
            self.round(o(args[0]), o(args[1]))
        elif op == "CALL":
            name = args[0].split(":")[-1].upper().replace("SBR_", "SBR")
            sbr = self.sbrs.get(name) or self.sbrs.get(args[0].upper())
            if sbr is None:
                raise ValueError(f"{where}: subroutine {args[0]!r} is not defined")
            params = [*sbr.inputs, *sbr.inouts, *sbr.outputs]
            if len(params) != len(args) - 1:
                raise ValueError(
                    f"{where}: {sbr.name} takes {len(params)} parameters, {len(args) - 1} given"
                )
            # S7-200 copies parameters by value (into the callee's L memory, back after
            # RET); an AWL FC receives references. Copy through per-POU scratch double
            # words so that CALL ARCCOS, VD48, VD48 (IN and OUT aliased) keeps its
            # S7-200 meaning.
            if len(params) > 4 or any(
                sbr.types[p].upper() not in ("REAL", "DINT", "DWORD") for p in params
            ):
                raise ValueError(f"{where}: only up to 4 REAL/DINT/DWORD parameters are translated")
            slots = [f"MD {self.call_base + 4 * k}" for k in range(len(params))]
            n_in = len(sbr.inputs) + len(sbr.inouts)
            for slot, a in zip(slots[:n_in], args[1 : 1 + n_in], strict=True):
                self.i("L", o(a))
                self.i("T", slot)
            binds = ", ".join(f"{p} := {slot}" for p, slot in zip(params, slots, strict=True))
            self.i("CALL", f"FC {sbr.number + 1} ({binds})")
            for slot, a in zip(slots[len(sbr.inputs) :], args[1 + len(sbr.inputs) :], strict=True):
                self.i("L", slot)
                self.i("T", o(a))
            self.i("A", f"M {STOP_BIT[0]}.{STOP_BIT[1]}")  # the callee stopped the CPU
            self.i("BEC")
        elif op == "PLS":
            ch = int(args[0])
            self.i("L", f"MD {SM_BASE + 72 + 10 * ch}")
            self.i("T", f"MD {PLS_LOG + 4 * ch}")
            self.i("L", f"MW {PLS_LOG + 12 + 2 * ch}")
            self.i("+", "1")
            self.i("T", f"MW {PLS_LOG + 12 + 2 * ch}")
            self.i("SET")
            self.i("R", f"M {SM_BASE + 66 + 10 * ch}.7")
        else:
            raise ValueError(f"{where}: instruction {op!r} is not in the translated subset")

    def round(self, src: str, dst: str) -> None:
        d, t, f = f"MD {ROUND_SCRATCH}", f"MD {ROUND_SCRATCH + 4}", f"MD {ROUND_SCRATCH + 8}"
        self.n_skip += 2
        l1, l2 = f"S{self.n_skip - 1:03d}", f"S{self.n_skip:03d}"
        for ins in (
            ("L", src),
            ("TRUNC",),
            ("T", d),
            ("L", d),
            ("DTR",),
            ("T", t),
            ("L", src),
            ("L", t),
            ("-R",),
            ("T", f),
            ("L", f),
            ("L", "0.5"),
            (">=R",),
            ("JCN", l1),
            ("L", d),
            ("L", "L#1"),
            ("+D",),
            ("T", d),
        ):
            self.i(*ins)
        self.out.append(f"{l1}: L     {f}")
        for ins in (
            ("L", "-0.5"),
            ("<=R",),
            ("JCN", l2),
            ("L", d),
            ("L", "L#1"),
            ("-D",),
            ("T", d),
        ):
            self.i(*ins)
        self.out.append(f"{l2}: L     {d}")
        self.i("T", dst)


def translate_s7200(text: str, *, optimize: bool = True) -> Translation:
    """Translate S7-200 STL text (Micro/WIN text form) into AWL for awlsim.

    Parameters
    ----------
    text : str
        ``ORGANIZATION_BLOCK ...:OB1`` and ``SUBROUTINE_BLOCK NAME:SBRn`` blocks.
    optimize : bool
        Remove reloads and overwritten stores (:func:`~.peephole.optimize_awl`).

    Returns
    -------
    Translation
        ``awl`` source (FC n+1 per SBRn, OB1) and notes on assumptions.

    Raises
    ------
    ValueError
        An instruction or operand outside the subset (with the line number).
    """
    pous = _parse(text)
    notes: list[str] = []
    sbrs: dict[str, _Pou] = {}
    for p in pous:
        if p.kind == "SBR":
            sbrs[p.name.upper()] = p
            sbrs[f"SBR{p.number}"] = p
    obs = [p for p in pous if p.kind == "OB"]
    if len(obs) != 1:
        raise ValueError(f"expected one ORGANIZATION_BLOCK, found {len(obs)}")
    out: list[str] = []
    for idx, p in enumerate([*[q for q in pous if q.kind == "SBR"], obs[0]]):
        e = _Emitter(p, idx, sbrs, notes)
        for lineno, op, args in p.code:
            e.emit(lineno, op, args)
        if p.kind == "SBR":
            out += [
                f"FUNCTION FC {p.number + 1} : VOID",
                f"TITLE = {p.name} (S7-200 SBR{p.number})",
            ]
            for kw, names in (
                ("VAR_INPUT", p.inputs),
                ("VAR_IN_OUT", p.inouts),
                ("VAR_OUTPUT", p.outputs),
                ("VAR_TEMP", p.temps),
            ):
                if names:
                    out += [kw, *(f"  {n} : {p.types[n]};" for n in names), "END_VAR"]
            out.append("BEGIN")
            out += e.out
            out += ["      BEU"]
            if e.nan_used:
                out += ["NAN:  SET", f"      S     M {STOP_BIT[0]}.{STOP_BIT[1]}", "      BEU"]
            out += ["END_FUNCTION", ""]
        else:
            out += [
                "ORGANIZATION_BLOCK OB 1",
                f"TITLE = {p.name} (translated from S7-200 STL)",
                "BEGIN",
                f"      A     M {STOP_BIT[0]}.{STOP_BIT[1]}",
                "      BEC",
            ]
            out += e.out
            out += [
                "      SET",
                f"      S     M {FIRST_SCAN_DONE[0]}.{FIRST_SCAN_DONE[1]}",
                "      BEU",
            ]
            out += ["NAN:  SET", f"      S     M {STOP_BIT[0]}.{STOP_BIT[1]}", "      BEU"]
            out += ["END_ORGANIZATION_BLOCK", ""]
    awl = "\n".join(out)
    return Translation(optimize_awl(awl) if optimize else awl, tuple(notes))
