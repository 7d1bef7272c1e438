#!/usr/bin/env python3
"""Counts what the COLLADA importer should find in each corpus file, independently of it.

The expected table of core/src/test/java/org/skinlab/collada/CorpusConformanceTest.java is this
script's output. It uses nothing but the Python standard library (xml.etree) and shares no code
or logic with the Java importer: it reads the XML as plainly as possible, so that a disagreement
points at a bug on one side or the other.

Usage:  python3 core/src/test/tools/corpus_counts.py [CORPUS_DIR]   (default: ../shared/corpus)

Output, one record per line, fields separated by " | ":

  mesh | FILE | GEOMETRY_ID | POSITIONS | TRIANGLES | skinned/static | JOINTS | MAX_INFLUENCES
      one per <geometry> that holds a <mesh>, in document order.
      POSITIONS  the count of the accessor of the <vertices> POSITION source;
      TRIANGLES  the sum over <triangles>, <polylist>, <polygons>, <trifans> and <tristrips> of
                 their fan-triangulated triangle counts: an n-corner polygon, fan or strip gives
                 max(0, n - 2); <lines> and <linestrips> are not counted;
      skinned    when a <controller><skin> deforms the geometry (directly, or through the base
                 geometry of a <morph>); JOINTS is the count of that first skin's JOINT source
                 accessor and MAX_INFLUENCES the largest <vertex_weights><vcount> entry
                 (0 and 0 for static geometry).
  clip | FILE | NAME | CHANNELS
      one per <animation_clip> (NAME: its name, else its id, else clip-N counting from 1); when
      the file has no clips but has channels, one clip named "default" over all of them.
      CHANNELS counts the <channel>s of the clip's animations (nested <animation>s included)
      whose target "node/sid..." names a node of the instantiated visual scene that has a
      transform element with that sid, once per copy of the node (<instance_node> copies).
The importer warns about everything it tolerates; these records are the warnings it must give
(and, by the test, the only ones):

  lines | FILE | GEOMETRY_ID | ELEMENT
      one per <lines> or <linestrips> ELEMENT of a geometry: skipped, not drawn.
  noasset | FILE
      a file without <asset>: Y_UP and meters are assumed.
  unweighted | FILE | CONTROLLER_ID | N | POSITIONS
      a skin in which N of its POSITIONS positions have no influence (<vcount> entry 0).
  badsums | FILE | CONTROLLER_ID | N | POSITIONS
      a skin in which N positions have weights summing to more than 1e-3 away from 1.
  nomaterial | FILE | NODE_ID | TARGET
      an <instance_material> (of an instance in the visual scene) whose target names no <material>:
      drawn with the default material.
"""

import os
import sys
import xml.etree.ElementTree as ET

TRANSFORMS = {"matrix", "translate", "rotate", "scale", "lookat", "skew"}
POLYGON_PRIMITIVES = {"triangles", "polylist", "polygons", "trifans", "tristrips"}
LINE_PRIMITIVES = {"lines", "linestrips"}


def local(tag):
    """The tag without its {namespace}."""
    return tag.rsplit("}", 1)[-1]


def children(element, name):
    return [c for c in element if local(c.tag) == name]


def child(element, name):
    found = children(element, name)
    return found[0] if found else None


def ints(element):
    return [int(t) for t in (element.text or "").split()]


def ref(value):
    """'#id' -> 'id'."""
    return value[1:] if value.startswith("#") else value


class Document:
    def __init__(self, path):
        self.root = ET.parse(path).getroot()
        self.ids = {}
        for e in self.root.iter():
            i = e.get("id")
            if i is not None and i not in self.ids:
                self.ids[i] = e

    def by_id(self, value):
        return self.ids.get(ref(value))

    def libraries(self, name):
        return children(self.root, name)

    def accessor_count(self, source):
        accessor = source.find(".//{*}accessor")
        return int(accessor.get("count"))


def triangle_count(primitive):
    """Fan-triangulated triangles of one primitive element."""
    kind = local(primitive.tag)
    stride = 1 + max(int(i.get("offset")) for i in children(primitive, "input"))
    if kind == "triangles":
        return int(primitive.get("count"))
    if kind == "polylist":
        vcount = child(primitive, "vcount")
        return sum(max(0, n - 2) for n in (ints(vcount) if vcount is not None else []))
    # polygons (every <p>, and the outer <p> of every <ph>), trifans, tristrips: one polygon,
    # fan or strip per <p>.
    rings = children(primitive, "p")
    if kind == "polygons":
        rings += [child(ph, "p") for ph in children(primitive, "ph")]
    return sum(max(0, len(ints(p)) // stride - 2) for p in rings)


def skins_by_geometry(doc):
    """geometry element -> its first <skin> (document order of the controllers)."""
    result = {}
    for library in doc.libraries("library_controllers"):
        for controller in children(library, "controller"):
            skin = child(controller, "skin")
            if skin is None:
                continue
            target = doc.by_id(skin.get("source"))
            if target is not None and local(target.tag) == "controller":
                target = doc.by_id(child(target, "morph").get("source"))
            if target is not None and target not in result:
                result[target] = skin
    return result


def weight_rows(doc, name):
    """unweighted and badsums records, one per skin that has such positions."""
    rows = []
    for library in doc.libraries("library_controllers"):
        for controller in children(library, "controller"):
            skin = child(controller, "skin")
            if skin is None:
                continue
            weights = child(skin, "vertex_weights")
            inputs = children(weights, "input")
            stride = 1 + max(int(i.get("offset")) for i in inputs)
            weight_input = [i for i in inputs if i.get("semantic") == "WEIGHT"][0]
            source = doc.by_id(weight_input.get("source"))
            accessor = source.find(".//{*}accessor")
            array = [float(t) for t in doc.by_id(accessor.get("source")).text.split()]
            first, step = int(accessor.get("offset", "0")), int(accessor.get("stride", "1"))
            vcount, v = ints(child(weights, "vcount")), ints(child(weights, "v"))
            at, unweighted, badsums = 0, 0, 0
            for n in vcount:
                total = 0.0
                for k in range(n):
                    total += array[first + step * v[(at + k) * stride + int(weight_input.get("offset"))]]
                at += n
                if n == 0:
                    unweighted += 1
                elif abs(total - 1.0) > 1e-3:
                    badsums += 1
            if unweighted:
                rows.append(["unweighted", name, controller.get("id"), unweighted, len(vcount)])
            if badsums:
                rows.append(["badsums", name, controller.get("id"), badsums, len(vcount)])
    return rows


def mesh_rows(doc, name):
    skins = skins_by_geometry(doc)
    rows, lines = [], []
    for library in doc.libraries("library_geometries"):
        for geometry in children(library, "geometry"):
            mesh = child(geometry, "mesh")
            if mesh is None:
                continue
            vertices = child(mesh, "vertices")
            position = [i for i in children(vertices, "input") if i.get("semantic") == "POSITION"][0]
            positions = doc.accessor_count(doc.by_id(position.get("source")))
            triangles = sum(triangle_count(p) for p in mesh if local(p.tag) in POLYGON_PRIMITIVES)
            line_elements = [local(p.tag) for p in mesh if local(p.tag) in LINE_PRIMITIVES]
            skin = skins.get(geometry)
            if skin is None:
                rows.append(["mesh", name, geometry.get("id"), positions, triangles, "static", 0, 0])
            else:
                joint_input = [i for i in children(child(skin, "joints"), "input") if i.get("semantic") == "JOINT"][0]
                joints = doc.accessor_count(doc.by_id(joint_input.get("source")))
                vcount = child(child(skin, "vertex_weights"), "vcount")
                most = max(ints(vcount), default=0) if vcount is not None else 0
                rows.append(["mesh", name, geometry.get("id"), positions, triangles, "skinned", joints, most])
            for element in line_elements:
                lines.append(["lines", name, geometry.get("id"), element])
    return rows, lines


def visual_scene(doc):
    scene = child(doc.root, "scene")
    instance = child(scene, "instance_visual_scene") if scene is not None else None
    if instance is not None:
        return doc.by_id(instance.get("url"))
    for library in doc.libraries("library_visual_scenes"):
        first = child(library, "visual_scene")
        if first is not None:
            return first
    return None


def node_copies(doc):
    """node id -> list of node elements, one per copy in the instantiated visual scene."""
    copies = {}
    scene = visual_scene(doc)
    if scene is None:
        return copies
    todo = list(reversed(children(scene, "node")))
    while todo:
        node = todo.pop()
        if node.get("id") is not None:
            copies.setdefault(node.get("id"), []).append(node)
        for c in reversed(list(node)):
            if local(c.tag) == "node":
                todo.append(c)
            elif local(c.tag) == "instance_node":
                todo.append(doc.by_id(c.get("url")))
    return copies


def channel_count(doc, copies, animation):
    """Channels of the animation and its nested animations that drive a scene transform."""
    total = 0
    for a in animation.iter():
        if local(a.tag) != "animation":
            continue
        for channel in children(a, "channel"):
            target = channel.get("target")
            if "/" not in target:
                continue
            node_id, rest = target.split("/", 1)
            sid = rest
            for stop in ".(":
                sid = sid.split(stop, 1)[0]
            for node in copies.get(node_id, []):
                if any(local(t.tag) in TRANSFORMS and t.get("sid") == sid for t in node):
                    total += 1
    return total


def clip_rows(doc, name):
    copies = node_copies(doc)
    top_level = [a for library in doc.libraries("library_animations") for a in children(library, "animation")]
    clips = [c for library in doc.libraries("library_animation_clips") for c in children(library, "animation_clip")]
    rows = []
    for n, clip in enumerate(clips, 1):
        channels = sum(channel_count(doc, copies, doc.by_id(i.get("url"))) for i in children(clip, "instance_animation"))
        rows.append(["clip", name, clip.get("name") or clip.get("id") or "clip-%d" % n, channels])
    if not clips:
        channels = sum(channel_count(doc, copies, a) for a in top_level)
        if channels:
            rows.append(["clip", name, "default", channels])
    return rows


def material_rows(doc, name):
    """nomaterial records: bound material targets that name no <material>."""
    rows = []
    scene = visual_scene(doc)
    if scene is None:
        return rows
    for node in scene.iter():
        if local(node.tag) != "node":
            continue
        for instance in node:
            if local(instance.tag) not in ("instance_geometry", "instance_controller"):
                continue
            for bound in instance.iter():
                if local(bound.tag) != "instance_material":
                    continue
                target = doc.by_id(bound.get("target", ""))
                if target is None or local(target.tag) != "material":
                    rows.append(["nomaterial", name, node.get("id"), bound.get("target")])
    return rows


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    corpus = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "..", "..", "..", "shared", "corpus")
    for name in sorted(f for f in os.listdir(corpus) if f.lower().endswith(".dae")):
        doc = Document(os.path.join(corpus, name))
        meshes, lines = mesh_rows(doc, name)
        for row in meshes + clip_rows(doc, name) + lines:
            print(" | ".join(str(v) for v in row))
        if child(doc.root, "asset") is None:
            print("noasset | " + name)
        for row in weight_rows(doc, name) + material_rows(doc, name):
            print(" | ".join(str(v) for v in row))


if __name__ == "__main__":
    main()
