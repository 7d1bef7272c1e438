// The independent reference for blending clips: three.js' AnimationMixer, run in Node, plays
// several clips of a file at once, with weights and as additive layers, and writes every vertex's
// skinned position in world space (docs/references.md, "glTF: three.js", "Blended clips").
//
//   node blend-reference.mjs --out DIR FILE...     writes DIR/<file name>.blends.json.gz
//     --cases FILE.json   the cases (default: blend-cases.json beside this script), by file name
//     --as NAME           take the cases of NAME and write the reference as NAME's: for a copy of
//                         a file under another name (the JSON says what it was computed from)
//     --single REF        also pose every clip of the single-clip reference REF (gltf-reference.mjs'
//                         JSON, .gz or not) alone through this script's path and print the largest
//                         difference from it: 0 where REF's times (written with 9 digits) are the
//                         times it posed, else a last-digit rounding (Fox: 1e-5 of 175, its size)
//
// The cases (blend-cases.json): per file name, "times" (seconds) and "combinations", each
//   {"blend": [{"clip", "weight"}, ...], "additive": [{"clip", "weight", "refTime"}, ...]};
// every combination is posed at every time, one case each. The scene is loaded afresh for each
// case (loading as gltf-reference.mjs does, gltf-scene.mjs: same vertices, same unit-quaternion
// keys) and one AnimationMixer plays:
//  - per "blend" entry, mixer.clipAction(clip), LoopRepeat, setEffectiveWeight(weight), play();
//  - per "additive" entry, the clip made additive, THREE.AnimationUtils.makeClipAdditive(
//    clip.clone(), refTime, clip, 1) (fps 1, so the reference frame is refTime seconds exactly),
//    played as an action with AdditiveAnimationBlendMode, LoopRepeat, setEffectiveWeight(weight);
// then mixer.setTime(time): every action at `time` wrapped into its own clip (LoopRepeat: time minus
// its duration times floor(time / duration)), so clips of different lengths are each at time mod
// their length. The actions are played in the order listed, blend entries first.
//
// What three.js computes then, per animated property (PropertyMixer, in double precision): the
// normal actions that animate it are blended in the order played, each new value mixed into the
// running result with its weight over the weights so far (quaternions by slerp on the shorter arc,
// vectors by lerp), so with weights summing to W the result is their weighted average; where
// W < 1 the result is then mixed with the rest value (the node's own, as loaded) by 1 - W; then
// the additive actions' deltas (d starting at the identity, 0 for vectors): per additive action in
// order, rotation d := d * slerp(1, conj(k(refTime)) * k(t), w) (k: the clip's keys interpolated, the quaternion
// product Hamilton's, x y z w as three stores them; makeClipAdditive multiplies every key by the
// reference's conjugate on the left), translation and scale d := d + w * (k(t) - k(refTime));
// finally q := q * d (the delta on the right, in the joint's own frame) and v := v + d. A property
// that no action animates keeps its rest value; one animated only additively starts from its rest
// value. So where two normal clips with weight 1 each animate a joint, it gets half of each
// (walk 1 + wave 1: the right arm halfway between walk's and wave's, every other joint walk's).
// Slerp is three's Quaternion.slerpFlat: for quaternions closer than a dot product of 0.9995 it
// normalises the linear blend instead.
//
// JSON: {"about", "file", "three", "size" (the rest bounding-box diagonal, as gltf-reference.mjs
// computes it), "meshes": [per triangle mesh: node, mesh, primitive, name, attributes, skinned,
// influences, vertices, morphTargets, as in gltf-reference.mjs' "rest" entries],
// "times", "cases": [{"blend", "additive", "time", "positions"}], "computedFrom" (with --as)}.
// "positions" holds x, y, z of every vertex of every mesh, the meshes in the order of "meshes"
// (three's traversal order of the scene: depth first, a node's primitives before its children) and
// each mesh's vertices in the order of its glTF primitive's accessors: exactly the concatenation of
// the "positions" arrays gltf-reference.mjs writes per mesh (one mesh for our assets and Fox, so
// the same array). Rounded to 7 significant digits.
import { createHash } from 'node:crypto';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { gunzipSync, gzipSync } from 'node:zlib';
import * as THREE from 'three';
import { describe, eightInfluenceData, load, meshesOf, normalizeRotations, prepare, sizeOf, worldPositions }
    from './gltf-scene.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));

function parseArgs(argv) {
    const opts = { out: null, cases: path.join(HERE, 'blend-cases.json'), as: null, single: null, files: [] };
    for (let i = 0; i < argv.length; i++) {
        if (argv[i] === '--out') {
            opts.out = argv[++i];
        } else if (argv[i] === '--cases') {
            opts.cases = argv[++i];
        } else if (argv[i] === '--as') {
            opts.as = argv[++i];
        } else if (argv[i] === '--single') {
            opts.single = argv[++i];
        } else {
            opts.files.push(argv[i]);
        }
    }
    if (!opts.out || opts.files.length === 0 || (opts.as && opts.files.length > 1)) {
        console.error('usage: node blend-reference.mjs --out DIR [--cases FILE.json] [--as NAME] [--single REF] FILE...');
        process.exit(2);
    }
    return opts;
}

function clipNamed(gltf, name) {
    const clip = THREE.AnimationClip.findByName(gltf.animations, name);
    if (!clip) {
        throw new Error(`no clip ${name}; the file has ${gltf.animations.map((c) => c.name).join(', ')}`);
    }
    return clip;
}

/** World positions of every vertex (all meshes, concatenated) with the combination posed at time. */
async function pose(doc, combination, time) {
    const gltf = normalizeRotations(await load(doc));
    const meshes = meshesOf(gltf);
    const sets = eightInfluenceData(doc, meshes);
    const mixer = new THREE.AnimationMixer(gltf.scene);
    for (const { clip, weight } of combination.blend ?? []) {
        const action = mixer.clipAction(clipNamed(gltf, clip));
        action.setLoop(THREE.LoopRepeat, Infinity);
        action.setEffectiveWeight(weight);
        action.play();
    }
    for (const { clip, weight, refTime } of combination.additive ?? []) {
        const source = clipNamed(gltf, clip);
        const additive = THREE.AnimationUtils.makeClipAdditive(source.clone(), refTime, source, 1);
        const action = mixer.clipAction(additive, undefined, THREE.AdditiveAnimationBlendMode);
        action.setLoop(THREE.LoopRepeat, Infinity);
        action.setEffectiveWeight(weight);
        action.play();
    }
    mixer.setTime(time);
    gltf.scene.updateMatrixWorld(true);
    return meshes.flatMap((m, k) => worldPositions(m, sets[k]));
}

function readJson(file) {
    const bytes = readFileSync(file);
    return JSON.parse((file.endsWith('.gz') ? gunzipSync(bytes) : bytes).toString('utf8'));
}

/**
 * Every clip of the single-clip reference posed alone (weight 1) at each of its times before the
 * clip's end (there the reference holds the last key, LoopRepeat wraps to the first): the largest
 * coordinate difference per clip.
 */
async function againstSingle(doc, single) {
    const differences = [];
    for (const clip of single.clips) {
        const reference = clip.meshes.map((m) => m.positions);
        let worst = 0;
        let compared = 0;
        for (let k = 0; k < clip.times.length; k++) {
            if (clip.times[k] >= clip.duration) {
                continue;
            }
            const ours = await pose(doc, { blend: [{ clip: clip.name, weight: 1 }] }, clip.times[k]);
            const theirs = reference.flatMap((perTime) => perTime[k]);
            for (let i = 0; i < ours.length; i++) {
                worst = Math.max(worst, Math.abs(ours[i] - theirs[i]));
            }
            compared++;
        }
        differences.push({ clip: clip.name, times: compared, worst });
    }
    return differences;
}

async function reference(file, name, spec) {
    const doc = prepare(file);
    const rest = normalizeRotations(await load(doc));
    rest.scene.updateMatrixWorld(true);
    const meshes = meshesOf(rest);
    const sets = eightInfluenceData(doc, meshes);
    const described = meshes.map((m, k) => describe(m, sets[k], doc.json));
    const size = sizeOf(meshes.map((m, k) => ({ positions: worldPositions(m, sets[k]) })));
    const cases = [];
    for (const combination of spec.combinations) {
        for (const time of spec.times) {
            cases.push({ blend: combination.blend ?? [], additive: combination.additive ?? [], time,
                positions: await pose(doc, combination, time) });
        }
    }
    const result = {
        about: 'three.js ' + THREE.REVISION + ' AnimationMixer in Node (bench/threejs/blend-reference.mjs): world-space '
            + 'positions of every vertex with clips blended by weight and layered additively, each case at one time; '
            + '7 significant digits',
        file: name,
        three: THREE.REVISION,
        size,
        meshes: described,
        times: spec.times,
        cases,
    };
    if (name !== path.basename(file)) {
        result.computedFrom = { file: path.basename(file),
            sha256: createHash('sha256').update(readFileSync(file)).digest('hex') };
    }
    return { result, doc };
}

const opts = parseArgs(process.argv.slice(2));
console.warn = () => {}; // GLTFLoader's notes (unknown extensions, skinning disabled) are not errors here
const allCases = readJson(opts.cases);
let failed = 0;
for (const file of opts.files) {
    const name = opts.as ?? path.basename(file);
    try {
        const spec = allCases[name];
        if (!spec) {
            throw new Error(`${opts.cases} has no cases for ${name}`);
        }
        const { result, doc } = await reference(file, name, spec);
        mkdirSync(opts.out, { recursive: true });
        const target = path.join(opts.out, name + '.blends.json.gz');
        writeFileSync(target, gzipSync(Buffer.from(JSON.stringify(result) + '\n'), { level: 9 }));
        const vertices = result.meshes.reduce((n, m) => n + m.vertices, 0);
        console.log(`${name}: ${vertices} vertices, ${spec.combinations.length} combinations x ${spec.times.length} `
            + `times = ${result.cases.length} cases, size ${result.size} -> ${target}`);
        if (opts.single) {
            for (const d of await againstSingle(doc, readJson(opts.single))) {
                console.log(`  ${d.clip} alone (weight 1) against ${path.basename(opts.single)} at its ${d.times} times `
                    + `before the clip's end: largest difference ${d.worst.toPrecision(2)} (${(d.worst / result.size)
                        .toPrecision(2)} of the size)`);
            }
        }
    } catch (e) {
        failed++;
        console.log(`${name}: failed: ${e.stack ?? e}`);
    }
}
process.exit(failed > 0 ? 1 : 0);
