// The editor in a real browser (Debian's Chromium, headless, driven by playwright-core): open
// the page `deform view` prints, paint a handle region, drag its gizmo and check that the mesh
// on the server moved as the drag says, switch the method, play the rig's animation, cut it and
// undo. Fails on any console error; keeps a screenshot of each step under OUT and checks that
// none is blank.
//
//   node deform/tests/view/browser.mjs PATH/TO/deform OUT
import fs from 'node:fs';
import path from 'node:path';
import { startServer, openPage, until, settled, drag, paintGroup, arrow, drawnShare, drawnNear } from './driver.mjs';

const [program, out] = process.argv.slice(2);
if (!program || !out) { console.error('usage: browser.mjs DEFORM OUT'); process.exit(2); }
fs.mkdirSync(out, { recursive: true });
const { server, url } = await startServer(program);
const problems = [];
const { browser, page } = await openPage(url, problems);
let shots = 0;

function check(ok, what) {
  if (!ok) throw new Error(what);
  console.log(`ok: ${what}`);
}
async function shot(name) {
  const file = path.join(out, `${++shots}-${name}.png`);
  await page.waitForTimeout(150);
  await page.screenshot({ path: file });
  const drawn = await drawnShare(page);
  check(drawn > 0.02, `${name}: ${(100 * drawn).toFixed(1)}% of the canvas drawn (${file})`);
}

try {
  await until(page, () => editor.state && editor.n > 0 && editor.positions, null, 'the first scene');
  check(await page.evaluate(() => editor.state.scene) === 'sphere', 'the page opens the demo sphere');
  await shot('open');

  // Paint a new handle group where the sphere faces the camera.
  const front = await page.evaluate(() => {
    const c = editor.camera;
    return c.screen(V.norm(V.sub(c.eye(), c.target)));
  });
  await paintGroup(page, 3, front);
  const painted = await page.evaluate(() => editor.groupsOf.filter((g) => g === 4).length);
  check(painted > 5, `painting made group 3 (${painted} vertices)`);
  await shot('painted');

  // Lasso a fifth group below it.
  await page.check('input[name=tool][value=lasso]');
  await page.selectOption('#group', '4');
  {
    const b = await page.locator('#view').boundingBox(), [x, y] = [front[0], front[1] + 60];
    await page.mouse.move(b.x + x - 25, b.y + y - 20);
    await page.mouse.down();
    for (const [dx, dy] of [[25, -20], [25, 20], [-25, 20], [-25, -20]]) { await page.mouse.move(b.x + x + dx, b.y + y + dy, { steps: 4 }); }
    await page.mouse.up();
  }
  await until(page, () => editor.state.groups.length === 5 && !editor.state.stale, null, 'the lassoed group bound');
  const lassoed = await page.evaluate(() => editor.groupsOf.filter((g) => g === 5).length);
  check(lassoed > 5, `the lasso made group 4 (${lassoed} vertices)`);
  // Undo the lasso (the page's button), then redo it: the groups come back, bound.
  await page.click('#undo-select');
  await until(page, () => editor.state.groups.length === 4 && !editor.state.stale, null, 'the lasso undone');
  check(await page.evaluate(() => editor.groupsOf.filter((g) => g === 5).length) === 0, 'Undo selection took the lassoed group away');
  await page.click('#redo-select');
  await until(page, () => editor.state.groups.length === 5 && !editor.state.stale, null, 'the lasso redone');
  check(await page.evaluate(() => editor.groupsOf.filter((g) => g === 5).length) === lassoed, 'Redo selection brought it back');
  // The second rebind of the same method came with the first one's time (the progress bar's
  // estimate); the bar is gone once the server is idle.
  const expect = await page.evaluate(() => editor.busyExpect);
  check(expect > 0, `the redo's rebind was expected to take about ${expect && expect.toFixed(1)} ms`);
  await until(page, () => document.getElementById('busy-box').hidden, null, 'the progress bar hidden when idle');
  await page.selectOption('#group', '3');

  // Drag the gizmo's x arrow of group 3.
  await page.check('input[name=tool][value=move]');
  await settled(page);
  const a = await arrow(page);
  await drag(page, a.p, [a.p[0] + 90 * a.dir[0], a.p[1] + 90 * a.dir[1]]);
  await settled(page);
  const moved = await page.evaluate(() => {
    const t = editor.groups[3].t;
    let worst = 0, count = 0;
    for (let v = 0; v < editor.n; v++) {
      if (editor.groupsOf[v] !== 4) continue;
      count++;
      for (let k = 0; k < 3; k++) worst = Math.max(worst, Math.abs(editor.positions[3 * v + k] - editor.rest[3 * v + k] - t[k]));
    }
    return { t, worst, count };
  });
  check(moved.t[0] > 0.05 && Math.abs(moved.t[1]) < 1e-9 && Math.abs(moved.t[2]) < 1e-9, `the drag moved group 3 along x by ${moved.t[0].toFixed(3)}`);
  check(moved.worst < 1e-5, `the server moved its ${moved.count} vertices by exactly that (worst ${moved.worst.toExponential(2)})`);
  check(await page.isVisible('button[data-export=selection]'), 'handles offer their selection for export');
  await shot('dragged');
  // Undo the drag, then redo it (Ctrl+Z, Ctrl+Shift+Z).
  await page.keyboard.press('Control+z');
  await settled(page);
  check(await page.evaluate(() => editor.groups[3].t[0]) === 0, 'Ctrl+Z undid the drag');
  await page.keyboard.press('Control+Shift+z');
  await settled(page);
  check(await page.evaluate((t) => editor.groups[3].t[0] === t, moved.t[0]), 'Ctrl+Shift+Z redid it');

  // Switch the method: ARAP keeps the handle where the drag put it.
  await page.selectOption('#method', 'arap');
  await until(page, () => editor.state.method === 'arap', null, 'ARAP bound');
  await settled(page);
  const arap = await page.evaluate(() => {
    const t = editor.groups[3].t;
    let worst = 0, far = 0;
    for (let v = 0; v < editor.n; v++) {
      const d = Math.hypot(...[0, 1, 2].map((k) => editor.positions[3 * v + k] - editor.rest[3 * v + k]));
      far = Math.max(far, d);
      if (editor.groupsOf[v] === 4) for (let k = 0; k < 3; k++) worst = Math.max(worst, Math.abs(editor.positions[3 * v + k] - editor.rest[3 * v + k] - t[k]));
    }
    return { worst, far };
  });
  check(arap.worst < 1e-5 && arap.far > 0.05, `ARAP: the handle stays put (${arap.worst.toExponential(2)}), the surface moved (${arap.far.toFixed(3)})`);
  await shot('arap');

  // A lattice: click a control point, drag its arrow; the bar follows.
  await page.selectOption('#scene', 'lattice');
  await until(page, () => editor.state && editor.state.scene === 'lattice' && editor.controls, null, 'the lattice');
  await settled(page);
  const corner = await page.evaluate(() => {
    const i = editor.groups.length - 1;
    return { i, at: editor.camera.screen(editor.groups[i].c) };
  });
  const b = await page.locator('#view').boundingBox();
  await page.mouse.click(b.x + corner.at[0], b.y + corner.at[1]);
  check(await page.evaluate(() => $("group").value) === `${corner.i}`, `clicking control point ${corner.i} selects it`);
  // (The corner is at the canvas's right edge: grab its arrow halfway and pull it inwards.)
  const la = await arrow(page, 0.5);
  await drag(page, la.p, [la.p[0] - 80 * la.dir[0], la.p[1] - 80 * la.dir[1]]);
  await settled(page);
  const bent = await page.evaluate(() => {
    let d = 0;
    for (let i = 0; i < editor.positions.length; i++) d = Math.max(d, Math.abs(editor.positions[i] - editor.rest[i]));
    return d;
  });
  check(bent > 0.05, `dragging the control point moved the bar (${bent.toFixed(3)})`);
  // A lattice is replayed from its motors alone: no selection to export.
  check(!(await page.isVisible('button[data-export=selection]')) && !(await page.isVisible('#load-selection'))
    && await page.isVisible('button[data-export=motors]'),
    'the lattice offers its motors, not a selection, for export');
  await shot('lattice');
  // A finer B-spline lattice from the panel: the server rebinds to 6 x 3 x 3 points.
  await page.fill('#lattice-x', '6');
  await page.dispatchEvent('#lattice-x', 'change');
  await page.selectOption('#basis', 'bspline-2');
  await until(page, () => editor.state && editor.state.options.basis === 'bspline-2' && editor.state.controls.points.length === 54, null, 'the 6x3x3 B-spline lattice');
  await settled(page);
  check(await page.evaluate(() => editor.groups.length) === 54, 'the page keeps a gizmo per point of the new lattice');
  await shot('lattice-6x3x3');

  // The rig: play its animation.
  await page.selectOption('#scene', 'arm');
  await until(page, () => editor.state && editor.state.kind === 'rig', null, 'the arm rig');
  await settled(page);
  const before = await page.evaluate(() => editor.received);
  await page.click('#play');
  await page.waitForTimeout(1500);
  await page.click('#play');
  await settled(page);
  const played = await page.evaluate((b) => {
    let d = 0;
    for (let i = 0; i < editor.positions.length; i++) d = Math.max(d, Math.abs(editor.positions[i] - editor.rest[i]));
    return { frames: editor.received - b, moved: d };
  }, before);
  check(played.frames >= 5 && played.moved > 0.1, `the animation played: ${played.frames} frames in 1.5 s, largest move ${played.moved.toFixed(2)}`);
  await shot('played');

  // Cut with the plane through the middle of the arm, then undo.
  const vertices = await page.evaluate(() => editor.state.vertices);
  await page.check('#plane');
  await shot('plane');
  await page.click('#cut');
  await until(page, (n) => editor.state.rig.undo === 1 && editor.state.vertices > n, vertices, 'the cut');
  await settled(page);
  check(true, `the cut made ${await page.evaluate(() => editor.state.vertices) - vertices} vertices`);
  await shot('cut');
  await page.click('#undo');
  await until(page, (n) => editor.state.rig.undo === 0 && editor.state.vertices === n, vertices, 'the undo');
  check(true, `undo restored the ${vertices} vertices of the uncut arm`);
  await shot('undone');

  // Drill where the arm is drawn nearest the middle of the view; the result animates.
  await page.check('input[name=rig-tool][value=drill]');
  const [spot] = await drawnNear(page, [await page.evaluate(() => editor.camera.screen(editor.camera.target))]);
  await page.mouse.click(b.x + spot[0], b.y + spot[1]);
  await until(page, (n) => editor.state.rig.undo === 1 && editor.state.vertices !== n, vertices, 'the drill');
  const made = await page.evaluate(() => editor.state.vertices);
  await page.selectOption('#field', 'made');
  await page.click('#play');
  await page.waitForTimeout(600);
  await page.click('#play');
  await settled(page);
  check(await page.evaluate(() => editor.positions.length / 3) === made, `the drilled arm (${made} vertices) animates`);
  await shot('drilled');

  // Open a model from "disk": an octahedron as OBJ through the page's file input.
  const octahedron = 'v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n' +
    'f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n';
  await page.setInputFiles('#upload', { name: 'octahedron.obj', mimeType: 'text/plain', buffer: Buffer.from(octahedron) });
  await until(page, () => editor.state.scene === 'octahedron.obj' && editor.state.kind === 'mesh' && editor.state.vertices === 6, null, 'the uploaded model');
  check(true, 'the uploaded octahedron opened as a scene');
  await shot('uploaded');
  check(problems.length === 0, `no console errors${problems.length ? ': ' + problems.join('; ') : ''}`);
} catch (e) {
  console.error(`FAILED: ${e.message}`);
  for (const p of problems) console.error(p);
  await page.screenshot({ path: path.join(out, 'failure.png') }).catch(() => {});
  process.exitCode = 1;
} finally {
  await browser.close();
  server.kill();
}
