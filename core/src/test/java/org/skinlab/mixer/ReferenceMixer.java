package org.skinlab.mixer;

import java.util.List;

/**
 * The mixer's rules written plainly from the formulas in double precision, on {@link MixerRig}'s
 * keys (not through the model, its sampler or any skinlab math): each clip sampled by lerp and
 * slerp between its keys, three.js' accumulation within a layer with the rest pose filling the
 * remainder, override layers by slerp, additive layers as {@code base * slerp(1, conj(ref) q, w)}.
 * Poses are double[node][10]: translation, rotation x y z w, scale.
 */
final class ReferenceMixer {
    record Entry(String clip, double weight, double elapsed) {
    }

    record RefLayer(boolean additive, double weight, double[] mask, double referenceTime, List<Entry> entries) {
    }

    private final MixerRig rig;

    ReferenceMixer(MixerRig rig) {
        this.rig = rig;
    }

    static double[][] rest() {
        double[] arm = MixerRig.axisAngle(0, 0, 1, MixerRig.ARM_REST_Z);
        double[] yaw = MixerRig.axisAngle(0, 1, 0, 30);
        return new double[][] {
            {0.5, 0, 0, yaw[0], yaw[1], yaw[2], yaw[3], 2, 2, 2},
            {0, 1, 0, 0, 0, 0, 1, 1, 1, 1},
            {0, 0.5, 0, 0, 0, 0, 1, 1, 1, 1},
            {0.3, 0.4, 0, arm[0], arm[1], arm[2], arm[3], 1, 1, 1},
            {0.1, -0.5, 0, 0, 0, 0, 1, 1, 1, 1}};
    }

    /** The clip's local transform of {@code node} at {@code elapsed} seconds, or null where it has no keys. */
    double[] sample(String clip, int node, double elapsed) {
        MixerRig.RigClip c = rig.clip(clip);
        double time = Math.max(0, Math.min(c.duration(), elapsed));
        for (MixerRig.Keyed k : c.keyed()) {
            if (k.node() != node) {
                continue;
            }
            double[] times = k.times();
            int s = 0;
            while (s + 1 < times.length - 1 && times[s + 1] <= time) {
                s++;
            }
            double u = Math.max(0, Math.min(1, (time - times[s]) / (times[s + 1] - times[s])));
            double[] a = k.values()[s];
            double[] b = k.values()[s + 1];
            if (k.rotateElement() >= 0) {
                double angle = a[0] + u * (b[0] - a[0]);
                double[] q = k.rotateElement() == 1
                        ? mul(MixerRig.axisAngle(0, 0, 1, angle), new double[] {0, 0, 0, 1})
                        : mul(MixerRig.axisAngle(0, 0, 1, MixerRig.ARM_REST_Z), MixerRig.axisAngle(1, 0, 0, angle));
                return new double[] {0.3, 0.4, 0, q[0], q[1], q[2], q[3], 1, 1, 1};
            }
            double[] q = slerp(new double[] {a[3], a[4], a[5], a[6]}, new double[] {b[3], b[4], b[5], b[6]}, u);
            return new double[] {a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2]),
                q[0], q[1], q[2], q[3], 1, 1, 1};
        }
        return null;
    }

    double[][] evaluate(List<RefLayer> layers) {
        double[][] rest = rest();
        double[][] pose = rest();
        for (RefLayer layer : layers) {
            for (int j = 0; j < MixerRig.NODES; j++) {
                double m = layer.weight() * (layer.mask() == null ? 1 : layer.mask()[j]);
                if (m == 0) {
                    continue;
                }
                if (layer.additive()) {
                    for (Entry e : layer.entries()) {
                        double[] v = sample(e.clip(), j, e.elapsed());
                        if (v == null || e.weight() == 0) {
                            continue;
                        }
                        double[] ref = sample(e.clip(), j, layer.referenceTime());
                        double w = e.weight() * m;
                        double[] delta = mul(conj(part(ref)), part(v));
                        double[] r = mul(part(pose[j]), slerp(new double[] {0, 0, 0, 1}, delta, w));
                        for (int c = 0; c < 3; c++) {
                            pose[j][c] += w * (v[c] - ref[c]);
                            pose[j][7 + c] += w * (v[7 + c] - ref[7 + c]);
                        }
                        System.arraycopy(r, 0, pose[j], 3, 4);
                    }
                    continue;
                }
                double[] acc = null;
                double cumulative = 0;
                for (Entry e : layer.entries()) {
                    double[] v = sample(e.clip(), j, e.elapsed());
                    if (v == null || e.weight() == 0) {
                        continue;
                    }
                    if (acc == null) {
                        acc = v;
                        cumulative = e.weight();
                    } else {
                        cumulative += e.weight();
                        acc = mix(acc, v, e.weight() / cumulative);
                    }
                }
                if (acc == null) {
                    continue;
                }
                if (cumulative < 1) {
                    acc = mix(acc, rest[j], 1 - cumulative);
                }
                pose[j] = mix(pose[j], acc, Math.min(1, m));
            }
        }
        return pose;
    }

    static double[] mix(double[] a, double[] b, double t) {
        double[] r = new double[10];
        for (int c = 0; c < 3; c++) {
            r[c] = a[c] + t * (b[c] - a[c]);
            r[7 + c] = a[7 + c] + t * (b[7 + c] - a[7 + c]);
        }
        System.arraycopy(slerp(part(a), part(b), t), 0, r, 3, 4);
        return r;
    }

    private static double[] part(double[] trs) {
        return new double[] {trs[3], trs[4], trs[5], trs[6]};
    }

    static double[] slerp(double[] a, double[] b, double t) {
        double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
        double sign = dot < 0 ? -1 : 1;
        double angle = Math.acos(Math.min(1, Math.abs(dot)));
        double wa;
        double wb;
        if (angle < 1e-9) {
            wa = 1 - t;
            wb = t;
        } else {
            wa = Math.sin((1 - t) * angle) / Math.sin(angle);
            wb = Math.sin(t * angle) / Math.sin(angle);
        }
        double[] r = new double[4];
        double len = 0;
        for (int c = 0; c < 4; c++) {
            r[c] = wa * a[c] + sign * wb * b[c];
            len += r[c] * r[c];
        }
        for (int c = 0; c < 4; c++) {
            r[c] /= Math.sqrt(len);
        }
        return r;
    }

    static double[] mul(double[] a, double[] b) {
        return new double[] {
            a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
            a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
            a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
            a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
    }

    static double[] conj(double[] q) {
        return new double[] {-q[0], -q[1], -q[2], q[3]};
    }
}
