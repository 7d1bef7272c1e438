package org.skinlab.desktop.viewer;

import static org.lwjgl.glfw.GLFW.*;

import java.util.Locale;
import java.util.Optional;

/**
 * Every function of the toolbar, each also on a key: the thesis' buttons (play/pause, mesh
 * updates, skinning method, interpolation, slower/faster, previous/next mesh, centre camera) and
 * the viewer's own. Labels are what the toolbar shows and what scripts click; the help panel lists
 * {@link #keyName()} and {@link #description()}.
 */
public enum ViewerAction {
    TOGGLE_ANIMATION("Play/Pause", "start or stop the animation", GLFW_KEY_SPACE, 0, "Space"),
    TOGGLE_MESH_UPDATES("Mesh updates", "start or stop updating the mesh (the simulation keeps its time)",
            GLFW_KEY_U, 0, "U"),
    NEXT_METHOD("Method", "switch the skinning method (LBS, DQS, CoR, BFDQS, STBS-LBS, STBS-DQS, spline)", GLFW_KEY_M, 0,
            "M"),
    NEXT_INTERPOLATION("Interpolation", "switch the rotation interpolation (slerp, nlerp, lerp)", GLFW_KEY_I, 0, "I"),
    SLOWER("Slower", "play slower (x0.71)", GLFW_KEY_MINUS, 0, "-"),
    FASTER("Faster", "play faster (x1.41)", GLFW_KEY_EQUAL, 0, "+ (=)"),
    PREVIOUS_MESH("Previous mesh", "show the previous model", GLFW_KEY_PAGE_UP, 0, "Page Up"),
    NEXT_MESH("Next mesh", "show the next model", GLFW_KEY_PAGE_DOWN, 0, "Page Down"),
    CENTRE_CAMERA("Centre camera", "frame the model again", GLFW_KEY_C, 0, "C"),
    TOGGLE_FOLLOW_CAMERA("Follow camera", "AR mode: turn the model on the marker toward the camera", GLFW_KEY_F, 0, "F"),
    TOGGLE_GPU_SKINNING("GPU skinning", "skin in the vertex shader or on the CPU", GLFW_KEY_G, 0, "G"),
    NEXT_CLIP("Next clip", "play the model's next animation clip", GLFW_KEY_K, 0, "K"),
    STEP_BACK("Step back", "move the playback back 1/30 s", GLFW_KEY_COMMA, 0, ","),
    STEP_FORWARD("Step forward", "move the playback on 1/30 s", GLFW_KEY_PERIOD, 0, "."),
    FEWER_INSTANCES("Fewer", "fewer copies in the instance grid", GLFW_KEY_LEFT_BRACKET, 0, "["),
    MORE_INSTANCES("More", "more copies in the instance grid", GLFW_KEY_RIGHT_BRACKET, 0, "]"),
    TOGGLE_SKELETON("Skeleton", "show the joints and bones", GLFW_KEY_B, 0, "B"),
    TOGGLE_WIREFRAME("Wireframe", "draw the triangle edges", GLFW_KEY_W, 0, "W"),
    VIEW_SHADED("Shaded", "colours from materials and light", GLFW_KEY_1, 0, "1"),
    VIEW_WEIGHTS("Weights", "colour by the weight of the selected joint", GLFW_KEY_2, 0, "2"),
    VIEW_DIFFERENCE("Difference", "colour by how far LBS and DQS place each vertex apart", GLFW_KEY_3, 0, "3"),
    VIEW_CHECKER("Checker", "shaded, with a checker fixed to the rest shape (twist and stretch show)", GLFW_KEY_4, 0,
            "4"),
    TOGGLE_BIND_POSE("Bind pose", "show the bind pose (every joint at its bind frame) instead of the clip",
            GLFW_KEY_P, 0, "P"),
    PREVIOUS_JOINT("Previous joint", "select the previous joint (weight view)", GLFW_KEY_J, GLFW_MOD_SHIFT,
            "Shift+J"),
    NEXT_JOINT("Next joint", "select the next joint (weight view)", GLFW_KEY_J, 0, "J"),
    TOGGLE_SPLIT("Split view", "the other skinning method beside this one, in sync", GLFW_KEY_S, 0, "S"),
    OPEN_FILE("Open...", "open a COLLADA file (or drop one on the window)", GLFW_KEY_O, 0, "O"),
    SCREENSHOT("Screenshot", "write the window to skinlab-DATE.png", GLFW_KEY_F12, 0, "F12"),
    TOGGLE_HELP("Help", "show or hide this list", GLFW_KEY_F1, 0, "F1 or H"),
    QUIT("Quit", "close the window", GLFW_KEY_ESCAPE, 0, "Esc");

    private final String label;
    private final String description;
    private final int key;
    private final int mods;
    private final String keyName;

    ViewerAction(String label, String description, int key, int mods, String keyName) {
        this.label = label;
        this.description = description;
        this.key = key;
        this.mods = mods;
        this.keyName = keyName;
    }

    public String label() {
        return label;
    }

    public String description() {
        return description;
    }

    public int key() {
        return key;
    }

    public int mods() {
        return mods;
    }

    public String keyName() {
        return keyName;
    }

    private static final ViewerAction[] ALL = values();

    /** The action on a key press with these modifiers (Shift counts; Caps and Num Lock do not). */
    public static Optional<ViewerAction> forKey(int key, int mods) {
        int shift = mods & GLFW_MOD_SHIFT;
        if ((mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER)) != 0) {
            return Optional.empty();
        }
        for (ViewerAction a : ALL) {
            if (a.key == key && a.mods == shift) {
                return Optional.of(a);
            }
        }
        // Second keys: keypad signs, H for help, shifted '=' for '+'.
        switch (key) {
            case GLFW_KEY_KP_SUBTRACT:
                return Optional.of(SLOWER);
            case GLFW_KEY_KP_ADD:
                return Optional.of(FASTER);
            case GLFW_KEY_EQUAL:
                return Optional.of(FASTER);
            case GLFW_KEY_H:
                return Optional.of(TOGGLE_HELP);
            default:
                return Optional.empty();
        }
    }

    /** An action by enum name (any case, '-' or '_') or by its label; for scripts. */
    public static Optional<ViewerAction> byName(String name) {
        String n = name.trim().toUpperCase(Locale.ROOT).replace('-', '_').replace(' ', '_');
        for (ViewerAction a : ALL) {
            if (a.name().equals(n) || a.label.equalsIgnoreCase(name.trim())) {
                return Optional.of(a);
            }
        }
        return Optional.empty();
    }
}
