// The Khronos glTF validator (npm gltf-validator) on files: node gltf_validate.js PACKAGE_DIR FILE...
// Prints one line per file, "FILE: N errors", then its errors' codes, pointers and messages.
// Exits 0 when every file was judged (whatever it found), 2 when one could not be.
const fs = require("fs");
const path = require("path");
const validator = require(path.resolve(process.argv[2]));

async function judge(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) =>
        fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(data)))),
  });
  const errors = report.issues.messages.filter((m) => m.severity === 0);
  console.log(file + ": " + errors.length + " errors");
  for (const m of errors) console.log("  " + m.code + " " + (m.pointer || "") + " " + m.message);
}

(async () => {
  for (const file of process.argv.slice(3)) await judge(file);
})().catch((e) => {
  console.error(String(e));
  process.exit(2);
});
