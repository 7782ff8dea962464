// The viewer in headless Chromium (Debian's, driven by puppeteer-core): a
// progressive file (spec 12) streams from a throttled local server, a
// screenshot is taken while each level is on screen, and each is checked
// from its pixels: the mesh is there (not blank) and gains detail level by
// level (more distinct flat-shaded facets). The last level must equal the
// whole-file decode, and each level below it must have been on screen before
// the whole body had arrived. Screenshots: web/test-output/.
import assert from 'node:assert/strict';
import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { test } from 'node:test';

import { CHROMIUM, openViewer, streamIntoViewer } from './browser.mjs';

const FILE = '/conformance/vectors/valid_loop_octahedron_sphere_5_levels.qmc';
const BYTES_PER_SECOND = 3000; // 4869 bytes: about 1.6 s

// Runs in the page: decodes a screenshot and measures it against the
// background colour (#20242a).
async function measure(base64) {
  const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${base64}`)).blob());
  const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
  const context = canvas.getContext('2d');
  context.drawImage(bitmap, 0, 0);
  const { data } = context.getImageData(0, 0, bitmap.width, bitmap.height);
  const colours = new Set();
  let foreground = 0;
  for (let i = 0; i < data.length; i += 4) {
    const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
    if (Math.abs(r - 0x20) + Math.abs(g - 0x24) + Math.abs(b - 0x2a) < 24) continue;
    foreground += 1;
    colours.add((r << 16) | (g << 8) | b);
  }
  return { foregroundFraction: foreground / (bitmap.width * bitmap.height), distinctColours: colours.size };
}

// Runs in the page: the last streamed level against qmc.decode of the whole file.
async function lastLevelEqualsWholeDecode(url) {
  const { loadQMC } = await import('../src/qmc.js');
  const whole = (await loadQMC()).decode(new Uint8Array(await (await fetch(url)).arrayBuffer()));
  const last = window.qmcViewer.levels.at(-1);
  const same = (a, b) => a.length === b.length && a.every((v, i) => v === b[i]);
  return same(last.attributes.position.array, whole.positions) && same(last.index.array, whole.indices);
}

test('the viewer shows a throttled progressive file level by level', { timeout: 60000 }, async () => {
  assert.ok(existsSync(CHROMIUM), `${CHROMIUM} (scripts/install-web-deps.sh installs it)`);
  const { page, pageErrors, close } = await openViewer({ throttle: BYTES_PER_SECOND });
  try {
    const shots = [];
    const started = Date.now();
    const error = await streamIntoViewer(page, FILE, async (info) => {
      shots.push({ info, png: await page.screenshot({ encoding: 'base64' }) });
    });
    assert.deepEqual(pageErrors, []);
    assert.equal(error, null);
    const total = await page.evaluate(() => window.qmcViewer.total);
    assert.equal(shots.length, 6, 'base mesh and 5 levels, one screenshot each');

    mkdirSync(new URL('../test-output/', import.meta.url), { recursive: true });
    const measured = [];
    for (const [level, { info, png }] of shots.entries()) {
      writeFileSync(new URL(`../test-output/level${level}.png`, import.meta.url), Buffer.from(png, 'base64'));
      measured.push(await page.evaluate(measure, png));
      assert.equal(info.level, level);
      assert.equal(info.faceCount, 8 * 4 ** level);
      assert.ok(measured[level].foregroundFraction > 0.05, `level ${level} on screen: ${JSON.stringify(measured[level])}`);
      if (level < 5) assert.ok(info.bytesReceived < total, `level ${level} shown after ${info.bytesReceived} of ${total} bytes`);
    }
    console.log(`first level on screen after ${shots[0].info.bytesReceived} bytes; all in ${Date.now() - started} ms;`,
                measured.map((m) => `${m.distinctColours} colours / ${(100 * m.foregroundFraction).toFixed(1)}%`).join(', '));
    for (let level = 1; level < 4; ++level) {
      assert.ok(measured[level].distinctColours > measured[level - 1].distinctColours,
        `level ${level} has more facets than level ${level - 1}: ${measured[level].distinctColours} colours`);
    }
    assert.ok(await page.evaluate(lastLevelEqualsWholeDecode, FILE), 'the last level is the whole-file decode');
    const slidToLevel1 = await page.evaluate(() => {
      const slider = document.getElementById('level');
      slider.value = '1';
      slider.dispatchEvent(new Event('input'));
      return [window.qmcViewer.shown.userData.level, document.getElementById('status').textContent];
    });
    assert.equal(slidToLevel1[0], 1, 'the slider shows level 1 again');
    assert.match(slidToLevel1[1], /level 1 of 5: 18 vertices, 32 faces/);
  } finally {
    await close();
  }
});

test('a .qmc dropped on the viewer is shown with its counts', { timeout: 60000 }, async () => {
  const { page, pageErrors, close } = await openViewer();
  try {
    await page.evaluate(async () => {
      const bytes = await (await fetch('/conformance/vectors/valid_cube_8bit.qmc')).arrayBuffer();
      const transfer = new DataTransfer();
      transfer.items.add(new File([bytes], 'cube.qmc'));
      document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
    });
    await page.waitForFunction(() => window.qmcViewer.done || window.qmcViewer.error, { timeout: 30000 });
    assert.deepEqual(pageErrors, []);
    const status = await page.evaluate(() => document.getElementById('status').textContent);
    assert.match(status, /cube\.qmc: \d+ of \d+ bytes received\nsingle mesh: 8 vertices, 6 faces/);
  } finally {
    await close();
  }
});
