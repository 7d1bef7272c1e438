"""Build one of the test cylinders and export it as COLLADA.

Usage (from the repository root):
  blender --background --factory-startup --python-exit-code 1 \
      --python assets/src/make_cylinder.py -- VARIANT OUT.dae [REFERENCE.json]
VARIANT is one of twist-low, twist-high, bend (keys 1 s apart, never a half turn) or twist-full,
bend-full (a whole turn, 0 to 360 degrees, 25 keys 0.25 s apart).

Geometry: a closed cylinder along +Z (Blender's up axis) from z=0 to z=2, radius 0.25, 32 vertices
per ring, 32-gon caps (the exporter triangulates each into 30 triangles). Triangles:
2 * 32 * segments + 60, so 17 segments give 1148 triangles (thesis: cylinderYLow, 1148) and 31
segments give 2044 (thesis: cylinderYHigh / cylinderXHigh, 2044).
Skeleton: two chained bones, "lower" z 0..1 and "upper" z 1..2 (joint at half height).
Weights: heat diffusion (ARMATURE_AUTO).
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

HEIGHT = 2.0
RADIUS = 0.25
SEGMENTS_AROUND = 32
JOINT_Z = 1.0
VARIANTS = ("twist-low", "twist-high", "bend", "twist-full", "bend-full")
FULL_TURN_STEP_FRAMES = 6   # 0.25 s at 24 fps


def rings_even(segments):
    return [HEIGHT * i / segments for i in range(segments + 1)]


def rings_dense_at_joint(segments, linear_share=0.2):
    """Ring heights concentrated around the joint: z - 1 = s * (a*|u| + (1-a)*|u|^3), u evenly
    spaced in [-1, 1]. Near the joint the spacing is a (= 0.2) times the even spacing, at the
    caps 2.8 times."""
    zs = []
    for i in range(segments + 1):
        u = -1.0 + 2.0 * i / segments
        s = math.copysign(1.0, u)
        au = abs(u)
        zs.append(JOINT_Z + s * (linear_share * au + (1.0 - linear_share) * au ** 3) * (HEIGHT / 2))
    zs[0], zs[-1] = 0.0, HEIGHT
    return zs


def build_cylinder_mesh(name, ring_heights):
    me = bpy.data.meshes.new(name)
    bm = bmesh.new()
    rings = []
    for z in ring_heights:
        ring = []
        for k in range(SEGMENTS_AROUND):
            a = 2.0 * math.pi * k / SEGMENTS_AROUND
            ring.append(bm.verts.new((RADIUS * math.cos(a), RADIUS * math.sin(a), z)))
        rings.append(ring)
    n = SEGMENTS_AROUND
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


def main():
    args = common.script_args()
    if len(args) not in (2, 3) or args[0] not in VARIANTS:
        raise SystemExit("usage: make_cylinder.py -- %s OUT.dae [REFERENCE.json]" % "|".join(VARIANTS))
    variant, out = args[:2]
    reference = args[2] if len(args) == 3 else None

    heights = rings_even(17) if variant == "twist-low" else rings_dense_at_joint(31)
    if variant in ("twist-low", "twist-high"):
        # upper bone twists about the height axis (bone Y = world +Z); keys 1 s apart
        keys = [(0, 0.0), (24, 45.0), (48, 90.0), (72, 135.0), (96, 172.0)]
        axis = 1
    elif variant == "bend":
        # upper bone bends about its local X axis (= world X): 90 degrees at 2 s, 170 at 4 s
        keys = [(0, 0.0), (24, 45.0), (48, 90.0), (72, 130.0), (96, 170.0)]
        axis = 0
    else:
        # a whole turn about bone Y (twist-full) or local X (bend-full): 15 degrees every 6 frames
        # (0.25 s), so 60 t degrees; every step is far below 180, so a reader interpolating
        # between two keys has one shortest way. 360 at 6 s is the rest pose again.
        keys = [(FULL_TURN_STEP_FRAMES * i, 15.0 * i) for i in range(25)]
        axis = 1 if variant == "twist-full" else 0
    spacing = keys[1][0]   # frames between keys: the exporters sample exactly the keys

    common.reset_scene(frame_end=keys[-1][0])
    mesh = build_cylinder_mesh("Cylinder", heights)
    mesh_obj = common.link(bpy.data.objects.new("Cylinder", mesh))
    common.add_material(mesh_obj, "CylinderMaterial", (0.8, 0.55, 0.3, 1.0))

    arm_obj = common.create_armature("Armature", [
        ("lower", Vector((0, 0, 0)), Vector((0, 0, JOINT_Z)), None, 0.0),
        ("upper", Vector((0, 0, JOINT_Z)), Vector((0, 0, HEIGHT)), "lower", 0.0),
    ])
    common.skin_with_auto_weights(mesh_obj, arm_obj, max_influences=4)

    action = common.make_action(arm_obj, "Cylinder_" + variant.replace("-", "_"))
    for pb in arm_obj.pose.bones:
        pb.rotation_mode = 'XYZ'
    lower = arm_obj.pose.bones["lower"]
    upper = arm_obj.pose.bones["upper"]
    for frame, angle in keys:
        rot = [0.0, 0.0, 0.0]
        rot[axis] = math.radians(angle)
        common.key_pose_bone(lower, frame, loc=(0, 0, 0), rot=(0, 0, 0), scale=(1, 1, 1))
        common.key_pose_bone(upper, frame, loc=(0, 0, 0), rot=rot, scale=(1, 1, 1))
    common.finish_action(action)

    tris = sum(len(p.vertices) - 2 for p in mesh.polygons)
    print("cylinder %s: %d rings, %d vertices, %d triangles, ring heights %s" % (
        variant, len(heights), len(mesh.vertices), tris, " ".join("%.3f" % z for z in heights)))
    common.write_reference(mesh_obj, [k[0] for k in keys], reference)
    common.export_dae(out, sampling_rate=spacing)
    common.export_glb(out, frame_step=spacing)


main()
