#!/usr/bin/env node
// Runs the Khronos glTF-Validator (npm package gltf-validator, installed by install_deps.sh into
// build-tools/gltf-validator) on one .glb/.gltf file: prints the issue counts and every error or
// warning, exits 1 when there is an error.
'use strict';
const fs = require('fs');
const path = require('path');

const file = process.argv[2];
if (!file) {
  console.error('usage: validate_gltf.js FILE.glb');
  process.exit(2);
}
const root = path.join(__dirname, '..', 'build-tools', 'gltf-validator', 'node_modules', 'gltf-validator');
const validator = require(root);
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {maxIssues: 100})
  .then((report) => {
    const issues = report.issues;
    console.log(`errors ${issues.numErrors} warnings ${issues.numWarnings} infos ${issues.numInfos} hints ${issues.numHints}`);
    for (const m of issues.messages) {
      if (m.severity <= 1) console.log(`${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer || ''}: ${m.message}`);
    }
    process.exit(issues.numErrors > 0 ? 1 : 0);
  })
  .catch((e) => {
    console.error(`error: ${e}`);
    process.exit(1);
  });
