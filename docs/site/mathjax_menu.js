// MathJax's contextual menu without the entries that would load components this site does not
// ship (analysis.app.report._prune_static keeps only what the pages load): the SVG renderer
// (output/svg) and the accessibility explorer, speech and semantic collapse (a11y/explorer,
// a11y/sre and the speech-rule maps). Kept: "Include Hidden MathML" (assistive MathML, part
// of tex-chtml.js and on by default) and "Include in Tab Order". Sphinx inlines this file
// after the site's MathJax configuration (mathjax_config_path in conf.py).
(function () {
  const mj = (window.MathJax = window.MathJax || {});
  mj.startup = Object.assign(mj.startup || {}, {
    ready() {
      MathJax.startup.defaultReady();
      const menu = MathJax.startup.document.menu && MathJax.startup.document.menu.menu;
      if (!menu) return;
      const keep = new Set(["InTabOrder", "AssistiveMml"]);
      const hidden = [["Settings", "Renderer"], ["Show", "Speech"], ["Copy", "Speech"]];
      const a11y = menu.findID("Accessibility");
      for (const item of a11y ? a11y.submenu.items : []) {
        if (item.id && !keep.has(item.id)) hidden.push(["Accessibility", item.id]);
      }
      for (const ids of hidden) {
        const item = menu.findID(...ids);
        if (item) item.hide();
      }
      MathJax.hiddenMenuItems = hidden.map((ids) => ids.join("/"));  // read by the browser tests
    },
  });
})();
