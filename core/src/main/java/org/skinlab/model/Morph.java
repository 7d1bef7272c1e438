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
 * Target position {@code p} pairs with base position {@code p}; a target with more positions than
 * the base contributes its first ones (the importer says so).
 *
 * <p><b>Normals</b> are morphed by the same formula, per vertex, then renormalised, when the base
 * and every target have normals for the same vertices ({@link #morphsNormals()}: for RELATIVE,
 * glTF's, the targets' normals are offsets, zero where a target moves none; for NORMALIZED,
 * COLLADA's, each target geometry's own normals, used when its vertices pair with the base's, as
 * the same exporter writes them); otherwise the base's normals are kept. Colours and texture
 * coordinates are always the base's.
 */
public final class Morph {
    /** How targets combine with the base. */
    public enum Method {
        /** Targets are whole shapes; the base gets weight 1 - &Sigma; w<sub>i</sub> (COLLADA's default). */
        NORMALIZED,
        /** Targets are offsets added to the base, which keeps weight 1 (glTF's morph targets). */
        RELATIVE
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
    /** Per target its normals, or null when normals are not morphed. */
    private final float[][] targetNormals;
    private final float[] baseNormals;

    /**
     * @param controllerId the controller's id, also the id of {@link #result()} (for glTF, a JSON path ending
     *                     in {@code /weights})
     * @param name         the controller's name, or null
     * @param base         the mesh being morphed (a geometry's, or another morph's result)
     * @param method       how the targets combine with the base
     * @param targets      meshes with at least as many positions as the base
     * @param weights      one per target
     * @throws IllegalArgumentException when there is not one weight per target, or a target has fewer positions
     *         than the base
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
        this.targetNormals = normalsPairUp(base, this.targets) ? new float[targetPositions.length][] : null;
        this.baseNormals = targetNormals == null ? null : base.normals();
        for (int t = 0; targetNormals != null && t < targetNormals.length; t++) {
            targetNormals[t] = this.targets.get(t).normals();
        }
        float[] positions = new float[3 * base.positionCount()];
        apply(this.weights, positions);
        float[] normals = targetNormals == null ? base.normals() : new float[baseNormals.length];
        if (targetNormals != null) {
            applyNormals(this.weights, normals);
        }
        this.result = base.withPositionsAndNormals(controllerId, name, positions, normals);
    }

    private static boolean normalsPairUp(Mesh base, List<Mesh> targets) {
        if (!base.hasNormals() || targets.isEmpty()) {
            return false;
        }
        for (Mesh t : targets) {
            if (!t.hasNormals() || t.vertexCount() != base.vertexCount()) {
                return false;
            }
        }
        return true;
    }

    /**
     * Whether normals are morphed too (see the class comment); else they are the base's.
     *
     * @return true when the base and every target have normals for the same vertices
     */
    public boolean morphsNormals() {
        return targetNormals != null;
    }

    /**
     * The controller's id: also the id of {@link #result()}.
     *
     * @return the id (for glTF, a JSON path ending in {@code /weights})
     */
    public String controllerId() {
        return controllerId;
    }

    /**
     * The controller's name, or null.
     *
     * @return the name (for glTF, the mesh's), or null when the file gives none
     */
    public String name() {
        return name;
    }

    /**
     * The mesh being morphed.
     *
     * @return the base: a geometry's mesh, or another morph's result
     */
    public Mesh base() {
        return base;
    }

    /**
     * How the targets combine with the base.
     *
     * @return the method
     */
    public Method method() {
        return method;
    }

    /**
     * The target meshes, in file order, each with at least as many positions as the base.
     *
     * @return an unmodifiable list, one mesh per weight
     */
    public List<Mesh> targets() {
        return targets;
    }

    /**
     * A copy of the file's weights, one per target.
     *
     * @return a new array, in target order
     */
    public float[] weights() {
        return weights.clone();
    }

    /**
     * The base morphed with the file's weights.
     *
     * @return the morphed mesh, with the base's topology, colours and texture coordinates, the id
     *         {@link #controllerId()} and the name {@link #name()}
     */
    public Mesh result() {
        return result;
    }

    /**
     * Writes the base's positions morphed with the given weights (one per target) into
     * {@code dest} (3 floats per base position), computed in double and rounded once; allocates
     * nothing, so animated weights can be applied per frame.
     *
     * @param w    one weight per target, in target order
     * @param dest receives x, y, z of each base position from index 0; entries past them are left as they are
     * @throws IllegalArgumentException when {@code w} does not hold one weight per target, or {@code dest} is
     *         shorter than 3 floats per base position
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

    /**
     * Writes the base's normals morphed with the given weights (one per target) and renormalised
     * into {@code dest} (3 floats per base vertex); a normal that morphs to zero stays zero.
     * Allocates nothing.
     *
     * @param w    one weight per target, in target order
     * @param dest receives x, y, z of each base vertex's normal from index 0, unit length or zero; entries past
     *             them are left as they are
     * @throws IllegalStateException when normals are not morphed ({@link #morphsNormals()})
     * @throws IllegalArgumentException when {@code w} does not hold one weight per target, or {@code dest} is
     *         shorter than 3 floats per base vertex
     */
    public void applyNormals(float[] w, float[] dest) {
        if (targetNormals == null) {
            throw new IllegalStateException(this + " does not morph normals");
        }
        if (w.length != targets.size() || dest.length < baseNormals.length) {
            throw new IllegalArgumentException("need " + targets.size() + " weights and room for "
                    + baseNormals.length / 3 + " normals");
        }
        double baseWeight = 1.0;
        if (method == Method.NORMALIZED) {
            for (float x : w) {
                baseWeight -= x;
            }
        }
        for (int i = 0, n = baseNormals.length; i < n; i += 3) {
            double x = baseWeight * baseNormals[i];
            double y = baseWeight * baseNormals[i + 1];
            double z = baseWeight * baseNormals[i + 2];
            for (int t = 0; t < w.length; t++) {
                float[] tn = targetNormals[t];
                x += w[t] * (double) tn[i];
                y += w[t] * (double) tn[i + 1];
                z += w[t] * (double) tn[i + 2];
            }
            double len = Math.sqrt(x * x + y * y + z * z);
            double inv = len > 0 ? 1 / len : 0;
            dest[i] = (float) (x * inv);
            dest[i + 1] = (float) (y * inv);
            dest[i + 2] = (float) (z * inv);
        }
    }

    @Override
    public String toString() {
        return "Morph[" + controllerId + ", " + method + ", " + targets.size() + " targets of " + base.id() + "]";
    }
}
