package org.skinlab.collada;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

import org.joml.Matrix4f;
import org.skinlab.model.Mesh;
import org.skinlab.model.Morph;
import org.skinlab.model.Skin;

/**
 * Reads a {@code <controller><skin>} into a {@link Skin}: bind shape matrix, joints
 * ({@code Name_array} or {@code IDREF_array}) with inverse bind matrices, and every influence of
 * every position ({@code <vertex_weights>}), converting COLLADA's row-major matrices to
 * JOML's column-major order.
 *
 * <p>A skin on a {@code <morph>} deforms the morph's result (its targets applied with the file's
 * weights). Lenient (with a warning): positions without influences; weight sums that differ from one; a
 * bottom matrix row other than (0 0 0 1), which is replaced by it. Refused: a
 * {@code <vertex_weights count>} other than the mesh's position count, joint and inverse bind
 * matrix counts that differ, and joint or weight indices out of range.
 */
final class SkinLoader {
    /** Weight sums further than this from one are reported. */
    static final float WEIGHT_SUM_TOLERANCE = 1e-3f;

    private final ImportContext ctx;
    private final Map<XmlElement, Mesh> meshes;
    private final Map<XmlElement, Morph> morphs;

    SkinLoader(ImportContext ctx, Map<XmlElement, Mesh> meshesByGeometry, Map<XmlElement, Morph> morphsByController) {
        this.ctx = ctx;
        this.meshes = meshesByGeometry;
        this.morphs = morphsByController;
    }

    Skin load(XmlElement controller, XmlElement skin) throws ColladaException {
        Mesh mesh = skinnedMesh(skin);
        Matrix4f bindShape = bindShapeMatrix(skin);
        Joints joints = joints(skin);
        XmlElement weights = ctx.child(skin, "vertex_weights");
        int count = ctx.count(weights, "count", -1);
        if (count != mesh.positionCount()) {
            throw ctx.error(weights, "count=\"" + count + "\" but geometry \"" + mesh.id() + "\" has "
                    + mesh.positionCount() + " positions");
        }
        WeightInputs inputs = weightInputs(weights, joints);
        Influences influences = influences(weights, count, inputs, joints.names.length);
        return new Skin(controller.id(), controller.attr("name"), mesh, bindShape, Arrays.asList(joints.names),
                joints.source.isIdrefs(), joints.inverseBinds, influences.start, influences.joints,
                influences.weights);
    }

    /** The skin's {@code <bind_shape_matrix>}, column-major; the identity when it has none. */
    private Matrix4f bindShapeMatrix(XmlElement skin) throws ColladaException {
        Matrix4f bindShape = new Matrix4f();
        XmlElement bsm = skin.child("bind_shape_matrix");
        if (bsm != null) {
            float[] v = NumberParser.floats(ctx, bsm, -1);
            if (v.length != 16) {
                throw ctx.error(bsm, "has " + v.length + " values, expected 16");
            }
            RowMajor.toColumnMajor(ctx, v, 0, bsm, "bind shape matrix");
            bindShape.set(v);
        }
        return bindShape;
    }

    /** The skin's {@code <joints>}: their names and inverse bind matrices (column-major), one per joint. */
    private static final class Joints {
        Source source;
        String[] names;
        float[] inverseBinds;
    }

    private Joints joints(XmlElement skin) throws ColladaException {
        XmlElement element = ctx.child(skin, "joints");
        Source jointSource = null;
        Source inverseBindSource = null;
        XmlElement jointInput = null;
        XmlElement inverseBindInput = null;
        for (XmlElement input : element.children("input")) {
            String semantic = ctx.attr(input, "semantic");
            if (semantic.equals("JOINT")) {
                jointSource = ctx.inputSource(input);
                jointInput = input;
            } else if (semantic.equals("INV_BIND_MATRIX")) {
                inverseBindSource = ctx.inputSource(input);
                inverseBindInput = input;
            }
        }
        if (jointSource == null) {
            throw ctx.error(element, "has no JOINT input");
        }
        if (inverseBindSource == null) {
            throw ctx.error(element, "has no INV_BIND_MATRIX input");
        }
        Joints joints = new Joints();
        joints.source = jointSource;
        joints.names = jointSource.names(ctx, jointInput, "JOINT");
        joints.inverseBinds = inverseBindSource.floats(ctx, inverseBindInput, 16, "INV_BIND_MATRIX");
        if (inverseBindSource.count() != joints.names.length) {
            throw ctx.error(inverseBindInput, joints.names.length + " joints but " + inverseBindSource.count()
                    + " inverse bind matrices");
        }
        for (int j = 0; j < joints.names.length; j++) {
            RowMajor.toColumnMajor(ctx, joints.inverseBinds, 16 * j, inverseBindInput,
                    "inverse bind matrix of joint \"" + joints.names[j] + "\"");
        }
        return joints;
    }

    /** The {@code <input>}s of {@code <vertex_weights>}: where {@code <v>} holds joint and weight indices. */
    private static final class WeightInputs {
        int jointOffset = -1;
        int weightOffset = -1;
        /** Indices per influence in {@code <v>}. */
        int stride;
        Source weightSource;
        /** Per index of {@link #weightJoints}, the skin's joint; null when it is the skin's own JOINT source. */
        int[] jointRemap;
        /** The source {@code <v>}'s joint indices refer to. */
        Source weightJoints;
    }

    private WeightInputs weightInputs(XmlElement weights, Joints joints) throws ColladaException {
        WeightInputs in = new WeightInputs();
        in.weightJoints = joints.source;
        int maxOffset = -1;
        for (XmlElement input : weights.children("input")) {
            String semantic = ctx.attr(input, "semantic");
            int offset = ctx.inputOffset(input);
            maxOffset = Math.max(maxOffset, offset);
            if (semantic.equals("JOINT")) {
                in.jointOffset = offset;
                in.weightJoints = ctx.inputSource(input);
                in.jointRemap = in.weightJoints == joints.source ? null
                        : remap(input, in.weightJoints.names(ctx, input, "JOINT"), joints.names);
            } else if (semantic.equals("WEIGHT")) {
                in.weightOffset = offset;
                in.weightSource = ctx.inputSource(input);
                in.weightSource.requireFloats(ctx, input, "WEIGHT");
                in.weightSource.requireComponent(ctx, input, "WEIGHT");
            }
        }
        if (in.jointOffset < 0 || in.weightSource == null) {
            throw ctx.error(weights, "needs a JOINT and a WEIGHT input");
        }
        in.stride = maxOffset + 1;
        return in;
    }

    /** Every influence of every position, as {@link Skin} takes them. */
    private static final class Influences {
        int[] start;
        int[] joints;
        float[] weights;
    }

    /** Reads {@code <vcount>} and {@code <v>} into influences, then warns about the weights read. */
    private Influences influences(XmlElement weights, int count, WeightInputs in, int skinJoints)
            throws ColladaException {
        XmlElement vcountElement = weights.child("vcount");
        XmlElement vElement = weights.child("v");
        int[] vcount = vcountElement == null ? new int[0] : NumberParser.ints(ctx, vcountElement, -1);
        int[] v = vElement == null ? new int[0] : NumberParser.ints(ctx, vElement, -1);
        int total = influenceTotal(weights, count, vcountElement, vcount, vElement, v.length, in.stride);
        Influences out = new Influences();
        out.start = new int[count + 1];
        out.joints = new int[total];
        out.weights = new float[total];
        WeightTally tally = new WeightTally();
        int at = 0;
        for (int p = 0; p < count; p++) {
            out.start[p] = at;
            at = readPosition(vElement, v, at, vcount[p], in, skinJoints, out, tally);
        }
        out.start[count] = at;
        tally.warn(ctx, weights, count);
        return out;
    }

    /**
     * The number of influences {@code <vcount>} lists, checked against the position count and
     * the length of {@code <v>}.
     */
    private int influenceTotal(XmlElement weights, int count, XmlElement vcountElement, int[] vcount,
            XmlElement vElement, int vLength, int stride) throws ColladaException {
        if (vcount.length != count) {
            throw ctx.error(vcountElement == null ? weights : vcountElement, "has " + vcount.length
                    + " entries but count=\"" + count + "\"");
        }
        long total = 0;
        for (int n : vcount) {
            if (n < 0) {
                throw ctx.error(vcountElement, "negative influence count " + n);
            }
            total += n;
        }
        if (total * stride != vLength) {
            throw ctx.error(vElement == null ? weights : vElement, "<vcount> adds up to " + total + " influences, which with "
                    + stride + " index offsets need " + total * stride + " indices, <v> has " + vLength);
        }
        return (int) total;
    }

    /**
     * Reads the {@code n} influences of one position, starting with influence {@code at}, into
     * {@code out}; returns the index after them.
     */
    private int readPosition(XmlElement vElement, int[] v, int at, int n, WeightInputs in, int skinJoints,
            Influences out, WeightTally tally) throws ColladaException {
        float sum = 0f;
        boolean negative = false;
        for (int k = 0; k < n; k++, at++) {
            int base = at * in.stride;
            int joint = v[base + in.jointOffset];
            int weightIndex = v[base + in.weightOffset];
            // Indices count in the source <vertex_weights> names, which may be shorter than
            // <joints> when it is another source.
            int jointLimit = in.jointRemap == null ? skinJoints : in.jointRemap.length;
            if (joint < -1 || joint >= jointLimit) {
                throw ctx.error(vElement, "joint index " + joint + " (value " + (base + in.jointOffset)
                        + ") is out of range: " + (in.jointRemap == null ? "the skin has " + jointLimit + " joints"
                        : "JOINT source \"" + in.weightJoints.id() + "\" has " + jointLimit + " names"));
            }
            if (weightIndex < 0 || weightIndex >= in.weightSource.count()) {
                throw ctx.error(vElement, "weight index " + weightIndex + " (value " + (base + in.weightOffset)
                        + ") is out of range: source \"" + in.weightSource.id() + "\" has "
                        + in.weightSource.count() + " weights");
            }
            out.joints[at] = joint < 0 || in.jointRemap == null ? joint : in.jointRemap[joint];
            float w = in.weightSource.floatAt(weightIndex, 0);
            if (w < 0f) {
                // Dividing by a sum with negative terms can push a position anywhere (a lone
                // negative weight divided by itself becomes 1); read as no influence instead.
                tally.negative(w);
                negative = true;
                w = 0f;
            }
            out.weights[at] = w;
            sum += w;
        }
        tally.position(n, sum, negative);
        return at;
    }

    /** What the importer tells about a skin's weights: positions without any, negative ones, sums other than one. */
    private static final class WeightTally {
        int unweighted;
        int badSums;
        float worstSum = 1f;
        int negatives;
        int negativePositions;
        int emptied;
        float mostNegative;

        void negative(float w) {
            negatives++;
            mostNegative = Math.min(mostNegative, w);
        }

        /** Counts a position of {@code n} influences whose weights, negative ones read as 0, sum to {@code sum}. */
        void position(int n, float sum, boolean negative) {
            if (negative) {
                // Told in the negative-weight warning, not counted again as a sum that is not one.
                negativePositions++;
                emptied += sum == 0f ? 1 : 0;
            } else if (n == 0) {
                unweighted++;
            } else if (Math.abs(sum - 1f) > WEIGHT_SUM_TOLERANCE) {
                badSums++;
                if (Math.abs(sum - 1f) > Math.abs(worstSum - 1f)) {
                    worstSum = sum;
                }
            }
        }

        void warn(ImportContext ctx, XmlElement weights, int count) {
            if (unweighted > 0) {
                ctx.warn(weights, unweighted + " of " + count + " positions have no influences; they keep the bind"
                        + " shape (kept as written)");
            }
            if (negatives > 0) {
                ctx.warn(weights, negatives + " negative " + (negatives == 1 ? "weight" : "weights") + " (most negative "
                        + mostNegative + ") on " + negativePositions + " of " + count + " positions read as 0; the other"
                        + " weights of those positions are divided by their sum"
                        + (emptied == 0 ? "" : ", and " + emptied + (emptied == 1 ? " position is" : " positions are")
                        + " left without weight, keeping the bind shape"));
            }
            if (badSums > 0) {
                ctx.warn(weights, badSums + " of " + count + " positions have weights that do not sum to 1 (worst "
                        + worstSum + "); kept as written");
            }
        }
    }

    /** The mesh a skin deforms: its source geometry, or the result of a morph (with the file's weights). */
    private Mesh skinnedMesh(XmlElement skin) throws ColladaException {
        XmlElement target = ctx.resolve(skin, "source", "geometry", "controller");
        if (target.name().equals("controller")) {
            Morph morph = morphs.get(target);
            if (morph == null) {
                throw ctx.error(skin, "source=\"" + skin.attr("source") + "\" is a controller that is no morph of a"
                        + " mesh; a skin cannot deform another skin");
            }
            return morph.result();
        }
        Mesh mesh = meshes.get(target);
        if (mesh == null) {
            throw ctx.error(skin, "source=\"" + skin.attr("source") + "\" is a geometry without a <mesh>");
        }
        return mesh;
    }

    /** Maps joint indices of another name source onto the skin's joints, by name. */
    private int[] remap(XmlElement input, String[] names, String[] jointNames) throws ColladaException {
        Map<String, Integer> index = new HashMap<>();
        for (int j = jointNames.length - 1; j >= 0; j--) {
            index.put(jointNames[j], j);
        }
        int[] map = new int[names.length];
        for (int i = 0; i < names.length; i++) {
            Integer j = index.get(names[i]);
            if (j == null) {
                throw ctx.error(input, "joint \"" + names[i] + "\" is not among the skin's <joints>");
            }
            map[i] = j;
        }
        return map;
    }
}
