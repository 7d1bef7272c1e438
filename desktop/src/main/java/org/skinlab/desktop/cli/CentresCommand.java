package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.skinning.CentresOfRotation;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab centres FILE... [--sigma S] [--epsilon E|none] [--runs N] [--json OUT [--time T,...]]}:
 * CoR's precomputation ({@link CentresOfRotation}) timed per skinned mesh, and the centres
 * exported for other tools.
 *
 * <p>The table has a row per skinned mesh: positions, triangles, the triangles integrated over
 * after subdivision, and the time of the computation (all cores, the disk cache not used) on its
 * first run (what a user waits for on a first load, JIT compilation included) and the median of
 * the later runs.
 *
 * <p>{@code --json OUT} (one file) writes, per skinned mesh in scene order, everything needed to
 * recompute and check the centres and CoR skinning elsewhere, one entry per {@code <vertices>}
 * POSITION entry in source order (docs/skinning.md, "Centres for other tools"):
 * <pre>
 * {"file", "sigma", "epsilon" (null: no subdivision), "meshes":[{"geometry", "name",
 *   "positions":[x,y,z,...], "triangles":[i,j,k,...], "joints":J, "influences":[[j,w,...],...],
 *   "centres":[x,y,z,...], "poses":[{"time", "matrices":[12 per joint], "cor":[x,y,z,...]}]}]}
 * </pre>
 * Positions and centres are in the skin's bind space (the space the skinning matrices map from);
 * the matrices (row-major 3x4 {@code [R | t]}, one per joint) map it to the document's frame, in
 * which the CoR-skinned points lie, as {@code skinlab pose} writes them.
 */
@Command(name = "centres", aliases = "centers", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"CoR skinning's centres of rotation: the precomputation timed per skinned mesh, and exported "
                + "as JSON for other tools (--json)."})
public final class CentresCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE", description = "model files (.dae, .gltf, .glb)")
    List<Path> files = new ArrayList<>();

    @Option(names = "--sigma", paramLabel = "S", description = "width of the weight-similarity kernel (default: "
            + "${DEFAULT-VALUE}, the paper's)")
    double sigma = CentresOfRotation.Parameters.DEFAULT.sigma();

    @Option(names = "--epsilon", paramLabel = "E|none", description = "largest weight difference along an edge of "
            + "the integration mesh, at least " + CentresOfRotation.MIN_WEIGHT_EPSILON + "; none: the triangles as "
            + "they are (default: 0.1, the paper's)")
    String epsilon = "0.1";

    @Option(names = "--runs", paramLabel = "N", description = "computations per mesh: the first, and the median of "
            + "the others (default: ${DEFAULT-VALUE})")
    int runs = 5;

    @Option(names = "--json", paramLabel = "OUT", description = "write the meshes, weights and centres as JSON to "
            + "OUT ('-': stdout); one FILE only")
    String json;

    @Option(names = "--time", split = ",", paramLabel = "T", converter = PoseCommand.TimeConverter.class,
            description = "with --json: clip times whose skinning matrices and CoR-skinned points are written too")
    List<Float> times = new ArrayList<>();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        CentresOfRotation.Parameters parameters = parameters();
        if (runs < 1) {
            throw usage("--runs must be at least 1");
        }
        if (json != null && files.size() != 1) {
            throw usage("--json writes one file's centres: name one FILE");
        }
        if (json == null && !times.isEmpty()) {
            throw usage("--time goes with --json");
        }
        if (!times.isEmpty() && !parameters.equals(CentresOfRotation.Parameters.DEFAULT)) {
            throw usage("--time: the runtime skins with the paper's centres (sigma 0.1, epsilon 0.1); leave "
                    + "--sigma and --epsilon at their defaults");
        }
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter report = json != null && json.equals("-") ? spec.commandLine().getErr() : out;
        report.printf(Locale.ROOT, "sigma %s, epsilon %s, %d threads, %d runs per mesh (ms: the first; the median of"
                + " the others)%n%n", sigma, epsilon, Runtime.getRuntime().availableProcessors(), runs);
        report.println("| file | mesh | positions | triangles | integrated | first ms | median ms |");
        report.println("|---|---|---:|---:|---:|---:|---:|");
        report.flush();
        for (Path file : files) {
            Model model = ModelFiles.load(file).model;
            SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                    NormalTransform.INVERSE_TRANSPOSE, EnumSet.of(SkinningMethod.COR));
            List<float[]> centres = new ArrayList<>();
            for (SkinnedGeometry g : skinned.geometries()) {
                if (!g.isSkinned() || g.mesh() == null) {
                    centres.add(null);
                    continue;
                }
                double[] millis = new double[runs];
                float[] c = null;
                for (int r = 0; r < runs; r++) {
                    long start = System.nanoTime();
                    c = CentresOfRotation.compute(g, parameters, CentresOfRotation.Progress.NONE);
                    millis[r] = (System.nanoTime() - start) / 1e6;
                }
                centres.add(c);
                Mesh mesh = g.mesh();
                report.printf(Locale.ROOT, "| %s | %s | %d | %d | %d | %.1f | %s |%n", file.getFileName(), mesh.id(),
                        mesh.positionCount(), mesh.triangleCount(),
                        CentresOfRotation.integrationTriangles(g, parameters), millis[0],
                        runs > 1 ? String.format(Locale.ROOT, "%.1f", median(Arrays.copyOfRange(millis, 1, runs))) : "-");
                report.flush();
            }
            if (json != null) {
                export(file, skinned, centres, parameters, out);
            }
        }
        return ExitCodes.OK;
    }

    private CentresOfRotation.Parameters parameters() {
        double e;
        if (epsilon.equalsIgnoreCase("none")) {
            e = Double.POSITIVE_INFINITY;
        } else {
            try {
                e = Double.parseDouble(epsilon);
            } catch (NumberFormatException x) {
                throw usage("--epsilon: '" + epsilon + "' is neither a number nor 'none'");
            }
        }
        try {
            return new CentresOfRotation.Parameters(sigma, e);
        } catch (IllegalArgumentException x) {
            throw usage(x.getMessage());
        }
    }

    private void export(Path file, SkinnedModel skinned, List<float[]> centres, CentresOfRotation.Parameters parameters,
            PrintWriter out) throws IOException {
        if (json.equals("-")) {
            write(file, skinned, centres, parameters, out);
            out.println();
            out.flush();
            return;
        }
        Path target = Path.of(json);
        try (Writer w = Files.newBufferedWriter(target, StandardCharsets.UTF_8)) {
            write(file, skinned, centres, parameters, w);
            w.write('\n');
        } catch (IOException e) {
            throw new CommandFailure(ExitCodes.USAGE, "cannot write " + target + ": " + e.getMessage(), e);
        }
    }

    private void write(Path file, SkinnedModel skinned, List<float[]> centres, CentresOfRotation.Parameters parameters,
            Writer w) throws IOException {
        try (JsonGenerator g = new JsonFactory().createGenerator(w)) {
            g.disable(JsonGenerator.Feature.AUTO_CLOSE_TARGET);
            g.writeStartObject();
            g.writeStringField("file", file.toString());
            g.writeNumberField("sigma", parameters.sigma());
            g.writeFieldName("epsilon");
            if (Double.isInfinite(parameters.weightEpsilon())) {
                g.writeNull();
            } else {
                g.writeNumber(parameters.weightEpsilon());
            }
            g.writeArrayFieldStart("meshes");
            List<SkinnedGeometry> geometries = skinned.geometries();
            for (int i = 0; i < geometries.size(); i++) {
                if (centres.get(i) != null) {
                    writeMesh(g, skinned, i, centres.get(i));
                }
            }
            g.writeEndArray();
            g.writeEndObject();
        }
    }

    /** One mesh, every array in POSITION source order. */
    private void writeMesh(JsonGenerator g, SkinnedModel skinned, int index, float[] centres) throws IOException {
        SkinnedGeometry geometry = skinned.geometries().get(index);
        Mesh mesh = geometry.mesh();
        int positions = mesh.positionCount();
        g.writeStartObject();
        g.writeStringField("geometry", mesh.id());
        g.writeStringField("name", mesh.name());
        writeFloats(g, "positions", geometry.positionsInSourceOrder(geometry.positionArray(), new float[3 * positions]));
        g.writeArrayFieldStart("triangles");
        for (int v : mesh.triangles()) {
            g.writeNumber(mesh.vertexPosition(v));
        }
        g.writeEndArray();
        g.writeNumberField("joints", geometry.jointCount());
        g.writeArrayFieldStart("influences");
        int k = geometry.influencesPerPoint();
        for (int p = 0; p < positions; p++) {
            int point = geometry.pointOfPosition(p);
            g.writeStartArray();
            for (int a = 0; a < k; a++) {
                float weight = geometry.weightArray()[k * point + a];
                if (weight > 0) {
                    g.writeNumber(geometry.jointArray()[k * point + a]);
                    g.writeNumber(weight);
                }
            }
            g.writeEndArray();
        }
        g.writeEndArray();
        writeFloats(g, "centres", geometry.positionsInSourceOrder(centres, new float[3 * positions]));
        g.writeArrayFieldStart("poses");
        float[] points = new float[3 * geometry.pointCount()];
        float[] normals = new float[points.length];
        for (float requested : times) {
            float t = skinned.sampler().clamp(requested);
            skinned.pose(t, RotationInterpolation.SLERP);
            skinned.skin(index, SkinningMethod.COR, points, normals);
            g.writeStartObject();
            g.writeNumberField("time", t);
            writeFloats(g, "matrices", Arrays.copyOf(skinned.palette(index).matrices(), 12 * geometry.jointCount()));
            writeFloats(g, "cor", geometry.positionsInSourceOrder(points, new float[3 * positions]));
            g.writeEndObject();
        }
        g.writeEndArray();
        g.writeEndObject();
    }

    private static void writeFloats(JsonGenerator g, String name, float[] values) throws IOException {
        g.writeArrayFieldStart(name);
        for (float v : values) {
            // Jackson prints a float with Float.toString: the digits that read back to it.
            g.writeNumber(v);
        }
        g.writeEndArray();
    }

    private static double median(double[] values) {
        double[] v = values.clone();
        Arrays.sort(v);
        int n = v.length;
        return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
    }

    private CommandLine.ParameterException usage(String message) {
        return new CommandLine.ParameterException(spec.commandLine(), message);
    }
}
