#!/usr/bin/env bash
# Places the glTF-Validator's test files (KhronosGroup/glTF-Validator, folder test/: about 370
# .gltf/.glb files, each with the validator's report beside it as <file>.report.json) in
# ../shared/gltf-validator/, where GltfValidatorSuiteTest reads them. They are never committed.
#
#   tools/get-gltf-validator-suite.sh [SOURCE] [DEST]
#
# SOURCE: a local git repository of the validator (bare or not), e.g. a mirror; without it the
# repository is cloned (depth 1) from GitHub. DEST defaults to ../shared/gltf-validator beside the
# repository. The folder is replaced; the commit it came from is written to DEST/COMMIT.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source="${1:-}"
dest="${2:-$root/../shared/gltf-validator}"
url=https://github.com/KhronosGroup/glTF-Validator.git

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
if [ -z "$source" ]; then
  git clone -q --depth 1 "$url" "$work/repo"
  source="$work/repo"
fi
commit="$(git -C "$source" rev-parse HEAD)"
mkdir -p "$work/out"
git -C "$source" archive "$commit" test | tar -x -C "$work/out"
count="$(find "$work/out/test" -name '*.report.json' | wc -l)"
if [ "$count" -lt 300 ]; then
  echo "only $count reports under test/ at $commit: not the validator's suite" >&2
  exit 1
fi
mkdir -p "$(dirname "$dest")"
rm -rf "$dest"
mv "$work/out/test" "$dest"
echo "$commit" > "$dest/COMMIT"
echo "glTF-Validator suite ($count files with reports, commit ${commit:0:12}) in $dest"
