/**
 * Placing a model in a scene, shared by the viewer and the AR presenters: {@code ModelFraming}
 * turns the file's up axis and unit into Y-up metres, stands the model on the floor and centres
 * it; {@code PartMaterial}, {@code PartCentres}, {@code BlendOrder} and {@code MaterialGlsl} resolve
 * what each triangle run is drawn with and in which order; {@code ColourRamp} is the data views'
 * colour map, for shaders and legends alike; {@code DefaultAsset} names the asset that opens first.
 * Depends on {@code org.skinlab.model}, {@code org.skinlab.skinning},
 * {@code org.skinlab.simulation} (a frame's posed bounds) and {@code org.skinlab.glsl}.
 */
package org.skinlab.internal.scene;
