"""Issue 31 item 6: a command line without slips, each as a user meets it (in-process
``analysis.app.cli.main``; the help examples as typed, in a shell)."""

from __future__ import annotations

import csv
import io
import json
import re
import shlex
import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from analysis.app.cli import build_parser, main
from analysis.kinematics.arm import load_arm
from analysis.kinematics.pose import fk_document
from analysis.paths import data_dir

PROJECT = Path(__file__).resolve().parents[2]


def run(capsys, *argv: str) -> tuple[int, str, str]:
    try:
        code = main(list(argv))
    except SystemExit as exc:
        code = exc.code
    out, err = capsys.readouterr()
    return code, out, err


def _examples() -> list[str]:
    """Every example line of every ``--help`` (the main one first), as typed."""
    parser = build_parser()
    sub = next(a for a in parser._actions if a.choices and "ik" in a.choices)
    texts = [parser.format_help(), *(p.format_help() for p in sub.choices.values())]
    lines = []
    for text in texts:
        if "examples:" not in text:
            continue
        for line in text.split("examples:", 1)[1].splitlines():
            line = line.strip()
            if line.startswith("python -m analysis"):
                # the explanation after the command: two or more spaces, or a shell comment
                line = re.split(r"\s{2,}|\s#", line)[0]
                if line not in lines:
                    lines.append(line)
    return lines


@pytest.mark.slow
def test_every_help_example_runs_and_exits_0(tmp_path, capsys, monkeypatch):
    """What every ``--help`` shows runs as shown (issue 31 item 6: the GR-1 example printed
    by ``ik --help`` exited 2), in a folder holding the files the examples name; in-process,
    ``< file`` and ``> file`` done as the shell would."""
    from analysis.plc import st_engine

    try:
        st_engine.machine_engine_path()
        engine = True
    except st_engine.EngineMissing:  # built by make st-engine (g++)
        engine = False
    examples = _examples()
    assert len(examples) >= 15, examples
    monkeypatch.chdir(tmp_path)
    for name in ("targets.csv", "in.csv"):
        (tmp_path / name).write_text("x_mm,y_mm,z_mm\n100,100,600\n200,500,600\n")
    (tmp_path / "s.csv").write_text("t_s,name,value\n0,Enable,TRUE\n")
    shutil.copyfile(data_dir() / "arms" / "palletizer.toml", tmp_path / "my_arm.toml")
    shutil.copytree(Path(__file__).parents[1] / "audit" / "example", tmp_path / "example")
    failed, ran = [], 0
    for line in examples:
        if (("--dialect st" in line and "stl-run" in line) or " play " in line) and not engine:
            continue  # play: the trace that stl-run's example writes on the engine
        if line.startswith("python -m analysis report"):
            continue  # the whole site (minutes): tests/browser builds it with build_report
        argv = shlex.split(line)[3:]  # after "python -m analysis"
        for tok in argv:  # a file of the repository (tests/audit/example/paper.toml): its folder
            src = PROJECT / tok
            if "/" in tok and src.is_file() and not (tmp_path / tok).exists():
                shutil.copytree(src.parent, tmp_path / Path(tok).parent, dirs_exist_ok=True)
        out = None
        if ">" in argv:
            out = argv.pop(argv.index(">") + 1)
            argv.remove(">")
        if "<" in argv:
            given = argv.pop(argv.index("<") + 1)
            argv.remove("<")
            data = io.BytesIO((tmp_path / given).read_bytes())
            monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(data))
        code, stdout, err = run(capsys, *argv)
        ran += 1
        if out:
            (tmp_path / out).write_text(stdout)
        if code != 0:
            failed.append(f"{line}: exit {code}: {err.strip()[-300:]}")
    assert not failed, "\n".join(failed)
    assert ran >= 14


def test_ik_json_has_one_shape_for_every_arm_and_branch_option(capsys):
    """The arm, every requested branch with its status, whatever the arm and --branch."""
    docs = []
    for argv in (["ik", "100", "100", "600"], ["ik", "100", "100", "600", "--branch", "all"],
                 ["ik", "250", "0", "100", "--arm", "palletizer"]):  # fmt: skip
        code, out, _ = run(capsys, *argv, "--json")
        assert code == 0, out
        docs.append(json.loads(out))
    q = [30.0, 40.0, -60.0, -70.0, 10.0]
    target = fk_document(load_arm("gr1"), q)["target"]
    code, out, _ = run(capsys, "ik", *map(str, target), "--arm", "gr1", "--branch", "all",
                       "--json")  # fmt: skip
    assert code == 0, out
    docs.append(json.loads(out))
    keys = {frozenset(d) for d in docs}
    assert keys == {frozenset({"arm", "target", "reachable", "solutions", "branches",
                               "missing"})}, keys  # fmt: skip
    assert [d["arm"] for d in docs] == ["grabber", "grabber", "palletizer", "gr1"]
    for d in docs:
        assert all(s["status"] == "ok" for s in d["solutions"])
        assert all(m["status"] != "ok" and m["reason"] for m in d["missing"])
    gr1 = docs[-1]
    assert len(gr1["solutions"]) + len(gr1["missing"]) == gr1["branches"] == 4
    # the configuration fk was given is among the solutions (its branch marked ok)
    got = [s["theta_deg"] for s in gr1["solutions"]]
    assert np.min(np.abs(np.subtract(got, q)).max(axis=1)) < 1e-6


def _batch(capsys, tmp_path, text: str, *extra: str) -> list[dict]:
    src = tmp_path / "in.csv"
    src.write_text(text)
    code, out, err = run(capsys, "ik", "--input", str(src), "--output", "-", *extra)
    assert code == 0, err
    return list(csv.DictReader(io.StringIO(out)))


def test_batch_reason_is_filled_for_every_row_that_is_not_ok(capsys, tmp_path):
    """Out of reach, on the base axis, a bad number: each row says why, in the explorers'
    sentence; the distance is the one ``ik`` reports for the same target alone."""
    rows = _batch(capsys, tmp_path, "x_mm,y_mm,z_mm\n100,100,600\n5000,0,0\n0,0,900\n1,2,x\n",
                  "--branch", "all")  # fmt: skip
    assert len(rows) == 16
    for r in rows:
        assert (r["status"] == "ok") == (r["reason"] == ""), r
    _, out, _ = run(capsys, "ik", "5000", "0", "0", "--json")
    distance = json.loads(out)["distance_mm"]
    far = [r for r in rows if r["x_mm"] == "5000"]
    assert {r["reason"] for r in far} == {f"the target is {distance:.3f} mm beyond the reach"}
    axis = {r["reason"] for r in rows if r["z_mm"] == "900"}
    assert len(axis) == 1 and "--theta1-on-axis" in axis.pop()
    assert "'x' is not a number" in next(r["reason"] for r in rows if r["z_mm"] == "x")


def test_batch_header_aliases_x_y_z_solve_as_x_mm_y_mm_z_mm(capsys, tmp_path):
    """``x,y,z`` (and any of them mixed with the full names) read as ``x_mm, ...``; the
    input columns are echoed under their own names."""
    body = "100,100,600\n250,0,100\n"
    full = _batch(capsys, tmp_path, "x_mm,y_mm,z_mm\n" + body)
    for head in ("x,y,z", "x_mm,y,z", "x;y;z"):
        short = _batch(capsys, tmp_path, head + "\n" + body.replace(",", head[1] if ";" in head
                                                                     else ","))  # fmt: skip
        assert list(short[0])[:3] == re.split("[,;]", head)
        assert [list(r.values())[3:] for r in short] == [list(r.values())[3:] for r in full]
    src = tmp_path / "bad.csv"
    src.write_text("a,y,z\n1,2,3\n")
    code, _, err = run(capsys, "ik", "--input", str(src), "--output", "-")
    assert code == 2 and "x_mm (or x)" in err and "the header has: a, y, z" in err


def test_a_bad_number_names_the_column_as_the_header_wrote_it(capsys, tmp_path):
    """Under an alias (``z`` for ``z_mm``) a bad number, a coordinate beyond a REAL's range
    and ``--strict``'s error name the column ``z``, as the header says; the full name where
    the header has it."""
    rows = _batch(capsys, tmp_path, "x,y_mm,z\n1,2,x\n1,2,1e39\n1,x,3\n")
    assert "line 2 column z: 'x' is not a number" in rows[0]["reason"], rows[0]
    assert "line 3 column z: z = 1e+39 mm is beyond" in rows[1]["reason"], rows[1]
    assert "line 4 column y_mm: 'x'" in rows[2]["reason"], rows[2]
    assert "z_mm" not in rows[0]["reason"] + rows[1]["reason"]
    src = tmp_path / "strict.csv"
    src.write_text("x,y_mm,z\n1,2,x\n")
    code, _, err = run(capsys, "ik", "--input", str(src), "--output", "-", "--strict")
    assert code == 2 and "line 2 column z: 'x' is not a number" in err, err


@pytest.mark.parametrize(
    ("dialect", "read", "guess"), [("s7-200", "VD100:DINT", "st"), ("s7-300", "MD0:DINT", "st")]
)
def test_stl_run_names_the_dialect_it_expected(capsys, tmp_path, dialect, read, guess):
    """An ST program given as S7 STL: the error names the dialect expected and the one the
    text looks like (it said ``'(*' unknown instruction``)."""
    prog = tmp_path / "p.st"
    code, _, err = run(capsys, "stl", "--dialect", "st", "-o", str(prog))
    assert code == 0, err
    code, _, err = run(capsys, "stl-run", str(prog), "--dialect", dialect, "--read", read)
    assert code == 2 and f"--dialect {dialect} expects" in err, err
    assert err.rstrip().endswith(f"--dialect {guess})"), err


def test_dash_is_stdio_for_every_output_option_or_refused(capsys, tmp_path, monkeypatch):
    """``-`` is standard output for every file output (no file named ``-``), and refused in
    one line where the output is a folder (``report --out``)."""
    monkeypatch.chdir(tmp_path)
    code, out, _ = run(capsys, "stl", "--dialect", "s7-200", "-o", "p.awl", "--map", "-")
    assert code == 0 and json.loads(out)["dialect"] == "s7-200"
    code, out, _ = run(capsys, "urdf", "-o", "-")
    assert code == 0 and out.startswith("<?xml")
    code, _, err = run(capsys, "report", "--out", "-")
    assert code == 2 and "--out -" in err
    assert not (tmp_path / "-").exists()


@pytest.mark.parametrize("scenario", [False, True])
def test_stl_run_without_the_engine_is_one_line(capsys, tmp_path, monkeypatch, scenario):
    """The ST engine not built (or built from other sources) is said in one line naming
    ``make st-engine``, exit 2: not a traceback (a fresh clone before ``make st-engine``)."""
    from analysis.plc import st_engine

    for env in (st_engine.ENGINE_ENV, st_engine.MACHINE_ENGINE_ENV):
        monkeypatch.setenv(env, str(tmp_path / "not-built"))
    prog, mp = tmp_path / "g.st", tmp_path / "g.json"
    assert run(capsys, "stl", "--dialect", "st", "-o", str(prog), "--map", str(mp))[0] == 0
    argv = ["stl-run", str(prog), "--dialect", "st", "--map", str(mp)]
    if scenario:
        sc = tmp_path / "s.csv"
        sc.write_text("t_s,name,value\n0,Enable,TRUE\n", encoding="utf-8")
        argv += ["--scenario", str(sc), "--trace", str(tmp_path / "t.csv")]
    else:
        argv += ["--set", "Enable=TRUE", "--read", "Homed"]
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "not-built" in err and "make st-engine" in err, err
    assert not (tmp_path / "t.csv").exists()
