// Validates one glTF or GLB file with the Khronos glTF validator: `node validate.mjs FILE`.
// Prints "errors E warnings W infos I" and the first messages; exits 1 when E > 0 (2 on misuse).
// External buffers are read from the files beside FILE.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

const kShownMessages = 10;
const kSeverity = ['error', 'warning', 'info', 'hint'];

const file = process.argv[2];
if (!file || process.argv.length > 3) {
  console.error('usage: node validate.mjs FILE');
  process.exit(2);
}
const report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
  uri: path.basename(file),
  maxIssues: 0,  // every issue counted
  externalResourceFunction: (uri) =>
    readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((data) => new Uint8Array(data)),
});
const issues = report.issues;
console.log(`errors ${issues.numErrors} warnings ${issues.numWarnings} infos ${issues.numInfos}`);
for (const m of issues.messages.slice(0, kShownMessages))
  console.log(`  ${kSeverity[m.severity] ?? m.severity} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
process.exit(issues.numErrors > 0 ? 1 : 0);
