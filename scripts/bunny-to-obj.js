#!/usr/bin/env node
// Writes the Stanford bunny of the npm package `bunny` as a Wavefront OBJ.
// The package exports {positions: [[x, y, z], ...], cells: [[a, b, c], ...]}
// with 0-based indices; OBJ counts from 1.
//
// usage: node bunny-to-obj.js PACKAGE_DIR OUTPUT.obj
'use strict';
const fs = require('fs');
const path = require('path');

const [packageDir, output] = process.argv.slice(2);
if (!packageDir || !output) {
  console.error('usage: node bunny-to-obj.js PACKAGE_DIR OUTPUT.obj');
  process.exit(2);
}
const bunny = require(path.resolve(packageDir));
if (!Array.isArray(bunny.positions) || !Array.isArray(bunny.cells)) {
  console.error(`bunny-to-obj: ${packageDir} does not export {positions, cells}`);
  process.exit(1);
}

const lines = [
  '# The Stanford bunny (Stanford 3D Scanning Repository),',
  '# converted from the npm package "bunny" by scripts/bunny-to-obj.js.',
  `# ${bunny.positions.length} vertices, ${bunny.cells.length} triangles`,
];
for (const [x, y, z] of bunny.positions) lines.push(`v ${x} ${y} ${z}`);
for (const cell of bunny.cells) lines.push('f ' + cell.map((i) => i + 1).join(' '));
fs.writeFileSync(output, lines.join('\n') + '\n');
