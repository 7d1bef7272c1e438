/**
 * The measuring protocols that run on every platform, so that a phone times what the desktop's
 * {@code skinlab eval} times: one character's frame ({@code FrameBench}: sample, pose, skin, one
 * thread), repeated measurements interleaved across what they compare ({@code Rounds}) and their
 * spread ({@code Spread}); and what a phone's measurement carries to the desktop
 * ({@code DeviceResults}, written by {@code DeviceResultsJson}, read and checked by
 * {@code DeviceResultsReader}). Plain Java, Android-safe; how long a warm-up waits ({@code Warmup}) is
 * the platform's choice (the desktop waits for HotSpot's JIT, docs/evaluation.md). Depends on
 * {@code org.skinlab.skinning}, {@code org.skinlab.animation} and {@code org.skinlab.model}.
 */
package org.skinlab.internal.bench;
