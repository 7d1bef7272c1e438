package org.skinlab.model;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * Everything the importer read from one file: immutable, validated, in the document's own frame
 * and units (see {@link AssetInfo}).
 *
 * <ul>
 * <li>{@link #meshes()}: one per {@code <geometry>} with a {@code <mesh>}, in document order,
 *     whether or not anything instantiates it, then one per morph ({@link Morph#result()});</li>
 * <li>{@link #skins()}: one per {@code <controller>} with a {@code <skin>};</li>
 * <li>{@link #morphs()}: one per {@code <controller>} with a {@code <morph>} of a mesh;</li>
 * <li>{@link #materials()}: one per {@code <material>}, and {@link #images()}, those their
 *     textures use;</li>
 * <li>{@link #nodes()}: the instantiated visual scene, depth-first;</li>
 * <li>{@link #instances()}: meshes placed in that scene, static or skinned;</li>
 * <li>{@link #clips()}: animation clips whose channels target scene nodes;</li>
 * <li>{@link #warnings()}: everything the importer tolerated rather than refused.</li>
 * </ul>
 * The list above speaks COLLADA; how glTF 2.0's meshes, skins, morphs and scenes map onto the
 * same lists is in docs/importer.md ("glTF 2.0", "Mapping").
 */
public final class Model {
    private final String source;
    private final AssetInfo asset;
    private final List<Mesh> meshes;
    private final List<Skin> skins;
    private final List<Morph> morphs;
    private final List<Material> materials;
    private final List<Image> images;
    private final List<Node> nodes;
    private final List<MeshInstance> instances;
    private final List<AnimationClip> clips;
    private final List<ImportWarning> warnings;

    public Model(String source, AssetInfo asset, List<Mesh> meshes, List<Skin> skins, List<Morph> morphs,
            List<Material> materials, List<Image> images, List<Node> nodes, List<MeshInstance> instances,
            List<AnimationClip> clips, List<ImportWarning> warnings) {
        for (int i = 0; i < nodes.size(); i++) {
            if (nodes.get(i).index() != i) {
                throw new IllegalArgumentException("node " + i + " has index " + nodes.get(i).index());
            }
        }
        checkMorphWeights(instances, morphs, clips);
        this.source = source;
        this.asset = asset;
        this.meshes = List.copyOf(meshes);
        this.skins = List.copyOf(skins);
        this.morphs = List.copyOf(morphs);
        this.materials = List.copyOf(materials);
        this.images = List.copyOf(images);
        this.nodes = List.copyOf(nodes);
        this.instances = List.copyOf(instances);
        this.clips = List.copyOf(clips);
        this.warnings = List.copyOf(warnings);
    }

    private static void checkMorphWeights(List<MeshInstance> instances, List<Morph> morphs,
            List<AnimationClip> clips) {
        for (AnimationClip clip : clips) {
            for (MorphWeightChannel c : clip.morphWeights()) {
                if (c.instance() >= instances.size()) {
                    throw new IllegalArgumentException(c.target() + ": no mesh instance " + c.instance());
                }
                Morph morph = morphOf(instances.get(c.instance()), morphs);
                if (morph == null) {
                    throw new IllegalArgumentException(c.target() + ": instance " + c.instance() + " draws no morph");
                }
                if (c.weightOffset() + c.weightCount() > morph.targets().size()) {
                    throw new IllegalArgumentException(c.target() + ": weights " + c.weightOffset() + ".."
                            + (c.weightOffset() + c.weightCount() - 1) + " of a morph with " + morph.targets().size()
                            + " targets");
                }
            }
        }
    }

    private static Morph morphOf(MeshInstance instance, List<Morph> morphs) {
        for (Morph m : morphs) {
            if (m.result() == instance.mesh()) {
                return m;
            }
        }
        return null;
    }

    /**
     * The morph whose result the instance draws (and its skin deforms), whose weights a
     * {@link MorphWeightChannel} on the instance animates; empty for an unmorphed mesh.
     */
    public Optional<Morph> morphOf(MeshInstance instance) {
        return Optional.ofNullable(morphOf(instance, morphs));
    }

    /** Whether some clip animates a morph's weights. */
    public boolean hasMorphWeightAnimation() {
        return clips.stream().anyMatch(c -> !c.morphWeights().isEmpty());
    }

    /** The file name (or stream name) the model was read from. */
    public String source() {
        return source;
    }

    public AssetInfo asset() {
        return asset;
    }

    public List<Mesh> meshes() {
        return meshes;
    }

    public List<Skin> skins() {
        return skins;
    }

    public List<Morph> morphs() {
        return morphs;
    }

    public List<Material> materials() {
        return materials;
    }

    public List<Image> images() {
        return images;
    }

    public List<Node> nodes() {
        return nodes;
    }

    public Node node(int index) {
        return nodes.get(index);
    }

    public List<MeshInstance> instances() {
        return instances;
    }

    public List<AnimationClip> clips() {
        return clips;
    }

    public List<ImportWarning> warnings() {
        return warnings;
    }

    /** The mesh of the geometry with the given id. */
    public Optional<Mesh> mesh(String geometryId) {
        return meshes.stream().filter(m -> geometryId.equals(m.id())).findFirst();
    }

    /** The first skin that deforms the given mesh. */
    public Optional<Skin> skinOf(Mesh mesh) {
        return skins.stream().filter(s -> s.mesh() == mesh).findFirst();
    }

    /** The first instance that draws the given mesh (scene order). */
    public Optional<MeshInstance> instanceOf(Mesh mesh) {
        return instances.stream().filter(i -> i.mesh() == mesh).findFirst();
    }

    /**
     * What each material symbol of the mesh's primitives (first use first) is drawn with, bound
     * through the first instance that draws the mesh: {@link Material#DEFAULT} for a symbol
     * nothing binds (or when nothing draws the mesh).
     */
    public List<MaterialBinding> materialsOf(Mesh mesh) {
        Optional<MeshInstance> instance = instanceOf(mesh);
        Set<String> symbols = new LinkedHashSet<>();
        for (MeshPart part : mesh.parts()) {
            if (part.material() != null) {
                symbols.add(part.material());
            }
        }
        List<MaterialBinding> result = new ArrayList<>(symbols.size());
        for (String symbol : symbols) {
            result.add(instance.isPresent() ? instance.get().material(symbol)
                    : new MaterialBinding(symbol, Material.DEFAULT, -1));
        }
        return result;
    }

    /** The clip with the given name. */
    public Optional<AnimationClip> clip(String name) {
        return clips.stream().filter(c -> name.equals(c.name())).findFirst();
    }

    /** The first node with the given id, searching in depth-first order. */
    public Optional<Node> nodeById(String id) {
        return nodes.stream().filter(n -> id.equals(n.id())).findFirst();
    }
}
