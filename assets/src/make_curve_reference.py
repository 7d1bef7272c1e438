"""Blender's own evaluation of smooth (Bezier) animation curves between keys: the reference for
the Java curve tests. Writes two committed test fixtures:

  core/src/test/resources/fixtures/animation/blender-curves.dae   (exported by Blender 3.4)
  core/src/test/resources/fixtures/animation/blender-curves.json  (Blender's deformed meshes)

Usage (from the repository root; Blender 3.4.1, `apt-get install blender` on Debian bookworm):
  blender -t 1 --background --factory-startup --python-exit-code 1 \
      --python assets/src/make_curve_reference.py -- core/src/test/resources/fixtures/animation

The scene is built from nothing: two armatures, each with one bone and one 0.5 m cube weighted
fully to it (an Armature modifier, the cube parented to the armature, every transform identity):
- RigRot: bone "Bone" from (0,0,0) to (0,0,1), rotating about its own X axis only (one Euler
  channel: Blender 3.4's decomposed export re-expresses multi-axis Euler keys in the joint's frame
  and gives a child bone its parent's curves, so only a single-axis, single-bone rig keeps its
  curve shape in the file). Five keys at uneven frames with Blender's default (auto-clamped)
  handles; the inner keys are not extremes, so their handles slope and differ in length on the
  two sides.
- RigMove: bone "Bone" from (2,0,0) to (2,0,1), translating along its own Y axis (world +Z) with
  four Bezier keys, so a translate channel (no unit conversion) is checked too.

It exports with collada_export(keep_smooth_curves=True, export_animation_type_selection='keys',
export_animation_transformation_type_selection='decomposed') and then, in the ORIGINAL scene (no
re-import), evaluates each cube through the depsgraph at the key frames and at frames between
them (subframes included) and writes the world positions in the order of the geometry's
<vertices> POSITION source. Times are frame / 24 s, the exporter's own conversion.

It fails (exception, exit status 1) unless
- the written file has exactly the expected channels, one per rig, BEZIER throughout;
- each exported curve has the shape of the original F-curve: its tangents, taken relative to
  their key, equal the original handles relative to theirs (same times; values equal up to the
  sign and unit the exporter uses for that channel). This is what makes the file's curve and the
  scene's curve the same function, so a difference between the Java evaluation and this reference
  is the Java side's. For the rotation it also records the unit the tangent values are written in
  (radians, Blender's bug; see docs/importer.md);
- the file's POSITION i is Blender's vertex i (object coordinates, identity object transform), to
  1e-6 m, for every vertex;
- the cubes actually move between keys differently from a straight line (the curves matter).

JSON (numbers with 7 significant digits; Blender computes in float32):
  {"about": ..., "blender": "3.4.1", "file": "blender-curves.dae", "fps": 24,
   "times": [s, ...], "frames": [f, ...], "key_times": [s, ... every key of either rig],
   "meshes": [{"name": "CubeRot", "geometry": "<geometry id>", "extent": <rest bbox diagonal>,
               "key_times": [s, ... its rig's keys],
               "positions": [[x,y,z, x,y,z, ...] one array per time]}, ...],
   "channels": [{"target": ..., "tangent_unit": "radians"|"degrees"|"value"}, ...]}
The export's <created>/<modified> dates are pinned (as in common.py), so two runs give
byte-identical files.
"""
import json
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

import bpy

FPS = 24
NS = "{http://www.collada.org/2005/11/COLLADASchema}"
DAE = "blender-curves.dae"
JSON = "blender-curves.json"
FIXED_TIMESTAMP = "2024-01-01T00:00:00"   # as assets/src/common.py: two runs, identical files
MATCH = 1e-6          # metres: file positions vs Blender's vertices
SHAPE = 2e-5          # exported tangent (relative to its key) vs original handle: 7 digits of text

# (frame, value) keys. Degrees for the rotation, metres for the translation.
# The joint's rest rotation (90 degrees about X, bone Y = world Z) is added to the angle and the
# exporter writes angles in (-180, 180]: the keys stay inside (-270, 90) so no key wraps around.
ROT_KEYS = [(1, 0.0), (9, -35.0), (27, -120.0), (36, -80.0), (55, 20.0)]
MOVE_KEYS = [(1, 0.0), (15, 0.3), (22, 0.9), (49, 0.2)]


def fail(msg):
    raise RuntimeError("make_curve_reference: " + msg)


def new_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = FPS
    scene.render.fps_base = 1.0
    return scene


def make_rig(scene, name, head, tail):
    data = bpy.data.armatures.new(name)
    rig = bpy.data.objects.new(name, data)
    scene.collection.objects.link(rig)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode='EDIT')
    bone = data.edit_bones.new("Bone")
    bone.head = head
    bone.tail = tail
    bone.roll = 0.0
    bpy.ops.object.mode_set(mode='OBJECT')
    rig.pose.bones["Bone"].rotation_mode = 'XYZ'
    return rig


def make_cube(scene, name, rig, center, size=0.5):
    h = size / 2
    verts = [(center[0] + sx * h, center[1] + sy * h, center[2] + sz * h)
             for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)
    group = obj.vertex_groups.new(name="Bone")
    group.add(list(range(len(verts))), 1.0, 'REPLACE')
    mod = obj.modifiers.new("Armature", 'ARMATURE')
    mod.object = rig
    obj.parent = rig
    return obj


def key_channel(rig, path, index, keys, to_internal):
    """Inserts Bezier keys with Blender's default handles and returns the F-curve."""
    pb = rig.pose.bones["Bone"]
    for frame, value in keys:
        vec = list(getattr(pb, path))
        vec[index] = to_internal(value)
        setattr(pb, path, vec)
        pb.keyframe_insert(path, index=index, frame=frame)
    fcurves = [c for c in rig.animation_data.action.fcurves
               if c.data_path == 'pose.bones["Bone"].' + path and c.array_index == index]
    if len(fcurves) != 1:
        fail("expected one F-curve for %s[%d], got %d" % (path, index, len(fcurves)))
    fc = fcurves[0]
    for kp in fc.keyframe_points:
        if kp.interpolation != 'BEZIER':
            fail("key at frame %g is %s, not BEZIER" % (kp.co[0], kp.interpolation))
    return fc


def build():
    scene = new_scene()
    rot = make_rig(scene, "RigRot", (0, 0, 0), (0, 0, 1))
    make_cube(scene, "CubeRot", rot, (0.3, 0.35, 0.8))
    rot_curve = key_channel(rot, "rotation_euler", 0, ROT_KEYS, math.radians)
    move = make_rig(scene, "RigMove", (2, 0, 0), (2, 0, 1))
    make_cube(scene, "CubeMove", move, (2.35, 0.0, 0.6))
    move_curve = key_channel(move, "location", 0, MOVE_KEYS, float)
    scene.frame_start = 1
    scene.frame_end = max(ROT_KEYS[-1][0], MOVE_KEYS[-1][0])
    return scene, {"RigRot": rot_curve, "RigMove": move_curve}


def export(path):
    result = bpy.ops.wm.collada_export(
        filepath=path, check_existing=False, keep_smooth_curves=True,
        export_animation_type_selection='keys',
        export_animation_transformation_type_selection='decomposed')
    if result != {'FINISHED'}:
        fail("collada_export returned %r" % (result,))
    with open(path, encoding="utf-8") as fh:
        text = fh.read()
    text = re.sub(r"<created>[^<]*</created>", "<created>%s</created>" % FIXED_TIMESTAMP, text)
    text = re.sub(r"<modified>[^<]*</modified>", "<modified>%s</modified>" % FIXED_TIMESTAMP, text)
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(text)


# --------------------------------------------------------------------------- the written file

def floats(root, source_id):
    src = [s for s in root.iter(NS + "source") if s.get("id") == source_id]
    if len(src) != 1:
        fail("no unique <source id=%r>" % source_id)
    return [float(x) for x in src[0].find(NS + "float_array").text.split()]


def sampler_inputs(root, sampler_id):
    s = [e for e in root.iter(NS + "sampler") if e.get("id") == sampler_id][0]
    return {i.get("semantic"): i.get("source")[1:] for i in s.findall(NS + "input")}


def check_channels(root, curves):
    """The file's channels keep the F-curves' shapes; returns [{"target", "tangent_unit"}]."""
    channels = list(root.iter(NS + "channel"))
    if len(channels) != len(curves):
        fail("expected %d channels, the file has %s" % (len(curves), [c.get("target") for c in channels]))
    out = []
    for ch in channels:
        target = ch.get("target")
        rig = target.split("_Bone/")[0]
        fc = curves.get(rig)
        if fc is None:
            fail("unexpected channel target %r" % target)
        inputs = sampler_inputs(root, ch.get("source")[1:])
        names = [s for s in root.iter(NS + "source") if s.get("id") == inputs["INTERPOLATION"]][0]
        if set(names.find(NS + "Name_array").text.split()) != {"BEZIER"}:
            fail("%s: interpolation is not BEZIER throughout" % target)
        times = floats(root, inputs["INPUT"])
        values = floats(root, inputs["OUTPUT"])
        tin = floats(root, inputs["IN_TANGENT"])
        tout = floats(root, inputs["OUT_TANGENT"])
        kps = fc.keyframe_points
        if len(times) != len(kps):
            fail("%s: %d keys in the file, %d in the F-curve" % (target, len(times), len(kps)))
        angle = target.endswith(".ANGLE")
        # OUTPUT vs the F-curve's key values: v_file = offset + sign * unit * v_blender
        unit = 180 / math.pi if angle else 1.0
        sign = 1.0 if (values[1] - values[0]) * (kps[1].co[1] - kps[0].co[1]) > 0 else -1.0
        offset = values[0] - sign * unit * kps[0].co[1]
        # the unit the tangent values are in: try both for angles, pick the one that fits
        candidates = [("degrees", unit), ("radians", 1.0)] if angle else [("value", 1.0)]
        best = None
        for name, tunit in candidates:
            worst = 0.0
            for k, kp in enumerate(kps):
                if abs(times[k] - kp.co[0] / FPS) > 1e-6:
                    fail("%s: key %d at %g s, F-curve frame %g" % (target, k, times[k], kp.co[0]))
                if abs(values[k] - (offset + sign * unit * kp.co[1])) > SHAPE * max(1.0, abs(values[k])):
                    fail("%s: key %d value %g does not map to the F-curve's %g" % (target, k, values[k], kp.co[1]))
                key_file = values[k] * tunit / unit      # the key in the tangents' unit
                for tangent, handle in ((tin, kp.handle_left), (tout, kp.handle_right)):
                    dt = tangent[2 * k] - handle[0] / FPS
                    dv = (tangent[2 * k + 1] - key_file) - sign * tunit * (handle[1] - kp.co[1])
                    worst = max(worst, abs(dt), abs(dv) / max(1.0, abs(tangent[2 * k + 1])))
            if best is None or worst < best[1]:
                best = (name, worst)
        if best[1] > SHAPE:
            fail("%s: the exported tangents do not have the F-curve's shape (off by %.3g)" % (target, best[1]))
        print("  %s: %d keys, tangents = F-curve handles (%.1e), tangent values in %s"
              % (target, len(times), best[1], best[0]))
        out.append({"target": target, "tangent_unit": best[0]})
    return out


def geometry_positions(root, mesh_obj):
    """POSITION of the geometry Blender wrote for this mesh, checked against its vertices."""
    geoms = [g for g in root.iter(NS + "geometry") if g.get("name") == mesh_obj.data.name
             or g.get("id") == mesh_obj.data.name]
    if len(geoms) != 1:
        fail("no unique <geometry> for mesh %r" % mesh_obj.data.name)
    geom = geoms[0]
    verts = geom.find(NS + "mesh/" + NS + "vertices")
    pos_src = [i for i in verts.findall(NS + "input") if i.get("semantic") == "POSITION"][0].get("source")[1:]
    pos = floats(root, pos_src)
    mv = mesh_obj.data.vertices
    if len(pos) != 3 * len(mv):
        fail("%s: %d POSITION values for %d vertices" % (mesh_obj.name, len(pos), len(mv)))
    for i, v in enumerate(mv):
        for a in range(3):
            if abs(pos[3 * i + a] - v.co[a]) > MATCH:
                fail("%s: POSITION %d differs from Blender's vertex %d" % (mesh_obj.name, i, i))
    if any(abs(mesh_obj.matrix_world[r][c] - (1.0 if r == c else 0.0)) > 0 for r in range(4) for c in range(4)):
        fail("%s: the object transform is not the identity" % mesh_obj.name)
    return geom.get("id")


# --------------------------------------------------------------------------- evaluation

def sample_frames():
    """Every key frame of either rig, and frames between them (whole and sub-frames)."""
    keys = sorted({f for f, _ in ROT_KEYS} | {f for f, _ in MOVE_KEYS})
    frames = set(keys)
    for a, b in zip(keys, keys[1:]):
        for u in (0.13, 0.31, 0.5, 0.77, 0.94):
            frames.add(round(a + u * (b - a), 3))
    return sorted(frames), keys


def set_frame(scene, f):
    whole = math.floor(f + 1e-9)
    sub = f - whole
    scene.frame_set(int(whole), subframe=sub if sub > 1e-9 else 0.0)


def evaluated(obj):
    dg = bpy.context.evaluated_depsgraph_get()
    dg.update()
    ev = obj.evaluated_get(dg)
    me = ev.to_mesh()
    out = [tuple(ev.matrix_world @ v.co) for v in me.vertices]
    ev.to_mesh_clear()
    return out


def fmt(x):
    s = "%.7g" % x
    return "0" if s == "-0" else s


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    out_dir = os.path.abspath(argv[0] if argv else "core/src/test/resources/fixtures/animation")
    scene, curves = build()
    dae_path = os.path.join(out_dir, DAE)
    export(dae_path)
    root = ET.parse(dae_path).getroot()
    tool = root.find(NS + "asset/" + NS + "contributor/" + NS + "authoring_tool").text
    print("== %s (%s)" % (dae_path, tool))
    channels = check_channels(root, curves)

    frames, key_frames = sample_frames()
    meshes = []
    for name, keys in (("CubeRot", ROT_KEYS), ("CubeMove", MOVE_KEYS)):
        obj = bpy.data.objects[name]
        geom_id = geometry_positions(root, obj)
        co = [v.co for v in obj.data.vertices]
        lo = [min(c[a] for c in co) for a in range(3)]
        hi = [max(c[a] for c in co) for a in range(3)]
        extent = math.sqrt(sum((hi[a] - lo[a]) ** 2 for a in range(3)))
        meshes.append({"name": name, "geometry": geom_id, "extent": round(extent, 7),
                       "key_times": [f / FPS for f, _ in keys], "positions": []})
    for f in frames:
        set_frame(scene, f)
        for m in meshes:
            pts = evaluated(bpy.data.objects[m["name"]])
            m["positions"].append("[" + ",".join(fmt(p[a]) for p in pts for a in range(3)) + "]")

    # the curves matter: the motion between keys is not the straight line between the key poses
    for m in meshes:
        worst = 0.0
        for i, f in enumerate(frames):
            a = max([k for k in key_frames if k <= f])
            b = min([k for k in key_frames if k >= f])
            if a == b:
                continue
            ia, ib = frames.index(a), frames.index(b)
            u = (f - a) / (b - a)
            pa = json.loads(m["positions"][ia])
            pb = json.loads(m["positions"][ib])
            p = json.loads(m["positions"][i])
            worst = max(worst, max(abs(p[j] - (pa[j] + u * (pb[j] - pa[j]))) for j in range(len(p))))
        print("  %s: %d vertices, %d times, up to %.3f m from the straight line between key poses"
              % (m["name"], len(m["positions"][0].split(",")) // 3, len(frames), worst))
        if worst < 0.01:
            fail("%s hardly leaves the straight line between keys; the test would prove nothing" % m["name"])

    about = ("Blender %s: the deformed cubes of the original scene (not a re-import) at key frames "
             "and between them, world coordinates in POSITION order; made by "
             "assets/src/make_curve_reference.py together with %s" % (bpy.app.version_string, DAE))
    lines = ['{', ' "about": %s,' % json.dumps(about),
             ' "blender": %s,' % json.dumps(bpy.app.version_string),
             ' "file": %s,' % json.dumps(DAE),
             ' "fps": %d,' % FPS,
             ' "times": [%s],' % ",".join(fmt(f / FPS) for f in frames),
             ' "frames": [%s],' % ",".join(fmt(f) for f in frames),
             ' "key_times": [%s],' % ",".join(fmt(f / FPS) for f in key_frames),
             ' "channels": %s,' % json.dumps(channels),
             ' "meshes": [']
    for n, m in enumerate(meshes):
        lines.append('  {"name": %s, "geometry": %s, "extent": %s, "key_times": [%s], "positions": [' % (
            json.dumps(m["name"]), json.dumps(m["geometry"]), fmt(m["extent"]),
            ",".join(fmt(t) for t in m["key_times"])))
        lines.append(",\n".join("   " + p for p in m["positions"]))
        lines.append('  ]}' + ("," if n + 1 < len(meshes) else ""))
    lines.append(' ]')
    lines.append('}')
    json_path = os.path.join(out_dir, JSON)
    with open(json_path, "w") as fh:
        fh.write("\n".join(lines) + "\n")
    json.load(open(json_path))  # well-formed
    print("  wrote %s (%d times)" % (json_path, len(frames)))


main()
