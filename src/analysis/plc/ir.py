"""Intermediate representation of the corrected IK program (paper Figures 3-6, eqs. 6-22).

One program, generated from :class:`analysis.kinematics.params.ArmParams` (Table 3: L1, L2, L3,
pulses per revolution), feeds both emitters (S7-200 STL and S7-300 AWL). The IR is
three-address REAL arithmetic, REAL compare-and-jump, a finiteness test on the raw bits
(so no REAL compare ever sees a NaN: a NaN in a REAL compare stops an S7-200 CPU), bit
set/reset for the reach flag, ROUND to DINT and subroutine calls.

Instruction set (``Instr.op``)
------------------------------
``mov d a`` | ``add/sub/mul/div d a b`` (d := a op b) | ``sqrt/sin/cos d a`` |
``atan/acos d a`` (native, S7-300 only) | ``round d a`` (REAL -> DINT) |
``jcmp cmp a b L`` (jump to L if a cmp b, cmp in < <= > >= == <>) |
``jnotfinite a L`` (jump if a is inf/NaN: exponent bits all ones) | ``jmp L`` | ``label L`` |
``set/reset bit`` | ``call name (ins) (outs)`` | ``network title`` (a network boundary,
kept so the S7-200 listing mirrors the paper's figures).

Operands are variable names (str) or REAL constants (float). Variable names are either
program I/O (``px py pz c1 c2 c3 reachable``), work variables (allocated by the memory
map) or, inside a subroutine, its parameters and temporaries (``#name`` locals).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from analysis.kinematics.arm import BRANCHES
from analysis.kinematics.params import ArmParams
from analysis.plc.approx import ATAN_DEGREE, SQRT3, TAN_PI_12, atan_coefficients

__all__ = ["CMP", "Instr", "Program", "Subroutine", "build_program"]

CMP = ("<", "<=", ">", ">=", "==", "<>")
ARITH = ("add", "sub", "mul", "div")
UNARY = ("mov", "sqrt", "sin", "cos", "atan", "acos", "round")
BASE_AXIS_TOL_MM = (
    1e-6  # = analysis.kinematics.arm.DEFAULT_TOL_MM: closer to the axis -> theta1 := 0
)


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
    """The IK program: OB1 body, subroutines, and the names of its work variables."""

    body: tuple[Instr, ...]
    subroutines: tuple[Subroutine, ...]
    work: tuple[str, ...]
    params: ArmParams
    branch: str
    trig: str
    title: str
    notes: tuple[str, ...] = field(default=())

    def variables(self) -> set[str]:
        return {a for i in self.body for a in _names(i)}


def _names(i: Instr):
    """Variable names an instruction reads or writes."""
    if i.dst is not None:
        yield i.dst
    if i.op == "call":
        yield from i.args[1]
        yield from i.args[2]
    elif i.op == "jcmp":
        yield from (a for a in i.args[1:3] if isinstance(a, str))
    elif i.op == "jnotfinite":
        yield i.args[0]
    elif i.op in ARITH or i.op in UNARY:
        yield from (a for a in i.args if isinstance(a, str))


class _Builder:
    def __init__(self) -> None:
        self.code: list[Instr] = []
        self._n = 0

    def label(self) -> str:
        self._n += 1
        return f"@{self._n}"

    def __call__(self, op: str, dst: str | None = None, *args, comment: str = "") -> None:
        self.code.append(Instr(op, dst, tuple(args), comment))

    def net(self, title: str) -> None:
        self("network", None, title)

    def jcmp(self, a, cmp: str, b, lbl: str, comment: str = "") -> None:
        self("jcmp", None, cmp, a, b, lbl, comment=comment)


def _r(x: float) -> float:
    """A REAL constant: rounded to float32 by the CPU anyway; keep the float64 value."""
    return float(x)


def atan2_subroutine(number: int = 1, degree: int = ATAN_DEGREE) -> Subroutine:
    """ATAN2(Y, X) -> R [rad], from +-*/ and compares only (see :mod:`.approx`)."""
    b = _Builder()
    Y, X, R = "Y", "X", "R"
    A, B, T, U, P, S = "A", "B", "T", "U", "P", "S"
    pos_y, pos_x, noswap, small, done, nonzero = (b.label() for _ in range(6))
    b.net("|y|, |x| (no ABS for REAL on the S7-200: negate by 0 - v)")
    b("mov", A, Y)
    b.jcmp(A, ">=", 0.0, pos_y)
    b("sub", A, 0.0, Y)
    b("label", None, pos_y)
    b("mov", B, X)
    b.jcmp(B, ">=", 0.0, pos_x)
    b("sub", B, 0.0, X)
    b("label", None, pos_x)
    b.net("atan2(0, 0) := 0")
    b("mov", R, 0.0)
    b.jcmp(A, ">", 0.0, nonzero)
    b.jcmp(B, "==", 0.0, done)
    b("label", None, nonzero)
    b.net("t = min/max in [0, 1]; S = 1 if |y| > |x| (the result is then pi/2 - atan t)")
    swapped = b.label()
    b.jcmp(A, ">", B, swapped)
    b("mov", S, 0.0)
    b("div", T, A, B)
    b("jmp", None, noswap)
    b("label", None, swapped)
    b("mov", S, 1.0)
    b("div", T, B, A)
    b("label", None, noswap)
    b.net("reduce t > tan(pi/12): t' = (sqrt3 t - 1)/(t + sqrt3), R = pi/6 + atan t'")
    b.jcmp(T, "<=", _r(TAN_PI_12), small)
    b("mul", U, T, _r(SQRT3))
    b("sub", U, U, 1.0)
    b("add", P, T, _r(SQRT3))
    b("div", T, U, P)
    b("mov", R, _r(math.pi / 6))
    b("label", None, small)
    coef = atan_coefficients(degree)
    b.net(f"odd polynomial of degree {degree} (Horner in u = t^2)")
    b("mul", U, T, T)
    b("mov", P, coef[-1])
    for c in coef[-2::-1]:
        b("mul", P, P, U)
        b("add", P, P, c)
    b("mul", P, P, T)
    b("add", R, R, P)
    fin_swap, fin_x, fin_y = b.label(), b.label(), b.label()
    b.net("undo the reductions: pi/2 - R if swapped, pi - R if x < 0, -R if y < 0")
    b.jcmp(S, "==", 0.0, fin_swap)
    b("sub", R, _r(math.pi / 2), R)
    b("label", None, fin_swap)
    b.jcmp(X, ">=", 0.0, fin_x)
    b("sub", R, _r(math.pi), R)
    b("label", None, fin_x)
    b.jcmp(Y, ">=", 0.0, fin_y)
    b("sub", R, 0.0, R)
    b("label", None, fin_y)
    b("label", None, done)
    b("mov", R, R, comment="(end)")
    return Subroutine(
        "ATAN2",
        number,
        (Y, X),
        (R,),
        (A, B, T, U, P, S),
        tuple(b.code),
        f"ATAN2(Y, X) [rad], argument reduction + odd polynomial of degree {degree}",
    )


def acos_subroutine(number: int = 2, atan2_name: str = "ATAN2") -> Subroutine:
    """ACOS(C) -> R [rad] = ATAN2(sqrt((1 - C)(1 + C)), C); C must be in [-1, 1]."""
    b = _Builder()
    b.net("s = sqrt((1 - c)(1 + c)) (exact 1 - c near the reach boundary), R = atan2(s, c)")
    b("sub", "S", 1.0, "C")
    b("add", "T", "C", 1.0)
    b("mul", "S", "S", "T")
    b("sqrt", "S", "S")
    b("call", None, atan2_name, ("S", "C"), ("R",))
    return Subroutine(
        "ACOS",
        number,
        ("C",),
        ("R",),
        ("S", "T"),
        tuple(b.code),
        "ACOS(C) [rad] via ATAN2(sqrt((1-C)(1+C)), C)",
    )


def build_program(params: ArmParams, branch: str = "front-up", trig: str = "subroutine") -> Program:
    """The corrected IK program for one branch (eqs. 6-19 as corrected in analysis.kinematics.arm).

    Parameters
    ----------
    params : ArmParams
        Link lengths L1, L2, L3 [mm] and pulses per revolution (Table 3).
    branch : str
        One of :data:`analysis.kinematics.arm.BRANCHES` (front-up is the paper's).
    trig : {"subroutine", "native"}
        "subroutine": generated ATAN2/ACOS (required on the S7-200); "native": the S7-300
        ATAN/ACOS instructions with quadrant jumps.

    Networks (mirroring Figures 3-6): 1 inputs valid, 2 reach check, 3 theta1 (Fig. 4),
    4 theta3 (Fig. 6), 5 theta2 (Fig. 5), 6 pulses (eqs. 20-22) and reach flag.
    Unreachable or non-finite targets reset the flag and leave c1..c3 unchanged.
    """
    if branch not in BRANCHES:
        raise ValueError(f"unknown branch {branch!r}; expected one of {', '.join(BRANCHES)}")
    if trig not in ("subroutine", "native"):
        raise ValueError(f"trig = {trig!r}: expected 'subroutine' or 'native'")
    L1, L2, L3 = params.L1, params.L2, params.L3
    ppr = tuple(float(v) for v in params.pulses_per_rev)
    front = branch.startswith("front")
    # elbow sign as in analysis.kinematics.arm: theta3 = -usign * rsign * acos(c3)
    rsign = 1.0 if front else -1.0
    usign = 1.0 if branch.endswith("up") else -1.0
    t3sign = -usign * rsign

    b = _Builder()
    bad = b.label()
    subs: list[Subroutine] = []
    if trig == "subroutine":
        subs = [atan2_subroutine(1), acos_subroutine(2)]

    def atan2(dst: str, y: str, x: str) -> None:
        if trig == "subroutine":
            b("call", None, "ATAN2", (y, x), (dst,))
            return
        # native S7-300 ATAN with quadrant jumps; x, y finite here
        q_xneg, q_x0, q_yneg, q_done = (b.label() for _ in range(4))
        b.jcmp(x, "<=", 0.0, q_xneg)
        b("div", dst, y, x)
        b("atan", dst, dst)
        b("jmp", None, q_done)
        b("label", None, q_xneg)
        b.jcmp(x, "==", 0.0, q_x0)
        b("div", dst, y, x)
        b("atan", dst, dst)
        b.jcmp(y, "<", 0.0, q_yneg)
        b("add", dst, dst, _r(math.pi))
        b("jmp", None, q_done)
        b("label", None, q_yneg)
        b("sub", dst, dst, _r(math.pi))
        b("jmp", None, q_done)
        b("label", None, q_x0)
        b("mov", dst, 0.0)
        b.jcmp(y, "==", 0.0, q_done)
        b("mov", dst, _r(math.pi / 2))
        b.jcmp(y, ">", 0.0, q_done)
        b("mov", dst, _r(-math.pi / 2))
        b("label", None, q_done)

    def acos(dst: str, c: str) -> None:
        if trig == "subroutine":
            b("call", None, "ACOS", (c,), (dst,))
        else:
            b("acos", dst, c)

    b.net("inputs Px, Py, Pz [mm] (Fig. 3): finite? (bit test, no REAL compare on a NaN)")
    for v in ("px", "py", "pz"):
        b("jnotfinite", None, v, bad)
    b.net(f"reach check: |L2 - L3| <= |P - (0, 0, L1)| <= L2 + L3, L1 = {L1:g} mm")
    b("sub", "zr", "pz", _r(L1), comment="z = Pz - L1 (eq. 8)")
    # box check first: |Px|, |Py|, |z| <= L2 + L3 keeps every square below (L2 + L3)^2, so
    # no REAL overflow can occur (an S7-200 leaves OUT unchanged on overflow, which could
    # otherwise turn two huge coordinates into a plausible D^2)
    R = _r(L2 + L3)
    for v in ("px", "py", "zr"):
        b.jcmp(v, ">", R, bad, comment=f"|{v}| <= L2 + L3 = {L2 + L3:g}" if v == "px" else "")
        b.jcmp(v, "<", -R, bad)
    b("mul", "rho2", "px", "px")
    b("mul", "tmp", "py", "py")
    b("add", "rho2", "rho2", "tmp", comment="rho^2 = Px^2 + Py^2")
    b("mul", "tmp", "zr", "zr")
    b("add", "d2", "rho2", "tmp", comment="D^2 = rho^2 + z^2")
    b.jcmp("d2", ">", _r((L2 + L3) ** 2), bad, comment=f"(L2 + L3)^2 = {(L2 + L3) ** 2:g}")
    b.jcmp("d2", "<", _r((L2 - L3) ** 2), bad, comment=f"(L2 - L3)^2 = {(L2 - L3) ** 2:g}")

    b.net("theta1 = atan2(Py, Px) (eq. 6; Fig. 4); on the base axis theta1 := 0")
    b("mov", "t1", 0.0)
    axis = b.label()
    b.jcmp("rho2", "<=", _r(BASE_AXIS_TOL_MM**2), axis)
    atan2("t1", "py", "px")
    b("label", None, axis)
    b("sqrt", "r", "rho2", comment="r = cos(t1) Px + sin(t1) Py = rho (eq. 7)")
    if not front:
        wrap = b.label()
        done = b.label()
        b.jcmp("t1", ">", 0.0, wrap)
        b("add", "t1", "t1", _r(math.pi), comment="back: theta1 + pi, wrapped to (-pi, pi]")
        b("jmp", None, done)
        b("label", None, wrap)
        b("sub", "t1", "t1", _r(math.pi))
        b("label", None, done)
        b("sub", "r", 0.0, "r", comment="back: r = -rho")

    b.net("theta3 = -/+ acos((D^2 - L2^2 - L3^2) / (2 L2 L3)) (eqs. 9-10; Fig. 6)")
    b("sub", "ct3", "d2", _r(L2**2 + L3**2), comment=f"L2^2 + L3^2 = {L2**2 + L3**2:g}")
    b("div", "ct3", "ct3", _r(2 * L2 * L3), comment=f"2 L2 L3 = {2 * L2 * L3:g}")
    lo, hi = b.label(), b.label()
    b.jcmp("ct3", "<=", 1.0, hi, comment="clip float32 round-off to [-1, 1]")
    b("mov", "ct3", 1.0)
    b("label", None, hi)
    b.jcmp("ct3", ">=", -1.0, lo)
    b("mov", "ct3", -1.0)
    b("label", None, lo)
    acos("t3", "ct3")
    b("sub", "s3", 1.0, "ct3")
    b("add", "tmp", "ct3", 1.0)
    b("mul", "s3", "s3", "tmp")
    b("sqrt", "s3", "s3", comment="|sin theta3| = sqrt((1 - c3)(1 + c3))")
    if t3sign < 0:
        b("sub", "t3", 0.0, "t3", comment=f"{branch}: theta3 = -acos(c3)")
        b("sub", "s3", 0.0, "s3")

    b.net(
        "theta2 = atan2(z k + r s, r k - z s) - theta3, k = L2 c3 + L3, s = L2 s3 "
        "(eqs. 15-19; Fig. 5)"
    )
    b("mul", "k", "ct3", _r(L2))
    b("add", "k", "k", _r(L3))
    b("mul", "s", "s3", _r(L2))
    b("mul", "num", "zr", "k")
    b("mul", "tmp", "r", "s")
    b("add", "num", "num", "tmp")
    b("mul", "den", "r", "k")
    b("mul", "tmp", "zr", "s")
    b("sub", "den", "den", "tmp")
    atan2("t23", "num", "den")
    b("sub", "t2", "t23", "t3")
    w1, w2 = b.label(), b.label()
    b.jcmp("t2", "<=", _r(math.pi), w1, comment="wrap theta2 to (-pi, pi]")
    b("sub", "t2", "t2", _r(2 * math.pi))
    b("label", None, w1)
    b.jcmp("t2", ">", _r(-math.pi), w2)
    b("add", "t2", "t2", _r(2 * math.pi))
    b("label", None, w2)

    b.net(
        f"pulses c = ROUND(theta * {ppr[0]:g} / (2 pi)) (eqs. 20-22, theta in rad); reach flag on"
    )
    for t, n in zip(("t1", "t2", "t3"), ppr, strict=True):
        b("mul", t, t, _r(n / (2 * math.pi)), comment=f"{n:g} pulses/rev")
    b("round", "c1", "t1")
    b("round", "c2", "t2")
    b("round", "c3", "t3")
    b("set", "reachable")
    end = b.label()
    b("jmp", None, end)
    b.net("not reachable / not finite: flag off, c1..c3 unchanged, no motion")
    b("label", None, bad)
    b("reset", "reachable")
    b("label", None, end)
    code = b.code

    io = {"px", "py", "pz", "c1", "c2", "c3", "reachable"}
    work: list[str] = []
    for ins in code:
        for n in _names(ins):
            if n not in io and n not in work:
                work.append(n)
    ppr_txt = "/".join(f"{v:g}" for v in ppr)
    notes = (
        f"branch {branch}; L1 = {L1:g} mm, L2 = {L2:g} mm, L3 = {L3:g} mm, {ppr_txt} pulses/rev",
        "ATAN2/ACOS: generated subroutines"
        if trig == "subroutine"
        else "ATAN/ACOS: native instructions",
    )
    return Program(
        tuple(code),
        tuple(subs),
        tuple(work),
        params,
        branch,
        trig,
        f"IK {branch}: target (VD0/MD0...) -> pulses",
        notes,
    )
