"""The PLC program's intermediate representation, generated from an arm's closed form.

:func:`build_program` records :func:`analysis.plc.model.program_body` (the arm's one closed
form for one branch, its refusals, the joint limits and the pulse conversion, eqs. 20-22)
with :class:`~analysis.kinematics.trace.TraceOps`, and lowers the recording to a list of
:class:`Instr` (:class:`Lowering`): REAL three-address arithmetic, compare-and-jump for the
selects, the refusals and ``abs``, calls of the ATAN2/ACOS subroutines (themselves recorded
from :func:`analysis.plc.approx.atan2_poly`, the S7-200 has no inverse trigonometry) or the
S7-300's native ATAN (quadrants by :func:`analysis.plc.approx.atan2_from_atan`) and ACOS.
The printers of :data:`analysis.plc.dialects.DIALECTS` print this IR (its types:
:mod:`.instr`). No formula of an arm is written here.

Instructions (``Instr.op``), two levels
--------------------------------------
The lowering writes *structured* code, which every printer reads:

- a value operation of the one table :data:`analysis.kinematics.ops.OPS`, ``op d a [b]``
  (``add sub mul div neg sqrt sin cos atan acos abs round``; ``round`` is REAL -> DINT, the
  dialect's ROUND/RND); a printer refuses an operation its target cannot express;
- ``select d cond a b`` (d := a if cond else b; ``cond`` a :class:`Cond` tree of compares,
  ``and``/``or``/``not``, never a NaN: see below);
- ``refuse cond k`` (the target is refused with status k if cond holds: reach flag off,
  c1..cn unchanged), ``notfinite a k`` (refused with status k if a is inf/NaN: the
  exponent bits all ones, no REAL compare of a NaN, which stops an S7-200),
  ``accept (k1, k2, ...)`` (the end of the program: status 0, reach flag on; the refusal
  codes it may have given);
- ``call name (ins) (outs)``, ``network title`` (a network boundary: the S7-200 listing
  mirrors the paper's figures).

The S7 listings have only jumps: :func:`flatten` turns ``select``, ``abs``, ``refuse``,
``notfinite`` and ``accept`` into ``mov d a``, ``seti d k`` (DINT constant),
``jcmp cmp a b L`` (jump to L if a cmp b; cmp in < <= > >= == <>), ``jnotfinite a L``,
``jmp L``, ``label L`` and ``set``/``reset bit``. IEC 61131-3 ST (:mod:`.st`) has no jumps
and prints the structured form.

Operands are variable names (str) or REAL constants (float). Program I/O names are the
closed form's inputs (``px py pz``), ``c1..cn``, ``reachable`` and ``status``; work
variables are named after the closed form's ``let`` names, temporaries ``tmpK`` reuse
slots once dead (a subroutine's locals must fit the S7-200's 64 bytes of L memory).
"""

from __future__ import annotations

import dataclasses
import math
from collections import Counter

from analysis.kinematics.ops import CONDITIONS, OPS
from analysis.kinematics.status import Status
from analysis.kinematics.trace import Graph, Node, TraceOps
from analysis.plc.approx import ATAN_DEGREE, atan2_from_atan, atan2_poly
from analysis.plc.instr import (
    CMP,
    CMP_OF,
    Cond,
    Instr,
    Program,
    Subroutine,
    flatten,
    names,
    uncited,
)
from analysis.plc.model import PLC_MARGIN_MM, PLC_MARGIN_RAD, program_body

__all__ = [
    "CMP",
    "PLC_MARGIN_MM",
    "PLC_MARGIN_RAD",
    "TRIG",
    "Cond",
    "Instr",
    "Lowering",
    "Program",
    "Subroutine",
    "acos_subroutine",
    "atan2_subroutine",
    "build_program",
    "flatten",
]

_INFIX_WORDS = {"add": "plus", "sub": "minus", "mul": "x", "div": "over"}
_KIND_WORDS = {"add": "total", "sub": "difference", "mul": "product", "div": "quotient",
               "select": "choice", "neg": "negated"}  # fmt: skip
TRIG = ("subroutine", "native", "function")
"""How a program gets ATAN2 and ACOS: ``subroutine``, both generated from ``+ - * /`` and
compares (:func:`analysis.plc.approx.atan2_poly`; the S7-200 has no inverse trigonometry);
``native``, the ATAN and ACOS instructions, ATAN2's quadrants inline
(:func:`analysis.plc.approx.atan2_from_atan`; S7-300); ``function``, ACOS native and ATAN2 a
generated function of the same quadrant logic on ATAN (IEC 61131-3 ST and SCL: the standard
library has ATAN but no ATAN2). ``native`` and ``function`` compute the same REAL values."""


class Lowering:
    """Turn a recording into IR instructions.

    Parameters
    ----------
    graph : Graph
    fixed : dict of int to str
        Variable names for given nodes (inputs, outputs).
    trig : {"subroutine", "native"}
        ATAN2/ACOS as calls of the generated subroutines, or native instructions.
    keep_names : bool
        Give ``let``-named nodes their own work variable (readable main program); else
        every intermediate is a pooled temporary (subroutine locals).
    refusals : dict of int to int
        Condition node index -> the status code of the refusal when it is true, tested as
        soon as the condition is computed.
    """

    def __init__(
        self, graph, fixed, trig, *, keep_names, refusals=None, prefix="tmp", readable=False
    ):
        self.g, self.fixed, self.trig = graph, dict(fixed), trig
        self.keep_names, self.refusals = keep_names or readable, dict(refusals or {})
        self.prefix, self.readable = prefix, readable
        self.code: list[Instr] = []
        self.var: dict[int, str] = {}
        self.free: list[str] = []
        self.temps: list[str] = []
        self.named: list[str] = []
        self.live = graph.live()
        self.last_use = self._liveness()
        live = {n.index for n in self.live}
        self.repeats = Counter(v for k, v in graph.names.items() if k in live)
        self.seen: Counter = Counter()

    # --- bookkeeping ------------------------------------------------------------------------
    def emit(self, op, dst=None, *args, comment=""):
        self.code.append(Instr(op, dst, tuple(args), comment))

    def _liveness(self) -> dict[int, int]:
        """Last position at which each value node is read; a condition's operands are read
        where the condition is used (selects, refusal jumps), not where it was recorded."""
        use_pos: dict[int, int] = {}
        for n in reversed(self.live):
            if n.op in CONDITIONS:
                pos = self.refusals and n.index in self.refusals and n.index
                pos = max(pos or 0, use_pos.get(n.index, n.index))
            else:
                pos = n.index
            for a in n.args:
                if isinstance(a, Node):
                    use_pos[a.index] = max(use_pos.get(a.index, -1), pos)
        for v in self.g.outputs.values():
            if isinstance(v, Node):
                use_pos[v.index] = 1 << 30
        return use_pos

    def opnd(self, a):
        if isinstance(a, Node):
            return self.var[a.index]
        return float(a)

    def _alloc(self, n: Node) -> str:
        if n.index in self.fixed:
            name = self.fixed[n.index]
        elif self.keep_names and n.index in self.g.names:
            base = self.g.names[n.index]
            if self.readable and self.repeats[base] > 1:  # count1, count2, count3
                self.seen[base] += 1
                base = f"{base}{self.seen[base]}"
            name = self._unique(base) if self.readable else self._numbered(base)
            self.named.append(name)
        elif self.readable:  # a name from the operation and its operands (_describe)
            name = self._unique(self._describe(n))
            self.named.append(name)
            self.temps.append(name)
        elif self.free:
            name = self.free.pop()
        else:
            name = f"{self.prefix}{len(self.temps) + 1}"
            self.temps.append(name)
        self.var[n.index] = name
        return name

    def _numbered(self, base: str) -> str:
        name, k = base, 2
        while name in self.named or name in self.fixed.values():
            name, k = f"{base}_{k}", k + 1
        return name

    def _unique(self, base: str) -> str:
        """``base``, or ``base`` and the first number that no other variable has (names are
        compared as IEC 61131-3 compares them: case aside)."""
        taken = {n.upper() for n in (*self.named, *self.fixed.values())}
        name, k = base, 2
        while name.upper() in taken:
            name, k = f"{base}{k}", k + 1
        return name

    def _word(self, a) -> str:
        """An operand as a word of a name: its variable, or the constant's digits."""
        if isinstance(a, Node):
            return self.var[a.index]
        v = float(a)
        known = {math.pi: "pi", math.pi / 2: "half_pi", 2 * math.pi: "two_pi", 0.5: "half",
                 0.0: "zero", 1.0: "one", 2.0: "two"}  # fmt: skip
        text = known.get(abs(v)) or f"{abs(v):g}".replace(".", "p").replace("+", "")
        return ("minus_" if v < 0 else "") + text

    def _describe(self, n: Node) -> str:
        """A name for an intermediate that the closed form does not name, from its operation
        and the names of its operands (``px_sq``, ``abs_z``, ``y_over_x``), or the kind of
        value it is where that would be long (``product``)."""
        args = [a for a in n.args if not (isinstance(a, Node) and a.op in CONDITIONS)]
        words = [self._word(a) for a in args]
        if n.op == "mul" and len(n.args) == 2 and n.args[0] is n.args[1]:
            name = f"{words[0]}_sq"
        elif n.op in _INFIX_WORDS and len(words) == 2:
            name = f"{words[0]}_{_INFIX_WORDS[n.op]}_{words[1]}"
        elif n.op == "select" and len(words) == 2:
            name = f"{words[0]}_or_{words[1]}"
        else:
            name = "_".join([n.op, *words])
        return name if len(name) <= 24 else _KIND_WORDS.get(n.op, n.op)

    def _release(self, pos: int, n: Node) -> None:
        for a in {a.index: a for a in n.args if isinstance(a, Node)}.values():
            self._release_node(a, pos)

    def _release_node(self, a: Node, pos: int) -> None:
        if a.op in CONDITIONS:
            for b in a.args:
                if isinstance(b, Node):
                    self._release_node(b, pos)
            return
        name = self.var.get(a.index)
        if self.readable:  # each value its own variable: nothing is reused
            return
        if name in self.temps and self.last_use.get(a.index, -1) <= pos and name not in self.free:
            self.free.append(name)

    # --- conditions ---------------------------------------------------------------------------
    def cond(self, c: Node) -> Cond:
        """The :class:`Cond` tree of a recorded condition."""
        if c.op in CMP_OF:
            return Cond(c.op, (self.opnd(c.args[0]), self.opnd(c.args[1])))
        if OPS.get(c.op) is None or OPS[c.op].kind != "logic":
            raise ValueError(f"{c!r} is not a condition")
        return Cond(c.op, tuple(self.cond(a) for a in c.args))

    # --- values -------------------------------------------------------------------------------
    def node(self, n: Node) -> None:
        """One recorded operation: a table operation as the same IR instruction (the printers
        decide whether their target can express it), ``select`` with its condition tree,
        ATAN2/ACOS as calls where the program's ``trig`` says so."""
        op, args = n.op, n.args
        if op == "input":
            self.var[n.index] = self.fixed[n.index]
            return
        if op in CONDITIONS:
            return
        d = self._alloc(n)
        if op == "select":
            self.emit("select", d, self.cond(args[0]), self.opnd(args[1]), self.opnd(args[2]))
        elif op == "atan2" and self.trig in ("subroutine", "function"):
            self.emit("call", None, "ATAN2", (self.opnd(args[0]), self.opnd(args[1])), (d,))
        elif op == "atan2":
            raise ValueError("native atan2 is lowered by recording atan2_from_atan")
        elif op == "acos" and self.trig == "subroutine":
            self.emit("call", None, "ACOS", (self.opnd(args[0]),), (d,))
        else:
            self.emit(op, d, *(self.opnd(a) for a in args))

    def run(self) -> list[Instr]:
        """Lower every live node in order, with sections and refusal jumps in place."""
        sections = sorted(self.g.sections)
        k = 0
        for n in self.live:
            while k < len(sections) and sections[k][0] <= n.index:
                self.emit("network", None, sections[k][1])
                k += 1
            self.node(n)
            if n.index in self.refusals:
                self.emit("refuse", None, self.cond(n), self.refusals[n.index])
            self._release(n.index, n)
        return self.code


# ---------------------------------------------------------------------------------------------
# subroutines
# ---------------------------------------------------------------------------------------------
SUBROUTINE_TEMP = "TMP"
"""Prefix of a generated subroutine's temporaries (``TMP1``, ``TMP2``, ...). Not ``T1``:
STEP 7-Micro/WIN refuses symbol names that are addresses (``T1`` is a timer) or mnemonics
(``R`` is Reset), /work/shared/stl_reference.md, "Reserved names"; so the subroutines'
parameters are ``Y``, ``X``, ``COSINE`` and ``ANGLE``."""


def _subroutine(name, number, inputs, output, fn, trig, title, readable=False) -> Subroutine:
    g = Graph()
    m = TraceOps(g)
    ins = [g.input(k) for k in inputs]
    g.outputs = {output: fn(m, *ins)}
    fixed = {n.index: k for k, n in zip(inputs, ins, strict=True)}
    result = g.outputs[output]
    fixed[result.index] = output
    low = Lowering(g, fixed, trig, keep_names=False, prefix=SUBROUTINE_TEMP, readable=readable)
    body = [Instr("network", None, (title,)), *low.run()]
    temps = [n for n in low.named if n not in fixed.values()] if readable else low.temps
    return Subroutine(name, number, tuple(inputs), (output,), tuple(temps), tuple(body), title)


def atan2_subroutine(
    number: int = 1, degree: int = ATAN_DEGREE, readable: bool = False
) -> Subroutine:
    """ATAN2(Y, X) -> ANGLE [rad], recorded from :func:`analysis.plc.approx.atan2_poly`
    (``readable``: every value its own named variable, not the S7-200's reused temporaries
    that fit its 64 bytes of local memory)."""
    return _subroutine(
        "ATAN2",
        number,
        ("Y", "X"),
        "ANGLE",
        lambda m, y, x: atan2_poly(m, y, x, degree),
        "subroutine",
        f"ATAN2(Y, X) [rad], argument reduction + odd polynomial of degree {degree}",
        readable,
    )


def atan2_function(number: int = 1, readable: bool = False) -> Subroutine:
    """ATAN2(Y, X) -> ANGLE [rad] on the native ATAN, recorded from
    :func:`analysis.plc.approx.atan2_from_atan` (trig ``function``: IEC 61131-3 and SCL
    have ATAN, no ATAN2)."""
    return _subroutine(
        "ATAN2",
        number,
        ("Y", "X"),
        "ANGLE",
        lambda m, y, x: atan2_from_atan(m, y, x, names=readable),
        "native",
        "ATAN2(Y, X) [rad]: ATAN(Y / X) and the quadrant (no ATAN2 in the standard library)",
        readable,
    )


def acos_subroutine(
    number: int = 2, atan2_name: str = "ATAN2", readable: bool = False
) -> Subroutine:
    """ACOS(COSINE) -> ANGLE [rad] = ATAN2(sqrt((1 - c)(1 + c)), c) (``Ops.acos_via_atan2``)."""
    if atan2_name != "ATAN2":
        raise ValueError("the generated ACOS calls the generated ATAN2")
    return _subroutine(
        "ACOS",
        number,
        ("COSINE",),
        "ANGLE",
        lambda m, c: m.acos_via_atan2(c),
        "subroutine",
        "ACOS(COSINE) [rad] via ATAN2(sqrt((1-COSINE)(1+COSINE)), COSINE)",
        readable,
    )


# ---------------------------------------------------------------------------------------------
# the program
# ---------------------------------------------------------------------------------------------
class _PlcTrace(TraceOps):
    """The recorder for a PLC: ROUND/ACOS primitive; atan2 recorded from ATAN with trig
    ``native`` (S7-300), kept as a node (a call) otherwise."""

    def __init__(self, graph: Graph, trig: str) -> None:
        super().__init__(graph, primitives=("acos", "round"))
        self.trig = trig

    def atan2(self, y, x):
        if self.trig == "native":
            return atan2_from_atan(self, y, x)
        return super().atan2(y, x)


def _lower(g: Graph, fixed: dict[int, str], trig: str, inputs, refusals,
           readable: bool = False) -> tuple[Instr, ...]:  # fmt: skip
    """The program's structured code: the inputs' finiteness test (Figure 3's VD0/VD4/VD8),
    the graph lowered with its refusals, then ``accept`` (status 0 and the reach flag)."""
    codes = {int(code) for code, _ in refusals}
    low = Lowering(g, fixed, trig, keep_names=True, readable=readable,
                   refusals={c.index: int(s) for s, c in refusals})  # fmt: skip
    low.emit("network", None, "inputs (Fig. 3) finite? (bit test: no REAL compare sees a NaN)")
    for v in inputs:
        low.emit("notfinite", None, v, int(Status.INVALID))
    low.run()
    low.emit("accept", None, tuple(sorted({*codes, int(Status.INVALID)})))
    return tuple(low.code)


def _work_names(code: tuple[Instr, ...], io: set[str]) -> list[str]:
    """The scratch variables of ``code`` (every name but the inputs and outputs ``io``), in
    order of first use."""
    work: list[str] = []
    for ins in code:
        for n in names(ins):
            if n not in io and n not in work:
                work.append(n)
    return work


def _notes(arm, branch: str, trig: str, labels: dict) -> tuple[str, ...]:
    """The program header's notes: the arm, its lengths (assumed ones marked), pulses per
    revolution, the trigonometry, the status codes and the band it refuses."""
    params = arm.params
    ppr = params.pulses_per_rev
    desc = arm.description
    assumed = set(desc.assumed)
    vals = ", ".join(
        f"{k} = {v:g} mm" + (" (assumed)" if k in assumed else "") for k, v in params.items()
    )
    ppr_assumed = any(j.pulses_status == "assumed" for j in desc.joints)
    leads = "".join(  # prismatic joints: pulses = mm / lead * ppr
        f"; {j.name} prismatic, lead {j.lead_mm:g} mm/rev"
        + (" (assumed)" if j.lead_status == "assumed" else "")
        for j in desc.joints
        if j.kind == "prismatic"
    )
    return (
        f"arm {arm.name}"
        + (f" ({arm.description.title})" if arm.description.title else "")
        + f", branch {branch}; {vals}; "
        + "/".join(f"{v:g}" for v in ppr)
        + " pulses/rev"
        + (" (assumed)" if ppr_assumed else "")
        + leads,
        {
            "subroutine": "ATAN2/ACOS: generated subroutines",
            "native": "ATAN/ACOS: native instructions",
            "function": "ATAN2: generated function on the native ATAN; ACOS native",
        }[trig],
        "status: 0 ok, 1 out of reach, 2 inside reach, 3 base axis, 4 joint limits, 6 not finite"
        + "".join(
            f", {int(c)} {Status(c).text}"
            for c in (Status.DEGENERATE, Status.ORIENTATION)
            if c in labels
        ),
        f"refuses a band: {PLC_MARGIN_MM:g} mm inside the reach and around the base axis"
        + (
            f", {PLC_MARGIN_RAD:g} rad off the orientation tolerance"
            if Status.ORIENTATION in labels
            else ""
        )
        + " (REAL rounding cannot accept what float64 refuses)",
    )


REAL_EXACT = 2**24
"""The largest range of whole numbers a REAL (IEEE binary32) holds every one of: a count
beyond it is rounded to an even number, then to a multiple of 4, ..."""


def check_counts(arm) -> None:
    """Refuse an arm whose pulse counts can pass :data:`REAL_EXACT` (the program computes
    each count as a REAL, eqs. 20-22: beyond 2^24 it is off by whole pulses), naming the
    joint, its range and its resolution."""
    for j, ppr in zip(arm.description.joints, arm.params.pulses_per_rev, strict=True):
        if j.kind == "prismatic":
            ends = (j.lower, j.upper) if not j.unlimited else (float("inf"),)
            top = max(abs(e) for e in ends) / j.lead_mm * ppr
            what = (f"{max(abs(e) for e in ends):g} mm from zero at a {j.lead_mm:g} mm lead and "
                    f"{ppr:g} pulses/rev: {j.lead_mm / ppr:.3g} mm per pulse")  # fmt: skip
        else:
            reach = math.pi if j.unlimited else max(abs(j.lower), abs(j.upper))
            top = reach / (2 * math.pi) * ppr
            what = f"{math.degrees(reach):g} deg at {ppr:g} pulses/rev"
        if top > REAL_EXACT:
            step = 2.0 ** (math.floor(math.log2(top)) - 23) if math.isfinite(top) else math.inf
            raise ValueError(
                f"joint {j.name}: its counts reach {top:,.0f} pulses ({what}), beyond 2^24 = "
                f"{REAL_EXACT:,}, the largest count a REAL holds exactly: the PLC would count "
                f"in steps of {step:g} pulses there; give fewer pulses per revolution, a "
                "coarser lead or a shorter stroke"
            )


def build_program(
    arm,
    branch: str | None = None,
    trig: str = "subroutine",
    *,
    theta1_on_axis: float | None = None,
    readable: bool = False,
) -> Program:
    """The corrected IK program of an arm for one branch, from its closed form.

    Parameters
    ----------
    arm : Arm
        The arm (:class:`analysis.kinematics.arm.Arm`: its closed form, its parameters, e.g.
        Table 3, and its description's joints).
    branch : str, optional
        Default: the arm's first (the paper's) branch.
    trig : {"subroutine", "native"}
        "subroutine": generated ATAN2/ACOS (required on the S7-200); "native": the S7-300
        ATAN/ACOS instructions.
    theta1_on_axis : float, optional
        Waist angle [rad] for targets on the base axis; default: refuse them (status 3),
        as Python does.
    readable : bool
        Every intermediate its own variable, named after the closed form's symbols and the
        operation (``px_sq``, ``abs_z``, ``count1``; :meth:`Lowering._describe`), for a
        person to read (the ST family: :attr:`analysis.plc.printer.PlcPrinter.readable`);
        else the S7 programs' reused temporaries (``tmpK``: less memory, the same values).

    The program reads its inputs (Figure 3: VD0/VD4/VD8 = Px, Py, Pz) every scan: NaN or
    inf -> status 6; a refused target (the closed form's refusals, in its order, then the
    joint limits) -> its status, reach flag off, c1..cn unchanged; else c1..cn = the
    pulses (eqs. 20-22), status 0, reach flag on.
    """
    cf = arm.closed_form
    inputs = tuple(arm.inputs)
    branch = branch or arm.branches[0]
    check_counts(arm)
    if trig not in TRIG:
        raise ValueError(f"trig = {trig!r}: expected one of {', '.join(TRIG)}")
    if theta1_on_axis is not None and not math.isfinite(theta1_on_axis):
        raise ValueError(f"theta1_on_axis = {theta1_on_axis!r} rad is not finite")
    g = Graph()
    m = _PlcTrace(g, trig)
    p = [g.input(k) for k in inputs]
    body = program_body(m, arm, p, branch, theta1_on_axis=theta1_on_axis)
    refusals = body["refusals"]
    outs = {f"c{j + 1}": c for j, c in enumerate(body["c"])}
    conds = [c for _, c in refusals if isinstance(c, Node)]
    order = [c.index for c in conds]
    if order != sorted(order):
        raise ValueError(f"{cf.name}: refusals must be computed in priority order")
    g.outputs = {**outs, **{f"refuse{k}": c for k, c in enumerate(conds)}}
    labels = {code for code, _ in refusals}
    fixed = {n.index: name for name, n in zip(inputs, p, strict=True)}
    for name, v in outs.items():
        if not isinstance(v, Node) or v.op != "round":
            raise ValueError(f"{name}: pulse counts must end in the ROUND instruction")
        fixed[v.index] = name
    code = _lower(g, fixed, trig, inputs, refusals, readable)
    io = {*inputs, *outs, "reachable", "status"}
    work = _work_names(flatten(code), io)
    if trig == "subroutine":
        subs = (atan2_subroutine(1, readable=readable), acos_subroutine(2, readable=readable))
    elif trig == "function":
        subs = (atan2_function(1, readable),)
    else:
        subs = ()
    notes = _notes(arm, branch, trig, labels)
    # the paper's own arm cites it; another arm on its closed form says the same without
    cites = bool(arm.description.paper) and arm.closed_form.name == arm.name
    if not cites:
        code, notes = _uncited(code), tuple(uncited(n) for n in notes)
        subs = tuple(dataclasses.replace(s, body=_uncited(s.body), title=uncited(s.title))
                     for s in subs)  # fmt: skip
    return Program(
        code,
        subs,
        tuple(work),
        arm.name,
        branch,
        trig,
        f"IK {branch}: target ({', '.join(inputs)}) -> pulses",
        inputs,
        tuple(outs),
        notes,
        g,
        cites,
    )


def _uncited(code) -> tuple[Instr, ...]:
    """``code`` with its network titles and comments :func:`~.instr.uncited`."""
    out = []
    for i in code:
        if i.op == "network":
            i = dataclasses.replace(i, args=(uncited(i.args[0]),))
        out.append(dataclasses.replace(i, comment=uncited(i.comment)) if i.comment else i)
    return tuple(out)
