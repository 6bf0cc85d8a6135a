"""Bounded work of ``stl-run`` and the awlsim runner (issue 27 item 5): a scan watchdog and a
cap on scans x watchdog on awlsim, program files read at most the dialect's limit while
reading (no device, FIFO or endless stream), awlsim's M memory sized from the code alone and
capped at the target CPU's. (The S7-200 evaluator's watchdog: tests/hostile/
test_hostile_programs.py.)"""

from __future__ import annotations

import io
import os
import time

import pytest

from analysis.plc.engines import AwlSession
from analysis.plc.memmap import default_map
from analysis.plc.runner import AwlRunner, m_bytes_used
from hostile.registry import cli

LOOP = """ORGANIZATION_BLOCK OB 1
BEGIN
LOOP: JU LOOP
END_ORGANIZATION_BLOCK
"""

COUNT = """ORGANIZATION_BLOCK OB 1
BEGIN
      L     MD0
      L     L#1
      +D
      T     MD0
END_ORGANIZATION_BLOCK
"""


def test_an_endless_scan_stops_the_cpu_at_the_watchdog():
    s = AwlSession(LOOP, watchdog_s=0.2)
    t0 = time.monotonic()
    s.scan(5)
    assert time.monotonic() - t0 < 5
    assert s.fault.startswith("Cycle time exceed 0.200 seconds at line 3 (LOOP: JU LOOP)")
    assert s.fault.endswith("in scan 1") and "\n" not in s.fault


def test_scans_times_the_watchdog_is_capped():
    """A million quick scans stop at the cap, saying how many ran; the counter proves they
    ran until then."""
    s = AwlSession(COUNT, watchdog_s=0.05, budget_s=0.5)
    t0 = time.monotonic()
    s.scan(1_000_000)
    assert time.monotonic() - t0 < 5
    assert "scans ran in the 0.5 s that --scans x the 0.05 s watchdog allows" in s.fault
    done = int(s.fault.split(" of ")[0].replace(",", ""))
    assert 0 < done < 1_000_000 and s.read("DINT", "MD0") == done
    quick = AwlSession(COUNT, watchdog_s=0.05, budget_s=0.5)
    quick.scan(3)  # within the cap: every scan, no fault
    assert quick.fault is None and quick.read("DINT", "MD0") == 3


@pytest.mark.slow
def test_stl_run_of_an_endless_program_is_one_line(tmp_path):
    prog = tmp_path / "loop.awl"
    prog.write_text(LOOP, encoding="utf-8")
    out = cli("stl-run", str(prog), "--dialect", "s7-300", "--read", "MD0:DINT", "--json")
    assert out.code == 2
    assert out.message.startswith("the CPU went to STOP: Cycle time exceed 6.000 seconds at line 3")


def test_memory_is_sized_from_code_never_from_a_comment():
    text = COUNT.replace("BEGIN\n", "BEGIN\n// MD999999996 in a comment\nTITLE = MD888888888\n")
    assert m_bytes_used(text) == 4
    r = AwlRunner(text, default_map("s7-300"), first_scan=False)
    assert len(r.mem) == 2048  # awlsim's default, what a CPU 315-2 DP has


@pytest.mark.parametrize(("cpu", "top", "ok"), [(None, 2048, False), ("CPU 314", 256, False),
                                                ("317-2 DP", 4096, True)])  # fmt: skip
def test_memory_is_capped_at_the_target_cpu(tmp_path, cpu, top, ok):
    prog = tmp_path / "p.awl"
    prog.write_text(COUNT.replace("MD0", "MD2048"), encoding="utf-8")
    argv = ["stl-run", str(prog), "--dialect", "s7-300", "--read", "MD2048:DINT"]
    out = cli(*argv, *(["--cpu", cpu] if cpu else []))
    if ok:
        assert out.code == 0 and "MD2048 = 1" in out.stdout
    else:
        assert out.code == 2 and "beyond the CPU" in out.message
        assert f"M memory (MB0-MB{top - 1})" in out.message
    with pytest.raises(ValueError, match="beyond the runner's M memory"):
        AwlRunner("ORGANIZATION_BLOCK OB 1\nBEGIN\nL MD70000\nEND_ORGANIZATION_BLOCK\n",
                  default_map("s7-300"))  # fmt: skip


@pytest.mark.parametrize(("dialect", "limit"), [("s7-200", 8 * 1024 * 1024), ("s7-300", 1 << 20)])
def test_a_program_larger_than_the_limit_is_refused_while_reading(tmp_path, dialect, limit):
    prog = tmp_path / "big.txt"
    with prog.open("wb") as fh:  # sparse: the size without the memory
        fh.truncate(limit + 1)
    out = cli("stl-run", str(prog), "--dialect", dialect, "--read", "MD0:DINT")
    assert out.code == 2 and f"larger than {limit:,} bytes" in out.message


def test_special_files_are_refused(tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    for path, kind in (("/dev/zero", "a character device"), (str(fifo), "a FIFO"),
                       (str(tmp_path), "a directory")):  # fmt: skip
        out = cli("stl-run", path, "--dialect", "s7-300", "--read", "MD0:DINT")
        assert out.code == 2 and kind in out.message, out.message


class _Endless(io.RawIOBase):
    """Standard input that never ends; counts what was read."""

    def __init__(self):
        self.taken = 0

    def readable(self):
        return True

    def readinto(self, b):
        b[:] = b"L MD0\n" * (len(b) // 6) + b"\n" * (len(b) % 6)
        self.taken += len(b)
        return len(b)


def test_an_endless_standard_input_is_read_to_the_limit_only(monkeypatch):
    raw = _Endless()
    fake = io.TextIOWrapper(io.BufferedReader(raw), encoding="utf-8")
    monkeypatch.setattr("sys.stdin", fake)
    out = cli("stl-run", "-", "--dialect", "s7-300", "--read", "MD0:DINT")
    assert out.code == 2 and "longer than 1,048,576 bytes" in out.message
    assert raw.taken < 2 * (1 << 20)
