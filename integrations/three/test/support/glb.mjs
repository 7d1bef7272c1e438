// The JSON chunk of a binary glTF, and a clip's time range from it.
import {readFileSync} from 'node:fs';

/** The glTF JSON of a .glb (or a .gltf) file. */
export function gltfJson(file) {
    const data = readFileSync(file);
    if (data.readUInt32LE(0) !== 0x46546c67) {
        return JSON.parse(data.toString('utf8'));
    }
    const length = data.readUInt32LE(12);
    if (data.readUInt32LE(16) !== 0x4e4f534a) {
        throw new Error(`${file}: the first GLB chunk is not JSON`);
    }
    return JSON.parse(data.subarray(20, 20 + length).toString('utf8'));
}

/**
 * The first clip's [start, end] on its keys' timeline (the min and max its input accessors
 * declare, which glTF requires), or null without animations.
 */
export function firstClipRange(file) {
    const json = gltfJson(file);
    const animation = json.animations?.[0];
    if (!animation) {
        return null;
    }
    let start = Infinity;
    let end = -Infinity;
    for (const sampler of animation.samplers) {
        const accessor = json.accessors[sampler.input];
        start = Math.min(start, accessor.min[0]);
        end = Math.max(end, accessor.max[0]);
    }
    return {name: animation.name ?? null, start, end};
}
