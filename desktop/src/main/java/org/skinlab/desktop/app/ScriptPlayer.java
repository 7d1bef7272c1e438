package org.skinlab.desktop.app;

import static org.lwjgl.glfw.GLFW.*;

import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;

import org.lwjgl.glfw.GLFWCursorEnterCallback;
import org.lwjgl.PointerBuffer;
import org.lwjgl.glfw.GLFWCursorPosCallback;
import org.lwjgl.glfw.GLFWDropCallback;
import org.lwjgl.glfw.GLFWKeyCallback;
import org.lwjgl.glfw.GLFWMouseButtonCallback;
import org.lwjgl.glfw.GLFWScrollCallback;
import org.lwjgl.system.MemoryStack;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.ui.UserInterface;
import org.skinlab.desktop.viewer.LoadedModel;
import org.skinlab.desktop.viewer.MixerReadout;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.desktop.viewer.ViewerAction;
import org.skinlab.mixer.Mixer;
import org.skinlab.skinning.SkinningMethod;

/**
 * Plays a {@link UiScript} in the render loop. Input steps go through the GLFW callbacks
 * installed at that moment (the interface's, which chain to the window's), so the interface and
 * the scene see them as they would see a user's; a click spreads over frames because ImGui needs
 * separate frames to see the mouse arrive, go down and come up.
 */
final class ScriptPlayer {
    private static final int LOAD_TIMEOUT_FRAMES = 60 * 60;
    private static final long MIXER_TIMEOUT_SECONDS = 10;

    private final UiScript script;
    private final GlWindow window;
    private final SkinlabApp app;
    private final Viewer viewer;
    private final UserInterface ui;
    private int next;
    private int waitFrames;
    /** When a wait-seconds step ends (System.nanoTime()); 0 when none runs. */
    private long waitUntil;
    /** Frames waited for a load; -1 when not waiting. A script starts once the first model is shown. */
    private int loadWait = 0;
    /** A click in progress: frames until press (2), release (0). */
    private int clickPhase = -1;
    private String failure;
    private boolean entered;

    ScriptPlayer(UiScript script, GlWindow window, SkinlabApp app, Viewer viewer, UserInterface ui) {
        this.script = script;
        this.window = window;
        this.app = app;
        this.viewer = viewer;
        this.ui = ui;
    }

    /** Whether every step ran (or one failed). */
    boolean done() {
        return failure != null
                || (next >= script.steps().size() && clickPhase < 0 && waitFrames == 0 && waitUntil == 0);
    }

    /** The first failed expectation or step, or null. */
    String failure() {
        return failure;
    }

    /** Runs the steps due before this frame. */
    void beforeFrame() {
        if (!entered) {
            entered = true;
            // Without a cursor-enter event, ImGui's GLFW backend keeps reading the real pointer.
            GLFWCursorEnterCallback cb = glfwSetCursorEnterCallback(window.handle(), null);
            glfwSetCursorEnterCallback(window.handle(), cb);
            if (cb != null) {
                cb.invoke(window.handle(), true);
            }
        }
        if (clickPhase >= 0) {
            if (clickPhase == 2) {
                button(GLFW_PRESS);
            } else if (clickPhase == 0) {
                button(GLFW_RELEASE);
            }
            clickPhase--;
            return;
        }
        if (waitFrames > 0) {
            waitFrames--;
            return;
        }
        if (waitUntil != 0) {
            if (System.nanoTime() - waitUntil < 0) {
                return;
            }
            waitUntil = 0;
        }
        if (loadWait >= 0) {
            if (viewer.loading() && loadWait < LOAD_TIMEOUT_FRAMES) {
                loadWait++;
                return;
            }
            if (viewer.loading()) {
                failure = "the file being loaded was not shown within " + LOAD_TIMEOUT_FRAMES + " frames";
                return;
            }
            loadWait = -1;
            // Show what finished before the next steps look at it.
            viewer.update();
        }
        while (next < script.steps().size() && failure == null && waitFrames == 0 && waitUntil == 0 && clickPhase < 0
                && loadWait < 0) {
            UiScript.Step step = script.steps().get(next++);
            try {
                run(step);
            } catch (RuntimeException e) {
                failure = where(step) + e.getMessage();
            }
        }
    }

    private String where(UiScript.Step step) {
        return script.file() + " line " + step.line() + ": ";
    }

    private void run(UiScript.Step s) {
        if (!userInput(s) && !viewerStep(s)) {
            throw new IllegalArgumentException("unknown verb " + s.verb());
        }
    }

    /** The steps a user's keys, mouse and file drops would take; false for other verbs. */
    private boolean userInput(UiScript.Step s) {
        switch (s.verb()) {
            case "key":
                key(Keys.code(s.arg(0)), s.args().size() > 1 ? Keys.modifier(s.arg(1)) : 0);
                return true;
            case "click":
                float[] c = ui.itemCentre(s.rest());
                if (c == null) {
                    throw new IllegalArgumentException("no interface item labelled \"" + s.rest() + "\" was drawn");
                }
                move(c[0], c[1]);
                clickPhase = 2;
                return true;
            case "move":
                move(s.number(0), s.number(1));
                return true;
            case "drag":
                move(s.number(0), s.number(1));
                button(GLFW_PRESS);
                move((s.number(0) + s.number(2)) / 2, (s.number(1) + s.number(3)) / 2);
                move(s.number(2), s.number(3));
                button(GLFW_RELEASE);
                return true;
            case "scroll":
                GLFWScrollCallback sc = glfwSetScrollCallback(window.handle(), null);
                glfwSetScrollCallback(window.handle(), sc);
                if (sc != null) {
                    sc.invoke(window.handle(), 0, s.number(0));
                }
                return true;
            case "drop":
                drop(script.resolve(s.rest()));
                return true;
            default:
                return false;
        }
    }

    /** The steps that go to the viewer and the window directly, and the script's waits and checks. */
    private boolean viewerStep(UiScript.Step s) {
        switch (s.verb()) {
            case "action":
                ViewerAction a = ViewerAction.byName(s.rest())
                        .orElseThrow(() -> new IllegalArgumentException("no action named " + s.rest()));
                app.windowAction(a);
                return true;
            case "open":
                viewer.open(script.resolve(s.rest()));
                return true;
            case "seek":
                viewer.seek(s.number(0));
                return true;
            case "wait":
                waitFrames = Integer.parseInt(s.arg(0));
                return true;
            case "wait-seconds":
                // Never 0: 0 means no wait runs.
                waitUntil = (System.nanoTime() + (long) (s.number(0) * 1e9)) | 1L;
                return true;
            case "wait-loaded":
                loadWait = 0;
                return true;
            case "screenshot":
                app.writeScreenshot(script.resolve(s.rest()));
                return true;
            case "expect":
                expect(s);
                return true;
            case "quit":
                window.requestClose();
                return true;
            default:
                return false;
        }
    }

    private void expect(UiScript.Step s) {
        String value = String.join(" ", s.args().subList(1, s.args().size()));
        LoadedModel current = viewer.current();
        switch (s.arg(0)) {
            case "mesh":
                String shown = current == null ? "(none)" : current.displayName();
                if (!shown.equals(value)) {
                    throw new IllegalStateException("expected mesh " + value + " but " + shown + " is shown");
                }
                break;
            case "status":
                if (!viewer.statusMessage().contains(value)) {
                    throw new IllegalStateException("expected the status to contain \"" + value + "\" but it reads \""
                            + viewer.statusMessage() + "\"");
                }
                break;
            case "method":
                SkinningMethod m = viewer.config().method();
                if (m != SkinningMethod.fromKey(value)) {
                    throw new IllegalStateException("expected method " + value + " but it is " + m);
                }
                break;
            case "layers":
                String count = readMixer(mixer -> String.valueOf(mixer.layers().size()));
                if (!count.equals(s.arg(1))) {
                    throw new IllegalStateException("expected " + s.arg(1) + " layers but the mixer has " + count);
                }
                break;
            case "layer":
                int index = Integer.parseInt(s.arg(1));
                String text = String.join(" ", s.args().subList(2, s.args().size()));
                String layer = readMixer(mixer -> MixerReadout.layer(mixer, index));
                if (!layer.contains(text)) {
                    throw new IllegalStateException("expected layer " + index + " to contain \"" + text
                            + "\" but it reads \"" + layer + "\"");
                }
                break;
            default:
                throw new IllegalArgumentException("cannot expect " + s.arg(0));
        }
    }

    /**
     * Reads the shown model's mixer where it lives, on the simulation thread: the window waits for
     * the next step (the changes handed over before it run first).
     */
    private String readMixer(Function<Mixer, String> read) {
        LoadedModel current = viewer.current();
        if (current == null) {
            throw new IllegalStateException("no model is shown");
        }
        AtomicReference<String> text = new AtomicReference<>();
        try {
            current.mesh().direct(m -> text.set(read.apply(m))).get(MIXER_TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            throw new IllegalStateException("reading the mixer failed: " + e.getCause());
        } catch (TimeoutException e) {
            throw new IllegalStateException("the simulation did not step within " + MIXER_TIMEOUT_SECONDS + " s");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while reading the mixer");
        }
        return text.get();
    }

    private void key(int key, int mods) {
        GLFWKeyCallback cb = glfwSetKeyCallback(window.handle(), null);
        glfwSetKeyCallback(window.handle(), cb);
        if (cb != null) {
            cb.invoke(window.handle(), key, glfwGetKeyScancode(key), GLFW_PRESS, mods);
            cb.invoke(window.handle(), key, glfwGetKeyScancode(key), GLFW_RELEASE, mods);
        }
    }

    /** A file drop through the window's installed drop callback, with GLFW's list of UTF-8 paths. */
    private void drop(java.nio.file.Path file) {
        GLFWDropCallback cb = glfwSetDropCallback(window.handle(), null);
        glfwSetDropCallback(window.handle(), cb);
        if (cb != null) {
            try (MemoryStack stack = MemoryStack.stackPush()) {
                PointerBuffer names = stack.pointers(stack.UTF8(file.toString()));
                cb.invoke(window.handle(), 1, names.address());
            }
        }
    }

    private void move(float x, float y) {
        GLFWCursorPosCallback cb = glfwSetCursorPosCallback(window.handle(), null);
        glfwSetCursorPosCallback(window.handle(), cb);
        if (cb != null) {
            cb.invoke(window.handle(), x, y);
        }
    }

    private void button(int action) {
        GLFWMouseButtonCallback cb = glfwSetMouseButtonCallback(window.handle(), null);
        glfwSetMouseButtonCallback(window.handle(), cb);
        if (cb != null) {
            cb.invoke(window.handle(), GLFW_MOUSE_BUTTON_LEFT, action, 0);
        }
    }
}
