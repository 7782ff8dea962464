import { readFileSync } from 'node:fs';
import { loadQMC } from '../src/qmc.js';
const qmc = await loadQMC();
const bytes = readFileSync(process.argv[2]);
const w = qmc.wasm;
const t = { feed: [], cmesh: [], read: [], total: [] };
for (let r = 0; r < 25; ++r) {
  const t0 = performance.now();
  const s = qmc.createStreamDecoder();
  s.feed(bytes); s.finish();
  const t1 = performance.now();
  const out = w._malloc(32);
  w._qmc_decoder_mesh(s.handle, -1, out);
  const t2 = performance.now();
  const [vc, fc, cc, tc, pos, fs, co, tri] = w.HEAPU32.subarray(out >> 2, (out >> 2) + 8);
  const m = [new Float32Array(w.HEAPF32.buffer.slice(pos, pos + 12 * vc)), new Uint32Array(w.HEAPU32.buffer.slice(tri, tri + 12 * tc)),
    new Uint32Array(w.HEAPU32.buffer.slice(fs, fs + 4 * fc)), new Uint32Array(w.HEAPU32.buffer.slice(co, co + 4 * cc))];
  const t3 = performance.now();
  w._qmc_mesh_free(out); w._free(out); s.dispose();
  t.feed.push(t1 - t0); t.cmesh.push(t2 - t1); t.read.push(t3 - t2); t.total.push(performance.now() - t0);
}
const med = (a) => a.sort((x, y) => x - y)[a.length >> 1].toFixed(2);
console.log(Object.entries(t).map(([k, v]) => `${k} ${med(v)}`).join('  '));
