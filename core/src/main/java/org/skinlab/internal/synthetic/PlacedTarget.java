package org.skinlab.internal.synthetic;

import org.skinlab.internal.ar.CalibrationTarget;

/**
 * A printed calibration target in the synthetic scene: the pattern centred on its sheet, white
 * paper one square's pitch wide around it (the quiet zone the detectors need), at the pose
 * {@code X_cam = R X_target + t} ({@link PlacedSheet}'s frame: origin at the pattern's centre, y
 * toward its top row).
 *
 * @param target      the printed pattern
 * @param rotation    R, 3x3 row-major
 * @param translation t in metres
 */
public record PlacedTarget(CalibrationTarget target, double[] rotation, double[] translation) implements PlacedSheet {

    public PlacedTarget {
        if (rotation.length != 9 || translation.length != 3) {
            throw new IllegalArgumentException("need a 3x3 rotation and a translation");
        }
        rotation = rotation.clone();
        translation = translation.clone();
    }

    @Override
    public double[] rotation() {
        return rotation.clone();
    }

    @Override
    public double[] translation() {
        return translation.clone();
    }

    private double margin() {
        return target.squareMetres() + target.spaceMetres();
    }

    @Override
    public double paperHalfWidth() {
        return target.width() / 2 + margin();
    }

    @Override
    public double paperHalfHeight() {
        return target.height() / 2 + margin();
    }

    @Override
    public int grayAt(double x, double y) {
        return target.isBlackAt(x + target.width() / 2, target.height() / 2 - y) ? SyntheticCamera.INK
                : SyntheticCamera.PAPER;
    }
}
