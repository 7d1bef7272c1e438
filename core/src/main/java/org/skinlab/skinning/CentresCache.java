package org.skinlab.skinning;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;

/**
 * The files of {@link CentresOfRotation}'s cache: {@code HASH.cor}, a header (magic, version,
 * float count) and the centres, little-endian. The name is the SHA-256 of everything the centres
 * depend on, so a changed file or parameter is a different name and a stale entry is never read.
 * Files are written to a temporary name and moved into place, so a reader never sees half a file.
 */
final class CentresCache {
    private static final int MAGIC = 0x534b434f; // "SKCO"
    /** 2: the integration mesh subdivided by weight epsilon (version 1 integrated over the triangles as they were). */
    private static final int VERSION = 2;
    private static final int HEADER = 12;

    private CentresCache() {
    }

    /** The hex SHA-256 of the geometry's positions, triangles, influences and the parameters. */
    static String key(SkinnedGeometry g, CentresOfRotation.Parameters parameters) {
        MessageDigest sha;
        try {
            sha = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("no SHA-256 in this Java", e);
        }
        int[] triangles = g.mesh() == null ? new int[0] : g.mesh().triangles();
        ByteBuffer b = ByteBuffer.allocate(4 * (g.positionArray().length + triangles.length + 2 * g.jointArray().length)
                + 32).order(ByteOrder.LITTLE_ENDIAN);
        b.putInt(VERSION).putInt(g.pointCount()).putInt(g.influencesPerPoint()).putDouble(parameters.sigma())
                .putDouble(parameters.weightEpsilon());
        for (float f : g.positionArray()) {
            b.putFloat(f);
        }
        for (int t : triangles) {
            b.putInt(t);
        }
        for (int j : g.jointArray()) {
            b.putInt(j);
        }
        for (float w : g.weightArray()) {
            b.putFloat(w);
        }
        sha.update(b.array(), 0, b.position());
        StringBuilder hex = new StringBuilder();
        for (byte x : sha.digest()) {
            hex.append(String.format("%02x", x));
        }
        return hex.toString();
    }

    /** The cached centres, or null when absent, unreadable or not {@code floats} long. */
    static float[] load(Path dir, String key, int floats) {
        Path file = dir.resolve(key + ".cor");
        try {
            if (!Files.isRegularFile(file) || Files.size(file) != HEADER + 4L * floats) {
                return null;
            }
            ByteBuffer b = ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
            if (b.getInt() != MAGIC || b.getInt() != VERSION || b.getInt() != floats) {
                return null;
            }
            float[] centres = new float[floats];
            b.asFloatBuffer().get(centres);
            return centres;
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** Stores the centres; failures (read-only folder, full disk) leave the cache as it was. */
    static void store(Path dir, String key, float[] centres) {
        try {
            Files.createDirectories(dir);
            ByteBuffer b = ByteBuffer.allocate(HEADER + 4 * centres.length).order(ByteOrder.LITTLE_ENDIAN);
            b.putInt(MAGIC).putInt(VERSION).putInt(centres.length);
            b.asFloatBuffer().put(centres);
            Path tmp = Files.createTempFile(dir, key, ".tmp");
            try {
                Files.write(tmp, b.array());
                try {
                    Files.move(tmp, dir.resolve(key + ".cor"), StandardCopyOption.ATOMIC_MOVE,
                            StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(tmp, dir.resolve(key + ".cor"), StandardCopyOption.REPLACE_EXISTING);
                }
            } finally {
                Files.deleteIfExists(tmp);
            }
        } catch (IOException | RuntimeException e) {
            // A cache is an optimisation: without it the centres are computed next time.
        }
    }
}
