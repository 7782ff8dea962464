// Static file server for the viewer, bound to 127.0.0.1 only. Serves the
// repository (the viewer at /web/viewer/, three.js from web/node_modules,
// the conformance vectors) and, with --data DIR, DIR's files under /data/.
//
//   node web/tools/serve.mjs [--port 8080] [--data DIR] [--throttle BYTES_PER_SECOND]
//
// --throttle sends bodies in pieces at that rate, so that a progressive file
// arrives level by level as over a slow network.
import { createReadStream, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, normalize, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.css': 'text/css', '.json': 'application/json', '.qmc': 'application/octet-stream',
};
const PIECES_PER_SECOND = 20;

// Inside root, or null: no path may leave it.
function fileUnder(root, urlPath) {
  const path = normalize(join(root, decodeURIComponent(urlPath)));
  return path.startsWith(root) ? path : null;
}

function sendThrottled(response, path, bytesPerSecond) {
  const piece = Math.max(1, Math.round(bytesPerSecond / PIECES_PER_SECOND));
  const stream = createReadStream(path, { highWaterMark: piece });
  stream.on('data', (data) => {
    response.write(data);
    stream.pause();
    setTimeout(() => stream.resume(), 1000 / PIECES_PER_SECOND);
  });
  stream.on('end', () => response.end());
}

export function startServer({ port = 8080, data = null, throttle = 0 } = {}) {
  const repository = resolve(fileURLToPath(new URL('../..', import.meta.url)));
  const server = createServer((request, response) => {
    const urlPath = new URL(request.url, 'http://127.0.0.1').pathname;
    const path = urlPath.startsWith('/data/') && data
      ? fileUnder(resolve(data), urlPath.slice('/data'.length))
      : fileUnder(repository, urlPath.endsWith('/') ? urlPath + 'index.html' : urlPath);
    let size;
    try {
      size = path && statSync(path).isFile() ? statSync(path).size : -1;
    } catch {
      size = -1;
    }
    if (size < 0) {
      response.writeHead(404, { 'Content-Type': 'text/plain' }).end(`not found: ${urlPath}\n`);
      return;
    }
    response.writeHead(200, { 'Content-Type': TYPES[extname(path)] ?? 'application/octet-stream',
                              'Content-Length': size, 'Cache-Control': 'no-store' });
    if (throttle > 0 && extname(path) === '.qmc') sendThrottled(response, path, throttle);
    else createReadStream(path).pipe(response);
  });
  return new Promise((resolveListening) => server.listen(port, '127.0.0.1', () => resolveListening(server)));
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const options = {};
  for (let i = 2; i + 1 < process.argv.length; i += 2) options[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
  const server = await startServer({ port: Number(options.port ?? 8080), data: options.data ?? null,
                                     throttle: Number(options.throttle ?? 0) });
  console.log(`qmc viewer: http://127.0.0.1:${server.address().port}/web/viewer/`);
}
