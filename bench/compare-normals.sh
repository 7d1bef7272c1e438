#!/bin/sh
# Is DQS faster than LBS, with and without normals? One session, per kernel: the C++ programs
# (../shared/perf/skin_ref.cpp with normals; bench/cpp/skin_positions.cpp positions only, plus its
# with-normals calibration) and `skinlab bench skinning` with the scalar and the vector kernels,
# normals none, blended (the reference's rule) and exact, on the reference's synthetic data.
# Interleaved and repeated: each round runs every variant once, in the same order; the tables give
# per variant the median over the rounds of each run's median and of each run's minimum ns per
# vertex, with the smallest and largest, and the DQS/LBS ratios (on a busy machine the minimum is
# the less disturbed figure).
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
#   --report FILE        only print the tables of raw lines kept with --out
# Needs g++ (builds both programs in a temporary folder), python3 and the installed skinlab
# (gradle -q installDist); ours runs on the start script's Java (the newest JDK >= 17 installed, or
# SKINLAB_JAVA_HOME=DIR). About 3 minutes per round for the tables and 7 for the sweep here.
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
rounds=3
seconds=1.5
warmup=1.5
sizes="10000 100000"
influences="1 2 4 8"
sweep=100000
out=
report=
while [ $# -gt 0 ]; do
    case "$1" in
        --rounds) rounds=$2; shift 2 ;;
        --seconds) seconds=$2; shift 2 ;;
        --warmup-seconds) warmup=$2; shift 2 ;;
        --sizes) sizes=$2; shift 2 ;;
        --influences) influences=$2; shift 2 ;;
        --sweep-size) sweep=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        --report) report=$2; shift 2 ;;
        -h|--help) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "compare-normals: unknown argument $1" >&2; exit 2 ;;
    esac
done

report() { # raw lines -> tables
python3 - "$1" <<'PY'
import json, re, statistics, sys
runs = {}   # (table, kernel, normals, method, V, K) -> [(min ns, median ns)] per run
checks = {}
java = set()
for line in open(sys.argv[1]):
    m = re.match(r'cpp (\w+) (\d+) V=(\d+)\s+(\S+)\s+min\s+([\d.]+)\s+median\s+([\d.]+).*checksum ([-\d.]+)', line)
    if m:
        table, k, v, variant = m[1], int(m[2]), int(m[3]), m[4]
        method = variant.split('-')[1]
        if variant in ('c-lbs', 'c-dqs'):
            key = (table, 'C++ skin_ref', 'blended', method, v, k)
        elif variant.endswith('-nrm'):
            key = (table, 'C++ ours', 'blended', method, v, k)
        else:
            key = (table, 'C++ ours', 'none', method, v, k)
        runs.setdefault(key, []).append((float(m[5]), float(m[6])))
        checks[key] = m[7]
        continue
    m = re.match(r'java (\w+) (\{.*\})', line)
    if m:
        j = json.loads(m[2])
        java.add(f"Java {j['java']} ({j['javaVendor']})")
        key = (m[1], 'Java ' + j['implementation'], j['normals'], j['method'], j['vertices'], j['influences'])
        runs.setdefault(key, []).append((j['minNsPerVertex'], j['medianNsPerVertex']))
        checks[key] = f"{j['checksum']:.6f}"
sizes = sorted({k[4] for k in runs if k[0] == 'main'})
ks = sorted({k[5] for k in runs if k[0] == 'sweep'})
sweeps = sorted({k[4] for k in runs if k[0] == 'sweep'})
kernels = ['C++ skin_ref', 'C++ ours', 'Java scalar', 'Java vector-256']
def stat(key, which):
    xs = [r[which] for r in runs.get(key, [])]
    return (statistics.median(xs), min(xs), max(xs)) if xs else None
def text(s):
    return f'{s[0]:.2f} ({s[1]:.2f}-{s[2]:.2f})' if s else ''
def ratio(a, b):
    return f'{b[0] / a[0]:.2f}' if a and b else ''
rounds = max(len(x) for x in runs.values())
print(f"ours on {', '.join(sorted(java))}; {rounds} rounds. Per run its median and its minimum ns per vertex;")
print("a cell gives the median over the rounds (the smallest and largest in brackets).\n")
for v in sizes:
    print(f'V = {v}, 4 influences:\n')
    print('| kernel | normals | LBS median | DQS median | DQS / LBS | LBS min | DQS min | DQS / LBS (min) | checksums LBS, DQS |')
    print('|---|---|---:|---:|---:|---:|---:|---:|---|')
    for kern in kernels:
        for n in ['none', 'blended', 'exact']:
            key = lambda method: ('main', kern, n, method, v, 4)
            lm, dm, ln, dn = stat(key('lbs'), 1), stat(key('dqs'), 1), stat(key('lbs'), 0), stat(key('dqs'), 0)
            if not lm and not dm:
                continue
            print(f"| {kern} | {n} | {text(lm)} | {text(dm)} | {ratio(lm, dm)} | {text(ln)} | {text(dn)} | "
                  f"{ratio(ln, dn)} | {checks.get(key('lbs'), '')}, {checks.get(key('dqs'), '')} |")
    print()
for v in sweeps:
    print(f'DQS / LBS by influences, V = {v}: the ratio of the medians, then of the minima, and LBS and DQS by the minima in ns per vertex:\n')
    print('| kernel | normals | ' + ' | '.join(f'{k} influences' for k in ks) + ' |')
    print('|---|---|' + '---:|' * len(ks))
    for kern in ['C++ ours', 'Java scalar', 'Java vector-256']:
        for n in ['none', 'blended']:
            cells = []
            for k in ks:
                lm, dm = stat(('sweep', kern, n, 'lbs', v, k), 1), stat(('sweep', kern, n, 'dqs', v, k), 1)
                ln, dn = stat(('sweep', kern, n, 'lbs', v, k), 0), stat(('sweep', kern, n, 'dqs', v, k), 0)
                cells.append(f'{ratio(lm, dm)}, {ratio(ln, dn)} ({ln[0]:.1f}, {dn[0]:.1f})' if ln and dn else '')
            print(f'| {kern} | {n} | ' + ' | '.join(cells) + ' |')
    print()
PY
}

if [ -n "$report" ]; then
    report "$report"
    exit 0
fi

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
report "$raw"
