"""The PLC program's intermediate representation, generated from an arm's closed form.

:func:`build_program` records :func:`analysis.plc.model.program_body` (the arm's one closed
form for one branch, its refusals, the joint limits and the pulse conversion, eqs. 20-22)
with :class:`~analysis.kinematics.trace.TraceOps`, and lowers the recording to a list of
:class:`Instr` (:class:`Lowering`): REAL three-address arithmetic, compare-and-jump for the
selects, the refusals and ``abs``, calls of the ATAN2/ACOS subroutines (themselves recorded
from :func:`analysis.plc.approx.atan2_poly`, the S7-200 has no inverse trigonometry) or the
S7-300's native ATAN (quadrants by :func:`analysis.plc.approx.atan2_from_atan`) and ACOS.
Both emitters (:mod:`.emit`) print this IR. No formula of an arm is written here.

Instruction set (``Instr.op``)
------------------------------
``mov d a`` | ``add/sub/mul/div d a b`` (d := a op b) | ``sqrt/sin/cos/atan/acos d a`` |
``round d a`` (REAL -> DINT, the dialect's ROUND/RND) | ``seti d k`` (DINT constant) |
``jcmp cmp a b L`` (jump to L if a cmp b; cmp in < <= > >= == <>) | ``jnotfinite a L``
(jump if a is inf/NaN: exponent bits all ones, no REAL compare of a NaN, which stops an
S7-200) | ``jmp L`` | ``label L`` | ``set/reset bit`` | ``call name (ins) (outs)`` |
``network title`` (a network boundary: the S7-200 listing mirrors the paper's figures).

Operands are variable names (str) or REAL constants (float). Program I/O names are the
closed form's inputs (``px py pz``), ``c1..cn``, ``reachable`` and ``status``; work
variables are named after the closed form's ``let`` names, temporaries ``tmpK`` reuse
slots once dead (a subroutine's locals must fit the S7-200's 64 bytes of L memory).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from analysis.kinematics.arms import closed_form
from analysis.kinematics.status import Status
from analysis.kinematics.trace import Graph, Node, TraceOps
from analysis.plc.approx import ATAN_DEGREE, atan2_from_atan, atan2_poly
from analysis.plc.model import PLC_MARGIN_MM, PLC_MARGIN_RAD, program_body

__all__ = [
    "CMP",
    "PLC_MARGIN_MM",
    "PLC_MARGIN_RAD",
    "Instr",
    "Lowering",
    "Program",
    "Subroutine",
    "acos_subroutine",
    "atan2_subroutine",
    "build_program",
]

CMP = ("<", "<=", ">", ">=", "==", "<>")
ARITH = ("add", "sub", "mul", "div")
UNARY = ("mov", "sqrt", "sin", "cos", "atan", "acos", "round")
_CMP_OF = {"lt": "<", "le": "<=", "gt": ">", "ge": ">=", "eq": "=="}
_NOT = {"<": ">=", "<=": ">", ">": "<=", ">=": "<", "==": "<>", "<>": "=="}
_CONDITIONS = {"lt", "le", "gt", "ge", "eq", "and", "or", "not"}


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
    refusals : dict of int to str
        Condition node index -> label to jump to when it is true, emitted as soon as the
        condition is computed.
    """

    def __init__(self, graph, fixed, trig, *, keep_names, refusals=None, prefix="tmp"):
        self.g, self.fixed, self.trig = graph, dict(fixed), trig
        self.keep_names, self.refusals = keep_names, dict(refusals or {})
        self.prefix = prefix
        self.code: list[Instr] = []
        self.var: dict[int, str] = {}
        self.free: list[str] = []
        self.temps: list[str] = []
        self.named: list[str] = []
        self._labels = 0
        self.live = graph.live()
        self.last_use = self._liveness()

    # --- bookkeeping ------------------------------------------------------------------------
    def label(self) -> str:
        self._labels += 1
        return f"@{self._labels}"

    def emit(self, op, dst=None, *args, comment=""):
        self.code.append(Instr(op, dst, tuple(args), comment))

    def _liveness(self) -> dict[int, int]:
        """Last position at which each value node is read; a condition's operands are read
        where the condition is used (selects, refusal jumps), not where it was recorded."""
        use_pos: dict[int, int] = {}
        for n in reversed(self.live):
            if n.op in _CONDITIONS:
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
            name, k = base, 2
            while name in self.named or name in self.fixed.values():
                name, k = f"{base}_{k}", k + 1
            self.named.append(name)
        elif self.free:
            name = self.free.pop()
        else:
            name = f"{self.prefix}{len(self.temps) + 1}"
            self.temps.append(name)
        self.var[n.index] = name
        return name

    def _release(self, pos: int, n: Node) -> None:
        for a in {a.index: a for a in n.args if isinstance(a, Node)}.values():
            self._release_node(a, pos)

    def _release_node(self, a: Node, pos: int) -> None:
        if a.op in _CONDITIONS:
            for b in a.args:
                if isinstance(b, Node):
                    self._release_node(b, pos)
            return
        name = self.var.get(a.index)
        if name in self.temps and self.last_use.get(a.index, -1) <= pos and name not in self.free:
            self.free.append(name)

    # --- conditions ---------------------------------------------------------------------------
    def jump_if(self, cond, target: str, value: bool) -> None:
        """Jump to ``target`` if ``cond`` is ``value`` (short-circuit and/or/not)."""
        op = cond.op
        if op in _CMP_OF:
            cmp = _CMP_OF[op] if value else _NOT[_CMP_OF[op]]
            self.emit("jcmp", None, cmp, self.opnd(cond.args[0]), self.opnd(cond.args[1]), target)
        elif op == "not":
            self.jump_if(cond.args[0], target, not value)
        elif (op == "or") == value:  # or -> true, and -> false: either operand decides
            self.jump_if(cond.args[0], target, value)
            self.jump_if(cond.args[1], target, value)
        else:  # or -> false, and -> true: both operands must agree
            skip = self.label()
            self.jump_if(cond.args[0], skip, not value)
            self.jump_if(cond.args[1], target, value)
            self.emit("label", None, skip)
        if op not in _CONDITIONS:
            raise ValueError(f"{cond!r} is not a condition")

    # --- values -------------------------------------------------------------------------------
    def node(self, n: Node) -> None:
        op, args = n.op, n.args
        if op == "input":
            self.var[n.index] = self.fixed[n.index]
            return
        if op in _CONDITIONS:
            return
        d = self._alloc(n)
        a = [None if isinstance(x, Node) and x.op in _CONDITIONS else self.opnd(x) for x in args]
        if op in ARITH:
            self.emit(op, d, a[0], a[1])
        elif op == "neg":
            self.emit("sub", d, 0.0, a[0])
        elif op in ("sqrt", "sin", "cos", "atan"):
            self.emit(op, d, a[0])
        elif op == "round":
            self.emit("round", d, a[0])
        elif op == "abs":
            skip = self.label()
            self.emit("mov", d, a[0])
            self.emit("jcmp", None, ">=", a[0], 0.0, skip)
            self.emit("sub", d, 0.0, a[0])
            self.emit("label", None, skip)
        elif op == "select":
            skip = self.label()
            self.emit("mov", d, a[2])
            self.jump_if(args[0], skip, False)
            self.emit("mov", d, a[1])
            self.emit("label", None, skip)
        elif op == "atan2":
            if self.trig == "subroutine":
                self.emit("call", None, "ATAN2", (a[0], a[1]), (d,))
            else:
                raise ValueError("native atan2 is lowered by recording atan2_from_atan")
        elif op == "acos":
            if self.trig == "subroutine":
                self.emit("call", None, "ACOS", (a[0],), (d,))
            else:
                self.emit("acos", d, a[0])
        else:
            raise ValueError(f"cannot lower {op!r} to PLC instructions")

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
                self.jump_if(n, self.refusals[n.index], True)
            self._release(n.index, n)
        return self.code


# ---------------------------------------------------------------------------------------------
# subroutines
# ---------------------------------------------------------------------------------------------
def _subroutine(name, number, inputs, output, fn, trig, title) -> Subroutine:
    g = Graph()
    m = TraceOps(g)
    ins = [g.input(k) for k in inputs]
    g.outputs = {output: fn(m, *ins)}
    fixed = {n.index: k for k, n in zip(inputs, ins, strict=True)}
    result = g.outputs[output]
    fixed[result.index] = output
    low = Lowering(g, fixed, trig, keep_names=False, prefix="T")
    body = [Instr("network", None, (title,)), *low.run()]
    return Subroutine(name, number, tuple(inputs), (output,), tuple(low.temps), tuple(body), title)


def atan2_subroutine(number: int = 1, degree: int = ATAN_DEGREE) -> Subroutine:
    """ATAN2(Y, X) -> R [rad], recorded from :func:`analysis.plc.approx.atan2_poly`."""
    return _subroutine(
        "ATAN2",
        number,
        ("Y", "X"),
        "R",
        lambda m, y, x: atan2_poly(m, y, x, degree),
        "subroutine",
        f"ATAN2(Y, X) [rad], argument reduction + odd polynomial of degree {degree}",
    )


def acos_subroutine(number: int = 2, atan2_name: str = "ATAN2") -> Subroutine:
    """ACOS(C) -> R [rad] = ATAN2(sqrt((1 - C)(1 + C)), C) (``Ops.acos_via_atan2``)."""
    if atan2_name != "ATAN2":
        raise ValueError("the generated ACOS calls the generated ATAN2")
    return _subroutine(
        "ACOS",
        number,
        ("C",),
        "R",
        lambda m, c: m.acos_via_atan2(c),
        "subroutine",
        "ACOS(C) [rad] via ATAN2(sqrt((1-C)(1+C)), C)",
    )


# ---------------------------------------------------------------------------------------------
# the program
# ---------------------------------------------------------------------------------------------
class _PlcTrace(TraceOps):
    """The recorder for a PLC: ROUND/ACOS primitive; atan2 recorded from ATAN on the S7-300."""

    def __init__(self, graph: Graph, trig: str) -> None:
        super().__init__(graph, primitives=("acos", "round"))
        self.trig = trig

    def atan2(self, y, x):
        if self.trig == "native":
            return atan2_from_atan(self, y, x)
        return super().atan2(y, x)


def _lower(
    g: Graph, fixed: dict[int, str], trig: str, inputs, refusals, labels: dict
) -> tuple[Instr, ...]:
    """The program's code: the inputs' finiteness test (Figure 3's VD0/VD4/VD8), the graph
    lowered, then status 0 and the reach flag, or a refusal's status code."""
    low = Lowering(
        g, fixed, trig, keep_names=True, refusals={c.index: labels[s] for s, c in refusals}
    )
    low.emit("network", None, "inputs (Fig. 3) finite? (bit test: no REAL compare sees a NaN)")
    invalid = "@refuse6"
    for v in inputs:
        low.emit("jnotfinite", None, v, invalid)
    low.run()
    end = low.label()
    low.emit("seti", "status", 0)
    low.emit("set", "reachable")
    low.emit("jmp", None, end)
    low.emit("network", None, "refused: status code, reach flag off, c1..cn unchanged, no motion")
    for code in sorted({*labels, Status.INVALID}):
        low.emit("label", None, f"@refuse{int(code)}")
        low.emit("seti", "status", int(code), comment=Status(code).text)
        low.emit("reset", "reachable")
        low.emit("jmp", None, end)
    low.emit("label", None, end)
    return tuple(low.code)


def _work_names(code: tuple[Instr, ...], io: set[str]) -> list[str]:
    """The scratch variables of ``code`` (every name but the inputs and outputs ``io``), in
    order of first use."""
    work: list[str] = []
    for ins in code:
        for n in _names(ins):
            if n not in io and n not in work:
                work.append(n)
    return work


def _notes(params, branch: str, trig: str, labels: dict) -> tuple[str, ...]:
    """The program header's notes: the arm, its lengths (assumed ones marked), pulses per
    revolution, the trigonometry, the status codes and the band it refuses."""
    ppr = params.pulses_per_rev
    desc = params.description
    assumed = set(desc.assumed)
    vals = ", ".join(
        f"{k} = {v:g} mm" + (" (assumed)" if k in assumed else "") for k, v in params.items()
    )
    ppr_assumed = any(j.pulses_status == "assumed" for j in desc.joints)
    return (
        f"arm {params.arm}, branch {branch}; {vals}; "
        + "/".join(f"{v:g}" for v in ppr)
        + " pulses/rev"
        + (" (assumed)" if ppr_assumed else ""),
        "ATAN2/ACOS: generated subroutines"
        if trig == "subroutine"
        else "ATAN/ACOS: native instructions",
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


def build_program(
    params,
    branch: str | None = None,
    trig: str = "subroutine",
    *,
    theta1_on_axis: float | None = None,
) -> Program:
    """The corrected IK program of an arm for one branch, from its closed form.

    Parameters
    ----------
    params : Params
        The arm's parameters (:class:`analysis.kinematics.arm.Params`, e.g. Table 3).
    branch : str, optional
        Default: the arm's first (the paper's) branch.
    trig : {"subroutine", "native"}
        "subroutine": generated ATAN2/ACOS (required on the S7-200); "native": the S7-300
        ATAN/ACOS instructions.
    theta1_on_axis : float, optional
        Waist angle [rad] for targets on the base axis; default: refuse them (status 3),
        as Python does.

    The program reads its inputs (Figure 3: VD0/VD4/VD8 = Px, Py, Pz) every scan: NaN or
    inf -> status 6; a refused target (the closed form's refusals, in its order, then the
    joint limits) -> its status, reach flag off, c1..cn unchanged; else c1..cn = the
    pulses (eqs. 20-22), status 0, reach flag on.
    """
    cf = closed_form(params.description.closed_form)
    branch = branch or cf.BRANCHES[0]
    if trig not in ("subroutine", "native"):
        raise ValueError(f"trig = {trig!r}: expected 'subroutine' or 'native'")
    if theta1_on_axis is not None and not math.isfinite(theta1_on_axis):
        raise ValueError(f"theta1_on_axis = {theta1_on_axis!r} rad is not finite")
    g = Graph()
    m = _PlcTrace(g, trig)
    p = [g.input(k) for k in cf.INPUTS]
    body = program_body(m, params, p, branch, theta1_on_axis=theta1_on_axis)
    refusals = body["refusals"]
    outs = {f"c{j + 1}": c for j, c in enumerate(body["c"])}
    conds = [c for _, c in refusals if isinstance(c, Node)]
    order = [c.index for c in conds]
    if order != sorted(order):
        raise ValueError(f"{cf.__name__}: refusals must be computed in priority order")
    g.outputs = {**outs, **{f"refuse{k}": c for k, c in enumerate(conds)}}
    labels = {code: f"@refuse{int(code)}" for code, _ in refusals}
    fixed = {n.index: name for name, n in zip(cf.INPUTS, p, strict=True)}
    for name, v in outs.items():
        if not isinstance(v, Node) or v.op != "round":
            raise ValueError(f"{name}: pulse counts must end in the ROUND instruction")
        fixed[v.index] = name
    code = _lower(g, fixed, trig, cf.INPUTS, refusals, labels)
    io = {*cf.INPUTS, *outs, "reachable", "status"}
    work = _work_names(code, io)
    subs = (atan2_subroutine(1), acos_subroutine(2)) if trig == "subroutine" else ()
    notes = _notes(params, branch, trig, labels)
    return Program(
        code,
        subs,
        tuple(work),
        params.arm,
        branch,
        trig,
        f"IK {branch}: target ({', '.join(cf.INPUTS)}) -> pulses",
        tuple(cf.INPUTS),
        tuple(outs),
        notes,
        g,
    )
