"""``report.pdf`` as a reader sees it, for the browser tests: each page's text lines with their
position and font size, and how far down the page its content reaches (PDFium, ``pypdfium2``).

* :func:`read_pdf`: the pages, each with its lines (glyphs grouped by baseline) and the lowest
  point of anything drawn on it (text, images, paths);
* :func:`headings_left_alone`: heading lines (font size well above the body's) with nothing
  after them on their page: the heading is at the foot of one page, its text on the next;
* :func:`sparse_pages`: pages whose content stops high up (a page mostly blank), the last
  page excepted;
* :func:`render_page`: a page as a PNG, for people to look at.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from pathlib import Path

BODY_SIZE = 13.33
"""The body text's font size as PDFium reads Chromium's PDF (10 pt in ``report.css``'s print
styles, 13.33 CSS px); tables and captions are smaller."""
HEADING_RATIO = 1.25
"""A line is a heading when its font size is at least this times the body's (h3 and up)."""


@dataclass(frozen=True)
class Line:
    text: str
    top: float
    """Distance of the line's top from the top of the page [pt]."""
    bottom: float
    size: float
    """The largest font size on the line [pt]."""


@dataclass
class Page:
    number: int
    height: float
    lines: list[Line] = field(default_factory=list)
    bottom: float = 0.0
    """How far down the page its content reaches [pt from the top]."""

    @property
    def text(self) -> str:
        return "\n".join(line.text for line in self.lines)


def read_pdf(path: Path) -> list[Page]:
    """Every page of the PDF at ``path``: its text lines (top to bottom) and its lowest content."""
    import ctypes

    import pypdfium2 as pdfium
    import pypdfium2.raw as raw

    doc = pdfium.PdfDocument(str(path))
    out = []
    try:
        for k in range(len(doc)):
            page = doc[k]
            width, height = page.get_size()
            tp = page.get_textpage()
            glyphs = []  # (baseline from the top, left, top, bottom, size, char)
            x, y = ctypes.c_double(), ctypes.c_double()
            for i in range(tp.count_chars()):
                ch = tp.get_text_range(i, 1)
                left, bottom, _, top = tp.get_charbox(i)
                raw.FPDFText_GetCharOrigin(tp, i, ctypes.byref(x), ctypes.byref(y))
                size = float(raw.FPDFText_GetFontSize(tp, i))
                glyphs.append((height - y.value, left, height - top, height - bottom, size, ch))
            rows: dict[int, list] = {}
            for g in glyphs:  # glyphs of one line share a baseline (within 2 pt)
                key = next((r for r in rows if abs(r - g[0]) <= 2), g[0])
                rows.setdefault(key, []).append(g)
            lines = []
            for key in sorted(rows):
                gs = sorted(rows[key], key=lambda g: g[1])
                text = " ".join("".join(g[5] for g in gs).split())
                if text:
                    lines.append(Line(text, min(g[2] for g in gs), max(g[3] for g in gs),
                                      max(g[4] for g in gs)))  # fmt: skip
            lowest = max((ln.bottom for ln in lines), default=0.0)
            for obj in page.get_objects(max_depth=2):
                try:
                    left, b, right, t = obj.get_bounds()
                except pdfium.PdfiumError:  # an object without bounds draws nothing
                    continue
                if (right - left) * (t - b) > 0.5 * width * height:  # the page's background
                    continue
                lowest = max(lowest, height - b)
            out.append(Page(k + 1, height, lines, min(lowest, height)))
            tp.close()
            page.close()
    finally:
        doc.close()
    return out


def headings_left_alone(pages: list[Page]) -> list[str]:
    """Headings with nothing after them on their page (their text starts on the next page)."""
    out = []
    for p, nxt in itertools.pairwise(pages):
        if not p.lines or not nxt.lines:
            continue
        last = p.lines[-1]
        if last.size >= HEADING_RATIO * BODY_SIZE and p.bottom <= last.bottom + 2:
            out.append(f"page {p.number}: {last.text!r} at its foot")
    return out


def sparse_pages(pages: list[Page], margin_pt: float, least: float = 0.4) -> list[str]:
    """Pages (but the last) whose content fills less than ``least`` of the printable height
    (the page height less ``margin_pt`` top and bottom together)."""
    out = []
    for p in pages[:-1]:
        used = (p.bottom - margin_pt / 2) / (p.height - margin_pt)
        if used < least:
            out.append(f"page {p.number}: {used:.0%} used")
    return out


def render_page(path: Path, number: int, out: Path, scale: float = 1.5) -> Path:
    """Page ``number`` (from 1) of the PDF at ``path`` as a PNG at ``out``."""
    import pypdfium2 as pdfium

    doc = pdfium.PdfDocument(str(path))
    try:
        doc[number - 1].render(scale=scale).to_pil().save(out)
    finally:
        doc.close()
    return out
