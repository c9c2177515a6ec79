// A small static file server for the page: no dependencies, correct MIME types
// (application/wasm for the module), bound to localhost. `node scripts/serve.mjs` serves the
// project root and prints the URL; tests import `startServer` and use a free port.
import { createServer } from 'node:http';
import { createReadStream, statSync } from 'node:fs';
import { extname, join, normalize, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(fileURLToPath(new URL('..', import.meta.url)));

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.ico': 'image/x-icon',
  '.ts': 'text/plain; charset=utf-8',
  '.csv': 'text/csv; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/markdown; charset=utf-8',
};

/**
 * Serves `root` on `host:port` (port 0: any free port), adding `headers` to every response
 * (e.g. a Content-Security-Policy), and `headersFor(path)` to the response of that path. Every
 * file may be loaded by pages of other origins, as
 * from a static CDN (`Access-Control-Allow-Origin: *`): a sandboxed iframe of a course system
 * has an opaque origin and loads the page's modules and wasm cross-origin, and a Share snippet
 * on another site loads the viewer. Resolves to { server, url }.
 */
export function startServer({
  root = ROOT,
  port = 0,
  host = '127.0.0.1',
  headers = {},
  headersFor = (/** @type {string} */ _path) => /** @type {Record<string, string>} */ ({}),
} = {}) {
  const server = createServer((req, res) => {
    let path;
    try {
      path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
    } catch {
      res.writeHead(400).end('bad request');
      return;
    }
    if (path.endsWith('/')) path += 'index.html';
    const file = normalize(join(root, path));
    if (file !== root && !file.startsWith(root + sep)) {
      res.writeHead(403).end('forbidden');
      return;
    }
    let stat;
    try {
      stat = statSync(file);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain' }).end(`not found: ${path}`);
      return;
    }
    if (!stat.isFile()) {
      res.writeHead(404).end('not a file');
      return;
    }
    res.writeHead(200, {
      'content-type': TYPES[/** @type {keyof typeof TYPES} */ (extname(file))] ?? 'application/octet-stream',
      'content-length': stat.size,
      'cache-control': 'no-cache',
      'access-control-allow-origin': '*',
      ...headers,
      ...headersFor(path),
    });
    if (req.method === 'HEAD') res.end();
    else createReadStream(file).pipe(res);
  });
  return new Promise((resolvePromise, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      const { port: actual } = /** @type {import('node:net').AddressInfo} */ (server.address());
      resolvePromise({ server, url: `http://${host === '127.0.0.1' ? 'localhost' : host}:${actual}/` });
    });
  });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const first = Number(process.env.PORT ?? 8080);
  for (let port = first; port < first + 20; port++) {
    try {
      const { url } = await startServer({ port });
      console.log(`\nruledlab is running at ${url}\n(Ctrl-C to stop)`);
      break;
    } catch (e) {
      if (/** @type {NodeJS.ErrnoException} */ (e).code !== 'EADDRINUSE') throw e;
    }
  }
}
