package org.skinlab.internal.metrics;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * Where each skinning method wins, at one joint of one part of a model in one pose: per method
 * the part's volume kept (a part closed by itself), how the joint ring keeps its distance from the
 * bones (the candy wrapper collapses it), how far the joint region stands out beyond its rest
 * distance from the bones (the bulge of DQS at bent joints), and how far the method places points
 * from every other method's relative to the model's size. The evaluation tabulates these
 * (docs/skinning.md).
 *
 * <p><b>The joint region.</b> A joint J with a parent P in the same palette; the bones are, in
 * bind space, the segment from P's origin to J's origin and the segment from J's origin on by the
 * same length in the same direction (J's own bone, whose tip a palette does not record). The
 * region is every point with weight on both P and J; the ring is the region's points nearest the
 * plane through J's origin perpendicular to P's bone. In a pose, P's segment moves with P's
 * skinning matrix and J's with J's.
 *
 * <p><b>Against the rest pose.</b> Every rest quantity (the ring, the region's distances from the
 * bones, the volume, the size) is taken from the model's {@link RestPose}: the points and the
 * bones moved by the rest pose's skinning matrices exactly as a pose moves them, so that both are
 * in the document's frame and units whatever the node scales, and every measure is neutral at the
 * rest pose. Bulges are in the document's units.
 */
public final class JointArtifacts {
    /**
     * One method's numbers.
     *
     * @param volume     the part's volume over its rest volume; NaN unless the part is closed by
     *                   itself ({@link RestPose#partNote} says why)
     * @param ringRadius the joint ring's distance from the posed bones over its rest distance; NaN
     *                   without a region (no point weighted on both joints)
     * @param bulge      how far the region stands out beyond its rest distance from the bones at
     *                   most, in the document's units; NaN without a region
     * @param distanceTo per other method, the largest distance between the two methods' points over
     *                   the model's size ({@link RestPose#size()})
     */
    public record Report(SkinningMethod method, double volume, double ringRadius, double bulge,
            Map<SkinningMethod, Double> distanceTo) {
    }

    /** The ring's points lie within this much of the model's size from the plane of its nearest point. */
    private static final double RING_TOLERANCE = 5e-5;

    private final RestPose rest;
    private final int part;
    private final SkinnedGeometry geometry;
    private final int joint;
    private final int parent;
    /** The bones' ends in bind space: P's origin, J's origin, J's tip. */
    private final Vector3f base = new Vector3f();
    private final Vector3f origin = new Vector3f();
    private final Vector3f tip = new Vector3f();
    private final int[] region;
    private final int[] ring;
    private final double[] restDistance;

    /**
     * @param rest   the model's rest pose
     * @param part   the part measured (a {@link RestPose#geometries()} index)
     * @param joint  palette index of J
     * @param parent palette index of P (J's parent bone)
     */
    public JointArtifacts(RestPose rest, int part, int joint, int parent) {
        this.rest = rest;
        this.part = part;
        this.geometry = rest.geometries().get(part);
        this.joint = joint;
        this.parent = parent;
        float[] bind = geometry.bindMatrixArray();
        new Matrix4f().set(bind, 16 * parent).invert().getTranslation(base);
        new Matrix4f().set(bind, 16 * joint).invert().getTranslation(origin);
        tip.set(origin).mul(2f).sub(base);
        int k = geometry.influencesPerPoint();
        List<Integer> found = new ArrayList<>();
        for (int i = 0; i < geometry.vertexCount(); i++) {
            boolean onJoint = false;
            boolean onParent = false;
            for (int a = 0; a < k; a++) {
                if (geometry.weightArray()[k * i + a] > 0) {
                    onJoint |= geometry.jointArray()[k * i + a] == joint;
                    onParent |= geometry.jointArray()[k * i + a] == parent;
                }
            }
            if (onJoint && onParent) {
                found.add(i);
            }
        }
        region = found.stream().mapToInt(Integer::intValue).toArray();
        float[] points = rest.positions(part);
        float[] matrices = rest.matrices(part);
        Vector3f b = transform(matrices, parent, base);
        Vector3f o = transform(matrices, joint, origin);
        Vector3f t = transform(matrices, joint, tip);
        restDistance = new double[region.length];
        for (int r = 0; r < region.length; r++) {
            restDistance[r] = distanceToBones(points, region[r], b, o, t);
        }
        ring = ringOf(points, b, o, RING_TOLERANCE * rest.size());
    }

    /** The region's points nearest the plane through the joint across the parent's bone, at rest. */
    private int[] ringOf(float[] points, Vector3f base, Vector3f origin, double tolerance) {
        Vector3f axis = new Vector3f(origin).sub(base).normalize();
        double nearest = Double.POSITIVE_INFINITY;
        double[] plane = new double[region.length];
        for (int r = 0; r < region.length; r++) {
            int i = region[r];
            plane[r] = Math.abs((points[3 * i] - origin.x) * axis.x + (points[3 * i + 1] - origin.y) * axis.y
                    + (points[3 * i + 2] - origin.z) * axis.z);
            nearest = Math.min(nearest, plane[r]);
        }
        List<Integer> found = new ArrayList<>();
        for (int r = 0; r < region.length; r++) {
            if (plane[r] <= nearest + tolerance) {
                found.add(r);
            }
        }
        return found.stream().mapToInt(Integer::intValue).toArray();
    }

    private static double distanceToBones(float[] p, int i, Vector3f a, Vector3f b, Vector3f c) {
        return Math.min(distanceToSegment(p, i, a, b), distanceToSegment(p, i, b, c));
    }

    private static double distanceToSegment(float[] p, int i, Vector3f a, Vector3f b) {
        double abx = b.x - a.x, aby = b.y - a.y, abz = b.z - a.z;
        double apx = p[3 * i] - a.x, apy = p[3 * i + 1] - a.y, apz = p[3 * i + 2] - a.z;
        double len2 = abx * abx + aby * aby + abz * abz;
        double t = len2 > 0 ? Math.max(0, Math.min(1, (apx * abx + apy * aby + apz * abz) / len2)) : 0;
        double dx = apx - t * abx, dy = apy - t * aby, dz = apz - t * abz;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Points of the joint region (weight on both the joint and its parent). */
    public int regionSize() {
        return region.length;
    }

    /**
     * The numbers of every method in {@code posed} (the geometry's points deformed by each method
     * in the same pose) with the pose's skinning matrices (12 floats per joint, row-major 3x4).
     */
    public List<Report> report(Map<SkinningMethod, float[]> posed, float[] skinningMatrices) {
        Vector3f b = transform(skinningMatrices, parent, base);
        Vector3f o = transform(skinningMatrices, joint, origin);
        Vector3f t = transform(skinningMatrices, joint, tip);
        double size = rest.size();
        List<Report> reports = new ArrayList<>();
        for (Map.Entry<SkinningMethod, float[]> e : posed.entrySet()) {
            float[] p = e.getValue();
            double bulge = Double.NEGATIVE_INFINITY;
            double ringPosed = 0;
            double ringRest = 0;
            for (int r = 0; r < region.length; r++) {
                double d = distanceToBones(p, region[r], b, o, t);
                bulge = Math.max(bulge, d - restDistance[r]);
            }
            for (int r : ring) {
                ringPosed += distanceToBones(p, region[r], b, o, t);
                ringRest += restDistance[r];
            }
            Map<SkinningMethod, Double> distances = new EnumMap<>(SkinningMethod.class);
            for (Map.Entry<SkinningMethod, float[]> other : posed.entrySet()) {
                if (other.getKey() == e.getKey()) {
                    continue;
                }
                double most = 0;
                float[] q = other.getValue();
                for (int i = 0; i < geometry.vertexCount(); i++) {
                    double dx = p[3 * i] - q[3 * i], dy = p[3 * i + 1] - q[3 * i + 1], dz = p[3 * i + 2] - q[3 * i + 2];
                    most = Math.max(most, Math.sqrt(dx * dx + dy * dy + dz * dz));
                }
                distances.put(other.getKey(), size > 0 ? most / size : most);
            }
            reports.add(new Report(e.getKey(), rest.relativeVolume(part, p),
                    ring.length == 0 || ringRest == 0 ? Double.NaN : ringPosed / ringRest,
                    region.length == 0 ? Double.NaN : bulge, distances));
        }
        return reports;
    }

    private static Vector3f transform(float[] m, int j, Vector3f p) {
        int o = 12 * j;
        return new Vector3f(m[o] * p.x + m[o + 1] * p.y + m[o + 2] * p.z + m[o + 3],
                m[o + 4] * p.x + m[o + 5] * p.y + m[o + 6] * p.z + m[o + 7],
                m[o + 8] * p.x + m[o + 9] * p.y + m[o + 10] * p.z + m[o + 11]);
    }
}
