package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * {@link ArCamera}: a marker corner pushed through the OpenGL matrices lands on the pixel the
 * pinhole model gives (tolerance 1e-3 px: float matrices, coordinates of a few hundred pixels), in
 * every viewport layout; and end to end, through the tracker on a rendered frame, on the detected
 * corner (0.2 px, the tracker's own corner accuracy, FiducialTrackerTest).
 */
class ArCameraTest {
    static final CameraIntrinsics K = new CameraIntrinsics(640, 480, 610, 590, 322.3, 236.8);

    /** Window pixel (x right, y down, pixel centres at integers) of a marker point through GL's pipeline. */
    private static double[] toWindow(Matrix4f projection, Matrix4f modelView, double mx, double my, int vw, int vh) {
        Vector4f p = new Vector4f((float) mx, (float) my, 0, 1);
        modelView.transform(p);
        projection.transform(p);
        double ndcX = p.x / p.w;
        double ndcY = p.y / p.w;
        return new double[] {(ndcX + 1) / 2 * vw - 0.5, (1 - ndcY) / 2 * vh - 0.5};
    }

    private static double[] pinhole(double[] r, double[] t, double mx, double my) {
        double x = r[0] * mx + r[1] * my + t[0];
        double y = r[3] * mx + r[4] * my + t[1];
        double z = r[6] * mx + r[7] * my + t[2];
        return new double[] {K.fx() * x / z + K.cx(), K.fy() * y / z + K.cy()};
    }

    @Test
    void cornersLandOnTheirPinholePixels() {
        double[] r = PlacedMarker.facingCamera(25, -30, 40);
        double[] t = {0.04, -0.03, 0.6};
        Matrix4f projection = ArCamera.projection(K, 0.01f, 10f, new Matrix4f());
        Matrix4f modelView = ArCamera.markerModelView(r, t, new Matrix4f());
        for (double[] c : new double[][] {{-0.05, 0.05}, {0.05, 0.05}, {0.05, -0.05}, {-0.05, -0.05}, {0, 0}}) {
            double[] gl = toWindow(projection, modelView, c[0], c[1], K.width(), K.height());
            double[] pin = pinhole(r, t, c[0], c[1]);
            assertEquals(pin[0], gl[0], 1e-3, "x of " + c[0] + "," + c[1]);
            assertEquals(pin[1], gl[1], 1e-3, "y of " + c[0] + "," + c[1]);
        }
    }

    @Test
    void turnedAndScaledViewportsKeepTheModelOnTheImage() {
        // The background's image point (u, v) goes through the same 2-D map as the projection; so a
        // marker point and the image pixel under it meet in the viewport for every layout.
        double[] r = PlacedMarker.facingCamera(10, 20, -15);
        double[] t = {-0.02, 0.05, 0.5};
        Matrix4f modelView = ArCamera.markerModelView(r, t, new Matrix4f());
        int[][] viewports = {{1080, 1920}, {1920, 1080}, {800, 800}, {640, 480}};
        for (int[] v : viewports) {
            for (int rotation : new int[] {0, 90, 180, 270}) {
                for (boolean fit : new boolean[] {false, true}) {
                    Matrix4f projection = ArCamera.projection(K, 0.01f, 10f, v[0], v[1], rotation, fit, new Matrix4f());
                    Matrix4f map = ArCamera.imageToViewport(K.width(), K.height(), v[0], v[1], rotation, fit,
                            new Matrix4f());
                    double[] pin = pinhole(r, t, 0.05, 0.05);
                    // The image pixel in NDC of the unturned image, then through the map.
                    Vector4f bg = new Vector4f((float) (2 * (pin[0] + 0.5) / K.width() - 1),
                            (float) (1 - 2 * (pin[1] + 0.5) / K.height()), 0, 1);
                    map.transform(bg);
                    double[] gl = toWindow(projection, modelView, 0.05, 0.05, v[0], v[1]);
                    double bgX = (bg.x + 1) / 2 * v[0] - 0.5;
                    double bgY = (1 - bg.y) / 2 * v[1] - 0.5;
                    String where = v[0] + "x" + v[1] + " rotation " + rotation + (fit ? " fit" : " fill");
                    assertEquals(bgX, gl[0], 2e-3, where);
                    assertEquals(bgY, gl[1], 2e-3, where);
                }
            }
        }
    }

    @Test
    void fillCoversTheViewportAndFitShowsTheWholeImage() {
        // A 640x480 image turned upright (90) in a 1080x1920 portrait viewport.
        Matrix4f fill = ArCamera.imageToViewport(640, 480, 1080, 1920, 90, false, new Matrix4f());
        Matrix4f fit = ArCamera.imageToViewport(640, 480, 1080, 1920, 90, true, new Matrix4f());
        Vector4f corner = new Vector4f(1, 1, 0, 1);
        fill.transform(corner);
        assertTrue(Math.abs(corner.x) >= 1 - 1e-6 && Math.abs(corner.y) >= 1 - 1e-6, "fill: a corner at or beyond the edge");
        corner.set(1, 1, 0, 1);
        fit.transform(corner);
        assertTrue(Math.abs(corner.x) <= 1 + 1e-6 && Math.abs(corner.y) <= 1 + 1e-6, "fit: inside");
        assertTrue(Math.abs(Math.abs(corner.x) - 1) < 1e-6 || Math.abs(Math.abs(corner.y) - 1) < 1e-6, "fit: touches");
        assertThrows(IllegalArgumentException.class,
                () -> ArCamera.imageToViewport(640, 480, 100, 100, 45, false, new Matrix4f()));
    }

    @Test
    void aTrackedMarkersCornersProjectOntoTheDetectedOnes() {
        SyntheticCamera camera = new SyntheticCamera(K);
        PlacedMarker m = PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, 11), 0.1,
                PlacedMarker.facingCamera(20, 15, 30), new double[] {0.03, 0.02, 0.45});
        List<MarkerDetection> found = new FiducialTracker(TrackerConfig.defaults(0.1), K)
                .detect(camera.render(List.of(m), SceneOptions.clean(4)));
        assertEquals(1, found.size());
        MarkerDetection d = found.get(0);
        Matrix4f projection = ArCamera.projection(K, 0.01f, 10f, new Matrix4f());
        Matrix4f modelView = ArCamera.markerModelView(d.rotation(), d.translation(), new Matrix4f());
        double[][] corners = {{-0.05, 0.05}, {0.05, 0.05}, {0.05, -0.05}, {-0.05, -0.05}};
        for (int i = 0; i < 4; i++) {
            double[] gl = toWindow(projection, modelView, corners[i][0], corners[i][1], K.width(), K.height());
            assertEquals(d.cornerX(i), gl[0], 0.2, "corner " + i + " x");
            assertEquals(d.cornerY(i), gl[1], 0.2, "corner " + i + " y");
        }
    }
}
