// A class of thirty opening the page at once, on loopback: the server started as
// scripts/web.sh starts it (--no-build: caddy with web/serve/Caddyfile over build/web), then 30
// clients at the same moment fetch index.html and every file it loads (its scripts, icons and
// manifest, the manifest's icons, swarmlab.js and swarmlab.wasm as the page fetches them, the
// service worker), six connections each as a browser opens. Three rounds, by what the clients
// accept: br and gzip (a browser on https or on this computer), gzip (a browser over plain http
// to another computer: browsers ask for br on https only) and nothing (the files as built).
// Checks that every client finishes, that each file arrives as the copy its client asked for
// (Content-Encoding, Vary) and decodes to the file built, the cache headers (hashed names kept
// forever, the rest revalidated: a 304 for an unchanged index.html), nosniff and Referrer-Policy
// on each, the wasm's MIME type;
// prints the bytes sent and the slowest client's time per round.
//   node tests/web/serve_load_test.mjs           (after scripts/web.sh --build-only)
//   node tests/web/serve_load_test.mjs --nginx   the same against Debian's nginx with
//        web/serve/nginx.conf (docs/teacher-guide.md's lines for a school's server; needs nginx and
//        libnginx-mod-http-brotli-static; its temporary files go to build/serve/nginx)
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import http from 'node:http';
import { createServer } from 'node:net';
import { join, dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import zlib from 'node:zlib';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const webDir = join(root, 'build/web');
const CLIENTS = 30;
const CONNECTIONS = 6;  // per client, as a browser opens to one server
const LIMIT_MS = 120_000;
const HASHED = /\.[0-9a-f]{8}\.[0-9a-z]+$/;
const FOREVER = 'public, max-age=31536000, immutable';
// (Debian's nginx says application/javascript, which browsers take alike.)
const TYPES = { '.wasm': /^application\/wasm/, '.js': /^(text|application)\/javascript/, '.html': /^text\/html/,
                '.webmanifest': /^application\/manifest\+json/, '.png': /^image\/png/ };
const nginx = process.argv.includes('--nginx');

let passed = 0, failed = 0;
function check(name, ok, detail = '') {
  if (ok) { passed++; console.log(`ok    ${name}${detail ? ' (' + detail + ')' : ''}`); }
  else { failed++; console.log(`FAIL  ${name}${detail ? ': ' + detail : ''}`); }
  return ok;
}

let server = null;
function stop(code) {
  if (server && server.exitCode === null) server.kill('SIGTERM');
  process.exit(code);
}
setTimeout(() => { console.log(`FAIL  not done within ${LIMIT_MS / 1000} s`); stop(1); }, LIMIT_MS).unref();

function freePort() {
  return new Promise((res, rej) => {
    const s = createServer();
    s.once('error', rej);
    s.listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => res(port)); });
  });
}

// One GET: the status, the headers and the body as sent (not decoded), and its bytes.
function get(agent, port, path, headers) {
  return new Promise((res, rej) => {
    http.get({ host: '127.0.0.1', port, path: '/' + path, agent, headers }, (response) => {
      const chunks = [];
      response.on('data', (c) => chunks.push(c));
      response.on('end', () => res({ status: response.statusCode, headers: response.headers, body: Buffer.concat(chunks) }));
      response.on('error', rej);
    }).on('error', rej);
  });
}
const decode = (body, encoding) =>
  encoding === 'br' ? zlib.brotliDecompressSync(body) : encoding === 'gzip' ? zlib.gunzipSync(body) : body;

// What the page loads, as a browser would find it: its own tags, what its script fetches, the
// manifest's icons, the service worker.
function pageFiles(html, manifest) {
  const files = new Set();
  for (const m of html.matchAll(/<(?:script|link)\b[^>]*\b(?:src|href)="([^"]+)"/g)) files.add(m[1]);
  const named = JSON.parse(html.match(/window\.swarmlabFiles = (\{[^}]*\});/)[1]);
  files.add(named['swarmlab.js']).add(named['swarmlab.wasm']);
  for (const icon of JSON.parse(manifest).icons) files.add(icon.src);
  files.add('service_worker.js');
  return [...files];
}

// Whether a response is the copy of the file built that a client accepting `accept` should
// get, with its headers; a problem in words, or ''.
function problem(path, r, accept) {
  const file = join(webDir, path === '' ? 'index.html' : path);
  const encoding = r.headers['content-encoding'];
  const expected = accept.includes('br') && existsSync(file + '.br') ? 'br'
                 : accept.includes('gzip') && existsSync(file + '.gz') ? 'gzip' : undefined;
  const compressible = existsSync(file + '.br') || existsSync(file + '.gz');
  const cache = HASHED.test(path) ? FOREVER : 'no-cache';
  const type = TYPES[(path.match(/\.[a-z]+$/) || ['.html'])[0]];
  if (r.status !== 200) return `${path}: HTTP ${r.status}`;
  if (encoding !== expected) return `${path}: Content-Encoding ${encoding}, not ${expected}`;
  if (compressible && !/Accept-Encoding/i.test(r.headers.vary || '')) return `${path}: Vary ${r.headers.vary}`;
  if (r.headers['cache-control'] !== cache) return `${path}: Cache-Control ${r.headers['cache-control']}`;
  if (r.headers['x-content-type-options'] !== 'nosniff' || r.headers['referrer-policy'] !== 'same-origin')
    return `${path}: X-Content-Type-Options ${r.headers['x-content-type-options']}, Referrer-Policy ${r.headers['referrer-policy']}`;
  if (!type.test(r.headers['content-type'] || '')) return `${path}: Content-Type ${r.headers['content-type']}`;
  if (!decode(r.body, encoding).equals(readFileSync(file))) return `${path}: not the file built`;
  return '';
}

// One student's browser: index.html, then every file it loads, CONNECTIONS at a time. The
// responses are looked at after the clock stops (decoding them is the test's work, not the
// server's).
async function student(port, accept) {
  const agent = new http.Agent({ keepAlive: true, maxSockets: CONNECTIONS });
  const headers = accept ? { 'Accept-Encoding': accept } : {};
  const t0 = performance.now();
  const page = await get(agent, port, '', headers);
  const html = decode(page.body, page.headers['content-encoding']).toString();
  const manifest = readFileSync(join(webDir, 'manifest.webmanifest'), 'utf8');
  const files = pageFiles(html, manifest);
  const responses = [['', page], ...await Promise.all(files.map(async (f) => [f, await get(agent, port, f, headers)]))];
  const ms = performance.now() - t0;
  agent.destroy();
  return { ms, responses, bytes: responses.reduce((sum, [, r]) => sum + r.body.length, 0) };
}

// web/serve/nginx.conf's site on loopback, in an nginx of its own (not the system's).
function startNginx(port) {
  const dir = join(root, 'build/serve/nginx');
  mkdirSync(dir, { recursive: true });
  const site = readFileSync(join(root, 'web/serve/nginx.conf'), 'utf8')
    .replace(/listen 8080;/, `listen 127.0.0.1:${port};`).replace(/root \/srv\/swarmlab;/, `root ${webDir};`);
  const temp = ['client_body', 'proxy', 'fastcgi', 'uwsgi', 'scgi'].map((t) => `${t}_temp_path ${dir}/${t};`).join(' ');
  writeFileSync(join(dir, 'nginx.conf'), `load_module /usr/lib/nginx/modules/ngx_http_brotli_static_module.so;
pid ${dir}/nginx.pid; error_log stderr; daemon off; events {}
http { include /etc/nginx/mime.types; default_type application/octet-stream; access_log off; ${temp}
${site} }
`);
  return spawn('nginx', ['-c', join(dir, 'nginx.conf'), '-e', 'stderr'], { stdio: ['ignore', 'ignore', 'pipe'] });
}

async function main() {
  if (!check('build/web holds a published page', existsSync(join(webDir, 'index.html')) && existsSync(join(webDir, 'service_worker.js')),
             'scripts/web.sh --build-only first')) return;
  const port = await freePort();
  server = nginx ? startNginx(port)
                 : spawn(join(root, 'scripts/web.sh'), ['--no-build', '--port', String(port)], { stdio: ['ignore', 'ignore', 'pipe'] });
  let said = '';
  server.stderr.on('data', (d) => { said += d; });
  let up = false;
  for (const deadline = Date.now() + 30_000; Date.now() < deadline && server.exitCode === null && !up;) {
    up = await get(undefined, port, '', {}).then((r) => r.status === 200, () => false);
    if (!up) await new Promise((r) => setTimeout(r, 100));
  }
  if (!check(`${nginx ? 'nginx with web/serve/nginx.conf' : 'scripts/web.sh --no-build'} serves build/web on loopback`, up, said.trim().split('\n').slice(-3).join(' | '))) return;

  // --lan: the same config on every interface (read, not served: this test stays on loopback).
  if (!nginx) {
    const lan = spawnSync('caddy', ['adapt', '--adapter', 'caddyfile', '--config', join(root, 'web/serve/Caddyfile')],
                          { env: { ...process.env, SWARMLAB_BIND: '0.0.0.0', SWARMLAB_PORT: String(port) }, encoding: 'utf8' });
    const adapted = lan.status === 0 ? JSON.parse(lan.stdout) : {};
    check('for --lan the config listens on every interface, with no admin endpoint',
          JSON.stringify(adapted.apps?.http?.servers?.srv0?.listen) === JSON.stringify([`0.0.0.0:${port}`]) &&
          adapted.admin?.disabled === true, lan.stderr.trim().split('\n').pop());
  }

  const index = await get(undefined, port, '', { 'Accept-Encoding': 'gzip' });
  const again = await get(undefined, port, '', { 'Accept-Encoding': 'gzip', 'If-None-Match': index.headers.etag });
  check('an unchanged index.html is revalidated: 304, nothing sent again', again.status === 304 && again.body.length === 0,
        `${again.status}, ETag ${index.headers.etag}`);
  const missing = await get(undefined, port, 'nothing-here.js', {});
  check('a file that is not there: 404', missing.status === 404);

  const rounds = [['br, gzip', 'br and gzip (https, or this computer)'], ['gzip, deflate', 'gzip (plain http to another computer)'],
                  ['', 'nothing (the files as built)']];
  // One client of each kind first, untimed: the files in the page cache, the server warm, so
  // that no round pays for coming first.
  for (const [accept] of rounds) await student(port, accept);
  const figures = [];
  for (const [accept, what] of rounds) {
    const results = await Promise.allSettled(Array.from({ length: CLIENTS }, () => student(port, accept)));
    const done = results.filter((r) => r.status === 'fulfilled').map((r) => r.value);
    const problems = done.flatMap((d) => d.responses.map(([path, r]) => problem(path, r, accept))).filter(Boolean);
    const bytes = done.reduce((sum, r) => sum + r.bytes, 0);
    const slowest = Math.max(...done.map((r) => r.ms));
    check(`${CLIENTS} clients accepting ${what}: all finish`, done.length === CLIENTS,
          results.filter((r) => r.status === 'rejected').map((r) => String(r.reason)).slice(0, 3).join('; '));
    check(`  each of their ${done[0]?.responses.length} files arrives as the copy asked for, with its cache headers and type`,
          problems.length === 0, [...new Set(problems)].slice(0, 5).join('; '));
    figures.push({ what, bytes, perStudent: bytes / CLIENTS, slowest });
  }
  console.log(`\n${CLIENTS} clients at once on loopback, ${CONNECTIONS} connections each:`);
  for (const f of figures)
    console.log(`  accepting ${f.what.padEnd(38)} ${(f.bytes / 1048576).toFixed(1).padStart(6)} MB sent ` +
                `(${(f.perStudent / 1048576).toFixed(2)} MB a student), slowest client ${(f.slowest / 1000).toFixed(2)} s`);
}

main().catch((e) => check('the load test ran', false, String(e && e.stack || e)))
  .finally(() => {
    console.log(`${passed} passed, ${failed} failed`);
    stop(failed > 0 || passed === 0 ? 1 : 0);
  });
