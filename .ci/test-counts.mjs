// How many tests ran per workspace package, from the output of the README's test command, so a
// run that silently skipped a crate (or a binary that ran nothing) is visible.
//
//   node .ci/test-counts.mjs ARTIFACTS.json TEST.log
//
// ARTIFACTS.json: `cargo test --workspace --no-run --message-format=json` (maps each test
// binary to its package); TEST.log: the output of `cargo test --workspace`. Prints a table and
// exits 1 when a package that has test binaries ran no test at all, or when nothing was parsed.
import fs from 'node:fs';
import path from 'node:path';

const [artifactsFile, logFile] = process.argv.slice(2);
if (!artifactsFile || !logFile) {
  console.error('usage: node .ci/test-counts.mjs ARTIFACTS.json TEST.log');
  process.exit(2);
}

// `path+file:///work/main/cga#0.1.0` or `path+file:///work/x#name@0.1.0` -> package name.
function packageName(id) {
  const [url, frag = ''] = id.split('#');
  if (frag.includes('@')) return frag.split('@')[0];
  return url.replace(/\/+$/, '').split('/').pop();
}

const binaryPackage = new Map();
const packages = new Set();
for (const line of fs.readFileSync(artifactsFile, 'utf8').split('\n')) {
  if (!line.startsWith('{')) continue;
  const m = JSON.parse(line);
  if (m.reason !== 'compiler-artifact' || !m.executable || !m.profile?.test) continue;
  const name = packageName(m.package_id);
  binaryPackage.set(path.basename(m.executable), name);
  packages.add(name);
}

const counts = new Map();
const row = (p) => {
  if (!counts.has(p)) counts.set(p, { binaries: 0, passed: 0, failed: 0, ignored: 0, empty: [] });
  return counts.get(p);
};
let current = null;
let label = '';
for (const line of fs.readFileSync(logFile, 'utf8').split('\n')) {
  const running = line.match(/^\s+Running (.+?) \((?:.*[\/\\])?([^\/\\)]+)\)\s*$/);
  const doc = line.match(/^\s+Doc-tests (\S+)/);
  if (running) {
    current = binaryPackage.get(running[2]) ?? `(unknown: ${running[2]})`;
    label = running[1];
  } else if (doc) {
    const crate = doc[1];
    current = [...packages].find((p) => p.replace(/-/g, '_') === crate) ?? crate;
    label = 'doc-tests';
  }
  const result = line.match(/^test result: \w+\. (\d+) passed; (\d+) failed; (\d+) ignored/);
  if (result && current) {
    const r = row(current);
    const [passed, failed, ignored] = result.slice(1, 4).map(Number);
    r.binaries += 1;
    r.passed += passed;
    r.failed += failed;
    r.ignored += ignored;
    if (passed + failed === 0 && label !== 'doc-tests') r.empty.push(label);
    current = null;
  }
}

let bad = counts.size === 0;
console.log('package'.padEnd(14), 'binaries'.padStart(8), 'passed'.padStart(7), 'failed'.padStart(7), 'ignored'.padStart(8));
for (const p of [...new Set([...packages, ...counts.keys()])].sort()) {
  const r = counts.get(p) ?? { binaries: 0, passed: 0, failed: 0, ignored: 0, empty: [] };
  console.log(p.padEnd(14), String(r.binaries).padStart(8), String(r.passed).padStart(7), String(r.failed).padStart(7), String(r.ignored).padStart(8));
  if (r.passed === 0) {
    console.log(`  ${p}: no test ran`);
    bad = true;
  }
  if (r.empty.length) console.log(`  ${p}: binaries that ran no test: ${r.empty.join(', ')}`);
}
process.exit(bad ? 1 : 0);
