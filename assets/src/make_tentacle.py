"""Build a tapered tentacle with an 8-bone chain doing a travelling wave with squash and stretch
(bone scale, non-uniform on four bones) and export it as COLLADA.

Usage (from the repository root):
  blender --background --factory-startup --python-exit-code 1 \
      --python assets/src/make_tentacle.py -- OUT.dae [REFERENCE.json]

Mesh: a closed tapered tube along +Z from z=0 (radius 0.22) to z=2 (radius 0.03) plus a pole
vertex closing the tip; 41 rings of 16 vertices, a 16-gon cap at the base.
Skeleton: 8 chained bones t1..t8, each 0.25 m long. Weights: heat diffusion, at most 4 influences
per vertex, normalised.
Animation: period 2 s = 48 frames, 17 keys every 3 frames (0.125 s), last key = first key.
Each bone i bends about the X axis by A_i * sin(2 pi (t/T - i/8)) (a wave travelling to the tip)
plus a smaller sideways bend about Y; bones t3..t6 also scale: stretch along the bone
(sy in [0.8, 1.2]) with a non-uniform cross-section (sx != sz). Children inherit the scale
(Blender default), so world matrices below a scaled bone carry scale and shear.
"""
import math
import os
import sys

import bmesh
import bpy
from mathutils import Quaternion, Vector

sys.dont_write_bytecode = True   # no __pycache__ in the source folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

LENGTH = 2.0
N_BONES = 8
RINGS = 41
AROUND = 16
R_BASE, R_TIP = 0.22, 0.03
PERIOD = 48
STEP = 3
SCALED = {"t3", "t4", "t5", "t6"}


def radius(z):
    u = z / LENGTH
    return R_TIP + (R_BASE - R_TIP) * (1.0 - u) ** 1.3


def build_mesh():
    me = bpy.data.meshes.new("Tentacle")
    bm = bmesh.new()
    rings = []
    for i in range(RINGS):
        z = LENGTH * i / (RINGS - 1)
        r = radius(z)
        rings.append([bm.verts.new((r * math.cos(2 * math.pi * k / AROUND),
                                    r * math.sin(2 * math.pi * k / AROUND), z))
                      for k in range(AROUND)])
    n = AROUND
    for r0, r1 in zip(rings[:-1], rings[1:]):
        for k in range(n):
            bm.faces.new((r0[k], r0[(k + 1) % n], r1[(k + 1) % n], r1[k]))
    bm.faces.new(list(reversed(rings[0])))                     # base cap, normal -Z
    tip = bm.verts.new((0.0, 0.0, LENGTH + 0.03))              # rounded-off tip
    top = rings[-1]
    for k in range(n):
        bm.faces.new((top[k], top[(k + 1) % n], tip))
    for f in bm.faces:
        f.smooth = True
    bm.normal_update()
    bm.to_mesh(me)
    bm.free()
    obj = common.link(bpy.data.objects.new("Tentacle", me))
    return obj


def rot(axis, degrees):
    return Quaternion(axis, math.radians(degrees))


def pose(frame):
    """Per bone: (rotation in armature axes relative to the parent, scale in bone axes)."""
    t = (frame % PERIOD) / PERIOD
    out = {}
    for i in range(N_BONES):
        name = "t%d" % (i + 1)
        ph = 2.0 * math.pi * (t - i / N_BONES)
        amp = 10.0 + 3.5 * i                         # 10 .. 34.5 degrees, larger towards the tip
        q = rot(Vector((1, 0, 0)), amp * math.sin(ph)) @ rot(Vector((0, 1, 0)), 0.35 * amp * math.cos(ph))
        if name in SCALED:
            sy = 1.0 + 0.2 * math.sin(ph + math.pi / 4)           # stretch / squash along the bone
            flat = 0.15 * math.sin(ph)                            # non-uniform cross-section
            base = 1.0 / math.sqrt(sy)                            # roughly volume preserving
            scale = (base * (1.0 + flat), sy, base * (1.0 - flat))
        else:
            scale = (1.0, 1.0, 1.0)
        out[name] = (q, scale)
    return out


def main():
    args = common.script_args()
    if len(args) not in (1, 2):
        raise SystemExit("usage: make_tentacle.py -- OUT.dae [REFERENCE.json]")
    out = args[0]
    reference = args[1] if len(args) == 2 else None
    frames = list(range(0, PERIOD + 1, STEP))
    common.reset_scene(frame_end=PERIOD)

    mesh_obj = build_mesh()
    common.add_material(mesh_obj, "TentacleMaterial", (0.7, 0.35, 0.55, 1.0))
    seg = LENGTH / N_BONES
    bones = []
    for i in range(N_BONES):
        bones.append(("t%d" % (i + 1), Vector((0, 0, i * seg)), Vector((0, 0, (i + 1) * seg)),
                      "t%d" % i if i else None, 0.0))
    arm_obj = common.create_armature("Armature", bones)
    worst = common.skin_with_auto_weights(mesh_obj, arm_obj, max_influences=4)
    assert worst <= 4

    action = common.make_action(arm_obj, "Wave")
    for pb in arm_obj.pose.bones:
        pb.rotation_mode = 'QUATERNION'
    previous = {}
    for frame in frames:
        p = pose(frame)
        for pb in arm_obj.pose.bones:
            q_arm, scale = p[pb.name]
            rest = pb.bone.matrix_local.to_quaternion()
            q = rest.inverted() @ q_arm @ rest
            q.normalize()
            if pb.name in previous and previous[pb.name].dot(q) < 0:
                q.negate()
            previous[pb.name] = q.copy()
            common.key_pose_bone(pb, frame, loc=(0, 0, 0), rot=q, scale=scale)
    common.finish_action(action)

    me = mesh_obj.data
    tris = sum(len(poly.vertices) - 2 for poly in me.polygons)
    print("tentacle: %d vertices, %d triangles, %d bones" % (len(me.vertices), tris, len(arm_obj.data.bones)))
    common.write_reference(mesh_obj, frames, reference)
    common.export_dae(out, sampling_rate=STEP)
    common.export_glb(out, frame_step=STEP)


main()
