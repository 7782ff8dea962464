// Web Worker of QMCLoader: decodes the files the page streams to it, off the
// page's thread, and posts each progressive level's mesh (spec 12) the moment
// its chunk is decoded, then the file's mesh once QEND is in (3.5).
//
// page -> worker: {type: 'open', id, limits} {type: 'chunk', id, bytes} {type: 'end', id}
// worker -> page: {type: 'ready'} (decoder loaded and warmed up)
//                 {type: 'level', id, mesh, ...} {type: 'done', id, mesh, ...} {type: 'error', id, ...}
import { FINEST, loadQMC } from './qmc.js';

// conformance/vectors/valid_loop_octahedron_sphere_2_levels.qmc (261 bytes):
// decoded once at start so that the browser compiles the container, polygon
// connectivity, position and Loop code before the first real file arrives
// (its first decode otherwise takes about 20 times as long).
const WARM_UP = 'iVFNQw0KGgpRSERSAgAAAAEDZtFRBExPT1ACAAAAAgDxubHKQ09OTg0AAAACBggABUehABpENI/AVQ19aFBPU04+AAAABg6rqhLAq6oSwKuqEsCrqhJAq6oSQKuqEkAeQDCEeQDCEeQDCE//gAAAAf/+3/9v////P/+QAAAAgABIAAB96SbZTEVWTBkAAAABAAwuZRUfFuItP//////////////////wdD4kzkxFVkxBAAAAAgAwGOiJu+TZSz+q3+q1W/1Wq3+q3+q1W/1W/1W/1Wq3+q3+q3+q3+q3+/1Wq3+q3+q3+q3+q3+/1W/1W/3+/3927wDfUUVORAAAAAB647xy';

async function warmedUp() {
  const qmc = await loadQMC();
  const stream = qmc.createStreamDecoder();
  stream.feed(Uint8Array.from(atob(WARM_UP), (c) => c.charCodeAt(0)));
  stream.finish();
  stream.mesh(0);
  stream.mesh(FINEST);
  stream.dispose();
  return qmc;
}

const ready = warmedUp();
ready.then(() => self.postMessage({ type: 'ready' }));
const files = new Map(); // id -> { stream, shownLevel, decodeMs }

function transferables(mesh) {
  return [mesh.positions.buffer, mesh.indices.buffer, mesh.faceSizes.buffer, mesh.corners.buffer,
          ...mesh.attributes.map((a) => a.values.buffer),
          ...(mesh.cornerAttributes ?? []).flatMap((a) => [a.values.buffer, a.cornerValues.buffer]),
          ...(mesh.faceLabels ?? []).map((l) => l.faceValues.buffer)];
}

function post(type, id, file, mesh) {
  const message = { type, id, mesh, levelCount: file.stream.levelCount, bytesFed: file.stream.bytesFed,
                    decodeMs: file.decodeMs };
  self.postMessage(message, mesh ? transferables(mesh) : []);
}

function timed(file, work) {
  const start = performance.now();
  try {
    return work();
  } finally {
    file.decodeMs += performance.now() - start;
  }
}

// Every level completed by the last chunk, in order.
function postNewLevels(id, file) {
  while (file.shownLevel < file.stream.completeLevel) {
    file.shownLevel += 1;
    post('level', id, file, timed(file, () => file.stream.mesh(file.shownLevel)));
  }
}

function handle(qmc, { type, id, limits, bytes }) {
  if (type === 'open') {
    files.set(id, { stream: qmc.createStreamDecoder({ limits }), shownLevel: -1, decodeMs: 0 });
    return;
  }
  const file = files.get(id);
  if (!file) return;
  if (type === 'chunk') {
    timed(file, () => file.stream.feed(new Uint8Array(bytes)));
    postNewLevels(id, file);
  } else if (type === 'end') {
    timed(file, () => file.stream.finish());
    post('done', id, file, timed(file, () => file.stream.mesh(FINEST)));
    file.stream.dispose();
    files.delete(id);
  } else if (type === 'cancel') {
    file.stream.dispose();
    files.delete(id);
  }
}

self.onmessage = async ({ data }) => {
  const qmc = await ready;
  try {
    handle(qmc, data);
  } catch (e) {
    const file = files.get(data.id);
    file?.stream.dispose();
    files.delete(data.id);
    self.postMessage({ type: 'error', id: data.id, identifier: e.identifier ?? 'error', message: e.message });
  }
};
