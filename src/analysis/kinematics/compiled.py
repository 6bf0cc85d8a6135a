"""The compiled fast path, generated from the closed form (Numba).

Nothing here knows an arm. :func:`solve` records the shared solver body
(:func:`analysis.kinematics.arm.solve_body`, which calls the arm's one closed form) with
:class:`~analysis.kinematics.trace.TraceOps`, prints the recording as a Python loop
(:func:`kernel_source`), and compiles it with Numba; :func:`fk` does the same with the D-H
chain. The generated source is written to a cache folder and imported from there, so Numba
caches the machine code on disk (``cache=True``) and a new process does not compile again.

Vectorization: the printed loop is straight-line arithmetic with ``_select(c, a, b)`` on
values already computed (an LLVM ``select``, which becomes a vector blend), ``sqrt`` and
division, and one inlined branch-free ``atan2`` (below); inputs and outputs are separate
contiguous 1-D arrays, each output stored as soon as it is computed.

Compile time: the loop body is one basic block. Printed as Python's ``a if c else b`` (as it
was), every select was a branch of its own: the UR5's eight-branch kernel had about 900
blocks, and Numba's parfor copy propagation, which copies its per-block tables for every
block, took about 7 minutes of the first call (profile: 78% in ``copy.deepcopy`` under
``numba.core.ir_utils.copy_propagate``). As one block it compiles in about 10 s of CPU.

The loop is a ``numba.prange`` even on one thread: Numba then declares the arrays
``noalias`` to LLVM, without which the vectorizer needs a run-time overlap check for every
pair of the ~20 arrays and gives up (measured: 6x slower). Loop-invariant nodes
(parameters, tolerance) are hoisted out of the loop. Arithmetic is IEEE (no ``fastmath``),
so results equal the numpy evaluation of the same closed form to a few ulp (the ``atan2``
differs from libm by at most 2 ulp; ``sin`` and ``cos`` are libm's).

Why Numba rather than numexpr, JAX or a C extension: it compiles Python source we generate,
on the machine, with no compiler toolchain to install, and its parallel loops use both
cores; ``make bench`` measures it against numexpr and a plain numpy closed form.
"""

from __future__ import annotations

import hashlib
import importlib.util
import math
import os
import sys
import threading
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import ClassVar

import numpy as np
import numpy.typing as npt

from analysis.kinematics import pool
from analysis.kinematics.forward import chain_points
from analysis.kinematics.printing import INFIX, ExpressionPrinter
from analysis.kinematics.solution import IKSolutions, as_points, solve_body
from analysis.kinematics.trace import Graph, Node, TraceOps
from analysis.validate import MAX_COORD_MM

try:  # pragma: no cover - depends on the environment
    import numba  # noqa: F401

    HAVE_NUMBA = True
except ImportError:  # pragma: no cover
    HAVE_NUMBA = False

__all__ = [
    "CHUNK",
    "HAVE_NUMBA",
    "Kernel",
    "KernelPrinter",
    "allocate",
    "allocate_points",
    "atan2_reference",
    "build",
    "fk",
    "fk_kernel",
    "ik_kernel",
    "kernel_source",
    "solve",
    "threads",
]

CHUNK = 1 << 20
"""Targets per kernel call: bounds the contiguous copy of the inputs (24 MB for three
columns) while keeping the start-up of a parallel loop negligible."""

# Cephes atan (S. L. Moshier, Cephes Math Library, atan.c): atan(x) = x + x^3 P(x^2)/Q(x^2)
# on [0, 0.66] with its published coefficients (peak relative error 2.6e-18), plus the
# reduction atan(t) = pi/4 + atan((t - 1)/(t + 1)) above 0.66, t = min / max of |y|, |x|;
# (t - 1)/(t + 1) is taken as (min - max)/(min + max), so the reduced argument costs one
# division, not two (both operands scaled by 2^-4 above 2^1000, exactly, against overflow).
# Branch-free: every value is computed and chosen with ``_select`` (an LLVM ``select``: the
# loop body stays one basic block, which LLVM vectorizes and Numba types quickly); within
# 2 ulp of libm's atan2 (tests/kinematics/test_compiled.py).
PRIMITIVES = """
from numba.core import types as _types
from numba.extending import intrinsic as _intrinsic


@_intrinsic
def _select(typingctx, c, a, b):
    # c ? a : b as one LLVM select of values already computed (no branch)
    t = typingctx.unify_types(a, b)
    if t is None:
        return None

    def codegen(context, builder, sig, args):
        cond = context.cast(builder, args[0], sig.args[0], _types.boolean)
        x = context.cast(builder, args[1], sig.args[1], t)
        y = context.cast(builder, args[2], sig.args[2], t)
        return builder.select(cond, x, y)

    return t(c, a, b), codegen


_AP0 = -8.750608600031904122785e-1
_AP1 = -1.615753718733365076637e1
_AP2 = -7.500855792314704667340e1
_AP3 = -1.228866684490136173410e2
_AP4 = -6.485021904942025371773e1
_AQ0 = 2.485846490142306297962e1
_AQ1 = 1.650270098316988542046e2
_AQ2 = 4.328810604912902668951e2
_AQ3 = 4.853903996359136964868e2
_AQ4 = 1.945506571482613964425e2
_MOREBITS = 6.123233995736765886130e-17
_PI = 3.141592653589793
_PIO2 = 1.5707963267948966
_PIO4 = 0.7853981633974483
_HUGE = 2.0**1000
_NAN = math.nan


@jit
def _atan2(y, x):
    ay = abs(y)
    ax = abs(x)
    k = _select(max(ax, ay) > _HUGE, 0.0625, 1.0)
    mx = max(ax, ay) * k
    mn = min(ax, ay) * k
    big = mn > 0.66 * mx
    xx = _select(big, mn - mx, mn) / _select(big, mn + mx, _select(mx != 0.0, mx, 1.0))
    z = xx * xx
    num = ((((_AP0 * z + _AP1) * z + _AP2) * z + _AP3) * z + _AP4) * z
    den = ((((z + _AQ0) * z + _AQ1) * z + _AQ2) * z + _AQ3) * z + _AQ4
    r = xx * (num / den) + xx
    a = _select(big, _PIO4 + (r + 0.5 * _MOREBITS), r)
    a = _select(ay > ax, (_PIO2 - a) + _MOREBITS, a)
    neg = (x < 0.0) | ((x == 0.0) & (math.copysign(1.0, x) < 0.0))
    a = _select(neg, (_PI - a) + 2.0 * _MOREBITS, a)
    return math.copysign(a, y)


@jit
def _sign(x):
    return _select(x > 0.0, 1.0, _select(x < 0.0, -1.0, 0.0))


@jit
def _trunc(x):
    return np.trunc(x)
"""


class KernelPrinter(ExpressionPrinter):
    """The kernel's Python expressions, one per operation of
    :data:`~analysis.kinematics.ops.OPS` (Numba compiles them)."""

    target = "the compiled kernel"
    known_functions: ClassVar[dict[str, str]] = {
        "sqrt": "math.sqrt",
        "sin": "math.sin",
        "cos": "math.cos",
        "atan": "math.atan",
        "atan2": "_atan2",
        "abs": "abs",
        "trunc": "_trunc",
        "sign": "_sign",
        "isfinite": "math.isfinite",
    }
    infix: ClassVar[dict[str, str]] = {**INFIX, "eq": "==", "and": "&", "or": "|"}

    def _print_not(self, a):
        return f"({a} ^ True)"

    def _print_select(self, cond, a, b):
        return f"_select({cond}, {a}, {b})"


_KERNEL = KernelPrinter()


def atan2_reference():
    """The kernel's ``atan2``, as plain Python (for tests against libm)."""
    ns: dict = {"math": math, "np": np, "jit": lambda f: f}
    exec(PRIMITIVES, ns)
    ns["_select"] = lambda c, a, b: a if c else b
    return ns["_atan2"]


def _literal(v: float) -> str:
    if math.isnan(v):
        return "_NAN"
    if math.isinf(v):
        return "math.inf" if v > 0 else "(-math.inf)"
    return repr(float(v))


def kernel_source(
    graph: Graph, arrays: Sequence[str], scalars: Sequence[str], outputs: dict[str, str]
) -> str:
    """Python source of a Numba kernel looping over the recording ``graph``.

    Parameters
    ----------
    arrays : names of inputs given per element (1-D arrays of length n)
    scalars : names of inputs constant over the loop (hoisted)
    outputs : {graph output name: dtype name} written to 1-D output arrays, in order

    The kernel is ``kernel(n, <arrays>, <scalars>, <outputs>)``.
    """
    live = graph.live()
    per_elem: set[int] = set()
    for n in live:
        if n.op == "input":
            if n.args[0] in arrays:
                per_elem.add(n.index)
            elif n.args[0] not in scalars:
                raise ValueError(f"input {n.args[0]!r} is neither an array nor a scalar")
        elif any(isinstance(a, Node) and a.index in per_elem for a in n.args):
            per_elem.add(n.index)

    def ref(a) -> str:
        return f"v{a.index}" if isinstance(a, Node) else _literal(a)

    def line(n: Node) -> str:
        if n.op == "input":
            name = n.args[0]
            return f"v{n.index} = a_{name}[i]" if name in arrays else f"v{n.index} = s_{name}"
        name = graph.names.get(n.index)
        comment = f"  # {name}" if name else ""
        return f"v{n.index} = {_KERNEL.doprint(n.op, *map(ref, n.args))}{comment}"

    outs = list(outputs)
    args = ["n", *(f"a_{a}" for a in arrays), *(f"s_{s}" for s in scalars)]
    args += [f"o_{k}" for k in range(len(outs))]
    # each output is stored as soon as its value is computed (a value that lives to the end
    # of the loop body holds a register or a stack slot that long); values that are not per
    # element at the end
    stores: dict = {}
    for k, name in enumerate(outs):
        v = graph.outputs[name]
        cast = {"f8": "{}", "i8": "np.int64({})", "i1": "np.int8({})", "b1": "{}"}[outputs[name]]
        at = v.index if isinstance(v, Node) and v.index in per_elem else None
        stores.setdefault(at, []).append(f"        o_{k}[i] = {cast.format(ref(v))}")
    body = [f"def kernel({', '.join(args)}):"]
    body += [f"    {line(n)}" for n in live if n.index not in per_elem]
    body.append("    for i in numba.prange(n):")
    for n in live:
        if n.index in per_elem:
            body += [f"        {line(n)}", *stores.get(n.index, ())]
    body += stores.get(None, [])
    return "\n".join(body) + "\n"


def _cache_dir() -> Path:
    env = os.environ.get("ANALYSIS_KERNEL_CACHE")
    base = Path(env) if env else Path.home() / ".cache" / "analysis-kernels"
    base.mkdir(parents=True, exist_ok=True)
    return base


def module_text(source: str) -> str:
    """The generated module: imports, the primitives and the decorated kernel ``source``."""
    return (
        "# generated by analysis.kinematics.compiled: do not edit\n"
        "import math\n\nimport numba\nimport numpy as np\n\n"
        "jit = numba.njit(inline='always', error_model='numpy')\n"
        + PRIMITIVES
        + "\n\n@numba.njit(parallel=True, error_model='numpy', nogil=True, cache=True)\n"
        + source
        + TRANSPOSE
    )


TRANSPOSE = """

@numba.njit(parallel=True, nogil=True, cache=True)
def transpose_into(src, dst, start, k, lim):
    # rows start .. start + k of src (n, m) into the columns 0 .. k of dst (m, >= k),
    # in parallel (the kernel then reads each input as a contiguous row); returns how many
    # of the values copied are outside +-lim[j] of their column (NaN included)
    m = src.shape[1]
    bad = 0
    for i in numba.prange(k):
        for j in range(m):
            v = src[start + i, j]
            dst[j, i] = v
            bad += 0 if abs(v) <= lim[j] else 1
    return bad
"""
"""The input copy of :meth:`Kernel.run`, generated with each kernel (and cached with it):
a parallel transpose, twice as fast as ``np.copyto`` of the transposed rows on two cores,
which counts the inputs outside their range on the way (NaN and inf included: the
validation of :mod:`analysis.validate`, in the same pass)."""


@cache
def _compile(source: str):
    """Write the kernel module (primitives + kernel) to the cache folder, import, return it."""
    text = module_text(source)
    digest = hashlib.sha256(text.encode()).hexdigest()[:20]
    name = f"kernel_{digest}"
    path = _cache_dir() / f"{name}.py"
    if not path.exists() or path.read_text() != text:
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(text)
        os.replace(tmp, path)
    spec = importlib.util.spec_from_file_location(f"analysis_kernels.{name}", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def threads() -> int:
    """Threads the kernels' parallel loops use (Numba's; ``NUMBA_NUM_THREADS`` sets them)."""
    import numba

    return numba.get_num_threads()


_LOCAL = threading.local()

BLOCK = 4096
"""Targets per kernel call on large inputs: the kernel writes into per-thread scratch rows
that stay in the L2 cache, which are then copied out row by row. Written straight into the
caller's rows, one store stream per output (66 for a six-axis arm) far apart, the kernel ran
at 180-580 ns per target on one thread (PUMA 560, 200,000 targets, varying with where the
rows fall) against 120 ns in cache; through the scratch rows, 210 ns steadily (measured,
Python's copies included)."""


BLOCK_OUTPUTS = 32
"""Kernels with more outputs than this go through the scratch rows (:data:`BLOCK`); fewer
streams are written straight (the grabber's 22: 79 M targets/s straight, 34 M through the
scratch rows, whose copies then cost more than they save; measured)."""


def _scratch_out(dtype, idx: int) -> np.ndarray:
    """A per-thread scratch output row of :data:`BLOCK` values (``idx``: which output)."""
    rows = getattr(_LOCAL, "out_rows", None)
    if rows is None:
        rows = _LOCAL.out_rows = {}
    key = (idx, np.dtype(dtype).str)
    if key not in rows:
        rows[key] = np.empty(BLOCK, dtype=dtype)
    return rows[key]


def _scratch(rows: int, cols: int) -> np.ndarray:
    """A per-thread scratch buffer for the input copy, kept between calls: memory that was
    just freed and is touched again is slow on a virtual machine whose host reclaims it
    (measured: the first call after an idle second ran at a third of the warm speed)."""
    buf = getattr(_LOCAL, "buf", None)
    if buf is None or buf.shape[0] < rows or buf.shape[1] < cols:
        old = (0, 0) if buf is None else buf.shape
        buf = np.empty((max(rows, old[0]), max(cols, old[1])))
        _LOCAL.buf = buf
    return buf[:rows, :cols]


@dataclass(frozen=True)
class Kernel:
    """A compiled recording: ``run(inputs, scalars, outs)`` evaluates it per row.

    Attributes
    ----------
    source : str
        The generated loop (for reading, tests and the assembly check).
    graph : Graph
        The recording it was printed from.
    arrays, scalars : tuple of str
        Per-row inputs (columns of ``inputs``) and loop constants, in call order.
    outputs : dict
        Output name -> dtype code ("f8", "i8", "i1", "b1"), in call order.
    """

    fn: object
    source: str
    graph: Graph
    arrays: tuple
    scalars: tuple
    outputs: dict
    transpose: object = None

    def run(self, inputs: np.ndarray, scalars, outs, limits=None) -> int:
        """Evaluate rows ``inputs`` (n, len(arrays)) into 1-D arrays ``outs`` (length n);
        return how many input values are outside +-``limits`` (one per column; default: how
        many are not finite). Their rows are evaluated all the same.

        The input columns are copied into contiguous buffers a chunk at a time (at most
        :data:`CHUNK` rows: bounded memory), then one parallel kernel call per chunk.
        """
        n = inputs.shape[0]
        scal = [float(v) for v in scalars]
        k_in = len(self.arrays)
        buf = _scratch(k_in, min(CHUNK, max(n, 1)))
        lim = np.full(k_in, np.inf) if limits is None else np.asarray(limits, dtype=np.float64)
        fast = (
            self.transpose is not None
            and inputs.ndim == 2
            and inputs.dtype == np.float64
            and inputs.flags.c_contiguous
        )
        bad = 0
        for s in range(0, n, CHUNK):
            e = min(s + CHUNK, n)
            k = e - s
            if fast:
                bad += self.transpose(inputs, buf, s, k, lim)
            else:
                np.copyto(buf[:, :k], inputs[s:e].T)
                bad += int(k * k_in - (np.abs(buf[:, :k]) <= lim[:, None]).sum())
            if k <= BLOCK or len(outs) <= BLOCK_OUTPUTS:
                self.fn(k, *(buf[j, :k] for j in range(k_in)), *scal, *(o[s:e] for o in outs))
                continue
            scratch = [_scratch_out(o.dtype, idx) for idx, o in enumerate(outs)]
            for b in range(0, k, BLOCK):  # through cache-resident rows (BLOCK's docstring)
                f = min(b + BLOCK, k)
                self.fn(f - b, *(buf[j, b:f] for j in range(k_in)), *scal,
                        *(x[: f - b] for x in scratch))  # fmt: skip
                for o, x in zip(outs, scratch, strict=True):
                    o[s + b : s + f] = x[: f - b]
        return bad


def build(fn, arrays, scalars, outputs: dict, primitives=()) -> Kernel:
    """Record ``fn(m, inputs)`` (inputs: name -> traced value; returns a dict of results)
    and compile it; ``outputs`` selects and orders the results with their dtypes."""
    g = Graph()
    m = TraceOps(g, primitives)
    nodes = {k: g.input(k) for k in (*arrays, *scalars)}
    result = fn(m, nodes)
    g.outputs = {k: result[k] for k in outputs}
    src = kernel_source(g, tuple(arrays), tuple(scalars), dict(outputs))
    mod = _compile(src)
    return Kernel(
        mod.kernel, src, g, tuple(arrays), tuple(scalars), dict(outputs), mod.transpose_into
    )


# --------------------------------------------------------------------------------------------
# inverse kinematics
# --------------------------------------------------------------------------------------------
@cache
def ik_kernel(cf, params: tuple, names: tuple, limits: tuple) -> Kernel:
    """The kernel of :func:`~analysis.kinematics.solution.solve_body` for the closed form
    ``cf`` (a :class:`~analysis.kinematics.arms.ClosedForm`, the arm's) and the parameter
    names ``params`` (their values are the kernel's scalar inputs)."""

    def body(m, v):
        p = tuple(v[k] for k in cf.INPUTS)
        P = {k: v[k] for k in params}
        return solve_body(m, cf, p, P, names, tol=v["tol"], limits=limits)

    n_joints = cf.probe(params)
    outputs = {"status": "i1", "outside": "f8"}
    outputs.update({f"ok:{b}": "b1" for b in names})
    outputs.update({f"status:{b}": "i1" for b in names})
    outputs.update({f"q:{b}:{j}": "f8" for b in names for j in range(n_joints)})
    return build(body, cf.INPUTS, (*params, "tol"), outputs)


def allocate(n_joints: int, shape: tuple, branches: Sequence[str]):
    """Output buffers for :func:`solve` (pass them back as ``out=`` to reuse memory).

    They come from :mod:`analysis.kinematics.pool`: memory of results that are gone is
    reused, not mapped and touched again."""
    n = int(np.prod(shape, dtype=np.int64))
    B = len(branches)
    theta = pool.empty((B, n_joints, n))
    ok = pool.empty((B, n), dtype=bool)
    branch_status = pool.empty((B, n), dtype=np.int8)
    return IKSolutions(
        np.moveaxis(theta, -1, 0).reshape(*shape, B, n_joints),
        np.moveaxis(ok, -1, 0).reshape(*shape, B),
        pool.empty(shape, dtype=np.int8),
        pool.empty(shape),
        tuple(branches),
        np.moveaxis(branch_status, -1, 0).reshape(*shape, B),
    )


def allocate_points(shape: tuple) -> np.ndarray:
    """An output buffer of shape (..., 3) for :func:`fk` (``out=``): x, y and z each
    contiguous underneath, as the kernel writes them."""
    n = int(np.prod(shape, dtype=np.int64))
    return np.moveaxis(pool.empty((3, n)), 0, -1).reshape(*shape, 3)


def _storage(view: np.ndarray, shape: tuple) -> np.ndarray:
    """The contiguous storage behind an output view: ``view`` reshaped to ``shape`` (n
    first, without copying) with n moved last (see :func:`allocate`)."""
    try:
        base = np.moveaxis(view.reshape(shape, copy=False), 0, -1)
    except ValueError:
        base = None
    if base is None or not base.flags.c_contiguous:
        raise ValueError("out= buffers must come from analysis.kinematics.compiled.allocate")
    return base


def input_limits(units: Sequence[str]) -> np.ndarray:
    """Largest |input| per column (:mod:`analysis.validate`): coordinates [mm]; angles [rad]
    any finite value."""
    return np.array([np.finfo(np.float64).max if u == "rad" else MAX_COORD_MM for u in units])


def solve(arm, p: npt.NDArray[np.float64], names, *, tol: float, limits, out=None):
    """:meth:`Arm.solve` with the compiled kernel (same arguments, validated but for the
    values of ``p``, whose ranges the kernel's input copy checks: ``ValueError`` as from
    :func:`~analysis.kinematics.solution.as_points`, after the outputs were written)."""
    if not HAVE_NUMBA:  # pragma: no cover
        return arm.solve(p, names, tol=tol, limits=bool(limits))
    names = tuple(names)
    kern = ik_kernel(arm.cf, tuple(arm.params), names, tuple(limits))
    nj = arm.n_joints
    shape = p.shape[:-1]
    res = out if out is not None else allocate(nj, shape, names)
    if res.status.shape != shape or res.branches != names or res.theta.shape[-1] != nj:
        raise ValueError(f"out= buffers do not fit {shape} targets and branches {names}")
    n = int(np.prod(shape, dtype=np.int64))
    theta = _storage(res.theta, (n, len(names), nj))  # (B, J, n)
    ok = _storage(res.ok, (n, len(names)))  # (B, n)
    outs = [res.status.reshape(n, copy=False), res.outside_mm.reshape(n, copy=False)]
    if res.branch_status is None:
        raise ValueError("out= buffers must come from analysis.kinematics.compiled.allocate")
    bstat = _storage(res.branch_status, (n, len(names)))  # (B, n)
    outs += [ok[b] for b in range(len(names))]
    outs += [bstat[b] for b in range(len(names))]
    outs += [theta[b, j] for b in range(len(names)) for j in range(nj)]
    limits = input_limits(arm.input_units)
    if kern.run(p.reshape(n, p.shape[-1]), [*arm.params.values(), tol], outs, limits):
        # raises, naming the first target outside analysis.validate's ranges
        as_points(p, inputs=arm.inputs, units=arm.input_units)
    return IKSolutions(res.theta, res.ok, res.status, res.outside_mm, names, res.branch_status)


# --------------------------------------------------------------------------------------------
# forward kinematics
# --------------------------------------------------------------------------------------------
@cache
def fk_kernel(description, cf, params: tuple) -> Kernel:
    """The kernel of the arm's end point (:func:`analysis.kinematics.forward.chain_points`:
    the D-H chain, or the closed form ``cf``'s own FK for a closed chain)."""
    nq = len(description.joints)

    def body(m, v):
        P = {k: v[k] for k in params}
        end = chain_points(m, description, cf, P, [v[f"q{j}"] for j in range(nq)])["frames"][-1]
        return {"x": end[0], "y": end[1], "z": end[2]}

    return build(body, tuple(f"q{j}" for j in range(nq)), params, dict.fromkeys("xyz", "f8"))


def fk(arm, q: npt.ArrayLike, out: npt.NDArray[np.float64] | None = None):
    """:meth:`Arm.fk` with the compiled kernel: end points (..., 3) [mm] for (..., n)
    [rad | mm] (a closed chain's joint values are checked as :meth:`Arm.fk` does)."""
    q = arm._q(q)
    if not HAVE_NUMBA:  # pragma: no cover
        return arm.fk(q)
    kern = fk_kernel(arm.description, arm.closed_form, tuple(arm.params))
    shape = q.shape[:-1]
    n = int(np.prod(shape, dtype=np.int64))
    res = np.empty((3, n)) if out is None else _storage(out, (n, 3))
    kern.run(q.reshape(n, -1), list(arm.params.values()), [res[0], res[1], res[2]])
    return (np.moveaxis(res, 0, -1) if out is None else out).reshape(*shape, 3)
