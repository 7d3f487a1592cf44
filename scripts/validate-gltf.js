#!/usr/bin/env node
// The Khronos glTF validator (npm's gltf-validator, pinned by web/package-lock.json and
// installed by scripts/install-deps.sh) on each file given: prints its errors,
// warnings, infos and hints and every error's code, message and JSON pointer; exits 1
// when any file has an error (or cannot be read), 2 without the validator, else 0.
//   node scripts/validate-gltf.js out/office/scene.glb [more.glb ...]
// The validator is looked for in web/node_modules, then wherever Node's own
// resolution finds it.
'use strict';
const fs = require('fs');
const path = require('path');

function loadValidator() {
  const candidates = [path.join(__dirname, '..', 'web', 'node_modules', 'gltf-validator'), 'gltf-validator'];
  for (const c of candidates) {
    try {
      return require(c);
    } catch (e) {
      if (e.code !== 'MODULE_NOT_FOUND') throw e;
    }
  }
  return null;
}

async function main(files) {
  if (files.length === 0) {
    console.error('usage: validate-gltf.js FILE.glb [FILE.glb ...]');
    return 2;
  }
  const validator = loadValidator();
  if (!validator) {
    console.error('validate-gltf: the npm package gltf-validator is missing (run scripts/install-deps.sh)');
    return 2;
  }
  let failed = 0;
  for (const file of files) {
    let report;
    try {
      const bytes = new Uint8Array(fs.readFileSync(file));
      report = await validator.validateBytes(bytes, { uri: path.basename(file), maxIssues: 0 });
    } catch (e) {
      console.log(`${file}: cannot validate: ${e && e.message ? e.message : e}`);
      ++failed;
      continue;
    }
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints` +
                ` (validator ${report.validatorVersion})`);
    for (const m of i.messages) {
      // Severity 0 error, 1 warning, 2 info, 3 hint: errors and warnings are listed.
      if (m.severity <= 1)
        console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code}: ${m.message}${m.pointer ? ' at ' + m.pointer : ''}`);
    }
    if (i.numErrors > 0) ++failed;
  }
  if (files.length > 1) console.log(`validate-gltf: ${files.length - failed} of ${files.length} files without errors`);
  return failed ? 1 : 0;
}

main(process.argv.slice(2)).then((code) => process.exit(code), (e) => {
  console.error(`validate-gltf: ${e && e.stack ? e.stack : e}`);
  process.exit(2);
});
