package org.skinlab.desktop.eval;

/**
 * The AR question "will anyone see the difference?" as a camera: a character
 * {@value #CHARACTER_METRES} m tall standing on the marker, seen from {@value #DISTANCE_METRES} m
 * (from its centre, level with it) by a phone camera of {@value #WIDTH}x{@value #HEIGHT} pixels
 * with a {@value #FOV_DEGREES}-degree horizontal field of view, from {@value #VIEWS} directions
 * around it. A point's position in the scene (Y-up metres) becomes pixels by a pinhole projection;
 * a difference between two methods is the distance between their pixels.
 */
final class PhoneView {
    static final double CHARACTER_METRES = 0.2;
    static final double DISTANCE_METRES = 0.5;
    static final int WIDTH = 1920;
    static final int HEIGHT = 1080;
    static final double FOV_DEGREES = 65;
    /** Directions the camera looks from, evenly around the character. */
    static final int VIEWS = 8;

    /** The focal length in pixels. */
    static final double FOCAL_PIXELS = WIDTH / 2.0 / Math.tan(Math.toRadians(FOV_DEGREES / 2));

    private final double[] centre;
    private final double scale;

    /**
     * The camera for a model whose scene bounds (Y-up metres, at its first pose) are
     * {@code min}..{@code max}: scaled so that its height (y extent) is
     * {@value #CHARACTER_METRES} m, about the bounds' centre.
     */
    PhoneView(double[] min, double[] max) {
        centre = new double[] {(min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2};
        double height = max[1] - min[1];
        scale = height > 0 ? CHARACTER_METRES / height : 1;
    }

    /**
     * The pixels of {@code count} scene points (3 floats each) seen from direction {@code view}
     * (0 to {@link #VIEWS} - 1) into {@code pixels} (2 per point: column, row).
     */
    void project(float[] scene, int count, int view, double[] pixels) {
        double yaw = 2 * Math.PI * view / VIEWS;
        double sin = Math.sin(yaw);
        double cos = Math.cos(yaw);
        for (int i = 0; i < count; i++) {
            double x = scale * (scene[3 * i] - centre[0]);
            double y = scale * (scene[3 * i + 1] - centre[1]);
            double z = scale * (scene[3 * i + 2] - centre[2]);
            // The eye at DISTANCE (sin yaw, 0, cos yaw) looking at the centre: right (cos, 0, -sin).
            double depth = DISTANCE_METRES - (x * sin + z * cos);
            double right = x * cos - z * sin;
            pixels[2 * i] = WIDTH / 2.0 + FOCAL_PIXELS * right / depth;
            pixels[2 * i + 1] = HEIGHT / 2.0 - FOCAL_PIXELS * y / depth;
        }
    }

    /** The largest distance in pixels between the same point in two projections of {@code count} points. */
    static double largestShift(double[] a, double[] b, int count) {
        double max = 0;
        for (int i = 0; i < count; i++) {
            double dx = a[2 * i] - b[2 * i];
            double dy = a[2 * i + 1] - b[2 * i + 1];
            max = Math.max(max, dx * dx + dy * dy);
        }
        return Math.sqrt(max);
    }
}
