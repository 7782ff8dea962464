// The geometry QMCLoader gives (geometryFromMesh): corner attributes of spec
// 15 on an indexed geometry, split only where a seam gives a position
// several values, and smooth normals where the file has none.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { BufferAttribute, BufferGeometry } from 'three';

import { geometryFromMesh } from '../src/QMCLoader.js';
import { loadQMC } from '../src/qmc.js';

const qmc = await loadQMC();
const decode = (name) => qmc.decode(readFileSync(new URL(`../../conformance/vectors/${name}`, import.meta.url)));
const CHANNELS = { uv: 1, normal: 2, color: 3 };

// The mesh corner behind each entry of the index: polygons cut into fans
// from their first corner, as mesh.indices are.
function fanCorners(mesh) {
  const corners = [];
  for (let f = 0, k0 = 0; f < mesh.faceSizes.length; k0 += mesh.faceSizes[f++]) {
    for (let i = 1; i + 1 < mesh.faceSizes[f]; ++i) corners.push(k0, k0 + i, k0 + i + 1);
  }
  return corners;
}

// Every corner of every triangle has the decoded position and values, and
// the geometry has one vertex per distinct (position, values) of the corners.
function assertFaithful(mesh, geometry) {
  const index = geometry.getIndex().array;
  const corners = fanCorners(mesh);
  assert.equal(index.length, corners.length);
  const keys = new Set();
  const channels = Object.entries(CHANNELS)
    .map(([name, kind]) => [geometry.getAttribute(name), mesh.cornerAttributes.find((a) => a.kind === kind)])
    .filter(([, attribute]) => attribute);
  corners.forEach((k, j) => {
    const v = index[j], p = mesh.corners[k];
    const position = geometry.getAttribute('position');
    assert.deepEqual([position.getX(v), position.getY(v), position.getZ(v)], [...mesh.positions.subarray(3 * p, 3 * p + 3)]);
    for (const [out, { values, components, cornerValues }] of channels) {
      const at = components * cornerValues[k];
      for (let c = 0; c < out.itemSize; ++c) assert.equal(out.array[out.itemSize * v + c], values[at + c]);
    }
    keys.add([p, ...channels.map(([, a]) => a.cornerValues[k])].join(' '));
  });
  assert.equal(geometry.getAttribute('position').count, keys.size);
}

test('a texture seam splits a position; corners that agree share a vertex', () => {
  const mesh = decode('valid_attr_mapping3_texcoords.qmc');
  const geometry = geometryFromMesh(mesh);
  assertFaithful(mesh, geometry);
  // 160 positions, 176 (position, texture coordinate) pairs, 960 corners.
  assert.equal(geometry.getAttribute('position').count, 176);
  assert.equal(geometry.getAttribute('uv').itemSize, 2);
});

test('quads are cut into fans as mesh.indices are', () => {
  const mesh = decode('valid_attr_coding7_quads.qmc');
  const geometry = geometryFromMesh(mesh);
  assertFaithful(mesh, geometry);
  const index = geometry.getIndex().array, position = geometry.getAttribute('position').array;
  // The triangles are mesh.indices's, vertex for vertex.
  for (let j = 0; j < index.length; ++j) {
    const p = mesh.indices[j];
    assert.deepEqual([...position.subarray(3 * index[j], 3 * index[j] + 3)], [...mesh.positions.subarray(3 * p, 3 * p + 3)]);
  }
});

test('normals and colours of the file are the geometry\'s, flat normals split every corner', () => {
  for (const name of ['valid_attr_coding8_normals.qmc', 'valid_attr_mapping3_flat_normals.qmc',
                      'valid_attr_coding9_colours.qmc']) {
    const mesh = decode(name);
    assertFaithful(mesh, geometryFromMesh(mesh));
  }
  const flat = decode('valid_attr_mapping3_flat_normals.qmc');
  assert.equal(geometryFromMesh(flat).getAttribute('position').count, flat.corners.length);
});

test('without normals in the file, a position\'s split vertices share the smooth normal of all its faces', () => {
  const mesh = decode('valid_attr_mapping3_texcoords.qmc');
  const geometry = geometryFromMesh(mesh);
  // The normals three computes for the mesh indexed by positions alone.
  const plain = new BufferGeometry();
  plain.setAttribute('position', new BufferAttribute(mesh.positions, 3));
  plain.setIndex(new BufferAttribute(mesh.indices, 1));
  plain.computeVertexNormals();
  const expected = plain.getAttribute('normal').array, normal = geometry.getAttribute('normal').array;
  const index = geometry.getIndex().array;
  fanCorners(mesh).forEach((k, j) => {
    const p = mesh.corners[k];
    for (let axis = 0; axis < 3; ++axis) {
      assert.ok(Math.abs(normal[3 * index[j] + axis] - expected[3 * p + axis]) < 1e-5, `corner ${k} axis ${axis}`);
    }
  });
});

test('a mesh without corner attributes keeps the decoder\'s positions and indices', () => {
  const mesh = decode('valid_cube_8bit.qmc');
  const geometry = geometryFromMesh(mesh, { level: 0 });
  assert.equal(geometry.getAttribute('position').array, mesh.positions);
  assert.equal(geometry.getIndex().array, mesh.indices);
  assert.equal(geometry.userData.level, 0);
});

// A fan of `spokes` triangles around position 0 whose centre corners take
// `groups` texture coordinates in turn, each rim position one of its own.
function fanMesh(spokes, groups) {
  const positions = [0, 0, 0.5], corners = [], cornerValues = [], values = [];
  for (let i = 0; i < spokes; ++i) positions.push(Math.cos(2 * Math.PI * i / spokes), Math.sin(2 * Math.PI * i / spokes), 0);
  for (let g = 0; g < groups; ++g) values.push(g / groups, 0);
  for (let i = 0; i < spokes; ++i) values.push(i / spokes, 1);
  for (let i = 0; i < spokes; ++i) {
    const next = (i + 1) % spokes;
    corners.push(0, 1 + i, 1 + next);
    cornerValues.push(i % groups, groups + i, groups + next);
  }
  return {
    level: 0, vertexCount: spokes + 1, faceCount: spokes, positions: new Float32Array(positions),
    corners: new Uint32Array(corners), indices: new Uint32Array(corners), faceSizes: new Uint32Array(spokes).fill(3),
    attributes: [], faceLabels: [],
    cornerAttributes: [{ name: 'texcoord', kind: 1, components: 2, values: new Float32Array(values),
                         cornerValues: new Uint32Array(cornerValues) }],
  };
}

test('a position of many values splits into the groups of its values, numbered by their first corners', () => {
  // 3,000 corners and 100 values at the centre: beyond the 32 vertices a corner is compared with, the corners
  // are set aside and sorted by their values.
  for (const [spokes, groups] of [[3000, 100], [3000, 7], [20, 3]]) {
    const mesh = fanMesh(spokes, groups);
    const geometry = geometryFromMesh(mesh);
    assertFaithful(mesh, geometry);
    assert.equal(geometry.getAttribute('position').count, spokes + groups);
    // The centre's vertices come first in each of the first `groups` triangles.
    const index = geometry.getIndex().array;
    for (let g = 0; g < groups; ++g) assert.equal(index[3 * g], g === 0 ? 0 : 2 + 2 * (g - 1) + 1, `group ${g}`);
  }
});

test('200,000 values at one position split in linearithmic time', () => {
  // Comparing each corner with the vertices before it took 94 s on the development machine (loaded);
  // sorting them, under half a second. A generous bound, as the encoder's complexity tests have
  // (tests/encoder_test.cc).
  const spokes = 200000;
  const mesh = fanMesh(spokes, spokes);
  const start = performance.now();
  const geometry = geometryFromMesh(mesh);
  const seconds = (performance.now() - start) / 1000;
  assert.equal(geometry.getAttribute('position').count, 2 * spokes);
  assert.ok(seconds < 10, `${seconds.toFixed(1)} s`);
});
