/**
 * The AR app's decisions in plain Java, tested on the JVM without Android: the buttons and their
 * labels ({@code AppActions}), the status line, which camera streams and lens model to use, the
 * permission flow, model loading and the model list, saved choices, the GLSL ES shader texts and
 * the palette texture layout, and the measurement ({@code DeviceMeasurement}: the evaluation's
 * protocols on the phone, written as core's device file) (docs/ar.md, "The Android app"). Depends on core only; the Android
 * classes in {@code org.skinlab.android} call it.
 */
package org.skinlab.android.logic;
