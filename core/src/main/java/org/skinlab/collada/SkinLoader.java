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

        XmlElement joints = ctx.child(skin, "joints");
        Source jointSource = null;
        Source inverseBindSource = null;
        XmlElement jointInput = null;
        XmlElement inverseBindInput = null;
        for (XmlElement input : joints.children("input")) {
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
            throw ctx.error(joints, "has no JOINT input");
        }
        if (inverseBindSource == null) {
            throw ctx.error(joints, "has no INV_BIND_MATRIX input");
        }
        String[] jointNames = jointSource.names(ctx, jointInput, "JOINT");
        float[] inverseBinds = inverseBindSource.floats(ctx, inverseBindInput, 16, "INV_BIND_MATRIX");
        if (inverseBindSource.count() != jointNames.length) {
            throw ctx.error(inverseBindInput, jointNames.length + " joints but " + inverseBindSource.count()
                    + " inverse bind matrices");
        }
        for (int j = 0; j < jointNames.length; j++) {
            RowMajor.toColumnMajor(ctx, inverseBinds, 16 * j, inverseBindInput, "inverse bind matrix of joint \"" + jointNames[j] + "\"");
        }

        XmlElement weights = ctx.child(skin, "vertex_weights");
        int count = ctx.count(weights, "count", -1);
        if (count != mesh.positionCount()) {
            throw ctx.error(weights, "count=\"" + count + "\" but geometry \"" + mesh.id() + "\" has "
                    + mesh.positionCount() + " positions");
        }
        int jointOffset = -1;
        int weightOffset = -1;
        int maxOffset = -1;
        Source weightSource = null;
        int[] jointRemap = null; // when <vertex_weights> names joints through another source
        Source weightJoints = jointSource; // the source <v>'s joint indices refer to
        for (XmlElement input : weights.children("input")) {
            String semantic = ctx.attr(input, "semantic");
            int offset = ctx.inputOffset(input);
            maxOffset = Math.max(maxOffset, offset);
            if (semantic.equals("JOINT")) {
                jointOffset = offset;
                weightJoints = ctx.inputSource(input);
                jointRemap = weightJoints == jointSource ? null
                        : remap(input, weightJoints.names(ctx, input, "JOINT"), jointNames);
            } else if (semantic.equals("WEIGHT")) {
                weightOffset = offset;
                weightSource = ctx.inputSource(input);
                weightSource.requireFloats(ctx, input, "WEIGHT");
                weightSource.requireComponent(ctx, input, "WEIGHT");
            }
        }
        if (jointOffset < 0 || weightSource == null) {
            throw ctx.error(weights, "needs a JOINT and a WEIGHT input");
        }
        int stride = maxOffset + 1;
        XmlElement vcountElement = weights.child("vcount");
        XmlElement vElement = weights.child("v");
        int[] vcount = vcountElement == null ? new int[0] : NumberParser.ints(ctx, vcountElement, -1);
        int[] v = vElement == null ? new int[0] : NumberParser.ints(ctx, vElement, -1);
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
        if (total * stride != v.length) {
            throw ctx.error(vElement == null ? weights : vElement, "<vcount> adds up to " + total + " influences, which with "
                    + stride + " index offsets need " + total * stride + " indices, <v> has " + v.length);
        }
        int n = (int) total;
        int[] start = new int[count + 1];
        int[] influenceJoints = new int[n];
        float[] influenceWeights = new float[n];
        int unweighted = 0;
        int badSums = 0;
        float worstSum = 1f;
        int negatives = 0;
        int negativePositions = 0;
        int emptied = 0;
        float mostNegative = 0f;
        int at = 0;
        for (int p = 0; p < count; p++) {
            start[p] = at;
            float sum = 0f;
            boolean negative = false;
            for (int k = 0; k < vcount[p]; k++, at++) {
                int base = at * stride;
                int joint = v[base + jointOffset];
                int weightIndex = v[base + weightOffset];
                // Indices count in the source <vertex_weights> names, which may be shorter than
                // <joints> when it is another source.
                int jointLimit = jointRemap == null ? jointNames.length : jointRemap.length;
                if (joint < -1 || joint >= jointLimit) {
                    throw ctx.error(vElement, "joint index " + joint + " (value " + (base + jointOffset)
                            + ") is out of range: " + (jointRemap == null ? "the skin has " + jointLimit + " joints"
                            : "JOINT source \"" + weightJoints.id() + "\" has " + jointLimit + " names"));
                }
                if (weightIndex < 0 || weightIndex >= weightSource.count()) {
                    throw ctx.error(vElement, "weight index " + weightIndex + " (value " + (base + weightOffset)
                            + ") is out of range: source \"" + weightSource.id() + "\" has "
                            + weightSource.count() + " weights");
                }
                influenceJoints[at] = joint < 0 || jointRemap == null ? joint : jointRemap[joint];
                float w = weightSource.floatAt(weightIndex, 0);
                if (w < 0f) {
                    // Dividing by a sum with negative terms can push a position anywhere (a lone
                    // negative weight divided by itself becomes 1); read as no influence instead.
                    negatives++;
                    negative = true;
                    mostNegative = Math.min(mostNegative, w);
                    w = 0f;
                }
                influenceWeights[at] = w;
                sum += w;
            }
            if (negative) {
                // Told in the negative-weight warning, not counted again as a sum that is not one.
                negativePositions++;
                emptied += sum == 0f ? 1 : 0;
            } else if (vcount[p] == 0) {
                unweighted++;
            } else if (Math.abs(sum - 1f) > WEIGHT_SUM_TOLERANCE) {
                badSums++;
                if (Math.abs(sum - 1f) > Math.abs(worstSum - 1f)) {
                    worstSum = sum;
                }
            }
        }
        start[count] = at;
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
        return new Skin(controller.id(), controller.attr("name"), mesh, bindShape, Arrays.asList(jointNames),
                jointSource.isIdrefs(), inverseBinds, start, influenceJoints, influenceWeights);
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
