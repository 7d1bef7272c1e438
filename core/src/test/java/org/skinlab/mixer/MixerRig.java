package org.skinlab.mixer;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleFunction;

import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.AssetInfo;
import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;
import org.skinlab.model.TransformElement.Kind;
import org.skinlab.model.UpAxis;

/**
 * A small skeleton with every kind of transform stack the mixer must read (glTF TRS, one COLLADA
 * matrix, COLLADA translate/rotate elements) under a rotated, scaled armature node, and clips
 * keyed from known functions: walk and run with root motion forward, a turn along a quarter
 * circle, a wave on the arm alone, a lean on the spine alone. {@link #key} gives every key as
 * translation and rotation in double precision for the reference implementation.
 *
 * <pre>
 * 0 armature (not a joint): T(0.5, 0, 0) R(yaw 30 deg) S(2)
 * 1   hips: T R S (glTF)          root motion joint
 * 2     spine: one matrix
 * 3       arm: translate, rotate z, rotate x
 * 4     leg: T R S (glTF)
 * </pre>
 */
final class MixerRig {
    static final int ARMATURE = 0;
    static final int HIPS = 1;
    static final int SPINE = 2;
    static final int ARM = 3;
    static final int LEG = 4;
    static final int NODES = 5;
    static final double ARM_REST_Z = 10;

    /** One animated node of a clip: its key times and per key translation (3) + rotation (4), or an angle. */
    record Keyed(int node, int rotateElement, double[] times, double[][] values) {
    }

    record RigClip(String name, double duration, List<Keyed> keyed) {
    }

    final List<RigClip> clips = new ArrayList<>();
    final Model model;

    MixerRig() {
        clips.add(clip("walk", 1.0, 0.125, t -> new double[] {0, 1 + 0.05 * Math.sin(4 * Math.PI * t), 1.2 * t},
                t -> 5 * Math.sin(2 * Math.PI * t), t -> 30 * Math.sin(2 * Math.PI * t), t -> 5 * Math.sin(2 * Math.PI * t),
                t -> ARM_REST_Z + 20 * Math.sin(2 * Math.PI * t)));
        clips.add(clip("run", 0.6, 0.075, t -> new double[] {0, 1 + 0.08 * Math.sin(4 * Math.PI * t / 0.6), 3.5 * t},
                t -> 8 * Math.sin(2 * Math.PI * t / 0.6), t -> 50 * Math.sin(2 * Math.PI * t / 0.6),
                t -> 10 + 3 * Math.sin(2 * Math.PI * t / 0.6), t -> ARM_REST_Z + 40 * Math.sin(2 * Math.PI * t / 0.6)));
        // A quarter circle of radius 2 in 2 s, heading with the path.
        clips.add(clip("turn", 2.0, 0.1, t -> new double[] {2 * (1 - Math.cos(Math.PI / 4 * t)), 1,
                2 * Math.sin(Math.PI / 4 * t)}, t -> 45 * t, t -> 20 * Math.sin(Math.PI * t), null, null));
        List<Keyed> wave = new ArrayList<>();
        wave.add(angles(ARM, 2, 1.5, 0.125, t -> 60 * Math.sin(2 * Math.PI * t / 1.5)));
        clips.add(new RigClip("wave", 1.5, wave));
        List<Keyed> lean = new ArrayList<>();
        lean.add(matrix(SPINE, 1.0, 0.125, t -> 20 * Math.min(1, 2 * t)));
        clips.add(new RigClip("lean", 1.0, lean));
        model = build();
    }

    private static RigClip clip(String name, double duration, double step, DoubleFunction<double[]> hips,
            DoubleFunction<Double> hipsYaw, DoubleFunction<Double> legSwing, DoubleFunction<Double> spineRoll,
            DoubleFunction<Double> armZ) {
        List<Keyed> keyed = new ArrayList<>();
        int keys = (int) Math.round(duration / step) + 1;
        double[] times = new double[keys];
        double[][] h = new double[keys][];
        double[][] l = new double[keys][];
        for (int k = 0; k < keys; k++) {
            double t = k * step;
            times[k] = t;
            double[] p = hips.apply(t);
            double[] q = axisAngle(0, 1, 0, hipsYaw.apply(t));
            h[k] = new double[] {p[0], p[1], p[2], q[0], q[1], q[2], q[3]};
            double[] lq = axisAngle(1, 0, 0, legSwing.apply(t));
            l[k] = new double[] {0.1, -0.5, 0, lq[0], lq[1], lq[2], lq[3]};
        }
        keyed.add(new Keyed(HIPS, -1, times, h));
        keyed.add(new Keyed(LEG, -1, times, l));
        if (spineRoll != null) {
            keyed.add(matrix(SPINE, duration, step, spineRoll));
        }
        if (armZ != null) {
            keyed.add(angles(ARM, 1, duration, step, armZ));
        }
        return new RigClip(name, duration, keyed);
    }

    private static Keyed matrix(int node, double duration, double step, DoubleFunction<Double> roll) {
        int keys = (int) Math.round(duration / step) + 1;
        double[] times = new double[keys];
        double[][] v = new double[keys][];
        for (int k = 0; k < keys; k++) {
            times[k] = k * step;
            double[] q = axisAngle(0, 0, 1, roll.apply(times[k]));
            v[k] = new double[] {0, 0.5, 0, q[0], q[1], q[2], q[3]};
        }
        return new Keyed(node, -1, times, v);
    }

    private static Keyed angles(int node, int element, double duration, double step, DoubleFunction<Double> angle) {
        int keys = (int) Math.round(duration / step) + 1;
        double[] times = new double[keys];
        double[][] v = new double[keys][];
        for (int k = 0; k < keys; k++) {
            times[k] = k * step;
            v[k] = new double[] {angle.apply(times[k])};
        }
        return new Keyed(node, element, times, v);
    }

    static double[] axisAngle(double x, double y, double z, double degrees) {
        double h = Math.toRadians(degrees) / 2;
        double s = Math.sin(h);
        return new double[] {x * s, y * s, z * s, Math.cos(h)};
    }

    private Model build() {
        double[] arm = axisAngle(0, 1, 0, 30);
        List<Node> nodes = new ArrayList<>();
        nodes.add(new Node(0, -1, new int[] {1}, null, null, "armature", false, false, List.of(
                element(Kind.TRANSLATE, 0.5, 0, 0), element(Kind.QUATERNION, arm[0], arm[1], arm[2], arm[3]),
                element(Kind.SCALE, 2, 2, 2))));
        nodes.add(new Node(1, 0, new int[] {2, 4}, null, null, "hips", true, false, List.of(
                element(Kind.TRANSLATE, 0, 1, 0), element(Kind.QUATERNION, 0, 0, 0, 1), element(Kind.SCALE, 1, 1, 1))));
        nodes.add(new Node(2, 1, new int[] {3}, null, null, "spine", true, false, List.of(
                element(Kind.MATRIX, 1, 0, 0, 0, 0, 1, 0, 0.5, 0, 0, 1, 0, 0, 0, 0, 1))));
        nodes.add(new Node(3, 2, new int[0], null, null, "arm", true, false, List.of(
                element(Kind.TRANSLATE, 0.3, 0.4, 0), element(Kind.ROTATE, 0, 0, 1, ARM_REST_Z),
                element(Kind.ROTATE, 1, 0, 0, 0))));
        nodes.add(new Node(4, 1, new int[0], null, null, "leg", true, false, List.of(
                element(Kind.TRANSLATE, 0.1, -0.5, 0), element(Kind.QUATERNION, 0, 0, 0, 1),
                element(Kind.SCALE, 1, 1, 1))));
        List<AnimationClip> animationClips = new ArrayList<>();
        for (RigClip c : clips) {
            List<AnimationChannel> channels = new ArrayList<>();
            for (Keyed k : c.keyed()) {
                channels.addAll(channels(k));
            }
            animationClips.add(new AnimationClip(null, c.name(), 0f, (float) c.duration(), channels));
        }
        return new Model("mixer-rig", new AssetInfo(UpAxis.Y_UP, 1.0, "meter", null, true), List.of(), List.of(),
                List.of(), List.of(), List.of(), nodes, List.of(), animationClips, List.of());
    }

    private static List<AnimationChannel> channels(Keyed k) {
        int keys = k.times().length;
        float[] times = new float[keys];
        for (int i = 0; i < keys; i++) {
            times[i] = (float) k.times()[i];
        }
        Interpolation[] linear = new Interpolation[keys];
        java.util.Arrays.fill(linear, Interpolation.LINEAR);
        if (k.rotateElement() >= 0) {
            float[] a = new float[keys];
            for (int i = 0; i < keys; i++) {
                a[i] = (float) k.values()[i][0];
            }
            return List.of(new AnimationChannel(k.node(), k.rotateElement(), 3,
                    new KeyframeTrack(times, a, 1, linear, null, null), "angle"));
        }
        if (k.node() == SPINE) {
            float[] m = new float[16 * keys];
            for (int i = 0; i < keys; i++) {
                double[] v = k.values()[i];
                double[] r = rotationRows(v[3], v[4], v[5], v[6]);
                for (int row = 0; row < 3; row++) {
                    for (int col = 0; col < 3; col++) {
                        m[16 * i + 4 * row + col] = (float) r[3 * row + col];
                    }
                    m[16 * i + 4 * row + 3] = (float) v[row];
                }
                m[16 * i + 15] = 1f;
            }
            return List.of(new AnimationChannel(k.node(), 0, 0, new KeyframeTrack(times, m, 16, linear, null, null),
                    "matrix"));
        }
        float[] t = new float[3 * keys];
        float[] q = new float[4 * keys];
        for (int i = 0; i < keys; i++) {
            for (int c = 0; c < 3; c++) {
                t[3 * i + c] = (float) k.values()[i][c];
            }
            for (int c = 0; c < 4; c++) {
                q[4 * i + c] = (float) k.values()[i][3 + c];
            }
        }
        return List.of(new AnimationChannel(k.node(), 0, 0, new KeyframeTrack(times, t, 3, linear, null, null), "t"),
                new AnimationChannel(k.node(), 1, 0, new KeyframeTrack(times, q, 4, linear.clone(), null, null), "r"));
    }

    /** Row-major 3x3 rotation of a unit quaternion. */
    static double[] rotationRows(double x, double y, double z, double w) {
        return new double[] {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
            2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    }

    private static TransformElement element(Kind kind, double... v) {
        float[] f = new float[v.length];
        for (int i = 0; i < v.length; i++) {
            f[i] = (float) v[i];
        }
        return new TransformElement(kind, null, f);
    }

    RigClip clip(String name) {
        return clips.stream().filter(c -> c.name().equals(name)).findFirst().orElseThrow();
    }
}
