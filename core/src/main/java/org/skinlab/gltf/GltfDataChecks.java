package org.skinlab.gltf;

import java.util.Locale;

/**
 * The checks of {@link GltfDocumentChecks} that need the buffers' values and that reading the
 * model does not make itself: accessor bounds ({@code min}/{@code max} must be the data's, and
 * float data finite), for every accessor that stores values, used or not, as the validator does;
 * float colours in [0, 1]. Non-unit normals are tolerated with a warning (the validator calls them
 * an error, but exporters write them and they are renormalised when drawn). Indices, joints,
 * weights, inverse bind matrices and key times are checked where the importer reads them
 * ({@link MeshReader}, {@link Influences}, {@link InstanceBuilder}, {@link AnimationReader}).
 */
final class GltfDataChecks {
    private static final double UNIT_TOLERANCE = 1e-3;

    private final GltfContext ctx;
    private final JsonNode root;
    private final Buffers buffers;
    private final Accessors accessors;

    private GltfDataChecks(GltfContext ctx, JsonNode root, Buffers buffers, Accessors accessors) {
        this.ctx = ctx;
        this.root = root;
        this.buffers = buffers;
        this.accessors = accessors;
    }

    /** Refuses values the specification forbids; warns about the tolerated ones (class comment). */
    static void check(GltfContext ctx, JsonNode root, Buffers buffers, Accessors accessors) throws GltfException {
        GltfDataChecks checks = new GltfDataChecks(ctx, root, buffers, accessors);
        checks.checkBounds();
        checks.checkMeshes();
    }

    private void checkBounds() throws GltfException {
        for (int i = 0; i < root.get("accessors").size(); i++) {
            JsonNode a = accessors.node(i);
            if (!knownType(a) || !hasData(a)) {
                continue;
            }
            if (!a.has("min") && !a.has("max")) {
                if (a.get("componentType").number() == AccessorFormat.FLOAT) {
                    accessors.floats(i); // refuses NaN and infinities, in unused accessors too
                }
                continue;
            }
            float[] values = accessors.floats(i);
            int n = accessors.components(i);
            float[] lo = new float[n];
            float[] hi = new float[n];
            extremes(values, n, lo, hi);
            for (int c = 0; c < n; c++) {
                checkBound(a, "min", c, lo[c], -1);
                checkBound(a, "max", c, hi[c], 1);
            }
        }
    }

    /** Per component, the smallest and largest value, in one pass (the values are finite). */
    private static void extremes(float[] values, int n, float[] lo, float[] hi) {
        java.util.Arrays.fill(lo, Float.POSITIVE_INFINITY);
        java.util.Arrays.fill(hi, Float.NEGATIVE_INFINITY);
        for (int k = 0; k < values.length; k += n) {
            for (int c = 0; c < n; c++) {
                float v = values[k + c];
                lo[c] = v < lo[c] ? v : lo[c];
                hi[c] = v > hi[c] ? v : hi[c];
            }
        }
    }

    /**
     * Whether the accessor stores values: one without a buffer view or sparse values is zeros by
     * definition, and one in a placeholder buffer has none; the validator does not hold either
     * against its bounds (its files use them to describe structure), nor do we. Reading the
     * latter refuses the file where it is used.
     */
    private boolean hasData(JsonNode a) throws GltfException {
        if (a.has("sparse")) {
            JsonNode sparse = a.get("sparse");
            return inBufferWithData(sparse.get("indices")) && inBufferWithData(sparse.get("values"))
                    && (!a.has("bufferView") || inBufferWithData(a));
        }
        return a.has("bufferView") && inBufferWithData(a);
    }

    private boolean inBufferWithData(JsonNode part) throws GltfException {
        return buffers.hasData((int) part.get("bufferView").number());
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
            case AccessorFormat.BYTE:
                return Math.max(declared / 127, -1);
            case AccessorFormat.UNSIGNED_BYTE:
                return declared / 255;
            case AccessorFormat.SHORT:
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
            }
        }
    }

    private void checkAttribute(JsonNode attribute, String name) throws GltfException {
        if (name.startsWith("COLOR_") && accessors.node(accessors.resolve(attribute)).get("componentType")
                .number() == AccessorFormat.FLOAT) {
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

}
