package org.skinlab.internal.synthetic;

import org.skinlab.ar.GrayImage;

/**
 * One rendered frame of one marker with its truth: the marker as placed, and the tilt it was given
 * (degrees between its normal and the line of sight to it, before the turn about that normal).
 *
 * @param image  the frame
 * @param marker the marker's pattern, size and pose
 * @param tilt   its tilt in degrees
 */
public record MarkerShot(GrayImage image, PlacedMarker marker, double tilt) {
    /** The marker's distance along the optical axis (metres). */
    public double distance() {
        return marker.translation()[2];
    }
}
