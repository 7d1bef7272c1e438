package org.skinlab.desktop.eval;

import java.nio.file.Path;
import java.util.List;
import java.util.function.DoubleConsumer;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.PaletteBench;
import org.skinlab.desktop.bench.SkinningTiming;
import org.skinlab.desktop.bench.SyntheticSkinData;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * How the cost of a frame grows, for {@code skinlab eval}'s advice: skinning time against the
 * vertex count and against the influences per vertex (the reference's synthetic data, one thread,
 * exact normals as the apps use them, the fastest and the scalar kernels: the scalar ones are what
 * a phone runs, as Android's runtime has no Vector API), and the pose's time against the joints of
 * real characters. Each series gets a least-squares line; its slope is the cost per vertex,
 * influence or joint.
 */
final class EvalScaling {
    /**
     * The methods scaled: LBS, DQS and CoR. The synthetic data has no joint hierarchy (every joint
     * a bone of its own, SkinnedGeometry.fromArrays), so the bone methods would be timed on bones
     * no rig has; their cost per vertex is timed on the assets (eval's time section, bench frame).
     */
    static final List<SkinningMethod> METHODS = List.of(SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.COR);

    private static final NormalTransform NORMALS = NormalTransform.INVERSE_TRANSPOSE;

    private EvalScaling() {
    }

    /** A least-squares line y = intercept + slope x, with its coefficient of determination. */
    record Line(double intercept, double slope, double r2) {
        static Line fit(double[] x, double[] y) {
            int n = x.length;
            double mx = 0;
            double my = 0;
            for (int i = 0; i < n; i++) {
                mx += x[i] / n;
                my += y[i] / n;
            }
            double sxx = 0;
            double sxy = 0;
            double syy = 0;
            for (int i = 0; i < n; i++) {
                sxx += (x[i] - mx) * (x[i] - mx);
                sxy += (x[i] - mx) * (y[i] - my);
                syy += (y[i] - my) * (y[i] - my);
            }
            double slope = sxx == 0 ? 0 : sxy / sxx;
            double r2 = syy == 0 || sxx == 0 ? 1 : sxy * sxy / (sxx * syy);
            return new Line(my - slope * mx, slope, r2);
        }
    }

    /**
     * Time per frame (µs) against the vertex count, per method and kernel, with the fitted line:
     * slope in ns per vertex, intercept in µs.
     */
    static void vertices(List<Integer> sizes, double warmup, double seconds, ObjectNode out, DoubleConsumer progress) {
        out.put("joints", SyntheticSkinData.JOINTS);
        out.put("influences", SyntheticSkinData.INFLUENCES);
        ArrayNode xs = out.putArray("vertices");
        sizes.forEach(xs::add);
        ArrayNode series = out.putArray("series");
        int total = sizes.size() * 2 * METHODS.size();
        int done = 0;
        for (boolean scalar : new boolean[] {false, true}) {
            for (SkinningMethod m : METHODS) {
                ObjectNode s = series.addObject();
                s.put("method", m.key());
                s.put("kernels", scalar ? "scalar" : "fastest");
                ArrayNode micros = s.putArray("medianMicros");
                double[] x = new double[sizes.size()];
                double[] y = new double[sizes.size()];
                String kernel = null;
                for (int i = 0; i < sizes.size(); i++) {
                    int v = sizes.get(i);
                    SyntheticSkinData data = new SyntheticSkinData(v);
                    Skinner k = kernel(m, data.geometry(), scalar);
                    kernel = k.implementation();
                    x[i] = v;
                    y[i] = EvalReport.round(time(k, data.palette(), v, warmup, seconds) * v / 1000);
                    micros.add(y[i]);
                    progress.accept((double) ++done / total);
                }
                s.put("kernel", kernel);
                putLine(s, Line.fit(x, y), "nsPerVertex", 1000, "interceptMicros");
            }
        }
    }

    /** ns per vertex against the influences per vertex, per method (fastest kernels), with the line. */
    static void influences(int vertices, List<Integer> counts, double warmup, double seconds, ObjectNode out,
            DoubleConsumer progress) {
        out.put("vertices", vertices);
        ArrayNode xs = out.putArray("influences");
        counts.forEach(xs::add);
        ArrayNode series = out.putArray("series");
        int total = counts.size() * METHODS.size();
        int done = 0;
        for (SkinningMethod m : METHODS) {
            ObjectNode s = series.addObject();
            s.put("method", m.key());
            ArrayNode ns = s.putArray("nsPerVertex");
            double[] x = new double[counts.size()];
            double[] y = new double[counts.size()];
            for (int i = 0; i < counts.size(); i++) {
                SyntheticSkinData data = new SyntheticSkinData(vertices, SyntheticSkinData.SEED, counts.get(i));
                Skinner k = kernel(m, data.geometry(), false);
                x[i] = counts.get(i);
                y[i] = EvalReport.round(time(k, data.palette(), vertices, warmup, seconds));
                ns.add(y[i]);
                s.put("kernel", k.implementation());
                progress.accept((double) ++done / total);
            }
            putLine(s, Line.fit(x, y), "nsPerInfluence", 1, "interceptNs");
        }
    }

    /**
     * The pose's time per frame (sample, evaluate, skinning matrices, dual quaternions) against the
     * joints of each skinned file, with the line: slope in µs per joint.
     */
    static void joints(List<Path> files, double warmup, double seconds, ObjectNode out, DoubleConsumer progress) {
        ArrayNode rows = out.putArray("files");
        int n = 0;
        double[] x = new double[files.size()];
        double[] y = new double[files.size()];
        for (Path f : files) {
            Model model = ModelFiles.load(f).model;
            if (model.instances().stream().noneMatch(MeshInstance::isSkinned) || model.clips().isEmpty()) {
                continue;
            }
            SkinnedModel skinned = new SkinnedModel(model, model.clips().get(0), NORMALS);
            PaletteBench.Samples s = PaletteBench.measure(skinned, warmup, seconds);
            ObjectNode row = rows.addObject();
            row.put("file", f.getFileName().toString());
            row.put("joints", s.joints());
            row.put("nodes", skinned.skeleton().nodeCount());
            row.put("medianMicros", EvalReport.round(s.medianTotal()));
            x[n] = s.joints();
            y[n++] = s.medianTotal();
            progress.accept((double) n / files.size());
        }
        if (n >= 2) {
            putLine(out, Line.fit(java.util.Arrays.copyOf(x, n), java.util.Arrays.copyOf(y, n)), "microsPerJoint", 1,
                    "interceptMicros");
        }
    }

    private static Skinner kernel(SkinningMethod m, SkinnedGeometry geometry, boolean scalar) {
        return scalar ? Skinners.scalar(m, geometry, NORMALS) : Skinners.create(m, geometry, NORMALS);
    }

    /** Median ns per vertex of skinning every vertex, the reference's protocol. */
    private static double time(Skinner kernel, JointPalette palette, int vertices, double warmup, double seconds) {
        float[] positions = new float[3 * vertices];
        float[] normals = new float[3 * vertices];
        return SkinningTiming.measure(() -> kernel.skinAll(palette, positions, normals), positions, normals, vertices,
                warmup, seconds).median();
    }

    /** Stores the line: its slope times {@code scale} and its intercept under the names given. */
    private static void putLine(ObjectNode node, Line line, String slopeName, double scale, String interceptName) {
        node.put(slopeName, EvalReport.round(line.slope() * scale));
        node.put(interceptName, EvalReport.round(line.intercept()));
        node.put("r2", EvalReport.round(line.r2()));
    }
}
