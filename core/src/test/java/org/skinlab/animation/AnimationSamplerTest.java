package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.animation.MathAssertions.angleBetween;
import static org.skinlab.animation.MathAssertions.assertMatrixEquals;
import static org.skinlab.animation.MathAssertions.axisAngle;
import static org.skinlab.animation.MathAssertions.rows;

import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.collada.AnimationXml;
import org.skinlab.collada.Fixtures;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.AssetInfo;
import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;
import org.skinlab.model.UpAxis;

/**
 * {@link AnimationSampler}: what each interpolation writes between and at keys, whole-matrix keys
 * split into translation, rotation and scale, the ends of a track, clip time with loop and clamp,
 * and the order of channels.
 *
 * <p>Most tests build one node {@code N} with the stack translate, rotate, scale, matrix (element
 * indices {@link #TRANSLATE} .. {@link #MATRIX}) and hand-made tracks, so that the keys, tangents
 * and interpolations are exactly those written in the test; {@link #importedChannelsDriveTheirTargets}
 * goes through the importer for the COLLADA target syntax.
 */
class AnimationSamplerTest {
    /** Values blended in float from operands up to 30: 1e-5 absolute. */
    private static final float VALUE = 1e-5f;
    /** Recomposed matrices from float quaternions, entries up to 4. */
    private static final double MATRIX_EPS = 2e-6 * 4;

    private static final int TRANSLATE = 0;
    private static final int ROTATE = 1;
    private static final int SCALE = 2;
    private static final int MATRIX = 3;

    private static final float C45 = (float) Math.cos(Math.PI / 4);

    private static final Skeleton SKELETON = Skeleton.of(new Model("sampler-test",
            new AssetInfo(UpAxis.Y_UP, 1, "meter", null, true), List.of(), List.of(), List.of(), List.of(), List.of(),
            List.of(new Node(0, -1, new int[0], "N", "N", "N", true, false, List.of(
                    new TransformElement(TransformElement.Kind.TRANSLATE, "translate", new float[] {0, 5, 6}),
                    new TransformElement(TransformElement.Kind.ROTATE, "rotateZ", new float[] {0, 0, 1, 0}),
                    new TransformElement(TransformElement.Kind.SCALE, "scale", new float[] {1, 1, 1}),
                    new TransformElement(TransformElement.Kind.MATRIX, "transform", rowMajor(new Matrix4f()))))),
            List.of(), List.of(), List.of()));

    // ------------------------------------------------------------------------------ helpers

    private static KeyframeTrack track(float[] times, float[] values, int width, Interpolation how) {
        Interpolation[] i = new Interpolation[times.length];
        Arrays.fill(i, how);
        return new KeyframeTrack(times, values, width, i, null, null);
    }

    private static AnimationChannel channel(int element, int offset, KeyframeTrack track) {
        return new AnimationChannel(0, element, offset, track, "N/" + element + "(" + offset + ")");
    }

    private static AnimationSampler sampler(AnimationChannel... channels) {
        return new AnimationSampler(SKELETON, new AnimationClip(null, "test", 0, 10, List.of(channels)));
    }

    /** The pose's values of element {@code element} after sampling at {@code time}. */
    private static float[] sample(AnimationSampler sampler, float time, RotationInterpolation mode, int element) {
        Pose pose = SKELETON.newPose();
        sampler.sample(time, mode, pose);
        int o = SKELETON.valueOffset(0, element);
        return Arrays.copyOfRange(pose.values(), o, o + SKELETON.kind(0, element).size());
    }

    private static float sample1(AnimationSampler sampler, float time, int element, int offset) {
        return sample(sampler, time, RotationInterpolation.SLERP, element)[offset];
    }

    /** Row-major 16 values, as a {@code <matrix>} holds them. */
    private static float[] rowMajor(Matrix4f m) {
        float[] v = new float[16];
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                v[4 * r + c] = m.getRowColumn(r, c);
            }
        }
        return v;
    }

    /** The affine matrix of 16 row-major values, after checking that the bottom row is 0 0 0 1. */
    private static Matrix4f fromRowMajor(float[] v) {
        assertArrayEquals(new float[] {0, 0, 0, 1}, Arrays.copyOfRange(v, 12, 16), 0f, "bottom row");
        return rows(Arrays.copyOf(v, 12));
    }

    private static float[] concat(float[]... parts) {
        int n = 0;
        for (float[] p : parts) {
            n += p.length;
        }
        float[] out = new float[n];
        int o = 0;
        for (float[] p : parts) {
            System.arraycopy(p, 0, out, o, p.length);
            o += p.length;
        }
        return out;
    }

    // ------------------------------------------------------------------- scalar channels

    @Test
    void importedChannelsDriveTheirTargets() {
        String nodes = """
                      <node id="N" name="N" sid="N">
                        <translate sid="translate">0 5 6</translate>
                        <rotate sid="rotateZ">0 0 1 0</rotate>
                        <matrix sid="transform">1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1</matrix>
                      </node>
                """;
        String animations = AnimationXml.animation("tx", "N/translate.X", "1 3", "0 10", 1)
                + AnimationXml.animation("rz", "N/rotateZ.ANGLE", "0 1", "0 90", 1)
                + AnimationXml.animation("mx", "N/transform(3)(0)", "0 1", "0 4", 1);
        Model model = Fixtures.read("sampler.dae", AnimationXml.document(nodes, animations));
        Skeleton skeleton = Skeleton.of(model);
        AnimationSampler sampler = new AnimationSampler(skeleton, model.clips().get(0));
        Pose pose = skeleton.newPose();
        sampler.sample(2, RotationInterpolation.SLERP, pose);
        float[] v = pose.values();
        // translate.X half way from 0 to 10; Y and Z keep the file's 5 6. The angle is past its
        // last key (90); the matrix's translation x (row 0, column 3) past its last key (4).
        assertArrayEquals(new float[] {5, 5, 6}, Arrays.copyOfRange(v, 0, 3), VALUE);
        assertEquals(90, v[skeleton.valueOffset(0, 1) + 3], VALUE);
        assertEquals(4, v[skeleton.valueOffset(0, 2) + 3], VALUE);

        sampler.sample(0.25f, RotationInterpolation.SLERP, pose);
        skeleton.evaluate(pose);
        // X before its first key (time 1) holds 0; angle 22.5; matrix translation x 1, and only
        // that value of the matrix moves (a partial matrix channel is not decomposed).
        // World: T(0 5 6) Rz(22.5) T(1 0 0): translation (cos 22.5, 5 + sin 22.5, 6).
        double a = Math.toRadians(22.5);
        float c = (float) Math.cos(a);
        float s = (float) Math.sin(a);
        assertEquals(22.5f, v[skeleton.valueOffset(0, 1) + 3], VALUE);
        assertArrayEquals(new float[] {1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},
                Arrays.copyOfRange(v, skeleton.valueOffset(0, 2), skeleton.valueOffset(0, 2) + 16), VALUE);
        assertMatrixEquals(rows(c, -s, 0, c, s, c, 0, 5 + s, 0, 0, 1, 6), pose.world(0, new Matrix4f()), 1e-6);
    }

    @Test
    void linearBlendsAndHoldsBeforeTheFirstAndAfterTheLastKey() {
        // Keys (1, 10) and (3, 30): 10 + 10 (t - 1) between them.
        AnimationSampler s = sampler(channel(TRANSLATE, 1, track(new float[] {1, 3}, new float[] {10, 30}, 1,
                Interpolation.LINEAR)));
        assertEquals(10, sample1(s, -5, TRANSLATE, 1), VALUE);
        assertEquals(10, sample1(s, 1, TRANSLATE, 1), VALUE);
        assertEquals(15, sample1(s, 1.5f, TRANSLATE, 1), VALUE);
        assertEquals(27.5f, sample1(s, 2.75f, TRANSLATE, 1), VALUE);
        assertEquals(30, sample1(s, 3, TRANSLATE, 1), VALUE);
        assertEquals(30, sample1(s, 100, TRANSLATE, 1), VALUE);
        assertEquals(30, sample1(s, Float.POSITIVE_INFINITY, TRANSLATE, 1), VALUE);
        // The neighbours of the driven value keep their rest values.
        assertArrayEquals(new float[] {0, 15, 6}, sample(s, 1.5f, RotationInterpolation.SLERP, TRANSLATE), VALUE);
    }

    @Test
    void vectorChannelsBlendEveryComponent() {
        AnimationSampler s = sampler(channel(TRANSLATE, 0, track(new float[] {0, 2},
                new float[] {0, 10, -4, 2, 20, 4}, 3, Interpolation.LINEAR)));
        assertArrayEquals(new float[] {0.5f, 12.5f, -2}, sample(s, 0.5f, RotationInterpolation.SLERP, TRANSLATE),
                VALUE);
    }

    @Test
    void stepHoldsEachKeyUntilTheNext() {
        AnimationSampler s = sampler(channel(TRANSLATE, 0, track(new float[] {0, 1, 2}, new float[] {0, 10, 20}, 1,
                Interpolation.STEP)));
        assertEquals(0, sample1(s, 0.999f, TRANSLATE, 0));
        assertEquals(10, sample1(s, 1, TRANSLATE, 0));
        assertEquals(10, sample1(s, 1.999f, TRANSLATE, 0));
        assertEquals(20, sample1(s, 2, TRANSLATE, 0));
        assertEquals(20, sample1(s, 5, TRANSLATE, 0));
    }

    @Test
    void eachSegmentUsesTheInterpolationOfTheKeyThatStartsIt() {
        // Key 0 STEP, key 1 LINEAR: [0, 1) holds 0, [1, 2] blends 10 -> 20.
        KeyframeTrack t = new KeyframeTrack(new float[] {0, 1, 2}, new float[] {0, 10, 20}, 1,
                new Interpolation[] {Interpolation.STEP, Interpolation.LINEAR, Interpolation.STEP}, null, null);
        AnimationSampler s = sampler(channel(TRANSLATE, 0, t));
        assertEquals(0, sample1(s, 0.5f, TRANSLATE, 0));
        assertEquals(15, sample1(s, 1.5f, TRANSLATE, 0), VALUE);
    }

    @Test
    void equalKeyTimesJumpAndTheLaterKeyHoldsFromThen() {
        // Keys (0, 0), (1, 10), (1, 20), (2, 30): a jump at t = 1 from 10 to 20.
        AnimationSampler s = sampler(channel(TRANSLATE, 0, track(new float[] {0, 1, 1, 2},
                new float[] {0, 10, 20, 30}, 1, Interpolation.LINEAR)));
        assertEquals(5, sample1(s, 0.5f, TRANSLATE, 0), VALUE);
        assertEquals(20, sample1(s, 1, TRANSLATE, 0), VALUE);
        assertEquals(25, sample1(s, 1.5f, TRANSLATE, 0), VALUE);
    }

    // ---------------------------------------------------------------- BEZIER and HERMITE

    /** A one-segment curve from (t0, v0) to (t1, v1) with control points (c0t, c0v), (c1t, c1v). */
    private static AnimationSampler curve(Interpolation how, float t0, float v0, float c0t, float c0v, float c1t,
            float c1v, float t1, float v1) {
        // Key 0's out-tangent and key 1's in-tangent matter; the others are placed on the keys.
        float[] in = {t0, v0, c1t, c1v};
        float[] out = {c0t, c0v, t1, v1};
        KeyframeTrack t = new KeyframeTrack(new float[] {t0, t1}, new float[] {v0, v1}, 1,
                new Interpolation[] {how, how}, in, out);
        return sampler(channel(TRANSLATE, 0, t));
    }

    @Test
    void bezierWithControlPointsOnTheLineIsLinear() {
        // Keys (0, 0) and (3, 6): every point of the curve lies on v = 2 t, so the value at time t
        // is 2 t exactly when the cubic x(s) = t was solved right, whatever the control points'
        // spacing (at thirds, x(s) is linear; at 0.5 and 2.9 it is not).
        for (float[] cp : new float[][] {{1, 2, 2, 4}, {0.5f, 1, 2.9f, 5.8f}, {0, 0, 3, 6}}) {
            AnimationSampler s = curve(Interpolation.BEZIER, 0, 0, cp[0], cp[1], cp[2], cp[3], 3, 6);
            for (float t : new float[] {0.001f, 0.3f, 1.7f, 2.9f, 2.999f}) {
                assertEquals(2 * t, sample1(s, t, TRANSLATE, 0), 1e-5, "control points " + Arrays.toString(cp) + ", t " + t);
            }
        }
    }

    @Test
    void bezierEaseFollowsTheCubicSolvedForTheSampleTime() {
        // Keys (2, 10), (4, 30), control points (3, 10), (3, 30). On the unit square the curve is
        // x(s) = 3(1-s)^2 s/2 + 3(1-s) s^2/2 + s^3 = 1.5 s - 1.5 s^2 + s^3 (increasing: x' > 0),
        // y(s) = 3(1-s) s^2 + s^3 = 3 s^2 - 2 s^3. At s = 1/4: x = 19/64, y = 5/32, so at time
        // 2 + 2 * 19/64 = 2.59375 the value is 10 + 20 * 5/32 = 13.125 (a straight line: 15.9375).
        AnimationSampler s = curve(Interpolation.BEZIER, 2, 10, 3, 10, 3, 30, 4, 30);
        assertEquals(13.125f, sample1(s, 2.59375f, TRANSLATE, 0), 1e-5);
        // s = 1/2: x = 1/2, y = 1/2 by symmetry.
        assertEquals(20f, sample1(s, 3f, TRANSLATE, 0), 1e-5);
        // s = 3/4: x = 45/64, y = 27/32: time 3.40625, value 26.875.
        assertEquals(26.875f, sample1(s, 3.40625f, TRANSLATE, 0), 1e-5);
    }

    @Test
    void bezierWithFlatTimeHandlesIsSolvedRightAtTheSegmentEnds() {
        // Keys (0, 0), (1, 1), control points (0, 0.5), (1, 0.5): x(s) = 3 s^2 - 2 s^3 has zero
        // slope at both ends, where Newton's step is undefined; y(s) = 1.5 s - 1.5 s^2 + s^3.
        //   s = 0.001: x = 2.998e-6, y = 1.498501e-3
        //   s = 0.01:  x = 2.98e-4,  y = 0.014851
        //   s = 0.99:  x = 0.999702, y = 0.985149
        // dy/dx reaches 250 at s = 0.001: float rounding of the time and the solver's tolerance
        // give at most 3e-7 there, and 8e-7 at s = 0.99 (time rounded by 6e-8, dy/dx = 25).
        AnimationSampler s = curve(Interpolation.BEZIER, 0, 0, 0, 0.5f, 1, 0.5f, 1, 1);
        assertEquals(1.498501e-3, sample1(s, 2.998e-6f, TRANSLATE, 0), 1e-6);
        assertEquals(0.014851, sample1(s, 2.98e-4f, TRANSLATE, 0), 1e-6);
        assertEquals(0.985149, sample1(s, 0.999702f, TRANSLATE, 0), 2e-6);
    }

    @Test
    void hermiteKeysFollowTheStoredControlPointsLikeBezier() {
        // The class doc: BEZIER and HERMITE both follow the cubic through the keys and the 2-D
        // control points the track stores.
        AnimationSampler bezier = curve(Interpolation.BEZIER, 2, 10, 3, 10, 3, 30, 4, 30);
        AnimationSampler hermite = curve(Interpolation.HERMITE, 2, 10, 3, 10, 3, 30, 4, 30);
        for (float t = 2; t <= 4; t += 0.125f) {
            assertEquals(sample1(bezier, t, TRANSLATE, 0), sample1(hermite, t, TRANSLATE, 0), 0f, "t " + t);
        }
        assertEquals(13.125f, sample1(hermite, 2.59375f, TRANSLATE, 0), 1e-5);
    }

    @Test
    void bezierMatrixKeysAreBlendedValueByValue() {
        // Whole-matrix keys with BEZIER: each of the 16 values on its own curve. With control
        // points at thirds on the line, that is the element-wise average at the midpoint:
        // (I + Rz(90)) / 2, which is not a rotation (no TRS split for curved keys).
        float[] k0 = rowMajor(new Matrix4f());
        float[] k1 = rowMajor(rows(0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0));
        float[] in = new float[64];
        float[] out = new float[64];
        for (int c = 0; c < 16; c++) {
            out[2 * c] = 1 / 3f;
            out[2 * c + 1] = k0[c] + (k1[c] - k0[c]) / 3;
            in[2 * (16 + c)] = 2 / 3f;
            in[2 * (16 + c) + 1] = k0[c] + 2 * (k1[c] - k0[c]) / 3;
        }
        KeyframeTrack t = new KeyframeTrack(new float[] {0, 1}, concat(k0, k1), 16,
                new Interpolation[] {Interpolation.BEZIER, Interpolation.BEZIER}, in, out);
        float[] m = sample(sampler(channel(MATRIX, 0, t)), 0.5f, RotationInterpolation.SLERP, MATRIX);
        assertMatrixEquals(rows(0.5f, -0.5f, 0, 0, 0.5f, 0.5f, 0, 0, 0, 0, 1, 0), fromRowMajor(m), 1e-6);
    }

    // ------------------------------------------------------------------ whole matrices

    // K0 = T(1 0 0) S(2 1 1); K1 = T(3 4 0) Rz(90) S(4 3 1), i.e. e0 -> 4e1, e1 -> -3e0.
    private static final float[] K0 = rowMajor(rows(2, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0));
    private static final float[] K1 = rowMajor(rows(0, -3, 0, 3, 4, 0, 0, 4, 0, 0, 1, 0));

    private static AnimationSampler matrixSampler(float[]... keys) {
        float[] times = new float[keys.length];
        for (int k = 0; k < keys.length; k++) {
            times[k] = k;
        }
        return sampler(channel(MATRIX, 0, track(times, concat(keys), 16, Interpolation.LINEAR)));
    }

    private static Matrix4f sampleMatrix(AnimationSampler s, float time, RotationInterpolation mode) {
        return fromRowMajor(sample(s, time, mode, MATRIX));
    }

    @Test
    void matrixKeysAreSplitIntoTranslationRotationAndScale() {
        // Half way: T(2 2 0) Rz(45) S(3 2 1): columns 3 (c, c, 0), 2 (-c, c, 0), (0 0 1).
        AnimationSampler s = matrixSampler(K0, K1);
        Matrix4f expected = rows(3 * C45, -2 * C45, 0, 2, 3 * C45, 2 * C45, 0, 2, 0, 0, 1, 0);
        assertMatrixEquals(expected, sampleMatrix(s, 0.5f, RotationInterpolation.SLERP), MATRIX_EPS);
        assertMatrixEquals(expected, sampleMatrix(s, 0.5f, RotationInterpolation.NLERP), MATRIX_EPS);
        // LERP: the rotation block shrinks by |q|^2 = cos^2(90/4) = (1 + cos 45)/2.
        float k = (1 + C45) / 2;
        assertMatrixEquals(rows(3 * C45 * k, -2 * C45 * k, 0, 2, 3 * C45 * k, 2 * C45 * k, 0, 2, 0, 0, k, 0),
                sampleMatrix(s, 0.5f, RotationInterpolation.LERP), MATRIX_EPS);
    }

    @Test
    void matrixRotationFollowsTheChosenInterpolation() {
        // A quarter of the way: T(1.5 1 0), S(2.5 1.5 1); SLERP turns 22.5 degrees, NLERP
        // 2 atan(sin 45 / 4 / (3/4 + cos 45 / 4)) = 21.598 degrees (see AnimationHelperTest).
        AnimationSampler s = matrixSampler(K0, K1);
        double nlerp = Math.toDegrees(2 * Math.atan(0.25 * C45 / (0.75 + 0.25 * C45)));
        for (Object[] c : new Object[][] {{RotationInterpolation.SLERP, 22.5}, {RotationInterpolation.NLERP, nlerp}}) {
            Matrix4f expected = new Matrix4f().translation(1.5f, 1, 0)
                    .rotate(axisAngle((Double) c[1], 0, 0, 1)).scale(2.5f, 1.5f, 1);
            assertMatrixEquals(expected, sampleMatrix(s, 0.25f, (RotationInterpolation) c[0]), MATRIX_EPS);
        }
    }

    @Test
    void matrixKeysAreReproducedExactlyAtKeyTimesShearIncluded() {
        // A sheared first key (x += 0.5 y), a rotated and scaled one, and a last one: at each key
        // time the key's 16 values come back bit for bit, though shear has no place in T*R*S.
        float[] sheared = rowMajor(rows(1, 0.5f, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3));
        float[] general = rowMajor(new Matrix4f().translation(-1, 2, 0.5f).rotate(axisAngle(123, 1, -2, 3))
                .scale(0.3f, 2, 5));
        AnimationSampler s = matrixSampler(sheared, general, K1);
        assertArrayEquals(sheared, sample(s, 0, RotationInterpolation.SLERP, MATRIX), 0f);
        assertArrayEquals(general, sample(s, 1, RotationInterpolation.LERP, MATRIX), 0f);
        assertArrayEquals(K1, sample(s, 2, RotationInterpolation.NLERP, MATRIX), 0f);
        // Before the first key and after the last: held, also exactly.
        assertArrayEquals(sheared, sample(s, -1, RotationInterpolation.SLERP, MATRIX), 0f);
        assertArrayEquals(K1, sample(s, 7, RotationInterpolation.SLERP, MATRIX), 0f);
    }

    @Test
    void shearIsDroppedBetweenKeys() {
        // Between two equal sheared keys the sampler writes T*R*S of the decomposition: the
        // columns come out orthogonal (what the class doc says: shear is kept only on keys).
        float[] sheared = rowMajor(rows(1, 0.5f, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3));
        Matrix4f m = sampleMatrix(matrixSampler(sheared, sheared), 0.5f, RotationInterpolation.SLERP);
        Vector3f c0 = m.getColumn(0, new Vector3f());
        Vector3f c1 = m.getColumn(1, new Vector3f());
        assertEquals(0, c0.dot(c1), 1e-6);
        assertEquals(0, m.getTranslation(new Vector3f()).distance(1, 2, 3), 1e-6);
    }

    @Test
    void matrixRotationTakesTheShortWayRound() {
        // Keys Rz(0) and Rz(350) are 10 degrees apart: half way is Rz(-5), not Rz(175). LERP also
        // shrinks by cos^2(10/4).
        float c = (float) Math.cos(Math.toRadians(350));
        float sn = (float) Math.sin(Math.toRadians(350));
        AnimationSampler s = matrixSampler(rowMajor(new Matrix4f()), rowMajor(rows(c, -sn, 0, 0, sn, c, 0, 0, 0, 0, 1,
                0)));
        Matrix4f minus5 = new Matrix4f().rotation(axisAngle(-5, 0, 0, 1));
        assertMatrixEquals(minus5, sampleMatrix(s, 0.5f, RotationInterpolation.SLERP), 1e-6);
        assertMatrixEquals(minus5, sampleMatrix(s, 0.5f, RotationInterpolation.NLERP), 1e-6);
        float k = (float) Math.pow(Math.cos(Math.toRadians(2.5)), 2);
        assertMatrixEquals(new Matrix4f(minus5).scale(k), sampleMatrix(s, 0.5f, RotationInterpolation.LERP), 1e-6);
    }

    @Test
    void aKeyScaledToZeroOnOneAxisKeepsTheRotation() {
        // Rz(30) with scale 1, then Rz(30) flattened along Y (scale (1 0 1)): half way is
        // Rz(30) S(1 0.5 1). The rotation must not turn on the way (before the fix of
        // AnimationHelper's singular fallback, the second key read as Rz(30) Rx(90)).
        Quaternionf r = axisAngle(30, 0, 0, 1);
        AnimationSampler s = matrixSampler(rowMajor(new Matrix4f().rotation(r)),
                rowMajor(new Matrix4f().rotation(r).scale(1, 0, 1)));
        for (RotationInterpolation mode : RotationInterpolation.values()) {
            assertMatrixEquals(new Matrix4f().rotation(r).scale(1, 0.5f, 1), sampleMatrix(s, 0.5f, mode), 1e-6);
        }
    }

    @Test
    void slightlyNonOrthonormalMatrixKeysBlendWithoutShear() {
        // Keys Rz(0) and Rz(90), each entry off by up to 1e-3 (exporter float noise). Between them
        // the result is still T*R*S: orthogonal columns (to float precision, 1e-6, while an
        // element-wise blend would keep the noise, ~1e-3), the rotation within the noise of
        // Rz(45), and scales within the noise of 1.
        Random random = new Random(5);
        float[][] keys = {rowMajor(new Matrix4f()), rowMajor(rows(0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0))};
        for (float[] key : keys) {
            for (int r = 0; r < 3; r++) {
                for (int c = 0; c < 3; c++) {
                    key[4 * r + c] += (2 * random.nextFloat() - 1) * 1e-3f;
                }
            }
        }
        AnimationSampler s = matrixSampler(keys);
        for (RotationInterpolation mode : new RotationInterpolation[] {RotationInterpolation.SLERP,
            RotationInterpolation.NLERP}) {
            Matrix4f m = sampleMatrix(s, 0.5f, mode);
            Vector3f[] col = {m.getColumn(0, new Vector3f()), m.getColumn(1, new Vector3f()),
                m.getColumn(2, new Vector3f())};
            assertEquals(0, col[0].dot(col[1]), 1e-6, mode.toString());
            assertEquals(0, col[0].dot(col[2]), 1e-6, mode.toString());
            assertEquals(0, col[1].dot(col[2]), 1e-6, mode.toString());
            for (Vector3f v : col) {
                assertEquals(1, v.length(), 2e-3, mode.toString());
            }
            Quaternionf q = new Matrix4f(m).normalize3x3().getNormalizedRotation(new Quaternionf());
            assertTrue(angleBetween(axisAngle(45, 0, 0, 1), q) < 3e-3, mode + ": " + q);
        }
    }

    @Test
    void blendedMatrixKeysEqualAnimationHelpersInterpolationToTheBit() {
        // The sampler keeps per segment what slerp derives from the two keys alone and composes
        // on arrays; its matrix must still be AnimationHelper's interpolate and compose of the
        // decomposed keys, float for float, in every mode. Random keys: about half the pairs lie
        // in opposite hemispheres, and every fourth pair is 0.02 degrees apart (slerp's fallback).
        Random random = new Random(8);
        for (int pair = 0; pair < 200; pair++) {
            Quaternionf ra = randomRotation(random);
            Quaternionf rb = pair % 4 == 0 ? new Quaternionf(ra).rotateX((float) Math.toRadians(0.02))
                    : randomRotation(random);
            float[] ka = rowMajor(new Matrix4f().translation(3 * random.nextFloat(), -random.nextFloat(), 1).rotate(ra)
                    .scale(0.5f + random.nextFloat(), 1, 2 * random.nextFloat() + 0.1f));
            float[] kb = rowMajor(new Matrix4f().translation(random.nextFloat(), 2, -4 * random.nextFloat()).rotate(rb)
                    .scale(1, 0.5f + random.nextFloat(), 0.3f));
            Vector3f ta = new Vector3f();
            Quaternionf qa = new Quaternionf();
            Vector3f sa = new Vector3f();
            AnimationHelper.decompose(fromRowMajor(ka), ta, qa, sa);
            Vector3f tb = new Vector3f();
            Quaternionf qb = new Quaternionf();
            Vector3f sb = new Vector3f();
            AnimationHelper.decompose(fromRowMajor(kb), tb, qb, sb);
            AnimationSampler s = matrixSampler(ka, kb);
            for (RotationInterpolation mode : RotationInterpolation.values()) {
                for (float u : new float[] {0.25f, 0.5f, random.nextFloat()}) {
                    // Keys at times 0 and 1: the blend parameter is the time itself.
                    Quaternionf q = AnimationHelper.interpolate(mode, qa, qb, u, new Quaternionf());
                    Matrix4f expected = AnimationHelper.compose(lerp(ta, tb, u), q, lerp(sa, sb, u), new Matrix4f());
                    assertArrayEquals(rowMajor(expected), sample(s, u, mode, MATRIX), 0f,
                            "pair " + pair + ", " + mode + " at " + u);
                }
            }
        }
    }

    private static Quaternionf randomRotation(Random random) {
        return axisAngle(360 * random.nextDouble(), random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
    }

    /** The sampler's linear blend, a + u (b - a). */
    private static Vector3f lerp(Vector3f a, Vector3f b, float u) {
        return new Vector3f(a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), a.z + u * (b.z - a.z));
    }

    // --------------------------------------------------------------------- the sampler

    @Test
    void channelsKeyedAtDifferentTimesEachFindTheirOwnSegment() {
        // Channels keyed at equal times share one key search (even from different arrays);
        // between them, one keyed at other times must search its own keys. X: keys at 0, 1, 2;
        // scale X: keys at 0, 4; Y: keys at 0, 1, 2 again.
        KeyframeTrack x = track(new float[] {0, 1, 2}, new float[] {0, 10, 20}, 1, Interpolation.LINEAR);
        KeyframeTrack sx = track(new float[] {0, 4}, new float[] {0, 4}, 1, Interpolation.LINEAR);
        KeyframeTrack y = track(new float[] {0, 1, 2}, new float[] {0, 100, 200}, 1, Interpolation.LINEAR);
        AnimationSampler s = sampler(channel(TRANSLATE, 0, x), channel(SCALE, 0, sx), channel(TRANSLATE, 1, y));
        // 1.5: half way between the second and third keys of X and Y, 1.5/4 of the way for scale.
        assertArrayEquals(new float[] {15, 150, 6}, sample(s, 1.5f, RotationInterpolation.SLERP, TRANSLATE), 0f);
        assertEquals(1.5f, sample1(s, 1.5f, SCALE, 0));
        // 3: X and Y hold their last keys, scale still blends.
        assertArrayEquals(new float[] {20, 200, 6}, sample(s, 3, RotationInterpolation.SLERP, TRANSLATE), 0f);
        assertEquals(3f, sample1(s, 3, SCALE, 0));
        // Before every first key: the first keys.
        assertArrayEquals(new float[] {0, 0, 6}, sample(s, -1, RotationInterpolation.SLERP, TRANSLATE), 0f);
        assertEquals(0f, sample1(s, -1, SCALE, 0));
    }

    @Test
    void nanTimeIsRefused() {
        AnimationSampler s = matrixSampler(K0, K1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> s.sample(Float.NaN, RotationInterpolation.SLERP, SKELETON.newPose()));
        assertTrue(e.getMessage().contains("NaN"), e.getMessage());
    }

    @Test
    void theLaterOfTwoChannelsOnTheSameValueWins() {
        KeyframeTrack one = track(new float[] {0}, new float[] {1}, 1, Interpolation.LINEAR);
        KeyframeTrack two = track(new float[] {0}, new float[] {2}, 1, Interpolation.LINEAR);
        assertEquals(2, sample1(sampler(channel(TRANSLATE, 0, one), channel(TRANSLATE, 0, two)), 0.5f, TRANSLATE, 0));
        assertEquals(1, sample1(sampler(channel(TRANSLATE, 0, two), channel(TRANSLATE, 0, one)), 0.5f, TRANSLATE, 0));
        // A whole-vector channel, then one of its components: X from the later, Y Z from the first.
        KeyframeTrack xyz = track(new float[] {0}, new float[] {7, 8, 9}, 3, Interpolation.LINEAR);
        assertArrayEquals(new float[] {2, 8, 9}, sample(sampler(channel(TRANSLATE, 0, xyz), channel(TRANSLATE, 0, two)),
                0.5f, RotationInterpolation.SLERP, TRANSLATE));
        assertArrayEquals(new float[] {7, 8, 9}, sample(sampler(channel(TRANSLATE, 0, two), channel(TRANSLATE, 0, xyz)),
                0.5f, RotationInterpolation.SLERP, TRANSLATE));
    }

    @Test
    void aRestSamplerLeavesThePoseAlone() {
        Pose pose = SKELETON.newPose();
        float[] before = pose.values().clone();
        AnimationSampler.rest(SKELETON).sample(3, RotationInterpolation.SLERP, pose);
        assertArrayEquals(before, pose.values(), 0f);
    }

    // ---------------------------------------------------------------------- clip time

    private static AnimationSampler clip(float start, float end) {
        return new AnimationSampler(SKELETON, new AnimationClip(null, "c", start, end, List.of()));
    }

    @Test
    void loopWrapsElapsedTimeIntoTheClip() {
        // Clip [1, 3], duration 2: elapsed e plays clip time 1 + (e mod 2).
        AnimationSampler s = clip(1, 3);
        assertEquals(1f, s.clipTime(0, WrapMode.LOOP));
        assertEquals(1.5f, s.clipTime(0.5, WrapMode.LOOP), 1e-6);
        assertEquals(1f, s.clipTime(2, WrapMode.LOOP), 1e-6);
        assertEquals(2.5f, s.clipTime(5.5, WrapMode.LOOP), 1e-6);
        assertEquals(1.25f, s.clipTime(1e9 + 0.25, WrapMode.LOOP), 1e-6);
        // Negative elapsed time plays backwards from the end: -0.5 is 0.5 before the end.
        assertEquals(2.5f, s.clipTime(-0.5, WrapMode.LOOP), 1e-6);
        assertEquals(2.5f, s.clipTime(-4.5, WrapMode.LOOP), 1e-6);
    }

    @Test
    void wrappedElapsedTimeStaysBelowTheDurationWhenLooping() {
        // -1e-17 mod 2 is -1e-17; adding the duration 2 rounds to exactly 2.0 in double, which is
        // not in [0, 2): it must come back as 0, the same instant of the loop.
        AnimationSampler s = clip(1, 3);
        assertEquals(2.0, -1e-17 + 2.0, "the rounding this test is about");
        assertEquals(0.0, s.wrapElapsed(-1e-17, WrapMode.LOOP));
        assertEquals(0.5, s.wrapElapsed(4.5, WrapMode.LOOP), 1e-12);
        assertEquals(2.0, s.wrapElapsed(9, WrapMode.CLAMP));
        assertEquals(0.0, s.wrapElapsed(-9, WrapMode.CLAMP));
        assertEquals(0.0, clip(2, 2).wrapElapsed(7, WrapMode.LOOP), "zero-length clip");
    }

    @Test
    void clampHoldsTheEnds() {
        AnimationSampler s = clip(1, 3);
        assertEquals(1f, s.clipTime(-1, WrapMode.CLAMP));
        assertEquals(1.5f, s.clipTime(0.5, WrapMode.CLAMP), 1e-6);
        assertEquals(3f, s.clipTime(2, WrapMode.CLAMP));
        assertEquals(3f, s.clipTime(50, WrapMode.CLAMP));
        assertEquals(1f, s.clamp(0));
        assertEquals(3f, s.clamp(4));
        assertEquals(2f, s.clamp(2));
    }

    @Test
    void aClipOfZeroLengthStaysAtItsStart() {
        AnimationSampler s = clip(2, 2);
        for (double e : new double[] {-3, 0, 0.5, 1e6}) {
            assertEquals(2f, s.clipTime(e, WrapMode.LOOP));
            assertEquals(2f, s.clipTime(e, WrapMode.CLAMP));
        }
    }
}
