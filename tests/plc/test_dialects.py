"""The registry of PLC dialects (analysis.plc.dialects.DIALECTS, issue 28 item 2): the
command line's choices come from it, every dispatch reads it, and a new dialect is one class
and one entry (a toy dialect here, registered for the test only)."""

from __future__ import annotations

import contextlib
import io
import re

import pytest

from analysis.app import cli
from analysis.kinematics.arm import paper_arm
from analysis.plc.approx import PlcFloat32Ops
from analysis.plc.dialects import DIALECTS, printer_class
from analysis.plc.generate import generate
from analysis.plc.st import StPrinter


def _help(*argv: str) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), pytest.raises(SystemExit):
        cli.main([*argv, "--help"])
    return " ".join(out.getvalue().split())


def _choices(help_text: str, option: str = "--dialect") -> list[str]:
    m = re.search(re.escape(option) + r" \{([^}]*)\}", help_text)
    assert m, help_text[:300]
    return m.group(1).split(",")


@pytest.fixture
def fresh_parser(monkeypatch):
    """The command line's parser rebuilt for this test (it is built once per process)."""
    monkeypatch.setattr(cli, "_PARSER", [])


def test_each_class_is_registered_under_its_own_name():
    assert list(DIALECTS) == ["s7-200", "s7-300", "st", "scl", "plcopen-xml"]
    for name, cls in DIALECTS.items():
        assert cls.name == name and cls.title and cls.trigs
        assert printer_class(name) is cls
    with pytest.raises(ValueError, match=r"dialect 's7-400' is not one of s7-200, s7-300"):
        printer_class("s7-400")


def test_stl_and_stl_run_choices_come_from_the_registry(fresh_parser):
    stl = _help("stl")
    assert _choices(stl) == list(DIALECTS)
    for cls in DIALECTS.values():  # each dialect's help line is its class's title
        assert " ".join(cls.title.split()) in stl
    run = _help("stl-run")
    assert _choices(run) == [n for n, cls in DIALECTS.items() if cls.engine]


def test_a_dialect_that_extends_another_subclasses_it():
    assert issubclass(DIALECTS["s7-300"], DIALECTS["s7-200"])
    assert issubclass(DIALECTS["scl"], DIALECTS["st"])
    assert issubclass(DIALECTS["plcopen-xml"], DIALECTS["st"])


def test_dispatch_reads_the_class():
    """The float32 model's tie rule and the trigonometry a dialect accepts are its class's."""
    for name, cls in DIALECTS.items():
        assert PlcFloat32Ops(name).rounding == cls.rounding
        assert PlcFloat32Ops(name).trig == cls.trigs[0]
    with pytest.raises(ValueError, match="not possible on the S7-200"):
        generate(paper_arm(), "s7-200", trig="native")
    with pytest.raises(ValueError, match="memory layout names addresses; st has none"):
        from analysis.plc.memmap import default_map

        generate(paper_arm(), "st", mmap=default_map("s7-300"))


class ToyPrinter(StPrinter):
    """A toy dialect: IEC 61131-3 ST with ``//`` line comments (CODESYS and TwinCAT accept
    them), everything else inherited."""

    name = "st-slash"
    title = "IEC 61131-3 ST with // comments (a toy dialect of the registry's test)"

    def comment(self, text: str) -> str:
        return "// " + " ".join(text.split())

    def comment_block(self, lines) -> list[str]:
        return [self.comment(line) for line in lines]


def test_a_new_dialect_is_one_class_and_one_entry(monkeypatch, fresh_parser, tmp_path):
    monkeypatch.setitem(DIALECTS, ToyPrinter.name, ToyPrinter)  # the one entry
    assert ToyPrinter.name in _choices(_help("stl"))
    out = tmp_path / "toy.st"
    assert cli.main(["stl", "--dialect", "st-slash", "-o", str(out)]) == 0
    toy, st = out.read_text(encoding="utf-8"), generate(paper_arm(), "st", motion=False).program

    def code(text: str) -> list[str]:  # the statements: comments and blank lines removed
        text = re.sub(r"\(\*.*?\*\)", "", text, flags=re.S)
        text = re.sub(r"//[^\n]*", "", text)
        return [ln.rstrip() for ln in text.splitlines() if ln.strip()]

    assert "//" in toy and "(*" not in toy
    assert code(toy) == code(st)  # the same program, its own comments
    assert PlcFloat32Ops("st-slash").rounding == "half-away"  # the model follows the class
