// Decode time in node: qmc (web/src/qmc.js) against npm draco3d and npm
// meshoptimizer on the same meshes, interleaved (each round decodes every
// mesh with every codec in turn), medians over the rounds. Inputs from
// web/bench/prepare.sh; meshoptimizer's buffers are encoded here from the
// same OBJ (positions quantized to 14 bits in uint16x4, reorderMesh, then
// encodeVertexBuffer / encodeIndexBuffer).
//   node web/bench/decode.mjs DIR [ROUNDS]
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

import draco3d from 'draco3d';
import { MeshoptDecoder, MeshoptEncoder } from 'meshoptimizer';

import { loadQMC } from '../src/qmc.js';

const [dir, roundsArgument] = process.argv.slice(2);
const rounds = Number(roundsArgument ?? 15);

function readObj(path) {
  const positions = [], indices = [];
  for (const line of readFileSync(path, 'utf8').split('\n')) {
    const fields = line.trim().split(/\s+/);
    if (fields[0] === 'v') positions.push(+fields[1], +fields[2], +fields[3]);
    if (fields[0] === 'f') {
      const corners = fields.slice(1).map((f) => parseInt(f, 10) - 1);
      for (let k = 1; k + 1 < corners.length; ++k) indices.push(corners[0], corners[k], corners[k + 1]);
    }
  }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

function meshoptEncode({ positions, indices }) {
  const vertexCount = positions.length / 3;
  const [remap, unique] = MeshoptEncoder.reorderMesh(indices.slice(), true, false);
  const order = indices.map((i) => remap[i]);
  let min = Infinity, max = -Infinity;
  for (const v of positions) [min, max] = [Math.min(min, v), Math.max(max, v)];
  const quantized = new Uint16Array(4 * unique);
  for (let v = 0; v < vertexCount; ++v) {
    if (remap[v] === 0xffffffff) continue;
    for (let axis = 0; axis < 3; ++axis) {
      quantized[4 * remap[v] + axis] = Math.round(((positions[3 * v + axis] - min) / (max - min)) * 16383);
    }
  }
  return {
    vertexCount: unique, indexCount: order.length,
    vertices: MeshoptEncoder.encodeVertexBuffer(new Uint8Array(quantized.buffer), unique, 8),
    indices: MeshoptEncoder.encodeIndexBuffer(new Uint8Array(order.buffer), order.length, 4),
  };
}

function dracoDecode(draco, bytes) {
  const decoder = new draco.Decoder();
  const mesh = new draco.Mesh();
  const status = decoder.DecodeArrayToMesh(bytes, bytes.length, mesh);
  if (!status.ok()) throw new Error(`draco: ${status.error_msg()}`);
  const attribute = decoder.GetAttributeByUniqueId(mesh, decoder.GetAttributeId(mesh, draco.POSITION));
  const valueCount = mesh.num_points() * 3;
  const positionPointer = draco._malloc(4 * valueCount);
  decoder.GetAttributeDataArrayForAllPoints(mesh, attribute, draco.DT_FLOAT32, 4 * valueCount, positionPointer);
  const positions = new Float32Array(draco.HEAPF32.buffer, positionPointer, valueCount).slice();
  const indexCount = mesh.num_faces() * 3;
  const indexPointer = draco._malloc(4 * indexCount);
  decoder.GetTrianglesUInt32Array(mesh, 4 * indexCount, indexPointer);
  const indices = new Uint32Array(draco.HEAPU32.buffer, indexPointer, indexCount).slice();
  draco._free(positionPointer);
  draco._free(indexPointer);
  draco.destroy(mesh);
  draco.destroy(decoder);
  return { positions, indices };
}

function meshoptDecode(encoded) {
  const vertices = new Uint8Array(8 * encoded.vertexCount);
  const indices = new Uint32Array(encoded.indexCount);
  MeshoptDecoder.decodeVertexBuffer(vertices, encoded.vertexCount, 8, encoded.vertices);
  MeshoptDecoder.decodeIndexBuffer(new Uint8Array(indices.buffer), encoded.indexCount, 4, encoded.indices);
  return { positions: vertices, indices };
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[sorted.length >> 1];
}

const qmc = await loadQMC();
const draco = await draco3d.createDecoderModule({});
await MeshoptEncoder.ready;
await MeshoptDecoder.ready;

const meshes = readdirSync(dir).filter((f) => f.endsWith('.drc')).map((f) => f.slice(0, -4)).sort();
const cases = meshes.map((name) => {
  const obj = readObj(join(dir, `${name}.obj`));
  const qmcBytes = new Uint8Array(readFileSync(join(dir, `${name}.qmc`)));
  const dracoBytes = new Int8Array(readFileSync(join(dir, `${name}.drc`)));
  const meshopt = meshoptEncode(obj);
  const decoders = {
    qmc: () => qmc.decode(qmcBytes),
    draco3d: () => dracoDecode(draco, dracoBytes),
    meshoptimizer: () => meshoptDecode(meshopt),
  };
  // The same triangles from each (draco and meshopt may renumber vertices).
  for (const [codec, decode] of Object.entries(decoders)) {
    const { indices } = decode();
    if (indices.length !== obj.indices.length) throw new Error(`${name}: ${codec} gave ${indices.length / 3} triangles`);
  }
  const bytes = { qmc: qmcBytes.length, draco3d: dracoBytes.length,
                  meshoptimizer: meshopt.vertices.length + meshopt.indices.length };
  return { name, vertices: obj.positions.length / 3, triangles: obj.indices.length / 3, decoders, bytes, times: {} };
});

for (let round = 0; round < rounds; ++round) {
  for (const c of cases) {
    for (const [codec, decode] of Object.entries(c.decoders)) {
      const start = process.hrtime.bigint();
      decode();
      (c.times[codec] ??= []).push(Number(process.hrtime.bigint() - start) / 1e6);
    }
  }
}

console.log(`node ${process.version}, ${rounds} interleaved rounds, median ms (bytes)`);
console.log('| mesh | V | T | qmc | draco3d | meshoptimizer | draco3d / qmc time |');
console.log('| --- | --- | --- | --- | --- | --- | --- |');
for (const c of cases) {
  const m = Object.fromEntries(Object.entries(c.times).map(([codec, t]) => [codec, median(t)]));
  const cell = (codec) => `${m[codec].toFixed(2)} (${c.bytes[codec]})`;
  console.log(`| ${c.name} | ${c.vertices} | ${c.triangles} | ${cell('qmc')} | ${cell('draco3d')} | ${cell('meshoptimizer')} | ${(m.draco3d / m.qmc).toFixed(2)}x |`);
}
