package org.skinlab.internal.scene;

import org.joml.Matrix4fc;

/**
 * The order blended parts are drawn in: farthest first (painter's order), each part by the
 * distance of its posed centre ({@link PartCentres#posed}) along the view. Parts are few, so an
 * insertion sort into arrays made once; nothing is allocated per frame.
 */
public final class BlendOrder {
    private final int[] geometries;
    private final int[] parts;
    private final float[] depths;
    private int size;

    /** Room for {@code capacity} parts (the model's blended parts). */
    public BlendOrder(int capacity) {
        geometries = new int[capacity];
        parts = new int[capacity];
        depths = new float[capacity];
    }

    public void clear() {
        size = 0;
    }

    /** Adds part {@code part} of geometry {@code geometry} at view distance {@code depth}. */
    public void add(int geometry, int part, float depth) {
        int at = size++;
        while (at > 0 && depths[at - 1] < depth) {
            geometries[at] = geometries[at - 1];
            parts[at] = parts[at - 1];
            depths[at] = depths[at - 1];
            at--;
        }
        geometries[at] = geometry;
        parts[at] = part;
        depths[at] = depth;
    }

    public int size() {
        return size;
    }

    /** The geometry of the k-th part to draw. */
    public int geometry(int k) {
        return geometries[k];
    }

    /** The part index (in its geometry) of the k-th part to draw. */
    public int part(int k) {
        return parts[k];
    }

    /**
     * The clip-space w of posed centre {@code i} in {@code posed} under {@code modelViewProjection}:
     * for a perspective projection, the distance along the view direction.
     */
    public static float distance(Matrix4fc modelViewProjection, float[] posed, int i) {
        Matrix4fc m = modelViewProjection;
        return m.m03() * posed[3 * i] + m.m13() * posed[3 * i + 1] + m.m23() * posed[3 * i + 2] + m.m33();
    }
}
