"""What a reader of the report site sees, checked in a real browser (see conftest.py)."""

from __future__ import annotations

import hashlib
import json
import re
from urllib.parse import unquote, urlsplit

import pytest

from analysis.app.site_content import MISSING_CAPTION

# a caption says in which units: one of these must occur in it
UNITS = re.compile(r"\bmm\b|mm[²³]|°|\bdeg|\bpulses?\b|\brad\b|\bs\b|%")
NOTEBOOKS = re.compile(r"^notebooks/\d\d_\w+\.html$")


def _goto(page, url: str) -> None:
    """Open ``url`` and wait until MathJax (where the page loads it) has typeset the page."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    page.goto(url, wait_until="load")
    try:
        page.wait_for_function(
            "() => !document.querySelector('script[src*=\"mathjax\"]')"
            " || (window.MathJax && MathJax.startup && MathJax.startup.promise)",
            timeout=20_000,
        )
    except PlaywrightTimeout:
        raise AssertionError(
            f"{url}: MathJax did not start; requests outside 127.0.0.1 (aborted): "
            f"{page.blocked[-5:]}"
        ) from None
    page.evaluate("() => window.MathJax?.startup?.promise?.then(() => true) ?? true")


def test_site_built_cleanly(site_dir, build_problems):
    """Every notebook executed and the front page computed (else the site says what failed)."""
    assert not build_problems, build_problems[0]
    front = (site_dir / "index.html").read_text()
    at = front.find("This build is incomplete.")
    assert at < 0, " ".join(re.sub(r"<[^>]+>", " ", front[at : at + 1500]).split())


def test_front_page_shows_the_verdicts(page, site_url, shots, blocked):
    from analysis.audit import register
    from analysis.audit.papers.grabber import table4
    from analysis.audit.schema import COUNTED

    reg = register.register("grabber")
    c = reg.counts()
    causes = sum(c[s] for s in COUNTED)
    places = sum(len(x.manifestations) for x in reg.causes if x.status in COUNTED)
    n = register.coverage("grabber")[0]["items"]
    _goto(page, site_url + "index.html")
    page.screenshot(path=shots / "front-page.png", full_page=False)
    page.screenshot(path=shots / "front-page-full.png", full_page=True)
    labels = page.locator(".verdict-label").all_inner_texts()
    numbers = page.locator(".verdict-number").all_inner_texts()
    cards = dict(zip(labels, numbers, strict=True))
    assert cards["root causes against the paper"] == f"{causes:,}"
    assert cards["errors"] == f"{c['error']:,}" and cards["places they show"] == f"{places:,}"
    assert cards["printed items checked"] == f"{n.sum():,}"
    text = page.locator("main").inner_text()
    assert f"{causes} root causes against the paper" in text
    assert f"{n['holds']} of {n.sum()} printed items hold" in text
    for heading in (
        "What the audit found",
        "Table 4, recomputed",
        "The PLC program, executed",
        "What 0.09° per pulse means at the gripper",
    ):
        assert page.get_by_role("heading", name=heading).is_visible(), heading
    # Table 4: one line per printed row, the verdicts as computed
    t4 = table4.report_table()
    table = page.locator("section#table-4-recomputed table")
    assert table.locator("tbody tr").count() == len(t4)
    assert f"{(t4['verdict'] == 'holds').sum()} of {len(t4)} rows hold" in text
    # every section links to its evidence, and the links lead to the notebooks
    evidence = page.locator("p:has-text('Evidence:') a")
    hrefs = {evidence.nth(i).get_attribute("href") for i in range(evidence.count())}
    assert {
        "register.html",
        "notebooks/03_table4.html",
        "notebooks/07_plc_stl.html",
        "notebooks/06_quantization.html",
    } <= hrefs
    # the PLC proof and the quantization figures, captioned
    assert "awlsim" in text and "pulse mismatches vs Python" in text
    for stem in ("06-error-distribution", "06-error-maps", "07-rounding-margin"):
        assert page.locator(f"figure img[src$='{stem}.png']").count() == 1, stem
    assert not page.js_errors and not blocked


def test_maths_is_rendered_with_every_outside_request_blocked(
    page, site_url, site_dir, pages, blocked, shots
):
    with_maths = [p for p in pages if 'class="math' in (site_dir / p).read_text()] + [
        p for p in pages if "math notranslate" in (site_dir / p).read_text()
    ]
    with_maths = sorted(set(with_maths))
    assert with_maths, "no page with maths (notebooks 01 and 02 print SymPy matrices)"
    for p in with_maths:
        _goto(page, site_url + p)
        state = page.evaluate(
            """() => ({
                math: document.querySelectorAll('.math').length,
                typeset: document.querySelectorAll('.math mjx-container').length,
                errors: document.querySelectorAll('mjx-merror').length,
                fonts: [...document.fonts].filter(f => f.family.includes('MJXTEX')
                                                      && f.status === 'loaded').length,
                text: document.querySelector('main').innerText,
            })"""
        )
        assert state["math"] > 0 and state["typeset"] >= state["math"], (p, state["math"])
        assert state["errors"] == 0, p
        assert state["fonts"] > 0, f"{p}: MathJax fonts not loaded"
        for raw in ("$\\displaystyle", "\\displaystyle", "\\left[", "\\begin{matrix}"):
            assert raw not in state["text"], (p, raw)
        if p == "notebooks/02_inverse_kinematics.html":
            page.locator(".bd-article mjx-container").nth(2).scroll_into_view_if_needed()
            page.screenshot(path=shots / "maths-02.png")
    assert blocked == [], f"requests outside 127.0.0.1: {blocked[:5]}"
    # the pages carry no address of a CDN or any outside script at all
    for p in pages:
        html = (site_dir / p).read_text()
        assert not re.search(r"<script[^>]+src=\"(https?:)?//", html), p


# What three tests check on every page, read in one visit per page (MathJax typeset, every
# image loaded or failed): the images that did not load, the URLs the page refers to, and each
# figure image of the main text with its caption.
_CRAWL = """async () => {
    const imgs = [...document.images];
    imgs.forEach(i => { i.loading = 'eager'; });
    await Promise.all(imgs.map(i => i.complete ? null
        : new Promise(r => { i.onload = i.onerror = r; })));
    return {
        broken: imgs.filter(i => !(i.naturalWidth > 0)).map(i => i.src),
        urls: [
            ...[...document.querySelectorAll('a[href]')].map(a => a.href),
            ...[...document.querySelectorAll('img[src], script[src]')].map(e => e.src),
            ...[...document.querySelectorAll('link[href]')].map(l => l.href),
        ],
        figures: [...document.querySelectorAll('main img')].map(i => {
            const c = i.closest('figure')?.querySelector('figcaption .caption-text');
            return {src: i.getAttribute('src'), caption: c ? c.innerText : null};
        }),
    };
}"""


@pytest.fixture(scope="module")
def crawl(context, site_url, pages, blocked) -> dict[str, dict]:
    """Every page opened once in the browser: page path -> what :data:`_CRAWL` read."""
    page = context.new_page()
    page.blocked = blocked
    try:
        out = {}
        for p in pages:
            _goto(page, site_url + p)
            out[p] = page.evaluate(_CRAWL)
        return out
    finally:
        page.close()


def test_every_image_loads(crawl, blocked):
    broken = [f"{p}: {src}" for p, seen in crawl.items() for src in seen["broken"]]
    assert not broken, broken
    assert not blocked


def test_every_internal_link_resolves(crawl, context, site_url):
    targets: dict[str, set[str]] = {}
    for seen in crawl.values():
        for url in seen["urls"]:
            if not url.startswith(site_url):
                continue
            parts = urlsplit(url)
            base = url.split("#", 1)[0].split("?", 1)[0]
            targets.setdefault(base, set())
            if parts.fragment:
                targets[base].add(unquote(parts.fragment))
    assert len(targets) > 50
    failures = []
    for url, fragments in sorted(targets.items()):
        r = context.request.get(url)
        if r.status != 200:
            failures.append(f"{url}: HTTP {r.status}")
            continue
        if fragments and url.endswith(".html"):
            html = r.text()
            failures += [
                f"{url}#{f}: no such anchor"
                for f in sorted(fragments)
                if f'id="{f}"' not in html and f'name="{f}"' not in html
            ]
    assert not failures, failures


def test_downloads_are_present_and_what_they_say(page, context, site_url, site_dir):
    _goto(page, site_url + "downloads.html")
    links = page.locator("a.download")
    files = {
        links.nth(i).inner_text().strip(): links.nth(i).evaluate("a => a.href")
        for i in range(links.count())
    }
    nbs = {p.stem + ".ipynb" for p in (site_dir / "notebooks").glob("*.html")}
    expected = {
        "ik_s7-200.awl",
        "ik_s7-200_map.json",
        "ik_s7-300.awl",
        "ik_s7-300_map.json",
        "grabber.csv",
        "grabber_items.csv",
        "table4_audit.csv",
        "report.pdf",
    } | nbs
    assert expected <= set(files), sorted(expected - set(files))
    body = {name: context.request.get(url).body() for name, url in files.items()}
    assert b"ORGANIZATION_BLOCK" in body["ik_s7-200.awl"] and b"Network" in body["ik_s7-200.awl"]
    assert b"ORGANIZATION_BLOCK OB 1" in body["ik_s7-300.awl"]
    for dialect in ("s7-200", "s7-300"):
        mmap = json.loads(body[f"ik_{dialect}_map.json"])
        assert mmap["dialect"] == dialect and {"px", "py", "pz"} <= set(mmap["inputs"])
    header = b"id,cause,status,kind,severity,location,printed,reading,corrected"
    assert body["grabber.csv"].startswith(header)
    assert body["grabber_items.csv"].startswith(b"id,location,verdict")
    assert body["table4_audit.csv"].startswith(b"row,")
    assert body["report.pdf"].startswith(b"%PDF")
    assert len(re.findall(rb"/Type\s*/Page[^s]", body["report.pdf"])) > 20
    for name in nbs:
        assert json.loads(body[name])["cells"], name
    # the digests printed on the page are those of the files
    text = page.locator("main").inner_text()
    for name in ("ik_s7-200.awl", "grabber.csv", "report.pdf"):
        assert hashlib.sha256(body[name]).hexdigest() in text, name
    # and a click downloads the file under its name, as a reader would
    with page.expect_download() as dl:
        page.get_by_role("link", name="ik_s7-200.awl").click()
    assert dl.value.suggested_filename == "ik_s7-200.awl"


def test_every_figure_has_a_caption_with_units(page, crawl, site_url, site_dir, shots):
    stems = sorted({p.stem for p in (site_dir / "_images").glob("[0-9][0-9]-*.png")})
    assert stems
    _goto(page, site_url + "figures.html")
    page.screenshot(path=shots / "figures.png")
    captions = page.evaluate(
        """() => [...document.querySelectorAll('main figure')].map(f => ({
            src: f.querySelector('img').getAttribute('src'),
            caption: (f.querySelector('figcaption') || {innerText: ''}).innerText}))"""
    )
    assert sorted(c["src"].rsplit("/", 1)[-1][:-4] for c in captions) == stems
    bad = []
    for p, seen in crawl.items():
        for f in seen["figures"]:
            stem = f["src"].rsplit("/", 1)[-1].rsplit(".", 1)[0]
            cap = (f["caption"] or "").split(" (SVG", 1)[0].strip()  # without the links
            if not cap or MISSING_CAPTION in cap or cap.startswith(stem) or not UNITS.search(cap):
                bad.append(f"{p}: {f['src']}: {cap[:80]!r}")
    assert not bad, bad


def test_navigation_sidebar_previous_next_home_and_search(page, site_url, pages, shots):
    notebooks = [p for p in pages if NOTEBOOKS.match(p)]
    assert len(notebooks) >= 2
    first, second = notebooks[0], notebooks[1]
    _goto(page, site_url + second)
    # contents sidebar: every notebook and the report pages, the current one marked
    side = page.locator("nav.bd-docs-nav")
    hrefs = side.locator("a").evaluate_all("as => as.map(a => a.getAttribute('href'))")
    names = {h.rsplit("/", 1)[-1] for h in hrefs}
    others = {p.rsplit("/", 1)[-1] for p in notebooks if p != second}
    assert others | {"register.html", "figures.html", "downloads.html", "index.html"} <= names
    current = side.locator("li.current a").first
    assert current.get_attribute("href") == "#"  # the page itself, marked current
    assert current.inner_text().startswith(second.split("/")[1][:2])
    # previous / next
    prev = page.locator("a.left-prev")
    nxt = page.locator("a.right-next")
    assert prev.get_attribute("href").endswith(first.split("/")[1])
    nxt.click()
    page.wait_for_load_state("load")
    assert page.url.endswith(notebooks[2].split("/")[1]) if len(notebooks) > 2 else True
    # back to the start: the site title links to the front page
    page.locator("a.navbar-brand").first.click()
    page.wait_for_load_state("load")
    assert page.url.rstrip("/").endswith("index.html") or page.url == site_url
    # search, as typed into the sidebar's search field
    page.locator(".bd-sidebar-primary .search-button-field").first.click()
    box = page.locator("#pst-search-dialog input[name='q']")
    box.fill("atan2")
    box.press("Enter")
    page.wait_for_url(re.compile(r"search\.html\?q=atan2"))
    results = page.locator("#search-results ul.search li a")
    results.first.wait_for(timeout=30_000)
    found = results.evaluate_all("as => as.map(a => a.getAttribute('href'))")
    assert any("notebooks/02_inverse_kinematics" in h for h in found), found
    page.screenshot(path=shots / "search.png")


def test_print_form_hides_the_site_chrome(page, site_url, shots):
    _goto(page, site_url + "notebooks/06_quantization.html")
    page.emulate_media(media="print")
    hidden = page.evaluate(
        """() => ['.bd-sidebar-primary', '.bd-sidebar-secondary', '.bd-header',
                  '.prev-next-area', '.header-article']
            .map(s => document.querySelector(s))
            .filter(e => e && getComputedStyle(e).display !== 'none').map(e => e.className)"""
    )
    assert hidden == []
    assert page.locator("main figure img").first.is_visible()
    width, page_width = page.evaluate(
        """() => [document.querySelector('.bd-article').getBoundingClientRect().width,
                  document.documentElement.clientWidth]"""
    )
    assert width > 0.8 * page_width  # the article takes the page width
    pdf = page.pdf(format="A4")
    assert pdf.startswith(b"%PDF")
    page.emulate_media(media="screen")


@pytest.mark.parametrize("path", ["notebooks/09_explore.html"])
def test_widgets_say_how_to_use_them(page, site_url, site_dir, path):
    if not (site_dir / path).exists():
        pytest.skip(f"{path} is not part of this build")
    _goto(page, site_url + path)
    assert "make lab" in page.locator("main").inner_text()


def test_explorer_3d_view_renders_and_rotates_offline(page, site_url, site_dir, shots):
    """The explorer page's 3D arm (plotly, text/html output) is drawn from the site's own
    plotly.js with every outside request blocked, and turns when dragged."""
    path = "notebooks/09_explore.html"
    if not (site_dir / path).exists():
        pytest.skip(f"{path} is not part of this build")
    n_blocked = len(page.blocked)
    _goto(page, site_url + path)
    srcs = page.evaluate("() => [...document.scripts].map(s => s.src).filter(s => s)")
    plotly = [s for s in srcs if "plotly" in s]
    assert len(plotly) == 1 and "/_static/plotly.min.js" in plotly[0], plotly
    plot = page.locator(".js-plotly-plot").first
    plot.wait_for()
    plot.scroll_into_view_if_needed()
    assert plot.locator("canvas").count() >= 1  # the WebGL scene exists
    title = plot.locator(".gtitle").text_content()
    assert "front-up" in title and "45.00, 10.21, -155.13" in title
    eye = "el => el._fullLayout.scene._scene.getCamera().eye"
    before = plot.evaluate(eye)
    box = plot.bounding_box()
    cx, cy = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(cx, cy)
    page.mouse.down()
    page.mouse.move(cx + 120, cy + 30, steps=12)
    page.mouse.up()
    assert plot.evaluate(eye) != before
    page.screenshot(path=shots / "site-explorer-3d.png", full_page=False)
    assert page.blocked[n_blocked:] == [] and page.js_errors == []


def test_footer_says_no_by_analysis(site_dir):
    """Issue 31 polish: the footer read "By analysis" (the package named as the author)."""
    for page in ("index.html", "register.html", "notebooks/09_explore.html"):
        text = (site_dir / page).read_text(encoding="utf-8")
        assert "By analysis" not in text and "Copyright" in text, page
