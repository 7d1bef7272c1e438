package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.testing.TestPaths;

/**
 * {@link MarkerScene} and {@link CameraFollow}, hand-derived cases (tolerance 1e-5 m: float
 * matrices on values below 1) and the default character standing on a 10 cm marker.
 */
class MarkerSceneTest {
    /** A model already upright in Y-up metres, 2 m tall, feet on the floor: upright = identity. */
    private static final ModelFraming Y_UP_TWO_METRES = new ModelFraming(new Matrix4f(), new Vector3f(0, 1, 0), 1.2f,
            2f);

    private static Vector3f place(MarkerScene scene, ModelFraming framing, double yaw, float x, float y, float z) {
        return scene.modelToMarker(framing, yaw, new Matrix4f()).transformPosition(new Vector3f(x, y, z));
    }

    @Test
    void feetOnTheMarkerHeadUpTheNormalFrontTowardTheBottomEdge() {
        MarkerScene scene = new MarkerScene(0.1);
        assertEquals(0.15, scene.modelHeightMetres(), 1e-12);
        Vector3f feet = place(scene, Y_UP_TWO_METRES, 0, 0, 0, 0);
        assertEquals(0, feet.length(), 1e-6);
        Vector3f head = place(scene, Y_UP_TWO_METRES, 0, 0, 2, 0);
        assertEquals(0, head.x, 1e-6);
        assertEquals(0, head.y, 1e-6);
        assertEquals(0.15, head.z, 1e-5);
        Vector3f nose = place(scene, Y_UP_TWO_METRES, 0, 0, 0, 1);
        assertEquals(0, nose.x, 1e-6);
        assertEquals(-0.075, nose.y, 1e-5, "the front (+z of the Y-up model) faces the marker's bottom edge");
        // A quarter turn of yaw turns the front from -y to +x.
        Vector3f turned = place(scene, Y_UP_TWO_METRES, Math.PI / 2, 0, 0, 1);
        assertEquals(0.075, turned.x, 1e-5);
        assertEquals(0, turned.y, 1e-5);
    }

    @Test
    void theDefaultCharacterStandsOnTheMarker() throws Exception {
        // A Z-up Blender file; every posed vertex must lie between the marker plane and 15 cm above it.
        Model model = ColladaImporter.read(TestPaths.asset("characters/humanoid-walk.dae"));
        MarkerScene scene = new MarkerScene(0.1);
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model)) {
            mesh.step(0);
            try (Frame f = mesh.acquire()) {
                ModelFraming framing = ModelFraming.of(model.asset(), mesh.geometries(), f);
                Matrix4f toMarker = scene.modelToMarker(framing, 0, new Matrix4f());
                float minZ = Float.POSITIVE_INFINITY;
                float maxZ = Float.NEGATIVE_INFINITY;
                float maxRadius = 0;
                for (int g = 0; g < mesh.geometries().size(); g++) {
                    SkinnedGeometry geometry = mesh.geometries().get(g);
                    float[] posed = f.positions(g);
                    for (int i = 0; i < geometry.vertexCount(); i++) {
                        Vector3f p = toMarker.transformPosition(new Vector3f(posed[3 * i], posed[3 * i + 1],
                                posed[3 * i + 2]));
                        minZ = Math.min(minZ, p.z);
                        maxZ = Math.max(maxZ, p.z);
                        maxRadius = Math.max(maxRadius, (float) Math.hypot(p.x, p.y));
                    }
                }
                assertEquals(0, minZ, 1e-4, "the lowest point on the marker");
                assertEquals(0.15, maxZ, 1e-4, "1.5 marker widths tall");
                assertTrue(maxRadius < 0.1, "within the marker's neighbourhood: " + maxRadius);
            }
        }
    }

    @Test
    void theModelTurnsToFaceTheCamera() {
        // Camera in front of the marker's bottom edge, looking at it from 45 degrees above: yaw 0.
        double[] r = org.skinlab.internal.synthetic.PlacedMarker.facingCamera(-45, 0, 0);
        double[] t = {0, 0, 0.5};
        assertEquals(0, CameraFollow.yawTowardCamera(r, t, 9), 1e-9);
        // The same camera turned about the marker's normal by 90 degrees (marker rotated -90 in the
        // image): the camera now sits off the marker's right (+x) edge, so the front turns to +x.
        double[] turned = org.skinlab.internal.synthetic.PlacedMarker.facingCamera(-45, 0, 0);
        double[] rz = {0, -1, 0, 1, 0, 0, 0, 0, 1}; // Rz(+90): marker frame to the old marker frame
        double[] r2 = multiply(turned, rz);
        double yaw = CameraFollow.yawTowardCamera(r2, t, 9);
        Vector3f front = new MarkerScene(0.1).modelToMarker(Y_UP_TWO_METRES, yaw, new Matrix4f())
                .transformDirection(new Vector3f(0, 0, 1)).normalize();
        double[] c = cameraCentre(r2, t);
        double n = Math.hypot(c[0], c[1]);
        assertEquals(c[0] / n, front.x, 1e-5, "front toward the camera, x");
        assertEquals(c[1] / n, front.y, 1e-5, "front toward the camera, y");
        assertEquals(0, front.z, 1e-5, "up kept");
        // Straight overhead: the yaw is kept.
        assertEquals(1.25, CameraFollow.yawTowardCamera(org.skinlab.internal.synthetic.PlacedMarker.facingCamera(0, 0, 0),
                new double[] {0, 0, 0.5}, 1.25), 0);
        CameraFollow follow = new CameraFollow();
        assertEquals(yaw, follow.update(r2, t), 1e-12);
        assertEquals(yaw, follow.update(org.skinlab.internal.synthetic.PlacedMarker.facingCamera(1, 0, 0), t), 1e-12,
                "1 degree off the normal: still overhead, the last yaw stays");
    }

    @Test
    void placeGivesTheMarkersViewAndTheModelFollowingOrNot() {
        double[] r = multiply(org.skinlab.internal.synthetic.PlacedMarker.facingCamera(-45, 0, 0),
                new double[] {0, -1, 0, 1, 0, 0, 0, 0, 1});
        double[] t = {0.05, -0.02, 0.5};
        ArPose pose = new ArPose(TrackingState.TRACKING, r, t, 0, 1, 1.0, 0L, 1L);
        MarkerScene scene = new MarkerScene(0.1);
        Matrix4f markerView = new Matrix4f();
        Matrix4f model = new Matrix4f();
        scene.place(pose, new CameraFollow(), false, Y_UP_TWO_METRES, markerView, model);
        assertTrue(markerView.equals(pose.markerModelView(new Matrix4f()), 0f));
        assertTrue(model.equals(scene.modelToMarker(Y_UP_TWO_METRES, 0, new Matrix4f()), 0f), "no follow: yaw 0");
        scene.place(pose, new CameraFollow(), true, Y_UP_TWO_METRES, markerView, model);
        double yaw = CameraFollow.yawTowardCamera(r, t, 0);
        assertTrue(Math.abs(yaw) > 1, "the camera is off to the side: " + yaw);
        assertTrue(model.equals(scene.modelToMarker(Y_UP_TWO_METRES, yaw, new Matrix4f()), 1e-6f), "follow: the camera's yaw");
    }

    private static double[] cameraCentre(double[] r, double[] t) {
        return new double[] {-(r[0] * t[0] + r[3] * t[1] + r[6] * t[2]), -(r[1] * t[0] + r[4] * t[1] + r[7] * t[2])};
    }

    private static double[] multiply(double[] a, double[] b) {
        double[] m = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
            }
        }
        return m;
    }
}
