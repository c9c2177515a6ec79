// A small static file server for the page: no dependencies, correct MIME types
// (application/wasm for the module, so browsers compile it while it downloads), bound to
// localhost. A file with a precompressed sibling (`x.br`, `x.gz`, written by scripts/web.mjs)
// goes out compressed to a browser that accepts it (Content-Encoding, Vary: Accept-Encoding);
// a file named by its content's hash (`assets/main-3F2A9C1B.js`) may be cached for a year,
// every other file is revalidated (ETag). `node scripts/serve.mjs` serves the production build
// (dist/web/, `npm start`), `--dev` the project root with the unbundled page (`npm run dev`),
// and prints the URL; tests import `startServer` and use a free port.
import { createServer } from 'node:http';
import { createReadStream, statSync } from 'node:fs';
import { extname, join, normalize, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(fileURLToPath(new URL('..', import.meta.url)));
/** The production build (scripts/web.mjs). */
export const SITE = join(ROOT, 'dist/web');

/** A name with a content hash (scripts/web.mjs): its bytes never change. */
const HASHED = /-[0-9A-Z]{8}\.[a-z0-9]+$/;
/** Compressions a sibling file may hold, best first. */
const ENCODINGS = [
  ['br', '.br'],
  ['gzip', '.gz'],
];

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
    // the compressed sibling the browser accepts, if there is one
    const accepted = String(req.headers['accept-encoding'] ?? '')
      .split(',')
      .map((e) => e.trim().split(';')[0].toLowerCase());
    let body = file;
    let size = stat.size;
    /** @type {Record<string, string>} */
    const encoding = {};
    for (const [name, suffix] of ENCODINGS) {
      const sibling = siblingSize(`${file}${suffix}`);
      if (sibling === null) continue;
      encoding.vary = 'accept-encoding';
      if (!accepted.includes(name) || encoding['content-encoding']) continue;
      encoding['content-encoding'] = name;
      body = `${file}${suffix}`;
      size = sibling;
    }
    const etag = `"${stat.size.toString(36)}-${Math.round(stat.mtimeMs).toString(36)}${encoding['content-encoding'] ? `-${encoding['content-encoding']}` : ''}"`;
    const cache = HASHED.test(path) ? 'public, max-age=31536000, immutable' : 'no-cache';
    const common = { etag, 'cache-control': cache, 'access-control-allow-origin': '*', ...encoding };
    if (req.headers['if-none-match'] === etag) {
      res.writeHead(304, { ...common, ...headers, ...headersFor(path) }).end();
      return;
    }
    res.writeHead(200, {
      'content-type': TYPES[/** @type {keyof typeof TYPES} */ (extname(file))] ?? 'application/octet-stream',
      'content-length': size,
      ...common,
      ...headers,
      ...headersFor(path),
    });
    if (req.method === 'HEAD') res.end();
    else createReadStream(body).pipe(res);
  });
  return new Promise((resolvePromise, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      const { port: actual } = /** @type {import('node:net').AddressInfo} */ (server.address());
      resolvePromise({ server, url: `http://${host === '127.0.0.1' ? 'localhost' : host}:${actual}/` });
    });
  });
}

/** The size of the file `path`, or null when there is none. */
function siblingSize(/** @type {string} */ path) {
  try {
    const stat = statSync(path);
    return stat.isFile() ? stat.size : null;
  } catch {
    return null;
  }
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const dev = process.argv.includes('--dev');
  const root = dev ? ROOT : SITE;
  const first = Number(process.env.PORT ?? 8080);
  for (let port = first; port < first + 20; port++) {
    try {
      const { url } = await startServer({ port, root });
      console.log(
        `\nruledlab is running at ${url}\n(${dev ? 'the unbundled page of www/' : 'the production build, dist/web/'}; Ctrl-C to stop)`,
      );
      break;
    } catch (e) {
      if (/** @type {NodeJS.ErrnoException} */ (e).code !== 'EADDRINUSE') throw e;
    }
  }
}
