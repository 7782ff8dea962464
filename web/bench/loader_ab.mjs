// Two versions of the three.js loader's geometry (geometryFromMesh of
// src/QMCLoader.js) timed in one process, in turns: each round builds every
// file's geometry with A and with B (which first alternates), from a fresh
// decode each time; medians over the rounds, and B's over A's.
//   node web/bench/loader_ab.mjs A/QMCLoader.js B/QMCLoader.js ROUNDS FILE.qmc...
// An older version comes from a worktree of its commit with this package's
// node_modules and dist/ beside its src/ (so that its imports resolve).
import { readFileSync } from 'node:fs';
import { basename, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

import { loadQMC } from '../src/qmc.js';

const [pathA, pathB, roundsArgument, ...files] = process.argv.slice(2);
const load = async (path) => (await import(pathToFileURL(resolve(path)).href)).geometryFromMesh;
const versions = [['A', await load(pathA)], ['B', await load(pathB)]];
const qmc = await loadQMC();
const bytesOf = new Map(files.map((f) => [f, readFileSync(f)]));
const times = new Map(files.map((f) => [f, { A: [], B: [] }]));
for (let round = 0; round < Number(roundsArgument); ++round) {
  for (const file of files) {
    for (const [name, geometryFromMesh] of round % 2 ? versions : [...versions].reverse()) {
      const mesh = qmc.decode(bytesOf.get(file));
      const start = performance.now();
      geometryFromMesh(mesh);
      times.get(file)[name].push(performance.now() - start);
    }
  }
}
const median = (values) => [...values].sort((a, b) => a - b)[values.length >> 1];
console.log('| file | A ms | B ms | B / A |');
console.log('| --- | ---: | ---: | ---: |');
for (const [file, { A, B }] of times) {
  console.log(`| ${basename(file)} | ${median(A).toFixed(2)} | ${median(B).toFixed(2)} | ${(median(B) / median(A)).toFixed(3)} |`);
}
