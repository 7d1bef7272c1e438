package org.skinlab.simulation;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Decides whether a {@link Frame} is one whole simulation step: every position and normal of every
 * geometry must equal what a separate {@link SkinnedModel} of the same model computes for the
 * clip time, method and interpolation the frame records.
 *
 * <p>Why this catches tearing: a torn frame holds some vertices of one step and some of another
 * (or data of one step under the description of another). Two steps differ in clip time, method
 * or interpolation, and each of those moves the vertices (the ribbon's root vertices alone move by
 * the clip time), so the mixed part disagrees with the recomputation of the recorded step. The
 * comparison is exact: the same kernels run on the same inputs (Java floating point is strict), so
 * any difference at all is another step's data. The only steps it cannot tell apart are equal
 * ones (paused, same switches), where mixing them changes nothing a viewer could see.
 *
 * <p>As a check that does not rest on the skinning code, {@link TwistRibbon}'s vertices at rest
 * x = 0 must sit at x = clip time (within float rounding of the key blend).
 */
final class FrameChecker {
    /** Float rounding of the linear translation blend t0 + u (t1 - t0) over times up to 4 s. */
    static final float AXIS_TOLERANCE = 1e-5f;

    private final SkinnedModel reference;
    private final float[][] positions;
    private final float[][] normals;
    private final boolean ribbon;
    private float cachedTime = Float.NaN;
    private SkinningMethod cachedMethod;
    private RotationInterpolation cachedInterpolation;

    FrameChecker(Model model, AnimationClip clip, boolean ribbon) {
        this.reference = new SkinnedModel(model, clip, NormalTransform.INVERSE_TRANSPOSE);
        int n = reference.geometries().size();
        positions = new float[n][];
        normals = new float[n][];
        for (int g = 0; g < n; g++) {
            SkinnedGeometry geometry = reference.geometries().get(g);
            positions[g] = new float[3 * geometry.pointCount()];
            normals[g] = new float[3 * geometry.pointCount()];
        }
        this.ribbon = ribbon;
    }

    static FrameChecker ribbon(Model model) {
        return new FrameChecker(model, model.clips().get(0), true);
    }

    /** Null when the frame is one whole step, else what is wrong with it. */
    String problem(Frame frame) {
        float time = frame.clipTime();
        SkinningMethod method = frame.method();
        RotationInterpolation interpolation = frame.interpolation();
        if (method == null || interpolation == null || Float.isNaN(time)) {
            return "frame " + frame.sequence() + " has no description";
        }
        if (Float.floatToIntBits(time) != Float.floatToIntBits(cachedTime) || method != cachedMethod
                || interpolation != cachedInterpolation) {
            reference.pose(time, interpolation);
            for (int g = 0; g < positions.length; g++) {
                reference.skin(g, method, positions[g], normals[g]);
            }
            cachedTime = time;
            cachedMethod = method;
            cachedInterpolation = interpolation;
        }
        for (int g = 0; g < positions.length; g++) {
            String p = compare(frame, g, "position", frame.positions(g), positions[g]);
            if (p == null) {
                p = compare(frame, g, "normal", frame.normals(g), normals[g]);
            }
            if (p != null) {
                return p;
            }
        }
        if (ribbon) {
            float[] pos = frame.positions(0);
            SkinnedGeometry geometry = reference.geometries().get(0);
            for (int p = 0; p < 2; p++) { // positions 0 and 1: rest x = 0, on Root's axis
                float x = pos[3 * geometry.pointOfPosition(p)];
                if (Math.abs(x - time) > AXIS_TOLERANCE) {
                    return "frame " + frame.sequence() + ": axis vertex " + p + " at x = " + x + ", clip time " + time;
                }
            }
        }
        return null;
    }

    private static String compare(Frame frame, int g, String what, float[] actual, float[] expected) {
        for (int i = 0; i < expected.length; i++) {
            if (Float.floatToIntBits(actual[i]) != Float.floatToIntBits(expected[i])) {
                return "frame " + frame.sequence() + " (" + frame + "): geometry " + g + " " + what + " component " + i
                        + " is " + actual[i] + ", the recorded step gives " + expected[i];
            }
        }
        return null;
    }
}
