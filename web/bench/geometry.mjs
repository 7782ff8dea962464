// What QMCLoader's geometry costs a textured mesh: vertices and GPU bytes
// of geometryFromMesh against one vertex per triangle corner (a non-indexed
// geometry), and the median time to build it, in node.
//   node web/bench/geometry.mjs ROUNDS FILE.qmc...
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';

import { geometryFromMesh } from '../src/QMCLoader.js';
import { loadQMC } from '../src/qmc.js';

const [rounds, ...files] = process.argv.slice(2);
const qmc = await loadQMC();
const median = (values) => [...values].sort((a, b) => a - b)[values.length >> 1];
const bytesOf = (geometry) => Object.values(geometry.attributes).reduce((sum, a) => sum + a.array.byteLength, 0) +
  (geometry.index ? geometry.index.array.byteLength : 0);

console.log('| file | positions | corner attributes (kinds) | vertices | one per triangle corner | bytes (attributes + index) | bytes, one per corner | build ms |');
console.log('| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: |');
for (const file of files) {
  const mesh = qmc.decode(readFileSync(file));
  const times = [];
  let geometry;
  for (let r = 0; r < Number(rounds); ++r) {
    const start = performance.now();
    geometry = geometryFromMesh(mesh);
    times.push(performance.now() - start);
  }
  const corners = mesh.indices.length;
  const perCorner = Object.values(geometry.attributes).reduce((sum, a) => sum + 4 * a.itemSize * corners, 0);
  console.log(`| ${basename(file)} | ${mesh.vertexCount} | ${mesh.cornerAttributes.map((a) => a.kind).join(', ') || '-'} | ` +
              `${geometry.getAttribute('position').count} | ${corners} | ${bytesOf(geometry)} | ${perCorner} | ${median(times).toFixed(2)} |`);
}
