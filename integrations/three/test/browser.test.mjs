// The browser tests need Chromium; without it they must fail, not vanish (a skip is only for
// SKINLAB_THREE_SKIP_BROWSER=1, which says so in the output).
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {CHROMIUM, chromiumAvailable} from './support/browser.mjs';

const SKIP = process.env.SKINLAB_THREE_SKIP_BROWSER === '1'
    ? 'SKINLAB_THREE_SKIP_BROWSER=1: the browser tests are skipped' : false;

test('Chromium is installed for the GPU tests', {skip: SKIP}, () => {
    assert.ok(chromiumAvailable(), `no Chromium at ${CHROMIUM}: apt-get install chromium, or set CHROMIUM`);
});
