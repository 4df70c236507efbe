// Validate every .glb/.gltf under the given folders with the Khronos glTF validator (npm
// package `gltf-validator`): print each file's error/warning counts and every error; exit 1 on
// any error, or when no file was found.
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
// The validator is installed by .ci/run under .ci/node (or $GLTF_VALIDATOR_DIR).
const here = path.dirname(new URL(import.meta.url).pathname);
const require = createRequire(path.resolve(process.env.GLTF_VALIDATOR_DIR ?? path.join(here, 'node')) + '/');
const validator = require('gltf-validator');

function* files(dir) {
  for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) yield* files(p);
    else if (/\.(glb|gltf)$/i.test(e.name)) yield p;
  }
}

let count = 0, failed = 0;
for (const dir of process.argv.slice(2)) {
  if (!fs.existsSync(dir)) continue;
  for (const f of files(dir)) {
    count++;
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(f)), {
      uri: f,
      externalResourceFunction: (uri) => Promise.reject(new Error('external ' + uri)),
    });
    const { numErrors, numWarnings } = report.issues;
    console.log(`${f}: ${numErrors} errors, ${numWarnings} warnings`);
    for (const m of report.issues.messages) {
      if (m.severity === 0 || process.env.GLTF_VERBOSE) console.log(`  ${m.code} ${m.pointer ?? ''}: ${m.message}`);
    }
    if (numErrors > 0) failed++;
  }
}
if (count === 0) { console.log('no glTF files found'); process.exit(1); }
console.log(`${count} glTF file(s) validated, ${failed} with errors`);
process.exit(failed ? 1 : 0);
