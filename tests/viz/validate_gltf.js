// Validates .glb files with the Khronos glTF validator (npm package gltf-validator, installed
// by scripts/test.sh): exits 1 when any file has an error or a warning.
const validator = require(process.env.MECHANIST_GLTF_VALIDATOR);
const fs = require('fs');

(async () => {
  let failed = false;
  for (const file of process.argv.slice(2)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)));
    const issues = report.issues;
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings`);
    for (const m of issues.messages) console.log(`  ${m.severity} ${m.code} ${m.pointer || ''}: ${m.message}`);
    failed = failed || issues.numErrors > 0 || issues.numWarnings > 0;
  }
  process.exit(failed ? 1 : 0);
})().catch((e) => { console.error(e); process.exit(2); });
