// npm run screenshot [-- MODEL.glb]: serves the example with the exported walking character and
// writes docs/example.png (headless Chromium, CoR on the right, the clip frozen at one time, a close-up of one knee).
// MODEL defaults to $SKINLAB_EXPORT_DIR/humanoid-walk.glb (the tests' export folder).
import {existsSync} from 'node:fs';
import {dirname, join, resolve} from 'node:path';
import {fileURLToPath} from 'node:url';
import {launch, newPage} from '../test/support/browser.mjs';
import {serve} from '../test/support/server.mjs';

const PACKAGE = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const model = resolve(process.argv[2] ?? join(process.env.SKINLAB_EXPORT_DIR ?? '.', 'humanoid-walk.glb'));
if (!existsSync(model)) {
    console.error(`screenshot: no model at ${model} (export it: skinlab export assets/characters/humanoid-walk.glb`
        + ' --out humanoid-walk.glb --methods lbs,dqs,cor, and pass its path)');
    process.exit(1);
}
const method = process.env.METHOD ?? 'cor';
const time = process.env.TIME ?? '0.25';
const focus = process.env.FOCUS ?? 'shin_R';
const server = await serve(PACKAGE, {'/example/model.glb': model});
const browser = await launch();
try {
    const page = await newPage(browser);
    await page.setViewport({width: 1200, height: 700});
    await page.goto(`${server.url}/example/index.html?method=${method}&time=${time}&focus=${focus}`);
    await page.waitForFunction('window.exampleReady === true', {timeout: 60000});
    const out = join(PACKAGE, 'docs', process.env.OUT ?? 'example.png');
    await page.screenshot({path: out});
    console.log('wrote ' + out);
} finally {
    await browser.close();
    await server.close();
}
