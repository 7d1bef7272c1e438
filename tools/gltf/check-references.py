#!/usr/bin/env python3
"""Checks the three.js glTF references against a third, plain-Python evaluation of the glTF 2.0
specification's formulas, straight from each file (no three.js, no skinlab code): every vertex at
rest and at every time of every clip of the reference, in world space.

    python3 tools/gltf/check-references.py            # fixtures, assets' .glb, samples if present

The reference (bench/threejs/gltf-reference.mjs) puts two things three.js does differently right
(more than four influences; rotation keys off unit length); this shows the result is the
specification's answer. Python 3 standard library only.

What is evaluated: accessors of every component type, normalized, byteStride, sparse (GLB or data
URIs or files beside the .gltf); node TRS or matrix; LINEAR (slerp for rotations), STEP and
CUBICSPLINE (Hermite, rotations normalized) samplers on translation, rotation, scale and morph
weights, clamped outside their keys; morph targets (POSITION) with mesh or node weights; skins
(every JOINTS_n/WEIGHTS_n set, inverse bind matrices or identity) as sum(w * jointWorld * ibm * p);
static meshes by their node's world matrix.

The blend references (bench/threejs/blend-reference.mjs, assets/reference/threejs/blends/) are
checked the same way, with the clips blended as that script's header says three.js' AnimationMixer
blends them (weights, the rest value filling up to 1, additive deltas from a reference time): it
shows that description is what three.js computes.
"""

import base64
import gzip
import json
import math
import os
import struct
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOLERANCE = 1e-5  # of the model's size: float32 data and 7-digit references

FORMAT = {5120: ("b", 127), 5121: ("B", 255), 5122: ("h", 32767), 5123: ("H", 65535), 5125: ("I", 0),
          5126: ("f", 0)}
WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


class Document:
    def __init__(self, path):
        data = open(path, "rb").read()
        self.bin = None
        if data[:4] == b"glTF":
            offset = 12
            while offset < len(data):
                length, kind = struct.unpack_from("<II", data, offset)
                chunk = data[offset + 8:offset + 8 + length]
                if kind == 0x4E4F534A:
                    self.json = json.loads(chunk)
                elif kind == 0x004E4942:
                    self.bin = chunk
                offset += 8 + length
        else:
            self.json = json.loads(data)
        folder = os.path.dirname(path)
        self.buffers = []
        for b in self.json.get("buffers", []):
            uri = b.get("uri")
            if uri is None:
                self.buffers.append(self.bin)
            elif uri.startswith("data:"):
                self.buffers.append(base64.b64decode(uri[uri.index(",") + 1:]))
            else:
                self.buffers.append(open(os.path.join(folder, uri), "rb").read())
        self.cache = {}

    def accessor(self, index):
        if index in self.cache:
            return self.cache[index]
        a = self.json["accessors"][index]
        fmt, norm = FORMAT[a["componentType"]]
        width = WIDTH[a["type"]]
        size = struct.calcsize("<" + fmt)
        scale = (lambda v: max(v / norm, -1.0)) if a.get("normalized") else (lambda v: v)
        rows = [[0.0] * width for _ in range(a["count"])]
        if "bufferView" in a:
            view = self.json["bufferViews"][a["bufferView"]]
            data = self.buffers[view["buffer"]]
            stride = view.get("byteStride", size * width)
            start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
            for i in range(a["count"]):
                rows[i] = [scale(v) for v in struct.unpack_from("<" + fmt * width, data, start + i * stride)]
        sparse = a.get("sparse")
        if sparse:
            iv = self.json["bufferViews"][sparse["indices"]["bufferView"]]
            vv = self.json["bufferViews"][sparse["values"]["bufferView"]]
            ifmt = FORMAT[sparse["indices"]["componentType"]][0]
            idata, vdata = self.buffers[iv["buffer"]], self.buffers[vv["buffer"]]
            istart = iv.get("byteOffset", 0) + sparse["indices"].get("byteOffset", 0)
            vstart = vv.get("byteOffset", 0) + sparse["values"].get("byteOffset", 0)
            for k in range(sparse["count"]):
                i = struct.unpack_from("<" + ifmt, idata, istart + k * struct.calcsize("<" + ifmt))[0]
                rows[i] = [scale(v) for v in struct.unpack_from("<" + fmt * width, vdata, vstart + k * size * width)]
        self.cache[index] = rows
        return rows


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def trs(t, r, s):
    x, y, z, w = r
    n = math.sqrt(x * x + y * y + z * z + w * w) or 1.0
    x, y, z, w = x / n, y / n, z / n, w / n
    m = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[m[i][0] * s[0], m[i][1] * s[1], m[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def transform(m, p):
    return [m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3)]


def slerp(a, b, u):
    d = sum(x * y for x, y in zip(a, b))
    if d < 0:
        b, d = [-x for x in b], -d
    if d > 0.9995:
        q = [x + (y - x) * u for x, y in zip(a, b)]
    else:
        th = math.acos(d)
        s = math.sin(th)
        q = [(math.sin((1 - u) * th) * x + math.sin(u * th) * y) / s for x, y in zip(a, b)]
    n = math.sqrt(sum(x * x for x in q))
    return [x / n for x in q]


def unit(q):
    n = math.sqrt(sum(x * x for x in q))
    return [x / n for x in q]


def sample(doc, sampler, path, t):
    times = [r[0] for r in doc.accessor(sampler["input"])]
    out = doc.accessor(sampler["output"])
    kind = sampler.get("interpolation", "LINEAR")
    per_key = len(out) // len(times)  # morph weights: one row per target per key
    if kind == "CUBICSPLINE":
        per_key //= 3

    def value(k, part=1):
        rows = out[(3 * k + part) * per_key:(3 * k + part + 1) * per_key] if kind == "CUBICSPLINE" \
            else out[k * per_key:(k + 1) * per_key]
        return [v for r in rows for v in r]

    if t <= times[0]:
        v = value(0)
    elif t >= times[-1]:
        v = value(len(times) - 1)
    else:
        k = max(i for i in range(len(times) - 1) if times[i] <= t)
        td = times[k + 1] - times[k]
        u = (t - times[k]) / td
        if kind == "STEP":
            v = value(k)
        elif kind == "LINEAR":
            a, b = value(k), value(k + 1)
            v = slerp(unit(a), unit(b), u) if path == "rotation" else [x + (y - x) * u for x, y in zip(a, b)]
        else:
            p0, m0, p1, m1 = value(k), value(k, 2), value(k + 1), value(k + 1, 0)
            u2, u3 = u * u, u * u * u
            v = [(2 * u3 - 3 * u2 + 1) * a + (u3 - 2 * u2 + u) * td * b + (-2 * u3 + 3 * u2) * c
                 + (u3 - u2) * td * d for a, b, c, d in zip(p0, m0, p1, m1)]
    return unit(v) if path == "rotation" else v


def rest_state(doc):
    """Every node's own translation, rotation, scale and morph weights, as the file gives them."""
    return {i: {"translation": list(n.get("translation", [0, 0, 0])), "rotation": list(n.get("rotation", [0, 0, 0, 1])),
                "scale": list(n.get("scale", [1, 1, 1])), "weights": n.get("weights")}
            for i, n in enumerate(doc.json["nodes"])}


def channel_values(doc, anim, t):
    """{(node, path): value} of an animation's node channels at time t."""
    return {(ch["target"]["node"], ch["target"]["path"]): sample(doc, anim["samplers"][ch["sampler"]], ch["target"]["path"], t)
            for ch in anim["channels"] if "node" in ch["target"]}


def positions(doc, clip_index, t, entries):
    """World positions of each reference entry (node, mesh, primitive) at time t of a clip."""
    t = struct.unpack("<f", struct.pack("<f", t))[0]  # times are float32, as the key times are
    state = rest_state(doc)
    if clip_index is not None:
        for (node, path), value in channel_values(doc, doc.json["animations"][clip_index], t).items():
            state[node][path] = value
    return skinned(doc, state, entries)


def skinned(doc, state, entries):
    """World positions of each reference entry (node, mesh, primitive) with the nodes at `state`."""
    nodes = doc.json["nodes"]
    parent = {c: i for i, n in enumerate(nodes) for c in n.get("children", [])}
    world = {}

    def world_of(i):
        if i not in world:
            n = nodes[i]
            if "matrix" in n:
                c = n["matrix"]
                local = [[c[col * 4 + row] for col in range(4)] for row in range(4)]
            else:
                s = state[i]
                local = trs(s["translation"], s["rotation"], s["scale"])
            world[i] = local if i not in parent else mat_mul(world_of(parent[i]), local)
        return world[i]

    result = []
    for e in entries:
        node = nodes[e["node"]]
        mesh = doc.json["meshes"][node["mesh"]]
        prim = mesh["primitives"][e["primitive"]]
        pos = [list(p) for p in doc.accessor(prim["attributes"]["POSITION"])]
        weights = state[e["node"]]["weights"] or mesh.get("weights") or []
        for w, target in zip(weights, prim.get("targets", [])):
            if w and "POSITION" in target:
                for p, d in zip(pos, doc.accessor(target["POSITION"])):
                    for c in range(3):
                        p[c] += w * d[c]
        if "skin" in node:
            skin = doc.json["skins"][node["skin"]]
            ibms = doc.accessor(skin["inverseBindMatrices"]) if "inverseBindMatrices" in skin else None
            mats = []
            for j, jn in enumerate(skin["joints"]):
                ibm = [[ibms[j][col * 4 + row] for col in range(4)] for row in range(4)] if ibms \
                    else [[float(r == c) for c in range(4)] for r in range(4)]
                mats.append(mat_mul(world_of(jn), ibm))
            sets = []
            s = 0
            while "JOINTS_%d" % s in prim["attributes"]:
                sets.append((doc.accessor(prim["attributes"]["JOINTS_%d" % s]),
                             doc.accessor(prim["attributes"]["WEIGHTS_%d" % s])))
                s += 1
            out = []
            for v, p in enumerate(pos):
                acc = [0.0, 0.0, 0.0]
                for joints, ws in sets:
                    for c in range(4):
                        if ws[v][c]:
                            q = transform(mats[int(joints[v][c])], p)
                            for k in range(3):
                                acc[k] += ws[v][c] * q[k]
                out.extend(acc)
        else:
            m = world_of(e["node"])
            out = [x for p in pos for x in transform(m, p)]
        result.append(out)
    return result


def qmul(a, b):
    """Hamilton product of quaternions stored x, y, z, w."""
    x0, y0, z0, w0 = a
    x1, y1, z1, w1 = b
    return [x0 * w1 + w0 * x1 + y0 * z1 - z0 * y1, y0 * w1 + w0 * y1 + z0 * x1 - x0 * z1,
            z0 * w1 + w0 * z1 + x0 * y1 - y0 * x1, w0 * w1 - x0 * x1 - y0 * y1 - z0 * z1]


def mix(path, a, b, u):
    return slerp(a, b, u) if path == "rotation" else [x + (y - x) * u for x, y in zip(a, b)]


def blended_state(doc, case):
    """The nodes' values with the case's clips blended as three.js' AnimationMixer blends them
    (bench/threejs/blend-reference.mjs says how): each clip at the case's time wrapped into its
    own length; normal clips averaged by weight in the order listed, the rest value filling up to a
    weight of 1; then the additive clips' deltas from their reference times, on the right."""
    names = {a.get("name"): a for a in doc.json["animations"]}
    state = rest_state(doc)

    def at(anim, t):
        length = max(doc.accessor(s["input"])[-1][0] for s in anim["samplers"])
        return channel_values(doc, anim, t - length * math.floor(t / length))

    blended = {}
    for entry in case["blend"]:
        for key, value in at(names[entry["clip"]], case["time"]).items():
            if key not in blended:
                blended[key] = (value, entry["weight"])
            else:
                so_far, weight = blended[key]
                weight += entry["weight"]
                blended[key] = (mix(key[1], so_far, value, entry["weight"] / weight), weight)
    for (node, path), (value, weight) in blended.items():
        state[node][path] = mix(path, value, state[node][path], 1 - weight) if weight < 1 else value
    deltas = {}
    for entry in case["additive"]:
        anim = names[entry["clip"]]
        reference = channel_values(doc, anim, entry["refTime"])
        for key, value in at(anim, case["time"]).items():
            if key[1] == "rotation":
                r = reference[key]
                d = qmul([-r[0], -r[1], -r[2], r[3]], value)
                so_far = deltas.get(key, [0.0, 0.0, 0.0, 1.0])
                deltas[key] = slerp(so_far, qmul(so_far, d), entry["weight"])
            else:
                so_far = deltas.get(key, [0.0] * len(value))
                deltas[key] = [a + entry["weight"] * (v - r) for a, v, r in zip(so_far, value, reference[key])]
    for (node, path), d in deltas.items():
        state[node][path] = qmul(state[node][path], d) if path == "rotation" else [a + b for a, b in zip(state[node][path], d)]
    return state


def check_blends(path, reference):
    ref = json.load(gzip.open(reference))
    doc = Document(path)
    d = 0.0
    for case in ref["cases"]:
        ours = [x for mesh in skinned(doc, blended_state(doc, case), ref["meshes"]) for x in mesh]
        d = max(d, worst([ours], [case["positions"]]))
    ok = d <= TOLERANCE * ref["size"]
    print("%-28s %6d blends %.2e of the size  %s" % (os.path.basename(path), len(ref["cases"]), d / ref["size"],
                                                    "ok" if ok else "DIFFERENT"))
    return ok


def worst(ours, theirs):
    d = 0.0
    for a, b in zip(ours, theirs):
        for i in range(0, len(a), 3):
            d = max(d, math.dist(a[i:i + 3], b[i:i + 3]))
    return d


def check(path, reference):
    ref = json.load(gzip.open(reference) if reference.endswith(".gz") else open(reference))
    doc = Document(path)
    size = ref["size"]
    d = worst(positions(doc, None, 0.0, ref["rest"]), [e["positions"] for e in ref["rest"]])
    times = 1
    for clip in ref["clips"]:
        for k, t in enumerate(clip["times"]):
            ours = positions(doc, clip["index"], t, clip["meshes"])
            d = max(d, worst(ours, [e["positions"][k] for e in clip["meshes"]]))
        times += len(clip["times"])
    ok = d <= TOLERANCE * size
    print("%-28s %6d times  %.2e of the size  %s" % (os.path.basename(path), times, d / size, "ok" if ok else "DIFFERENT"))
    return ok


def pairs():
    fixtures = os.path.join(ROOT, "core", "src", "test", "resources", "gltf")
    for name in sorted(os.listdir(fixtures)):
        if name.endswith((".gltf", ".glb")):
            yield os.path.join(fixtures, name), os.path.join(fixtures, "threejs", name + ".json")
    for folder, _, files in sorted(os.walk(os.path.join(ROOT, "assets"))):
        for name in sorted(files):
            if name.endswith(".glb"):
                yield os.path.join(folder, name), os.path.join(ROOT, "assets", "reference", "threejs", name + ".json.gz")
    samples = os.environ.get("SKINLAB_GLTF_SAMPLES") or os.path.join(ROOT, "..", "shared", "gltf-samples")
    refs = os.path.join(fixtures, "threejs", "samples")
    for ref in sorted(os.listdir(refs)):
        name = ref[:ref.index(".json")]
        found = [os.path.join(samples, d, name) for d in sorted(os.listdir(samples))
                 if os.path.isfile(os.path.join(samples, d, name))] if os.path.isdir(samples) else []
        if found:
            yield found[0], os.path.join(refs, ref)
        else:
            print("%-28s skipped: not in %s" % (name, samples))


def blend_pairs():
    """(file, reference) per blend reference: the file among our assets' .glb, else among the samples."""
    folder = os.path.join(ROOT, "assets", "reference", "threejs", "blends")
    samples = os.environ.get("SKINLAB_GLTF_SAMPLES") or os.path.join(ROOT, "..", "shared", "gltf-samples")
    for ref in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        name = ref[:ref.index(".blends.json")]
        found = [os.path.join(d, name) for d, _, files in sorted(os.walk(os.path.join(ROOT, "assets"))) if name in files]
        if not found and os.path.isdir(samples):
            found = [os.path.join(samples, d, name) for d in sorted(os.listdir(samples))
                     if os.path.isfile(os.path.join(samples, d, name))]
        if found:
            yield found[0], os.path.join(folder, ref)
        else:
            print("%-28s blends skipped: not in assets/ nor %s" % (name, samples))


def main():
    bad = 0
    for path, reference in pairs():
        if not os.path.exists(reference):
            reference = reference[:-3] if reference.endswith(".gz") else reference + ".gz"
        if not check(path, reference):
            bad += 1
    for path, reference in blend_pairs():
        if not check_blends(path, reference):
            bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
