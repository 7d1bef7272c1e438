package org.skinlab.collada;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.model.TransformElement;

/**
 * Reads a node's transform stack ({@code <matrix>}, {@code <translate>}, {@code <rotate>},
 * {@code <scale>}, {@code <lookat>}, {@code <skew>}) into {@link TransformElement}s, values as
 * written.
 *
 * <p>Lenient (with a warning): a rotation or skew about a zero axis, a {@code <lookat>} without a
 * view direction, a matrix whose bottom row is not (0 0 0 1). Refused: a transform with the wrong
 * number of values.
 *
 * <p>One exporter habit is repaired here: Blender 2.7x writes an object's node as one
 * {@code <matrix sid="transform">} but animates the object through {@code location.X},
 * {@code rotationZ.ANGLE} and {@code scale.Y} channels, which name no element of that node (an
 * armature object's root motion would be lost). When a Blender file animates such sids of a node
 * that has only a matrix, the matrix is read as the stack Blender writes for such objects
 * otherwise, {@code translate location, rotate rotationZ, rotationY, rotationX, scale scale}
 * (T Rz Ry Rx S, Blender's XYZ Euler), which reproduces it (checked to 1e-5) and which the
 * channels then drive. A matrix with shear keeps its form (its channels stay skipped).
 */
final class TransformReader {
    /** The sids Blender 2.7x gives an object's animated transforms. */
    private static final Set<String> BLENDER_OBJECT_SIDS = Set.of("location", "rotationX", "rotationY", "rotationZ",
            "scale");
    /** How far from orthonormal a matrix's rotation may be (float noise), beyond which it has shear. */
    private static final float SHEAR_TOLERANCE = 1e-4f;

    private final ImportContext ctx;
    /** Node ids whose Blender object sids some channel animates (empty unless written by Blender). */
    private final Map<String, Set<String>> blenderObjectChannels;

    TransformReader(ImportContext ctx, String authoringTool) {
        this.ctx = ctx;
        this.blenderObjectChannels = authoringTool != null && authoringTool.startsWith("Blender")
                ? blenderObjectChannels(ctx.root()) : Map.of();
    }

    /** The node's transform elements, in document order. */
    List<TransformElement> read(XmlElement node) throws ColladaException {
        List<TransformElement> transforms = new ArrayList<>(4);
        for (XmlElement c : node.children()) {
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
            transforms.add(new TransformElement(kind, c.attr("sid"), v));
        }
        Set<String> animated = node.id() == null ? null : blenderObjectChannels.get(node.id());
        if (animated != null && transforms.size() == 1 && transforms.get(0).kind() == TransformElement.Kind.MATRIX
                && !animated.contains(transforms.get(0).sid())) {
            List<TransformElement> stack = blenderObjectStack(transforms.get(0).values());
            if (stack != null) {
                ctx.warnOnce("blender-object-matrix", node, "Blender writes animated objects as one <matrix> but"
                        + " animates location, rotation and scale; read as that stack so the channels apply (node \""
                        + node.id() + "\" and maybe others)");
                return stack;
            }
        }
        return transforms;
    }

    private static boolean isZero(float[] v, int o) {
        return v[o] == 0f && v[o + 1] == 0f && v[o + 2] == 0f;
    }

    /** Node id to the Blender object sids the file's channels animate on it. */
    private static Map<String, Set<String>> blenderObjectChannels(XmlElement root) {
        Map<String, Set<String>> result = new HashMap<>();
        Deque<XmlElement> todo = new ArrayDeque<>();
        for (XmlElement library : root.children("library_animations")) {
            todo.push(library);
        }
        while (!todo.isEmpty()) {
            XmlElement e = todo.pop();
            for (XmlElement c : e.children()) {
                if (c.name().equals("animation")) {
                    todo.push(c);
                } else if (c.name().equals("channel") && c.attr("target") != null) {
                    String target = c.attr("target");
                    int slash = target.indexOf('/');
                    if (slash > 0) {
                        String sid = target.substring(slash + 1).split("[.(]", 2)[0];
                        if (BLENDER_OBJECT_SIDS.contains(sid)) {
                            result.computeIfAbsent(target.substring(0, slash), k -> new HashSet<>()).add(sid);
                        }
                    }
                }
            }
        }
        return result;
    }

    /**
     * The row-major matrix as Blender's object stack T Rz Ry Rx S (angles in degrees), or null
     * when it has shear (no such stack reproduces it).
     */
    static List<TransformElement> blenderObjectStack(float[] m) {
        Vector3f col0 = new Vector3f(m[0], m[4], m[8]);
        Vector3f col1 = new Vector3f(m[1], m[5], m[9]);
        Vector3f col2 = new Vector3f(m[2], m[6], m[10]);
        float sx = col0.length();
        float sy = col1.length();
        float sz = col2.length();
        if (sx == 0f || sy == 0f || sz == 0f) {
            return null;
        }
        Matrix3f linear = new Matrix3f(col0, col1, col2);
        if (linear.determinant() < 0) {
            sx = -sx; // a mirror: one negative scale, the rotation proper
        }
        Matrix3f r = new Matrix3f(col0.div(sx), col1.div(sy), col2.div(sz));
        Matrix3f check = new Matrix3f(r).transpose().mul(r);
        if (!check.equals(new Matrix3f(), SHEAR_TOLERANCE)) {
            return null;
        }
        Vector3f euler = r.getEulerAnglesZYX(new Vector3f()); // r = Rz(z) Ry(y) Rx(x)
        List<TransformElement> stack = new ArrayList<>(5);
        stack.add(new TransformElement(TransformElement.Kind.TRANSLATE, "location", new float[] {m[3], m[7], m[11]}));
        stack.add(new TransformElement(TransformElement.Kind.ROTATE, "rotationZ",
                new float[] {0, 0, 1, (float) Math.toDegrees(euler.z)}));
        stack.add(new TransformElement(TransformElement.Kind.ROTATE, "rotationY",
                new float[] {0, 1, 0, (float) Math.toDegrees(euler.y)}));
        stack.add(new TransformElement(TransformElement.Kind.ROTATE, "rotationX",
                new float[] {1, 0, 0, (float) Math.toDegrees(euler.x)}));
        stack.add(new TransformElement(TransformElement.Kind.SCALE, "scale", new float[] {sx, sy, sz}));
        return stack;
    }
}
