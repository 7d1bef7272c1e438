package org.skinlab.internal.synthetic;

import java.util.List;
import java.util.Random;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;

/**
 * Frames of one marker of known pose for measuring a tracker, deterministic for the caller's
 * {@link Random}: a random code of the dictionary at a given distance and tilt (about a random axis
 * in the marker's plane), turned at random about its normal, every fifth with a disc over the code
 * (radius 0.08 of the marker's width, about 1.3 code cells, its centre within a quarter of the
 * width of the marker's); each frame blurred (sigma 0.5-1.2 px), noisy (sigma 2-5 levels) and lit
 * unevenly (up to 50% falloff).
 *
 * <p>Two placements. {@link #central}: the marker anywhere within 22.5% of its distance of the
 * optical axis across and 15% up or down (its sheet in view at 60 degrees), rendered with 3x3 rays
 * per pixel; {@link #inView}: anywhere its paper stays inside 90% of the image, 2x2 rays. Each draws
 * its random numbers in its own fixed order (the sets the tests were measured with).
 */
public final class MarkerShots {
    /** Every this many frames (on average) has a disc over the code. */
    private static final int OCCLUDED_EVERY = 5;

    private final SyntheticCamera camera;
    private final MarkerDictionary dictionary;
    private final double size;
    private final boolean central;
    private final int supersampling;

    private MarkerShots(CameraIntrinsics k, MarkerDictionary dictionary, double size, boolean central,
            int supersampling) {
        if (!(size > 0)) {
            throw new IllegalArgumentException("marker size " + size);
        }
        this.camera = new SyntheticCamera(k);
        this.dictionary = dictionary;
        this.size = size;
        this.central = central;
        this.supersampling = supersampling;
    }

    /** Markers {@code size} metres wide of {@code dictionary} near the image's middle, 3x3 rays per pixel. */
    public static MarkerShots central(CameraIntrinsics k, MarkerDictionary dictionary, double size) {
        return new MarkerShots(k, dictionary, size, true, 3);
    }

    /** Markers {@code size} metres wide of the default dictionary anywhere in view, 2x2 rays per pixel. */
    public static MarkerShots inView(CameraIntrinsics k, double size) {
        return new MarkerShots(k, MarkerDictionary.DEFAULT, size, false, 2);
    }

    public SyntheticCamera camera() {
        return camera;
    }

    public double markerSize() {
        return size;
    }

    /** One frame at a distance and a tilt drawn uniformly from the ranges (metres, degrees). */
    public MarkerShot shot(Random random, double minDistance, double maxDistance, double minTilt, double maxTilt) {
        double d = minDistance + (maxDistance - minDistance) * random.nextDouble();
        double tilt = minTilt + (maxTilt - minTilt) * random.nextDouble();
        return shot(random, d, tilt);
    }

    /** One frame of a marker {@code distance} metres away, tilted {@code tilt} degrees. */
    public MarkerShot shot(Random random, double distance, double tilt) {
        PlacedMarker m = marker(random, distance, tilt);
        return new MarkerShot(camera.render(List.of(m), degradation(random)), m, tilt);
    }

    /** The marker of one frame: its code, pose and occluder (the random numbers {@link #shot} draws first). */
    public PlacedMarker marker(Random random, double distance, double tilt) {
        int id = central ? random.nextInt(dictionary.codeCount()) : -1;
        double axis = random.nextDouble() * 2 * Math.PI;
        double[] r = PlacedMarker.facingCamera(tilt * Math.cos(axis), tilt * Math.sin(axis), random.nextDouble() * 360);
        double x;
        double y;
        if (central) {
            x = (random.nextDouble() - 0.5) * 0.45 * distance;
            y = (random.nextDouble() - 0.5) * 0.3 * distance;
        } else {
            // The paper reaches 0.8 of the marker's width beyond its centre.
            CameraIntrinsics k = camera.intrinsics();
            double hw = 0.9 * k.width() / 2 / k.fx() * distance - 0.8 * size;
            double hh = 0.9 * k.height() / 2 / k.fy() * distance - 0.8 * size;
            x = (2 * random.nextDouble() - 1) * hw;
            y = (2 * random.nextDouble() - 1) * hh;
            id = random.nextInt(dictionary.codeCount());
        }
        PlacedMarker m = PlacedMarker.of(MarkerPattern.of(dictionary, id), size, r, new double[] {x, y, distance});
        if (random.nextInt(OCCLUDED_EVERY) == 0) {
            m = m.occludedBy((random.nextDouble() - 0.5) * 0.5 * size, (random.nextDouble() - 0.5) * 0.5 * size,
                    0.08 * size);
        }
        return m;
    }

    /** One frame's blur, noise and light (the random numbers {@link #shot} draws after the marker's). */
    public SceneOptions degradation(Random random) {
        return new SceneOptions(0.5 + 0.7 * random.nextDouble(), 2 + 3 * random.nextDouble(), 0.5 * random.nextDouble(),
                0, supersampling, random.nextLong());
    }
}
