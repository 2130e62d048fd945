// Writes the mesh an npm data package exports (`positions`: [x, y, z] per vertex, `cells`:
// vertex indices per face, counted from 0; the stackgl convention of bunny, teapot, snowden) as
// a triangulated OBJ that our loader reads. Used by scripts/fetch-models.sh.
//   node npm-mesh-to-obj.js MODULE.js OUT.obj [COMMENT ...]
'use strict';
const fs = require('fs');
const path = require('path');

function fail(message) {
  process.stderr.write(`npm-mesh-to-obj: ${message}\n`);
  process.exit(1);
}

// The shortest decimal that reads back as the same 32-bit float (our loader keeps floats, so
// more digits would only make the file larger), with an exponent below 1e-4 as C's %g writes
// it ("1.5e-05"), so the files match the developers' copies byte for byte.
function shortestFloat(x) {
  const f = Math.fround(x);
  let value = Number(f.toPrecision(9));
  for (let digits = 1; digits < 9; ++digits) {
    const candidate = Number(f.toPrecision(digits));
    if (Math.fround(candidate) === f) {
      value = candidate;
      break;
    }
  }
  if (value !== 0 && Math.abs(value) < 1e-4) {
    return value.toExponential().replace(/e-(\d)$/, 'e-0$1');
  }
  return String(value);
}

const [moduleFile, outFile, ...comments] = process.argv.slice(2);
if (!moduleFile || !outFile) fail('usage: node npm-mesh-to-obj.js MODULE.js OUT.obj [COMMENT ...]');
const mesh = require(path.resolve(moduleFile));
const positions = mesh.positions;
const cells = mesh.cells;
if (!Array.isArray(positions) || !Array.isArray(cells)) {
  fail(`${moduleFile}: exports no 'positions' and 'cells' arrays`);
}

const lines = comments.map((c) => `# ${c}`);
positions.forEach((p, i) => {
  if (p.length !== 3 || !p.every(Number.isFinite)) fail(`${moduleFile}: vertex ${i} is not 3 finite numbers`);
  lines.push(`v ${p.map(shortestFloat).join(' ')}`);
});
cells.forEach((cell, i) => {
  if (cell.length < 3) fail(`${moduleFile}: face ${i} has ${cell.length} corners`);
  for (const v of cell) {
    if (!Number.isInteger(v) || v < 0 || v >= positions.length) {
      fail(`${moduleFile}: face ${i} names vertex ${v} of ${positions.length}`);
    }
  }
  // Polygons as fans, as our loader would triangulate them.
  for (let k = 1; k + 1 < cell.length; ++k) lines.push(`f ${cell[0] + 1} ${cell[k] + 1} ${cell[k + 1] + 1}`);
});
// Written beside the target and renamed, so an interrupted run leaves no half-written model.
const temporary = `${outFile}.partial`;
fs.writeFileSync(temporary, lines.join('\n') + '\n');
fs.renameSync(temporary, outFile);
