// Validates glTF files with the Khronos glTF validator (the npm package gltf-validator) and prints one line,
// "GRCIS-RESULT <json>": per file its error and warning counts and the errors' messages. Used by GltfValidatorTests.
//   node validate-gltf.js <folder of the gltf-validator package> <file.glb|file.gltf>...
const validator = require(process.argv[2]);
const fs = require("fs");
const path = require("path");

(async () => {
  const reports = [];
  for (const file of process.argv.slice(3)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: path.basename(file),
      maxIssues: 100,
      // A .gltf's buffer is the .bin file beside it.
      externalResourceFunction: uri => new Promise((resolve, reject) =>
        fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (e, data) => (e ? reject(e) : resolve(new Uint8Array(data))))),
    });
    reports.push({
      file: path.basename(file),
      errors: report.issues.numErrors,
      warnings: report.issues.numWarnings,
      messages: report.issues.messages.filter(m => m.severity === 0).map(m => `${m.code} ${m.pointer ?? ""}: ${m.message}`),
    });
  }
  console.log("GRCIS-RESULT " + JSON.stringify(reports));
})().catch(e => {
  console.error(String(e));
  process.exit(1);
});
