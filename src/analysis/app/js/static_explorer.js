// The explorer on the static report site: no kernel. Builds the controls into every
// <div class="static-explorer"> (analysis.app.site_content.static_explorer_html) and drives the
// 3D view (arm3d_view.js) with the arms' kinematics printed from their closed forms
// (analysis.app.explore_js; window.analysisArms). Interface glue: the kinematics is printed,
// the sentences are analysis.app.explain's templates (arm.explain), filled here with the same
// numbers as in Python (the browser tests hold the two equal).
(function () {
  "use strict";
  const A = globalThis.analysisArm3d;
  const DEG = Math.PI / 180;
  const GREEK = [["theta", "θ"], ["alpha", "α"], ["beta", "β"], ["gamma", "γ"]];
  const greek = (n) => { for (const [w, l] of GREEK) if (n.startsWith(w)) return l + n.slice(w.length); return n; };
  const AXIS = {px: "x", py: "y", pz: "z"};

  function el(tag, attrs, ...kids) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === "class") e.className = v; else if (k === "text") e.textContent = v; else e.setAttribute(k, v);
    }
    for (const k of kids) e.append(k);
    return e;
  }

  function slider(label, lo, hi, step, value, onchange) {
    const range = el("input", {type: "range", min: lo, max: hi, step, "aria-label": label});
    const box = el("input", {type: "number", min: lo, max: hi, step, class: "explorer-number", "aria-label": label});
    range.value = box.value = value;
    const note = el("span", {class: "explorer-clamped", role: "status"});
    const row = el("label", {class: "explorer-slider"}, el("span", {class: "explorer-label", text: label}), range, box, note);
    const set = (v) => { range.value = box.value = v; onchange(); };
    range.addEventListener("input", () => { note.textContent = ""; set(range.value); });
    box.addEventListener("change", () => {
      // a typed value beyond the slider's range is taken at the range's end, and says so
      const typed = Number(box.value);
      if (!Number.isFinite(typed)) { note.textContent = "not a number"; return; }
      const v = Math.min(Number(hi), Math.max(Number(lo), typed));
      note.textContent = v !== typed ? `${A.num(typed, 2)} is beyond ${lo} .. ${hi}: ${v} taken` : "";
      set(v);
    });
    row.value = () => Number(box.value);
    row.set = (v) => { range.value = box.value = v; note.textContent = ""; };
    return row;
  }

  // --- analysis.app.explain, filled with the page's numbers ----------------------------
  function fmtG(v) { // Python's format(v, "g") for the values a slider holds
    if (v === 0) return "0";
    const s = Number(v.toPrecision(6));
    const e = Math.floor(Math.log10(Math.abs(s)));
    if (e < -4 || e >= 6) {
      const [m, x] = s.toExponential().split("e");
      const xs = Math.abs(Number(x)) < 10 ? "0" + Math.abs(Number(x)) : String(Math.abs(Number(x)));
      return Number(m) + "e" + (Number(x) < 0 ? "-" : "+") + xs;
    }
    return String(s);
  }

  function targetText(arm, p, decimals, word = true) {
    const f = decimals === undefined ? (v) => fmtG(v + 0) : (v) => (v + 0).toFixed(decimals);
    const mm = [], deg = [];
    p.forEach((v, i) => (arm.units[i] === "mm" ? mm : deg).push(arm.units[i] === "mm" ? f(v) : f(v * 180 / Math.PI)));
    const text = deg.length ? `pose (${mm.join(", ")}) mm, RPY (${deg.join(", ")}) deg` : `target (${mm.join(", ")}) mm`;
    return word ? text : text.slice(text.indexOf(" ") + 1);
  }

  function fill(template, fields) { return template.replace(/\{(\w+)\}/g, (_, k) => fields[k]); }

  /** explain.line_search: the s nearest 1 in (0, sMax] where ok(s), ok(1) false. */
  function lineSearch(ok, sMax, scan, rounds) {
    let best = null;
    for (let k = 1; k <= scan; k++) {
      const s = sMax * k / scan;
      if (ok(s) && (best === null || Math.abs(s - 1) < Math.abs(best - 1))) best = s;
    }
    if (best === null) return null;
    let lo = best, hi = 1;
    for (let r = 0; r < rounds; r++) {
      const grid = [];
      for (let k = 1; k < scan; k++) grid.push(lo + (hi - lo) * k / scan);
      let last = -1;
      grid.forEach((s, k) => { if (ok(s)) last = k; });
      if (last >= 0) { lo = grid[last]; if (last + 1 < grid.length) hi = grid[last + 1]; } else hi = grid[0];
    }
    return lo;
  }

  function nearestTarget(arm, p, branch, theta1) {
    const pos = arm.units.map((u, k) => (u === "mm" ? k : -1)).filter((k) => k >= 0).slice(0, 3);
    const c = arm.center.slice(0, pos.length);
    const d = Math.hypot(...pos.map((k, i) => p[k] - c[i]));
    const sMax = 2 + 2 * arm.reach / Math.max(d, 1e-9);
    const at = (s) => { const out = p.slice(); pos.forEach((k, i) => { out[k] = c[i] + s * (p[k] - c[i]); }); return out; };
    const ok = (s) => Boolean(arm.solve(at(s), theta1).branches[branch].ok);
    const s = lineSearch(ok, sMax, arm.explain.scan, arm.explain.rounds);
    return s === null ? null : at(s);
  }

  function explain(arm, p, status, outside, branch, why, theta1) {
    const T = arm.explain.templates;
    const fields = {target: targetText(arm, p), branch, why, outside: Math.abs(outside).toFixed(3), choose: arm.explain.choose};
    if (status === 0) return {word: "ok", sentence: fill(T.branch, fields), nearest: null};
    const word = arm.status_text[status];
    let nearest = null;
    if (word === "out-of-reach" || word === "inside-reach") {
      nearest = nearestTarget(arm, p, branch, theta1);
      const center = "(" + arm.center.map((v) => fmtG(v + 0)).join(", ") + ")";
      fields.nearest_sentence = fill(T[nearest === null ? "no-nearest" : "nearest"],
        {center, nearest: nearest === null ? "" : targetText(arm, nearest, 3, false)});
    }
    return {word, sentence: fill(T[word], fields), nearest};
  }

  // --- the explorer ---------------------------------------------------------------------
  function build(root) {
    const cfg = JSON.parse(root.dataset.explorer);
    const figures = cfg.figures;
    const names = cfg.arms.filter((n) => globalThis.analysisArms && globalThis.analysisArms[n]);
    if (!names.length || !A) return;
    const pick = el("select", {class: "explorer-arm", "aria-label": "arm"});
    for (const n of names) pick.append(el("option", {value: n, text: globalThis.analysisArms[n].title + " (" + n + ")"}));
    const fkBox = el("input", {type: "checkbox", class: "explorer-fk"});
    const axisBox = el("input", {type: "checkbox", class: "explorer-axis"});
    const axisLabel = el("label", {class: "explorer-axis-label"}, axisBox, " allow θ1 on the base axis");
    const top = el("div", {class: "explorer-top"}, pick, el("label", {class: "explorer-fk-label"}, fkBox, " FK mode: set the joints"), axisLabel);
    const branchRow = el("div", {class: "explorer-branches", role: "radiogroup", "aria-label": "branch"});
    const sliders = el("div", {class: "explorer-sliders"});
    const message = el("div", {class: "explorer-message", role: "status"});
    const table = el("div", {class: "explorer-table-wrap"});
    const plot = el("div", {class: "explorer-plot"});
    const left = cfg.left || {};
    const leftNote = Object.keys(left).length
      ? el("p", {class: "explorer-left-out", text: Object.entries(left).map(([n, why]) => `${n}: ${why}`).join("; ")})
      : "";
    root.replaceChildren(top, branchRow, sliders, message, table, plot, leftNote);
    let arm, view, ins = [], joints = [], axisDeg = null, branch, lastQ = null;

    function setArm(name, start) {
      arm = globalThis.analysisArms[name];
      branch = arm.branches[0];
      lastQ = null;
      branchRow.replaceChildren(...arm.branches.map((b) => {
        const r = el("input", {type: "radio", name: "branch-" + cfg.id, value: b});
        r.checked = b === branch;
        r.addEventListener("change", () => { branch = b; update(); });
        return el("label", {class: "explorer-branch"}, r, " " + b);
      }));
      const fig = figures[name];
      const scene = fig.layout.scene;
      const t = start || cfg.start[name];
      ins = arm.inputs.map((k, i) => {
        if (AXIS[k]) {
          const r = scene[AXIS[k] + "axis"].range;
          return slider(AXIS[k] + " [mm]", r[0], r[1], 0.1, Number(t[i].toFixed(1)), update);
        }
        return slider(greek(k) + " [°]", -180, 180, 0.01, (t[i] / DEG).toFixed(2), update);
      });
      joints = arm.joints.map((j, i) => {
        const lim = arm.limits[i] || [-Math.PI, Math.PI];
        return slider(greek(j) + " [°]", (lim[0] / DEG).toFixed(2), (lim[1] / DEG).toFixed(2), 0.01, 0, update);
      });
      axisDeg = arm.on_axis ? slider("θ1 on the axis [°]", -180, 180, 0.01, 0, update) : null;
      axisBox.checked = false;
      axisLabel.style.display = arm.on_axis ? "" : "none";
      sliders.replaceChildren(...ins, ...joints, ...(axisDeg ? [axisDeg] : []));
      showMode();
      const ready = view ? view.reset(fig) : null;
      if (!view) view = new A.View(plot, globalThis.Plotly, fig);
      return Promise.resolve(ready).then(update);
    }

    function showMode() {
      for (const s of ins) s.style.display = fkBox.checked ? "none" : "";
      for (const s of joints) s.style.display = fkBox.checked ? "" : "none";
      if (axisDeg) axisDeg.style.display = axisBox.checked && !fkBox.checked ? "" : "none";
      axisLabel.style.visibility = fkBox.checked ? "hidden" : "";
    }

    function inputs() { return ins.map((s, i) => s.value() * (arm.units[i] === "rad" ? DEG : 1)); }
    function theta1() { return axisDeg && axisBox.checked ? axisDeg.value() * DEG : null; }

    function update() {
      let r;
      if (fkBox.checked) {
        const q = joints.map((s) => s.value() * DEG);
        r = A.pose(arm, {q});
        message.textContent = fkLine(q, r);
        message.className = "explorer-message explorer-ok";
      } else {
        const p = inputs(), t1 = theta1();
        r = A.pose(arm, {branch, p, theta1: t1});
        const s = r.status;
        const b = s.branches[branch];
        let text;
        if (s.status === 0 && b.ok) {
          text = "ok — " + branch + ": θ = (" + b.q.map((v) => A.num(v / DEG, 2)).join(", ") +
            ")° -> " + pulsesText(b.c);
        } else {
          const e = explain(arm, p, s.status, s.outside, branch, s.status === 0 ? rowStatus(s, branch) : "", t1);
          text = e.word + " — " + e.sentence;
        }
        message.textContent = text;
        message.className = "explorer-message " + (s.status === 0 && b.ok ? "explorer-ok" : "explorer-bad");
        table.replaceChildren(branchTable(s, arm.explain.captions.ik, p, t1));
      }
      if (r.q) lastQ = r.q;
      view.draw(r.frames, r.target, r.title, "static", r.transforms);
    }

    /** A branch's own status word (as solved alone: explore_logic.pose_report's table). */
    function rowStatus(s, b) { return arm.status_text[s.branches[b].status]; }

    /** RPY angles [rad] of a rotation R (3 rows): analysis.kinematics.rpy.rpy_from_matrix
     * (seed 004 eq. 3.18, beta in [-90, 90] deg; at gimbal lock alpha = 0). */
    function rpy(R) {
      const cb = Math.hypot(R[0][0], R[1][0]);
      const beta = Math.atan2(-R[2][0], cb);
      if (cb < arm.gimbal_lock_cos) {
        const sign = R[2][0] < 0 ? 1 : -1;
        return [0, beta, Math.atan2(sign * R[0][1], R[1][1])];
      }
      return [Math.atan2(R[1][0], R[0][0]), beta, Math.atan2(R[2][1], R[2][2])];
    }

    /** Whole pulses as the explorer says them (explore_logic: "pulses: no drive given"
     * where the description gives none, c null). */
    function pulsesText(c) { return c === null ? "pulses: no drive given" : "pulses (" + c.join(", ") + ")"; }

    /** explore_logic.fk_line: joints, pulses, the full pose (fk --json: the tool point and
     * its RPY angles) and the branch they belong to. */
    function fkLine(q, r) {
      const joints = q.map((v, j) => A.num(v / DEG, 2) + (arm.joint_units[j] === "deg" ? "°" : " " + arm.joint_units[j])).join(", ");
      const tool = r.frames[r.frames.length - 1];
      const angles = rpy(arm.tool_rotation(q)).map((v) => A.num(v / DEG, 2)).join(", ");
      let text = `FK: joints (${joints}) → ${pulsesText(arm.pulses(q))}; tool at (${tool.map((v) => A.num(v, 2)).join(", ")}) mm, RPY (${angles})°`;
      const pointOnly = arm.inputs.every((k) => AXIS[k]);
      if (pointOnly) {
        const s = arm.solve(tool, q[0]);
        const mine = belongs(q, s);
        text += mine.branch ? `; branch: ${mine.branch}` : `; branch: none (${mine.why})`;
        table.replaceChildren(branchTable(s, arm.explain.captions.fk, tool, q[0]));
      } else {
        table.replaceChildren();
      }
      return text;
    }

    function belongs(q, s) {
      let best = null, worst = 0, diff = Infinity;
      for (const b of arm.branches) {
        const x = s.branches[b];
        if (!x.ok) continue;
        const d = x.q.map((v, j) => Math.abs((((v - q[j]) / DEG + 180) % 360 + 360) % 360 - 180));
        const m = Math.max(...d);
        if (m <= 1e-6 / DEG) return {branch: b};
        if (m < diff) { best = b; worst = d.indexOf(m); diff = m; }
      }
      if (best === null) return {why: "no branch solves the point"};
      const j = worst, label = greek(arm.joints[j]);
      return {why: `the nearest, ${best}, has ${label} = ${A.num(s.branches[best].q[j] / DEG, 2)}° where it is set to ${A.num(q[j] / DEG, 2)}°`};
    }

    function branchTable(s, caption, p, t1) {
      const head = el("tr", {}, el("th", {text: "branch"}),
        ...arm.joints.map((j) => el("th", {text: greek(j) + " [°]"})),
        ...(arm.pulses_per_rev === null ? [] : arm.joints.map((_, i) => el("th", {text: "c" + (i + 1)}))),
        el("th", {text: "status"}));
      const rows = arm.branches.map((b) => {
        const x = s.branches[b];
        const ok = s.status === 0 && x.ok;
        const c = x.c === null ? [] : x.c;
        const cells = ok ? [...x.q.map((v) => A.num(v / DEG, 2)), ...c.map(String)] : arm.joints.flatMap(() => x.c === null ? ["—"] : ["—", "—"]);
        const word = ok ? "ok" : s.status !== 0 ? arm.status_text[s.status] : rowStatus(s, b);
        return el("tr", {class: b === branch ? "explorer-chosen" : ""}, el("td", {text: b}),
          ...cells.map((c) => el("td", {text: c})), el("td", {text: word}));
      });
      return el("table", {class: "explorer-table"}, el("caption", {text: caption}), el("thead", {}, head), el("tbody", {}, ...rows));
    }

    fkBox.addEventListener("change", () => {
      // keep the arm where it is: IK -> the joints of the chosen branch (or of the pose kept,
      // greyed, when the target has none); FK -> its point
      if (fkBox.checked) {
        const b = arm.solve(inputs(), theta1()).branches[branch];
        const q = b && b.ok ? b.q : lastQ;
        if (q) q.forEach((v, i) => joints[i].set((v / DEG).toFixed(2)));
      } else {
        const p = A.pose(arm, {q: joints.map((s) => s.value() * DEG)}).target;
        ins.forEach((s, i) => { if (AXIS[arm.inputs[i]]) s.set(p[i].toFixed(1)); });
      }
      showMode();
      update();
    });
    axisBox.addEventListener("change", () => { showMode(); update(); });
    pick.addEventListener("change", () => { fkBox.checked = false; setArm(pick.value); });
    pick.value = cfg.arm;
    setArm(cfg.arm);
    root.explorer = {setArm, update, explain: (p, st, out, b, why, t1) => explain(arm, p, st, out, b, why, t1), get arm() { return arm; }};
  }

  function start() { for (const root of document.querySelectorAll(".static-explorer[data-explorer]")) build(root); }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start); else start();
})();
