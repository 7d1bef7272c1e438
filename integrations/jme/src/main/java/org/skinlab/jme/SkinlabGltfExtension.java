package org.skinlab.jme;

import java.io.IOException;
import java.nio.Buffer;
import java.nio.FloatBuffer;

import com.jme3.asset.AssetLoadException;
import com.jme3.plugins.json.JsonElement;
import com.jme3.plugins.json.JsonObject;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.plugins.gltf.ExtensionLoader;
import com.jme3.scene.plugins.gltf.GltfLoader;
import com.jme3.util.BufferUtils;

/**
 * Reads skinlab's glTF extension {@code SKINLAB_skinning} on a mesh primitive (what
 * {@code skinlab export --methods cor} writes): the vertex attribute it names for CoR (normally
 * {@code _COR_CENTER}, VEC3 FLOAT, one per vertex, the mesh's bind space), which jME's loader
 * would drop as an unknown attribute, is kept in the mesh's {@link MeshBinding#CENTRES} buffer, where
 * the control finds it instead of computing the centres again. Register it before loading:
 * {@code GltfLoader.registerExtension(SkinlabGltfExtension.NAME, SkinlabGltfExtension.class)}
 * ({@link #register()}).
 */
public final class SkinlabGltfExtension implements ExtensionLoader {
    /** The extension's name in the glTF file. */
    public static final String NAME = "SKINLAB_skinning";
    private static final int FLOAT = 5126;

    /** Registers this extension with jME's glTF loader (for every load from now on). */
    public static void register() {
        GltfLoader.registerExtension(NAME, SkinlabGltfExtension.class);
    }

    @Override
    public Object handleExtension(GltfLoader loader, String parentName, JsonElement parent, JsonElement extension,
            Object input) throws IOException {
        if (!"primitive".equals(parentName) || !(input instanceof Mesh)) {
            return input;
        }
        JsonObject ext = extension.getAsJsonObject();
        JsonObject attributeNames = ext.has("attributes") ? ext.getAsJsonObject("attributes") : null;
        if (attributeNames == null || !attributeNames.has("cor")) {
            return input;
        }
        String attribute = attributeNames.get("cor").getAsString();
        JsonObject attributes = parent.getAsJsonObject().getAsJsonObject("attributes");
        String where = loader.getInfo().getKey().getName() + ": primitive's " + NAME + " names attribute " + attribute;
        if (attributes == null || !attributes.has(attribute)) {
            throw new AssetLoadException(where + ", which the primitive does not have");
        }
        int index = attributes.get(attribute).getAsInt();
        JsonObject accessor = loader.getDocRoot().getAsJsonArray("accessors").get(index).getAsJsonObject();
        Mesh mesh = (Mesh) input;
        int count = accessor.get("count").getAsInt();
        if (accessor.get("componentType").getAsInt() != FLOAT || !"VEC3".equals(accessor.get("type").getAsString())
                || count != mesh.getVertexCount() || !accessor.has("bufferView")) {
            throw new AssetLoadException(where + " (accessor " + index + "): expected VEC3 FLOAT with a bufferView, "
                    + mesh.getVertexCount() + " elements");
        }
        int offset = accessor.has("byteOffset") ? accessor.get("byteOffset").getAsInt() : 0;
        Buffer view = loader.viewBuffer(accessor.get("bufferView").getAsInt(), offset, count, 3,
                VertexBuffer.Format.Float, VertexBuffer.Format.Float);
        FloatBuffer source = (FloatBuffer) view;
        FloatBuffer centres = BufferUtils.createFloatBuffer(3 * count);
        for (int i = 0; i < 3 * count; i++) {
            centres.put(source.get(i));
        }
        centres.flip();
        mesh.setBuffer(MeshBinding.CENTRES, 3, centres);
        return mesh;
    }
}
