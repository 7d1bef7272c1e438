package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;

import org.joml.Matrix4fc;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.ImportException;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.TestPaths;

/**
 * Frames in the bind pose ({@link AnimationConfig#setBindPose}): on every asset of ours, COLLADA and
 * glTF, each method skinned on the CPU puts every POSITION where the skin's bind shape matrix puts
 * the mesh's position (an independent reference: the model's own numbers, not the geometry the
 * kernels read), while the clip's first frame puts the walking character elsewhere: its clip does
 * not start in its A-pose bind pose.
 */
class BindPoseFrameTest {
    private static final String[] ASSETS = {"characters/humanoid-walk", "cylinders/cylinder-bend",
        "cylinders/cylinder-twist-high", "creatures/tentacle-wave", "stretch/limb-stretch", "twist/arm-twist"};
    /**
     * Of the bind-pose bounds' diagonal. The joints' bind frames are the inverted INV_BIND
     * matrices (float), times INV_BIND again: about 1e-7 of the size off identity; 1e-5 allows
     * for the methods that blend in other forms (dual quaternions, bones).
     */
    private static final double TOLERANCE = 1e-5;

    private static Model read(String file) {
        try {
            return ModelImporter.read(TestPaths.asset(file));
        } catch (IOException | ImportException e) {
            throw new AssertionError(file + ": " + e.getMessage(), e);
        }
    }

    /** The largest distance of a frame's positions from the bind shape, over the bounds' diagonal of the bind shape. */
    private static double fromBindShape(Frame frame, SkeletalAnimatedMesh mesh) {
        double worst = 0;
        for (int g = 0; g < mesh.geometries().size(); g++) {
            SkinnedGeometry geometry = mesh.geometries().get(g);
            if (!geometry.isSkinned()) {
                continue;
            }
            Mesh m = geometry.mesh();
            Matrix4fc bindShape = geometry.instance().skin().bindShapeMatrix();
            float[] expected = new float[3 * m.positionCount()];
            Vector3f v = new Vector3f();
            for (int p = 0; p < m.positionCount(); p++) {
                bindShape.transformPosition(v.set(m.position(p, 0), m.position(p, 1), m.position(p, 2)));
                expected[3 * p] = v.x;
                expected[3 * p + 1] = v.y;
                expected[3 * p + 2] = v.z;
            }
            double size = diagonal(expected);
            float[] posed = frame.positions(g);
            for (int p = 0; p < m.positionCount(); p++) {
                int point = geometry.pointOfPosition(p);
                double d = Math.sqrt(sq(posed[3 * point] - expected[3 * p])
                        + sq(posed[3 * point + 1] - expected[3 * p + 1]) + sq(posed[3 * point + 2] - expected[3 * p + 2]));
                worst = Math.max(worst, d / size);
            }
        }
        return worst;
    }

    private static double sq(double x) {
        return x * x;
    }

    private static double diagonal(float[] xyz) {
        double[] min = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] max = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = 0; i < xyz.length; i++) {
            min[i % 3] = Math.min(min[i % 3], xyz[i]);
            max[i % 3] = Math.max(max[i % 3], xyz[i]);
        }
        return Math.sqrt(sq(max[0] - min[0]) + sq(max[1] - min[1]) + sq(max[2] - min[2]));
    }

    @Test
    void everyMethodSkinsTheBindPoseToTheBindShape() {
        for (String asset : ASSETS) {
            for (String extension : new String[] {".dae", ".glb"}) {
                Model model = read(asset + extension);
                AnimationConfig config = new AnimationConfig();
                try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model, config)) {
                    assertTrue(mesh.geometries().stream().anyMatch(SkinnedGeometry::isSkinned), asset);
                    config.setBindPose(true);
                    for (SkinningMethod method : SkinningMethod.values()) {
                        config.setMethod(method);
                        // Halfway through the clip: the bind pose does not depend on the time.
                        mesh.seek(0.5 * mesh.clipDuration());
                        mesh.step(0.0);
                        try (Frame frame = mesh.acquire()) {
                            double off = fromBindShape(frame, mesh);
                            assertTrue(off < TOLERANCE, asset + extension + " " + method.key() + ": " + off
                                    + " of the size from the bind shape");
                        }
                    }
                }
            }
        }
    }

    @Test
    void theWalksFirstFrameIsNotItsBindPose() {
        Model model = read("characters/humanoid-walk.dae");
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model, config)) {
            mesh.step(0.0);
            double keyZero;
            try (Frame frame = mesh.acquire()) {
                keyZero = fromBindShape(frame, mesh);
            }
            config.setBindPose(true);
            mesh.step(0.0);
            try (Frame frame = mesh.acquire()) {
                assertTrue(fromBindShape(frame, mesh) < TOLERANCE);
            }
            // The arms hang from the A-pose and the legs step: several percent of the height.
            assertTrue(keyZero > 0.02, "key 0 lies " + keyZero + " of the size from the bind shape");
        }
    }
}
