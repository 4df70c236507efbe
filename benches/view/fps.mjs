// End-to-end frame rates of `deform view` on a large mesh (issue 24's speed targets), in
// headless Chromium: paint 4 handle groups (timing each bind from the mouse's release, which
// sends it, to the bound state at the page), then drag a gizmo for a few seconds with handles and with ARAP (2
// iterations per frame) and count the poses that came back (edit in, positions received and
// drawn) per second. Each row also gives the edits made per second: in a mouse drag the
// driver's mouse events (which a busy renderer delivers late) bound the poses. Two more rows
// make one edit per animation frame from the page itself, with and without the renderer's
// draw call, and one drag with handles and one with ARAP skip the draw call: without the
// rasteriser (a GPU's job) what is left is the socket, the page's upload and normals, and the
// server.
//
//   cargo build --release -p deform
//   node benches/view/fps.mjs target/release/deform ../shared/data/meshes/large/armadillo-50k.obj [SECONDS] [WxH]
//
// Runs the server and the browser on this machine (both cores shared); the browser draws with
// SwiftShader (software GL), or with Mesa's llvmpipe under CHROMIUM_GL=llvmpipe (a faster
// software rasteriser), so "drawn" is a floor for a machine with a GPU.
import { startServer, openPage, until, settled, drag, arrow, drawnNear } from '../../deform/tests/view/driver.mjs';

const [program, model, seconds = '4', size = '1200x760'] = process.argv.slice(2);
if (!program || !model) { console.error('usage: fps.mjs DEFORM MODEL [SECONDS]'); process.exit(2); }
const { server, url } = await startServer(program, [model]);
const problems = [];
const [width, height] = size.split('x').map(Number);
const { browser, page } = await openPage(url, problems, { width, height });
const rows = [];

// Drag the current gizmo's x arrow back and forth for `s` seconds; poses and drawn frames per s.
async function measureDrag(name, s) {
  await page.check('input[name=tool][value=move]');
  await settled(page);
  const a = await arrow(page);
  const start = await page.evaluate(() => {
    return { received: editor.received, drawn: editor.drawn || 0, t: performance.now() };
  });
  const median = (v) => { const w = v.filter((x) => x != null).sort((p, q) => p - q); return w.length ? w[w.length >> 1] : NaN; };
  const b = await page.locator('#view').boundingBox();
  await page.mouse.move(b.x + a.p[0], b.y + a.p[1]);
  await page.mouse.down();
  const t0 = Date.now();
  let k = 0;
  const draws = [], messages = [];
  while (Date.now() - t0 < s * 1000) {
    const off = 60 * Math.sin(k++ / 10);
    await page.mouse.move(b.x + a.p[0] + off * a.dir[0], b.y + a.p[1] + off * a.dir[1]);
    await page.waitForTimeout(8);
    // The page's own work per frame: upload (normals, buffers) and draw; one message's handling
    // (read every 8th move: each read is a round trip to the page that delays the next move).
    if (k % 8 === 0) {
      const [d, m] = await page.evaluate(() => [editor.drawMs, editor.messageMs]);
      draws.push(d); messages.push(m);
    }
  }
  await page.mouse.up();
  const end = await page.evaluate((st) => {
    const t = (performance.now() - st.t) / 1000;
    return { poses: (editor.received - st.received) / t, drawn: (editor.drawn - st.drawn) / t, roundTrip: editor.roundTrip, poseMs: editor.poseMs };
  }, start);
  rows.push({ name, ...end, moves: k / ((Date.now() - t0) / 1000), drawMs: median(draws), messageMs: median(messages) });
}

// Edits made by the page itself, one per animation frame (group 1 moved along x), for `s`
// seconds: the pipeline's own rate, without the driver's mouse events (which a busy renderer
// delays: above, poses received match the mouse moves delivered).
async function measureEdits(name, s) {
  await settled(page);
  const r = await page.evaluate((s) => new Promise((done) => {
    const g = editor.groups[1], t0 = performance.now(), start = { received: editor.received, drawn: editor.drawn || 0 };
    let edits = 0;
    const step = (now) => {
      if (now - t0 > s * 1000) {
        const t = (performance.now() - t0) / 1000;
        done({ moves: edits / t, poses: (editor.received - start.received) / t, drawn: (editor.drawn - start.drawn) / t, roundTrip: editor.roundTrip, poseMs: editor.poseMs, drawMs: editor.drawMs, messageMs: editor.messageMs });
        return;
      }
      g.t = [0.05 * Math.sin(edits / 10), 0, 0]; editor.dirty = true; edits++;
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }), s);
  rows.push({ name, ...r });
}

try {
  await until(page, () => editor.state && editor.n > 0, null, 'the model');
  const n = await page.evaluate(() => editor.n);
  // Four groups: points of the surface under a cross around the middle of the view.
  const middle = await page.evaluate(() => {
    const c = editor.camera, m = c.screen(c.target);
    return [[0, -0.2], [0, 0.2], [-0.1, 0], [0.1, 0]].map(([x, y]) => [m[0] + x * c.w, m[1] + y * c.h]);
  });
  const spots = await drawnNear(page, middle);
  for (let g = 0; g < 4; g++) {
    // The stroke (paintGroup's), then the time from the mouse's release (the page sends the
    // bind) to the bound state at the page.
    await page.check('input[name=tool][value=paint]');
    await page.selectOption('#group', `${g}`);
    const at = spots[g];
    await drag(page, [at[0], at[1] - 4], [at[0], at[1] + 4], 4);
    const t = Date.now();
    await until(page, (g) => editor.state.groups.length === g + 1 && !editor.state.stale, g, `group ${g} bound`);
    const ms = Date.now() - t;
    const s = await page.evaluate(() => editor.state);
    rows.push({ name: `bind ${g + 1} handle group(s)`, bindMs: s.bind_ms, pageMs: ms, vertices: s.groups[g].vertices });
  }
  await page.selectOption('#group', '1');
  await measureDrag('handles (motor-log), dragging', +seconds);
  await measureEdits('handles (motor-log), an edit every frame from the page', +seconds);
  // The same drag with the rasteriser left out (the renderer's draw call skipped; positions
  // still received, normals computed and buffers uploaded): what a browser whose GPU draws the
  // mesh in no time would get, on this machine's two cores.
  await page.evaluate(() => { editor.renderer.realDraw = editor.renderer.draw; editor.renderer.draw = () => {}; });
  await measureDrag('handles (motor-log), dragging, draw call skipped', +seconds);
  await measureEdits('handles (motor-log), an edit every frame, draw call skipped', +seconds);
  await page.evaluate(() => { editor.renderer.draw = editor.renderer.realDraw; });
  await page.selectOption('#method', 'arap');
  const t = Date.now();
  await until(page, () => editor.state.method === 'arap' && !editor.state.stale, null, 'ARAP bound');
  rows.push({ name: 'bind ARAP', bindMs: await page.evaluate(() => editor.state.bind_ms), pageMs: Date.now() - t });
  await measureDrag('ARAP, 2 iterations per frame, dragging', +seconds);
  await page.evaluate(() => { editor.renderer.draw = () => {}; });
  await measureDrag('ARAP, 2 iterations per frame, dragging, draw call skipped', +seconds);
  await page.evaluate(() => { editor.renderer.draw = editor.renderer.realDraw; });
  console.log(`deform view on ${model} (${n} vertices)`);
  for (const r of rows) {
    if (r.poses !== undefined) {
      console.log(`${r.name}: ${r.moves.toFixed(1)} edits/s, ${r.poses.toFixed(1)} poses/s received, ${r.drawn.toFixed(1)} frames/s drawn, pose ${r.poseMs.toFixed(1)} ms, round trip ${r.roundTrip.toFixed(1)} ms; in the page per frame: upload and draw ${r.drawMs.toFixed(1)} ms, a message ${r.messageMs.toFixed(1)} ms (medians)`);
    } else {
      console.log(`${r.name}: server ${r.bindMs.toFixed(0)} ms, seen by the page ${r.pageMs} ms${r.vertices ? `, ${r.vertices} vertices painted` : ''}`);
    }
  }
  if (problems.length) { console.error(problems.join('\n')); process.exitCode = 1; }
} catch (e) {
  console.error(`FAILED: ${e.message}`);
  process.exitCode = 1;
} finally {
  await browser.close();
  server.kill();
}
