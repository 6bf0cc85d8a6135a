"""Readable output (issue 29 item 5 and its other PLC findings): ST and SCL name every
intermediate after the closed form's symbols and the operation, never ``TMPn`` or ``tmpK``;
a user's arm gets comments from its description, not the paper's citations; counts beyond
REAL's exact range (2^24) are refused naming the joint and the resolution."""

from __future__ import annotations

import re
import tempfile
from pathlib import Path

import pytest

from analysis.kinematics.arm import load_arm
from analysis.paths import data_dir
from analysis.plc.generate import generate
from analysis.plc.ir import build_program
from hostile.texts import description

CITES = re.compile(r"\b(?:eqs?|Figs?|Fig|sec|Table)\.?\s*\d", re.I)


@pytest.mark.parametrize("name", ["grabber", "palletizer", "gr1", "picker"])
@pytest.mark.parametrize("dialect", ["st", "scl", "plcopen-xml"])
def test_no_temporaries_in_the_st_family(name, dialect):
    text = generate(load_arm(name), dialect, motion=False).program
    assert not re.search(r"\b(?:TMP|tmp)\d+\b", text)
    assert not re.search(r"\b(?:count|theta\w*)_\d\b", text)  # a repeated name: count1 ...


def test_the_grabbers_intermediates_carry_its_symbols():
    text = generate(load_arm("grabber"), "st", motion=False).program
    for name in ("rho2", "d2", "rho", "v_d", "theta1", "cos_theta3", "s3", "count1", "count3",
                 "px_sq", "z_sq", "abs_z"):  # fmt: skip
        assert re.search(rf"^\s+{name} : REAL;$", text, re.M), name


def test_the_s7_programs_keep_their_memory():
    """The S7 listings still reuse temporaries (the S7-200's 64 bytes of local memory; the
    same work area as before)."""
    arm = load_arm("grabber")
    assert build_program(arm).work == build_program(arm, readable=False).work
    assert "tmp1" in build_program(arm).work
    assert "tmp1" not in build_program(arm, readable=True).work


def test_a_users_arm_is_described_by_its_own_description(tmp_path):
    """The README's user arm (closed_form = "grabber"): its title in the header, none of the
    paper's equation or figure numbers; the paper's own arm keeps them."""
    mine = load_arm(str(description(tmp_path, None)))
    for dialect in ("s7-200", "s7-300", "st", "scl", "plcopen-xml"):
        text = generate(mine, dialect, motion=False).program
        assert "arm mine (my 3R arm)" in text, dialect
        assert not CITES.search(text), (dialect, CITES.search(text).group(0))
        paper = generate(load_arm("grabber"), dialect, motion=False).program
        assert CITES.search(paper) and "3R material-grabbing robot" in paper


def _picker(lead_mm: float) -> str:
    text = (data_dir() / "arms" / "picker.toml").read_text(encoding="utf-8")
    text = re.sub(r'(?m)^name = "picker"', 'name = "mypicker"', text)
    return re.sub(r"lead_mm = \{[^}]*\}",
                  f'lead_mm = {{ value = {lead_mm}, status = "measured", source = "my screw" }}',
                  text)  # fmt: skip


def test_counts_beyond_real_are_refused_naming_the_joint():
    """A picker with a 0.05 mm screw: 300 mm of stroke are 24,000,000 pulses, beyond 2^24;
    with a 1 mm screw it fits."""
    with tempfile.TemporaryDirectory() as tmp:
        fine, coarse = Path(tmp) / "fine.toml", Path(tmp) / "coarse.toml"
        fine.write_text(_picker(0.05), encoding="utf-8")
        coarse.write_text(_picker(1.0), encoding="utf-8")
        with pytest.raises(ValueError) as exc:
            build_program(load_arm(str(fine)), "front")
        generate(load_arm(str(coarse)), "st", "front", motion=False)
    message = str(exc.value)
    assert message.startswith("joint theta2: its counts reach 24,000,000 pulses")
    assert "0.05 mm lead" in message and "1.25e-05 mm per pulse" in message
    assert "2^24 = 16,777,216" in message and "steps of 2 pulses" in message
