"""``make lab``: JupyterLab on working copies of the notebooks, as root or not.

The notebooks in ``notebooks/`` are the references that nbval compares (``make test``), and
JupyterLab autosaves what it shows: the explorer of notebook 09 moved to another arm, widget
state, outputs of cells re-run by hand. So Lab never opens them: :func:`prepare` copies them
into ``build/lab/`` (a copy is refreshed only when the stored notebook is newer than it, e.g.
after ``make notebooks`` or a pull, so edits made in Lab survive a restart), and Lab's root
is that folder. To change a stored notebook, edit ``notebooks/NN_*.ipynb`` and run
``make notebooks NB=...``.

Chosen over a contents manager that strips outputs on save (it would still rewrite the
references, with whatever the user did) and over read-only files (Lab then refuses to save
at all, and asks on every autosave). ``--allow-root`` is passed when running as root (the
usual case in a container), where Jupyter otherwise exits.
"""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

from analysis.paths import PROJECT

__all__ = ["LAB_DIR", "command", "prepare"]

LAB_DIR = PROJECT / "build" / "lab"


def prepare(work: Path = LAB_DIR, source: Path | None = None) -> list[Path]:
    """Copy the numbered notebooks of ``source`` (default ``notebooks/``) into ``work`` where
    the copy is missing or older than the stored notebook; returns the copies refreshed."""
    source = source or PROJECT / "notebooks"
    work.mkdir(parents=True, exist_ok=True)
    fresh = []
    for nb in sorted(source.glob("[0-9][0-9]_*.ipynb")):
        dst = work / nb.name
        if not dst.exists() or dst.stat().st_mtime < nb.stat().st_mtime:
            shutil.copy2(nb, dst)
            fresh.append(dst)
    return fresh


def command(root: Path, *extra: str) -> list[str]:
    """The ``jupyter lab`` command serving ``root`` (``--allow-root`` when run as root)."""
    jupyter = Path(sys.executable).with_name("jupyter")
    root_flag = ["--allow-root"] if hasattr(os, "geteuid") and os.geteuid() == 0 else []
    return [str(jupyter), "lab", f"--ServerApp.root_dir={root}", *root_flag, *extra]


def main(argv: list[str]) -> None:
    fresh = prepare()
    print(
        f"JupyterLab works on copies in {LAB_DIR.relative_to(PROJECT)}/ "
        f"({len(fresh)} refreshed from notebooks/); the stored notebooks are nbval's "
        "references: change one in notebooks/ and run make notebooks NB=...",
        flush=True,
    )
    cmd = command(LAB_DIR, *argv)
    os.execv(cmd[0], cmd)


if __name__ == "__main__":
    main(sys.argv[1:])
