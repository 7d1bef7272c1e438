#!/usr/bin/env bash
# Checks the debug APK as CI does (no device here): manifest facts through aapt's badging, the v2+
# signature, our classes and the tracker's surviving R8's shrinking in the dex, BoofCV's dictionary
# resources and the skinning shader's formulas at the APK's root, and the size budget.
# Usage: android/check-apk.sh [APK]
set -euo pipefail
apk=${1:-"$(dirname "$0")/build/outputs/skinlab-debug.apk"}
budget=$((2 * 1024 * 1024))
fail() { echo "check-apk: FAIL: $*" >&2; exit 1; }
[ -f "$apk" ] || fail "$apk not found (gradle :android:apk builds it)"
for tool in aapt apksigner dexdump unzip; do
  command -v "$tool" >/dev/null || fail "'$tool' missing: apt-get install aapt apksigner dexdump unzip"
done

badging=$(aapt dump badging "$apk" 2>/dev/null)
expect() { grep -qF -- "$1" <<<"$badging" || fail "badging lacks: $1"; }
expect "package: name='org.skinlab.android'"
expect "launchable-activity: name='org.skinlab.android.SkinlabActivity'"
expect "uses-permission: name='android.permission.CAMERA'"
expect "uses-gl-es: '0x30000'"
expect "sdkVersion:'26'"
expect "targetSdkVersion:'37'"
expect "application: label='skinlab AR' icon='res/mipmap-anydpi-v26/ic_launcher.xml'"
echo "check-apk: badging: package, launchable activity, CAMERA, GLES 3.0, min SDK 26, target SDK 37, icon"

verify=$(apksigner verify --verbose "$apk" 2>&1) || fail "apksigner verify: $verify"
grep -q 'Verified using v2 scheme (APK Signature Scheme v2): true' <<<"$verify" || fail "no v2 signature"
v3=""
grep -q 'v3 scheme (APK Signature Scheme v3): true' <<<"$verify" && v3=", v3"
echo "check-apk: signature verifies (v2$v3)"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unzip -q -o "$apk" 'classes*.dex' -d "$work"
classes=$(for d in "$work"/classes*.dex; do dexdump "$d"; done | grep 'Class descriptor' | sed "s/.*'\(.*\)'.*/\1/")
for c in Lorg/skinlab/android/SkinlabActivity\; Lorg/skinlab/android/ArRenderer\; Lorg/skinlab/android/CameraSource\; \
    Lorg/skinlab/simulation/SkeletalAnimatedMesh\; Lorg/skinlab/ar/ArSession\; Lorg/skinlab/mixer/Mixer\; \
    Lorg/skinlab/android/logic/MixerControl\; Lorg/skinlab/android/logic/MarkerSteering\; \
    Lboofcv/alg/fiducial/square/DetectFiducialSquareHamming\; Lboofcv/alg/fiducial/square/QuadPoseEstimator\;; do
  grep -qxF "$c" <<<"$classes" || fail "dex lacks $c"
done
# R8 inlines and merges classes, so the importer is checked by package (its readers survive).
grep -q '^Lorg/skinlab/collada/' <<<"$classes" || fail "dex lacks core's COLLADA importer (org.skinlab.collada)"
echo "check-apk: dex: $(wc -l <<<"$classes") classes; the Activity, renderer, camera, the mixer and its buttons' steering, core's importer, simulation and AR session, BoofCV's detector and pose estimator present"

listing=$(unzip -l "$apk")
grep -q 'boofcv/factory/fiducial/aruco_mip_36h12.txt' <<<"$listing" || fail "BoofCV's dictionary resources missing"
grep -q ' org/skinlab/skinning/skinning.glsl$' <<<"$listing" || fail "the skinning shader's formulas (core's skinning.glsl) missing"
grep -q ' org/skinlab/ar/lens.glsl$' <<<"$listing" || fail "the background shader's lens formulas (core's lens.glsl) missing"
grep -q ' org/skinlab/internal/scene/material.glsl$' <<<"$listing" || fail "the model shader's material formulas (core's material.glsl) missing"
grep -q 'assets/models/humanoid-walk.dae' <<<"$listing" || fail "the default model is not bundled"
grep -q 'assets/models/humanoid-walk.glb' <<<"$listing" || fail "the default model's .glb twin is not bundled"
grep -q 'assets/models/humanoid-moves.glb' <<<"$listing" || fail "the five-clip humanoid (the mixer's buttons) is not bundled"
grep -q '^Lorg/skinlab/gltf/' <<<"$classes" || fail "dex lacks core's glTF importer (org.skinlab.gltf)"
size=$(stat -c %s "$apk")
echo "check-apk: size $size bytes ($(( size / 1024 )) KiB; budget $(( budget / 1024 )) KiB)"
[ "$size" -le "$budget" ] || fail "APK over the 2 MB budget"
echo "check-apk: OK"
