#!/usr/bin/env python3
"""Check every COLLADA file under assets/ (plain Python 3, standard library only, no Blender).

Usage (from the repository root):  python3 assets/src/check_assets.py [ASSETS_DIR]

For each .dae it prints the geometry (positions, normals, triangles, closed or not, enclosed
volume), the skin (joints, influences per vertex, bind shape matrix) and the animation (channels,
key times, rotation step between consecutive keys, bone scale), then asserts the requirements in
EXPECT below plus generic ones (one mesh, one skin, <= 4 influences, weights sum to 1, every joint
and channel target resolves, no cameras or lights, steps < 180 degrees, file < 2 MB).
If assets/reference/<name>.json exists (written by the Blender build scripts: Blender's own
deformed vertices at each key), it also skins the mesh itself with linear blend skinning,
  v' = sum_i w_i * JointWorld_i(t) * INV_BIND_MATRIX_i * BIND_SHAPE_MATRIX * v,
from the file alone and asserts that the result matches Blender's. It also prints the enclosed
volume of that LBS result at each key (the volume loss the project measures later).
Each .dae must have its .glb beside it, holding the same scene (check_glb.py: same joints and key
times, every vertex at a .dae position, its own LBS against the same reference).
Exit status 1 if any check fails.
"""
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import check_glb

NS = "{http://www.collada.org/2005/11/COLLADASchema}"
MAX_BYTES = 2 * 1024 * 1024

HUMANOID = ("hips", "spine", "chest", "neck", "head", "shoulder_L", "upper_arm_L", "forearm_L", "hand_L",
            "shoulder_R", "upper_arm_R", "forearm_R", "hand_R", "thigh_L", "shin_L", "foot_L", "thigh_R",
            "shin_R", "foot_R")

# Requirements per file (paths relative to the assets directory); "clips": per clip, by name.
EXPECT = {
    "cylinders/cylinder-twist-low.dae": dict(
        joints=(2, 2), triangles=(1000, 1300), closed=True, min_keys=5,
        motion=("upper", "Y", 165.0, 179.0)),
    "cylinders/cylinder-twist-high.dae": dict(
        joints=(2, 2), triangles=(1900, 2200), closed=True, min_keys=5,
        motion=("upper", "Y", 165.0, 179.0)),
    "cylinders/cylinder-bend.dae": dict(
        joints=(2, 2), triangles=(1900, 2200), closed=True, min_keys=5,
        motion=("upper", "X", 160.0, 179.0), passes_through=[("upper", 90.0)]),
    # a whole turn, 15 degrees per key, back at rest at the last key (so the clip loops)
    "cylinders/cylinder-twist-full.dae": dict(
        joints=(2, 2), triangles=(1900, 2200), closed=True, min_keys=25, loop=True, duration=(5.9, 6.1),
        turn=("upper", "Y", 15.0, 360.0)),
    "cylinders/cylinder-bend-full.dae": dict(
        joints=(2, 2), triangles=(1900, 2200), closed=True, min_keys=25, loop=True, duration=(5.9, 6.1),
        turn=("upper", "X", 15.0, 360.0)),
    "characters/humanoid-walk.dae": dict(
        joints=(15, 64), triangles=(1000, 2000), closed=True, min_keys=5, loop=True,
        duration=(0.8, 1.2)),
    # the same character with five clips (make_mover.py), each keying only the joints it moves
    "characters/humanoid-moves.dae": dict(
        joints=(19, 19), triangles=(1000, 2000), closed=True, clips={
            "idle": dict(keyed=HUMANOID, min_keys=17, duration=(2.0, 2.0), loop=True, in_place="hips"),
            "lean": dict(keyed=("spine", "chest"), min_keys=13, duration=(1.5, 1.5), starts_at_rest=True,
                         bends=("chest", 1.0, 20.0, "Y")),
            "run": dict(keyed=HUMANOID, min_keys=6, duration=(0.625, 0.625), root_motion=("hips", (0.0, -2.1875, 0.0))),
            "walk": dict(keyed=HUMANOID, min_keys=9, duration=(1.0, 1.0), root_motion=("hips", (0.0, -1.2, 0.0))),
            "wave": dict(keyed=("shoulder_R", "upper_arm_R", "forearm_R", "hand_R"), min_keys=13,
                         duration=(1.5, 1.5), loop=True, raised=("hand_R", 1.7)),
        }),
    "creatures/tentacle-wave.dae": dict(
        joints=(6, 10), triangles=(500, 3000), closed=True, min_keys=5, loop=True,
        scaled=True, non_uniform=True),
    "stretch/limb-stretch.dae": dict(
        joints=(3, 3), triangles=(3000, 3300), closed=True, min_keys=5, loop=True, duration=(1.9, 2.1),
        scaled=True, stretch=("middle", 1.5, "end")),
    "twist/arm-twist.dae": dict(
        joints=(3, 3), triangles=(3000, 3300), closed=True, min_keys=5, loop=True, duration=(1.9, 2.1),
        motion=("forearm", "Y", 0.0, 1.0), passes_through=[("forearm", 90.0), ("forearm", 170.0)],
        peak=("forearm", 179.9)),
}


class CheckError(Exception):
    pass


FAILURES = []


def check(cond, msg):
    if not cond:
        FAILURES.append(msg)
        print("    FAIL: " + msg)
    return cond


# ---------------------------------------------------------------- small 4x4 matrix helpers
def mat(values):
    """COLLADA matrices are written row by row."""
    v = [float(x) for x in values]
    return [v[0:4], v[4:8], v[8:12], v[12:16]]


def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def identity():
    return [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]


def is_identity(m, tol=1e-6):
    return all(abs(m[i][j] - (1.0 if i == j else 0.0)) < tol for i in range(4) for j in range(4))


def transform_point(m, p):
    return [m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3)]


def column_scales(m):
    return [math.sqrt(sum(m[r][c] ** 2 for r in range(3))) for c in range(3)]


def rotation_part(m):
    s = column_scales(m)
    return [[m[r][c] / s[c] for c in range(3)] for r in range(3)]


def relative_rotation(m0, m1):
    """Angle (degrees) and axis (in m0's frame) of the rotation taking m0's rotation to m1's."""
    r0, r1 = rotation_part(m0), rotation_part(m1)
    rel = [[sum(r0[k][i] * r1[k][j] for k in range(3)) for j in range(3)] for i in range(3)]  # r0^T r1
    c = max(-1.0, min(1.0, (rel[0][0] + rel[1][1] + rel[2][2] - 1.0) / 2.0))
    axis = [rel[2][1] - rel[1][2], rel[0][2] - rel[2][0], rel[1][0] - rel[0][1]]
    n = math.sqrt(sum(a * a for a in axis))
    if n > 1e-6:
        axis = [a / n for a in axis]
    elif c < 0.0:
        # a half turn: rel = 2 a a^T - I, so the axis is the largest column of rel + I
        k = max(range(3), key=lambda i: rel[i][i])
        col = [rel[i][k] + (1.0 if i == k else 0.0) for i in range(3)]
        n = math.sqrt(sum(a * a for a in col))
        axis = [a / n for a in col]
    else:
        axis = [0.0, 0.0, 0.0]
    return math.degrees(math.acos(c)), axis


def decompose_rotation_matrix(m):
    """3x3 rotation matrix of a COLLADA transform row-major list-of-rows."""
    return rotation_part(m)


# ---------------------------------------------------------------- COLLADA reading
def floats(el):
    return [float(x) for x in (el.text or "").split()]


def ints(el):
    return [int(x) for x in (el.text or "").split()]


def source_by_id(root, ref):
    ref = ref.lstrip("#")
    for el in root.iter():
        if el.get("id") == ref:
            return el
    raise CheckError("no element with id %r" % ref)


def source_array(root, ref):
    """(values, stride) of a <source>, values as floats or names."""
    src = source_by_id(root, ref)
    acc = src.find(NS + "technique_common/" + NS + "accessor")
    stride = int(acc.get("stride", "1")) if acc is not None else 1
    fa = src.find(NS + "float_array")
    if fa is not None:
        return floats(fa), stride
    na = src.find(NS + "Name_array")
    if na is None:
        na = src.find(NS + "IDREF_array")
    return (na.text or "").split(), stride


def read_geometry(root, geom):
    mesh = geom.find(NS + "mesh")
    verts = mesh.find(NS + "vertices")
    pos_ref = [i for i in verts.findall(NS + "input") if i.get("semantic") == "POSITION"][0].get("source")
    positions, stride = source_array(root, pos_ref)
    assert stride == 3
    pts = [positions[i:i + 3] for i in range(0, len(positions), 3)]
    normals = 0
    tris = []
    kinds = []
    for prim in list(mesh):
        tag = prim.tag.replace(NS, "")
        if tag not in ("triangles", "polylist", "polygons"):
            continue
        kinds.append(tag)
        inputs = prim.findall(NS + "input")
        n_off = max(int(i.get("offset", "0")) for i in inputs) + 1
        v_off = [int(i.get("offset", "0")) for i in inputs if i.get("semantic") == "VERTEX"][0]
        for i in inputs:
            if i.get("semantic") == "NORMAL":
                normals = max(normals, len(source_array(root, i.get("source"))[0]) // 3)
        if tag == "polygons":
            polys = [ints(p) for p in prim.findall(NS + "p")]
            counts = [len(p) // n_off for p in polys]
            idx = [x for p in polys for x in p]
        else:
            idx = ints(prim.find(NS + "p"))
            if tag == "triangles":
                counts = [3] * int(prim.get("count"))
            else:
                counts = ints(prim.find(NS + "vcount"))
        at = 0
        for c in counts:
            corner = [idx[(at + k) * n_off + v_off] for k in range(c)]
            for k in range(1, c - 1):       # fan; Blender writes triangles anyway
                tris.append((corner[0], corner[k], corner[k + 1]))
            at += c
    return dict(id=geom.get("id"), points=pts, triangles=tris, normals=normals, kinds=kinds)


def closed_manifold(tris):
    """Every edge used by exactly two triangles, once in each direction (closed, oriented)."""
    directed = {}
    for a, b, c in tris:
        for e in ((a, b), (b, c), (c, a)):
            directed[e] = directed.get(e, 0) + 1
    bad = 0
    for (a, b), n in directed.items():
        if n != 1 or directed.get((b, a), 0) != 1:
            bad += 1
    return bad == 0, bad


def volume(points, tris):
    v = 0.0
    for a, b, c in tris:
        p, q, r = points[a], points[b], points[c]
        v += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
              + p[2] * (q[0] * r[1] - q[1] * r[0]))
    return v / 6.0


def node_matrix(node):
    m = identity()
    for el in list(node):
        tag = el.tag.replace(NS, "")
        if tag == "matrix":
            m = mul(m, mat(floats(el)))
        elif tag == "translate":
            x, y, z = floats(el)
            m = mul(m, [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]])
        elif tag == "scale":
            x, y, z = floats(el)
            m = mul(m, [[x, 0, 0, 0], [0, y, 0, 0], [0, 0, z, 0], [0, 0, 0, 1]])
        elif tag == "rotate":
            x, y, z, a = floats(el)
            a = math.radians(a)
            c, s, t = math.cos(a), math.sin(a), 1 - math.cos(a)
            m = mul(m, [[t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0],
                        [t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0],
                        [t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0], [0, 0, 0, 1]])
    return m


def read_scene(root):
    nodes = {}     # id -> dict
    order = []

    def walk(el, parent):
        for n in el.findall(NS + "node"):
            nid = n.get("id")
            nodes[nid] = dict(el=n, parent=parent, sid=n.get("sid"), name=n.get("name"),
                              type=n.get("type", "NODE"), matrix=node_matrix(n),
                              has_matrix_el=n.find(NS + "matrix") is not None)
            order.append(nid)
            walk(n, nid)

    for vs in root.iter(NS + "visual_scene"):
        walk(vs, None)
    return nodes, order


def read_clips(root):
    """[dict(name, start, end, channels)] per <animation_clip>, channels as read_animations gives
    them for the animations the clip instances (nested ones included); a file without clips has
    one clip named None over all its channels."""
    clips = []
    for clip in root.iter(NS + "animation_clip"):
        channels = {}
        for inst in clip.findall(NS + "instance_animation"):
            channels.update(read_animations(root, source_by_id(root, inst.get("url")), channels))
        clips.append(dict(name=clip.get("name") or clip.get("id"), start=float(clip.get("start", "0")),
                          end=float(clip.get("end")), channels=channels))
    if not clips:
        clips.append(dict(name=None, channels=read_animations(root)))
    return clips


def read_animations(root, within=None, seen=()):
    """Channels of all animations (or of the animation `within` and those nested in it); a node
    with two channels (also one in `seen`) is an error."""
    channels = {}   # target node id -> (times, matrices, interpolations, target string)
    for anim in (within if within is not None else root).iter(NS + "animation"):
        for ch in anim.findall(NS + "channel"):
            target = ch.get("target")
            sampler = source_by_id(root, ch.get("source"))
            inputs = {i.get("semantic"): i.get("source") for i in sampler.findall(NS + "input")}
            times, _ = source_array(root, inputs["INPUT"])
            out, stride = source_array(root, inputs["OUTPUT"])
            interp, _ = source_array(root, inputs["INTERPOLATION"]) if "INTERPOLATION" in inputs else ([], 1)
            node_id, _, what = target.partition("/")
            if stride != 16:
                raise CheckError("channel %s is not a baked matrix (stride %d)" % (target, stride))
            mats = [mat(out[i:i + 16]) for i in range(0, len(out), 16)]
            if node_id in channels or node_id in seen:
                raise CheckError("two channels for node %s" % node_id)
            channels[node_id] = dict(times=times, mats=mats, interp=interp, target=target, what=what)
    return channels


def read_skin(root):
    skins = list(root.iter(NS + "skin"))
    if len(skins) != 1:
        raise CheckError("expected exactly one <skin>, found %d" % len(skins))
    skin = skins[0]
    bsm_el = skin.find(NS + "bind_shape_matrix")
    bsm = mat(floats(bsm_el)) if bsm_el is not None else identity()
    jinputs = {i.get("semantic"): i.get("source") for i in skin.find(NS + "joints").findall(NS + "input")}
    joint_names, _ = source_array(root, jinputs["JOINT"])
    joint_src = source_by_id(root, jinputs["JOINT"])
    name_kind = "Name_array" if joint_src.find(NS + "Name_array") is not None else "IDREF_array"
    ibm_vals, _ = source_array(root, jinputs["INV_BIND_MATRIX"])
    ibms = [mat(ibm_vals[i:i + 16]) for i in range(0, len(ibm_vals), 16)]
    vw = skin.find(NS + "vertex_weights")
    vinputs = vw.findall(NS + "input")
    stride = max(int(i.get("offset")) for i in vinputs) + 1
    j_off = [int(i.get("offset")) for i in vinputs if i.get("semantic") == "JOINT"][0]
    w_off = [int(i.get("offset")) for i in vinputs if i.get("semantic") == "WEIGHT"][0]
    w_src = [i.get("source") for i in vinputs if i.get("semantic") == "WEIGHT"][0]
    weights, _ = source_array(root, w_src)
    vcount = ints(vw.find(NS + "vcount"))
    v = ints(vw.find(NS + "v"))
    infl = []
    at = 0
    for c in vcount:
        infl.append([(v[(at + k) * stride + j_off], weights[v[(at + k) * stride + w_off]]) for k in range(c)])
        at += c
    return dict(source=skin.get("source"), bsm=bsm, joints=joint_names, name_kind=name_kind,
                ibms=ibms, influences=infl, count=int(vw.get("count")))


def resolve_joints(nodes, joint_names):
    """Skin joint names refer to node sids (COLLADA 1.4 with <skeleton>); fall back to ids/names."""
    by_sid = {n["sid"]: nid for nid, n in nodes.items() if n["sid"]}
    by_name = {n["name"]: nid for nid, n in nodes.items() if n["name"]}
    out, how = [], set()
    for j in joint_names:
        if j in by_sid:
            out.append(by_sid[j]); how.add("sid")
        elif j in nodes:
            out.append(j); how.add("id")
        elif j in by_name:
            out.append(by_name[j]); how.add("name")
        else:
            out.append(None)
    return out, how


def world_matrices(nodes, order, channels, key_index):
    world = {}
    for nid in order:
        n = nodes[nid]
        local = channels[nid]["mats"][key_index] if nid in channels else n["matrix"]
        world[nid] = mul(world[n["parent"]], local) if n["parent"] else local
    return world


def lbs(points, skin, joint_nodes, world):
    mats = [mul(mul(world[jn], ibm), skin["bsm"]) for jn, ibm in zip(joint_nodes, skin["ibms"])]
    out = []
    for p, infl in zip(points, skin["influences"]):
        acc = [0.0, 0.0, 0.0]
        for j, w in infl:
            q = transform_point(mats[j], p)
            acc = [a + w * b for a, b in zip(acc, q)]
        out.append(acc)
    return out


def check_stretch(rel, spec, nodes, order, channels, joint_nodes):
    """The stretched joint's world matrix scales its own Y axis (the bone axis) up to the wanted
    factor, X and Z stay 1; the child is carried without scale (it does not inherit the stretch)."""
    sid, want, child = spec
    by_sid = {nodes[j]["sid"]: j for j in joint_nodes}
    n_keys = len(channels[by_sid[sid]]["times"])
    ys, worst_xz, worst_child = [], 0.0, 0.0
    for k in range(n_keys):
        world = world_matrices(nodes, order, channels, k)
        sx, sy, sz = column_scales(world[by_sid[sid]])
        ys.append(sy)
        worst_xz = max(worst_xz, abs(sx - 1.0), abs(sz - 1.0))
        worst_child = max(worst_child, max(abs(x - 1.0) for x in column_scales(world[by_sid[child]])))
    print("  %s: world scale along the bone per key %s; |x, z scale - 1| <= %.1e; %s's world scale "
          "|s - 1| <= %.1e" % (sid, " ".join("%.4f" % y for y in ys), worst_xz, child, worst_child))
    check(abs(max(ys) - want) < 1e-4, "%s: %s stretches to %.4f, not %g" % (rel, sid, max(ys), want))
    check(worst_xz < 1e-4, "%s: %s scales across its axis" % (rel, sid))
    check(worst_child < 1e-4, "%s: %s inherits the stretch (world scale off by %.1e)" % (rel, child, worst_child))


def check_turn(rel, spec, nodes, joint_nodes, channels):
    """A whole turn of one joint about one of its local axes, starting at rest: every step between
    consecutive keys rotates about that axis, in the positive sense, by the same angle; the other
    joints' keys are their rest matrices. Returns the angle at each key unwrapped (the sum of the
    steps), which one key matrix cannot give past 180 degrees (a matrix of 195 is one of -165)."""
    sid, axis_name, step, total = spec
    nid = [j for j in joint_nodes if nodes[j]["sid"] == sid][0]
    c = channels[nid]
    a = "XYZ".index(axis_name)
    start, _ = relative_rotation(nodes[nid]["matrix"], c["mats"][0])
    check(start < 1e-3, "%s: %s's first key is %.4f deg from its rest pose" % (rel, sid, start))
    unwrapped = [start]
    worst_step, worst_axis = 0.0, 0.0
    for k in range(1, len(c["mats"])):
        angle, axis = relative_rotation(c["mats"][k - 1], c["mats"][k])
        worst_step = max(worst_step, abs(angle - step))
        worst_axis = max(worst_axis, max(abs(axis[i]) for i in range(3) if i != a), 1.0 - axis[a])
        unwrapped.append(unwrapped[-1] + math.copysign(angle, axis[a]))
    # the angle from key 0 that each key matrix alone gives: the unwrapped angle folded into [0, 180]
    folded = [relative_rotation(c["mats"][0], m)[0] for m in c["mats"]]
    worst_fold = max(abs(f - min(u % 360.0, 360.0 - u % 360.0)) for f, u in zip(folded, unwrapped))
    print("  %s: steps of %g deg about local %s (largest deviation %.1e deg, axis off by %.1e), unwrapped "
          "angle per key %s deg; from key 0 as one matrix tells it %s"
          % (sid, step, axis_name, worst_step, worst_axis, " ".join("%.2f" % u for u in unwrapped),
             " ".join("%.1f" % f for f in folded)))
    check(worst_step < 1e-3, "%s: a step of %s is %.2e deg off %g" % (rel, sid, worst_step, step))
    check(worst_axis < 1e-4, "%s: a step of %s is not about +%s (off by %.2e)" % (rel, sid, axis_name, worst_axis))
    check(abs(unwrapped[-1] - total) < 1e-3, "%s: %s turns %.4f deg in all, not %g" % (rel, sid, unwrapped[-1], total))
    check(worst_fold < 1e-3, "%s: %s's angles from key 0 are not the unwrapped ones folded" % (rel, sid))
    for other, oc in channels.items():
        if other != nid and other in joint_nodes:
            off = max(max_abs_diff(m, nodes[other]["matrix"]) for m in oc["mats"])
            check(off < 1e-6, "%s: %s moves (%.2e from its rest matrix)" % (rel, nodes[other]["sid"], off))
    return unwrapped


def max_abs_diff(m0, m1):
    return max(abs(m0[i][j] - m1[i][j]) for i in range(4) for j in range(4))


def check_turn_volumes(rel, unwrapped, vols, vol0):
    """LBS volume at 90, 180, 270 and 360 degrees of the turn; at 360 the mesh is back at rest.
    The volumes at a and 360 - a differ a little although the points are mirror images (a key
    of 360 - a is one of -a, the rings and weights are symmetric under y -> -y): every quad's
    diagonal leans the same way around the cylinder, so the triangulated surface is not."""
    at = {round(u): v for u, v in zip(unwrapped, vols)}
    print("  LBS volume at 90/180/270/360 deg: %s m^3 (rest %.5f; %s)"
          % (" ".join("%.5f" % at[a] for a in (90, 180, 270, 360)), vol0,
             " ".join("%+.1f%%" % (100.0 * (at[a] / vol0 - 1.0)) for a in (90, 180, 270, 360))))
    worst = max(abs(at[a] - at[360 - a]) for a in at if 360 - a in at) / vol0
    print("  LBS volume at a vs 360 - a: largest difference %.1e of the rest volume (the triangles' diagonals)"
          % worst)
    check(abs(at[360] - vol0) < 1e-5 * vol0, "%s: LBS volume at 360 deg %.6f, rest %.6f" % (rel, at[360], vol0))


# ---------------------------------------------------------------- per file
def check_file(path, rel, ref_dir):
    exp = EXPECT.get(rel, {})
    size = os.path.getsize(path)
    print("\n== %s (%d bytes)%s" % (rel, size, "" if exp else "  [no specific requirements]"))
    check(size < MAX_BYTES, "%s: file size %d >= 2 MB" % (rel, size))
    root = ET.parse(path).getroot()

    # no cameras, no lights
    for tag in ("camera", "light", "instance_camera", "instance_light"):
        check(next(root.iter(NS + tag), None) is None, "%s: contains <%s>" % (rel, tag))
    up = root.find(NS + "asset/" + NS + "up_axis")
    print("  up_axis %s, unit %s" % (up.text if up is not None else "?",
                                     (root.find(NS + "asset/" + NS + "unit").attrib
                                      if root.find(NS + "asset/" + NS + "unit") is not None else "?")))

    geoms = list(root.iter(NS + "geometry"))
    check(len(geoms) == 1, "%s: %d geometries, expected 1" % (rel, len(geoms)))
    g = read_geometry(root, geoms[0])
    closed, bad_edges = closed_manifold(g["triangles"])
    vol0 = volume(g["points"], g["triangles"])
    print("  geometry %s: %d positions, %d normals, %d triangles (%s), closed: %s%s, volume %.5f m^3"
          % (g["id"], len(g["points"]), g["normals"], len(g["triangles"]), "+".join(g["kinds"]),
             closed, "" if closed else " (%d bad edges)" % bad_edges, vol0))
    if "triangles" in exp:
        lo, hi = exp["triangles"]
        check(lo <= len(g["triangles"]) <= hi, "%s: %d triangles not in [%d, %d]" % (rel, len(g["triangles"]), lo, hi))
    if exp.get("closed"):
        check(closed, "%s: mesh is not closed (%d bad edges)" % (rel, bad_edges))

    skin = read_skin(root)
    nodes, order = read_scene(root)
    joint_nodes, how = resolve_joints(nodes, skin["joints"])
    max_infl = max(len(i) for i in skin["influences"])
    hist = {}
    for i in skin["influences"]:
        hist[len(i)] = hist.get(len(i), 0) + 1
    sums = [sum(w for _, w in i) for i in skin["influences"]]
    print("  skin of %s: %d joints (%s, resolved by %s), bind_shape_matrix %s"
          % (skin["source"], len(skin["joints"]), skin["name_kind"], "/".join(sorted(how)) or "-",
             "identity" if is_identity(skin["bsm"]) else skin["bsm"]))
    print("    joints: %s" % " ".join(skin["joints"]))
    print("    influences per vertex: max %d, histogram %s; weight sums in [%.6f, %.6f]"
          % (max_infl, dict(sorted(hist.items())), min(sums), max(sums)))
    check(skin["source"].lstrip("#") == g["id"], "%s: skin source %s is not the geometry" % (rel, skin["source"]))
    check(skin["count"] == len(g["points"]), "%s: %d weighted vertices for %d positions" % (rel, skin["count"], len(g["points"])))
    check(max_infl <= 4, "%s: %d influences per vertex" % (rel, max_infl))
    check(min(hist) >= 1, "%s: a vertex has no influence" % rel)
    check(all(abs(s - 1.0) < 1e-3 for s in sums), "%s: weights do not sum to 1" % rel)
    check(None not in joint_nodes, "%s: unresolved joints %s" % (rel, [j for j, n in zip(skin["joints"], joint_nodes) if n is None]))
    check(len(skin["ibms"]) == len(skin["joints"]), "%s: %d inverse bind matrices for %d joints" % (rel, len(skin["ibms"]), len(skin["joints"])))
    if "joints" in exp:
        lo, hi = exp["joints"]
        check(lo <= len(skin["joints"]) <= hi, "%s: %d joints not in [%d, %d]" % (rel, len(skin["joints"]), lo, hi))
    joint_types = {nodes[j]["type"] for j in joint_nodes if j}
    check(joint_types == {"JOINT"}, "%s: skin joints are nodes of type %s" % (rel, joint_types))
    # the skinned mesh node and the armature node sit at the origin (the LBS check relies on it)
    inst = [nid for nid, n in nodes.items() if n["el"].find(NS + "instance_controller") is not None]
    check(len(inst) == 1, "%s: %d instance_controller nodes" % (rel, len(inst)))
    skel_roots = [nid for nid in order if nodes[nid]["type"] == "JOINT"
                  and (nodes[nid]["parent"] is None or nodes[nodes[nid]["parent"]]["type"] != "JOINT")]
    check(len(skel_roots) == 1, "%s: %d skeleton roots %s" % (rel, len(skel_roots), skel_roots))
    if inst:
        sk = nodes[inst[0]]["el"].find(NS + "instance_controller/" + NS + "skeleton")
        print("  scene: mesh node %s (parent %s), <skeleton> %s, joint root %s, node transforms as %s"
              % (inst[0], nodes[inst[0]]["parent"], sk.text if sk is not None else "-", skel_roots,
                 "<matrix>" if all(n["has_matrix_el"] for n in nodes.values()) else "decomposed"))

    clips = read_clips(root)
    ref_path = os.path.join(ref_dir, os.path.splitext(os.path.basename(rel))[0] + ".json")
    ref = None
    if os.path.exists(ref_path):
        with open(ref_path, encoding="utf-8") as fh:
            ref = json.load(fh)
        check(ref["vertex_count"] == len(g["points"]), "%s: reference has %d vertices" % (rel, ref["vertex_count"]))
        check(("clips" in ref) == (clips[0]["name"] is not None),
              "%s: the reference has %s, the file %s" % (rel, "clips" if "clips" in ref else "no clips",
                                                         "clips" if clips[0]["name"] else "none"))
    if "clips" in exp:
        check([c["name"] for c in clips] == list(exp["clips"]),
              "%s: clips %s, expected %s" % (rel, [c["name"] for c in clips], list(exp["clips"])))
    print("  %d clip(s)%s" % (len(clips), "" if clips[0]["name"] is None
                               else ": " + ", ".join(c["name"] for c in clips)))
    facts = []
    for clip in clips:
        clip_exp = exp["clips"].get(clip["name"], {}) if "clips" in exp else exp
        clip_ref = None
        if ref is not None:
            if clip["name"] is None:
                clip_ref = ref
            else:
                clip_ref = next((c for c in ref["clips"] if c["name"] == clip["name"]), None)
                check(clip_ref is not None, "%s: no reference for clip %s" % (rel, clip["name"]))
        facts.append(check_clip(rel, clip, clip_exp, clip_ref, g, skin, nodes, order, joint_nodes, vol0))
    if ref is None:
        print("  (no reference %s: LBS comparison skipped)" % ref_path)
    if None in facts:
        return

    glb = os.path.splitext(path)[0] + ".glb"
    if check(os.path.exists(glb), "%s: no .glb beside it" % rel):
        dae = dict(points=g["points"], triangles=g["triangles"], joint_names=skin["joints"], clips=facts)
        check_glb.check_glb(glb, os.path.splitext(rel)[0] + ".glb", dae, ref, check)


def check_clip(rel, clip, exp, ref, g, skin, nodes, order, joint_nodes, vol0):
    """The checks of one clip (of the whole animation, in a file without clips); exp: the clip's
    requirements, ref: its reference keys or None. Returns what check_glb needs (name, key times,
    animated joints), or None when its channels have different key times."""
    channels = clip["channels"]
    if clip["name"] is not None:
        rel = "%s clip %s" % (rel, clip["name"])
        print("  -- clip %s (%g to %g s)" % (clip["name"], clip["start"], clip["end"]))
    check(len(channels) > 0, "%s: no animation" % rel)
    for t in channels:
        check(t in nodes, "%s: channel target %s does not resolve" % (rel, t))
    joint_set = set(joint_nodes)
    non_joint = [t for t in channels if t not in joint_set]
    unanimated = [nodes[j]["sid"] for j in joint_nodes if j not in channels]
    time_sets = {tuple(c["times"]) for c in channels.values()}
    print("  animation: %d channels (%d on joints; also on %s), targets like %s, interpolation %s"
          % (len(channels), len(channels) - len(non_joint), non_joint or "-",
             next(iter(channels.values()))["target"],
             sorted({i for c in channels.values() for i in c["interp"]})))
    if unanimated:
        print("    joints without a channel: %s" % unanimated)
    for ts in sorted(time_sets):
        users = [nodes[t]["sid"] or t for t, c in channels.items() if tuple(c["times"]) == ts]
        print("    key times (%d keys) %s  <- %d channels" % (len(ts), " ".join("%g" % x for x in ts), len(users)))
    all_times = sorted({x for ts in time_sets for x in ts})
    for nid, c in channels.items():
        ts = c["times"]
        check(len(c["mats"]) == len(ts), "%s: %s has %d matrices for %d times" % (rel, nid, len(c["mats"]), len(ts)))
        check(all(b > a for a, b in zip(ts, ts[1:])), "%s: %s key times not increasing" % (rel, nid))
    if "min_keys" in exp:
        n_keys = min(len(c["times"]) for t, c in channels.items() if t in joint_set) if joint_set & set(channels) else 0
        check(n_keys >= exp["min_keys"], "%s: %d keys < %d" % (rel, n_keys, exp["min_keys"]))
    if "duration" in exp:
        d = all_times[-1] - all_times[0]
        check(exp["duration"][0] <= d <= exp["duration"][1], "%s: duration %g s" % (rel, d))
    if clip["name"] is not None:
        check(abs(clip["start"] - all_times[0]) < 1e-6 and abs(clip["end"] - all_times[-1]) < 1e-6,
              "%s: the clip runs from %g to %g s, its keys from %g to %g s"
              % (rel, clip["start"], clip["end"], all_times[0], all_times[-1]))

    # rotation steps between consecutive keys, and scales
    worst_step = (0.0, None)
    scales_seen = []
    for nid, c in channels.items():
        for k in range(1, len(c["mats"])):
            a, _ = relative_rotation(c["mats"][k - 1], c["mats"][k])
            if a > worst_step[0]:
                worst_step = (a, nodes[nid]["sid"] or nid)
        for m in c["mats"]:
            scales_seen.append((column_scales(m), nodes[nid]["sid"] or nid))
    print("    largest rotation step between consecutive keys: %.2f deg (%s)" % worst_step)
    check(worst_step[0] < 179.0, "%s: a key is %.2f deg from the previous one (ambiguous)" % (rel, worst_step[0]))
    scaled = [(s, j) for s, j in scales_seen if any(abs(x - 1.0) > 1e-3 for x in s)]
    if scaled:
        lo = [min(s[k] for s, _ in scaled) for k in range(3)]
        hi = [max(s[k] for s, _ in scaled) for k in range(3)]
        nonuni = [(s, j) for s, j in scaled if max(s) - min(s) > 1e-3]
        print("    bone scale in keys: %d keyed matrices on %s, scale x [%.3f, %.3f] y [%.3f, %.3f] z [%.3f, %.3f], "
              "%d non-uniform" % (len(scaled), sorted({j for _, j in scaled}), lo[0], hi[0], lo[1], hi[1],
                                   lo[2], hi[2], len(nonuni)))
    else:
        print("    bone scale in keys: none (all 1)")
    if exp.get("scaled"):
        check(bool(scaled), "%s: no bone scale in the animation" % rel)
    if exp.get("non_uniform"):
        check(any(max(s) - min(s) > 1e-3 for s, _ in scaled), "%s: no non-uniform bone scale" % rel)
    if exp.get("loop"):
        diff = max(abs(c["mats"][0][i][j] - c["mats"][-1][i][j])
                   for c in channels.values() for i in range(4) for j in range(4))
        print("    loop: first and last key differ by at most %.2e" % diff)
        check(diff < 1e-5, "%s: first and last key differ (%.2e), does not loop" % (rel, diff))
    if "motion" in exp:
        sid, axis_name, lo, hi = exp["motion"]
        nid = [j for j in joint_nodes if nodes[j]["sid"] == sid][0]
        c = channels[nid]
        angles = []
        for k, m in enumerate(c["mats"]):
            a, axis = relative_rotation(c["mats"][0], m)
            angles.append(a)
            if a > 1.0:
                ax = "XYZ"[max(range(3), key=lambda i: abs(axis[i]))]
                check(ax == axis_name, "%s: %s key %d rotates about %s (%s), expected %s"
                      % (rel, sid, k, ax, ["%.3f" % x for x in axis], axis_name))
        steps = [relative_rotation(c["mats"][k - 1], c["mats"][k])[0] for k in range(1, len(c["mats"]))]
        print("  %s: angle from key 0 about its local %s axis: %s deg; steps %s deg"
              % (sid, axis_name, " ".join("%.1f" % a for a in angles), " ".join("%.1f" % a for a in steps)))
        check(lo <= angles[-1] <= hi, "%s: final angle %.1f not in [%g, %g]" % (rel, angles[-1], lo, hi))
    for sid, want in exp.get("passes_through", []):
        nid = [j for j in joint_nodes if nodes[j]["sid"] == sid][0]
        c = channels[nid]
        got = [relative_rotation(c["mats"][0], m)[0] for m in c["mats"]]
        check(any(abs(a - want) < 2.0 for a in got), "%s: no key at %g deg" % (rel, want))
    if "peak" in exp:
        sid, least = exp["peak"]
        nid = [j for j in joint_nodes if nodes[j]["sid"] == sid][0]
        c = channels[nid]
        got = [relative_rotation(c["mats"][0], m)[0] for m in c["mats"]]
        peak = max(range(len(got)), key=lambda k: got[k])
        print("  %s: largest angle from key 0 %.4f deg at t=%g s" % (sid, got[peak], c["times"][peak]))
        check(got[peak] >= least, "%s: %s never turns %g deg" % (rel, sid, least))
    if "stretch" in exp:
        check_stretch(rel, exp["stretch"], nodes, order, channels, joint_nodes)
    unwrapped = check_turn(rel, exp["turn"], nodes, joint_nodes, channels) if "turn" in exp else None

    if "keyed" in exp:
        keyed = sorted(nodes[t]["sid"] for t in channels if t in joint_set)
        check(keyed == sorted(exp["keyed"]) and not non_joint,
              "%s: keys %s, expected the joints %s" % (rel, keyed + non_joint, sorted(exp["keyed"])))
    if "root_motion" in exp:
        check_root_motion(rel, exp["root_motion"], nodes, joint_nodes, channels)
    if "in_place" in exp:
        nid = [j for j in joint_nodes if nodes[j]["sid"] == exp["in_place"]][0]
        moved = max(abs(m[r][3] - nodes[nid]["matrix"][r][3]) for m in channels[nid]["mats"] for r in range(3))
        print("  %s stays in place: its translation is at most %.1e m from rest" % (exp["in_place"], moved))
        check(moved < 1e-6, "%s: %s moves %.2e m" % (rel, exp["in_place"], moved))
    if exp.get("starts_at_rest"):
        off = max(max_abs_diff(c["mats"][0], nodes[t]["matrix"]) for t, c in channels.items())
        print("  key 0 is the rest pose: largest difference of a key-0 matrix from its rest matrix %.1e" % off)
        check(off < 1e-6, "%s: key 0 is %.2e from the rest pose" % (rel, off))
    if "bends" in exp:
        check_bend(rel, exp["bends"], nodes, order, joint_nodes, channels)
    if "raised" in exp:
        sid, least = exp["raised"]
        nid = [j for j in joint_nodes if nodes[j]["sid"] == sid][0]
        heights = [world_matrices(nodes, order, channels, k)[nid][2][3] for k in range(len(channels[nid]["times"]))]
        print("  %s raised: its joint at z %.3f to %.3f m" % (sid, min(heights), max(heights)))
        check(min(heights) > least, "%s: %s is at z %.3f, below %g" % (rel, sid, min(heights), least))

    # linear blend skinning from the file alone, against Blender's own deformation
    keyed = [t for t in channels if t in joint_set]
    base_times = channels[keyed[0]]["times"] if keyed else []
    same_times = all(channels[t]["times"] == base_times for t in channels)
    if not same_times:
        print("  (channels have different key times: LBS check skipped)")
        return None
    if ref is not None:
        check(len(ref["keys"]) == len(base_times), "%s: reference has %d keys for %d key times" % (rel, len(ref["keys"]), len(base_times)))
    vols = []
    worst = 0.0
    for k, t in enumerate(base_times):
        world = world_matrices(nodes, order, channels, k)
        pts = lbs(g["points"], skin, joint_nodes, world)
        vols.append(volume(pts, g["triangles"]))
        if ref is not None and k < len(ref["keys"]):
            rk = ref["keys"][k]
            check(abs(rk["time"] - t) < 1e-4, "%s: reference key %d at %g s, file at %g s" % (rel, k, rk["time"], t))
            for i, p in rk["vertices"].items():
                worst = max(worst, max(abs(a - b) for a, b in zip(pts[int(i)], p)))
            lo = [min(p[a] for p in pts) for a in range(3)]
            hi = [max(p[a] for p in pts) for a in range(3)]
            worst = max(worst, max(abs(a - b) for a, b in zip(lo + hi, rk["bbox_min"] + rk["bbox_max"])))
    print("  LBS volume per key (m^3, rest %.5f): %s" % (vol0, " ".join("%.5f" % v for v in vols)))
    if unwrapped is not None and len(unwrapped) == len(vols):
        check_turn_volumes(rel, unwrapped, vols, vol0)
    if ref is not None:
        print("  LBS from the file vs Blender's deformation: max deviation %.2e m" % worst)
        check(worst < 1e-4, "%s: LBS from the file deviates %.2e m from Blender's deformation" % (rel, worst))
    return dict(name=clip["name"], times=base_times,
                joints=sorted(nodes[t]["sid"] for t in channels if t in joint_set))


def check_root_motion(rel, spec, nodes, joint_nodes, channels):
    """A loop that travels: the root joint's translation moves by `delta` (armature axes) from the
    first key to the last at constant velocity (every key on the straight line, in proportion to
    its time), up and down aside (a bob along z is allowed); every other value of the last key is
    the first key's, so that the clip repeats from where it ends."""
    sid, delta = spec
    nid = [j for j in joint_nodes if nodes[j]["sid"] == sid][0]
    c = channels[nid]
    t0, t1 = c["times"][0], c["times"][-1]
    first = [c["mats"][0][r][3] for r in range(3)]
    line = 0.0
    for t, m in zip(c["times"], c["mats"]):
        u = (t - t0) / (t1 - t0)
        line = max(line, max(abs(m[r][3] - first[r] - u * delta[r]) for r in range(2)))
    moved = [c["mats"][-1][r][3] - first[r] for r in range(3)]
    rest = 0.0
    for t, ch in channels.items():
        for i in range(4):
            for j in range(4):
                if not (t == nid and j == 3 and i < 3):
                    rest = max(rest, abs(ch["mats"][0][i][j] - ch["mats"][-1][i][j]))
    print("  root motion: %s moves (%.4f, %.4f, %.4f) m in %g s (%.3f m/s); keys off the line by at most "
          "%.1e m; the last key's other values are the first's to %.1e"
          % (sid, moved[0], moved[1], moved[2], t1 - t0, math.hypot(moved[0], moved[1]) / (t1 - t0), line, rest))
    check(max(abs(a - b) for a, b in zip(moved, delta)) < 1e-5,
          "%s: %s moves %s per loop, expected %s" % (rel, sid, moved, delta))
    check(line < 1e-5, "%s: %s does not move at constant velocity (%.2e m off)" % (rel, sid, line))
    check(rest < 1e-5, "%s: the last key differs from the first by %.2e beyond the root's travel" % (rel, rest))


def check_bend(rel, spec, nodes, order, joint_nodes, channels):
    """A joint's world rotation relative to its rest turns by `degrees` about a world axis by time
    `at` and holds there to the end."""
    sid, at, degrees, axis_name = spec
    nid = [j for j in joint_nodes if nodes[j]["sid"] == sid][0]
    rest = world_matrices(nodes, order, {}, 0)[nid]
    a = "XYZ".index(axis_name)
    angles, worst_axis = [], 0.0
    times = next(iter(channels.values()))["times"]
    for k, t in enumerate(times):
        m = world_matrices(nodes, order, channels, k)[nid]
        rel_rot = [[sum(m[r][i] * rest[r2][i] for i in range(3)) for r2 in range(3)] for r in range(3)]  # m R^T
        c = max(-1.0, min(1.0, (rel_rot[0][0] + rel_rot[1][1] + rel_rot[2][2] - 1.0) / 2.0))
        axis = [rel_rot[2][1] - rel_rot[1][2], rel_rot[0][2] - rel_rot[2][0], rel_rot[1][0] - rel_rot[0][1]]
        n = math.sqrt(sum(x * x for x in axis))
        angles.append(math.degrees(math.acos(c)))
        if n > 1e-6:
            worst_axis = max(worst_axis, 1.0 - abs(axis[a]) / n)
    held = [x for t, x in zip(times, angles) if t >= at - 1e-9]
    print("  %s bends about world %s: %s deg (axis off by %.1e)" % (sid, axis_name, " ".join("%.2f" % x for x in angles), worst_axis))
    check(all(abs(x - degrees) < 0.01 for x in held), "%s: %s is at %s deg from %g s, not %g" % (rel, sid, held, at, degrees))
    check(worst_axis < 1e-4, "%s: %s bends about another axis (%.1e)" % (rel, sid, worst_axis))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    assets = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.dirname(here)
    ref_dir = os.path.join(assets, "reference")
    found = []
    for dirpath, dirnames, filenames in os.walk(assets):
        dirnames.sort()
        for f in sorted(filenames):
            if f.lower().endswith(".dae"):
                found.append(os.path.relpath(os.path.join(dirpath, f), assets).replace(os.sep, "/"))
    for rel in EXPECT:
        check(rel in found, "%s is missing" % rel)
    for rel in found:
        try:
            check_file(os.path.join(assets, rel), rel, ref_dir)
        except (CheckError, ET.ParseError, KeyError, IndexError, ValueError) as e:
            check(False, "%s: %s: %s" % (rel, type(e).__name__, e))
    print()
    if FAILURES:
        print("%d check(s) FAILED" % len(FAILURES))
        for f in FAILURES:
            print("  - " + f)
        return 1
    print("all checks passed (%d files)" % len(found))
    return 0


if __name__ == "__main__":
    sys.exit(main())
