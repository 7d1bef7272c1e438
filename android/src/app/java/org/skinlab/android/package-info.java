/**
 * The Android code of the AR app: {@code SkinlabActivity}, the Camera2 source, and the OpenGL ES 3
 * renderer that draws the camera image and the skinned model on the marker
 * ({@code ArRenderer}, {@code ModelGl}, {@code TexturesGl}), and the measurement's buttons and
 * copies ({@code MeasureControl}, {@code CopiesDrawer}). Compiled against android-all for
 * API 26 and run by the Robolectric tests; every decision it needs lives in
 * {@code org.skinlab.android.logic} and core (docs/ar.md, "The Android app").
 */
package org.skinlab.android;
