// The orbit camera: target, distance, yaw, pitch; rays through pixels for picking.
"use strict";
class Camera {
  constructor() { this.target = [0, 0, 0]; this.distance = 5; this.yaw = 0.6; this.pitch = 0.35; this.fovy = 45 * Math.PI / 180; }
  frame(min, max) {
    this.target = V.scale(V.add(min, max), 0.5);
    const r = Math.max(V.len(V.sub(max, min)) / 2, 1e-6);
    this.distance = r / Math.sin(this.fovy / 2) * 1.05;
  }
  eye() {
    const cp = Math.cos(this.pitch);
    return V.add(this.target, V.scale([cp * Math.sin(this.yaw), Math.sin(this.pitch), cp * Math.cos(this.yaw)], this.distance));
  }
  basis() {
    const f = V.norm(V.sub(this.target, this.eye())), r = V.norm(V.cross(f, [0, 1, 0]));
    return { f, r, u: V.cross(r, f) };
  }
  matrices(w, h) {
    const proj = M4.perspective(this.fovy, w / h, this.distance * 0.01, this.distance * 100);
    const view = M4.lookAt(this.eye(), this.target, [0, 1, 0]);
    this.viewProj = M4.mul(proj, view); this.w = w; this.h = h;
    return { proj, view, viewProj: this.viewProj };
  }
  // Pixel (CSS px) of a world point, or null behind the eye.
  screen(p) {
    const c = M4.apply(this.viewProj, p);
    if (c[3] <= 0) return null;
    return [(c[0] * 0.5 + 0.5) * this.w, (0.5 - c[1] * 0.5) * this.h];
  }
  ray(x, y) {
    const { f, r, u } = this.basis(), t = Math.tan(this.fovy / 2), a = this.w / this.h;
    const sx = (2 * x / this.w - 1) * t * a, sy = (1 - 2 * y / this.h) * t;
    return { origin: this.eye(), direction: V.norm(V.add(f, V.add(V.scale(r, sx), V.scale(u, sy)))) };
  }
  orbit(dx, dy) { this.yaw -= dx * 0.008; this.pitch = Math.max(-1.55, Math.min(1.55, this.pitch + dy * 0.008)); }
  pan(dx, dy) {
    const { r, u } = this.basis(), k = this.distance * 2 * Math.tan(this.fovy / 2) / this.h;
    this.target = V.add(this.target, V.add(V.scale(r, -dx * k), V.scale(u, dy * k)));
  }
  zoom(steps) { this.distance *= Math.exp(steps * 0.1); }
}
