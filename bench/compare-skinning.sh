#!/bin/sh
# Skinning speed of skinlab against the shared scalar C++ reference (../shared/perf/skin_ref.cpp)
# on the same synthetic data, in one session: C++ first, then ours, per vertex count. What counts
# are the ratios ours / C++ measured here together (absolute times drift between machines and
# with the load of the moment).
#
# usage: bench/compare-skinning.sh [--sizes "10000 100000 1000000"] [--seconds S] [--baseline-size N] [--out FILE]
#   --sizes "V..."       vertex counts (default "10000 100000 1000000")
#   --seconds S          timed seconds per variant (default 2)
#   --baseline-size N    vertex count of the thesis-style baseline runs (default 100000; 0: none)
#   --out FILE           keep the raw lines (C++ output and our JSON) there
# The C++ is run as `VARIANTS=c-lbs,c-dqs,c-dqs-2t skin_ref 3 S/3 V` (3 rounds of S/3 seconds; min
# and median over all samples). Ours: `skinlab bench skinning --json` for the scalar and vector
# kernels, 1 and 2 threads, 2 s warm-up each, then the thesis-style baseline at one size. The table
# gives both ratios, min / C++ min and median / C++ median: on a shared machine the minimum is the
# less disturbed figure. Needs g++ (builds /tmp/skin_ref once), python3, JDK 17 and Gradle. Ours runs
# on the start script's Java: the newest JDK >= 17 installed, or SKINLAB_JAVA_HOME=DIR (=build: the
# default java); the table names it (docs/running.md, "Which Java runs skinlab").
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
sizes="10000 100000 1000000"
seconds=2
baseline=100000
out=
while [ $# -gt 0 ]; do
    case "$1" in
        --sizes) sizes=$2; shift 2 ;;
        --seconds) seconds=$2; shift 2 ;;
        --baseline-size) baseline=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -h|--help) sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "compare-skinning: unknown argument $1" >&2; exit 2 ;;
    esac
done

cd "$root"
skinlab=desktop/build/install/skinlab/bin/skinlab
[ -x "$skinlab" ] || gradle -q installDist
ref=/tmp/skin_ref
if [ ! -x "$ref" ] || [ "$root/../shared/perf/skin_ref.cpp" -nt "$ref" ]; then
    g++ -O3 -DNDEBUG -std=c++17 "$root/../shared/perf/skin_ref.cpp" -o "$ref" -lpthread
fi
raw=$(mktemp)
round=$(python3 -c "print($seconds / 3)")
for v in $sizes; do
    VARIANTS=c-lbs,c-dqs,c-dqs-2t "$ref" 3 "$round" "$v" >> "$raw"
    for m in lbs dqs; do
        for impl in scalar vector; do
            for t in 1 2; do
                printf 'ours %s ' "$impl" >> "$raw"
                "$skinlab" bench skinning --vertices "$v" --method "$m" --threads "$t" --implementation "$impl" \
                    --warmup-seconds 2 --seconds "$seconds" --json 2>/dev/null >> "$raw"
            done
        done
        if [ "$v" = "$baseline" ]; then
            printf 'thesis ' >> "$raw"
            "$skinlab" bench skinning --vertices "$v" --method "$m" --baseline thesis --warmup-seconds 2 \
                --seconds "$seconds" --json 2>/dev/null >> "$raw"
        fi
    done
done
[ -z "$out" ] || cp "$raw" "$out"
python3 - "$raw" <<'PY'
import json, re, sys
cpp, ours, thesis = {}, {}, {}
for line in open(sys.argv[1]):
    m = re.match(r'V=(\d+)\s+(\S+)\s+min\s+([\d.]+)\s+median\s+([\d.]+).*checksum ([-\d.]+)', line)
    if m:
        cpp[(m[2], int(m[1]))] = (float(m[3]), float(m[4]), m[5])
        continue
    kind, rest = line.split(' ', 1)
    if kind == 'ours':
        impl, js = rest.split(' ', 1)
        j = json.loads(js)
        ours[(j['method'], impl, j['threads'], j['vertices'])] = j
    elif kind == 'thesis':
        j = json.loads(rest)
        thesis[(j['method'], j['vertices'])] = j
sizes = sorted({k[1] for k in cpp})
javas = sorted({f"Java {j['java']} ({j['javaVendor']})" for j in list(ours.values()) + list(thesis.values())})
print(f"ours on {', '.join(javas)}\n")
print('| method | implementation | threads | V | min ns/v | median ns/v | min / C++ min | median / C++ median | checksum |')
print('|---|---|---:|---:|---:|---:|---:|---:|---|')
for method in ('lbs', 'dqs'):
    for v in sizes:
        c = cpp[('c-' + method, v)]
        print(f'| {method} | C++ scalar (skin_ref c-{method}) | 1 | {v} | {c[0]:.2f} | {c[1]:.2f} | 1.00 | 1.00 | {c[2]} |')
        if method == 'dqs' and ('c-dqs-2t', v) in cpp:
            c2 = cpp[('c-dqs-2t', v)]
            print(f'| dqs | C++ scalar (skin_ref c-dqs-2t) | 2 | {v} | {c2[0]:.2f} | {c2[1]:.2f} | '
                  f'{c2[0] / c[0]:.2f} | {c2[1] / c[1]:.2f} | {c2[2]} |')
        for impl in ('scalar', 'vector'):
            for t in (1, 2):
                j = ours.get((method, impl, t, v))
                if j:
                    print(f"| {method} | ours {j['implementation']} | {t} | {v} | {j['minNsPerVertex']:.2f} | "
                          f"{j['medianNsPerVertex']:.2f} | {j['minNsPerVertex'] / c[0]:.2f} | "
                          f"{j['medianNsPerVertex'] / c[1]:.2f} | {j['checksum']:.6f} |")
for (method, v), j in sorted(thesis.items()):
    bmin = j.get('baselineMinNsPerVertex')
    extra = f", at the minimum {bmin / j['minNsPerVertex']:.0f}x (baseline min {bmin:.1f})" if bmin else ''
    print(f"\nthesis-style baseline, {method}, V={v}: median {j['baselineMedianNsPerVertex']:.1f} ns/vertex, "
          f"ours ({j['implementation']}, 1 thread) {j['medianNsPerVertex']:.2f}: {j['baselineRatio']:.0f}x faster "
          f"at the median{extra}")
PY
rm -f "$raw"
