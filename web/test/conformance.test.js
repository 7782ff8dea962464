// The JS package against every conformance vector (spec 10): each decoded
// whole and streamed in 1-byte, random and 4 KB pieces (3.5). A valid vector
// gives the manifest's SHA-256 of its canonical output (10.2), an invalid one
// a QMCError with the manifest's identifier (section 9).
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { loadQMC, QMCError } from '../src/qmc.js';

const conformance = new URL('../../conformance/', import.meta.url);
const vectors = readFileSync(new URL('MANIFEST', conformance), 'utf8')
  .split('\n')
  .filter((line) => line.trim() && !line.startsWith('#'))
  .map((line) => {
    const [kind, path, expected] = line.split(/\s+/);
    return { kind, path, expected, bytes: readFileSync(new URL(path, conformance)) };
  });

// xorshift32: the same random piece sizes on every run.
function* randomPieces(size, seed) {
  let state = seed >>> 0 || 1;
  for (let at = 0; at < size; ) {
    state ^= state << 13; state >>>= 0;
    state ^= state >>> 17;
    state ^= state << 5; state >>>= 0;
    const n = Math.min(1 + (state % 700), size - at);
    yield [at, at + n];
    at += n;
  }
}

function* fixedPieces(size, n) {
  for (let at = 0; at < size; at += n) yield [at, Math.min(at + n, size)];
}

const ways = {
  whole: (size) => [[0, size]],
  '1-byte pieces': (size) => fixedPieces(size, 1),
  'random pieces': (size) => randomPieces(size, 0x9e3779b9 ^ size),
  '4 KB pieces': (size) => fixedPieces(size, 4096),
};

// Decodes in the given pieces; returns the SHA-256 of the canonical output,
// checking on the way that complete levels only grow and each has a mesh.
function streamedDigest(qmc, bytes, pieces) {
  const stream = qmc.createStreamDecoder();
  try {
    let shownLevel = -1;
    for (const [from, to] of pieces) {
      stream.feed(bytes.subarray(from, to));
      if (stream.completeLevel !== shownLevel) {
        assert.ok(stream.completeLevel > shownLevel, 'complete level never goes back');
        shownLevel = stream.completeLevel;
        const mesh = stream.mesh(shownLevel);
        assert.equal(mesh.indices.length, 3 * mesh.faceCount, 'a level is triangles');
      }
    }
    stream.finish();
    return createHash('sha256').update(stream.canonicalOutput()).digest('hex');
  } finally {
    stream.dispose();
  }
}

const qmc = await loadQMC();

for (const [way, pieces] of Object.entries(ways)) {
  test(`every conformance vector, ${way}`, () => {
    assert.ok(vectors.length > 200, 'the manifest lists the vectors');
    for (const { kind, path, expected, bytes } of vectors) {
      if (kind === 'valid') {
        assert.equal(streamedDigest(qmc, bytes, pieces(bytes.length)), expected, path);
      } else {
        assert.throws(() => streamedDigest(qmc, bytes, pieces(bytes.length)),
          (e) => e instanceof QMCError && e.identifier === expected && e.message.length > expected.length + 2, path);
      }
    }
  });
}
