package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.Snippets.assertNoWarnings;
import static org.skinlab.collada.Snippets.assertRows;
import static org.skinlab.collada.Snippets.collada;
import static org.skinlab.collada.Snippets.geometry;
import static org.skinlab.collada.Snippets.node;
import static org.skinlab.collada.Snippets.oneWarning;
import static org.skinlab.collada.Snippets.skin;

import java.util.List;
import java.util.stream.Collectors;

import org.joml.Matrix4fc;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;

/**
 * {@link SceneLoader} on hand-made scenes: transform stacks multiply in document order, the node
 * list is depth-first with {@code <instance_node>} copies in place, non-joint nodes stay where
 * they are, and the tolerated oddities come with a warning.
 */
class SceneImportTest {
    /** Right angles and small integers: float rounding of sin/cos only. */
    private static final float EPS = 1e-6f;

    private static Matrix4fc local(Model m, String id) {
        return node(m, id).localMatrix();
    }

    // --------------------------------------------------------------------------- transform stacks

    @Test
    void translateRotateScaleMultiplyInDocumentOrder() {
        Model m = Fixtures.resource("scene/transform-stacks.dae");
        // T(1 2 3) Rz(90) S(2): columns Rz*(2 0 0) = (0 2 0), Rz*(0 2 0) = (-2 0 0), (0 0 2); t = (1 2 3).
        assertRows(new float[][] {{0, -2, 0, 1}, {2, 0, 0, 2}, {0, 0, 2, 3}}, local(m, "trs"), EPS);
        // S(2) T(1 0 0): the translation happens in the scaled frame, so it moves by 2.
        assertRows(new float[][] {{2, 0, 0, 2}, {0, 2, 0, 0}, {0, 0, 2, 0}}, local(m, "scale-then-translate"), EPS);
        assertNoWarnings(m);
    }

    @Test
    void maxAndMayaStackTranslateRotateZYXScaleAtRightAngles() {
        Model m = Fixtures.resource("scene/transform-stacks.dae");
        // T(1 2 3) Rz(90) Ry(90) Rx(90) S(1 2 3), column by column (Rx: y->z, z->-y; Ry: z->x,
        // x->-z; Rz: x->y, y->-x):
        //   e0: Rx e0 = e0, Ry e0 = -e2, Rz(-e2) = -e2, times sx = 1 -> (0 0 -1)
        //   e1: Rx e1 = e2, Ry e2 = e0, Rz e0 = e1, times sy = 2  -> (0 2 0)
        //   e2: Rx e2 = -e1, Ry(-e1) = -e1, Rz(-e1) = e0, times sz = 3 -> (3 0 0)
        // The reverse order (Rx Ry Rz) would send e0 to +e2 instead.
        assertRows(new float[][] {{0, 0, 3, 1}, {0, 2, 0, 2}, {-1, 0, 0, 3}}, local(m, "max-right-angles"), EPS);
        List<TransformElement> stack = node(m, "max-right-angles").transforms();
        assertEquals(List.of("translate", "rotateZ", "rotateY", "rotateX", "scale"),
                stack.stream().map(TransformElement::sid).collect(Collectors.toList()));
        assertEquals(TransformElement.Kind.ROTATE, stack.get(2).kind());
        assertArrayEquals(new float[] {0, 1, 0, 90}, stack.get(2).values());
    }

    @Test
    void maxAndMayaStackAtOddAnglesEqualsTheTextbookProduct() {
        Model m = Fixtures.resource("scene/transform-stacks.dae");
        // Expected: the textbook matrices (Foley et al.), multiplied here in doubles, independent
        // of TransformElement and JOML.
        double[][] expected = product(translation(-4, 0.5, 7), rotationZ(30), rotationY(-45), rotationX(60),
                scaling(0.5, 2, 1.5));
        Matrix4fc actual = local(m, "max-odd-angles");
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                // Products of three sines/cosines in float: 1e-6 relative; tolerance 1e-5.
                assertEquals(expected[r][c], actual.get(c, r), 1e-5, "row " + r + " column " + c);
            }
        }
    }

    @Test
    void rotationAxisNeedNotBeNormalised() {
        Model m = Fixtures.resource("scene/transform-stacks.dae");
        float c = (float) Math.cos(Math.toRadians(30));
        float s = (float) Math.sin(Math.toRadians(30));
        assertRows(new float[][] {{c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}}, local(m, "long-axis"), EPS);
    }

    @Test
    void matrixIsReadRowMajorAndFollowedByTheNextElement() {
        Model m = Fixtures.resource("scene/transform-stacks.dae");
        // M = [Rz(90) | (5 0 0)] then T(1 0 0): the translation (1 0 0) is rotated to (0 1 0) and
        // added: (5 1 0). Column-major reading would give the transposed rotation and t = (0 0 0).
        assertRows(new float[][] {{0, -1, 0, 5}, {1, 0, 0, 1}, {0, 0, 1, 0}}, local(m, "matrix-then-translate"), EPS);
        // The element keeps the file's values (row-major): the translation in values 3, 7, 11.
        TransformElement matrix = node(m, "matrix-then-translate").transforms().get(0);
        assertEquals(5f, matrix.value(3), 0f);
        assertEquals(-1f, matrix.value(1), 0f);
    }

    @Test
    void lookatPlacesTheNodeAtTheEyeWithMinusZTowardTheInterestPoint() {
        Model m = Fixtures.resource("scene/transform-stacks.dae");
        Matrix4fc onZ = local(m, "eye-on-z");
        // Eye (0 0 5), looking at the origin with Y up: no rotation, translation (0 0 5).
        assertRows(new float[][] {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 5}}, onZ, EPS);
        assertVector(new Vector3f(0, 0, 0), onZ.transformPosition(new Vector3f(0, 0, -5)));
        assertVector(new Vector3f(0, 0, -1), onZ.transformDirection(new Vector3f(0, 0, -1)));

        Matrix4fc onX = local(m, "eye-on-x");
        // Eye (5 0 0): forward f = (-1 0 0), right = f x up = (0 0 -1), up stays (0 1 0), so the
        // local axes X Y Z map to (0 0 -1) (0 1 0) (1 0 0).
        assertRows(new float[][] {{0, 0, 1, 5}, {0, 1, 0, 0}, {-1, 0, 0, 0}}, onX, EPS);
        assertVector(new Vector3f(-1, 0, 0), onX.transformDirection(new Vector3f(0, 0, -1)));
        assertVector(new Vector3f(0, 0, 0), onX.transformPosition(new Vector3f(0, 0, -5)));
    }

    @Test
    void degenerateLookatPlacesTheNodeAtTheEyeWithoutRotationWithAWarning() {
        // No direction to look in: the eye on the interest point, or the up vector along the view.
        Model m = Fixtures.read("degenerate-lookat.dae", collada("""
                <library_visual_scenes><visual_scene id="s">
                  <node id="on-target"><lookat>0 0 5  0 0 5  0 1 0</lookat></node>
                  <node id="up-along-view"><lookat>0 5 0  0 0 0  0 1 0</lookat></node>
                </visual_scene></library_visual_scenes>
                <scene><instance_visual_scene url="#s"/></scene>
                """));
        assertRows(new float[][] {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 5}}, local(m, "on-target"), 0f);
        assertRows(new float[][] {{1, 0, 0, 0}, {0, 1, 0, 5}, {0, 0, 1, 0}}, local(m, "up-along-view"), 0f);
        assertEquals(2, Snippets.warningsContaining(m, "lookat without a view direction").size(),
                () -> m.warnings().toString());
    }

    @Test
    void skewMovesPointsAlongTheTranslationAxisByTanAngleTimesTheirRotationAxisComponent() {
        Model m = Fixtures.resource("scene/transform-stacks.dae");
        // 45 degrees, rotation axis X, translation axis Y: y' = y + tan(45) x = y + x.
        Matrix4fc skew45 = local(m, "skew-45");
        assertRows(new float[][] {{1, 0, 0, 0}, {1, 1, 0, 0}, {0, 0, 1, 0}}, skew45, EPS);
        assertVector(new Vector3f(1, 1, 0), skew45.transformPosition(new Vector3f(1, 0, 0)));
        assertVector(new Vector3f(0, 1, 0), skew45.transformPosition(new Vector3f(0, 1, 0)));
        // 30 degrees, axes (0 0 2) and (3 0 0), normalised to Z and X: x' = x + tan(30) z.
        float t = (float) Math.tan(Math.toRadians(30));
        assertRows(new float[][] {{1, 0, t, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}, local(m, "skew-30"), EPS);
    }

    @Test
    void rotationAboutAZeroAxisRotatesNothingWithAWarning() {
        Model m = Fixtures.read("zero-axis.dae", collada("""
                <library_visual_scenes><visual_scene id="s">
                  <node id="n"><translate>1 2 3</translate><rotate sid="spin">0 0 0 45</rotate><translate>1 0 0</translate></node>
                </visual_scene></library_visual_scenes>
                <scene><instance_visual_scene url="#s"/></scene>
                """));
        // T(1 2 3) I T(1 0 0): translation (2 2 3); a rotation would have turned the second one.
        assertRows(new float[][] {{1, 0, 0, 2}, {0, 1, 0, 2}, {0, 0, 1, 3}}, local(m, "n"), EPS);
        ImportWarning w = oneWarning(m, "rotation about a zero axis");
        assertTrue(w.element().startsWith("<rotate sid=\"spin\"> in <node id=\"n\">"), w::toString);
        // The element is kept as written (an animation may give it an axis later).
        assertArrayEquals(new float[] {0, 0, 0, 45}, node(m, "n").transforms().get(1).values());
    }

    @Test
    void aZeroRotationAboutAZeroAxisIsNoRotationWithoutAWarning() {
        // FBX writes "0 0 0 0" on its pivot nodes, 64 of them in one file: no angle, no question.
        Model m = Fixtures.read("zero-zero.dae", collada("""
                <library_visual_scenes><visual_scene id="s">
                  <node id="n"><rotate sid="pivot">0 0 0 0</rotate><translate>1 0 0</translate></node>
                </visual_scene></library_visual_scenes>
                <scene><instance_visual_scene url="#s"/></scene>
                """));
        assertRows(new float[][] {{1, 0, 0, 1}, {0, 1, 0, 0}, {0, 0, 1, 0}}, local(m, "n"), EPS);
        assertNoWarnings(m);
    }

    @Test
    void matrixWithAProjectiveBottomRowIsTreatedAsAffineWithAWarning() {
        Model m = Fixtures.read("bottom-row.dae", collada("""
                <library_visual_scenes><visual_scene id="s">
                  <node id="n"><matrix sid="transform">1 0 0 4  0 1 0 5  0 0 1 6  0.5 0 0 2</matrix></node>
                </visual_scene></library_visual_scenes>
                <scene><instance_visual_scene url="#s"/></scene>
                """));
        // assertRows also checks the bottom row is exactly (0 0 0 1).
        assertRows(new float[][] {{1, 0, 0, 4}, {0, 1, 0, 5}, {0, 0, 1, 6}}, local(m, "n"), 0f);
        oneWarning(m, "matrix has bottom row (0.5 0.0 0.0 2.0), treated as (0 0 0 1)");
        TransformElement matrix = node(m, "n").transforms().get(0);
        assertEquals(0.5f, matrix.value(12), 0f);
        assertEquals(2f, matrix.value(15), 0f);
    }

    // ------------------------------------------------------------------------------- hierarchy

    @Test
    void instanceNodeCopiesTheLibrarySubtreeDepthFirstInPlace() {
        Model m = Fixtures.resource("scene/instance-node.dae");
        // Written order: table { leg-copy, top, leg-copy }, bench { pair-copy { leg-copy } },
        // each leg being leg > foot > toe.
        String[] ids = {"table", "leg", "foot", "toe", "top", "leg", "foot", "toe",
                "bench", "pair", "leg", "foot", "toe"};
        int[] parents = {-1, 0, 1, 2, 0, 0, 5, 6, -1, 8, 9, 10, 11};
        boolean[] instanced = {false, true, true, true, false, true, true, true, false, true, true, true, true};
        assertEquals(ids.length, m.nodes().size());
        for (int i = 0; i < ids.length; i++) {
            Node n = m.node(i);
            assertEquals(ids[i], n.id(), "node " + i);
            assertEquals(parents[i], n.parent(), "parent of node " + i);
            assertEquals(instanced[i], n.instanced(), "instanced() of node " + i);
            assertTrue(n.parent() < i, "parents come before their children");
        }
        assertArrayEquals(new int[] {1, 4, 5}, m.node(0).children());
        assertArrayEquals(new int[] {9}, m.node(8).children());
        assertArrayEquals(new int[] {10}, m.node(9).children());
        // Copies keep the library node's sid, name and transforms.
        assertEquals("foot", m.node(6).sid());
        assertEquals("foot", m.node(11).name());
        assertRows(new float[][] {{1, 0, 0, 0}, {0, 1, 0, -2}, {0, 0, 1, 0}}, m.node(11).localMatrix(), 0f);
        assertRows(new float[][] {{1, 0, 0, 10}, {0, 1, 0, 0}, {0, 0, 1, 0}}, m.node(9).localMatrix(), 0f);
        assertNoWarnings(m);
    }

    @Test
    void nonJointNodeBetweenJointsStaysInTheHierarchyWithItsTransform() {
        // hip (JOINT) > twist (NODE, not a skin joint) > knee (JOINT): the skin uses hip and knee.
        Model m = Fixtures.read("helper-between-joints.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                "<library_controllers>" + skin("c", "g", "Name_array", "hip knee", "1", "1 1 1", "0 0 1 0 1 0")
                        + "</library_controllers>",
                """
                <library_visual_scenes><visual_scene id="s">
                  <node id="rig">
                    <node id="hip" sid="hip" type="JOINT">
                      <node id="twist" sid="twist" type="NODE">
                        <translate>0 -1 0</translate><rotate>0 1 0 90</rotate>
                        <node id="knee" sid="knee" type="JOINT"><translate>0 -1 0</translate></node>
                      </node>
                    </node>
                  </node>
                  <node id="body"><instance_controller url="#c"><skeleton>#hip</skeleton></instance_controller></node>
                </visual_scene></library_visual_scenes>
                <scene><instance_visual_scene url="#s"/></scene>
                """));
        Node hip = node(m, "hip");
        Node twist = node(m, "twist");
        Node knee = node(m, "knee");
        assertEquals(hip.index(), twist.parent());
        assertEquals(twist.index(), knee.parent());
        assertTrue(hip.isJoint());
        assertFalse(twist.isJoint());
        assertTrue(knee.isJoint());
        // T(0 -1 0) Ry(90): x -> -z, z -> x.
        assertRows(new float[][] {{0, 0, 1, 0}, {0, 1, 0, -1}, {-1, 0, 0, 0}}, twist.localMatrix(), EPS);
        MeshInstance body = m.instances().get(0);
        assertArrayEquals(new int[] {hip.index(), knee.index()}, body.jointNodes());
        assertNoWarnings(m);
    }

    @Test
    void fileWithoutSceneUsesTheFirstVisualSceneWithAWarning() {
        Model m = Fixtures.read("no-scene.dae", collada("""
                <library_visual_scenes>
                  <visual_scene id="first"><node id="a"><node id="a-child"/></node></visual_scene>
                  <visual_scene id="second"><node id="b"/></visual_scene>
                </library_visual_scenes>
                """));
        assertEquals(List.of("a", "a-child"), m.nodes().stream().map(Node::id).collect(Collectors.toList()));
        ImportWarning w = oneWarning(m, "no <scene><instance_visual_scene>");
        assertTrue(w.message().contains("using the first visual scene \"first\""), w::toString);
    }

    @Test
    void sceneElementChoosesItsVisualSceneWithoutWarning() {
        Model m = Fixtures.read("second-scene.dae", collada("""
                <library_visual_scenes>
                  <visual_scene id="first"><node id="a"/></visual_scene>
                  <visual_scene id="second"><node id="b"/></visual_scene>
                </library_visual_scenes>
                <scene><instance_visual_scene url="#second"/></scene>
                """));
        assertEquals(List.of("b"), m.nodes().stream().map(Node::id).collect(Collectors.toList()));
        assertNoWarnings(m);
    }

    // ----------------------------------------------------------------------------- helpers

    private static void assertVector(Vector3f expected, Vector3f actual) {
        assertEquals(expected.x, actual.x, EPS, () -> "x of " + actual);
        assertEquals(expected.y, actual.y, EPS, () -> "y of " + actual);
        assertEquals(expected.z, actual.z, EPS, () -> "z of " + actual);
    }

    private static double[][] translation(double x, double y, double z) {
        return new double[][] {{1, 0, 0, x}, {0, 1, 0, y}, {0, 0, 1, z}, {0, 0, 0, 1}};
    }

    private static double[][] scaling(double x, double y, double z) {
        return new double[][] {{x, 0, 0, 0}, {0, y, 0, 0}, {0, 0, z, 0}, {0, 0, 0, 1}};
    }

    private static double[][] rotationX(double degrees) {
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        return new double[][] {{1, 0, 0, 0}, {0, c, -s, 0}, {0, s, c, 0}, {0, 0, 0, 1}};
    }

    private static double[][] rotationY(double degrees) {
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        return new double[][] {{c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}, {0, 0, 0, 1}};
    }

    private static double[][] rotationZ(double degrees) {
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        return new double[][] {{c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    }

    /** The product of the matrices, left to right. */
    private static double[][] product(double[][]... factors) {
        double[][] p = factors[0];
        for (int f = 1; f < factors.length; f++) {
            double[][] q = new double[4][4];
            for (int r = 0; r < 4; r++) {
                for (int c = 0; c < 4; c++) {
                    for (int k = 0; k < 4; k++) {
                        q[r][c] += p[r][k] * factors[f][k][c];
                    }
                }
            }
            p = q;
        }
        return p;
    }
}
