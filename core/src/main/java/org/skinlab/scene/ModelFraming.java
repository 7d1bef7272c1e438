package org.skinlab.scene;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Vector3f;
import org.skinlab.model.AssetInfo;
import org.skinlab.simulation.Frame;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * How a file stands in the scene: its up axis and unit turned into Y-up metres
 * ({@link AssetInfo#toYUpMeters}), then moved so that its posed bounds are centred over the origin
 * with the lowest point on the floor (y = 0). Measured once, on the first frame, from the posed
 * points (the bind-space points moved by the frame's skinning matrices), so files whose bind pose
 * is far from their animation still land in view.
 *
 * @param upright the model matrix: document frame to the scene
 * @param centre  the centre of the posed bounds in the scene
 * @param radius  half the bounds' diagonal (the bounding sphere the camera frames), > 0
 * @param height  the bounds' extent along the scene's up axis
 */
public record ModelFraming(Matrix4fc upright, Vector3f centre, float radius, float height) {
    /** The smallest radius a framing reports: a point-like or empty model still gets a camera. */
    public static final float MIN_RADIUS = 1e-3f;

    /**
     * Distance between copies in the instance grid: they never touch.
     *
     * @return the spacing in scene units (metres), 2.2 radii
     */
    public float gridSpacing() {
        return 2.2f * radius;
    }

    /**
     * The bounding sphere of a grid of {@code instances} copies laid out as the skinning shader
     * does (rows of {@code columns} centred on x, going back along -z), into {@code centre};
     * returns its radius.
     *
     * @param instances the number of copies, at least 1
     * @param columns   copies per row, at least 1
     * @param centre    set to the sphere's centre in the scene
     * @return the sphere's radius in scene units (metres)
     */
    public float gridSphere(int instances, int columns, Vector3f centre) {
        int rows = (instances + columns - 1) / columns;
        float halfWidth = 0.5f * (Math.min(instances, columns) - 1) * gridSpacing();
        float depth = (rows - 1) * gridSpacing();
        centre.set(this.centre).add(0, 0, -0.5f * depth);
        return (float) Math.sqrt(radius * radius + halfWidth * halfWidth + 0.25f * depth * depth);
    }

    /**
     * The size the difference view measures against: the bounds' diagonal.
     *
     * @return twice the radius, in scene units (metres)
     */
    public float size() {
        return 2f * radius;
    }

    /**
     * The framing of the geometries posed as {@code frame} poses them.
     *
     * @param asset      the file's up axis and unit ({@link org.skinlab.model.Model#asset()})
     * @param geometries the model's geometries, in the frame's order
     *                   ({@link org.skinlab.simulation.SkeletalAnimatedMesh#geometries()})
     * @param frame      a frame of those geometries: its palettes pose the points measured
     * @return the framing; a model with no finite point gets one at the origin of radius
     *         {@link #MIN_RADIUS}
     */
    public static ModelFraming of(AssetInfo asset, List<SkinnedGeometry> geometries, Frame frame) {
        Matrix4f toScene = asset.toYUpMeters(new Matrix4f());
        Vector3f min = new Vector3f(Float.POSITIVE_INFINITY);
        Vector3f max = new Vector3f(Float.NEGATIVE_INFINITY);
        Vector3f p = new Vector3f();
        for (int g = 0; g < geometries.size(); g++) {
            SkinnedGeometry geometry = geometries.get(g);
            float[] m = frame.palette(g).matrices();
            // A morphing geometry's own array is rewritten by the simulation thread; the frame holds
            // the rest shape its palette goes with.
            float[] points = frame.restPositions(g) != null ? frame.restPositions(g) : geometry.positionArray();
            int[] joints = geometry.jointArray();
            float[] weights = geometry.weightArray();
            int k = geometry.influencesPerPoint();
            for (int i = 0; i < geometry.vertexCount(); i++) {
                float x = points[3 * i];
                float y = points[3 * i + 1];
                float z = points[3 * i + 2];
                float px = 0;
                float py = 0;
                float pz = 0;
                for (int a = 0; a < k; a++) {
                    float w = weights[k * i + a];
                    int o = 12 * joints[k * i + a];
                    px += w * (m[o] * x + m[o + 1] * y + m[o + 2] * z + m[o + 3]);
                    py += w * (m[o + 4] * x + m[o + 5] * y + m[o + 6] * z + m[o + 7]);
                    pz += w * (m[o + 8] * x + m[o + 9] * y + m[o + 10] * z + m[o + 11]);
                }
                toScene.transformPosition(p.set(px, py, pz));
                if (Float.isFinite(p.x) && Float.isFinite(p.y) && Float.isFinite(p.z)) {
                    min.min(p);
                    max.max(p);
                }
            }
        }
        if (!(min.x <= max.x)) {
            min.zero();
            max.zero();
        }
        Vector3f centre = new Vector3f(min).add(max).mul(0.5f);
        float radius = Math.max(MIN_RADIUS, new Vector3f(max).sub(min).length() * 0.5f);
        Matrix4f upright = new Matrix4f().translation(-centre.x, -min.y, -centre.z).mul(toScene);
        Vector3f placedCentre = new Vector3f(0f, centre.y - min.y, 0f);
        return new ModelFraming(upright, placedCentre, radius, max.y - min.y);
    }
}
