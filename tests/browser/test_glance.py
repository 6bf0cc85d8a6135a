"""The four verdicts at a glance: on the first screen of the site at 1366 x 768 and on page 1
of report.pdf, each row from the registers (read through the register API here, apart from
the site's own code); and the PDF as printed: no markup leaks, no page left mostly blank, no
heading alone at the foot of a page."""

from __future__ import annotations

import re

import pytest
from tests.browser.pdf_pages import headings_left_alone, read_pdf, render_page, sparse_pages

FIRST_SCREEN = {"width": 1366, "height": 768}
PAPERS = {"grabber": "000", "palletizer": "001", "picker": "002", "gr1": "004"}
PRINT_MARGINS_PT = (14 + 16) * 72 / 25.4  # report.css: @page margin 14 mm top, 16 mm bottom
LEAKS = (":orphan:", "{doc}", "{ref}", "{download}", ":::", "```", "\\displaystyle", "$$",
         "**", "](")  # fmt: skip


def _expected() -> dict[str, dict]:
    """Per paper: headline, worst consequence and counted causes per severity, from the
    registers (analysis.audit.register), not from the site's code."""
    from analysis.audit import register
    from analysis.audit.schema import COUNTED, SEVERITIES

    out = {}
    for paper in PAPERS:
        reg = register.register(paper)
        counted = [c for c in reg.causes if c.status in COUNTED]
        out[paper] = {
            "headline": reg.summary["headline"],
            "worst": reg.summary["worst"],
            "counts": [sum(c.severity == s for c in counted) for s in SEVERITIES],
        }
    return out


def test_the_four_verdicts_fill_the_first_screen(context, site_url, shots):
    page = context.new_page()
    page.set_viewport_size(FIRST_SCREEN)
    try:
        page.goto(site_url + "index.html", wait_until="load")
        page.evaluate("() => document.fonts.ready.then(() => true)")
        page.screenshot(path=shots / "first-screen-1366x768.png")
        rows = page.evaluate(
            """() => [...document.querySelectorAll('table.glance tbody tr')].map(tr => {
                const r = tr.getBoundingClientRect();
                const a = tr.querySelector('th a');
                const target = document.getElementById((a.getAttribute('href') || '').slice(1));
                return {id: tr.id, top: r.top, bottom: r.bottom, left: r.left, right: r.right,
                        headline: tr.querySelector('.glance-verdict').innerText.trim(),
                        worst: tr.querySelector('.glance-worst').innerText.trim(),
                        counts: [...tr.querySelectorAll('td.glance-n')].map(td => +td.innerText),
                        seed: a.innerText.replace(/\\s+/g, ' ').trim(),
                        heading: target ? target.querySelector('h3').innerText : null};
            })"""
        )
        first = page.evaluate(  # the block right after the title holds the table
            "() => { const h = document.querySelector('.bd-article section > h1');"
            " const n = h.nextElementSibling;"
            " return Boolean(n && n.querySelector('table.glance')); }"
        )
    finally:
        page.close()
    want = _expected()
    assert [r["id"] for r in rows] == [f"glance-{p}" for p in PAPERS]
    assert first, "the glance table is the first thing under the title"
    for r, (paper, seed) in zip(rows, PAPERS.items(), strict=True):
        w = want[paper]
        assert r["bottom"] <= FIRST_SCREEN["height"] and r["top"] >= 0, (paper, r["bottom"])
        assert r["right"] <= FIRST_SCREEN["width"], (paper, r["right"])
        assert r["headline"] == w["headline"] and len(r["headline"].split()) <= 15
        assert r["worst"] == w["worst"] and re.search(r"\d", r["worst"])
        assert r["counts"] == w["counts"], (paper, r["counts"], w["counts"])
        assert r["seed"] == f"Seed {seed}" and r["heading"].startswith(f"Seed {seed}:"), r


@pytest.fixture(scope="module")
def pdf(site_dir):
    path = site_dir / "report.pdf"
    if not path.exists():
        pytest.skip("no report.pdf in this build (printed by make report, not by make test)")
    return path


def _flat(text: str) -> str:
    """Page text as one line: a word hyphenated at a line end joined again (PDFium marks
    that hyphen U+FFFE), every other line break a space."""
    return " ".join(text.replace("\ufffe\r\n", "-").replace("\ufffe", "-").split())


def test_pdf_page_one_is_the_four_verdicts(pdf, shots):
    import pypdfium2 as pdfium

    render_page(pdf, 1, shots / "pdf-page-1.png")
    doc = pdfium.PdfDocument(str(pdf))
    try:
        text = _flat(doc[0].get_textpage().get_text_range())  # in the order it is drawn
    finally:
        doc.close()
    for paper, w in _expected().items():
        row = f"{w['headline']} {' '.join(map(str, w['counts']))} {w['worst']}"
        assert _flat(row) in text, f"page 1 lacks {paper}'s row: {row!r}"


def test_pdf_has_no_markup_leaks_blank_pages_or_lonely_headings(pdf):
    pages = read_pdf(pdf)
    leaks = [f"page {p.number}: {s!r}" for p in pages for s in LEAKS if s in p.text]
    assert not leaks, leaks
    assert not sparse_pages(pages, PRINT_MARGINS_PT), sparse_pages(pages, PRINT_MARGINS_PT)
    assert not headings_left_alone(pages), headings_left_alone(pages)
