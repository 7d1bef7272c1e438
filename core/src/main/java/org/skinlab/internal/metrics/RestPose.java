package org.skinlab.internal.metrics;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.skinlab.animation.Pose;
import org.skinlab.animation.Skeleton;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * A model's placed parts in its rest pose (every node's transforms as the file writes them, no
 * clip): what the artifact measures compare a pose with ({@link MethodComparison},
 * {@link JointArtifacts}, the viewer's numbers, {@code skinlab compare}). Built once per model,
 * off the frame path; immutable, so any thread may read it.
 *
 * <p><b>The same space as a pose.</b> A part's rest is its points skinned by LBS with the rest
 * pose's skinning matrices, by the same kernel and palette code a pose is skinned with, so that
 * both are in the document's frame and units: node scales, the armature's scale (0.01 in FBX and
 * Sketchfab exports), mirroring nodes and a glTF skin's inverse bind matrices taken against the
 * mesh node all act on the rest exactly as on a pose. (The points themselves are in bind space,
 * the mesh's own units before any of that: measured there, a part under a 0.01 armature keeps a
 * millionth of its volume at rest.) At the rest pose LBS reproduces the rest bit for bit, so every
 * measure is neutral there; the other methods up to their rounding. A part whose rest shape
 * morphs is measured against the shape it had when the rest pose was built.
 *
 * <p><b>The model's volume</b> is the sum of the signed volumes of its counted parts over the sum
 * of their rest volumes' magnitudes, each part against its own rest (a part whose rest volume is
 * negative, because it is mirrored or wound inside out, counts with its sign turned), so big parts
 * weigh as much as they hold. Counted are the skinned parts whose triangles are closed surfaces
 * ({@link ClosedSurfaces}, in the rest pose) that enclose a volume, alone or together with other
 * skinned parts that are open alone (a surface cut into meshes by material: the open parts that
 * share a point form a group, and a closed group counts as one part; an open part that touches
 * the group, a cloak at a boot's rim, opens it). Not counted: open parts, closed parts that
 * enclose no volume (a sheet drawn from both sides), and static parts (placed rigidly by their
 * node, the same for every method). Parts placed twice count twice, as they are drawn twice.
 * Overlapping parts (clothes over a body) add up: the sum is of the parts, not of the space they
 * fill.
 *
 * <p><b>The model's size</b>, which distances are measured against, is the diagonal of the
 * bounding box of every part's render vertices, static ones included, in the rest pose.
 */
public final class RestPose {
    /** What a part contributes to the model's volume. */
    public enum PartVolume {
        /** A skinned part whose triangles are closed surfaces: it has a volume of its own and counts. */
        CLOSED,
        /** Open alone, but closed together with other skinned parts: counts, has no volume of its own. */
        CLOSED_WITH_OTHERS,
        /** A skinned part whose triangles are not closed surfaces: not counted. */
        OPEN,
        /** Closed, but enclosing no volume at rest (a sheet drawn from both sides): not counted. */
        FLAT,
        /** Not skinned: placed rigidly by its node, the same for every method; not counted. */
        STATIC
    }

    /** A rest volume this small against the cube of its bounds' diagonal is no volume. */
    private static final double FLAT = 1e-9;

    private final List<SkinnedGeometry> geometries;
    private final float[][] matrices;
    private final float[][] positions;
    private final int[][] triangles;
    private final PartVolume[] states;
    /** Per part, its signed rest volume when {@link PartVolume#CLOSED}, else NaN. */
    private final double[] volumes;
    /** Per part, +1 or -1 when counted (the sign of its own or its group's rest volume), else 0. */
    private final double[] signs;
    private final double countedVolume;
    private final double size;

    private RestPose(List<SkinnedGeometry> geometries, List<float[]> restMatrices) {
        this.geometries = List.copyOf(geometries);
        int n = geometries.size();
        if (restMatrices.size() != n) {
            throw new IllegalArgumentException(restMatrices.size() + " palettes for " + n + " parts");
        }
        matrices = new float[n][];
        positions = new float[n][];
        triangles = new int[n][];
        states = new PartVolume[n];
        volumes = new double[n];
        signs = new double[n];
        for (int g = 0; g < n; g++) {
            SkinnedGeometry geometry = geometries.get(g);
            JointPalette palette = geometry.newPalette();
            float[] m = restMatrices.get(g);
            if (m.length != palette.matrices().length) {
                throw new IllegalArgumentException("part " + g + ": " + m.length / 12 + " rest matrices for "
                        + geometry.jointCount() + " joints");
            }
            matrices[g] = m.clone();
            System.arraycopy(m, 0, palette.writableMatrices(), 0, m.length);
            positions[g] = new float[3 * geometry.pointCount()];
            Skinners.scalar(SkinningMethod.LBS, geometry, NormalTransform.INVERSE_TRANSPOSE)
                    .skinAll(palette, positions[g], new float[positions[g].length]);
            triangles[g] = geometry.mesh() == null ? new int[0] : geometry.mesh().triangles();
        }
        size = diagonal(positions, geometries);
        countedVolume = classify();
    }

    /** The rest pose of a model's parts ({@link SkinnedModel#geometries()}), whatever pose it holds now. */
    public static RestPose of(SkinnedModel model) {
        return of(model.skeleton(), model.geometries());
    }

    /** The rest pose of parts built from the model whose skeleton is {@code skeleton}. */
    public static RestPose of(Skeleton skeleton, List<SkinnedGeometry> geometries) {
        Pose rest = skeleton.newPose();
        List<float[]> matrices = new ArrayList<>(geometries.size());
        for (SkinnedGeometry g : geometries) {
            float[] m = new float[12 * g.jointCount()];
            skeleton.skinningMatrices(rest, g.jointNodeArray(), g.bindMatrixArray(), m);
            matrices.add(m);
        }
        return new RestPose(geometries, matrices);
    }

    /**
     * Parts whose rest pose is given as skinning matrices (12 floats per palette joint, row-major
     * 3x4, as a {@link JointPalette} holds them), e.g. parts made with
     * {@link SkinnedGeometry#fromArrays}, which have no scene.
     */
    public static RestPose of(List<SkinnedGeometry> geometries, List<float[]> restMatrices) {
        return new RestPose(geometries, restMatrices);
    }

    /** Sorts every part into its {@link PartVolume}; returns the sum of the counted rest volumes' magnitudes. */
    private double classify() {
        int n = geometries.size();
        ClosedSurfaces surfaces = new ClosedSurfaces();
        int[][] corners = new int[n][];
        List<Integer> open = new ArrayList<>();
        double counted = 0;
        for (int g = 0; g < n; g++) {
            volumes[g] = Double.NaN;
            if (!geometries.get(g).isSkinned()) {
                states[g] = PartVolume.STATIC;
                continue;
            }
            corners[g] = surfaces.corners(positions[g], triangles[g]);
            if (!ClosedSurfaces.closed(corners[g])) {
                states[g] = PartVolume.OPEN;
                open.add(g);
                continue;
            }
            double v = ArtifactMetrics.signedVolume(positions[g], triangles[g]);
            if (flat(v, g)) {
                states[g] = PartVolume.FLAT;
                continue;
            }
            states[g] = PartVolume.CLOSED;
            volumes[g] = v;
            signs[g] = Math.signum(v);
            counted += Math.abs(v);
        }
        for (int[] group : groups(open, corners)) {
            int[][] sets = new int[group.length][];
            double v = 0;
            for (int k = 0; k < group.length; k++) {
                sets[k] = corners[group[k]];
                v += ArtifactMetrics.signedVolume(positions[group[k]], triangles[group[k]]);
            }
            if (group.length > 1 && ClosedSurfaces.closed(sets) && !flat(v, group)) {
                for (int g : group) {
                    states[g] = PartVolume.CLOSED_WITH_OTHERS;
                    signs[g] = Math.signum(v);
                }
                counted += Math.abs(v);
            }
        }
        return counted;
    }

    /** The open parts in groups of parts that share a point (union-find over the point ids). */
    private static List<int[]> groups(List<Integer> open, int[][] corners) {
        int[] parent = new int[open.size()];
        Map<Integer, Integer> firstPartAt = new HashMap<>();
        for (int k = 0; k < open.size(); k++) {
            parent[k] = k;
            for (int id : corners[open.get(k)]) {
                Integer other = firstPartAt.putIfAbsent(id, k);
                if (other != null) {
                    parent[root(parent, k)] = root(parent, other);
                }
            }
        }
        Map<Integer, List<Integer>> byRoot = new LinkedHashMap<>();
        for (int k = 0; k < open.size(); k++) {
            byRoot.computeIfAbsent(root(parent, k), r -> new ArrayList<>()).add(open.get(k));
        }
        List<int[]> groups = new ArrayList<>();
        for (List<Integer> members : byRoot.values()) {
            groups.add(members.stream().mapToInt(Integer::intValue).toArray());
        }
        return groups;
    }

    private static int root(int[] parent, int k) {
        while (parent[k] != k) {
            parent[k] = parent[parent[k]];
            k = parent[k];
        }
        return k;
    }

    private boolean flat(double volume, int... parts) {
        float[][] of = new float[parts.length][];
        List<SkinnedGeometry> which = new ArrayList<>();
        for (int k = 0; k < parts.length; k++) {
            of[k] = positions[parts[k]];
            which.add(geometries.get(parts[k]));
        }
        double d = diagonal(of, which);
        return !(Math.abs(volume) > FLAT * d * d * d);
    }

    /** The diagonal of the bounding box of the parts' render vertices; 0 for none. */
    private static double diagonal(float[][] points, List<SkinnedGeometry> parts) {
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int g = 0; g < points.length; g++) {
            for (int i = 0; i < 3 * parts.get(g).vertexCount(); i++) {
                min[i % 3] = Math.min(min[i % 3], points[g][i]);
                max[i % 3] = Math.max(max[i % 3], points[g][i]);
            }
        }
        if (!(min[0] <= max[0])) {
            return 0;
        }
        double dx = max[0] - min[0];
        double dy = max[1] - min[1];
        double dz = max[2] - min[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** The parts, in the order given ({@link SkinnedModel#geometries()} order). */
    public List<SkinnedGeometry> geometries() {
        return geometries;
    }

    /** Part {@code g}'s skinning matrices in the rest pose (12 floats per joint, row-major 3x4). Read-only. */
    public float[] matrices(int g) {
        return matrices[g];
    }

    /** Part {@code g}'s points in the rest pose (3 floats per point, document frame). Read-only. */
    public float[] positions(int g) {
        return positions[g];
    }

    /** The model's size: the diagonal of the rest pose's bounds over every part, in the document's units. */
    public double size() {
        return size;
    }

    /** What part {@code g} contributes to the model's volume. */
    public PartVolume partVolume(int g) {
        return states[g];
    }

    /** Part {@code g}'s signed volume in the rest pose when it is {@link PartVolume#CLOSED}, else NaN. */
    public double volume(int g) {
        return volumes[g];
    }

    /** Whether the model has a volume: some part counts. */
    public boolean hasVolume() {
        return countedVolume > 0;
    }

    /**
     * Part {@code g}'s volume in a pose over its rest volume (its points deformed, 3 floats per
     * point); NaN unless the part is {@link PartVolume#CLOSED}.
     */
    public double relativeVolume(int g, float[] posed) {
        return states[g] == PartVolume.CLOSED
                ? ArtifactMetrics.signedVolume(posed, triangles[g]) / volumes[g] : Double.NaN;
    }

    /**
     * The model's volume in a pose over its rest volume (see the class comment); NaN when no part
     * counts. Allocates nothing.
     *
     * @param posed per part, its points deformed (3 floats per point); entries of parts that do
     *              not count are not read and may be null
     */
    public double relativeVolume(float[][] posed) {
        if (!hasVolume()) {
            return Double.NaN;
        }
        double sum = 0;
        for (int g = 0; g < signs.length; g++) {
            if (signs[g] != 0) {
                sum += signs[g] * ArtifactMetrics.signedVolume(posed[g], triangles[g]);
            }
        }
        return sum / countedVolume;
    }

    /**
     * Which parts the model's volume holds, or why it has none, in a few words every front end
     * shows after "volume: ": "the mesh is not closed", "3 of 3 skinned parts open", "no skinned
     * part"; "5 of 6 skinned parts (2 closed only together); 1 open: not counted"; empty for a
     * model whose one skinned part counts and that has nothing else.
     */
    public String volumeNote() {
        int[] count = new int[PartVolume.values().length];
        for (PartVolume s : states) {
            count[s.ordinal()]++;
        }
        int together = count[PartVolume.CLOSED_WITH_OTHERS.ordinal()];
        int open = count[PartVolume.OPEN.ordinal()];
        int flat = count[PartVolume.FLAT.ordinal()];
        int stat = count[PartVolume.STATIC.ordinal()];
        int skinned = states.length - stat;
        int counted = skinned - open - flat;
        if (skinned == 0) {
            return "no skinned part";
        }
        if (skinned == 1 && counted == 0) {
            return open == 1 ? "the mesh is not closed" : "the mesh encloses no volume";
        }
        if (counted == 0) {
            String of = " of " + skinned + " skinned parts ";
            return open > 0 ? open + of + "open" + (flat > 0 ? ", " + flat + " enclosing no volume" : "")
                    : flat + of + "enclosing no volume";
        }
        List<String> left = new ArrayList<>();
        if (open > 0) {
            left.add(open + " open");
        }
        if (flat > 0) {
            left.add(flat + " enclosing no volume");
        }
        if (stat > 0) {
            left.add(stat + (stat == 1 ? " static part" : " static parts"));
        }
        String held = skinned == 1 ? "" : counted + " of " + skinned + " skinned parts"
                + (together > 0 ? " (" + together + " closed only together)" : "");
        if (left.isEmpty()) {
            return held;
        }
        return (held.isEmpty() ? "" : held + "; ") + String.join(", ", left) + ": not counted";
    }

    /**
     * Part {@code g}'s {@link PartVolume} in a few words that follow "the part is": why it has no
     * volume of its own ("not closed", "closed only together with other parts", "not skinned"), or
     * "closed".
     */
    public String partNote(int g) {
        switch (states[g]) {
            case CLOSED:
                return "closed";
            case CLOSED_WITH_OTHERS:
                return "closed only together with other parts";
            case OPEN:
                return "not closed";
            case FLAT:
                return "flat (it encloses no volume)";
            default:
                return "not skinned";
        }
    }
}
