// The explorer's 3D view: one plotly figure (built in Python by analysis.app.arm3d.arm_figure)
// whose arm and target traces are redrawn in place. Shared by the JupyterLab widget
// (analysis.app.arm3d.Arm3DWidget) and the static report page (analysis.app.site_content).
// Drawing only: the kinematics is printed from the closed form (analysis.app.explore_js).
// Every redraw is logged once it is on screen (the next frame painted after plotly returns):
// element.arm3dDraws and window.arm3dDraws hold {t, source, path, frames, target, title}, what the
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

  // The camera through redraws. plotly.js (7.1) redraws the 3D scene on every update with
  // setViewport (the camera from the layout: the user's, saved there at mouseup) and then
  // updateFx, which sets camera.mode = "turntable" again and so puts a camera keyframe 500 ms
  // into the future: for half a second after each redraw the mouse's rotations are dropped (a
  // drag started right after a slider change does nothing, or only part of it counts), and a
  // drag that ends inside that window leaves the camera off the one plotly saved at mouseup,
  // so the next redraw moves it by the difference (the explorer's browser test saw 0.0014).
  // The explorer redraws on every change, so its scene (a) keeps its camera controller when
  // it is already in turntable mode and (b) keeps the camera where the mouse has it while a
  // drag is in progress (plotly saves it into the layout at mouseup, as before).
  /** plotly's 3D scene object of the plot `gd` (undefined before the first draw). */
  function glScene(gd) {
    return gd._fullLayout && gd._fullLayout.scene && gd._fullLayout.scene._scene;
  }

  /** A mouse button is down on the scene's camera: the user is dragging the view. */
  function dragging(scene) {
    const mouse = scene.camera && scene.camera.mouseListener;
    return Boolean(mouse && mouse.buttons);
  }

  function keepCamera(gd) {
    const scene = glScene(gd);
    if (!scene || scene.arm3dKeepsCamera) return;
    if (typeof scene.updateFx !== "function" || typeof scene.setViewport !== "function") return;
    const {updateFx, setViewport} = scene;
    scene.updateFx = function (dragmode, hovermode) {
      if (dragmode === "turntable" && this.camera && this.camera.mode === "turntable") {
        this.fullSceneLayout.hovermode = hovermode;
        return undefined;
      }
      return updateFx.call(this, dragmode, hovermode);
    };
    scene.setViewport = function (sceneLayout) {
      if (dragging(this) && this.camera.mode === "turntable") {
        this.glplot.setAspectratio(sceneLayout.aspectratio); // a drag: the camera is the mouse's
        return undefined;
      }
      return setViewport.call(this, sceneLayout);
    };
    scene.arm3dKeepsCamera = true;
  }

  // The camera a redraw is given: the one on screen, not the one plotly last saved into the
  // layout (at a drag's mouseup plotly saves the camera of that moment, and mouse moves it
  // applies in the next animation frame leave the view a little further on: a redraw from
  // the saved camera moved the view back, by up to 0.06 in the explorer's browser test).
  // During a drag nothing: the camera is the mouse's (keepCamera).
  function liveCamera(gd) {
    const scene = glScene(gd);
    if (!scene || typeof scene.getCamera !== "function" || dragging(scene)) return {};
    return {"scene.camera": scene.getCamera()};
  }

  // WebGL at the screen's own pixel ratio, not plotly's default of 2 (four times the pixels
  // on an ordinary screen): a browser without a GPU (headless Chromium, software WebGL)
  // paints a redraw of the arm in about three quarters of the time (measured in headless
  // Chromium at load 7 on 2 cores, from draw() to the pose on screen: median 190 -> 142 ms);
  // a high-density screen keeps its sharpness.
  function glConfig(config) {
    const ratio = Math.max(1, Math.round(globalThis.devicePixelRatio || 1));
    return Object.assign({plotGlPixelRatio: ratio}, config || {});
  }

  // WebGL without multisampling where the browser renders WebGL in software (no GPU:
  // SwiftShader, llvmpipe; headless Chromium, virtual machines, remote desktops): there every
  // frame's 4x multisampled raster and its read-back to the compositor are most of the time
  // from a typed value to the pose on screen (a trace of Lab's explorer: the main thread's
  // work 8-10 ms, the commit waiting 28-110 ms for the GPU process at load 14 on 2 cores),
  // and without it the static explorer's median went from 42 to 30 ms and its p90 from 90
  // to 39 ms (same browser, alternating blocks; benchmarks/explorer_latency.py measures the
  // explorers). With a GPU nothing changes. plotly.js creates the scene's context itself
  // with antialias on, so the context request of a canvas inside a view (.arm3d-view: the
  // canvas is in its container when gl-plot3d asks) is given antialias off; every other
  // canvas on the page is left alone.
  let softwareGL = null;
  /** The renderer's name when WebGL is rendered in software, else "" (asked once). */
  function softwareRenderer() {
    if (softwareGL !== null) return softwareGL;
    softwareGL = "";
    try {
      const gl = document.createElement("canvas").getContext("webgl");
      const info = gl && gl.getExtension("WEBGL_debug_renderer_info");
      const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : "";
      if (/swiftshader|llvmpipe|softpipe|software/i.test(name)) softwareGL = name;
      const lose = gl && gl.getExtension("WEBGL_lose_context");
      if (lose) lose.loseContext();
    } catch (e) { /* no WebGL: plotly says so */ }
    return softwareGL;
  }
  function noMultisampling() {
    const proto = globalThis.HTMLCanvasElement && HTMLCanvasElement.prototype;
    if (!proto || proto.arm3dGetContext || !softwareRenderer()) return;
    const getContext = proto.getContext;
    proto.arm3dGetContext = getContext;
    proto.getContext = function (kind, attrs) {
      if (/webgl/.test(String(kind)) && this.closest && this.closest(".arm3d-view")) {
        attrs = Object.assign({}, attrs, {antialias: false});
      }
      return getContext.call(this, kind, attrs);
    };
  }

  // A trace's WebGL objects (line, markers, ...) as plotly.js 4 names them on its scene trace.
  const GL_PARTS = ["linePlot", "scatterPlot", "textMarkers", "errorBars", "delaunayMesh"];

  // An empty trace (no solution) cannot be updated in place (plotly's update of a trace with
  // no points throws): its objects are taken off the scene instead and kept, and put back
  // with the next pose. `showHidden` puts every one back, before plotly redraws the figure
  // itself, so that plotly finds the scene as it left it.
  function hide(scene, obj) {
    if (obj.arm3dHidden) return;
    obj.arm3dHidden = GL_PARTS.map((k) => obj[k]).filter(Boolean);
    for (const o of obj.arm3dHidden) scene.glplot.remove(o);
  }
  function show(scene, obj) {
    for (const o of obj.arm3dHidden || []) scene.glplot.add(o);
    obj.arm3dHidden = null;
  }
  function showHidden(gd) {
    const scene = glScene(gd);
    if (!scene || !scene.traces) return;
    for (const obj of Object.values(scene.traces)) if (obj && obj.arm3dHidden) show(scene, obj);
  }

  // A redraw of the arm and target traces alone, in place: the new coordinates go into the
  // figure's data (gd.data, what any later plotly redraw starts from) and its full data, each
  // trace's WebGL objects are updated from them (plotly's own LineWithMarkers.update, which
  // Plotly.update calls too) and the scene is drawn once. Plotly.update recomputes the whole
  // figure for a data change (calc, supplyDefaults, the scene's axes, ticks and every trace)
  // before that same draw; in headless Chromium (software WebGL), with the explorer's figure,
  // measured from the call to the next frame painted: Plotly.update median 72 ms (57-96),
  // this path 27 ms (20-35), the title's relayout included. Returns false (the caller then
  // uses Plotly.update) when the scene is not drawn yet, a trace has never been drawn, or the
  // scene is not plotly's gl3d scene as expected (another plotly.js version).
  function redrawInPlace(gd, idx, data, style) {
    const scene = glScene(gd);
    if (!scene || !scene.glplot || typeof scene.glplot.redraw !== "function" || !scene.traces) return false;
    if (typeof scene.glplot.add !== "function" || typeof scene.glplot.remove !== "function") return false;
    const full = idx.map((i) => (gd._fullData || []).find((t) => t.index === i));
    // a trace hidden from the legend (the link frames, say) has no WebGL objects: its new
    // points go into its data only, which plotly draws when it is shown again
    const off = idx.map((i) => Boolean(gd.data[i]) && gd.data[i].visible !== undefined && gd.data[i].visible !== true);
    const objs = full.map((t, k) => (off[k] ? null : t && scene.traces[t.uid]));
    if (objs.some((o, k) => !off[k] && (!o || typeof o.update !== "function")) || idx.some((i) => !gd.data[i])) return false;
    // a trace plotly has never drawn (empty from the start) has no objects yet: plotly draws it
    if (objs.some((o, k) => !off[k] && !o.arm3dHidden && !GL_PARTS.some((p) => o[p]))) return false;
    idx.forEach((i, k) => {
      for (const c of ["x", "y", "z"]) {
        gd.data[i][c] = data[c][k];
        if (full[k]) full[k][c] = data[c][k]; // (full[k]._input is gd.data[i])
      }
      if (style && style[k]) { // the arm's colours: its own, or greyed (a pose kept, stale)
        for (const part of ["line", "marker"]) {
          gd.data[i][part] = Object.assign({}, gd.data[i][part], {color: style[k][part]});
          if (full[k][part]) full[k][part].color = style[k][part];
        }
      }
      if (off[k]) {
        // drawn when shown again (from gd.data)
      } else if (!data.x[k].length) {
        hide(scene, objs[k]);
      } else {
        // after a redraw with the trace empty, plotly's full trace is a stub (visible: false,
        // no styles): the trace's last drawn full data, with the new points, is drawn
        const from = full[k].visible === false && objs[k].data
          ? Object.assign({}, objs[k].data, {x: data.x[k], y: data.y[k], z: data.z[k]}) : full[k];
        if (style && style[k] && from !== full[k]) {
          for (const part of ["line", "marker"]) from[part] = Object.assign({}, from[part], {color: style[k][part]});
        }
        show(scene, objs[k]);
        objs[k].update(from);
      }
    });
    scene.glplot.redraw();
    return true;
  }

  // The title set where plotly drew it, instead of Plotly.relayout: a relayout of the title
  // re-runs plotly's layout drawing (the title, the modebar, the layout's styles), about 4 ms
  // of the 8 ms a redraw of the arm took on the main thread (headless Chromium, software
  // WebGL, measured by benchmarks/explorer_latency.py's phases). The text goes into the
  // figure's layout (what any later plotly redraw starts from), its full layout and the SVG
  // text node, as plotly writes it for a plain title (one text node, data-unformatted).
  // Only a plain title (nothing plotly would parse: tags, entities, LaTeX) over a title plotly
  // drew as plain text; otherwise false, and the caller relayouts.
  function setTitle(gd, title) {
    const el = gd.querySelector(".g-gtitle > text.gtitle");
    const full = gd._fullLayout && gd._fullLayout.title;
    const layout = gd.layout && gd.layout.title;
    if (!el || !full || !layout || typeof layout !== "object" || /[<>&$]/.test(title)) return false;
    if (el.childElementCount || el.getAttribute("data-math") !== "N" || el.textContent !== full.text) return false;
    layout.text = title;
    full.text = title;
    el.setAttribute("data-unformatted", title);
    el.textContent = title;
    return true;
  }

  /** The points of one joint-axes or frames trace (its `meta.arm3d`, written by
   * analysis.app.arm3d_frames.frame_spec) for the frames `T` (3x4 blocks [R | o], base first):
   * {x, y, z}, null between segments. As arm3d_frames.segments: per joint axis o -/+ L/2 z
   * and an arrowhead at its + end; per triad o -> o + L x, o -> o + L y, o -> o + L z. No
   * frames: empty. */
  function segments(spec, T) {
    const x = [], y = [], z = [];
    const put = (p) => { x.push(p[0]); y.push(p[1]); z.push(p[2]); };
    const gap = [null, null, null];
    if (!T || !T.length) return {x, y, z};
    const L = spec.length;
    for (const f of spec.frames) {
      const M = T[f];
      const o = [M[0][3], M[1][3], M[2][3]];
      const along = (k, s) => [0, 1, 2].map((r) => o[r] + s * M[r][k]);
      if (spec.kind === "axes") { // start, tip, barb, gap, tip, barb, gap (arm3d_frames.HEAD)
        const tip = along(2, 0.5 * L);
        const barb = (s) => [0, 1, 2].map((r) => tip[r] - spec.head[0] * L * M[r][2] + s * spec.head[1] * L * M[r][0]);
        put(along(2, -0.5 * L)); put(tip); put(barb(1)); put(gap); put(tip); put(barb(-1)); put(gap);
      } else {
        for (let k = 0; k < 3; k++) { put(o); put(along(k, L)); put(gap); }
      }
    }
    return {x, y, z};
  }

  const STALE = {line: "#8f969e", marker: "#6b7178"}; // a pose kept without a solution: grey
  const POSE_TOL_MM = 1e-6; // the kernel rounds its frames to 1e-6 mm (explore.Explorer._draw)

  /** Two poses [frames, target, title, transforms] that draw the same: titles equal, every
   * coordinate (and rotation entry) within POSE_TOL_MM. */
  function samePose(a, b) {
    if (!a || !b || a[2] !== b[2]) return false;
    const flat = (v) => (v == null ? null : v.flat(Infinity));
    for (const k of [0, 1, 3]) {
      const u = flat(a[k]), w = flat(b[k]);
      if (u === null || w === null) { if (u !== w) return false; continue; }
      if (u.length !== w.length || u.some((x, i) => !(Math.abs(x - w[i]) <= POSE_TOL_MM))) return false;
    }
    return true;
  }

  class View {
    constructor(el, Plotly, figure) {
      this.el = el;
      this.Plotly = Plotly;
      this.div = document.createElement("div");
      this.div.className = "arm3d-view";
      el.appendChild(this.div);
      el.arm3dDraws = [];
      noMultisampling();
      el.arm3dSoftwareGL = softwareRenderer(); // what the browser tests read
      this.queue = Promise.resolve();
      this.inPlace = true; // false: every redraw through Plotly.update (benchmarks/explorer_redraw.py)
      this.reset(figure);
    }

    reset(figure) {
      const fig = JSON.parse(JSON.stringify(figure));
      this.names = fig.data.map((t) => t.name);
      this.arm = this.names.indexOf("arm");
      this.target = this.names.indexOf("target");
      this.last = null;
      this.lastFrames = null; // the last pose with a solution: kept, greyed, when one has none
      this.lastTransforms = null;
      // the joint axes, link frames and tool frame (traces with meta.arm3d: arm3d_frames), and
      // their own colours (put back after a greyed pose)
      this.frameTraces = fig.data.map((t, i) => [i, t]).filter(([, t]) => t.meta && t.meta.arm3d)
        .map(([i, t]) => ({i, spec: t.meta.arm3d, colours: {line: t.line.color, marker: t.line.color}}));
      const armTrace = fig.data[this.arm] || {};
      this.colours = {
        line: (armTrace.line && armTrace.line.color) || "#1f77b4",
        marker: (armTrace.marker && armTrace.marker.color) || "#0b3c5d",
      };
      this.queue = this.queue
        .then(() => showHidden(this.div))
        .then(() => this.Plotly.react(this.div, fig.data, fig.layout, glConfig(fig.config)))
        .then(() => keepCamera(this.div));
      return this.queue;
    }

    /** Redraw the arm through `frames` ([[x, y, z], ...] mm, or null: no solution), the
     * target cross at `target`, the title, and the joint axes and frames from `transforms`
     * (3x4 blocks, base first: arm.transforms(q), or the kernel's); resolves once it is on
     * screen. */
    draw(frames, target, title, source, transforms) {
      const asked = performance.now();
      // no solution: the last pose stays where it was, greyed (the view does not jump, and
      // what the arm last did stays in sight); the first pose of an arm has none to keep
      const stale = !frames && Boolean(this.lastFrames);
      if (frames) { this.lastFrames = frames; this.lastTransforms = transforms || null; }
      else if (stale) { frames = this.lastFrames; transforms = this.lastTransforms; }
      const pose = [frames, target, title, frames ? transforms || null : null];
      // the same pose again (the kernel's, rounded to 1e-6 mm, after the browser's): no redraw
      if (samePose(pose, this.last)) return this.queue;
      this.last = pose;
      this.el.arm3dPending = (this.el.arm3dPending || 0) + 1;
      const pts = frames || [];
      const col = (k) => pts.map((p) => p[k]);
      const data = {x: [col(0)], y: [col(1)], z: [col(2)]};
      const idx = [this.arm];
      const colours = stale ? STALE : this.colours;
      const style = [colours];
      if (this.target >= 0) {
        const t = target ? [target] : [];
        data.x.push(t.map((p) => p[0]));
        data.y.push(t.map((p) => p[1]));
        data.z.push(t.map((p) => p[2]));
        idx.push(this.target);
        style.push(null);
      }
      for (const f of this.frameTraces) { // joint axes, link frames, tool frame
        const seg = segments(f.spec, frames ? transforms : null);
        data.x.push(seg.x); data.y.push(seg.y); data.z.push(seg.z);
        idx.push(f.i);
        style.push(stale ? STALE : f.colours);
      }
      let started, plotted, path;
      this.queue = this.queue
        .then(() => { started = performance.now(); })
        .then(() => {
          let inPlace = false;
          try {
            inPlace = this.inPlace && redrawInPlace(this.div, idx, data, style);
          } catch (e) { // the figure's data already holds the pose: plotly redraws it all
            console.warn("arm3d: redraw in place failed, plotly redraws", e);
          }
          path = inPlace ? "in-place" : "plotly";
          if (!inPlace) {
            showHidden(this.div);
            const now = (k, part) => ((this.div.data[idx[k]] || {})[part] || {}).color || null;
            const styled = Object.assign({}, data, {
              "line.color": style.map((c, k) => (c ? c.line : now(k, "line"))),
              "marker.color": style.map((c, k) => (c ? c.marker : now(k, "marker"))),
            });
            return this.Plotly.update(this.div, styled, Object.assign({"title.text": title}, liveCamera(this.div)), idx);
          }
          const now = this.div._fullLayout.title && this.div._fullLayout.title.text;
          if (now === title || setTitle(this.div, title)) return undefined;
          return this.Plotly.relayout(this.div, {"title.text": title});
        })
        .then(() => { plotted = performance.now(); })
        .then(onScreen)
        .then(() => {
          // asked: draw() called; started: plotly began (after earlier draws); plotted: it
          // returned; t: the next frame painted; path: redrawn in place or by Plotly.update
          const rec = {t: performance.now(), asked, started, plotted, path, source, frames, target, title, stale};
          this.el.arm3dDraws.push(rec);
          (globalThis.arm3dDraws = globalThis.arm3dDraws || []).push(rec);
          this.el.dispatchEvent(new CustomEvent("arm3d-drawn", {detail: rec, bubbles: true}));
        })
        .catch((e) => console.error("arm3d: a redraw failed", e)) // the next one still runs
        .finally(() => { this.el.arm3dPending -= 1; });
      return this.queue;
    }
  }

  /** The pose the printed kinematics gives: for IK, target `p` (inputs, angles in rad) on
   * `branch` (`theta1`: the waist angle on the base axis [rad], or null); for FK (`q`
   * given), the joint angles. Returns {frames, target, title, q, status}. */
  function pose(arm, {branch, p, q, theta1}) {
    let title = arm.title + " · ";
    let target = null;
    if (q) {
      title += "FK";
      const frames = arm.frames(q);
      target = frames[frames.length - 1];
      return {frames, target, q, transforms: arm.transforms(q), title: title + " · θ = (" + q.map((v) => num(v * 180 / Math.PI, 2)).join(", ") + ")°"};
    }
    const ix = ["px", "py", "pz"].map((k) => arm.inputs.indexOf(k));
    if (ix.every((i) => i >= 0)) target = ix.map((i) => p[i]);
    const s = arm.solve(p, theta1);
    const b = s.branches[branch];
    title += branch;
    if (!b || !b.ok) return {frames: null, target, q: null, title: title + " · no solution", status: s};
    title += " · θ = (" + b.q.map((v) => num(v * 180 / Math.PI, 2)).join(", ") + ")°";
    return {frames: arm.frames(b.q), transforms: arm.transforms(b.q), target, q: b.q, title, status: s};
  }

  globalThis.analysisArm3d = {plotly, View, pose, num, segments};
})();
