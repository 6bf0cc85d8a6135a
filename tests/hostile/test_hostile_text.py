"""Hostile text and structure (issue 27 items 4 and 7): a description field drawn from
hostile strings (:mod:`hostile.texts`) through every generator that embeds it.

For every field and generator of the registry: the description is refused in one line, or
every output parses as its kind (the program on its engine or reader, XML by a parser and
the PLCopen schema, JSON strictly, HTML by a parser, what a command prints without a control
character) and says, outside its comments, what the clean arm's says. The issue's own
attacks are reproduced by name and must fail to reproduce: the OB100 that a line break in the
name put into the S7-300 program (awlsim read back c1 = 99999 for an unreachable target), a
``*)`` that ends an ST comment (the ST engine runs the program), ``</script>`` in a title.

Escaping is by construction: each printer's comment, title and identifier go through
:mod:`analysis.escape`; :func:`test_every_printer_escapes_its_texts` feeds the printers an
IR whose every text (arm, titles, notes, network titles, comments) is hostile, whatever the
description schema lets through.
"""

from __future__ import annotations

import dataclasses
import json
import re
import tempfile
import xml.etree.ElementTree as ET
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from hypothesis import example, given

from analysis.kinematics.arm import load_arm
from hostile.strategies import examples
from hostile.texts import (
    FIELDS,
    GENERATORS,
    HOSTILE,
    check_identifiers,
    check_script,
    description,
    hostile_strings,
    plc_code,
    strict_json,
)


@cache
def clean_outputs(gen: str) -> dict:
    folder = Path(tempfile.mkdtemp(prefix="hostile-text-clean-"))
    return GENERATORS[gen].run(description(folder, None))


def run_hostile(gen: str, field: str, value: str) -> None:
    """The property for one string: refused in one line, or every output safe."""
    g = GENERATORS[gen]
    clean = clean_outputs(gen)  # the clean arm goes through (else nothing is compared)
    with tempfile.TemporaryDirectory(prefix="hostile-text-") as tmp:
        path = description(Path(tmp), field, value)
        try:
            out = g.run(path)
        except ValueError as exc:  # only the description's reader may refuse it: one line
            message = str(exc)
            assert message.strip() and "\n" not in message.strip(), message
            assert "Traceback" not in message
            with pytest.raises(ValueError):  # a generator never refuses what loads
                load_arm(str(path))
            return
    g.check(out, clean, value, field)


FAST = [name for name, g in GENERATORS.items() if not g.slow]
SLOW = [name for name, g in GENERATORS.items() if g.slow]


@pytest.mark.parametrize("gen", FAST)
@pytest.mark.parametrize(
    "field", [f if f == "name" else pytest.param(f, marks=pytest.mark.slow) for f in FIELDS]
)
def test_hostile_text_in_a_description_through_every_generator(field, gen):
    """The name (it reaches the most: comments, block names, XML attributes, JSON, the
    terminal) in ``make test-fast``; the other fields in ``make test``."""

    @examples(6)
    @given(value=hostile_strings())
    def prop(value):
        run_hostile(gen, field, value)

    prop()


_REACH = {"urdf": ("name", "title"), "explorer js": ("name", "title"), "arms": ("title",),
          "site html": ("title",)}  # fmt: skip
"""The fields whose text a generator shows (the PLC programs: the name; the title is in the
machine's comments, covered by the drawn strings)."""


def _fixed_cases():
    """(string, generator, fields): every fixed string through every generator, in the
    fields it shows (:data:`_REACH`); the site's page only for the strings that are markup."""
    markup = re.compile("[<>&\u2028\u2029]")
    for k, value in enumerate(HOSTILE):
        for gen in FAST + SLOW:
            if gen == "site html" and not markup.search(value):
                continue
            yield pytest.param(value, gen, _REACH.get(gen, ("name",)), id=f"{k}-{gen}")


@pytest.mark.slow
@pytest.mark.parametrize(("value", "gen", "fields"), list(_fixed_cases()))
def test_every_hostile_string_in_the_name_and_title(value, gen, fields):
    """Each fixed string of the issue's classes through every generator (the site's HTML
    included)."""
    for field in fields:
        run_hostile(gen, field, value)


@pytest.mark.parametrize("value", ["theta2", "a\x01b", "c\x1b[0m--", "\u2028"])
def test_a_joint_name_in_the_urdf(value):
    """A joint named as another (``theta2``) is refused (by the description's reader: its
    schema; the URDF writer refuses one too, :func:`analysis.kinematics.urdf.to_xml`), not
    written twice; control characters never reach the XML."""
    run_hostile("urdf", "joint name", value)
    with tempfile.TemporaryDirectory() as tmp:
        path = description(Path(tmp), "joint name", value)
        try:
            out = GENERATORS["urdf"].run(path)
        except ValueError as exc:
            assert f"{value!r}"[1:-1] in str(exc) or repr(value) in str(exc), str(exc)
            return
    assert value != "theta2", "a duplicate joint name was written"
    assert "\x01" not in out["urdf"] and "\x1b" not in out["urdf"]


def test_the_urdf_writer_refuses_two_joints_of_one_name_and_writes_xml():
    import numpy as np

    from analysis.kinematics.urdf import UrdfJoint, to_xml

    j = UrdfJoint("j", "revolute", "base_link", "l1", np.eye(4), limits=(-1.0, 1.0))
    with pytest.raises(ValueError, match="two joints are named 'j'"):
        to_xml("r", [], ["base_link", "l1", "l2"], [j, dataclasses.replace(j, child="l2")])
    # whatever reaches the writer, its XML parses (characters XML 1.0 forbids removed)
    odd = dataclasses.replace(j, name="a\x01b\x1b", comments=("-->\x00 ---",))
    root = ET.fromstring(to_xml("r\x02", ["h\x0b"], ["base_link", "l1"], [odd]))
    assert [e.get("name") for e in root.iter("joint")] == ["ab"]


# --------------------------------------------------------------------------------------------
# the printers, whatever a description lets through
# --------------------------------------------------------------------------------------------
def _hostile_program(program, value: str):
    """``program`` with every text a printer embeds replaced by ``value`` (the arm's name,
    title, notes, network titles, instruction comments, subroutine titles)."""

    def code(body):
        out = []
        for i in body:
            if i.op == "network":
                i = dataclasses.replace(i, args=(value,))
            out.append(dataclasses.replace(i, comment=value) if i.comment else i)
        return tuple(out)

    subs = tuple(dataclasses.replace(s, title=value, body=code(s.body))
                 for s in program.subroutines)  # fmt: skip
    return dataclasses.replace(program, arm=value, title=value, notes=(value, value),
                               body=code(program.body), subroutines=subs)  # fmt: skip


@cache
def _programs(trig: str):
    from analysis.plc.ir import build_program

    arm = load_arm("grabber")
    return arm, build_program(arm, None, trig)


def _print(dialect: str, program) -> str:
    from analysis.plc.dialects import printer_class
    from analysis.plc.emit import emit_s7200, emit_s7300

    if dialect == "s7-200":
        return emit_s7200(program, startup_target=None)
    if dialect == "s7-300":
        return emit_s7300(program, startup_target=None)
    cls = printer_class(dialect)
    return cls().doprint_program(program, units=("mm",) * 3, default_branch="front-up")


TRIG = {"s7-200": "subroutine", "s7-300": "native", "st": "function", "scl": "subroutine",
        "plcopen-xml": "function"}  # fmt: skip


@pytest.mark.parametrize("dialect", list(TRIG))
def test_every_printer_escapes_its_texts(dialect):
    """Every text a printer embeds (comments, titles, the block name) hostile: the program
    parses and its code is the clean one's."""
    _, program = _programs(TRIG[dialect])
    clean = _print(dialect, program)

    @examples(10)
    @given(value=hostile_strings())
    def prop(value):
        text = _print(dialect, _hostile_program(program, value))
        if dialect == "plcopen-xml":
            from hostile.texts import check_xml_program

            check_xml_program(text, clean, schema=True)
            return
        assert plc_code(text, dialect) == plc_code(clean, dialect)
        if dialect in ("st", "scl"):
            check_identifiers(text)
        if dialect == "s7-200":
            from analysis.plc.stl_eval import load_program

            load_program(text)

    prop()


# --------------------------------------------------------------------------------------------
# the attacks, executed
# --------------------------------------------------------------------------------------------
UNREACHABLE = [5000.0, 0.0, 0.0]


def _stl(tmp: Path, dialect: str, field: str | None, value: str = "", *extra: str):
    from hostile.texts import cli_outputs

    folder = tmp / (field or "clean").replace(" ", "-")
    folder.mkdir()
    path = description(folder, field, value)
    prog, mp = folder / "p", folder / "m.json"
    cli_outputs("stl", "--dialect", dialect, "--arm", str(path), "-o", str(prog), "--map",
                str(mp), *extra, files={})  # fmt: skip
    return prog.read_text(encoding="utf-8"), strict_json(mp.read_text(encoding="utf-8"))


def _fields_through(tmp: Path, value: str) -> list[str]:
    """The fields of the description that load with ``value``; every other refuses it at
    load, in one line naming the field (the schema's identifiers and one-line text). The
    issue put its attacks in the ``name``: a name must now be an identifier."""
    from hostile.texts import cli_outputs

    through = []
    for field in FIELDS:
        folder = tmp / ("try-" + field.replace(" ", "-"))
        folder.mkdir()
        try:
            cli_outputs("stl", "--dialect", "st", "--arm", str(description(folder, field, value)),
                        "-o", str(folder / "p"), files={})  # fmt: skip
        except ValueError as exc:
            assert re.search(r"hostile.toml: .*: ", str(exc)), exc
            assert "\n" not in str(exc).strip()
            continue
        through.append(field)
    assert "name" not in through
    return through


@pytest.mark.slow
def test_the_ob100_of_a_name_does_not_run_on_awlsim(tmp_path):
    """The issue's reproduction: a name with a line break and an OB100 that writes 99999
    into c1. Refused at load in every field; and behind the schema, the printed program
    whose every text (name, title, notes, titles, comments) is the attack runs on awlsim as
    the clean one: an unreachable target reads back what the clean program leaves (the
    refusal keeps c1), not 99999."""
    from analysis.plc.memmap import MemoryMap
    from analysis.plc.runner import AwlRunner

    assert _fields_through(tmp_path, HOSTILE[0]) == []  # a line break: no field holds one
    _, doc = _stl(tmp_path, "s7-300", None)
    _, program = _programs(TRIG["s7-300"])
    results = []
    hostile = _hostile_program(program, HOSTILE[0])
    for text in (_print("s7-300", program), _print("s7-300", hostile)):
        assert "ORGANIZATION_BLOCK OB 100" not in plc_code(text, "s7-300")
        r = AwlRunner(text, MemoryMap.from_dict(doc))
        res = r.solve([UNREACHABLE])
        results.append((int(res.pulses[0, 0]), int(res.status[0]), bool(res.reachable[0])))
    assert results[1] == results[0] and results[1][0] != 99999, results


@pytest.mark.slow
def test_a_comment_terminator_does_not_run_on_the_st_engine(tmp_path):
    """``*)`` then ``c1 := 99999; RETURN;`` in the name: refused at load in every field; the
    ST program whose every text is the attack compiles on the ST engine and computes what
    the clean one computes, targets reachable or not."""
    from analysis.plc import st_engine

    try:
        st_engine.engine_path()
    except st_engine.EngineMissing as exc:
        pytest.skip(str(exc))
    through = _fields_through(tmp_path, HOSTILE[2])
    assert "title" in through  # free text: it reaches the program through the CLI
    texts = [_stl(tmp_path, "st", f, HOSTILE[2], "--no-motion")[0] for f in [None, *through]]
    _, program = _programs(TRIG["st"])  # the grabber's, every text hostile
    texts += [_print("st", program), _print("st", _hostile_program(program, HOSTILE[2]))]
    targets = np.array([UNREACHABLE, [300.0, 200.0, 700.0]])
    out = []
    for text in texts:
        block = re.search(r"^FUNCTION_BLOCK (\w+)", text, re.M).group(1)
        res, _ = st_engine.sweep(text, block, ["px", "py", "pz"], 3, targets)
        out.append((res.pulses.tolist(), res.status.tolist()))
    cli, api = out[: len(through) + 1], out[len(through) + 1 :]
    assert all(o == cli[0] for o in cli) and api[1] == api[0], out


def test_a_script_end_in_a_title_stays_inside_the_script():
    """``</script>`` in a title: the explorer's JavaScript and the site's ``<script>``
    hold it as data (its JSON round-trips), nothing ends or opens a script."""
    from analysis.app.explore_js import arm_module_js

    with tempfile.TemporaryDirectory() as tmp:
        path = description(Path(tmp), "title", HOSTILE[5])
        js = arm_module_js(load_arm(str(path)))
    check_script(js)
    meta = re.search(r"^const arm = (.*);$", js, re.M).group(1)
    assert json.loads(meta)["title"] == HOSTILE[5]


def _renamed(program, names: dict):
    """``program`` with its inputs and work variables renamed by ``names``."""
    from analysis.plc.instr import Cond

    def arg(a):
        if isinstance(a, Cond):
            return Cond(a.op, tuple(arg(b) for b in a.args))
        if isinstance(a, tuple):
            return tuple(arg(b) for b in a)
        return names.get(a, a) if isinstance(a, str) else a

    def instr(i):
        args = i.args if i.op in ("network", "accept") else tuple(arg(a) for a in i.args)
        if i.op == "call":  # the function's name stays
            args = (i.args[0], *args[1:])
        return dataclasses.replace(i, dst=names.get(i.dst, i.dst), args=args)

    return dataclasses.replace(
        program, body=tuple(instr(i) for i in program.body),
        work=tuple(names.get(n, n) for n in program.work),
        inputs=tuple(names.get(n, n) for n in program.inputs),
    )  # fmt: skip


@pytest.mark.parametrize("dialect", ["st", "scl", "plcopen-xml"])
def test_variables_named_by_hostile_text_are_iec_identifiers(dialect):
    """Inputs and work variables named by hostile text (a user's closed form names them):
    every declared name an IEC 61131-3 identifier, distinct within its block; the XML
    parses and validates."""
    _, program = _programs(TRIG[dialect])

    @examples(8)
    @given(value=hostile_strings())
    def prop(value):
        names = {n: f"{value}{k}" for k, n in enumerate((*program.inputs, *program.work))}
        text = _print(dialect, _renamed(program, names))
        if dialect == "plcopen-xml":
            from analysis.plc.plcopen import validate_plcopen

            root = validate_plcopen(text)
            assert root is not None
            return
        check_identifiers(text)
        for block in re.split(r"^END_FUNCTION(?:_BLOCK)?$", text, flags=re.M):
            declared = re.findall(r"^\s+#?(\S+) : \w+;$", block, re.M)
            assert len({d.upper() for d in declared}) == len(declared), declared

    prop()


# --------------------------------------------------------------------------------------------
# what the description's schema refuses today, escaped all the same (defence in depth)
# --------------------------------------------------------------------------------------------
def test_the_machine_program_escapes_the_arm_it_names():
    """The machine program (ST and SCL) of an arm whose name and title are hostile: the code
    is the clean one's, every name an IEC 61131-3 identifier."""
    from analysis.plc.machine.generate import machine_text
    from analysis.plc.machine.spec import machine_spec

    arm = load_arm(str(description(Path(tempfile.mkdtemp()), None)))
    spec = machine_spec(arm)

    @examples(6)
    @given(value=hostile_strings())
    @example(value=HOSTILE[3])  # an opened (* (CODESYS nests comments)
    def prop(value):
        odd = dataclasses.replace(spec, arm=value, title=value)
        for dialect in ("st", "scl"):
            clean, text = (
                machine_text(spec, "IK_MINE", dialect),
                machine_text(odd, "IK_MINE", dialect),
            )
            assert plc_code(text, dialect) == plc_code(clean, dialect)
            check_identifiers(text)

    prop()


def test_the_explorer_escapes_the_arm_it_names():
    """The explorer's JavaScript of an arm whose name, title and joint names are hostile:
    nothing ends the script, the JSON round-trips, the code is the clean one's."""
    from analysis.app.explore_js import arm_module_js

    arm = load_arm("grabber")
    clean = arm_module_js(arm)
    meta = re.compile(r"^const arm = (.*);$", re.M)

    @examples(6)
    @given(value=hostile_strings())
    def prop(value):
        joints = tuple(dataclasses.replace(j, name=value + str(k))
                       for k, j in enumerate(arm.description.joints))  # fmt: skip
        desc = dataclasses.replace(arm.description, name=value, title=value, joints=joints)
        js = arm_module_js(dataclasses.replace(arm, description=desc))
        check_script(js)
        doc = json.loads(meta.search(js).group(1))
        assert (doc["name"], doc["title"], doc["joints"][0]) == (value, value, value + "0")

        def code(text):
            lines = [meta.sub("META", ln) for ln in text.split("\n")]
            return [re.sub(r"\s*//.*$", "", ln) for ln in lines]

        assert code(js) == code(clean)

    prop()


def test_a_terminal_never_gets_a_control_sequence(monkeypatch, tmp_path):
    """``arms`` prints a title, ``stl`` the file it wrote: control characters shown as
    escapes, whatever the text."""
    from analysis.kinematics import catalog
    from hostile.registry import cli
    from hostile.texts import check_terminal

    value = "\x1b[2J\x1b]0;pwned\x07\r\u202eevil\x9b"
    fake = {"name": value, "title": value, "joints": ["a"], "parameters": {}}
    monkeypatch.setattr(catalog, "describe_arm", lambda a: fake)
    out = cli("arms", "--arm", "grabber")
    assert out.code == 0 and "pwned" in out.stdout
    check_terminal(out.stdout)
    prog = tmp_path / f"p{value.replace('/', '')}.awl"
    out = cli("stl", "--dialect", "s7-300", "-o", str(prog))
    assert out.code == 0 and prog.exists()
    check_terminal(out.stdout + out.stderr)
