#!/usr/bin/env python3
"""What the COLLADA importer must produce for each file of the Khronos conformance suite subset.

An independent reader in the manner of corpus_counts.py (whose small helpers and channel count it
imports; its own output is unchanged): Python standard library only (zipfile, xml.etree,
posixpath, math, urllib.parse.unquote, re, hashlib), no code or logic shared with the Java
importer, the XML read as plainly as possible, so that a disagreement points at a bug on one side
or the other. Its output is core/src/test/resources/conformance/cts-1.4.1-expected.txt; the first
comment lines name the archive (with its sha256) and the suite's commit.

Usage:  python3 core/src/test/tools/cts_expected.py [ZIP]
        (default: ../shared/cts/collada-cts-1.4.1-subset.zip relative to the repository root)

The archive is read in place. Every entry ending in .dae is one file, in sorted entry-path order;
PATH below is the entry path (StandardDataSets/collada/...). Output: a few "#" comment lines, then
one record per line, fields separated by " | ", per file in this order: file, mesh, morph, scene,
instance, material, clip, quirk.

References (URLs)
  A URL "doc#id" names the element with that id in this document when its document part is empty,
  or when it resolves to PATH itself (percent-decoded, joined with PATH's directory and normalised:
  "self.dae#x", "./one_dot.dae#x", "../two_dots/two_dots.dae#x"): a self-url quirk. Any other
  non-empty document part points into another document. Ids: the first element carrying the id.
  <skeleton> text is such a URL too.

  file | PATH | loaded
  file | PATH | refused | REASON
      REASON malformed-xml: xml.etree cannot parse the file.
      REASON another-document: a reference the importer follows points into another document;
      the references checked (anywhere in the document) are <scene><instance_visual_scene url>,
      <instance_node url>, <instance_geometry url>, <instance_controller url>, <skin source>,
      <morph source>, <input source> and <accessor source> inside library_geometries,
      library_controllers and library_animations, <channel source>, <instance_animation url> and
      <skeleton> text. Image <init_from>, <instance_material target> and <instance_effect url>
      are not followed that way: materials are optional, an external or dangling one gives "-".
      A refused file has no other record.

  mesh | PATH | ID | POSITIONS | TRIANGLES | skinned/static | JOINTS | MAX_INFLUENCES
      One per <geometry> holding a <mesh>, in document order (ID: the geometry id); then one per
      morph controller whose base (its <morph source>, followed through other morph controllers)
      is a geometry holding a mesh, in document order of the controllers (ID: the morph
      controller's id; POSITIONS and TRIANGLES those of its base geometry).
      POSITIONS  the count attribute of the accessor of the <vertices> POSITION source (2-D
                 positions count the same, they get z = 0).
      TRIANGLES  from the data present, not from count attributes; stride = 1 + the largest input
                 offset (offset absent: 0) of the primitive:
                   <triangles>: len(all <p> ints) // (3 * stride);
                   <polylist>: sum over <vcount> of max(0, n - 2);
                   <polygons> (every <p>, and the outer <p> of every <ph>), <trifans>,
                   <tristrips>: per <p>, max(0, len // stride - 2);
                 <lines> and <linestrips> are not counted.
      skinned    a geometry is skinned when the first <skin> (document order) whose source is that
                 geometry deforms it; a morph controller's mesh is skinned when the first
                 <skin source="#thatMorphController"> deforms it (a skin on a morph deforms the
                 morphed mesh, no longer the base geometry). JOINTS: the count attribute of the
                 accessor of that skin's <joints> JOINT source; MAX_INFLUENCES: the largest
                 <vertex_weights><vcount> entry. Static: 0 and 0.

  morph | PATH | CONTROLLER_ID | BASE_GEOMETRY_ID | TARGETS | METHOD | SX SY SZ
      One per morph controller with a geometry base (the same controllers, in the same order, as
      its mesh record; a morph on a skin has neither record). METHOD: the method attribute,
      NORMALIZED when absent. Targets: the MORPH_TARGET IDREF_array and MORPH_WEIGHT float_array
      of the <targets> inputs, paired by index (as many pairs as both arrays, read through their
      accessors, provide). A target that is not a geometry holding a mesh, or with fewer
      POSITIONS than the base, is left out (one with more contributes its first ones); TARGETS
      counts the ones used. Per position index,
      with B the base positions (for a morph on a morph: the inner morph's result) and T_i
      target i's positions:
          NORMALIZED  P = (1 - sum w_i) * B + sum w_i * T_i
          RELATIVE    P = B + sum w_i * T_i
      Positions are read through the accessor (offset, stride; x, y, z are the first three named
      params, or the first three params when none is named); missing components, and values
      past the end of a short array, are 0 (2-D positions get z = 0). Weights past the end of
      their array do not exist (no pair). SX SY SZ: the sums over all positions of x, y and z of
      P, in index order in double precision, each "%.4f" ("-0.0000" is written "0.0000").

  scene | PATH | NODES | INSTANCES
      The instantiated visual scene: the one <scene><instance_visual_scene> names, else the
      first <visual_scene>. NODES: its nodes, depth-first, with every <instance_node> expanded in
      place (a copy of the target node's subtree per instance; children and instance_nodes in
      document order), plus extra roots appended after the scene's own nodes, in order of first
      mention:
        - for each <instance_controller> in instance order (see below), each of its <skeleton>s
          that names a <node> inside <library_nodes> which is not part of the scene (no
          <instance_node> placed it, no extra root holds it): that node's subtree;
        - then, for the skin that instance deforms with (a skin controller, or the skin under a
          morph on a skin), each joint that matches no node of the scene (IDREF_array: by id;
          Name_array: by sid, id or name) but names a node inside <library_nodes> (same
          matching): the outermost <library_nodes> node holding it.
      Extra roots are themselves searched for instances (they extend the instance order). A
      <skeleton> naming anything else (a scene node, a <visual_scene>, nothing) adds nothing.
      No visual scene at all: 0 nodes. INSTANCES: the number of instance records.

  instance | PATH | ORDINAL | NODE_ID | MESH_ID | skinned/static
      Every <instance_geometry> and <instance_controller> of the scene (extra roots included),
      nodes depth-first, within a node in document order; ORDINAL counts from 0; NODE_ID is the
      holding node's id, or "-". MESH_ID and kind:
        instance_geometry: the geometry id, static (no record when it is not a geometry holding
          a mesh);
        instance_controller of a skin: the mesh the skin deforms (the geometry id, or the morph
          controller id for a skin on a morph), skinned;
        of a morph with a geometry base: the morph controller's id, static;
        of a morph whose base (through morphs) is a skin (morph on skin): the skin's mesh,
          skinned (the morph is ignored).
      No record when the reference dangles or leads to no mesh.

  material | PATH | MESH_ID | SYMBOL | NAME | DIFFUSE | TEXTURE
      For each mesh record, in its order: the distinct material attributes of its polygon
      primitives (the base geometry's for a morph; lines excluded; primitives without the
      attribute give nothing), in order of first appearance, bound through the first instance
      record with that MESH_ID (none: NAME, DIFFUSE and TEXTURE are "-"). Binding: the first
      <bind_material><technique_common><instance_material> with that symbol; its target
      <material>: NAME is its name attribute (if non-empty), else its id; "-" when unbound or the
      target dangles or is in another document. Then <instance_effect url> -> <effect>; its first
      <profile_COMMON>; that profile's first <technique>; the first of its <constant>, <lambert>,
      <phong>, <blinn> children. Parameters are looked up in the material's <instance_effect>
      <setparam ref="X"> first, then <newparam sid="X"> in the technique, the profile, the effect.
      DIFFUSE: that shading's <diffuse> as <color> ("r g b a", each "%g"; 3 values get alpha 1),
        or <param ref="X"> resolved to the parameter holding <float4>/<float3>; "-" when there is
        no diffuse colour (constant shading, a texture, nothing, or an unresolvable param).
      TEXTURE: the texture the material shows: its diffuse's, or for <constant> shading its
        <emission>'s. A <texture texture="S">: S names a parameter (same search) holding
        <sampler2D>, whose <source> text is
        the sid of a <newparam> (same search) holding <surface>, whose <init_from> text is an
        <image> id (1.5 style: <sampler2D><instance_image url="#img">); when S names no such
        newparam but is the id of an <image>: that image. The image's <init_from> text (1.4.1) or
        <init_from><ref> (1.5) is a URI, read as exporters write it: "\\" turned into "/"; a
        "file:" scheme removed ("file:///x" is "/x", "file://localhost/x" is "/x", "file://x" is
        the relative path "x", as 3ds Max and FBX mean it); any other scheme ("http:", ...): "-";
        percent-decoded; "/C:/x" is "C:/x"; a leading "/" before "../" or "./" dropped (no root
        is climbed above); "../../C:/x" (a relative path to another drive) is "C:/x"; absolute
        ("/..." or a drive letter "X:/") kept; else joined with PATH's directory and normalised
        (posixpath.normpath). "-" when not a texture or unresolvable.

  clip | PATH | NAME | CHANNELS
      As corpus_counts.py (one per <animation_clip>, NAME its name, else id, else clip-N; no
      clips but channels: one clip "default"; CHANNELS: channels whose target "node/sid..."
      names a scene node having a transform with that sid, once per copy of the node), with the
      scene as above (extra roots included) and <instance_animation url> resolved as a URL. An
      animation a clip instances several times (or also through an outer animation) counts once.

  quirk | PATH | KIND
      Once per file per kind, in this order of kinds, for what the importer reads: every
      geometry (mesh, its sources, vertices and polygon primitives), every controller, the
      instantiated scene's nodes (transforms), <asset><unit meter>, every animation:
        decimal-comma   a float written with a comma as decimal separator ("0,01", read as
                        0.01), in a float array, a node transform, <bind_shape_matrix>, a
                        diffuse colour that is used, or <unit meter>;
        unnamed-params  an accessor with at least one <param>, none of which has a name;
        2d-positions    a POSITION accessor with fewer than three components;
        count-mismatch  an array whose count attribute differs from the number of values
                        present; an accessor reaching past the end of its array (offset +
                        (count - 1) * stride + the values its params span > values present;
                        a float4x4 param spans 16, float3x3 9, float2x2 and float4 4, float3 3,
                        float2 2, others 1; no params: stride); a primitive whose count attribute
                        differs from its data (triangles: p ints // (3 * stride); polylist:
                        vcount entries, and p ints != sum(vcount) * stride; polygons: <p>s +
                        <ph>s; trifans, tristrips, linestrips: <p>s; lines: p ints //
                        (2 * stride)); a <vertex_weights count> != its vcount entries;
        non-finite      NaN or INF in a source used by a TEXCOORD, NORMAL or COLOR input (of
                        <vertices> or of a polygon primitive);
        dropped-input   in a polygon primitive, an index of a TEXCOORD/NORMAL/COLOR input out of
                        the range of its source's accessor count (for inputs of <vertices>: the
                        VERTEX index): that input is dropped for the primitive;
        self-url        a followed URL (or a material/effect one) naming this document by name;
        vertex-ref      a primitive's VERTEX input whose source names no element, or an element
                        other than the mesh's own <vertices> (which is used instead);
        accessor-ref    an accessor whose source dangles (names nothing in this document, or
                        no array) while its <source> holds exactly one array (that array is
                        used; with no or several arrays the source has no values);
        library-skeleton  an extra root was appended to the scene;
        morph-on-skin   a morph controller whose base (through morphs) is a skin controller.
"""

import hashlib
import math
import os
import posixpath
import re
import sys
import zipfile
import xml.etree.ElementTree as ET
from urllib.parse import unquote

sys.dont_write_bytecode = True  # importing corpus_counts must leave no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_counts import LINE_PRIMITIVES, POLYGON_PRIMITIVES, channel_count, child, children, local  # noqa: E402

SUITE = "KhronosGroup/COLLADA-CTS"
SUITE_COMMIT = "61f2a560cbb2a06ee62da8025241f6b08d06bfd9"
QUIRK_ORDER = ["decimal-comma", "unnamed-params", "2d-positions", "count-mismatch", "non-finite",
               "dropped-input", "self-url", "vertex-ref", "accessor-ref", "library-skeleton",
               "morph-on-skin"]
OPTIONAL_INPUTS = {"TEXCOORD", "NORMAL", "COLOR"}
SHADINGS = ("constant", "lambert", "phong", "blinn")
PARAM_SIZES = {"float2": 2, "float3": 3, "float4": 4, "float2x2": 4, "float3x3": 9, "float4x4": 16}
ARRAYS = {"float_array", "int_array", "bool_array", "Name_array", "IDREF_array", "SIDREF_array"}
DECIMAL_COMMA = re.compile(r"^[+-]?[0-9]*,[0-9]+([eE][+-]?[0-9]+)?$")
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]+:")
DRIVE = re.compile(r"^[A-Za-z]:/")


class External(Exception):
    """A followed reference points into another document."""


class Cts:
    def __init__(self, path, root):
        self.path = path
        self.root = root
        self.quirks = set()
        self.ids = {}
        self.parent = {}
        for e in root.iter():
            for c in e:
                self.parent[c] = e
            i = e.get("id")
            if i is not None and i not in self.ids:
                self.ids[i] = e

    # ---- references ---------------------------------------------------------------------------

    def split(self, url):
        """(document part, fragment) of a URL; document part "" when it is this document."""
        url = (url or "").strip()
        document, _, fragment = url.partition("#")
        if document:
            here = posixpath.normpath(posixpath.join(posixpath.dirname(self.path), unquote(document)))
            if here == self.path:
                self.quirks.add("self-url")
                document = ""
        return document, unquote(fragment)

    def points_elsewhere(self, url):
        return self.split(url)[0] != ""

    def element(self, url):
        """The element a URL names in this document, or None (dangling or in another document)."""
        document, fragment = self.split(url)
        if document:
            return None
        return self.ids.get(fragment)

    def check_external(self):
        """Raises External when a reference the importer follows points into another document."""
        followed = []
        scene = child(self.root, "scene")
        if scene is not None:
            followed += [i.get("url") for i in children(scene, "instance_visual_scene")]
        for e in self.root.iter():
            kind = local(e.tag)
            if kind in ("instance_node", "instance_geometry", "instance_controller"):
                followed.append(e.get("url"))
            elif kind in ("skin", "morph", "channel"):
                followed.append(e.get("source"))
            elif kind == "instance_animation":
                followed.append(e.get("url"))
            elif kind == "skeleton":
                followed.append(e.text)
        for name in ("library_geometries", "library_controllers", "library_animations"):
            for library in children(self.root, name):
                for e in library.iter():
                    if local(e.tag) in ("input", "accessor"):
                        followed.append(e.get("source"))
        for url in followed:
            if url is not None and self.points_elsewhere(url):
                raise External(url)

    # ---- numbers and sources ------------------------------------------------------------------

    def floats(self, text):
        values = []
        for token in (text or "").split():
            if DECIMAL_COMMA.match(token):
                self.quirks.add("decimal-comma")
                token = token.replace(",", ".")
            values.append(float(token))
        return values

    def array_of(self, source):
        """The array element an accessor of <source> reads, with the accessor (either may be None)."""
        accessor = source.find("{*}technique_common/{*}accessor")
        if accessor is None:
            return None, None
        target = self.element(accessor.get("source"))
        if target is None or local(target.tag) not in ARRAYS:
            arrays = [c for c in source if local(c.tag) in ARRAYS]
            if len(arrays) != 1:
                return None, accessor
            self.quirks.add("accessor-ref")
            target = arrays[0]
        return target, accessor

    def components(self, accessor):
        """Indices, within one stride, of the values an accessor's params select."""
        params = children(accessor, "param")
        named = [k for k, p in enumerate(params) if p.get("name")]
        if params and not named:
            return list(range(len(params)))
        if params:
            return named
        return list(range(int(accessor.get("stride", "1"))))

    def tuples(self, source, present_only=False):
        """The accessor's count tuples of a float source, each the values its params select;
        values past the end of the array are 0 (present_only: such tuples are left out)."""
        array, accessor = self.array_of(source)
        if array is None:
            return []
        values = self.floats(array.text)
        first, step = int(accessor.get("offset", "0")), int(accessor.get("stride", "1"))
        picks = self.components(accessor)
        result = []
        for i in range(int(accessor.get("count"))):
            at = first + i * step
            if present_only and at + max(picks, default=0) >= len(values):
                break
            result.append([values[at + k] if at + k < len(values) else 0.0 for k in picks])
        return result

    def names(self, source):
        """The accessor's values of a Name_array/IDREF_array source, and the array kind."""
        if source is None:
            return [], None
        array, accessor = self.array_of(source)
        if array is None:
            return [], None
        values = (array.text or "").split()
        first, step = int(accessor.get("offset", "0")), int(accessor.get("stride", "1"))
        return [values[first + i * step] for i in range(int(accessor.get("count")))
                if first + i * step < len(values)], local(array.tag)

    def accessor_count(self, source):
        accessor = source.find("{*}technique_common/{*}accessor")
        return int(accessor.get("count"))

    # ---- meshes --------------------------------------------------------------------------------

    def geometries(self):
        return [g for library in children(self.root, "library_geometries") for g in children(library, "geometry")]

    def controllers(self):
        return [c for library in children(self.root, "library_controllers") for c in children(library, "controller")]

    def position_source(self, mesh):
        vertices = child(mesh, "vertices")
        position = [i for i in children(vertices, "input") if i.get("semantic") == "POSITION"][0]
        return self.element(position.get("source"))

    def positions(self, geometry):
        """Positions of a geometry's mesh as [x, y, z] lists."""
        return [(p + [0.0, 0.0, 0.0])[:3] for p in self.tuples(self.position_source(child(geometry, "mesh")))]

    def mesh_of(self, element):
        """A geometry element holding a mesh, else None."""
        if element is not None and local(element.tag) == "geometry" and child(element, "mesh") is not None:
            return element
        return None

    def morph_chain(self, controller):
        """(morph controllers from outermost to innermost, the element at the end of the chain)."""
        chain = []
        element = controller
        while element is not None and local(element.tag) == "controller" and child(element, "morph") is not None:
            if element in chain:
                return chain, None
            chain.append(element)
            element = self.element(child(element, "morph").get("source"))
        return chain, element

    def morph_base(self, controller):
        """The geometry (with mesh) at the base of a morph controller, else None."""
        return self.mesh_of(self.morph_chain(controller)[1])

    def skins(self):
        """deformed element (geometry or morph controller) -> its first <skin>."""
        result = {}
        for controller in self.controllers():
            skin = child(controller, "skin")
            if skin is None:
                continue
            target = self.element(skin.get("source"))
            if target is not None and target not in result:
                result[target] = skin
        return result

    def skin_counts(self, skin):
        joint_input = [i for i in children(child(skin, "joints"), "input") if i.get("semantic") == "JOINT"][0]
        joints = self.accessor_count(self.element(joint_input.get("source")))
        vcount = child(child(skin, "vertex_weights"), "vcount")
        most = max([int(t) for t in (vcount.text or "").split()], default=0) if vcount is not None else 0
        return joints, most

    def triangles(self, mesh):
        total = 0
        for primitive in mesh:
            kind = local(primitive.tag)
            if kind not in POLYGON_PRIMITIVES:
                continue
            stride = self.stride(primitive)
            if kind == "triangles":
                total += sum(len(ints(p)) for p in children(primitive, "p")) // (3 * stride)
            elif kind == "polylist":
                total += sum(max(0, n - 2) for n in ints(child(primitive, "vcount")))
            else:
                total += sum(max(0, len(ints(p)) // stride - 2) for p in rings(primitive))
        return total

    def stride(self, primitive):
        return 1 + max([int(i.get("offset", "0")) for i in children(primitive, "input")], default=0)

    def symbols(self, mesh):
        result = []
        for primitive in mesh:
            if local(primitive.tag) in POLYGON_PRIMITIVES:
                symbol = primitive.get("material")
                if symbol is not None and symbol not in result:
                    result.append(symbol)
        return result

    def morph_result(self, controller):
        """(morphed positions, targets used) of a morph controller with a geometry base."""
        morph = child(controller, "morph")
        inner = self.element(morph.get("source"))
        if self.mesh_of(inner) is not None:
            base = self.positions(inner)
        else:
            base = self.morph_result(inner)[0]
        count = len(base)
        targets, weights = [], []
        for i in children(child(morph, "targets"), "input"):
            source = self.element(i.get("source"))
            if source is None:
                continue
            if i.get("semantic") == "MORPH_TARGET":
                targets = self.names(source)[0]
            elif i.get("semantic") == "MORPH_WEIGHT":
                weights = [t[0] for t in self.tuples(source, present_only=True) if t]
        used = []
        for target, weight in zip(targets, weights):
            geometry = self.mesh_of(self.ids.get(target))
            if geometry is None:
                continue
            if self.accessor_count(self.position_source(child(geometry, "mesh"))) < count:
                continue
            used.append((weight, self.positions(geometry)))
        total = sum(w for w, _ in used)
        relative = morph.get("method", "NORMALIZED") == "RELATIVE"
        result = []
        for k, b in enumerate(base):
            p = list(b) if relative else [(1.0 - total) * v for v in b]
            for w, t in used:
                p = [p[c] + w * t[k][c] for c in range(3)]
            result.append(p)
        return result, len(used)

    # ---- scene ---------------------------------------------------------------------------------

    def visual_scene(self):
        scene = child(self.root, "scene")
        instance = child(scene, "instance_visual_scene") if scene is not None else None
        if instance is not None:
            return self.element(instance.get("url"))
        for library in children(self.root, "library_visual_scenes"):
            first = child(library, "visual_scene")
            if first is not None:
                return first
        return None

    def expand(self, node, out, stack=()):
        """Appends node and its subtree (instance_nodes expanded) depth-first to out."""
        out.append(node)
        for c in node:
            if local(c.tag) == "node":
                self.expand(c, out, stack + (node,))
            elif local(c.tag) == "instance_node":
                target = self.element(c.get("url"))
                if target is not None and local(target.tag) == "node" and target not in stack + (node,):
                    self.expand(target, out, stack + (node,))

    def in_library_nodes(self, element):
        """The outermost <library_nodes> <node> holding element, else None."""
        outer = None
        while element is not None:
            up = self.parent.get(element)
            if up is not None and local(up.tag) == "library_nodes":
                outer = element
            element = up
        return outer

    def scene(self):
        """(node copies in order, instance list of (node, instance element), extra root count)."""
        nodes = []
        visual_scene = self.visual_scene()
        if visual_scene is not None:
            for n in children(visual_scene, "node"):
                self.expand(n, nodes)
        library = [n for lib in children(self.root, "library_nodes") for n in lib.iter() if local(n.tag) == "node"]
        instances = []
        done = 0
        extra = 0
        while done < len(nodes):
            node = nodes[done]
            done += 1
            for c in node:
                if local(c.tag) not in ("instance_geometry", "instance_controller"):
                    continue
                instances.append((node, c))
                if local(c.tag) != "instance_controller":
                    continue
                # skeletons, then the joints of its skin
                for skeleton in children(c, "skeleton"):
                    target = self.element(skeleton.text)
                    if (target is not None and local(target.tag) == "node" and target not in nodes
                            and self.in_library_nodes(target) is not None):
                        self.expand(target, nodes)
                        extra += 1
                skin = self.skin_of_instance(c)
                if skin is None:
                    continue
                joint_input = [i for i in children(child(skin, "joints"), "input") if i.get("semantic") == "JOINT"]
                if not joint_input:
                    continue
                joints, kind = self.names(self.element(joint_input[0].get("source")))
                for joint in joints:
                    if any(self.joint_matches(n, joint, kind) for n in nodes):
                        continue
                    found = [n for n in library if self.joint_matches(n, joint, kind)]
                    if found:
                        outer = self.in_library_nodes(found[0])
                        if outer not in nodes:
                            self.expand(outer, nodes)
                            extra += 1
        return nodes, instances, extra

    def joint_matches(self, node, joint, kind):
        if kind == "IDREF_array":
            return node.get("id") == joint
        return joint in (node.get("sid"), node.get("id"), node.get("name"))

    def skin_of_instance(self, instance):
        controller = self.element(instance.get("url"))
        if controller is None or local(controller.tag) != "controller":
            return None
        if child(controller, "skin") is not None:
            return child(controller, "skin")
        end = self.morph_chain(controller)[1]
        if end is not None and local(end.tag) == "controller" and child(end, "skin") is not None:
            return child(end, "skin")
        return None

    def instance_mesh(self, instance):
        """(MESH_ID, skinned/static) of an instance element, or None."""
        target = self.element(instance.get("url"))
        if local(instance.tag) == "instance_geometry":
            geometry = self.mesh_of(target)
            return (geometry.get("id"), "static") if geometry is not None else None
        if target is None or local(target.tag) != "controller":
            return None
        skin = child(target, "skin")
        if skin is None:
            chain, end = self.morph_chain(target)
            if not chain:
                return None
            if self.mesh_of(end) is not None:
                return target.get("id"), "static"
            if end is None or local(end.tag) != "controller" or child(end, "skin") is None:
                return None
            skin = child(end, "skin")
        deformed = self.element(skin.get("source"))
        if self.mesh_of(deformed) is not None:
            return deformed.get("id"), "skinned"
        if deformed is not None and local(deformed.tag) == "controller" and self.morph_base(deformed) is not None:
            return deformed.get("id"), "skinned"
        return None

    # ---- materials -----------------------------------------------------------------------------

    def material(self, instance, symbol):
        """(NAME, DIFFUSE, TEXTURE) of a symbol bound through an instance element."""
        bound = None
        bind_material = child(instance, "bind_material")
        for technique in (children(bind_material, "technique_common") if bind_material is not None else []):
            for im in children(technique, "instance_material"):
                if im.get("symbol") == symbol and bound is None:
                    bound = im
        if bound is None:
            return "-", "-", "-"
        material = self.element(bound.get("target"))
        if material is None or local(material.tag) != "material":
            return "-", "-", "-"
        name = material.get("name") or material.get("id")
        instance_effect = child(material, "instance_effect")
        effect = self.element(instance_effect.get("url")) if instance_effect is not None else None
        if effect is None or local(effect.tag) != "effect":
            return name, "-", "-"
        profile = child(effect, "profile_COMMON")
        technique = child(profile, "technique") if profile is not None else None
        if technique is None:
            return name, "-", "-"
        shading = [c for c in technique if local(c.tag) in SHADINGS]
        if not shading:
            return name, "-", "-"
        scopes = [instance_effect, technique, profile, effect]
        if local(shading[0].tag) == "constant":
            # Unlit: no diffuse; what it shows is its emission, a texture there counts.
            emission = child(shading[0], "emission")
            texture = child(emission, "texture") if emission is not None else None
            return name, "-", self.texture(scopes, texture.get("texture")) if texture is not None else "-"
        diffuse = child(shading[0], "diffuse")
        if diffuse is None:
            return name, "-", "-"
        colour = child(diffuse, "color")
        if colour is None and child(diffuse, "param") is not None:
            newparam = self.newparam(scopes, child(diffuse, "param").get("ref"), ("float4", "float3"))
            if newparam is not None:
                colour = [c for c in newparam if local(c.tag) in ("float4", "float3")][0]
        if colour is not None:
            values = self.floats(colour.text)
            if len(values) == 3:
                values.append(1.0)
            return name, " ".join("%g" % v for v in values[:4]), "-"
        texture = child(diffuse, "texture")
        if texture is None:
            return name, "-", "-"
        return name, "-", self.texture(scopes, texture.get("texture"))

    def newparam(self, scopes, sid, holding):
        """The <setparam ref> of the material's <instance_effect> (scopes[0]), else the first
        <newparam sid> of the technique, profile or effect, holding one of the given elements."""
        for scope in scopes:
            for param in list(children(scope, "setparam")) + list(children(scope, "newparam")):
                key = param.get("ref") if local(param.tag) == "setparam" else param.get("sid")
                if key == sid and any(local(c.tag) in holding for c in param):
                    return param
        return None

    def texture(self, scopes, sampler_sid):
        image = None
        sampler = self.newparam(scopes, sampler_sid, ("sampler2D",))
        if sampler is not None:
            sampler2d = child(sampler, "sampler2D")
            instance_image = child(sampler2d, "instance_image")
            if instance_image is not None:
                image = self.element(instance_image.get("url"))
            else:
                source = child(sampler2d, "source")
                surface = self.newparam(scopes, (source.text or "").strip(), ("surface",)) if source is not None else None
                init = child(child(surface, "surface"), "init_from") if surface is not None else None
                if init is not None:
                    image = self.ids.get((init.text or "").strip())
        else:
            image = self.ids.get(sampler_sid)
        if image is None or local(image.tag) != "image":
            return "-"
        init = child(image, "init_from")
        if init is None:
            return "-"
        uri = child(init, "ref").text if child(init, "ref") is not None else init.text
        return self.image_path((uri or "").strip())

    def image_path(self, uri):
        if not uri:
            return "-"
        path = uri.replace("\\", "/")
        if re.match(r"^file:", path, re.I):
            path = path[len("file:"):]
            if path.startswith("///"):
                path = path[2:]
            elif path.startswith("//localhost/"):
                path = path[len("//localhost"):]
            elif path.startswith("//"):
                path = path[2:]  # file://relative: exporters mean a path, not a host
        elif SCHEME.match(path) and not DRIVE.match(path):
            return "-"
        path = unquote(path)
        if re.match(r"^/[A-Za-z]:/", path):
            path = path[1:]
        elif path.startswith("/../") or path.startswith("/./"):
            path = path[1:]
        other_drive = re.match(r"^(?:\.\./)+([A-Za-z]:/.*)$", path)
        if other_drive:
            return other_drive.group(1)
        if path.startswith("/") or DRIVE.match(path):
            return path
        return posixpath.normpath(posixpath.join(posixpath.dirname(self.path), path))

    # ---- quirks --------------------------------------------------------------------------------

    def scan_quirks(self, scene_nodes):
        for asset in children(self.root, "asset"):
            for unit in children(asset, "unit"):
                self.floats(unit.get("meter"))
        scanned = []
        for geometry in self.geometries():
            mesh = child(geometry, "mesh")
            if mesh is not None:
                scanned.append(mesh)
                self.scan_mesh(mesh)
        for controller in self.controllers():
            scanned.append(controller)
            skin = child(controller, "skin")
            if skin is not None:
                self.floats(child(skin, "bind_shape_matrix").text if child(skin, "bind_shape_matrix") is not None else "")
                weights = child(skin, "vertex_weights")
                if weights is not None and weights.get("count") is not None:
                    if int(weights.get("count")) != len(ints(child(weights, "vcount"))):
                        self.quirks.add("count-mismatch")
            if self.morph_chain(controller)[0] and self.morph_chain(controller)[1] is not None:
                end = self.morph_chain(controller)[1]
                if local(end.tag) == "controller" and child(end, "skin") is not None:
                    self.quirks.add("morph-on-skin")
        scanned += children(self.root, "library_animations")
        for element in scanned:
            for e in element.iter():
                if local(e.tag) == "source":
                    self.scan_source(e)
        for node in scene_nodes:
            for t in node:
                if local(t.tag) in ("matrix", "translate", "rotate", "scale", "lookat", "skew"):
                    self.floats(t.text)

    def scan_source(self, source):
        for array in source:
            if local(array.tag) in ARRAYS:
                values = (array.text or "").split()
                if local(array.tag) == "float_array":
                    self.floats(array.text)
                if array.get("count") is not None and int(array.get("count")) != len(values):
                    self.quirks.add("count-mismatch")
        accessor = source.find("{*}technique_common/{*}accessor")
        if accessor is None:
            return
        params = children(accessor, "param")
        if params and not any(p.get("name") for p in params):
            self.quirks.add("unnamed-params")
        array, _ = self.array_of(source)
        count = int(accessor.get("count"))
        if array is not None and count > 0:
            stride = int(accessor.get("stride", "1"))
            span = sum(PARAM_SIZES.get(p.get("type"), 1) for p in params) if params else stride
            if int(accessor.get("offset", "0")) + (count - 1) * stride + span > len((array.text or "").split()):
                self.quirks.add("count-mismatch")

    def scan_mesh(self, mesh):
        vertices = child(mesh, "vertices")
        position = self.position_source(mesh)
        if len(self.components(position.find("{*}technique_common/{*}accessor"))) < 3:
            self.quirks.add("2d-positions")
        vertex_inputs = [i for i in children(vertices, "input") if i.get("semantic") in OPTIONAL_INPUTS]
        for i in vertex_inputs:
            self.scan_finite(i)
        for primitive in mesh:
            kind = local(primitive.tag)
            if kind not in POLYGON_PRIMITIVES and kind not in LINE_PRIMITIVES:
                continue
            stride = self.stride(primitive)
            self.scan_count(primitive, kind, stride)
            if kind in LINE_PRIMITIVES:
                continue
            if kind == "polylist":
                flat = ints(child(primitive, "p"))[:sum(ints(child(primitive, "vcount"))) * stride]
            elif kind == "triangles":
                flat = [v for p in children(primitive, "p") for v in ints(p)]
                flat = flat[:len(flat) // (3 * stride) * 3 * stride]
            else:
                flat = [v for p in rings(primitive) for v in ints(p)[:len(ints(p)) // stride * stride]]
            for i in children(primitive, "input"):
                semantic = i.get("semantic")
                offset = int(i.get("offset", "0"))
                indices = flat[offset::stride]
                if semantic == "VERTEX":
                    target = self.element(i.get("source"))
                    if target is not vertices:
                        self.quirks.add("vertex-ref")
                    for v in vertex_inputs:
                        self.scan_range(v, indices)
                elif semantic in OPTIONAL_INPUTS:
                    self.scan_finite(i)
                    self.scan_range(i, indices)

    def scan_finite(self, input_element):
        source = self.element(input_element.get("source"))
        if source is None:
            return
        array, _ = self.array_of(source)
        if array is not None and local(array.tag) == "float_array":
            if any(math.isnan(v) or math.isinf(v) for v in self.floats(array.text)):
                self.quirks.add("non-finite")

    def scan_range(self, input_element, indices):
        source = self.element(input_element.get("source"))
        count = self.accessor_count(source) if source is not None else 0
        if any(index < 0 or index >= count for index in indices):
            self.quirks.add("dropped-input")

    def scan_count(self, primitive, kind, stride):
        if primitive.get("count") is None:
            return
        count = int(primitive.get("count"))
        ps = children(primitive, "p")
        flat = sum(len(ints(p)) for p in ps)
        if kind == "triangles":
            data = flat // (3 * stride)
        elif kind == "lines":
            data = flat // (2 * stride)
        elif kind == "polylist":
            vcount = ints(child(primitive, "vcount"))
            data = len(vcount)
            if flat != sum(vcount) * stride:
                self.quirks.add("count-mismatch")
        elif kind == "polygons":
            data = len(ps) + len(children(primitive, "ph"))
        else:
            data = len(ps)
        if count != data:
            self.quirks.add("count-mismatch")


def ints(element):
    return [int(t) for t in (element.text or "").split()] if element is not None else []


def rings(primitive):
    """The <p>s of a polygons/trifans/tristrips element, with the outer <p> of every <ph>."""
    result = children(primitive, "p")
    if local(primitive.tag) == "polygons":
        result += [child(ph, "p") for ph in children(primitive, "ph") if child(ph, "p") is not None]
    return result


def four(value):
    text = "%.4f" % value
    return "0.0000" if text == "-0.0000" else text


def records(path, data):
    try:
        root = ET.fromstring(data)
    except ET.ParseError:
        return [["file", path, "refused", "malformed-xml"]]
    doc = Cts(path, root)
    try:
        doc.check_external()
    except External:
        return [["file", path, "refused", "another-document"]]
    rows = [["file", path, "loaded"]]
    skins = doc.skins()

    meshes = []  # (MESH_ID, geometry element with the primitives)
    for geometry in doc.geometries():
        mesh = child(geometry, "mesh")
        if mesh is None:
            continue
        meshes.append((geometry.get("id"), geometry, geometry))
    morphs = []
    for controller in doc.controllers():
        if child(controller, "morph") is None:
            continue
        base = doc.morph_base(controller)
        if base is not None:
            meshes.append((controller.get("id"), base, controller))
            morphs.append((controller, base))
    for mesh_id, geometry, deformed in meshes:
        mesh = child(geometry, "mesh")
        positions = doc.accessor_count(doc.position_source(mesh))
        skin = skins.get(deformed)
        if skin is None:
            rows.append(["mesh", path, mesh_id, positions, doc.triangles(mesh), "static", 0, 0])
        else:
            joints, most = doc.skin_counts(skin)
            rows.append(["mesh", path, mesh_id, positions, doc.triangles(mesh), "skinned", joints, most])
    for controller, base in morphs:
        result, used = doc.morph_result(controller)
        sums = " ".join(four(sum(p[c] for p in result)) for c in range(3))
        method = child(controller, "morph").get("method") or "NORMALIZED"
        rows.append(["morph", path, controller.get("id"), base.get("id"), used, method, sums])

    nodes, instances, extra = doc.scene()
    if extra:
        doc.quirks.add("library-skeleton")
    instance_rows = []
    first_instance = {}
    for node, instance in instances:
        found = doc.instance_mesh(instance)
        if found is None:
            continue
        first_instance.setdefault(found[0], instance)
        instance_rows.append(["instance", path, len(instance_rows), node.get("id") or "-", found[0], found[1]])
    rows.append(["scene", path, len(nodes), len(instance_rows)])
    rows += instance_rows

    for mesh_id, geometry, _ in meshes:
        instance = first_instance.get(mesh_id)
        for symbol in doc.symbols(child(geometry, "mesh")):
            if instance is None:
                rows.append(["material", path, mesh_id, symbol, "-", "-", "-"])
            else:
                rows.append(["material", path, mesh_id, symbol] + list(doc.material(instance, symbol)))

    rows += clip_rows(doc, nodes)
    doc.scan_quirks(nodes)
    rows += [["quirk", path, kind] for kind in QUIRK_ORDER if kind in doc.quirks]
    return rows


def clip_rows(doc, nodes):
    copies = {}
    for node in nodes:
        if node.get("id") is not None:
            copies.setdefault(node.get("id"), []).append(node)
    top_level = [a for library in children(doc.root, "library_animations") for a in children(library, "animation")]
    clips = [c for library in children(doc.root, "library_animation_clips") for c in children(library, "animation_clip")]
    rows = []
    for n, clip in enumerate(clips, 1):
        # Each animation counts once per clip, however often the clip instances it (directly or
        # through an outer animation): the same channel twice would drive the same values twice.
        instanced = []
        for i in children(clip, "instance_animation"):
            animation = doc.element(i.get("url"))
            if animation is not None and local(animation.tag) == "animation":
                instanced += [a for a in animation.iter() if local(a.tag) == "animation"
                              and not any(a is b for b in instanced)]
        outermost = [a for a in instanced
                     if not any(b is not a and any(a is d for d in b.iter()) for b in instanced)]
        channels = sum(channel_count(doc, copies, a) for a in outermost)
        rows.append(["clip", doc.path, clip.get("name") or clip.get("id") or "clip-%d" % n, channels])
    if not clips:
        channels = sum(channel_count(doc, copies, a) for a in top_level)
        if channels:
            rows.append(["clip", doc.path, "default", channels])
    return rows


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    archive = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "..", "..", "..", "..", "..", "shared", "cts", "collada-cts-1.4.1-subset.zip")
    with open(archive, "rb") as f:
        digest = hashlib.sha256(f.read()).hexdigest()
    print("# Generated by core/src/test/tools/cts_expected.py: do not edit by hand, run the script again.")
    print("# From %s (sha256 %s)," % (os.path.basename(archive), digest))
    print("# a subset of the 1.4.1 data sets of %s at commit %s." % (SUITE, SUITE_COMMIT))
    print("# Records and rules: the script's docstring.")
    with zipfile.ZipFile(archive) as z:
        for name in sorted(n for n in z.namelist() if n.lower().endswith(".dae")):
            for row in records(name, z.read(name)):
                print(" | ".join(str(v) for v in row))


if __name__ == "__main__":
    main()
