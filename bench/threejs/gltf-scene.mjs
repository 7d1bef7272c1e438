// How the three.js references load and pose a glTF file, shared by gltf-reference.mjs (every clip
// alone) and blend-reference.mjs (clips blended by an AnimationMixer): the file is parsed from an
// ArrayBuffer, a triangle mesh's vertices are read in three's traversal order, and two things
// three.js does differently from the specification are put right (docs/references.md, "glTF:
// three.js"):
//  - JOINTS_1/WEIGHTS_1 (more than four influences): three skins four. For such a primitive
//    worldPositions blends every set with three's bone matrices (bones[j].matrixWorld *
//    boneInverses[j], as SkinnedMesh.applyBoneTransform does), from the accessors as stored
//    (GLTFLoader has renormalized the first four weights in place).
//  - Rotations are made unit quaternions first (normalizeRotations: node rotations, LINEAR and STEP
//    keys), as the specification defines them and our importer reads them; three.js would
//    otherwise scale a mesh by |q|^2 where a file's keys are a little off unit length
//    (SimpleSkin's 0.707, normalized-integer keys).
// Textures and images are removed before parsing (Node has no image decoder); geometry and
// animation are untouched. All buffers (data URIs, files beside a .gltf, a GLB's chunk) are joined
// into one GLB in memory, which GLTFLoader parses without fetching.
//
// Positions are rounded to 7 significant digits (float32 holds about 7).
import { readFileSync } from 'node:fs';
import path from 'node:path';
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

/**
 * The file as one GLB in an ArrayBuffer: all buffers (GLB chunk, data URIs, files beside it)
 * joined into the BIN chunk with the buffer views moved accordingly, and no textures or images.
 */
export function prepare(file) {
    const bytes = readFileSync(file);
    let json;
    let bin = null;
    if (bytes.readUInt32LE(0) === 0x46546c67) {
        let offset = 12;
        while (offset < bytes.length) {
            const length = bytes.readUInt32LE(offset);
            const type = bytes.readUInt32LE(offset + 4);
            const chunk = bytes.subarray(offset + 8, offset + 8 + length);
            if (type === 0x4e4f534a) {
                json = JSON.parse(new TextDecoder().decode(chunk));
            } else if (type === 0x004e4942) {
                bin = chunk;
            }
            offset += 8 + length;
        }
    } else {
        json = JSON.parse(new TextDecoder().decode(bytes));
    }
    const folder = path.dirname(file);
    const parts = [];
    const starts = [];
    let total = 0;
    for (const buffer of json.buffers ?? []) {
        let data;
        if (buffer.uri === undefined) {
            data = bin;
        } else if (buffer.uri.startsWith('data:')) {
            data = Buffer.from(buffer.uri.slice(buffer.uri.indexOf(',') + 1), 'base64');
        } else {
            data = readFileSync(path.join(folder, decodeURIComponent(buffer.uri)));
        }
        starts.push(total);
        parts.push(data, Buffer.alloc((4 - data.length % 4) % 4));
        total += data.length + (4 - data.length % 4) % 4;
    }
    for (const view of json.bufferViews ?? []) {
        view.byteOffset = (view.byteOffset ?? 0) + starts[view.buffer];
        view.buffer = 0;
    }
    if (parts.length > 0) {
        json.buffers = [{ byteLength: total }];
    }
    delete json.textures;
    delete json.images;
    delete json.samplers;
    for (const material of json.materials ?? []) {
        dropTextureInfos(material);
    }
    return { json, bin: Buffer.concat(parts) };
}

function glb(json, bin) {
    let text = Buffer.from(JSON.stringify(json));
    text = Buffer.concat([text, Buffer.alloc((4 - text.length % 4) % 4, 0x20)]);
    const header = Buffer.alloc(12);
    const total = 12 + 8 + text.length + (bin.length > 0 ? 8 + bin.length : 0);
    header.writeUInt32LE(0x46546c67, 0);
    header.writeUInt32LE(2, 4);
    header.writeUInt32LE(total, 8);
    const chunk = (type, data) => {
        const h = Buffer.alloc(8);
        h.writeUInt32LE(data.length, 0);
        h.writeUInt32LE(type, 4);
        return [h, data];
    };
    const all = Buffer.concat([header, ...chunk(0x4e4f534a, text), ...(bin.length > 0 ? chunk(0x004e4942, bin) : [])]);
    return all.buffer.slice(all.byteOffset, all.byteOffset + all.length);
}

function dropTextureInfos(object) {
    for (const key of Object.keys(object)) {
        const value = object[key];
        if (value && typeof value === 'object') {
            if (typeof value.index === 'number' && key.endsWith('Texture')) {
                delete object[key];
            } else {
                dropTextureInfos(value);
            }
        }
    }
}

export function load(doc) {
    const bytes = glb(structuredClone(doc.json), doc.bin);
    return new Promise((resolve, reject) => new GLTFLoader().parse(bytes, '', resolve, reject));
}

/**
 * Triangle meshes with their glTF node, mesh and primitive, in three's traversal order of the
 * scene: depth first, a node's primitives (in order) before its children, scene roots in order.
 */
export function meshesOf(gltf) {
    const found = [];
    const associations = gltf.parser.associations;
    gltf.scene.traverse((object) => {
        if (!object.isMesh) {
            return;
        }
        const own = associations.get(object) ?? {};
        const node = own.nodes ?? associations.get(object.parent)?.nodes;
        found.push({ object, node, mesh: own.meshes, primitive: own.primitives });
    });
    return found;
}

/**
 * Per mesh, for primitives with a second joint set, every JOINTS_n/WEIGHTS_n set read from the
 * file (not through GLTFLoader, whose cached WEIGHTS_0 attribute it has renormalized in place);
 * null for the others.
 */
export function eightInfluenceData(doc, meshes) {
    return meshes.map((m) => {
        const attributes = doc.json.meshes[m.mesh].primitives[m.primitive].attributes;
        if (attributes.JOINTS_1 === undefined || !m.object.isSkinnedMesh) {
            return null;
        }
        const sets = [];
        for (let s = 0; attributes[`JOINTS_${s}`] !== undefined; s++) {
            sets.push({ joints: readAccessor(doc, attributes[`JOINTS_${s}`]),
                weights: readAccessor(doc, attributes[`WEIGHTS_${s}`]) });
        }
        return sets;
    });
}

const COMPONENTS = {
    5120: ['getInt8', 1, 127], 5121: ['getUint8', 1, 255], 5122: ['getInt16', 2, 32767],
    5123: ['getUint16', 2, 65535], 5125: ['getUint32', 4, 0], 5126: ['getFloat32', 4, 0],
};

/** A VEC4 accessor's values as { getComponent(i, c) } (normalized integers as reals; sparse applied). */
function readAccessor(doc, index) {
    const a = doc.json.accessors[index];
    const [getter, size, max] = COMPONENTS[a.componentType];
    const data = new DataView(doc.bin.buffer, doc.bin.byteOffset, doc.bin.length);
    const values = new Float64Array(4 * a.count);
    const read = (offset) => {
        const raw = data[getter](offset, true);
        return a.normalized ? Math.max(raw / max, -1) : raw;
    };
    if (a.bufferView !== undefined) {
        const view = doc.json.bufferViews[a.bufferView];
        const stride = view.byteStride ?? 4 * size;
        const start = view.byteOffset + (a.byteOffset ?? 0);
        for (let i = 0; i < a.count; i++) {
            for (let c = 0; c < 4; c++) {
                values[4 * i + c] = read(start + i * stride + c * size);
            }
        }
    }
    if (a.sparse !== undefined) {
        const iv = doc.json.bufferViews[a.sparse.indices.bufferView];
        const vv = doc.json.bufferViews[a.sparse.values.bufferView];
        const [indexGetter, indexSize] = COMPONENTS[a.sparse.indices.componentType];
        for (let k = 0; k < a.sparse.count; k++) {
            const i = data[indexGetter](iv.byteOffset + (a.sparse.indices.byteOffset ?? 0) + k * indexSize, true);
            for (let c = 0; c < 4; c++) {
                values[4 * i + c] = read(vv.byteOffset + (a.sparse.values.byteOffset ?? 0) + (4 * k + c) * size);
            }
        }
    }
    return { getComponent: (i, c) => values[4 * i + c] };
}

/**
 * Rotations as unit quaternions, as the specification defines them: node rotations and the keys
 * of LINEAR and STEP rotation tracks (three.js uses stored keys as they are, so keys a little off
 * unit length, such as rounded decimals or normalized-integer keys, would scale the mesh by
 * |q|^2). CUBICSPLINE tracks hold tangents too and three.js normalizes their results already.
 */
export function normalizeRotations(gltf) {
    gltf.scene.traverse((object) => object.quaternion.normalize());
    for (const clip of gltf.animations) {
        for (const track of clip.tracks) {
            if (track.ValueTypeName !== 'quaternion' || track.values.length !== 4 * track.times.length) {
                continue;
            }
            const v = track.values;
            for (let i = 0; i < v.length; i += 4) {
                const n = Math.hypot(v[i], v[i + 1], v[i + 2], v[i + 3]);
                v[i] /= n;
                v[i + 1] /= n;
                v[i + 2] /= n;
                v[i + 3] /= n;
            }
        }
    }
    return gltf;
}

const _v = new THREE.Vector3();
const _p = new THREE.Vector4();
const _q = new THREE.Vector4();
const _sum = new THREE.Vector4();
const _m = new THREE.Matrix4();

export function worldPositions(entry, sets) {
    const object = entry.object;
    const count = object.geometry.getAttribute('position').count;
    const out = new Array(3 * count);
    for (let i = 0; i < count; i++) {
        if (sets) {
            THREE.Mesh.prototype.getVertexPosition.call(object, i, _v);
            blendAll(object, sets, i, _v);
        } else {
            object.getVertexPosition(i, _v);
            _v.applyMatrix4(object.matrixWorld);
        }
        out[3 * i] = round(_v.x);
        out[3 * i + 1] = round(_v.y);
        out[3 * i + 2] = round(_v.z);
    }
    return out;
}

/** sum over every influence of w * bone.matrixWorld * boneInverse * bindMatrix * p, in world space. */
function blendAll(object, sets, i, v) {
    const bones = object.skeleton.bones;
    const inverses = object.skeleton.boneInverses;
    _p.set(v.x, v.y, v.z, 1).applyMatrix4(object.bindMatrix);
    _sum.set(0, 0, 0, 0);
    for (const set of sets) {
        for (let c = 0; c < 4; c++) {
            const w = set.weights.getComponent(i, c);
            if (w !== 0) {
                const j = set.joints.getComponent(i, c);
                _m.multiplyMatrices(bones[j].matrixWorld, inverses[j]);
                _sum.addScaledVector(_q.copy(_p).applyMatrix4(_m), w);
            }
        }
    }
    v.set(_sum.x, _sum.y, _sum.z);
}

export function round(x) {
    return x === 0 ? 0 : Number(x.toPrecision(7));
}

export function describe(entry, sets, json) {
    const primitive = json.meshes[entry.mesh].primitives[entry.primitive];
    return {
        node: entry.node, mesh: entry.mesh, primitive: entry.primitive, name: entry.object.name,
        // primitives of one mesh with equal attributes share their vertices in an importer
        attributes: JSON.stringify([primitive.attributes, primitive.targets ?? []]),
        skinned: entry.object.isSkinnedMesh === true,
        influences: sets ? 4 * sets.length : entry.object.isSkinnedMesh ? 4 : 0,
        vertices: entry.object.geometry.getAttribute('position').count,
        morphTargets: entry.object.morphTargetInfluences?.length ?? 0,
    };
}

export function sizeOf(rest) {
    const min = [Infinity, Infinity, Infinity];
    const max = [-Infinity, -Infinity, -Infinity];
    for (const m of rest) {
        for (let i = 0; i < m.positions.length; i++) {
            min[i % 3] = Math.min(min[i % 3], m.positions[i]);
            max[i % 3] = Math.max(max[i % 3], m.positions[i]);
        }
    }
    return round(Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]));
}
