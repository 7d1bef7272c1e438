package org.skinlab.ar;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import boofcv.alg.distort.LensDistortionNarrowFOV;
import boofcv.concurrency.BoofConcurrency;
import boofcv.alg.fiducial.square.FoundFiducial;
import boofcv.alg.fiducial.square.QuadPoseEstimator;
import boofcv.factory.distort.LensDistortionFactory;
import boofcv.struct.image.GrayU8;
import georegression.struct.se.Se3_F64;
import georegression.struct.shapes.Quadrilateral_F64;

/**
 * Finds square fiducials (BoofCV's {@code squareHamming} detector: ArUco and AprilTag codes) in
 * gray camera images and estimates each one's pose; one instance per thread (it keeps BoofCV's
 * work images between frames).
 *
 * <p><b>Conventions</b> (those of {@link MarkerDetection}): BoofCV places a pixel's centre at
 * (x + 0.5, y + 0.5), ours at (x, y); corners are reported in ours (BoofCV's minus 0.5) and the
 * pose is estimated with BoofCV's camera ({@link BoofCameras}), so pose and corners agree with
 * {@link CameraIntrinsics}. Without that, every pose is off by half a pixel's ray (0.6 mm at
 * 0.6 m for fx = 500).
 *
 * <p><b>Lens distortion.</b> With a distorted camera the corners are where they appear in the
 * image (distorted pixels); the detector fits the square's sides to its undistorted contour and
 * the pose estimator undistorts the corners, so only points are undistorted, never the image.
 *
 * <p><b>False markers.</b> BoofCV accepts a square whose bits are up to the dictionary's minimum
 * Hamming distance away from a code (12 of 36 bits for 36h12), which reads codes into clutter, into
 * other dictionaries' markers and into AprilTags. We read each bit with a confidence and charge a
 * wrong bit what we were sure of it ({@link ConfidentHammingDetector}, limits in
 * {@link TrackerConfig#maxBitErrors()} and {@link TrackerConfig#MAX_UNCERTAIN_BITS}): clutter's bits
 * are crisp, a far, tilted marker's wrong bits are smeared by blur.
 *
 * <p><b>Video.</b> {@link #track} first looks for each marker of the last frame in its own region
 * of the image, where it should be now, and only when one of them is not found there at the whole
 * frame; every {@link #FULL_FRAME_EVERY}th frame it looks at the whole frame anyway, so that markers
 * coming into view are found. One region per marker, not one around all: markers far apart would
 * make one box cover most of the frame. {@link #detect} always looks at the whole frame.
 *
 * <p>Pose: BoofCV's quadrilateral estimator (IPPE's two planar solutions, the better kept, then
 * refined by Gauss-Newton on the four corners). Near face-on both solutions fit almost equally well
 * and one frame's choice may flip; callers that filter over time must not trust a sudden rotation
 * jump there ({@code MarkerTracking}).
 */
public final class FiducialTracker {
    /** In {@link #track}, a whole-frame search at least this often (frames). */
    public static final int FULL_FRAME_EVERY = 30;
    /** A search region is given up for the whole frame when it covers more than this share of it. */
    private static final double REGION_LIMIT = 0.5;
    /** The least room around a marker's predicted bounds in its search region (pixels). */
    private static final double MIN_MARGIN = 24;
    /** How much a marker's outline may shrink or grow between two frames for the region search. */
    private static final double CONTOUR_CHANGE = 1.5;

    private final TrackerConfig config;
    private final CameraIntrinsics intrinsics;
    private final ConfidentHammingDetector detector;
    private final QuadPoseEstimator pose = new QuadPoseEstimator(1e-6, 200);
    private final Quadrilateral_F64 quad = new Quadrilateral_F64();
    private final GrayU8 frame = new GrayU8(1, 1);
    private final GrayU8 region = new GrayU8(1, 1);
    /** The lens shifted to the searched region, or null for a camera without distortion. */
    private final RegionLens regionLens;
    /** Keeps the region searches to contours of about the last markers' size. */
    private final ContourSizeFilter contourSizes = new ContourSizeFilter();
    /** The last frame's markers: how many, their ids, bounds (x0, y0, x1, y1) and motion (dx, dy). */
    private int lastCount;
    private int[] lastIds = new int[4];
    private double[] lastBounds = new double[16];
    /** How far each marker moved since the frame before (pixels), 0 if it was not in that frame. */
    private double[] lastMotion = new double[8];
    /** Spares that {@link #remember} fills and swaps with the last ones. */
    private int[] nextIds = new int[4];
    private double[] nextBounds = new double[16];
    private double[] nextMotion = new double[8];
    private boolean[] matched = new boolean[4];
    /** This frame's search regions (x0, y0, x1, y1), {@link #regionCount} of them. */
    private int[] regions = new int[16];
    private int regionCount;
    /** The contour lengths (pixels) this frame's region searches pass on to the square fitting. */
    private int contourMin;
    private int contourMax;
    private boolean lastFromRegion;
    private int framesSinceFullSearch;

    /**
     * A tracker for one camera; every image it is given must have the camera's size.
     *
     * @param config     what to look for: dictionary, printed size (the poses' scale), target id, bit-error limit and
     *                   whether {@link #track} searches near the last markers first
     * @param intrinsics the camera that takes the images, in the pixel convention of {@link CameraIntrinsics}; with
     *                   a distorted lens the corners are reported where they appear in the image, and the poses
     *                   account for the lens
     */
    public FiducialTracker(TrackerConfig config, CameraIntrinsics intrinsics) {
        this.config = config;
        this.intrinsics = intrinsics;
        this.detector = ConfidentHammingDetector.create(config.dictionary(), config.maxBitErrors(),
                TrackerConfig.MAX_UNCERTAIN_BITS);
        detector.getSquareDetector().setHelper(contourSizes);
        LensDistortionNarrowFOV lens = LensDistortionFactory.narrow(BoofCameras.toBoof(intrinsics));
        if (intrinsics.isDistorted()) {
            // The square's contour is undistorted before its sides are fitted and its bits are read
            // through the lens; the image itself is never remapped. RegionLens keeps the tables per
            // pixel that BoofCV's cache would, and follows the searched region.
            regionLens = new RegionLens(lens, intrinsics.width(), intrinsics.height());
            detector.configure(regionLens, intrinsics.width(), intrinsics.height(), false);
        } else {
            regionLens = null;
        }
        pose.setLensDistoriton(lens);
        double r = config.markerSizeMetres() / 2;
        // TL, TR, BR, BL of the printed marker in its frame (y toward the top edge): BoofCV's corner order.
        pose.setFiducial(-r, r, r, r, r, -r, -r, -r);
    }

    /**
     * Makes BoofCV run on the calling thread alone, process-wide (its {@code BoofConcurrency}
     * switch is global). For video: a region search is too small to be worth sharing out (on a real
     * video the median frame was faster without BoofCV's pool: docs/benchmarks.md), and on a phone
     * the other cores skin and draw.
     */
    public static void runOnCallingThread() {
        BoofConcurrency.USE_CONCURRENT = false;
    }

    /**
     * What this tracker looks for.
     *
     * @return the config it was made with
     */
    public TrackerConfig config() {
        return config;
    }

    /**
     * The camera whose images this tracker reads.
     *
     * @return the intrinsics it was made with; images must be {@code width x height} of these
     */
    public CameraIntrinsics intrinsics() {
        return intrinsics;
    }

    /**
     * Every marker in the whole image (of the target id, if the config names one).
     *
     * <p>Also remembers them as the last frame's markers for the next {@link #track}.
     *
     * @param image a camera image of the intrinsics' width and height; read during this call only (wrapped, not
     *              copied)
     * @return a new, modifiable list of the markers found, possibly empty, in no particular order; an id may occur
     *         more than once when several copies of one marker are in view
     * @throws IllegalArgumentException when the image's size is not the camera's
     */
    public List<MarkerDetection> detect(GrayImage image) {
        wrap(image);
        List<MarkerDetection> found = new ArrayList<>(2);
        search(frame, 0, 0, found);
        remember(found);
        framesSinceFullSearch = 0;
        lastFromRegion = false;
        return found;
    }

    /**
     * The markers of one video frame. When the config says so, each marker of the last frame is
     * looked for in its own region, where it should be now (its bounds moved as between the last
     * two frames, enlarged by a quarter of its size plus that motion, at least 24 px; overlapping
     * regions are merged); the whole frame is searched instead when a marker of the last frame is
     * not found again, when the regions would cover more than half the frame, and every
     * {@link #FULL_FRAME_EVERY}th frame (markers coming into view).
     *
     * @param image the next video frame, of the intrinsics' width and height; read during this call only (wrapped,
     *              not copied)
     * @return a new, modifiable list of the markers found, possibly empty, in no particular order (as
     *         {@link #detect})
     * @throws IllegalArgumentException when the image's size is not the camera's
     */
    public List<MarkerDetection> track(GrayImage image) {
        if (!config.searchNearLastPose() || lastCount == 0 || framesSinceFullSearch + 1 >= FULL_FRAME_EVERY) {
            return detect(image);
        }
        wrap(image);
        if (!planRegions(image.width(), image.height())) {
            return detect(image);
        }
        List<MarkerDetection> found = new ArrayList<>(lastCount);
        for (int r = 0; r < regionCount; r++) {
            int[] b = regions;
            frame.subimage(b[4 * r], b[4 * r + 1], b[4 * r + 2], b[4 * r + 3], region);
            if (regionLens != null) {
                regionLens.setOffset(b[4 * r], b[4 * r + 1]);
            }
            contourSizes.set(contourMin, contourMax);
            try {
                search(region, b[4 * r], b[4 * r + 1], found);
            } finally {
                if (regionLens != null) {
                    regionLens.setOffset(0, 0);
                }
                contourSizes.off();
            }
        }
        if (!foundAllLast(found)) {
            return detect(image);
        }
        remember(found);
        framesSinceFullSearch++;
        lastFromRegion = true;
        return found;
    }

    /**
     * One region per last marker, overlapping ones merged, into {@link #regions}; false when the
     * whole frame should be searched instead (regions too large, or one squeezed by the border).
     */
    private boolean planRegions(int width, int height) {
        if (regions.length < 4 * lastCount) {
            regions = new int[4 * lastCount];
        }
        regionCount = 0;
        double shortest = Double.POSITIVE_INFINITY;
        double longest = 0;
        for (int m = 0; m < lastCount; m++) {
            double x0 = lastBounds[4 * m];
            double y0 = lastBounds[4 * m + 1];
            double x1 = lastBounds[4 * m + 2];
            double y1 = lastBounds[4 * m + 3];
            shortest = Math.min(shortest, 2 * (x1 - x0 + y1 - y0));
            longest = Math.max(longest, 2 * (x1 - x0 + y1 - y0));
            double dx = lastMotion[2 * m];
            double dy = lastMotion[2 * m + 1];
            // Where the marker should be now if it keeps moving as between the last two frames, with
            // room for a quarter of its size (turning, coming closer) and for the motion doubling.
            double margin = Math.max(MIN_MARGIN, 0.25 * Math.max(x1 - x0, y1 - y0) + Math.hypot(dx, dy));
            int r = 4 * regionCount;
            regions[r] = (int) Math.max(0, Math.floor(x0 + dx - margin));
            regions[r + 1] = (int) Math.max(0, Math.floor(y0 + dy - margin));
            regions[r + 2] = (int) Math.min(width, Math.ceil(x1 + dx + margin));
            regions[r + 3] = (int) Math.min(height, Math.ceil(y1 + dy + margin));
            if (regions[r + 2] - regions[r] < 16 || regions[r + 3] - regions[r + 1] < 16) {
                return false;
            }
            regionCount++;
        }
        mergeOverlappingRegions();
        // A quadrilateral's outline traced in 8-connected pixels has between a half and all of its
        // bounding box's perimeter in pixels; the marker may shrink or grow by half since then.
        contourMin = (int) Math.floor(shortest / 2 / CONTOUR_CHANGE);
        contourMax = (int) Math.ceil(longest * CONTOUR_CHANGE) + 8;
        double area = 0;
        for (int r = 0; r < regionCount; r++) {
            area += (double) (regions[4 * r + 2] - regions[4 * r]) * (regions[4 * r + 3] - regions[4 * r + 1]);
        }
        return area <= REGION_LIMIT * width * height;
    }

    /**
     * Replaces every two overlapping regions by their bounding box until none overlap: a marker
     * lies wholly inside one region, and no pixel is searched twice.
     */
    private void mergeOverlappingRegions() {
        int[] b = regions;
        boolean merged = true;
        while (merged) {
            merged = false;
            for (int i = 0; i < regionCount && !merged; i++) {
                for (int j = i + 1; j < regionCount && !merged; j++) {
                    int p = 4 * i;
                    int q = 4 * j;
                    if (b[p] < b[q + 2] && b[q] < b[p + 2] && b[p + 1] < b[q + 3] && b[q + 1] < b[p + 3]) {
                        b[p] = Math.min(b[p], b[q]);
                        b[p + 1] = Math.min(b[p + 1], b[q + 1]);
                        b[p + 2] = Math.max(b[p + 2], b[q + 2]);
                        b[p + 3] = Math.max(b[p + 3], b[q + 3]);
                        int last = 4 * (regionCount - 1);
                        System.arraycopy(b, last, b, q, 4);
                        regionCount--;
                        merged = true;
                    }
                }
            }
        }
    }

    /** Whether every marker of the last frame (each id as often as it was there) is among {@code found}. */
    private boolean foundAllLast(List<MarkerDetection> found) {
        for (int m = 0; m < lastCount; m++) {
            int id = lastIds[m];
            int before = 0;
            for (int k = 0; k < lastCount; k++) {
                before += lastIds[k] == id ? 1 : 0;
            }
            int now = 0;
            for (MarkerDetection d : found) {
                now += d.id() == id ? 1 : 0;
            }
            if (now < before) {
                return false;
            }
        }
        return true;
    }

    /**
     * Whether the last call found its markers in the region around the previous frame's, without a
     * whole-frame search ({@link #track}'s fast path; the benchmark reports how often).
     *
     * @return true when the last {@link #track} searched only the regions, false after a whole-frame search
     *         (any {@link #detect}) or before the first call
     */
    public boolean lastFoundInRegion() {
        return lastFromRegion;
    }

    /** Forgets the last frame (a cut in the video, a new camera). */
    public void reset() {
        lastCount = 0;
        framesSinceFullSearch = 0;
    }

    /** Makes {@link #frame} a view of the image's bytes (no copy). */
    private void wrap(GrayImage image) {
        if (image.width() != intrinsics.width() || image.height() != intrinsics.height()) {
            throw new IllegalArgumentException("image of " + image.width() + "x" + image.height()
                    + " for a camera of " + intrinsics.width() + "x" + intrinsics.height());
        }
        frame.data = image.pixels();
        frame.width = image.width();
        frame.height = image.height();
        frame.stride = image.rowStride();
        frame.startIndex = 0;
        frame.subImage = false;
    }

    /** Detects in {@code image}, whose pixel (0, 0) is the frame's (x0, y0), and estimates poses. */
    private void search(GrayU8 image, int x0, int y0, List<MarkerDetection> out) {
        detector.process(image);
        for (FoundFiducial f : detector.getFound().toList()) {
            if (config.targetId() >= 0 && f.id != config.targetId()) {
                continue;
            }
            for (int i = 0; i < 4; i++) {
                quad.get(i).setTo(f.distortedPixels.get(i).x + x0, f.distortedPixels.get(i).y + y0);
            }
            if (!pose.process(quad, true)) {
                continue;
            }
            Se3_F64 m = pose.getWorldToCamera();
            double[] corners = new double[8];
            for (int i = 0; i < 4; i++) {
                corners[2 * i] = quad.get(i).x - 0.5;
                corners[2 * i + 1] = quad.get(i).y - 0.5;
            }
            double[] rotation = new double[9];
            for (int row = 0; row < 3; row++) {
                for (int col = 0; col < 3; col++) {
                    rotation[3 * row + col] = m.R.get(row, col);
                }
            }
            double[] translation = {m.T.x, m.T.y, m.T.z};
            out.add(new MarkerDetection((int) f.id, corners, rotation, translation, reprojectionError(corners,
                    rotation, translation)));
        }
    }

    /** Root-mean-square distance in pixels between the corners and the pose's projections of the marker's corners. */
    private double reprojectionError(double[] corners, double[] r, double[] t) {
        double h = config.markerSizeMetres() / 2;
        double[] mx = {-h, h, h, -h};
        double[] my = {h, h, -h, -h};
        double[] pixel = new double[2];
        double sum = 0;
        for (int i = 0; i < 4; i++) {
            double x = r[0] * mx[i] + r[1] * my[i] + t[0];
            double y = r[3] * mx[i] + r[4] * my[i] + t[1];
            double z = r[6] * mx[i] + r[7] * my[i] + t[2];
            intrinsics.toPixel(x, y, z, pixel);
            double u = pixel[0] - corners[2 * i];
            double v = pixel[1] - corners[2 * i + 1];
            sum += u * u + v * v;
        }
        return Math.sqrt(sum / 4);
    }

    /** Keeps {@code found} as the last frame's markers, with each one's motion since its last sighting. */
    private void remember(List<MarkerDetection> found) {
        int n = found.size();
        // The new markers go to the spare arrays while the old ones are still read for the motion.
        if (nextIds.length < n) {
            nextIds = new int[n];
            nextBounds = new double[4 * n];
            nextMotion = new double[2 * n];
        }
        if (matched.length < lastCount) {
            matched = new boolean[lastCount];
        }
        Arrays.fill(matched, false);
        int[] newIds = nextIds;
        double[] newBounds = nextBounds;
        double[] newMotion = nextMotion;
        for (int m = 0; m < n; m++) {
            MarkerDetection d = found.get(m);
            double x0 = Double.POSITIVE_INFINITY;
            double y0 = Double.POSITIVE_INFINITY;
            double x1 = Double.NEGATIVE_INFINITY;
            double y1 = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < 4; i++) {
                x0 = Math.min(x0, d.cornerX(i));
                y0 = Math.min(y0, d.cornerY(i));
                x1 = Math.max(x1, d.cornerX(i));
                y1 = Math.max(y1, d.cornerY(i));
            }
            newIds[m] = d.id();
            newBounds[4 * m] = x0;
            newBounds[4 * m + 1] = y0;
            newBounds[4 * m + 2] = x1;
            newBounds[4 * m + 3] = y1;
            newMotion[2 * m] = 0;
            newMotion[2 * m + 1] = 0;
            for (int k = 0; k < lastCount; k++) {
                if (!matched[k] && lastIds[k] == d.id()) {
                    matched[k] = true;
                    newMotion[2 * m] = (x0 + x1 - lastBounds[4 * k] - lastBounds[4 * k + 2]) / 2;
                    newMotion[2 * m + 1] = (y0 + y1 - lastBounds[4 * k + 1] - lastBounds[4 * k + 3]) / 2;
                    break;
                }
            }
        }
        nextIds = lastIds;
        nextBounds = lastBounds;
        nextMotion = lastMotion;
        lastIds = newIds;
        lastBounds = newBounds;
        lastMotion = newMotion;
        lastCount = n;
    }
}
