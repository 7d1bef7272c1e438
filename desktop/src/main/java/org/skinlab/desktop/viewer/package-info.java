/**
 * What the viewer shows and does, apart from drawing: {@code Viewer} (the model shown, the
 * actions, loading off the window thread), {@code ViewerAction} (every function with its label and
 * key), {@code ViewerSettings}, {@code ModelLibrary}, {@code OrbitCamera} and {@code LiveStats};
 * what the mixer panel chose for the model's mixer ({@code MixerControls}, {@code BlendPad}) and
 * its layers in words for scripts ({@code MixerReadout}). Depends on core, JOML, GLFW's key codes
 * and the render package's {@code DrawSettings}; tested without a window.
 */
package org.skinlab.desktop.viewer;
