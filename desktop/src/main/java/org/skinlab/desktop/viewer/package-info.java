/**
 * What the viewer shows and does, apart from drawing: {@code Viewer} (the model shown, the
 * actions, loading off the window thread), {@code ViewerAction} (every function with its label and
 * key), {@code ViewerSettings}, {@code ModelLibrary}, {@code OrbitCamera} and {@code LiveStats}.
 * Depends on core, JOML, GLFW's key codes and the render package's {@code DrawSettings}; tested
 * without a window.
 */
package org.skinlab.desktop.viewer;
