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
* An SVG figure (``svg.fonttype = "none"``, text kept as text): the glyphs of its text
  embedded as data URIs under the families the figure names (:func:`embed_fonts`, called by
  :func:`analysis.app.plotting.save_figure`): its CJK characters from Noto Sans SC, the rest
  from matplotlib's DejaVu Sans, so that it needs neither font on the viewer's machine.
"""

from __future__ import annotations

import base64
import io
import logging
import re

__all__ = [
    "CJK",
    "CJK_RANGES",
    "LATIN_FAMILY",
    "SUBSET_FAMILY",
    "cjk_characters",
    "embed_fonts",
    "subset_cjk",
    "subset_font",
    "svg_text",
]

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
    """The bundled Noto Sans SC cut down to the CJK characters of ``text``, as WOFF bytes,
    renamed :data:`SUBSET_FAMILY`.

    Raises ``ValueError`` if ``text`` has no CJK character (there would be nothing to serve)
    or if the font lacks one of them (naming it).
    """
    from fontTools.ttLib import TTFont

    from analysis.fonts import cjk_font_path

    chars = cjk_characters(text)
    if not chars:
        raise ValueError("the text has no CJK character: no font subset to make")
    with TTFont(str(cjk_font_path()), lazy=True) as font:  # closed: no ResourceWarning
        have = font.getBestCmap()
    missing = [c for c in chars if ord(c) not in have]
    if missing:
        raise ValueError(f"{cjk_font_path().name} has no glyph for {''.join(missing)!r}")
    return subset_font(cjk_font_path(), chars, name=SUBSET_FAMILY)


LATIN_FAMILY = "DejaVu Sans"
"""The family of the figures' other text (matplotlib's default, shipped in its wheel)."""


def subset_font(path, chars: str, *, name: str | None = None) -> bytes:
    """The font file ``path`` cut down to ``chars`` (those it has), as WOFF bytes; renamed
    ``name`` if given. The same input gives the same bytes (the font's timestamp is kept)."""
    from fontTools import subset
    from fontTools.ttLib import TTFont

    # fontTools logs each subsetting step at INFO, which a build that logs at INFO (Sphinx,
    # make report) would print: only its warnings are kept
    logging.getLogger("fontTools").setLevel(logging.WARNING)
    with TTFont(str(path), recalcTimestamp=False) as font:  # the file is closed after
        have = font.getBestCmap()
        options = subset.Options()
        options.flavor = "woff"
        options.layout_features = ["*"]
        options.name_IDs = [0, 1, 2, 3, 4, 5, 6]
        options.drop_tables += ["FFTM"]
        sub = subset.Subsetter(options)
        sub.populate(unicodes=[ord(c) for c in sorted(set(chars)) if ord(c) in have])
        sub.subset(font)
        if name is not None:
            table = font["name"]
            for nid, value in ((1, name), (3, name), (4, name), (6, name.replace(" ", "-"))):
                table.setName(value, nid, 3, 1, 0x409)
                table.setName(value, nid, 1, 0, 0)
            table.removeNames(nameID=16)
            table.removeNames(nameID=17)
        buf = io.BytesIO()
        font.flavor = "woff"
        font.save(buf)
    return buf.getvalue()


def svg_text(svg: str) -> str:
    """The characters of the ``<text>`` elements of ``svg`` (tags dropped, entities read)."""
    import html

    inner = re.findall(r"<text\b[^>]*>(.*?)</text>", svg, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", "", "".join(inner)))


def _face(family: str, woff: bytes, ranges: str | None = None) -> str:
    data = base64.b64encode(woff).decode("ascii")
    rng = f" unicode-range: {ranges};" if ranges else ""
    return (
        f'@font-face {{ font-family: "{family}"; '
        f'src: url(data:font/woff;base64,{data}) format("woff");{rng} }}'
    )


def embed_fonts(svg: str, cjk_family: str) -> str:
    """``svg`` (matplotlib's, ``svg.fonttype = "none"``: text kept as text) with the glyphs of
    its text embedded, so that it looks the same on a machine without its fonts: its
    :data:`LATIN_FAMILY` characters from matplotlib's own DejaVu Sans, its CJK characters
    from the bundled Noto Sans SC (under ``cjk_family``, the name its text elements use, for
    CJK code points only). Each as a data URI in one ``<style>`` after the ``<svg>`` tag."""
    from matplotlib import font_manager

    head = re.search(r"<svg\b[^>]*>", svg)
    if head is None:
        raise ValueError("not an SVG document: no <svg> element")
    text = svg_text(svg)
    faces = []
    latin = "".join(c for c in set(text) if not CJK.match(c) and not c.isspace())
    if latin:
        dejavu = font_manager.findfont(
            font_manager.FontProperties(family=LATIN_FAMILY), fallback_to_default=False
        )
        faces.append(_face(LATIN_FAMILY, subset_font(dejavu, latin)))
    if cjk_characters(text):
        faces.append(_face(cjk_family, subset_cjk(text), CJK_RANGES))
    if not faces:
        return svg
    style = '<style type="text/css">' + " ".join(faces) + "</style>"
    return svg[: head.end()] + "\n " + style + svg[head.end() :]
