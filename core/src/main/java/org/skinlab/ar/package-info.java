/**
 * Augmented reality without Vuforia: a printed square fiducial tracked with BoofCV, the camera
 * model, and the math that puts the animated model on the marker.
 *
 * <p>Conventions used throughout (and by {@code skinlab track}'s JSON): camera x right, y down,
 * z forward; pixel (i, j) has its centre at (i, j); the marker frame's origin is the centre of the
 * black square, x to the right, y toward the marker's top edge, z out of the printed face;
 * {@code X_cam = R X_marker + t} in metres; corners TL, TR, BR, BL of the printed marker. See
 * {@code docs/ar.md}.
 *
 * <p>Depends on BoofCV's recognition module (never boofcv-io), JOML, {@code org.skinlab.internal.scene}
 * (standing a model on the marker) and {@code org.skinlab.glsl} (the lens formulas for the
 * background shaders); never on a GL binding.
 */
package org.skinlab.ar;
