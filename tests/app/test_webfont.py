"""The CJK glyphs of the site and its SVG figures, cut from the pinned Noto Sans SC."""

from __future__ import annotations

import base64
import io
import re

import pytest
from fontTools.ttLib import TTFont

from analysis.app.webfont import (
    LATIN_FAMILY,
    SUBSET_FAMILY,
    cjk_characters,
    embed_fonts,
    subset_cjk,
    svg_text,
)


def test_the_subset_holds_exactly_the_cjk_characters_of_the_text():
    font = TTFont(io.BytesIO(subset_cjk("Table 4 row 8: 无解; 材料抓取 (grab)")))
    cjk = {c for c in font.getBestCmap() if c > 0x2E7F}
    assert cjk == {ord(c) for c in "无解材料抓取"}
    assert font.flavor == "woff" and font["name"].getDebugName(1) == SUBSET_FAMILY
    assert "Noto" not in (font["name"].getDebugName(4) or "")


def test_no_cjk_no_font():
    assert cjk_characters("plain ASCII, θ, °") == ""
    with pytest.raises(ValueError, match="no CJK character"):
        subset_cjk("plain ASCII")


def test_an_svg_carries_the_glyphs_of_its_cjk_text(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from analysis.app.plotting import cjk_fonts, save_figure, style
    from analysis.fonts import CJK_FAMILY

    with style():
        fig, ax = plt.subplots()
        ax.text(0.5, 0.5, "row 8: 无解", fontfamily=["DejaVu Sans", *cjk_fonts()])
        save_figure(fig, "99-cjk", tmp_path)
        save_figure(fig, "99-cjk-again", tmp_path)
        fig2, ax2 = plt.subplots()
        ax2.set_title("no CJK here")
        save_figure(fig2, "99-latin", tmp_path)
    plt.close("all")
    svg = (tmp_path / "99-cjk.svg").read_text(encoding="utf-8")
    faces = dict(re.findall(r'@font-face \{ font-family: "([^"]+)"; src: url\(data:font/woff;'
                            r"base64,([A-Za-z0-9+/=]+)\)", svg))  # fmt: skip
    assert set(faces) == {CJK_FAMILY, LATIN_FAMILY}
    assert f"'{CJK_FAMILY}'" in svg and "<text" in svg  # the text stays text, naming the family
    cjk = set(TTFont(io.BytesIO(base64.b64decode(faces[CJK_FAMILY]))).getBestCmap())
    latin = set(TTFont(io.BytesIO(base64.b64decode(faces[LATIN_FAMILY]))).getBestCmap())
    assert {ord("无"), ord("解")} <= cjk and ord("r") not in cjk
    # every other character of the figure's text from DejaVu Sans
    assert {ord(c) for c in svg_text(svg) if not c.isspace() and c not in "无解"} <= latin
    other = (tmp_path / "99-latin.svg").read_text(encoding="utf-8")
    assert f'font-family: "{LATIN_FAMILY}"' in other and f'"{CJK_FAMILY}"' not in other
    # the same figure saved twice is the same file (no date, a deterministic subset)
    assert (tmp_path / "99-cjk-again.svg").read_text(encoding="utf-8") == svg


def test_embed_fonts_refuses_what_is_not_an_svg():
    with pytest.raises(ValueError, match="no <svg> element"):
        embed_fonts("<html>无解</html>", "Noto Sans SC")
