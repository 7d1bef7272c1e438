/**
 * Skinning kernels on the JDK Vector API ({@code jdk.incubator.vector}), for desktop JVMs: a
 * {@link org.skinlab.skinning.SkinnerProvider} that core's {@code Skinners} finds through
 * {@link java.util.ServiceLoader}. Needs {@code --add-modules jdk.incubator.vector} at compile and
 * run time and 256-bit vectors (AVX2); otherwise the provider declines and the scalar kernels of
 * core run. See docs/benchmarks.md ("Skinning") for the layouts and the measurements.
 */
package org.skinlab.simd;
