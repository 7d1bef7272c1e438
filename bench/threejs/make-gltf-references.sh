#!/bin/sh
# Regenerates the committed three.js references of the glTF agreement test (ThreeJsAgreementTest;
# docs/references.md, "glTF: three.js"): our fixtures, our assets' .glb and, when present, the
# third-party samples (tools/gltf/gltf-samples.py says which and from where); then the blend
# references (blend-reference.mjs) of humanoid-moves and, when present, Fox.
#
#   sh bench/threejs/make-gltf-references.sh        from the repository root, after `npm ci` in bench/threejs
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
ref="node $root/bench/threejs/gltf-reference.mjs"
fixtures=$root/core/src/test/resources/gltf
$ref --out "$fixtures/threejs" "$fixtures"/*.gltf "$fixtures"/*.glb
assets=$(find "$root/assets" -name '*.glb' ! -name 'cylinder-*-full.glb' | sort)
if [ -n "$assets" ]; then
    $ref --out "$root/assets/reference/threejs" $assets
fi
# The whole-turn cylinders (assets/README.md): every one of their 25 keys and every midpoint. The
# default budget would keep every other key, whose midpoints are keys again, and between keys is
# where a reader could take the long way round past a half turn.
full=$(find "$root/assets" -name 'cylinder-*-full.glb' | sort)
if [ -n "$full" ]; then
    $ref --budget 60000 --out "$root/assets/reference/threejs" $full
fi
samples=${SKINLAB_GLTF_SAMPLES:-$root/../shared/gltf-samples}
if [ -d "$samples" ]; then
    $ref --out "$fixtures/threejs/samples" $(find "$samples" -mindepth 2 -maxdepth 2 \( -name '*.gltf' -o -name '*.glb' \) | sort)
else
    echo "no samples at $samples: their references are left as they are"
fi
# Clips blended by three.js' AnimationMixer (blend-reference.mjs, the cases in blend-cases.json),
# each file's clips also posed alone against its single-clip reference above.
blend="node $root/bench/threejs/blend-reference.mjs --out $root/assets/reference/threejs/blends"
$blend --single "$root/assets/reference/threejs/humanoid-moves.glb.json.gz" "$root/assets/characters/humanoid-moves.glb"
if [ -f "$samples/Fox/Fox-notexture.gltf" ]; then
    $blend --single "$fixtures/threejs/samples/Fox-notexture.gltf.json.gz" "$samples/Fox/Fox-notexture.gltf"
else
    echo "no Fox at $samples/Fox: its blend reference is left as it is"
fi
