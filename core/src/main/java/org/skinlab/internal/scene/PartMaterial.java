package org.skinlab.internal.scene;

import org.skinlab.model.Material;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Texture;

/**
 * What a renderer draws for one run of a mesh's triangles, resolved once from the material bound
 * to it, in the terms of core's {@code material.glsl} ({@link MaterialGlsl}), which both apps'
 * fragment shaders include: base colour (RGBA, times the base texture and the vertex colour),
 * emission added after lighting, unlit or lit, alpha mode and cutoff, and whether back faces are
 * culled.
 *
 * <p>The base colour is the material's diffuse colour (glTF: {@code baseColorFactor}; white when
 * the material gives none, as a COLLADA diffuse texture does), its alpha at most the material's
 * opacity; for constant shading (COLLADA {@code <constant>}, glTF {@code KHR_materials_unlit}) it
 * is the emission colour and the part is drawn unlit. Emission (lit parts only) is COLLADA's and
 * glTF's emissive term, added to the lit colour.
 */
public final class PartMaterial {
    /** A part no material is bound to: {@link Material#DEFAULT}. */
    public static final PartMaterial DEFAULT = of(Material.DEFAULT);

    private static final float[] WHITE = {1f, 1f, 1f, 1f};
    private static final float[] IDENTITY_UV = {1, 0, 0, 0, 1, 0, 0, 0, 1};

    private final Material material;
    private final float[] baseColor;
    private final float[] emission;
    private final Texture baseTexture;
    private final Texture emissionTexture;
    private final boolean unlit;

    private PartMaterial(Material m) {
        this.material = m;
        this.unlit = m.shading() == Material.Shading.CONSTANT;
        float[] base = unlit ? m.emission() : m.diffuse();
        this.baseColor = base != null ? base : WHITE.clone();
        baseColor[3] = Math.min(baseColor[3], m.opacity());
        float[] e = unlit ? null : m.emission();
        this.emission = e != null ? new float[] {e[0], e[1], e[2]} : new float[3];
        this.baseTexture = m.baseTexture();
        this.emissionTexture = unlit ? null : m.emissionTexture();
    }

    /** The draw-ready form of {@code material}. */
    public static PartMaterial of(Material material) {
        return new PartMaterial(material);
    }

    /** The material {@code instance} binds to {@code part}'s symbol, else {@link #DEFAULT}. */
    public static PartMaterial of(MeshInstance instance, MeshPart part) {
        MaterialBinding binding = instance == null || part.material() == null ? null
                : instance.material(part.material());
        return binding == null || binding.material() == null ? DEFAULT : of(binding.material());
    }

    public Material material() {
        return material;
    }

    /** A copy of the base colour, RGBA. */
    public float[] baseColor() {
        return baseColor.clone();
    }

    /** A copy of the emitted colour added to lit parts, RGB (zero when none, and for unlit parts). */
    public float[] emission() {
        return emission.clone();
    }

    /** The texture the base colour is multiplied by, or null. */
    public Texture baseTexture() {
        return baseTexture;
    }

    /** The texture the emission is multiplied by (lit parts), or null. */
    public Texture emissionTexture() {
        return emissionTexture;
    }

    /** Drawn without lighting: the base colour as it is. */
    public boolean unlit() {
        return unlit;
    }

    public Material.AlphaMode alphaMode() {
        return material.alphaMode();
    }

    public float alphaCutoff() {
        return material.alphaCutoff();
    }

    /** False when back faces are culled. */
    public boolean doubleSided() {
        return material.doubleSided();
    }

    /** Drawn in the blended pass, after every opaque and masked part. */
    public boolean blended() {
        return material.alphaMode() == Material.AlphaMode.BLEND;
    }

    /**
     * {@code texture}'s coordinate transform as a GLSL {@code mat3}, column-major (for
     * {@code glUniformMatrix3fv} without transposing): {@code uv' = (M * vec3(uv, 1)).xy}. The
     * identity for a null texture.
     */
    public static float[] uvMatrix(Texture texture) {
        if (texture == null) {
            return IDENTITY_UV.clone();
        }
        float[] m = texture.transform().values(); // m00 m01 m02 m10 m11 m12, row-major
        return new float[] {m[0], m[3], 0, m[1], m[4], 0, m[2], m[5], 1};
    }

    /**
     * The texture coordinates a renderer feeds {@code mesh}'s vertices with: the set the
     * instance's first textured binding names, else the mesh's first set; null when it has none.
     * One set per mesh: parts whose textures name different sets all read this one.
     */
    public static float[] texCoords(Mesh mesh, MeshInstance instance) {
        if (mesh == null || mesh.texCoordSetCount() == 0) {
            return null;
        }
        int set = 0;
        if (instance != null) {
            for (MaterialBinding b : instance.materials()) {
                if (b.texCoordSet() >= 0) {
                    set = b.texCoordSet();
                    break;
                }
            }
        }
        return mesh.texCoords(set);
    }

    @Override
    public String toString() {
        return "PartMaterial[" + material.name() + ", " + material.alphaMode() + (unlit ? ", unlit" : "")
                + (doubleSided() ? ", double-sided" : "") + "]";
    }
}
