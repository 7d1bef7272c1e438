package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.Snippets.node;
import static org.skinlab.collada.Snippets.oneWarning;

import java.util.List;
import java.util.Random;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.Pose;
import org.skinlab.animation.AnimationSampler;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;

/**
 * Blender 2.7x's animated objects ({@code fixtures/quirks/blender279-object-matrix.dae}): a node
 * written as one matrix whose channels animate {@code location}, {@code rotation*} and
 * {@code scale} is read as Blender's object stack, which must reproduce the matrix and let the
 * channels move it.
 */
class BlenderObjectMatrixTest {
    private static final String NAME = "quirks/blender279-object-matrix.dae";

    @Test
    void theAnimatedObjectsMatrixBecomesTheStackItsChannelsDrive() {
        Model m = Fixtures.resource(NAME);
        Node armature = node(m, "Armature");
        assertEquals(List.of("location", "rotationZ", "rotationY", "rotationX", "scale"),
                armature.transforms().stream().map(TransformElement::sid).collect(java.util.stream.Collectors.toList()));
        float c = (float) Math.cos(Math.toRadians(30));
        float s = (float) Math.sin(Math.toRadians(30));
        Matrix4f written = new Matrix4f(2 * c, 2 * s, 0, 0, -2 * s, 2 * c, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1);
        assertTrue(armature.localMatrix().equals(written, 1e-5f), () -> "stack " + armature.localMatrix()
                + " vs matrix " + written);
        assertEquals(30f, armature.transforms().get(1).values()[3], 1e-4f, "rotationZ angle");
        assertEquals(1, m.clips().get(0).channels().size(), "location.X now has its element");

        Skeleton skeleton = Skeleton.of(m);
        AnimationSampler sampler = new AnimationSampler(skeleton, m.clips().get(0));
        Pose pose = skeleton.newPose();
        sampler.sample(1f, RotationInterpolation.SLERP, pose);
        skeleton.evaluate(pose);
        Matrix4f world = pose.world(armature.index(), new Matrix4f());
        assertEquals(3f, world.m30(), 1e-5f, "x at 1 s");
        assertEquals(2f, world.m31(), 1e-5f, "y unchanged");

        assertEquals(TransformElement.Kind.MATRIX, node(m, "Still").transforms().get(0).kind(), "no channel: kept");
        oneWarning(m, "Blender writes animated objects as one <matrix>");
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void onlyBlenderFilesGetTheRepair() {
        Model m = Fixtures.read("other.dae", Fixtures.text(NAME).replace("Blender 2.79.0", "Some Exporter"));
        assertEquals(TransformElement.Kind.MATRIX, node(m, "Armature").transforms().get(0).kind());
        oneWarning(m, "node \"Armature\" has no transform element with sid \"location\"");
    }

    @Test
    void theStackReproducesRandomMatricesWithoutShearAndRefusesShear() {
        Random random = new Random(279);
        for (int i = 0; i < 1000; i++) {
            Matrix4f expected = new Matrix4f().translate(random.nextFloat() * 10 - 5, random.nextFloat() * 10 - 5,
                    random.nextFloat() * 10 - 5)
                    .rotateXYZ(random.nextFloat() * 7 - 3.5f, random.nextFloat() * 3 - 1.5f, random.nextFloat() * 7 - 3.5f)
                    .scale(0.1f + random.nextFloat() * 3, (random.nextBoolean() ? 1 : -1) * (0.1f + random.nextFloat() * 3),
                            0.1f + random.nextFloat() * 3);
            float[] rowMajor = new float[16];
            expected.transpose(new Matrix4f()).get(rowMajor);
            List<TransformElement> stack = TransformReader.blenderObjectStack(rowMajor);
            Matrix4f actual = new Matrix4f();
            Matrix4f scratch = new Matrix4f();
            for (TransformElement t : stack) {
                t.multiply(actual, scratch);
            }
            int n = i;
            assertTrue(actual.equals(expected, 2e-4f), () -> "matrix " + n + ": " + expected + " vs " + actual);
        }
        float[] shear = {1, 0.5f, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        assertNull(TransformReader.blenderObjectStack(shear));
    }
}
