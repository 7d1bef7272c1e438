#!/usr/bin/env bash
# Exports every model file under the given folders (or the given files) with `skinlab export`
# (lbs, dqs and cor) and runs the Khronos glTF-Validator (validate.mjs) over each GLB. Prints one
# JSON line per file and a summary; exits 1 when any export fails or any GLB has a validator error
# or warning (infos, such as the validator not knowing SKINLAB_skinning, are reported only).
#
#   bash bench/threejs/validate-exports.sh SKINLAB_BIN PATH...
#   e.g. bash bench/threejs/validate-exports.sh desktop/build/install/skinlab/bin/skinlab assets ../shared/corpus
# Needs `npm ci` in bench/threejs once.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
skinlab="$1"
shift
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
files=()
for p in "$@"; do
    if [ -d "$p" ]; then
        while IFS= read -r f; do files+=("$f"); done < <(find "$p" -type f \( -name '*.dae' -o -name '*.glb' -o -name '*.gltf' \) | sort)
    else
        files+=("$p")
    fi
done
failed=0
exported=()
for f in "${files[@]}"; do
    name="$(echo "$f" | tr '/' '_')"
    target="$out/${name%.*}-${name##*.}.glb"
    if "$skinlab" export "$f" --out "$target" > "$out/log" 2>&1; then
        exported+=("$target")
    else
        status=$?
        # A file the importer refuses (the corpus's malformed category) is not the exporter's to fix.
        if [ "$status" -eq 3 ]; then
            echo "{\"file\":\"$f\",\"skipped\":\"not importable (exit 3): $(tail -1 "$out/log" | tr -d '"')\"}"
        else
            echo "{\"file\":\"$f\",\"exportFailed\":$status}"
            cat "$out/log" >&2
            failed=1
        fi
    fi
done
if [ "${#exported[@]}" -eq 0 ]; then
    echo "nothing exported" >&2
    exit 1
fi
node "$here/validate.mjs" --json "${exported[@]}" | tee "$out/report" || true
reported=$(grep -c '"file"' "$out/report" || true)
if [ "$reported" -ne "${#exported[@]}" ]; then
    echo "the validator reported on $reported of ${#exported[@]} files" >&2
    exit 1
fi
count() { grep -o "\"$1\":[0-9]*" "$out/report" | cut -d: -f2 | awk '{ s += $1 } END { print s + 0 }'; }
errors=$(count errors)
warnings=$(count warnings)
infos=$(count infos)
echo "validated ${#exported[@]} exported files: $errors errors, $warnings warnings, $infos infos"
if [ "$failed" -ne 0 ] || [ "$errors" -ne 0 ] || [ "$warnings" -ne 0 ]; then
    exit 1
fi
