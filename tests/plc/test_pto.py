"""The S7-200's pulse train outputs as the System Manual documents them
(analysis.plc.stl_eval.pulse_output.PtoChannel), on the evaluator and, through the
translation's PLS log, on awlsim. Each test names its rule; the expected pulse times are
computed here from the cycle times."""

from __future__ import annotations

import struct

import pytest

from analysis.plc.stl_eval import S7200, PtoChannel, StlError, load_program


def _table(segments) -> bytes:
    return bytes([len(segments)]) + b"".join(struct.pack(">HhI", *s) for s in segments)


def _reader(raw: bytes, base: int = 500):
    return lambda off, n: raw[off - base : off - base + n]


def test_single_segment_runs_its_count_at_its_cycle_then_idles():
    """S2M-C p.233: SMW68 cycle, SMD72 count, SM66.7 idle; the update bits (16#85)."""
    p = PtoChannel(0)
    assert p.pls(0.0, 0x85, 500, 10) == "start" and not p.idle
    p.advance(0.004)
    assert p.pulses == pytest.approx([k * 500e-6 for k in range(8)])
    p.advance(0.0049)
    assert not p.idle  # the tenth pulse's cycle ends at 5 ms
    p.advance(0.005)
    assert p.idle and len(p.pulses) == 10 and p.trains[0].end == "done"


def test_defaults_and_the_update_bits():
    """S2M-6 Table 6-33: a cycle under 2 units is 2, a count of 0 is 1; S2M-C p.226: the
    registers start at 0 and PLS takes SMW68/SMD72 only with their update bits set."""
    p = PtoChannel(0)
    p.pls(0.0, 0x80, 500, 10)  # enabled, no update bit: the registers' 0 and 0
    assert p.trains[-1].segments == [(2, 0, 1)]
    p.advance(1.0)
    p.pls(1.0, 0x85 | 0x08, 3, 4)  # ms time base
    assert p.trains[-1].segments == [(3, 0, 4)] and p.trains[-1].unit == 1e-3


def test_the_pipeline_holds_one_train_then_overflows():
    """S2M-C p.228: a PLS during a train goes into a one-entry pipeline that starts when the
    train ends; a PLS into a full pipeline sets SM66.6 and is ignored."""
    p = PtoChannel(0)
    assert p.pls(0.0, 0x85, 1000, 2) == "start"
    assert p.pls(0.0, 0x85, 500, 3) == "queued"
    assert p.pls(0.0, 0x85, 500, 7) == "overflow" and p.flags & 0x40
    p.advance(1.0)
    assert p.pulses == pytest.approx([0.0, 0.001, 0.002, 0.0025, 0.003])
    assert [t.end for t in p.trains] == ["done", "done"] and p.idle


def test_a_cleared_enable_bit_aborts_and_every_later_pls_aborts_too():
    """S2M-C p.226: zero the enable bit and execute PLS to stop a train (SM66.5, S2M-A p.9-53);
    while the control byte stays disabled, PLS never starts one (the issue's silent move)."""
    p = PtoChannel(0)
    p.pls(0.0, 0x85, 500, 100)
    p.advance(0.002)
    assert p.pls(0.002, 0x05, 500, 100) == "abort" and p.flags & 0x20 and p.idle
    assert p.trains[0].end == "aborted" and len(p.pulses) == 4
    assert p.pls(0.003, 0x05, 500, 100) == "idle" and len(p.trains) == 1
    p.advance(1.0)
    assert len(p.pulses) == 4


def test_a_profile_changes_the_cycle_every_pulse():
    """S2M-A p.9-53, Table 9-15: segments (initial cycle, delta per pulse, count) read from
    V memory at SMW168; pulse k of a segment lasts initial + k x delta."""
    p = PtoChannel(0)
    raw = _table([(1000, -100, 3), (700, 0, 2)])
    assert p.pls(0.0, 0xA0, 500, 0, _reader(raw)) == "start"
    p.advance(1.0)
    cycles = [1000, 900, 800, 700, 700]
    times = [sum(cycles[:k]) * 1e-6 for k in range(5)]
    assert p.pulses == pytest.approx(times) and p.trains[0].end == "done"


def test_a_delta_that_leaves_the_legal_cycles_ends_the_profile():
    """S2M-A p.9-53: a delta that gives an illegal cycle time terminates the PTO and sets
    SM66.4; a profile of 0 segments generates no output."""
    p = PtoChannel(0)
    p.pls(0.0, 0xA0, 500, 0, _reader(_table([(300, -100, 5)])))
    p.advance(1.0)
    assert len(p.pulses) == 3 and p.flags & 0x10 and p.trains[0].end == "delta error"
    q = PtoChannel(0)
    assert q.pls(0.0, 0xA0, 500, 0, _reader(b"\x00")) == "no segments" and q.idle


def test_status_bits_stay_until_the_program_clears_them():
    """The CPU copies the channel's flags into SMB66 and the program resets them there."""
    text = "\n".join(["ORGANIZATION_BLOCK MAIN:OB1", "BEGIN", "Network 1",
                      "LD SM0.1", "MOVB 16#85, SMB67", "MOVW 500, SMW68", "MOVD 100, SMD72",
                      "PLS 0", "LD V0.0", "MOVB 16#05, SMB67", "PLS 0",
                      "LD V0.1", "R SM66.5, 1", "END_ORGANIZATION_BLOCK"])  # fmt: skip
    cpu = S7200(load_program(text), scan_ms=2)
    cpu.scan()
    assert cpu.read("BYTE", "SMB66") == 0x00 and len(cpu.pto[0].pulses) == 4
    cpu.write("BOOL", "V0.0", True)
    cpu.scan(3)
    assert cpu.read("BYTE", "SMB66") == 0xA0 and len(cpu.pto[0].pulses) == 4
    cpu.write("BOOL", "V0.1", True)
    cpu.scan()
    assert cpu.read("BYTE", "SMB66") == 0x80


def test_pwm_and_a_profile_beyond_v_memory_stop_the_cpu_saying_why():
    for body, why in ((["MOVB 16#C0, SMB67", "PLS 0"], "PWM is not modelled"),
                      (["MOVB 16#A0, SMB67", "MOVW 8190, SMW168", "MOVB 3, VB8190", "PLS 0"],
                       "beyond V memory")):  # fmt: skip
        text = "\n".join(["LD SM0.0", *body])
        cpu = S7200(load_program(text))
        cpu.scan()
        assert cpu.fault is not None and why in str(cpu.fault)


@pytest.mark.slow
def test_awlsim_runs_the_same_generator_on_the_pls_log():
    """Five PLS in one scan overflow the translation's log of four: refused, saying so; the
    log's records reach the model in order (a start, a queued train, an abort)."""
    pytest.importorskip("awlsim")
    from analysis.plc.motion.engines import AwlsimEngine, EvaluatorEngine

    text = "\n".join(["ORGANIZATION_BLOCK MAIN:OB1", "BEGIN", "Network 1",
                      "LD SM0.1", "MOVB 16#85, SMB67", "MOVW 500, SMW68", "MOVD 3, SMD72",
                      "PLS 0", "MOVD 2, SMD72", "PLS 0", "LD V0.0", "MOVB 16#05, SMB67",
                      "PLS 0", "END_ORGANIZATION_BLOCK"])  # fmt: skip
    runs = []
    for eng in (EvaluatorEngine(text, scan_ms=2), AwlsimEngine(text, scan_ms=2)):
        eng.scan()
        eng.write("BOOL", "V0.0", True)
        eng.scan()
        runs.append(([(t.segments, t.pulses, t.end) for t in eng.pto[0].trains],
                     eng.pto[0].pulses, eng.read("BYTE", "SMB66")))  # fmt: skip
    assert runs[0] == runs[1]
    assert runs[0][0] == [([(500, 0, 3)], 3, "done"), ([(500, 0, 2)], 1, "aborted")]
    five = "\n".join(["LD SM0.0", *["MOVB 16#85, SMB67", "PLS 0"] * 5])
    eng = AwlsimEngine(five)
    with pytest.raises(ValueError, match="more than 4 times in one scan"):
        eng.scan()
    with pytest.raises(StlError):
        load_program("LD SM0.0\nPLS 2")
