#!/usr/bin/env python3
"""Writes the synthetic glTF 2.0 fixtures of core/src/test/resources/gltf/ and validates them.

Each file is a small skinned "column" (rings of four vertices along +Y, weighted between joints)
that exercises what a skinned character can use, one group of features per file:

  skin-component-types.gltf   every accessor component type: indices u8/u16/u32, JOINTS_0 u8/u16,
                              WEIGHTS_0 float / normalized u8 / normalized u16, TEXCOORD_0 float /
                              normalized u8 / normalized u16, COLOR_0 normalized u8 RGBA and
                              u16 RGB; rotation keys as normalized i16 and i8 (three primitives,
                              one mesh)
  skin-interleaved.glb        GLB; one interleaved bufferView (byteStride 52) for POSITION, NORMAL,
                              TEXCOORD_0, JOINTS_0, WEIGHTS_0; TEXCOORD_1 and COLOR_0 (float RGB);
                              two primitives (materials) sharing those attributes;
                              the skinned node has its own TRS and a transformed parent (both
                              ignored, as the specification says), the joints lie outside the
                              skinned node's subtree, skin.skeleton set
  skin-sparse.gltf            sparse accessors: POSITION (sparse over a bufferView, u8 indices), a
                              morph target with no bufferView (zeros + sparse, u16 indices), an
                              animation output (sparse, u32 indices)
  skin-quantized.glb          KHR_mesh_quantization: POSITION i16, NORMAL normalized i8,
                              TEXCOORD_0 normalized u16, morph target POSITION i16 (its weight
                              animated in a second clip); the dequantization lives in the inverse
                              bind matrices
  skin-strip-fan.gltf         TRIANGLE_STRIP (indexed), TRIANGLE_FAN (not indexed), TRIANGLES (not
                              indexed)
  skin-eight-influences.gltf  JOINTS_0/JOINTS_1 and WEIGHTS_0/WEIGHTS_1: eight joints per vertex
  skin-no-ibm.gltf            a skin without inverseBindMatrices (identity): joints at the origin
  anim-interpolation.gltf     LINEAR, STEP and CUBICSPLINE on translation, rotation and scale (every
                              pair once), uneven key times, keys starting after 0; two animations
                              (clips) with different permutations
  morph-skin.gltf             morph targets (POSITION and NORMAL) on a skinned mesh with default
                              mesh weights, a node that overrides them, and a clip that animates
                              the weights (LINEAR) beside the joints, and one with CUBICSPLINE
                              and STEP weights
  materials.glb               GLB with PNG images in buffer views: unit quads facing +Z in a grid,
                              one material feature each (the viewer's pixel tests look at them):
                              a four-colour texture, the same with KHR_texture_transform, a MASK
                              cutout, a BLEND quad in front of an opaque one (listed first), an
                              emissive quad, KHR_materials_unlit, single- and double-sided quads
                              facing -Z, vertex colours
  skin-textured.glb           a skinned, textured strip (the four-colour picture of materials.glb,
                              embedded): 1 x 2 facing +Z, its upper half on a joint at y = 1 whose
                              clip moves it 0.5 along +X by t = 1 (the phone's and the viewer's
                              textured-and-skinned check)
  scaled-parts.gltf           a character of many parts as FBX and Sketchfab exports make them: a
                              Z-up root turned Y-up, an armature scaled by 0.01 (centimetres),
                              joints hips, spine, head; skinned parts under nodes with their own
                              scales, each skin's inverse bind matrices taken against its mesh
                              node (so the rest pose places a part by that node): a closed body
                              column (uniform scale 2), a helmet (non-uniform scale, turned) and
                              the same helmet mesh again under a mirroring node with a skin of its
                              own, an open cloak, a boot cut into two meshes by material (each
                              open, closed together), and a static crate; a clip that scales the
                              spine by 1.25 at t = 1 and twists it by 170 degrees at t = 2, at
                              rest at t = 0 and 3

Run from the repository root (Python 3 standard library; the validation needs Node and
`npm ci` in bench/threejs):

    python3 tools/gltf/make-fixtures.py                 # write and validate
    python3 tools/gltf/make-fixtures.py --no-validate   # write only
    python3 tools/gltf/make-fixtures.py --check         # are the committed files what it writes? (CI)

The output is deterministic: two runs write identical bytes. The validator (npm gltf-validator,
pinned in bench/threejs/package.json) must report zero errors for every file, or the script fails.
"""

import base64
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OUT = os.path.join(ROOT, "core", "src", "test", "resources", "gltf")

BYTE, UBYTE, SHORT, USHORT, UINT, FLOAT = 5120, 5121, 5122, 5123, 5125, 5126
FORMAT = {BYTE: "b", UBYTE: "B", SHORT: "h", USHORT: "H", UINT: "I", FLOAT: "f"}
SIZE = {BYTE: 1, UBYTE: 1, SHORT: 2, USHORT: 2, UINT: 4, FLOAT: 4}
NORM_MAX = {BYTE: 127, UBYTE: 255, SHORT: 32767, USHORT: 65535}
WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


# ---------------------------------------------------------------------------------------------
# Small linear algebra (4x4 matrices as row-major lists of rows)

def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def mat_inverse(m):
    a = [row[:] + [1.0 if i == j else 0.0 for j in range(4)] for i, row in enumerate(m)]
    for c in range(4):
        p = max(range(c, 4), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        d = a[c][c]
        a[c] = [x / d for x in a[c]]
        for r in range(4):
            if r != c and a[r][c] != 0.0:
                f = a[r][c]
                a[r] = [x - f * y for x, y in zip(a[r], a[c])]
    return [row[4:] for row in a]


def trs_matrix(t=(0, 0, 0), r=(0, 0, 0, 1), s=(1, 1, 1)):
    x, y, z, w = r
    rot = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
           [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
           [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[rot[i][0] * s[0], rot[i][1] * s[1], rot[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def column_major(m):
    return [m[r][c] for c in range(4) for r in range(4)]


def quat_axis_angle(axis, degrees):
    n = math.sqrt(sum(a * a for a in axis))
    h = math.radians(degrees) / 2
    return tuple(a / n * math.sin(h) for a in axis) + (math.cos(h),)


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


# ---------------------------------------------------------------------------------------------
# Document builder

class Doc:
    """One glTF document: JSON plus one binary buffer (data URI for .gltf, BIN chunk for .glb)."""

    def __init__(self, name):
        self.name = name
        self.bin = bytearray()
        self.json = {"asset": {"version": "2.0", "generator": "skinlab tools/gltf/make-fixtures.py"},
                     "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "skins": [],
                     "animations": [], "accessors": [], "bufferViews": [], "buffers": []}

    def node(self, **props):
        self.json["nodes"].append({k: v for k, v in props.items() if v is not None})
        return len(self.json["nodes"]) - 1

    def view(self, data, stride=None, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        v = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            v["byteStride"] = stride
        if target:
            v["target"] = target
        self.bin += data
        self.json["bufferViews"].append(v)
        return len(self.json["bufferViews"]) - 1

    def accessor(self, rows, ctype, atype, normalized=False, target=None, minmax=False, view=None,
                 offset=0, sparse=None, no_view=False, vertex=True):
        """rows: list of tuples (or numbers for SCALAR) in real values; normalized integers are
        quantized here. Writes its own view unless view is given (then the bytes must already be
        there): tightly packed, except vertex attributes whose elements are not a multiple of 4
        bytes, which the specification requires padded (the view then has that byteStride)."""
        rows = [r if isinstance(r, (tuple, list)) else (r,) for r in rows]
        width = WIDTH[atype]
        encoded = [tuple(encode(v, ctype, normalized) for v in r) for r in rows]
        if view is None and not no_view:
            pad = vertex and atype not in ("SCALAR", "MAT4")
            data = pack_rows(encoded, ctype, atype, pad)
            stride = stride_of(ctype, atype) if pad and stride_of(ctype, atype) != SIZE[ctype] * WIDTH[atype] else None
            view = self.view(data, stride=stride, target=target)
        acc = {"componentType": ctype, "count": len(rows), "type": atype}
        if view is not None:
            acc["bufferView"] = view
            if offset:
                acc["byteOffset"] = offset
        if normalized:
            acc["normalized"] = True
        if sparse is not None:
            encoded = self.add_sparse(acc, encoded, sparse, ctype, atype, normalized)
        if minmax:
            values = encoded  # raw values: integers for integer types, normalized or not
            acc["min"] = [min(r[i] for r in values) for i in range(width)]
            acc["max"] = [max(r[i] for r in values) for i in range(width)]
            if ctype != FLOAT:
                acc["min"] = [int(x) for x in acc["min"]]
                acc["max"] = [int(x) for x in acc["max"]]
        self.json["accessors"].append(acc)
        return len(self.json["accessors"]) - 1

    def add_sparse(self, acc, encoded, sparse, ctype, atype, normalized):
        """sparse: (index component type, {row: real values}). Returns the rows as read."""
        index_type, changes = sparse
        indices = sorted(changes)
        values = [tuple(encode(v, ctype, normalized) for v in changes[i]) for i in indices]
        iv = self.view(struct.pack("<%d%s" % (len(indices), FORMAT[index_type]), *indices))
        vv = self.view(pack_rows(values, ctype, atype, False))
        acc["sparse"] = {"count": len(indices), "indices": {"bufferView": iv, "componentType": index_type},
                         "values": {"bufferView": vv}}
        out = list(encoded)
        for i, v in zip(indices, values):
            out[i] = v
        return out

    def finish(self):
        j = self.json
        for key in ["skins", "animations"]:
            if not j[key]:
                del j[key]
        while len(self.bin) % 4:
            self.bin.append(0)
        j["buffers"] = [{"byteLength": len(self.bin)}]
        return j


def encode(v, ctype, normalized):
    if ctype == FLOAT:
        return f32(v)
    if normalized:
        m = NORM_MAX[ctype]
        return int(round(max(-1.0, min(1.0, v)) * m)) if ctype in (BYTE, SHORT) else int(round(v * m))
    return int(v)


def pack_rows(rows, ctype, atype, pad):
    """Packs rows, each padded to a multiple of 4 bytes when pad (vertex attributes)."""
    fmt = "<" + FORMAT[ctype] * WIDTH[atype]
    size = struct.calcsize(fmt)
    pad = (-size) % 4 if pad else 0
    return b"".join(struct.pack(fmt, *r) + b"\0" * pad for r in rows)


def stride_of(ctype, atype):
    size = SIZE[ctype] * WIDTH[atype]
    return size + ((-size) % 4 if atype != "SCALAR" else 0)


def write(doc, glb=False):
    j = doc.finish()
    path = os.path.join(OUT, doc.name)
    if glb:
        body = json.dumps(j, separators=(",", ":")).encode()
        body += b" " * ((-len(body)) % 4)
        chunks = struct.pack("<II", len(body), 0x4E4F534A) + body
        chunks += struct.pack("<II", len(doc.bin), 0x004E4942) + bytes(doc.bin)
        data = struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks
        with open(path, "wb") as f:
            f.write(data)
    else:
        j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bytes(doc.bin)).decode()
        with open(path, "w", encoding="utf-8", newline="\n") as f:
            json.dump(j, f, indent=1, sort_keys=False)
            f.write("\n")
    return path


# ---------------------------------------------------------------------------------------------
# The column: rings of 4 vertices along +Y from 0 to height, weighted from joint to joint

def column(rings=5, height=2.0, half=0.25, x=0.0):
    pos, nrm, uv = [], [], []
    corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    for r in range(rings):
        y = height * r / (rings - 1)
        for cx, cz in corners:
            pos.append((x + cx * half, y, cz * half))
            n = math.sqrt(2) / 2
            nrm.append((cx * n, 0.0, cz * n))
            uv.append(((corners.index((cx, cz))) / 4.0, r / (rings - 1)))
    tris = []
    for r in range(rings - 1):
        for c in range(4):
            a, b = 4 * r + c, 4 * r + (c + 1) % 4
            tris += [a, b, b + 4, a, b + 4, a + 4]
    return pos, nrm, uv, tris


def blend_weights(pos, joint_heights):
    """Per vertex: the two joints whose heights bracket it, weights linear in between."""
    joints, weights = [], []
    for p in pos:
        y = p[1]
        k = 0
        while k + 1 < len(joint_heights) and joint_heights[k + 1] <= y:
            k += 1
        if k + 1 < len(joint_heights):
            t = (y - joint_heights[k]) / (joint_heights[k + 1] - joint_heights[k])
            t = max(0.0, min(1.0, t))
            if t == 0.0 or t == 1.0:
                joints.append((k + int(t), 0, 0, 0))
                weights.append((1.0, 0.0, 0.0, 0.0))
            else:
                joints.append((k, k + 1, 0, 0))
                weights.append((1 - t, t, 0.0, 0.0))
        else:
            joints.append((k, 0, 0, 0))
            weights.append((1.0, 0.0, 0.0, 0.0))
    return joints, weights


def quantized_weights(weights, ctype):
    """Normalized integer weights that sum exactly to the type's maximum (the validator's rule)."""
    m = NORM_MAX[ctype]
    out = []
    for w in weights:
        q = [int(round(x * m)) for x in w]
        q[q.index(max(q))] += m - sum(q)
        out.append(tuple(x / m for x in q))
    return out


def chain(doc, heights, parent=None, names="joint"):
    """A chain of joints at the given heights (each a child of the previous one)."""
    nodes = []
    prev_h = 0.0
    for i, h in enumerate(heights):
        n = doc.node(name="%s%d" % (names, i), translation=[0.0, h - prev_h, 0.0])
        if nodes:
            doc.json["nodes"][nodes[-1]].setdefault("children", []).append(n)
        nodes.append(n)
        prev_h = h
    if parent is not None:
        doc.json["nodes"][parent].setdefault("children", []).append(nodes[0])
    return nodes


def world_of(doc, node, parents):
    m = local_of(doc.json["nodes"][node])
    p = parents.get(node)
    return m if p is None else mat_mul(world_of(doc, p, parents), m)


def local_of(n):
    if "matrix" in n:
        c = n["matrix"]
        return [[c[col * 4 + row] for col in range(4)] for row in range(4)]
    return trs_matrix(n.get("translation", (0, 0, 0)), n.get("rotation", (0, 0, 0, 1)), n.get("scale", (1, 1, 1)))


def parent_map(doc):
    parents = {}
    for i, n in enumerate(doc.json["nodes"]):
        for c in n.get("children", []):
            parents[c] = i
    return parents


def skin(doc, joints, skeleton=None, with_ibm=True, extra=None):
    """A skin over the joints; inverse bind matrices from their rest world matrices (times extra,
    a matrix applied to the mesh's positions first, e.g. dequantization)."""
    s = {"joints": joints}
    if skeleton is not None:
        s["skeleton"] = skeleton
    if with_ibm:
        parents = parent_map(doc)
        mats = []
        for j in joints:
            ibm = mat_inverse(world_of(doc, j, parents))
            if extra is not None:
                ibm = mat_mul(ibm, extra)
            mats.append(tuple(column_major(ibm)))
        s["inverseBindMatrices"] = doc.accessor(mats, FLOAT, "MAT4", vertex=False)
    doc.json["skins"].append(s)
    return len(doc.json["skins"]) - 1


def channel(doc, anim, node, path, times, values, interpolation="LINEAR", ctype=FLOAT, normalized=False,
            sparse=None):
    """values: one tuple per key (for CUBICSPLINE: (in, value, out) triples flattened by key)."""
    atype = {"translation": "VEC3", "rotation": "VEC4", "scale": "VEC3", "weights": "SCALAR"}[path]
    inp = doc.accessor(times, FLOAT, "SCALAR", minmax=True)
    out = doc.accessor(values, ctype, atype, normalized=normalized, sparse=sparse, vertex=False)
    anim["samplers"].append({"input": inp, "output": out, "interpolation": interpolation})
    anim["channels"].append({"sampler": len(anim["samplers"]) - 1, "target": {"node": node, "path": path}})


def animation(doc, name):
    a = {"name": name, "channels": [], "samplers": []}
    doc.json["animations"].append(a)
    return a


def bend(degrees_list, axis=(0, 0, 1)):
    return [quat_axis_angle(axis, d) for d in degrees_list]


def mesh_of(doc, primitives, weights=None, name=None):
    m = {"primitives": primitives}
    if weights is not None:
        m["weights"] = weights
    if name:
        m["name"] = name
    doc.json["meshes"].append(m)
    return len(doc.json["meshes"]) - 1


# ---------------------------------------------------------------------------------------------
# The fixtures

def skin_component_types():
    doc = Doc("skin-component-types.gltf")
    heights = [0.0, 1.0, 1.6]
    root = doc.node(name="root")
    joints = chain(doc, heights, parent=root)
    prims = []
    variants = [
        (UBYTE, UBYTE, (FLOAT, False), (FLOAT, False), None),
        (USHORT, USHORT, (UBYTE, True), (UBYTE, True), ((UBYTE, True), "VEC4")),
        (UINT, UBYTE, (USHORT, True), (USHORT, True), ((USHORT, True), "VEC3")),
    ]
    for k, (itype, jtype, (wtype, wnorm), (ttype, tnorm), color) in enumerate(variants):
        pos, nrm, uv, tris = column(x=1.0 * (k - 1))
        jts, wts = blend_weights(pos, heights)
        if wnorm:
            wts = quantized_weights(wts, wtype)
        attrs = {"POSITION": doc.accessor(pos, FLOAT, "VEC3", minmax=True, target=ARRAY_BUFFER),
                 "NORMAL": doc.accessor(nrm, FLOAT, "VEC3", target=ARRAY_BUFFER),
                 "TEXCOORD_0": doc.accessor(uv, ttype, "VEC2", normalized=tnorm, target=ARRAY_BUFFER),
                 "JOINTS_0": doc.accessor(jts, jtype, "VEC4", target=ARRAY_BUFFER),
                 "WEIGHTS_0": doc.accessor(wts, wtype, "VEC4", normalized=wnorm, target=ARRAY_BUFFER)}
        if color:
            (ctype, cnorm), atype = color
            rgba = [(p[1] / 2.0, 0.5, 1.0 - p[1] / 2.0, 1.0)[:WIDTH[atype]] for p in pos]
            attrs["COLOR_0"] = doc.accessor(rgba, ctype, atype, normalized=cnorm, target=ARRAY_BUFFER)
        prims.append({"attributes": attrs,
                      "indices": doc.accessor(tris, itype, "SCALAR", target=ELEMENT_ARRAY_BUFFER)})
    mesh = mesh_of(doc, prims, name="three columns")
    body = doc.node(name="body", mesh=mesh, skin=0)
    doc.json["scenes"][0]["nodes"] = [root, body]
    skin(doc, joints)
    a = animation(doc, "bend")
    channel(doc, a, joints[1], "rotation", [0.0, 0.5, 1.0, 1.5], bend([0, 40, -25, 10]),
            ctype=SHORT, normalized=True)
    channel(doc, a, joints[2], "rotation", [0.0, 0.75, 1.5], bend([0, 30, -30], axis=(1, 0, 0)),
            ctype=BYTE, normalized=True)
    channel(doc, a, joints[0], "translation", [0.0, 1.5], [(0, 0, 0), (0.2, 0.1, 0)])
    return write(doc)


def skin_interleaved():
    doc = Doc("skin-interleaved.glb")
    heights = [0.0, 0.8, 1.5]
    rig = doc.node(name="rig", translation=[0.5, 0.0, 0.0], rotation=list(quat_axis_angle((0, 1, 0), 30)))
    joints = chain(doc, heights, parent=rig)
    pos, nrm, uv, tris = column(rings=6)
    jts, wts = blend_weights(pos, heights)
    rows = bytearray()
    for p, n, t, j, w in zip(pos, nrm, uv, jts, wts):
        rows += struct.pack("<3f3f2f4B4f", *p, *n, *t, *j, *w)
    stride = 52
    view = doc.view(bytes(rows), stride=stride, target=ARRAY_BUFFER)
    acc = doc.json["accessors"]

    def interleaved(offset, ctype, atype, values, minmax=False):
        return doc.accessor(values, ctype, atype, view=view, offset=offset, minmax=minmax)

    attrs = {"POSITION": interleaved(0, FLOAT, "VEC3", pos, minmax=True),
             "NORMAL": interleaved(12, FLOAT, "VEC3", nrm),
             "TEXCOORD_0": interleaved(24, FLOAT, "VEC2", uv),
             "JOINTS_0": interleaved(32, UBYTE, "VEC4", jts),
             "WEIGHTS_0": interleaved(36, FLOAT, "VEC4", wts)}
    assert all(acc[i]["bufferView"] == view for i in attrs.values())
    attrs["TEXCOORD_1"] = doc.accessor([(p[0] + 0.5, p[2] + 0.5) for p in pos], FLOAT, "VEC2", target=ARRAY_BUFFER)
    attrs["COLOR_0"] = doc.accessor([(0.2, p[1] / 2, 0.8) for p in pos], FLOAT, "VEC3", target=ARRAY_BUFFER)
    # Two primitives on the same attributes (a two-material split): they share their vertices.
    half = len(tris) // 2 // 3 * 3
    prims = [{"attributes": attrs, "material": m,
              "indices": doc.accessor(part, USHORT, "SCALAR", target=ELEMENT_ARRAY_BUFFER)}
             for m, part in enumerate([tris[:half], tris[half:]])]
    doc.json["materials"] = [{"name": "lower", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.3, 0.2, 1.0]}},
                             {"name": "upper", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.8, 1.0]}}]
    mesh = mesh_of(doc, prims, name="interleaved column")
    # The skinned node sits under a transformed parent and has its own TRS: both are ignored.
    holder = doc.node(name="holder", translation=[3.0, 2.0, 1.0], scale=[2.0, 2.0, 2.0])
    body = doc.node(name="body", mesh=mesh, skin=0, translation=[-1.0, 0.0, 4.0],
                    rotation=list(quat_axis_angle((1, 0, 0), 90)), scale=[0.5, 0.5, 0.5])
    doc.json["nodes"][holder]["children"] = [body]
    doc.json["scenes"][0]["nodes"] = [rig, holder]
    skin(doc, joints, skeleton=rig)
    a = animation(doc, "wave")
    channel(doc, a, joints[1], "rotation", [0.0, 0.4, 1.2, 2.0], bend([0, 35, -35, 0], axis=(1, 0, 1)))
    channel(doc, a, rig, "translation", [0.0, 1.0, 2.0], [(0.5, 0, 0), (0.5, 0.3, 0), (0.5, 0, 0.2)])
    return write(doc, glb=True)


def skin_sparse():
    doc = Doc("skin-sparse.gltf")
    heights = [0.0, 1.0]
    joints = chain(doc, heights)
    pos, nrm, uv, tris = column()
    jts, wts = blend_weights(pos, heights)
    dented = {r: (pos[r][0] * 1.5, pos[r][1], pos[r][2] * 1.5) for r in (8, 9, 10, 11)}
    # POSITION: the column's positions with the middle ring widened by a sparse substitution.
    p_acc = doc.accessor(pos, FLOAT, "VEC3", minmax=True, sparse=(UBYTE, dented))
    # A morph target with no bufferView: zeros, the top ring moved by the sparse values.
    target = {r: (0.0, 0.0, 0.3) for r in (16, 17, 18, 19)}
    t_acc = doc.accessor([(0.0, 0.0, 0.0)] * len(pos), FLOAT, "VEC3", sparse=(USHORT, target), minmax=True,
                         no_view=True)
    prim = {"attributes": {"POSITION": p_acc, "NORMAL": doc.accessor(nrm, FLOAT, "VEC3"),
                           "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4"),
                           "WEIGHTS_0": doc.accessor(wts, FLOAT, "VEC4")},
            "indices": doc.accessor(tris, USHORT, "SCALAR"), "targets": [{"POSITION": t_acc}]}
    mesh = mesh_of(doc, [prim], weights=[0.5], name="sparse column")
    body = doc.node(name="body", mesh=mesh, skin=0)
    doc.json["scenes"][0]["nodes"] = [joints[0], body]
    skin(doc, joints)
    a = animation(doc, "sway")
    keys = bend([0, 20, 40, 20, 0])
    channel(doc, a, joints[1], "rotation", [0.0, 0.25, 0.5, 0.75, 1.0], keys,
            sparse=(UINT, {2: quat_axis_angle((0, 0, 1), -40)}))
    return write(doc)


def skin_quantized():
    doc = Doc("skin-quantized.glb")
    doc.json["extensionsUsed"] = ["KHR_mesh_quantization"]
    doc.json["extensionsRequired"] = ["KHR_mesh_quantization"]
    heights = [0.0, 1.0]
    joints = chain(doc, heights)
    pos, nrm, uv, tris = column()
    jts, wts = blend_weights(pos, heights)
    q = 1000.0  # i16 units per metre
    qpos = [tuple(round(c * q) for c in p) for p in pos]
    attrs = {"POSITION": doc.accessor(qpos, SHORT, "VEC3", minmax=True, target=ARRAY_BUFFER),
             "NORMAL": doc.accessor(nrm, BYTE, "VEC3", normalized=True, target=ARRAY_BUFFER),
             "TEXCOORD_0": doc.accessor(uv, USHORT, "VEC2", normalized=True, target=ARRAY_BUFFER),
             "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4", target=ARRAY_BUFFER),
             "WEIGHTS_0": doc.accessor(quantized_weights(wts, UBYTE), UBYTE, "VEC4", normalized=True,
                                       target=ARRAY_BUFFER)}
    # A morph target in quantized units too: i16 offsets (12.5 cm), dequantized with the positions.
    bulge = [(round(p[0] * 0.5 * q), 0, round(p[2] * 0.5 * q)) if 0.4 < p[1] < 1.6 else (0, 0, 0) for p in pos]
    target = doc.accessor(bulge, SHORT, "VEC3", minmax=True, target=ARRAY_BUFFER)
    prim = {"attributes": attrs, "indices": doc.accessor(tris, USHORT, "SCALAR", target=ELEMENT_ARRAY_BUFFER),
            "targets": [{"POSITION": target}]}
    mesh = mesh_of(doc, [prim], weights=[0.0], name="quantized column")
    body = doc.node(name="body", mesh=mesh, skin=0)
    doc.json["scenes"][0]["nodes"] = [joints[0], body]
    dequantize = [[1 / q, 0, 0, 0], [0, 1 / q, 0, 0], [0, 0, 1 / q, 0], [0, 0, 0, 1]]
    skin(doc, joints, extra=dequantize)
    a = animation(doc, "bend")
    channel(doc, a, joints[1], "rotation", [0.0, 1.0, 2.0], bend([0, 60, 0]))
    b = animation(doc, "bulge")
    channel(doc, b, joints[1], "rotation", [0.0, 2.0], bend([0, -30]))
    channel(doc, b, body, "weights", [0.0, 1.0, 2.0], [0.0, 1.0, 0.5])
    return write(doc, glb=True)


def skin_strip_fan():
    doc = Doc("skin-strip-fan.gltf")
    heights = [0.0, 1.0]
    joints = chain(doc, heights)
    prims = []
    # TRIANGLE_STRIP, indexed: a ribbon up the column's front face.
    pos, nrm, uv, tris = column(x=-1.0)
    jts, wts = blend_weights(pos, heights)
    strip = []
    for r in range(5):
        strip += [4 * r, 4 * r + 1]
    prims.append({"attributes": {"POSITION": doc.accessor(pos, FLOAT, "VEC3", minmax=True),
                                 "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4"),
                                 "WEIGHTS_0": doc.accessor(wts, FLOAT, "VEC4")},
                  "indices": doc.accessor(strip, USHORT, "SCALAR"), "mode": 5})
    # TRIANGLE_FAN, not indexed: a disc standing in the XY plane around (1, 1, 0).
    fan = [(1.0, 1.0, 0.0)] + [(1.0 + 0.5 * math.cos(a), 1.0 + 0.8 * math.sin(a), 0.0)
                               for a in [2 * math.pi * k / 8 for k in range(9)]]
    jts, wts = blend_weights(fan, [0.4, 1.6])
    prims.append({"attributes": {"POSITION": doc.accessor(fan, FLOAT, "VEC3", minmax=True),
                                 "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4"),
                                 "WEIGHTS_0": doc.accessor(wts, FLOAT, "VEC4")}, "mode": 6})
    # TRIANGLES, not indexed: the column's triangles expanded.
    pos, nrm, uv, tris = column(x=0.0, rings=3)
    flat = [pos[i] for i in tris]
    jts, wts = blend_weights(flat, heights)
    prims.append({"attributes": {"POSITION": doc.accessor(flat, FLOAT, "VEC3", minmax=True),
                                 "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4"),
                                 "WEIGHTS_0": doc.accessor(wts, FLOAT, "VEC4")}})
    mesh = mesh_of(doc, prims, name="strip fan soup")
    body = doc.node(name="body", mesh=mesh, skin=0)
    doc.json["scenes"][0]["nodes"] = [joints[0], body]
    skin(doc, joints)
    a = animation(doc, "nod")
    channel(doc, a, joints[1], "rotation", [0.0, 0.5, 1.0], bend([0, 45, 0], axis=(1, 0, 0)))
    return write(doc)


def skin_eight_influences():
    doc = Doc("skin-eight-influences.gltf")
    root = doc.node(name="root")
    joints = []
    for k in range(8):
        a = 2 * math.pi * k / 8
        j = doc.node(name="spoke%d" % k, translation=[0.6 * math.cos(a), 1.0, 0.6 * math.sin(a)])
        joints.append(j)
    doc.json["nodes"][root]["children"] = list(joints)
    pos, nrm, uv, tris = column(rings=5)
    j0, j1, w0, w1 = [], [], [], []
    for v, p in enumerate(pos):
        # Every vertex is bound to all eight spokes, nearest ones heaviest; weights sum to one.
        d = []
        for k in range(8):
            t = doc.json["nodes"][joints[k]]["translation"]
            d.append(1.0 / (0.3 + math.dist(p, t)) ** 2)
        s = sum(d)
        w = [x / s for x in d]
        order = sorted(range(8), key=lambda k: (k + v) % 8)  # sets differ per vertex, not sorted by weight
        j0.append(tuple(order[:4]))
        j1.append(tuple(order[4:]))
        w0.append(tuple(w[k] for k in order[:4]))
        w1.append(tuple(w[k] for k in order[4:]))
    prim = {"attributes": {"POSITION": doc.accessor(pos, FLOAT, "VEC3", minmax=True),
                           "JOINTS_0": doc.accessor(j0, UBYTE, "VEC4"), "JOINTS_1": doc.accessor(j1, UBYTE, "VEC4"),
                           "WEIGHTS_0": doc.accessor(w0, FLOAT, "VEC4"), "WEIGHTS_1": doc.accessor(w1, FLOAT, "VEC4")},
            "indices": doc.accessor(tris, USHORT, "SCALAR")}
    mesh = mesh_of(doc, [prim], name="eight influences")
    body = doc.node(name="body", mesh=mesh, skin=0)
    doc.json["scenes"][0]["nodes"] = [root, body]
    skin(doc, joints)
    a = animation(doc, "spread")
    for k, j in enumerate(joints):
        t = doc.json["nodes"][j]["translation"]
        out = [tuple(t), tuple(c * (1.3 if k % 2 else 0.8) for c in t), tuple(t)]
        channel(doc, a, j, "translation", [0.0, 0.5 + 0.05 * k, 1.0 + 0.1 * k], out)
        channel(doc, a, j, "rotation", [0.0, 1.0], bend([0, 15 * (k - 3.5)], axis=(0, 1, 0)))
    return write(doc)


def skin_no_ibm():
    doc = Doc("skin-no-ibm.gltf")
    # Joints at the origin at rest, so the identity inverse bind matrices the specification
    # prescribes are the right ones; the vertices are given in that shared space.
    joints = [doc.node(name="lower"), doc.node(name="upper")]
    pivot = doc.node(name="pivot", children=list(joints))
    pos, nrm, uv, tris = column()
    jts, wts = blend_weights(pos, [0.0, 1.0])
    prim = {"attributes": {"POSITION": doc.accessor(pos, FLOAT, "VEC3", minmax=True),
                           "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4"),
                           "WEIGHTS_0": doc.accessor(wts, FLOAT, "VEC4")},
            "indices": doc.accessor(tris, USHORT, "SCALAR")}
    mesh = mesh_of(doc, [prim], name="no inverse bind matrices")
    body = doc.node(name="body", mesh=mesh, skin=0)
    doc.json["scenes"][0]["nodes"] = [pivot, body]
    skin(doc, joints, with_ibm=False)
    a = animation(doc, "shear")
    channel(doc, a, joints[1], "translation", [0.0, 1.0], [(0, 0, 0), (0.4, 0.2, 0)])
    channel(doc, a, joints[1], "rotation", [0.0, 1.0], bend([0, 20]))
    channel(doc, a, joints[0], "scale", [0.0, 1.0], [(1, 1, 1), (1.2, 0.9, 1.2)])
    return write(doc)


def cubic(keys, tangents):
    """CUBICSPLINE output rows: per key (in-tangent, value, out-tangent)."""
    rows = []
    for k, v in zip(keys, tangents):
        value, a, b = v
        rows += [a, value, b]
    return rows


def anim_interpolation():
    doc = Doc("anim-interpolation.gltf")
    heights = [0.0, 0.7, 1.4]
    joints = chain(doc, heights)
    pos, nrm, uv, tris = column(rings=7, height=2.1)
    jts, wts = blend_weights(pos, heights)
    prim = {"attributes": {"POSITION": doc.accessor(pos, FLOAT, "VEC3", minmax=True),
                           "NORMAL": doc.accessor(nrm, FLOAT, "VEC3"),
                           "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4"),
                           "WEIGHTS_0": doc.accessor(wts, FLOAT, "VEC4")},
            "indices": doc.accessor(tris, USHORT, "SCALAR")}
    mesh = mesh_of(doc, [prim], name="interpolated column")
    body = doc.node(name="body", mesh=mesh, skin=0)
    doc.json["scenes"][0]["nodes"] = [joints[0], body]
    skin(doc, joints)
    times = [0.2, 0.5, 1.3, 1.6]

    def translation(j):
        base = doc.json["nodes"][joints[j]]["translation"]
        return [tuple(base), (base[0] + 0.2, base[1], 0.1), (base[0] - 0.1, base[1] + 0.1, 0.0), tuple(base)]

    def rotation(j):
        return bend([0, 35, -20, 50], axis=(0.3, 0.2, 1))

    def scale(j):
        return [(1, 1, 1), (1.2, 0.9, 1.0), (0.8, 1.1, 1.3), (1, 1, 1)]

    def tangents(values, size):
        # In-tangents and out-tangents per key (units per second): not zero, not symmetric.
        out = []
        for k, v in enumerate(values):
            a = tuple(0.3 * math.sin(k + i) for i in range(size))
            b = tuple(-0.2 * math.cos(k + 2 * i) for i in range(size))
            out.append((tuple(v), a, b))
        return out

    plans = {"clip-a": [("LINEAR", "STEP", "CUBICSPLINE"), ("STEP", "CUBICSPLINE", "LINEAR"),
                        ("CUBICSPLINE", "LINEAR", "STEP")],
             "clip-b": [("CUBICSPLINE", "STEP", "LINEAR"), ("LINEAR", "CUBICSPLINE", "STEP"),
                        ("STEP", "LINEAR", "CUBICSPLINE")]}
    for clip, plan in plans.items():
        a = animation(doc, clip)
        shift = 0.0 if clip == "clip-a" else 0.1
        for j, kinds in enumerate(plan):
            for path, kind, values, size in [("translation", kinds[0], translation(j), 3),
                                             ("rotation", kinds[1], rotation(j), 4),
                                             ("scale", kinds[2], scale(j), 3)]:
                keys = [t + shift * j for t in times]
                rows = cubic(values, tangents(values, size)) if kind == "CUBICSPLINE" else values
                channel(doc, a, joints[j], path, keys, rows, interpolation=kind)
    return write(doc)


def morph_skin():
    doc = Doc("morph-skin.gltf")
    heights = [0.0, 1.0]
    joints = chain(doc, heights)
    pos, nrm, uv, tris = column()
    jts, wts = blend_weights(pos, heights)
    swell = [(p[0] * 0.6, 0.0, p[2] * 0.6) if 0.4 < p[1] < 1.6 else (0.0, 0.0, 0.0) for p in pos]
    lean = [(0.3 * p[1] / 2.0, 0.0, 0.0) for p in pos]
    tilt = [(0.0, 0.1, 0.0) for _ in nrm]
    targets = [{"POSITION": doc.accessor(swell, FLOAT, "VEC3", minmax=True)},
               {"POSITION": doc.accessor(lean, FLOAT, "VEC3", minmax=True),
                "NORMAL": doc.accessor(tilt, FLOAT, "VEC3")}]
    prim = {"attributes": {"POSITION": doc.accessor(pos, FLOAT, "VEC3", minmax=True),
                           "NORMAL": doc.accessor(nrm, FLOAT, "VEC3"),
                           "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4"),
                           "WEIGHTS_0": doc.accessor(wts, FLOAT, "VEC4")},
            "indices": doc.accessor(tris, USHORT, "SCALAR"), "targets": targets}
    mesh = mesh_of(doc, [prim], weights=[0.5, 0.25], name="morphed column")
    mesh2 = mesh_of(doc, [dict(prim)], weights=[0.5, 0.25], name="morphed column, node weights")
    body = doc.node(name="body", mesh=mesh, skin=0)
    # A second instance whose node overrides the mesh's default weights.
    body2 = doc.node(name="body2", mesh=mesh2, skin=0, weights=[1.0, 0.0])
    doc.json["scenes"][0]["nodes"] = [joints[0], body, body2]
    skin(doc, joints)
    a = animation(doc, "bend")
    channel(doc, a, joints[1], "rotation", [0.0, 1.0], bend([0, 30]))
    b = animation(doc, "breathe")
    channel(doc, b, joints[1], "rotation", [0.0, 1.0], bend([0, -20]))
    channel(doc, b, body, "weights", [0.0, 0.5, 1.0], [0.5, 0.25, 1.0, 0.0, 0.0, 1.0])
    # Weights by CUBICSPLINE (body; per key in-tangents, values, out-tangents, one per target) and
    # STEP (body2), keyed at other times than the rotation.
    c = animation(doc, "pulse")
    channel(doc, c, joints[1], "rotation", [0.0, 1.2], bend([0, 15]))
    channel(doc, c, body, "weights", [0.0, 0.6, 1.2],
            [0.0, 0.0, 0.2, 0.1, 1.5, -0.8,
             -1.0, 0.4, 0.9, 0.6, 0.3, 1.2,
             0.5, -0.5, 0.1, 0.0, 0.0, 0.0], interpolation="CUBICSPLINE")
    channel(doc, c, body2, "weights", [0.1, 0.7], [1.0, 0.0, 0.3, 0.7], interpolation="STEP")
    return write(doc)


def png(width, height, pixel):
    """An RGBA PNG (no filter, zlib level 9: deterministic); pixel(x, y) -> (r, g, b, a), row 0 the top."""
    raw = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


# The four-colour picture: red top left, green top right, blue bottom left, yellow bottom right.
QUADRANTS = [[(255, 0, 0, 255), (0, 255, 0, 255)], [(0, 0, 255, 255), (255, 255, 0, 255)]]


def quad(doc, facing_back=False, color=None):
    """A unit quad around the origin in the XY plane facing +Z (or -Z: reversed winding and normal),
    glTF texture coordinates with (0, 0) at the image's top left."""
    pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    uv = [(0, 1), (1, 1), (1, 0), (0, 0)]
    nz = -1 if facing_back else 1
    attributes = {"POSITION": doc.accessor(pos, FLOAT, "VEC3", target=ARRAY_BUFFER, minmax=True),
                  "NORMAL": doc.accessor([(0, 0, nz)] * 4, FLOAT, "VEC3", target=ARRAY_BUFFER),
                  "TEXCOORD_0": doc.accessor(uv, FLOAT, "VEC2", target=ARRAY_BUFFER)}
    if color:
        attributes["COLOR_0"] = doc.accessor([color] * 4, FLOAT, "VEC4", target=ARRAY_BUFFER)
    tris = [0, 2, 1, 0, 3, 2] if facing_back else [0, 1, 2, 0, 2, 3]
    return attributes, doc.accessor(tris, USHORT, "SCALAR", target=ELEMENT_ARRAY_BUFFER, vertex=False)


def materials():
    doc = Doc("materials.glb")
    j = doc.json
    four = png(8, 8, lambda x, y: QUADRANTS[y // 4][x // 4])
    cutout = png(8, 8, lambda x, y: (255, 255, 255, 51 if x < 4 else 230))
    j["images"] = [{"bufferView": doc.view(four), "mimeType": "image/png", "name": "quadrants"},
                   {"bufferView": doc.view(cutout), "mimeType": "image/png", "name": "cutout"}]
    j["textures"] = [{"source": 0}, {"source": 1}]
    # A quarter turn and an offset (glTF's convention): uv' = (v, 1 - u), so the picture turns.
    turned = {"KHR_texture_transform": {"offset": [0, 1], "rotation": math.pi / 2}}
    j["materials"] = [
        {"name": "quadrants", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
        {"name": "turned", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions": turned}}},
        {"name": "cutout", "alphaMode": "MASK", "alphaCutoff": 0.5,
         "pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 1], "baseColorTexture": {"index": 1}}},
        {"name": "glass", "alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 0.5]}},
        {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}},
        {"name": "glow", "emissiveFactor": [0, 1, 0], "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]}},
        {"name": "unlit", "extensions": {"KHR_materials_unlit": {}},
         "pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0, 1]}},
        {"name": "single-sided", "pbrMetallicRoughness": {"baseColorFactor": [0, 1, 1, 1]}},
        {"name": "double-sided", "doubleSided": True, "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 0, 1]}},
        {"name": "white", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}},
    ]
    j["extensionsUsed"] = ["KHR_materials_unlit", "KHR_texture_transform"]
    # (column, row, z, material, facing back, vertex colour); rows from the top, 1.25 apart.
    layout = [(0, 0, 0, 0, False, None), (1, 0, 0, 1, False, None), (2, 0, 0, 2, False, None),
              (0, 1, 0.3, 3, False, None), (0, 1, 0, 4, False, None), (1, 1, 0, 5, False, None),
              (2, 1, 0, 6, False, None), (0, 2, 0, 7, True, None), (1, 2, 0, 8, True, None),
              (2, 2, 0, 9, False, (1, 0, 1, 1))]
    for column, row, z, material, back, color in layout:
        attributes, indices = quad(doc, back, color)
        j["meshes"].append({"name": j["materials"][material]["name"],
                            "primitives": [{"attributes": attributes, "indices": indices, "material": material}]})
        n = doc.node(name=j["materials"][material]["name"], mesh=len(j["meshes"]) - 1,
                     translation=[(column - 1) * 1.25, (2 - row) * 1.25, z])
        j["scenes"][0]["nodes"].append(n)
    return write(doc, glb=True)


def skin_textured():
    doc = Doc("skin-textured.glb")
    j = doc.json
    four = png(8, 8, lambda x, y: QUADRANTS[y // 4][x // 4])
    j["images"] = [{"bufferView": doc.view(four), "mimeType": "image/png", "name": "quadrants"}]
    j["textures"] = [{"source": 0}]
    j["materials"] = [{"name": "quadrants", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    xs, ys = [-0.5, 0.0, 0.5], [0.0, 0.5, 1.0, 1.5, 2.0]
    pos = [(x, y, 0.0) for y in ys for x in xs]
    uv = [((x + 0.5), 1 - y / 2) for y in ys for x in xs]
    tris = []
    for r in range(len(ys) - 1):
        for c in range(len(xs) - 1):
            a = r * len(xs) + c
            tris += [a, a + 1, a + 1 + len(xs), a, a + 1 + len(xs), a + len(xs)]
    joints = chain(doc, [0.0, 1.0])
    jts, wts = blend_weights(pos, [0.0, 1.0])
    prim = {"attributes": {"POSITION": doc.accessor(pos, FLOAT, "VEC3", target=ARRAY_BUFFER, minmax=True),
                           "NORMAL": doc.accessor([(0, 0, 1)] * len(pos), FLOAT, "VEC3", target=ARRAY_BUFFER),
                           "TEXCOORD_0": doc.accessor(uv, FLOAT, "VEC2", target=ARRAY_BUFFER),
                           "JOINTS_0": doc.accessor(jts, UBYTE, "VEC4", target=ARRAY_BUFFER),
                           "WEIGHTS_0": doc.accessor(wts, FLOAT, "VEC4", target=ARRAY_BUFFER)},
            "indices": doc.accessor(tris, USHORT, "SCALAR", target=ELEMENT_ARRAY_BUFFER, vertex=False),
            "material": 0}
    mesh = mesh_of(doc, [prim], name="strip")
    body = doc.node(name="strip", mesh=mesh, skin=0)
    j["scenes"][0]["nodes"] = [joints[0], body]
    skin(doc, joints)
    a = animation(doc, "slide")
    channel(doc, a, joints[1], "translation", [0.0, 1.0], [(0, 1, 0), (0.5, 1, 0)])
    return write(doc, glb=True)


def prism(zs, half, centre=(0.0, 0.0), bottom=True, top=True):
    """Square rings about the local Z axis at heights zs, corners counter-clockwise seen from +Z,
    side faces and the chosen caps wound outward (a box for two rings and both caps)."""
    cx, cy = centre
    pos = [(cx + sx * half, cy + sy * half, z) for z in zs for sx, sy in [(-1, -1), (1, -1), (1, 1), (-1, 1)]]
    tris = []
    for r in range(len(zs) - 1):
        for c in range(4):
            a, b = 4 * r + c, 4 * r + (c + 1) % 4
            tris += [a, b, b + 4, a, b + 4, a + 4]
    if bottom:
        tris += [0, 2, 1, 0, 3, 2]
    if top:
        t = 4 * (len(zs) - 1)
        tris += [t, t + 1, t + 2, t, t + 2, t + 3]
    return pos, tris


def signed_volume(pos, tris):
    v = 0.0
    for i in range(0, len(tris), 3):
        a, b, c = (pos[k] for k in tris[i:i + 3])
        v += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2])
              + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    return v


def reindexed(pos, tris):
    """The vertices the triangles use, in first-use order, and the triangles on them."""
    order = {}
    for i in tris:
        order.setdefault(i, len(order))
    return [pos[i] for i in order], [order[i] for i in tris]


def scaled_parts():
    doc = Doc("scaled-parts.gltf")
    j = doc.json
    root = doc.node(name="Sketchfab_model", rotation=list(quat_axis_angle((1, 0, 0), -90)))
    armature = doc.node(name="Armature", scale=[0.01, 0.01, 0.01])
    j["nodes"][root]["children"] = [armature]
    hips = doc.node(name="hips")
    spine = doc.node(name="spine", translation=[0.0, 0.0, 100.0])
    head = doc.node(name="head", translation=[0.0, 0.0, 100.0])
    j["nodes"][hips]["children"] = [spine]
    j["nodes"][spine]["children"] = [head]
    joints = [hips, spine, head]
    j["materials"] = [{"name": name, "pbrMetallicRoughness": {"baseColorFactor": colour}}
                      for name, colour in [("skin", [0.8, 0.6, 0.5, 1.0]), ("cloth", [0.3, 0.3, 0.6, 1.0]),
                                           ("leather", [0.4, 0.25, 0.1, 1.0]), ("sole", [0.1, 0.1, 0.1, 1.0]),
                                           ("metal", [0.7, 0.7, 0.75, 1.0])]]

    def part(name, pos, tris, weights, material):
        """A mesh of one primitive; weights(position) gives (joints, weights) in skin order."""
        jw = [weights(p) for p in pos]
        prim = {"attributes": {"POSITION": doc.accessor(pos, FLOAT, "VEC3", minmax=True, target=ARRAY_BUFFER),
                               "JOINTS_0": doc.accessor([x[0] for x in jw], UBYTE, "VEC4", target=ARRAY_BUFFER),
                               "WEIGHTS_0": doc.accessor([x[1] for x in jw], FLOAT, "VEC4", target=ARRAY_BUFFER)},
                "indices": doc.accessor(tris, USHORT, "SCALAR", target=ELEMENT_ARRAY_BUFFER, vertex=False),
                "material": material}
        return mesh_of(doc, [prim], name=name)

    def along_spine(p):
        # Local z 0..100 on a node of scale 2: the hips below 25, the spine above 75, half and
        # half on the ring at the joint (z = 50).
        if p[2] < 40:
            return (0, 0, 0, 0), (1.0, 0.0, 0.0, 0.0)
        if p[2] > 60:
            return (1, 0, 0, 0), (1.0, 0.0, 0.0, 0.0)
        return (0, 1, 0, 0), (0.5, 0.5, 0.0, 0.0)

    def on(joint):
        return lambda p: ((joint, 0, 0, 0), (1.0, 0.0, 0.0, 0.0))

    rings = [0.0, 25.0, 50.0, 75.0, 100.0]
    body_mesh = part("body", *prism(rings, 12.5), along_spine, 0)
    cloak_mesh = part("cloak", *prism(rings, 15.0, bottom=False), along_spine, 1)
    # The boot: one box, its faces in two meshes by material, each mesh its own vertices.
    box, faces = prism([2.5, 22.5], 10.0, centre=(37.5, 0.0))
    for closed in [prism(rings, 12.5), (box, faces), prism([-0.5, 0.5], 0.5)]:
        assert signed_volume(*closed) > 0, "wound outward"
    sides = [faces[6 * f:6 * f + 6] for f in range(6)]  # four sides, then bottom and top
    upper_mesh = part("boot-upper", *reindexed(box, sides[0] + sides[1] + sides[5]), on(0), 2)
    lower_mesh = part("boot-lower", *reindexed(box, sides[2] + sides[3] + sides[4]), on(0), 3)
    helmet_mesh = part("helmet", *prism([-0.5, 0.5], 0.5), on(2), 4)
    crate, crate_tris = prism([-0.5, 0.5], 0.5)
    crate_mesh = mesh_of(doc, [{"attributes": {"POSITION": doc.accessor(crate, FLOAT, "VEC3", minmax=True,
                                                                        target=ARRAY_BUFFER)},
                                "indices": doc.accessor(crate_tris, USHORT, "SCALAR", target=ELEMENT_ARRAY_BUFFER,
                                                        vertex=False),
                                "material": 2}], name="crate")
    two = [2.0, 2.0, 2.0]
    body = doc.node(name="body", mesh=body_mesh, scale=two)
    cloak = doc.node(name="cloak", mesh=cloak_mesh, scale=two)
    upper = doc.node(name="boot-upper", mesh=upper_mesh, scale=two)
    lower = doc.node(name="boot-lower", mesh=lower_mesh, scale=two)
    helmet = doc.node(name="helmet", mesh=helmet_mesh, translation=[0.0, 0.0, 250.0],
                      rotation=list(quat_axis_angle((0, 0, 1), 30)), scale=[40.0, 30.0, 50.0])
    badge = doc.node(name="badge", mesh=helmet_mesh, translation=[60.0, 0.0, 250.0], scale=[-20.0, 15.0, 25.0])
    prop = doc.node(name="crate", mesh=crate_mesh, translation=[-150.0, 0.0, 0.0], scale=[30.0, 30.0, 30.0])
    j["nodes"][armature]["children"] = [hips, body, cloak, upper, lower, helmet, badge, prop]
    j["scenes"][0]["nodes"] = [root]
    # Each skin's inverse bind matrices against its mesh node's world: at rest a part stands where
    # its node puts it, scale and mirror included.
    parents = parent_map(doc)
    for skinned, s in [(body, 0), (cloak, 0), (upper, 0), (lower, 0), (helmet, 1), (badge, 2)]:
        if s == len(j["skins"]):
            skin(doc, joints, skeleton=hips, extra=world_of(doc, skinned, parents))
        j["nodes"][skinned]["skin"] = s
    a = animation(doc, "grow-and-twist")
    # Keys inside the clip (it ends at rest at t = 3), so a looping player reaches each of them.
    channel(doc, a, spine, "scale", [0.0, 1.0, 2.0, 3.0], [(1, 1, 1), (1.25, 1.25, 1.25), (1, 1, 1), (1, 1, 1)])
    channel(doc, a, spine, "rotation", [0.0, 1.0, 2.0, 3.0],
            [(0, 0, 0, 1), (0, 0, 0, 1), quat_axis_angle((0, 0, 1), 170), (0, 0, 0, 1)])
    return write(doc)


FIXTURES = [skin_component_types, skin_interleaved, skin_sparse, skin_quantized, skin_strip_fan,
            skin_eight_influences, skin_no_ibm, anim_interpolation, morph_skin, materials,
            skin_textured, scaled_parts]


def check():
    """Regenerates into a temporary folder and compares with the committed files (CI)."""
    global OUT
    committed = OUT
    with tempfile.TemporaryDirectory() as tmp:
        OUT = tmp
        names = [os.path.basename(make()) for make in FIXTURES]
        stale = [n for n in names if not os.path.isfile(os.path.join(committed, n))
                 or open(os.path.join(tmp, n), "rb").read() != open(os.path.join(committed, n), "rb").read()]
    OUT = committed
    for n in stale:
        print("%s differs from what tools/gltf/make-fixtures.py writes: run it" % n, file=sys.stderr)
    print("glTF fixtures: %d of %d as the generator writes them" % (len(names) - len(stale), len(names)))
    return 1 if stale else 0


def main(argv):
    if "--check" in argv:
        return check()
    os.makedirs(OUT, exist_ok=True)
    paths = [make() for make in FIXTURES]
    for p in paths:
        print("wrote %s (%d bytes)" % (os.path.relpath(p, ROOT), os.path.getsize(p)))
    if "--no-validate" in argv:
        return 0
    bench = os.path.join(ROOT, "bench", "threejs")
    if not os.path.isdir(os.path.join(bench, "node_modules", "gltf-validator")):
        print("gltf-validator missing: run `npm ci` in bench/threejs first", file=sys.stderr)
        return 1
    print("glTF-Validator report (npm gltf-validator, bench/threejs/package.json):")
    r = subprocess.run(["node", os.path.join(bench, "validate.mjs")] + paths)
    if r.returncode != 0:
        print("validation failed: the fixtures must have zero errors", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
