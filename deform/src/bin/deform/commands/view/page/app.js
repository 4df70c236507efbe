// The editor page: panels, mouse, the socket to the server, and the frame loop.
"use strict";
const $ = (id) => document.getElementById(id);
const canvas = $("view"), camera = new Camera(), gizmo = new Gizmo(camera);
const renderer = new Renderer(canvas);
const ed = {
  state: null, rest: null, positions: null, groupsOf: null, n: 0, bbox: null,
  groups: [], // per group: { c, s, q, t }
  joints: [], // joint frames [x y z qx qy qz qw] of the last pose
  edits: {}, // joint -> { s, q, t }
  plane: null, // { c, q, t }
  seq: 0, received: 0, sentAt: new Map(), dirty: false,
  playing: false, clock: 0, lastTick: 0,
  frames: [], poseMs: 0, roundTrip: 0, fieldRange: [0, 0], errors: [],
  // What arrived since the last frame: uploaded once, just before drawing (a GPU upload can
  // wait for the frame in flight; poses can arrive faster than frames are drawn).
  upload: { positions: false, field: false, groups: false },
};
// For scripted sessions (the browser test): the editor's state, camera, gizmo and renderer.
window.editor = ed;
Object.assign(ed, { camera, gizmo, renderer });

// --- the socket -----------------------------------------------------------------------------
const socket = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + "/ws" + location.search);
socket.binaryType = "arraybuffer";
ed.socket = socket;
function send(request) { if (socket.readyState === 1) socket.send(JSON.stringify(request)); }
socket.onclose = () => say("connection closed: reload the page to start a new session");
// Positions in f32 (kind 5), as they are drawn: half the bytes of the library's f64.
socket.onopen = () => send({ op: "precision", positions: "f32" });
socket.onmessage = (e) => {
  const t = performance.now();
  if (typeof e.data === "string") onText(JSON.parse(e.data)); else onBinary(e.data);
  ed.messageMs = performance.now() - t;
};

function say(text, isError = true) {
  $("message").textContent = text;
  if (isError) ed.errors.push(text);
}

function onBinary(buf) {
  const kind = new Uint32Array(buf, 0, 1)[0];
  if (kind === 1) {
    const [n, m] = new Uint32Array(buf, 4, 2);
    ed.n = n;
    ed.rest = new Float32Array(new Float64Array(buf, 16, 3 * n));
    renderer.setMesh(n, new Uint32Array(buf.slice(16 + 24 * n, 16 + 24 * n + 12 * m)));
    ed.positions = ed.rest.slice();
    ed.groupsOf = new Uint8Array(n);
    ed.upload = { positions: true, field: false, groups: false };
    const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < 3 * n; i++) { min[i % 3] = Math.min(min[i % 3], ed.rest[i]); max[i % 3] = Math.max(max[i % 3], ed.rest[i]); }
    ed.bbox = { min, max };
    camera.frame(min, max);
    ed.plane = null; $("plane").checked = false;
  } else if (kind === 2 || kind === 5) {
    const seq = new Uint32Array(buf, 4, 1)[0];
    ed.poseMs = new Float32Array(buf, 8, 1)[0];
    ed.positions = kind === 2 ? new Float32Array(new Float64Array(buf, 16)) : new Float32Array(buf.slice(16));
    ed.upload.positions = true;
    // A pose answers its request and every older one (the server drops a pose that a newer
    // one replaced before it started).
    ed.received = Math.max(ed.received, seq);
    if (ed.sentAt.has(seq)) ed.roundTrip = performance.now() - ed.sentAt.get(seq);
    for (const s of ed.sentAt.keys()) if (s <= seq) ed.sentAt.delete(s);
    ed.frames.push(performance.now());
  } else if (kind === 3) {
    const [min, max] = new Float32Array(buf, 4, 2);
    ed.fieldRange = [min, max];
    ed.field = new Float32Array(buf.slice(12));
    ed.upload.field = true;
  } else if (kind === 4) {
    const n = new Uint32Array(buf, 4, 1)[0];
    ed.groupsOf = new Uint8Array(buf.slice(8, 8 + n));
    ed.upload.groups = true;
  }
}

// A slow request in the server (a bind, a cut), over the top of the view: its name and the
// seconds it has taken so far, counted until the server's `idle` says it is done; where it
// knows how long the same request took last time (`expect_ms`), a bar shows the fraction of
// that estimate (held below full until it is done), else an indeterminate bar.
function busy(what, expectMs) {
  clearInterval(ed.busyTimer);
  ed.busySince = performance.now();
  const bar = $("busy-bar");
  $("busy-box").hidden = false;
  if (!expectMs) bar.removeAttribute("value");
  const show = () => {
    const s = (performance.now() - ed.busySince) / 1000;
    if (expectMs) {
      bar.value = Math.min(s * 1000 / expectMs, 0.99);
      $("busy").textContent = `${what} ... ${s.toFixed(1)} s of about ${(expectMs / 1000).toFixed(1)} s`;
    } else {
      $("busy").textContent = `${what} ... ${s.toFixed(1)} s`;
    }
  };
  show();
  ed.busyTimer = setInterval(show, 100);
}
function idle() { clearInterval(ed.busyTimer); $("busy").textContent = ""; $("busy-box").hidden = true; }

function onText(m) {
  if (m.type === "state") return onState(m);
  if (m.type === "error") { ed.received = ed.seq; return say(m.message); }
  if (m.type === "note") return say(m.message, false);
  if (m.type === "binding") { ed.busyExpect = m.expect_ms ?? null; busy(m.what, m.expect_ms); return; }
  if (m.type === "idle") { idle(); return; }
  if (m.type === "posed") {
    if (m.joints) ed.joints = m.joints;
    ed.energy = m.energy;
    return;
  }
  if (m.type === "file") return download(m);
  if (m.type === "motors") {
    m.motors.forEach((x, g) => { if (ed.groups[g]) Object.assign(ed.groups[g], { s: x[0], q: x.slice(1, 5), t: x.slice(5, 8) }); });
    ed.dirty = true;
  }
}

function fill(select, items, value) {
  select.replaceChildren(...items.map((x) => { const o = document.createElement("option"); o.value = o.textContent = x; return o; }));
  if (value !== undefined) select.value = value;
}

function onState(s) {
  const first = !ed.state || ed.state.scene !== s.scene;
  if (first) { ed.history = []; ed.future = []; }
  ed.state = s;
  idle();
  ed.bindShown = performance.now() - (ed.busySince || performance.now());
  fill($("scene"), s.scenes, s.scene);
  const rig = s.kind === "rig";
  $("mesh-tools").classList.toggle("hidden", rig);
  $("rig-tools").classList.toggle("hidden", !rig);
  document.querySelectorAll(".rig-only").forEach((e) => e.classList.toggle("hidden", !rig));
  document.querySelectorAll(".mesh-only").forEach((e) => e.classList.toggle("hidden", rig));
  // The files the method's command reads (lattices and cages: no --select), for its replay.
  document.querySelectorAll("[data-input]").forEach((e) => e.classList.toggle("hidden", rig || !s.inputs.includes(e.dataset.input)));
  const field = $("field").value;
  fill($("field"), s.fields, s.fields.includes(field) && !first ? field : "displacement");
  if (!rig) {
    fill($("method"), s.methods, s.method); fill($("blend"), s.blends, s.blend);
    optionPanel(s);
    // The keys: a lattice's or cage's control points, else the painted groups. Keep each
    // key's gizmo; new keys start at the identity about their rest centre.
    const keys = s.controls ? s.controls.points : s.groups.map((g) => g.center);
    const sameKind = !first && !!ed.controls === !!s.controls && ed.groups.length === keys.length;
    ed.controls = s.controls;
    ed.groups = keys.map((c, i) => {
      const old = sameKind || (!first && !s.controls && !ed.controls) ? ed.groups[i] : null;
      return old ? Object.assign(old, { c }) : { c, s: 1, q: Q.id(), t: [0, 0, 0] };
    });
    const keep = Math.min(+$("group").value || 0, s.controls ? keys.length - 1 : keys.length);
    fill($("group"), [...keys.map((g, i) => `${i}`), ...(s.controls ? [] : [`${keys.length}`])], `${keep}`);
    [...$("group").options].forEach((o, i) => {
      o.textContent = s.controls ? `control point ${i}` : i < s.groups.length ? `group ${i} (${s.groups[i].vertices} vertices)` : "new group";
    });
    document.querySelectorAll(".paint-only").forEach((e) => e.classList.toggle("hidden", !!s.controls));
    $("undo-select").disabled = s.selection_undo === 0; $("redo-select").disabled = s.selection_redo === 0;
    if (s.controls) $("tool").querySelector("[value=move]").checked = true;
    $("replay").textContent = "Replay (after saving the files it names): " + s.replay;
  } else {
    if (first) { ed.edits = {}; ed.clock = s.rig.animations.length ? s.rig.animations[0].start : 0; }
    fill($("animation"), ["(rest)", ...s.rig.animations.map((a, i) => `${i}: ${a.name}`)], first ? (s.rig.animations.length ? "0: " + s.rig.animations[0].name : "(rest)") : $("animation").value);
    if (first) fill($("backend"), s.rig.backends, s.rig.backends[0]);
    const joint = $("joint").value;
    fill($("joint"), ["(none)", ...s.rig.joints.map((j, i) => `${i}: ${j}`)], first ? "(none)" : joint);
    $("undo").disabled = s.rig.undo === 0; $("redo").disabled = s.rig.redo === 0;
    $("replay").textContent = s.replay;
  }
  ed.dirty = true;
  sendField();
  retarget();
}

function download(m) {
  const bytes = m.base64 ? Uint8Array.from(atob(m.text), (c) => c.charCodeAt(0)) : new TextEncoder().encode(m.text);
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([bytes])); a.download = m.name;
  ed.lastFile = m;
  document.body.append(a); a.click(); a.remove();
}

// --- motors and rig frames --------------------------------------------------------------------
function motorSpec(g) {
  const r = Q.toAxisDegrees(g.q), spec = { translate: g.t, scale: g.s };
  if (r) spec.rotate = { axis: r.axis, degrees: r.degrees, center: g.c }; else spec.center = g.c;
  return spec;
}
function jointSpec(e) {
  const r = Q.toAxisDegrees(e.q), spec = { translate: e.t, scale: e.s };
  if (r) spec.rotate = { axis: r.axis, degrees: r.degrees };
  return spec;
}
function animationIndex() { const v = $("animation").value; return v === "(rest)" ? null : parseInt(v, 10); }
function pump() {
  if (!ed.state || socket.readyState !== 1 || ed.seq - ed.received >= 2) return;
  if (ed.state.kind === "rig") {
    if (!ed.dirty && !ed.playing) return;
    const edits = Object.entries(ed.edits).map(([j, e]) => ({ joint: +j, motor: jointSpec(e) }));
    ed.seq++; ed.sentAt.set(ed.seq, performance.now());
    send({ op: "rig", seq: ed.seq, animation: animationIndex(), time: ed.clock, backend: $("backend").value, edits });
  } else {
    if (!ed.dirty || ed.groups.length === 0) return;
    ed.seq++; ed.sentAt.set(ed.seq, performance.now());
    send({ op: "motors", seq: ed.seq, motors: ed.groups.map(motorSpec) });
  }
  ed.dirty = false;
}

// --- gizmo targets ------------------------------------------------------------------------------
const WORLD = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
function groupTarget(g) {
  return {
    scalable: true,
    origin: () => V.add(g.c, g.t), axes: () => WORLD,
    snapshot: () => ({ s: g.s, q: g.q.slice(), t: g.t.slice() }),
    apply: (st, op) => {
      if (op.kind === "translate") g.t = V.add(st.t, V.scale(op.axis, op.amount));
      if (op.kind === "rotate") g.q = Q.normalize(Q.mul(Q.axisAngle(op.axis, op.angle), st.q));
      if (op.kind === "scale") g.s = st.s * op.factor;
      ed.dirty = true;
    },
  };
}
function jointTarget(j) {
  const e = ed.edits[j] || (ed.edits[j] = { s: 1, q: Q.id(), t: [0, 0, 0] });
  const frame = () => ed.joints[j] || [0, 0, 0, 0, 0, 0, 1];
  return {
    scalable: true,
    origin: () => frame().slice(0, 3),
    axes: () => WORLD.map((a) => Q.rotate(frame().slice(3, 7), a)),
    snapshot: () => ({ s: e.s, q: e.q.slice(), t: e.t.slice() }),
    apply: (st, op) => {
      const local = (i) => Q.rotate(st.q, WORLD[i]);
      if (op.kind === "translate") {
        const i = gizmo.drag.handle.axis;
        e.t = V.add(st.t, V.scale(local(i), op.amount));
      }
      if (op.kind === "rotate") e.q = Q.normalize(Q.mul(st.q, Q.axisAngle(WORLD[op.axisIndex], op.angle)));
      if (op.kind === "scale") e.s = st.s * op.factor;
      ed.dirty = true;
    },
  };
}
function planeTarget() {
  if (!ed.plane) ed.plane = { c: V.scale(V.add(ed.bbox.min, ed.bbox.max), 0.5), q: Q.id(), t: [0, 0, 0] };
  const p = ed.plane;
  return {
    scalable: false,
    origin: () => V.add(p.c, p.t), axes: () => WORLD,
    snapshot: () => ({ q: p.q.slice(), t: p.t.slice() }),
    apply: (st, op) => {
      if (op.kind === "translate") p.t = V.add(st.t, V.scale(op.axis, op.amount));
      if (op.kind === "rotate") p.q = Q.normalize(Q.mul(Q.axisAngle(op.axis, op.angle), st.q));
    },
  };
}
function retarget() {
  const s = ed.state;
  gizmo.target = null;
  if (!s) return;
  if (s.kind === "rig") {
    if ($("plane").checked) gizmo.target = planeTarget();
    else if ($("joint").value !== "(none)") gizmo.target = jointTarget(parseInt($("joint").value, 10));
  } else {
    const g = ed.groups[+$("group").value];
    if (g) gizmo.target = groupTarget(g);
  }
}

// --- overlays -----------------------------------------------------------------------------------
// The lattice or cage, each point moved by its motor (a motor about the point moves it by t).
function controlLines() {
  if (!ed.controls || !ed.state || ed.state.kind !== "mesh") return [];
  const p = ed.groups.map((g) => V.add(g.c, g.t)), ink = [0.95, 0.45, 0.35, 1];
  const lines = [{ points: ed.controls.edges.flatMap(([a, b]) => [p[a], p[b]]), ink, strip: false }];
  for (const q of p) lines.push({ points: gizmo.square(q, 3), ink, strip: true });
  return lines;
}
// The point of `points` drawn within a few pixels of (x, y), or -1.
function nearestDrawn(points, x, y) {
  let best = -1, bd = 8;
  points.forEach((p, i) => {
    const s = camera.screen(p);
    if (s && Math.hypot(s[0] - x, s[1] - y) < bd) { bd = Math.hypot(s[0] - x, s[1] - y); best = i; }
  });
  return best;
}
const controlAt = (x, y) => (ed.controls ? nearestDrawn(ed.groups.map((g) => V.add(g.c, g.t)), x, y) : -1);
const jointAt = (x, y) => (ed.state && ed.state.kind === "rig" ? nearestDrawn(ed.joints.map((j) => j.slice(0, 3)), x, y) : -1);
// The skeleton as posed: a line from each joint to its parent joint, a square per joint.
function skeletonLines() {
  if (!ed.state || ed.state.kind !== "rig" || !ed.joints.length) return [];
  const p = ed.joints.map((j) => j.slice(0, 3)), parents = ed.state.rig.parents, ink = [0.3, 0.9, 1, 1];
  const bones = p.flatMap((q, i) => (parents[i] >= 0 && p[parents[i]] ? [p[parents[i]], q] : []));
  return [{ points: bones, ink, strip: false }, ...p.map((q) => ({ points: gizmo.square(q, 3), ink, strip: true }))];
}
// The lasso being drawn, just in front of the eye.
function lassoLines() {
  if (!mouse || mouse.mode !== "lasso") return [];
  const pts = [...mouse.polygon, mouse.polygon[0]].map(([x, y]) => { const r = camera.ray(x, y); return V.add(r.origin, V.scale(r.direction, camera.distance * 0.2)); });
  return [{ points: pts, ink: [1, 1, 0.4, 1], strip: true }];
}
function planeLines() {
  if (!$("plane").checked || !ed.plane) return [];
  const p = V.add(ed.plane.c, ed.plane.t), n = Q.rotate(ed.plane.q, [1, 0, 0]), L = V.len(V.sub(ed.bbox.max, ed.bbox.min)) * 0.35;
  const u = Q.rotate(ed.plane.q, [0, 1, 0]), w = Q.rotate(ed.plane.q, [0, 0, 1]);
  const c = (a, b) => V.add(p, V.add(V.scale(u, a * L), V.scale(w, b * L)));
  return [{ points: [c(-1, -1), c(1, -1), c(1, 1), c(-1, 1), c(-1, -1)], ink: [1, 0.6, 0.2, 1], strip: true },
    { points: [p, V.add(p, V.scale(n, L * 0.5))], ink: [1, 0.6, 0.2, 1], strip: true }];
}
function legend() {
  const bar = $("legend-bar"), c = bar.getContext("2d");
  for (let x = 0; x < bar.width; x++) {
    const t = x / (bar.width - 1);
    // The shader's viridis, at a few stops (close enough for a legend).
    const stops = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
    const f = t * 4, i = Math.min(3, Math.floor(f)), k = f - i;
    const col = stops[i].map((v, j) => Math.round(v + (stops[i + 1][j] - v) * k));
    c.fillStyle = `rgb(${col})`; c.fillRect(x, 0, 1, bar.height);
  }
  const fmt = (x) => (Math.abs(x) >= 1000 || (Math.abs(x) < 0.01 && x !== 0) ? x.toExponential(2) : x.toFixed(3));
  $("legend-min").textContent = fmt(ed.fieldRange[0]); $("legend-max").textContent = fmt(ed.fieldRange[1]);
}
function sendField() {
  send({ op: "field", name: $("field").value, group: +$("group").value || 0 });
}

// --- undo and redo of gizmo edits (motors of groups, control points and joints) --------------------
const snapshot = () => JSON.stringify({ groups: ed.groups, edits: ed.edits });
ed.history = []; ed.future = [];
function restore(from, to) {
  if (!from.length) return say("nothing to undo or redo", false);
  to.push(snapshot());
  const s = JSON.parse(from.pop());
  if (s.groups.length === ed.groups.length) s.groups.forEach((g, i) => Object.assign(ed.groups[i], g));
  ed.edits = s.edits;
  retarget(); ed.dirty = true;
}
$("undo-edit").onclick = () => restore(ed.history, ed.future);
$("redo-edit").onclick = () => restore(ed.future, ed.history);
addEventListener("keydown", (e) => {
  if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === "z") { e.preventDefault(); (e.shiftKey ? $("redo-edit") : $("undo-edit")).click(); }
});

// --- panels -------------------------------------------------------------------------------------
$("scene").onchange = () => { ed.state = null; send({ op: "scene", name: $("scene").value }); };
// The method's options, as the library describes them (state.option_specs): a select for a
// choice, a number box for a number, three for points per axis (NAME-x, NAME-y, NAME-z), a
// checkbox for a switch; each change sends them all.
const AXES = ["x", "y", "z"];
function optionPanel(s) {
  const box = $("method-options");
  const shape = JSON.stringify(s.option_specs);
  if (box.dataset.shape !== shape) {
    box.dataset.shape = shape;
    box.replaceChildren(...s.option_specs.map((o) => {
      const label = document.createElement(o.kind === "dims" ? "div" : "label");
      label.className = o.kind === "dims" ? "row" : "";
      label.title = o.help;
      label.append(`${o.name[0].toUpperCase()}${o.name.slice(1).replaceAll("-", " ")} `);
      const input = (id) => {
        const e = document.createElement(o.kind === "choice" ? "select" : "input");
        e.id = id;
        if (o.kind === "choice") fill(e, o.values, o.values[0]);
        else if (o.kind === "switch") e.type = "checkbox";
        else Object.assign(e, { type: "number", min: o.min, max: o.max, className: o.kind === "dims" ? "dim" : "" });
        e.onchange = sendMethod;
        return e;
      };
      if (o.kind === "dims") AXES.forEach((a, i) => label.append(...(i ? [" x ", input(`${o.name}-${a}`)] : [input(`${o.name}-${a}`)])));
      else label.append(input(o.name));
      return label;
    }));
  }
  for (const o of s.option_specs) {
    const v = s.options[o.name];
    if (o.kind === "dims") AXES.forEach((a, i) => { $(`${o.name}-${a}`).value = v[i]; });
    else if (o.kind === "switch") $(o.name).checked = v;
    else $(o.name).value = v;
  }
}
const optionValues = () => Object.fromEntries(ed.state.option_specs.map((o) => [o.name,
  o.kind === "dims" ? AXES.map((a) => +$(`${o.name}-${a}`).value)
    : o.kind === "number" ? +$(o.name).value : o.kind === "switch" ? $(o.name).checked : $(o.name).value]));
// A new method starts from its options as the server keeps them.
const sendMethod = (e) => send({ op: "method", method: $("method").value, blend: $("blend").value,
  options: e && e.target.id === "method" ? {} : optionValues() });
for (const id of ["method", "blend"]) $(id).onchange = sendMethod;
$("group").onchange = () => { retarget(); sendField(); };
$("field").onchange = () => { sendField(); ed.dirty = true; };
$("clear").onclick = () => send({ op: "clear-groups" });
$("reset").onclick = () => { const g = ed.groups[+$("group").value]; if (g) Object.assign(g, { s: 1, q: Q.id(), t: [0, 0, 0] }); ed.dirty = true; };
$("reset-joint").onclick = () => { delete ed.edits[$("joint").value.split(":")[0]]; retarget(); ed.dirty = true; };
$("joint").onchange = retarget; $("plane").onchange = retarget;
$("backend").onchange = () => { ed.dirty = true; };
$("animation").onchange = () => { const a = ed.state.rig.animations[animationIndex()]; ed.clock = a ? a.start : 0; ed.dirty = true; };
$("play").onclick = () => { ed.playing = !ed.playing; $("play").textContent = ed.playing ? "Pause" : "Play"; ed.lastTick = performance.now(); };
$("time").oninput = () => {
  const a = ed.state.rig.animations[animationIndex()];
  if (a) { ed.clock = a.start + (a.end - a.start) * +$("time").value; ed.dirty = true; }
};
$("cut").onclick = () => {
  if (!$("plane").checked || !ed.plane) return say("turn on the cut plane and place it first");
  send({ op: "cut", point: V.add(ed.plane.c, ed.plane.t), normal: Q.rotate(ed.plane.q, [1, 0, 0]), cap: true });
};
$("undo-select").onclick = () => send({ op: "undo" });
$("redo-select").onclick = () => send({ op: "redo" });
$("undo").onclick = () => send({ op: "undo" });
$("redo").onclick = () => send({ op: "redo" });
$("frame").onclick = () => ed.bbox && camera.frame(ed.bbox.min, ed.bbox.max);
document.querySelectorAll("[data-export]").forEach((b) => { b.onclick = () => send({ op: "export", what: b.dataset.export }); });
// A model from the user's disk: read here, parsed and checked by the server as the CLI does.
$("upload").onchange = async (e) => {
  const f = e.target.files[0]; if (!f) return;
  if (f.size > 16 << 20) { e.target.value = ""; return say(`${f.name}: larger than 16 MiB`); }
  const bytes = new Uint8Array(await f.arrayBuffer());
  let binary = "";
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  send({ op: "upload", name: f.name, base64: btoa(binary) }); e.target.value = "";
};
for (const what of ["selection", "motors"]) {
  $("load-" + what).onchange = async (e) => {
    const f = e.target.files[0]; if (!f) return;
    if (f.size > 3 << 20) return say(`${f.name}: larger than 3 MiB`);
    send({ op: "load", what, text: await f.text() }); e.target.value = "";
  };
}
addEventListener("keydown", (e) => { if (e.key === "f" && e.target === document.body) $("frame").click(); });

// --- mouse --------------------------------------------------------------------------------------
let mouse = null;
const tool = () => document.querySelector("input[name=tool]:checked").value;
function paintAt(x, y, begin) {
  const r = camera.ray(x, y), size = V.len(V.sub(ed.bbox.max, ed.bbox.min));
  send({ op: "paint", origin: r.origin, direction: r.direction, radius: +$("brush").value * size, group: +$("group").value, erase: tool() === "erase", begin });
}
canvas.addEventListener("contextmenu", (e) => e.preventDefault());
canvas.addEventListener("pointerdown", (e) => {
  canvas.setPointerCapture(e.pointerId);
  const x = e.offsetX, y = e.offsetY;
  const before = snapshot();
  if (e.button === 0 && !e.shiftKey && gizmo.target && gizmo.begin(x, y)) {
    ed.history.push(before); ed.future = []; if (ed.history.length > 200) ed.history.shift();
    mouse = { mode: "gizmo", x, y }; return;
  }
  const point = e.button === 0 && !e.shiftKey ? controlAt(x, y) : -1;
  if (point >= 0) { $("group").value = `${point}`; retarget(); sendField(); mouse = { mode: "none", x, y }; return; }
  const rigTool = ed.state && ed.state.kind === "rig" && e.button === 0 && !e.shiftKey ? document.querySelector("input[name=rig-tool]:checked").value : null;
  const joint = rigTool === "joint" ? jointAt(x, y) : -1;
  if (joint >= 0) { $("joint").selectedIndex = joint + 1; $("plane").checked = false; retarget(); mouse = { mode: "none", x, y }; return; }
  if (rigTool === "drill") {
    const r = camera.ray(x, y);
    send({ op: "drill", origin: r.origin, direction: r.direction, radius: +$("drill-radius").value, depth: 0.15 });
    mouse = { mode: "none", x, y }; return;
  }
  if (rigTool === "scalpel") { const r = camera.ray(x, y); mouse = { mode: "scalpel", x, y, rays: [[r.origin, r.direction]] }; return; }
  const painting = e.button === 0 && !e.shiftKey && ed.state && ed.state.kind === "mesh" && tool() !== "move";
  const lasso = painting && tool() === "lasso";
  mouse = { mode: lasso ? "lasso" : painting ? "paint" : e.button === 2 || e.shiftKey ? "pan" : "orbit", x, y, polygon: [[x, y]] };
  if (painting && !lasso) paintAt(x, y, true);
});
canvas.addEventListener("pointermove", (e) => {
  const x = e.offsetX, y = e.offsetY;
  if (!mouse) { gizmo.move(x, y); return; }
  if (mouse.mode === "gizmo") gizmo.move(x, y);
  else if (mouse.mode === "paint") paintAt(x, y, false);
  else if (mouse.mode === "lasso") { if (Math.hypot(x - mouse.x, y - mouse.y) < 4) return; mouse.polygon.push([x, y]); }
  else if (mouse.mode === "none") return;
  else if (mouse.mode === "scalpel") {
    if (Math.hypot(x - mouse.x, y - mouse.y) < 6) return;
    const r = camera.ray(x, y); mouse.rays.push([r.origin, r.direction]);
  }
  else if (mouse.mode === "pan") camera.pan(x - mouse.x, y - mouse.y);
  else camera.orbit(x - mouse.x, y - mouse.y);
  mouse.x = x; mouse.y = y;
});
canvas.addEventListener("pointerup", () => {
  if (mouse && mouse.mode === "paint") send({ op: "bind" });
  if (mouse && mouse.mode === "lasso" && mouse.polygon.length >= 3) {
    const polygon = mouse.polygon.map(([px, py]) => [2 * px / camera.w - 1, 1 - 2 * py / camera.h]);
    send({ op: "lasso", eye: camera.eye(), view_proj: camera.viewProj, polygon, group: +$("group").value, erase: false });
    send({ op: "bind" });
  }
  if (mouse && mouse.mode === "scalpel" && mouse.rays.length >= 2) send({ op: "tear", rays: mouse.rays, open: +$("open").value });
  gizmo.end(); mouse = null;
});
canvas.addEventListener("wheel", (e) => { e.preventDefault(); camera.zoom(Math.sign(e.deltaY)); }, { passive: false });

// --- the frame loop -------------------------------------------------------------------------------
// Upload what arrived, then draw the mesh and the overlays.
function draw() {
  const { viewProj } = camera.matrices(canvas.clientWidth, canvas.clientHeight);
  const { f } = camera.basis();
  const lines = [...controlLines(), ...skeletonLines(), ...gizmo.lines(), ...planeLines(), ...lassoLines()];
  const t0 = performance.now();
  if (ed.upload.positions) renderer.setPositions(ed.positions);
  if (ed.upload.field) { renderer.setScalar(ed.field, ...ed.fieldRange); legend(); }
  if (ed.upload.groups) renderer.setGroups(ed.groupsOf);
  ed.upload = { positions: false, field: false, groups: false };
  renderer.draw({ viewProj, light: V.scale(f, -1), colourBy: $("field").value !== "group", wireframe: $("wireframe").checked, lines });
  ed.drawMs = performance.now() - t0;
}
ed.redraw = draw;
function tick(now) {
  const dpr = window.devicePixelRatio || 1, w = canvas.clientWidth, h = canvas.clientHeight;
  if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) { canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr); }
  if (ed.playing && ed.state && ed.state.kind === "rig") {
    const a = ed.state.rig.animations[animationIndex()];
    if (a) {
      const span = Math.max(a.end - a.start, 1e-6);
      ed.clock = a.start + ((ed.clock - a.start + (now - ed.lastTick) / 1000) % span);
      $("time").value = (ed.clock - a.start) / span;
    }
  }
  ed.lastTick = now;
  pump();
  // Draw only when something shows a change: a software GL (no GPU) takes long per frame, and
  // a browser busy drawing delivers the socket's messages late.
  const key = JSON.stringify([w, h, camera.target, camera.distance, camera.yaw, camera.pitch, gizmo.hover && [gizmo.hover.kind, gizmo.hover.axis],
    gizmo.target && gizmo.target.origin(), ed.groups, ed.edits, ed.plane, mouse && mouse.polygon && mouse.polygon.length, $("plane").checked, $("wireframe").checked, $("field").value, ed.joints]);
  if (key !== ed.viewKey || ed.upload.positions || ed.upload.field || ed.upload.groups) {
    ed.viewKey = key;
    draw();
    ed.frameMs = now - (ed.lastFrame || now); ed.lastFrame = now; ed.drawn = (ed.drawn || 0) + 1;
  }
  ed.frames = ed.frames.filter((t) => now - t < 1000);
  const s = ed.state;
  if (s) {
    $("stats").textContent = [
      `${s.vertices} vertices, ${s.triangles} triangles`,
      `frame ${ed.frameMs.toFixed(1)} ms (draw ${ed.drawMs.toFixed(1)} ms), last message ${(ed.messageMs || 0).toFixed(1)} ms`,
      `positions ${ed.frames.length} / s, round trip ${ed.roundTrip.toFixed(1)} ms`,
      `pose ${ed.poseMs.toFixed(2)} ms, bind ${s.bind_ms.toFixed(1)} ms`,
      ed.energy != null ? `ARAP energy ${ed.energy.toExponential(3)}` : "",
      s.stale ? "groups changed: binding on release" : "",
    ].filter(Boolean).join("\n");
  }
  requestAnimationFrame(tick);
}
requestAnimationFrame(tick);
