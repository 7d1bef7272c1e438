package org.skinlab.desktop.app;

import static org.lwjgl.glfw.GLFW.*;

import java.nio.file.Path;

import org.lwjgl.glfw.GLFWCursorPosCallback;
import org.lwjgl.glfw.GLFWDropCallback;
import org.lwjgl.glfw.GLFWKeyCallback;
import org.lwjgl.glfw.GLFWMouseButtonCallback;
import org.lwjgl.glfw.GLFWScrollCallback;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.ui.UserInterface;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.desktop.viewer.ViewerAction;

/**
 * The window's keys, mouse and file drops: keys fire {@link ViewerAction}s, the left button
 * orbits the camera, the right or middle button pans, the wheel zooms, a dropped file opens.
 * What the interface uses (a slider being dragged, a text field) does not reach the scene. The
 * interface installs its own GLFW callbacks after these and chains to them, so the same events
 * reach both; scripted input goes through the installed callbacks too.
 */
final class WindowInput implements AutoCloseable {
    private final GlWindow window;
    private final Viewer viewer;
    private final SkinlabApp app;
    private final GLFWKeyCallback keys;
    private final GLFWMouseButtonCallback buttons;
    private final GLFWCursorPosCallback cursor;
    private final GLFWScrollCallback scroll;
    private final GLFWDropCallback drop;
    private UserInterface ui = UserInterface.NONE;
    private final int[] height = new int[1];
    private int dragButton = -1;
    private double lastX;
    private double lastY;

    WindowInput(GlWindow window, Viewer viewer, SkinlabApp app) {
        this.window = window;
        this.viewer = viewer;
        this.app = app;
        long w = window.handle();
        keys = GLFWKeyCallback.create((win, key, scancode, action, mods) -> onKey(key, action, mods));
        buttons = GLFWMouseButtonCallback.create((win, button, action, mods) -> onButton(button, action));
        cursor = GLFWCursorPosCallback.create((win, x, y) -> onCursor(x, y));
        scroll = GLFWScrollCallback.create((win, dx, dy) -> onScroll(dy));
        drop = GLFWDropCallback.create((win, count, names) -> {
            if (count > 0) {
                onDrop(Path.of(GLFWDropCallback.getName(names, 0)));
            }
        });
        glfwSetKeyCallback(w, keys);
        glfwSetMouseButtonCallback(w, buttons);
        glfwSetCursorPosCallback(w, cursor);
        glfwSetScrollCallback(w, scroll);
        glfwSetDropCallback(w, drop);
    }

    void setUi(UserInterface ui) {
        this.ui = ui;
    }

    private void onKey(int key, int action, int mods) {
        if (action == GLFW_RELEASE || ui.wantsKeyboard()) {
            return;
        }
        ViewerAction.forKey(key, mods).ifPresent(a -> {
            // Holding a key repeats only what makes sense to repeat.
            if (action == GLFW_REPEAT && !repeats(a)) {
                return;
            }
            app.windowAction(a);
        });
    }

    private static boolean repeats(ViewerAction a) {
        switch (a) {
            case SLOWER:
            case FASTER:
            case STEP_BACK:
            case STEP_FORWARD:
            case PREVIOUS_JOINT:
            case NEXT_JOINT:
                return true;
            default:
                return false;
        }
    }

    private void onButton(int button, int action) {
        if (action == GLFW_PRESS && !ui.wantsMouse() && dragButton < 0) {
            dragButton = button;
        } else if (action == GLFW_RELEASE && button == dragButton) {
            dragButton = -1;
        }
    }

    private void onCursor(double x, double y) {
        double dx = x - lastX;
        double dy = y - lastY;
        lastX = x;
        lastY = y;
        if (dragButton == GLFW_MOUSE_BUTTON_LEFT) {
            viewer.camera().orbit((float) dx, (float) dy);
        } else if (dragButton == GLFW_MOUSE_BUTTON_RIGHT || dragButton == GLFW_MOUSE_BUTTON_MIDDLE) {
            glfwGetWindowSize(window.handle(), null, height);
            viewer.camera().pan((float) dx, (float) dy, height[0]);
        }
    }

    private void onScroll(double dy) {
        if (!ui.wantsMouse()) {
            viewer.camera().zoom((float) dy);
        }
    }

    private void onDrop(Path file) {
        app.dropped(file);
    }

    @Override
    public void close() {
        long w = window.handle();
        glfwSetKeyCallback(w, null);
        glfwSetMouseButtonCallback(w, null);
        glfwSetCursorPosCallback(w, null);
        glfwSetScrollCallback(w, null);
        glfwSetDropCallback(w, null);
        keys.free();
        buttons.free();
        cursor.free();
        scroll.free();
        drop.free();
    }
}
