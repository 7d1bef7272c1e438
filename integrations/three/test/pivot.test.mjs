// The DQS pivot on the GPU: slot 0 of a glTF vertex need not be its heaviest influence, and the
// header must pick the heaviest (test/page/pivot.js describes the case). The expected positions
// are worked out here from the definitions (Kavan et al. 2008: rotations on the pivot's side of
// the 4-sphere, blended and normalised), independently of the add-on.
import {after, before, describe, test} from 'node:test';
import assert from 'node:assert/strict';
import {dirname, resolve} from 'node:path';
import {fileURLToPath} from 'node:url';
import {launch, newPage} from './support/browser.mjs';
import {serve} from './support/server.mjs';

const SKIP = process.env.SKINLAB_THREE_SKIP_BROWSER === '1'
    ? 'SKINLAB_THREE_SKIP_BROWSER=1: the browser tests are skipped' : false;
const ANGLES = [0, 100, 200];
const WEIGHTS = [0.2, 0.5, 0.3];
const POINT = [1, 0, 0.5];

/** The unit quaternion of a turn about Z with Shepperd's sign (w >= 0 unless the trace is negative). */
function turnZ(degrees) {
    const a = degrees * Math.PI / 180;
    const q = [0, 0, Math.sin(a / 2), Math.cos(a / 2)];
    const trace = 1 + 2 * Math.cos(a);
    // Shepperd: w's branch when the trace is not negative (w > 0), else z's (z > 0).
    const flip = trace >= 0 ? q[3] < 0 : q[2] < 0;
    return flip ? q.map(v => -v) : q;
}

/** The point turned by the blend of the turns with {@code pivot}'s hemisphere. */
function expected(pivot) {
    const qs = ANGLES.map(turnZ);
    const blend = [0, 0, 0, 0];
    qs.forEach((q, i) => {
        const dot = q.reduce((s, v, k) => s + v * qs[pivot][k], 0);
        const w = dot < 0 ? -WEIGHTS[i] : WEIGHTS[i];
        q.forEach((v, k) => blend[k] += w * v);
    });
    const angle = 2 * Math.atan2(blend[2], blend[3]);
    return [POINT[0] * Math.cos(angle) - POINT[1] * Math.sin(angle), POINT[0] * Math.sin(angle) + POINT[1] * Math.cos(angle),
        POINT[2]];
}

describe('the DQS pivot is the heaviest influence', {skip: SKIP}, () => {
    let browser;
    let server;
    let page;

    before(async () => {
        server = await serve(resolve(dirname(fileURLToPath(import.meta.url)), '..'));
        browser = await launch();
        page = await newPage(browser);
        await page.goto(server.url + '/test/page/pivot.html');
        await page.waitForFunction('window.pivotReady === true', {timeout: 60000});
    });

    after(async () => {
        await browser?.close();
        await server?.close();
    });

    test('the case tells the pivots apart', () => {
        const heaviest = expected(1);
        const first = expected(0);
        assert.ok(Math.hypot(...heaviest.map((v, i) => v - first[i])) > 0.1, `${heaviest} vs ${first}`);
    });

    for (const method of ['dqs', 'cor']) {
        test(`${method}: the vertex turns by the blend with the heaviest influence as pivot`, async () => {
            const got = await page.evaluate((m, p, a, w) => window.pivotCase(m, p, a, w), method, POINT, ANGLES, WEIGHTS);
            const want = expected(1);
            assert.ok(Math.hypot(...got.map((v, i) => v - want[i])) < 1e-5, `${method}: GPU ${got}, expected ${want}`);
        });
    }

    test('a mesh bound away from the origin (bindMatrix not the identity) moves rigidly with its one joint alike in'
        + ' LBS, DQS and CoR', async () => {
        const points = [0, 0, 0, 1, 0, 0, 0, 2, 0, -0.5, 0.3, 0.8];
        const run = m => page.evaluate((method, p) => window.boundAwayCase(method, p), m, points);
        const lbs = await run('lbs');
        const rest = [2, -1, 0.5];
        assert.ok(Math.hypot(lbs[0] - rest[0], lbs[1] - rest[1], lbs[2] - rest[2]) > 0.5, 'the joint moved the mesh');
        for (const method of ['dqs', 'cor']) {
            const got = await run(method);
            const worst = Math.max(...got.map((v, i) => Math.abs(v - lbs[i])));
            assert.ok(worst < 1e-5, `${method}: ${got} vs three's LBS ${lbs}`);
        }
    });
});
