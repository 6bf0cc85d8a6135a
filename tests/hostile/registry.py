"""The entry points a user can hand numbers to, as one registry (issue 19 item 6).

Every property in ``tests/hostile`` runs over every entry point registered here, for every
arm it takes: a new entry point (a command, a file format, an API) gets the whole harness by
adding one :func:`entry_point` below, not by writing tests.

An entry point is a function ``run(arm, slot, value) -> Outcome`` that puts ``value`` into
its ``slot``-th number (the others valid: a reachable target of the arm, its lengths, ...)
and runs the real code path: :func:`analysis.app.cli.main` in-process for the command line,
a CSV or TOML file on disk for the file formats, the Python API for the rest. ``form`` says
what ``value`` is: ``"text"`` (typed: a command-line argument, a CSV cell) or ``"api"`` (a
Python object). It returns how the code answered; it never swallows an exception other than
the documented ``ValueError``, so a traceback fails the property that met it.
"""

from __future__ import annotations

import contextlib
import csv
import io
import json
import math
import os
import tempfile
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

import numpy as np

ARMS = ("grabber", "palletizer", "gr1")
"""The arms with a closed form (the picker has no IK: issue 21 is adding it)."""


@dataclass
class Outcome:
    """How an entry point answered.

    ``refused``: the documented refusal (exit 2 with one line, a ValueError, an ``invalid``
    batch row); ``message``: that line. ``stdout``, ``stderr``, ``code``: what a command
    printed; ``result``: what an API returned; ``files``: the outputs a command wrote.
    """

    refused: bool
    message: str = ""
    stdout: str = ""
    stderr: str = ""
    code: int = 0
    result: object = None
    files: dict = field(default_factory=dict)
    warned: list = field(default_factory=list)


@dataclass(frozen=True)
class EntryPoint:
    name: str
    form: str  # "text" or "api"
    run: Callable[[str, int, object], Outcome]
    slots: Callable[[str], int]
    arms: tuple[str, ...] = ARMS
    kind: Callable[[str, int], str] = lambda arm, slot: "mm"
    """What the slot's number is: "mm" (a coordinate), "len" (a length of the arm), "deg",
    "jdeg" (a joint angle in degrees), "rad" (a joint or waist angle), "ang" (an orientation
    angle in radians), "tol", "ppr"."""
    cost: int = 1
    """Relative cost of one run (examples are divided by it to keep the suite's budget)."""
    optional: Callable[[str, int], bool] = lambda arm, slot: False
    """Whether None is the slot's documented "not given" (``theta1_on_axis=None``: refuse
    targets on the base axis), so that None there is not a hostile value."""


REGISTRY: dict[str, EntryPoint] = {}


def entry_point(name: str, form: str, slots, arms=ARMS, kind=None, cost=1, optional=None):
    """Register ``run`` as an entry point (see the module docstring)."""

    def register(run):
        REGISTRY[name] = EntryPoint(
            name, form, run, slots if callable(slots) else (lambda arm, n=slots: n), tuple(arms),
            kind or (lambda arm, slot: "mm"), cost, optional or (lambda arm, slot: False),
        )  # fmt: skip
        return run

    return register


# --------------------------------------------------------------------------------------------
# valid defaults
# --------------------------------------------------------------------------------------------
@cache
def arm_of(name: str):
    from analysis.kinematics.arm import load_arm

    return load_arm(name)


@cache
def default_target(name: str) -> tuple[float, ...]:
    """A reachable target (a pose for the GR-1) in user units, away from every boundary."""
    from analysis.kinematics import rpy

    arm = arm_of(name)
    q = {
        "grabber": [45.0, 10.0, -150.0],
        "palletizer": [10.0, -60.0, 120.0, 30.0],
        "gr1": [30.0, 20.0, -40.0, 10.0, 15.0],
    }[name]
    q = np.radians(q)
    if name == "gr1":
        pose = rpy.pose_from_transform(arm.table.fk(q))
        return (*pose[:3].tolist(), *np.degrees(pose[3:]).tolist())
    if name == "palletizer":  # eq. 12: a level gripper (theta4 = pi/2 - theta2 - theta3)
        q[3] = math.pi / 2 - q[1] - q[2]
    return tuple(arm.fk(q).tolist())


def input_kind(arm: str, slot: int) -> str:
    return "deg" if arm_of(arm).user_units[slot] == "deg" else "mm"


def _text(v) -> str:
    return v if isinstance(v, str) else repr(float(v))


@contextlib.contextmanager
def _captured():
    out, err = io.StringIO(), io.StringIO()
    with warnings.catch_warnings(record=True) as warned:
        warnings.simplefilter("always")
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            yield out, err, warned


def cli(*argv: str) -> Outcome:
    """``python -m analysis ARGV`` in this process."""
    from analysis.app.cli import main

    with _captured() as (out, err, warned):
        try:
            code = main(list(argv))
        except SystemExit as exc:  # argparse: usage errors (2), --help and --version (0)
            code = int(exc.code or 0)
    stdout, stderr = out.getvalue(), err.getvalue()
    lines = [line for line in stderr.splitlines() if line.strip()]
    refused = code != 0
    message = lines[-1] if refused and lines else ""
    if refused and "--json" in argv and stdout.strip():
        message = json.loads(stdout)["error"]
    return Outcome(refused, message, stdout, stderr, code, warned=list(warned))


# --------------------------------------------------------------------------------------------
# the command line
# --------------------------------------------------------------------------------------------
@entry_point("cli ik X Y Z", "text", lambda arm: len(arm_of(arm).inputs), kind=input_kind)
def _cli_ik(arm: str, slot: int, value) -> Outcome:
    values = [repr(v) for v in default_target(arm)]
    values[slot] = _text(value)
    return cli("ik", *values, "--arm", arm, "--json")


@entry_point("cli fk DEG", "text", lambda arm: arm_of(arm).n_joints, kind=lambda a, s: "jdeg")
def _cli_fk(arm: str, slot: int, value) -> Outcome:
    values = ["10"] * arm_of(arm).n_joints
    values[slot] = _text(value)
    return cli("fk", *values, "--arm", arm, "--json")


@entry_point("cli ik --tol", "text", 1, kind=lambda a, s: "tol")
def _cli_tol(arm: str, slot: int, value) -> Outcome:
    return cli("ik", *map(repr, default_target(arm)), "--arm", arm, "--tol", _text(value),
               "--json")  # fmt: skip


def on_axis_target(arm: str) -> list[str]:
    t = list(default_target(arm))
    t[0] = t[1] = 0.0
    if arm == "grabber":
        t[2] = 900.0
    elif arm == "palletizer":
        t[2] = -40.0  # the wrist 50 mm behind the axis, within reach
    else:  # the GR-1: straight up, the hand vertical
        t[:6] = [0.0, 0.0, 400.0, 0.0, 0.0, 180.0]
    return [repr(v) for v in t]


@entry_point("cli ik --theta1-on-axis", "text", 1, kind=lambda a, s: "deg")
def _cli_axis(arm: str, slot: int, value) -> Outcome:
    return cli("ik", *on_axis_target(arm), "--arm", arm, "--theta1-on-axis", _text(value),
               "--branch", "all", "--json")  # fmt: skip


@entry_point("cli stl --theta1-on-axis", "text", 1, arms=("grabber", "palletizer"),
             kind=lambda a, s: "deg", cost=10)  # fmt: skip
def _cli_stl_axis(arm: str, slot: int, value) -> Outcome:
    with tempfile.TemporaryDirectory() as tmp:
        prog = Path(tmp) / "p.awl"
        out = cli("stl", "--dialect", "s7-300", "--arm", arm, "-o", str(prog),
                  "--theta1-on-axis", _text(value), "--json")  # fmt: skip
        if prog.exists():
            out.files["program"] = prog.read_text()
    return out


# --------------------------------------------------------------------------------------------
# files: the batch CSV, a Table 3 file (--params), an arm description (TOML)
# --------------------------------------------------------------------------------------------
def batch(arm: str, rows: list[list[str]], header: list[str], *extra: str) -> Outcome:
    """``ik --input IN.csv --output OUT.csv`` on ``rows``; the output's rows in ``files``."""
    with tempfile.TemporaryDirectory() as tmp:
        src, dst = Path(tmp) / "in.csv", Path(tmp) / "out.csv"
        with src.open("w", newline="", encoding="utf-8") as fh:
            csv.writer(fh, lineterminator="\n").writerows([header, *rows])
        out = cli("ik", "--input", str(src), "--output", str(dst), "--arm", arm, "--json", *extra)
        if dst.exists():
            with dst.open(newline="", encoding="utf-8") as fh:
                out.files["rows"] = list(csv.reader(fh))
        out.files["left"] = sorted(os.listdir(tmp))
    return out


@entry_point("batch CSV cell", "text", lambda arm: len(arm_of(arm).inputs), kind=input_kind,
             cost=2)  # fmt: skip
def _batch_cell(arm: str, slot: int, value) -> Outcome:
    from analysis.app.batch import input_columns

    cells = [repr(v) for v in default_target(arm)]
    cells[slot] = _text(value)
    out = batch(arm, [cells], list(input_columns(arm_of(arm))))
    if out.code == 0:  # a bad row is a row: status invalid, the reason beside it
        header, *rows = out.files["rows"]
        status = {r[header.index("status")] for r in rows}
        if status == {"invalid"}:
            out.refused = True
            out.message = rows[0][header.index("reason")]
    return out


TABLE3 = None


@entry_point("--params Table 3 cell", "text", 4, arms=("grabber",),
             kind=lambda a, s: ("len", "len", "len", "ppr")[s], cost=2)  # fmt: skip
def _table3_cell(arm: str, slot: int, value) -> Outcome:
    from analysis.paths import data_dir

    with (data_dir() / "table3.csv").open(newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    col, row = [("d_mm", 1), ("a_mm", 2), ("a_mm", 3), ("pulses_per_rev", 2)][slot]
    rows[row][rows[0].index(col)] = _text(value)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "t3.csv"
        with path.open("w", newline="", encoding="utf-8") as fh:
            csv.writer(fh).writerows(rows)
        return cli("ik", *map(repr, default_target(arm)), "--params", str(path), "--json")


def toml_literal(value) -> str:
    """``value`` as a TOML literal (text is taken as written: TOML's own syntax)."""
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_literal(v) for v in value) + "]"
    return repr(value)


@entry_point("arm description TOML value", "toml", 3,
             kind=lambda a, s: ("len", "ppr", "deg")[s], cost=3)  # fmt: skip
def _toml_value(arm: str, slot: int, value) -> Outcome:
    """A length, a pulses_per_rev or a joint limit of ``data/arms/<arm>.toml``, rewritten."""
    with _toml_folder(arm, slot, value) as path, _captured() as (_out, _err, warned):
        try:
            from analysis.kinematics.arm import load_arm

            a = load_arm(str(path))
            result = a.solve(np.array(a.from_user(default_target(arm))))
        except ValueError as exc:
            return Outcome(True, str(exc), warned=list(warned))
    return Outcome(False, result=result, warned=list(warned))


@contextlib.contextmanager
def _toml_folder(arm: str, slot: int, value):
    """``data/arms/<arm>.toml`` with its ``slot``-th number (a length, a pulses_per_rev, a
    joint limit) rewritten as ``value``, in a folder with the tables it may read."""
    import re

    from analysis.paths import data_dir

    text = (data_dir() / "arms" / f"{arm}.toml").read_text(encoding="utf-8")
    lit = toml_literal(value)
    if slot == 0:  # the first numeric parameter value
        text, n = re.subn(r"(?m)^(\w+ = \{ *value = )[-0-9.e+]+", rf"\g<1>{lit}", text, count=1)
        if n == 0:  # grabber: a table reference; give it a value instead
            text = re.sub(r"(?m)^(L1 = )\{[^\n]*\}", rf"\g<1>{{ value = {lit} }}", text, count=1)
    elif slot == 1:
        text = re.sub(r"(?m)^pulses_per_rev = .*$", f"pulses_per_rev = {lit}", text, count=1)
        text = re.sub(r"pulses_per_rev = \{ *value = [^,}]+", f"pulses_per_rev = {{ value = {lit}",
                      text, count=1)  # fmt: skip
    else:
        text = re.sub(r"(?m)^limits_deg = \[[^\]]*\]", f"limits_deg = [{lit}, 180]", text, count=1)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "arms" / f"{arm}.toml"
        path.parent.mkdir()
        path.write_text(text, encoding="utf-8")
        for csv_file in data_dir().glob("*.csv"):  # the tables a description may read
            (Path(tmp) / csv_file.name).write_bytes(csv_file.read_bytes())
        yield path


@entry_point("cli urdf --arm TOML value", "toml", 3,
             kind=lambda a, s: ("len", "ppr", "deg")[s], cost=4)  # fmt: skip
def _cli_urdf(arm: str, slot: int, value) -> Outcome:
    """``urdf --arm FILE`` on a description with one number rewritten (as typed in the TOML)."""
    with _toml_folder(arm, slot, value) as path:
        urdf = path.parent / "arm.urdf"
        out = cli("urdf", "--arm", str(path), "-o", str(urdf), "--json")
        if urdf.exists():
            out.files["urdf"] = urdf.read_text(encoding="utf-8")
    return out


@cache
def s7200_program(arm: str) -> tuple[str, dict]:
    """The arm's generated S7-200 program (a file kept for the session) and its MAP.json."""
    from analysis.plc.generate import generate

    text, mjson = generate(arm_of(arm), "s7-200")
    path = Path(tempfile.mkdtemp(prefix="hostile-stl-run-")) / f"{arm}.awl"
    path.write_text(text, encoding="utf-8")
    return str(path), json.loads(mjson)


def _stl_run_kind(arm: str, slot: int) -> str:
    """A coordinate in mm, or an orientation angle the program takes in radians (any)."""
    return "ang" if arm_of(arm).input_units[slot] == "rad" else "mm"


@entry_point("cli stl-run --set", "text", lambda arm: len(arm_of(arm).inputs),
             kind=_stl_run_kind, cost=4)  # fmt: skip
def _cli_stl_run(arm: str, slot: int, value) -> Outcome:
    """``stl-run`` of the arm's S7-200 program, its inputs ``--set`` to a reachable target
    (radians for angles, as the program takes them) and the ``slot``-th to ``value``."""
    path, doc = s7200_program(arm)
    target = list(arm_of(arm).from_user(default_target(arm)))
    sets = [f"{addr}={float(v)!r}" for addr, v in zip(doc["inputs"].values(), target,
                                                       strict=True)]  # fmt: skip
    addr = list(doc["inputs"].values())[slot]
    sets[slot] = f"{addr}={_text(value)}"
    reads = [f"{a}:DINT" for k, a in doc["outputs"].items() if k.startswith("c")]
    argv = [a for s_ in sets for a in ("--set", s_)] + [a for r in reads for a in ("--read", r)]
    return cli("stl-run", path, "--dialect", "s7-200", *argv, "--json")


# --------------------------------------------------------------------------------------------
# the Python API
# --------------------------------------------------------------------------------------------
def api(fn: Callable[[], object]) -> Outcome:
    with _captured() as (_out, _err, warned):
        try:
            result = fn()
        except ValueError as exc:
            return Outcome(True, str(exc), warned=list(warned))
    return Outcome(False, result=result, warned=list(warned))


def _api_target(arm: str, slot: int, value) -> list:
    a = arm_of(arm)
    p = list(a.from_user(default_target(arm)).tolist())
    p[slot] = value
    return p


def _api_kind(arm: str, slot: int) -> str:
    """An orientation angle in radians ("ang": any finite value) or a coordinate."""
    return "ang" if arm_of(arm).input_units[slot] == "rad" else "mm"


for _backend in ("numpy", "compiled"):

    @entry_point(f"Arm.solve ({_backend})", "api", lambda arm: len(arm_of(arm).inputs),
                 kind=_api_kind)  # fmt: skip
    def _solve(arm: str, slot: int, value, backend=_backend) -> Outcome:
        return api(lambda: arm_of(arm).solve([_api_target(arm, slot, value)], backend=backend))


@entry_point("Arm.ik", "api", lambda arm: len(arm_of(arm).inputs), kind=_api_kind)
def _ik(arm: str, slot: int, value) -> Outcome:
    from analysis.kinematics.solution import OrientationError

    def call():
        try:
            return arm_of(arm).ik(_api_target(arm, slot, value))
        except OrientationError as exc:  # a refusal with its reason: still a ValueError
            raise ValueError(str(exc)) from None

    return api(call)


@entry_point("Arm.fk", "api", lambda arm: arm_of(arm).n_joints, kind=lambda a, s: "rad")
def _fk(arm: str, slot: int, value) -> Outcome:
    q = [0.1] * arm_of(arm).n_joints
    q[slot] = value
    return api(lambda: arm_of(arm).fk(q))


@entry_point("Arm.solve options", "api", 2, kind=lambda a, s: ("rad", "tol")[s],
             optional=lambda a, s: s == 0)  # fmt: skip
def _options(arm: str, slot: int, value) -> Outcome:
    key = ("theta1_on_axis", "tol")[slot]
    target = [float(v) for v in arm_of(arm).from_user([float(t) for t in on_axis_target(arm)])]
    return api(lambda: arm_of(arm).solve([target], "all", **{key: value}))


@entry_point("Params.with_", "api", lambda arm: len(arm_of(arm).params) + 1,
             kind=lambda a, s: "ppr" if s == len(arm_of(a).params) else "len")  # fmt: skip
def _params(arm: str, slot: int, value) -> Outcome:

    a = arm_of(arm)
    names = list(a.params)
    if slot < len(names):
        change = {names[slot]: value}
    else:
        change = {"pulses_per_rev": (value, *a.params.pulses_per_rev[1:])}

    def call():
        b = a.with_(**change)
        return b.solve([a.from_user(default_target(arm))], "all")

    return api(call)


def slots(ep: EntryPoint, arm: str) -> range:
    return range(ep.slots(arm))


def cases(form: str | None = None) -> list[tuple[str, str]]:
    """(entry point, arm) pairs, for ``pytest.mark.parametrize``."""
    return [
        (name, arm)
        for name, ep in REGISTRY.items()
        if form is None or ep.form == form
        for arm in ep.arms
    ]
