"""The CJK glyphs of the site and its figures, from the pinned Noto Sans SC, subset for the web.

The papers' Chinese (Table 4's 无解, titles, quotations in the registers) must look the same
on a machine without any CJK font (this one has none), so the site and its SVG figures carry
the glyphs they use: :func:`subset_cjk` cuts the bundled font
(:func:`analysis.fonts.cjk_font_path`, SIL OFL 1.1) down to the CJK characters of a text with
fontTools and returns it as WOFF (zlib; WOFF2 would need the brotli package). The subset is
renamed :data:`SUBSET_FAMILY` (the licence asks modified fonts to go by another name than the
original's reserved ones; Noto reserves none, the name only says what the file is).

* The report site: ``_static/cjk-subset.woff`` with an ``@font-face`` for
  :data:`SUBSET_FAMILY` limited to :data:`CJK_RANGES` (``unicode-range``), first in the
  page's font lists (``docs/site/_static/report.css``), so that only CJK characters come
  from it.
* An SVG figure (``svg.fonttype = "none"``, text kept as text): its CJK characters' glyphs
  embedded as a data URI under the family the figure names them by (:func:`embed_in_svg`,
  called by :func:`analysis.app.plotting.save_figure`).
"""

from __future__ import annotations

import base64
import io
import re

__all__ = ["CJK", "CJK_RANGES", "SUBSET_FAMILY", "cjk_characters", "embed_in_svg", "subset_cjk"]

CJK_RANGES = "U+2E80-2FFF, U+3000-303F, U+3400-4DBF, U+4E00-9FFF, U+F900-FAFF, U+FF00-FFEF"
"""The code points the subset serves: CJK radicals, punctuation, ideographs, full-width forms."""

CJK = re.compile("[\u2e80-\u2fff\u3000-\u303f\u3400-\u4dbf\u4e00-\u9fff\uf900-\ufaff\uff00-\uffef]")
"""One character of :data:`CJK_RANGES`."""

SUBSET_FAMILY = "Analysis CJK subset"
"""The family name of the subset (in the file and in the site's CSS)."""


def cjk_characters(text: str) -> str:
    """The distinct CJK characters of ``text``, sorted.

    >>> cjk_characters("Table 4: 无解, 无解 (no solution)")
    '无解'
    """
    return "".join(sorted(set(CJK.findall(text))))


def subset_cjk(text: str) -> bytes:
    """The bundled Noto Sans SC cut down to the CJK characters of ``text``, as WOFF bytes.

    Raises ``ValueError`` if ``text`` has no CJK character (there would be nothing to serve)
    or if the font lacks one of them (naming it).
    """
    from fontTools import subset
    from fontTools.ttLib import TTFont

    from analysis.fonts import cjk_font_path

    chars = cjk_characters(text)
    if not chars:
        raise ValueError("the text has no CJK character: no font subset to make")
    font = TTFont(str(cjk_font_path()), recalcTimestamp=False)  # the same bytes every run
    missing = [c for c in chars if ord(c) not in font.getBestCmap()]
    if missing:
        raise ValueError(f"{cjk_font_path().name} has no glyph for {''.join(missing)!r}")
    options = subset.Options()
    options.flavor = "woff"
    options.layout_features = ["*"]  # vertical forms and locl stay usable
    options.name_IDs = [0, 1, 2, 3, 4, 5, 6]
    sub = subset.Subsetter(options)
    sub.populate(unicodes=[ord(c) for c in chars])
    sub.subset(font)
    name = font["name"]
    for nid, value in ((1, SUBSET_FAMILY), (3, SUBSET_FAMILY), (4, SUBSET_FAMILY),
                       (6, SUBSET_FAMILY.replace(" ", "-"))):  # fmt: skip
        name.setName(value, nid, 3, 1, 0x409)
        name.setName(value, nid, 1, 0, 0)
    name.removeNames(nameID=16)
    name.removeNames(nameID=17)
    buf = io.BytesIO()
    font.flavor = "woff"
    font.save(buf)
    return buf.getvalue()


def embed_in_svg(svg: str, family: str) -> str:
    """``svg`` (matplotlib's, text as ``<text>``) with the glyphs of its CJK characters
    embedded: an ``@font-face`` for ``family`` (the name its text elements use) whose source
    is the subset as a data URI. An SVG without CJK text is returned unchanged.
    """
    chars = cjk_characters(svg)
    if not chars:
        return svg
    data = base64.b64encode(subset_cjk(chars)).decode("ascii")
    face = (
        f'<style type="text/css">@font-face {{ font-family: "{family}"; '
        f'src: url(data:font/woff;base64,{data}) format("woff"); '
        f"unicode-range: {CJK_RANGES}; }}</style>"
    )
    head = re.search(r"<svg\b[^>]*>", svg)
    if head is None:
        raise ValueError("not an SVG document: no <svg> element")
    return svg[: head.end()] + "\n " + face + svg[head.end() :]
