package org.skinlab.desktop.app;

/**
 * The window's user interface drawn over the scene (the ImGui toolbar, help and plots), seen from
 * the render loop. Called on the window's thread only.
 */
public interface AppUi extends AutoCloseable {
    /** Builds and draws the interface for this frame, over the scene already drawn. */
    void render(AppFrame frame);

    /** Window pixels at the left the interface keeps for itself (the toolbar beside the scene). */
    int reservedLeft();

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

    /** No interface: the scene only (--hide-ui, headless pictures). */
    AppUi NONE = new AppUi() {
        @Override
        public void render(AppFrame frame) {
        }

        @Override
        public int reservedLeft() {
            return 0;
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
