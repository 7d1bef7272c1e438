/**
 * How skinlab's own viewer and AR presenters draw a model (not API): {@code PartMaterial},
 * {@code PartCentres}, {@code BlendOrder} and {@code MaterialGlsl} resolve what each triangle run
 * is drawn with and in which order; {@code ColourRamp} is the data views' colour map, for shaders
 * and legends alike; {@code DefaultAsset} names the asset that opens first. Depends on
 * {@code org.skinlab.model}, {@code org.skinlab.skinning} and {@code org.skinlab.glsl}.
 */
package org.skinlab.internal.scene;
