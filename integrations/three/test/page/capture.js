// Reads the skinned positions back from the GPU: the model is drawn by three's own pipeline
// (three's program for the material, with the add-on's chunks when DQS or CoR is chosen), and
// the draw call three issues is replaced by one with the same program, uniforms, textures and
// vertex arrays bound, but drawing every vertex once as a point into a transform feedback buffer
// (WebGL2 forbids indexed draws during transform feedback). The vertex shader gets one output
// more, the vertex's world position ((modelMatrix * transformed).xyz, after morphs and skinning),
// named in transformFeedbackVaryings before three links the program.
import * as THREE from 'three';
import {GLTFLoader} from 'three/addons/loaders/GLTFLoader.js';
import {setSkinningMethod} from '../../src/index.js';

const CAPTURED = 'skinlabCaptured';

/** A WebGL2 context whose programs with the captured output are linked for transform feedback. */
export function captureContext() {
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = 4;
    const gl = canvas.getContext('webgl2');
    if (!gl) {
        throw new Error('no WebGL2 context');
    }
    const sources = new WeakMap();
    const shaders = new WeakMap();
    const shaderSource = gl.shaderSource.bind(gl);
    const attachShader = gl.attachShader.bind(gl);
    const linkProgram = gl.linkProgram.bind(gl);
    gl.shaderSource = (shader, source) => {
        sources.set(shader, source);
        shaderSource(shader, source);
    };
    gl.attachShader = (program, shader) => {
        shaders.set(program, [...(shaders.get(program) ?? []), shader]);
        attachShader(program, shader);
    };
    gl.linkProgram = program => {
        if ((shaders.get(program) ?? []).some(s => (sources.get(s) ?? '').includes(`out vec3 ${CAPTURED};`))) {
            gl.transformFeedbackVaryings(program, [CAPTURED], gl.SEPARATE_ATTRIBS);
        }
        linkProgram(program);
    };
    const draws = {};
    let request = null;
    for (const name of ['drawElements', 'drawArrays', 'drawElementsInstanced', 'drawArraysInstanced',
        'drawRangeElements']) {
        draws[name] = gl[name].bind(gl);
        gl[name] = (...args) => {
            if (request === null) {
                draws[name](...args);
                return;
            }
            const r = request;
            request = null;
            r.result = feedback(gl, draws.drawArrays, r.count);
        };
    }
    return {
        canvas,
        gl,
        /** Runs draw() and returns the world positions of the first draw call it makes (count vertices). */
        capture(count, draw) {
            const r = {count, result: null};
            request = r;
            draw();
            request = null;
            if (r.result === null) {
                throw new Error('three issued no draw call for the mesh');
            }
            return r.result;
        },
    };
}

function feedback(gl, drawArrays, count) {
    const program = gl.getParameter(gl.CURRENT_PROGRAM);
    if (gl.getProgramParameter(program, gl.TRANSFORM_FEEDBACK_VARYINGS) !== 1) {
        throw new Error('the bound program was not linked for transform feedback');
    }
    const buffer = gl.createBuffer();
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, buffer);
    gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, 12 * count, gl.STATIC_READ);
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, null);
    const tf = gl.createTransformFeedback();
    gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, tf);
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    gl.enable(gl.RASTERIZER_DISCARD);
    gl.beginTransformFeedback(gl.POINTS);
    drawArrays(gl.POINTS, 0, count);
    gl.endTransformFeedback();
    gl.disable(gl.RASTERIZER_DISCARD);
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
    gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, null);
    const out = new Float32Array(3 * count);
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, buffer);
    gl.getBufferSubData(gl.TRANSFORM_FEEDBACK_BUFFER, 0, out);
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, null);
    gl.deleteTransformFeedback(tf);
    gl.deleteBuffer(buffer);
    const error = gl.getError();
    if (error !== gl.NO_ERROR) {
        throw new Error('WebGL error 0x' + error.toString(16) + ' during transform feedback');
    }
    return out;
}

/** Adds the captured output to the material's vertex shader (after the add-on's rewrite, if any). */
export function withCapture(material) {
    if (material.userData.skinlabCapture) {
        return;
    }
    material.userData.skinlabCapture = true;
    const compile = material.onBeforeCompile;
    const key = material.customProgramCacheKey;
    material.onBeforeCompile = function (shader, renderer) {
        compile.call(this, shader, renderer);
        if (!shader.vertexShader.includes('#include <project_vertex>')) {
            throw new Error('the material\'s vertex shader has no project_vertex chunk');
        }
        shader.vertexShader = `out vec3 ${CAPTURED};\n` + shader.vertexShader.replace('#include <project_vertex>',
            `#include <project_vertex>\n\t${CAPTURED} = (modelMatrix * vec4(transformed, 1.0)).xyz;`);
    };
    material.customProgramCacheKey = function () {
        return key.call(this) + '|capture';
    };
}

/**
 * The placed meshes of the scene in skinlab's order (depth-first over the scene's nodes), each
 * with the three meshes of its glTF primitives.
 */
function placedMeshes(gltf) {
    const json = gltf.parser.json;
    const placed = [];
    const visit = object => {
        const a = gltf.parser.associations.get(object);
        if (a && a.nodes !== undefined && json.nodes[a.nodes].mesh !== undefined) {
            const mi = json.nodes[a.nodes].mesh;
            const primitives = new Map();
            for (const o of [object, ...object.children]) {
                const b = gltf.parser.associations.get(o);
                if (o.isMesh && b && b.meshes === mi && b.primitives !== undefined) {
                    primitives.set(b.primitives, o);
                }
            }
            placed.push({mesh: mi, primitives});
        }
        for (const child of object.children) {
            visit(child);
        }
    };
    visit(gltf.scene);
    return placed;
}

/**
 * skinlab's vertex blocks of a glTF mesh (core's MeshReader): primitives that are drawn as
 * triangles and have POSITION, one block per distinct set of attribute and target accessors, in
 * first-use order. Returns the three mesh of each block's first primitive.
 */
function blocks(meshDef, primitives) {
    const key = attributes => Object.entries(attributes ?? {}).map(([k, v]) => `${k}=${v},`).join('');
    const result = new Map();
    meshDef.primitives.forEach((p, i) => {
        if ((p.mode ?? 4) < 4 || p.attributes.POSITION === undefined) {
            return;
        }
        const k = key(p.attributes) + '|' + (p.targets ?? []).map(t => key(t) + ';').join('');
        if (!result.has(k)) {
            const mesh = primitives.get(i);
            if (!mesh) {
                throw new Error(`no three.js mesh for primitive ${i} of mesh '${meshDef.name}'`);
            }
            result.set(k, mesh);
        }
    });
    return [...result.values()];
}

/**
 * Per vertex of the blocks, its position in skinlab's order (core's PositionWelder): vertices
 * with bitwise equal position, influences (joint and weight of each non-zero weight, in set order)
 * and morph offsets share one position, numbered by first vertex. Returns the first vertex of
 * each position as [block, vertex].
 */
function weld(meshes) {
    const bits = new Float32Array(1);
    const word = new Uint32Array(bits.buffer);
    const f = v => {
        bits[0] = v;
        return word[0].toString(36);
    };
    const seen = new Map();
    const first = [];
    meshes.forEach((mesh, b) => {
        const g = mesh.geometry;
        const pos = g.getAttribute('position');
        const sets = [['skinIndex', 'skinWeight'], ['joints_1', 'weights_1'], ['joints_2', 'weights_2']]
            .map(([j, w]) => [g.getAttribute(j), g.getAttribute(w)]).filter(([j, w]) => j && w);
        const targets = g.morphAttributes.position ?? [];
        for (let v = 0; v < pos.count; v++) {
            let key = `${f(pos.getX(v))},${f(pos.getY(v))},${f(pos.getZ(v))}`;
            if (mesh.isSkinnedMesh) {
                for (const [j, w] of sets) {
                    for (let c = 0; c < 4; c++) {
                        const weight = w.getComponent(v, c);
                        if (weight > 0) {
                            key += `|${j.getComponent(v, c)}:${f(weight)}`;
                        }
                    }
                }
            }
            for (const t of targets) {
                key += `;${f(t.getX(v))},${f(t.getY(v))},${f(t.getZ(v))}`;
            }
            if (!seen.has(key)) {
                seen.set(key, first.length);
                first.push([b, v]);
            }
        }
    });
    return first;
}

/** The clip's time range on its keys' timeline: [first key, last key]. */
function clipRange(clip) {
    let start = Infinity;
    for (const track of clip.tracks) {
        start = Math.min(start, track.times[0]);
    }
    return [Number.isFinite(start) ? start : 0, clip.duration];
}

/**
 * Loads the model at {@code url}, skins it by {@code method} at each clip time and returns the
 * world positions in the shape of `skinlab pose --json` (without "file").
 */
export async function capturePoses(url, method, times, clipName) {
    const context = captureContext();
    const renderer = new THREE.WebGLRenderer({canvas: context.canvas, context: context.gl});
    const gltf = await new GLTFLoader().loadAsync(url);
    const json = gltf.parser.json;
    let clip = null;
    if (clipName) {
        clip = gltf.animations.find(c => c.name === clipName);
        if (!clip) {
            throw new Error(`unknown clip '${clipName}'; available clips: ${gltf.animations.map(c => `'${c.name}'`).join(', ') || '(none)'}`);
        }
    } else if (gltf.animations.length > 0) {
        clip = gltf.animations[0];
    }
    setSkinningMethod(gltf.scene, method);
    const placed = placedMeshes(gltf).map(p => {
        const meshes = blocks(json.meshes[p.mesh], p.primitives);
        meshes.forEach(m => {
            m.frustumCulled = false;
            withCapture(m.material);
        });
        return {def: json.meshes[p.mesh], index: p.mesh, meshes, positions: weld(meshes)};
    });
    const camera = new THREE.PerspectiveCamera();
    const mixer = new THREE.AnimationMixer(gltf.scene);
    const [start, end] = clip ? clipRange(clip) : [0, 0];
    const used = times.map(t => (clip ? Math.min(Math.max(t, start), end) : t));
    const poses = placed.map(() => []);
    for (const t of used) {
        if (clip) {
            mixer.stopAllAction();
            const action = mixer.clipAction(clip);
            action.reset();
            action.setLoop(THREE.LoopOnce, 1);
            action.clampWhenFinished = true;
            action.play();
            mixer.setTime(t);
        }
        gltf.scene.updateMatrixWorld(true);
        placed.forEach((p, i) => {
            const captured = p.meshes.map(m => context.capture(m.geometry.getAttribute('position').count,
                () => renderer.render(m, camera)));
            const pose = new Array(3 * p.positions.length);
            p.positions.forEach(([b, v], k) => {
                pose[3 * k] = captured[b][3 * v];
                pose[3 * k + 1] = captured[b][3 * v + 1];
                pose[3 * k + 2] = captured[b][3 * v + 2];
            });
            poses[i].push(pose);
        });
    }
    const gl = context.gl;
    const debug = gl.getExtension('WEBGL_debug_renderer_info');
    const rendererName = debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
    // Chromium keeps a few WebGL contexts alive at a time: give this one back now.
    renderer.dispose();
    gl.getExtension('WEBGL_lose_context')?.loseContext();
    return {
        clip: clip ? clip.name : null,
        method,
        times: used,
        readBack: 'transform feedback',
        renderer: rendererName,
        meshes: placed.map((p, i) => ({geometry: '/meshes/' + p.index, name: p.def.name ?? null, poses: poses[i]})),
    };
}
