#!/usr/bin/env python3
"""Writes the hand-made seeds of GltfImporterFuzzTest into
core/src/test/resources/org/skinlab/gltf/fuzz-seeds/ (run from the repository root).

Each seed is small (a few hundred bytes to a few kilobytes: the fuzzer mutates small inputs
fastest) and valid glTF 2.0 (the glTF-Validator finds no error in any of them), and together they
reach every part of the importer: .gltf with data URIs and .glb with a BIN chunk; indexed and
unindexed triangles, strips and fans; byte, short and float data, normalized integers, an
interleaved view with byteStride, a sparse accessor, KHR_mesh_quantization; a skin with inverse
bind matrices, skeleton and two JOINTS/WEIGHTS sets; morph targets with default weights; LINEAR,
STEP and CUBICSPLINE animation of translation, rotation, scale and weights; a material with
textures, KHR_texture_transform, alpha mode and double-sidedness; a camera and a matrix node.
"""
import base64
import json
import os
import struct

OUT = "core/src/test/resources/org/skinlab/gltf/fuzz-seeds"


class Builder:
    """Collects binary data into one buffer, 4-byte aligned, and the views and accessors over it."""

    def __init__(self):
        self.data = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "gltf_fuzz_seeds.py"},
                    "bufferViews": [], "accessors": []}

    def view(self, blob, target=None, stride=None):
        while len(self.data) % 4:
            self.data.append(0)
        v = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(blob)}
        if target:
            v["target"] = target
        if stride:
            v["byteStride"] = stride
        self.data += blob
        self.doc["bufferViews"].append(v)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, fmt, ctype, atype, values, per, target=None, bounds=False, normalized=False):
        blob = struct.pack("<%d%s" % (len(values), fmt), *values)
        a = {"bufferView": self.view(blob, target), "componentType": ctype, "count": len(values) // per,
             "type": atype}
        if normalized:
            a["normalized"] = True
        if bounds:
            a["min"] = [min(values[i::per]) for i in range(per)]
            a["max"] = [max(values[i::per]) for i in range(per)]
        self.doc["accessors"].append(a)
        return len(self.doc["accessors"]) - 1

    def floats(self, atype, values, per, target=None, bounds=False):
        return self.accessor("f", 5126, atype, values, per, target, bounds)

    def gltf(self):
        doc = dict(self.doc)
        doc["buffers"] = [{"byteLength": len(self.data),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(self.data).decode()}]
        return json.dumps(doc, separators=(",", ":")).encode()

    def glb(self):
        doc = dict(self.doc)
        doc["buffers"] = [{"byteLength": len(self.data)}]
        js = json.dumps(doc, separators=(",", ":")).encode()
        js += b" " * (-len(js) % 4)
        binary = bytes(self.data) + b"\0" * (-len(self.data) % 4)
        body = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(binary), b"BIN\0") + binary
        return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


QUAD = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]
QUAD_INDICES = [0, 1, 2, 0, 2, 3]


def triangle_strip_and_fan():
    b = Builder()
    pos = b.floats("VEC3", QUAD, 3, 34962, bounds=True)
    idx = b.accessor("B", 5121, "SCALAR", [0, 1, 3, 2], 1, 34963, bounds=True)
    b.doc["meshes"] = [{"primitives": [
        {"attributes": {"POSITION": pos}, "indices": idx, "mode": 5},
        {"attributes": {"POSITION": pos}, "mode": 6},
        {"attributes": {"POSITION": pos}, "indices": b.accessor("I", 5125, "SCALAR", QUAD_INDICES, 1, 34963, bounds=True),
         "mode": 4}]}]
    b.doc["nodes"] = [{"mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1]}]
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["scene"] = 0
    return b


def skinned(cubic, glb):
    """Two joints bending a quad, with a second influence set and an animation of every path."""
    b = Builder()
    # Interleaved positions and normals (byteStride 24).
    inter = []
    for i in range(4):
        inter += QUAD[3 * i:3 * i + 3] + [0, 0, 1]
    view = b.view(struct.pack("<24f", *inter), 34962, 24)
    b.doc["accessors"] += [
        {"bufferView": view, "componentType": 5126, "count": 4, "type": "VEC3",
         "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": view, "byteOffset": 12, "componentType": 5126, "count": 4, "type": "VEC3"}]
    idx = b.accessor("H", 5123, "SCALAR", QUAD_INDICES, 1, 34963, bounds=True)
    uv = b.accessor("H", 5123, "VEC2", [0, 0, 65535, 0, 65535, 65535, 0, 65535], 2, 34962, normalized=True)
    joints0 = b.accessor("B", 5121, "VEC4", [0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0], 4, 34962)
    weights0 = b.accessor("B", 5121, "VEC4", [255, 0, 0, 0, 128, 127, 0, 0, 255, 0, 0, 0, 200, 55, 0, 0], 4, 34962,
                          normalized=True)
    joints1 = b.accessor("B", 5121, "VEC4", [0] * 16, 4, 34962)
    weights1 = b.accessor("f", 5126, "VEC4", [0.0] * 16, 4, 34962)
    ibm = b.floats("MAT4", [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -0.5, 0, 1], 16)
    target = b.floats("VEC3", [0, 0, 0.5] * 4, 3, 34962, bounds=True)
    b.doc["meshes"] = [{"primitives": [{
        "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": uv, "JOINTS_0": joints0, "WEIGHTS_0": weights0,
                       "JOINTS_1": joints1, "WEIGHTS_1": weights1},
        "indices": idx, "material": 0, "targets": [{"POSITION": target}]}], "weights": [0.25]}]
    b.doc["skins"] = [{"joints": [1, 2], "inverseBindMatrices": ibm, "skeleton": 1}]
    b.doc["nodes"] = [{"mesh": 0, "skin": 0, "name": "skinned"},
                      {"children": [2], "name": "root", "translation": [0, 0, 0]},
                      {"name": "tip", "translation": [0, 0.5, 0], "rotation": [0, 0, 0, 1], "scale": [1, 1, 1]}]
    b.doc["scenes"] = [{"nodes": [0, 1]}]
    times = b.floats("SCALAR", [0, 0.5, 1], 1, bounds=True)
    k = 3 if cubic else 1
    s = 0.38268343
    c = 0.9238795
    rot = []
    for q in ([0, 0, 0, 1], [0, 0, s, c], [0, 0, 0, 1]):
        rot += ([0, 0, 0, 0] + q + [0, 0, 0, 0]) if cubic else q
    tr = []
    for v in ([0, 0.5, 0], [0, 0.6, 0], [0, 0.5, 0]):
        tr += ([0, 0, 0] + v + [0, 0, 0]) if cubic else v
    sc = [1.0] * 9 * k
    wt = ([0, 0, 0] if cubic else []) and []
    wt = []
    for w in (0.0, 1.0, 0.0):
        wt += [0.0, w, 0.0] if cubic else [w]
    interp = "CUBICSPLINE" if cubic else "LINEAR"
    b.doc["animations"] = [{"name": "bend", "samplers": [
        {"input": times, "output": b.floats("VEC4", rot, 4), "interpolation": interp},
        {"input": times, "output": b.floats("VEC3", tr, 3), "interpolation": interp},
        {"input": times, "output": b.floats("VEC3", sc, 3), "interpolation": "STEP" if not cubic else interp},
        {"input": times, "output": b.floats("SCALAR", wt, 1), "interpolation": interp}],
        "channels": [
            {"sampler": 0, "target": {"node": 2, "path": "rotation"}},
            {"sampler": 1, "target": {"node": 2, "path": "translation"}},
            {"sampler": 2, "target": {"node": 1, "path": "scale"}},
            {"sampler": 3, "target": {"node": 0, "path": "weights"}}]}]
    b.doc["materials"] = [{"name": "skin", "pbrMetallicRoughness": {
        "baseColorFactor": [1, 0.5, 0.5, 1], "baseColorTexture": {"index": 0, "texCoord": 0,
                                                                  "extensions": {"KHR_texture_transform": {
                                                                      "offset": [0.5, 0], "scale": [2, 2],
                                                                      "rotation": 0.1}}},
        "metallicFactor": 0, "roughnessFactor": 0.8},
        "emissiveFactor": [0.1, 0, 0], "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": True}]
    b.doc["textures"] = [{"source": 0, "sampler": 0}]
    b.doc["samplers"] = [{"magFilter": 9729, "minFilter": 9987, "wrapS": 33648, "wrapT": 33071}]
    # A 1x1 PNG, embedded as a data URI (never decoded by the importer).
    png = base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==")
    if glb:
        b.doc["images"] = [{"bufferView": b.view(png), "mimeType": "image/png"}]
    else:
        b.doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png).decode()}]
    b.doc["extensionsUsed"] = ["KHR_texture_transform"]
    return b


def sparse_quantized():
    """Quantized positions (KHR_mesh_quantization) moved by a sparse accessor, and a camera."""
    b = Builder()
    # Short VEC3 positions padded to 8 bytes (byteStride 8: vertex data is 4-byte aligned).
    quantized = [0, 0, 0, 100, 0, 0, 100, 100, 0, 0, 100, 0]
    padded = []
    for i in range(4):
        padded += quantized[3 * i:3 * i + 3] + [0]
    b.doc["accessors"].append({"bufferView": b.view(struct.pack("<16h", *padded), 34962, 8), "componentType": 5122,
                               "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [100, 100, 0]})
    pos = len(b.doc["accessors"]) - 1
    idx = b.accessor("B", 5121, "SCALAR", QUAD_INDICES, 1, 34963, bounds=True)
    base = b.floats("VEC3", [0.0] * 12, 3)
    idx_view = b.view(struct.pack("<2H", 1, 3))
    val_view = b.view(struct.pack("<6f", 0, 0, 1, 0, 0, -1))
    acc = b.doc["accessors"][base]
    acc["sparse"] = {"count": 2, "indices": {"bufferView": idx_view, "componentType": 5123},
                     "values": {"bufferView": val_view}}
    acc["min"] = [0, 0, -1]
    acc["max"] = [0, 0, 1]
    b.doc["meshes"] = [{"primitives": [{"attributes": {"POSITION": pos}, "indices": idx,
                                        "targets": [{"POSITION": base}]}]}]
    b.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.01, "zfar": 100}}]
    b.doc["nodes"] = [{"mesh": 0, "scale": [0.01, 0.01, 0.01], "weights": [0.5]}, {"camera": 0}]
    b.doc["scenes"] = [{"nodes": [0, 1]}]
    b.doc["extensionsUsed"] = ["KHR_mesh_quantization"]
    b.doc["extensionsRequired"] = ["KHR_mesh_quantization"]
    return b


def main():
    os.makedirs(OUT, exist_ok=True)
    seeds = {
        "strip-fan-matrix.gltf": triangle_strip_and_fan().gltf(),
        "skinned-linear.gltf": skinned(False, False).gltf(),
        "skinned-cubic.glb": skinned(True, True).glb(),
        "sparse-quantized.glb": sparse_quantized().glb(),
    }
    for name, data in seeds.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)
        print(name, len(data), "bytes")


if __name__ == "__main__":
    main()
