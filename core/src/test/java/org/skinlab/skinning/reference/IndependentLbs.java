package org.skinlab.skinning.reference;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;

import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.SAXException;

/**
 * A second, independent evaluation of Linear Blend Skinning at key times, straight from a COLLADA
 * 1.4.1 file, for conformance tests. It shares no code with {@code org.skinlab.collada},
 * {@code org.skinlab.model}, {@code org.skinlab.animation} or {@code org.skinlab.skinning} (nor
 * JOML): the JDK's DOM parser, its own number reading, its own row-major {@code double[16]}
 * matrices, its own scene walk and its own joint resolution, all in double precision.
 *
 * <p>What it does, by the specification (COLLADA 1.4.1, chapters 5 "Skin", 6 "Animation"
 * and the "Address Syntax" of chapter 3):
 * <ul>
 * <li>Scene: the {@code <instance_visual_scene>} of {@code <scene>} (else the first visual scene),
 *     walked depth-first; {@code <instance_node>} instantiates a copy. A node's local matrix is
 *     the product, in document order, of its {@code <matrix>} (row-major), {@code <translate>},
 *     {@code <rotate>} (axis, degrees) and {@code <scale>}; its world matrix the parent's world
 *     times that.</li>
 * <li>Animation: the channels of the first {@code <animation_clip>} (those of its
 *     {@code <instance_animation>}s, at any nesting depth), or of every {@code <animation>} when the
 *     file has no clips. At a key time the value of a channel <em>is</em> its OUTPUT at that key:
 *     no interpolation is evaluated, so the key times checked are those shared by every channel.
 *     Targets: {@code node/sid} (the whole element) and the members {@code .X .Y .Z .ANGLE} and
 *     {@code (i)} of a vector.</li>
 * <li>Skin: per {@code <instance_controller>}, Name_array joints are the nodes whose
 *     <b>sid</b> matches, searched depth-first under each {@code <skeleton>} root in order;
 *     IDREF_array joints are node ids. Joint index -1 is the bind shape itself.
 *     {@code v' = sum_i w_i * World(joint_i) * INV_BIND_MATRIX_i * BIND_SHAPE_MATRIX * v / sum_i w_i};
 *     a position without influences (or with weights summing to zero) stays at
 *     {@code BIND_SHAPE_MATRIX * v}. A static mesh is placed by its node's world matrix.</li>
 * </ul>
 * What it does not do is refused with {@link Unsupported} naming the feature, so that a test can
 * skip the file and say why: {@code <lookat>}, {@code <skew>}, {@code (i)(j)} matrix targets,
 * nested sid paths, morph controllers, joints that are no sid under the skeleton roots (the
 * lenient fallbacks of real importers are not the specification), and key times where a channel
 * has two keys.
 */
public final class IndependentLbs {
    /** The file uses something this evaluator does not implement. */
    public static final class Unsupported extends Exception {
        private static final long serialVersionUID = 1L;

        Unsupported(String reason) {
            super(reason);
        }
    }

    /** One placed mesh: the instance's node id and geometry id, as the file writes them. */
    public static final class Placement {
        public final String nodeId;
        public final String geometryId;
        public final boolean skinned;
        final int node;
        final double[] positions;
        // Skin (null when static).
        final double[] bindShape;
        final int[] jointNodes;
        final double[][] inverseBind;
        final int[] influenceStart;
        final int[] influenceJoint;
        final double[] influenceWeight;

        Placement(String nodeId, String geometryId, int node, double[] positions, double[] bindShape,
                int[] jointNodes, double[][] inverseBind, int[] influenceStart, int[] influenceJoint,
                double[] influenceWeight) {
            this.nodeId = nodeId;
            this.geometryId = geometryId;
            this.skinned = bindShape != null;
            this.node = node;
            this.positions = positions;
            this.bindShape = bindShape;
            this.jointNodes = jointNodes;
            this.inverseBind = inverseBind;
            this.influenceStart = influenceStart;
            this.influenceJoint = influenceJoint;
            this.influenceWeight = influenceWeight;
        }

        /** Number of entries of the mesh's POSITION source. */
        public int positionCount() {
            return positions.length / 3;
        }
    }

    /** One node of the instantiated scene. */
    private static final class SceneNode {
        final Element element;
        final int parent;
        final List<Element> transforms;

        SceneNode(Element element, int parent, List<Element> transforms) {
            this.element = element;
            this.parent = parent;
            this.transforms = transforms;
        }
    }

    /** A channel reduced to what key sampling needs. */
    private static final class Channel {
        final String target;
        final Element element;
        final int first;
        final double[] times;
        final double[] values;
        final int width;

        Channel(String target, Element element, int first, double[] times, double[] values, int width) {
            this.target = target;
            this.element = element;
            this.first = first;
            this.times = times;
            this.values = values;
            this.width = width;
        }
    }

    private static final int MAX_INSTANCE_DEPTH = 64;

    private final Map<String, Element> ids = new HashMap<>();
    private final List<SceneNode> nodes = new ArrayList<>();
    private final List<Placement> placements = new ArrayList<>();
    private final Map<Element, double[]> restValues = new IdentityHashMap<>();
    private final List<Channel> channels = new ArrayList<>();
    private String clipName;
    private double clipStart;
    private double clipEnd;

    private IndependentLbs() {
    }

    /** Reads a file. */
    public static IndependentLbs read(Path file) throws IOException, Unsupported {
        Element root;
        try (InputStream in = Files.newInputStream(file)) {
            root = parser().parse(in).getDocumentElement();
        } catch (SAXException | ParserConfigurationException e) {
            throw new IOException(file + ": " + e.getMessage(), e);
        }
        IndependentLbs lbs = new IndependentLbs();
        lbs.indexIds(root);
        lbs.readScene(root);
        lbs.readAnimation(root);
        return lbs;
    }

    /** A DOM parser that refuses DTDs and never reads anything but the file itself. */
    private static DocumentBuilder parser() throws ParserConfigurationException {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setNamespaceAware(true);
        f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        f.setFeature("http://xml.org/sax/features/external-general-entities", false);
        f.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
        f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        f.setXIncludeAware(false);
        f.setExpandEntityReferences(false);
        return f.newDocumentBuilder();
    }

    // ------------------------------------------------------------------------------ public view

    /** The placed meshes in scene order (depth-first, a node's instances before its children). */
    public List<Placement> placements() {
        return placements;
    }

    /** Name (else id) of the clip evaluated; null when the file has no {@code <animation_clip>}. */
    public String clipName() {
        return clipName;
    }

    /** Number of channels that drive scene nodes. */
    public int channelCount() {
        return channels.size();
    }

    /**
     * The times at which every channel has exactly one key, within the clip's [start, end]
     * (the whole key range when the file has no clips), ascending.
     */
    public double[] keyTimes() {
        if (channels.isEmpty()) {
            return new double[0];
        }
        TreeSet<Double> common = null;
        for (Channel c : channels) {
            TreeSet<Double> once = new TreeSet<>();
            TreeSet<Double> seen = new TreeSet<>();
            for (double t : c.times) {
                if (!seen.add(t)) {
                    once.remove(t); // two keys at one time: the value there is ambiguous
                } else {
                    once.add(t);
                }
            }
            if (common == null) {
                common = once;
            } else {
                common.retainAll(once);
            }
        }
        return common.stream().filter(t -> t >= clipStart && t <= clipEnd).mapToDouble(Double::doubleValue).toArray();
    }

    /**
     * Deformed positions of every placement at key time {@code time}: per placement, 3 doubles per
     * entry of its POSITION source, in source order.
     */
    public double[][] pose(double time) {
        return evaluate(time, true);
    }

    /** Positions as written, no channel applied: the pose of a file without animation. */
    public double[][] restPose() {
        return evaluate(Double.NaN, false);
    }

    private double[][] evaluate(double time, boolean animate) {
        Map<Element, double[]> values = new IdentityHashMap<>();
        for (Map.Entry<Element, double[]> e : restValues.entrySet()) {
            values.put(e.getKey(), e.getValue().clone());
        }
        for (Channel c : animate ? channels : List.<Channel>of()) {
            int k = -1;
            for (int i = 0; i < c.times.length; i++) {
                if (c.times[i] == time) {
                    k = i;
                }
            }
            if (k < 0) {
                throw new IllegalArgumentException(time + " is no key time of channel " + c.target);
            }
            System.arraycopy(c.values, k * c.width, values.get(c.element), c.first, c.width);
        }
        double[][] world = new double[nodes.size()][];
        for (int i = 0; i < nodes.size(); i++) {
            SceneNode n = nodes.get(i);
            double[] local = identity();
            for (Element t : n.transforms) {
                local = mul(local, matrixOf(t.getLocalName(), values.get(t)));
            }
            world[i] = n.parent < 0 ? local : mul(world[n.parent], local);
        }
        double[][] result = new double[placements.size()][];
        for (int p = 0; p < placements.size(); p++) {
            result[p] = deform(placements.get(p), world);
        }
        return result;
    }

    private static double[] deform(Placement pl, double[][] world) {
        double[] in = pl.positions;
        double[] out = new double[in.length];
        if (!pl.skinned) {
            for (int v = 0; v < in.length; v += 3) {
                transformPoint(world[pl.node], in, v, 1.0, out);
            }
            return out;
        }
        int joints = pl.jointNodes.length;
        double[][] skinning = new double[joints][];
        for (int j = 0; j < joints; j++) {
            skinning[j] = mul(mul(world[pl.jointNodes[j]], pl.inverseBind[j]), pl.bindShape);
        }
        for (int v = 0; v < in.length / 3; v++) {
            int start = pl.influenceStart[v];
            int end = pl.influenceStart[v + 1];
            double sum = 0;
            for (int i = start; i < end; i++) {
                sum += pl.influenceWeight[i];
            }
            if (end == start || sum == 0) {
                transformPoint(pl.bindShape, in, 3 * v, 1.0, out);
                continue;
            }
            for (int i = start; i < end; i++) {
                int j = pl.influenceJoint[i];
                transformPoint(j < 0 ? pl.bindShape : skinning[j], in, 3 * v, pl.influenceWeight[i] / sum, out);
            }
        }
        return out;
    }

    /** out[v..v+2] += weight * (M * (p, 1)). */
    private static void transformPoint(double[] m, double[] p, int v, double weight, double[] out) {
        double x = p[v];
        double y = p[v + 1];
        double z = p[v + 2];
        for (int r = 0; r < 3; r++) {
            out[v + r] += weight * (m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3]);
        }
    }

    // ------------------------------------------------------------------------------------ XML

    private void indexIds(Element e) {
        String id = e.getAttribute("id");
        if (!id.isEmpty()) {
            ids.putIfAbsent(id, e);
        }
        for (Element c : children(e)) {
            indexIds(c);
        }
    }

    private static List<Element> children(Element e) {
        List<Element> list = new ArrayList<>();
        for (Node n = e.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element) {
                list.add((Element) n);
            }
        }
        return list;
    }

    private static List<Element> children(Element e, String name) {
        List<Element> list = new ArrayList<>();
        for (Element c : children(e)) {
            if (name.equals(c.getLocalName())) {
                list.add(c);
            }
        }
        return list;
    }

    private static Element child(Element e, String name) {
        List<Element> list = children(e, name);
        return list.isEmpty() ? null : list.get(0);
    }

    private static void descendants(Element e, String name, List<Element> into) {
        for (Element c : children(e)) {
            if (name.equals(c.getLocalName())) {
                into.add(c);
            }
            descendants(c, name, into);
        }
    }

    private Element byUrl(String url, String expected, String from) throws Unsupported {
        Element e = url.startsWith("#") ? ids.get(url.substring(1)) : null;
        if (e == null || !expected.equals(e.getLocalName())) {
            throw new Unsupported(from + " refers to " + url + ", which is no <" + expected + "> in the file");
        }
        return e;
    }

    private static String[] tokens(Element e) {
        String text = e.getTextContent().trim();
        return text.isEmpty() ? new String[0] : text.split("\\s+");
    }

    private static double[] doubles(Element e) {
        String[] t = tokens(e);
        double[] d = new double[t.length];
        for (int i = 0; i < t.length; i++) {
            d[i] = Double.parseDouble(t[i]);
        }
        return d;
    }

    private static int[] ints(Element e) {
        String[] t = tokens(e);
        int[] d = new int[t.length];
        for (int i = 0; i < t.length; i++) {
            d[i] = Integer.parseInt(t[i]);
        }
        return d;
    }

    private static int intAttribute(Element e, String name, int fallback) {
        String s = e.getAttribute(name);
        return s.isEmpty() ? fallback : Integer.parseInt(s);
    }

    /**
     * A {@code <source>} read through its accessor: {@code width} values per entry. An accessor
     * with one parameter (a float, a float4x4, a name) yields {@code stride} values per entry; with
     * several, the named parameters in order (unnamed ones are skipped, as the specification says).
     */
    private double[] floatSource(Element source, int width) throws Unsupported {
        Element accessor = child(child(source, "technique_common"), "accessor");
        Element array = byUrl(accessor.getAttribute("source"), "float_array", "<accessor> in <source id=\""
                + source.getAttribute("id") + "\">");
        double[] data = doubles(array);
        int count = intAttribute(accessor, "count", 0);
        int stride = intAttribute(accessor, "stride", 1);
        int offset = intAttribute(accessor, "offset", 0);
        int[] picks = picks(accessor, stride, width, source);
        double[] out = new double[count * width];
        for (int k = 0; k < count; k++) {
            for (int c = 0; c < width; c++) {
                out[k * width + c] = data[offset + k * stride + picks[c]];
            }
        }
        return out;
    }

    private static int[] picks(Element accessor, int stride, int width, Element source) throws Unsupported {
        List<Element> params = children(accessor, "param");
        int[] picks = new int[width];
        if (params.size() == 1) {
            if (stride < width) {
                throw new Unsupported("<source id=\"" + source.getAttribute("id") + "\"> has " + stride
                        + " values per entry, expected " + width);
            }
            for (int c = 0; c < width; c++) {
                picks[c] = c;
            }
            return picks;
        }
        int c = 0;
        for (int i = 0; i < params.size() && c < width; i++) {
            if (!params.get(i).getAttribute("name").isEmpty()) {
                picks[c++] = i;
            }
        }
        if (c < width) {
            throw new Unsupported("<source id=\"" + source.getAttribute("id") + "\"> has fewer than " + width
                    + " named parameters");
        }
        return picks;
    }

    /** The {@code Name_array} or {@code IDREF_array} a joint source reads. */
    private Element nameArray(Element source) throws Unsupported {
        Element accessor = child(child(source, "technique_common"), "accessor");
        String url = accessor.getAttribute("source");
        Element array = url.startsWith("#") ? ids.get(url.substring(1)) : null;
        if (array == null || !(array.getLocalName().equals("Name_array") || array.getLocalName().equals("IDREF_array"))) {
            throw new Unsupported("joint source " + source.getAttribute("id") + " is no Name_array or IDREF_array");
        }
        return array;
    }

    private String[] nameSource(Element source) throws Unsupported {
        Element accessor = child(child(source, "technique_common"), "accessor");
        String[] names = tokens(nameArray(source));
        int count = intAttribute(accessor, "count", 0);
        int stride = intAttribute(accessor, "stride", 1);
        int offset = intAttribute(accessor, "offset", 0);
        String[] out = new String[count];
        for (int k = 0; k < count; k++) {
            out[k] = names[offset + k * stride];
        }
        return out;
    }

    private Element input(Element parent, String semantic) {
        for (Element in : children(parent, "input")) {
            if (semantic.equals(in.getAttribute("semantic"))) {
                return in;
            }
        }
        return null;
    }

    private Element inputSource(Element parent, String semantic, String where) throws Unsupported {
        Element in = input(parent, semantic);
        if (in == null) {
            throw new Unsupported(where + " has no " + semantic + " input");
        }
        return byUrl(in.getAttribute("source"), "source", where + " " + semantic);
    }

    // ---------------------------------------------------------------------------------- scene

    private void readScene(Element root) throws Unsupported {
        Element visualScene = null;
        Element scene = child(root, "scene");
        Element ivs = scene == null ? null : child(scene, "instance_visual_scene");
        if (ivs != null) {
            visualScene = byUrl(ivs.getAttribute("url"), "visual_scene", "<instance_visual_scene>");
        } else {
            for (Element lib : children(root, "library_visual_scenes")) {
                if (visualScene == null) {
                    visualScene = child(lib, "visual_scene");
                }
            }
        }
        if (visualScene == null) {
            return;
        }
        List<Element> controllers = new ArrayList<>();
        List<int[]> slots = new ArrayList<>();
        for (Element n : children(visualScene, "node")) {
            walk(n, -1, 0, controllers, slots);
        }
        // Skins need every node of the scene (joints may come after the instance).
        for (int i = 0; i < controllers.size(); i++) {
            int[] slot = slots.get(i);
            placements.set(slot[0], skinned(controllers.get(i), slot[1]));
        }
    }

    /**
     * Adds the node and its subtree. Skinned instances get a placeholder in {@link #placements}:
     * {@code controllers} and {@code slots} (placement index, node index) say which to fill.
     */
    private void walk(Element node, int parent, int depth, List<Element> controllers, List<int[]> slots)
            throws Unsupported {
        if (depth > MAX_INSTANCE_DEPTH) {
            throw new Unsupported("<instance_node> nested deeper than " + MAX_INSTANCE_DEPTH);
        }
        List<Element> transforms = new ArrayList<>();
        for (Element c : children(node)) {
            switch (c.getLocalName()) {
                case "matrix":
                case "translate":
                case "rotate":
                case "scale": {
                    double[] values = doubles(c);
                    int expected = c.getLocalName().equals("matrix") ? 16 : c.getLocalName().equals("rotate") ? 4 : 3;
                    if (values.length != expected) {
                        throw new Unsupported("<" + c.getLocalName() + "> in <node id=\"" + node.getAttribute("id")
                                + "\"> has " + values.length + " values");
                    }
                    if (c.getLocalName().equals("rotate") && values[0] == 0 && values[1] == 0 && values[2] == 0) {
                        throw new Unsupported("<rotate> about a zero axis in <node id=\"" + node.getAttribute("id")
                                + "\">");
                    }
                    transforms.add(c);
                    restValues.put(c, values);
                    break;
                }
                case "lookat":
                case "skew":
                    throw new Unsupported("<" + c.getLocalName() + "> in <node id=\"" + node.getAttribute("id")
                            + "\"> (not implemented by the independent evaluator)");
                default:
                    break;
            }
        }
        int index = nodes.size();
        nodes.add(new SceneNode(node, parent, transforms));
        for (Element c : children(node)) {
            if (c.getLocalName().equals("instance_geometry")) {
                Element geometry = byUrl(c.getAttribute("url"), "geometry", "<instance_geometry>");
                if (child(geometry, "mesh") != null) {
                    placements.add(new Placement(node.getAttribute("id"), geometry.getAttribute("id"), index,
                            positions(geometry), null, null, null, null, null, null));
                }
            } else if (c.getLocalName().equals("instance_controller")) {
                slots.add(new int[] {placements.size(), index});
                placements.add(null);
                controllers.add(c);
            }
        }
        for (Element c : children(node)) {
            if (c.getLocalName().equals("node")) {
                walk(c, index, depth, controllers, slots);
            } else if (c.getLocalName().equals("instance_node")) {
                walk(byUrl(c.getAttribute("url"), "node", "<instance_node>"), index, depth + 1, controllers, slots);
            }
        }
    }

    private double[] positions(Element geometry) throws Unsupported {
        Element mesh = child(geometry, "mesh");
        Element vertices = child(mesh, "vertices");
        if (vertices == null) {
            throw new Unsupported("<geometry id=\"" + geometry.getAttribute("id") + "\"> has no <vertices>");
        }
        return floatSource(inputSource(vertices, "POSITION", "<vertices> of " + geometry.getAttribute("id")), 3);
    }

    private Placement skinned(Element instance, int node) throws Unsupported {
        Element controller = byUrl(instance.getAttribute("url"), "controller", "<instance_controller>");
        Element skin = child(controller, "skin");
        if (skin == null) {
            throw new Unsupported("<controller id=\"" + controller.getAttribute("id") + "\"> is no <skin>");
        }
        String where = "<skin> of " + controller.getAttribute("id");
        String sourceUrl = skin.getAttribute("source");
        Element base = sourceUrl.startsWith("#") ? ids.get(sourceUrl.substring(1)) : null;
        if (base == null || !base.getLocalName().equals("geometry") || child(base, "mesh") == null) {
            throw new Unsupported(where + " skins " + sourceUrl + ", which is no mesh geometry (morph?)");
        }
        double[] positions = positions(base);
        Element bsm = child(skin, "bind_shape_matrix");
        double[] bindShape = bsm == null ? identity() : doubles(bsm);
        Element jointsElement = child(skin, "joints");
        Element jointSource = inputSource(jointsElement, "JOINT", where + " <joints>");
        String[] jointNames = nameSource(jointSource);
        boolean idrefs = nameArray(jointSource).getLocalName().equals("IDREF_array");
        double[] ibm = floatSource(inputSource(jointsElement, "INV_BIND_MATRIX", where + " <joints>"), 16);
        double[][] inverseBind = new double[jointNames.length][];
        for (int j = 0; j < jointNames.length; j++) {
            inverseBind[j] = Arrays.copyOfRange(ibm, 16 * j, 16 * j + 16);
        }
        int[] jointNodes = new int[jointNames.length];
        List<Integer> roots = new ArrayList<>();
        for (Element s : children(instance, "skeleton")) {
            String url = s.getTextContent().trim();
            for (int i = 0; i < nodes.size(); i++) {
                if (url.equals("#" + nodes.get(i).element.getAttribute("id"))) {
                    roots.add(i);
                    break;
                }
            }
        }
        for (int j = 0; j < jointNames.length; j++) {
            jointNodes[j] = idrefs ? nodeById(jointNames[j]) : nodeBySidUnder(roots, jointNames[j]);
            if (jointNodes[j] < 0) {
                throw new Unsupported(where + ": joint \"" + jointNames[j] + "\" is no "
                        + (idrefs ? "node id" : "sid under the " + roots.size() + " <skeleton> root(s)")
                        + " (only the specification's resolution is implemented)");
            }
        }

        Element vw = child(skin, "vertex_weights");
        Element jointInput = input(vw, "JOINT");
        Element weightInput = input(vw, "WEIGHT");
        if (jointInput == null || weightInput == null) {
            throw new Unsupported(where + " <vertex_weights> lacks JOINT or WEIGHT");
        }
        // The JOINT input of <vertex_weights> may name joints through another source: by name.
        Element vwJointSource = byUrl(jointInput.getAttribute("source"), "source", where + " <vertex_weights> JOINT");
        int[] jointMap = new int[0];
        if (vwJointSource != jointSource) {
            String[] vwNames = nameSource(vwJointSource);
            jointMap = new int[vwNames.length];
            for (int i = 0; i < vwNames.length; i++) {
                jointMap[i] = Arrays.asList(jointNames).indexOf(vwNames[i]);
                if (jointMap[i] < 0) {
                    throw new Unsupported(where + ": weight joint " + vwNames[i] + " is not among the skin's joints");
                }
            }
        }
        double[] weights = floatSource(byUrl(weightInput.getAttribute("source"), "source", where + " WEIGHT"), 1);
        int jointOffset = intAttribute(jointInput, "offset", 0);
        int weightOffset = intAttribute(weightInput, "offset", 0);
        int tuple = 0;
        for (Element in : children(vw, "input")) {
            tuple = Math.max(tuple, intAttribute(in, "offset", 0) + 1);
        }
        int count = positions.length / 3;
        if (intAttribute(vw, "count", -1) != count) {
            throw new Unsupported(where + ": <vertex_weights count> is not the position count " + count);
        }
        Element vcountElement = child(vw, "vcount");
        Element vElement = child(vw, "v");
        int[] vcount = vcountElement == null ? new int[count] : ints(vcountElement);
        int[] v = vElement == null ? new int[0] : ints(vElement);
        int[] start = new int[count + 1];
        for (int i = 0; i < count; i++) {
            start[i + 1] = start[i] + vcount[i];
        }
        int[] joint = new int[start[count]];
        double[] weight = new double[start[count]];
        for (int i = 0; i < joint.length; i++) {
            int j = v[tuple * i + jointOffset];
            joint[i] = j < 0 || jointMap.length == 0 ? j : jointMap[j];
            weight[i] = weights[v[tuple * i + weightOffset]];
        }
        return new Placement(nodes.get(node).element.getAttribute("id"), base.getAttribute("id"), node, positions,
                bindShape, jointNodes, inverseBind, start, joint, weight);
    }

    private int nodeById(String id) {
        for (int i = 0; i < nodes.size(); i++) {
            if (id.equals(nodes.get(i).element.getAttribute("id"))) {
                return i;
            }
        }
        return -1;
    }

    /** The first node, depth-first under each root in order (the root included), with this sid. */
    private int nodeBySidUnder(List<Integer> roots, String sid) {
        for (int root : roots) {
            // Nodes are stored depth-first, so a root's subtree is the run of its descendants after it.
            for (int i = root; i < nodes.size() && (i == root || isUnder(i, root)); i++) {
                if (sid.equals(nodes.get(i).element.getAttribute("sid"))) {
                    return i;
                }
            }
        }
        return -1;
    }

    private boolean isUnder(int node, int root) {
        for (int p = nodes.get(node).parent; p >= 0; p = nodes.get(p).parent) {
            if (p == root) {
                return true;
            }
        }
        return false;
    }

    // ------------------------------------------------------------------------------ animation

    private void readAnimation(Element root) throws Unsupported {
        List<Element> channelElements = new ArrayList<>();
        Element clip = null;
        for (Element lib : children(root, "library_animation_clips")) {
            if (clip == null) {
                clip = child(lib, "animation_clip");
            }
        }
        if (clip != null) {
            clipName = !clip.getAttribute("name").isEmpty() ? clip.getAttribute("name") : clip.getAttribute("id");
            for (Element ia : children(clip, "instance_animation")) {
                descendants(byUrl(ia.getAttribute("url"), "animation", "<instance_animation>"), "channel",
                        channelElements);
            }
        } else {
            for (Element lib : children(root, "library_animations")) {
                descendants(lib, "channel", channelElements);
            }
        }
        double first = Double.POSITIVE_INFINITY;
        double last = Double.NEGATIVE_INFINITY;
        for (Element ch : channelElements) {
            Channel c = channel(ch);
            if (c != null) {
                channels.add(c);
                first = Math.min(first, c.times[0]);
                last = Math.max(last, c.times[c.times.length - 1]);
            }
        }
        clipStart = first;
        clipEnd = last;
        if (clip != null) {
            clipStart = clip.getAttribute("start").isEmpty() ? 0 : Double.parseDouble(clip.getAttribute("start"));
            if (!clip.getAttribute("end").isEmpty()) {
                clipEnd = Double.parseDouble(clip.getAttribute("end"));
            }
        }
    }

    /** The channel, or null when its target is no node of the file (a material, a camera...). */
    private Channel channel(Element ch) throws Unsupported {
        String target = ch.getAttribute("target");
        int slash = target.indexOf('/');
        Element node = slash < 0 ? null : ids.get(target.substring(0, slash));
        if (node == null || !node.getLocalName().equals("node")) {
            return null;
        }
        String rest = target.substring(slash + 1);
        if (rest.contains("/")) {
            throw new Unsupported("channel target " + target + ": nested sid paths are not implemented");
        }
        String sid = rest;
        String member = null;
        int cut = indexOfAny(rest, ".(");
        if (cut >= 0) {
            sid = rest.substring(0, cut);
            member = rest.substring(cut);
        }
        Element element = null;
        for (Element c : children(node)) {
            if (sid.equals(c.getAttribute("sid")) && restValues.containsKey(c)) {
                element = c;
            }
        }
        if (element == null) {
            // Not a transform of a node in the scene: it cannot move anything we place.
            for (Element c : children(node)) {
                if (sid.equals(c.getAttribute("sid"))) {
                    throw new Unsupported("channel target " + target + " is a <" + c.getLocalName() + ">");
                }
            }
            return null;
        }
        int size = restValues.get(element).length;
        int firstValue = 0;
        int width = size;
        if (member != null) {
            width = 1;
            String kind = element.getLocalName();
            if (member.matches("\\(\\d+\\)")) {
                firstValue = Integer.parseInt(member.substring(1, member.length() - 1));
            } else if (member.equals(".ANGLE") && kind.equals("rotate")) {
                firstValue = 3;
            } else if (member.matches("\\.[XYZ]") && !kind.equals("matrix")) {
                firstValue = member.charAt(1) - 'X';
            } else {
                throw new Unsupported("channel target " + target + ": member " + member + " of a <" + kind
                        + "> is not implemented");
            }
            if (firstValue >= size) {
                throw new Unsupported("channel target " + target + " is beyond the element's " + size + " values");
            }
        }
        Element sampler = byUrl(ch.getAttribute("source"), "sampler", "<channel target=\"" + target + "\">");
        double[] times = floatSource(inputSource(sampler, "INPUT", "<sampler>"), 1);
        double[] values = floatSource(inputSource(sampler, "OUTPUT", "<sampler>"), width);
        if (times.length == 0 || values.length != times.length * width) {
            throw new Unsupported("sampler of " + target + ": INPUT and OUTPUT counts disagree");
        }
        return new Channel(target, element, firstValue, times, values, width);
    }

    private static int indexOfAny(String s, String chars) {
        for (int i = 0; i < s.length(); i++) {
            if (chars.indexOf(s.charAt(i)) >= 0) {
                return i;
            }
        }
        return -1;
    }

    // ------------------------------------------------------------------- row-major 4x4 doubles

    private static double[] identity() {
        double[] m = new double[16];
        m[0] = m[5] = m[10] = m[15] = 1;
        return m;
    }

    private static double[] mul(double[] a, double[] b) {
        double[] c = new double[16];
        for (int r = 0; r < 4; r++) {
            for (int k = 0; k < 4; k++) {
                double s = 0;
                for (int i = 0; i < 4; i++) {
                    s += a[4 * r + i] * b[4 * i + k];
                }
                c[4 * r + k] = s;
            }
        }
        return c;
    }

    /** The matrix of one transform element from its (possibly animated) values. */
    private static double[] matrixOf(String kind, double[] v) {
        double[] m = identity();
        switch (kind) {
            case "matrix":
                return v.clone();
            case "translate":
                m[3] = v[0];
                m[7] = v[1];
                m[11] = v[2];
                return m;
            case "scale":
                m[0] = v[0];
                m[5] = v[1];
                m[10] = v[2];
                return m;
            case "rotate": {
                // Rodrigues: R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T, k the unit axis.
                double len = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                double x = v[0] / len;
                double y = v[1] / len;
                double z = v[2] / len;
                double a = Math.toRadians(v[3]);
                double c = Math.cos(a);
                double s = Math.sin(a);
                double t = 1 - c;
                m[0] = c + t * x * x;
                m[1] = t * x * y - s * z;
                m[2] = t * x * z + s * y;
                m[4] = t * x * y + s * z;
                m[5] = c + t * y * y;
                m[6] = t * y * z - s * x;
                m[8] = t * x * z - s * y;
                m[9] = t * y * z + s * x;
                m[10] = c + t * z * z;
                return m;
            }
            default:
                throw new IllegalArgumentException(kind);
        }
    }
}
