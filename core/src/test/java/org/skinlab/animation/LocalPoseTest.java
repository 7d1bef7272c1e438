package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * Sampling into local translation, rotation and scale and evaluating from there gives the world
 * matrices that sampling into the transform values gives, on our assets (COLLADA matrices and
 * their glTF twins) and the glTF fixtures (TRS, STEP and CUBICSPLINE keys, matrices on nodes): the
 * blend path poses a clip played alone as the file does. Tolerance: 2e-5 of the model's size per
 * matrix entry (the T*R*S round trip in float; none of these files has shear).
 */
class LocalPoseTest {
    static Stream<Path> files() throws IOException {
        List<Path> files = new ArrayList<>();
        try (Stream<Path> s = Files.walk(TestPaths.root().resolve("assets"))) {
            s.filter(p -> p.toString().endsWith(".dae") || p.toString().endsWith(".glb")).sorted().forEach(files::add);
        }
        try (Stream<Path> s = Files.list(TestPaths.root().resolve("core/src/test/resources/gltf"))) {
            s.filter(p -> p.toString().endsWith(".gltf") || p.toString().endsWith(".glb")).sorted().forEach(files::add);
        }
        return files.stream();
    }

    @ParameterizedTest
    @MethodSource("files")
    void localTransformsEvaluateToTheFilesWorldMatrices(Path file) throws Exception {
        Model model = ModelImporter.read(file);
        Skeleton skeleton = Skeleton.of(model);
        Pose direct = skeleton.newPose();
        Pose viaLocal = skeleton.newPose();
        Pose scratch = skeleton.newPose();
        LocalPose local = skeleton.newLocalPose();
        // The rest pose first.
        skeleton.evaluate(local, viaLocal);
        double size = compare(model, direct, viaLocal, file + " at rest", 0);
        assertTrue(size > 0);
        for (AnimationClip clip : model.clips()) {
            AnimationSampler sampler = new AnimationSampler(skeleton, clip);
            // Nodes the clip does not animate stay as the pose holds them: at rest.
            local.setRest();
            skeleton.reset(scratch);
            for (int i = 0; i <= 16; i++) {
                float t = clip.start() + clip.duration() * i / 16f + (i % 2 == 1 ? 0.013f * clip.duration() : 0f);
                t = sampler.clamp(t);
                skeleton.reset(direct);
                sampler.sample(t, RotationInterpolation.SLERP, direct);
                skeleton.evaluate(direct);
                sampler.sampleLocal(t, RotationInterpolation.SLERP, scratch, local);
                skeleton.evaluate(local, viaLocal);
                compare(model, direct, viaLocal, file.getFileName() + " clip " + clip.name() + " at " + t, size);
            }
        }
    }

    /** Compares every world matrix; returns the model's size (largest translation seen, at least 1e-3). */
    private static double compare(Model model, Pose a, Pose b, String what, double size) {
        float[] wa = a.worldArray();
        float[] wb = b.worldArray();
        double s = size;
        if (s == 0) {
            for (int i = 0; i < wa.length / 16; i++) {
                s = Math.max(s, Math.abs(wa[16 * i + 12]) + Math.abs(wa[16 * i + 13]) + Math.abs(wa[16 * i + 14]));
            }
            s = Math.max(s, 1e-3);
        }
        for (int k = 0; k < wa.length; k++) {
            int e = k;
            double scale = k % 16 >= 12 ? s : 1;
            assertEquals(wa[k], wb[k], 2e-5 * scale, () -> what + ": node " + e / 16 + " entry " + e % 16);
        }
        return s;
    }
}
