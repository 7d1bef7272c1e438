"""Build one of the limb assets for stretchable and twistable bones and export it as COLLADA.

Usage (from the repository root):
  blender --background --factory-startup --python-exit-code 1 \
      --python assets/src/make_limb.py -- VARIANT OUT.dae [REFERENCE.json]
VARIANT is stretch (assets/stretch/limb-stretch.dae) or twist (assets/twist/arm-twist.dae).

Geometry: a closed tube along +Z (Blender's up axis), rings every 0.0625 m (stretch) or 0.05 m
(twist) of 32 vertices, flat 32-gon caps (the exporter triangulates each into 30 triangles).
Skeleton: a chain of three bones along +Z, bone Y = world +Z, roll 0.
Weights: our own smooth falloff, not heat diffusion: within a band of half-width b around each
joint the child's weight rises as smoothstep(u) = u^2 (3 - 2u), u = (z - z_joint + b) / (2b), and
the parent's is 1 minus that; outside the bands a vertex has one influence. So every ring inside a
band has exactly two influences, the weights depend on the height alone (the same for every vertex
of a ring), and the band width is a number in this file rather than an outcome of bone heat.
Animation: see STRETCH_KEYS and TWIST_KEYS; keys evenly spaced, LINEAR, the clip loops.
"""
import math
import os
import sys

import bmesh
import bpy
from mathutils import Vector

sys.dont_write_bytecode = True   # no __pycache__ in the source folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

AROUND = 32

# stretch: root z 0..1, middle z 1..2, end z 2..3; radius 0.2; joint bands of half-width 0.25 m
STRETCH_BONES = [("root", 0.0, 1.0), ("middle", 1.0, 2.0), ("end", 2.0, 3.0)]
STRETCH_RINGS = 48           # segments: rings every 0.0625 m, 7 rings strictly inside each band
STRETCH_BANDS = [0.25, 0.25]
STRETCH_STEP = 6             # frames between keys (0.25 s)
# middle's scale along its own axis (pose bone scale Y) per key, 0 .. 2 s; 1.5 at t = 1 s
STRETCH_KEYS = [1.0, 1.125, 1.25, 1.375, 1.5, 1.375, 1.25, 1.125, 1.0]

# twist: upper_arm z 0..1, forearm z 1..2, hand z 2..2.4; radius 0.2, the hand flattened
TWIST_BONES = [("upper_arm", 0.0, 1.0), ("forearm", 1.0, 2.0), ("hand", 2.0, 2.4)]
TWIST_RINGS = 48             # segments: rings every 0.05 m, 21 rings from elbow to wrist
TWIST_BANDS = [0.25, 0.15]   # elbow: 9 rings with two influences, wrist: 5
TWIST_STEP = 3               # frames between keys (0.125 s)
# forearm's rotation about its own axis (pose bone Euler Y, degrees) per key, 0 .. 2 s:
# 90 at 0.5 s, 170 at 0.875 s, exactly 180 at 1 s (ambiguous as a relative rotation), then back
TWIST_KEYS = [0, 20, 45, 70, 90, 115, 145, 170, 180, 170, 145, 115, 90, 70, 45, 20, 0]

RADIUS = 0.2
HAND_THICKNESS = 0.09        # half-thickness of the flat hand (y), its width stays 0.2 (x)


def smoothstep(u):
    u = max(0.0, min(1.0, u))
    return u * u * (3.0 - 2.0 * u)


def band_weights(z, bones, bands):
    """{bone index: weight} for a vertex at height z (weights > 0 only, summing to 1). z is rounded
    to 10 µm first, so a ring that lies on a band's edge (stored as float32) gets one influence."""
    z = round(z, 5)
    for j, b in enumerate(bands):
        zj = bones[j][2]                       # joint j sits at the tail of bone j
        if z <= zj - b:
            return {j: 1.0}
        if z < zj + b:
            s = smoothstep((z - zj + b) / (2.0 * b))
            return {j: 1.0 - s, j + 1: s}
    return {len(bones) - 1: 1.0}


def hand_half_thickness(z):
    """y radius of the arm: round up to the wrist, flattening to the hand's thickness by z = 2.15."""
    return RADIUS - (RADIUS - HAND_THICKNESS) * smoothstep((z - 2.0) / 0.15)


def build_tube(name, heights, y_radius):
    me = bpy.data.meshes.new(name)
    bm = bmesh.new()
    rings = []
    for z in heights:
        ry = y_radius(z)
        rings.append([bm.verts.new((RADIUS * math.cos(2.0 * math.pi * k / AROUND),
                                    ry * math.sin(2.0 * math.pi * k / AROUND), z))
                      for k in range(AROUND)])
    n = AROUND
    for r0, r1 in zip(rings[:-1], rings[1:]):
        for k in range(n):
            f = bm.faces.new((r0[k], r0[(k + 1) % n], r1[(k + 1) % n], r1[k]))
            f.smooth = True
    bottom = bm.faces.new(list(reversed(rings[0])))   # normal -Z
    top = bm.faces.new(rings[-1])                      # normal +Z
    bottom.smooth = top.smooth = False
    bm.normal_update()
    bm.to_mesh(me)
    bm.free()
    me.use_auto_smooth = True       # smooth sides, sharp rim at the caps
    me.auto_smooth_angle = math.radians(60)
    return me


def skin_with_band_weights(mesh_obj, arm_obj, bones, bands):
    """Parent with empty groups (ARMATURE_NAME: one group per bone, an Armature modifier), then
    fill the groups with band_weights of each vertex's rest height."""
    common.activate(arm_obj, mesh_obj)
    result = bpy.ops.object.parent_set(type='ARMATURE_NAME')
    if result != {'FINISHED'}:
        raise RuntimeError("parent_set failed: %r" % (result,))
    groups = [mesh_obj.vertex_groups[name] for name, _, _ in bones]
    hist = {}
    for v in mesh_obj.data.vertices:
        w = band_weights(v.co.z, bones, bands)
        for j, x in w.items():
            groups[j].add([v.index], x, 'REPLACE')
        hist[len(w)] = hist.get(len(w), 0) + 1
    mods = [m for m in mesh_obj.modifiers]
    assert len(mods) == 1 and mods[0].type == 'ARMATURE', mods
    print("skin: %d vertices, %d groups, influences per vertex %s"
          % (len(mesh_obj.data.vertices), len(groups), dict(sorted(hist.items()))))


def check_stretch_pose(arm_obj, frame, sy):
    """end does not inherit middle's scale but sits on its stretched tail (inherit_scale NONE)."""
    bpy.context.scene.frame_set(frame)
    middle, end = arm_obj.pose.bones["middle"], arm_obj.pose.bones["end"]
    scales = end.matrix.to_3x3().to_scale()
    tail_z = 1.0 + sy * 1.0
    assert max(abs(s - 1.0) for s in scales) < 1e-5, ("end is scaled", frame, scales)
    assert abs(end.head.z - tail_z) < 1e-5 and abs(middle.tail.z - tail_z) < 1e-5, (frame, end.head, middle.tail)
    assert abs(middle.matrix.to_3x3().to_scale().y - sy) < 1e-5, (frame, middle.matrix)


def main():
    args = common.script_args()
    if len(args) not in (2, 3) or args[0] not in ("stretch", "twist"):
        raise SystemExit("usage: make_limb.py -- stretch|twist OUT.dae [REFERENCE.json]")
    variant, out = args[:2]
    reference = args[2] if len(args) == 3 else None
    if variant == "stretch":
        bones, bands, segments, step, keys = STRETCH_BONES, STRETCH_BANDS, STRETCH_RINGS, STRETCH_STEP, STRETCH_KEYS
        y_radius = lambda z: RADIUS  # noqa: E731
        colour = (0.45, 0.65, 0.35, 1.0)
    else:
        bones, bands, segments, step, keys = TWIST_BONES, TWIST_BANDS, TWIST_RINGS, TWIST_STEP, TWIST_KEYS
        y_radius = hand_half_thickness
        colour = (0.8, 0.6, 0.5, 1.0)
    length = bones[-1][2]
    heights = [length * i / segments for i in range(segments + 1)]
    frames = [k * step for k in range(len(keys))]

    common.reset_scene(frame_end=frames[-1])
    name = "Limb" if variant == "stretch" else "Arm"
    mesh = build_tube(name, heights, y_radius)
    mesh_obj = common.link(bpy.data.objects.new(name, mesh))
    common.add_material(mesh_obj, name + "Material", colour)
    arm_obj = common.create_armature("Armature", [
        (bname, Vector((0, 0, z0)), Vector((0, 0, z1)), bones[i - 1][0] if i else None, 0.0)
        for i, (bname, z0, z1) in enumerate(bones)])
    if variant == "stretch":
        # Without this, end would inherit middle's stretch and be 1.5x long itself. 'NONE' drops the
        # parent's scale from the child's frame while the child's head still follows the parent's
        # (stretched) tail; 'NONE_LEGACY' gives the same here (no shear in a straight chain), 'ALIGNED'
        # would pass middle's Y scale on to end's Y axis.
        arm_obj.data.bones["end"].inherit_scale = 'NONE'
    skin_with_band_weights(mesh_obj, arm_obj, bones, bands)

    action = common.make_action(arm_obj, "Stretch" if variant == "stretch" else "Twist")
    for pb in arm_obj.pose.bones:
        pb.rotation_mode = 'XYZ'
    moving = arm_obj.pose.bones[bones[1][0]]
    for frame, value in zip(frames, keys):
        for pb in arm_obj.pose.bones:
            rot, scale = (0.0, 0.0, 0.0), (1.0, 1.0, 1.0)
            if pb == moving and variant == "stretch":
                scale = (1.0, value, 1.0)
            elif pb == moving:
                rot = (0.0, math.radians(value), 0.0)
            common.key_pose_bone(pb, frame, loc=(0, 0, 0), rot=rot, scale=scale)
    common.finish_action(action)
    if variant == "stretch":
        for frame, sy in zip(frames, keys):
            check_stretch_pose(arm_obj, frame, sy)
        bpy.context.scene.frame_set(0)

    tris = sum(len(p.vertices) - 2 for p in mesh.polygons)
    print("limb %s: %d rings, %d vertices, %d triangles, bones %s, keys every %d frames: %s" % (
        variant, len(heights), len(mesh.vertices), tris, " ".join(b[0] for b in bones), step,
        " ".join("%g" % k for k in keys)))
    common.write_reference(mesh_obj, frames, reference)
    common.export_dae(out, sampling_rate=step)
    common.export_glb(out, frame_step=step)


main()
