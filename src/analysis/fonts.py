"""The one CJK font of every figure and page: Noto Sans SC, from the pinned environment.

The papers print Chinese (Table 4's 无解, the registers' quotations of seeds 001 and 004), and
a figure that shows it must not depend on the fonts of whoever runs the notebook: with no
system CJK font, matplotlib draws empty boxes and warns on stderr (which nbval then reports as
an unexpected output of the cell). So the font comes with the environment: the PyPI package
``pylopdf-fonts-zh-cn`` (pinned in ``requirements.lock``) ships Google's Noto Sans SC Regular
(``NotoSansSC-Regular.otf``, SIL Open Font License 1.1, 30,890 code points: simplified and
traditional Chinese, Latin, Greek), and :func:`register_cjk_font` registers that file with
matplotlib explicitly, by path. Nothing here scans or asks for system fonts.

For matplotlib: ``fontfamily=["DejaVu Sans", register_cjk_font()]`` (per-glyph fallback:
Latin and Greek from DejaVu Sans, what it lacks from Noto Sans SC). For the report site and
its PDF: :func:`cjk_font_path` is the file to serve with CSS ``@font-face`` (or to subset with
fontTools' ``pyftsubset`` first; the license allows both, keeping the font's name off a
modified file).

Why a package and not a file in this repository: the font is 8.3 MB, and the environment
already pins and installs every other binary the project uses; the package is only the font
and a path function, with no dependencies.
"""

from __future__ import annotations

import functools
from pathlib import Path

__all__ = ["CJK_FAMILY", "cjk_font_path", "register_cjk_font"]

CJK_FAMILY = "Noto Sans SC"
"""The family name matplotlib (and CSS) know the bundled font by."""


def cjk_font_path() -> Path:
    """The bundled CJK font file (Noto Sans SC Regular, OpenType; SIL OFL 1.1).

    Raises ``RuntimeError`` naming the package if the environment lacks it (a ``.venv`` built
    before it was pinned: ``make venv`` installs it).

    >>> cjk_font_path().name
    'NotoSansSC-Regular.otf'
    """
    try:
        import pylopdf_fonts_zh_cn
    except ImportError:
        raise RuntimeError(
            "the CJK font package pylopdf-fonts-zh-cn is not installed: run `make venv` "
            "(it is pinned in requirements.lock)"
        ) from None
    path = Path(pylopdf_fonts_zh_cn.sans_path())
    if not path.is_file():
        raise RuntimeError(f"the bundled CJK font {path} is missing: reinstall with `make venv`")
    return path


@functools.cache
def register_cjk_font() -> str:
    """Register :func:`cjk_font_path` with matplotlib (once per process); return its family
    name, :data:`CJK_FAMILY`, for a ``fontfamily`` fallback list.

    >>> from matplotlib import font_manager
    >>> register_cjk_font()
    'Noto Sans SC'
    >>> font_manager.findfont(font_manager.FontProperties(family="Noto Sans SC"),
    ...                       fallback_to_default=False).endswith("NotoSansSC-Regular.otf")
    True
    """
    from matplotlib import font_manager

    path = cjk_font_path()
    font_manager.fontManager.addfont(str(path))
    name = font_manager.FontProperties(fname=str(path)).get_name()
    if name != CJK_FAMILY:  # pragma: no cover - a different file in the package
        raise RuntimeError(f"{path} is the family {name!r}, not {CJK_FAMILY!r}")
    return name
