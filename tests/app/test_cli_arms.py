"""``python -m analysis arms`` lists every file of data/arms/, the picker's dimensions-only
description included (it has no D-H rows; the command used to stop on it)."""

import json

from analysis.app.cli import main


def test_arms_lists_every_description(capsys):
    assert main(["arms"]) == 0
    out = capsys.readouterr().out
    lines = {line.split()[0]: line for line in out.splitlines()}
    assert set(lines) >= {"grabber", "palletizer", "picker"}
    assert "L1 = 200 mm (assumed)" in lines["palletizer"]
    assert "x_A = 100 mm (assumed)" in lines["picker"]
    assert main(["arms", "--json"]) == 0
    docs = {d["name"]: d for d in json.loads(capsys.readouterr().out)}
    assert (
        docs["picker"]["joints"] == [] and docs["picker"]["parameters"]["g"]["status"] == "assumed"
    )
