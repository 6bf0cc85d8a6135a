// The anywidget module of analysis.app.arm3d.Arm3DWidget (prefixed by arm3d_view.js).
// The kernel sends the figure, the arm's kinematics printed as JavaScript (explore_js) and the
// ids of the explorer's controls. On every change of a control the pose is drawn at once from
// the printed kinematics, without a round trip to the kernel; the kernel's own pose (trait
// `pose`, computed by Arm.solve/Arm.frames) is drawn when it arrives for the controls' current
// values (and is what an arm without printed kinematics shows). plotly.js is not stored in the
// widget's state: the kernel sends it once per page as a binary message (5 MB that a saved
// notebook would otherwise carry).
// The kernel confirms: when its pose for the controls' values differs from the one the browser
// drew for the same values (a joint position by more than 1e-6 mm, or the title), the kernel's
// is drawn and a note over the view says by how much (el.arm3dDisagreement holds it; the Lab
// browser test makes the browser's kinematics wrong and reads it); the next pose they agree on
// clears it.
const A = globalThis.analysisArm3d;

function fetchPlotly(model) {
  return new Promise((resolve) => {
    const onMsg = (msg, buffers) => {
      if (msg && msg.type === "plotly" && buffers && buffers.length) {
        model.off("msg:custom", onMsg);
        resolve(new TextDecoder().decode(buffers[0]));
      }
    };
    model.on("msg:custom", onMsg);
    model.send({type: "plotly?"});
  });
}

// a control's value: selection widgets (the branch buttons) sync an index into their labels
function value(m) {
  if (!m) return null;
  const labels = m.get("_options_labels");
  return labels ? labels[m.get("index")] : m.get("value");
}

/** The largest distance [mm] between two poses' joint positions (Infinity: one has a
 * solution and the other not, or they have different joints); 0 for two without. */
function poseGap(a, b) {
  if (!a || !b) return a === b ? 0 : Infinity;
  if (a.length !== b.length) return Infinity;
  return Math.max(0, ...a.map((p, i) => Math.hypot(p[0] - b[i][0], p[1] - b[i][1], p[2] - b[i][2])));
}

function sameKey(a, b) {
  if (!a || !b || a.length !== b.length) return false;
  return a.every((v, i) => (typeof v === "number" && typeof b[i] === "number"
    ? Math.abs(v - b[i]) <= 1e-9 * Math.max(1, Math.abs(v)) : v === b[i]));
}

async function render({model, el}) {
  el.classList.add("arm3d-widget");
  const Plotly = await A.plotly(() => fetchPlotly(model));
  const view = new A.View(el, Plotly, model.get("figure"));
  // over the view's lower left corner: the page does not move when it appears
  el.style.position = "relative";
  const note = document.createElement("div");
  note.className = "arm3d-disagree";
  note.setAttribute("role", "status");
  note.style.cssText = "position:absolute;left:8px;bottom:8px;max-width:70%;font-size:12px;"
    + "background:#fff3cd;color:#664d03;padding:2px 6px;border-radius:3px;display:none";
  el.appendChild(note);
  let drawnHere = null; // the browser's last pose: {key, frames, title}
  let arm = null;
  let ctl = null;
  const unhook = [];

  function compile() {
    const src = model.get("kinematics");
    try {
      arm = src ? new Function("return " + src)() : null;
    } catch (e) {
      console.error("arm3d: kinematics did not load", e);
      arm = null;
    }
  }

  async function wire() {
    for (const f of unhook.splice(0)) f();
    const ids = model.get("controls") || {};
    const get = (id) => model.widget_manager.get_model(id.replace(/^IPY_MODEL_/, ""));
    const one = async (id) => (id ? await get(id) : null);
    const many = async (list) => Promise.all((list || []).map(get));
    const c = {
      inputs: await many(ids.inputs), joints: await many(ids.joints), units: ids.units || [],
      branch: await one(ids.branch), fk: await one(ids.fk), axis: await one(ids.on_axis),
      axisDeg: await one(ids.on_axis_deg),
    };
    for (const m of [...c.inputs, ...c.joints, c.branch, c.fk, c.axis, c.axisDeg]) {
      if (!m) continue;
      const cb = () => { el.arm3dKernelCurrent = false; local(); };
      m.on("change:value change:index", cb);
      unhook.push(() => m.off("change:value change:index", cb));
    }
    ctl = c;
  }

  // the controls' values, in the order of Explorer.pose_key() (Python)
  function key() {
    if (!ctl) return null;
    const v = value;
    return [v(ctl.fk), v(ctl.branch), ...ctl.inputs.map(v), ...ctl.joints.map(v), v(ctl.axis), v(ctl.axisDeg)];
  }

  function local() {
    if (!arm || !ctl || ctl.inputs.length !== arm.inputs.length) return;
    const fk = value(ctl.fk);
    const rad = Math.PI / 180;
    let r;
    if (fk) {
      r = A.pose(arm, {q: ctl.joints.map((m) => value(m) * rad)});
    } else {
      const p = ctl.inputs.map((m, i) => value(m) * (ctl.units[i] === "rad" ? rad : 1));
      const theta1 = value(ctl.axis) && arm.on_axis ? value(ctl.axisDeg) * rad : null;
      r = A.pose(arm, {branch: value(ctl.branch), p, theta1});
    }
    drawnHere = {key: key(), frames: r.frames, title: r.title, transforms: r.transforms};
    view.draw(r.frames, r.target, r.title, "local", r.transforms);
  }

  // the kernel's pose against the browser's for the same controls' values
  function confirm(p) {
    if (!drawnHere || !sameKey(drawnHere.key, p.key)) return;
    const gap = poseGap(drawnHere.frames, p.frames);
    // the joint axes and frames too (the kernel rounds them to 1e-6, as the joint positions)
    const flat = (T) => (T ? [].concat(...T.map((M) => [].concat(...M))) : []);
    const [u, w] = [flat(drawnHere.transforms), flat(p.transforms)];
    const frames = u.length === w.length && u.every((v, i) => Math.abs(v - w[i]) <= 1e-6);
    const agree = gap <= 1e-6 && drawnHere.title === p.title && frames;
    el.arm3dDisagreement = agree ? null : {mm: gap, browser: drawnHere.title, kernel: p.title};
    note.style.display = agree ? "none" : "";
    note.textContent = agree ? "" : "The kernel corrected the pose the browser drew ("
      + (Number.isFinite(gap) ? `${A.num(gap, 3)} mm apart` : "one of them without a solution")
      + (drawnHere.title === p.title ? "" : "; the titles differ")
      + (frames ? "" : "; the joint axes or frames differ") + "): the kernel's is drawn.";
  }

  function kernel() {
    const p = model.get("pose");
    if (!p || !p.title) return;
    // for values the controls have left: not drawn (el.arm3dKernelCurrent says whether the
    // kernel's pose is for the controls' values, what the browser tests wait on)
    el.arm3dKernelCurrent = !(ctl && p.key && !sameKey(p.key, key()));
    if (!el.arm3dKernelCurrent) return;
    el.arm3dConfirmedAt = performance.now(); // the kernel's pose in (benchmarks/explorer_latency.py)
    confirm(p);
    view.draw(p.frames, p.target, p.title, "kernel", p.transforms);
  }

  const onFigure = () => view.reset(model.get("figure")).then(kernel);
  const onKin = () => { compile(); local(); };
  const onCtl = () => wire().then(local);
  model.on("change:figure", onFigure);
  model.on("change:kinematics", onKin);
  model.on("change:controls", onCtl);
  model.on("change:pose", kernel);
  compile();
  await wire();
  kernel();
  return () => {
    for (const f of unhook.splice(0)) f();
    model.off("change:figure", onFigure);
    model.off("change:kinematics", onKin);
    model.off("change:controls", onCtl);
    model.off("change:pose", kernel);
  };
}

export default {render};
