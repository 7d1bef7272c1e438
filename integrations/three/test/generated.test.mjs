// The package's copy of core's skinning.glsl must be core's file as it is now.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {readFileSync} from 'node:fs';
import {CORE_GLSL, GENERATED, moduleText} from '../scripts/build-glsl.mjs';
import glsl from '../src/generated/skinning-glsl.js';

test('src/generated/skinning-glsl.js is core\'s skinning.glsl (else run npm run build)', () => {
    const core = readFileSync(CORE_GLSL, 'utf8');
    assert.equal(glsl, core, 'the generated GLSL differs from core\'s file: run `npm run build` in integrations/three');
    assert.equal(readFileSync(GENERATED, 'utf8'), moduleText(core));
});
