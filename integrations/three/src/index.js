// skinlab's skinning methods for three.js: switch a SkinnedMesh between three's own linear blend
// skinning (LBS), skinlab's dual quaternion skinning (DQS, with its scale phase) and skinning
// with optimised centres of rotation (CoR, Le and Hodgins 2016, from the _COR_CENTER attribute
// `skinlab export --methods cor` writes). The GPU formulas are core's skinning.glsl; the per-frame
// palette (each joint's matrix, scale part and dual quaternion) is filled here from three's
// skeleton. See README.md.
import {DataTexture, FloatType, Matrix4, NearestFilter, RGBAFormat} from 'three';
import {bindPivots, splitPalette, TEXELS_PER_JOINT} from './palette.js';
import {COR_ATTRIBUTE, skinningVertexShader} from './shader.js';

export {COR_ATTRIBUTE} from './shader.js';
export {bindPivots, splitPalette, TEXELS_PER_JOINT} from './palette.js';

/** The methods {@link setSkinningMethod} takes. */
export const SKINNING_METHODS = Object.freeze(['lbs', 'dqs', 'cor']);

/** Per skinned mesh: its own materials, the method materials made from them, its palette. */
const states = new WeakMap();

/**
 * Switches how three skins each SkinnedMesh in {@code object} (itself or its descendants):
 * 'lbs' is three's own skinning, 'dqs' and 'cor' skinlab's. The mesh keeps its material's kind,
 * maps, morphs and lighting: it gets a copy of its material(s) per method whose vertex shader has
 * three's skinbase, skinnormal and skinning chunks replaced (through onBeforeCompile and
 * customProgramCacheKey); 'lbs' gives it back the material(s) it had. Switching again is cheap
 * (each method's program is compiled once).
 *
 * @param {import('three').Object3D} object a SkinnedMesh, or a tree holding some (e.g. gltf.scene)
 * @param {'lbs'|'dqs'|'cor'} method the method
 * @returns {number} how many skinned meshes were switched
 * @throws {Error} for an unknown method, or 'cor' where a skinned mesh has no _COR_CENTER
 *   attribute (nothing is switched then)
 */
export function setSkinningMethod(object, method) {
    if (!SKINNING_METHODS.includes(method)) {
        throw new Error(`skinlab-three: unknown skinning method '${method}' (expected ${SKINNING_METHODS.join(', ')})`);
    }
    const meshes = [];
    object.traverse(o => {
        if (o.isSkinnedMesh) {
            meshes.push(o);
        }
    });
    if (method === 'cor') {
        const without = meshes.filter(m => !m.geometry.getAttribute(COR_ATTRIBUTE));
        if (without.length > 0) {
            throw new Error(`skinlab-three: CoR needs the ${COR_ATTRIBUTE.toUpperCase()} vertex attribute, which `
                + `${without.map(m => `'${m.name}'`).join(', ')} lack${without.length === 1 ? 's' : ''} (write the file`
                + ' with `skinlab export FILE --out OUT.glb --methods cor`)');
        }
    }
    for (const mesh of meshes) {
        stateOf(mesh).use(mesh, method);
    }
    return meshes.length;
}

/**
 * The method a skinned mesh is drawn with.
 *
 * @param {import('three').SkinnedMesh} mesh
 * @returns {'lbs'|'dqs'|'cor'} 'lbs' unless {@link setSkinningMethod} chose another
 */
export function skinningMethodOf(mesh) {
    return states.get(mesh)?.method ?? 'lbs';
}

function stateOf(mesh) {
    let state = states.get(mesh);
    if (!state) {
        state = new MeshSkinning(mesh);
        states.set(mesh, state);
    }
    return state;
}

/** One skinned mesh's materials per method and its palette texture. */
class MeshSkinning {
    constructor(mesh) {
        this.method = 'lbs';
        this.original = mesh.material;
        this.materials = new Map([['lbs', mesh.material]]);
        const joints = mesh.skeleton.bones.length;
        this.texels = new Float32Array(4 * TEXELS_PER_JOINT * joints);
        this.texture = new DataTexture(this.texels, TEXELS_PER_JOINT, joints, RGBAFormat, FloatType);
        this.texture.minFilter = NearestFilter;
        this.texture.magFilter = NearestFilter;
        this.texture.generateMipmaps = false;
        this.uniforms = {
            skinlabPalette: {value: this.texture},
            uHasScale: {value: false},
            uMatricesMirror: {value: false},
            uScalesMirror: {value: false},
        };
        this.influences = mesh.geometry.getAttribute('joints_1') && mesh.geometry.getAttribute('weights_1') ? 8 : 4;
        this.bindMatrix = new Matrix4().set(NaN, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
        this.pivots = null;
        this.matrices = new Float64Array(12 * joints);
        this.frame = -1;
        this.boneMatrix = new Matrix4();
        const previous = mesh.onBeforeRender;
        const state = this;
        mesh.onBeforeRender = function (renderer, ...rest) {
            if (state.method !== 'lbs') {
                state.update(this, renderer);
            }
            previous.call(this, renderer, ...rest);
        };
    }

    use(mesh, method) {
        if (!this.materials.has(method)) {
            const make = m => this.methodMaterial(m, method);
            this.materials.set(method, Array.isArray(this.original) ? this.original.map(make) : make(this.original));
        }
        mesh.material = this.materials.get(method);
        this.method = method;
        this.frame = -1;
    }

    methodMaterial(material, method) {
        const copy = material.clone();
        const influences = this.influences;
        const uniforms = this.uniforms;
        copy.onBeforeCompile = shader => {
            Object.assign(shader.uniforms, uniforms);
            shader.vertexShader = skinningVertexShader(shader.vertexShader, method, influences);
        };
        copy.customProgramCacheKey = () => `skinlab-${method}-${influences}`;
        return copy;
    }

    /** This frame's palette from three's bone matrices (computed by three before onBeforeRender). */
    update(mesh, renderer) {
        const frame = renderer.info.render.frame;
        if (frame === this.frame) {
            return;
        }
        this.frame = frame;
        const skeleton = mesh.skeleton;
        const joints = skeleton.bones.length;
        const identity = isIdentity(mesh.bindMatrix);
        if (this.pivots === null || !this.bindMatrix.equals(mesh.bindMatrix)) {
            // The joints' inverse bind matrices in the mesh's bind space: boneInverse * bindMatrix.
            const bind = new Float64Array(16 * joints);
            const m = new Matrix4();
            for (let j = 0; j < joints; j++) {
                m.multiplyMatrices(skeleton.boneInverses[j], mesh.bindMatrix);
                bind.set(m.elements, 16 * j);
            }
            this.pivots = bindPivots(bind);
            this.bindMatrix.copy(mesh.bindMatrix);
        }
        // M_j = bindMatrixInverse * boneMatrix_j * bindMatrix, row-major 3x4.
        const bones = skeleton.boneMatrices;
        const b = this.boneMatrix;
        for (let j = 0; j < joints; j++) {
            let e = bones;
            let at = 16 * j;
            if (!identity) {
                b.fromArray(bones, at).premultiply(mesh.bindMatrixInverse).multiply(mesh.bindMatrix);
                e = b.elements;
                at = 0;
            }
            const o = 12 * j;
            for (let r = 0; r < 3; r++) {
                this.matrices[o + 4 * r] = e[at + r];
                this.matrices[o + 4 * r + 1] = e[at + 4 + r];
                this.matrices[o + 4 * r + 2] = e[at + 8 + r];
                this.matrices[o + 4 * r + 3] = e[at + 12 + r];
            }
        }
        const flags = splitPalette(this.matrices, this.pivots, this.texels);
        this.uniforms.uHasScale.value = flags.hasScale;
        this.uniforms.uMatricesMirror.value = flags.matricesMirror;
        this.uniforms.uScalesMirror.value = flags.scalesMirror;
        this.texture.needsUpdate = true;
    }
}

function isIdentity(m) {
    const e = m.elements;
    for (let i = 0; i < 16; i++) {
        if (e[i] !== (i % 5 === 0 ? 1 : 0)) {
            return false;
        }
    }
    return true;
}
