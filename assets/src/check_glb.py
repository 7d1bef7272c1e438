"""The .glb half of check_assets.py (plain Python 3, standard library only, no Blender).

For each asset's .glb (written beside its .dae by common.export_glb) it reads the binary glTF
itself and asserts that it holds the same scene as the .dae: no extension (so no Draco), one mesh,
one skin with the .dae's joints, one animation per clip of the .dae (one in all for a .dae without
clips; with clips, in the same order and with the same names), each animating the joints its clip
animates, every channel LINEAR with exactly the clip's key times, at most 4 influences summing to
1, every glTF vertex at the place of one .dae position. Then it skins the glTF mesh itself with
linear blend skinning at every key of every animation (joints without a channel at rest),
  v' = sum_i w_i * World(joint_i, t) * inverseBindMatrix_i * v   (the mesh node's transform ignored),
turns the result from glTF's Y-up back to Blender's Z-up ((x, y, z) -> (x, -z, y)) and matches it
with Blender's own deformation in assets/reference/<name>.json (bounding box and sample vertices).
"""
import json
import math
import struct

GLB_MAGIC = 0x46546C67
CHUNK_JSON = 0x4E4F534A
CHUNK_BIN = 0x004E4942
COMPONENTS = {5120: "b", 5121: "B", 5122: "h", 5123: "H", 5125: "I", 5126: "f"}
WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def read_glb(path):
    with open(path, "rb") as fh:
        data = fh.read()
    magic, version, length = struct.unpack_from("<III", data, 0)
    if magic != GLB_MAGIC or version != 2 or length != len(data):
        raise ValueError("not a glTF 2.0 binary (magic %08x, version %d, length %d of %d)"
                         % (magic, version, length, len(data)))
    json_len, json_type = struct.unpack_from("<II", data, 12)
    if json_type != CHUNK_JSON:
        raise ValueError("first chunk is not JSON")
    doc = json.loads(data[20:20 + json_len].decode("utf-8"))
    offset = 20 + json_len
    bin_len, bin_type = struct.unpack_from("<II", data, offset)
    if bin_type != CHUNK_BIN:
        raise ValueError("second chunk is not BIN")
    return doc, data[offset + 8:offset + 8 + bin_len]


def accessor(doc, binary, index):
    """The accessor's elements as tuples (no sparse accessors: Blender writes none here)."""
    acc = doc["accessors"][index]
    if "sparse" in acc:
        raise ValueError("accessor %d is sparse" % index)
    view = doc["bufferViews"][acc["bufferView"]]
    fmt = COMPONENTS[acc["componentType"]]
    n = WIDTH[acc["type"]]
    size = struct.calcsize("<" + fmt)
    stride = view.get("byteStride", size * n)
    base = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    return [struct.unpack_from("<%d%s" % (n, fmt), binary, base + i * stride) for i in range(acc["count"])]


def trs_matrix(t, r, s):
    """4x4 row-major matrix T * R * S (column vectors), r = quaternion (x, y, z, w)."""
    x, y, z, w = r
    rot = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
           [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
           [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[rot[i][0] * s[0], rot[i][1] * s[1], rot[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def column_major(m16):
    return [[m16[c * 4 + r] for c in range(4)] for r in range(4)]


def node_trs(node):
    if "matrix" in node:
        raise ValueError("node %s has a matrix, not TRS" % node.get("name"))
    return (list(node.get("translation", (0, 0, 0))), list(node.get("rotation", (0, 0, 0, 1))),
            list(node.get("scale", (1, 1, 1))))


def world_matrices(doc, pose):
    """World matrix of every node, pose[node] = (t, r, s)."""
    parent = {}
    for i, n in enumerate(doc["nodes"]):
        for c in n.get("children", ()):
            parent[c] = i
    world = {}

    def of(i):
        if i not in world:
            local = trs_matrix(*pose[i])
            world[i] = mul(of(parent[i]), local) if i in parent else local
        return world[i]

    for i in range(len(doc["nodes"])):
        of(i)
    return world


def transform(m, p):
    return [m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3)]


def check_glb(path, rel, dae, ref, check):
    """dae: facts from the .dae (points, triangles as position indices, joint_names, and per clip
    its name (None in a file without clips), key times and animated joints); ref: the reference JSON
    or None; check(cond, message) records a failure."""
    doc, binary = read_glb(path)
    print("  glb: %s, generator %s" % (rel, doc["asset"].get("generator")))
    check(not doc.get("extensionsUsed") and not doc.get("extensionsRequired"),
          "%s: uses extensions %s" % (rel, doc.get("extensionsUsed")))
    check(len(doc.get("meshes", ())) == 1 and len(doc.get("skins", ())) == 1
          and len(doc.get("animations", ())) == len(dae["clips"]),
          "%s: expected one mesh, one skin, %d animation(s)" % (rel, len(dae["clips"])))
    check(not doc.get("cameras"), "%s: has cameras" % rel)
    skin = doc["skins"][0]
    joints = skin["joints"]
    names = [doc["nodes"][j]["name"] for j in joints]
    check(sorted(names) == sorted(dae["joint_names"]), "%s: joints %s, the .dae has %s" % (rel, names, dae["joint_names"]))
    ibm = [column_major(m) for m in accessor(doc, binary, skin["inverseBindMatrices"])]

    prims = doc["meshes"][0]["primitives"]
    points, joint_sets, weight_sets = [], [], []
    for p in prims:
        a = p["attributes"]
        check(p.get("mode", 4) == 4, "%s: primitive mode %s, expected triangles" % (rel, p.get("mode")))
        check("JOINTS_1" not in a, "%s: more than one JOINTS set" % rel)
        points += accessor(doc, binary, a["POSITION"])
        joint_sets += accessor(doc, binary, a["JOINTS_0"])
        weight_sets += accessor(doc, binary, a["WEIGHTS_0"])
    worst_sum = max(abs(sum(w) - 1) for w in weight_sets)
    most = max(sum(1 for x in w if x > 0) for w in weight_sets)
    check(worst_sum < 1e-3, "%s: weights sum to 1 +- %.2g" % (rel, worst_sum))
    check(most <= 4, "%s: %d influences" % (rel, most))

    # every glTF vertex (Y-up) lies on one .dae position (Z-up)
    up = [(x, -z, y) for x, y, z in points]
    index = {}
    for i, q in enumerate(dae["points"]):
        index.setdefault(tuple(round(c, 4) for c in q), []).append(i)
    source = []
    for q in up:
        near = [i for i in index.get(tuple(round(c, 4) for c in q), ())
                if max(abs(a - b) for a, b in zip(dae["points"][i], q)) < 1e-5]
        source.append(near[0] if near else None)
    unmatched = sum(1 for s in source if s is None)
    check(unmatched == 0, "%s: %d glTF vertices are at no .dae position" % (rel, unmatched))
    triangles = []
    base = 0
    for p in prims:
        count = doc["accessors"][p["attributes"]["POSITION"]]["count"]
        idx = [i[0] for i in accessor(doc, binary, p["indices"])]
        triangles += [tuple(sorted(source[base + v] for v in idx[t:t + 3])) for t in range(0, len(idx), 3)]
        base += count
    dae_triangles = set(tuple(sorted(t)) for t in dae["triangles"])
    same = sum(1 for t in triangles if t in dae_triangles)
    check(same == len(triangles) == len(dae_triangles),
          "%s: %d of its %d triangles are among the .dae's %d (CoR integrates over the triangles: they must be the same)"
          % (rel, same, len(triangles), len(dae_triangles)))
    print("  glb: %d vertices in %d primitive(s) (%d distinct .dae positions), %d joints, max %d influences"
          % (len(points), len(prims), len(set(s for s in source if s is not None)), len(joints), most))

    rest = {i: node_trs(n) for i, n in enumerate(doc["nodes"])}
    worst = 0.0
    for anim, clip in zip(doc["animations"], dae["clips"]):
        label = rel if clip["name"] is None else "%s animation %s" % (rel, clip["name"])
        if clip["name"] is not None:
            check(anim.get("name") == clip["name"], "%s: animation %r where the .dae has clip %r"
                  % (rel, anim.get("name"), clip["name"]))
        tracks = []
        for ch in anim["channels"]:
            sampler = anim["samplers"][ch["sampler"]]
            check(sampler.get("interpolation", "LINEAR") == "LINEAR", "%s: %s interpolation" % (label, sampler.get("interpolation")))
            times = [t[0] for t in accessor(doc, binary, sampler["input"])]
            check(len(times) == len(clip["times"]) and all(abs(a - b) < 1e-6 for a, b in zip(times, clip["times"])),
                  "%s: channel on %s keyed at %s, the .dae at %s" % (label, doc["nodes"][ch["target"]["node"]]["name"], times, clip["times"]))
            tracks.append((ch["target"]["node"], ch["target"]["path"], accessor(doc, binary, sampler["output"])))
        animated = sorted({doc["nodes"][node]["name"] for node, _, _ in tracks})
        check(animated == clip["joints"], "%s: animates %s, the .dae %s" % (label, animated, clip["joints"]))
        print("  glb: animation %r, %d channels on %d joints, %d keys each"
              % (anim.get("name"), len(tracks), len(animated), len(clip["times"])))
        keys = None
        if ref is not None:
            keys = ref["keys"] if clip["name"] is None else next(
                (c["keys"] for c in ref["clips"] if c["name"] == clip["name"]), None)
        pose = dict(rest)
        slot = {"translation": 0, "rotation": 1, "scale": 2}
        for k in range(len(clip["times"])):
            for node, what, values in tracks:
                pose[node] = tuple(list(values[k]) if j == slot[what] else pose[node][j] for j in range(3))
            world = world_matrices(doc, pose)
            skinning = [mul(world[j], ibm[n]) for n, j in enumerate(joints)]
            posed = []
            for p, js, ws in zip(points, joint_sets, weight_sets):
                acc = [0.0, 0.0, 0.0]
                for j, w in zip(js, ws):
                    if w > 0:
                        q = transform(skinning[j], p)
                        acc = [a + w * b for a, b in zip(acc, q)]
                posed.append((acc[0], -acc[2], acc[1]))
            if keys is not None:
                rk = keys[k]
                lo = [min(p[a] for p in posed) for a in range(3)]
                hi = [max(p[a] for p in posed) for a in range(3)]
                worst = max(worst, max(abs(a - b) for a, b in zip(lo + hi, rk["bbox_min"] + rk["bbox_max"])))
                for v, s in enumerate(source):
                    if s is not None and str(s) in rk["vertices"]:
                        worst = max(worst, max(abs(a - b) for a, b in zip(posed[v], rk["vertices"][str(s)])))
    if ref is not None:
        print("  LBS from the .glb vs Blender's deformation: max deviation %.2e m" % worst)
        check(worst < 1e-4, "%s: LBS from the .glb deviates %.2e m from Blender's deformation" % (rel, worst))
    if math.isnan(worst):
        check(False, "%s: NaN in the skinned .glb" % rel)
