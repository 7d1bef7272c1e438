package org.skinlab.internal.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.nio.file.Paths;

import org.joml.Matrix3f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Image;
import org.skinlab.model.Material;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Texture;
import org.skinlab.model.TextureTransform;

/**
 * What the renderers draw per part: core's gltf/materials.glb (tools/gltf/make-fixtures.py)
 * resolved into {@link PartMaterial}s, the texture transform's shader matrix against
 * {@link TextureTransform#apply}, and COLLADA's defaults (BLEND, double-sided) left as they were.
 */
class PartMaterialTest {
    private static final Path MATERIALS = Paths.get("src/test/resources/gltf/materials.glb");

    private static PartMaterial part(Model model, String name) {
        for (MeshInstance instance : model.instances()) {
            if (instance.mesh().name() != null && instance.mesh().name().equals(name)) {
                return PartMaterial.of(instance, instance.mesh().parts().get(0));
            }
        }
        throw new AssertionError("no mesh " + name);
    }

    @Test
    void glTfMaterialsResolveToWhatTheShaderNeeds() throws Exception {
        Model model = ModelImporter.read(MATERIALS);
        PartMaterial glass = part(model, "glass");
        assertTrue(glass.blended());
        assertArrayEquals(new float[] {0, 0, 1, 0.5f}, glass.baseColor());
        assertFalse(glass.doubleSided(), "glTF's default is single-sided");
        PartMaterial cutout = part(model, "cutout");
        assertEquals(Material.AlphaMode.MASK, cutout.alphaMode());
        assertEquals(0.5f, cutout.alphaCutoff());
        assertTrue(cutout.baseTexture() != null);
        PartMaterial glow = part(model, "glow");
        assertArrayEquals(new float[] {0, 1, 0}, glow.emission());
        assertFalse(glow.unlit());
        PartMaterial unlit = part(model, "unlit");
        assertTrue(unlit.unlit());
        assertArrayEquals(new float[] {1, 0.5f, 0, 1}, unlit.baseColor());
        assertArrayEquals(new float[3], unlit.emission(), "unlit parts add no emission on top");
        assertTrue(part(model, "double-sided").doubleSided());
        PartMaterial quadrants = part(model, "quadrants");
        assertEquals(Material.AlphaMode.OPAQUE, quadrants.alphaMode());
        assertArrayEquals(new float[] {1, 1, 1, 1}, quadrants.baseColor());
    }

    @Test
    void theShadersMatrixIsTheTransformColumnMajor() {
        TextureTransform t = TextureTransform.fromGltf(0.25f, -0.5f, 0.7f, 2f, 0.5f);
        float[] m = PartMaterial.uvMatrix(new Texture(new Image("i", null, null, null), "TEXCOORD_0", t));
        Matrix3f shader = new Matrix3f().set(m); // JOML reads column-major, as glUniformMatrix3fv does
        float[] expected = new float[2];
        for (float[] uv : new float[][] {{0, 0}, {1, 0}, {0.3f, 0.9f}, {-2, 5}}) {
            Vector3f r = shader.transform(new Vector3f(uv[0], uv[1], 1));
            t.apply(uv[0], uv[1], expected);
            assertEquals(expected[0], r.x, 1e-6f);
            assertEquals(expected[1], r.y, 1e-6f);
            assertEquals(1f, r.z, 0f);
        }
        assertArrayEquals(new float[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, PartMaterial.uvMatrix(null));
    }

    @Test
    void glTfsQuarterTurnMapsAsTheSpecificationsFormulaAfterTheVFlip() {
        // KHR_texture_transform in glTF's v-down convention: uv' = T R S uv with R = [c s; -s c];
        // rotation pi/2 and offset (0, 1) give (v, 1 - u). The model's coordinates are (u, 1 - v).
        TextureTransform t = TextureTransform.fromGltf(0f, 1f, (float) (Math.PI / 2), 1f, 1f);
        float[] out = new float[2];
        for (float[] g : new float[][] {{0.25f, 0.25f}, {0.75f, 0.1f}, {0.6f, 0.8f}}) {
            float[] gltf = {g[1], 1 - g[0]};
            t.apply(g[0], 1 - g[1], out);
            assertEquals(gltf[0], out[0], 1e-6f);
            assertEquals(1 - gltf[1], out[1], 1e-6f, "v flipped back into the model's convention");
        }
    }

    @Test
    void colladaMaterialsKeepBlendingAndBothFaces() {
        Material m = new Material.Builder("m", "m").diffuse(new float[] {0.2f, 0.4f, 0.6f, 1f}).opacity(0.5f).build();
        PartMaterial p = PartMaterial.of(m);
        assertTrue(p.blended());
        assertTrue(p.doubleSided());
        assertArrayEquals(new float[] {0.2f, 0.4f, 0.6f, 0.5f}, p.baseColor(), "alpha limited by the opacity");
        Material constant = new Material.Builder("c", "c").shading(Material.Shading.CONSTANT)
                .emission(new float[] {0.1f, 0.2f, 0.3f, 1f}).build();
        assertTrue(PartMaterial.of(constant).unlit());
        assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f, 1f}, PartMaterial.of(constant).baseColor());
        assertSame(Material.DEFAULT, PartMaterial.DEFAULT.material());
        assertNull(PartMaterial.DEFAULT.baseTexture());
    }

    @Test
    void partCentresArePlacedByTheFramesMatrices() throws Exception {
        Model model = ModelImporter.read(MATERIALS);
        org.skinlab.simulation.AnimationConfig config = new org.skinlab.simulation.AnimationConfig(
                org.skinlab.simulation.AnimationConfig.Settings.DEFAULT.withCpuSkinning(false));
        try (org.skinlab.simulation.SkeletalAnimatedMesh mesh = org.skinlab.simulation.SkeletalAnimatedMesh.of(model,
                config); org.skinlab.simulation.Frame frame = mesh.acquire()) {
            for (int g = 0; g < mesh.geometries().size(); g++) {
                if (!"glass".equals(mesh.geometries().get(g).mesh().name())) {
                    continue;
                }
                PartCentres centres = PartCentres.of(mesh.geometries().get(g));
                float[] posed = new float[3];
                centres.posed(0, frame.palette(g).matrices(), posed);
                // The glass quad's node: column 0, row 1, in front (make-fixtures.py's layout).
                assertArrayEquals(new float[] {-1.25f, 1.25f, 0.3f}, posed, 1e-6f);
                assertFalse(PartCentres.firstJointMirrors(frame.palette(g).matrices()));
                return;
            }
        }
        throw new AssertionError("no glass geometry");
    }

    @Test
    void aMirroringMatrixReversesTheWinding() {
        float[] mirror = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
        float[] turn = {0, -1, 0, 3, 1, 0, 0, 0, 0, 0, 1, 0};
        assertTrue(PartCentres.firstJointMirrors(mirror));
        assertFalse(PartCentres.firstJointMirrors(turn));
    }

    @Test
    void blendedPartsAreOrderedFarthestFirst() {
        BlendOrder order = new BlendOrder(4);
        order.add(0, 0, 2f);
        order.add(1, 0, 5f);
        order.add(0, 1, 1f);
        order.add(2, 3, 3f);
        int[][] expected = {{1, 0}, {2, 3}, {0, 0}, {0, 1}};
        assertEquals(4, order.size());
        for (int k = 0; k < 4; k++) {
            assertEquals(expected[k][0], order.geometry(k));
            assertEquals(expected[k][1], order.part(k));
        }
        order.clear();
        assertEquals(0, order.size());
    }
}
