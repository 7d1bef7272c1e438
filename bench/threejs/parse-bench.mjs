// three.js ColladaLoader parse speed in Node: a baseline for `skinlab bench parse`.
//
// Same protocol as ours: every file is read once into memory; a shared warm-up of --warmup-seconds
// over the files under 10 MB; then --runs timed parses per file (5 for files of 10 MB or more, each
// after a GC when node runs with --expose-gc). A timed parse is bytes -> string (TextDecoder, the
// BOM picks UTF-8 or UTF-16, as our importer does) -> new ColladaLoader().parse(text, TEXTURES).
// Between parses (untimed) the script yields to the event loop, so texture requests settle.
//
// Usage: node [--expose-gc] parse-bench.mjs [--json] [--warmup-seconds S] [--runs N] FILE...

import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import { performance } from 'node:perf_hooks';

import { DOMParser, parseHTML } from 'linkedom';

// Node has no DOM. ColladaLoader needs DOMParser (with querySelector and parentElement, which
// linkedom's XML documents have), and its TextureLoader creates <img> elements through
// `document`; linkedom's <img> never loads anything. A browser only starts loading textures
// during the parse (asynchronously), so not loading them keeps the comparison fair.
globalThis.DOMParser = DOMParser;
globalThis.document = parseHTML('<!doctype html><html><body></body></html>').document;
// TGA textures go through fetch(): it fails at once (asynchronously), nothing is read. The URLs
// must be absolute, as in a browser (Node's Request refuses relative ones).
globalThis.fetch = () => Promise.reject(new Error('parse-bench loads no textures'));
const TEXTURES = 'file:///parse-bench-loads-no-textures/';

const { REVISION } = await import('three');
const { ColladaLoader } = await import('three/addons/loaders/ColladaLoader.js');

const LARGE = 10_000_000;

function parseArgs(argv) {
    const opts = { json: false, warmupSeconds: 3, runs: 25, files: [] };
    for (let i = 0; i < argv.length; i++) {
        const a = argv[i];
        const value = () => {
            const eq = a.indexOf('=');
            if (eq >= 0) return a.slice(eq + 1);
            if (i + 1 >= argv.length) usage(`${a} needs a value`);
            return argv[++i];
        };
        if (a === '--json') opts.json = true;
        else if (a.startsWith('--warmup-seconds')) opts.warmupSeconds = Number(value());
        else if (a.startsWith('--runs')) opts.runs = Number(value());
        else if (a === '-h' || a === '--help') usage(null);
        else if (a.startsWith('--')) usage(`unknown option ${a}`);
        else opts.files.push(a);
    }
    if (opts.files.length === 0) usage('no files given');
    if (!(opts.runs >= 1) || !(opts.warmupSeconds >= 0)) usage('--runs must be >= 1, --warmup-seconds >= 0');
    return opts;
}

function usage(problem) {
    const text = 'usage: node [--expose-gc] parse-bench.mjs [--json] [--warmup-seconds S] [--runs N] FILE...';
    if (problem) {
        console.error(`parse-bench: ${problem}\n${text}`);
        process.exit(2);
    }
    console.log(text);
    process.exit(0);
}

function decode(bytes) {
    if (bytes[0] === 0xff && bytes[1] === 0xfe) return new TextDecoder('utf-16le').decode(bytes);
    if (bytes[0] === 0xfe && bytes[1] === 0xff) return new TextDecoder('utf-16be').decode(bytes);
    return new TextDecoder('utf-8').decode(bytes);
}

function parseOnce(bytes) {
    const result = new ColladaLoader().parse(decode(bytes), TEXTURES);
    if (result === null) throw new Error('ColladaLoader returned null (XML parser error)');
    return result;
}

/** Triangles of the distinct mesh geometries (lines and points not counted), for a sanity check. */
function triangles(result) {
    const seen = new Set();
    let count = 0;
    result.scene.traverse((o) => {
        if (!o.isMesh || seen.has(o.geometry)) return;
        seen.add(o.geometry);
        const g = o.geometry;
        count += (g.index ? g.index.count : g.attributes.position.count) / 3;
    });
    return count;
}

function median(xs) {
    const s = [...xs].sort((a, b) => a - b);
    const n = s.length;
    return n % 2 === 1 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
}

const round = (x) => Math.round(x * 1000) / 1000;
const gc = globalThis.gc ?? (() => {});

const opts = parseArgs(process.argv.slice(2));
const files = opts.files.map((path) => ({ path, name: basename(path), bytes: readFileSync(path) }));

// ColladaLoader logs through console on every parse (its file version, Z_UP warnings); keep the
// output clean. Our progress lines go to the saved stderr writer.
const quiet = { log: console.log, info: console.info, debug: console.debug, warn: console.warn, error: console.error };
console.log = console.info = console.debug = console.warn = console.error = () => {};
const settle = () => new Promise((resolve) => setImmediate(resolve));

// One parse per file first: what fails is reported, not timed, and left out of the warm-up.
for (const f of files) {
    try {
        f.triangles = triangles(parseOnce(f.bytes));
    } catch (e) {
        f.error = String(e && e.message ? e.message : e).replace(/\s+/g, ' ').trim();
    }
    await settle();
}
const warmupEnd = performance.now() + opts.warmupSeconds * 1000;
do {
    for (const f of files) {
        if (!f.error && f.bytes.length < LARGE) {
            parseOnce(f.bytes);
            await settle();
        }
    }
} while (performance.now() < warmupEnd);

for (const f of files) {
    if (f.error) continue;
    const large = f.bytes.length >= LARGE;
    const n = large ? 5 : opts.runs;
    f.millis = [];
    for (let r = 0; r < n; r++) {
        if (large) gc();
        const t0 = performance.now();
        parseOnce(f.bytes);
        f.millis.push(performance.now() - t0);
        await settle();
    }
    quiet.error(`parse-bench: ${f.name} ${median(f.millis).toFixed(2)} ms`);
}
Object.assign(console, quiet);

// three's package exports hide package.json; read the installed one directly.
const three = JSON.parse(readFileSync(new URL('./node_modules/three/package.json', import.meta.url))).version;
if (opts.json) {
    console.log(JSON.stringify({
        benchmark: 'threejs-parse',
        node: process.versions.node,
        three,
        threeRevision: REVISION,
        files: files.map((f) => f.error
            ? { file: f.name, bytes: f.bytes.length, error: f.error }
            : {
                file: f.name, bytes: f.bytes.length, triangles: f.triangles, runs: f.millis.length,
                minMillis: round(Math.min(...f.millis)), medianMillis: round(median(f.millis)),
                mbPerSecond: round(f.bytes.length / 1e6 / (median(f.millis) / 1000)),
            }),
    }));
} else {
    console.log(`three.js ${three} ColladaLoader, Node ${process.versions.node}`);
    console.log(`${'file'.padEnd(40)} ${'MB'.padStart(9)} ${'triangles'.padStart(10)} ${'min ms'.padStart(9)} `
        + `${'median ms'.padStart(9)} ${'MB/s'.padStart(8)}`);
    for (const f of files) {
        const head = `${f.name.padEnd(40)} ${(f.bytes.length / 1e6).toFixed(3).padStart(9)}`;
        if (f.error) {
            console.log(`${head} failed: ${f.error}`);
            continue;
        }
        const med = median(f.millis);
        console.log(`${head} ${String(f.triangles).padStart(10)} ${Math.min(...f.millis).toFixed(2).padStart(9)} `
            + `${med.toFixed(2).padStart(9)} ${(f.bytes.length / 1e6 / (med / 1000)).toFixed(1).padStart(8)}`);
    }
}
