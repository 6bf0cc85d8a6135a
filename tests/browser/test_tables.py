"""Tables and maths as a reader sees them: no word broken across lines (ids, severities, counts,
headers), on every page of the site at a laptop's and a phone's width and in the printed form.

A word is a run of characters without white space. In a cell that holds one word (an id such as
``grabber-stl-degrees``, a severity, a count) the word never wraps, not even at a hyphen; in a
cell of several words a word may wrap only just after a hyphen or an operator of its own (prose
such as "one-argument", a formula in a sentence), never between two letters or digits
("brea/ks", "sev/erit/y", "1/0"); Chinese breaks between characters, as it should. Measured
on the page as laid out: each word's glyphs must share one line box (``Range.getClientRects``).
"""

from __future__ import annotations

import pytest

WIDTHS = {"laptop": (1366, 768), "phone": (390, 844)}
PRINT_WIDTH = (703, 1000)  # A4 less report.css's 12 mm side margins, in CSS px

_BROKEN_WORDS = r"""() => {
    const lineOf = (r) => Math.round(r.top + r.height / 2);
    const lines = (range) => new Set([...range.getClientRects()].filter(r => r.width > 0.5)
                                     .map(lineOf));
    const AFTER = "-*+/=),;";  // in prose a word may wrap after a hyphen or an operator
    const CJK = /[\u2e80-\u9fff\uf900-\ufaff\uff00-\uffef]/;
    const bad = [];
    for (const cell of document.querySelectorAll('main td, main th')) {
        if (!cell.getClientRects().length) continue;            // not shown
        if (cell.querySelector('mjx-container, img, svg, canvas, table')) continue;
        const single = !/\s/.test(cell.textContent.trim());
        const walk = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT);
        for (let node = walk.nextNode(); node; node = walk.nextNode()) {
            for (const m of node.data.matchAll(/\S+/g)) {
                if (CJK.test(m[0])) continue;  // Chinese breaks between characters by rule
                const range = document.createRange();
                range.setStart(node, m.index);
                range.setEnd(node, m.index + m[0].length);
                if (lines(range).size <= 1) continue;
                // where does the word wrap? after a hyphen of its own, in prose, is allowed
                let ok = !single;
                for (let k = 1; k < m[0].length && ok; k++) {
                    const a = document.createRange(), b = document.createRange();
                    a.setStart(node, m.index + k - 1); a.setEnd(node, m.index + k);
                    b.setStart(node, m.index + k); b.setEnd(node, m.index + k + 1);
                    const la = [...lines(a)][0], lb = [...lines(b)][0];
                    const wraps = la !== undefined && lb !== undefined && la !== lb;
                    if (wraps && !AFTER.includes(m[0][k - 1])) ok = false;
                }
                if (!ok) bad.push(m[0]);
            }
        }
    }
    return [...new Set(bad)];
}"""


def _broken(page, url: str) -> list[str]:
    page.goto(url, wait_until="load")
    page.evaluate("() => document.fonts.ready.then(() => true)")
    return page.evaluate(_BROKEN_WORDS)


@pytest.mark.parametrize("width", list(WIDTHS))
def test_no_word_in_a_table_is_broken(context, site_url, pages, width):
    page = context.new_page()
    w, h = WIDTHS[width]
    page.set_viewport_size({"width": w, "height": h})
    bad = {}
    try:
        for p in pages:
            words = _broken(page, site_url + p)
            if words:
                bad[p] = words[:6]
    finally:
        page.close()
    assert not bad, f"words broken across lines at {w} px: {bad}"


def test_no_word_in_a_table_is_broken_in_print(context, site_url):
    """The printed form (report.pdf is printed from the same pages and style sheet): the front
    page at the width of an A4 page."""
    page = context.new_page()
    page.set_viewport_size({"width": PRINT_WIDTH[0], "height": PRINT_WIDTH[1]})
    page.emulate_media(media="print")
    try:
        words = _broken(page, site_url + "index.html")
    finally:
        page.close()
    assert not words, f"words broken across lines in print: {words[:10]}"
