package org.skinlab.simulation;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Decides whether a {@link Frame} is one whole simulation step: the joint palette of every
 * geometry (skinning matrices, dual quaternions, scale parts, the scale flag) and, when the frame
 * has a skinned mesh, every position and normal must equal what a separate {@link SkinnedModel}
 * of the same model computes for the clip time, method and interpolation the frame records. A
 * palette-only frame must refuse its positions and normals.
 *
 * <p>Why this catches tearing: a torn frame holds some data of one step and some of another (or
 * data of one step under the description of another). Two steps differ in clip time, method or
 * interpolation, and each of those moves the vertices and (time and interpolation) the palette:
 * the ribbon's root joint alone moves by the clip time. So the mixed part disagrees with the
 * recomputation of the recorded step. Since palette and mesh are each held to the recorded step,
 * they also belong to the same step as each other. The comparison is exact: the same kernels run
 * on the same inputs (Java floating point is strict), so any difference at all is another step's
 * data. The only steps it cannot tell apart are equal ones (paused, same switches), where mixing
 * them changes nothing a viewer could see. Palette and mesh are judged separately
 * ({@link #check}), so a test can show that each check on its own catches tearing.
 *
 * <p>As a check that does not rest on the skinning code, {@link TwistRibbon}'s vertices at rest
 * x = 0 must sit at x = clip time (within float rounding of the key blend), and so must its root
 * joint's translation, read from the skinning matrix and from the dual quaternion.
 */
final class FrameChecker {
    /** Float rounding of the linear translation blend t0 + u (t1 - t0) over times up to 4 s. */
    static final float AXIS_TOLERANCE = 1e-5f;

    /** What is wrong with a frame's palette and with its mesh; null where nothing is. */
    record Verdict(String palette, String mesh) {
        /** The first problem, or null for a whole step. */
        String problem() {
            return palette != null ? palette : mesh;
        }
    }

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
        return check(frame).problem();
    }

    /** Palette and mesh judged separately against the step the frame's description names. */
    Verdict check(Frame frame) {
        // The description is read once, first: the recomputation below then takes long enough
        // for a writer filling this very buffer (the negative control) to move on a step.
        float time = frame.clipTime();
        SkinningMethod method = frame.method();
        RotationInterpolation interpolation = frame.interpolation();
        boolean skinnedMesh = frame.hasSkinnedMesh();
        if (method == null || interpolation == null || Float.isNaN(time)) {
            String p = "frame " + frame.sequence() + " has no description";
            return new Verdict(p, p);
        }
        if (Float.floatToIntBits(time) != Float.floatToIntBits(cachedTime) || method != cachedMethod
                || interpolation != cachedInterpolation) {
            reference.pose(time, interpolation);
            for (int g = 0; g < positions.length; g++) {
                reference.palette(g).prepareAll();
                reference.skin(g, method, positions[g], normals[g]);
            }
            cachedTime = time;
            cachedMethod = method;
            cachedInterpolation = interpolation;
        }
        return new Verdict(paletteProblem(frame, time), skinnedMesh ? meshProblem(frame, time) : refusal(frame));
    }

    private String paletteProblem(Frame frame, float time) {
        for (int g = 0; g < positions.length; g++) {
            JointPalette expected = reference.palette(g);
            if (frame.palette(g).jointCount() != expected.jointCount()) {
                return "frame " + frame.sequence() + ": geometry " + g + " has " + frame.palette(g).jointCount()
                        + " palette joints, the model " + expected.jointCount();
            }
            String p = compare(frame, g, "skinning matrix", frame.palette(g).matrices(), expected.matrices());
            if (p == null) {
                p = compare(frame, g, "dual quaternion", frame.palette(g).dualQuaternions(), expected.dualQuaternions());
            }
            if (p == null) {
                p = compare(frame, g, "scale part", frame.palette(g).scales(), expected.scales());
            }
            if (p == null && frame.palette(g).hasScale() != expected.hasScale()) {
                p = "frame " + frame.sequence() + ": geometry " + g + " hasScale " + frame.palette(g).hasScale();
            }
            if (p == null && (frame.palette(g).mirrorsMatrices() != expected.mirrorsMatrices()
                    || frame.palette(g).mirrorsScales() != expected.mirrorsScales())) {
                p = "frame " + frame.sequence() + ": geometry " + g + " mirror flags " + frame.palette(g).mirrorsMatrices()
                        + ", " + frame.palette(g).mirrorsScales();
            }
            if (p != null) {
                return p;
            }
        }
        if (ribbon) {
            // Root is joint 0; its skinning matrix is its world matrix (identity bind): translate(t, 0, 0) R.
            float x = frame.palette(0).matrices()[3];
            if (Math.abs(x - time) > AXIS_TOLERANCE) {
                return "frame " + frame.sequence() + ": root matrix translation x = " + x + ", clip time " + time;
            }
            float[] q = frame.palette(0).dualQuaternions();
            // t = 2 (r.w d.xyz - d.w r.xyz + r.xyz x d.xyz), x component (Frame's class comment).
            float tx = 2 * (q[3] * q[4] - q[7] * q[0] + (q[1] * q[6] - q[2] * q[5]));
            if (Math.abs(tx - time) > AXIS_TOLERANCE) {
                return "frame " + frame.sequence() + ": root dual quaternion translation x = " + tx + ", clip time "
                        + time;
            }
        }
        return null;
    }

    private String meshProblem(Frame frame, float time) {
        try {
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
        } catch (IllegalStateException e) {
            return "frame " + frame.sequence() + " said it has a skinned mesh, then refused it: " + e.getMessage();
        }
        return null;
    }

    /** A palette-only frame must refuse its stale mesh. */
    private static String refusal(Frame frame) {
        for (int g = 0; g < frame.geometryCount(); g++) {
            try {
                frame.positions(g);
                return "palette-only frame " + frame.sequence() + " handed out positions of geometry " + g;
            } catch (IllegalStateException expected) {
                // what a palette-only frame must do
            }
            try {
                frame.normals(g);
                return "palette-only frame " + frame.sequence() + " handed out normals of geometry " + g;
            } catch (IllegalStateException expected) {
                // likewise
            }
        }
        return null;
    }

    private static String compare(Frame frame, int g, String what, float[] actual, float[] expected) {
        if (actual.length != expected.length) {
            return "frame " + frame.sequence() + ": geometry " + g + " has " + actual.length + " " + what
                    + " floats, expected " + expected.length;
        }
        for (int i = 0; i < expected.length; i++) {
            if (Float.floatToIntBits(actual[i]) != Float.floatToIntBits(expected[i])) {
                return "frame " + frame.sequence() + " (" + frame + "): geometry " + g + " " + what + " component " + i
                        + " is " + actual[i] + ", the recorded step gives " + expected[i];
            }
        }
        return null;
    }
}
