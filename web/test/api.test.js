// What the JS API promises beyond the vectors: typed arrays of the polygon
// structure and fan triangles, limits (spec 8.1), peek, levels of a
// progressive file (section 12).
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { FINEST, loadQMC, QMCError } from '../src/qmc.js';

const vector = (name) => readFileSync(new URL(`../../conformance/vectors/${name}`, import.meta.url));
const qmc = await loadQMC();

test('the cube of quads: 8 vertices, 6 quads, 12 fan triangles', () => {
  const mesh = qmc.decode(vector('valid_cube_8bit.qmc'));
  assert.equal(mesh.positions.length, 24);
  assert.ok(mesh.positions instanceof Float32Array && mesh.indices instanceof Uint32Array);
  assert.deepEqual([...mesh.faceSizes], [4, 4, 4, 4, 4, 4]);
  assert.equal(mesh.corners.length, 24);
  const [c0, c1, c2, c3] = mesh.corners.subarray(0, 4);
  assert.deepEqual([...mesh.indices.subarray(0, 6)], [c0, c1, c2, c0, c2, c3]);
});

test('a limit below the file rejects it as limit_exceeded naming the limit', () => {
  assert.equal(qmc.defaultLimits().maxOutputBytes, 256 * 2 ** 20);
  assert.throws(() => qmc.decode(vector('valid_cube_8bit.qmc'), { limits: { maxVertices: 7 } }),
    (e) => e instanceof QMCError && e.identifier === 'limit_exceeded' && /max_vertices/.test(e.message));
  assert.equal(qmc.decode(vector('valid_cube_8bit.qmc'), { limits: { maxVertices: 8, maxFaces: Infinity } }).vertexCount, 8);
  assert.throws(() => qmc.createStreamDecoder({ limits: { maxVertex: 1 } }), TypeError);
});

test('peek reads the counts before decoding; a prefix is truncated', () => {
  const cube = vector('valid_cube_8bit.qmc');
  assert.deepEqual([qmc.peek(cube).vertexCount, qmc.peek(cube).faceCount, qmc.peek(cube).levelCount], [8, 6, 0]);
  assert.throws(() => qmc.peek(cube.subarray(0, 12)), (e) => e.identifier === 'truncated');
});

test('a progressive file streams level by level, each 4 times the faces of the one before', () => {
  const bytes = vector('valid_loop_octahedron_sphere_5_levels.qmc');
  const stream = qmc.createStreamDecoder();
  const faces = [];
  for (let at = 0; at < bytes.length; ++at) {
    stream.feed(bytes.subarray(at, at + 1));
    if (stream.completeLevel === faces.length) faces.push(stream.mesh(stream.completeLevel).faceCount);
  }
  stream.finish();
  assert.equal(stream.levelCount, 5);
  assert.deepEqual(faces, [8, 32, 128, 512, 2048, 8192]);
  assert.equal(stream.mesh(FINEST).faceCount, 8192);
  assert.throws(() => stream.mesh(6), (e) => e.identifier === 'invalid_argument');
  stream.dispose();
});

test('a geometry image with normals and a curvature: attributes of kinds 3..6, one value per vertex', () => {
  const mesh = qmc.decode(vector('valid_gim_f32_attributes.qmc'));
  assert.deepEqual(mesh.attributes.map((a) => a.kind), [3, 4, 5, 6]);
  for (const { values } of mesh.attributes) assert.equal(values.length, mesh.vertexCount);
  // The vector generator made kinds 3..5 the position over 3 (tools/make_vectors_main.cc).
  for (let v = 0; v < mesh.vertexCount; ++v) {
    assert.ok(Math.abs(mesh.attributes[0].values[v] - mesh.positions[3 * v] / 3) < 1e-6);
  }
  assert.deepEqual(qmc.decode(vector('valid_cube_8bit.qmc')).attributes, []);
});

test('texture coordinates with a seam and per-vertex normals: cornerAttributes (spec 15)', () => {
  const mesh = qmc.decode(vector('valid_attr_quads_texcoord_normal.qmc'));
  assert.deepEqual(mesh.cornerAttributes.map((a) => [a.name, a.kind, a.components]), [['texcoord', 1, 2], ['normal', 2, 3]]);
  const [texcoord, normal] = mesh.cornerAttributes;
  assert.equal(texcoord.cornerValues.length, mesh.corners.length);
  assert.ok(texcoord.values.length / 2 > mesh.vertexCount); // the seam splits vertices
  // Normals are one per vertex: every corner refers to its vertex's value, of unit length.
  assert.deepEqual([...normal.cornerValues], [...mesh.corners]);
  for (let v = 0; v < mesh.vertexCount; ++v) {
    const [x, y, z] = normal.values.subarray(3 * v, 3 * v + 3);
    assert.ok(Math.abs(Math.hypot(x, y, z) - 1) < 0.01);
  }
  assert.deepEqual(qmc.decode(vector('valid_cube_8bit.qmc')).cornerAttributes, []);
});

test('face labels: a material per face with its library, a group (spec 16)', () => {
  const mesh = qmc.decode(vector('valid_flbl_material_group.qmc'));
  assert.deepEqual(mesh.faceLabels.map((l) => l.name), ['material', 'group']);
  const [material, group] = mesh.faceLabels;
  assert.deepEqual(material.values, ['red', 'green', 'blue']);
  assert.deepEqual(material.references, ['m.mtl']);
  assert.deepEqual(group.values, ['left', '']);
  assert.equal(material.faceValues.length, mesh.faceSizes.length);
  for (const v of material.faceValues) assert.ok(v <= 3);
  assert.ok(material.faceValues.some((v) => v === 3) && material.faceValues.some((v) => v < 3));
  assert.deepEqual(qmc.decode(vector('valid_cube_8bit.qmc')).faceLabels, []);
});

test('hostile files of under 130 bytes are refused by the default limits, not allocated (spec 8.1)', () => {
  const hostile = (name) => readFileSync(new URL(`../../fuzz/regressions/decode_file/${name}`, import.meta.url));
  for (const name of ['loop_base_claims_2p32_vertices', 'loop_base_claims_200M_vertices', 'gim_unmasked_33M_triangles']) {
    const bytes = hostile(name);
    assert.ok(bytes.length < 130, name);
    assert.throws(() => qmc.decode(bytes), (e) => e.identifier === 'limit_exceeded', name);
  }
  assert.ok(qmc.wasm.HEAPU8.length < 64 * 2 ** 20, `the wasm heap stayed small: ${qmc.wasm.HEAPU8.length} bytes`);
});
