/**
 * The desktop's side of augmented reality: camera frames and intrinsics from files, the
 * {@code skinlab track} output, the printable marker and calibration target, and the camera
 * calibration (BoofCV's planar calibration, desktop only). The tracking itself is core's
 * {@code org.skinlab.ar}.
 * Depends on core, BoofCV (calibration), PDFBox, JCodec, webcam-capture, SnakeYAML and
 * Jackson; no GL.
 */
package org.skinlab.desktop.ar;
