#!/usr/bin/env bash
# Regenerate every asset under assets/ from the Blender scripts in assets/src/, then check them.
#
#   bash assets/src/build_assets.sh              # build + check_assets.py + Blender re-import check
#                                                # + skinning references (make/check_skin_reference.py)
#   bash assets/src/build_assets.sh --previews   # also render assets/src/previews/*.png
#
# Needs Blender 3.4 (`blender` on PATH, or set BLENDER=/path/to/blender) and python3.
# Fails on the first error. Blender's output of each step goes to a log that is shown on failure.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/../.."       # repository root
BLENDER="${BLENDER:-blender}"
SRC=assets/src
REF=assets/reference
PREVIEWS=0
for arg in "$@"; do
  case "$arg" in
    --previews) PREVIEWS=1 ;;
    *) echo "unknown argument: $arg" >&2; exit 2 ;;
  esac
done

LOGDIR="$(mktemp -d)"
trap 'rm -rf "$LOGDIR"' EXIT

"$BLENDER" --version | head -n 1

# run_blender LOGNAME SCRIPT [ARGS...]: headless Blender, factory settings, non-zero exit on error.
# -t 1 (one thread): with several threads Blender sums vertex normals in a varying order and a few
# normal components differ in the 7th digit from run to run; single-threaded the output is
# byte-identical on every run.
run_blender() {
  local log="$LOGDIR/$1.log"; shift
  local script="$1"; shift
  if ! "$BLENDER" -t 1 --background --factory-startup --python-exit-code 1 --python "$script" -- "$@" >"$log" 2>&1; then
    cat "$log" >&2
    echo "FAILED: $script $*" >&2
    exit 1
  fi
  grep -E '^(skin:|cylinder |humanoid:|tentacle:|limb |wrote |  imported:|  re-imported|re-import check|  [0-9]+ key times|  skip )' "$log" || true
}

mkdir -p assets/cylinders assets/characters assets/creatures assets/stretch assets/twist "$REF"

for variant in twist-low twist-high bend twist-full bend-full; do
  echo "--- cylinder-$variant"
  rm -f "assets/cylinders/cylinder-$variant.dae" "$REF/cylinder-$variant.json"
  run_blender "cylinder-$variant" "$SRC/make_cylinder.py" "$variant" \
    "assets/cylinders/cylinder-$variant.dae" "$REF/cylinder-$variant.json"
done

echo "--- humanoid-walk"
rm -f assets/characters/humanoid-walk.dae "$REF/humanoid-walk.json"
run_blender humanoid "$SRC/make_humanoid.py" assets/characters/humanoid-walk.dae "$REF/humanoid-walk.json"

echo "--- humanoid-moves"
rm -f assets/characters/humanoid-moves.dae assets/characters/humanoid-moves.glb "$REF/humanoid-moves.json"
run_blender humanoid-moves "$SRC/make_mover.py" assets/characters/humanoid-moves.dae "$REF/humanoid-moves.json"

echo "--- tentacle-wave"
rm -f assets/creatures/tentacle-wave.dae "$REF/tentacle-wave.json"
run_blender tentacle "$SRC/make_tentacle.py" assets/creatures/tentacle-wave.dae "$REF/tentacle-wave.json"

echo "--- limb-stretch"
rm -f assets/stretch/limb-stretch.dae "$REF/limb-stretch.json"
run_blender limb-stretch "$SRC/make_limb.py" stretch assets/stretch/limb-stretch.dae "$REF/limb-stretch.json"

echo "--- arm-twist"
rm -f assets/twist/arm-twist.dae "$REF/arm-twist.json"
run_blender arm-twist "$SRC/make_limb.py" twist assets/twist/arm-twist.dae "$REF/arm-twist.json"

echo "--- check_assets.py"
python3 "$SRC/check_assets.py" assets

echo "--- Blender re-import check"
run_blender reimport "$SRC/reimport_check.py" assets

echo "--- skinning references: Blender's LBS and DQS of every vertex at every key (docs/references.md)"
rm -f assets/reference/skinning/*.json
run_blender skinref "$SRC/make_skin_reference.py" assets
python3 "$SRC/check_skin_reference.py" assets

if [ "$PREVIEWS" = 1 ]; then
  echo "--- previews"
  mkdir -p "$SRC/previews"
  run_blender p1 "$SRC/render_preview.py" assets/characters/humanoid-walk.dae "$SRC/previews/humanoid-walk-side.png" side 0 0.125 0.25 0.375 0.5
  run_blender p2 "$SRC/render_preview.py" assets/characters/humanoid-walk.dae "$SRC/previews/humanoid-walk-front.png" front 0 0.25 0.5 0.75
  run_blender p3 "$SRC/render_preview.py" assets/creatures/tentacle-wave.dae "$SRC/previews/tentacle-wave.png" side 0 0.5 1 1.5
  run_blender p4 "$SRC/render_preview.py" assets/cylinders/cylinder-twist-low.dae "$SRC/previews/cylinder-twist-low.png" front 0 1 2 3 4
  run_blender p5 "$SRC/render_preview.py" assets/cylinders/cylinder-twist-high.dae "$SRC/previews/cylinder-twist-high.png" front 0 1 2 3 4
  run_blender p6 "$SRC/render_preview.py" assets/cylinders/cylinder-bend.dae "$SRC/previews/cylinder-bend.png" side 0 1 2 3 4
  run_blender p7 "$SRC/render_preview.py" assets/stretch/limb-stretch.dae "$SRC/previews/limb-stretch.png" front 0 0.5 1
  run_blender p8 "$SRC/render_preview.py" assets/twist/arm-twist.dae "$SRC/previews/arm-twist.png" front 0 0.5 0.875 1
  run_blender p9 "$SRC/render_preview.py" assets/cylinders/cylinder-twist-full.dae "$SRC/previews/cylinder-twist-full.png" front 0 1.5 2.75 3.25 4.5 6
  run_blender p10 "$SRC/render_preview.py" assets/cylinders/cylinder-bend-full.dae "$SRC/previews/cylinder-bend-full.png" side 0 1.5 2.75 3.25 4.5 6
  run_blender p11 "$SRC/render_preview.py" assets/characters/humanoid-moves.dae "$SRC/previews/humanoid-moves-front.png" front --follow hips idle@1 walk@0.25 run@0.125 wave@0.375 lean@1.5
  run_blender p12 "$SRC/render_preview.py" assets/characters/humanoid-moves.dae "$SRC/previews/humanoid-moves-side.png" side --follow hips walk@0 walk@0.25 walk@0.5 run@0 run@0.125 run@0.25
fi

echo "all assets built and checked"
