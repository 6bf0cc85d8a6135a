"""Every generated PLC program and MAP.json, written to one folder (a byte-identity check).

    .venv/bin/python tools/plc_snapshot.py OUT_DIR

writes, through the ``stl`` command (the same code path a user takes), the program and the
MAP.json of every arm (the four of ``data/arms``, the README's user arm, and arms with a
derived closed form: one per family and D-H convention) x every branch x every dialect the
command offers, with the default options, plus the options that change the text (``--trig``,
``--no-motion``, ``--cpu``, ``--theta1-on-axis``), and ``MANIFEST.sha256`` (one line per file).
Run it before and after a change that must not move any output, then ``diff -r`` the two
folders (or the manifests). Nothing is compared here: the folders are the evidence.
"""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import io
import sys
import tempfile
from pathlib import Path

import numpy as np

from analysis.app.cli import main
from analysis.kinematics.arm import load_arm
from analysis.kinematics.derive.samples import random_arm
from analysis.paths import PROJECT

SEED_ARMS = ("grabber", "palletizer", "gr1", "picker")
VARIANTS = {
    "s7-200": [[], ["--no-motion"], ["--cpu", "224XP"]],
    "s7-300": [[], ["--trig", "subroutine"], ["--cpu", "317-2 DP"]],
    "st": [[], ["--trig", "native"], ["--trig", "subroutine"]],
    "scl": [[], ["--trig", "subroutine"]],
    "plcopen-xml": [[]],
}


def _user_arms(folder: Path) -> dict[str, str]:
    """The README's ``my_arms/mine.toml`` and one derived arm per family and convention."""
    readme = (PROJECT / "README.md").read_text(encoding="utf-8")
    section = readme.split("## One source per arm (and how to add one)")[1]
    toml = section.split("```toml\n", 1)[1].split("```", 1)[0]
    arms = {"mine": folder / "mine.toml"}
    arms["mine"].write_text(toml, encoding="utf-8")
    for k, (fam, conv) in enumerate(
        (f, c) for f in ("3R", "4R-kept", "5R") for c in ("standard", "modified")
    ):
        name = f"derived_{fam.replace('-', '_')}_{conv}"  # an identifier (the schema)
        path = folder / f"{name}.toml"
        path.write_text(random_arm(np.random.default_rng(11 + k), fam, conv, name), "utf-8")
        arms[name] = path
    return {k: str(v) for k, v in arms.items()}


def _stl(argv: list[str]) -> tuple[int, str]:
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:
            code = int(exc.code or 0)
    return code, err.getvalue().strip()


def snapshot(out: Path) -> int:
    out.mkdir(parents=True, exist_ok=True)
    n = 0
    with tempfile.TemporaryDirectory() as tmp:
        arms = {a: a for a in SEED_ARMS} | _user_arms(Path(tmp))
        for label, spec in arms.items():
            arm = load_arm(spec)
            for branch in arm.branches:
                for dialect, variants in VARIANTS.items():
                    for extra in variants:
                        tag = "_".join(e.replace(" ", "") for e in extra).lstrip("-") or "default"
                        stem = f"{label}__{branch}__{dialect}__{tag}"
                        argv = ["stl", "--arm", spec, "--branch", branch, "--dialect", dialect,
                                "-o", str(out / f"{stem}.prog"), "--map",
                                str(out / f"{stem}.map.json"), *extra]  # fmt: skip
                        code, err = _stl(argv)
                        if code != 0:  # a refusal is an output too
                            (out / f"{stem}.refused").write_text(err + "\n", encoding="utf-8")
                        n += 1
            if arm.inputs[:2] == ("px", "py") and "theta1" in arm.joint_names[0]:
                stem = f"{label}__axis__s7-300"
                code, err = _stl(["stl", "--arm", spec, "--dialect", "s7-300", "--theta1-on-axis",
                                  "30", "-o", str(out / f"{stem}.prog")])  # fmt: skip
                if code != 0:
                    (out / f"{stem}.refused").write_text(err + "\n", encoding="utf-8")
    lines = []
    for f in sorted(out.iterdir()):
        if f.name != "MANIFEST.sha256":
            lines.append(f"{hashlib.sha256(f.read_bytes()).hexdigest()}  {f.name}")
    (out / "MANIFEST.sha256").write_text("\n".join(lines) + "\n", encoding="utf-8")
    return n


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", type=Path)
    args = ap.parse_args()
    n = snapshot(args.out)
    print(f"{n} stl runs -> {args.out}", file=sys.stderr)
