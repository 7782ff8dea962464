// three.js loader for .qmc files, in the shape of three's DRACOLoader:
//
//   const loader = new QMCLoader();
//   loader.load('model.qmc', (geometry) => scene.add(new Mesh(geometry, material)),
//               (event) => { if (event.geometry) show(event.geometry); },  // each progressive level
//               (error) => console.error(error));
//   const geometry = await loader.loadAsync('model.qmc');
//   loader.parse(arrayBuffer, onLoad, onError);
//   loader.preload();  // optional: start the worker before the first load
//   loader.dispose();
//
// Decoding runs in a Web Worker (qmc_worker.js). The HTTP body is read as a
// stream and handed to the worker chunk by chunk, so a progressive file
// (spec 12) calls onProgress with each level's BufferGeometry as soon as its
// chunk has arrived; onLoad gets the finest. Geometry userData carries level,
// levelCount, vertexCount, faceCount, the polygon structure (faceSizes,
// corners), a geometry image's attributes (its normals also become the
// 'normal' attribute), the corner attributes of spec 15, the face labels of
// spec 16 (a "material" label also makes the geometry's groups), bytesReceived
// and decodeMs. A file with texture coordinates, normals or colours per corner
// (spec 15) gives 'uv', 'normal' and 'color' on an indexed geometry whose
// vertices are split where a seam gives a position several values.
// geometryFromMesh builds the same geometry from a mesh that web/src/qmc.js
// decoded, for an application that runs the decoder itself.
import { BufferAttribute, BufferGeometry, Loader } from 'three';

export class QMCLoader extends Loader {
  constructor(manager) {
    super(manager);
    this.limits = undefined; // spec 8.1, as qmc.js's limits; undefined: the defaults
    this.worker = null;
    this.nextId = 1;
    this.pending = new Map(); // id -> { onLevel, resolve, reject }
    // Resolves once the worker's decoder is loaded and warmed up (preload starts it).
    this.ready = new Promise((resolve) => { this.onReady = resolve; });
  }

  // Starts the worker and its WebAssembly now rather than at the first load,
  // as DRACOLoader.preload does: the first mesh then shows sooner.
  preload() {
    this.workerFor();
    return this;
  }

  // What one file may cost (qmc.js: maxVertices, maxFaces, maxOutputBytes ...).
  setLimits(limits) {
    this.limits = limits;
    return this;
  }

  load(url, onLoad, onProgress, onError) {
    this.manager.itemStart(url);
    this.stream(this.resolveURL(url), onProgress)
      .then((geometry) => onLoad?.(geometry))
      .catch((error) => {
        if (onError) onError(error);
        else console.error(error);
        this.manager.itemError(url);
      })
      .finally(() => this.manager.itemEnd(url));
  }

  // The finest level's geometry of a complete file held in memory; like
  // load, onProgress (optional) gets each level's geometry of a progressive file.
  parse(buffer, onLoad, onError, onProgress) {
    const id = this.open();
    const bytes = buffer instanceof ArrayBuffer ? buffer.slice(0) : buffer.slice().buffer;
    const total = bytes.byteLength;
    this.finished(id, (geometry) => onProgress?.({ loaded: total, total, lengthComputable: true, geometry }))
      .then(onLoad, onError);
    this.workerFor().postMessage({ type: 'chunk', id, bytes }, [bytes]);
    this.workerFor().postMessage({ type: 'end', id });
  }

  dispose() {
    this.worker?.terminate();
    this.worker = null;
    for (const { reject } of this.pending.values()) reject(new Error('QMCLoader disposed'));
    this.pending.clear();
    return this;
  }

  resolveURL(url) {
    return this.path ? this.path + url : url;
  }

  async stream(url, onProgress) {
    const response = await fetch(url, { headers: this.requestHeader, credentials: this.withCredentials ? 'include' : 'same-origin' });
    if (!response.ok) throw new Error(`QMCLoader: ${url}: HTTP ${response.status}`);
    const total = Number(response.headers.get('Content-Length')) || 0;
    const id = this.open();
    let loaded = 0;
    const done = this.finished(id, (geometry) => onProgress?.({ loaded, total, lengthComputable: total > 0, geometry }));
    const reader = response.body.getReader();
    for (;;) {
      const { value, done: ended } = await reader.read();
      if (ended || !this.pending.has(id)) break;
      loaded += value.byteLength;
      const bytes = value.buffer.slice(value.byteOffset, value.byteOffset + value.byteLength);
      this.workerFor().postMessage({ type: 'chunk', id, bytes }, [bytes]);
      onProgress?.({ loaded, total, lengthComputable: total > 0 });
    }
    if (this.pending.has(id)) this.workerFor().postMessage({ type: 'end', id });
    else reader.cancel();
    return done;
  }

  open() {
    const id = this.nextId++;
    this.workerFor().postMessage({ type: 'open', id, limits: this.limits });
    return id;
  }

  finished(id, onLevel) {
    return new Promise((resolve, reject) => this.pending.set(id, { onLevel, resolve, reject }));
  }

  workerFor() {
    if (!this.worker) {
      this.worker = new Worker(new URL('./qmc_worker.js', import.meta.url), { type: 'module' });
      this.worker.onmessage = ({ data }) => this.receive(data);
    }
    return this.worker;
  }

  receive({ type, id, mesh, levelCount, bytesFed, decodeMs, identifier, message }) {
    if (type === 'ready') this.onReady();
    const pending = this.pending.get(id);
    if (!pending) return;
    if (type === 'error') {
      this.pending.delete(id);
      const error = new Error(`QMCLoader: ${identifier}: ${message}`);
      error.identifier = identifier; // spec section 9
      pending.reject(error);
      return;
    }
    const geometry = toGeometry(mesh, { levelCount, bytesReceived: bytesFed, decodeMs });
    if (type === 'level') {
      pending.onLevel?.(geometry);
    } else {
      this.pending.delete(id);
      pending.resolve(geometry);
    }
  }
}

// The BufferGeometry of a mesh of web/src/qmc.js (decode, or a stream
// decoder's mesh(level)), as the loader gives it, with `info` in userData.
export function geometryFromMesh(mesh, info = {}) {
  return toGeometry(mesh, info);
}

function toGeometry(mesh, info) {
  const geometry = cornerGeometry(mesh) ?? indexedGeometry(mesh);
  addMaterialGroups(mesh, geometry);
  geometry.userData = { level: mesh.level, vertexCount: mesh.vertexCount, faceCount: mesh.faceCount,
                        faceSizes: mesh.faceSizes, corners: mesh.corners, attributes: mesh.attributes,
                        cornerAttributes: mesh.cornerAttributes, faceLabels: mesh.faceLabels, ...info };
  return geometry;
}

// Spec 16: faces labelled "material" become the geometry's groups, one per run
// of faces with one material, materialIndex the label's index (values.length:
// none), over the fan triangles both geometries draw in face order.
function addMaterialGroups(mesh, geometry) {
  const material = (mesh.faceLabels ?? []).find((l) => l.name === 'material');
  if (!material) return;
  let start = 0;
  for (let f = 0; f < mesh.faceSizes.length; ++f) {
    const count = 3 * (mesh.faceSizes[f] - 2);
    const last = geometry.groups[geometry.groups.length - 1];
    if (last && last.materialIndex === material.faceValues[f]) last.count += count;
    else geometry.addGroup(start, count, material.faceValues[f]);
    start += count;
  }
}

function indexedGeometry(mesh) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(mesh.positions, 3));
  geometry.setIndex(new BufferAttribute(mesh.indices, 1));
  const normal = normalsOf(mesh);
  if (normal) geometry.setAttribute('normal', new BufferAttribute(normal, 3));
  else geometry.computeVertexNormals();
  return geometry;
}

// Spec 15: texture coordinates (kind 1), normals (kind 2) and colours (kind 3)
// per corner, on the polygons cut into fans from their first corner as
// mesh.indices are. Corners that share a position and every value share a
// vertex, so the geometry is indexed and split only where a seam gives a
// position several values (as a texture atlas's borders do). Without
// normals in the file, each position gets the normal of all its faces, so a
// texture seam does not show as a crease in the shading.
function cornerGeometry(mesh) {
  const channel = (name, kind, accepts, size) => {
    const attribute = (mesh.cornerAttributes ?? []).find((a) => a.kind === kind && accepts(a.components));
    return attribute && { name, attribute, size: size ?? attribute.components };
  };
  const channels = [channel('uv', 1, (c) => c >= 2, 2), channel('normal', 2, (c) => c === 3),
                    channel('color', 3, (c) => c === 3 || c === 4)].filter(Boolean);
  if (!channels.length) return null;
  const { vertexOf, cornerOf, count } = splitVertices(mesh, channels.map((c) => c.attribute.cornerValues));
  // Per vertex, `size` numbers from values[offsetOf(its corner)].
  const gather = (values, offsetOf, size) => {
    const out = new Float32Array(size * count);
    for (let r = 0; r < count; ++r) {
      const at = offsetOf(cornerOf[r]);
      for (let c = 0; c < size; ++c) out[size * r + c] = values[at + c];
    }
    return new BufferAttribute(out, size);
  };
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', gather(mesh.positions, (k) => 3 * mesh.corners[k], 3));
  for (const { name, attribute, size } of channels) {
    const { values, components, cornerValues } = attribute;
    geometry.setAttribute(name, gather(values, (k) => components * cornerValues[k], size));
  }
  if (!geometry.getAttribute('normal')) {
    // The smooth normals of the mesh indexed by positions alone, the same for every split vertex of one.
    const normals = indexedGeometry(mesh).getAttribute('normal').array;
    geometry.setAttribute('normal', gather(normals, (k) => 3 * mesh.corners[k], 3));
  }
  const index = new Uint32Array(mesh.indices.length);
  for (let f = 0, k0 = 0, j = 0; f < mesh.faceSizes.length; k0 += mesh.faceSizes[f++]) {
    for (let i = 1; i + 1 < mesh.faceSizes[f]; ++i) {
      index[j++] = vertexOf[k0];
      index[j++] = vertexOf[k0 + i];
      index[j++] = vertexOf[k0 + i + 1];
    }
  }
  geometry.setIndex(new BufferAttribute(index, 1));
  return geometry;
}

// A position has at most this many vertices found by comparing its corners
// with them; a corner of another value beyond them is set aside.
const kComparedVertices = 32;

// One vertex per distinct (position, value index of each channel) among the
// corners, numbered in the order of their first corners: vertexOf[corner],
// cornerOf[vertex] (its first corner) and count. The vertices of a position
// are chained from firstOf[position] through nextOf, so a corner is compared
// only with those, at most kComparedVertices; the corners whose values none
// of them has are set aside and sorted (splitSetAside), where comparing
// with every vertex found before would take a fan of a million corners of
// distinct values 5 10^11 steps.
function splitVertices(mesh, cornerValues) {
  const cornerCount = mesh.corners.length;
  const vertexOf = new Uint32Array(cornerCount);
  const cornerOf = new Uint32Array(cornerCount);
  const nextOf = new Int32Array(cornerCount);
  const firstOf = new Int32Array(mesh.vertexCount).fill(-1);
  const chained = new Uint8Array(mesh.vertexCount);  // per position, its vertices so far
  const setAside = [];
  // One to three channels, compared without a loop over them per corner.
  const [first, second, third] = cornerValues;
  const same = (k, other) => first[k] === first[other] && (!second || second[k] === second[other]) &&
    (!third || third[k] === third[other]);
  let count = 0;
  for (let k = 0; k < cornerCount; ++k) {
    const position = mesh.corners[k];
    let r = firstOf[position];
    while (r >= 0 && !same(k, cornerOf[r])) r = nextOf[r];
    if (r < 0) {
      if (chained[position] === kComparedVertices) {
        setAside.push(k);
        continue;
      }
      r = count++;
      cornerOf[r] = k;
      nextOf[r] = firstOf[position];
      firstOf[position] = r;
      chained[position] += 1;
    }
    vertexOf[k] = r;
  }
  return setAside.length ? splitSetAside(mesh, cornerValues, vertexOf, cornerOf, setAside) : { vertexOf, cornerOf, count };
}

// splitVertices's result where corners were set aside: those corners sorted
// by position, values and corner, so that each run of equal position and
// values is one vertex led by its first corner (n log n); then every vertex
// numbered again in the order of its first corner.
function splitSetAside(mesh, [first, second, third], vertexOf, cornerOf, setAside) {
  const cornerCount = mesh.corners.length;
  const leader = new Uint32Array(cornerCount);  // the first corner of each corner's vertex
  for (let k = 0; k < cornerCount; ++k) leader[k] = cornerOf[vertexOf[k]];
  const key = (a, b) => mesh.corners[a] - mesh.corners[b] || first[a] - first[b] ||
    (second ? second[a] - second[b] : 0) || (third ? third[a] - third[b] : 0);
  const sorted = setAside.sort((a, b) => key(a, b) || a - b);
  sorted.forEach((k, i) => { leader[k] = i > 0 && key(sorted[i - 1], k) === 0 ? leader[sorted[i - 1]] : k; });
  let count = 0;
  for (let k = 0; k < cornerCount; ++k) {
    if (leader[k] === k) {
      cornerOf[count] = k;
      vertexOf[k] = count++;
    } else {
      vertexOf[k] = vertexOf[leader[k]];  // leader[k] < k: numbered already
    }
  }
  return { vertexOf, cornerOf, count };
}

// A geometry image's normal planes (spec 13.2 kinds 3, 4, 5), interleaved.
function normalsOf(mesh) {
  const planes = [3, 4, 5].map((kind) => mesh.attributes.find((a) => a.kind === kind));
  if (planes.some((p) => !p)) return null;
  const normal = new Float32Array(3 * mesh.vertexCount);
  for (let v = 0; v < mesh.vertexCount; ++v) {
    for (let axis = 0; axis < 3; ++axis) normal[3 * v + axis] = planes[axis].values[v];
  }
  return normal;
}
