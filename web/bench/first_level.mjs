// Bytes and time until the first mesh is on screen in the viewer (headless
// Chromium), for a progressive file against the plain file of the same mesh,
// both sent by web/tools/serve.mjs at a throttled rate. Inputs from
// web/bench/prepare.sh. Time is from the viewer's open to the frame drawn.
//   node web/bench/first_level.mjs DIR [BYTES_PER_SECOND]
import { statSync } from 'node:fs';
import { join } from 'node:path';

import { openViewer, streamIntoViewer } from '../test/browser.mjs';

const [dir, rateArgument] = process.argv.slice(2);
const rate = Number(rateArgument ?? 32000);

console.log(`headless Chromium, server at ${rate} bytes/s`);
console.log('| file | page | bytes | first mesh on screen: bytes decoded, ms | levels | last level on screen, ms |');
console.log('| --- | --- | --- | --- | --- | --- |');
// cold: the file requested as the page has loaded, as with viewer/?url=;
// warm: once the worker's decoder is loaded and warmed up.
for (const [file, warm] of [['bunny_progressive.qmc', false], ['bunny_progressive.qmc', true],
                            ['stanford-bunny.qmc', false], ['stanford-bunny.qmc', true]]) {
  const { page, pageErrors, close } = await openViewer({ throttle: rate, data: dir, warm });
  const shown = [];
  const error = await streamIntoViewer(page, `/data/${file}`, (info, ms) => shown.push({ info, ms }));
  await close();
  if (error || pageErrors.length) throw new Error(`${file}: ${error ?? pageErrors[0]}`);
  const [first, last] = [shown[0], shown.at(-1)];
  const levels = shown.map(({ info }) => `${info.faceCount} faces at ${info.bytesReceived} B`).join('; ');
  console.log(`| ${file} | ${warm ? 'warm' : 'cold'} | ${statSync(join(dir, file)).size} | ${first.info.bytesReceived} B, ${first.ms.toFixed(0)} ms | ` +
              `${levels} | ${last.ms.toFixed(0)} |`);
}
