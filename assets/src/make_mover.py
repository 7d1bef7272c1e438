"""Build the humanoid with five clips (idle, walk, run, wave, lean) and export it as COLLADA and glTF.

Usage (from the repository root):
  blender --background --factory-startup --python-exit-code 1 \
      --python assets/src/make_mover.py -- OUT.dae [REFERENCE.json]

The character is make_humanoid.py's (same mesh, weights and skeleton, built by the same code);
only the animation differs. Each clip is its own Blender action, keyed every 3 frames (0.125 s)
with LINEAR keys; a clip keys only the channels it moves, so that the exported files say which
joints a clip drives (assets/README.md, "Humanoid with several clips"):
  idle  2 s     rotation of every joint (breathing and a slight sway); the hips stay in place
  walk  1 s     rotation of every joint and the hips' location: humanoid-walk's cycle with root
                motion, 1.2 m forward per loop at constant speed
  run   0.625 s rotation of every joint and the hips' location: 2.1875 m forward per loop
                (3.5 m/s), longer strides, bent elbows, the trunk leaning forward
  wave  1.5 s   rotation of the right arm chain only (shoulder_R, upper_arm_R, forearm_R, hand_R)
  lean  1.5 s   rotation of spine and chest only: the rest pose at 0 s, bent 20 degrees sideways
                (to the character's left) at 1 s, held to 1.5 s; meant to be added to another clip
idle and wave loop (the last key is the first); walk and run loop with root motion (the last key
is the first with the hips moved forward); lean does not loop.
"""
import math
import os
import sys

import bpy
from mathutils import Quaternion, Vector

sys.dont_write_bytecode = True   # no __pycache__ in the source folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import make_humanoid as humanoid  # noqa: E402

X, Y, Z = humanoid.X, humanoid.Y, humanoid.Z
rot = humanoid.rot
STEP = 3                        # frames between keys: 0.125 s, so every key time is exact in binary
WALK_STRIDE = 1.2               # metres forward per walk loop
RUN_STRIDE = 2.1875             # metres forward per run loop: 3.5 m/s over 0.625 s
RIGHT_ARM = ("shoulder_R", "upper_arm_R", "forearm_R", "hand_R")
SPINE = ("spine", "chest")
ALL = tuple(name for name, _, _, _ in humanoid.BONES)


def sides():
    return (("L", 1.0), ("R", -1.0))


def idle_pose(phase, _):
    """Standing at ease: one breath per loop (chest, shoulders), the weight shifting from one foot
    to the other (hips roll, legs counter it so the feet stay put), the head looking around a
    little. The arms hang as in the walk (35 degrees down from the A pose)."""
    w = 2.0 * math.pi * phase
    breath, sway = math.sin(w), math.sin(w + 0.6)
    pose = {
        "hips": (rot(Y, 1.5 * sway) @ rot(Z, 1.0 * math.sin(w + 2.0)), None),
        "spine": (rot(X, 1.0 * breath) @ rot(Y, -1.0 * sway), None),
        "chest": (rot(X, -2.0 * breath), None),
        "neck": (rot(X, 1.0 * breath), None),
        "head": (rot(X, -1.5 * breath) @ rot(Z, 4.0 * math.sin(w + 1.0)), None),
    }
    for side, sign in sides():
        pose["shoulder_" + side] = (rot(Y, -sign * 2.0 * breath), None)
        pose["upper_arm_" + side] = (rot(X, 2.0 * math.sin(w + sign)) @ rot(Y, sign * 35.0), None)
        pose["forearm_" + side] = (rot(X, -(10.0 + 2.0 * breath)), None)
        pose["hand_" + side] = (rot(X, -5.0 - 2.0 * math.sin(w + 0.5 * sign)), None)
        pose["thigh_" + side] = (rot(Y, -1.5 * sway) @ rot(Z, -1.0 * math.sin(w + 2.0)), None)
        knee = 3.0 + 2.0 * (1.0 + sign * sway)           # the leg taking the weight straightens
        pose["shin_" + side] = (rot(X, knee), None)
        pose["foot_" + side] = (rot(X, -0.6 * knee), None)
    return pose


def walk_pose(phase, travelled):
    """humanoid-walk's cycle (make_humanoid.walk_pose) moving forward (-Y) by `travelled` metres;
    neck, head and hands, which that cycle holds still, nod and swing a little, so that every
    keyed channel changes."""
    w = 2.0 * math.pi * phase
    pose = humanoid.walk_pose(phase)
    hips_rot, hips_loc = pose["hips"]
    pose["hips"] = (hips_rot, hips_loc + Vector((0.0, -travelled, 0.0)))
    pose["neck"] = (rot(X, 3.0 + 1.5 * math.cos(2.0 * w)), None)
    pose["head"] = (rot(X, -1.5 * math.cos(2.0 * w)) @ rot(Z, -2.0 * math.cos(w)), None)
    for side, sign in sides():
        pose["hand_" + side] = (rot(X, -5.0 + 4.0 * sign * math.cos(w)), None)
    return pose


def run_pose(phase, travelled):
    """A run cycle (two strides) moving forward by `travelled` metres: thighs 45 degrees forward
    and 25 back, knees bent up to 100 degrees in the swing, elbows bent about 80 degrees, arms
    swinging 35 degrees, the trunk leaning 12 degrees forward, the hips bobbing 4 cm."""
    w = 2.0 * math.pi * phase
    c, s = math.cos(w), math.sin(w)
    pose = {}
    for side, sign in sides():
        cs, ss = sign * c, sign * s
        thigh = -10.0 - 35.0 * cs
        shin = 15.0 + 85.0 * max(0.0, -ss) + 20.0 * max(0.0, ss)
        pose["thigh_" + side] = (rot(X, thigh), None)
        pose["shin_" + side] = (rot(X, shin), None)
        pose["foot_" + side] = (rot(X, -0.5 * (thigh + shin) + 10.0 * max(0.0, cs)), None)
        pose["shoulder_" + side] = (rot(X, 6.0 * cs), None)
        pose["upper_arm_" + side] = (rot(X, 35.0 * cs) @ rot(Y, sign * 40.0), None)
        pose["forearm_" + side] = (rot(X, -(70.0 + 15.0 * max(0.0, -cs))), None)
        pose["hand_" + side] = (rot(X, -10.0 + 5.0 * cs), None)
    # a positive rotation about X tips the trunk's top forward (towards -Y)
    bob = -0.04 * math.cos(2.0 * w)
    pose["hips"] = (rot(Z, -8.0 * c) @ rot(Y, 4.0 * s), Vector((0.0, -travelled, bob)))
    pose["spine"] = (rot(X, 8.0) @ rot(Z, 6.0 * c), None)
    pose["chest"] = (rot(X, 4.0) @ rot(Z, 7.0 * c) @ rot(Y, -3.0 * s), None)
    pose["neck"] = (rot(X, -6.0 + 2.0 * math.cos(2.0 * w)), None)
    pose["head"] = (rot(X, -4.0 - 2.0 * math.cos(2.0 * w)) @ rot(Z, -5.0 * c), None)
    return pose


def wave_pose(phase, _):
    """The right hand raised and waving twice per loop: the upper arm lifted 105 degrees from the
    A pose (65 degrees above horizontal), the forearm another 25 degrees up and swinging +-25
    degrees in the frontal plane, the hand following a little later. For the right side a
    positive rotation about Y raises the arm."""
    w = 2.0 * math.pi * 2.0 * phase
    return {
        "shoulder_R": (rot(Y, 12.0 + 2.0 * math.sin(w)), None),
        "upper_arm_R": (rot(Y, 105.0 + 4.0 * math.sin(w)) @ rot(X, -10.0), None),
        "forearm_R": (rot(Y, 25.0 + 25.0 * math.sin(w)), None),
        "hand_R": (rot(Y, 15.0 * math.sin(w - 0.8)), None),
    }


def lean_pose(t):
    """Sideways bend to the character's left (+X; about the forward axis): 0 at t = 0 (exactly the
    rest pose), eased in to 10 degrees at spine and 10 at chest (20 in all) by t = 1 s, held."""
    u = min(1.0, t)
    angle = 10.0 * u * u * (3.0 - 2.0 * u)
    return {"spine": (rot(Y, angle), None), "chest": (rot(Y, angle), None)}


# name, frames, keyed bones, keys location of the hips, loops, pose(phase in [0, 1], metres travelled)
CLIPS = [
    ("idle", 48, ALL, False, True, idle_pose),
    ("walk", 24, ALL, True, True, walk_pose),
    ("run", 15, ALL, True, True, run_pose),
    ("wave", 36, RIGHT_ARM, False, True, wave_pose),
    ("lean", 36, SPINE, False, False, lambda phase, _: lean_pose(1.5 * phase)),
]
STRIDES = {"walk": WALK_STRIDE, "run": RUN_STRIDE}


def key_clip(arm_obj, name, frames, bones, keys_location, loops, pose_at):
    """One action keyed every STEP frames from 0 to `frames`: the bones' rotations and, if
    keys_location, the hips' location; nothing else (no scale, no other bone)."""
    action = bpy.data.actions.new(name)
    action.use_fake_user = True      # kept (and exported) while another action is active
    arm_obj.animation_data.action = action
    common.rest_pose(arm_obj)
    previous = {}
    for frame in range(0, frames + 1, STEP):
        # a loop's last key is computed exactly like its first
        phase = (frame % frames if loops else frame) / frames
        pose = pose_at(phase, STRIDES.get(name, 0.0) * frame / frames)
        for bone in bones:
            pb = arm_obj.pose.bones[bone]
            q_arm, loc_arm = pose[bone]
            if q_arm == Quaternion():
                q, loc = Quaternion(), Vector()          # exactly the rest pose (lean at 0 s)
            else:
                q, loc = humanoid.to_bone_axes(pb, q_arm, loc_arm)
            if bone in previous and previous[bone].dot(q) < 0:
                q.negate()                               # shortest path between keys
            previous[bone] = q.copy()
            pb.rotation_quaternion = q
            pb.keyframe_insert("rotation_quaternion", frame=frame)
            if keys_location and bone == "hips":
                pb.location = loc
                pb.keyframe_insert("location", frame=frame)
    common.finish_action(action)
    return action, list(range(0, frames + 1, STEP)), bones


def main():
    args = common.script_args()
    if len(args) not in (1, 2):
        raise SystemExit("usage: make_mover.py -- OUT.dae [REFERENCE.json]")
    out = args[0]
    reference = args[1] if len(args) == 2 else None

    common.reset_scene(frame_end=max(clip[1] for clip in CLIPS))
    mesh_obj, arm_obj = humanoid.build_character()
    arm_obj.animation_data_create()
    # in the glTF exporter's order (it sorts actions by name), so a clip has the same index in both files
    clips = sorted((key_clip(arm_obj, *clip) for clip in CLIPS), key=lambda c: c[0].name.lower())

    me = mesh_obj.data
    print("humanoid: %d vertices, %d triangles, %d bones, clips %s" % (
        len(me.vertices), sum(len(p.vertices) - 2 for p in me.polygons), len(arm_obj.data.bones),
        " ".join("%s (%g s)" % (a.name, frames[-1] / common.FPS) for a, frames, _ in clips)))
    common.write_clips_reference(mesh_obj, arm_obj, clips, reference)
    common.export_dae_clips(out, STEP, arm_obj, clips)
    arm_obj.animation_data.action = clips[0][0]
    common.rest_pose(arm_obj)
    # Optimising leaves out the channels an action does not key (bones and paths it never sets
    # and that stay at rest): wave and lean then drive only their own joints, as in the .dae. It
    # would also shorten a keyed channel whose values never change to two keys, but every channel
    # the clips key changes (check_glb.py finds every key of the .dae's clip in each channel).
    common.export_glb(out, frame_step=STEP, export_optimize_animation_size=True)

if __name__ == "__main__":
    main()
