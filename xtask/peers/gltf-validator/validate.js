#!/usr/bin/env node
// SPDX-License-Identifier: MIT
//
// Runs the Khronos glTF-Validator (npm package `gltf-validator`) on every .gltf or .glb file
// named on the command line. A .gltf file's external buffers are read relative to the file.
//
//   node validate.js FILE...
//
// For each file it prints one summary line
//   FILE: validator VERSION errors=E warnings=W infos=I hints=H
// followed by one line per reported message. Exit status: 0 if every file has no errors and no
// warnings (infos and hints are allowed), 1 if any file has an error or a warning, 2 on a usage
// error or when a file cannot be read or the validator fails.
//
// Install once with `npm ci` (or `npm install`) in this directory; node_modules is not committed.

'use strict';

const fs = require('fs');
const path = require('path');

const SEVERITY = ['ERROR', 'WARN', 'INFO', 'HINT'];

function loadValidator() {
  try {
    return require('gltf-validator');
  } catch (e) {
    console.error(`gltf-validator is not installed: run \`npm install\` in ${__dirname} (${e.message})`);
    process.exit(2);
  }
}

async function validateFile(validator, file) {
  const bytes = new Uint8Array(await fs.promises.readFile(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 200,
    externalResourceFunction: (uri) =>
      fs.promises
        .readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)))
        .then((buf) => new Uint8Array(buf), (err) => Promise.reject(err.toString())),
  });
  const issues = report.issues;
  console.log(
    `${file}: validator ${report.validatorVersion} errors=${issues.numErrors} ` +
      `warnings=${issues.numWarnings} infos=${issues.numInfos} hints=${issues.numHints}`,
  );
  for (const m of issues.messages) {
    console.log(`  [${SEVERITY[m.severity] || m.severity}] ${m.code} ${m.pointer || ''}: ${m.message}`);
  }
  return issues.numErrors === 0 && issues.numWarnings === 0;
}

async function main() {
  const files = process.argv.slice(2);
  if (files.length === 0 || files.includes('--help') || files.includes('-h')) {
    console.error('usage: node validate.js FILE.gltf|FILE.glb ...');
    process.exit(2);
  }
  const validator = loadValidator();
  let clean = true;
  for (const file of files) {
    try {
      clean = (await validateFile(validator, file)) && clean;
    } catch (e) {
      console.error(`${file}: validation failed: ${e}`);
      process.exit(2);
    }
  }
  process.exit(clean ? 0 : 1);
}

main();
