// One frame's joint palette for the GPU, as core's org.skinlab.skinning.JointPalette and
// ScaleSplit derive it: per joint the skinning matrix M (row-major 3x4, in the mesh's bind
// space), its scale part S and the dual quaternion of its rigid part D, with M = D S (Kavan et
// al. 2008, section 4). S is centred on the joint's bind frame and R keeps the posed frame's Y
// axis (Blender's choice); JointPalette's class comment gives the reasons. The arithmetic is in
// doubles here and in floats in core; both round to the same floats up to a few ulps.

import {Matrix4} from 'three';

const IDENTITY = Object.freeze([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);

/** Texels (RGBA floats) per joint in the palette texture: M rows 0-2, S rows 3-5, rotation 6, dual 7. */
export const TEXELS_PER_JOINT = 8;
export const MATRIX_ROWS = 0;
export const SCALE_ROWS = 3;
export const ROTATION_TEXEL = 6;
export const DUAL_TEXEL = 7;

/**
 * The rigid part B of each joint's bind frame, row-major 3x4: the polar rotation of
 * inverse(bind) and its translation (core's ScaleSplit constructor).
 *
 * @param {ArrayLike<number>} bindMatrices per joint 16 numbers column-major: the matrix that takes
 *   bind-space points into the joint's frame (glTF's inverse bind matrix, in the mesh's bind space)
 * @returns {Float64Array} 12 numbers per joint
 */
export function bindPivots(bindMatrices) {
    const joints = bindMatrices.length / 16;
    const pivots = new Float64Array(12 * joints);
    for (let j = 0; j < joints; j++) {
        const bind = new Matrix4().fromArray(bindMatrices, 16 * j);
        const det = bind.determinant();
        // Singular or not finite: centre scale at the origin, as core does.
        const base = det !== 0 && Number.isFinite(det) && bind.invert().elements.every(Number.isFinite)
            ? bind.elements : IDENTITY;
        // Columns of the linear part.
        const cols = [[base[0], base[1], base[2]], [base[4], base[5], base[6]], [base[8], base[9], base[10]]];
        const r = rotationOf(cols);
        const o = 12 * j;
        for (let row = 0; row < 3; row++) {
            pivots[o + 4 * row] = r[0][row];
            pivots[o + 4 * row + 1] = r[1][row];
            pivots[o + 4 * row + 2] = r[2][row];
            pivots[o + 4 * row + 3] = base[12 + row];
        }
    }
    return pivots;
}

/** Scratch of {@link splitPalette}: one joint's D, S and rotation quaternion. */
const D = new Float64Array(12);
const S = new Float64Array(12);
const Q = new Float64Array(4);

/**
 * Splits every joint's matrix into D and S and writes the palette's texels.
 *
 * @param {ArrayLike<number>} matrices per joint 12 numbers, row-major 3x4 (M)
 * @param {Float64Array} pivots from {@link bindPivots}
 * @param {Float32Array} texels out: {@link TEXELS_PER_JOINT} x 4 floats per joint
 * @returns {{hasScale: boolean, matricesMirror: boolean, scalesMirror: boolean}} what the
 *   shader's uniforms uHasScale, uMatricesMirror and uScalesMirror get
 */
export function splitPalette(matrices, pivots, texels) {
    const joints = matrices.length / 12;
    let hasScale = false;
    let matricesMirror = false;
    let scalesMirror = false;
    const d = D;
    const s = S;
    const q = Q;
    for (let j = 0; j < joints; j++) {
        const o = 12 * j;
        const scaled = split(matrices, pivots, o, d, s);
        hasScale ||= scaled;
        matricesMirror ||= det3(matrices, o) < 0;
        if (scaled) {
            scalesMirror ||= det3(s, 0) < 0;
        }
        quaternionOf(d, q);
        const t = 4 * TEXELS_PER_JOINT * j;
        for (let i = 0; i < 12; i++) {
            texels[t + 4 * MATRIX_ROWS + i] = matrices[o + i];
            texels[t + 4 * SCALE_ROWS + i] = s[i];
        }
        const [x, y, z, w] = q;
        const tx = d[3], ty = d[7], tz = d[11];
        const r = t + 4 * ROTATION_TEXEL;
        texels[r] = x;
        texels[r + 1] = y;
        texels[r + 2] = z;
        texels[r + 3] = w;
        // The dual part (t, 0) q / 2, as core's DualQuaternion.set.
        const u = t + 4 * DUAL_TEXEL;
        texels[u] = 0.5 * (tx * w + ty * z - tz * y);
        texels[u + 1] = 0.5 * (-tx * z + ty * w + tz * x);
        texels[u + 2] = 0.5 * (tx * y - ty * x + tz * w);
        texels[u + 3] = -0.5 * (tx * x + ty * y + tz * z);
    }
    return {hasScale, matricesMirror, scalesMirror: hasScale && scalesMirror};
}

/** Scratch of the split: the posed frame's linear part and its rotation, as columns. */
const X = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
const XT = [0, 0, 0];

/**
 * Joint at offset o of matrices into D and S; true when it has a scale part (ScaleSplit.split).
 * Allocation-free for rigid joints (the common case); a scaled joint allocates a few small arrays.
 */
function split(m, p, o, d, s) {
    // Xl = Ml Bl, the posed joint frame's linear part, as columns.
    for (let c = 0; c < 3; c++) {
        for (let r = 0; r < 3; r++) {
            X[c][r] = m[o + 4 * r] * p[o + c] + m[o + 4 * r + 1] * p[o + 4 + c] + m[o + 4 * r + 2] * p[o + 8 + c];
        }
    }
    if (isRigid(X)) {
        for (let i = 0; i < 12; i++) {
            d[i] = m[o + i];
            s[i] = i === 0 || i === 5 || i === 10 ? 1 : 0;
        }
        return false;
    }
    const rot = boneAxisFrame(X); // columns
    // D = [R Bl^T | x - Dl b], x the translation of X = M B.
    for (let r = 0; r < 3; r++) {
        XT[r] = m[o + 4 * r] * p[o + 3] + m[o + 4 * r + 1] * p[o + 7] + m[o + 4 * r + 2] * p[o + 11] + m[o + 4 * r + 3];
    }
    for (let r = 0; r < 3; r++) {
        for (let c = 0; c < 3; c++) {
            // (R Bl^T)[r][c] = sum_k R[r][k] Bl[c][k]
            d[4 * r + c] = rot[0][r] * p[o + 4 * c] + rot[1][r] * p[o + 4 * c + 1] + rot[2][r] * p[o + 4 * c + 2];
        }
        d[4 * r + 3] = XT[r] - (d[4 * r] * p[o + 3] + d[4 * r + 1] * p[o + 7] + d[4 * r + 2] * p[o + 11]);
    }
    // S = [Dl^T Ml | Dl^T (m - d)].
    const e0 = m[o + 3] - d[3];
    const e1 = m[o + 7] - d[7];
    const e2 = m[o + 11] - d[11];
    for (let r = 0; r < 3; r++) {
        for (let c = 0; c < 3; c++) {
            s[4 * r + c] = d[r] * m[o + c] + d[4 + r] * m[o + 4 + c] + d[8 + r] * m[o + 8 + c];
        }
        s[4 * r + 3] = d[r] * e0 + d[4 + r] * e1 + d[8 + r] * e2;
    }
    return true;
}

/** Unit columns to within Blender's 1e-4 and no reflection (ScaleSplit.isRigid). */
function isRigid(x) {
    const [a, b, c] = x;
    const l0 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2] - 1;
    const l1 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2] - 1;
    const l2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - 1;
    const det = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    return !(l0 * l0 + l1 * l1 + l2 * l2 > 4e-8 || det < 0);
}

/** The rotation keeping the frame's Y axis (Blender's orthogonalize_m4 with axis 1), as columns. */
function boneAxisFrame(x) {
    const y = x[1];
    const z = cross(x[0], y);
    const yl = Math.hypot(...y);
    const zl = Math.hypot(...z);
    if (yl > 1e-12 && zl > 1e-12 * yl) {
        const yn = y.map(v => v / yl);
        const zn = z.map(v => v / zl);
        return [cross(yn, zn), yn, zn];
    }
    return rotationOf(x);
}

/**
 * The rotation of a 3x3 matrix given as columns (core's AnimationHelper.rotationOf): the
 * orthogonal polar factor by Higham's scaled Newton iteration, of minus the matrix when it
 * reflects; Gram-Schmidt on the usable columns of a (near) singular one.
 */
export function rotationOf(cols) {
    let a = cols.map(c => c.slice());
    let det = dot(a[0], cross(a[1], a[2]));
    if (det < 0) {
        a = a.map(c => c.map(v => -v));
        det = -det;
    }
    const norm = frobenius(a);
    if (!(norm > 0) || !(det > 1e-12 * norm * norm * norm)) {
        return gramSchmidt(a);
    }
    let xm = a;
    for (let i = 0; i < 30; i++) {
        const inv = inverseTransposeColumns(xm);
        const g = Math.sqrt(frobenius(inv) / frobenius(xm));
        let change = 0;
        const next = xm.map((c, ci) => c.map((v, ri) => {
            const n = 0.5 * (g * v + inv[ci][ri] / g);
            change = Math.max(change, Math.abs(n - v));
            return n;
        }));
        xm = next;
        if (change < 1e-14) {
            break;
        }
    }
    return xm;
}

function gramSchmidt(c) {
    const u = [null, null, null];
    let first = -1;
    let second = -1;
    for (let i = 0; i < 3 && second < 0; i++) {
        let v = c[i].slice();
        if (first >= 0) {
            const dd = dot(v, u[first]);
            v = v.map((x, k) => x - dd * u[first][k]);
        }
        const len = Math.hypot(...v);
        if (len > 1e-9) {
            u[i] = v.map(x => x / len);
            if (first < 0) {
                first = i;
            } else {
                second = i;
            }
        }
    }
    if (first < 0) {
        return [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
    }
    if (second < 0) {
        const k = u[first];
        const e = Math.abs(k[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
        const dd = dot(e, k);
        const v = e.map((x, i) => x - dd * k[i]);
        const len = Math.hypot(...v);
        second = (first + 1) % 3;
        u[second] = v.map(x => x / len);
    }
    const k = 3 - first - second;
    u[k] = cross(u[(k + 1) % 3], u[(k + 2) % 3]);
    return u;
}

/** Shepperd's method on D's rotation (row-major in d), normalised (ScaleSplit.quaternionOf). */
function quaternionOf(d, q) {
    const r00 = d[0], r01 = d[1], r02 = d[2], r10 = d[4], r11 = d[5], r12 = d[6], r20 = d[8], r21 = d[9], r22 = d[10];
    let x, y, z, w;
    const trace = r00 + r11 + r22;
    if (trace >= 0) {
        let s = Math.sqrt(trace + 1);
        w = s * 0.5;
        s = 0.5 / s;
        x = (r21 - r12) * s;
        y = (r02 - r20) * s;
        z = (r10 - r01) * s;
    } else if (r00 >= r11 && r00 >= r22) {
        let s = Math.sqrt(r00 - (r11 + r22) + 1);
        x = s * 0.5;
        s = 0.5 / s;
        y = (r01 + r10) * s;
        z = (r02 + r20) * s;
        w = (r21 - r12) * s;
    } else if (r11 > r22) {
        let s = Math.sqrt(r11 - (r22 + r00) + 1);
        y = s * 0.5;
        s = 0.5 / s;
        x = (r01 + r10) * s;
        z = (r12 + r21) * s;
        w = (r02 - r20) * s;
    } else {
        let s = Math.sqrt(r22 - (r00 + r11) + 1);
        z = s * 0.5;
        s = 0.5 / s;
        x = (r02 + r20) * s;
        y = (r12 + r21) * s;
        w = (r10 - r01) * s;
    }
    const il = 1 / Math.sqrt(x * x + y * y + z * z + w * w);
    q[0] = x * il;
    q[1] = y * il;
    q[2] = z * il;
    q[3] = w * il;
}

function det3(m, o) {
    return m[o] * (m[o + 5] * m[o + 10] - m[o + 9] * m[o + 6])
        + m[o + 1] * (m[o + 6] * m[o + 8] - m[o + 10] * m[o + 4])
        + m[o + 2] * (m[o + 4] * m[o + 9] - m[o + 8] * m[o + 5]);
}

function dot(a, b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

function cross(a, b) {
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function frobenius(c) {
    return Math.sqrt(c.reduce((s, col) => s + dot(col, col), 0));
}

/** The inverse transpose of a 3x3 given as columns, as columns: the cofactors over the determinant. */
function inverseTransposeColumns(c) {
    const det = dot(c[0], cross(c[1], c[2]));
    return [cross(c[1], c[2]), cross(c[2], c[0]), cross(c[0], c[1])].map(v => v.map(x => x / det));
}
