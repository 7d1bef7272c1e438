package org.skinlab.collada;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.skinlab.model.Material;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Morph;
import org.skinlab.model.Node;
import org.skinlab.model.Skin;
import org.skinlab.model.TransformElement;

/**
 * Instantiates the visual scene: the node tree in depth-first order (with {@code <instance_node>}
 * copies), each node's transform stack, and the meshes placed in it, with every skin joint
 * resolved to a node.
 *
 * <p>Its helpers, one job each: {@link TransformReader} (a node's transform stack),
 * {@link InstanceExpansion} ({@code <instance_node>} targets, cycles and instancing bombs),
 * {@link JointResolver} (skeleton roots and joints to nodes), {@link MaterialBinder} (material
 * symbols to materials).
 *
 * <p>Lenient (with a warning): no {@code <scene>} (the first visual scene is used); a
 * {@code <skeleton>} that names no node (ignored); skeletons in {@code <library_nodes>} that
 * nothing places (instantiated as scene roots); a morph on a skin (drawn as the skin). Refused:
 * {@code <instance_node>} cycles, more than {@link #MAX_INSTANCE_DEPTH} nested instances or
 * {@link #MAX_NODES} nodes in all (instancing bombs), and joints that match no node.
 */
final class SceneLoader {
    static final int MAX_NODES = 1_000_000;
    static final int MAX_INSTANCE_DEPTH = 64;

    private final ImportContext ctx;
    private final Map<XmlElement, Mesh> meshes;
    private final Map<XmlElement, Morph> morphs;
    private final Map<XmlElement, Skin> skins;
    private final TransformReader transforms;
    private final InstanceExpansion expansion;
    private final MaterialBinder binder;
    private JointResolver joints; // once the scene is walked

    // Drafts of the nodes, in depth-first order.
    private final List<Draft> drafts = new ArrayList<>();
    private final Map<String, IntList> byId = new HashMap<>();
    private final Map<String, IntList> bySid = new HashMap<>();
    private final Map<String, IntList> byName = new HashMap<>();

    /** @param authoringTool the file's authoring tool, or null (some exporter habits depend on it) */
    SceneLoader(ImportContext ctx, Map<XmlElement, Mesh> meshesByGeometry, Map<XmlElement, Morph> morphsByController,
            Map<XmlElement, Skin> skinsByController, Map<XmlElement, Material> materialsByElement,
            String authoringTool) {
        this.ctx = ctx;
        this.meshes = meshesByGeometry;
        this.morphs = morphsByController;
        this.skins = skinsByController;
        this.transforms = new TransformReader(ctx, authoringTool);
        this.expansion = new InstanceExpansion(ctx);
        this.binder = new MaterialBinder(ctx, materialsByElement);
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
        List<TransformElement> transforms;
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
        long size = expansion.checkExpandedSize(visualScene.children("node"), visualScene, 0);
        Deque<Pending> todo = new ArrayDeque<>();
        pushChildren(todo, visualScene, -1, null);
        walk(todo);
        // Skeletons that live in <library_nodes> and that nothing places in the scene: first
        // those a <skeleton> names, then (with them in place) those holding joints found nowhere else.
        for (int phase = 0; phase < 2; phase++) {
            for (XmlElement root : libraryRoots(phase == 0)) {
                size = expansion.checkExpandedSize(List.of(root), root, size);
                todo.push(new Pending(root, -1, null));
                walk(todo);
            }
        }
        int n = drafts.size();
        int[] parents = new int[n];
        int[] subtreeEnd = new int[n];
        for (int i = n - 1; i >= 0; i--) {
            parents[i] = drafts.get(i).parent;
            int end = i + 1;
            IntList ch = drafts.get(i).children;
            if (ch.size() > 0) {
                end = subtreeEnd[ch.get(ch.size() - 1)];
            }
            subtreeEnd[i] = end;
        }
        joints = new JointResolver(ctx, byId, bySid, byName, parents, subtreeEnd);
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
            d.transforms = transforms.read(p.element);
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
                        String id = ImportContext.idPart(s.text().trim());
                        XmlElement target = byId.containsKey(id) ? null : ctx.byId(id);
                        if (target != null && target.name().equals("node") && seen.add(target)) {
                            ctx.warn(s, "skeleton root \"" + s.text().trim() + "\" lives in <library_nodes> and is"
                                    + " placed nowhere in the scene; instantiated as a root of the scene");
                            roots.add(target);
                        }
                    }
                    continue;
                }
                Skin skin = skins.get(ctx.byId(ImportContext.idPart(String.valueOf(inst.attr("url")))));
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
                XmlElement target = expansion.instanceTarget(c);
                if (chain != null && chain.contains(target)) {
                    throw expansion.cycle(c);
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

    // ------------------------------------------------------------------------------- instances

    private MeshInstance instance(int node, XmlElement inst) throws ColladaException {
        if (inst.name().equals("instance_geometry")) {
            XmlElement geometry = ctx.resolve(inst, "url", "geometry");
            Mesh mesh = meshes.get(geometry);
            if (mesh == null) {
                return null; // not a <mesh>; warned when the geometry was read
            }
            return new MeshInstance(node, mesh, null, new int[0], new int[0], binder.bindings(inst, mesh));
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
                        binder.bindings(inst, morph.result()));
            }
            controller = skinUnderMorphs(controller);
            if (controller == null) {
                return null; // a morph of a geometry that is no mesh
            }
            skin = skins.get(controller);
            ctx.warn(inst, "morph on skin controller \"" + controller.id() + "\": drawn as that skin, without the"
                    + " morph (a morph after skinning is not supported)");
        }
        int[] roots = joints.skeletonRoots(inst, node);
        int[] jointNodes = joints.joints(inst, controller, skin, node, roots);
        return new MeshInstance(node, skin.mesh(), skin, jointNodes, roots, binder.bindings(inst, skin.mesh()));
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


}
