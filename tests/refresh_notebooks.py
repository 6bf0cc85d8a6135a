"""Re-execute notebooks top to bottom in a fresh kernel and store them with their outputs.

The stored outputs are nbval's reference (``make test`` compares against them), so a change
that alters what a notebook shows is committed together with the notebook re-executed by
this script (``make notebooks``, or ``make notebooks NB="notebooks/03_table4.ipynb ..."``).
Cells are stored without nbclient's timing metadata, and a cell's stream outputs coalesced
(how nbval compares them; how the kernel split them varies with load). The kernels get the
same environment as under ``make test``: the inline backend (``MPLBACKEND`` from the
Makefile) and ``PYTHONHASHSEED=0``.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import nbformat
from nbval.plugin import coalesce_streams

from analysis.app.report import execute_notebook


def main(argv: list[str]) -> int:
    paths = [Path(a) for a in argv] or sorted(Path("notebooks").glob("[0-9][0-9]_*.ipynb"))
    failed = 0
    for path in paths:
        t = time.perf_counter()
        nb = nbformat.read(path, as_version=4)
        try:
            execute_notebook(path, into=nb)
        except Exception as exc:  # report and keep the stored notebook unchanged
            print(f"{path}: FAILED ({type(exc).__name__}); not written", file=sys.stderr)
            print(str(exc)[-2000:], file=sys.stderr)
            failed += 1
            continue
        for cell in nb.cells:  # wall-clock stamps: they vary and would only make merges conflict
            cell.metadata.pop("execution", None)
            if cell.cell_type == "code":  # one stream output per name, as nbval compares them
                cell.outputs = coalesce_streams(cell.outputs)
        nbformat.write(nb, path)
        print(f"{path}: executed and stored in {time.perf_counter() - t:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
