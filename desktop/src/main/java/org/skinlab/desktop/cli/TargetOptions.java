package org.skinlab.desktop.cli;

import org.skinlab.internal.ar.CalibrationTarget;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;

import picocli.CommandLine.Option;

/**
 * The options that name a calibration target, shared by {@code skinlab calibration-target} (which
 * prints it) and {@code skinlab calibrate} (which looks for it): a chessboard of 7 x 10 squares of
 * 20 mm by default, a grid of 5 x 7 squares of 20 mm, 10 mm apart, with {@code --target grid}.
 */
final class TargetOptions {
    @Option(names = "--target", paramLabel = "chessboard|grid", description = "the target's kind (default: chessboard)")
    String kind = CalibrationTarget.Kind.CHESSBOARD.key();

    @Option(names = "--rows", paramLabel = "N", description = "rows of squares (default: 7 for a chessboard, 5 for a grid)")
    Integer rows;

    @Option(names = "--cols", paramLabel = "N", description = "columns of squares (default: 10 for a chessboard, 7 for a grid)")
    Integer cols;

    @Option(names = "--square-mm", paramLabel = "MM", description = "a square's printed side (default: 20)")
    Double squareMm;

    @Option(names = "--space-mm", paramLabel = "MM", description = "a grid's space between squares (default: 10)")
    Double spaceMm;

    /** The target these options name; CommandFailure (usage) when they do not name one. */
    CalibrationTarget target() {
        try {
            CalibrationTarget.Kind k = CalibrationTarget.Kind.byKey(kind);
            boolean chess = k == CalibrationTarget.Kind.CHESSBOARD;
            if (chess && spaceMm != null) {
                throw new IllegalArgumentException("--space-mm is for --target grid (a chessboard's squares touch)");
            }
            double square = (squareMm != null ? squareMm : 20) / 1000;
            int r = rows != null ? rows : chess ? 7 : 5;
            int c = cols != null ? cols : chess ? 10 : 7;
            return chess ? CalibrationTarget.chessboard(r, c, square)
                    : CalibrationTarget.grid(r, c, square, (spaceMm != null ? spaceMm : 10) / 1000);
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        }
    }
}
