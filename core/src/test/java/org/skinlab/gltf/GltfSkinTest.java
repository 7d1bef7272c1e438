package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * A two-bone skin posed by hand: root at the origin, tip one unit up and turned 90 degrees about
 * Z by a one-key animation. Vertex (0,2,0) on the tip goes to (-1,1,0); (1,1,0) half on each bone
 * goes to the mean of (1,1,0) and (0,2,0). The skinned mesh's node is moved by 100 in x, which
 * the specification says to ignore.
 */
class GltfSkinTest {
    private static final float EPS = 1e-6f;

    /** The joints' inverse bind matrices, column-major: the identity, and a translation by (0, -1, 0). */
    private static final double[] INVERSE_BINDS = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};

    private static String twoBoneSkin(GltfFixture f, String skinExtra, String meshNodeExtra) {
        return twoBoneSkin(f, skinExtra, meshNodeExtra, INVERSE_BINDS);
    }

    private static String twoBoneSkin(GltfFixture f, String skinExtra, String meshNodeExtra, double[] inverseBinds) {
        f.floats("VEC3", 0, 0, 0, 0, 2, 0, 1, 1, 0); // 0 positions
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "VEC4", false, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0); // 1 joints
        f.floats("VEC4", 1, 0, 0, 0, 1, 0, 0, 0, 0.5, 0.5, 0, 0); // 2 weights
        f.floats("MAT4", inverseBinds); // 3
        f.floats("SCALAR", 0); // 4 time
        double h = Math.sqrt(0.5);
        f.floats("VEC4", 0, 0, h, h); // 5 rotation
        return f.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"JOINTS_0\":1,"
                + "\"WEIGHTS_0\":2}}]}],"
                + "\"skins\":[{\"joints\":[0,1]" + skinExtra + "}],"
                + "\"nodes\":[{\"name\":\"root\",\"children\":[1]},{\"name\":\"tip\",\"translation\":[0,1,0]},"
                + "{\"name\":\"body\",\"mesh\":0,\"skin\":0,\"translation\":[100,0,0]" + meshNodeExtra + "}],"
                + "\"scenes\":[{\"nodes\":[2,0]}],"
                + "\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":1,\"path\":\"rotation\"}}],"
                + "\"samplers\":[{\"input\":4,\"output\":5}]}]");
    }

    private static float[] lbs(Model model) {
        SkinnedModel skinned = SkinnedModel.of(model);
        skinned.pose(0f, RotationInterpolation.SLERP);
        float[] out = new float[9];
        skinned.skin(0, SkinningMethod.LBS, out, new float[9]);
        return out;
    }

    @Test
    void twoBonePoseMatchesTheHandComputedOne() throws Exception {
        Model model = GltfFixture.read(twoBoneSkin(new GltfFixture(), ",\"inverseBindMatrices\":3", ""));
        MeshInstance instance = model.instances().get(0);
        assertEquals("body", model.node(instance.node()).name());
        assertArrayEquals(new int[] {1, 2}, instance.jointNodes(), "scene order: body (0), root (1), tip (2)");
        assertArrayEquals(new float[] {0, 0, 0, -1, 1, 0, 0.5f, 1.5f, 0}, lbs(model), EPS);
        assertTrue(model.node(1).isJoint() && !model.node(0).isJoint());
    }

    @Test
    void theSkinnedNodesTransformIsIgnoredButAStaticNodesIsNot() throws Exception {
        String json = twoBoneSkin(new GltfFixture(), ",\"inverseBindMatrices\":3", "")
                .replace("{\"name\":\"body\"", "{\"name\":\"static\",\"mesh\":0,\"translation\":[100,0,0]},"
                        + "{\"name\":\"body\"")
                .replace("\"scenes\":[{\"nodes\":[2,0]}]", "\"scenes\":[{\"nodes\":[3,2,0]}]");
        Model model = GltfFixture.read(json);
        SkinnedModel skinned = SkinnedModel.of(model);
        skinned.pose(0f, RotationInterpolation.SLERP);
        float[] out = new float[9];
        skinned.skin(0, SkinningMethod.LBS, out, new float[9]);
        assertArrayEquals(new float[] {0, 0, 0, -1, 1, 0, 0.5f, 1.5f, 0}, out, EPS, "body, skinned: not moved");
        skinned.skin(1, SkinningMethod.LBS, out, new float[9]);
        assertArrayEquals(new float[] {100, 0, 0, 100, 2, 0, 101, 1, 0}, out, EPS, "the same mesh static: moved");
    }

    @Test
    void everyJointsAndWeightsSetIsRead() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 0, 2, 0, 1, 1, 0);
        f.accessor(AccessorFormat.UNSIGNED_SHORT, "VEC4", false, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0); // 1 JOINTS_0
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "VEC4", true, 51, 51, 0, 0, 255, 0, 0, 0, 128, 127, 0, 0); // 2 WEIGHTS_0
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "VEC4", false, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0); // 3 JOINTS_1
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "VEC4", true, 153, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0); // 4 WEIGHTS_1
        Model model = GltfFixture.read(f.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,"
                + "\"JOINTS_0\":1,\"WEIGHTS_0\":2,\"JOINTS_1\":3,\"WEIGHTS_1\":4}}]}],\"skins\":[{\"joints\":[1,2]}],"
                + "\"nodes\":[{\"mesh\":0,\"skin\":0},{\"children\":[2]},{}],\"scenes\":[{\"nodes\":[0,1]}]"));
        Skin skin = model.skins().get(0);
        assertEquals(3, skin.influenceCount(0), "0.2 + 0.2 from set 0, 0.6 from set 1");
        assertEquals(0.6f, skin.influenceWeight(skin.influenceStart(0) + 2), 1e-7f);
        assertEquals(1, skin.influenceJoint(skin.influenceStart(0) + 2));
        assertEquals(1, skin.influenceCount(1));
        assertEquals(128 / 255f, skin.influenceWeight(skin.influenceStart(2)), 1e-7f);
        assertTrue(model.warnings().isEmpty(), "sums within 1/255 of 1: " + model.warnings());
    }

    @Test
    void splitVerticesShareAPositionOnlyWhenTheirInfluencesAgree() throws Exception {
        GltfFixture f = new GltfFixture();
        // Vertices 0 and 1 are one point with one influence; vertex 2 is the same point weighted otherwise.
        f.floats("VEC3", 0, 2, 0, 0, 2, 0, 0, 2, 0);
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "VEC4", false, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0);
        f.floats("VEC4", 1, 0, 0, 0, 1, 0, 0, 0, 0.5, 0.5, 0, 0);
        Model model = GltfFixture.read(f.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,"
                + "\"JOINTS_0\":1,\"WEIGHTS_0\":2}}]}],\"skins\":[{\"joints\":[1,2]}],"
                + "\"nodes\":[{\"mesh\":0,\"skin\":0},{\"children\":[2]},{\"rotation\":[0,0,1,0]}],"
                + "\"scenes\":[{\"nodes\":[0,1]}]"));
        Skin skin = model.skins().get(0);
        assertEquals(2, skin.mesh().positionCount());
        assertArrayEquals(new int[] {0, 0, 1}, skin.mesh().vertexPositions());
        assertEquals(1, skin.influenceCount(0));
        assertEquals(2, skin.influenceCount(1));
        // Joint 1 (node 2) turns 180 degrees about Z: the shared point follows it to (0,-2,0) for
        // both of its vertices; the half-weighted vertex lands halfway, at the origin.
        SkinnedModel skinned = SkinnedModel.of(model);
        skinned.pose(0f, RotationInterpolation.SLERP);
        float[] out = new float[9];
        skinned.skin(0, SkinningMethod.LBS, out, new float[9]);
        assertArrayEquals(new float[] {0, -2, 0, 0, -2, 0, 0, 0, 0}, out, EPS);
    }

    @Test
    void zeroWeightsAreDroppedAndWeightsKeptAsWritten() throws Exception {
        Skin skin = GltfFixture.read(twoBoneSkin(new GltfFixture(), ",\"inverseBindMatrices\":3", ""))
                .skins().get(0);
        assertEquals(1, skin.influenceCount(0));
        assertEquals(2, skin.influenceCount(2));
        assertEquals(0.5f, skin.influenceWeight(skin.influenceStart(2) + 1));
        assertEquals(1, skin.influenceJoint(skin.influenceStart(2) + 1));
        assertTrue(skin.bindShapeMatrix().equals(new org.joml.Matrix4f(), 0f));
    }

    @Test
    void withoutInverseBindMatricesEachIsTheIdentity() throws Exception {
        // Identity binds: the tip's skinning matrix is its world matrix T(0,1,0) R, so (0,2,0) -> (-2,1,0).
        float[] out = lbs(GltfFixture.read(twoBoneSkin(new GltfFixture(), "", "")));
        assertArrayEquals(new float[] {-2, 1, 0}, new float[] {out[3], out[4], out[5]}, EPS);
    }

    @Test
    void skeletonPropertyBecomesTheInstancesSkeletonRoot() throws Exception {
        Model model = GltfFixture.read(twoBoneSkin(new GltfFixture(), ",\"inverseBindMatrices\":3,\"skeleton\":0", ""));
        assertArrayEquals(new int[] {1}, model.instances().get(0).skeletonRoots());
    }

    @Test
    void aNonAffineInverseBindMatrixIsRefused() {
        double[] ibm = INVERSE_BINDS.clone();
        ibm[3] = 1; // column 0, row 3: the first matrix's last row is no longer 0 0 0 1
        String json = twoBoneSkin(new GltfFixture(), ",\"inverseBindMatrices\":3", "", ibm);
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(json));
        assertEquals("test.gltf: /skins/0/inverseBindMatrices: inverse bind matrix 0 is not affine (its last row is"
                + " not 0 0 0 1)", e.getMessage());
    }

    @Test
    void aSkinOnANodeWithoutAMeshIsRefused() {
        String json = twoBoneSkin(new GltfFixture(), "", "").replace("{\"name\":\"root\",", "{\"name\":\"root\","
                + "\"skin\":0,");
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(json));
        assertEquals("/nodes/0/skin", e.path());
    }

    @Test
    void jointBeyondTheSkinIsRefusedWithTheJointsPath() throws Exception {
        GltfFixture f = new GltfFixture();
        String json = twoBoneSkin(f, "", "").replace("\"joints\":[0,1]", "\"joints\":[0]");
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(json));
        assertEquals("test.gltf: /meshes/0/primitives/0/attributes/JOINTS_0: joint 1 is weighted, but skin 0 has 1"
                + " joints", e.getMessage());
    }
}
