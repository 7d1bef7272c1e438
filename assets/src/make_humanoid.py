"""Build the default humanoid character with a looping walk cycle and export it as COLLADA.

Usage (from the repository root):
  blender --background --factory-startup --python-exit-code 1 \
      --python assets/src/make_humanoid.py -- OUT.dae [REFERENCE.json]

Mesh: a Skin modifier over a stick-figure edge skeleton (one connected, closed surface), then
one level of Catmull-Clark subdivision; both applied. Z up, the figure faces -Y (Blender's front
view), its left side is +X, feet on z=0, about 1.8 m tall, arms in an A pose (40 degrees below
horizontal) in the rest/bind pose.
Skeleton: 19 deforming bones. Weights: heat diffusion (ARMATURE_AUTO), weights below 0.001
removed, at most 4 influences per vertex, normalised.
Animation: a walk in place, one full cycle (two steps) in 1 s = 24 frames, 9 keys every 3 frames
(0.125 s); the last key equals the first so the cycle loops.
"""
import math
import os
import sys

import bpy
from mathutils import Quaternion, Vector

sys.dont_write_bytecode = True   # no __pycache__ in the source folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

ARM_DIR_ANGLE = 40.0  # rest pose: arms this many degrees below horizontal


def arm_dir(side):
    a = math.radians(ARM_DIR_ANGLE)
    return Vector((side * math.cos(a), 0.0, -math.sin(a)))


def landmarks():
    """Named points of the stick figure (also used for the bone heads/tails)."""
    p = {
        "pelvis": Vector((0, 0.0, 0.95)),
        "waist": Vector((0, 0.0, 1.10)),
        "chest": Vector((0, 0.0, 1.28)),
        "neck_base": Vector((0, 0.0, 1.45)),
        "head_base": Vector((0, 0.0, 1.54)),
        "jaw": Vector((0, -0.01, 1.60)),
        "head_mid": Vector((0, -0.01, 1.68)),
        "crown": Vector((0, 0.0, 1.76)),
        "head_top": Vector((0, 0.0, 1.81)),
        "nose": Vector((0, -0.10, 1.66)),
    }
    for side, s in (("L", 1), ("R", -1)):
        d = arm_dir(s)
        sh = Vector((s * 0.19, 0.0, 1.42))
        p["clavicle_" + side] = Vector((s * 0.03, 0.0, 1.42))
        p["shoulder_" + side] = sh
        p["elbow_" + side] = sh + 0.28 * d
        p["wrist_" + side] = sh + 0.54 * d
        p["hand_" + side] = sh + 0.64 * d
        p["hip_" + side] = Vector((s * 0.10, 0.0, 0.92))
        p["knee_" + side] = Vector((s * 0.10, -0.01, 0.50))
        p["ankle_" + side] = Vector((s * 0.10, 0.0, 0.09))
        p["toe_" + side] = Vector((s * 0.10, -0.16, 0.03))
    return p


def stick_figure(p):
    """(vertices, radii, edges) of the stick figure for the Skin modifier. Limbs get extra
    in-between vertices so that elbows and knees have enough rings."""
    verts, radii, edges = [], [], []
    index = {}

    def v(name, co, r):
        index[name] = len(verts)
        verts.append(tuple(co))
        radii.append(r)
        return index[name]

    def chain(names_points_radii, start=None):
        prev = start
        for name, co, r in names_points_radii:
            i = v(name, co, r)
            if prev is not None:
                edges.append((prev, i))
            prev = i
        return prev

    def lerp(a, b, t):
        return a.lerp(b, t)

    # trunk and head
    chain([
        ("pelvis", p["pelvis"], (0.15, 0.11)),
        ("waist", p["waist"], (0.13, 0.095)),
        ("chest", p["chest"], (0.155, 0.105)),
        ("neck_base", p["neck_base"], (0.055, 0.05)),
        ("head_base", p["head_base"], (0.055, 0.055)),
        ("jaw", p["jaw"], (0.08, 0.09)),
        ("head_mid", p["head_mid"], (0.095, 0.105)),
        ("crown", p["crown"], (0.085, 0.095)),
        ("head_top", p["head_top"], (0.04, 0.045)),
    ])
    v("nose", p["nose"], (0.02, 0.02))
    edges.append((index["head_mid"], index["nose"]))
    for side in ("L", "R"):
        # shoulders from the chest, then the arm
        chain([
            ("shoulder_" + side, p["shoulder_" + side], (0.065, 0.06)),
            ("upper_arm_mid_" + side, lerp(p["shoulder_" + side], p["elbow_" + side], 0.5), (0.05, 0.05)),
            ("elbow_" + side, p["elbow_" + side], (0.042, 0.042)),
            ("forearm_mid_" + side, lerp(p["elbow_" + side], p["wrist_" + side], 0.5), (0.04, 0.038)),
            ("wrist_" + side, p["wrist_" + side], (0.03, 0.025)),
            ("hand_" + side, p["hand_" + side], (0.04, 0.015)),
        ], start=index["chest"])
        # legs from the pelvis
        chain([
            ("hip_" + side, p["hip_" + side], (0.085, 0.085)),
            ("thigh_mid_" + side, lerp(p["hip_" + side], p["knee_" + side], 0.5), (0.075, 0.075)),
            ("knee_" + side, p["knee_" + side], (0.055, 0.055)),
            ("shin_mid_" + side, lerp(p["knee_" + side], p["ankle_" + side], 0.5), (0.05, 0.05)),
            ("ankle_" + side, p["ankle_" + side], (0.04, 0.04)),
            ("toe_" + side, p["toe_" + side], (0.045, 0.03)),
        ], start=index["pelvis"])
    return verts, radii, edges, index


def build_mesh():
    p = landmarks()
    verts, radii, edges, index = stick_figure(p)
    me = bpy.data.meshes.new("Humanoid")
    me.from_pydata(verts, edges, [])
    me.update()
    obj = common.link(bpy.data.objects.new("Humanoid", me))
    skin = obj.modifiers.new("Skin", 'SKIN')
    skin.use_smooth_shade = True
    skin.branch_smoothing = 0.0
    skin.use_x_symmetry = True
    for i, r in enumerate(radii):
        sv = me.skin_vertices[0].data[i]
        sv.radius = r
        sv.use_root = (i == index["pelvis"])
    sub = obj.modifiers.new("Subdivision", 'SUBSURF')
    sub.levels = 1
    sub.render_levels = 1
    common.apply_all_modifiers(obj)
    for poly in obj.data.polygons:
        poly.use_smooth = True
    return obj, p


BONES = [
    # name, head, tail, parent
    ("hips", "pelvis", "waist", None),
    ("spine", "waist", "chest", "hips"),
    ("chest", "chest", "neck_base", "spine"),
    ("neck", "neck_base", "head_base", "chest"),
    ("head", "head_base", "head_top", "neck"),
    ("shoulder_L", "clavicle_L", "shoulder_L", "chest"),
    ("upper_arm_L", "shoulder_L", "elbow_L", "shoulder_L"),
    ("forearm_L", "elbow_L", "wrist_L", "upper_arm_L"),
    ("hand_L", "wrist_L", "hand_L", "forearm_L"),
    ("shoulder_R", "clavicle_R", "shoulder_R", "chest"),
    ("upper_arm_R", "shoulder_R", "elbow_R", "shoulder_R"),
    ("forearm_R", "elbow_R", "wrist_R", "upper_arm_R"),
    ("hand_R", "wrist_R", "hand_R", "forearm_R"),
    ("thigh_L", "hip_L", "knee_L", "hips"),
    ("shin_L", "knee_L", "ankle_L", "thigh_L"),
    ("foot_L", "ankle_L", "toe_L", "shin_L"),
    ("thigh_R", "hip_R", "knee_R", "hips"),
    ("shin_R", "knee_R", "ankle_R", "thigh_R"),
    ("foot_R", "ankle_R", "toe_R", "shin_R"),
]


def rot(axis, degrees):
    return Quaternion(axis, math.radians(degrees))


X, Y, Z = Vector((1, 0, 0)), Vector((0, 1, 0)), Vector((0, 0, 1))


def walk_pose(phase):
    """Pose at phase in [0, 1): per bone (rotation relative to the parent, expressed in armature
    axes; location offset in armature axes). The figure faces -Y: a negative rotation about X
    swings a hanging limb forward."""
    w = 2.0 * math.pi * phase
    c, s = math.cos(w), math.sin(w)
    pose = {}
    # legs: left thigh forward at phase 0 (left heel strike), back at 0.5
    for side, sign in (("L", 1.0), ("R", -1.0)):
        cs, ss = sign * c, sign * s
        thigh = -25.0 * cs
        # knee: strongly bent while the leg swings forward (left: phase 0.5..1), a little during
        # stance (loading)
        shin = 5.0 + 55.0 * max(0.0, -ss) + 10.0 * max(0.0, ss)
        foot = -0.6 * (thigh + shin) + 8.0 * max(0.0, cs)  # keep the foot roughly level, toes up at heel strike
        pose["thigh_" + side] = (rot(X, thigh), None)
        pose["shin_" + side] = (rot(X, shin), None)
        pose["foot_" + side] = (rot(X, foot), None)
        # arms: hang down (rotate 35 degrees from the A pose towards the body), swing opposite to
        # the leg on the same side, elbow bent more when the arm is forward
        lower = rot(Y, sign * 35.0)
        swing = rot(X, 20.0 * cs)
        pose["upper_arm_" + side] = (swing @ lower, None)
        pose["forearm_" + side] = (rot(X, -(12.0 + 18.0 * max(0.0, -cs))), None)
        pose["hand_" + side] = (rot(X, -5.0), None)
        pose["shoulder_" + side] = (rot(X, 4.0 * cs), None)
    # hips: bob (lowest at heel strike, highest at passing), sway and yaw with the stride
    bob = -0.025 * math.cos(2.0 * w)
    pose["hips"] = (rot(Z, -6.0 * c) @ rot(Y, 3.0 * s), Vector((0.0, 0.0, bob)))
    pose["spine"] = (rot(X, -3.0) @ rot(Z, 4.0 * c), None)        # lean forward, counter-rotate
    pose["chest"] = (rot(Z, 5.0 * c) @ rot(Y, -2.0 * s), None)
    pose["neck"] = (rot(X, 3.0), None)
    pose["head"] = (rot(X, 0.0), None)
    for name, _, _, _ in BONES:
        pose.setdefault(name, (Quaternion(), None))
    return pose


def to_bone_axes(pb, q_arm, loc_arm):
    """A pose given in armature axes (rotation relative to the parent, location offset) as the
    pose bone's own quaternion and location, which are relative to the bone's rest axes."""
    rest = pb.bone.matrix_local.to_quaternion()       # bone axes in armature space
    q = rest.inverted() @ q_arm @ rest               # same rotation in bone axes
    q.normalize()
    loc = (rest.inverted() @ loc_arm) if loc_arm is not None else Vector()
    return q, loc


def build_character():
    """The skinned humanoid in the current (empty) scene: mesh, material, armature with rolls,
    heat-diffusion weights. Returns (mesh object, armature object)."""
    mesh_obj, p = build_mesh()
    common.add_material(mesh_obj, "BodyMaterial", (0.45, 0.6, 0.8, 1.0))
    arm_obj = common.create_armature(
        "Armature", [(n, p[h], p[t], parent, 0.0) for n, h, t, parent in BONES])
    # bone rolls: let Blender compute them consistently (local Z towards global -Y)
    common.activate(arm_obj)
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.armature.select_all(action='SELECT')
    bpy.ops.armature.calculate_roll(type='GLOBAL_NEG_Y')
    bpy.ops.object.mode_set(mode='OBJECT')

    worst = common.skin_with_auto_weights(mesh_obj, arm_obj, max_influences=4)
    assert worst <= 4
    for pb in arm_obj.pose.bones:
        pb.rotation_mode = 'QUATERNION'
    return mesh_obj, arm_obj


def main():
    args = common.script_args()
    if len(args) not in (1, 2):
        raise SystemExit("usage: make_humanoid.py -- OUT.dae [REFERENCE.json]")
    out = args[0]
    reference = args[1] if len(args) == 2 else None

    cycle, step = 24, 3
    frames = list(range(0, cycle + 1, step))   # 0, 3, ..., 24
    common.reset_scene(frame_end=cycle)
    mesh_obj, arm_obj = build_character()

    action = common.make_action(arm_obj, "Walk")
    previous = {}
    for frame in frames:
        phase = (frame % cycle) / cycle    # the last key is computed exactly like the first
        pose = walk_pose(phase)
        for pb in arm_obj.pose.bones:
            q, loc = to_bone_axes(pb, *pose[pb.name])
            if pb.name in previous and previous[pb.name].dot(q) < 0:
                q.negate()                                    # shortest path for Blender's own playback
            previous[pb.name] = q.copy()
            common.key_pose_bone(pb, frame, loc=loc, rot=q, scale=(1, 1, 1))
    common.finish_action(action)

    me = mesh_obj.data
    tris = sum(len(poly.vertices) - 2 for poly in me.polygons)
    print("humanoid: %d vertices, %d polygons, %d triangles, %d bones" % (
        len(me.vertices), len(me.polygons), tris, len(arm_obj.data.bones)))
    common.write_reference(mesh_obj, frames, reference)
    common.export_dae(out, sampling_rate=step)
    common.export_glb(out, frame_step=step)


if __name__ == "__main__":   # make_mover.py imports the character from here
    main()
