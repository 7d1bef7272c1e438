package org.skinlab.ar;

import java.util.ArrayList;
import java.util.List;

import boofcv.alg.distort.LensDistortionNarrowFOV;
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
 * <p><b>Video.</b> {@link #track} first looks at the image region where the markers of the last
 * frame should be now (their bounds moved as between the last two frames, enlarged by a quarter of
 * their size plus that motion, at least 24 px; a marker that jumps farther is found by the
 * whole-frame pass that follows a miss) and only then at the whole frame; every
 * {@link #FULL_FRAME_EVERY}th frame it looks at the whole frame anyway, so that markers coming into
 * view are found. {@link #detect} always looks at the whole frame.
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

    private final TrackerConfig config;
    private final CameraIntrinsics intrinsics;
    private final ConfidentHammingDetector detector;
    /** The detector's lens, moved to each searched region; null for an ideal camera. */
    private final RegionLens regionLens;
    private final QuadPoseEstimator pose = new QuadPoseEstimator(1e-6, 200);
    private final Quadrilateral_F64 quad = new Quadrilateral_F64();
    private final GrayU8 frame = new GrayU8(1, 1);
    private final GrayU8 region = new GrayU8(1, 1);
    /** The last frame's markers' bounds in pixels (x0, y0, x1, y1), or empty. */
    private final double[] lastBounds = new double[4];
    /** How far the bounds' centre moved from the frame before (pixels), 0 after a whole-frame search gap. */
    private double motionX;
    private double motionY;
    private boolean haveLast;
    private boolean lastFromRegion;
    private int framesSinceFullSearch;

    public FiducialTracker(TrackerConfig config, CameraIntrinsics intrinsics) {
        this.config = config;
        this.intrinsics = intrinsics;
        this.detector = ConfidentHammingDetector.create(config.dictionary(), config.maxBitErrors(),
                TrackerConfig.MAX_UNCERTAIN_BITS);
        LensDistortionNarrowFOV lens = LensDistortionFactory.narrow(BoofCameras.toBoof(intrinsics));
        if (intrinsics.isDistorted()) {
            // The square's contour is undistorted before its sides are fitted and its bits are read
            // through the lens; the image itself is never remapped. BoofCV applies the lens to the
            // coordinates of the image it is given, which for track's region is a subimage: the
            // region's lens shifts them back to the frame's (RegionLens). Not BoofCV's cache: its
            // tables are per pixel of the image configured, not of a moving region (RegionLens
            // keeps the frame's instead).
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

    public TrackerConfig config() {
        return config;
    }

    public CameraIntrinsics intrinsics() {
        return intrinsics;
    }

    /** Every marker in the whole image (of the target id, if the config names one). */
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
     * The markers of one video frame: near the last frame's markers first when the config says so,
     * else (and when nothing is found there) in the whole image.
     */
    public List<MarkerDetection> track(GrayImage image) {
        if (!config.searchNearLastPose() || !haveLast || framesSinceFullSearch + 1 >= FULL_FRAME_EVERY) {
            return detect(image);
        }
        wrap(image);
        double w = lastBounds[2] - lastBounds[0];
        double h = lastBounds[3] - lastBounds[1];
        // Where the markers should be now if they keep moving as between the last two frames, with
        // room for a quarter of their size (turning, coming closer) and for the motion doubling.
        double margin = Math.max(24, 0.25 * Math.max(w, h) + Math.hypot(motionX, motionY));
        int x0 = (int) Math.max(0, Math.floor(lastBounds[0] + motionX - margin));
        int y0 = (int) Math.max(0, Math.floor(lastBounds[1] + motionY - margin));
        int x1 = (int) Math.min(image.width(), Math.ceil(lastBounds[2] + motionX + margin));
        int y1 = (int) Math.min(image.height(), Math.ceil(lastBounds[3] + motionY + margin));
        if (x1 - x0 < 16 || y1 - y0 < 16) {
            return detect(image);
        }
        if ((double) (x1 - x0) * (y1 - y0) > REGION_LIMIT * image.width() * image.height()) {
            return detect(image);
        }
        frame.subimage(x0, y0, x1, y1, region);
        List<MarkerDetection> found = new ArrayList<>(2);
        search(region, x0, y0, found);
        if (found.isEmpty()) {
            return detect(image);
        }
        remember(found);
        framesSinceFullSearch++;
        lastFromRegion = true;
        return found;
    }

    /**
     * Whether the last call found its markers in the region around the previous frame's, without a
     * whole-frame search ({@link #track}'s fast path; the benchmark reports how often).
     */
    public boolean lastFoundInRegion() {
        return lastFromRegion;
    }

    /** Forgets the last frame (a cut in the video, a new camera). */
    public void reset() {
        haveLast = false;
        motionX = motionY = 0;
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
        if (regionLens != null) {
            regionLens.moveTo(x0, y0);
        }
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

    private void remember(List<MarkerDetection> found) {
        boolean had = haveLast;
        double oldX = (lastBounds[0] + lastBounds[2]) / 2;
        double oldY = (lastBounds[1] + lastBounds[3]) / 2;
        haveLast = !found.isEmpty();
        if (!haveLast) {
            motionX = motionY = 0;
            return;
        }
        lastBounds[0] = lastBounds[1] = Double.POSITIVE_INFINITY;
        lastBounds[2] = lastBounds[3] = Double.NEGATIVE_INFINITY;
        for (MarkerDetection d : found) {
            for (int i = 0; i < 4; i++) {
                lastBounds[0] = Math.min(lastBounds[0], d.cornerX(i));
                lastBounds[1] = Math.min(lastBounds[1], d.cornerY(i));
                lastBounds[2] = Math.max(lastBounds[2], d.cornerX(i));
                lastBounds[3] = Math.max(lastBounds[3], d.cornerY(i));
            }
        }
        motionX = had ? (lastBounds[0] + lastBounds[2]) / 2 - oldX : 0;
        motionY = had ? (lastBounds[1] + lastBounds[3]) / 2 - oldY : 0;
    }
}
