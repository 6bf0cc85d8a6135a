"""``make bench``: the report build (``python -m analysis report``) as a whole process.

Three runs into a scratch site folder: *cold* (an empty cache: every notebook executed, the
front page computed, Sphinx, the PDF), *warm* (nothing changed: the build sees that the site
is current), and *one notebook changed* (a copy of the notebooks with one code cell of
notebook 09 touched: that notebook executed, the others from the cache, the site rebuilt).
Targets (issue 23): cold under 60 s, warm under 15 s, on the 2-core reference machine when
idle; the load average is recorded with each run.

Usage: ``python benchmarks/report_build.py --out build/bench-report.json``
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PROJECT = Path(__file__).resolve().parents[1]


def _run(out: Path, cache: Path, notebooks: list[Path] | None = None) -> dict:
    env = os.environ | {
        "ANALYSIS_REPORT_CACHE": str(cache),
        "MPLBACKEND": "module://matplotlib_inline.backend_inline",
    }
    cmd = [sys.executable, "-m", "analysis", "report", "--out", str(out)]
    if notebooks:
        cmd += ["--notebooks", *(str(p) for p in notebooks)]
    load = os.getloadavg()[0]
    t = time.perf_counter()
    run = subprocess.run(cmd, cwd=PROJECT, env=env, capture_output=True, text=True)
    dt = time.perf_counter() - t
    tail = (run.stdout + run.stderr).strip().splitlines()[-1:]
    return {
        "seconds": round(dt, 1),
        "exit": run.returncode,
        "load_before": round(load, 2),
        "load_after": round(os.getloadavg()[0], 2),
        "last_line": tail[0] if tail else "",
    }


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", type=Path, default=PROJECT / "build" / "bench-report.json")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="bench-report-") as tmp:
        tmp = Path(tmp)
        site, cache = tmp / "report", tmp / "cache"
        result = {"cpus": os.cpu_count(), "targets_s": {"cold": 60, "warm": 15}}
        result["cold"] = _run(site, cache)
        result["warm"] = _run(site, cache)
        nbs = tmp / "notebooks"
        shutil.copytree(PROJECT / "notebooks", nbs)
        nb = nbs / "09_explore.ipynb"
        doc = json.loads(nb.read_text())
        code = next(c for c in doc["cells"] if c["cell_type"] == "code")
        code["source"] = "".join(code["source"]) + "\n# touched by benchmarks/report_build.py\n"
        nb.write_text(json.dumps(doc))
        result["one_changed"] = _run(site, cache, sorted(nbs.glob("[0-9][0-9]_*.ipynb")))
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=1) + "\n")
    print(json.dumps(result, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
