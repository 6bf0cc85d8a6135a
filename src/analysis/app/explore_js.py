"""An arm's kinematics printed as JavaScript, from its one closed form (no hand-written copy).

The explorer draws the arm in the browser: in JupyterLab (the widget of
:mod:`analysis.app.arm3d`, which redraws the moment a slider moves, without waiting for the
kernel) and on the static report site (sliders that need no kernel at all). Both run the
JavaScript that :func:`arm_module_js` prints from two recordings
(:mod:`analysis.kinematics.trace`):

* the shared solver body :func:`~analysis.kinematics.solution.solve_body` with the arm's
  closed form (statuses, joint limits, every branch; what :meth:`Arm.solve` runs with numpy
  and what the compiled kernel is printed from), plus the whole pulse counts of eqs. 20-22
  (:func:`~analysis.kinematics.pulses.pulse_count`);
* the D-H chain's frame origins (:func:`~analysis.kinematics.dh.chain_frames`, what
  :meth:`Arm.frames` evaluates with numpy), which the 3D view draws.

The printer is one class of the project's printers (:mod:`analysis.kinematics.printing`,
beside the compiled kernel's and the PLC dialects'): :class:`JsPrinter`, a method or a known
function per operation of the one op table, and a loop over the live nodes of a graph in
execution order. The recording keeps the order of every
floating-point operation of the closed form, so the printed function computes what numpy
computes: ``+ - * / sqrt`` are correctly rounded in both, and ``Math.atan2``, ``acos``,
``sin``, ``cos`` differ from the C library by an ulp or two. The browser tests hold the
printed functions to :meth:`Arm.solve` and :meth:`Arm.frames` within 1e-9 (rad, mm) on
seeded targets of every arm (``tests/browser/test_explorer_static.py``).

Why not SymPy's ``jscode``: SymPy reorders sums and products (other rounding than numpy's),
and its expressions of the closed form drop ``wrap`` and ``clip``
(:class:`~analysis.kinematics.symbolic.SympyOps`), which the explorer needs at the wrap cut
and at the reach shells.
"""

from __future__ import annotations

import math
from typing import ClassVar

from analysis.escape import js_comment, js_json
from analysis.kinematics.dh import chain_transforms
from analysis.kinematics.printing import INFIX, ExpressionPrinter
from analysis.kinematics.pulses import pulse_count
from analysis.kinematics.rpy import GIMBAL_LOCK_COS
from analysis.kinematics.solution import DEFAULT_TOL_MM, solve_body
from analysis.kinematics.status import STATUS_TEXT
from analysis.kinematics.trace import Graph, Node, TraceOps

__all__ = [
    "JsPrinter", "arm_module_js", "frames_graph", "graph_js", "pulses_graph", "solve_graph",
]  # fmt: skip


class JsPrinter(ExpressionPrinter):
    """JavaScript expressions, one per operation of :data:`~analysis.kinematics.ops.OPS`
    (the recorder expands the derived ``round`` into ``trunc``/``sign``/``select``)."""

    target = "JavaScript"
    known_functions: ClassVar[dict[str, str]] = {
        "sqrt": "Math.sqrt",
        "sin": "Math.sin",
        "cos": "Math.cos",
        "atan": "Math.atan",
        "atan2": "Math.atan2",
        "acos": "Math.acos",
        "abs": "Math.abs",
        "trunc": "Math.trunc",
        "sign": "Math.sign",
        "isfinite": "Number.isFinite",
    }
    infix: ClassVar[dict[str, str]] = {**INFIX, "eq": "===", "and": "&&", "or": "||"}

    def _print_not(self, a):
        return f"(!{a})"

    def _print_select(self, cond, a, b):
        return f"({cond} ? {a} : {b})"


JS = JsPrinter()


def _literal(v: float) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    v = float(v)
    if math.isnan(v):
        return "NaN"
    if math.isinf(v):
        return "Infinity" if v > 0 else "(-Infinity)"
    return repr(v)


def graph_js(graph: Graph, arg: str = "a") -> str:
    """The body of a JavaScript function of one array argument ``arg`` (the graph's inputs in
    declaration order) that returns an object of the graph's outputs by name."""
    order = {name: k for k, name in enumerate(graph.inputs)}

    def ref(a) -> str:
        return f"v{a.index}" if isinstance(a, Node) else _literal(a)

    lines = []
    for n in graph.live():
        if n.op == "input":
            expr = f"{arg}[{order[n.args[0]]}]"
        else:
            expr = JS.doprint(n.op, *map(ref, n.args))
        name = graph.names.get(n.index)
        lines.append(f"  const v{n.index} = {expr};" + (f"  // {js_comment(name)}" if name else ""))
    outs = ", ".join(f"{js_json(k)}: {ref(v)}" for k, v in graph.outputs.items())
    lines.append(f"  return {{{outs}}};")
    return "\n".join(lines)


def solve_graph(arm, tol: float = DEFAULT_TOL_MM, *, on_axis: bool = False) -> Graph:
    """:func:`solve_body` of ``arm`` (every branch, its joint limits, tolerance ``tol``)
    recorded with the arm's parameters as constants, plus each branch's whole pulses
    ``c:<branch>:<j>`` (eqs. 20-22; NaN where the branch has no solution). ``on_axis``: the
    waist angle on the base axis is one more input, ``theta1_on_axis`` [rad], last (only for
    an arm whose closed form takes it)."""
    g = Graph()
    m = TraceOps(g)
    p = tuple(g.input(k) for k in arm.inputs)
    opts = {"theta1_on_axis": g.input("theta1_on_axis")} if on_axis else {}
    out = solve_body(
        m, arm.closed_form, p, dict(arm.params), arm.branches, tol=tol, limits=arm.limits,
        **opts,
    )
    for b in arm.branches if arm.has_drive else ():  # no drive given: no pulses
        for j, ppr in enumerate(arm.params.pulses_per_rev):
            out[f"c:{b}:{j}"] = pulse_count(m, out[f"q:{b}:{j}"], float(ppr))
    g.outputs = out
    return g


def frames_graph(arm) -> Graph:
    """The origins of the arm's frames 0..n (:meth:`Arm.frames`) recorded from its D-H chain,
    outputs ``f<i>:<x|y|z>`` [mm], and the tool frame's rotation (the last frame's, as
    :func:`analysis.kinematics.forward.chain_points`), outputs ``R:<row><col>``, for joint
    inputs ``q0 .. q<n-1>`` [rad]; and every frame's rotation, ``R<i>:<row><col>``, i = 1..n."""
    g = Graph()
    m = TraceOps(g)
    q = [g.input(f"q{j}") for j in range(arm.n_joints)]
    Ts = chain_transforms(m, arm.table, q)
    origins = [(0.0, 0.0, 0.0), *((T[0][3], T[1][3], T[2][3]) for T in Ts)]
    g.outputs = {f"f{i}:{'xyz'[k]}": c for i, o in enumerate(origins) for k, c in enumerate(o)}
    g.outputs |= {f"R:{r}{c}": Ts[-1][r][c] for r in range(3) for c in range(3)}
    # every frame's rotation: the joint axes and frames drawn (analysis.app.arm3d_frames)
    g.outputs |= {f"R{i}:{r}{c}": T[r][c] for i, T in enumerate(Ts, start=1)
                  for r in range(3) for c in range(3)}  # fmt: skip
    return g


def pulses_graph(arm) -> Graph:
    """The whole pulses of joint values ``q0 .. q<n-1>`` [rad | mm] (eqs. 20-22,
    :func:`~analysis.kinematics.pulses.pulse_count`), outputs ``c<j>``."""
    g = Graph()
    m = TraceOps(g)
    q = [g.input(f"q{j}") for j in range(arm.n_joints)]
    g.outputs = {
        f"c{j}": pulse_count(m, q[j], float(ppr))
        for j, ppr in enumerate(arm.params.pulses_per_rev if arm.has_drive else ())
    }
    return g


def _module(arm) -> str:
    from analysis.app.explain import CHOOSE_THETA1, ROUNDS, SCAN, TEMPLATES, reach_sphere
    from analysis.app.explore_logic import FK_CAPTION, IK_CAPTION

    n_frames = sum(k.endswith(":x") for k in frames_graph(arm).outputs)  # origins f<i>:x
    center, reach = reach_sphere(arm)
    on_axis = "theta1_on_axis" in arm.closed_form.options
    meta = {
        "name": arm.name,
        "title": arm.description.title,
        "inputs": list(arm.inputs),
        "units": list(arm.input_units),
        "branches": list(arm.branches),
        "joints": [j.name for j in arm.description.joints],
        "limits": [None if lim is None else list(lim) for lim in arm.limits],
        "pulses_per_rev": list(arm.params.pulses_per_rev) if arm.has_drive else None,
        "status_text": {int(k): v for k, v in STATUS_TEXT.items()},
        "n_frames": n_frames,
        "joint_units": list(arm.joint_user_units),
        "center": list(center),
        "reach": reach,
        "on_axis": on_axis,
        "gimbal_lock_cos": GIMBAL_LOCK_COS,
        "explain": {"templates": TEMPLATES, "choose": CHOOSE_THETA1, "scan": SCAN,
                    "rounds": ROUNDS, "captions": {"ik": IK_CAPTION, "fk": FK_CAPTION}},
    }
    axis_solve = (
        "const raw_solve_axis = function (a) {\n"
        + graph_js(solve_graph(arm, on_axis=True))
        + "\n};\n"
        if on_axis
        else ""
    )
    solve_call = "raw_solve_axis(p.concat([theta1]))" if on_axis else "raw_solve(p)"
    return (
        "(function () {\n"
        "// "
        + js_comment(
            f"{arm.name}: printed by analysis.app.explore_js from the closed form "
            f"'{arm.cf.name}' and the D-H chain of data/arms; do not edit"
        )
        + "\n"
        "const raw_solve = function (a) {\n" + graph_js(solve_graph(arm)) + "\n};\n"
        "const raw_frames = function (a) {\n" + graph_js(frames_graph(arm)) + "\n};\n"
        "const raw_pulses = function (a) {\n" + graph_js(pulses_graph(arm)) + "\n};\n"
        + axis_solve
        + f"const arm = {js_json(meta)};\n"
        "arm.solve = function (p, theta1) {\n"
        "  const r = (theta1 === undefined || theta1 === null) ? raw_solve(p)\n"
        f"    : {solve_call};\n"
        "  const out = {status: r.status, outside: r.outside, branches: {}};\n"
        "  for (const b of arm.branches) {\n"
        "    const q = [], c = [];\n"
        "    for (let j = 0; j < arm.joints.length; j++) {\n"
        "      q.push(r['q:' + b + ':' + j]); c.push(r['c:' + b + ':' + j]);\n"
        "    }\n"
        "    out.branches[b] = {ok: r['ok:' + b], status: r['status:' + b], q: q,\n"
        "                       c: arm.pulses_per_rev === null ? null : c};"
        "\n"
        "  }\n"
        "  return out;\n"
        "};\n"
        "arm.pulses = function (q) {\n"
        "  if (arm.pulses_per_rev === null) return null;\n"
        "  const r = raw_pulses(q), c = [];\n"
        "  for (let j = 0; j < arm.joints.length; j++) c.push(r['c' + j]);\n"
        "  return c;\n"
        "};\n"
        "arm.tool_rotation = function (q) {\n"
        "  const r = raw_frames(q);\n"
        "  return [0, 1, 2].map((i) => [0, 1, 2].map((j) => r['R:' + i + j]));\n"
        "};\n"
        "arm.transforms = function (q) {\n"
        "  const r = raw_frames(q), out = [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]];\n"
        "  for (let i = 1; i < arm.n_frames; i++) out.push([0, 1, 2].map((j) => [\n"
        "    r['R' + i + ':' + j + '0'], r['R' + i + ':' + j + '1'], r['R' + i + ':' + j + '2'],\n"
        "    r['f' + i + ':' + 'xyz'[j]]]));\n"
        "  return out;\n"
        "};\n"
        "arm.frames = function (q) {\n"
        "  const r = raw_frames(q), pts = [];\n"
        "  for (let i = 0; i < arm.n_frames; i++) "
        "pts.push([r['f' + i + ':x'], r['f' + i + ':y'], r['f' + i + ':z']]);\n"
        "  return pts;\n"
        "};\n"
        "return arm;\n"
        "})()"
    )


def arm_module_js(arm) -> str:
    """A JavaScript expression whose value is the arm: ``name``, ``title``, ``inputs`` (with
    ``units``: "mm" or "rad"), ``branches``, ``joints``, ``limits`` [rad], ``pulses_per_rev``
    (null where the description gives no drive: ``c`` and ``pulses(q)`` are null too),
    ``status_text`` (code -> word), ``center`` and ``reach`` (the reach centre and largest
    radius, for the nearest reachable target), ``on_axis`` and ``explain`` (the sentences
    of :mod:`analysis.app.explain` and its search's constants), and three functions printed
    from the closed form:

    * ``solve(p, theta1)``: ``{status, outside, branches: {name: {ok, status, q: [rad],
      c: [pulses]}}}`` for one target ``p`` (the inputs' values, angles in rad), as
      :meth:`Arm.solve` (NaN angles and pulses where a branch has no solution; a branch's
      ``status`` its own, as solved alone); ``theta1`` the waist angle on the base axis
      [rad] (an arm that takes it), as ``theta1_on_axis``;
    * ``pulses(q)``: the whole pulses of joint values ``q`` (eqs. 20-22);
    * ``frames(q)``: the frame origins [[x, y, z], ...] [mm] for joint angles ``q`` [rad], as
      :meth:`Arm.frames`;
    * ``transforms(q)``: every frame's 3x4 block ``[R | o]`` (3 rows), the base frame first,
      as :func:`analysis.app.arm3d_frames.frame_transforms` (what the 3D view draws its joint
      axes and frames from);
    * ``tool_rotation(q)``: the tool frame's rotation (3 rows), as
      :func:`analysis.kinematics.pose.pose`'s ``rotation`` (its RPY angles are
      ``js/static_explorer.js``'s ``rpy``, as :func:`analysis.kinematics.rpy.rpy_from_matrix`,
      with ``gimbal_lock_cos``).

    Arms whose forward kinematics is not a D-H chain raise ``ValueError`` (the explorer then
    draws what the kernel sends)."""
    return _module(arm)
