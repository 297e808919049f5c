// Fuzzes the embed bridge's message parser (web/embed_bridge.js) under node: the file as the
// page links it, in a context of its own with a stand-in for the page (its address, the window's
// message listener, window.swarmlab). The parser is JavaScript: a message is checked there and
// reaches the app only as a call of window.swarmlab with checked arguments, whose C++ is
// libFuzzer's (preset_fuzz.cpp for load's presets).
//   node tests/fuzz/embed_bridge_fuzz.mjs [seconds]      (default 20)
// Seeds: a good request of every call, as the example course page sends them. Each round mutates
// one (its id, call, args, version; foreign keys, huge and deep values, cycles, numbers at the
// edges of the safe integers and of 2^32) and posts it from the allowed origin or from another.
// Every message must be handled without a throw; one from another origin, or one that is no
// object with a `swarmlab` key, gets no reply and reaches no call; any other gets exactly one
// reply, at its origin, that a browser can post (a structured clone), with the request's id
// when that is a good id (else null) and either a result or a one-line error; a call reaches
// window.swarmlab only with the arguments its table promises (an index a safe integer, ...).
// A third of the time goes to the ?origins= list: mutated lists, and the origins that may then
// drive the app must each be an entry of the list that is an exact http(s) origin.
// Last line: "N passed, M failed" (passes are the rounds).
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import vm from 'node:vm';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const seconds = Number(process.argv[2] || 20);
const bridgeSource = readFileSync(join(root, 'web/embed_bridge.js'), 'utf8');
const bridgeScript = new vm.Script(bridgeSource, { filename: 'web/embed_bridge.js' });
const maxPresetBytes = 4 * 1024 * 1024;
const COURSE = 'https://course.example.org';

// A small deterministic generator, so that a failure can be replayed with the same seed.
let state = BigInt(process.env.SEED || 20261207);
function random() {
  state = (state * 6364136223846793005n + 1442695040888963407n) & 0xffffffffffffffffn;
  return Number(state >> 11n) / 2 ** 53;
}
const pick = (n) => Math.floor(random() * n);
const choose = (list) => list[pick(list.length)];

// What window.swarmlab's calls accept, written here from web/README.md's table (not read from
// the bridge): a call that reaches the stand-in with anything else is a failure.
const safeIndex = (v) => Number.isSafeInteger(v) && v >= 0;
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const accepts = {
  ready: [], state: [], time: [], preset: [], positions: [], shipped: [], frames: [], lastMessage: [],
  load: [(v) => typeof v === 'string' || (v !== null && typeof v === 'object')],
  set: [isObject],
  seek: [(v) => typeof v === 'number' && Number.isFinite(v)],
  select: [(v) => v === null || safeIndex(v)],
  stopwatch: [(v) => typeof v === 'string'],
  link: [], openLink: [(v) => typeof v === 'string'], download: [], exportCsv: [],
  screenPosition: [safeIndex],
  buttonRect: [(v) => typeof v === 'string'], welcomeShown: [], lessons: [],
  openLesson: [(v) => typeof v === 'string' || (v !== null && typeof v === 'object')],
  lessonState: [], lessonAnswer: [(v) => typeof v === 'number' && Number.isFinite(v)],
  lessonNext: [], lessonBack: [], lessonFinish: [], lessonRestart: [],
  lessonLink: [(v) => typeof v === 'string' || (v !== null && typeof v === 'object')],
};

// The bridge in a fresh context: its page's address, its listener, its calls and replies.
function loadBridge(search) {
  const page = { listener: null, calls: [], warnings: 0 };
  const api = { ready: Promise.resolve(), lastMessage: null };
  for (const name of Object.keys(accepts)) {
    api[name] = (...args) => {
      page.calls.push({ name, args });
      if (name === 'seek' || name === 'link') return Promise.resolve(1);
      if (name === 'lessonAnswer' && args[0] > 1e300) throw new Error('swarmlab.lessonAnswer(value): too large');
      return { called: name };
    };
  }
  const window = {
    addEventListener(type, f) { if (type === 'message') page.listener = f; },
    parent: null,
  };
  window.parent = window;
  const context = vm.createContext({
    window, location: { search, hash: '' }, URL,
    console: { warn() { page.warnings++; }, log() {} },
    Module: { swarmlab: api, swarmlabStarted() {} },
    SwarmlabLink: { maxPresetBytes },
  });
  bridgeScript.runInContext(context);
  if (context.Module.swarmlabStarted) context.Module.swarmlabStarted();
  return page;
}

let passed = 0, failed = 0;
function fail(what, input) {
  ++failed;
  let shown;
  try { shown = JSON.stringify(input); } catch { shown = typeof input; }
  if (failed <= 5) console.log(`FAIL  ${what}: ${String(shown).slice(0, 200)}`);
}

const settle = () => new Promise((resolve) => setImmediate(resolve));

// Posts data from origin to the bridge and checks what comes back and what was called.
async function post(page, data, origin) {
  const replies = [];
  const source = { postMessage(message, target) { replies.push({ message, target }); } };
  page.calls.length = 0;
  try {
    page.listener({ data, origin, source });
  } catch (e) {
    return fail(`the listener threw (${e && e.message})`, data);
  }
  await settle();
  const ours = data !== null && typeof data === 'object' && !Array.isArray(data) && 'swarmlab' in data;
  if (origin !== COURSE || !ours) {
    if (replies.length || page.calls.length) return fail(`${origin !== COURSE ? 'another origin' : 'someone else\'s message'} was answered or called`, data);
    return ++passed;
  }
  if (replies.length !== 1) return fail(`${replies.length} replies`, data);
  const { message, target } = replies[0];
  if (target !== origin) return fail(`a reply to ${target}`, data);
  try { structuredClone(message); } catch (e) { return fail(`a reply that cannot be posted (${e.message})`, data); }
  const id = data.id;
  const goodId = (typeof id === 'string' && id.length <= 200) || (typeof id === 'number' && Number.isFinite(id));
  if (message.swarmlab !== 1) return fail('a reply without swarmlab: 1', data);
  if (message.id !== (goodId ? id : null)) return fail(`reply id ${String(message.id).slice(0, 40)}`, data);
  if (('result' in message) === ('error' in message)) return fail('a reply with both or neither of result and error', data);
  if ('error' in message && !(typeof message.error === 'string' && message.error && message.error.length < 2000 && !message.error.includes('\n')))
    return fail(`an error that is not one line: ${JSON.stringify(message.error).slice(0, 80)}`, data);
  for (const { name, args } of page.calls) {
    const wanted = accepts[name];
    if (!wanted || args.length !== wanted.length || !wanted.every((ok, i) => ok(args[i])))
      return fail(`${name} was called with ${args.map((a) => { try { return JSON.stringify(a); } catch { return String(a); } }).join(', ').slice(0, 80)}`, data);
  }
  return ++passed;
}

// Values at the edges: of the safe integers, of 2^32, of JSON.
const edges = [0, -0, 1, -1, 3, 0.5, 2 ** 31, 2 ** 32, 2 ** 32 + 1, 4294967298, 2 ** 53 - 1, 2 ** 53, 2 ** 53 + 2, 2 ** 62, 2 ** 64,
               -(2 ** 53), 1e308, 1e400, -1e400, NaN, Number.MAX_VALUE, Number.MIN_VALUE, '5', '', null, true, undefined,
               [], {}, [1], { length: 1 }, 5n];
const strings = ['state', 'select', 'screenPosition', 'constructor', '__proto__', 'toString', 'hasOwnProperty', 'rmrf',
                 'x'.repeat(300), 'l\u0000ad', 'two\nlines', '\u202e', 'javascript:alert(1)'];

function anyValue(depth = 0) {
  switch (pick(depth > 3 ? 4 : 8)) {
    case 0: return choose(edges);
    case 1: return choose(strings);
    case 2: return pick(2) ? pick(1000) : random() * 10 ** pick(400) * (pick(2) ? 1 : -1);
    case 3: return 'x'.repeat(pick(4) ? pick(64) : maxPresetBytes + 65536 - 200 + pick(400));
    case 4: return Array.from({ length: pick(4) }, () => anyValue(depth + 1));
    case 5: { const o = {}; for (let k = 0; k < pick(4); ++k) o[choose(strings)] = anyValue(depth + 1); return o; }
    case 6: { const a = [anyValue(depth + 1)]; a.push(a); return a; }
    default: return new Map([[1, 2]]);
  }
}

// The good requests the course page sends, one a call.
const goodArgs = {
  load: [{ version: 1, name: 'x' }], set: [{ playing: false }], seek: [1], select: [2], stopwatch: ['start'],
  openLink: ['#preset=e30'], screenPosition: [1], buttonRect: ['Copy link'], openLesson: ['gas-at-the-wall'],
  lessonAnswer: [1.5], lessonLink: ['one-period'],
};
const seeds = Object.keys(accepts).map((call, i) => ({ swarmlab: 1, id: i, call, args: goodArgs[call] || [] }));

function mutate(seed) {
  const m = { ...seed, args: Array.isArray(seed.args) ? [...seed.args] : seed.args };
  for (let k = 0; k <= pick(3); ++k) {
    switch (pick(9)) {
      case 0: m.id = anyValue(); break;
      case 1: m.call = choose(pick(2) ? strings : Object.keys(accepts)); break;
      case 2: if (Array.isArray(m.args) && m.args.length) m.args[pick(m.args.length)] = anyValue(); else m.args = [anyValue()]; break;
      case 3: m.args = pick(2) ? anyValue() : undefined; break;
      case 4: m.swarmlab = anyValue(); break;
      case 5: m[choose(strings)] = anyValue(); break;
      case 6: if (Array.isArray(m.args)) m.args.push(anyValue()); break;
      case 7: if (Array.isArray(m.args)) m.args[0] = choose(edges); else m.args = [choose(edges)]; break;
      default: delete m[choose(['id', 'call', 'args', 'swarmlab'])];
    }
  }
  return pick(20) ? m : anyValue();
}

// ?origins=: which origins may drive the app after a list is read.
const originEntries = [COURSE, 'http://127.0.0.1:8080', 'https://moodle.example.org/', 'https://a.b:443',
                       'HTTPS://UPPER.example.org', 'https://x.y/path', 'https://u:p@x.y', 'javascript:alert(1)', 'null', '*',
                       'https://*.example.org', 'file:///etc', 'https://x.y?q', 'https://x.y#f', 'data:,x', 'https://x.y\n',
                       'https://x.y\t', '\u0000https://x.y', 'https://xn--e1afmkfd.xn--p1ai', 'https://x.y.', 'http://[::1]:9'];
function mutateOriginList() {
  const entries = Array.from({ length: 1 + pick(3) }, () => {
    let e = choose(originEntries);
    if (pick(3) === 0) {
      const at = pick(e.length + 1);
      e = e.slice(0, at) + choose(['%0a', '%09', '%00', '\t', ' ', '/', '@', '%2F', ':0', '\u0085', '\u2028', '.', '%']) + e.slice(at + pick(2));
    }
    return e;
  });
  return entries.join(choose([',', ', ', ',,', '%2C']));
}
// The entries of a list that are exact http(s) origins (as event.origin spells them, but for
// the case of letters and a trailing '/'), judged without the URL parser's help.
function exactEntries(search) {
  let list = search.slice('?origins='.length);
  try { list = decodeURIComponent(list.replace(/\+/g, ' ')); } catch { /* as it is */ }
  return list.split(',').map((e) => e.trim())
    .filter((e) => /^https?:\/\/[a-z0-9.\-[\]:]+\/?$/i.test(e) && !/[\u0000-\u001f\u007f-\u009f]/.test(e));
}
async function originRound() {
  const search = '?origins=' + mutateOriginList();
  let page;
  try { page = loadBridge(search); } catch (e) { return fail(`the bridge threw on load (${e.message})`, search); }
  if (!page.listener) return ++passed;  // no allowed origin: no bridge at all
  const exact = exactEntries(search);
  const candidates = [COURSE, 'null', 'https://x.y', 'https://a.b', 'https://moodle.example.org', 'https://upper.example.org',
                      'http://127.0.0.1:8080', 'http://[::1]:9', ...exact.map((e) => { try { return new URL(e).origin; } catch { return e; } })];
  for (const origin of candidates) {
    const replies = [];
    page.listener({ data: { swarmlab: 1, id: 1, call: 'ready', args: [] }, origin, source: { postMessage(m) { replies.push(m); } } });
    await settle();
    if (!replies.length) continue;
    const listed = exact.some((e) => e.replace(/\/$/, '').toLowerCase() === origin);
    if (!listed) return fail(`${origin} may drive the app`, search);
  }
  return ++passed;
}

const bridge = loadBridge('?embed&origins=' + encodeURIComponent(COURSE));
if (!bridge.listener) {
  fail('the bridge did not listen with an allowed origin', COURSE);
} else {
  for (const seed of seeds) await post(bridge, seed, COURSE);  // every good request is answered
}
const end = performance.now() + 1000 * seconds;
let rounds = 0;
while (performance.now() < end && bridge.listener) {
  if (rounds % 3 === 2) await originRound();
  else await post(bridge, mutate(choose(seeds)), pick(10) ? COURSE : choose(['https://evil.example', 'null', COURSE + '/']));
  ++rounds;
}
console.log(`embed-bridge fuzz: ${rounds} rounds in ${seconds} s (SEED=${process.env.SEED || 20261207})`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
