package org.skinlab.desktop.ar;

import java.util.List;

import boofcv.abst.fiducial.calib.CalibrationDetectorSquareGrid;
import boofcv.abst.fiducial.calib.ConfigChessboardX;
import boofcv.abst.fiducial.calib.ConfigGridDimen;
import boofcv.abst.fiducial.calib.ConfigSquareGrid;
import boofcv.abst.geo.calibration.DetectSingleFiducialCalibration;
import boofcv.alg.fiducial.calib.chess.ChessboardCornerClusterToGrid;
import boofcv.alg.fiducial.calib.chess.DetectChessboardXCornerPatterns;
import boofcv.alg.geo.calibration.CalibrationObservation;
import boofcv.factory.fiducial.FactoryFiducialCalibration;
import boofcv.struct.image.GrayF32;
import georegression.struct.point.Point2D_F64;

import org.ddogleg.struct.DogArray;
import org.skinlab.internal.ar.CalibrationTarget;
import org.skinlab.ar.GrayImage;

/**
 * Finds a {@link CalibrationTarget} in camera images with BoofCV's calibration detectors: X-corners
 * for a chessboard ({@code chessboardX}), black squares for a grid ({@code squareGrid}). Either
 * finds every point of the target or nothing, and says why when it finds nothing. Points are in
 * BoofCV's pixel convention (a pixel's centre at +0.5, {@link org.skinlab.ar.BoofCameras}), the
 * calibration's input. One instance per thread.
 */
public final class TargetDetector {
    private final CalibrationTarget target;
    private final DetectSingleFiducialCalibration detector;
    private final GrayF32 frame = new GrayF32(1, 1);
    /** Made on the first miss: finds boards of any size, to say what was seen instead. */
    private DetectChessboardXCornerPatterns<GrayF32> anyChessboard;

    /** A view of the target: its points in image pixels, or why there are none. */
    public record View(CalibrationObservation points, String problem) {
        public boolean found() {
            return points != null;
        }
    }

    public TargetDetector(CalibrationTarget target) {
        this.target = target;
        ConfigGridDimen grid = new ConfigGridDimen(target.rows(), target.cols(), target.squareMetres(),
                target.spaceMetres());
        detector = target.kind() == CalibrationTarget.Kind.CHESSBOARD
                ? FactoryFiducialCalibration.chessboardX(new ConfigChessboardX(), grid)
                : FactoryFiducialCalibration.squareGrid(new ConfigSquareGrid(), grid);
    }

    public CalibrationTarget target() {
        return target;
    }

    /** The target's points in its own plane (metres), in the order of a view's point indices. */
    public List<Point2D_F64> layout() {
        return detector.getLayout();
    }

    /** The target in {@code image}, or the reason it is not there. */
    public View detect(GrayImage image) {
        frame.reshape(image.width(), image.height());
        byte[] pixels = image.pixels();
        for (int y = 0; y < image.height(); y++) {
            int in = y * image.rowStride();
            int out = y * frame.width;
            for (int x = 0; x < image.width(); x++) {
                frame.data[out + x] = pixels[in + x] & 0xFF;
            }
        }
        if (detector.process(frame)) {
            CalibrationObservation points = detector.getDetectedPoints().copy();
            if (points.size() == target.points()) {
                return new View(points, null);
            }
            return new View(null, points.size() + " of the target's " + target.points() + " points found");
        }
        return new View(null, target.kind() == CalibrationTarget.Kind.CHESSBOARD ? whyNoChessboard() : whyNoGrid());
    }

    /**
     * Looks again for chessboards of any size: a board of another size is the usual reason (part
     * of it outside the image or covered, or other --rows/--cols); none at all means too blurred,
     * too small or not there.
     */
    private String whyNoChessboard() {
        if (anyChessboard == null) {
            // Without a shape check: it keeps boards of every size.
            anyChessboard = new DetectChessboardXCornerPatterns<>(new ConfigChessboardX(), GrayF32.class);
        }
        anyChessboard.findPatterns(frame);
        DogArray<ChessboardCornerClusterToGrid.GridInfo> found = anyChessboard.getFoundChessboard();
        int best = -1;
        for (int i = 0; i < found.size; i++) {
            if (best < 0 || found.get(i).nodes.size() > found.get(best).nodes.size()) {
                best = i;
            }
        }
        String wanted = "expected " + (target.rows() - 1) + " x " + (target.cols() - 1) + " inner corners";
        // A 2 x 2 patch of corners is texture more often than a board: only a grid of 3 x 3 or more is reported.
        if (best >= 0 && found.get(best).rows >= 3 && found.get(best).cols >= 3) {
            ChessboardCornerClusterToGrid.GridInfo g = found.get(best);
            return "saw a chessboard of " + g.rows + " x " + g.cols + " inner corners, " + wanted
                    + " (part of the board outside the image or covered, or other --rows/--cols)";
        }
        int corners = anyChessboard.getDetector().getCorners().size;
        return corners == 0 ? "no board: no chessboard corners seen (no target, or too blurred or dark)"
                : "no board: " + corners + " chessboard-like corners seen (" + wanted
                        + "; no target, or too blurred, too small or too steep)";
    }

    private String whyNoGrid() {
        int squares = ((CalibrationDetectorSquareGrid) detector).getAlgorithm().getDetectorSquare().getPolygonInfo()
                .size();
        return "no grid of " + target.rows() + " x " + target.cols() + " squares: " + squares + " dark squares seen"
                + " (part of the grid outside the image or covered, other --rows/--cols, or too blurred)";
    }
}
