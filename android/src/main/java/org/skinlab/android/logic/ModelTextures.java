package org.skinlab.android.logic;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.skinlab.model.Image;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Model;
import org.skinlab.model.Texture;
import org.skinlab.internal.scene.PartMaterial;

/**
 * The decoded pictures of a model's drawn textures (base and emission textures of every part's
 * material), decoded once on the loader thread so that the GL thread only uploads them. The app
 * has no folder beside its bundled models: only pictures embedded in the document (a
 * {@code .glb}'s buffer views, data URIs) are read; an image in a file, one that does not decode
 * or one larger than {@value #MAX_SIDE} pixels a side is left out (its part is drawn in its
 * colour) with one line in {@link #problems()}.
 */
public final class ModelTextures {
    /** Larger pictures are left out: 4096 x 4096 RGBA is already 64 MiB. */
    public static final int MAX_SIDE = 4096;

    /** Decodes a PNG or JPEG (Android's BitmapFactory in the app); null when it cannot. */
    public interface Decoder {
        TexturePixels decode(byte[] encoded);
    }

    /** No textures (a model without any, or before one is loaded). */
    public static final ModelTextures NONE = new ModelTextures(new IdentityHashMap<>(), List.of());

    private final Map<Image, TexturePixels> pixels;
    private final List<String> problems;

    private ModelTextures(Map<Image, TexturePixels> pixels, List<String> problems) {
        this.pixels = pixels;
        this.problems = Collections.unmodifiableList(problems);
    }

    /** Decodes every picture {@code model}'s drawn materials use, each image once. */
    public static ModelTextures decode(Model model, Decoder decoder) {
        Map<Image, TexturePixels> pixels = new IdentityHashMap<>();
        List<String> problems = new ArrayList<>();
        for (MeshInstance instance : model.instances()) {
            for (MeshPart part : instance.mesh().parts()) {
                PartMaterial m = PartMaterial.of(instance, part);
                for (Texture t : new Texture[] {m.baseTexture(), m.emissionTexture()}) {
                    if (t != null && !pixels.containsKey(t.image())) {
                        pixels.put(t.image(), decodeOne(t.image(), decoder, problems));
                    }
                }
            }
        }
        pixels.values().removeIf(p -> p == null);
        return new ModelTextures(pixels, problems);
    }

    private static TexturePixels decodeOne(Image image, Decoder decoder, List<String> problems) {
        String name = image.name() != null ? image.name() : image.id();
        byte[] bytes = image.bytes();
        if (bytes == null) {
            problems.add("texture " + name + ": not embedded in the model (the app reads no files beside it)");
            return null;
        }
        TexturePixels p;
        try {
            p = decoder.decode(bytes);
        } catch (RuntimeException e) {
            p = null;
        }
        if (p == null) {
            problems.add("texture " + name + ": not a picture the phone can decode");
            return null;
        }
        if (p.width() > MAX_SIDE || p.height() > MAX_SIDE) {
            problems.add("texture " + name + ": " + p.width() + "x" + p.height() + " is larger than " + MAX_SIDE
                    + " a side");
            return null;
        }
        return p;
    }

    /** The decoded picture of {@code image}, or null (none, or left out). */
    public TexturePixels of(Image image) {
        return image == null ? null : pixels.get(image);
    }

    /** Pictures decoded. */
    public int count() {
        return pixels.size();
    }

    /** One line per picture left out. */
    public List<String> problems() {
        return problems;
    }
}
