#!/bin/sh
# Is DQS faster than LBS, with and without normals? One session, per kernel: the C++ programs
# (../shared/perf/skin_ref.cpp with normals; bench/cpp/skin_positions.cpp positions only, plus its
# with-normals calibration) and `skinlab bench skinning` with the scalar and the vector kernels,
# normals none, blended (the reference's rule) and exact, on the reference's synthetic data.
# Interleaved and repeated: each round runs every variant once, in the same order; the tables give
# per variant the median over the rounds of each run's median ns per vertex, with the smallest and
# largest of those medians, and the DQS/LBS ratio of the medians.
#
# usage: bench/compare-normals.sh [--rounds R] [--seconds S] [--warmup-seconds W] [--sizes "V..."]
#                                 [--influences "K..."] [--sweep-size V] [--out FILE]
#   --rounds R           rounds (default 3)
#   --seconds S          timed seconds per run (default 1.5)
#   --warmup-seconds W   Java warm-up per run (default 1.5; bench skinning waits for the JIT too)
#   --sizes "V..."       vertex counts of the 4-influence table (default "10000 100000")
#   --influences "K..."  influence counts of the sweep (default "1 2 4 8"; "" for none)
#   --sweep-size V       vertex count of the sweep (default 100000)
#   --out FILE           keep the raw lines (C++ output and our JSON) there
# Needs g++ (builds both programs in a temporary folder), python3 and the installed skinlab
# (gradle -q installDist); ours runs on the start script's Java (the newest JDK >= 17 installed, or
# SKINLAB_JAVA_HOME=DIR). About 4 minutes per round with the defaults.
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
rounds=3
seconds=1.5
warmup=1.5
sizes="10000 100000"
influences="1 2 4 8"
sweep=100000
out=
while [ $# -gt 0 ]; do
    case "$1" in
        --rounds) rounds=$2; shift 2 ;;
        --seconds) seconds=$2; shift 2 ;;
        --warmup-seconds) warmup=$2; shift 2 ;;
        --sizes) sizes=$2; shift 2 ;;
        --influences) influences=$2; shift 2 ;;
        --sweep-size) sweep=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -h|--help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "compare-normals: unknown argument $1" >&2; exit 2 ;;
    esac
done

cd "$root"
skinlab=desktop/build/install/skinlab/bin/skinlab
[ -x "$skinlab" ] || gradle -q installDist
bin=$(mktemp -d)
raw=$(mktemp)
trap 'rm -rf "$bin" "$raw"' EXIT
g++ -O3 -DNDEBUG -std=c++17 "$root/../shared/perf/skin_ref.cpp" -o "$bin/skin_ref" -lpthread
g++ -O3 -DNDEBUG -std=c++17 "$root/bench/cpp/skin_positions.cpp" -o "$bin/skin_positions" -lpthread

java_run() { # table V K impl method normals
    printf 'java %s ' "$1" >> "$raw"
    "$skinlab" bench skinning --vertices "$2" --influences "$3" --implementation "$4" --method "$5" \
        --normals "$6" --warmup-seconds "$warmup" --seconds "$seconds" --json 2>/dev/null >> "$raw"
}

r=1
while [ "$r" -le "$rounds" ]; do
    for v in $sizes; do
        printf 'round %s\n' "$r" >> "$raw"
        VARIANTS=c-lbs,c-dqs "$bin/skin_ref" 1 "$seconds" "$v" | sed 's/^/cpp main 4 /' >> "$raw"
        "$bin/skin_positions" 1 "$seconds" "$v" | sed 's/^/cpp main 4 /' >> "$raw"
        for impl in scalar vector; do
            for m in lbs dqs; do
                for n in none blended exact; do
                    java_run main "$v" 4 "$impl" "$m" "$n"
                done
            done
        done
    done
    for k in $influences; do
        INFLUENCES=$k "$bin/skin_positions" 1 "$seconds" "$sweep" | sed "s/^/cpp sweep $k /" >> "$raw"
        for impl in scalar vector; do
            for m in lbs dqs; do
                for n in none blended; do
                    java_run sweep "$sweep" "$k" "$impl" "$m" "$n"
                done
            done
        done
    done
    r=$((r + 1))
done
[ -z "$out" ] || cp "$raw" "$out"
python3 - "$raw" "$sizes" "$influences" "$sweep" <<'PY'
import json, re, statistics, sys
raw, sizes, ks, sweep = sys.argv[1], [int(s) for s in sys.argv[2].split()], [int(k) for k in sys.argv[3].split()], int(sys.argv[4])
runs = {}   # (table, kernel, normals, method, V, K) -> [median ns]
checks = {}
java = set()
for line in open(raw):
    m = re.match(r'cpp (\w+) (\d+) V=(\d+)\s+(\S+)\s+min\s+([\d.]+)\s+median\s+([\d.]+).*checksum ([-\d.]+)', line)
    if m:
        table, k, v, variant, med = m[1], int(m[2]), int(m[3]), m[4], float(m[6])
        method = variant.split('-')[1]
        if variant in ('c-lbs', 'c-dqs'):
            key = (table, 'C++ skin_ref', 'blended', method, v, k)
        elif variant.endswith('-nrm'):
            key = (table, 'C++ ours', 'blended', method, v, k)
        else:
            key = (table, 'C++ ours', 'none', method, v, k)
        runs.setdefault(key, []).append(med)
        checks[key] = m[7]
        continue
    m = re.match(r'java (\w+) (\{.*\})', line)
    if m:
        j = json.loads(m[2])
        java.add(f"Java {j['java']} ({j['javaVendor']})")
        key = (m[1], 'Java ' + j['implementation'], j['normals'], j['method'], j['vertices'], j['influences'])
        runs.setdefault(key, []).append(j['medianNsPerVertex'])
        checks[key] = f"{j['checksum']:.6f}"
kernels = ['C++ skin_ref', 'C++ ours', 'Java scalar', 'Java vector-256']
order = ['none', 'blended', 'exact']
def cell(key):
    xs = runs.get(key)
    if not xs:
        return None, ''
    med = statistics.median(xs)
    return med, f'{med:.2f} ({min(xs):.2f}-{max(xs):.2f})'
print(f"ours on {', '.join(sorted(java))}; medians over {max(len(x) for x in runs.values())} rounds (min-max of the rounds' medians), ns per vertex\n")
for v in sizes:
    print(f'V = {v}, 4 influences:\n')
    print('| kernel | normals | LBS | DQS | DQS / LBS | checksums LBS, DQS |')
    print('|---|---|---:|---:|---:|---|')
    for kern in kernels:
        for n in order:
            (l, lt), (d, dt) = cell(('main', kern, n, 'lbs', v, 4)), cell(('main', kern, n, 'dqs', v, 4))
            if l is None and d is None:
                continue
            ratio = f'{d / l:.2f}' if l and d else ''
            print(f"| {kern} | {n} | {lt} | {dt} | {ratio} | {checks.get(('main', kern, n, 'lbs', v, 4), '')}, "
                  f"{checks.get(('main', kern, n, 'dqs', v, 4), '')} |")
    print()
if ks:
    print(f'DQS / LBS by influences, V = {sweep} (the medians, LBS and DQS ns per vertex in brackets):\n')
    print('| kernel | normals | ' + ' | '.join(f'{k} influences' for k in ks) + ' |')
    print('|---|---|' + '---:|' * len(ks))
    for kern in ['C++ ours', 'Java scalar', 'Java vector-256']:
        for n in ['none', 'blended']:
            cells = []
            for k in ks:
                l, _ = cell(('sweep', kern, n, 'lbs', sweep, k))
                d, _ = cell(('sweep', kern, n, 'dqs', sweep, k))
                cells.append(f'{d / l:.2f} ({l:.1f}, {d:.1f})' if l and d else '')
            print(f'| {kern} | {n} | ' + ' | '.join(cells) + ' |')
PY
