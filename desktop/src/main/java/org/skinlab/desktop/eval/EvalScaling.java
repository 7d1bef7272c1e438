package org.skinlab.desktop.eval;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.function.DoubleConsumer;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
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
 * exact normals as the apps use them, the fastest and the scalar kernels), and the pose's time
 * against the joints of real characters. Every point is {@link Rounds#MIN_RUNS} runs interleaved
 * across what is compared at it (methods and kernels; files). The fits are {@link EvalFits}':
 * only where their model describes the points, with residuals.
 */
final class EvalScaling {
    /**
     * The methods scaled: LBS, DQS and CoR. The synthetic data has no joint hierarchy (every joint
     * a bone of its own, SkinnedGeometry.fromArrays), so the bone methods would be timed on bones
     * no rig has; their cost per vertex is timed on the assets (eval's time section, bench frame).
     */
    static final List<SkinningMethod> METHODS = List.of(SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.COR);
    private static final String[] KERNELS = {"fastest", "scalar"};

    private static final NormalTransform NORMALS = NormalTransform.INVERSE_TRANSPOSE;

    private EvalScaling() {
    }

    /**
     * Time per frame (µs) against the vertex count, per method and kernel, each point in
     * interleaved runs, with the proportional fit ({@link EvalFits#proportional}): ns per vertex.
     */
    static void vertices(List<Integer> sizes, double warmup, double seconds, ObjectNode out, DoubleConsumer progress) {
        out.put("joints", SyntheticSkinData.JOINTS);
        out.put("influences", SyntheticSkinData.INFLUENCES);
        ArrayNode xs = out.putArray("vertices");
        sizes.forEach(xs::add);
        int series = KERNELS.length * METHODS.size();
        Spread[][] micros = new Spread[series][sizes.size()];
        String[] names = new String[series];
        for (int i = 0; i < sizes.size(); i++) {
            int v = sizes.get(i);
            SyntheticSkinData data = new SyntheticSkinData(v);
            Skinner[] kernels = new Skinner[series];
            for (int s = 0; s < series; s++) {
                kernels[s] = kernel(METHODS.get(s % METHODS.size()), data.geometry(), s >= METHODS.size());
                names[s] = kernels[s].implementation();
            }
            Spread[] nsPerVertex = Rounds.interleaved(series, Rounds.MIN_RUNS,
                    (s, round) -> time(kernels[s], data.palette(), v, round == 0 ? warmup : 0.02, seconds));
            for (int s = 0; s < series; s++) {
                micros[s][i] = scaled(nsPerVertex[s], v / 1000.0);
            }
            progress.accept((double) (i + 1) / sizes.size());
        }
        ArrayNode out2 = out.putArray("series");
        for (int s = 0; s < series; s++) {
            ObjectNode node = out2.addObject();
            node.put("method", METHODS.get(s % METHODS.size()).key());
            node.put("kernels", KERNELS[s / METHODS.size()]);
            node.put("kernel", names[s]);
            ArrayNode points = node.putArray("points");
            double[] x = new double[sizes.size()];
            double[] y = new double[sizes.size()];
            for (int i = 0; i < sizes.size(); i++) {
                EvalReport.putSpread(points.addObject().put("vertices", sizes.get(i)), "micros", micros[s][i]);
                x[i] = sizes.get(i);
                y[i] = micros[s][i].median();
            }
            EvalFits.proportional(x, y).put(node.putObject("fit"), 1000);
        }
    }

    /** ns per vertex against the influences per vertex, per method (fastest kernels), interleaved, with the line. */
    static void influences(int vertices, List<Integer> counts, double warmup, double seconds, ObjectNode out,
            DoubleConsumer progress) {
        out.put("vertices", vertices);
        ArrayNode xs = out.putArray("influences");
        counts.forEach(xs::add);
        Spread[][] ns = new Spread[METHODS.size()][counts.size()];
        String[] names = new String[METHODS.size()];
        for (int i = 0; i < counts.size(); i++) {
            SyntheticSkinData data = new SyntheticSkinData(vertices, SyntheticSkinData.SEED, counts.get(i));
            Skinner[] kernels = new Skinner[METHODS.size()];
            for (int m = 0; m < kernels.length; m++) {
                kernels[m] = kernel(METHODS.get(m), data.geometry(), false);
                names[m] = kernels[m].implementation();
            }
            Spread[] spreads = Rounds.interleaved(kernels.length, Rounds.MIN_RUNS,
                    (m, round) -> time(kernels[m], data.palette(), vertices, round == 0 ? warmup : 0.02, seconds));
            for (int m = 0; m < kernels.length; m++) {
                ns[m][i] = spreads[m];
            }
            progress.accept((double) (i + 1) / counts.size());
        }
        ArrayNode series = out.putArray("series");
        for (int m = 0; m < METHODS.size(); m++) {
            ObjectNode s = series.addObject();
            s.put("method", METHODS.get(m).key());
            s.put("kernel", names[m]);
            ArrayNode points = s.putArray("points");
            double[] x = new double[counts.size()];
            double[] y = new double[counts.size()];
            for (int i = 0; i < counts.size(); i++) {
                EvalReport.putSpread(points.addObject().put("influences", counts.get(i)), "nsPerVertex", ns[m][i]);
                x[i] = counts.get(i);
                y[i] = ns[m][i].median();
            }
            EvalFits.line(x, y).put(s.putObject("fit"), 1);
        }
    }

    /**
     * The pose's time per frame (sample, evaluate, skinning matrices, dual quaternions) of each
     * skinned file, in runs interleaved across the files, against its joints, with the line.
     */
    static void joints(List<Path> files, double warmup, double seconds, ObjectNode out, DoubleConsumer progress) {
        List<String> names = new ArrayList<>();
        List<SkinnedModel> models = new ArrayList<>();
        for (Path f : files) {
            Model model = ModelFiles.load(f).model;
            if (model.instances().stream().anyMatch(MeshInstance::isSkinned) && !model.clips().isEmpty()) {
                names.add(f.getFileName().toString());
                models.add(new SkinnedModel(model, model.clips().get(0), NORMALS, EnumSet.of(SkinningMethod.LBS)));
            }
        }
        int[] joints = new int[models.size()];
        int[] done = {0};
        Spread[] micros = Rounds.interleaved(models.size(), Rounds.MIN_RUNS, (i, round) -> {
            PaletteBench.Samples s = PaletteBench.measure(models.get(i), round == 0 ? warmup : 0.02, seconds);
            joints[i] = s.joints();
            progress.accept((double) ++done[0] / (models.size() * Rounds.MIN_RUNS));
            return s.medianTotal();
        });
        ArrayNode rows = out.putArray("files");
        double[] x = new double[models.size()];
        double[] y = new double[models.size()];
        for (int i = 0; i < models.size(); i++) {
            ObjectNode row = rows.addObject();
            row.put("file", names.get(i));
            row.put("joints", joints[i]);
            row.put("nodes", models.get(i).skeleton().nodeCount());
            EvalReport.putSpread(row, "micros", micros[i]);
            x[i] = joints[i];
            y[i] = micros[i].median();
        }
        if (models.size() >= 3) {
            EvalFits.line(x, y).put(out.putObject("fit"), 1);
        }
    }

    private static Skinner kernel(SkinningMethod m, SkinnedGeometry unbound, boolean scalar) {
        SkinnedGeometry geometry = unbound.boundFor(m);
        return scalar ? Skinners.scalar(m, geometry, NORMALS) : Skinners.create(m, geometry, NORMALS);
    }

    /** Median ns per vertex of skinning every vertex in one run, the reference's protocol. */
    private static double time(Skinner kernel, JointPalette palette, int vertices, double warmup, double seconds) {
        float[] positions = new float[3 * vertices];
        float[] normals = new float[3 * vertices];
        return SkinningTiming.measure(() -> kernel.skinAll(palette, positions, normals), positions, normals, vertices,
                warmup, seconds).median();
    }

    private static Spread scaled(Spread s, double factor) {
        double[] runs = s.runs();
        for (int i = 0; i < runs.length; i++) {
            runs[i] *= factor;
        }
        return Spread.of(runs);
    }
}
