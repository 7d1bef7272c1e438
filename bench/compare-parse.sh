#!/bin/sh
# Import speed of skinlab, assimp and three.js' ColladaLoader on the same files, in one session:
# our assets, the shared corpus (read in place) and a generated file. Machines are noisy, so what
# counts are the ratios (assimp median / ours, three.js median / ours) measured here together.
#
# usage: bench/compare-parse.sh [--sessions K] [--triangles N] [--runs N] [--warmup-seconds S] [--out DIR]
#   --sessions K        run both benchmarks K times, alternating (default 1); the table then gives
#                       medians over sessions and each ratio's median over sessions
#   --triangles N       triangles of the generated file (default 1000000; 0 for none)
#   --runs N            timed imports per file under 10 MB, for every tool (default 25)
#   --warmup-seconds S  shared warm-up per tool (default 3)
#   --out DIR           keep the raw JSON of both benchmarks there
# Needs JDK 17, Gradle (builds desktop/build/install when missing), Node >= 18 and npm (installs
# bench/threejs/node_modules from package-lock.json when missing). Ours runs on the start script's
# Java: the newest JDK >= 17 installed, or SKINLAB_JAVA_HOME=DIR (=build: the default java); the
# table names it (docs/running.md, "Which Java runs skinlab").
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
triangles=1000000
runs=25
sessions=1
warmup=3
out=
while [ $# -gt 0 ]; do
    case "$1" in
        --sessions) sessions=$2; shift 2 ;;
        --triangles) triangles=$2; shift 2 ;;
        --runs) runs=$2; shift 2 ;;
        --warmup-seconds) warmup=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
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

load() { cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?'; }
session=1
while [ "$session" -le "$sessions" ]; do
    echo "compare-parse: session $session of $sessions, load average before: $(load)" >&2
    # shellcheck disable=SC2046  # file names come from find above and hold no spaces
    "$skinlab" bench parse --compare-assimp --json --runs "$runs" --warmup-seconds "$warmup" \
        $(cat "$tmp/files") > "$out/skinlab-assimp-$session.json"
    # ColladaLoader needs about 2 GB of heap for the 1M-triangle file.
    # shellcheck disable=SC2046
    node --expose-gc --max-old-space-size=4096 bench/threejs/parse-bench.mjs --json --runs "$runs" \
        --warmup-seconds "$warmup" $(cat "$tmp/files") > "$out/threejs-$session.json"
    session=$((session + 1))
done
echo "compare-parse: load average after: $(load)" >&2

node bench/combine-parse.mjs "$out" "$sessions"
