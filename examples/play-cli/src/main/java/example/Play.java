package example;

import java.nio.file.Path;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Model;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * What an app that depends on {@code org.skinlab:skinlab-core} does, in a few lines: plays a
 * character on skinlab's simulation thread and reads a frame, then poses it itself (the per-frame
 * path without a thread) and skins one pose with LBS and with DQS to see how far apart the two
 * place its points.
 *
 * <p>Usage: {@code java --add-modules jdk.incubator.vector -jar play-cli.jar FILE} (.dae, .gltf or
 * .glb); without the module, core's scalar kernels skin instead of the SIMD ones.
 */
public final class Play {
    private Play() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 1) {
            System.err.println("usage: play-cli FILE (.dae, .gltf or .glb)");
            System.exit(2);
        }
        Model model = ModelImporter.read(Path.of(args[0]));

        // On the simulation thread: 60 steps a second; a leased frame is never torn.
        AnimationConfig config = new AnimationConfig();
        config.setMethod(SkinningMethod.DQS);
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model, config)) {
            mesh.start();
            Thread.sleep(500);
            try (Frame frame = mesh.acquire()) {
                float[] p = frame.positions(0);
                System.out.printf("played: clip time %.3f s, vertex 0 at (%.4f, %.4f, %.4f), %d joints%n",
                        frame.clipTime(), p[0], p[1], p[2], frame.palette(0).jointCount());
            }
        }

        // Without a thread: pose at a time of your choosing, then skin with any method.
        SkinnedModel skinned = SkinnedModel.of(model);
        float time = skinned.sampler().start() + 0.5f * (skinned.sampler().end() - skinned.sampler().start());
        skinned.pose(time, RotationInterpolation.SLERP);
        int points = skinned.geometries().get(0).pointCount();
        float[][] positions = new float[2][3 * points];
        float[] normals = new float[3 * points];
        skinned.skin(0, SkinningMethod.LBS, positions[0], normals);
        skinned.skin(0, SkinningMethod.DQS, positions[1], normals);
        double largest = 0;
        for (int i = 0; i < 3 * points; i += 3) {
            largest = Math.max(largest, Math.sqrt(Math.pow(positions[0][i] - positions[1][i], 2)
                    + Math.pow(positions[0][i + 1] - positions[1][i + 1], 2)
                    + Math.pow(positions[0][i + 2] - positions[1][i + 2], 2)));
        }
        System.out.printf("posed at %.3f s: %d points, LBS and DQS at most %.5f apart (model units)%n", time, points,
                largest);
    }
}
