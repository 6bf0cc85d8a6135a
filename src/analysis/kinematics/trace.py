"""Record a closed form once as a straight-line program, for the generated backends.

:class:`TraceOps` is a namespace (see :mod:`analysis.kinematics.ops`) whose values are
:class:`Node` objects: running a closed form with it records every operation, in the order
the closed form performs them, into a :class:`Graph` in SSA form. The compiled kernel
(:mod:`analysis.kinematics.compiled`) and the PLC program (:mod:`analysis.plc.ir`) are
generated from such graphs, and :meth:`Graph.evaluate` replays one with any namespace, so a
test can hold the recording against a direct evaluation.

While recording, identical operations on identical operands are merged (hash-consing:
the common-subexpression elimination of ``sympy.cse``, but without reordering anything),
operations on constants are folded in float64, and the identities ``x + 0``, ``x * 1``,
``x * 0`` (finite x: the D-H chains multiply by exact zeros of cos(pi/2) rows),
``x / 1``, ``--x`` and ``select(c, a, a)`` are applied. Nothing else is rewritten, so the
floating-point result of every node is what the written formula computes.

Why not ``sympy.cse`` + printers: SymPy canonicalises sums and products (it reorders and
merges terms), which changes rounding and hides the order of the derivation that the PLC
listing should mirror; the recording keeps both.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from analysis.kinematics.ops import OPS, Ops

__all__ = ["PRIMITIVES", "Graph", "Node", "TraceOps", "apply", "trace"]

PRIMITIVES = frozenset(OPS)
"""Operations a :class:`Node` can hold ("input" nodes aside): the table
:data:`analysis.kinematics.ops.OPS`."""


class Node:
    """One recorded operation: ``op`` applied to ``args`` (nodes or float constants)."""

    __slots__ = ("args", "graph", "index", "op")

    def __init__(self, graph: Graph, op: str, args: tuple, index: int) -> None:
        self.graph, self.op, self.args, self.index = graph, op, args, index

    def __repr__(self) -> str:
        name = self.graph.names.get(self.index)
        return f"<{self.op} #{self.index}{' ' + name if name else ''}>"

    # arithmetic records into the graph (the "arith" rows of OPS: __add__ / __radd__ ...)
    def __neg__(self):
        return self.graph.op("neg", self)

    def __abs__(self):  # Python's abs() in a closed form records m.abs
        return self.graph.op("abs", self)

    def __pow__(self, k):
        return _power(self, k)

    def __bool__(self):
        raise TypeError(
            "a traced value has no truth value: write conditions with m.lt/m.gt/... and "
            "m.select, not Python if/and/or"
        )


def _binary(op: str):
    def left(self, o):
        return self.graph.op(op, self, o)

    def right(self, o):
        return self.graph.op(op, o, self)

    return left, right


for _s in OPS.values():
    if _s.dunder:
        _l, _r = _binary(_s.name)
        setattr(Node, f"__{_s.dunder}__", _l)
        setattr(Node, f"__r{_s.dunder}__", _r)
del _s, _l, _r


@dataclass
class Graph:
    """A recorded straight-line program (SSA): nodes in execution order.

    Attributes
    ----------
    nodes : list of Node
    inputs : dict of str to Node
        Named inputs, in declaration order.
    outputs : dict of str to Node or float
        Named results (set by the caller of the recording).
    names : dict of int to str
        Readable names of intermediates (``m.let``), by node index.
    sections : list of (int, str)
        ``(first node index, title)`` of each derivation step (``m.section``).
    """

    nodes: list[Node] = field(default_factory=list)
    inputs: dict[str, Node] = field(default_factory=dict)
    outputs: dict = field(default_factory=dict)
    names: dict[int, str] = field(default_factory=dict)
    sections: list[tuple[int, str]] = field(default_factory=list)
    _memo: dict = field(default_factory=dict, repr=False)

    def input(self, name: str) -> Node:
        """Declare a named input."""
        if name in self.inputs:
            raise ValueError(f"input {name!r} declared twice")
        node = self._new("input", (name,))
        self.inputs[name] = node
        return node

    def _new(self, op: str, args: tuple) -> Node:
        node = Node(self, op, args, len(self.nodes))
        self.nodes.append(node)
        return node

    def op(self, op: str, *args):
        """Record ``op(*args)``: folded, simplified or merged with an identical node."""
        if op not in PRIMITIVES:
            raise ValueError(f"unknown traced operation {op!r}")
        args = tuple(float(a) if isinstance(a, (int, float)) else a for a in args)
        for a in args:
            if isinstance(a, Node) and a.graph is not self:
                raise ValueError("cannot mix nodes of two recordings")
            if not isinstance(a, (Node, float)):
                raise TypeError(f"{op}: operand {a!r} is neither a traced value nor a number")
        fold = OPS[op].fold
        if fold is not None and all(isinstance(a, float) for a in args):
            return float(fold(*args))
        simple = _simplify(op, args)
        if simple is not None:
            return simple if not isinstance(simple, tuple) else self.op(*simple)
        key = (op, tuple(a.index if isinstance(a, Node) else ("c", a) for a in args))
        node = self._memo.get(key)
        if node is None:
            node = self._new(op, args)
            self._memo[key] = node
        return node

    # --- queries --------------------------------------------------------------------------
    def live(self) -> list[Node]:
        """Nodes the outputs depend on, in execution order (dead code removed)."""
        need: set[int] = set()
        stack = [v for v in self.outputs.values() if isinstance(v, Node)]
        while stack:
            n = stack.pop()
            if n.index in need:
                continue
            need.add(n.index)
            stack.extend(a for a in n.args if isinstance(a, Node))
        return [n for n in self.nodes if n.index in need]

    def count(self, ops: Iterable[str] | None = None) -> dict[str, int]:
        """How many live nodes of each operation (all, or only ``ops``)."""
        out: dict[str, int] = {}
        for n in self.live():
            if ops is None or n.op in ops:
                out[n.op] = out.get(n.op, 0) + 1
        return out

    def evaluate(self, m: Ops, inputs: dict) -> dict:
        """Replay the recording with namespace ``m``; ``inputs`` maps input names to values.

        Returns the outputs by name. The replay performs exactly the recorded operations,
        so it equals a direct run of the closed form with ``m`` wherever ``m``'s
        operations are deterministic.
        """
        missing = set(self.inputs) - set(inputs)
        if missing:
            raise ValueError(f"missing input value(s) {sorted(missing)}")
        val: dict[int, object] = {}

        def v(a):
            return val[a.index] if isinstance(a, Node) else a

        for n in self.live():
            if n.op == "input":
                val[n.index] = inputs[n.args[0]]
            else:
                val[n.index] = apply(m, n.op, [v(a) for a in n.args])
        return {k: v(x) for k, x in self.outputs.items()}


def _power(x, k):
    """``x ** k`` for a whole exponent 0 <= k <= 8, as repeated multiplication (what ``**``
    on a traced value means; numpy's ``**`` gives the same to round-off). Other exponents:
    TypeError (write ``m.sqrt`` or divide)."""
    if isinstance(k, bool) or not isinstance(k, (int, float)) or k != int(k) or not 0 <= k <= 8:
        raise TypeError(f"** {k!r}: a traced value takes whole exponents 0..8 (else use m.sqrt)")
    out = 1.0
    for _ in range(int(k)):
        out = x * out
    return out


def apply(m: Ops, op: str, args: list):
    """Perform one recorded operation with namespace ``m`` (an ``arith`` row of
    :data:`~analysis.kinematics.ops.OPS` by its Python operator, any other by the
    namespace's method)."""
    spec = OPS[op]
    if spec.kind == "arith":
        return spec.fold(*args)
    return getattr(m, spec.method)(*args)


def _is(a, value: float) -> bool:
    return isinstance(a, float) and a == value


def _simplify(op: str, args: tuple):
    """An equivalent simpler form (a value, or an ``(op, *args)`` tuple), or None."""
    if op == "add":
        a, b = args
        if _is(a, 0.0):
            return b
        if _is(b, 0.0):
            return a
    elif op == "sub":
        a, b = args
        if _is(b, 0.0):
            return a
        if _is(a, 0.0):
            return ("neg", b)
    elif op == "mul":
        a, b = args
        if _is(a, 0.0) or _is(b, 0.0):
            return 0.0
        if _is(a, 1.0):
            return b
        if _is(b, 1.0):
            return a
        if _is(a, -1.0):
            return ("neg", b)
        if _is(b, -1.0):
            return ("neg", a)
    elif op == "div":
        if _is(args[1], 1.0):
            return args[0]
    elif op == "neg":
        (a,) = args
        if isinstance(a, Node) and a.op == "neg":
            return a.args[0]
    elif op == "select":
        _, a, b = args
        if a is b or (isinstance(a, float) and isinstance(b, float) and a == b):
            return a
    return None


class TraceOps(Ops):
    """A namespace that records into a :class:`Graph`.

    Parameters
    ----------
    graph : Graph
    primitives : set of str
        Derived operations to record as single nodes instead of expanding them with their
        one definition in :class:`~analysis.kinematics.ops.Ops`: ``"acos"`` (else
        ``acos_via_atan2``), ``"round"`` (else ``round_half_away``). A PLC has native
        ``ROUND``/``ACOS``; the compiled kernel expands both.
    """

    def __init__(self, graph: Graph, primitives: Iterable[str] = ()) -> None:
        super().__init__()
        self.g = graph
        self.primitives = frozenset(primitives)
        unknown = self.primitives - {"acos", "round"}
        if unknown:
            raise ValueError(f"cannot keep {sorted(unknown)} primitive; only acos, round")

    def const(self, x):
        return float(x)

    def let(self, name: str, value):
        if isinstance(value, Node):
            self.g.names.setdefault(value.index, name)
        return value

    def section(self, title: str) -> None:
        self.g.sections.append((len(self.g.nodes), title))

    def acos(self, c):
        if "acos" in self.primitives:
            return self.g.op("acos", c)
        return self.acos_via_atan2(c)

    def round(self, x):
        if "round" in self.primitives:
            return self.g.op("round", x)
        return self.round_half_away(x)


def _recorder(name: str):
    def method(self, *args):
        return self.g.op(name, *args)

    method.__name__ = name
    return method


for _s in OPS.values():  # every operation but the arith (Node operators) and derived ones
    if _s.kind not in ("arith", "derived"):
        setattr(TraceOps, _s.method, _recorder(_s.name))
del _s


def trace(fn: Callable, inputs: Iterable[str], primitives: Iterable[str] = ()) -> Graph:
    """Record ``fn(m, *inputs)`` into a new graph; its return value (a dict of named
    results) becomes the graph's outputs."""
    g = Graph()
    m = TraceOps(g, primitives)
    args = [g.input(name) for name in inputs]
    out = fn(m, *args)
    if not isinstance(out, dict):
        raise TypeError("a traced function must return a dict of named results")
    g.outputs = dict(out)
    return g
