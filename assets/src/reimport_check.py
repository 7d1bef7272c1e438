"""Re-import every exported .dae into an empty Blender scene and check that Blender reads it back:
exactly one armature and one mesh, the mesh deformed by that armature (Armature modifier, one
vertex group per joint), an action on the armature whose key frames are the key times of the file,
and, if assets/reference/<name>.json exists, that the re-imported rig deforms the mesh like the
original rig did at every key (Blender's deformation of the imported file vs. of the source rig).
Blender's importer knows no <animation_clip>, so a file with several clips is checked clip by
clip, each from a copy holding that clip's animations alone (common.write_single_clip_dae).

Usage (from the repository root):
  blender --background --factory-startup --python-exit-code 1 \
      --python assets/src/reimport_check.py -- ASSETS_DIR
Exits with status 1 (through an exception) if a check fails.
"""
import json
import os
import sys
import tempfile
import xml.etree.ElementTree as ET

import bpy

sys.dont_write_bytecode = True   # no __pycache__ in the source folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

NS = "{http://www.collada.org/2005/11/COLLADASchema}"
TOLERANCE = 1e-3   # metres


def key_times_in_file(path):
    times = set()
    for arr in ET.parse(path).getroot().iter(NS + "float_array"):
        if arr.get("id", "").endswith("-input-array"):
            times.update(float(x) for x in arr.text.split())
    return sorted(times)


def check_one(path, ref):
    """ref: the reference keys ({"keys": [...]}) of the file (or of its one clip), or None."""
    failures = []
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = common.FPS
    result = bpy.ops.wm.collada_import(filepath=path)
    if result != {'FINISHED'}:
        return ["import returned %r" % (result,)]
    objs = list(scene.objects)
    arms = [o for o in objs if o.type == 'ARMATURE']
    meshes = [o for o in objs if o.type == 'MESH']
    others = [o.name for o in objs if o.type not in ('ARMATURE', 'MESH')]
    if len(arms) != 1 or len(meshes) != 1 or others:
        return ["expected one armature and one mesh, got %s" % [(o.name, o.type) for o in objs]]
    arm, mesh = arms[0], meshes[0]
    mods = [m for m in mesh.modifiers if m.type == 'ARMATURE']
    if len(mods) != 1 or mods[0].object != arm:
        failures.append("mesh is not deformed by the armature (modifiers %s)" % [m.type for m in mesh.modifiers])
    bones = {b.name for b in arm.data.bones}
    groups = {g.name for g in mesh.vertex_groups}
    if not groups <= bones:
        failures.append("vertex groups without bone: %s" % sorted(groups - bones))
    ad = arm.animation_data
    action = ad.action if ad else None
    if action is None or not action.fcurves:
        return failures + ["no action on the armature"]
    frames = sorted({round(kp.co[0], 3) for fc in action.fcurves for kp in fc.keyframe_points})
    want = [round(t * common.FPS, 3) for t in key_times_in_file(path)]
    if frames != want:
        failures.append("imported key frames %s != file key times x %d fps %s" % (frames, common.FPS, want))
    animated_bones = {fc.data_path.split('"')[1] for fc in action.fcurves if fc.data_path.startswith("pose.bones")}
    print("  imported: armature %r (%d bones), mesh %r (%d vertices, %d polygons, %d vertex groups), "
          "action %r: %d F-curves on %d bones, key frames %s"
          % (arm.name, len(bones), mesh.name, len(mesh.data.vertices), len(mesh.data.polygons),
             len(groups), action.name, len(action.fcurves), len(animated_bones), frames))

    if ref is None:
        print("  (no reference)")
        return failures
    worst = 0.0
    for key in ref["keys"]:
        scene.frame_set(key["frame"])
        dg = bpy.context.evaluated_depsgraph_get()
        ev = mesh.evaluated_get(dg)
        me = ev.to_mesh()
        for i, p in key["vertices"].items():
            co = mesh.matrix_world @ me.vertices[int(i)].co
            worst = max(worst, max(abs(a - b) for a, b in zip(co, p)))
        ev.to_mesh_clear()
    print("  re-imported deformation vs original rig at %d keys: max deviation %.2e m" % (len(ref["keys"]), worst))
    if worst > TOLERANCE:
        failures.append("re-imported deformation deviates %.3g m from the original" % worst)
    return failures


def main():
    args = common.script_args()
    assets = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    ref_dir = os.path.join(assets, "reference")
    paths = []
    for dirpath, dirnames, filenames in os.walk(assets):
        dirnames.sort()
        paths += [os.path.join(dirpath, f) for f in sorted(filenames) if f.lower().endswith(".dae")]
    if not paths:
        raise SystemExit("no .dae files under %s" % assets)
    all_failures = []
    tmp = tempfile.TemporaryDirectory()
    for p in paths:
        rel = os.path.relpath(p, assets)
        ref_path = os.path.join(ref_dir, os.path.splitext(os.path.basename(p))[0] + ".json")
        ref = None
        if os.path.exists(ref_path):
            with open(ref_path, encoding="utf-8") as fh:
                ref = json.load(fh)
        clips = common.dae_clip_names(p)
        if not clips:
            print("== re-import %s" % rel)
            runs = [(rel, p, ref)]
        else:
            runs = []
            for clip in clips:
                one = os.path.join(tmp.name, "%s.dae" % clip)
                common.write_single_clip_dae(p, clip, one)
                clip_ref = None if ref is None else next(c for c in ref["clips"] if c["name"] == clip)
                runs.append(("%s clip %s" % (rel, clip), one, clip_ref))
        for label, path, r in runs:
            if clips:
                print("== re-import %s (a copy with this clip alone)" % label)
            fails = check_one(path, r)
            for f in fails:
                print("  FAIL: " + f)
            all_failures += ["%s: %s" % (label, f) for f in fails]
    tmp.cleanup()
    if all_failures:
        raise RuntimeError("re-import check failed:\n  " + "\n  ".join(all_failures))
    print("re-import check passed (%d files)" % len(paths))


main()
