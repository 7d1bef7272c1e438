// A copy of a .glb whose JOINTS_0/WEIGHTS_0 slots are reordered per vertex, lightest non-zero
// weight first and zero weights last: a file as other exporters may write it (glTF does not
// sort influences), where slot 0 is not the heaviest influence the DQS pivot must be.
import {readFileSync, writeFileSync} from 'node:fs';

const COMPONENT = {
    5121: ['getUint8', 'setUint8', 1], 5123: ['getUint16', 'setUint16', 2], 5126: ['getFloat32', 'setFloat32', 4],
};

export function writeLightestFirst(source, target) {
    const data = readFileSync(source);
    const jsonLength = data.readUInt32LE(12);
    const json = JSON.parse(data.subarray(20, 20 + jsonLength).toString('utf8'));
    const binStart = 20 + jsonLength + 8;
    const bin = Buffer.from(data.subarray(binStart, binStart + data.readUInt32LE(20 + jsonLength)));
    const view = new DataView(bin.buffer, bin.byteOffset, bin.byteLength);
    const slots = accessor => {
        const a = json.accessors[accessor];
        const bv = json.bufferViews[a.bufferView];
        const [get, set, size] = COMPONENT[a.componentType];
        const stride = bv.byteStride ?? 4 * size;
        const at = (v, c) => (bv.byteOffset ?? 0) + (a.byteOffset ?? 0) + v * stride + c * size;
        return {
            count: a.count,
            read: (v, c) => view[get](at(v, c), true),
            write: (v, c, x) => view[set](at(v, c), x, true),
        };
    };
    let permuted = 0;
    const done = new Set();
    for (const mesh of json.meshes) {
        for (const p of mesh.primitives) {
            const {JOINTS_0: ja, WEIGHTS_0: wa} = p.attributes;
            if (ja === undefined || wa === undefined || done.has(`${ja},${wa}`)) {
                continue;
            }
            done.add(`${ja},${wa}`);
            const j = slots(ja);
            const w = slots(wa);
            for (let v = 0; v < j.count; v++) {
                const pairs = [0, 1, 2, 3].map(c => [j.read(v, c), w.read(v, c)]);
                const order = [...pairs].sort((a, b) => (a[1] === 0) - (b[1] === 0) || a[1] - b[1]);
                if (order.some((o, c) => o !== pairs[c])) {
                    permuted++;
                }
                order.forEach(([joint, weight], c) => {
                    j.write(v, c, joint);
                    w.write(v, c, weight);
                });
            }
        }
    }
    writeFileSync(target, Buffer.concat([data.subarray(0, binStart), bin, data.subarray(binStart + bin.length)]));
    return permuted;
}
