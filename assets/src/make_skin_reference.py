"""Write Blender's full-vertex skinning of our assets, LBS and DQS, at every key time:
assets/reference/skinning/<name>.json, the ground truth for the Java skinning tests.

Usage (from the repository root):
  blender -t 1 --background --factory-startup --python-exit-code 1 \
      --python assets/src/make_skin_reference.py -- ASSETS_DIR [NAME.dae ...]

For each .dae (default: the nine assets in ASSETS) it re-imports the committed file into an empty
scene with Blender's COLLADA importer (so the reference is Blender's reading of the very file the
Java code reads) and, at every key time of the file (the union of its samplers' INPUT arrays), sets
the frame (time * 24 fps, with a subframe if needed), evaluates the mesh through the depsgraph with
the Armature modifier's use_deform_preserve_volume off (linear blend skinning) and on (Blender's
dual quaternion skinning) and writes the evaluated vertices in world coordinates
(obj.matrix_world @ v) in the order of the geometry's <vertices> POSITION source.

It fails (exception, exit status 1) unless
- the importer made one armature and one mesh with one Armature modifier, used no unit or axis
  conversion (file: Z_UP, metres; import_units off; scene unit scale 1; both objects' world
  matrices equal the file's node world matrices),
- Blender's rest vertex i (matrix_world @ co) is the file's POSITION i (after BIND_SHAPE_MATRIX),
  for every vertex, to 1e-5 m: this is what makes the JSON's vertex order the file's,
- every bone's rest matrix (arm_mat) is the inverse of its INV_BIND_MATRIX and, at every key time,
  every evaluated pose bone matrix is the file's joint world matrix at that key (1e-5),
- LBS and DQS actually differ somewhere (the modifier flag reached the evaluation), for rigs where
  joints sharing vertices rotate relative to each other (with no such rotation they coincide).
Key times where two joints sharing vertices are rotated within 2 degrees of 180 apart are left out
and listed in "skipped" (the dual quaternion sign is arbitrary there; check_skin_reference.py
decides this from the file alone, with the same function).

JSON (one flat array per line):
  {"about": ..., "file": "<path relative to ASSETS_DIR>", "extent": <rest bbox diagonal, m>,
   "times": [s, ...], "lbs": [[x,y,z, x,y,z, ...] per time], "dqs": [[...] per time],
   "skipped": [{"time": s, "why": "..."}]}
Numbers are written with 7 significant digits (Blender's float32 results; ~1e-7 of the extent).
"""
import json
import math
import os
import sys

import bpy

sys.dont_write_bytecode = True   # no __pycache__ in the source folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import check_assets as ca  # noqa: E402
import check_skin_reference as csr  # noqa: E402

ASSETS = [
    "cylinders/cylinder-twist-low.dae",
    "cylinders/cylinder-twist-high.dae",
    "cylinders/cylinder-bend.dae",
    "cylinders/cylinder-twist-full.dae",
    "cylinders/cylinder-bend-full.dae",
    "characters/humanoid-walk.dae",
    "creatures/tentacle-wave.dae",
    "stretch/limb-stretch.dae",
    "twist/arm-twist.dae",
]
MATCH = 1e-5   # metres (and matrix entries): float32 import and pose evaluation vs the file


def max_matrix_diff(a, b):
    return max(abs(a[i][j] - b[i][j]) for i in range(4) for j in range(4))


def fail(rel, msg):
    raise RuntimeError("%s: %s" % (rel, msg))


def import_file(path, rel):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps = common.FPS
    scene.render.fps_base = 1.0
    # import_units=False (the default, spelled out): keep the file's numbers as they are
    result = bpy.ops.wm.collada_import(filepath=path, import_units=False, fix_orientation=False,
                                       find_chains=False, auto_connect=False, keep_bind_info=False)
    if result != {'FINISHED'}:
        fail(rel, "collada_import returned %r" % (result,))
    objs = list(scene.objects)
    arms = [o for o in objs if o.type == 'ARMATURE']
    meshes = [o for o in objs if o.type == 'MESH']
    if len(arms) != 1 or len(meshes) != 1 or len(objs) != 2:
        fail(rel, "expected one armature and one mesh, got %s" % [(o.name, o.type) for o in objs])
    mesh = meshes[0]
    mods = [m for m in mesh.modifiers]
    if len(mods) != 1 or mods[0].type != 'ARMATURE' or mods[0].object != arms[0]:
        fail(rel, "the mesh's modifiers are %s, expected one Armature modifier on %s"
             % ([m.type for m in mods], arms[0].name))
    if abs(scene.unit_settings.scale_length - 1.0) > 0 or scene.unit_settings.system != 'METRIC':
        fail(rel, "scene units changed by the import: %s x %g"
             % (scene.unit_settings.system, scene.unit_settings.scale_length))
    return scene, arms[0], mesh, mods[0]


def check_frame_and_rest(rel, setup, arm, mesh):
    """No unit/axis conversion, vertex order = POSITION order, bones rest = inverse bind."""
    root = setup["root"]
    up = root.find(ca.NS + "asset/" + ca.NS + "up_axis")
    unit = root.find(ca.NS + "asset/" + ca.NS + "unit")
    if up is None or up.text.strip() != "Z_UP" or unit is None or float(unit.get("meter", "1")) != 1.0:
        fail(rel, "the file is not Z_UP metres; this script assumes no conversion")
    nodes = setup["nodes"]
    # the objects sit where the file's nodes are (names: Blender names objects after node names)
    for obj in (arm, mesh):
        nid = [i for i, n in nodes.items() if n["name"] == obj.name]
        if len(nid) != 1:
            fail(rel, "no unique node named %r for object %r" % (obj.name, obj.name))
        rest_world = ca.identity()
        chain = []
        p = nid[0]
        while p:
            chain.append(p)
            p = nodes[p]["parent"]
        for p in reversed(chain):
            rest_world = ca.mul(rest_world, nodes[p]["matrix"])
        d = max_matrix_diff(obj.matrix_world, rest_world)
        if d > MATCH:
            fail(rel, "object %s world matrix %s differs from node %s (%.2e): the importer converted"
                 % (obj.name, list(obj.matrix_world), nid[0], d))
    # vertex order: Blender vertex i == POSITION i, every vertex
    verts = mesh.data.vertices
    pts = setup["bind_points"]
    if len(verts) != len(pts):
        fail(rel, "Blender's mesh has %d vertices, the file %d positions" % (len(verts), len(pts)))
    worst, at = 0.0, -1
    for i, v in enumerate(verts):
        co = mesh.matrix_world @ v.co
        d = max(abs(co[a] - pts[i][a]) for a in range(3))
        if d > worst:
            worst, at = d, i
    if worst > MATCH:
        fail(rel, "Blender's rest vertex %d is %.3g m from POSITION %d: vertex order or frame differs"
             % (at, worst, at))
    print("  rest: %d vertices in POSITION order (max %.1e m), objects at their node transforms"
          % (len(verts), worst))
    # bone rest frames (arm_mat, Blender's DQS pivot) == inverse(INV_BIND_MATRIX)
    worst = 0.0
    for name, ibm in zip(setup["skin"]["joints"], setup["skin"]["ibms"]):
        bone = arm.data.bones.get(name)
        if bone is None:
            fail(rel, "no bone %r" % name)
        d = max_matrix_diff(arm.matrix_world @ bone.matrix_local, csr.inverse(ibm))
        worst = max(worst, d)
        if d > MATCH:
            fail(rel, "bone %s rest matrix differs from inverse(INV_BIND_MATRIX) by %.2e" % (name, d))
    print("  bones: rest matrices = inverse(INV_BIND_MATRIX) (max %.1e)" % worst)


def set_time(scene, t):
    f = t * common.FPS
    whole = math.floor(f + 1e-6)
    sub = f - whole
    scene.frame_set(int(whole), subframe=sub if sub > 1e-6 else 0.0)


def check_pose(rel, setup, arm, t):
    world = csr.world_at(setup, t)
    worst = 0.0
    for name, nid in zip(setup["skin"]["joints"], setup["joint_nodes"]):
        pb = arm.pose.bones[name]
        d = max_matrix_diff(arm.matrix_world @ pb.matrix, world[nid])
        worst = max(worst, d)
        if d > MATCH:
            fail(rel, "at t=%g bone %s is not in the key pose (deviation %.2e)" % (t, name, d))
    return worst


def evaluated(mesh):
    dg = bpy.context.evaluated_depsgraph_get()
    dg.update()
    ev = mesh.evaluated_get(dg)
    me = ev.to_mesh()
    mw = ev.matrix_world
    out = [mw @ v.co for v in me.vertices]
    ev.to_mesh_clear()
    return out


def fmt(x):
    s = "%.7g" % x
    return "0" if s == "-0" else s


def flat_line(cos):
    return "[" + ",".join(fmt(c[a]) for c in cos for a in range(3)) + "]"


def make_one(assets, rel, out_dir):
    path = os.path.join(assets, rel)
    print("== %s" % rel)
    setup = csr.load(path)
    scene, arm, mesh, mod = import_file(path, rel)
    check_frame_and_rest(rel, setup, arm, mesh)
    n = len(setup["points"])
    times, lbs, dqs, skipped = [], [], [], []
    worst_pose = 0.0
    worst_angle = 0.0
    lbs_dqs = 0.0
    for t in setup["times"]:
        reason, angle = csr.antipodal_reason(setup, t)
        worst_angle = max(worst_angle, angle)
        if reason is not None:
            skipped.append({"time": t, "why": reason})
            print("  skip t=%g: %s" % (t, reason))
            continue
        set_time(scene, t)
        worst_pose = max(worst_pose, check_pose(rel, setup, arm, t))
        mod.use_deform_preserve_volume = False
        a = evaluated(mesh)
        mod.use_deform_preserve_volume = True
        b = evaluated(mesh)
        if len(a) != n or len(b) != n:
            fail(rel, "evaluated mesh has %d/%d vertices, expected %d" % (len(a), len(b), n))
        lbs_dqs = max(lbs_dqs, max((p - q).length for p, q in zip(a, b)))
        times.append(t)
        lbs.append(a)
        dqs.append(b)
    mod.use_deform_preserve_volume = False
    # Without rotation between joints that share vertices (limb-stretch: a pure stretch along a
    # straight chain) the two coincide by construction, so only a rotating rig can show the flag works.
    if worst_angle > 1.0 and lbs_dqs < 1e-4 * setup["extent"]:
        fail(rel, "LBS and DQS agree everywhere (%.2e m): the preserve-volume flag had no effect" % lbs_dqs)
    print("  %d key times, %d skipped; pose = file's joint world matrices (max %.1e); largest rotation "
          "between joints sharing vertices %.1f deg; LBS vs DQS up to %.4f m"
          % (len(setup["times"]), len(skipped), worst_pose, worst_angle, lbs_dqs))

    about = ("Blender %s (COLLADA importer, Armature modifier, evaluated through the depsgraph, "
             "single-threaded) deformation of every vertex of %s at every key time of the file: "
             "'lbs' with use_deform_preserve_volume off (linear blend skinning), 'dqs' with it on "
             "(Blender's dual quaternion skinning; bone scale split off about the bone rest frame and "
             "blended linearly, see docs/references.md). World coordinates of the document (Z up, "
             "metres), vertices in POSITION-index order, flat x,y,z per vertex, one array per entry "
             "of 'times' (seconds; frame = time * %d fps). 'extent' is the diagonal of the rest "
             "bounding box. Made by assets/src/make_skin_reference.py; checked by "
             "assets/src/check_skin_reference.py." % (bpy.app.version_string, rel, common.FPS))
    name = os.path.splitext(os.path.basename(rel))[0] + ".json"
    out = os.path.join(out_dir, name)
    os.makedirs(out_dir, exist_ok=True)
    lines = ["{",
             ' "about": %s,' % json.dumps(about),
             ' "file": %s,' % json.dumps(rel),
             ' "extent": %s,' % repr(round(setup["extent"], 9)),
             ' "times": [%s],' % ", ".join(repr(t) for t in times),
             ' "lbs": [']
    lines += ["  " + flat_line(a) + ("," if k < len(lbs) - 1 else "") for k, a in enumerate(lbs)]
    lines += [' ],', ' "dqs": [']
    lines += ["  " + flat_line(b) + ("," if k < len(dqs) - 1 else "") for k, b in enumerate(dqs)]
    lines += [' ],', ' "skipped": %s' % json.dumps(skipped), "}"]
    with open(out, "w", encoding="utf-8", newline="\n") as fh:
        fh.write("\n".join(lines) + "\n")
    json.load(open(out, encoding="utf-8"))   # well-formed
    print("wrote %s (%d bytes)" % (out, os.path.getsize(out)))


def main():
    args = common.script_args()
    if not args:
        raise SystemExit("usage: make_skin_reference.py -- ASSETS_DIR [NAME.dae ...]")
    assets = os.path.abspath(args[0])
    rels = args[1:] or ASSETS
    out_dir = os.path.join(assets, "reference", "skinning")
    for rel in rels:
        make_one(assets, rel, out_dir)


main()
