// The explorer's 3D view: one plotly figure (built in Python by analysis.app.arm3d.arm_figure)
// whose arm and target traces are redrawn in place. Shared by the JupyterLab widget
// (analysis.app.arm3d.Arm3DWidget) and the static report page (analysis.app.site_content).
// Drawing only: the kinematics is printed from the closed form (analysis.app.explore_js).
// Every redraw is logged once it is on screen (the next frame painted after plotly returns):
// element.arm3dDraws and window.arm3dDraws hold {t, source, frames, target, title}, what the
// browser tests read (time from a control's change to the new pose on screen, the drawn
// joint positions against forward kinematics).
(function () {
  "use strict";
  if (globalThis.analysisArm3d) return;

  let plotlyPromise = null;
  /** window.Plotly, or the text fetch() returns (plotly.min.js) evaluated once per page. */
  function plotly(fetchText) {
    if (globalThis.Plotly) return Promise.resolve(globalThis.Plotly);
    if (!plotlyPromise) {
      plotlyPromise = fetchText().then((text) => {
        // plotly.min.js is a UMD bundle: with no `module` in scope it sets window.Plotly
        new Function("module", "exports", "define", text)();
        return globalThis.Plotly;
      });
    }
    return plotlyPromise;
  }

  function num(v, d) {
    // as analysis.app.explore_logic.num: d decimals, never "-0.00"
    const s = v.toFixed(d);
    return /^-0\.?0*$/.test(s) ? s.slice(1) : s;
  }

  // resolves just after the next frame is painted: an animation frame callback runs before
  // the paint, a message posted from it runs after (the usual "next paint" measure)
  function onScreen() {
    return new Promise((r) => requestAnimationFrame(() => {
      const ch = new MessageChannel();
      ch.port1.onmessage = () => r();
      ch.port2.postMessage(0);
    }));
  }

  class View {
    constructor(el, Plotly, figure) {
      this.el = el;
      this.Plotly = Plotly;
      this.div = document.createElement("div");
      this.div.className = "arm3d-view";
      el.appendChild(this.div);
      el.arm3dDraws = [];
      this.queue = Promise.resolve();
      this.reset(figure);
    }

    reset(figure) {
      const fig = JSON.parse(JSON.stringify(figure));
      this.names = fig.data.map((t) => t.name);
      this.arm = this.names.indexOf("arm");
      this.target = this.names.indexOf("target");
      this.last = null;
      this.queue = this.queue.then(() =>
        this.Plotly.react(this.div, fig.data, fig.layout, fig.config || {}));
      return this.queue;
    }

    /** Redraw the arm through `frames` ([[x, y, z], ...] mm, or null: no solution), the
     * target cross at `target` and the title; resolves once it is on screen. */
    draw(frames, target, title, source) {
      const asked = performance.now();
      const key = JSON.stringify([frames, target, title]);
      if (key === this.last) return this.queue;
      this.last = key;
      const pts = frames || [];
      const col = (k) => pts.map((p) => p[k]);
      const data = {x: [col(0)], y: [col(1)], z: [col(2)]};
      const idx = [this.arm];
      if (this.target >= 0) {
        const t = target ? [target] : [];
        data.x.push(t.map((p) => p[0]));
        data.y.push(t.map((p) => p[1]));
        data.z.push(t.map((p) => p[2]));
        idx.push(this.target);
      }
      let started, plotted;
      this.queue = this.queue
        .then(() => { started = performance.now(); })
        .then(() => this.Plotly.update(this.div, data, {"title.text": title}, idx))
        .then(() => { plotted = performance.now(); })
        .then(onScreen)
        .then(() => {
          // asked: draw() called; started: plotly began (after earlier draws); plotted: it
          // returned; t: the next frame painted
          const rec = {t: performance.now(), asked, started, plotted, source, frames, target, title};
          this.el.arm3dDraws.push(rec);
          (globalThis.arm3dDraws = globalThis.arm3dDraws || []).push(rec);
          this.el.dispatchEvent(new CustomEvent("arm3d-drawn", {detail: rec, bubbles: true}));
        });
      return this.queue;
    }
  }

  /** The pose the printed kinematics gives: for IK, target `p` (inputs, angles in rad) on
   * `branch`; for FK (`q` given), the joint angles. Returns {frames, target, title, q}. */
  function pose(arm, {branch, p, q}) {
    let title = arm.title + " · ";
    let target = null;
    if (q) {
      title += "FK";
      const frames = arm.frames(q);
      target = frames[frames.length - 1];
      return {frames, target, q, title: title + " · θ = (" + q.map((v) => num(v * 180 / Math.PI, 2)).join(", ") + ")°"};
    }
    const ix = ["px", "py", "pz"].map((k) => arm.inputs.indexOf(k));
    if (ix.every((i) => i >= 0)) target = ix.map((i) => p[i]);
    const s = arm.solve(p);
    const b = s.branches[branch];
    title += branch;
    if (!b || !b.ok) return {frames: null, target, q: null, title: title + " · no solution", status: s};
    title += " · θ = (" + b.q.map((v) => num(v * 180 / Math.PI, 2)).join(", ") + ")°";
    return {frames: arm.frames(b.q), target, q: b.q, title, status: s};
  }

  globalThis.analysisArm3d = {plotly, View, pose, num};
})();
