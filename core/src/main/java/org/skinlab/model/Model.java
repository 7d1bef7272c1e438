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

    /**
     * A model of the given parts; the lists are copied (and must hold no nulls). Importers build
     * models; see the class comment for what each list holds and in which order.
     *
     * @param source    the file name (or stream name) the model was read from, for messages
     * @param asset     what the document says about its frame and units
     * @param meshes    the geometries' meshes, then the morphs' results
     * @param skins     the skins
     * @param morphs    the morphs
     * @param materials the materials
     * @param images    the images the materials' textures use
     * @param nodes     the scene's nodes in depth-first order, node {@code i} at index {@code i}
     * @param instances the meshes placed in the scene
     * @param clips     the animation clips
     * @param warnings  what the importer tolerated
     * @throws IllegalArgumentException when a node's {@link Node#index()} is not its place in {@code nodes},
     *                                  or a clip's {@link MorphWeightChannel} names no instance, an instance
     *                                  that draws no morph, or more weights than its morph has targets
     * @throws NullPointerException     when a list, or an element of one, is null
     */
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
     *
     * @param instance one of {@link #instances()}
     * @return the morph whose {@link Morph#result()} is the instance's mesh, or empty
     */
    public Optional<Morph> morphOf(MeshInstance instance) {
        return Optional.ofNullable(morphOf(instance, morphs));
    }

    /**
     * Whether some clip animates a morph's weights.
     *
     * @return true when a clip has a {@link AnimationClip#morphWeights()} channel
     */
    public boolean hasMorphWeightAnimation() {
        return clips.stream().anyMatch(c -> !c.morphWeights().isEmpty());
    }

    /**
     * The file name (or stream name) the model was read from.
     *
     * @return the name as given to the importer, for messages
     */
    public String source() {
        return source;
    }

    /**
     * What the document's {@code <asset>} says about its frame and units; the model's coordinates
     * are in that frame, not converted.
     *
     * @return the asset information, never null for an imported model
     */
    public AssetInfo asset() {
        return asset;
    }

    /**
     * The meshes: one per geometry in document order, then one per morph (its result).
     *
     * @return an unmodifiable list
     */
    public List<Mesh> meshes() {
        return meshes;
    }

    /**
     * The skins, one per skin controller.
     *
     * @return an unmodifiable list
     */
    public List<Skin> skins() {
        return skins;
    }

    /**
     * The morphs, one per morph controller of a mesh.
     *
     * @return an unmodifiable list
     */
    public List<Morph> morphs() {
        return morphs;
    }

    /**
     * The materials, one per {@code <material>} (glTF: per material).
     *
     * @return an unmodifiable list
     */
    public List<Material> materials() {
        return materials;
    }

    /**
     * The images the materials' textures use.
     *
     * @return an unmodifiable list
     */
    public List<Image> images() {
        return images;
    }

    /**
     * The instantiated scene's nodes, depth-first: a parent before its children, node {@code i}
     * at index {@code i} ({@link Node#index()}).
     *
     * @return an unmodifiable list, which node, channel and instance indices point into
     */
    public List<Node> nodes() {
        return nodes;
    }

    /**
     * The node at the given index of {@link #nodes()}.
     *
     * @param index the node's index, 0 to {@code nodes().size() - 1}
     * @return the node whose {@link Node#index()} is {@code index}
     * @throws IndexOutOfBoundsException when there is no such node
     */
    public Node node(int index) {
        return nodes.get(index);
    }

    /**
     * The meshes placed in the scene, static or skinned, in scene order.
     *
     * @return an unmodifiable list, which {@link MorphWeightChannel#instance()} indexes
     */
    public List<MeshInstance> instances() {
        return instances;
    }

    /**
     * The animation clips; empty when the file animates nothing.
     *
     * @return an unmodifiable list
     */
    public List<AnimationClip> clips() {
        return clips;
    }

    /**
     * Everything the importer tolerated rather than refused, in the order it met it.
     *
     * @return an unmodifiable list, empty for a clean file
     */
    public List<ImportWarning> warnings() {
        return warnings;
    }

    /**
     * The mesh of the geometry with the given id.
     *
     * @param geometryId the {@link Mesh#id()} looked for (a morph's result has its controller's id); not null
     * @return the first such mesh of {@link #meshes()}, or empty
     */
    public Optional<Mesh> mesh(String geometryId) {
        return meshes.stream().filter(m -> geometryId.equals(m.id())).findFirst();
    }

    /**
     * The first skin that deforms the given mesh.
     *
     * @param mesh one of {@link #meshes()} (compared by identity)
     * @return the first skin of {@link #skins()} whose {@link Skin#mesh()} it is, or empty
     */
    public Optional<Skin> skinOf(Mesh mesh) {
        return skins.stream().filter(s -> s.mesh() == mesh).findFirst();
    }

    /**
     * The first instance that draws the given mesh (scene order).
     *
     * @param mesh one of {@link #meshes()} (compared by identity)
     * @return the first instance of {@link #instances()} whose {@link MeshInstance#mesh()} it is, or empty
     */
    public Optional<MeshInstance> instanceOf(Mesh mesh) {
        return instances.stream().filter(i -> i.mesh() == mesh).findFirst();
    }

    /**
     * What each material symbol of the mesh's primitives (first use first) is drawn with, bound
     * through the first instance that draws the mesh: {@link Material#DEFAULT} for a symbol
     * nothing binds (or when nothing draws the mesh).
     *
     * @param mesh one of {@link #meshes()}
     * @return a new list, one binding per distinct symbol of the mesh's parts; empty when no part names one
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

    /**
     * The clip with the given name.
     *
     * @param name the {@link AnimationClip#name()} looked for; not null
     * @return the first such clip of {@link #clips()}, or empty
     */
    public Optional<AnimationClip> clip(String name) {
        return clips.stream().filter(c -> name.equals(c.name())).findFirst();
    }

    /**
     * The first node with the given id, searching in depth-first order.
     *
     * @param id the {@link Node#id()} looked for; not null
     * @return the first such node of {@link #nodes()} (an instanced library node appears once per instance),
     *         or empty
     */
    public Optional<Node> nodeById(String id) {
        return nodes.stream().filter(n -> id.equals(n.id())).findFirst();
    }
}
