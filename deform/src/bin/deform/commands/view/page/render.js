// The WebGL2 renderer: one shaded mesh (normals from the positions, colour by a scalar field
// or by handle group), its wireframe, and overlay lines drawn on top.
"use strict";
const MESH_VS = `#version 300 es
in vec3 position; in vec3 normal; in float scalar; in float group;
uniform mat4 viewProj; uniform vec2 range;
out vec3 vNormal; out float vT; flat out int vGroup;
void main() {
  vNormal = normal; vGroup = int(group + 0.5);
  vT = range.y > range.x ? clamp((scalar - range.x) / (range.y - range.x), 0.0, 1.0) : 0.0;
  gl_Position = viewProj * vec4(position, 1.0);
}`;
const MESH_FS = `#version 300 es
precision highp float;
in vec3 vNormal; in float vT; flat in int vGroup;
uniform vec3 light; uniform int colourBy; uniform vec2 range;
out vec4 colour;
vec3 ramp(float t) { // viridis, as the PNG previews
  vec3 c0 = vec3(0.2777, 0.0054, 0.3341), c1 = vec3(0.1051, 1.4046, 1.3846), c2 = vec3(-0.3309, 0.2148, 0.0951),
       c3 = vec3(-4.6342, -5.7991, -19.3324), c4 = vec3(6.2283, 14.1799, 56.6906), c5 = vec3(4.7764, -13.7451, -65.3530),
       c6 = vec3(-5.4355, 4.6459, 26.3124);
  return c0 + t * (c1 + t * (c2 + t * (c3 + t * (c4 + t * (c5 + t * c6)))));
}
const vec3 palette[8] = vec3[8](vec3(0.95,0.35,0.2), vec3(0.2,0.6,0.95), vec3(0.3,0.85,0.35), vec3(0.95,0.8,0.2),
  vec3(0.75,0.35,0.9), vec3(0.2,0.85,0.85), vec3(0.95,0.5,0.7), vec3(0.6,0.6,0.6));
void main() {
  vec3 n = normalize(vNormal); if (!gl_FrontFacing) n = -n;
  vec3 base = colourBy == 1 && range.y > range.x ? ramp(vT) : vec3(0.78, 0.76, 0.72);
  if (vGroup > 0) base = mix(base, palette[(vGroup - 1) % 8], 0.75);
  float d = max(dot(n, light), 0.0);
  colour = vec4(base * (0.3 + 0.7 * d), 1.0);
}`;
const LINE_VS = `#version 300 es
in vec3 position; uniform mat4 viewProj; uniform float bias;
void main() { gl_Position = viewProj * vec4(position, 1.0); gl_Position.z -= bias * gl_Position.w; }`;
const LINE_FS = `#version 300 es
precision highp float; uniform vec4 ink; out vec4 colour; void main() { colour = ink; }`;

function compile(gl, vs, fs) {
  const p = gl.createProgram();
  for (const [type, src] of [[gl.VERTEX_SHADER, vs], [gl.FRAGMENT_SHADER, fs]]) {
    const s = gl.createShader(type); gl.shaderSource(s, src); gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    gl.attachShader(p, s);
  }
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
  return p;
}

class Renderer {
  constructor(canvas) {
    // Multisampling costs a software GL (no GPU: SwiftShader, llvmpipe) half its frame rate.
    const probe = document.createElement("canvas").getContext("webgl2");
    const info = probe && probe.getExtension("WEBGL_debug_renderer_info");
    const name = info ? String(probe.getParameter(info.UNMASKED_RENDERER_WEBGL)) : "";
    this.software = /swiftshader|llvmpipe|software/i.test(name);
    const gl = canvas.getContext("webgl2", { antialias: !this.software });
    if (!gl) throw new Error("this browser has no WebGL2");
    this.gl = gl; this.canvas = canvas;
    this.mesh = compile(gl, MESH_VS, MESH_FS); this.line = compile(gl, LINE_VS, LINE_FS);
    this.vao = gl.createVertexArray();
    this.buf = {};
    for (const name of ["position", "normal", "scalar", "group", "index", "edges", "lines"]) this.buf[name] = gl.createBuffer();
    this.lineVao = gl.createVertexArray();
    this.count = 0; this.edgeCount = 0; this.n = 0;
  }
  attribute(program, vao, name, buffer, size, type) {
    const gl = this.gl, loc = gl.getAttribLocation(program, name);
    if (loc < 0) return;
    gl.bindVertexArray(vao); gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    gl.enableVertexAttribArray(loc); gl.vertexAttribPointer(loc, size, type, false, 0, 0);
  }
  // A new mesh: triangles (Uint32Array) and vertex count.
  setMesh(n, triangles) {
    const gl = this.gl; this.n = n; this.count = triangles.length; this.triangles = triangles;
    gl.bindVertexArray(this.vao);
    this.attribute(this.mesh, this.vao, "position", this.buf.position, 3, gl.FLOAT);
    this.attribute(this.mesh, this.vao, "normal", this.buf.normal, 3, gl.FLOAT);
    this.attribute(this.mesh, this.vao, "scalar", this.buf.scalar, 1, gl.FLOAT);
    this.attribute(this.mesh, this.vao, "group", this.buf.group, 1, gl.UNSIGNED_BYTE);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.buf.index);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, triangles, gl.STATIC_DRAW);
    this.setScalar(new Float32Array(n), 0, 0);
    this.setGroups(new Uint8Array(n));
    // Unique edges for the wireframe.
    const seen = new Set(), edges = [];
    for (let i = 0; i < triangles.length; i += 3) for (let k = 0; k < 3; k++) {
      let a = triangles[i + k], b = triangles[i + (k + 1) % 3];
      if (a > b) [a, b] = [b, a];
      const key = a * n + b;
      if (!seen.has(key)) { seen.add(key); edges.push(a, b); }
    }
    this.edgeCount = edges.length;
    gl.bindVertexArray(this.lineVao);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.buf.edges);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint32Array(edges), gl.STATIC_DRAW);
    this.attribute(this.line, this.lineVao, "position", this.buf.position, 3, gl.FLOAT);
    this.overlayVao = gl.createVertexArray();
    this.attribute(this.line, this.overlayVao, "position", this.buf.lines, 3, gl.FLOAT);
  }
  // Positions (Float32Array, 3 per vertex) and area-weighted normals.
  setPositions(p) {
    const gl = this.gl, t = this.triangles, nrm = new Float32Array(p.length);
    for (let i = 0; i < t.length; i += 3) {
      const a = 3 * t[i], b = 3 * t[i + 1], c = 3 * t[i + 2];
      const ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
      const vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
      const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      nrm[a] += nx; nrm[a + 1] += ny; nrm[a + 2] += nz;
      nrm[b] += nx; nrm[b + 1] += ny; nrm[b + 2] += nz;
      nrm[c] += nx; nrm[c + 1] += ny; nrm[c + 2] += nz;
    }
    this.positions = p;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buf.position); gl.bufferData(gl.ARRAY_BUFFER, p, gl.DYNAMIC_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buf.normal); gl.bufferData(gl.ARRAY_BUFFER, nrm, gl.DYNAMIC_DRAW);
  }
  setScalar(values, min, max) {
    const gl = this.gl; this.range = [min, max];
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buf.scalar); gl.bufferData(gl.ARRAY_BUFFER, values, gl.DYNAMIC_DRAW);
  }
  setGroups(bytes) {
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buf.group); gl.bufferData(gl.ARRAY_BUFFER, bytes, gl.DYNAMIC_DRAW);
  }
  // Draw: options { viewProj, eye, colourBy, wireframe, lines: [{points: [[x,y,z]...], ink: [r,g,b,a]}] }.
  draw(o) {
    const gl = this.gl;
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(0.13, 0.14, 0.16, 1); gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    if (this.count > 0) {
      gl.useProgram(this.mesh); gl.bindVertexArray(this.vao);
      gl.uniformMatrix4fv(gl.getUniformLocation(this.mesh, "viewProj"), false, o.viewProj);
      gl.uniform2fv(gl.getUniformLocation(this.mesh, "range"), this.range);
      gl.uniform3fv(gl.getUniformLocation(this.mesh, "light"), o.light);
      gl.uniform1i(gl.getUniformLocation(this.mesh, "colourBy"), o.colourBy ? 1 : 0);
      gl.drawElements(gl.TRIANGLES, this.count, gl.UNSIGNED_INT, 0);
      if (o.wireframe) {
        gl.useProgram(this.line); gl.bindVertexArray(this.lineVao);
        gl.uniformMatrix4fv(gl.getUniformLocation(this.line, "viewProj"), false, o.viewProj);
        gl.uniform1f(gl.getUniformLocation(this.line, "bias"), 0.0005);
        gl.uniform4fv(gl.getUniformLocation(this.line, "ink"), [0.05, 0.05, 0.05, 1]);
        gl.drawElements(gl.LINES, this.edgeCount, gl.UNSIGNED_INT, 0);
      }
    }
    if (o.lines && o.lines.length && this.overlayVao) {
      gl.disable(gl.DEPTH_TEST);
      gl.useProgram(this.line); gl.bindVertexArray(this.overlayVao);
      gl.uniformMatrix4fv(gl.getUniformLocation(this.line, "viewProj"), false, o.viewProj);
      gl.uniform1f(gl.getUniformLocation(this.line, "bias"), 0);
      for (const l of o.lines) {
        const flat = new Float32Array(l.points.flat());
        gl.bindBuffer(gl.ARRAY_BUFFER, this.buf.lines); gl.bufferData(gl.ARRAY_BUFFER, flat, gl.STREAM_DRAW);
        gl.uniform4fv(gl.getUniformLocation(this.line, "ink"), l.ink);
        gl.drawArrays(l.strip ? gl.LINE_STRIP : gl.LINES, 0, l.points.length);
      }
    }
  }
}
