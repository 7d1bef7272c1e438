package org.skinlab.model;

import java.util.List;

/**
 * One {@code <controller><morph>}: a base mesh, target meshes of the same positions, and a weight
 * per target. {@link #result()} is the base deformed with the file's weights, the mesh that
 * instances of the controller draw (and that a skin on the morph deforms).
 *
 * <p>COLLADA 1.4.1 (morph): with weights w<sub>i</sub> and target positions T<sub>i</sub>,
 * <ul>
 * <li>{@link Method#NORMALIZED}: P = (1 - &Sigma; w<sub>i</sub>) B + &Sigma; w<sub>i</sub> T<sub>i</sub>;</li>
 * <li>{@link Method#RELATIVE}: P = B + &Sigma; w<sub>i</sub> T<sub>i</sub> (targets are offsets).</li>
 * </ul>
 * Only positions are morphed; normals, colours and texture coordinates are the base's. Target
 * position {@code p} pairs with base position {@code p}; a target with more positions than the
 * base contributes its first ones (the importer says so).
 */
public final class Morph {
    /** How targets combine with the base. */
    public enum Method {
        NORMALIZED, RELATIVE
    }

    private final String controllerId;
    private final String name;
    private final Mesh base;
    private final Method method;
    private final List<Mesh> targets;
    private final float[] weights;
    private final Mesh result;
    private final float[] basePositions;
    private final float[][] targetPositions;

    /**
     * @param base    the mesh being morphed (a geometry's, or another morph's result)
     * @param targets meshes with at least as many positions as the base
     * @param weights one per target
     */
    public Morph(String controllerId, String name, Mesh base, Method method, List<Mesh> targets, float[] weights) {
        if (weights.length != targets.size()) {
            throw new IllegalArgumentException(targets.size() + " targets but " + weights.length + " weights");
        }
        for (Mesh t : targets) {
            if (t.positionCount() < base.positionCount()) {
                throw new IllegalArgumentException("target " + t.id() + " has fewer positions than the base");
            }
        }
        this.controllerId = controllerId;
        this.name = name;
        this.base = base;
        this.method = method;
        this.targets = List.copyOf(targets);
        this.weights = weights.clone();
        this.basePositions = base.positions();
        this.targetPositions = new float[targets.size()][];
        for (int t = 0; t < targetPositions.length; t++) {
            targetPositions[t] = targets.get(t).positions();
        }
        float[] positions = new float[3 * base.positionCount()];
        apply(this.weights, positions);
        this.result = base.withPositions(controllerId, name, positions);
    }

    /** The controller's id: also the id of {@link #result()}. */
    public String controllerId() {
        return controllerId;
    }

    /** The controller's name, or null. */
    public String name() {
        return name;
    }

    public Mesh base() {
        return base;
    }

    public Method method() {
        return method;
    }

    public List<Mesh> targets() {
        return targets;
    }

    /** A copy of the file's weights, one per target. */
    public float[] weights() {
        return weights.clone();
    }

    /** The base morphed with the file's weights. */
    public Mesh result() {
        return result;
    }

    /**
     * Writes the base's positions morphed with the given weights (one per target) into
     * {@code dest} (3 floats per base position), computed in double and rounded once; allocates
     * nothing, so animated weights can be applied per frame.
     */
    public void apply(float[] w, float[] dest) {
        if (w.length != targets.size() || dest.length < 3 * base.positionCount()) {
            throw new IllegalArgumentException("need " + targets.size() + " weights and room for "
                    + base.positionCount() + " positions");
        }
        double baseWeight = 1.0;
        if (method == Method.NORMALIZED) {
            for (float x : w) {
                baseWeight -= x;
            }
        }
        for (int i = 0, n = basePositions.length; i < n; i++) {
            double v = baseWeight * basePositions[i];
            for (int t = 0; t < w.length; t++) {
                v += w[t] * (double) targetPositions[t][i];
            }
            dest[i] = (float) v;
        }
    }

    @Override
    public String toString() {
        return "Morph[" + controllerId + ", " + method + ", " + targets.size() + " targets of " + base.id() + "]";
    }
}
