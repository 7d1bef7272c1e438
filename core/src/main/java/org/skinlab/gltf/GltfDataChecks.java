package org.skinlab.gltf;

import java.util.Locale;

/**
 * The checks of {@link GltfDocumentChecks} that need the buffers' values: accessor bounds
 * ({@code min}/{@code max} must be the data's), indices inside the vertex range and never the
 * primitive-restart value, joints inside their skin, weights not negative, affine inverse bind
 * matrices, key times from 0 on and increasing, colours in [0, 1]. As the validator does, every
 * accessor with bounds is checked, used or not.
 *
 * <p>Tolerated with a warning (the validator calls them errors, but real exporters write them and
 * the skinning and sampling do what the file means): weights whose sum is off by more than
 * {@value #WEIGHT_SUM_TOLERANCE}, non-unit normals, non-unit rotation keys (the sampler
 * renormalises).
 */
final class GltfDataChecks {
    static final double WEIGHT_SUM_TOLERANCE = 2e-3;
    private static final double UNIT_TOLERANCE = 1e-3;
    /** An affine matrix's last row (0 0 0 1) within float noise. */
    private static final double AFFINE_TOLERANCE = 1e-5;

    private final GltfContext ctx;
    private final JsonNode root;
    private final Accessors accessors;

    private GltfDataChecks(GltfContext ctx, JsonNode root, Accessors accessors) {
        this.ctx = ctx;
        this.root = root;
        this.accessors = accessors;
    }

    /** Refuses values the specification forbids; warns about the tolerated ones (class comment). */
    static void check(GltfContext ctx, JsonNode root, Accessors accessors) throws GltfException {
        GltfDataChecks checks = new GltfDataChecks(ctx, root, accessors);
        checks.checkBounds();
        checks.checkMeshes();
        checks.checkSkins();
        checks.checkAnimations();
    }

    private void checkBounds() throws GltfException {
        for (int i = 0; i < accessors.count(); i++) {
            JsonNode a = accessors.node(i);
            if (!knownType(a) || !hasData(a)) {
                continue;
            }
            if (!a.has("min") && !a.has("max")) {
                if (a.get("componentType").number() == Accessors.FLOAT) {
                    accessors.floats(i); // refuses NaN and infinities, in unused accessors too
                }
                continue;
            }
            float[] values = accessors.floats(i);
            int n = accessors.components(i);
            for (int c = 0; c < n; c++) {
                float lo = Float.POSITIVE_INFINITY;
                float hi = Float.NEGATIVE_INFINITY;
                for (int k = c; k < values.length; k += n) {
                    lo = Math.min(lo, values[k]);
                    hi = Math.max(hi, values[k]);
                }
                checkBound(a, "min", c, lo, -1);
                checkBound(a, "max", c, hi, 1);
            }
        }
    }

    /**
     * Whether the accessor stores values: one without a buffer view or sparse values is zeros by
     * definition, which the validator does not hold against its bounds (its files use such
     * accessors to describe structure), nor do we.
     */
    private static boolean hasData(JsonNode a) throws GltfException {
        return a.has("bufferView") || a.has("sparse");
    }

    private static boolean knownType(JsonNode a) throws GltfException {
        return a.get("type").string().matches("SCALAR|VEC[234]|MAT[234]");
    }

    /** The declared bound must be the data's extreme: nothing beyond it, and attained. */
    private void checkBound(JsonNode a, String which, int c, float actual, int sign) throws GltfException {
        JsonNode bound = a.get(which);
        if (bound.isMissing()) {
            return;
        }
        JsonNode at = bound.get(c);
        double declared = declaredInDataUnits(a, at.number());
        double tolerance = 1e-6 * Math.max(1, Math.abs(declared));
        if (sign * (actual - declared) > tolerance) {
            throw at.error(String.format(Locale.ROOT, "%s %s but a value is %s", which, at.number(), actual));
        }
        if (sign * (declared - actual) > tolerance) {
            throw at.error(String.format(Locale.ROOT, "%s %s but the data's %s is %s", which, at.number(), which,
                    actual));
        }
    }

    /** Bounds are the stored integers; {@link Accessors#floats} gives normalized ones mapped. */
    private static double declaredInDataUnits(JsonNode a, double declared) throws GltfException {
        if (!a.get("normalized").bool(false)) {
            return declared;
        }
        switch ((int) a.get("componentType").number()) {
            case Accessors.BYTE:
                return Math.max(declared / 127, -1);
            case Accessors.UNSIGNED_BYTE:
                return declared / 255;
            case Accessors.SHORT:
                return Math.max(declared / 32767, -1);
            default:
                return declared / 65535;
        }
    }

    private void checkMeshes() throws GltfException {
        JsonNode meshes = root.get("meshes");
        for (int m = 0; m < meshes.size(); m++) {
            JsonNode primitives = meshes.get(m).get("primitives");
            for (int p = 0; p < primitives.size(); p++) {
                JsonNode primitive = primitives.get(p);
                JsonNode attributes = primitive.get("attributes");
                for (String name : attributes.keys()) {
                    checkAttribute(attributes.get(name), name);
                }
                if (primitive.has("indices") && attributes.has("POSITION")) {
                    checkIndices(primitive.get("indices"), accessors.elementCount(
                            accessors.resolve(attributes.get("POSITION"))));
                }
            }
        }
    }

    private void checkAttribute(JsonNode attribute, String name) throws GltfException {
        if (name.startsWith("COLOR_") && accessors.node(accessors.resolve(attribute)).get("componentType")
                .number() == Accessors.FLOAT) {
            for (float v : accessors.floats(accessors.resolve(attribute))) {
                if (!(v >= 0 && v <= 1)) {
                    throw attribute.error("a colour component is " + v + ", outside [0, 1]");
                }
            }
        } else if (name.equals("NORMAL")) {
            float[] n = accessors.floats(accessors.resolve(attribute));
            for (int i = 0; i + 2 < n.length; i += 3) {
                double length = Math.sqrt(n[i] * n[i] + n[i + 1] * n[i + 1] + n[i + 2] * n[i + 2]);
                if (Math.abs(length - 1) > UNIT_TOLERANCE) {
                    ctx.warn(attribute.path(), "normal " + i / 3 + " has length " + (float) length
                            + " (and maybe others); normals are renormalised when drawn");
                    break;
                }
            }
        }
    }

    private void checkIndices(JsonNode indices, int vertices) throws GltfException {
        int accessor = accessors.resolve(indices);
        long restart = restartValue((int) accessors.node(accessor).get("componentType").number());
        int[] values = accessors.ints(accessor);
        for (int i = 0; i < values.length; i++) {
            long v = Integer.toUnsignedLong(values[i]);
            if (v == restart) {
                throw indices.error("index " + i + " is " + v + ", the primitive-restart value, which glTF forbids");
            }
            if (v >= vertices) {
                throw indices.error("index " + i + " is " + v + " but the primitive has " + vertices + " vertices");
            }
        }
    }

    private static long restartValue(int componentType) {
        return componentType == Accessors.UNSIGNED_BYTE ? 0xffL : componentType == Accessors.UNSIGNED_SHORT
                ? 0xffffL : 0xffffffffL;
    }

    /** Joints of each skinned node's mesh inside the node's skin; weights not negative. */
    private void checkSkins() throws GltfException {
        JsonNode nodes = root.get("nodes");
        for (int n = 0; n < nodes.size(); n++) {
            JsonNode node = nodes.get(n);
            if (!node.has("skin") || !node.has("mesh")) {
                continue;
            }
            int joints = root.get("skins").get((int) node.get("skin").number()).get("joints").size();
            JsonNode primitives = root.get("meshes").get((int) node.get("mesh").number()).get("primitives");
            for (int p = 0; p < primitives.size(); p++) {
                checkInfluences(primitives.get(p).get("attributes"), joints);
            }
        }
        JsonNode skins = root.get("skins");
        for (int s = 0; s < skins.size(); s++) {
            JsonNode ibm = skins.get(s).get("inverseBindMatrices");
            if (ibm.isMissing() || !hasData(accessors.node(accessors.resolve(ibm)))) {
                continue;
            }
            float[] m = accessors.floats(accessors.resolve(ibm));
            for (int k = 0; k + 15 < m.length; k += 16) {
                if (Math.abs(m[k + 3]) > AFFINE_TOLERANCE || Math.abs(m[k + 7]) > AFFINE_TOLERANCE
                        || Math.abs(m[k + 11]) > AFFINE_TOLERANCE || Math.abs(m[k + 15] - 1) > AFFINE_TOLERANCE) {
                    throw ibm.error("inverse bind matrix " + k / 16 + " is not affine (its last row is not 0 0 0 1)");
                }
            }
        }
    }

    private void checkInfluences(JsonNode attributes, int joints) throws GltfException {
        float[] sums = null;
        for (int set = 0; attributes.has("JOINTS_" + set) && attributes.has("WEIGHTS_" + set); set++) {
            JsonNode jointsAttribute = attributes.get("JOINTS_" + set);
            for (int j : accessors.ints(accessors.resolve(jointsAttribute))) {
                if (j >= joints) {
                    throw jointsAttribute.error("joint " + j + " but the skin has " + joints + " joints");
                }
            }
            JsonNode weightsAttribute = attributes.get("WEIGHTS_" + set);
            float[] w = accessors.floats(accessors.resolve(weightsAttribute));
            sums = sums == null ? new float[w.length / 4] : sums;
            for (int i = 0; i < w.length; i++) {
                if (w[i] < 0) {
                    throw weightsAttribute.error("weight " + i % 4 + " of vertex " + i / 4 + " is negative (" + w[i] + ")");
                }
                if (i / 4 < sums.length) {
                    sums[i / 4] += w[i];
                }
            }
        }
        for (int v = 0; sums != null && v < sums.length; v++) {
            if (Math.abs(sums[v] - 1) > WEIGHT_SUM_TOLERANCE) {
                ctx.warn(attributes.path(), "the weights of vertex " + v + " sum to " + sums[v]
                        + " (and maybe others'); they are kept as written");
                break;
            }
        }
    }

    private void checkAnimations() throws GltfException {
        JsonNode animations = root.get("animations");
        for (int a = 0; a < animations.size(); a++) {
            JsonNode samplers = animations.get(a).get("samplers");
            for (int s = 0; s < samplers.size(); s++) {
                JsonNode input = samplers.get(s).get("input");
                if (!hasData(accessors.node(accessors.resolve(input)))) {
                    continue;
                }
                float[] t = accessors.floats(accessors.resolve(input));
                if (t.length > 0 && t[0] < 0) {
                    throw input.error("the first key time is negative (" + t[0] + ")");
                }
                for (int k = 1; k < t.length; k++) {
                    if (!(t[k] > t[k - 1])) {
                        throw input.error("key times must increase: key " + k + " is " + t[k] + " after " + t[k - 1]);
                    }
                }
            }
            checkRotationKeys(animations.get(a));
        }
    }

    private void checkRotationKeys(JsonNode animation) throws GltfException {
        JsonNode channels = animation.get("channels");
        for (int c = 0; c < channels.size(); c++) {
            JsonNode channel = channels.get(c);
            if (!"rotation".equals(channel.get("target").get("path").string(""))) {
                continue;
            }
            JsonNode sampler = animation.get("samplers").get((int) channel.get("sampler").number());
            boolean cubic = sampler.get("interpolation").string("LINEAR").equals("CUBICSPLINE");
            float[] q = accessors.floats(accessors.resolve(sampler.get("output")));
            for (int i = 0; i + 3 < q.length; i += 4) {
                if (cubic && i / 4 % 3 != 1) {
                    continue; // tangents need not be unit
                }
                double length = Math.sqrt(q[i] * q[i] + q[i + 1] * q[i + 1] + q[i + 2] * q[i + 2] + q[i + 3] * q[i + 3]);
                if (Math.abs(length - 1) > UNIT_TOLERANCE) {
                    ctx.warn(channel.get("sampler").path(), "rotation key " + i / 4 + " has length " + (float) length
                            + " (and maybe others); rotations are renormalised when sampled");
                    break;
                }
            }
        }
    }
}
