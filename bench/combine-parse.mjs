// Combines the JSON of `skinlab bench parse --compare-assimp --json` and bench/threejs/parse-bench.mjs
// from one or more sessions into a markdown table. Used by compare-parse.sh.
//
// usage: node combine-parse.mjs DIR K
//   DIR holds skinlab-assimp-1.json, threejs-1.json, ... up to K.

import { readFileSync } from 'node:fs';

const [dir, k] = [process.argv[2], Number(process.argv[3])];
const read = (name) => JSON.parse(readFileSync(`${dir}/${name}`, 'utf8'));
const sessions = [];
for (let s = 1; s <= k; s++) {
    sessions.push({ ours: read(`skinlab-assimp-${s}.json`), three: read(`threejs-${s}.json`) });
}

const median = (xs) => {
    const v = xs.filter((x) => x != null).sort((a, b) => a - b);
    if (v.length === 0) return null;
    return v.length % 2 ? v[(v.length - 1) / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
};
const min = (xs) => (xs.some((x) => x == null) ? null : Math.min(...xs));
const ms = (x) => (x == null ? 'failed' : x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x.toFixed(2));
const r2 = (x) => (x == null ? '' : x.toFixed(2));

const first = sessions[0];
console.log(`skinlab (Java ${first.ours.java}, ${first.ours.cores} cores) | assimp ${first.ours.assimpVersion} `
    + `(${first.ours.assimpFlags}) | three.js ${first.three.three} ColladaLoader (Node ${first.three.node}); `
    + `${k} session(s)\n`);
console.log('Times: medians in ms (for several sessions, the median of the session medians). x/ours: the '
    + 'median over sessions of each session\'s ratio of medians. best: fastest run of x / fastest run of ours, '
    + 'over all sessions.\n');
console.log('| file | MB | triangles | ours | assimp | three.js | assimp/ours | three.js/ours '
    + '| best assimp/ours | best three.js/ours |');
console.log('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|');

const big = [];
first.ours.files.forEach((f, i) => {
    const per = sessions.map(({ ours, three }) => {
        const o = ours.files[i];
        const t = three.files.find((x) => x.file === o.file);
        const tOk = t !== undefined && !t.error;
        return {
            ours: o.medianMillis,
            oursMin: o.minMillis,
            assimp: o.assimpMedianMillis,
            assimpMin: o.assimpMinMillis,
            three: tOk ? t.medianMillis : null,
            threeMin: tOk ? t.minMillis : null,
            assimpRatio: o.assimpMedianMillis == null ? null : o.assimpMedianMillis / o.medianMillis,
            threeRatio: tOk ? t.medianMillis / o.medianMillis : null,
            notes: [
                o.assimpError && `assimp failed: ${o.assimpError}`,
                t === undefined && 'three.js did not measure it',
                t && t.error && `three.js failed: ${t.error}`,
                o.assimpTriangles != null && o.assimpTriangles !== o.triangles
                    && `assimp has ${o.assimpTriangles} triangles, ours ${o.triangles}`,
                tOk && t.triangles !== o.triangles && `three.js has ${t.triangles} triangles, ours ${o.triangles}`,
            ].filter(Boolean),
        };
    });
    const col = (key) => per.map((p) => p[key]);
    const oursBest = min(col('oursMin'));
    const best = (key) => {
        const m = min(col(key));
        return m == null ? null : m / oursBest;
    };
    const row = { ours: median(col('ours')), assimp: median(col('assimp')), three: median(col('three')) };
    console.log(`| ${f.file} | ${(f.bytes / 1e6).toFixed(3)} | ${f.triangles} | ${ms(row.ours)} | ${ms(row.assimp)} `
        + `| ${ms(row.three)} | ${r2(median(col('assimpRatio')))} | ${r2(median(col('threeRatio')))} `
        + `| ${r2(best('assimpMin'))} | ${r2(best('threeMin'))} |`);
    if (f.bytes >= 10_000_000) big.push([f, row]);
    const notes = [...new Set(per.flatMap((p) => p.notes))];
    if (notes.length) console.error(`compare-parse: ${f.file}: ${notes.join('; ')}`);
});
for (const [f, row] of big) {
    const mbs = (m) => (m == null ? 'failed' : (f.bytes / 1e6 / (m / 1000)).toFixed(1));
    console.log(`\n${f.file}: MB/s at the median: ours ${mbs(row.ours)}, assimp ${mbs(row.assimp)}, `
        + `three.js ${mbs(row.three)}`);
}
