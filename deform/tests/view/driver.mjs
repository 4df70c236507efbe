// Driving `deform view` in headless Chromium (playwright-core): shared by the browser test
// (deform/tests/view/browser.mjs) and the frame-rate measurement (benches/view/fps.mjs).
import { spawn } from 'node:child_process';
import path from 'node:path';
import { createRequire } from 'node:module';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../../..');

/// `deform view ARGS --port 0`; resolves to { server, url } once it printed its address.
export async function startServer(program, args = []) {
  const server = spawn(program, ['view', ...args, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve, reject) => {
    let text = '';
    server.stdout.on('data', (d) => { text += d; const m = text.match(/http:\/\/\S+/); if (m) resolve(m[0]); });
    server.on('exit', (code) => reject(new Error(`deform view exited with ${code}`)));
    setTimeout(() => reject(new Error('no address printed in 120 s')), 120000);
  });
  return { server, url };
}

/// Headless Chromium (Debian's, or $CHROMIUM) and a page that records console errors.
export async function openPage(url, problems, viewport = { width: 1200, height: 760 }) {
  // playwright-core from $PLAYWRIGHT_DIR, else .ci/node (where .ci/run installs it).
  const require = createRequire(path.resolve(process.env.PLAYWRIGHT_DIR ?? path.join(root, '.ci/node')) + '/');
  const { chromium } = require('playwright-core');
  // WebGL through SwiftShader by default; CHROMIUM_GL=llvmpipe draws with Mesa's llvmpipe
  // (ANGLE over EGL), a faster software rasteriser.
  const gl = process.env.CHROMIUM_GL === 'llvmpipe'
    ? ['--use-angle=gl-egl', '--ignore-gpu-blocklist']
    : ['--disable-gpu', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'];
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run', ...gl],
  });
  const page = await browser.newPage({ viewport });
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  await page.goto(url);
  return { browser, page };
}

/// Wait for `fn(arg)` to hold in the page.
export const until = (page, fn, arg, what, timeout = 120000) =>
  page.waitForFunction(fn, arg, { timeout, polling: 20 }).catch(() => { throw new Error(`timed out: ${what}`); });

/// Every pose the page sent has come back.
export const settled = (page) =>
  until(page, () => editor.received === editor.seq && !editor.dirty, null, 'the last pose');

/// A mouse drag between canvas pixels, in `steps` moves `pause` ms apart.
export async function drag(page, from, to, steps = 12, pause = 16) {
  const b = await page.locator('#view').boundingBox();
  await page.mouse.move(b.x + from[0], b.y + from[1]);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(b.x + from[0] + (to[0] - from[0]) * k / steps, b.y + from[1] + (to[1] - from[1]) * k / steps);
    await page.waitForTimeout(pause);
  }
  await page.mouse.up();
}

/// Paint group `group` with a short stroke through the canvas pixel `at`; resolves when bound.
export async function paintGroup(page, group, at) {
  await page.check('input[name=tool][value=paint]');
  await page.selectOption('#group', `${group}`);
  await drag(page, [at[0], at[1] - 4], [at[0], at[1] + 4], 4);
  await until(page, (g) => editor.state.groups.length === g + 1 && !editor.state.stale, group, `group ${group} bound`);
}

/// The canvas pixel of the gizmo's x arrow at `at` of its length, and its screen direction.
export const arrow = (page, at = 0.8) => page.evaluate((at) => {
  const g = editor.gizmo, p = g.grip('translate', 0, at), c = editor.camera.screen(g.target.origin());
  const d = [p[0] - c[0], p[1] - c[1]], l = Math.hypot(d[0], d[1]);
  return { p, dir: [d[0] / l, d[1] / l] };
}, at);

/// For each canvas point of `wanted`, the nearest canvas pixel where something is drawn.
export const drawnNear = (page, wanted) => page.evaluate((wanted) => {
  const gl = editor.renderer.gl, w = gl.drawingBufferWidth, h = gl.drawingBufferHeight, px = new Uint8Array(4 * w * h);
  editor.redraw();
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
  const k = w / editor.camera.w;
  return wanted.map((want) => {
    let best = null, bd = Infinity;
    for (let j = 0; j < h; j += 2) for (let i = 0; i < w; i += 2) {
      const o = 4 * (j * w + i);
      if (Math.abs(px[o] - 33) + Math.abs(px[o + 1] - 36) + Math.abs(px[o + 2] - 41) <= 24) continue;
      const p = [i / k, (h - 1 - j) / k], d = Math.hypot(p[0] - want[0], p[1] - want[1]);
      if (d < bd) { bd = d; best = p; }
    }
    return best;
  });
}, wanted);

/// The share of canvas pixels that are not the background.
export const drawnShare = (page) => page.evaluate(() => {
  const gl = editor.renderer.gl, w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  editor.redraw(); // read in the same task as the draw (the drawing buffer is not preserved)
  const px = new Uint8Array(4 * w * h);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
  let n = 0;
  for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - 33) + Math.abs(px[i + 1] - 36) + Math.abs(px[i + 2] - 41) > 24) n++;
  return n / (w * h);
});
