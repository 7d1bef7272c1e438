/**
 * Placing a model in a scene: {@code ModelFraming} turns the file's up axis and unit into Y-up
 * metres, stands the model on the floor and centres it, as the viewer and the AR presenters
 * ({@code org.skinlab.ar.MarkerScene}) stand models. Depends on {@code org.skinlab.model},
 * {@code org.skinlab.skinning} and {@code org.skinlab.simulation} (a frame's posed bounds).
 */
package org.skinlab.scene;
