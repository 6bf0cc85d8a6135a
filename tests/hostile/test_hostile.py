"""The hostile-input harness (issue 19): one property per class, over every entry point of
:mod:`hostile.registry` (tests/hostile/registry.py) and every arm it takes.

Classes (each closed at its source, :mod:`analysis.validate` and the boundaries that call it):

1. hostile text (NaN, inf, 1_000, non-ASCII digits, decimal commas, hex, empty, overflow) is
   refused with one line naming it, at every text entry point;
2. hostile Python values (complex, masked, boolean, None, text, 10**400, NaN, inf) raise a
   one-line ValueError at every API entry point, never TypeError or OverflowError;
3. the command line and a CSV cell read a text alike (one rule);
4. values inside the supported range give finite results only (no NaN, no inf, valid JSON,
   no warning, no ``inf`` in a generated program), or a one-line refusal;
5. values beyond the supported range are refused naming the limit;
6. angles in degrees are reduced exactly before use;
7. at the reach shells, the base axis and the joint stops numpy and the compiled kernel agree
   on every status, and a solution reaches its target within the tolerance;
8. theta1_on_axis wraps as documented;
9. batch I/O echoes every cell and header as given, clashes renamed, never merged.

Example counts are the ``ci`` profile's (tests/conftest.py), scaled per entry point by its
cost to keep the harness within the suite's budget; ``HYPOTHESIS_PROFILE=thorough`` draws
many more.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from analysis import validate
from hostile import strategies as hs
from hostile.registry import ARMS, REGISTRY, arm_of, batch, cases, cli, default_target

examples = hs.examples


def one_line(text: str) -> bool:
    return bool(text.strip()) and "\n" not in text.strip() and "Traceback" not in text


def strict_json(text: str):
    """Parse JSON refusing NaN, Infinity and -Infinity (Python's json accepts them)."""

    def refuse(token):
        raise AssertionError(f"invalid JSON token {token} in {text[:200]!r}")

    return json.loads(text, parse_constant=refuse)


def all_finite(obj) -> bool:
    if isinstance(obj, float):
        return math.isfinite(obj)
    if isinstance(obj, dict):
        return all(all_finite(v) for v in obj.values())
    if isinstance(obj, (list, tuple)):
        return all(all_finite(v) for v in obj)
    if isinstance(obj, np.ndarray) and obj.dtype.kind == "f":
        return True  # NaN marks "no solution" in IKSolutions.theta; checked where it matters
    return True


def check_outcome(out, value=None) -> None:
    """What every answer must look like, whatever the input."""
    assert not out.warned, [str(w.message) for w in out.warned]
    if out.stdout.strip() and "--json" not in str(out):
        pass
    if out.stdout.strip().startswith(("{", "[")):
        strict_json(out.stdout)
    if out.refused:
        assert one_line(out.message), out
        assert "Traceback" not in out.stderr, out.stderr
    program = out.files.get("program")
    if program is not None:  # no inf or nan operand (comments and titles may name NaN)
        code = re.sub(r"(?m)//.*$|^\s*TITLE\s*=.*$", "", program)
        assert not re.search(r"\b(inf|nan)\b", code, re.IGNORECASE), "inf in the program"


def _mentions(message: str, text: str) -> bool:
    shown = repr(text)[:30]
    return (
        shown[:-1] in message
        or (not text.strip() and "empty" in message)
        or f"unrecognized arguments: {text}" in message  # "--1": an option, named as given
    )


# --- 1. hostile text ---------------------------------------------------------------------------
@pytest.mark.parametrize(("entry", "arm"), cases("text"))
def test_hostile_text_is_refused_in_one_line_naming_it(entry, arm):
    ep = REGISTRY[entry]

    @examples(10, ep.cost)
    @given(slot=st.integers(0, ep.slots(arm) - 1), text=hs.hostile_texts())
    def prop(slot, text):
        out = ep.run(arm, slot, text)
        check_outcome(out)
        assert out.refused, f"{entry} accepted {text!r}: {out}"
        assert _mentions(out.message, text), (text, out.message)
        assert out.code in (0, 2)  # a batch row is marked, a command exits 2

    prop()


# --- 2. hostile Python values ------------------------------------------------------------------
@pytest.mark.parametrize(("entry", "arm"), cases("api"))
def test_hostile_api_values_raise_one_line_value_errors(entry, arm):
    ep = REGISTRY[entry]

    @examples(12, ep.cost)
    @given(slot=st.integers(0, ep.slots(arm) - 1), value=hs.hostile_api_values())
    def prop(slot, value):
        out = ep.run(arm, slot, value)  # a TypeError or OverflowError fails here
        check_outcome(out)
        if value is None and ep.optional(arm, slot):
            return  # None is that option's "not given" (its default)
        assert out.refused, f"{entry} accepted {value!r}: {out.result}"

    prop()


# --- 3. the command line and a CSV cell read alike --------------------------------------------
@examples(40)
@given(text=hs.number_texts())
def test_command_line_and_csv_read_a_number_alike(text):
    """The same text as the x coordinate on the command line and in a CSV cell: accepted by
    both or refused by both, as analysis.validate.parse_real says; accepted, the same answer."""
    try:
        v = validate.parse_real(text)
        expected = abs(v) <= validate.MAX_COORD_MM
    except validate.InvalidValue:
        expected = False
    target = [repr(t) for t in default_target("grabber")]
    line = cli("ik", text, *target[1:], "--json")
    read_cli = not ("argument X Y Z:" in line.message or "largest coordinate" in line.message)
    rows = batch("grabber", [[text, *target[1:]]], ["x_mm", "y_mm", "z_mm"])
    header, row = rows.files["rows"][0], rows.files["rows"][1]
    read_csv = row[header.index("status")] != "invalid"
    assert read_cli == read_csv == expected, (text, line.message, row)
    if read_cli and line.code == 0:
        theta = strict_json(line.stdout)["solutions"][0]["theta_deg"]
        assert [float(row[header.index(f"theta{j}_deg")]) for j in (1, 2, 3)] == theta


# --- 4. in range: finite results only ---------------------------------------------------------
def in_range(kind: str):
    limit = {"mm": validate.MAX_COORD_MM, "len": validate.MAX_LENGTH_MM,
             "rad": validate.MAX_ANGLE_RAD, "tol": validate.MAX_TOL_MM, "ang": 1e308,
             "jdeg": validate.MAX_JOINT_DEG,
             "deg": 1e308, "ppr": validate.MAX_PULSES_PER_REV}[kind]  # fmt: skip
    lo = 0.0 if kind in ("tol", "ppr") else -limit
    edge = st.sampled_from([lo, limit, 0.0, 5e-324, -5e-324, limit * (1 - 1e-16)])
    values = st.floats(lo, limit, allow_nan=False) | edge
    if kind == "ppr":
        return st.integers(1, validate.MAX_PULSES_PER_REV)
    if kind == "len":
        return values.filter(lambda v: v == 0 or abs(v) >= validate.MIN_LENGTH_MM)
    return values


@pytest.mark.parametrize(("entry", "arm"), cases())
def test_values_in_range_give_finite_results_or_one_line(entry, arm):
    ep = REGISTRY[entry]

    @examples(10, ep.cost)
    @given(data=st.data())
    def prop(data):
        slot = data.draw(st.integers(0, ep.slots(arm) - 1))
        value = data.draw(in_range(ep.kind(arm, slot)))
        arg = value if ep.form == "api" else repr(value)
        out = ep.run(arm, slot, arg)
        check_outcome(out)
        if not out.refused and out.stdout.strip().startswith("{"):
            assert all_finite(strict_json(out.stdout))
        sol = out.result
        if hasattr(sol, "ok"):  # IKSolutions: angles finite exactly where a branch solved
            assert np.isfinite(sol.theta[sol.ok]).all() and np.isnan(sol.theta[~sol.ok]).all()
            assert np.isfinite(sol.outside_mm).all()

    prop()


# --- 5. beyond the range: refused, naming the limit -------------------------------------------
LIMIT_TEXT = {"mm": ("3.403e+38",), "len": ("1e+06",), "rad": ("62.83", "3600 deg"), "tol": ("1",),
              "ppr": ("1e+07", "10,000,000"), "jdeg": ("3600 deg",)}  # fmt: skip


@pytest.mark.parametrize(("entry", "arm"), cases())
def test_values_beyond_the_range_are_refused_naming_the_limit(entry, arm):
    ep = REGISTRY[entry]
    kinds = [k for k in map(lambda s: ep.kind(arm, s), range(ep.slots(arm)))
             if k not in ("deg", "ang")]  # fmt: skip
    if not kinds:
        pytest.skip(f"{entry}: angles in degrees have no range (reduced exactly)")

    @examples(6, ep.cost)
    @given(data=st.data())
    def prop(data):
        slot = data.draw(st.sampled_from(
            [s for s in range(ep.slots(arm)) if ep.kind(arm, s) not in ("deg", "ang")]))
        kind = ep.kind(arm, slot)
        value = data.draw(hs.beyond(kind))
        if kind in ("tol", "ppr"):  # no negative side: below 0 (1) is refused as such
            value = abs(value)
        out = ep.run(arm, slot, value if ep.form == "api" else repr(value))
        check_outcome(out)
        assert out.refused, (entry, value, out)
        assert any(t in out.message for t in LIMIT_TEXT[kind]), out.message

    prop()


# --- 6. degrees reduced exactly ----------------------------------------------------------------
@examples(30)
@given(turns=st.integers(-(10**9), 10**9), x=st.floats(-1e308, 1e308))
def test_degrees_are_reduced_exactly(turns, x):
    """reduce_deg(x) differs from x by an exact multiple of 360 and lies in (-180, 180]; on
    the command line a pose angle k turns away gives the same solution as the angle itself."""
    from fractions import Fraction

    r = validate.reduce_deg(x)
    assert -180 < r <= 180
    assert (Fraction(x) - Fraction(r)) % 360 == 0
    pose = [repr(v) for v in default_target("gr1")]
    alpha = float(pose[3]) + 360.0 * turns  # rounded once; its reduction is exact
    shifted = cli("ik", *pose[:3], repr(alpha), *pose[4:], "--arm", "gr1", "--json")
    plain = cli("ik", *pose[:3], repr(validate.reduce_deg(alpha)), *pose[4:], "--arm", "gr1",
                "--json")  # fmt: skip
    assert (shifted.code, shifted.stdout.split('"reachable"')[-1]) == (
        plain.code, plain.stdout.split('"reachable"')[-1])  # fmt: skip


def test_the_issue_reproduction_reduces_alpha_to_16_degrees():
    """ik 433.351 250.195 -12.676 1.0000000000031762e+17 9.656 177.387 --arm gr1: that alpha
    is 16 deg (exactly), a pose the arm cannot take; it used to be solved as about 14.78 deg."""
    assert validate.reduce_deg(1.0000000000031762e17) == 16.0
    big = cli("ik", "433.351", "250.195", "-12.676", "1.0000000000031762e+17", "9.656", "177.387",
              "--arm", "gr1", "--json")  # fmt: skip
    at16 = cli("ik", "433.351", "250.195", "-12.676", "16", "9.656", "177.387", "--arm", "gr1",
               "--json")  # fmt: skip
    assert big.code == at16.code == 2
    assert "out of the arm plane" in big.message and "RPY (16, 9.656" in big.message


# --- 7. the backends agree at every edge --------------------------------------------------------
EDGE_ARMS = (*ARMS, "picker", "derived:grabber", "derived:palletizer", "derived:gr1")
"""Every seed arm, on its hand-written closed form and (``derived:``) on the one derived from its
D-H rows; random user arms of each family: test_random_arms_honour_the_tolerance_at_the_edges."""
EDGE_TOL = 1e-6


def edge_arm(name: str):
    if name.startswith("derived:"):
        from analysis.kinematics.arm import derived_arm

        return derived_arm(name.split(":", 1)[1])
    return arm_of(name)


def edge_targets(arm, rng: np.random.Generator, deltas) -> np.ndarray:
    """Targets at the reach boundaries, the joint stops and the base axis of any arm, displaced
    by ``deltas`` [mm; 1e-3 rad per mm at a stop]: on, just inside, just outside, at the
    tolerance.

    From valid configurations (:meth:`Arm.sample_q`): each target is moved (the orientation of
    a pose kept) along the gradient of ``outside_mm``, the signed distance to the nearer
    boundary, to ``delta`` outside it (two Newton steps: exact on a reach sphere); one joint of
    each configuration is put on a stop (plus ``delta`` 1e-3 rad) and its target taken; and the
    target put at ``delta`` from the base axis."""
    n = len(deltas)
    q = arm.sample_q(rng, n)
    p0 = arm.target(q)
    shells = p0.copy()
    h = 1e-4
    mm = position_columns(arm)
    for _ in range(2):
        g = np.zeros((n, len(mm)))
        for k, col in enumerate(mm):
            e = np.zeros(p0.shape[-1])
            e[col] = h
            g[:, k] = (arm.solve(shells + e, limits=False).outside_mm
                       - arm.solve(shells - e, limits=False).outside_mm) / (2 * h)  # fmt: skip
        g /= np.maximum(np.linalg.norm(g, axis=-1, keepdims=True), 1e-300)
        o = arm.solve(shells, limits=False).outside_mm
        shells[:, mm] += (deltas - o)[:, None] * g
    stops = q.copy()
    lim = np.array([lim if lim is not None else (-math.pi, math.pi) for lim in arm.limits])
    j = rng.integers(0, arm.n_joints, n)
    stops[np.arange(n), j] = np.where(rng.random(n) < 0.5, lim[j, 0], lim[j, 1]) + deltas * 1e-3
    stops = stops[arm.valid_q(stops)]  # (the picker's link 5 closes or not)
    axis = p0.copy()
    axis[:, 0], axis[:, 1] = deltas, 0.0
    return np.concatenate([shells, arm.target(stops), axis])


def position_columns(arm) -> list[int]:
    """The target's coordinates [mm] (a planar arm has two, a pose or a turn adds angles)."""
    return [i for i, u in enumerate(arm.input_units) if u == "mm"]


def projection_mm(arm) -> float:
    """What a derived 5R arm may miss by besides the tolerance, as documented
    (analysis.kinematics.derive: a roll axis up to ``ORIENTATION_TOL_RAD`` out of the reachable
    set is projected onto it, turning the tool offset with it): tool offset times the sine of
    that angle. 0 for every other arm (the GR-1's hand-written form keeps the tool point)."""
    orient = getattr(arm.closed_form, "ORIENTATION_TOL_RAD", None)
    if not arm.closed_form.name.startswith("derived:5R") or orient is None:
        return 0.0
    return arm.geometry["tool_offset"] * math.sin(orient)


def check_edges(arm, p, tol=EDGE_TOL, compiled=True) -> dict:
    """Both backends' statuses agree (``compiled``), and every ok solution reaches its target
    within ``tol`` (plus :func:`projection_mm`; FK computed apart: :meth:`Arm.target`, the
    position part). Returns the measured figures: targets, ok solutions, the largest position
    error."""
    bound = tol + projection_mm(arm)
    sols = [arm.solve(p, tol=tol)]
    if compiled:
        sols.append(arm.solve(p, tol=tol, backend="compiled"))
        a, b = sols
        bad = np.flatnonzero((a.status != b.status) | (a.ok != b.ok).any(axis=-1))
        assert not bad.size, (arm.name, p[bad[0]].tolist(), a.status[bad[0]], b.status[bad[0]],
                              a.ok[bad[0]], b.ok[bad[0]])  # fmt: skip
    worst, solutions = 0.0, 0
    for sol in sols:
        ok = sol.ok
        assert (ok.any(axis=-1) == (sol.status == 0)).all()
        if not ok.any():
            continue
        idx, k = np.nonzero(ok)
        mm = position_columns(arm)
        reached = arm.target(sol.theta[idx, k])[:, mm]
        err = np.linalg.norm(reached - p[idx][:, mm], axis=-1)
        solutions += len(err)
        i = int(err.argmax())
        where = (p[idx[i]].tolist(), sol.branches[k[i]])
        assert err[i] <= bound, (arm.name, f"{err[i]:.12g} mm", where)
        worst = max(worst, float(err[i]))
    return {"targets": len(p), "solutions": solutions, "max_error_mm": worst}


EDGE_STEPS = [0.0, EDGE_TOL, -EDGE_TOL, EDGE_TOL * (1 + 1e-9), EDGE_TOL * (1 - 1e-9), 1e-12,
              -1e-12, 1e-3, -1e-3, 5e-7, 2 * EDGE_TOL, EDGE_TOL * (1 - 1e-7)]  # fmt: skip


@pytest.mark.slow  # class 7 draws thousands of edge targets per arm: make test, not test-fast
@pytest.mark.parametrize("arm_name", EDGE_ARMS)
def test_backends_agree_and_the_tolerance_holds_at_the_edges(arm_name):
    """Class 7 for every seed arm and its derived twin: numpy and compiled agree on every status
    and branch, and no ok solution misses its target by more than the tolerance (the
    tolerance is the true one: :data:`analysis.kinematics.solution.DEFAULT_TOL_MM`)."""
    arm = edge_arm(arm_name)

    @examples(15)
    @given(seed=st.integers(0, 2**32 - 1),
           deltas=st.lists(st.sampled_from(EDGE_STEPS), min_size=32, max_size=32))  # fmt: skip
    def prop(seed, deltas):
        check_edges(arm, edge_targets(arm, np.random.default_rng(seed), np.array(deltas)))

    prop()


@pytest.mark.slow  # class 7 draws thousands of edge targets per arm: make test, not test-fast
@pytest.mark.parametrize("family", ["3R", "4R-kept", "5R"])
def test_random_arms_honour_the_tolerance_at_the_edges(family, tmp_path):
    """Class 7 for users' arms (analysis.kinematics.derive.samples, standard and modified
    D-H): no ok solution misses its target by more than the tolerance (numpy; the compiled
    kernel of a new arm takes 10-30 s to build: the seed arms' twins above compare it)."""
    from analysis.kinematics.arm import load_arm
    from analysis.kinematics.derive.samples import random_arm

    @examples(6)
    @given(convention=st.sampled_from(("standard", "modified")), seed=st.integers(0, 2**32 - 1),
           deltas=st.lists(st.sampled_from(EDGE_STEPS), min_size=64, max_size=64))  # fmt: skip
    def prop(convention, seed, deltas):
        rng = np.random.default_rng(seed)
        path = tmp_path / f"arm_{seed}.toml"
        path.write_text(random_arm(rng, family, convention, "user_arm"), encoding="utf-8")
        arm = load_arm(str(path))
        check_edges(arm, edge_targets(arm, rng, np.array(deltas)), compiled=False)

    prop()


@pytest.mark.slow  # class 7 draws thousands of edge targets per arm: make test, not test-fast
@pytest.mark.parametrize("arm_name", ["gr1", "derived:gr1"])
def test_the_wrist_near_the_shoulder_is_placed_within_the_tolerance(arm_name):
    """The GR-1 (a2 = a3) with its wrist folded to 1e-6 .. 1e-3 mm from the shoulder, solved
    without joint limits (its theta3 stop keeps the fold out otherwise): theta3 from
    1 -/+ c3 in factored form (``precise``); from acos(c3) the wrist at 2e-6 mm from the
    shoulder was placed on it, 2.0e-6 mm off against the 1e-6 mm tolerance."""
    from analysis.kinematics import rpy

    arm = edge_arm(arm_name)
    a = arm.params["a2"]

    @examples(20)
    @given(seed=st.integers(0, 2**32 - 1), d=st.floats(1e-6, 1e-3))
    def prop(seed, d):
        q = np.random.default_rng(seed).uniform(-1, 1, (64, 5))
        q[:, 2] = math.pi - 2 * math.asin(d / (2 * a))
        p = rpy.pose_from_transform(arm.table.fk(q))
        for backend in ("numpy", "compiled"):
            sol = arm.solve(p, limits=False, backend=backend)
            idx, k = np.nonzero(sol.ok)
            err = np.linalg.norm(arm.table.fk(sol.theta[idx, k])[:, :3, 3] - p[idx, :3], axis=-1)
            assert err.max(initial=0.0) <= EDGE_TOL, (backend, d, err.max())

    prop()


def test_the_issue_reproductions_at_the_edges():
    """GR-1 theta3 = -135 deg exactly (the stop): both backends agree; the palletizer's
    (50.0000025, 0, -70) is solved within the 1e-6 mm tolerance."""
    from analysis.kinematics import rpy

    gr1 = arm_of("gr1")
    rng = np.random.default_rng(7)
    q = rng.uniform(-1, 1, (200, 5))
    q[:, 2] = math.radians(-135.0)
    p = rpy.pose_from_transform(gr1.table.fk(q))
    a, b = gr1.solve(p), gr1.solve(p, backend="compiled")
    np.testing.assert_array_equal(a.ok, b.ok)
    np.testing.assert_array_equal(a.status, b.status)
    pal = arm_of("palletizer")
    target = np.array([50.0000025, 0.0, -70.0])
    sol = pal.solve(target)
    for k in np.flatnonzero(sol.ok):
        assert np.linalg.norm(pal.fk(sol.theta[k]) - target) <= 1e-6


# --- 8. theta1_on_axis wraps ------------------------------------------------------------------
@examples(30)
@given(deg=st.floats(-1e308, 1e308, allow_nan=False))
def test_theta1_on_axis_wraps_to_the_half_open_turn(deg):
    """`ik 0 0 800 --theta1-on-axis DEG`: theta1 is DEG reduced exactly to (-180, 180]; the
    count within half a turn (the issue: 3600 gave theta1 = 3240 deg, c1 = 36000)."""
    out = cli("ik", "0", "0", "800", "--theta1-on-axis", repr(deg), "--json")
    assert out.code == 0, out
    sol = strict_json(out.stdout)["solutions"][0]
    assert sol["theta_deg"][0] == pytest.approx(validate.reduce_deg(deg), abs=1e-9)
    assert -180 < sol["theta_deg"][0] <= 180 and abs(sol["pulses"][0]) <= 2000


def test_theta1_on_axis_3600_is_0():
    out = cli("ik", "0", "0", "800", "--theta1-on-axis", "3600", "--json")
    assert strict_json(out.stdout)["solutions"][0]["pulses"][0] == 0


# --- 9. batch I/O loses nothing --------------------------------------------------------------
cell_text = st.text(st.characters(exclude_categories=("Cs",), exclude_characters="\r\x00"),
                    max_size=30)  # fmt: skip


@examples(15)
@given(
    extra=st.lists(st.tuples(st.sampled_from(["status", "input_status", "input_status_2",
                                              "branch", "reason", "note", " c1", "theta1_deg",
                                              "c1"]), cell_text),
                   min_size=0, max_size=4, unique_by=lambda t: t[0].strip()),
    digits=st.sampled_from(["100.12345678901234", "1e2", "+100", "100.000000000000000001",
                            " 100 ", "0100"]),
    branch=st.sampled_from(["front-up", "all"]),
)
def test_batch_echoes_every_cell_as_given_and_never_merges_columns(extra, digits, branch):
    header = ["x_mm", "y_mm", "z_mm", *(name for name, _ in extra)]
    rows = [[digits, "100", "600", *(text for _, text in extra)]]
    out = batch("grabber", rows, header, "--branch", branch)
    assert out.code == 0, out
    head, *body = out.files["rows"]
    assert len(set(h.strip() for h in head)) == len(head), head  # no two columns one name
    assert len(body) == (4 if branch == "all" else 1)
    for row in body:
        assert row[: len(header)] == rows[0]  # byte for byte, under their own (or new) names
    for name, new in zip(header, head, strict=False):
        assert new == name or new.startswith(f"input_{name.strip()}")
    assert out.files["left"] == ["in.csv", "out.csv"]  # no temporary file left
