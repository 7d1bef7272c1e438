package org.skinlab.internal.metrics;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.skinlab.skinning.Bones;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * How a method spreads a bone's twist and stretch along the bone, ring by ring: for a tube-like
 * mesh around one joint's bone ({@link Bones}), its points grouped into rings by their rest
 * position along the bone, and per ring in a pose
 * <ul>
 * <li>its <b>twist</b>: the angle about the posed bone axis of the ring's marker (its first point)
 *     from where the parent's rigid motion alone would carry it (the parent's rotation, then the
 *     least turn from the parent-carried axis to the posed one); the joint's twist relative to its
 *     parent shows here as it is spread over the bone;</li>
 * <li>its <b>radius</b>: the mean distance of its points from the line through their centroid
 *     along the posed axis, over the same at rest (the candy wrapper collapses it, a bulge widens it);</li>
 * <li>its <b>position</b> along the posed axis from the posed head, in rest bone lengths (a
 *     stretch shows in how these advance from ring to ring).</li>
 * </ul>
 * The posed axis and head are the palette's bone rows 3 and 0, so the palette must have its bones
 * prepared ({@link JointPalette#prepare}). Rings are grouped to 0.1 mm along the bone.
 */
public final class BoneProfile {
    /** One ring: rest position along the bone (in bone lengths from the head) and its measures in a pose. */
    public record Ring(double along, double twist, double radius, double position) {
    }

    private final SkinnedGeometry geometry;
    private final int joint;
    private final int parent;
    private final double length;
    private final double[] head = new double[3];
    private final double[] axis = new double[3];
    /** Per ring its points, the first the marker. */
    private final List<int[]> rings = new ArrayList<>();
    private final List<Double> alongs = new ArrayList<>();
    private final List<Double> restRadii = new ArrayList<>();

    /**
     * The rings of joint {@code joint}'s bone whose rest position along it lies in
     * {@code [from, to]} bone lengths from the head, each of at least {@code minPoints} points.
     */
    public BoneProfile(SkinnedGeometry geometry, int joint, double from, double to, int minPoints) {
        this.geometry = geometry;
        this.joint = joint;
        Bones bones = geometry.bones();
        this.parent = bones.parent(joint);
        this.length = bones.length(joint);
        if (!(length > 0)) {
            throw new IllegalArgumentException("joint " + joint + " has a point-like bone: no axis to profile");
        }
        for (int a = 0; a < 3; a++) {
            head[a] = bones.head(joint, a);
            axis[a] = (bones.tail(joint, a) - head[a]) / length;
        }
        float[] p = geometry.positionArray();
        Map<Long, List<Integer>> byHeight = new TreeMap<>();
        for (int i = 0; i < geometry.pointCount(); i++) {
            double along = ((p[3 * i] - head[0]) * axis[0] + (p[3 * i + 1] - head[1]) * axis[1]
                    + (p[3 * i + 2] - head[2]) * axis[2]) / length;
            if (along >= from && along <= to) {
                byHeight.computeIfAbsent(Math.round(along * length * 1e4), k -> new ArrayList<>()).add(i);
            }
        }
        for (Map.Entry<Long, List<Integer>> e : byHeight.entrySet()) {
            if (e.getValue().size() >= minPoints) {
                int[] ring = e.getValue().stream().mapToInt(Integer::intValue).toArray();
                rings.add(ring);
                alongs.add(e.getKey() / (1e4 * length));
                restRadii.add(radius(p, ring, axis));
            }
        }
    }

    public int ringCount() {
        return rings.size();
    }

    /** Each ring's measures for points {@code posed} (3 floats per point) skinned with {@code palette}. */
    public List<Ring> measure(float[] posed, JointPalette palette) {
        float[] rows = palette.boneRows();
        int b = JointPalette.BONE_FLOATS * joint;
        double[] posedAxis = normalize(new double[] {rows[b + 12], rows[b + 13], rows[b + 14]});
        double[] posedHead = {rows[b], rows[b + 1], rows[b + 2]};
        double[] carriedAxis = parent < 0 ? axis.clone() : rotate(palette.dualQuaternions(), 8 * parent, axis);
        List<Ring> out = new ArrayList<>();
        float[] rest = geometry.positionArray();
        for (int r = 0; r < rings.size(); r++) {
            int[] ring = rings.get(r);
            int m = ring[0];
            double along = alongs.get(r);
            double[] restDirection = new double[3];
            for (int a = 0; a < 3; a++) {
                restDirection[a] = rest[3 * m + a] - head[a] - along * length * axis[a];
            }
            double[] reference = parent < 0 ? restDirection : rotate(palette.dualQuaternions(), 8 * parent, restDirection);
            reference = leastTurn(carriedAxis, posedAxis, reference);
            double[] centre = centroid(posed, ring);
            double[] marker = {posed[3 * m] - centre[0], posed[3 * m + 1] - centre[1], posed[3 * m + 2] - centre[2]};
            double[] d = perpendicular(marker, posedAxis);
            double[] ref = perpendicular(reference, posedAxis);
            double twist = Math.atan2(dot(cross(ref, d), posedAxis), dot(ref, d));
            double position = ((centre[0] - posedHead[0]) * posedAxis[0] + (centre[1] - posedHead[1]) * posedAxis[1]
                    + (centre[2] - posedHead[2]) * posedAxis[2]) / length;
            out.add(new Ring(along, twist, radius(posed, ring, posedAxis) / restRadii.get(r), position));
        }
        return out;
    }

    /** Mean distance of the ring's points from the line through their centroid along unit {@code a}. */
    private static double radius(float[] p, int[] ring, double[] a) {
        double[] c = centroid(p, ring);
        double sum = 0;
        for (int i : ring) {
            double[] v = {p[3 * i] - c[0], p[3 * i + 1] - c[1], p[3 * i + 2] - c[2]};
            double[] q = perpendicular(v, a);
            sum += Math.sqrt(dot(q, q));
        }
        return sum / ring.length;
    }

    private static double[] centroid(float[] p, int[] ring) {
        double[] c = new double[3];
        for (int i : ring) {
            for (int a = 0; a < 3; a++) {
                c[a] += p[3 * i + a] / ring.length;
            }
        }
        return c;
    }

    /** v turned by the unit quaternion (x y z w) at {@code dq[o]}. */
    private static double[] rotate(float[] dq, int o, double[] v) {
        double[] q = {dq[o], dq[o + 1], dq[o + 2]};
        double w = dq[o + 3];
        double[] c = cross(q, v);
        for (int a = 0; a < 3; a++) {
            c[a] += w * v[a];
        }
        double[] e = cross(q, c);
        return new double[] {v[0] + 2 * e[0], v[1] + 2 * e[1], v[2] + 2 * e[2]};
    }

    /** v turned by the least rotation taking unit {@code from} onto unit {@code to} (Rodrigues). */
    private static double[] leastTurn(double[] from, double[] to, double[] v) {
        double[] k = cross(from, to);
        double s = Math.sqrt(dot(k, k));
        double c = dot(from, to);
        if (s < 1e-12) {
            return v;
        }
        k = new double[] {k[0] / s, k[1] / s, k[2] / s};
        double[] kv = cross(k, v);
        double kd = dot(k, v);
        double[] out = new double[3];
        for (int a = 0; a < 3; a++) {
            out[a] = v[a] * c + kv[a] * s + k[a] * kd * (1 - c);
        }
        return out;
    }

    private static double[] perpendicular(double[] v, double[] a) {
        double d = dot(v, a);
        return new double[] {v[0] - d * a[0], v[1] - d * a[1], v[2] - d * a[2]};
    }

    private static double[] normalize(double[] v) {
        double n = Math.sqrt(dot(v, v));
        return new double[] {v[0] / n, v[1] / n, v[2] / n};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
}
