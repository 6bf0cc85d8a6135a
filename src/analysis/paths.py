"""Where the project's files are: ``data/`` (inputs, read-only) and ``build/`` (outputs).

``$ANALYSIS_DATA_DIR`` overrides the data folder (tests use it to point at a copy).
"""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["PROJECT", "build_dir", "data_dir"]

PROJECT = Path(__file__).resolve().parents[2]
"""The checkout: the folder holding ``data/``, ``notebooks/`` and ``src/``."""


def data_dir() -> Path:
    """The project's ``data/`` folder (``$ANALYSIS_DATA_DIR`` overrides)."""
    env = os.environ.get("ANALYSIS_DATA_DIR")
    path = Path(env) if env else PROJECT / "data"
    if not path.is_dir():
        raise FileNotFoundError(
            f"data folder {path} not found; run from a checkout of the project "
            "or set ANALYSIS_DATA_DIR"
        )
    return path


def build_dir() -> Path:
    """The project's ``build/`` folder (generated files; not version-controlled)."""
    return PROJECT / "build"
