/**
 * Deformation: a placed mesh's runtime arrays ({@code SkinnedGeometry}), one frame's joint palette
 * ({@code JointPalette}), the skinning methods' kernels behind {@code Skinner} (LBS, DQS, CoR,
 * bulge-free DQS, stretchable and twistable bones, spline skinning; a platform's faster kernels
 * through {@code SkinnerProvider}), the synchronous per-frame path ({@code SkinnedModel}), and the
 * metrics that compare the methods ({@code MethodComparison} on a frame, {@code LargestDifference}
 * over a clip; docs/skinning.md). Depends on {@code org.skinlab.animation},
 * {@code org.skinlab.model} and {@code org.skinlab.glsl} (the shader sources of the methods), never
 * on a GL binding.
 */
package org.skinlab.skinning;
