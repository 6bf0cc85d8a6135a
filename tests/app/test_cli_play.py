"""``python -m analysis play TRACE.csv --arm ARM -o FILE.html`` (analysis.app.cli_play): a
machine run as a page that plays offline; bad input one line and exit 2."""

import json
import re

import pytest

from analysis.app.cli import main

TRACE = "t_s,q1,q2,q3,v1,v2,v3,Busy,Status\n0,0,0,0,0,0,0,FALSE,0\n0.5,10,20,-30,0,0,0,TRUE,101\n"


def _run(capsys, *argv):
    code = main(["play", *map(str, argv)])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.slow  # a 5 MB page, twice (about 3 s)
def test_a_trace_becomes_a_page_that_plays_offline(tmp_path, capsys):
    (tmp_path / "t.csv").write_text(TRACE, encoding="utf-8")
    page = tmp_path / "run.html"
    code, out, err = _run(capsys, tmp_path / "t.csv", "-o", page, "--frames", "2", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc == {"html": str(page), "arm": "grabber", "cycles": 2, "seconds": 0.5, "frames": 2}
    html = page.read_text("utf-8")
    assert "Plotly.newPlot" in html and len(html) > 3_000_000  # plotly.js inside
    assert not re.search(r"<script[^>]+src=", html)  # nothing fetched
    assert "Status 101 (not-homed)" in html and "tool frame" in html
    code, out, _ = _run(capsys, tmp_path / "t.csv", "-o", "-", "--frames", "2")
    assert (
        code == 0 and out.lower().startswith("<!doctype html>") and out.rstrip().endswith("</html>")
    )


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--arm", "gr1"], "3 joint position columns (q1, q2, q3); the arm has 5 joints"),
        (["--frames", "1"], "--frames 1: between 2 and 400"),
        (["--title", "x" * 201], "--title has 201 characters: at most 200"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(tmp_path, capsys, argv, message):
    (tmp_path / "t.csv").write_text(TRACE, encoding="utf-8")
    code, _, err = _run(capsys, tmp_path / "t.csv", "-o", tmp_path / "r.html", *argv)
    assert code == 2 and message in err and err.count("\n") == 1, err
    assert not (tmp_path / "r.html").exists()


def test_never_over_its_input(tmp_path, capsys):
    (tmp_path / "t.csv").write_text(TRACE, encoding="utf-8")
    code, _, err = _run(capsys, tmp_path / "t.csv", "-o", tmp_path / "t.csv")
    assert code == 2 and (tmp_path / "t.csv").read_text("utf-8") == TRACE, err
