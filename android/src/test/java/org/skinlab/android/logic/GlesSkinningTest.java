package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengles.GLES30.*;

import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.internal.metrics.ArtifactMetrics;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PaletteTexels;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * The app's skinning vertex shader ({@link GlesShaders#skinnedVertex()}: its GLSL ES 3.00 header and
 * main around core's shared formulas) computes what core's CPU kernels compute, on a real OpenGL
 * ES 3.0 (Mesa's llvmpipe under Xvfb here), as the desktop's {@code skinlab check-gpu} does for its
 * GLSL 330 variant. For every asset in {@code assets/*}{@code /*.dae} and every method with shader
 * code ({@link SkinningGlsl#hasCode}; the app draws the others CPU-skinned):
 * <ul>
 * <li>the palette of simulation frames ({@link SkeletalAnimatedMesh}, palette only) at the clip's
 *     start and every quarter of it, and at its most bent time (the largest angle between two
 *     joints weighting one vertex, searched at 30 per second), packed by {@link PaletteTexture#pack}
 *     as the app uploads it, with the scale and mirror flags the app takes from the frame;</li>
 * <li>that last pose mirrored ({@code diag(-1, 1, 1)} times every skinning matrix, prepared by
 *     core's {@link JointPalette} as the simulation prepares a frame's): the assets never mirror,
 *     and this is what the LBS cofactor's sign and the scale phase's (uMatricesMirror,
 *     uScalesMirror) are for;</li>
 * <li>the vertices fed as ModelGl feeds them ({@link SkinnedVertexCapture}), read back with
 *     transform feedback, and compared with the scalar kernel ({@link Skinners#scalar}, exact
 *     normals) run on the same {@value GlesShaders#INFLUENCES}-influence view with the same
 *     palette and centres of rotation.</li>
 * </ul>
 * Skipped, saying why, only where no OpenGL ES 3.0 context can be had.
 */
class GlesSkinningTest {
    /**
     * Largest GPU-CPU position distance, relative to the bounding-box diagonal of the CPU's
     * posed vertices: the desktop's {@code check-gpu} default. Both sides compute in float32 the
     * same formulas in a different order (the GPU fuses multiply-adds, sums the blend in another
     * order), which moves positions by a few float roundings of the coordinates: measured at most
     * 3.1e-7 of the size over the assets (Mesa's llvmpipe). A wrong formula (a sign, a missed scale phase, a texel off)
     * moves them by percents.
     */
    private static final double POSITION_TOLERANCE = 1e-4;
    /**
     * Largest distance between the GPU's normal (renormalised) and the CPU's unit normal, about
     * the angle in radians: float32 roundings of the cofactor or of the rotation, measured at most
     * 4.1e-7 over the assets; the positions' bound (0.006 degrees) leaves a driver the same room. A
     * normal whose sign or formula is wrong is off by 0.1 to 2.
     */
    private static final double NORMAL_TOLERANCE = 1e-4;
    /** Samples per second of clip searched for the most bent pose. */
    private static final int SEARCH_RATE = 30;

    private static GlesContext context;
    private static int program;
    private static final List<Asset> ASSETS = new ArrayList<>();

    /** One asset: its simulation (palette-only frames) and the times looked at. */
    private record Asset(String name, SkeletalAnimatedMesh mesh, double[] times, double mostBent, double angle) {
    }

    @BeforeAll
    static void openContextAndLoadAssets() throws Exception {
        context = GlesContext.openOrSkip();
        program = GlesPrograms.link(GlesShaders.skinnedVertex(), GlesShaders.skinnedFragment(), SkinnedVertexCapture.VARYINGS);
        Path root = Path.of(System.getProperty("skinlab.root", ".."));
        List<Path> files = new ArrayList<>();
        try (DirectoryStream<Path> dirs = Files.newDirectoryStream(root.resolve("assets"), Files::isDirectory)) {
            for (Path dir : dirs) {
                try (DirectoryStream<Path> daes = Files.newDirectoryStream(dir, "*.dae")) {
                    daes.forEach(files::add);
                }
            }
        }
        files.sort(null);
        assertFalse(files.isEmpty(), "no assets under " + root.resolve("assets"));
        for (Path file : files) {
            Model model = ColladaImporter.read(file);
            AnimationConfig config = new AnimationConfig(AnimationConfig.Settings.DEFAULT.withCpuSkinning(false));
            config.stopAnimation();
            SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(model,
                    model.clips().isEmpty() ? null : model.clips().get(0), config);
            double d = mesh.clipDuration();
            double[] bent = mostBentTime(mesh);
            ASSETS.add(new Asset(root.relativize(file).toString(), mesh,
                    new double[] {0, d / 4, d / 2, 3 * d / 4, bent[0]}, bent[0], bent[1]));
        }
    }

    @AfterAll
    static void closeContext() {
        for (Asset a : ASSETS) {
            a.mesh().close();
        }
        ASSETS.clear();
        if (context != null) {
            glDeleteProgram(program);
            context.close();
            context = null;
        }
    }

    /** The methods the shader has code for. */
    static List<SkinningMethod> shaderMethods() {
        List<SkinningMethod> methods = new ArrayList<>();
        for (SkinningMethod m : SkinningMethod.values()) {
            if (SkinningGlsl.hasCode(m)) {
                methods.add(m);
            }
        }
        return methods;
    }

    @ParameterizedTest
    @MethodSource("shaderMethods")
    void theShaderSkinsAsTheCpuKernelOnEveryAsset(SkinningMethod method) {
        Errors all = new Errors();
        for (Asset asset : ASSETS) {
            Errors errors = new Errors();
            List<SkinnedGeometry> geometries = asset.mesh().geometries();
            for (int g = 0; g < geometries.size(); g++) {
                check(method, asset, g, geometries.get(g), errors);
            }
            System.out.printf(Locale.ROOT, "GlesSkinningTest %-4s %-36s positions %.2g of the size, normals %.2g"
                    + " (%d poses, %d of the frames' scaled; most bent at %.3f s: %.0f degrees between a vertex's"
                    + " joints)%n", method.key(), asset.name(), errors.position, errors.normal,
                    asset.times().length + 1, errors.scaledPoses, asset.mostBent(), asset.angle());
            all.add(errors);
        }
        System.out.printf(Locale.ROOT, "GlesSkinningTest %-4s all assets: positions %.2g of the size, normals %.2g%n",
                method.key(), all.position, all.normal);
        assertTrue(all.position <= POSITION_TOLERANCE, method + ": largest GPU-CPU position distance " + all.position
                + " of the model's size (tolerance " + POSITION_TOLERANCE + ")");
        assertTrue(all.normal <= NORMAL_TOLERANCE, method + ": largest GPU-CPU normal distance " + all.normal
                + " (tolerance " + NORMAL_TOLERANCE + ")");
    }

    /** One geometry of an asset at every pose of the asset, and mirrored at its most bent pose. */
    private static void check(SkinningMethod method, Asset asset, int g, SkinnedGeometry geometry, Errors errors) {
        InfluenceView view = InfluenceView.of(geometry, GlesShaders.INFLUENCES);
        // A view that drops no weight deforms exactly as the geometry (InfluenceView's contract),
        // so the kernel runs on the geometry itself, with the centres the app uploads (for every
        // asset). A capped view runs as a geometry of its own on both sides: built from arrays, it
        // has no mesh, and its centres of rotation are its points.
        // Its joints keep the geometry's hierarchy, so both sides have the same bones.
        int[] parents = new int[geometry.jointCount()];
        for (int j = 0; j < parents.length; j++) {
            parents[j] = geometry.jointParent(j);
        }
        SkinnedGeometry reference = view.cappedPointCount() == 0 ? geometry
                : SkinnedGeometry.fromArrays(geometry.positionArray(), geometry.normalArray(),
                        view.influencesPerPoint(), view.jointIndicesAsInts(), view.weights(),
                        geometry.bindMatrixArray(), parents);
        Skinner kernel = Skinners.scalar(method, reference, NormalTransform.INVERSE_TRANSPOSE);
        JointPalette palette = reference.newPalette();
        float[] cpuPositions = new float[3 * reference.pointCount()];
        float[] cpuNormals = new float[3 * reference.pointCount()];
        float[] packed = new float[PaletteTexture.floats(geometry.jointCount())];
        int code = SkinningGlsl.methodCode(method);
        try (SkinnedVertexCapture gpu = new SkinnedVertexCapture(reference, view)) {
            int n = gpu.vertexCount();
            float[] gpuPositions = new float[3 * n];
            float[] gpuNormals = new float[3 * n];
            for (double t : asset.times()) {
                SkeletalAnimatedMesh mesh = asset.mesh();
                mesh.seek(t);
                mesh.step(0.0);
                try (Frame frame = mesh.acquire()) {
                    PaletteTexture.pack(frame, g, packed);
                    gpu.capture(program, packed, code, frame.palette(g).hasScale(), frame.palette(g).mirrorsMatrices(),
                            frame.palette(g).mirrorsScales(), gpuPositions, gpuNormals);
                    // The kernel's palette is the frame's: the same matrices, prepared by the same code.
                    System.arraycopy(frame.palette(g).matrices(), 0, palette.writableMatrices(), 0, palette.matrices().length);
                    palette.prepareAll();
                    assertArrayEquals(frame.palette(g).dualQuaternions(), palette.dualQuaternions(), "dual quaternions");
                    assertArrayEquals(frame.palette(g).boneRows(), palette.boneRows(), "bone rows");
                    assertArrayEquals(frame.palette(g).scales(), palette.scales(), "scale parts");
                    assertEquals(frame.palette(g).hasScale(), palette.hasScale());
                    errors.scaledPoses += frame.palette(g).hasScale() ? 1 : 0;
                }
                kernel.skinAll(palette, cpuPositions, cpuNormals);
                errors.add(compare(gpuPositions, gpuNormals, cpuPositions, cpuNormals, n));
                if (t == asset.mostBent()) {
                    mirror(palette);
                    assertTrue(palette.mirrorsMatrices() && palette.mirrorsScales(), "the mirrored pose mirrors");
                    // Packed and flagged as a frame carrying this palette is (Frame.copyPalette).
                    palette.prepareAll();
                    PaletteTexels.pack(palette, true, packed);
                    gpu.capture(program, packed, code, palette.hasScale(), palette.mirrorsMatrices(),
                            palette.mirrorsScales(), gpuPositions, gpuNormals);
                    kernel.skinAll(palette, cpuPositions, cpuNormals);
                    errors.add(compare(gpuPositions, gpuNormals, cpuPositions, cpuNormals, n));
                }
            }
        }
    }

    /** Every skinning matrix M becomes F M, F = diag(-1, 1, 1); the palette prepared again. */
    private static void mirror(JointPalette palette) {
        float[] m = palette.writableMatrices();
        for (int j = 0; j < palette.jointCount(); j++) {
            for (int c = 0; c < 4; c++) {
                m[12 * j + c] = -m[12 * j + c];
            }
        }
        palette.prepareAll();
    }

    /** The largest position distance (relative to the CPU's bounding box) and normal distance. */
    private static Errors compare(float[] gpuPositions, float[] gpuNormals, float[] cpuPositions, float[] cpuNormals,
            int n) {
        Errors e = new Errors();
        double size = ArtifactMetrics.boundsDiagonal(cpuPositions, n);
        int normals = 0;
        for (int i = 0; i < 3 * n; i += 3) {
            double dx = (double) gpuPositions[i] - cpuPositions[i];
            double dy = (double) gpuPositions[i + 1] - cpuPositions[i + 1];
            double dz = (double) gpuPositions[i + 2] - cpuPositions[i + 2];
            e.position = Math.max(e.position, Math.sqrt(dx * dx + dy * dy + dz * dz) / size);
            double gx = gpuNormals[i];
            double gy = gpuNormals[i + 1];
            double gz = gpuNormals[i + 2];
            double length = Math.sqrt(gx * gx + gy * gy + gz * gz);
            double cpuLength = Math.sqrt((double) cpuNormals[i] * cpuNormals[i]
                    + (double) cpuNormals[i + 1] * cpuNormals[i + 1] + (double) cpuNormals[i + 2] * cpuNormals[i + 2]);
            if (cpuLength == 0) {
                // A vertex without a rest normal: the kernel writes zero, the shader a zero vector too.
                e.normal = Math.max(e.normal, length);
                continue;
            }
            normals++;
            double nx = gx / length - cpuNormals[i];
            double ny = gy / length - cpuNormals[i + 1];
            double nz = gz / length - cpuNormals[i + 2];
            double d = Math.sqrt(nx * nx + ny * ny + nz * nz);
            e.normal = Math.max(e.normal, Double.isNaN(d) ? Double.POSITIVE_INFINITY : d);
        }
        assertTrue(normals > 0 || n == 0, "no normal compared");
        return e;
    }

    /**
     * The clip time (and its angle) at which some point's influences disagree most: the largest
     * angle between the rotation of a point's dominant joint and that of another joint weighting
     * it, where LBS collapses and DQS and CoR must blend far-apart rotations.
     */
    private static double[] mostBentTime(SkeletalAnimatedMesh mesh) {
        double best = 0;
        double bestAngle = -1;
        int steps = (int) Math.ceil(mesh.clipDuration() * SEARCH_RATE);
        for (int s = 0; s <= steps; s++) {
            double t = Math.min(mesh.clipDuration(), (double) s / SEARCH_RATE);
            mesh.seek(t);
            mesh.step(0.0);
            try (Frame frame = mesh.acquire()) {
                for (int g = 0; g < frame.geometryCount(); g++) {
                    double angle = largestAngle(mesh.geometries().get(g), frame.palette(g).dualQuaternions());
                    if (angle > bestAngle) {
                        bestAngle = angle;
                        best = t;
                    }
                }
            }
        }
        return new double[] {best, Math.toDegrees(bestAngle)};
    }

    private static double largestAngle(SkinnedGeometry geometry, float[] dq) {
        int k = geometry.influencesPerPoint();
        int[] joints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        double largest = 0;
        for (int i = 0; i < geometry.pointCount(); i++) {
            int a = 8 * joints[k * i];
            for (int s = 1; s < k; s++) {
                if (weights[k * i + s] > 0) {
                    int b = 8 * joints[k * i + s];
                    double dot = (double) dq[a] * dq[b] + (double) dq[a + 1] * dq[b + 1]
                            + (double) dq[a + 2] * dq[b + 2] + (double) dq[a + 3] * dq[b + 3];
                    largest = Math.max(largest, 2 * Math.acos(Math.min(1.0, Math.abs(dot))));
                }
            }
        }
        return largest;
    }

    /** The largest errors seen. */
    private static final class Errors {
        double position;
        double normal;
        /** Poses of the assets' own frames that had a scale phase. */
        int scaledPoses;

        void add(Errors e) {
            position = Math.max(position, e.position);
            normal = Math.max(normal, e.normal);
            scaledPoses += e.scaledPoses;
        }
    }
}
