// qmc decoder for browsers, workers and node 18+: the C API of
// include/qmc/qmc.h compiled to WebAssembly (web/CMakeLists.txt), wrapped so
// that nothing of emscripten shows.
//
//   import { loadQMC } from './src/qmc.js';
//   const qmc = await loadQMC();
//   const mesh = qmc.decode(bytes);              // whole file
//   const stream = qmc.createStreamDecoder();    // progressive (spec 3.5, 12)
//   stream.feed(chunk); if (stream.completeLevel >= 0) stream.mesh(stream.completeLevel);
//
// Meshes are plain objects of typed arrays the caller owns: positions
// (Float32Array, 3 per vertex), indices (Uint32Array, the polygons cut into
// fans for rendering), faceSizes and corners (the polygon structure),
// attributes (a geometry image's planes after X Y Z: normals, curvature ...)
// and cornerAttributes (spec 15: texture coordinates, normals, colours, each
// { name, kind, components, values: Float32Array, cornerValues: Uint32Array },
// corner k's value at values[components * cornerValues[k]]) and faceLabels
// (spec 16: OBJ objects, groups, materials; each { name, values, references:
// arrays of strings, faceValues: Uint32Array, values.length meaning none }).
// Rejections throw a QMCError whose `identifier` is spec section 9's.
import createQmcModule from '../dist/qmc_decoder.mjs';

const isNode = typeof process === 'object' && typeof process.versions?.node === 'string';

// spec 8.1: what one file may cost; Infinity switches a limit off.
const LIMIT_FIELDS = ['maxChunkLength', 'maxLevels', 'maxVertices', 'maxFaces', 'maxPixels', 'maxOutputBytes'];
const NO_LIMIT = 0xffffffffffffffffn;
const LIMITS_SIZE = 40; // qmc_limits: two uint32, four uint64
const MESH_SIZE = 32; // qmc_mesh on wasm32: four uint32, four pointers
const SUMMARY_SIZE = 88;
const ATTRIBUTE_SIZE = 12; // qmc_attribute on wasm32: kind, count, pointer
const CORNER_ATTRIBUTE_SIZE = 280; // qmc_corner_attribute on wasm32: name[256], four uint32, two pointers
const FACE_LABELS_SIZE = 272; // qmc_face_labels on wasm32: name[256], three uint32, a pointer
export const FINEST = -1;

export class QMCError extends Error {
  constructor(code, identifier, message) {
    super(`${identifier}: ${message}`);
    this.name = 'QMCError';
    this.code = code; // qmc_error, numbered as qmc.h
    this.identifier = identifier; // "bad_crc", ... (spec section 9)
  }
}

async function nodeWasmBinary() {
  const { readFile } = await import('node:fs/promises');
  return readFile(new URL('../dist/qmc_decoder.wasm', import.meta.url));
}

// Loads the WebAssembly once per call. options.wasmBinary (bytes) or
// options.locateFile override where the .wasm comes from.
export async function loadQMC(options = {}) {
  const moduleOptions = { ...options };
  if (isNode && !moduleOptions.wasmBinary) moduleOptions.wasmBinary = await nodeWasmBinary();
  const wasm = await createQmcModule(moduleOptions);
  return new QMC(wasm);
}

class QMC {
  constructor(wasm) {
    this.wasm = wasm;
    this.scratch = 0; // wasm buffer the input is copied into, grown as needed
    this.scratchSize = 0;
  }

  // The defaults of decoder.h: 256 MiB of output, 2^24 vertices, 8 levels ...
  defaultLimits() {
    const w = this.wasm;
    const p = w._malloc(LIMITS_SIZE);
    w._qmc_limits_default(p);
    const limits = readLimits(w, p);
    w._free(p);
    return limits;
  }

  // Spec 8.1: QHDR, LOOP and the CONN or GIMG header, before anything is allocated.
  peek(bytes) {
    const w = this.wasm;
    const input = this.copyIn(bytes);
    const summary = w._malloc(SUMMARY_SIZE);
    const message = w._malloc(256);
    try {
      const code = w._qmc_peek(input, bytes.length, summary, message, 256);
      if (code !== 0) throw new QMCError(code, w.UTF8ToString(w._qmc_error_name(code)), w.UTF8ToString(message));
      return readSummary(w, summary);
    } finally {
      w._free(summary);
      w._free(message);
    }
  }

  // A whole file: its mesh, or for a progressive file its finest level.
  decode(bytes, { limits } = {}) {
    const stream = this.createStreamDecoder({ limits });
    try {
      stream.feed(bytes);
      stream.finish();
      return stream.mesh(FINEST);
    } finally {
      stream.dispose();
    }
  }

  createStreamDecoder({ limits } = {}) {
    return new StreamDecoder(this, limits);
  }

  copyIn(bytes) {
    const w = this.wasm;
    if (bytes.length > this.scratchSize) {
      w._free(this.scratch);
      const size = Math.max(bytes.length, 2 * this.scratchSize, 65536);
      this.scratch = w._malloc(size);
      this.scratchSize = this.scratch ? size : 0;
      if (!this.scratch) throw new QMCError(14, 'limit_exceeded', `no memory for ${bytes.length} input bytes`);
    }
    w.HEAPU8.set(bytes, this.scratch);
    return this.scratch;
  }
}

// Feeds a file's bytes as they arrive. Call dispose() when done (the
// decoder's memory lives in the WebAssembly heap, not the JS one).
class StreamDecoder {
  constructor(qmc, limits) {
    this.qmc = qmc;
    const w = qmc.wasm;
    let p = 0;
    if (limits) {
      p = w._malloc(LIMITS_SIZE);
      w._qmc_limits_default(p);
      writeLimits(w, p, { ...readLimits(w, p), ...limits });
    }
    this.handle = w._qmc_decoder_create(p);
    if (p) w._free(p);
    if (!this.handle) throw new QMCError(14, 'limit_exceeded', 'no memory for a decoder');
    this.bytesFed = 0;
  }

  // Consumes the next bytes (Uint8Array); throws the file's rejection.
  feed(chunk) {
    const w = this.qmc.wasm;
    const input = chunk.length ? this.qmc.copyIn(chunk) : 0;
    this.bytesFed += chunk.length;
    this.check(w._qmc_decoder_feed(this.handle, input, chunk.length));
  }

  // The input has ended: a file that stopped before QEND is truncated.
  finish() {
    this.check(this.qmc.wasm._qmc_decoder_finish(this.handle));
  }

  get complete() { return this.qmc.wasm._qmc_decoder_complete(this.handle) === 1; }
  get hasMesh() { return this.qmc.wasm._qmc_decoder_has_mesh(this.handle) === 1; }
  // Section 12: LOOP's K (0: not progressive) and the finest level decoded so far (-1: none yet).
  get levelCount() { return this.qmc.wasm._qmc_decoder_level_count(this.handle); }
  get completeLevel() { return this.qmc.wasm._qmc_decoder_complete_level(this.handle); }

  // The mesh of a complete level, or with FINEST the file's mesh so far,
  // with a geometry image's attribute planes (spec 13.2): attributes is a
  // list of { kind, values: Float32Array, one per vertex }.
  mesh(level = FINEST) {
    const w = this.qmc.wasm;
    const out = w._malloc(MESH_SIZE);
    try {
      this.check(w._qmc_decoder_mesh(this.handle, level, out));
      const mesh = readMesh(w, out, level === FINEST ? this.completeLevel : level);
      mesh.attributes = level === FINEST ? this.attributes() : [];
      mesh.cornerAttributes = level === FINEST ? this.cornerAttributes() : [];
      mesh.faceLabels = level === FINEST ? this.faceLabels() : [];
      return mesh;
    } finally {
      w._qmc_mesh_free(out);
      w._free(out);
    }
  }

  attributes() {
    const w = this.qmc.wasm;
    const out = w._malloc(ATTRIBUTE_SIZE);
    try {
      const attributes = [];
      for (let i = 0; i < w._qmc_decoder_attribute_count(this.handle); ++i) {
        this.check(w._qmc_decoder_attribute(this.handle, i, out));
        const [kind, count, values] = w.HEAPU32.subarray(out >> 2, (out >> 2) + 3);
        attributes.push({ kind, values: new Float32Array(w.HEAPF32.buffer.slice(values, values + 4 * count)) });
        w._qmc_free(values);
      }
      return attributes;
    } finally {
      w._free(out);
    }
  }

  // Spec 15: the attributes of the corners of the file's mesh (aTTR).
  cornerAttributes() {
    const w = this.qmc.wasm;
    const out = w._malloc(CORNER_ATTRIBUTE_SIZE);
    try {
      const attributes = [];
      for (let i = 0; i < w._qmc_decoder_corner_attribute_count(this.handle); ++i) {
        this.check(w._qmc_decoder_corner_attribute(this.handle, i, out));
        const [kind, components, valueCount, cornerCount, values, cornerValues] =
          w.HEAPU32.subarray((out + 256) >> 2, ((out + 256) >> 2) + 6);
        attributes.push({
          name: w.UTF8ToString(out, 256),
          kind,
          components,
          values: new Float32Array(w.HEAPF32.buffer.slice(values, values + 4 * components * valueCount)),
          cornerValues: new Uint32Array(w.HEAPU32.buffer.slice(cornerValues, cornerValues + 4 * cornerCount)),
        });
        w._qmc_corner_attribute_free(out);
      }
      return attributes;
    } finally {
      w._free(out);
    }
  }

  // Spec 16: the labels of the faces of the file's mesh (fLBL).
  faceLabels() {
    const w = this.qmc.wasm;
    const out = w._malloc(FACE_LABELS_SIZE);
    const length = w._malloc(4);
    try {
      const labels = [];
      const text = new TextDecoder();
      const strings = (i, reference, count) => Array.from({ length: count }, (_, v) => {
        const at = w._qmc_decoder_face_label_string(this.handle, i, reference, v, length);
        return text.decode(w.HEAPU8.slice(at, at + w.HEAPU32[length >> 2]));
      });
      for (let i = 0; i < w._qmc_decoder_face_labels_count(this.handle); ++i) {
        this.check(w._qmc_decoder_face_labels(this.handle, i, out));
        const [valueCount, referenceCount, faceCount, faceValues] = w.HEAPU32.subarray((out + 256) >> 2, ((out + 256) >> 2) + 4);
        labels.push({
          name: w.UTF8ToString(out, 256),
          values: strings(i, 0, valueCount),
          references: strings(i, 1, referenceCount),
          faceValues: new Uint32Array(w.HEAPU32.buffer.slice(faceValues, faceValues + 4 * faceCount)),
        });
        w._qmc_free(faceValues);
      }
      return labels;
    } finally {
      w._free(length);
      w._free(out);
    }
  }

  // Spec 10.2, 12.9, 13.10: the bytes whose SHA-256 the conformance manifest lists.
  canonicalOutput() {
    const w = this.qmc.wasm;
    const out = w._malloc(8);
    try {
      this.check(w._qmc_decoder_canonical_output(this.handle, out, out + 4));
      const [bytes, size] = [w.HEAPU32[out >> 2], w.HEAPU32[(out >> 2) + 1]];
      const copy = w.HEAPU8.slice(bytes, bytes + size);
      w._qmc_free(bytes);
      return copy;
    } finally {
      w._free(out);
    }
  }

  dispose() {
    if (this.handle) this.qmc.wasm._qmc_decoder_destroy(this.handle);
    this.handle = 0;
  }

  check(code) {
    if (code === 0) return;
    const w = this.qmc.wasm;
    const message = this.handle ? w.UTF8ToString(w._qmc_decoder_message(this.handle)) : 'decoder disposed';
    throw new QMCError(code, w.UTF8ToString(w._qmc_error_name(code)), message);
  }
}

function readMesh(w, p, level) {
  const [vertexCount, faceCount, cornerCount, triangleCount, positions, faceSizes, corners, triangles] =
    w.HEAPU32.subarray(p >> 2, (p >> 2) + 8);
  return {
    level,
    vertexCount,
    faceCount,
    positions: new Float32Array(w.HEAPF32.buffer.slice(positions, positions + 12 * vertexCount)),
    indices: new Uint32Array(w.HEAPU32.buffer.slice(triangles, triangles + 12 * triangleCount)),
    faceSizes: new Uint32Array(w.HEAPU32.buffer.slice(faceSizes, faceSizes + 4 * faceCount)),
    corners: new Uint32Array(w.HEAPU32.buffer.slice(corners, corners + 4 * cornerCount)),
  };
}

function readU64(w, p) {
  return Number(BigInt(w.HEAPU32[p >> 2]) | (BigInt(w.HEAPU32[(p >> 2) + 1]) << 32n));
}

function writeU64(w, p, value) {
  const v = value === Infinity ? NO_LIMIT : BigInt(value);
  w.HEAPU32[p >> 2] = Number(v & 0xffffffffn);
  w.HEAPU32[(p >> 2) + 1] = Number(v >> 32n);
}

function readLimits(w, p) {
  const limits = { maxChunkLength: w.HEAPU32[p >> 2], maxLevels: w.HEAPU32[(p >> 2) + 1] };
  LIMIT_FIELDS.slice(2).forEach((name, i) => {
    const value = readU64(w, p + 8 + 8 * i);
    limits[name] = value >= Number.MAX_SAFE_INTEGER * 2 ? Infinity : value;
  });
  return limits;
}

function writeLimits(w, p, limits) {
  for (const name of Object.keys(limits)) {
    if (!LIMIT_FIELDS.includes(name)) throw new TypeError(`unknown limit ${name}; known: ${LIMIT_FIELDS.join(', ')}`);
  }
  w.HEAPU32[p >> 2] = Math.min(limits.maxChunkLength, 0x7fffffff);
  w.HEAPU32[(p >> 2) + 1] = Math.min(limits.maxLevels, 0xffffffff);
  LIMIT_FIELDS.slice(2).forEach((name, i) => writeU64(w, p + 8 + 8 * i, limits[name]));
}

// qmc_summary: uint32 x4, uint64 x2 (at 16), uint32 (32), uint64 (40),
// uint32 x4 (48), uint64 (64); 72 bytes, 88 allocated.
function readSummary(w, p) {
  const u32 = (offset) => w.HEAPU32[(p + offset) >> 2];
  return {
    versionMajor: u32(0),
    versionMinor: u32(4),
    hasConnectivity: u32(8) === 1,
    method: u32(12),
    vertexCount: readU64(w, p + 16),
    faceCount: readU64(w, p + 24),
    levelCount: u32(32),
    finestFaceCount: readU64(w, p + 40),
    hasGeometryImage: u32(48) === 1,
    gimWidth: u32(52),
    gimHeight: u32(56),
    gimPlaneCount: u32(60),
    minOutputBytes: readU64(w, p + 64),
  };
}
