// The independent reference for our glTF import and LBS: three.js' GLTFLoader, run in Node, poses
// every clip of a file at its key times and between them and writes every vertex's skinned
// position in world space to JSON (docs/references.md, "glTF: three.js").
//
//   node gltf-reference.mjs --out DIR FILE...     writes DIR/<file name>.json (.json.gz when large)
//   node gltf-reference.mjs --max-keys N ...      at most N key times per clip (default 40)
//   node gltf-reference.mjs --budget N ...        and at most about N vertex-times per clip (default
//                                                 30000), so that large characters stay small
//
// Per file: the rest pose (the scene as loaded) and, per animation (clip), the union of its
// channels' key times (evenly thinned to --max-keys, or fewer for large meshes: --budget), the
// midpoints between consecutive ones, and time 0 when the first key comes later. The scene is
// loaded afresh for
// each clip, the clip alone is played by an AnimationMixer (LoopOnce, clamped at its end, so the
// last key is held rather than wrapped to the first), and at each time matrices are updated and
// each triangle mesh's vertices are taken with three's own Mesh/SkinnedMesh.getVertexPosition
// (morph targets, then the bone transform) and moved to world space by the mesh's matrixWorld.
// For a SkinnedMesh GLTFLoader binds with the identity bind matrix in attached mode, so this is
// sum(w * jointWorld * inverseBind * p): the specification's skinning, with the skinned node's own
// transform ignored.
//
// How the file is loaded and its vertices read, and the two places where the script puts three.js
// right by the specification (more than four influences, which the JSON then marks with
// "influences": 8; rotations off unit length): gltf-scene.mjs.
//
// Positions are rounded to 7 significant digits (float32 holds about 7), times to 9 (so that a
// float32 key time reads back as the same float).
import { writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import { gzipSync } from 'node:zlib';
import * as THREE from 'three';
import { describe, eightInfluenceData, load, meshesOf, normalizeRotations, prepare, round, sizeOf, worldPositions }
    from './gltf-scene.mjs';

const GZIP_ABOVE = 64 * 1024;

function parseArgs(argv) {
    const opts = { out: null, maxKeys: 40, budget: 30000, files: [] };
    for (let i = 0; i < argv.length; i++) {
        if (argv[i] === '--out') {
            opts.out = argv[++i];
        } else if (argv[i] === '--max-keys') {
            opts.maxKeys = Number(argv[++i]);
        } else if (argv[i] === '--budget') {
            opts.budget = Number(argv[++i]);
        } else {
            opts.files.push(argv[i]);
        }
    }
    if (!opts.out || opts.files.length === 0 || !(opts.maxKeys >= 2)) {
        console.error('usage: node gltf-reference.mjs --out DIR [--max-keys N] [--budget N] FILE...');
        process.exit(2);
    }
    return opts;
}

/** Key times of a clip (thinned to maxKeys), the midpoints between consecutive ones, and 0. */
function timesOf(clip, maxKeys) {
    const keys = new Set();
    for (const track of clip.tracks) {
        for (const t of track.times) {
            keys.add(t);
        }
    }
    let sorted = [...keys].sort((a, b) => a - b);
    if (sorted.length > maxKeys) {
        const thinned = [];
        for (let k = 0; k < maxKeys; k++) {
            thinned.push(sorted[Math.round(k * (sorted.length - 1) / (maxKeys - 1))]);
        }
        sorted = [...new Set(thinned)];
    }
    // Before a clip's first key every channel holds its first value: time 0 checks that too.
    const times = sorted[0] > 0 ? [0] : [];
    sorted.forEach((t, k) => {
        if (k > 0) {
            times.push((sorted[k - 1] + t) / 2);
        }
        times.push(t);
    });
    return times;
}

async function reference(file, opts) {
    const doc = prepare(file);
    const json = doc.json;
    const first = normalizeRotations(await load(doc));
    first.scene.updateMatrixWorld(true);
    const firstMeshes = meshesOf(first);
    const firstSets = eightInfluenceData(doc, firstMeshes);
    const rest = firstMeshes.map((m, k) => ({ ...describe(m, firstSets[k], json),
        positions: worldPositions(m, firstSets[k]) }));
    const clips = [];
    for (let c = 0; c < first.animations.length; c++) {
        const gltf = normalizeRotations(await load(doc)); // a fresh scene: no pose left over from another clip
        const clip = gltf.animations[c];
        const meshes = meshesOf(gltf);
        const sets = eightInfluenceData(doc, meshes);
        const mixer = new THREE.AnimationMixer(gltf.scene);
        const action = mixer.clipAction(clip);
        action.setLoop(THREE.LoopOnce, 1);
        action.clampWhenFinished = true;
        action.play();
        const vertices = meshes.reduce((n, m) => n + m.object.geometry.getAttribute('position').count, 0);
        const keys = Math.max(2, Math.min(opts.maxKeys, Math.floor(opts.budget / Math.max(1, 2 * vertices))));
        const times = timesOf(clip, keys);
        const positions = meshes.map(() => []);
        for (const t of times) {
            mixer.setTime(t);
            gltf.scene.updateMatrixWorld(true);
            meshes.forEach((m, k) => positions[k].push(worldPositions(m, sets[k])));
        }
        clips.push({
            // times with 9 digits, which float32 key times survive exactly (a STEP key sampled at
            // a time a rounding below it would give the previous key)
            index: c, name: clip.name, duration: round(clip.duration), times: times.map((t) => Number(t.toPrecision(9))),
            morphWeights: clip.tracks.some((track) => track.name.endsWith('.morphTargetInfluences')),
            meshes: meshes.map((m, k) => ({ ...describe(m, sets[k], json), positions: positions[k] })),
        });
    }
    return {
        about: 'three.js ' + THREE.REVISION + ' GLTFLoader in Node (bench/threejs/gltf-reference.mjs): world-space '
            + 'positions of every vertex of every triangle mesh, rest pose and each clip at its key times and '
            + 'midpoints; 7 significant digits',
        three: THREE.REVISION,
        file: path.basename(file),
        size: sizeOf(rest),
        rest,
        clips,
    };
}

function write(dir, ref) {
    mkdirSync(dir, { recursive: true });
    const text = JSON.stringify(ref) + '\n';
    let target = path.join(dir, ref.file + '.json');
    if (text.length > GZIP_ABOVE) {
        target += '.gz';
        writeFileSync(target, gzipSync(Buffer.from(text), { level: 9 }));
    } else {
        writeFileSync(target, text);
    }
    return target;
}

const opts = parseArgs(process.argv.slice(2));
console.warn = () => {}; // GLTFLoader's notes (unknown extensions, skinning disabled) are not errors here
let failed = 0;
for (const file of opts.files) {
    try {
        const ref = await reference(file, opts);
        const target = write(opts.out, ref);
        const vertices = ref.rest.reduce((n, m) => n + m.vertices, 0);
        const times = ref.clips.reduce((n, c) => n + c.times.length, 0);
        console.log(`${path.basename(file)}: ${ref.rest.length} meshes, ${vertices} vertices, `
            + `${ref.clips.length} clips, ${times} times, size ${ref.size} -> ${target}`);
    } catch (e) {
        failed++;
        console.log(`${path.basename(file)}: failed: ${e.stack ?? e}`);
    }
}
process.exit(failed > 0 ? 1 : 0);
