/**
 * Camera frames of known pose for tests, benchmarks and {@code skinlab ar-demo}:
 * {@code SyntheticCamera} ray-traces placed printed sheets ({@code PlacedMarker},
 * {@code PlacedTarget}) over a {@code Background} through a lens, so the tracker and the
 * calibration can be measured against the truth (docs/ar.md). Depends on {@code org.skinlab.ar}.
 */
package org.skinlab.internal.synthetic;
