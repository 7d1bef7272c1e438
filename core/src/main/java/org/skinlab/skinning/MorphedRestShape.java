package org.skinlab.skinning;

import java.util.List;

import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Morph;
import org.skinlab.model.Node;

/**
 * The rest shape of a placed mesh whose morph weights animate: its own {@link SkinnedGeometry}
 * (not shared with other characters) whose rest positions are rewritten from the morph before each
 * frame is skinned, so that every kernel that reads positions from the geometry's arrays skins
 * {@code P = B + sum w_i T_i} (COLLADA's NORMALIZED form likewise, {@link Morph#apply}), and its rest
 * normals too when the morph morphs them ({@link Morph#applyNormals}). CoR keeps the centres of
 * rotation of the rest shape (see docs/skinning.md, "Morphs"). Allocation-free per frame.
 */
final class MorphedRestShape {
    private final Morph morph;
    private final SkinnedGeometry geometry;
    /** The same mesh with the file's weights, never rewritten (shared by the characters of a model). */
    private final SkinnedGeometry rest;
    private final float[] meshPositions;
    /** Per point of {@link #geometry}, its mesh position. */
    private final int[] positionOfPoint;
    /** {@link BindSpace#pointTransform}, column-major. */
    private final float[] transform = new float[16];
    /** Its normal matrix (cofactor times the sign of the determinant), column-major; for morphed normals. */
    private final float[] normalTransform = new float[9];
    /** The morphed normals of the mesh's vertices, or null when the morph keeps the base's. */
    private final float[] meshNormals;

    /**
     * @param rest {@code SkinnedGeometry.of(instance, nodes)}, kept unmorphed, with its centres of
     *             rotation when CoR is to skin this shape
     */
    MorphedRestShape(MeshInstance instance, List<Node> nodes, Morph morph, SkinnedGeometry rest) {
        this.morph = morph;
        this.rest = rest;
        SkinnedGeometry own = SkinnedGeometry.of(instance, nodes);
        // CoR's centres stay those of the rest shape, not recomputed per frame (docs/skinning.md).
        this.geometry = rest.hasCentresOfRotation() ? own.withCentresOfRotation(rest.centresOfRotation()) : own;
        this.meshPositions = new float[3 * morph.base().positionCount()];
        this.positionOfPoint = PointLayout.of(instance.mesh()).positionOfPoint;
        Matrix4f m = BindSpace.pointTransform(instance);
        m.get(transform);
        Matrix3f n = m.get3x3(new Matrix3f()).cofactor();
        if (m.determinant3x3() < 0f) {
            n.scale(-1f);
        }
        n.get(normalTransform);
        meshNormals = morph.morphsNormals() ? new float[3 * morph.base().vertexCount()] : null;
    }

    /** The geometry this shape rewrites (its own). */
    SkinnedGeometry geometry() {
        return geometry;
    }

    /** Whether the rest normals morph too (then skinners must read them from the geometry per frame). */
    boolean morphsNormals() {
        return meshNormals != null;
    }

    /** The geometry with the file's weights, which no frame rewrites. */
    SkinnedGeometry rest() {
        return rest;
    }

    /** Rewrites the geometry's rest positions (and those of its shared positions) for these weights. */
    void apply(float[] weights) {
        morph.apply(weights, meshPositions);
        float[] points = geometry.positionArray();
        for (int i = 0; i < positionOfPoint.length; i++) {
            place(3 * positionOfPoint[i], points, 3 * i);
        }
        if (meshNormals != null) {
            morph.applyNormals(weights, meshNormals);
            float[] normals = geometry.normalArray();
            for (int i = 0, n = meshNormals.length; i < n; i += 3) {
                turn(i, normals);
            }
        }
        SkinnedGeometry shared = geometry.sharedPositions();
        if (shared != null) {
            float[] positions = shared.positionArray();
            for (int p = 0, n = positions.length; p < n; p += 3) {
                place(p, positions, p);
            }
        }
    }

    /** Normal {@code i} (of vertex, and point, i / 3) by the normal matrix, renormalised. */
    private void turn(int i, float[] dest) {
        float[] m = normalTransform;
        float x = meshNormals[i];
        float y = meshNormals[i + 1];
        float z = meshNormals[i + 2];
        float nx = m[0] * x + m[3] * y + m[6] * z;
        float ny = m[1] * x + m[4] * y + m[7] * z;
        float nz = m[2] * x + m[5] * y + m[8] * z;
        float len2 = nx * nx + ny * ny + nz * nz;
        float inv = len2 > 0f ? (float) (1.0 / Math.sqrt(len2)) : 0f;
        dest[i] = nx * inv;
        dest[i + 1] = ny * inv;
        dest[i + 2] = nz * inv;
    }

    private void place(int from, float[] dest, int to) {
        float[] m = transform;
        float x = meshPositions[from];
        float y = meshPositions[from + 1];
        float z = meshPositions[from + 2];
        dest[to] = m[0] * x + m[4] * y + m[8] * z + m[12];
        dest[to + 1] = m[1] * x + m[5] * y + m[9] * z + m[13];
        dest[to + 2] = m[2] * x + m[6] * y + m[10] * z + m[14];
    }
}
