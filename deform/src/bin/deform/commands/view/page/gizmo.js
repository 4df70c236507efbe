// The gizmo: three axes to translate along, three rings to turn about, a centre square to
// scale; drawn as overlay lines, picked and dragged in screen space. What it moves is a target:
// { origin() -> point, axes() -> 3 unit vectors, scalable, snapshot() -> state,
//   apply(start, op) } with op { kind: "translate", axis, amount } | { kind: "rotate", axis,
// angle } | { kind: "scale", factor }.
"use strict";
const AXIS_INK = [[0.95, 0.3, 0.3, 1], [0.35, 0.9, 0.35, 1], [0.35, 0.55, 1, 1]];
const PICK_PX = 9;

function segmentDistance(p, a, b) {
  const abx = b[0] - a[0], aby = b[1] - a[1], l2 = abx * abx + aby * aby;
  const t = l2 > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * abx + (p[1] - a[1]) * aby) / l2)) : 0;
  return Math.hypot(p[0] - a[0] - t * abx, p[1] - a[1] - t * aby);
}

class Gizmo {
  constructor(camera) { this.camera = camera; this.target = null; this.drag = null; this.hover = null; }
  size() { return this.camera.distance * 0.16; }
  ring(p, a, r) {
    const u = V.norm(Math.abs(a[0]) < 0.9 ? V.cross(a, [1, 0, 0]) : V.cross(a, [0, 1, 0])), w = V.cross(a, u), pts = [];
    for (let k = 0; k <= 64; k++) {
      const t = k / 64 * 2 * Math.PI;
      pts.push(V.add(p, V.add(V.scale(u, r * Math.cos(t)), V.scale(w, r * Math.sin(t)))));
    }
    return pts;
  }
  square(p, px) {
    const { r, u } = this.camera.basis(), k = px * this.camera.distance * 2 * Math.tan(this.camera.fovy / 2) / this.camera.h;
    const c = (sx, sy) => V.add(p, V.add(V.scale(r, sx * k), V.scale(u, sy * k)));
    return [c(-1, -1), c(1, -1), c(1, 1), c(-1, 1), c(-1, -1)];
  }
  // The handles: {kind, axis, points (world polyline)}.
  handles() {
    if (!this.target) return [];
    const p = this.target.origin(), axes = this.target.axes(), L = this.size(), out = [];
    axes.forEach((a, i) => out.push({ kind: "translate", axis: i, points: [p, V.add(p, V.scale(a, L))] }));
    axes.forEach((a, i) => out.push({ kind: "rotate", axis: i, points: this.ring(p, a, 0.7 * L) }));
    if (this.target.scalable) out.push({ kind: "scale", axis: -1, points: this.square(p, 7) });
    return out;
  }
  lines() {
    return this.handles().map((h) => {
      const hot = this.hover && this.hover.kind === h.kind && this.hover.axis === h.axis;
      const ink = h.axis >= 0 ? AXIS_INK[h.axis].slice() : [1, 0.85, 0.2, 1];
      if (hot) ink.splice(0, 3, 1, 1, 1);
      return { points: h.points, ink, strip: true };
    });
  }
  // The handle under the pixel, or null.
  pick(x, y) {
    let best = null, bestD = PICK_PX;
    for (const h of this.handles()) {
      const s = h.points.map((q) => this.camera.screen(q));
      for (let k = 0; k + 1 < s.length; k++) {
        if (!s[k] || !s[k + 1]) continue;
        const d = segmentDistance([x, y], s[k], s[k + 1]) - (h.kind === "scale" ? 4 : 0);
        if (d < bestD) { bestD = d; best = h; }
      }
    }
    return best;
  }
  // Screen position of a handle's grip (a point `at` along an arrow, a ring point, the centre),
  // for scripted sessions.
  grip(kind, axis, at = 0.8) {
    const h = this.handles().find((q) => q.kind === kind && q.axis === axis);
    if (!h) return null;
    const pt = kind === "translate" ? V.add(h.points[0], V.scale(V.sub(h.points[1], h.points[0]), at))
      : kind === "rotate" ? h.points[0] : this.target.origin();
    return this.camera.screen(pt);
  }
  begin(x, y) {
    const h = this.pick(x, y);
    if (!h) return false;
    const p = this.target.origin();
    this.drag = { handle: h, x, y, start: this.target.snapshot(), p, axes: this.target.axes(), center: this.camera.screen(p) };
    return true;
  }
  move(x, y) {
    const d = this.drag;
    if (!d) { this.hover = this.target ? this.pick(x, y) : null; return false; }
    const h = d.handle, L = this.size();
    let op;
    if (h.kind === "translate") {
      const a = d.axes[h.axis], s1 = this.camera.screen(V.add(d.p, V.scale(a, L)));
      if (!s1 || !d.center) return false;
      const dir = [s1[0] - d.center[0], s1[1] - d.center[1]], l2 = dir[0] * dir[0] + dir[1] * dir[1];
      if (l2 < 1) return false;
      op = { kind: "translate", axis: a, amount: ((x - d.x) * dir[0] + (y - d.y) * dir[1]) / l2 * L };
    } else if (h.kind === "rotate") {
      const a = d.axes[h.axis], c = d.center;
      const ang = (px, py) => Math.atan2(-(py - c[1]), px - c[0]);
      let angle = ang(x, y) - ang(d.x, d.y);
      if (V.dot(a, V.sub(this.camera.eye(), d.p)) < 0) angle = -angle;
      op = { kind: "rotate", axis: a, axisIndex: h.axis, angle };
    } else {
      op = { kind: "scale", factor: Math.exp((d.y - y) / 120) };
    }
    this.target.apply(d.start, op);
    return true;
  }
  end() { const was = !!this.drag; this.drag = null; return was; }
}
