package org.skinlab.desktop.bench;

import static org.lwjgl.assimp.Assimp.aiGetErrorString;
import static org.lwjgl.assimp.Assimp.aiGetVersionMajor;
import static org.lwjgl.assimp.Assimp.aiGetVersionMinor;
import static org.lwjgl.assimp.Assimp.aiGetVersionPatch;
import static org.lwjgl.assimp.Assimp.aiImportFileFromMemory;
import static org.lwjgl.assimp.Assimp.aiProcess_JoinIdenticalVertices;
import static org.lwjgl.assimp.Assimp.aiProcess_Triangulate;
import static org.lwjgl.assimp.Assimp.aiReleaseImport;

import java.nio.ByteBuffer;

import org.lwjgl.PointerBuffer;
import org.lwjgl.assimp.AIFace;
import org.lwjgl.assimp.AIMesh;
import org.lwjgl.assimp.AIScene;
import org.lwjgl.system.MemoryUtil;

/**
 * assimp (through LWJGL's binding) as a speed baseline for {@code skinlab bench parse
 * --compare-assimp}. Desktop only: core never sees assimp.
 *
 * <p>The default flags, {@link #FAIR_FLAGS}, make assimp do what our importer does: triangulate
 * every polygon and merge corners whose attributes agree into one vertex. Without
 * {@code JoinIdenticalVertices} assimp's COLLADA reader leaves one vertex per triangle corner,
 * which is less work than our importer does and a mesh no renderer would want.
 */
public final class AssimpBaseline implements AutoCloseable {
    /** {@code aiProcess_Triangulate | aiProcess_JoinIdenticalVertices}. */
    public static final int FAIR_FLAGS = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;

    private final ByteBuffer data;
    private final String formatHint;

    /**
     * Copies the file's bytes once into native memory (assimp reads from there every run);
     * {@code fileName}'s extension is assimp's format hint ("dae", "glb", "gltf"), as a file name
     * would give.
     */
    public AssimpBaseline(byte[] bytes, String fileName) {
        data = MemoryUtil.memAlloc(Math.max(1, bytes.length));
        data.put(bytes).flip();
        int dot = fileName.lastIndexOf('.');
        formatHint = dot >= 0 ? fileName.substring(dot + 1).toLowerCase(java.util.Locale.ROOT) : "dae";
    }

    /** The file's size in bytes. */
    public int size() {
        return data.limit();
    }

    /**
     * Loads assimp's native library now, so that a machine without it fails before any
     * measurement. Returns assimp's version, e.g. "5.4.1".
     *
     * @throws IllegalStateException naming the cause when the library cannot be loaded
     */
    public static String loadAndVersion() {
        try {
            return aiGetVersionMajor() + "." + aiGetVersionMinor() + "." + aiGetVersionPatch();
        } catch (LinkageError | RuntimeException e) {
            throw new IllegalStateException("assimp's native library (LWJGL lwjgl-assimp) cannot be loaded here: "
                    + e, e);
        }
    }

    /** The flags as assimp's names, for reports. */
    public static String describe(int flags) {
        if (flags == 0) {
            return "0";
        }
        StringBuilder sb = new StringBuilder();
        int rest = flags;
        if ((rest & aiProcess_Triangulate) != 0) {
            sb.append("aiProcess_Triangulate");
            rest &= ~aiProcess_Triangulate;
        }
        if ((rest & aiProcess_JoinIdenticalVertices) != 0) {
            sb.append(sb.length() > 0 ? " | " : "").append("aiProcess_JoinIdenticalVertices");
            rest &= ~aiProcess_JoinIdenticalVertices;
        }
        if (rest != 0) {
            sb.append(sb.length() > 0 ? " | " : "").append(String.format("0x%x", rest));
        }
        return sb.toString();
    }

    /**
     * Imports the bytes with the given post-processing flags and releases the scene: the timed
     * operation.
     *
     * @throws IllegalArgumentException with assimp's message when it refuses the file
     */
    public void importOnce(int flags) {
        aiReleaseImport(importScene(flags));
    }

    /**
     * Imports once (untimed) and counts the triangles of every mesh: faces with three indices, as
     * assimp also keeps points and lines as faces.
     *
     * @throws IllegalArgumentException with assimp's message when it refuses the file
     */
    public long triangles(int flags) {
        AIScene scene = importScene(flags);
        try {
            long triangles = 0;
            PointerBuffer meshes = scene.mMeshes();
            for (int m = 0; m < scene.mNumMeshes(); m++) {
                AIMesh mesh = AIMesh.create(meshes.get(m));
                long faces = mesh.mFaces().address();
                for (int f = 0; f < mesh.mNumFaces(); f++) {
                    if (AIFace.nmNumIndices(faces + (long) f * AIFace.SIZEOF) == 3) {
                        triangles++;
                    }
                }
            }
            return triangles;
        } finally {
            aiReleaseImport(scene);
        }
    }

    private AIScene importScene(int flags) {
        AIScene scene = aiImportFileFromMemory(data, flags, formatHint);
        if (scene == null) {
            String why = aiGetErrorString();
            throw new IllegalArgumentException(why == null || why.isBlank() ? "assimp returned no scene"
                    : why.replaceAll("\\s+", " ").trim());
        }
        return scene;
    }

    @Override
    public void close() {
        MemoryUtil.memFree(data);
    }
}
