package org.skinlab.collada;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.joml.Matrix4f;
import org.skinlab.model.Material;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Morph;
import org.skinlab.model.Node;
import org.skinlab.model.Skin;
import org.skinlab.model.TransformElement;

/**
 * Instantiates the visual scene: the node tree in depth-first order (with {@code <instance_node>}
 * copies), each node's transform stack, and the meshes placed in it, with every skin joint
 * resolved to a node.
 *
 * <p>Lenient (with a warning): no {@code <scene>} (the first visual scene is used); a
 * {@code <skeleton>} that names no node (ignored); joints found by id or name when no sid
 * matches under the skeleton roots; {@code <skew>} with a zero axis; a rotation about a zero axis;
 * a {@code <lookat>} without a view direction (the node stays unrotated at the eye); a matrix
 * whose bottom row is not (0 0 0 1). Refused: {@code <instance_node>} cycles, more than
 * {@link #MAX_INSTANCE_DEPTH} nested instances or {@link #MAX_NODES} nodes in all (instancing
 * bombs), transforms with the wrong number of values, and joints that match no node.
 */
final class SceneLoader {
    static final int MAX_NODES = 1_000_000;
    static final int MAX_INSTANCE_DEPTH = 64;

    private final ImportContext ctx;
    private final Map<XmlElement, Mesh> meshes;
    private final Map<XmlElement, Morph> morphs;
    private final Map<XmlElement, Skin> skins;
    private final Map<XmlElement, Material> materials;

    // Drafts of the nodes, in depth-first order.
    private final List<Draft> drafts = new ArrayList<>();
    private final Map<String, IntList> byId = new HashMap<>();
    private final Map<String, IntList> bySid = new HashMap<>();
    private final Map<String, IntList> byName = new HashMap<>();
    private final Map<String, RootScope> scopes = new HashMap<>();
    private int[] subtreeEnd;
    private int[] parents;
    /** Expanded subtree sizes, memoized across calls of {@link #checkExpandedSize}. */
    private final Map<XmlElement, Long> expandedSizes = new IdentityHashMap<>();
    /** The target of each {@code <instance_node>}, resolved once by {@link #checkExpandedSize}. */
    private final Map<XmlElement, XmlElement> instanceTargets = new IdentityHashMap<>();

    SceneLoader(ImportContext ctx, Map<XmlElement, Mesh> meshesByGeometry, Map<XmlElement, Morph> morphsByController,
            Map<XmlElement, Skin> skinsByController, Map<XmlElement, Material> materialsByElement) {
        this.ctx = ctx;
        this.meshes = meshesByGeometry;
        this.morphs = morphsByController;
        this.skins = skinsByController;
        this.materials = materialsByElement;
    }

    /** The nodes and instances of the scene (empty when the file has no visual scene). */
    static final class Result {
        final List<Node> nodes;
        final List<MeshInstance> instances;
        final Map<String, IntList> nodesById;

        Result(List<Node> nodes, List<MeshInstance> instances, Map<String, IntList> nodesById) {
            this.nodes = nodes;
            this.instances = instances;
            this.nodesById = nodesById;
        }
    }

    private static final class Draft {
        final XmlElement element;
        final int index;
        final int parent;
        final boolean instanced;
        final IntList children = new IntList(4);
        final List<TransformElement> transforms = new ArrayList<>(4);
        final List<XmlElement> meshInstances = new ArrayList<>(1);

        Draft(XmlElement element, int index, int parent, boolean instanced) {
            this.element = element;
            this.index = index;
            this.parent = parent;
            this.instanced = instanced;
        }
    }

    /** A pending node: its element, parent and the chain of instance_node targets leading to it. */
    private static final class Pending {
        final XmlElement element;
        final int parent;
        final Chain chain;

        Pending(XmlElement element, int parent, Chain chain) {
            this.element = element;
            this.parent = parent;
            this.chain = chain;
        }
    }

    /** Immutable list of the library nodes being instanced, innermost first. */
    private static final class Chain {
        final XmlElement target;
        final Chain outer;
        final int depth;

        Chain(XmlElement target, Chain outer) {
            this.target = target;
            this.outer = outer;
            this.depth = outer == null ? 1 : outer.depth + 1;
        }

        boolean contains(XmlElement e) {
            for (Chain c = this; c != null; c = c.outer) {
                if (c.target == e) {
                    return true;
                }
            }
            return false;
        }
    }

    Result load(XmlElement collada) throws ColladaException {
        XmlElement visualScene = visualScene(collada);
        if (visualScene == null) {
            return new Result(List.of(), List.of(), Map.of());
        }
        long size = checkExpandedSize(visualScene.children("node"), visualScene, 0);
        Deque<Pending> todo = new ArrayDeque<>();
        pushChildren(todo, visualScene, -1, null);
        walk(todo);
        // Skeletons that live in <library_nodes> and that nothing places in the scene: first
        // those a <skeleton> names, then (with them in place) those holding joints found nowhere else.
        for (int phase = 0; phase < 2; phase++) {
            for (XmlElement root : libraryRoots(phase == 0)) {
                size = checkExpandedSize(List.of(root), root, size);
                todo.push(new Pending(root, -1, null));
                walk(todo);
            }
        }
        int n = drafts.size();
        parents = new int[n];
        subtreeEnd = new int[n];
        for (int i = n - 1; i >= 0; i--) {
            parents[i] = drafts.get(i).parent;
            int end = i + 1;
            IntList ch = drafts.get(i).children;
            if (ch.size() > 0) {
                end = subtreeEnd[ch.get(ch.size() - 1)];
            }
            subtreeEnd[i] = end;
        }
        List<Node> nodes = new ArrayList<>(n);
        for (Draft d : drafts) {
            XmlElement e = d.element;
            nodes.add(new Node(d.index, d.parent, d.children.toArray(), e.id(), e.attr("sid"), e.attr("name"),
                    "JOINT".equals(e.attr("type")), d.instanced, d.transforms));
        }
        List<MeshInstance> instances = new ArrayList<>();
        for (Draft d : drafts) {
            for (XmlElement inst : d.meshInstances) {
                MeshInstance mi = instance(d.index, inst);
                if (mi != null) {
                    instances.add(mi);
                }
            }
        }
        return new Result(nodes, instances, byId);
    }

    /** Turns pending nodes into drafts, depth-first (iterative: the depth is the file's to choose). */
    private void walk(Deque<Pending> todo) throws ColladaException {
        while (!todo.isEmpty()) {
            Pending p = todo.pop();
            if (drafts.size() >= MAX_NODES) {
                throw ctx.error(p.element, "the scene would have more than " + MAX_NODES + " nodes");
            }
            Draft d = new Draft(p.element, drafts.size(), p.parent, p.chain != null);
            drafts.add(d);
            if (p.parent >= 0) {
                drafts.get(p.parent).children.add(d.index);
            }
            index(byId, p.element.id(), d.index);
            index(bySid, p.element.attr("sid"), d.index);
            index(byName, p.element.attr("name"), d.index);
            readTransforms(d);
            pushChildren(todo, p.element, d.index, p.chain);
        }
    }

    /**
     * Nodes of {@code <library_nodes>} that a controller instance needs and the scene does not
     * hold: with {@code skeletonRoots}, the nodes its {@code <skeleton>}s name; otherwise the
     * outermost library node holding a skin joint that matches no node of the scene. Such a
     * skeleton is instantiated once as a root of the scene: its nodes' own transforms place it
     * (ColladaMaya writes skins this way; the CTS has two such files).
     */
    private List<XmlElement> libraryRoots(boolean skeletonRoots) {
        List<XmlElement> roots = new ArrayList<>();
        Set<XmlElement> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        for (int i = 0, n = drafts.size(); i < n; i++) {
            for (XmlElement inst : drafts.get(i).meshInstances) {
                if (!inst.name().equals("instance_controller")) {
                    continue;
                }
                if (skeletonRoots) {
                    for (XmlElement s : inst.children("skeleton")) {
                        String id = fragment(s.text().trim());
                        XmlElement target = byId.containsKey(id) ? null : ctx.byId(id);
                        if (target != null && target.name().equals("node") && seen.add(target)) {
                            ctx.warn(s, "skeleton root \"" + s.text().trim() + "\" lives in <library_nodes> and is"
                                    + " placed nowhere in the scene; instantiated as a root of the scene");
                            roots.add(target);
                        }
                    }
                    continue;
                }
                Skin skin = skins.get(ctx.byId(fragment(String.valueOf(inst.attr("url")))));
                if (skin == null) {
                    continue;
                }
                for (String joint : skin.jointNames()) {
                    if (byId.containsKey(joint) || (!skin.jointsAreIdrefs() && (bySid.containsKey(joint)
                            || byName.containsKey(joint)))) {
                        continue;
                    }
                    XmlElement root = libraryNodeRoot(joint, skin.jointsAreIdrefs());
                    if (root != null && seen.add(root)) {
                        ctx.warn(inst, "joint \"" + joint + "\" lives in <library_nodes> under node \""
                                + (root.id() == null ? root.attr("name") : root.id())
                                + "\", which is placed nowhere in the scene; that node is instantiated as a root of"
                                + " the scene");
                        roots.add(root);
                    }
                }
            }
        }
        return roots;
    }

    /** The outermost {@code <library_nodes>} node holding a node with that id (or sid or name), or null. */
    private XmlElement libraryNodeRoot(String joint, boolean idOnly) {
        for (XmlElement library : ctx.root().children("library_nodes")) {
            for (XmlElement top : library.children("node")) {
                Deque<XmlElement> todo = new ArrayDeque<>();
                todo.push(top);
                while (!todo.isEmpty()) {
                    XmlElement e = todo.pop();
                    if (joint.equals(e.id()) || (!idOnly && (joint.equals(e.attr("sid"))
                            || joint.equals(e.attr("name"))))) {
                        return top;
                    }
                    for (XmlElement c : e.children("node")) {
                        todo.push(c);
                    }
                }
            }
        }
        return null;
    }

    private static String fragment(String ref) {
        return ref.startsWith("#") ? ref.substring(1) : ref;
    }

    private XmlElement visualScene(XmlElement collada) throws ColladaException {
        XmlElement scene = collada.child("scene");
        XmlElement instance = scene == null ? null : scene.child("instance_visual_scene");
        if (instance != null) {
            return ctx.resolve(instance, "url", "visual_scene");
        }
        for (XmlElement library : collada.children("library_visual_scenes")) {
            XmlElement first = library.child("visual_scene");
            if (first != null) {
                ctx.warn(collada, "no <scene><instance_visual_scene>; using the first visual scene"
                        + (first.id() == null ? "" : " \"" + first.id() + "\""));
                return first;
            }
        }
        return null;
    }

    private static void index(Map<String, IntList> map, String key, int node) {
        if (key != null) {
            map.computeIfAbsent(key, k -> new IntList(1)).add(node);
        }
    }

    private void pushChildren(Deque<Pending> todo, XmlElement parentElement, int parent, Chain chain)
            throws ColladaException {
        List<Pending> children = new ArrayList<>();
        for (XmlElement c : parentElement.children()) {
            if (c.name().equals("node")) {
                children.add(new Pending(c, parent, chain));
            } else if (c.name().equals("instance_node") && parent >= 0) {
                XmlElement target = instanceTarget(c);
                if (chain != null && chain.contains(target)) {
                    throw cycle(c);
                }
                Chain inner = new Chain(target, chain);
                if (inner.depth > MAX_INSTANCE_DEPTH) {
                    throw ctx.error(c, "more than " + MAX_INSTANCE_DEPTH + " nested <instance_node> levels");
                }
                children.add(new Pending(target, parent, inner));
            } else if (parent >= 0 && (c.name().equals("instance_geometry") || c.name().equals("instance_controller"))) {
                drafts.get(parent).meshInstances.add(c);
            }
        }
        for (int i = children.size() - 1; i >= 0; i--) {
            todo.push(children.get(i));
        }
    }

    private XmlElement instanceTarget(XmlElement instanceNode) throws ColladaException {
        XmlElement target = instanceTargets.get(instanceNode);
        if (target == null) {
            target = ctx.resolve(instanceNode, "url", "node");
            instanceTargets.put(instanceNode, target);
        }
        return target;
    }

    private ColladaException cycle(XmlElement instanceNode) {
        return ctx.error(instanceNode, "instance_node url=\"" + instanceNode.attr("url")
                + "\" instantiates a node that contains it (a cycle)");
    }

    /** A node whose expanded size is being computed: its edges and the sizes summed so far. */
    private static final class SizeFrame {
        final XmlElement node;
        final List<XmlElement> edges = new ArrayList<>(4);   // child nodes and instance targets
        final List<XmlElement> via = new ArrayList<>(4);     // the <instance_node>, or null for a child
        int next;
        long size = 1;

        SizeFrame(XmlElement node) {
            this.node = node;
        }
    }

    /**
     * Refuses an instancing bomb before anything is built. Library nodes that each instance the
     * previous one ten times make a 2 KB file that expands to 10^8 nodes; building drafts up to
     * {@link #MAX_NODES} would cost half a second and hundreds of megabytes (an OutOfMemoryError
     * on a 128 MB heap, common on phones). So each node's expanded size is computed first, once
     * per element (memoized; iterative, since nesting and instancing depth are the file's to
     * choose), saturating above the limit, and the first node found to exceed it is named.
     * Instance cycles show up here as an edge back to a node on the current path.
     */
    private long checkExpandedSize(List<XmlElement> tops, XmlElement scope, long total) throws ColladaException {
        Map<XmlElement, Long> sizes = expandedSizes;
        Map<XmlElement, Boolean> onPath = new IdentityHashMap<>();
        Deque<SizeFrame> path = new ArrayDeque<>();
        for (XmlElement top : tops) {
            path.push(sizeFrame(top, onPath));
            while (!path.isEmpty()) {
                SizeFrame f = path.peek();
                if (f.next < f.edges.size()) {
                    XmlElement target = f.edges.get(f.next);
                    XmlElement via = f.via.get(f.next);
                    f.next++;
                    Long known = sizes.get(target);
                    if (known != null) {
                        f.size = Math.min(MAX_NODES + 1L, f.size + known);
                    } else if (onPath.containsKey(target)) {
                        throw cycle(via);
                    } else {
                        path.push(sizeFrame(target, onPath));
                    }
                    continue;
                }
                path.pop();
                onPath.remove(f.node);
                if (f.size > MAX_NODES) {
                    throw ctx.error(f.node, "with its <instance_node>s it would expand to more than " + MAX_NODES
                            + " nodes");
                }
                sizes.put(f.node, f.size);
                if (!path.isEmpty()) {
                    path.peek().size = Math.min(MAX_NODES + 1L, path.peek().size + f.size);
                }
            }
            total += sizes.get(top);
            if (total > MAX_NODES) {
                throw ctx.error(scope, "the scene's nodes would expand to more than " + MAX_NODES + " nodes");
            }
        }
        return total;
    }

    private SizeFrame sizeFrame(XmlElement node, Map<XmlElement, Boolean> onPath) throws ColladaException {
        SizeFrame f = new SizeFrame(node);
        onPath.put(node, Boolean.TRUE);
        for (XmlElement c : node.children()) {
            if (c.name().equals("node")) {
                f.edges.add(c);
                f.via.add(null);
            } else if (c.name().equals("instance_node")) {
                f.edges.add(instanceTarget(c));
                f.via.add(c);
            }
        }
        return f;
    }

    private void readTransforms(Draft d) throws ColladaException {
        for (XmlElement c : d.element.children()) {
            TransformElement.Kind kind;
            switch (c.name()) {
                case "matrix": kind = TransformElement.Kind.MATRIX; break;
                case "translate": kind = TransformElement.Kind.TRANSLATE; break;
                case "rotate": kind = TransformElement.Kind.ROTATE; break;
                case "scale": kind = TransformElement.Kind.SCALE; break;
                case "lookat": kind = TransformElement.Kind.LOOKAT; break;
                case "skew": kind = TransformElement.Kind.SKEW; break;
                default: continue;
            }
            float[] v = NumberParser.floats(ctx, c, -1);
            if (v.length != kind.size()) {
                throw ctx.error(c, "has " + v.length + " values, expected " + kind.size());
            }
            if (kind == TransformElement.Kind.MATRIX) {
                RowMajor.checkBottomRow(ctx, v, 0, c, "matrix");
            } else if (kind == TransformElement.Kind.ROTATE && v[0] == 0f && v[1] == 0f && v[2] == 0f && v[3] != 0f) {
                // "0 0 0 0" (FBX pivots write it) is no rotation by any reading: nothing to say.
                ctx.warn(c, "rotation about a zero axis; treated as no rotation");
            } else if (kind == TransformElement.Kind.SKEW && (isZero(v, 1) || isZero(v, 4))) {
                ctx.warn(c, "skew with a zero axis; treated as no skew");
            } else if (kind == TransformElement.Kind.LOOKAT && !new Matrix4f().setLookAt(v[0], v[1], v[2], v[3], v[4],
                    v[5], v[6], v[7], v[8]).isFinite()) {
                ctx.warn(c, "lookat without a view direction (the eye on the interest point, or the up vector"
                        + " along the view); the node is placed at the eye without rotation");
            }
            d.transforms.add(new TransformElement(kind, c.attr("sid"), v));
        }
    }

    private static boolean isZero(float[] v, int o) {
        return v[o] == 0f && v[o + 1] == 0f && v[o + 2] == 0f;
    }

    // ------------------------------------------------------------------------------- instances

    private MeshInstance instance(int node, XmlElement inst) throws ColladaException {
        if (inst.name().equals("instance_geometry")) {
            XmlElement geometry = ctx.resolve(inst, "url", "geometry");
            Mesh mesh = meshes.get(geometry);
            if (mesh == null) {
                return null; // not a <mesh>; warned when the geometry was read
            }
            return new MeshInstance(node, mesh, null, new int[0], new int[0], bindings(inst, mesh));
        }
        XmlElement controller = ctx.resolve(inst, "url", "controller");
        Skin skin = skins.get(controller);
        if (skin == null) {
            if (controller.child("morph") == null) {
                throw ctx.error(inst, "url=\"" + inst.attr("url") + "\" is a controller without <skin> or <morph>");
            }
            Morph morph = morphs.get(controller);
            if (morph != null) {
                return new MeshInstance(node, morph.result(), null, new int[0], new int[0],
                        bindings(inst, morph.result()));
            }
            controller = skinUnderMorphs(controller);
            if (controller == null) {
                return null; // a morph of a geometry that is no mesh
            }
            skin = skins.get(controller);
            ctx.warn(inst, "morph on skin controller \"" + controller.id() + "\": drawn as that skin, without the"
                    + " morph (a morph after skinning is not supported)");
        }
        IntList roots = new IntList(2);
        for (XmlElement s : inst.children("skeleton")) {
            String ref = s.text().trim();
            String id = ref.startsWith("#") ? ref.substring(1) : ref;
            int root = nearest(byId.get(id), node);
            if (root < 0) {
                ctx.warn(s, "skeleton root \"" + ref + "\" is not a node of the scene; ignored");
            } else {
                roots.add(root);
            }
        }
        int[] rootArray = roots.toArray();
        RootScope scope = rootArray.length == 0 ? null
                : scopes.computeIfAbsent(java.util.Arrays.toString(rootArray), k -> new RootScope(rootArray));
        int[] joints = new int[skin.jointCount()];
        boolean outsideRoots = false;
        Map<String, Integer> resolved = new HashMap<>(); // joints of one skin may repeat a name
        for (int j = 0; j < joints.length; j++) {
            String name = skin.jointNames().get(j);
            Integer known = resolved.get(name);
            int found;
            if (known != null) {
                found = known;
            } else {
                found = scope == null ? -1 : scope.firstUnder((skin.jointsAreIdrefs() ? byId : bySid).get(name));
                if (found < 0) {
                    found = byIdOrName(name, skin.jointsAreIdrefs(), scope, node);
                    outsideRoots |= found >= 0 && scope != null;
                }
                resolved.put(name, found);
            }
            if (found < 0) {
                throw ctx.error(inst, "joint \"" + name + "\" of controller \"" + controller.id() + "\" matches no node"
                        + " in the scene (by " + (skin.jointsAreIdrefs() ? "id" : "sid, id or name") + ")");
            }
            joints[j] = found;
        }
        if (outsideRoots) {
            ctx.warn(inst, "some joints matched no " + (skin.jointsAreIdrefs() ? "id" : "sid")
                    + " under the <skeleton> roots and were found by id or name instead");
        }
        return new MeshInstance(node, skin.mesh(), skin, joints, rootArray, bindings(inst, skin.mesh()));
    }

    /** The skin controller a chain of morphs ends in, or null when it ends in a geometry. */
    private XmlElement skinUnderMorphs(XmlElement controller) throws ColladaException {
        XmlElement c = controller;
        for (int depth = 0; c.child("morph") != null; depth++) {
            if (depth > MAX_INSTANCE_DEPTH) {
                throw ctx.error(controller, "more than " + MAX_INSTANCE_DEPTH + " morphs on morphs");
            }
            XmlElement source = ctx.resolve(c.child("morph"), "source", "geometry", "controller");
            if (source.name().equals("geometry")) {
                return null;
            }
            c = source;
        }
        return c.child("skin") != null ? c : null;
    }

    /**
     * The materials an instance binds ({@code <bind_material><technique_common><instance_material>}),
     * and the texture coordinate set each one's {@link Material#baseTexture()} uses: the set its
     * {@code <bind_vertex_input>} names for the texture's {@code texcoord}, else the first. A
     * symbol of the mesh that nothing binds, or a binding to no material, is drawn with
     * {@link Material#DEFAULT}, warned.
     */
    private List<MaterialBinding> bindings(XmlElement inst, Mesh mesh) {
        List<MaterialBinding> result = new ArrayList<>();
        XmlElement bind = inst.child("bind_material");
        XmlElement common = bind == null ? null : bind.child("technique_common");
        Set<String> bound = new HashSet<>();
        if (common != null) {
            Set<String> used = new HashSet<>();
            for (MeshPart part : mesh.parts()) {
                used.add(part.material());
            }
            for (XmlElement im : common.children("instance_material")) {
                String symbol = im.attr("symbol");
                if (symbol == null || !bound.add(symbol)) {
                    continue;
                }
                // A binding for a symbol the mesh does not use changes nothing, dangling or not.
                Material material = used.contains(symbol) ? material(im) : materialOrNull(im);
                if (material == null) {
                    continue;
                }
                result.add(new MaterialBinding(symbol, material, texCoordSet(im, material, mesh)));
            }
        }
        Set<String> unbound = new LinkedHashSet<>();
        for (MeshPart part : mesh.parts()) {
            if (part.material() != null && !bound.contains(part.material())) {
                unbound.add(part.material());
            }
        }
        if (!unbound.isEmpty()) {
            ctx.warn(inst, "material symbol" + (unbound.size() == 1 ? " " : "s ") + String.join(", ", unbound)
                    + " of mesh \"" + mesh.id() + "\" bound to no material; drawn with the default material");
        }
        return result;
    }

    /** The material an {@code <instance_material>} names, or null (no warning). */
    private Material materialOrNull(XmlElement instanceMaterial) {
        String target = instanceMaterial.attr("target");
        XmlElement e = target == null ? null : ctx.byId(target.substring(target.indexOf('#') + 1));
        return e == null ? null : materials.get(e);
    }

    /** The material an {@code <instance_material>} names, or null with a warning. */
    private Material material(XmlElement instanceMaterial) {
        try {
            return materials.get(ctx.resolve(instanceMaterial, "target", "material"));
        } catch (ColladaException e) {
            ctx.warn(instanceMaterial, e.problem() + "; drawn with the default material");
            return null;
        }
    }

    private int texCoordSet(XmlElement instanceMaterial, Material material, Mesh mesh) {
        if (material.baseTexture() == null || mesh.texCoordSetCount() == 0) {
            return -1;
        }
        String texcoord = material.baseTexture().texcoord();
        for (XmlElement b : instanceMaterial.children("bind_vertex_input")) {
            if (texcoord != null && texcoord.equals(b.attr("semantic"))
                    && (b.attr("input_semantic") == null || "TEXCOORD".equals(b.attr("input_semantic")))) {
                String set = b.attr("input_set");
                int number;
                try {
                    number = set == null ? mesh.texCoordSetNumber(0) : Integer.parseInt(set.trim());
                } catch (NumberFormatException e) {
                    number = Integer.MIN_VALUE;
                }
                int index = mesh.texCoordSetIndex(number);
                if (index < 0) {
                    ctx.warn(b, "input_set=\"" + set + "\" is no texture coordinate set of mesh \"" + mesh.id()
                            + "\"; the first set is used");
                    return 0;
                }
                return index;
            }
        }
        return 0;
    }

    /**
     * Fallback joint lookup: by id, then (for Name_array joints) by name and by sid; under the
     * skeleton roots first (when there are any), then anywhere, preferring the copy nearest the
     * instance.
     */
    private int byIdOrName(String name, boolean idrefs, RootScope scope, int node) {
        List<Map<String, IntList>> maps = idrefs ? List.of(byId) : List.of(byId, byName, bySid);
        if (scope != null) {
            for (Map<String, IntList> map : maps) {
                int found = scope.firstUnder(map.get(name));
                if (found >= 0) {
                    return found;
                }
            }
        }
        for (Map<String, IntList> map : maps) {
            int found = nearest(map.get(name), node);
            if (found >= 0) {
                return found;
            }
        }
        return -1;
    }

    /**
     * The {@code <skeleton>} roots of an instance, as a rank per node: the file-order position of
     * the first root whose subtree holds the node. "The first candidate under the first root that
     * has one" is then the candidate of lowest rank (lowest index on ties), found in one pass over
     * the candidates, whatever the number of roots: a file with many roots and many joints must
     * not cost roots x joints steps. Built once per distinct root list, in one forward pass
     * (parents come before children).
     */
    private final class RootScope {
        private final int[] rank;

        RootScope(int[] roots) {
            int n = drafts.size();
            int[] own = new int[n];
            java.util.Arrays.fill(own, Integer.MAX_VALUE);
            for (int k = roots.length - 1; k >= 0; k--) {
                own[roots[k]] = k; // the first occurrence of a root wins
            }
            rank = new int[n];
            for (int i = 0; i < n; i++) {
                int inherited = parents[i] < 0 ? Integer.MAX_VALUE : rank[parents[i]];
                rank[i] = Math.min(own[i], inherited);
            }
        }

        /** The candidate under the first root that holds one (lowest index), or -1. */
        int firstUnder(IntList candidates) {
            if (candidates == null) {
                return -1;
            }
            int best = -1;
            int bestRank = Integer.MAX_VALUE;
            for (int i = 0; i < candidates.size(); i++) {
                int c = candidates.get(i);
                if (rank[c] < bestRank) {
                    best = c;
                    bestRank = rank[c];
                }
            }
            return best;
        }
    }

    /** The smallest candidate in [from, to), or -1 (binary search over the ascending list). */
    private static int firstInRange(IntList candidates, int from, int to) {
        int lo = 0;
        int hi = candidates.size();
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (candidates.get(mid) < from) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo < candidates.size() && candidates.get(lo) < to ? candidates.get(lo) : -1;
    }

    /**
     * Of several nodes with the same id (copies made by instance_node), the one that shares the
     * deepest ancestor with {@code from}; the first one on ties. -1 when there is none.
     *
     * <p>Walks up from {@code from}: the first ancestor whose subtree holds a candidate is the
     * deepest common ancestor any candidate can share, and every candidate in that subtree shares
     * exactly it, so the first of them is the answer; when no ancestor holds one, all tie and the
     * first candidate wins. Cost: depth x log(candidates), not candidates x depth.
     */
    private int nearest(IntList candidates, int from) {
        if (candidates == null || candidates.size() == 0) {
            return -1;
        }
        if (candidates.size() == 1) {
            return candidates.get(0);
        }
        for (int a = from; a >= 0; a = parents[a]) {
            int c = firstInRange(candidates, a, subtreeEnd[a]);
            if (c >= 0) {
                return c;
            }
        }
        return candidates.get(0);
    }
}
