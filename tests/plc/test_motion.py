"""The generated S7-200 motion networks (analysis.plc.motion): a move latches its target.

Issue 22: the networks recorded the IK outputs of the scan a move ended as the position
reached, and those outputs follow the HMI every scan; with the target changed mid-move the
next move was off by 81 shoulder and 974 elbow pulses. Here the target changes while the
trains run, on awlsim (the S7-200 text translated to AWL) and on the S7-200 evaluator.
"""

from __future__ import annotations

import pytest

from analysis.kinematics.arm import paper_arm
from analysis.plc.generate import generate
from analysis.plc.memmap import default_map

pytestmark = pytest.mark.slow  # awlsim: about a second (tests/conftest.py)

ROW1, ROW6 = (100.0, 100.0, 600.0), (200.0, 300.0, 600.0)
C_ROW1, C_ROW6 = (500, 113, -1724), (626, 264, -1013)  # python -m analysis ik X Y Z


class _Awlsim:
    """The translated program on awlsim, with the PTO idle bits driven by the test."""

    def __init__(self, text: str) -> None:
        pytest.importorskip("awlsim")
        from analysis.plc.runner import AwlRunner
        from analysis.plc.translate import translate_s7200

        self.tr = translate_s7200(text)
        self.r = AwlRunner(self.tr.awl, default_map("s7-200"))

    def target(self, xyz) -> None:
        for b, v in zip((0, 4, 8), xyz, strict=True):
            self.r.write_real(b, v)

    def sb1(self, on: bool) -> None:
        self.r.write_bit(self.tr.layout.byte("I", 0), 0, on)

    def idle(self, ch: int) -> None:
        self.r.write_bit(self.tr.layout.byte("SM", 66 + 10 * ch), 7, True)

    def scan(self) -> None:
        self.r.cycle()

    def dint(self, byte: int) -> int:
        return self.r.read_dint(byte)

    def step(self) -> int:
        return self.r.mem[120]

    def pls(self, ch: int) -> int:
        """The pulse count of the last PLS on channel ch (SMD72 / SMD82 when it ran)."""
        return self.r.read_dint(self.tr.layout.pls_log + 4 * ch)


class _Evaluator:
    """The same program text on the S7-200 evaluator."""

    def __init__(self, text: str) -> None:
        from analysis.plc.stl_eval import S7200, load_program

        self.cpu = S7200(load_program(text))
        self.cpu.scan()  # the first scan

    def target(self, xyz) -> None:
        for a, v in zip(("VD0", "VD4", "VD8"), xyz, strict=True):
            self.cpu.write("REAL", a, v)

    def sb1(self, on: bool) -> None:
        self.cpu.write("BOOL", "I0.0", on)

    def idle(self, ch: int) -> None:
        self.cpu.pto_done(ch)

    def scan(self) -> None:
        self.cpu.scan()

    def dint(self, byte: int) -> int:
        return self.cpu.read("DINT", f"VD{byte}")

    def step(self) -> int:
        return self.cpu.read("BYTE", "VB120")

    def pls(self, ch: int) -> int:
        return self.cpu.pto[ch].log[-1]


def _move(plc, target) -> None:
    """SB1 with ``target`` on the inputs, the target changed to Table 4 row 6 while the
    trains run, both phases completed: the positions must be ``target``'s counts."""
    plc.target(target)
    plc.sb1(True)
    plc.scan()
    assert plc.step() == 1
    plc.sb1(False)
    plc.target(ROW6)  # the HMI changes the target mid-move
    plc.scan()
    assert plc.step() == 1 and [plc.dint(b) for b in (100, 104, 108)] == list(C_ROW6)
    plc.idle(0)
    plc.idle(1)
    plc.scan()
    assert plc.step() == 2
    plc.idle(1)
    plc.scan()
    assert plc.step() == 0


@pytest.mark.parametrize("engine", [_Awlsim, _Evaluator])
def test_target_changed_mid_move_changes_nothing_until_the_move_ends(engine):
    plc = engine(generate(paper_arm(), "s7-200").program)
    _move(plc, ROW1)
    # the position reached is the latched target, not the IK's current output (row 6)
    assert [plc.dint(b) for b in (124, 128, 132)] == list(C_ROW1)
    # the next move goes from row 1 to row 6: exactly the difference of the counts
    plc.sb1(True)
    plc.scan()
    assert plc.pls(0) == abs(C_ROW6[0] - C_ROW1[0])  # waist, PTO0
    assert plc.pls(1) == abs(C_ROW6[1] - C_ROW1[1])  # shoulder, PTO1 through KM1
    plc.sb1(False)
    plc.idle(0)
    plc.idle(1)
    plc.scan()
    assert plc.pls(1) == abs(C_ROW6[2] - C_ROW1[2])  # elbow, PTO1 through KM2
