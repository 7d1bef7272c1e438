package org.skinlab.ar;

import boofcv.abst.fiducial.FiducialDetector;
import boofcv.factory.distort.LensDistortionFactory;
import boofcv.factory.fiducial.ConfigFiducialHammingDetector;
import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.factory.fiducial.FactoryFiducial;
import boofcv.struct.image.GrayU8;
import georegression.struct.se.Se3_F64;

/**
 * BoofCV's own square-marker detector ({@code FactoryFiducial.squareHamming}) with its default
 * settings: the reference {@link FiducialTracker} is measured against (its speed in
 * {@code skinlab bench track} and {@code skinlab eval}, its false markers in the tests and the
 * evaluation). BoofCV accepts a square whose bits are up to the dictionary's minimum Hamming distance
 * from a code ({@code minimumHamming}, 12 of 36 bits for 36h12, charging ambiguous bits half); that
 * cap is what reads codes into clutter, which our rule does not. One instance per thread.
 */
public final class BoofSquareHamming {
    private final FiducialDetector<GrayU8> detector;
    private final GrayU8 gray = new GrayU8(1, 1);

    private BoofSquareHamming(FiducialDetector<GrayU8> detector) {
        this.detector = detector;
    }

    /**
     * BoofCV's default detector for {@code dictionary} seeing markers {@code markerSizeMetres} wide
     * through {@code camera} (its lens, so that {@link #pose} is the marker's pose).
     *
     * @param dictionary       the codes to look for (BoofCV's wrong-bit cap is their minimum distance)
     * @param markerSizeMetres the printed black square's width in metres (the poses' scale)
     * @param camera           the camera whose images {@link #detect} gets, lens included
     * @return a new detector, for one thread
     */
    public static BoofSquareHamming defaults(MarkerDictionary dictionary, double markerSizeMetres,
            CameraIntrinsics camera) {
        ConfigHammingMarker code = dictionary.config();
        code.targetWidth = markerSizeMetres;
        FiducialDetector<GrayU8> d = FactoryFiducial.squareHamming(code, new ConfigFiducialHammingDetector(),
                GrayU8.class);
        d.setLensDistortion(LensDistortionFactory.narrow(BoofCameras.toBoof(camera)), camera.width(),
                camera.height());
        return new BoofSquareHamming(d);
    }

    /**
     * BoofCV's detector for {@code dictionary} with the wrong-bit cap {@code minimumHamming} (the
     * dictionary's own is the default) and no camera: ids only, no pose.
     *
     * @param dictionary     the codes to look for
     * @param minimumHamming BoofCV's cap on a square's wrong bits, 0 to {@code dictionary.minimumHamming()}
     * @return a new detector, for one thread; {@link #pose} is not meaningful with it
     * @throws IllegalArgumentException when the cap is outside that range
     */
    public static BoofSquareHamming capped(MarkerDictionary dictionary, int minimumHamming) {
        if (minimumHamming < 0 || minimumHamming > dictionary.minimumHamming()) {
            throw new IllegalArgumentException("cap " + minimumHamming + " outside 0-" + dictionary.minimumHamming());
        }
        ConfigHammingMarker code = dictionary.config();
        code.minimumHamming = minimumHamming;
        return new BoofSquareHamming(FactoryFiducial.squareHamming(code, new ConfigFiducialHammingDetector(),
                GrayU8.class));
    }

    /**
     * Looks for markers in {@code image}; returns how many were found.
     *
     * @param image the gray image to search (for a detector from {@link #defaults}, of the camera's size); read
     *              during this call only (wrapped, not copied)
     * @return the number of markers found, 0 or more: the range of {@code i} for {@link #id} and {@link #pose}
     */
    public int detect(GrayImage image) {
        gray.data = image.pixels();
        gray.width = image.width();
        gray.height = image.height();
        gray.stride = image.rowStride();
        detector.detect(gray);
        return detector.totalFound();
    }

    /**
     * The id of the {@code i}th marker of the last {@link #detect}.
     *
     * @param i the marker's index, 0 to the count {@link #detect} returned - 1
     * @return the marker's id in the dictionary
     */
    public int id(int i) {
        return (int) detector.getId(i);
    }

    /**
     * The {@code i}th marker's pose (marker to camera) of the last {@link #detect}, with a camera.
     *
     * @param i              the marker's index, 0 to the count {@link #detect} returned - 1
     * @param markerToCamera receives the marker-to-camera transform (BoofCV's marker frame), translation in metres
     */
    public void pose(int i, Se3_F64 markerToCamera) {
        detector.getFiducialToCamera(i, markerToCamera);
    }
}
