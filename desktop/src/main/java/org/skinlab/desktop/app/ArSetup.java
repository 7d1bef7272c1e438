package org.skinlab.desktop.app;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.desktop.ar.ArFeed;

/**
 * What {@code skinlab ar} hands the window: the running camera feed, the camera's intrinsics and
 * the printed marker's size.
 */
public record ArSetup(ArFeed feed, CameraIntrinsics intrinsics, double markerSizeMetres) {
}
