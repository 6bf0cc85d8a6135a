// The explorer on the static report site: no kernel. Builds the controls into every
// <div class="static-explorer"> (analysis.app.site_content.static_explorer_html) and drives the
// 3D view (arm3d_view.js) with the arms' kinematics printed from their closed forms
// (analysis.app.explore_js; window.analysisArms). Interface glue only: no kinematics here.
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
    const row = el("label", {class: "explorer-slider"}, el("span", {class: "explorer-label", text: label}), range, box);
    const set = (v) => { range.value = box.value = v; onchange(); };
    range.addEventListener("input", () => set(range.value));
    box.addEventListener("change", () => { const v = Math.min(hi, Math.max(lo, Number(box.value))); if (Number.isFinite(v)) set(v); });
    row.value = () => Number(box.value);
    row.set = (v) => { range.value = box.value = v; };
    return row;
  }

  function build(root) {
    const cfg = JSON.parse(root.dataset.explorer);
    const figures = cfg.figures;
    const names = cfg.arms.filter((n) => globalThis.analysisArms && globalThis.analysisArms[n]);
    if (!names.length || !A) return;
    const pick = el("select", {class: "explorer-arm", "aria-label": "arm"});
    for (const n of names) pick.append(el("option", {value: n, text: globalThis.analysisArms[n].title + " (" + n + ")"}));
    const fkBox = el("input", {type: "checkbox", class: "explorer-fk"});
    const top = el("div", {class: "explorer-top"}, pick, el("label", {class: "explorer-fk-label"}, fkBox, " FK mode: set the joints"));
    const branchRow = el("div", {class: "explorer-branches", role: "radiogroup", "aria-label": "branch"});
    const sliders = el("div", {class: "explorer-sliders"});
    const message = el("div", {class: "explorer-message"});
    const table = el("div", {class: "explorer-table-wrap"});
    const plot = el("div", {class: "explorer-plot"});
    root.replaceChildren(top, branchRow, sliders, message, table, plot);
    let arm, view, ins = [], joints = [], branch;

    function setArm(name, start) {
      arm = globalThis.analysisArms[name];
      branch = arm.branches[0];
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
      sliders.replaceChildren(...ins, ...joints);
      showMode();
      const ready = view ? view.reset(fig) : null;
      if (!view) view = new A.View(plot, globalThis.Plotly, fig);
      return Promise.resolve(ready).then(update);
    }

    function showMode() {
      for (const s of ins) s.style.display = fkBox.checked ? "none" : "";
      for (const s of joints) s.style.display = fkBox.checked ? "" : "none";
    }

    function inputs() { return ins.map((s, i) => s.value() * (arm.units[i] === "rad" ? DEG : 1)); }

    function update() {
      let r;
      if (fkBox.checked) {
        r = A.pose(arm, {q: joints.map((s) => s.value() * DEG)});
        const p = r.target;
        message.textContent = "FK: gripper at (" + p.map((v) => A.num(v, 2)).join(", ") + ") mm";
        message.className = "explorer-message explorer-ok";
        table.replaceChildren();
      } else {
        r = A.pose(arm, {branch, p: inputs()});
        const s = r.status;
        const word = arm.status_text[s.status];
        const b = s.branches[branch];
        if (s.status !== 0) {
          const far = s.outside > 0 ? ": " + A.num(s.outside, 3) + " mm outside the reach" : "";
          message.textContent = word + far;
        } else if (!b.ok) {
          message.textContent = branch + ": no solution on this branch; pick another branch";
        } else {
          message.textContent = "ok — " + branch + ": θ = (" + b.q.map((v) => A.num(v / DEG, 2)).join(", ") +
            ")° -> pulses (" + b.c.join(", ") + ")";
        }
        message.className = "explorer-message " + (s.status === 0 && b.ok ? "explorer-ok" : "explorer-bad");
        table.replaceChildren(s.status === 0 ? branchTable(s) : "");
      }
      view.draw(r.frames, r.target, r.title, "static");
    }

    function branchTable(s) {
      const head = el("tr", {}, el("th", {text: "branch"}),
        ...arm.joints.map((j) => el("th", {text: greek(j) + " [°]"})),
        ...arm.joints.map((_, i) => el("th", {text: "c" + (i + 1)})), el("th", {text: "status"}));
      const rows = arm.branches.map((b) => {
        const x = s.branches[b];
        const cells = x.ok ? [...x.q.map((v) => A.num(v / DEG, 2)), ...x.c.map(String)] : arm.joints.flatMap(() => ["—", "—"]);
        const tr = el("tr", {class: b === branch ? "explorer-chosen" : ""}, el("td", {text: b}),
          ...cells.map((c) => el("td", {text: c})), el("td", {text: x.ok ? "ok" : "no solution"}));
        return tr;
      });
      return el("table", {class: "explorer-table"}, el("thead", {}, head), el("tbody", {}, ...rows));
    }

    fkBox.addEventListener("change", () => {
      // keep the arm where it is: IK -> the joints of the chosen branch; FK -> its point
      if (fkBox.checked) {
        const b = arm.solve(inputs()).branches[branch];
        if (b && b.ok) b.q.forEach((v, i) => joints[i].set((v / DEG).toFixed(2)));
      } else {
        const p = A.pose(arm, {q: joints.map((s) => s.value() * DEG)}).target;
        ins.forEach((s, i) => { if (AXIS[arm.inputs[i]]) s.set(p[i].toFixed(1)); });
      }
      showMode();
      update();
    });
    pick.addEventListener("change", () => { fkBox.checked = false; setArm(pick.value); });
    pick.value = cfg.arm;
    setArm(cfg.arm);
    root.explorer = {setArm, update, get arm() { return arm; }};
  }

  function start() { for (const root of document.querySelectorAll(".static-explorer[data-explorer]")) build(root); }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start); else start();
})();
