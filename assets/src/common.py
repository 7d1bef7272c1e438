"""Shared helpers for the skinlab asset scripts (run inside Blender 3.4, headless).

Every asset script builds its scene from nothing (factory settings, empty scene), so the
output depends only on the script and the Blender version. Nothing here uses randomness.
"""
import math
import os
import re
import sys
import tempfile

import bpy

FPS = 24  # fixed frame rate of every asset; key frame f is written as time f / 24 s

# Export options shared by all assets (see README.md, "Export settings").
EXPORT_OPTIONS = dict(
    check_existing=False,
    apply_modifiers=False,          # all non-armature modifiers are applied by the scripts beforehand
    export_mesh_type_selection='view',
    selected=False,                 # the scene holds exactly one armature and one mesh
    include_children=False,
    include_armatures=True,
    include_shapekeys=False,
    deform_bones_only=True,
    include_animations=True,
    include_all_actions=False,      # only the armature's active action
    # 'keys' would be the natural choice, but Blender 3.4 then forces decomposed transforms
    # (per-F-curve <rotate>.ANGLE channels, io_collada.c). So: matrix samples, with the sampling
    # rate set per asset to the key spacing and keep_keyframes on, so that the samples fall
    # exactly on the key frames and nothing else is written.
    export_animation_type_selection='sample',
    keep_keyframes=True,
    keep_smooth_curves=False,
    keep_flat_curves=True,          # also write joints whose pose never changes
    export_animation_transformation_type_selection='matrix',
    export_object_transformation_type_selection='matrix',
    triangulate=True,
    use_object_instantiation=True,
    use_blender_profile=True,
    sort_by_name=False,
    open_sim=False,
    limit_precision=False,
    keep_bind_info=False,
    apply_global_orientation=False,
    active_uv_only=False,
    use_texture_copies=False,
)

FIXED_TIMESTAMP = "2024-01-01T00:00:00"

# glTF export options shared by all assets (see README.md, "glTF export settings"). The .glb holds
# the same scene as the .dae: same mesh, weights, rest pose and key poses.
GLTF_EXPORT_OPTIONS = dict(
    check_existing=False,
    export_format='GLB',
    export_yup=True,                # glTF is Y-up: Blender rotates the data, (x, y, z) -> (x, z, -y)
    export_apply=False,             # all non-armature modifiers are applied by the scripts beforehand
    export_texcoords=True,
    export_normals=True,
    export_tangents=False,
    export_colors=False,
    export_attributes=False,
    export_materials='EXPORT',
    export_cameras=False,
    export_lights=False,
    export_extras=False,
    use_selection=False,
    use_visible=False,
    export_draco_mesh_compression_enable=False,  # plain accessors, nothing a reader must decompress
    export_skins=True,
    export_all_influences=True,     # every weight (the default keeps 4); ours have at most 4 anyway
    export_def_bones=True,          # deforming bones only, as the .dae (every bone of ours deforms)
    export_morph=False,
    export_animations=True,
    export_frame_range=True,        # scene frames 0 .. frame_end
    # Blender 3.4 exports bone animation as sampled TRS; with the step equal to the key spacing the
    # samples fall exactly on the keys, as in the .dae, and nothing else is written.
    export_force_sampling=True,
    export_optimize_animation_size=False,  # keep every key, even of joints that never move
    export_nla_strips=True,
    export_anim_single_armature=True,
    export_reset_pose_bones=True,
    export_current_frame=False,
    export_copyright="",
)


def script_args():
    """Arguments after the '--' separator of the blender command line."""
    argv = sys.argv
    return argv[argv.index("--") + 1:] if "--" in argv else []


def reset_scene(frame_end):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = FPS
    scene.render.fps_base = 1.0
    scene.frame_start = 0
    scene.frame_end = frame_end
    scene.frame_set(0)
    return scene


def link(obj):
    bpy.context.scene.collection.objects.link(obj)
    return obj


def activate(obj, *others):
    """Deselect all, select obj and others, make obj active."""
    vl = bpy.context.view_layer
    for o in bpy.context.scene.objects:
        o.select_set(False)
    for o in others:
        o.select_set(True)
    obj.select_set(True)
    vl.objects.active = obj


def add_material(mesh_obj, name, rgba):
    mat = bpy.data.materials.new(name)
    mat.diffuse_color = rgba
    mat.use_nodes = False
    mat.specular_intensity = 0.2
    mat.roughness = 0.6
    mesh_obj.data.materials.append(mat)
    return mat


def create_armature(name, bones):
    """bones: list of (name, head, tail, parent_name_or_None, roll). Returns the armature object.

    All bones are connected to their parent when the head equals the parent's tail.
    """
    arm = bpy.data.armatures.new(name)
    arm.display_type = 'STICK'
    obj = link(bpy.data.objects.new(name, arm))
    activate(obj)
    bpy.ops.object.mode_set(mode='EDIT')
    ebs = {}
    for bname, head, tail, parent, roll in bones:
        eb = arm.edit_bones.new(bname)
        eb.head = head
        eb.tail = tail
        eb.roll = roll
        eb.use_deform = True
        if parent is not None:
            eb.parent = ebs[parent]
            eb.use_connect = (eb.parent.tail - eb.head).length < 1e-6
        ebs[bname] = eb
    bpy.ops.object.mode_set(mode='OBJECT')
    return obj


class _CaptureOutput:
    """Capture C-level stdout/stderr (operator reports are printed there in background mode)."""

    def __enter__(self):
        sys.stdout.flush()
        sys.stderr.flush()
        self.tmp = tempfile.TemporaryFile(mode="w+b")
        self.saved = (os.dup(1), os.dup(2))
        os.dup2(self.tmp.fileno(), 1)
        os.dup2(self.tmp.fileno(), 2)
        return self

    def __exit__(self, *exc):
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(self.saved[0], 1)
        os.dup2(self.saved[1], 2)
        os.close(self.saved[0])
        os.close(self.saved[1])
        self.tmp.seek(0)
        self.text = self.tmp.read().decode("utf-8", "replace")
        self.tmp.close()
        if self.text:
            sys.stdout.write(self.text)
        return False


def skin_with_auto_weights(mesh_obj, arm_obj, max_influences=4, clean_below=0.001):
    """Parent mesh to armature with heat-diffusion weights (ARMATURE_AUTO), then clean tiny
    weights, limit the influences per vertex and normalise. Fails if bone heat failed or a
    vertex is left without weight."""
    activate(arm_obj, mesh_obj)
    with _CaptureOutput() as cap:
        result = bpy.ops.object.parent_set(type='ARMATURE_AUTO')
    if result != {'FINISHED'} or "failed" in cap.text.lower():
        raise RuntimeError("automatic weights failed: %r %s" % (result, cap.text))

    activate(mesh_obj)
    n_groups = len(mesh_obj.vertex_groups)
    if clean_below > 0:
        bpy.ops.object.vertex_group_clean(group_select_mode='ALL', limit=clean_below, keep_single=True)
    if n_groups > max_influences:
        bpy.ops.object.vertex_group_limit_total(group_select_mode='ALL', limit=max_influences)
    bpy.ops.object.vertex_group_normalize_all(group_select_mode='ALL', lock_active=False)

    mods = [m for m in mesh_obj.modifiers]
    assert len(mods) == 1 and mods[0].type == 'ARMATURE', mods
    bone_names = {b.name for b in arm_obj.data.bones}
    worst = 0
    for v in mesh_obj.data.vertices:
        gs = [g for g in v.groups if g.weight > 0 and mesh_obj.vertex_groups[g.group].name in bone_names]
        total = sum(g.weight for g in gs)
        if not gs or abs(total - 1.0) > 1e-3:
            raise RuntimeError("vertex %d has weight sum %f (%d groups)" % (v.index, total, len(gs)))
        worst = max(worst, len(gs))
    print("skin: %d vertices, %d groups, max influences %d" % (len(mesh_obj.data.vertices), n_groups, worst))
    return worst


def make_action(arm_obj, name):
    arm_obj.animation_data_create()
    action = bpy.data.actions.new(name)
    arm_obj.animation_data.action = action
    return action


def key_pose_bone(pb, frame, loc=None, rot=None, scale=None):
    """Key location/rotation/scale of pose bone pb at frame (all three channels, so every bone
    has the same key times)."""
    if loc is not None:
        pb.location = loc
    if rot is not None:
        if pb.rotation_mode == 'QUATERNION':
            pb.rotation_quaternion = rot
        else:
            pb.rotation_euler = rot
    if scale is not None:
        pb.scale = scale
    pb.keyframe_insert("location", frame=frame)
    if pb.rotation_mode == 'QUATERNION':
        pb.keyframe_insert("rotation_quaternion", frame=frame)
    else:
        pb.keyframe_insert("rotation_euler", frame=frame)
    pb.keyframe_insert("scale", frame=frame)


def finish_action(action, interpolation='LINEAR'):
    """Linear interpolation between keys (what a COLLADA LINEAR sampler means)."""
    for fc in action.fcurves:
        for kp in fc.keyframe_points:
            kp.interpolation = interpolation
        fc.update()


def apply_all_modifiers(obj):
    activate(obj)
    for m in list(obj.modifiers):
        bpy.ops.object.modifier_apply(modifier=m.name)


def reference_keys(mesh_obj, frames, samples=24):
    """Blender's own (linear blend) deformation of the mesh at each key frame of the active
    action: per frame the bounding box and a few sample vertices (also printed)."""
    scene = bpy.context.scene
    n = len(mesh_obj.data.vertices)
    picks = sorted({(i * n) // samples for i in range(samples)} | {n - 1})
    keys = []
    for f in frames:
        scene.frame_set(f)
        dg = bpy.context.evaluated_depsgraph_get()
        ev = mesh_obj.evaluated_get(dg)
        me = ev.to_mesh()
        cos = [mesh_obj.matrix_world @ v.co for v in me.vertices]
        lo = [min(c[k] for c in cos) for k in range(3)]
        hi = [max(c[k] for c in cos) for k in range(3)]
        print("frame %3d (t=%.3f s): x [%.3f, %.3f] y [%.3f, %.3f] z [%.3f, %.3f]" % (
            f, f / FPS, lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]))
        keys.append({
            "frame": f,
            "time": round(f / FPS, 6),
            "bbox_min": [round(x, 6) for x in lo],
            "bbox_max": [round(x, 6) for x in hi],
            "vertices": {str(i): [round(x, 6) for x in cos[i]] for i in picks},
        })
        ev.to_mesh_clear()
    scene.frame_set(0)
    return keys


def write_reference(mesh_obj, frames, path, samples=24):
    """Evaluate Blender's own (linear blend) deformation of the mesh at each key frame; print the
    bounding boxes and, if path is given, write them with a few sample vertices to a JSON file.
    check_assets.py recomputes the same numbers from the exported .dae alone."""
    keys = reference_keys(mesh_obj, frames, samples)
    if path:
        _write_json(path, {
            "about": "Blender %s armature deformation (linear blend skinning) of the mesh at each key "
                     "frame, world coordinates; vertex keys are position indices in the .dae"
                     % bpy.app.version_string,
            "fps": FPS,
            "vertex_count": len(mesh_obj.data.vertices),
            "keys": keys,
        })


def write_clips_reference(mesh_obj, arm_obj, clips, path, samples=24):
    """write_reference for several actions: clips is a list of (action, key frames, keyed bones);
    the JSON has one entry per clip, {"name", "keys"}, in that order."""
    entries = []
    for action, frames, _ in clips:
        print("clip %s" % action.name)
        arm_obj.animation_data.action = action
        rest_pose(arm_obj)
        entries.append({"name": action.name, "keys": reference_keys(mesh_obj, frames, samples)})
    if path:
        _write_json(path, {
            "about": "Blender %s armature deformation (linear blend skinning) of the mesh at each key "
                     "frame of each clip (action), world coordinates; vertex keys are position "
                     "indices in the .dae" % bpy.app.version_string,
            "fps": FPS,
            "vertex_count": len(mesh_obj.data.vertices),
            "clips": entries,
        })


def _write_json(path, doc):
    import json
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        json.dump(doc, fh, indent=1, sort_keys=True)
        fh.write("\n")
    print("wrote %s" % path)


def rest_pose(arm_obj):
    """Every pose bone at rest. An action sets only the channels it keys, so before another
    action is evaluated the bones it leaves alone must be put back."""
    for pb in arm_obj.pose.bones:
        pb.location = (0.0, 0.0, 0.0)
        pb.rotation_quaternion = (1.0, 0.0, 0.0, 0.0)
        pb.rotation_euler = (0.0, 0.0, 0.0)
        pb.scale = (1.0, 1.0, 1.0)


def export_dae(path, sampling_rate, **overrides):
    """Export the scene with EXPORT_OPTIONS (sampling_rate = key spacing in frames; overrides replace
    single options) and pin the <created>/<modified> timestamps so a rebuild gives a byte-identical
    file."""
    path = os.path.abspath(path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    bpy.context.scene.frame_set(0)
    # no object is in edit mode and nothing else than one armature + one mesh is in the scene
    kinds = sorted(o.type for o in bpy.context.scene.objects)
    assert kinds == ['ARMATURE', 'MESH'], kinds
    options = dict(EXPORT_OPTIONS, **overrides)
    result = bpy.ops.wm.collada_export(filepath=path, sampling_rate=sampling_rate, **options)
    if result != {'FINISHED'}:
        raise RuntimeError("collada_export failed: %r" % (result,))
    with open(path, "r", encoding="utf-8") as f:
        text = f.read()
    text = re.sub(r"<created>[^<]*</created>", "<created>%s</created>" % FIXED_TIMESTAMP, text)
    text = re.sub(r"<modified>[^<]*</modified>", "<modified>%s</modified>" % FIXED_TIMESTAMP, text)
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)
    print("wrote %s (%d bytes)" % (path, os.path.getsize(path)))


_LIBRARY_ANIMATIONS = re.compile(r"  <library_animations>\n.*?  </library_animations>\n", re.S)
_CHANNEL_ANIMATION = re.compile(r'      <animation id="[^"]*" name="[^"]*">\n.*?\n      </animation>\n', re.S)


def export_dae_clips(path, sampling_rate, arm_obj, clips):
    """Export several actions of arm_obj into one .dae, one <animation_clip> per action.

    clips: list of (action, key frames, names of the bones the action keys), in the order the
    clips are to be written. Blender 3.4's COLLADA exporter writes the active action only: its
    include_all_actions option does nothing, because the call of its animation clip exporter is
    compiled out (io/collada/AnimationExporter.cpp, '#if 0'). So each action is exported alone,
    with the scene's frame range set to the action's keys, and the files are joined here: the
    document of the first export (the others must be the same outside <library_animations>),
    and per action one <animation> holding the channel animations of the bones it keys (the
    exporter also writes the bones it does not key, at rest, and the armature object's identity
    transform; both are left out), named by an <animation_clip> from 0 to the action's last key.
    """
    scene = bpy.context.scene
    frame_end = scene.frame_end
    base = None
    containers, clip_elements = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for k, (action, frames, bones) in enumerate(clips):
            arm_obj.animation_data.action = action
            rest_pose(arm_obj)
            scene.frame_end = frames[-1]
            part = os.path.join(tmp, "clip%d.dae" % k)
            export_dae(part, sampling_rate)
            with open(part, encoding="utf-8") as f:
                text = f.read()
            library = _LIBRARY_ANIMATIONS.search(text)
            outside = text[:library.start()] + text[library.end():]
            if base is None:
                base, at = outside, library.start()
            elif outside != base:
                raise RuntimeError("exporting action %s changed the document outside its animations" % action.name)
            by_target = {}
            for block in _CHANNEL_ANIMATION.findall(library.group(0)):
                target = re.search(r'<channel source="[^"]*" target="([^"]*)"/>', block).group(1)
                by_target[target] = block
            container = "action_container-%s-%s" % (arm_obj.name, action.name)
            kept = [by_target["%s_%s/transform" % (arm_obj.name, bone.name)]
                    for bone in arm_obj.data.bones if bone.name in bones]
            if len(kept) != len(bones):
                raise RuntimeError("action %s: %d of its %d bones were exported" % (action.name, len(kept), len(bones)))
            containers.append('    <animation id="%s" name="%s">\n%s    </animation>\n'
                              % (container, action.name, "".join(kept)))
            clip_elements.append('    <animation_clip id="%s-%s" name="%s" start="0" end="%g">\n'
                                 '      <instance_animation url="#%s"/>\n'
                                 '    </animation_clip>\n'
                                 % (arm_obj.name, action.name, action.name, frames[-1] / FPS, container))
    scene.frame_end = frame_end
    libraries = ("  <library_animations>\n" + "".join(containers) + "  </library_animations>\n"
                 "  <library_animation_clips>\n" + "".join(clip_elements) + "  </library_animation_clips>\n")
    path = os.path.abspath(path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        f.write(base[:at] + libraries + base[at:])
    print("wrote %s (%d bytes, clips %s)" % (path, os.path.getsize(path), " ".join(a.name for a, _, _ in clips)))


_CLIP = re.compile(r'    <animation_clip id="[^"]*" name="([^"]*)"[^>]*>\n      <instance_animation url="#([^"]*)"/>\n')
_CLIP_CONTAINER = re.compile(r'    <animation id="([^"]*)" name="[^"]*">\n.*?\n    </animation>\n', re.S)
_LIBRARY_CLIPS = re.compile(r"  <library_animation_clips>\n.*?  </library_animation_clips>\n", re.S)


def dae_clip_names(path):
    """Names of the clips export_dae_clips wrote into a .dae, in order; [] for a file without."""
    with open(path, encoding="utf-8") as f:
        return [name for name, _ in _CLIP.findall(f.read())]


def write_single_clip_dae(path, clip, out):
    """A copy of a .dae written by export_dae_clips with only one clip's animations and no
    <library_animation_clips>. Blender's COLLADA importer knows no clips: it merges the channels of
    all of them into one action; given this copy it reads back the one clip."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    container = dict(_CLIP.findall(text))[clip]
    text = _CLIP_CONTAINER.sub(lambda m: m.group(0) if m.group(1) == container else "", text)
    text = _LIBRARY_CLIPS.sub("", text)
    with open(out, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


def triangulate_like_collada(mesh_obj):
    """Split the mesh's quads and n-gons into the triangles the COLLADA exporter wrote: its
    triangulate option runs BM_mesh_triangulate with the shortest-edge diagonal for quads and the
    'beauty' fill for n-gons (io/collada/collada_utils.cpp, bc_triangulate_mesh). The glTF exporter
    would otherwise choose its own diagonals (half the humanoid's quads differ), and CoR's centres,
    integrated over the triangles, would differ by millimetres between the two files."""
    import bmesh
    me = mesh_obj.data
    bm = bmesh.new()
    bm.from_mesh(me)
    bmesh.ops.triangulate(bm, faces=bm.faces[:], quad_method='SHORT_EDGE', ngon_method='BEAUTY')
    bm.to_mesh(me)
    bm.free()
    me.update()


def export_glb(dae_path, frame_step, **overrides):
    """Export the same scene as a .glb beside the .dae (same name, .glb), sampling every
    frame_step frames (= the key spacing) with GLTF_EXPORT_OPTIONS (overrides replace single
    options). The exporter writes no date, so a rebuild gives a byte-identical file."""
    path = os.path.splitext(os.path.abspath(dae_path))[0] + ".glb"
    bpy.context.scene.frame_set(0)
    kinds = sorted(o.type for o in bpy.context.scene.objects)
    assert kinds == ['ARMATURE', 'MESH'], kinds
    triangulate_like_collada(next(o for o in bpy.context.scene.objects if o.type == 'MESH'))
    options = dict(GLTF_EXPORT_OPTIONS, **overrides)
    result = bpy.ops.export_scene.gltf(filepath=path, export_frame_step=frame_step, **options)
    if result != {'FINISHED'}:
        raise RuntimeError("gltf export failed: %r" % (result,))
    print("wrote %s (%d bytes)" % (path, os.path.getsize(path)))


def deg(a):
    return math.radians(a)
