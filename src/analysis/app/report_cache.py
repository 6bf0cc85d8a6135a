"""What ``make report`` keeps between builds: executed notebooks and the front page's data.

* **Executed notebooks** live in a jupyter-cache store (``build/report-cache/notebooks``;
  ``jupyter-cache`` is the cache that MyST-NB's ``cache`` mode uses, pinned in the lock). A
  notebook is matched by its code cells and kernel (jupyter-cache's hash) *and* by
  :func:`inputs_digest`, the digest of everything its outputs depend on besides its own code
  (the ``analysis`` package's sources, ``data/``, ``requirements.lock``): a change to a
  closed form re-executes every notebook, a change to one notebook's code re-executes that
  one. The figures a run saved are stored with it as jupyter-cache artifacts and put back on
  a hit. A notebook that raised is never stored.
* **The front page's data** (:func:`analysis.app.frontpage.front_page_data`: registers, the
  PLC programs on awlsim, the quantization statistics) is pickled under the same digest.

Why not MyST-NB's own ``nb_execution_mode = "cache"``: it hashes the notebook's code only, so
a change in ``src/analysis`` would serve stale outputs, and it executes inside Sphinx with
no progress and without the figure collection of :mod:`analysis.app.report`.
"""

from __future__ import annotations

import copy
import hashlib
import io
import os
import pickle
from pathlib import Path

import nbformat

from analysis.paths import PROJECT

__all__ = [
    "CACHE_DIR",
    "INPUTS_KEY",
    "SITE_ONLY",
    "NotebookCache",
    "cached_front_page",
    "inputs_digest",
    "site_digest",
]

CACHE_DIR = Path(os.environ.get("ANALYSIS_REPORT_CACHE") or PROJECT / "build" / "report-cache")
"""Where the cache lives (``$ANALYSIS_REPORT_CACHE`` overrides: ``make bench`` times a cold
build with an empty one)."""
INPUTS_KEY = "analysis_inputs"
"""Notebook metadata key holding :func:`inputs_digest` (hashed by jupyter-cache with the code)."""


SITE_ONLY = (
    "src/analysis/app/report.py",
    "src/analysis/app/report_cache.py",
    "src/analysis/app/report_files.py",
    "src/analysis/app/report_notebooks.py",
    "src/analysis/app/site_content.py",
    "src/analysis/app/site_explorer.py",
    "src/analysis/app/site_notebooks.py",
    "src/analysis/app/frontpage.py",
)
"""Modules that only build the site (no notebook imports them): a change to them does not
re-execute the notebooks (the front page's data is keyed with them, :func:`site_digest`)."""


def inputs_digest(root: Path = PROJECT, exclude: tuple[str, ...] = SITE_ONLY) -> str:
    """SHA-256 over the files every notebook's outputs depend on besides its own code: the
    package (``src/analysis``: Python, JavaScript, data files) but the modules that only
    build the site (``exclude``), ``data/`` and the lock."""
    h = hashlib.sha256()
    files = [root / "requirements.lock"]
    for top in ("src/analysis", "data"):
        files += [
            p for p in (root / top).rglob("*") if p.is_file() and "__pycache__" not in p.parts
        ]
    skip = {root / e for e in exclude}
    for f in sorted(f for f in files if f not in skip):
        if f.exists():
            h.update(f.relative_to(root).as_posix().encode() + b"\0" + f.read_bytes() + b"\0")
    return h.hexdigest()


def site_digest(root: Path = PROJECT) -> str:
    """:func:`inputs_digest` with the site's own modules: the key of the front page's data."""
    return inputs_digest(root, exclude=())


class NotebookCache:
    """Executed notebooks with their figures, keyed by code and :func:`inputs_digest`."""

    def __init__(self, folder: Path = CACHE_DIR / "notebooks", digest: str | None = None):
        from jupyter_cache.cache.main import JupyterCacheBase

        class _Cache(JupyterCacheBase):
            def create_hashed_notebook(self, nb, nb_metadata=("kernelspec", INPUTS_KEY),
                                       cell_metadata=None):  # fmt: skip
                return super().create_hashed_notebook(nb, nb_metadata, cell_metadata)

        folder.mkdir(parents=True, exist_ok=True)
        self.cache = _Cache(str(folder))
        self.digest = digest or inputs_digest()

    def _keyed(self, nb: nbformat.NotebookNode) -> nbformat.NotebookNode:
        nb = copy.deepcopy(nb)
        nb.metadata[INPUTS_KEY] = self.digest
        return nb

    def get(self, nb: nbformat.NotebookNode, fig_dir: Path) -> nbformat.NotebookNode | None:
        """The executed notebook for ``nb`` (its stored form) with its figures written to
        ``fig_dir``; None if this code has not been executed with these inputs."""
        try:
            pk, merged = self.cache.merge_match_into_notebook(self._keyed(nb))
        except KeyError:
            return None
        bundle = self.cache.get_cache_bundle(pk)
        for rel, handle in bundle.artifacts or []:
            out = fig_dir / Path(rel).name
            out.write_bytes(handle.read())
        merged.metadata.pop(INPUTS_KEY, None)
        return merged

    def put(self, nb: nbformat.NotebookNode, uri: str, figures: list[Path], folder: Path) -> None:
        """Store an executed notebook and the figure files it saved (in ``folder``)."""
        from jupyter_cache.base import CacheBundleIn
        from jupyter_cache.cache.main import NbArtifacts

        self.cache.cache_notebook_bundle(
            CacheBundleIn(self._keyed(nb), uri, artifacts=NbArtifacts(figures, in_folder=folder)),
            check_validity=False,
            overwrite=True,
        )


def cached_front_page(compute, digest: str, folder: Path = CACHE_DIR):
    """``compute()`` (the front page's sections), or its pickled result for ``digest``."""
    path = folder / f"front-page-{digest[:20]}.pickle"
    if path.exists():
        try:
            return pickle.loads(path.read_bytes())
        except Exception:  # a cache written by other versions: compute again
            path.unlink()
    value = compute()
    folder.mkdir(parents=True, exist_ok=True)
    for old in folder.glob("front-page-*.pickle"):
        old.unlink()
    buf = io.BytesIO()
    pickle.dump(value, buf)
    tmp = path.with_suffix(".tmp")
    tmp.write_bytes(buf.getvalue())
    tmp.replace(path)
    return value
