#!/bin/sh
# Regenerates the committed three.js references of the glTF agreement test (ThreeJsAgreementTest;
# docs/references.md, "glTF: three.js"): our fixtures, our assets' .glb and, when present, the
# third-party samples (tools/gltf/gltf-samples.py says which and from where).
#
#   sh bench/threejs/make-gltf-references.sh        from the repository root, after `npm ci` in bench/threejs
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
ref="node $root/bench/threejs/gltf-reference.mjs"
fixtures=$root/core/src/test/resources/gltf
$ref --out "$fixtures/threejs" "$fixtures"/*.gltf "$fixtures"/*.glb
assets=$(find "$root/assets" -name '*.glb' | sort)
if [ -n "$assets" ]; then
    $ref --out "$root/assets/reference/threejs" $assets
fi
samples=${SKINLAB_GLTF_SAMPLES:-$root/../shared/gltf-samples}
if [ -d "$samples" ]; then
    $ref --out "$fixtures/threejs/samples" $(find "$samples" -mindepth 2 -maxdepth 2 \( -name '*.gltf' -o -name '*.glb' \) | sort)
else
    echo "no samples at $samples: their references are left as they are"
fi
