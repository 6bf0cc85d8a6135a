"""Every generated output of the project, written to one folder, to diff two versions byte for
byte (issue 28 item 5: "behaviour unchanged").

    .venv/bin/python tools/outputs_snapshot.py build/snap-before
    ... change the code ...
    .venv/bin/python tools/outputs_snapshot.py build/snap-after
    diff -r build/snap-before build/snap-after && echo identical

Written: every PLC program and MAP.json (every arm x every dialect x the trig and motion
options, and each arm's every branch in S7-300 AWL), every arm's URDF, batch CSVs (Table 4 on
the paper's arm, sampled targets on every other arm, every branch), ``ik --json`` of sampled
targets, ``fk --json``, ``arms --json``, the compiled kernels' generated source, the
explorer's JavaScript closed forms and the golden files' regenerations. The arms: the four of
``data/arms``, the three D-H seed arms with their derived closed forms (the description
without ``closed_form``) and a user's arm that names ``closed_form = "grabber"`` (README).
The process runs every command in-process through :func:`analysis.app.cli.main`. The package
imported is the installed one (the checkout's ``src``); ``PYTHONPATH=<other>/src`` snapshots
another version with the same script.
"""

from __future__ import annotations

import contextlib
import io
import json
import re
import shutil
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
DIALECTS = ("s7-200", "s7-300", "st", "scl", "plcopen-xml")


def _cli(argv: list[str]) -> tuple[int, str, str]:
    from analysis.app.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(argv)
    return rc, out.getvalue(), err.getvalue()


def _arms(work: Path) -> dict[str, str]:
    """Arm name -> the --arm argument."""
    arms = {n: n for n in ("grabber", "palletizer", "gr1", "picker")}
    for name in ("grabber", "palletizer", "gr1"):
        text = (ROOT / "data" / "arms" / f"{name}.toml").read_text()
        text = re.sub(r'(?m)^closed_form = ".*"\n', "", text)
        text = text.replace(f'name = "{name}"', f'name = "{name}_derived"', 1)
        folder = work / "derived"
        folder.mkdir(exist_ok=True)
        if name == "grabber":
            shutil.copy(ROOT / "data" / "table3.csv", folder / "table3.csv")
        (folder / f"{name}-derived.toml").write_text(text)
        arms[f"{name}-derived"] = str(folder / f"{name}-derived.toml")
    readme = (ROOT / "README.md").read_text()
    mine = re.search(r"```toml\n# my_arms/mine.toml\n(.*?)```", readme, re.S)
    if mine:
        (work / "mine.toml").write_text(mine.group(1))
        arms["mine"] = str(work / "mine.toml")
    return arms


def _targets(arm, n: int = 12) -> np.ndarray:
    rng = np.random.default_rng(20240611)
    q = arm.sample_q(rng, n)
    return arm.target(q)


def snapshot(out: Path) -> None:
    from analysis.kinematics.arm import load_arm

    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    work = out / "_inputs"
    work.mkdir()
    log = []

    def run(name: str, argv: list[str]) -> None:
        rc, so, se = _cli(argv)
        text = so.replace(str(out), "<OUT>")
        se = se.replace(str(out), "<OUT>")
        (out / f"{name}.stdout").write_text(f"rc={rc}\n{text}\n--- stderr\n{se}")
        log.append(f"{name}: rc={rc}")

    for key, spec in _arms(work).items():
        d = out / key
        d.mkdir()
        arm = load_arm(spec)
        for dialect in DIALECTS:
            ext = {"s7-200": "awl", "s7-300": "awl", "st": "st", "scl": "scl"}.get(dialect, "xml")
            base = ["stl", "--arm", spec, "--dialect", dialect]
            run(f"{key}/stl-{dialect}", [*base, "-o", str(d / f"{dialect}.{ext}"),
                                         "--map", str(d / f"{dialect}.map.json")])  # fmt: skip
            variants = {"s7-300": [["--trig", "subroutine"]], "st": [["--trig", "native"]],
                        "s7-200": [["--no-motion"]]}.get(dialect, [])  # fmt: skip
            for v in variants:
                tag = "-".join(x.strip("-") for x in v)
                out_files = ["-o", str(d / f"{dialect}-{tag}.{ext}"),
                             "--map", str(d / f"{dialect}-{tag}.map.json")]  # fmt: skip
                run(f"{key}/stl-{dialect}-{tag}", [*base, *v, *out_files])
        for b in arm.branches[1:]:
            argv = ["stl", "--arm", spec, "--dialect", "s7-300", "--branch", b]
            run(f"{key}/stl-s7-300-{b}", [*argv, "-o", str(d / f"s7-300-{b}.awl")])
        run(f"{key}/urdf", ["urdf", "--arm", spec, "-o", str(d / "arm.urdf")])
        tg = _targets(arm)
        user = np.where(np.array([u == "deg" for u in arm.user_units]),
                        np.degrees(tg), tg)  # fmt: skip
        cols = [f"{n}_{u}" for n, u in zip(arm.inputs, arm.user_units, strict=True)]
        if arm.inputs[:3] == ("px", "py", "pz"):
            cols[:3] = ["x_mm", "y_mm", "z_mm"]
        if arm.inputs[3:] == ("alpha", "beta", "gamma"):
            cols[3:] = ["alpha_deg", "beta_deg", "gamma_deg"]
        csv = work / f"{key}-targets.csv"
        csv.write_text(",".join(cols) + "\n" + "".join(
            ",".join(repr(float(v)) for v in row) + "\n" for row in user))  # fmt: skip
        run(f"{key}/batch", ["ik", "--arm", spec, "--input", str(csv), "--output",
                             str(d / "batch.csv"), "--branch", "all"])  # fmt: skip
        for i, row in enumerate(user[:4]):
            run(f"{key}/ik-{i}", ["ik", "--arm", spec, "--branch", "all", "--json",
                                  *(repr(float(v)) for v in row)])  # fmt: skip
        q = arm.joints_to_user(arm.sample_q(np.random.default_rng(7), 3))
        for i, row in enumerate(q):
            run(f"{key}/fk-{i}", ["fk", "--arm", spec, "--json", *(repr(float(v)) for v in row)])
        from analysis.kinematics import compiled

        if compiled.HAVE_NUMBA:
            kern = compiled.ik_kernel(arm.closed_form, tuple(arm.params), arm.branches,
                                      tuple(arm.limits))  # fmt: skip
            (d / "ik_kernel.py").write_text(kern.source)
        try:
            from analysis.app.explore_js import arm_module_js

            (d / "explore.js").write_text(arm_module_js(arm))
        except (ImportError, ValueError) as exc:
            (d / "explore.js").write_text(f"unavailable: {exc}")
    run("batch-table4", ["ik", "--input", str(ROOT / "data" / "table4.csv"), "--output",
                         str(out / "table4.csv"), "--branch", "all"])  # fmt: skip
    run("arms", ["arms", "--json"])
    (out / "log.txt").write_text("\n".join(log) + "\n")


if __name__ == "__main__":
    snapshot(Path(sys.argv[1]).resolve())
    import analysis

    print(json.dumps({"written": sys.argv[1], "package": str(Path(analysis.__file__).parent)}))
