#!/bin/sh
# Import speed of skinlab, assimp and three.js' ColladaLoader on the same files, in one session:
# our assets, the shared corpus (read in place) and a generated file. Machines are noisy, so what
# counts are the ratios (assimp median / ours, three.js median / ours) measured here together.
#
# usage: bench/compare-parse.sh [--triangles N] [--runs N] [--warmup-seconds S] [--out DIR]
#   --triangles N       triangles of the generated file (default 1000000; 0 for none)
#   --runs N            timed imports per file under 10 MB, for every tool (default 25)
#   --warmup-seconds S  shared warm-up per tool (default 3)
#   --out DIR           keep the raw JSON of both benchmarks there
# Needs JDK 17, Gradle (builds desktop/build/install when missing), Node >= 18 and npm (installs
# bench/threejs/node_modules from package-lock.json when missing).
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
triangles=1000000
runs=25
warmup=3
out=
while [ $# -gt 0 ]; do
    case "$1" in
        --triangles) triangles=$2; shift 2 ;;
        --runs) runs=$2; shift 2 ;;
        --warmup-seconds) warmup=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "compare-parse: unknown argument $1" >&2; exit 2 ;;
    esac
done

cd "$root"
skinlab=desktop/build/install/skinlab/bin/skinlab
if [ ! -x "$skinlab" ]; then
    gradle -q installDist
fi
if [ ! -d bench/threejs/node_modules ]; then
    (cd bench/threejs && npm ci --silent)
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
[ -n "$out" ] || out=$tmp
mkdir -p "$out"

# The same files for every tool, in this order.
find assets -name '*.dae' | sort > "$tmp/files"
if [ -d ../shared/corpus ]; then
    find ../shared/corpus -name '*.dae' | sort >> "$tmp/files"
else
    echo "compare-parse: no corpus at ../shared/corpus; our assets only" >&2
fi
if [ "$triangles" -gt 0 ]; then
    generated=$tmp/generated-$triangles.dae
    java -cp "desktop/build/install/skinlab/lib/*" org.skinlab.desktop.bench.SyntheticCollada \
        "$generated" "$triangles" > /dev/null
    echo "$generated" >> "$tmp/files"
fi

echo "compare-parse: load average before: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')" >&2
# shellcheck disable=SC2046  # file names come from find above and hold no spaces
"$skinlab" bench parse --compare-assimp --json --runs "$runs" --warmup-seconds "$warmup" \
    $(cat "$tmp/files") > "$out/skinlab-assimp.json"
# ColladaLoader needs about 2 GB of heap for the 1M-triangle file.
node --expose-gc --max-old-space-size=4096 bench/threejs/parse-bench.mjs --json --runs "$runs" \
    --warmup-seconds "$warmup" $(cat "$tmp/files") > "$out/threejs.json"
echo "compare-parse: load average after: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')" >&2

node --input-type=module - "$out/skinlab-assimp.json" "$out/threejs.json" <<'EOF'
import { readFileSync } from 'node:fs';
const [ours, three] = process.argv.slice(2).map((f) => JSON.parse(readFileSync(f, 'utf8')));
const byName = new Map(three.files.map((f) => [f.file, f]));
const ms = (x) => (x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x.toFixed(2));
const ratio = (a, b) => (a / b).toFixed(2);
console.log(`skinlab (Java ${ours.java}, ${ours.cores} cores) | assimp ${ours.assimpVersion} (${ours.assimpFlags}) `
    + `| three.js ${three.three} ColladaLoader (Node ${three.node}); medians in ms\n`);
console.log('| file | MB | triangles | ours | assimp | three.js | assimp/ours | three.js/ours |');
console.log('|---|---:|---:|---:|---:|---:|---:|---:|');
const big = [];
for (const f of ours.files) {
    const t = byName.get(f.file);
    const a = f.assimpMedianMillis;
    const tm = t && !t.error ? t.medianMillis : null;
    console.log(`| ${f.file} | ${(f.bytes / 1e6).toFixed(3)} | ${f.triangles} | ${ms(f.medianMillis)} `
        + `| ${a == null ? 'failed' : ms(a)} | ${tm == null ? 'failed' : ms(tm)} `
        + `| ${a == null ? '' : ratio(a, f.medianMillis)} | ${tm == null ? '' : ratio(tm, f.medianMillis)} |`);
    if (f.bytes >= 10_000_000) big.push([f, a, tm]);
    const notes = [];
    if (f.assimpError) notes.push(`assimp: ${f.assimpError}`);
    if (t && t.error) notes.push(`three.js: ${t.error}`);
    if (f.assimpTriangles != null && f.assimpTriangles !== f.triangles) notes.push(`assimp has ${f.assimpTriangles} triangles`);
    if (t && !t.error && t.triangles !== f.triangles) notes.push(`three.js has ${t.triangles} triangles`);
    if (notes.length) console.error(`compare-parse: ${f.file}: ${notes.join('; ')}`);
}
for (const [f, a, tm] of big) {
    const mbs = (m) => (m == null ? 'failed' : (f.bytes / 1e6 / (m / 1000)).toFixed(1));
    console.log(`\n${f.file}: MB/s at the median: ours ${mbs(f.medianMillis)}, assimp ${mbs(a)}, three.js ${mbs(tm)}`);
}
EOF
