package org.skinlab.jme;

import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import com.jme3.anim.Armature;
import com.jme3.anim.MatrixJointModelTransform;
import com.jme3.anim.SkinningControl;
import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.VertexBuffer.Type;
import com.jme3.scene.control.AbstractControl;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * A drop-in replacement for jME's {@link SkinningControl} that deforms the meshes with one of
 * skinlab's skinning methods while jME's {@link Armature} (animated by jME's AnimComposer, or by
 * hand) keeps moving the joints:
 * <pre>
 * Spatial model = assetManager.loadModel("humanoid-walk.glb");
 * SkinlabSkinningControl.replace(model, SkinningMethod.DQS, SkinlabSkinningControl.Mode.GPU, assetManager);
 * </pre>
 *
 * <p>Each frame it reads the armature's skinning matrices as jME's control would
 * ({@link Armature#computeSkinningMatrices()}) into skinlab's {@link JointPalette}, then either
 * <ul>
 * <li>{@link Mode#CPU}: skins every target mesh with skinlab's kernels ({@link Skinners}) from its
 *     bind buffers into its Position and Normal buffers and updates its bound; allocation-free per
 *     frame. Every {@link SkinningMethod}.</li>
 * <li>{@link Mode#GPU}: fills a palette texture ({@link PaletteTexture}) that the material
 *     {@value #MATERIAL} skins with in its vertex shader, built from skinlab's shared skinning.glsl
 *     ({@link SkinlabShaderLoader}); the meshes' buffers stay in bind pose. Every method with shader
 *     code ({@link SkinningGlsl#hasCode}: all but spline). The material is skinlab's own lit
 *     material (one directional light and ambient, the glTF base colour), not jME's PBR lighting.</li>
 * </ul>
 *
 * <p>Not carried over from jME's control: attachment nodes (getAttachmentsNode), morph targets,
 * tangents, and the automatic fallback from GPU to CPU.
 */
public final class SkinlabSkinningControl extends AbstractControl {
    /** Where the mesh is deformed. */
    public enum Mode {
        /** skinlab's CPU kernels, into the mesh's Position and Normal buffers. */
        CPU,
        /** skinlab's vertex shader, with the palette in a float texture. */
        GPU
    }

    /** The GPU path's material definition. */
    public static final String MATERIAL = "org/skinlab/jme/SkinlabSkinned.j3md";

    private final ArmaturePalette armature;
    private final SkinningMethod method;
    private final Mode mode;
    /** An array, not a list: a frame's loop over it allocates no iterator. */
    private final Target[] targets;

    /** One deformed geometry and what skinning it needs. */
    private static final class Target {
        final Geometry geometry;
        final SkinnedGeometry skinned;
        final JointPalette palette;
        final Skinner skinner;
        final float[] positions;
        final float[] normals;
        final PaletteTexture texture;
        final Material material;

        Target(Geometry geometry, SkinnedGeometry skinned, Skinner skinner, PaletteTexture texture, Material material) {
            this.geometry = geometry;
            this.skinned = skinned;
            this.palette = skinned.newPalette();
            this.skinner = skinner;
            this.positions = skinner == null ? null : new float[3 * skinned.pointCount()];
            this.normals = skinner == null ? null : new float[3 * skinned.pointCount()];
            this.texture = texture;
            this.material = material;
        }
    }

    /**
     * Replaces the {@link SkinningControl} that jME's loaders put in {@code model} by a control
     * skinning the same meshes with {@code method}, added to the same spatial (after the
     * AnimComposer, so the armature it reads is this frame's). The armature is switched to
     * {@link MatrixJointModelTransform}, so that its joints compose as glTF's node matrices do.
     *
     * @param model  a loaded model holding one SkinningControl (on itself or a descendant)
     * @param method the skinning method
     * @param mode   CPU or GPU
     * @param assets the asset manager, for the GPU path's material (unused on the CPU)
     * @return the new control
     * @throws IllegalArgumentException when the model has no SkinningControl or more than one, or
     *                                  the GPU path is asked for a method without shader code
     */
    public static SkinlabSkinningControl replace(Spatial model, SkinningMethod method, Mode mode, AssetManager assets) {
        List<Spatial> holders = new ArrayList<>();
        model.depthFirstTraversal(s -> {
            if (s.getControl(SkinningControl.class) != null) {
                holders.add(s);
            }
        });
        if (holders.size() != 1) {
            throw new IllegalArgumentException("model '" + model.getName() + "' has " + holders.size()
                    + " SkinningControls; replace() handles exactly one (construct the control yourself for more)");
        }
        Spatial holder = holders.get(0);
        SkinningControl jme = holder.getControl(SkinningControl.class);
        List<Mesh> meshes = Arrays.asList(jme.getTargets());
        List<Geometry> geometries = new ArrayList<>();
        holder.depthFirstTraversal(s -> {
            if (s instanceof Geometry && meshes.contains(((Geometry) s).getMesh())) {
                geometries.add((Geometry) s);
            }
        });
        // glTF's (and skinlab's) joint matrices are products of the nodes' TRS matrices; jME's default
        // SeparateJointModelTransform composes transforms instead, which differs under a parent's
        // non-uniform scale (the tentacle's joints by 16% of its size).
        jme.getArmature().setModelTransformClass(MatrixJointModelTransform.class);
        SkinlabSkinningControl control = new SkinlabSkinningControl(jme.getArmature(), geometries, method, mode, assets);
        holder.removeControl(jme);
        holder.addControl(control);
        return control;
    }

    /**
     * A control skinning {@code geometries} by {@code armature}'s joints. Bind-time work (CoR's
     * centres when the meshes do not carry them): construct it where the model is loaded.
     *
     * @param armature   the armature whose skinning matrices deform the meshes
     * @param geometries the skinned geometries (BindPosePosition or Position, BoneIndex, BoneWeight)
     * @param method     the skinning method
     * @param mode       CPU or GPU
     * @param assets     the asset manager, for the GPU path's material (may be null on the CPU)
     */
    public SkinlabSkinningControl(Armature armature, List<Geometry> geometries, SkinningMethod method, Mode mode,
            AssetManager assets) {
        if (mode == Mode.GPU && !SkinningGlsl.hasCode(method)) {
            throw new IllegalArgumentException(method.key() + " has no shader code: use Mode.CPU");
        }
        this.armature = new ArmaturePalette(armature);
        this.method = method;
        this.mode = mode;
        if (mode == Mode.GPU) {
            SkinlabShaderLoader.register(assets);
        }
        targets = new Target[geometries.size()];
        for (int i = 0; i < targets.length; i++) {
            Geometry g = geometries.get(i);
            SkinnedGeometry skinned = MeshBinding.bind(g, this.armature, method);
            if (mode == Mode.CPU) {
                prepareCpu(g.getMesh());
                targets[i] = new Target(g, skinned, Skinners.create(method, skinned, NormalTransform.INVERSE_TRANSPOSE),
                        null, null);
            } else {
                PaletteTexture texture = new PaletteTexture(this.armature.jointCount());
                Material material = gpuMaterial(assets, g, skinned, texture);
                g.setMaterial(material);
                targets[i] = new Target(g, skinned, null, texture, material);
            }
        }
    }

    /** The skinning method. */
    public SkinningMethod method() {
        return method;
    }

    /** Where the meshes are deformed. */
    public Mode mode() {
        return mode;
    }

    /** The deformed geometries, in the order they were given. */
    public List<Geometry> geometries() {
        List<Geometry> list = new ArrayList<>();
        for (Target t : targets) {
            list.add(t.geometry);
        }
        return list;
    }

    /** The Position and Normal buffers get rewritten each frame from the bind buffers. */
    private static void prepareCpu(Mesh mesh) {
        for (Type type : new Type[] {Type.Position, Type.Normal}) {
            VertexBuffer b = mesh.getBuffer(type);
            if (b != null) {
                b.setUsage(VertexBuffer.Usage.Stream);
            }
        }
    }

    /**
     * The GPU material of {@code g}: its glTF base colour kept; the influences in the HWBoneIndex
     * and HWBoneWeight buffers (palette order, heaviest first), CoR's centres in
     * {@link MeshBinding#CENTRES}.
     */
    private Material gpuMaterial(AssetManager assets, Geometry g, SkinnedGeometry skinned, PaletteTexture texture) {
        Mesh mesh = g.getMesh();
        int k = skinned.influencesPerPoint();
        int vertices = skinned.pointCount();
        float[] joints = new float[4 * vertices];
        float[] weights = new float[4 * vertices];
        int[] j = skinned.jointArray();
        float[] w = skinned.weightArray();
        for (int v = 0; v < vertices; v++) {
            for (int s = 0; s < k; s++) {
                // Palette indices as floats: exact up to 2^24 joints, and an ordinary float attribute.
                joints[4 * v + s] = j[k * v + s];
                weights[4 * v + s] = w[k * v + s];
            }
        }
        mesh.clearBuffer(Type.HWBoneIndex);
        mesh.clearBuffer(Type.HWBoneWeight);
        mesh.setBuffer(Type.HWBoneIndex, 4, joints);
        mesh.setBuffer(Type.HWBoneWeight, 4, weights);
        mesh.getBuffer(Type.HWBoneIndex).setUsage(VertexBuffer.Usage.Static);
        mesh.getBuffer(Type.HWBoneWeight).setUsage(VertexBuffer.Usage.Static);
        Material m = new Material(assets, MATERIAL);
        m.setTexture("Palette", texture.texture());
        m.setInt("Method", SkinningGlsl.methodCode(method));
        m.setInt("Influences", k);
        m.setBoolean("HasScale", false);
        m.setBoolean("MatricesMirror", false);
        m.setBoolean("ScalesMirror", false);
        m.setBoolean("HasCentres", method == SkinningMethod.COR);
        Material old = g.getMaterial();
        if (old != null && old.getParam("BaseColor") != null && old.getParam("BaseColor").getValue() instanceof ColorRGBA) {
            m.setColor("BaseColor", (ColorRGBA) old.getParam("BaseColor").getValue());
        } else if (old != null && old.getParam("Diffuse") != null && old.getParam("Diffuse").getValue() instanceof ColorRGBA) {
            m.setColor("BaseColor", (ColorRGBA) old.getParam("Diffuse").getValue());
        }
        if (old != null) {
            m.getAdditionalRenderState().setFaceCullMode(old.getAdditionalRenderState().getFaceCullMode());
        }
        return m;
    }

    @Override
    protected void controlUpdate(float tpf) {
        // What jME's SkinningControl does here: the joints' model transforms from this frame's locals
        // (the AnimComposer, added before this control, has set them). Skinning here rather than in
        // controlRender: once per frame however many viewports draw it, and before the scene's
        // geometric update, so the new bounds are legal.
        armature.armature().update();
        for (Target t : targets) {
            armature.fill(t.palette);
            t.palette.prepare(method);
            if (mode == Mode.CPU) {
                skinOnCpu(t);
            } else {
                t.texture.fill(t.palette, method.usesBones());
                t.material.setBoolean("HasScale", t.palette.hasScale());
                t.material.setBoolean("MatricesMirror", t.palette.mirrorsMatrices());
                t.material.setBoolean("ScalesMirror", t.palette.mirrorsScales());
            }
        }
    }

    @Override
    protected void controlRender(RenderManager rm, ViewPort vp) {
        // Everything happened in controlUpdate.
    }

    private void skinOnCpu(Target t) {
        t.skinner.skinAll(t.palette, t.positions, t.normals);
        Mesh mesh = t.geometry.getMesh();
        write(mesh.getBuffer(Type.Position), t.positions);
        VertexBuffer normals = mesh.getBuffer(Type.Normal);
        if (normals != null) {
            normalize(t.normals);
            write(normals, t.normals);
        }
        mesh.updateBound();
        t.geometry.updateModelBound();
    }

    private static void write(VertexBuffer buffer, float[] values) {
        FloatBuffer data = (FloatBuffer) buffer.getData();
        data.clear();
        data.put(values, 0, Math.min(values.length, data.capacity()));
        data.clear();
        buffer.updateData(data);
    }

    /** skinlab's kernels leave normals unnormalised (the cofactor); jME's shaders expect unit ones. */
    private static void normalize(float[] n) {
        for (int i = 0; i < n.length; i += 3) {
            float len = (float) Math.sqrt(n[i] * n[i] + n[i + 1] * n[i + 1] + n[i + 2] * n[i + 2]);
            if (len > 0) {
                n[i] /= len;
                n[i + 1] /= len;
                n[i + 2] /= len;
            }
        }
    }
}
