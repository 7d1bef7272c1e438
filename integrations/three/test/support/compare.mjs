// Compares two pose documents of the `skinlab pose --json` shape: same meshes, same times, and
// per position the distance between the two, relative to the model's size (the diagonal of the
// bounding box of every position of the reference at every time).

/**
 * @param {object} reference skinlab's document
 * @param {object} actual the add-on's document
 * @returns {{worst: number, size: number, relative: number, where: string}} the largest distance,
 *   the model's size, their ratio and where the largest distance is
 * @throws {Error} when the documents do not have the same meshes, times or position counts
 */
export function comparePoses(reference, actual) {
    if (reference.meshes.length !== actual.meshes.length) {
        throw new Error(`${reference.meshes.length} meshes in skinlab's pose, ${actual.meshes.length} in the add-on's`);
    }
    if (reference.times.length !== actual.times.length
        || reference.times.some((t, i) => Math.abs(t - actual.times[i]) > 1e-6)) {
        throw new Error(`times differ: skinlab ${JSON.stringify(reference.times)}, add-on ${JSON.stringify(actual.times)}`);
    }
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (const mesh of reference.meshes) {
        for (const pose of mesh.poses) {
            for (let i = 0; i < pose.length; i++) {
                lo[i % 3] = Math.min(lo[i % 3], pose[i]);
                hi[i % 3] = Math.max(hi[i % 3], pose[i]);
            }
        }
    }
    const size = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    let worst = 0;
    let where = 'nowhere';
    reference.meshes.forEach((mesh, m) => {
        const other = actual.meshes[m];
        if (mesh.geometry !== other.geometry) {
            throw new Error(`mesh ${m} is ${mesh.geometry} in skinlab's pose, ${other.geometry} in the add-on's`);
        }
        mesh.poses.forEach((pose, t) => {
            const got = other.poses[t];
            if (pose.length !== got.length) {
                throw new Error(`${mesh.geometry}: ${pose.length / 3} positions in skinlab's pose, ${got.length / 3} in`
                    + ' the add-on\'s');
            }
            for (let i = 0; i < pose.length; i += 3) {
                const d = Math.hypot(pose[i] - got[i], pose[i + 1] - got[i + 1], pose[i + 2] - got[i + 2]);
                if (!(d <= worst)) {
                    worst = d;
                    where = `${mesh.geometry} position ${i / 3} at t=${reference.times[t]}`;
                }
            }
        });
    });
    return {worst, size, relative: worst / size, where};
}
