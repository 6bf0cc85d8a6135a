"""Browser tests of the report site: Debian's Chromium driven by Playwright, site on 127.0.0.1.

The site is built once per session by :func:`analysis.app.report.build_report` (every
notebook executed, about a minute), or taken from ``ANALYSIS_SITE_DIR`` (e.g. ``build/report``
after ``make report``). It is served by :func:`analysis.app.report.serve` on 127.0.0.1; every
request the browser makes to any other host is aborted and recorded (``blocked``), so a test
that renders maths proves that nothing is loaded from the network.

Chromium is Debian's ``/usr/bin/chromium`` (or ``ANALYSIS_CHROMIUM``), never a browser
downloaded by ``playwright install``; without it every test here is skipped with the reason.
"""

from __future__ import annotations

import os
from pathlib import Path
from urllib.parse import urlsplit

import pytest

from analysis.app.report import CHROMIUM, CHROMIUM_FLAGS, NotebookFailed, build_report, serve

PROJECT = Path(__file__).resolve().parents[2]
LOCAL_HOSTS = {"127.0.0.1", "localhost", "::1", "[::1]"}


def pytest_collection_modifyitems(items):
    # sphinx-book-theme 1.4 still touches an attribute Sphinx 11 will remove
    for item in items:
        item.add_marker(pytest.mark.filterwarnings("ignore:.*HandleFootnoteTransform.app"))


@pytest.fixture(scope="session")
def chromium() -> str:
    path = os.environ.get("ANALYSIS_CHROMIUM", CHROMIUM)
    # executable, not merely present: a machine without Chromium may still have the path (an
    # empty unreadable file is how ../shared/tools/bare-machine hides it)
    if not (Path(path).is_file() and os.access(path, os.X_OK) and Path(path).stat().st_size):
        pytest.skip(
            f"no Chromium at {path}: the browser tests need Debian's chromium "
            "(apt-get install chromium; .ci/run installs it)"
        )
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:  # pragma: no cover - the lock installs it
        pytest.skip("the playwright package is not installed (make venv)")
    return path


@pytest.fixture(scope="session")
def build_problems() -> list[str]:
    """What build_report raised (NotebookFailed), if anything: the site exists regardless."""
    return []


@pytest.fixture(scope="session")
def site_dir(chromium, tmp_path_factory, build_problems) -> Path:
    """The built site: ``ANALYSIS_SITE_DIR`` if set, else a fresh build of every notebook
    (``ANALYSIS_SITE_EXECUTE=0``: from their stored outputs and ``build/figures``, as
    ``make test`` does right after nbval has re-executed and compared them)."""
    given = os.environ.get("ANALYSIS_SITE_DIR")
    if given:
        path = Path(given).resolve()
        if not (path / "index.html").exists():
            pytest.fail(f"ANALYSIS_SITE_DIR={given} has no index.html: run make report first")
        return path
    out = tmp_path_factory.mktemp("site") / "report"
    try:
        build_report(out, execute=os.environ.get("ANALYSIS_SITE_EXECUTE", "1") != "0")
    except NotebookFailed as exc:  # the site exists: test it; test_site_built_cleanly fails
        build_problems.append(str(exc))
    return out


@pytest.fixture(scope="session")
def site_url(site_dir) -> str:
    with serve(site_dir) as url:
        yield url


@pytest.fixture(scope="session")
def pages(site_dir) -> list[str]:
    """Every HTML page of the site, as paths relative to its root."""
    found = sorted(site_dir.glob("*.html")) + sorted(site_dir.glob("notebooks/*.html"))
    return [p.relative_to(site_dir).as_posix() for p in found]


@pytest.fixture(scope="session")
def blocked() -> list[str]:
    """Requests to hosts other than 127.0.0.1 that the browser tried (and were aborted)."""
    return []


@pytest.fixture(scope="session")
def pw(chromium):
    """One Playwright driver for the session (a second one in the same process fails)."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        yield p


@pytest.fixture(scope="session")
def context(pw, chromium, site_url, blocked, tmp_path_factory):
    profile = tmp_path_factory.mktemp("chromium-profile")  # a fresh --user-data-dir

    def route(r):
        host = urlsplit(r.request.url).hostname or ""
        if host in LOCAL_HOSTS:
            r.continue_()
        else:
            blocked.append(r.request.url)
            r.abort()

    ctx = pw.chromium.launch_persistent_context(
        str(profile),
        executable_path=chromium,
        headless=True,
        args=list(CHROMIUM_FLAGS),
        viewport={"width": 1280, "height": 900},
        accept_downloads=True,
    )
    ctx.route("**/*", route)
    yield ctx
    ctx.close()


@pytest.fixture
def page(context, blocked):
    pg = context.new_page()
    pg.blocked = blocked
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.js_errors = errors
    yield pg
    pg.close()


@pytest.fixture(scope="session")
def shots() -> Path:
    """Where screenshots go for people to look at (not compared)."""
    d = Path(os.environ.get("ANALYSIS_SCREENSHOTS", PROJECT / "build" / "browser"))
    d.mkdir(parents=True, exist_ok=True)
    return d
