#!/usr/bin/env bash
# Rebuilds the pictures in docs/images with skinlab itself: each is a replayed UI script
# (docs/desktop.md, "Headless and scripted use"). Under Xvfb when there is no display.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
gradle -q :desktop:installDist
skinlab=desktop/build/install/skinlab/bin/skinlab
run() {
  if [ -n "${DISPLAY:-}" ]; then "$@"; else xvfb-run -a -s '-screen 0 1920x1080x24' "$@"; fi
}
run "$skinlab" view --size 1280x800 --script docs/images/viewer.txt
# The mixer panel: humanoid-moves on the blend pad, with a wave and an additive lean (docs/desktop.md).
run "$skinlab" view assets/characters/humanoid-moves.glb --size 1280x960 --yaw 35 --script docs/images/viewer-layers.txt
run "$skinlab" view --size 1280x720 --split dqs --script docs/images/split.txt
run "$skinlab" view assets/cylinders/cylinder-twist-high.dae --size 1280x720 --view difference \
  --script docs/images/difference.txt
# The AR preview on one frame of the synthetic demo video (the model on the printed marker).
demo=$(mktemp -d)
"$skinlab" ar-demo "$demo" --frames 40 --size 960x720
find "$demo" -name 'frame-*.png' ! -name frame-0002.png -delete
run "$skinlab" ar --images "$demo" --intrinsics "$demo/intrinsics.json" --method dqs --size 1280x800 \
  --screenshot docs/images/ar-demo.png
rm -rf "$demo"
# LBS, DQS and CoR side by side (docs/skinning.md): the twist cylinder at 172 degrees and the bend
# cylinder at 90 degrees seen from the side.
for m in lbs dqs cor; do
  run "$skinlab" view assets/cylinders/cylinder-twist-high.dae --method "$m" --time 4 --hide-ui --size 360x540 \
    --screenshot "docs/images/methods-twist-$m.png"
  run "$skinlab" view assets/cylinders/cylinder-bend.dae --method "$m" --hide-ui --size 360x540 \
    --script docs/images/methods-bend.txt
  mv docs/images/methods-bend.png "docs/images/methods-bend-$m.png"
done
# The checker view: LBS and DQS at 172 degrees of twist, and the bend cylinder's fold at 170 degrees
# from its side and above (docs/desktop.md).
run "$skinlab" view assets/cylinders/cylinder-twist-high.dae --time 4 --method lbs --split dqs --view checker \
  --hide-ui --size 720x480 --screenshot docs/images/checker.png
run "$skinlab" view assets/cylinders/cylinder-bend.dae --time 4 --yaw 90 --pitch 40 --method lbs --split dqs \
  --view checker --hide-ui --size 720x400 --screenshot docs/images/bend-checker-pitch.png
# Bulge-free DQS against DQS on the bend cylinder at 90 and 170 degrees (docs/skinning.md).
for m in dqs bfdqs; do
  run "$skinlab" view assets/cylinders/cylinder-bend.dae --method "$m" --hide-ui --size 360x540 \
    --script docs/images/methods-bend.txt
  mv docs/images/methods-bend.png "docs/images/methods-bend-$m.png"
  run "$skinlab" view assets/cylinders/cylinder-bend.dae --method "$m" --hide-ui --size 360x540 \
    --script docs/images/bend-170.txt
  mv docs/images/bend-170.png "docs/images/bend-170-$m.png"
done
# The Android app's screen as Robolectric's native graphics draws it at the target SDK (API 37 on a
# JDK 21 or newer, else 34): the status line and the buttons; the GL view (camera and model) stays empty.
rm -f android/build/screenshots/android-app-api*.png
gradle -q :android:appTestTargetSdk -PtestFilter='.*ScreenshotTest'
cp android/build/screenshots/android-app-api*.png docs/images/android-app.png
