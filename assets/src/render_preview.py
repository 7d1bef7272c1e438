"""Render a preview strip of an exported .dae, as Blender reads it back (optional, for humans).

Usage (from the repository root):
  blender --background --factory-startup --python-exit-code 1 \
      --python assets/src/render_preview.py -- IN.dae OUT.png VIEW [--follow BONE] TIME_S [TIME_S ...]
VIEW is front (oblique, from the front right and a bit above) or side (from +X, the figure's left).
A time may name a clip of a file with several clips, CLIP@TIME_S (e.g. walk@0.25): that tile is
rendered from a copy of the file holding that clip alone (Blender's importer knows no clips).
--follow BONE moves the camera along with the bone's horizontal travel (root motion), so that a
figure walking away from its start stays in the picture.

Imports IN.dae with bpy.ops.wm.collada_import, then renders the imported scene with the Workbench
engine at the given times (seconds) from a fixed oblique front view and writes them side by side
into one PNG. The camera and light exist only in this preview scene, never in the assets.
"""
import math
import os
import sys
import tempfile

import bpy
from mathutils import Vector

sys.dont_write_bytecode = True   # no __pycache__ in the source folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

TILE = 240
VIEWS = {"front": Vector((0.55, -1.0, 0.35)), "side": Vector((1.0, 0.0, 0.08))}


def import_scene(path, view):
    """Empty scene, the file imported, an orthographic camera framing its bounding box as
    imported; returns (scene, camera, the camera's location before any following)."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = common.FPS
    bpy.ops.wm.collada_import(filepath=os.path.abspath(path))
    meshes = [o for o in scene.objects if o.type == 'MESH']
    assert meshes, "no mesh imported"

    # frame the rest-pose bounding box, slightly enlarged
    pts = [m.matrix_world @ Vector(c) for m in meshes for c in m.bound_box]
    lo = Vector((min(p.x for p in pts), min(p.y for p in pts), min(p.z for p in pts)))
    hi = Vector((max(p.x for p in pts), max(p.y for p in pts), max(p.z for p in pts)))
    centre = (lo + hi) / 2
    size = max((hi - lo).length, 0.5)

    cam_data = bpy.data.cameras.new("PreviewCamera")
    cam_data.type = 'ORTHO'
    cam_data.ortho_scale = max(hi.z - lo.z, hi.x - lo.x, hi.y - lo.y) * 1.3
    cam = bpy.data.objects.new("PreviewCamera", cam_data)
    scene.collection.objects.link(cam)
    direction = VIEWS[view].normalized()
    cam.location = centre + direction * size * 3
    cam.rotation_euler = (-direction).to_track_quat('-Z', 'Y').to_euler()
    scene.camera = cam

    scene.render.engine = 'BLENDER_WORKBENCH'
    scene.display.shading.light = 'STUDIO'
    scene.display.shading.color_type = 'MATERIAL'
    scene.display.shading.show_cavity = False
    scene.render.resolution_x = TILE
    scene.render.resolution_y = TILE
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.render.image_settings.file_format = 'PNG'
    scene.render.image_settings.color_mode = 'RGB'
    scene.render.image_settings.compression = 100
    return scene, cam, cam.location.copy()


def travel(scene, bone):
    """How far the bone's head has moved horizontally from its rest place, in world axes."""
    arm = next(o for o in scene.objects if o.type == 'ARMATURE')
    pb = arm.pose.bones[bone]
    moved = arm.matrix_world @ pb.head - arm.matrix_world @ pb.bone.head_local
    return Vector((moved.x, moved.y, 0.0))


def main():
    args = common.script_args()
    follow = None
    if "--follow" in args:
        at = args.index("--follow")
        follow = args[at + 1]
        args = args[:at] + args[at + 2:]
    if len(args) < 4 or args[2] not in VIEWS:
        raise SystemExit("usage: render_preview.py -- IN.dae OUT.png front|side [--follow BONE] "
                         "TIME_S|CLIP@TIME_S [...]")
    src, out, view = args[0], args[1], args[2]
    tiles_wanted = [(a.split("@")[0], float(a.split("@")[1])) if "@" in a else (None, float(a)) for a in args[3:]]

    tiles = []
    loaded = scene = cam = cam_home = None
    with tempfile.TemporaryDirectory() as tmp:
        for i, (clip, t) in enumerate(tiles_wanted):
            if scene is None or clip != loaded:
                path = src
                if clip is not None:
                    path = os.path.join(tmp, clip + ".dae")
                    common.write_single_clip_dae(src, clip, path)
                scene, cam, cam_home = import_scene(path, view)
                loaded = clip
            frame = int(round(t * common.FPS))
            scene.frame_set(frame)
            if follow is not None:
                cam.location = cam_home + travel(scene, follow)
            scene.render.filepath = os.path.join(tmp, "tile%02d.png" % i)
            bpy.ops.render.render(write_still=True)
            img = bpy.data.images.load(scene.render.filepath)
            tiles.append(list(img.pixels))
            bpy.data.images.remove(img)
    strip = bpy.data.images.new("strip", TILE * len(tiles), TILE, alpha=False)
    scene.render.image_settings.color_mode = 'BW'     # grey PNG: keeps previews well under 200 KB
    width = TILE * len(tiles)
    pixels = [0.0] * (width * TILE * 4)
    for i, tile in enumerate(tiles):
        for row in range(TILE):
            dst = (row * width + i * TILE) * 4
            src_off = row * TILE * 4
            pixels[dst:dst + TILE * 4] = tile[src_off:src_off + TILE * 4]
    strip.pixels = pixels
    strip.filepath_raw = os.path.abspath(out)
    strip.file_format = 'PNG'
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    strip.save_render(os.path.abspath(out), scene=scene)
    print("wrote %s (%d frames: %s)" % (out, len(tiles), " ".join(args[3:])))


main()
