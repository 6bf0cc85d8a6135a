"""``python -m analysis stl-run`` (issue 22 item 3, a contract): run a program from a shell."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from analysis.app.cli import main
from analysis.kinematics.arm import paper_arm
from analysis.plc.generate import generate

ROOT = Path(__file__).resolve().parents[2]
ROW1 = ["--set", "VD0=100.0", "--set", "VD4=100.0", "--set", "VD8=600.0"]


@pytest.fixture(scope="module")
def programs(tmp_path_factory):
    d = tmp_path_factory.mktemp("stl-run")
    out = {}
    for dialect in ("s7-200", "s7-300"):
        text, _ = generate(paper_arm(), dialect)
        p = d / f"ik-{dialect}.awl"
        p.write_bytes(text.encode("utf-8"))
        out[dialect] = p
    return out


def _run(capsys, *argv):
    code = main(["stl-run", *map(str, argv)])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.slow
def test_the_contract_from_a_shell(programs):
    """The issue's command line, in a subprocess as a user runs it: exit 0 and exactly
    {"values": {...}} (Table 4 row 1: 500 pulses, reachable)."""
    cmd = [
        sys.executable,
        "-m",
        "analysis",
        "stl-run",
        str(programs["s7-200"]),
        "--dialect",
        "s7-200",
        *ROW1,
        "--read",
        "VD100:DINT",
        "--read",
        "V112.0:BOOL",
        "--json",
    ]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout) == {"values": {"VD100": 500, "V112.0": True}}


def test_every_type_and_the_text_output(programs, capsys):
    code, out, _ = _run(
        capsys,
        programs["s7-200"],
        "--dialect",
        "s7-200",
        *ROW1,
        "--read",
        "VD104:DINT",
        "--read",
        "VD108:DINT",
        "--read",
        "VD116:DINT",
        "--read",
        "VD0:REAL",
        "--read",
        "VB120:BYTE",
        "--read",
        "VW0:INT",
        "--read",
        "V112.0:BOOL",
        "--scans",
        "3",
    )
    assert code == 0
    assert out.splitlines() == [
        "VD104 = 113 (DINT)",
        "VD108 = -1724 (DINT)",
        "VD116 = 0 (DINT)",
        "VD0 = 100.0 (REAL)",
        "VB120 = 0 (BYTE)",
        "VW0 = 17096 (INT)",
        "V112.0 = 1 (BOOL)",
    ]


@pytest.mark.slow
def test_s7300_runs_awl_on_awlsim(programs, capsys):
    pytest.importorskip("awlsim")
    code, out, _ = _run(
        capsys,
        programs["s7-300"],
        "--dialect",
        "s7-300",
        "--set",
        "MD0=100.0",
        "--set",
        "MD4=100.0",
        "--set",
        "MD8=600.0",
        "--read",
        "MD100:DINT",
        "--read",
        "M112.0:BOOL",
        "--json",
    )
    assert code == 0 and json.loads(out) == {"values": {"MD100": 500, "M112.0": True}}


@pytest.mark.parametrize(
    ("args", "why"),
    [
        (["--set", "VD0=100"], "reads VD0 as a REAL; write 100.0"),
        (["--set", "VD0=1e39"], "beyond 3.403e+38, the largest REAL"),
        (["--set", "VB120=300"], "outside the BYTE range 0..255"),
        (["--set", "VD0"], "expected ADDRESS=VALUE"),
        (["--read", "VD100"], "expected ADDRESS:TYPE"),
        (["--read", "VD100:LREAL"], "not one of BOOL"),
        (["--read", "VW100:REAL"], "a word holds INT or WORD"),
        (["--read", "VD8192:DINT"], "beyond the CPU 224's V memory"),
        (["--read", "MD100:DINT"], "beyond the CPU 224's M memory (MB0-MB31)"),
        (["--read", "DB1.DBD0:DINT"], "not an s7-200 address"),
        (["--scans", "0"], "at least one scan"),
        (["--cpu", "CPU 314"], "is an s7-300 CPU, not an s7-200 one"),
        (["--cpu", "CPU 999"], "not known for s7-200 (known: CPU 221"),
        (["--set", "VD0=nan"], "'nan' is not a finite number; to store a REAL nan on purpose"),
        (["--set", "VD0=1_000.0"], "no underscores"),
        (["--set", "VD0=1,5"], "the decimal mark is '.'"),
        (["--set", "VD0=\u0663.0"], "digits must be ASCII"),
        (["--set", "VW4=\u0663"], "digits must be ASCII"),
        (["--set", "VW4=1.5"], "a INT is a whole number, not '1.5'"),
        (["--set", "VD0=1e999"], "beyond the float range"),
        (["--set", "VD0="], "the value is empty"),
        (["--set", "VW4=1\u00a0"], "is not a number"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(programs, capsys, args, why):
    base = [programs["s7-200"], "--dialect", "s7-200"]
    if not any(a == "--read" for a in args):
        base += ["--read", "VD100:DINT"]
    code, out, err = _run(capsys, *base, *args)
    assert code == 2 and len(err.strip().splitlines()) == 1 and why in err, err
    code, out, _ = _run(capsys, *base, *args, "--json")
    assert code == 2 and why in json.loads(out)["error"]


def test_a_program_error_names_the_line(tmp_path, capsys):
    p = tmp_path / "mine.awl"
    p.write_text(
        "ORGANIZATION_BLOCK MAIN:OB1\nBEGIN\nNetwork 1\nLD SM0.0\nMOVR 9.0 VD92\n"
        "END_ORGANIZATION_BLOCK\n"
    )
    code, _, err = _run(capsys, p, "--dialect", "s7-200", "--read", "VD92:REAL")
    assert code == 2 and "line 5 (MAIN (OB1), network 1)" in err and "comma" in err
    code, _, err = _run(
        capsys, tmp_path / "missing.awl", "--dialect", "s7-200", "--read", "VD0:REAL"
    )
    assert code == 2 and "cannot read" in err


def test_a_cpu_stop_is_reported_with_what_was_read(tmp_path, capsys):
    """A NaN in a REAL compare stops an S7-200 (S2M p.96): exit 2, where, and the values."""
    p = tmp_path / "cmp.awl"
    p.write_text("LD SM0.0\nMOVR 1.0, VD4\nLDR< VD0, 1.0\n= V8.0\n")  # a bare listing
    code, out, _ = _run(
        capsys, p, "--dialect", "s7-200", "--set", "VD0=nan:REAL", "--read", "VD4:REAL", "--json"
    )
    doc = json.loads(out)
    assert code == 2 and "line 3" in doc["error"] and "STOP" in doc["error"]
    assert doc["values"] == {"VD4": 1.0}
    code, out, _ = _run(
        capsys,
        p,
        "--dialect",
        "s7-200",
        "--set",
        "VD0=-inf:REAL",
        "--read",
        "VD0:REAL",
        "--read",
        "V8.0:BOOL",
        "--json",
    )
    assert code == 0 and json.loads(out) == {"values": {"VD0": "-Infinity", "V8.0": True}}


@pytest.mark.parametrize(
    ("argv", "code", "said"),
    [
        (["--dialect", "s7-200", "--arm", "gr1", "--cpu", "221"], 0, "CPU 221"),
        (["--dialect", "s7-300", "--cpu", "cpu317-2dp"], 0, "CPU 317-2 DP"),
        (["--dialect", "s7-300", "--arm", "gr1", "--cpu", "314"], 2,
         "the work area ends at MB351, beyond the CPU 314's M memory (MB0-MB255)"),
        (["--dialect", "s7-300", "--cpu", "312"], 2, "beyond the CPU 312's M memory (MB0-MB127)"),
        (["--dialect", "s7-200", "--cpu", "999"], 2, "target CPU '999' is not known for s7-200"),
        (["--dialect", "s7-300", "--cpu", "224"], 2, "is an s7-200 CPU, not an s7-300 one"),
        (["--dialect", "st", "--cpu", "224"], 2, "--cpu applies to --dialect s7-200 and s7-300"),
    ],
)  # fmt: skip
def test_stl_checks_the_target_cpu(tmp_path, capsys, argv, code, said):
    """``stl --cpu NAME``: the program and MAP.json checked against that CPU's memory at
    generation (memmap.CPUS); the map names it; a program that does not fit is refused with
    the CPU and the limit."""
    prog, mp = tmp_path / "p.awl", tmp_path / "p.json"
    got = main(["stl", *argv, "-o", str(prog), "--map", str(mp), "--json"])
    out = capsys.readouterr().out
    doc = json.loads(out)
    assert got == code, out
    if code == 0:
        assert doc["cpu"] == said == json.loads(mp.read_text())["target_cpu"]["name"]
    else:
        assert said in doc["error"] and not prog.exists()
