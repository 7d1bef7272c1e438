#!/usr/bin/env node
// node test/positions.mjs FILE.glb --method lbs|dqs|cor --times T,... [--clip NAME] --out OUT.json
//
// Runs the add-on in headless Chromium and writes the GPU's skinned world positions in the shape
// of `skinlab pose --json` (desktop's PoseCommand): {"file", "clip", "method", "times",
// "meshes":[{"geometry":"/meshes/I", "name", "poses":[[x,y,z, ...] per time]}]}, one entry per
// placed mesh in scene order, one x,y,z per position as skinlab's glTF importer numbers them
// (vertices equal in position, influences and morph offsets welded, in first-vertex order), plus
// "readBack" (how the positions came off the GPU) and "renderer" (the GL renderer's name).
// The positions come from three's own program by transform feedback (test/page/capture.js).
import {writeFileSync} from 'node:fs';
import {basename, dirname, resolve} from 'node:path';
import {fileURLToPath} from 'node:url';
import {launch, newPage} from './support/browser.mjs';
import {serve} from './support/server.mjs';

const PACKAGE = resolve(dirname(fileURLToPath(import.meta.url)), '..');
/** How long one file's capture may take (SwiftShader on a busy machine: seconds). */
const TIMEOUT_MS = 120000;

/** The promise, or a rejection naming {@code what} once {@code ms} have passed. */
function within(ms, what, promise) {
    let timer;
    const timeout = new Promise((_, reject) => {
        timer = setTimeout(() => reject(new Error(`${what} took more than ${ms / 1000} s`)), ms);
    });
    return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

/**
 * The poses of {@code file} as the GPU computes them.
 *
 * @param {string} file a .glb or .gltf
 * @param {{method: string, times: number[], clip?: string, browser?: object}} options a browser
 *   to reuse, else one is started and closed
 */
export async function gpuPoses(file, {method, times, clip, browser}) {
    const model = '/model/' + encodeURIComponent(basename(file));
    const server = await serve(PACKAGE, {[decodeURIComponent(model)]: resolve(file)});
    const own = browser ? null : await launch();
    try {
        const page = await newPage(browser ?? own);
        try {
            await page.goto(server.url + '/test/page/capture.html', {timeout: TIMEOUT_MS});
            await page.waitForFunction('window.captureReady === true', {timeout: TIMEOUT_MS});
            const result = await within(TIMEOUT_MS, `capturing ${file} (${method})`,
                page.evaluate((url, m, t, c) => window.capturePoses(url, m, t, c), server.url + model, method, times,
                    clip ?? null));
            return {file, ...result};
        } finally {
            await within(30000, 'closing the page', page.close()).catch(() => {});
        }
    } finally {
        await own?.close();
        await server.close();
    }
}

function parseArgs(argv) {
    const args = {method: 'lbs', times: null, clip: null, out: null, file: null};
    for (let i = 0; i < argv.length; i++) {
        const a = argv[i];
        const value = () => {
            if (i + 1 >= argv.length) {
                throw new Error(`${a} needs a value`);
            }
            return argv[++i];
        };
        if (a === '--method') {
            args.method = value();
        } else if (a === '--times' || a === '--time') {
            args.times = value().split(',').map(s => {
                const t = Number(s.trim());
                if (s.trim() === '' || !Number.isFinite(t)) {
                    throw new Error(`'${s}' is not a time in seconds`);
                }
                return t;
            });
        } else if (a === '--clip') {
            args.clip = value();
        } else if (a === '--out') {
            args.out = value();
        } else if (a.startsWith('--')) {
            throw new Error(`unknown option ${a}`);
        } else if (args.file === null) {
            args.file = a;
        } else {
            throw new Error(`one file only (got ${args.file} and ${a})`);
        }
    }
    if (args.file === null || args.times === null || args.out === null) {
        throw new Error('usage: node test/positions.mjs FILE.glb --method lbs|dqs|cor --times T,... [--clip NAME] --out OUT.json');
    }
    return args;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
    try {
        const args = parseArgs(process.argv.slice(2));
        const result = await gpuPoses(args.file, args);
        writeFileSync(args.out, JSON.stringify(result) + '\n');
    } catch (e) {
        process.stderr.write(`positions: ${e.message}\n`);
        process.exit(1);
    }
}
