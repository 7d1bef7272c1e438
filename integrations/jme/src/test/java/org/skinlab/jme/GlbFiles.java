package org.skinlab.jme;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import com.jme3.plugins.json.Json;
import com.jme3.plugins.json.JsonArray;
import com.jme3.plugins.json.JsonObject;

/** The glb files the tests run on, and the name of each one's first clip (what skinlab pose plays). */
final class GlbFiles {
    private GlbFiles() {
    }

    /** Every *.glb under {@code dir}, sorted; none when {@code dir} does not exist. */
    static List<Path> under(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            return new ArrayList<>();
        }
        try (Stream<Path> s = Files.walk(dir)) {
            return s.filter(p -> p.toString().endsWith(".glb")).sorted().collect(Collectors.toList());
        }
    }

    /** The name of the file's first animation (glTF's animations[0]). */
    static String firstClip(Path glb) throws IOException {
        ByteBuffer b = ByteBuffer.wrap(Files.readAllBytes(glb)).order(ByteOrder.LITTLE_ENDIAN);
        int length = b.getInt(12);
        JsonObject root = Json.create().parse(new ByteArrayInputStream(b.array(), 20, length));
        JsonArray animations = root.getAsJsonArray("animations");
        if (animations == null || animations.size() == 0) {
            throw new IllegalArgumentException(glb + " has no animation");
        }
        JsonObject first = animations.get(0).getAsJsonObject();
        return first.has("name") ? first.get("name").getAsString() : null;
    }

    /** Whether the file carries skinlab's CoR centres ({@code SKINLAB_skinning} used). */
    static boolean hasCentres(Path glb) throws IOException {
        ByteBuffer b = ByteBuffer.wrap(Files.readAllBytes(glb)).order(ByteOrder.LITTLE_ENDIAN);
        int length = b.getInt(12);
        return new String(b.array(), 20, length, java.nio.charset.StandardCharsets.UTF_8).contains("SKINLAB_skinning");
    }
}
