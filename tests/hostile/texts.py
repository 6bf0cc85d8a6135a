"""Hostile text and structure (issue 27 items 4 and 7): the strings, the description fields
they go into, and every generator whose output embeds them, as one registry.

A *field* puts a string into an arm description (the README's user arm, ``closed_form =
"grabber"``): its ``name``, its ``title``, the first joint's ``name`` (and the D-H row that
names it), a parameter's ``source``. A *generator* turns a description file into named
outputs (program text, MAP.json, URDF, the explorer's JavaScript, the site's HTML, what a
command prints) and a *check* holds a hostile description's outputs to the clean one's: each
output parses as its kind and, outside comments, says what the clean one says. A new output
kind is one :func:`generator` below; a new field one entry of :data:`FIELDS`.
"""

from __future__ import annotations

import json
import re
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from hypothesis import strategies as st

from analysis.escape import toml_string
from analysis.paths import PROJECT

# --------------------------------------------------------------------------------------------
# the strings
# --------------------------------------------------------------------------------------------
HOSTILE = [
    # the OB100, through a name: S7-300 code after a line break
    "x\nORGANIZATION_BLOCK OB 100\nBEGIN\n      L     L#99999\n      T     MD100\n"
    "END_ORGANIZATION_BLOCK\n// ",
    "x\r\nNetwork 99\r\nLD     SM0.0\r\nMOVD   99999, VD100\r\n",  # S7-200 code
    "x *) c1 := 99999; RETURN; (* y",  # out of an ST comment
    "x (* an opened comment",  # CODESYS nests (* *)
    "a */ b /* c",
    "</script><script>document.title='pwned'</script>",
    '--> <robot name="evil"/> <!--',
    "]]> <![CDATA[ & &amp; <&> \"quoted\" 'single'",
    "\x1b[2J\x1b]0;title\x07\x1b[31mred",  # terminal control sequences
    "a\rb\x00c\x01d\x0be\x0cf\x7fg\x85h",  # control characters, NEL
    "line\u2028separator\u2029paragraph",
    "bidi \u202eevil\u202c override",
    "θ1 ünïcödé 名前 emoji \U0001f916",
    "__double__trailing_",
    "1starts_with_digit",
    "END_FUNCTION_BLOCK",
    "TO",
    "// a comment",
    "{ S7_Optimized_Access := 'FALSE' }",
    "x" * 300,
    "theta2",  # as a joint name: another joint's (a URDF names each joint once)
]
"""One string per way out of a context (the module docstring's generators)."""

_PIECES = st.sampled_from(["\n", "\r", "*)", "(*", "*/", "/*", "</script>", "<!--", "-->",
                           "--", "]]>", "&", "<", ">", '"', "'", "\x1b", "\x00", "\u2028",
                           "\u2029", "\x85", "\t", "//", ";", "END_VAR", "θ", "_"])  # fmt: skip


def hostile_strings():
    """The fixed strings and random mixtures of the pieces they are made of."""
    mixed = st.lists(_PIECES | st.text(max_size=4), min_size=1, max_size=8).map("".join)
    return st.sampled_from(HOSTILE) | mixed


# --------------------------------------------------------------------------------------------
# the description and its fields
# --------------------------------------------------------------------------------------------
_MOTION = (
    'max_velocity = { value = 90.0, unit = "deg/s", status = "assumed", source = "test" }\n'
    'max_acceleration = { value = 360.0, unit = "deg/s2", status = "assumed", source = "test" }\n'
    'max_jerk = { value = 3600.0, unit = "deg/s3", status = "assumed", source = "test" }\n'
    'home = { mode = "set", position = 0.0, status = "assumed", source = "test" }\n'
)


@cache
def readme_toml() -> str:
    """The README's user arm (``closed_form = "grabber"``), as written there, with the
    joints' motion limits and homing the machine program needs (the shared contract)."""
    text = (PROJECT / "README.md").read_text(encoding="utf-8")
    section = text.split("## One source per arm (and how to add one)")[1]
    toml = section.split("```toml\n", 1)[1].split("```", 1)[0]
    return toml.replace("pulses_per_rev = 3200\n", "pulses_per_rev = 3200\n" + _MOTION)


def _field_name(toml: str, v: str) -> str:
    return toml.replace('name = "mine"', f"name = {toml_string(v)}", 1)


def _field_title(toml: str, v: str) -> str:
    return toml.replace('title = "my 3R arm"', f"title = {toml_string(v)}", 1)


def _field_joint(toml: str, v: str) -> str:
    s = toml_string(v)
    toml = toml.replace('joint = "theta1"', f"joint = {s}", 1)
    return toml.replace('name = "theta1"', f"name = {s}", 1)


def _field_source(toml: str, v: str) -> str:
    return toml.replace('source = "my arm"', f"source = {toml_string(v)}", 1)


FIELDS: dict[str, Callable[[str, str], str]] = {
    "name": _field_name,
    "title": _field_title,
    "joint name": _field_joint,
    "parameter source": _field_source,
}
"""Where a hostile string goes in the description (field -> TOML rewrite)."""


def description(folder: Path, field: str | None, value: str = "") -> Path:
    """The README's arm in ``folder``, with ``value`` in ``field`` (None: the clean arm)."""
    toml = readme_toml() if field is None else FIELDS[field](readme_toml(), value)
    path = folder / ("clean.toml" if field is None else "hostile.toml")
    path.write_text(toml, encoding="utf-8")
    return path


# --------------------------------------------------------------------------------------------
# the generators
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Generator:
    """``run(path) -> {output name: text}`` (raises ValueError when the description is
    refused); ``check(hostile, clean, value, field)`` asserts on the outputs."""

    name: str
    run: Callable[[Path], dict[str, str]]
    check: Callable[[dict, dict, str, str], None]
    slow: bool = False


GENERATORS: dict[str, Generator] = {}


def generator(name: str, *, slow: bool = False):
    def register(pair):
        run, check = pair
        GENERATORS[name] = Generator(name, run, check, slow)
        return pair

    return register


def cli_outputs(*argv: str, files: dict[str, Path] | None = None) -> dict[str, str]:
    """``python -m analysis ARGV`` in this process: ``stdout``, ``stderr``, ``code`` and the
    files it wrote; a refusal (exit 2) raises ValueError with its line."""
    from hostile.registry import cli

    out = cli(*argv)
    if out.code == 2:
        raise ValueError(out.message)
    assert out.code == 0, out
    result = {"stdout": out.stdout, "stderr": out.stderr}
    for key, path in (files or {}).items():
        result[key] = path.read_bytes().decode("utf-8")
    return result


def strict_json(text: str):
    def refuse(token):
        raise AssertionError(f"invalid JSON token {token}")

    return json.loads(text, parse_constant=refuse)


TERMINAL_CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")


def check_terminal(text: str) -> None:
    """What a command prints: no control character but TAB and LF, no bidi override."""
    assert not TERMINAL_CONTROL.search(text), repr(text[:300])


# --- PLC programs -----------------------------------------------------------------------------
_IK_BLOCK = re.compile(r"\bIK(?:_(?!ATAN2\b|ACOS\b)[A-Za-z0-9_]+)?\b")
_MACHINE_BLOCK = re.compile(r"\bMACHINE(?:_[A-Za-z0-9_]+)?\b")


IEC_IDENTIFIER = re.compile(r"[A-Za-z_](?:_?[A-Za-z0-9])*")
"""IEC 61131-3 6.1.2: a letter or underscore first, no two underscores in a row, none last."""


def check_identifiers(text: str) -> None:
    """Every POU and variable an ST or SCL source declares is an IEC 61131-3 identifier."""
    names = re.findall(r'^(?:FUNCTION_BLOCK|FUNCTION) "?([^\s":]+)', text, re.M)
    names += re.findall(r"^\s+#?(\S+) : \w+;$", text, re.M)
    assert names
    for n in names:
        assert IEC_IDENTIFIER.fullmatch(n), n


def strip_nested_comments(text: str) -> str:
    """ST text without its ``(* *)`` comments, nested ones as CODESYS reads them (an
    unclosed ``(*`` inside a comment keeps the comment open)."""
    out, depth, i = [], 0, 0
    while i < len(text):
        two = text[i : i + 2]
        if two == "(*":
            depth, i = depth + 1, i + 2
        elif two == "*)" and depth:
            depth, i = depth - 1, i + 2
        else:
            if not depth:
                out.append(text[i])
            i += 1
    return "".join(out)


def plc_code(text: str, dialect: str) -> list[str]:
    """The lines of a PLC program that are code: comments (nested ones as CODESYS reads
    them), titles and blank lines out, the arm's block names (built from its name) as
    ``IK_ARM`` and ``MACHINE_ARM``."""
    if dialect in ("st", "scl"):
        text = strip_nested_comments(text)
    text = re.sub(r"//[^\n]*", "", text)
    lines = []
    for line in text.replace("\r\n", "\n").split("\n"):
        s = line.rstrip()
        if not s.strip() or re.match(r"\s*TITLE\s*=", s):
            continue
        lines.append(_MACHINE_BLOCK.sub("MACHINE_ARM", _IK_BLOCK.sub("IK_ARM", s)))
    return lines


def _stl(dialect: str):
    def run(path: Path) -> dict[str, str]:
        with tempfile.TemporaryDirectory() as tmp:
            prog, mp = Path(tmp) / "p.txt", Path(tmp) / "m.json"
            return cli_outputs("stl", "--dialect", dialect, "--arm", str(path), "-o", str(prog),
                               "--map", str(mp), files={"program": prog, "map": mp})  # fmt: skip

    def check(hostile: dict, clean: dict, value: str, field: str) -> None:
        check_terminal(hostile["stdout"] + hostile["stderr"])
        doc = strict_json(hostile["map"])
        if field == "name":
            assert doc.get("arm", "") == value  # JSON carries the text as it is
        text = hostile["program"]
        if dialect == "plcopen-xml":
            check_xml_program(text, clean["program"])
            return
        assert plc_code(text, dialect) == plc_code(clean["program"], dialect)
        if dialect in ("st", "scl"):
            check_identifiers(text)
        if dialect == "s7-200":
            from analysis.plc.stl_eval import load_program

            load_program(text)  # the evaluator reads it (a refusal raises)

    return run, check


def check_xml_program(text: str, clean: str, schema: bool = False) -> None:
    """PLCopen XML: parses, validates against the TC6 0201 schema model (``schema``; the
    ``stl`` command validates what it writes and refuses what does not validate), and its
    ST bodies are the clean program's (comments and the block names aside)."""
    from analysis.plc.plcopen import validate_plcopen

    if schema:
        validate_plcopen(text)

    def bodies(xml: str) -> list[list[str]]:
        root = ET.fromstring(xml)
        ns = {"p": "http://www.plcopen.org/xml/tc6_0201", "x": "http://www.w3.org/1999/xhtml"}
        out = []
        for pou in root.iterfind(".//p:pou", ns):
            st_text = "".join(pou.find("p:body/p:ST", ns).itertext())
            name = _MACHINE_BLOCK.sub("MACHINE_ARM", _IK_BLOCK.sub("IK_ARM", pou.get("name")))
            out.append([name, *plc_code(st_text, "st")])
        return out

    assert bodies(text) == bodies(clean)


for _d in ("s7-200", "s7-300", "st", "scl", "plcopen-xml"):
    generator(f"stl {_d}")(_stl(_d))


# --- URDF ---------------------------------------------------------------------------------------
def _urdf_run(path: Path) -> dict[str, str]:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "arm.urdf"
        return cli_outputs("urdf", "--arm", str(path), "-o", str(out), files={"urdf": out})


def _urdf_shape(xml: str) -> list:
    """Every element with its attributes, names aside (comments are not elements)."""
    root = ET.fromstring(xml)
    return [(e.tag, {k: v for k, v in e.attrib.items() if k not in ("name", "link")})
            for e in root.iter()]  # fmt: skip


def _urdf_check(hostile: dict, clean: dict, value: str, field: str) -> None:
    check_terminal(hostile["stdout"] + hostile["stderr"])
    root = ET.fromstring(hostile["urdf"])  # parses
    names = [j.get("name") for j in root.iter("joint")]
    assert len(set(names)) == len(names), names  # each joint once
    assert _urdf_shape(hostile["urdf"]) == _urdf_shape(clean["urdf"])
    comments = re.findall(r"<!--(.*?)-->", hostile["urdf"], flags=re.S)
    assert all("--" not in c and "\n" not in c for c in comments)


generator("urdf")((_urdf_run, _urdf_check))


# --- the explorer's JavaScript, and the site's HTML -----------------------------------------
def _js_run(path: Path) -> dict[str, str]:
    from analysis.app.explore_js import arm_module_js
    from analysis.kinematics.arm import load_arm

    return {"js": arm_module_js(load_arm(str(path)))}


_META = re.compile(r"^const arm = (.*);$", re.M)


def check_script(js: str) -> None:
    """Text inside ``<script>``: nothing that ends it, opens an HTML comment or breaks a
    JavaScript line inside a string."""
    low = js.lower()
    assert "</script" not in low and "<!--" not in low and "<script" not in low
    assert "\u2028" not in js and "\u2029" not in js


def _js_check(hostile: dict, clean: dict, value: str, field: str) -> None:
    js = hostile["js"]
    check_script(js)

    def code(text: str) -> list[str]:
        lines = [_META.sub("const arm = META;", ln) for ln in text.split("\n")]
        lines = [re.sub(r"\s*//.*$", "", ln) for ln in lines]
        return [ln for ln in lines if ln.strip()]

    assert code(js) == code(clean["js"])  # comments aside, the same statements
    meta = strict_json(_META.search(js).group(1))
    if field in ("name", "title"):
        assert meta[field] == value  # the text itself, through JSON
    if field == "joint name":
        assert meta["joints"][0] == value


generator("explorer js")((_js_run, _js_check))


def _html_run(path: Path) -> dict[str, str]:
    from analysis.app.site_content import static_explorer_html

    return {"html": static_explorer_html("hostile", arms=[str(path)])}


def _html_check(hostile: dict, clean: dict, value: str, field: str) -> None:
    from html.parser import HTMLParser

    class Parts(HTMLParser):
        def __init__(self):
            super().__init__(convert_charrefs=True)
            self.tags, self.scripts, self.data_explorer, self._in = [], [], [], False

        def handle_starttag(self, tag, attrs):
            self.tags.append(tag)
            self._in = tag == "script"
            self.data_explorer += [v for k, v in attrs if k == "data-explorer"]
            if self._in:
                self.scripts.append("")

        def handle_endtag(self, tag):
            self._in = False

        def handle_data(self, data):
            if self._in:
                self.scripts[-1] += data

    a, b = Parts(), Parts()
    a.feed(hostile["html"])
    b.feed(clean["html"])
    assert a.tags == b.tags  # the same elements: no script closed or opened early
    assert len(a.scripts) == 1 and len(a.data_explorer) == 1
    check_script(a.scripts[0])
    cfg = strict_json(a.data_explorer[0])  # the attribute holds JSON, whole
    if field == "title":
        assert value.strip() == "" or cfg["figures"]


generator("site html", slow=True)((_html_run, _html_check))


# --- the command line's listing -------------------------------------------------------------
def _arms_run(path: Path) -> dict[str, str]:
    text = cli_outputs("arms", "--arm", str(path))
    js = cli_outputs("arms", "--arm", str(path), "--json")
    return {"stdout": text["stdout"] + text["stderr"], "json": js["stdout"]}


def _arms_check(hostile: dict, clean: dict, value: str, field: str) -> None:
    check_terminal(hostile["stdout"])
    doc = strict_json(hostile["json"])
    if field == "title" and "error" not in doc[0]:
        assert doc[0]["title"] == value  # the text itself, through JSON


generator("arms")((_arms_run, _arms_check))
