/**
 * Deformation, by when its code runs. <b>Bind time</b>, once per model, on the thread that loads it:
 * a placed mesh's runtime arrays and bones ({@code SkinnedGeometry}, {@code Bones}), CoR's centres
 * ({@code CentresOfRotation}), and every method's skinner with its bindings, all built by
 * {@code SkinnedModel}'s constructor. <b>Frame time</b>, allocation-free: one frame's joint
 * palette ({@code JointPalette}, with its {@code prepare(method)}), the methods' kernels behind
 * {@code Skinner} (LBS, DQS, CoR, bulge-free DQS, stretchable and twistable bones, spline
 * skinning; a platform's faster kernels through {@code SkinnerProvider}), and the synchronous
 * per-frame path ({@code SkinnedModel.pose}, {@code skin}). The metrics that compare the methods
 * live in {@code org.skinlab.internal.metrics} (docs/skinning.md). Depends on
 * {@code org.skinlab.animation}, {@code org.skinlab.model} and {@code org.skinlab.glsl} (the
 * shader sources of the methods), never on a GL binding.
 */
package org.skinlab.skinning;
