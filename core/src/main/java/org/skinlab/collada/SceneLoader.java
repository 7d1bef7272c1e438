package org.skinlab.collada;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.joml.Matrix4f;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
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
    private final Map<XmlElement, Skin> skins;

    // Drafts of the nodes, in depth-first order.
    private final List<Draft> drafts = new ArrayList<>();
    private final Map<String, IntList> byId = new HashMap<>();
    private final Map<String, IntList> bySid = new HashMap<>();
    private final Map<String, IntList> byName = new HashMap<>();
    private final Map<String, RootScope> scopes = new HashMap<>();
    private int[] subtreeEnd;
    private int[] parents;
    /** The target of each {@code <instance_node>}, resolved once by {@link #checkExpandedSize}. */
    private final Map<XmlElement, XmlElement> instanceTargets = new IdentityHashMap<>();

    SceneLoader(ImportContext ctx, Map<XmlElement, Mesh> meshesByGeometry, Map<XmlElement, Skin> skinsByController) {
        this.ctx = ctx;
        this.meshes = meshesByGeometry;
        this.skins = skinsByController;
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
        checkExpandedSize(visualScene);
        // Iterative depth-first walk: the depth of the tree is the file's to choose.
        Deque<Pending> todo = new ArrayDeque<>();
        pushChildren(todo, visualScene, -1, null);
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
    private void checkExpandedSize(XmlElement visualScene) throws ColladaException {
        Map<XmlElement, Long> sizes = new IdentityHashMap<>();
        Map<XmlElement, Boolean> onPath = new IdentityHashMap<>();
        Deque<SizeFrame> path = new ArrayDeque<>();
        long total = 0;
        for (XmlElement top : visualScene.children("node")) {
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
                throw ctx.error(visualScene, "its nodes would expand to more than " + MAX_NODES + " nodes");
            }
        }
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
            } else if (kind == TransformElement.Kind.ROTATE && v[0] == 0f && v[1] == 0f && v[2] == 0f) {
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
        List<String> materials = new ArrayList<>();
        XmlElement bind = inst.child("bind_material");
        XmlElement common = bind == null ? null : bind.child("technique_common");
        if (common != null) {
            for (XmlElement m : common.children("instance_material")) {
                String target = m.attr("target");
                if (target != null) {
                    materials.add(target.startsWith("#") ? target.substring(1) : target);
                }
            }
        }
        if (inst.name().equals("instance_geometry")) {
            XmlElement geometry = ctx.resolve(inst, "url", "geometry");
            Mesh mesh = meshes.get(geometry);
            if (mesh == null) {
                return null; // not a <mesh>; warned when the geometry was read
            }
            return new MeshInstance(node, mesh, null, new int[0], new int[0], materials);
        }
        XmlElement controller = ctx.resolve(inst, "url", "controller");
        Skin skin = skins.get(controller);
        if (skin == null) {
            XmlElement morph = controller.child("morph");
            if (morph != null) {
                Mesh base = meshes.get(ctx.resolve(morph, "source", "geometry"));
                ctx.warn(inst, "morph controller drawn as its base geometry (morphing is not supported)");
                return base == null ? null : new MeshInstance(node, base, null, new int[0], new int[0], materials);
            }
            throw ctx.error(inst, "url=\"" + inst.attr("url") + "\" is a controller without <skin> or <morph>");
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
        return new MeshInstance(node, skin.mesh(), skin, joints, rootArray, materials);
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
