// The palette split (src/palette.js) against cases derived by hand from the definitions in core's
// JointPalette: M = D S, X = M B = [R|x] S0, S = B S0 B^-1, D = [R|x] B^-1, R keeping X's Y axis.
import {test} from 'node:test';
import assert from 'node:assert/strict';
import {bindPivots, splitPalette, TEXELS_PER_JOINT} from '../src/palette.js';

const EPS = 1e-6;

/** Row-major 4x4 helpers, written for the test (not the add-on's code). */
function mul(a, b) {
    const c = new Array(16).fill(0);
    for (let r = 0; r < 4; r++) {
        for (let k = 0; k < 4; k++) {
            for (let col = 0; col < 4; col++) {
                c[4 * r + col] += a[4 * r + k] * b[4 * k + col];
            }
        }
    }
    return c;
}

function affine(linear, t = [0, 0, 0]) {
    return [...linear[0], t[0], ...linear[1], t[1], ...linear[2], t[2], 0, 0, 0, 1];
}

function rotationZ(deg) {
    const a = deg * Math.PI / 180;
    return [[Math.cos(a), -Math.sin(a), 0], [Math.sin(a), Math.cos(a), 0], [0, 0, 1]];
}

function rotationX(deg) {
    const a = deg * Math.PI / 180;
    return [[1, 0, 0], [0, Math.cos(a), -Math.sin(a)], [0, Math.sin(a), Math.cos(a)]];
}

/** Inverse of a rigid row-major 4x4. */
function invertRigid(m) {
    const r = [[m[0], m[4], m[8]], [m[1], m[5], m[9]], [m[2], m[6], m[10]]];
    const t = [m[3], m[7], m[11]];
    return affine(r, r.map(row => -(row[0] * t[0] + row[1] * t[1] + row[2] * t[2])));
}

function columnMajor(m) {
    const c = new Array(16);
    for (let r = 0; r < 4; r++) {
        for (let k = 0; k < 4; k++) {
            c[4 * k + r] = m[4 * r + k];
        }
    }
    return c;
}

function rows3x4(m) {
    return m.slice(0, 12);
}

/** Splits one joint: bind frame B (row-major rigid 4x4), skinning matrix M (row-major 4x4). */
function splitOne(bindFrame, m) {
    const pivots = bindPivots(columnMajor(invertRigid(bindFrame)));
    const texels = new Float32Array(4 * TEXELS_PER_JOINT);
    const flags = splitPalette(rows3x4(m), pivots, texels);
    return {flags, matrix: [...texels.slice(0, 12)], scale: [...texels.slice(12, 24)],
        rotation: [...texels.slice(24, 28)], dual: [...texels.slice(28, 32)]};
}

function near(actual, expected, what) {
    assert.equal(actual.length, expected.length, what);
    actual.forEach((v, i) => assert.ok(Math.abs(v - expected[i]) < EPS, `${what}[${i}]: ${v}, expected ${expected[i]}`));
}

/** The translation a unit dual quaternion carries: 2 d conj(r). */
function translationOf(r, d) {
    const [x, y, z, w] = r;
    const [a, b, c, e] = d;
    // (d * conj(r)).xyz with conj(r) = (-x, -y, -z, w)
    return [2 * (e * -x + a * w + (b * -z - c * -y)), 2 * (e * -y + b * w + (c * -x - a * -z)),
        2 * (e * -z + c * w + (a * -y - b * -x))];
}

test('a rigid joint keeps its matrix as D, the identity as S, and its rotation and translation as dual quaternion', () => {
    const m = affine(rotationZ(90), [1, 2, 3]);
    const s = splitOne(affine(rotationX(0)), m);
    assert.deepEqual(s.flags, {hasScale: false, matricesMirror: false, scalesMirror: false});
    near(s.matrix, rows3x4(m), 'M');
    near(s.scale, [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0], 'S');
    near(s.rotation, [0, 0, Math.SQRT1_2, Math.SQRT1_2], 'rotation');
    near(translationOf(s.rotation, s.dual), [1, 2, 3], 'translation');
});

test('a joint scaled along its bone axis in a turned bind frame splits into D = [R|x] B^-1 and S = B S0 B^-1', () => {
    // Bind frame B: 90 degrees about X, at (0, 1, 0). Posed frame X = [R|x] S0: 90 degrees about
    // Z at (5, 0, 0), scaled 3 times along its Y (bone) axis.
    const bind = affine(rotationX(90), [0, 1, 0]);
    const rigid = affine(rotationZ(90), [5, 0, 0]);
    const s0 = affine([[1, 0, 0], [0, 3, 0], [0, 0, 1]]);
    const m = mul(mul(rigid, s0), invertRigid(bind));
    const s = splitOne(bind, m);
    assert.equal(s.flags.hasScale, true);
    const d = mul(rigid, invertRigid(bind));
    const scale = mul(mul(bind, s0), invertRigid(bind));
    near(s.scale, rows3x4(scale), 'S');
    // D's rotation: rotationZ(90) * rotationX(-90).
    const dq = s.rotation;
    const rz = [0, 0, Math.SQRT1_2, Math.SQRT1_2];
    const rxInv = [-Math.SQRT1_2, 0, 0, Math.SQRT1_2];
    const product = [
        rz[3] * rxInv[0] + rz[0] * rxInv[3] + rz[1] * rxInv[2] - rz[2] * rxInv[1],
        rz[3] * rxInv[1] - rz[0] * rxInv[2] + rz[1] * rxInv[3] + rz[2] * rxInv[0],
        rz[3] * rxInv[2] + rz[0] * rxInv[1] - rz[1] * rxInv[0] + rz[2] * rxInv[3],
        rz[3] * rxInv[3] - rz[0] * rxInv[0] - rz[1] * rxInv[1] - rz[2] * rxInv[2],
    ];
    near(dq, product, 'rotation');
    near(translationOf(dq, s.dual), [d[3], d[7], d[11]], 'translation of D');
    // M = D S: the split loses nothing.
    near(rows3x4(mul(d, scale)), s.matrix, 'D S');
    // S is the scale about the bind frame: the bind head (0, 1, 0) stays put, the bone axis (B's Y,
    // world Z) is stretched 3 times.
    const apply = (a, p) => [0, 1, 2].map(r => a[4 * r] * p[0] + a[4 * r + 1] * p[1] + a[4 * r + 2] * p[2] + a[4 * r + 3]);
    near(apply(s.scale, [0, 1, 0]), [0, 1, 0], 'S at the head');
    near(apply(s.scale, [0, 1, 1]), [0, 1, 3], 'S along the bone');
});

test('a sheared frame keeps its Y axis in R (Blender\'s choice), not the polar rotation', () => {
    // X's columns: (1, 0, 0) and Y = (0.5, 1, 0), Z = (0, 0, 1): R's Y column is Y / |Y|.
    const m = affine([[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]);
    const s = splitOne(affine(rotationX(0)), m);
    assert.equal(s.flags.hasScale, true);
    const angle = Math.atan2(-0.5, 1); // Y turned from (0, 1, 0) towards +x: about Z by -atan(0.5)
    near(s.rotation, [0, 0, Math.sin(angle / 2), Math.cos(angle / 2)], 'rotation');
});

test('a mirroring matrix sets matricesMirror, and a mirroring scale part scalesMirror', () => {
    const m = affine([[-1, 0, 0], [0, 1, 0], [0, 0, 1]]);
    const s = splitOne(affine(rotationX(0)), m);
    assert.deepEqual(s.flags, {hasScale: true, matricesMirror: true, scalesMirror: true});
    near(rows3x4(mul(affine([[1, 0, 0], [0, 1, 0], [0, 0, 1]]), m)), s.matrix, 'M');
});

test('unit columns within Blender\'s 1e-4 count as rigid', () => {
    const m = affine([[1 + 2e-5, 0, 0], [0, 1, 0], [0, 0, 1]]);
    assert.equal(splitOne(affine(rotationX(0)), m).flags.hasScale, false);
    const n = affine([[1 + 2e-4, 0, 0], [0, 1, 0], [0, 0, 1]]);
    assert.equal(splitOne(affine(rotationX(0)), n).flags.hasScale, true);
});
