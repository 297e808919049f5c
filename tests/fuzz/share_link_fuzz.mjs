// Fuzzes the browser's share-link decoding (web/share_link.js) under node, which has the same
// TextDecoder, atob and DecompressionStream as the page. libFuzzer (preset_fuzz.cpp) covers
// the C++ that the decoded text then goes to; this covers the JavaScript before it.
//   node tests/fuzz/share_link_fuzz.mjs [seconds]      (default 20)
// Seeds: the links of the shipped presets, both forms. Each round mutates a seed (flipped,
// dropped, inserted and repeated characters, cuts, foreign characters, percent escapes,
// another key, random bytes deflated or not) and reads it. Every read must resolve, never
// reject or throw, to { json } of at most the size limit or to { error } with a "share link: ..."
// message, in at most a second of this process's CPU time (the work that would freeze a tab;
// reads here take 20 ms at most) and ten seconds of wall time: CI runs this niced beside a
// browser on both cores, where one read of 20 ms of work once waited 1.5 s for a core.
// The seeds must also round-trip exactly.
// Last line: "N passed, M failed" (passes are the rounds).
import { readFileSync, readdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import vm from 'node:vm';
import { deflateRawSync } from 'node:zlib';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const seconds = Number(process.argv[2] || 20);
const Link = vm.runInThisContext(readFileSync(join(root, 'web/share_link.js'), 'utf8') + '\nSwarmlabLink;');

// A small deterministic generator, so that a failure can be replayed with the same seed.
let state = BigInt(process.env.SEED || 20261123);
function random() {
  state = (state * 6364136223846793005n + 1442695040888963407n) & 0xffffffffffffffffn;
  return Number(state >> 11n) / 2 ** 53;
}
const pick = (n) => Math.floor(random() * n);
const alphabet = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_+/= %\n\u00e9\u{1f600}#&';

function mutate(text) {
  const at = pick(text.length + 1);
  switch (pick(9)) {
    case 0: return text.slice(0, at);
    case 1: return text.slice(0, at) + text.slice(at + 1 + pick(8));
    case 2: return text.slice(0, at) + alphabet[pick(alphabet.length)] + text.slice(at);
    case 3: return text.slice(0, at) + text.slice(at, at + 1 + pick(64)).repeat(1 + pick(50)) + text.slice(at);
    case 4: return text.slice(0, at) + '%' + pick(256).toString(16) + text.slice(at);
    case 5: return text.replace(/^#(preset|z)=/, pick(2) ? '#z=' : '#preset=');
    case 6: return 'a=1&' + text + '&b';
    case 7: {
      const bytes = Buffer.from(Array.from({ length: pick(2000) }, () => pick(256)));
      return (pick(2) ? '#preset=' : '#z=') + Link.toBase64url(new Uint8Array(pick(2) ? deflateRawSync(bytes) : bytes));
    }
    default: {
      const chars = text.split('');
      for (let k = 0; k < 1 + pick(4); ++k) chars[pick(chars.length)] = alphabet[pick(alphabet.length)];
      return chars.join('');
    }
  }
}

let passed = 0, failed = 0;
function fail(what, input) {
  ++failed;
  if (failed <= 5) console.log(`FAIL  ${what}: ${JSON.stringify(input).slice(0, 160)}`);
}

async function readChecked(hash) {
  const t0 = performance.now(), cpu0 = process.cpuUsage();
  let out;
  try {
    out = Link.read(hash);
    // A read that never settles is a hang: the race ends it at the wall-time bound.
    let timer;
    const hung = new Promise((resolve) => { timer = setTimeout(() => resolve(hung), 10_000); });
    if (out !== null) out = await Promise.race([out, hung]);
    clearTimeout(timer);
    if (out === hung) return fail('read() never settled (10 s)', hash);
  } catch (e) {
    return fail(`read() threw or rejected (${e && e.message})`, hash);
  }
  const ms = performance.now() - t0, cpu = process.cpuUsage(cpu0), cpuMs = (cpu.user + cpu.system) / 1000;
  if (cpuMs > 1000) return fail(`read() took ${cpuMs.toFixed(0)} ms of CPU time`, hash);
  if (ms > 10000) return fail(`read() took ${ms.toFixed(0)} ms`, hash);
  if (out === null) return ++passed;
  if (typeof out.json === 'string') {
    if (Buffer.byteLength(out.json) > Link.maxPresetBytes) return fail('a preset over the limit came through', hash);
    return ++passed;
  }
  if (typeof out.error === 'string' && out.error.startsWith('share link: ')) return ++passed;
  return fail(`read() gave ${JSON.stringify(out).slice(0, 80)}`, hash);
}

const presets = readdirSync(join(root, 'assets/presets')).filter((f) => f.endsWith('.json'))
  .map((f) => readFileSync(join(root, 'assets/presets', f), 'utf8'));
const seeds = [];
for (const json of presets) {
  const plain = '#preset=' + Link.toBase64url(new TextEncoder().encode(json));
  const z = await Link.fragment(json);
  for (const hash of [plain, z]) {
    const back = await Link.read(hash);
    if (back && back.json === json) ++passed; else fail('a shipped preset does not round-trip', hash);
    seeds.push(hash);
  }
}

const end = performance.now() + 1000 * seconds;
let rounds = 0;
while (performance.now() < end) {
  let hash = seeds[pick(seeds.length)];
  for (let k = 0; k <= pick(3); ++k) hash = mutate(hash);
  await readChecked(hash);
  ++rounds;
}
console.log(`share-link fuzz: ${rounds} mutated links in ${seconds} s (SEED=${process.env.SEED || 20261123})`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
