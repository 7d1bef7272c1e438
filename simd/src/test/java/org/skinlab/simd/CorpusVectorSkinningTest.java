package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * Every character of the third-party corpus (and our assets) skinned by what {@link Skinners}
 * picks here (the Vector API kernels, each position once where the geometry shares positions)
 * against core's scalar kernels point by point, at five times of the first clip.
 *
 * <p>Tolerance: |fast - scalar| <= 2e-5 * max(1, |scalar|, model extent) on positions and 2e-5
 * on unit normals: the same float formulas in a different order (fused multiply-adds, the frame
 * route's matrix products), as argued in {@link VectorSkinnerTest}, scaled by the model's size
 * for positions. Skipped, saying so, when the corpus is absent.
 */
class CorpusVectorSkinningTest {
    /** The methods with Vector API kernels: all of them. */
    private static final SkinningMethod[] WITH_VECTOR_KERNELS = SkinningMethod.values();

    private static final float TOLERANCE = 2e-5f;

    static Stream<Path> characters() throws Exception {
        Path root = Path.of(System.getProperty("skinlab.root", "..")).toAbsolutePath().normalize();
        Path shared = Path.of(System.getProperty("skinlab.shared", root.resolve("../shared").toString()));
        List<Path> files = new ArrayList<>();
        try (Stream<Path> s = Files.list(root.resolve("assets/characters"))) {
            s.filter(p -> p.toString().endsWith(".dae")).sorted().forEach(files::add);
        }
        Path corpus = shared.resolve("corpus");
        if (Files.isDirectory(corpus)) {
            try (Stream<Path> s = Files.list(corpus)) {
                s.filter(p -> p.toString().endsWith(".dae")).sorted().forEach(files::add);
            }
        } else {
            System.out.println("CorpusVectorSkinningTest: " + corpus + " absent, only our assets are checked");
        }
        return files.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("characters")
    void fastKernelsEqualTheScalarOnes(Path file) throws Exception {
        Model model = ColladaImporter.read(file);
        assumeTrue(model.instances().stream().anyMatch(i -> i.isSkinned()), "a corpus file without a skin");
        assumeTrue(VectorSkinnerProvider.moduleAvailable(), "no incubator module");
        SkinnedModel skinned = SkinnedModel.of(model);
        float start = skinned.sampler().start();
        float end = skinned.sampler().end();
        for (SkinningMethod method : WITH_VECTOR_KERNELS) {
            for (NormalTransform rule : NormalTransform.values()) {
                if (rule == NormalTransform.NONE && !method.skinsPositionsOnly()) {
                    continue; // refused (VectorPositionsOnlyTest)
                }
                for (int g = 0; g < skinned.geometries().size(); g++) {
                    SkinnedGeometry geometry = skinned.geometries().get(g);
                    Skinner fast = Skinners.create(method, geometry.boundFor(method), rule);
                    assertTrue(fast.implementation().startsWith("vector-256"), fast.implementation());
                    Skinner reference = Skinners.scalar(method, geometry.boundFor(method), rule);
                    for (int t = 0; t < 5; t++) {
                        skinned.pose(start + (end - start) * t / 4f, RotationInterpolation.SLERP);
                        skinned.palette(g).prepare(method);
                        compare(file, method, rule, geometry, fast, reference, skinned, g);
                    }
                }
            }
        }
    }

    private static void compare(Path file, SkinningMethod method, NormalTransform rule, SkinnedGeometry geometry,
            Skinner fast, Skinner reference, SkinnedModel skinned, int g) {
        int n = 3 * geometry.pointCount();
        float[] fp = new float[n], fn = new float[n], rp = new float[n], rn = new float[n];
        fast.skinAll(skinned.palette(g), fp, fn);
        reference.skinAll(skinned.palette(g), rp, rn);
        float extent = 0f;
        for (float v : rp) {
            extent = Math.max(extent, Math.abs(v));
        }
        for (int i = 0; i < n; i++) {
            float tp = TOLERANCE * Math.max(1f, extent);
            if (!(Math.abs(fp[i] - rp[i]) <= tp) || !(Math.abs(fn[i] - rn[i]) <= TOLERANCE * Math.max(1f, Math.abs(rn[i])))) {
                fail(file.getFileName() + " " + method + " " + rule + " " + fast.implementation() + " point " + i / 3
                        + ": position " + fp[i] + " vs " + rp[i] + ", normal " + fn[i] + " vs " + rn[i]);
            }
        }
    }
}
