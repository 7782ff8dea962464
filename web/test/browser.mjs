// Headless Chromium (Debian's /usr/bin/chromium, driven by puppeteer-core)
// on the viewer, served from 127.0.0.1 by web/tools/serve.mjs. Used by
// test/viewer.test.js and bench/first_level.mjs.
import puppeteer from 'puppeteer-core';

import { startServer } from '../tools/serve.mjs';

export const CHROMIUM = '/usr/bin/chromium';

// The viewer page at 640 x 480 behind a server sending .qmc bodies at
// `throttle` bytes per second; close() stops both. With warm, returns once
// the loader's worker has its decoder loaded and warmed up.
export async function openViewer({ throttle = 0, data = null, warm = false } = {}) {
  const server = await startServer({ port: 0, throttle, data });
  const browser = await puppeteer.launch({
    executablePath: CHROMIUM, headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=640,480'],
  });
  const page = await browser.newPage();
  await page.setViewport({ width: 640, height: 480 });
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(e.message));
  await page.goto(`http://127.0.0.1:${server.address().port}/web/viewer/`);
  if (warm) await page.waitForFunction(() => window.qmcViewer.decoderReady, { timeout: 30000 });
  const close = async () => {
    await browser.close();
    server.close();
  };
  return { page, pageErrors, close };
}

// Opens url in the viewer; onLevelShown(info, msSinceOpen) runs while each
// level (or a single mesh's geometry) is on screen. Resolves when the load
// ended, with the viewer's error or null.
export async function streamIntoViewer(page, url, onLevelShown) {
  const name = `levelShown${Math.random().toString(36).slice(2)}`;
  await page.exposeFunction(name, onLevelShown);
  await page.evaluate((url, name) => {
    const opened = performance.now();
    window.qmcViewer.onLevelShown = (info) => window[name](info, performance.now() - opened);
    document.getElementById('url').value = url;
    document.getElementById('open').requestSubmit();
  }, url, name);
  await page.waitForFunction(() => window.qmcViewer.done || window.qmcViewer.error, { timeout: 60000 });
  return page.evaluate(() => window.qmcViewer.error);
}
