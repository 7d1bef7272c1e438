package org.skinlab.desktop.eval;

import java.util.Map;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.internal.metrics.JointArtifacts;
import org.skinlab.internal.metrics.RestPose;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * The joint the quality and pictures sections look at in an asset ({@link #choose}): its
 * geometry and palette indices, its region ({@link JointArtifacts}), its angle over the clip
 * ({@link JointAngle}) and its ring's turn ({@link RingTurn}).
 */
final class MeasuredJoint {

    final int geometry;
    final int joint;
    final int parent;
    final JointArtifacts artifacts;
    final JointAngle angle;
    final RingTurn ring;
    /** The placed model's size ({@link RestPose#size}), what the bulge is in percent of. */
    final double size;
    /** How near a half turn (degrees) the ring's turn is left out: the rotation's sign is undefined there. */
    static final double HALF_TURN_DEGREES = 0.5;
    /** A joint that turns less than this over a clip is passed over when another turns more. */
    static final double MOVING_DEGREES = 20;

    MeasuredJoint(SkinnedGeometry g, int geometry, int joint, int parent, JointArtifacts artifacts, double size) {
        this.geometry = geometry;
        this.joint = joint;
        this.parent = parent;
        this.artifacts = artifacts;
        angle = new JointAngle(parent, joint);
        ring = new RingTurn(g, joint, parent);
        this.size = size;
    }

    /**
     * The joint measured: among the joints whose parent is in the same skin and whose region
     * (points weighted on both) is not empty, in the geometry with the most points that has
     * one, the largest region among those that turn at least {@value #MOVING_DEGREES} degrees
     * from the bind pose over the clip's {@code times} (a joint that stays still shows no
     * method's artefacts), else the one that turns most; null when there is none.
     */
    static MeasuredJoint choose(SkinnedModel skinned, float[] times) {
        RestPose rest = RestPose.of(skinned);
        int g = -1;
        for (int k = 0; k < skinned.geometries().size(); k++) {
            if (hasRegion(rest, k)
                    && (g < 0 || skinned.geometries().get(k).pointCount() > skinned.geometries().get(g).pointCount())) {
                g = k;
            }
        }
        if (g < 0) {
            return null;
        }
        SkinnedGeometry geometry = skinned.geometries().get(g);
        double[] turned = new double[geometry.jointCount()];
        for (float t : times) {
            skinned.pose(t, RotationInterpolation.SLERP);
            float[] m = skinned.palette(g).matrices();
            for (int j = 0; j < turned.length; j++) {
                if (geometry.jointParent(j) >= 0) {
                    turned[j] = Math.max(turned[j], JointAngle.degrees(m, geometry.jointParent(j), j));
                }
            }
        }
        MeasuredJoint best = null;
        double bestTurn = -1;
        for (int j = 0; j < turned.length; j++) {
            int p = geometry.jointParent(j);
            if (p < 0) {
                continue;
            }
            JointArtifacts a = new JointArtifacts(rest, g, j, p);
            if (a.regionSize() == 0) {
                continue;
            }
            boolean moving = turned[j] >= MOVING_DEGREES;
            boolean bestMoving = bestTurn >= MOVING_DEGREES;
            if (best == null || (moving && !bestMoving)
                    || (moving == bestMoving && (moving ? a.regionSize() > best.artifacts.regionSize()
                            : turned[j] > bestTurn))) {
                best = new MeasuredJoint(geometry, g, j, p, a, rest.size());
                bestTurn = turned[j];
            }
        }
        return best;
    }

    private static boolean hasRegion(RestPose rest, int part) {
        SkinnedGeometry geometry = rest.geometries().get(part);
        for (int j = 0; j < geometry.jointCount(); j++) {
            int p = geometry.jointParent(j);
            if (p >= 0 && new JointArtifacts(rest, part, j, p).regionSize() > 0) {
                return true;
            }
        }
        return false;
    }

    /**
     * This pose's volume, ring radius, bulge (in percent of the model's size) and ring turn per
     * method; the joint is at {@code angleDegrees} (unwrapped).
     */
    void measure(PosedMethods posed, float[] matrices, double angleDegrees, Map<SkinningMethod, ObjectNode> byMethod) {
        double[] axis = angle.axis();
        // Within a hair of a half turn the rotation has no sign, and the ring's turn none either.
        double offHalfTurn = Math.abs(Math.IEEEremainder(angleDegrees - 180, 360));
        boolean turnDefined = axis != null && ring.measurable() && offHalfTurn > HALF_TURN_DEGREES;
        for (JointArtifacts.Report r : artifacts.report(posed.geometry(geometry), matrices)) {
            ObjectNode node = byMethod.get(r.method());
            add((ArrayNode) node.get("volume"), r.volume());
            add((ArrayNode) node.get("ringRadius"), r.ringRadius());
            add((ArrayNode) node.get("bulge"), size > 0 ? 100 * r.bulge() / size : r.bulge());
            add((ArrayNode) node.get("ringTurnDegrees"), axis == null || !ring.measurable() ? 0
                    : ring.degrees(posed.geometry(geometry).get(r.method()), matrices, axis));
        }
    }

    private static void add(ArrayNode array, double value) {
        if (Double.isNaN(value)) {
            array.addNull();
        } else {
            array.add(EvalReport.round(value));
        }
    }
}
