package org.skinlab.desktop.ui;

/**
 * The window's user interface around the scene (the ImGui toolbar, numbers, help and status
 * line), seen from the render loop. Called on the window's thread only.
 */
public interface UserInterface extends AutoCloseable {
    /**
     * Places the panels for a framebuffer of {@code width x height} pixels and puts the part they
     * leave free into {@code area}: the scene is drawn there, so no panel covers the model.
     */
    void layOut(int width, int height, SceneArea area);

    /** Builds and draws the interface for this frame, over the scene already drawn. */
    void render(SceneReadout scene);

    /** Whether the interface uses the mouse now (then the camera ignores it). */
    boolean wantsMouse();

    /** Whether the interface uses the keyboard now (then the keys' actions do not fire). */
    boolean wantsKeyboard();

    /**
     * Centre of the interface item labelled {@code label} in window coordinates as of the last
     * frame, for scripted clicks; null when no such item was drawn.
     */
    float[] itemCentre(String label);

    @Override
    void close();

    /** No interface: the scene takes the whole window (--hide-ui, headless pictures). */
    UserInterface NONE = new UserInterface() {
        @Override
        public void layOut(int width, int height, SceneArea area) {
            area.set(0, 0, width, height);
        }

        @Override
        public void render(SceneReadout scene) {
        }

        @Override
        public boolean wantsMouse() {
            return false;
        }

        @Override
        public boolean wantsKeyboard() {
            return false;
        }

        @Override
        public float[] itemCentre(String label) {
            return null;
        }

        @Override
        public void close() {
        }
    };
}
