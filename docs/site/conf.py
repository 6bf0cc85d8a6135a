"""Sphinx configuration of the report site (``make report``; see src/analysis/app/report.py).

Sphinx reads a staged source folder written by ``analysis.app.report``: the executed
notebooks (``notebooks/*.ipynb``, rendered by MyST-NB without executing them again), the
generated pages (``index.md``, ``register.md``, ``figures.md``, ``downloads.md``), the
figures and the downloads. This folder only holds the configuration, the style sheet and
the figure captions (captions.toml).

Nothing is loaded from the network when the site is viewed: MathJax 3 is served from
``_static/mathjax`` (the files of the pinned PyPI package ``sphinx-mathjax-offline``),
the theme's fonts and scripts are bundled by the theme, MyST-NB's widget scripts (a
CDN) are switched off, and the explorer's 3D view (a plotly figure, ``text/html`` output of
``analysis.app.arm3d.figure_bundle``) gets ``_static/plotly.min.js``, the plotly.js of the
pinned ``plotly`` wheel, on the pages that hold one.
"""

from __future__ import annotations

from importlib.metadata import distribution
from pathlib import Path

project = "Audit of four robot-kinematics papers"
author = "analysis"
copyright = "the analysis project"
html_title = "Audit: four robot-kinematics papers"

extensions = ["myst_nb", "sphinx.ext.mathjax"]
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence"]
myst_heading_anchors = 3

# The notebooks were executed by analysis.app.report just before (fresh kernels, progress
# on the console); here they are only rendered.
nb_execution_mode = "off"
nb_merge_streams = True
nb_ipywidgets_js: dict = {}  # the default loads require.js and the widget manager from a CDN
nb_output_stderr = "show"

exclude_patterns = ["downloads/**", "figures/**", "**.ipynb_checkpoints"]  # report.py adds print.md for the site
suppress_warnings = ["mystnb.unknown_mime_type"]
# Figure numbers are written into the captions (analysis.app.site_notebooks.figure_numbers):
# one number per figure on every page and in the PDF; Sphinx's numfig numbers a figure where
# it stands (its notebook's page, the front page, the figures page: three numbers).
numfig = False

# --- MathJax 3, served locally ------------------------------------------------------------
_MATHJAX = Path(str(distribution("sphinx-mathjax-offline").locate_file("sphinx-mathjax-offline")))
# --- plotly.js, served locally (the explorer's 3D view) ------------------------------------
_PLOTLY_JS = Path(str(distribution("plotly").locate_file("plotly/package_data/plotly.min.js")))
# --- the explorer's JavaScript (3D view, static explorer), shared with the notebook widget ---
_APP_JS = Path(__file__).resolve().parents[2] / "src" / "analysis" / "app" / "js"
html_static_path = [
    "_static",
    str(_MATHJAX / "static"),
    str(_PLOTLY_JS),
    str(_APP_JS / "arm3d_view.js"),
    str(_APP_JS / "static_explorer.js"),
]  # -> _static/...
mathjax_path = "mathjax/tex-chtml.js"
# the contextual menu without the entries that need components the site does not ship
mathjax_config_path = "mathjax_menu.js"
templates_path = ["_templates"]  # layout.html: the theme's page without fontawesome.js


# --- theme: sphinx-book-theme (sidebar contents, previous/next, search, print) ---------------
html_theme = "sphinx_book_theme"
html_css_files = ["report.css"]
html_copy_source = True  # the header's download button offers the page source (.ipynb, .md)
html_show_sourcelink = False
html_last_updated_fmt = None
html_theme_options = {
    "home_page_in_toc": True,  # the start page is the first entry of the sidebar
    "show_navbar_depth": 1,
    "show_toc_level": 2,  # the page's own contents, right-hand side
    "use_download_button": True,  # .ipynb/.md source and "print to PDF"
    "use_fullscreen_button": False,
    "use_repository_button": False,
    "use_sidenotes": False,
    "show_prev_next": True,
    "navigation_with_keys": False,
    # one search box: the sidebar's (the header's persistent search button was a second one)
    "navbar_persistent": [],
    # the front page opens with the four verdicts at a glance, which link to its sections: its
    # table gets the width of the right-hand contents column (every other page keeps it)
    "secondary_sidebar_items": {"**": ["page-toc"], "index": []},
    # no "By analysis" (the author line names the package, not a person): the copyright only
    "footer_content_items": ["copyright.html", "extra-footer.html"],
}


def _plotly_where_needed(app, pagename, templatename, context, doctree) -> None:
    """Load plotly.min.js (synchronously, before the figures' inline scripts run) only on
    pages with a plotly figure: it is 5 MB."""
    body = context.get("body", "")
    if "plotly-graph-div" in body or "static-explorer" in body:
        app.add_js_file("plotly.min.js", priority=100)
    if "static-explorer" in body:
        app.add_js_file("arm3d_view.js", priority=101)
        app.add_js_file("static_explorer.js", priority=900, defer="defer")


def _words_whole(app, pagename, templatename, context, doctree) -> None:
    """A table cell of one word stays on one line (analysis.app.tables.keep_words_whole)."""
    from analysis.app.tables import keep_words_whole

    if "body" in context and "<t" in context["body"]:
        context["body"] = keep_words_whole(context["body"])


def setup(app) -> None:
    app.connect("html-page-context", _plotly_where_needed)
    app.connect("html-page-context", _words_whole)
