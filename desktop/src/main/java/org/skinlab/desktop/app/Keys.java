package org.skinlab.desktop.app;

import static org.lwjgl.glfw.GLFW.*;

import java.util.Locale;

/** GLFW key codes by name, for scripts: letters, digits, F1-F12 and the named keys. */
final class Keys {
    private Keys() {
    }

    /** The GLFW key code of a name (SPACE, A, 7, F12, PAGE_DOWN, MINUS, ...), -1 when unknown. */
    static int code(String name) {
        String n = name.toUpperCase(Locale.ROOT).replace('-', '_');
        if (n.length() == 1) {
            char c = n.charAt(0);
            if (c >= 'A' && c <= 'Z') {
                return GLFW_KEY_A + (c - 'A');
            }
            if (c >= '0' && c <= '9') {
                return GLFW_KEY_0 + (c - '0');
            }
        }
        if (n.matches("F([1-9]|1[0-2])")) {
            return GLFW_KEY_F1 + Integer.parseInt(n.substring(1)) - 1;
        }
        switch (n) {
            case "SPACE":
                return GLFW_KEY_SPACE;
            case "ESCAPE":
            case "ESC":
                return GLFW_KEY_ESCAPE;
            case "ENTER":
                return GLFW_KEY_ENTER;
            case "PAGE_UP":
                return GLFW_KEY_PAGE_UP;
            case "PAGE_DOWN":
                return GLFW_KEY_PAGE_DOWN;
            case "MINUS":
                return GLFW_KEY_MINUS;
            case "EQUAL":
            case "PLUS":
                return GLFW_KEY_EQUAL;
            case "COMMA":
                return GLFW_KEY_COMMA;
            case "PERIOD":
                return GLFW_KEY_PERIOD;
            case "LEFT_BRACKET":
                return GLFW_KEY_LEFT_BRACKET;
            case "RIGHT_BRACKET":
                return GLFW_KEY_RIGHT_BRACKET;
            case "LEFT":
                return GLFW_KEY_LEFT;
            case "RIGHT":
                return GLFW_KEY_RIGHT;
            case "UP":
                return GLFW_KEY_UP;
            case "DOWN":
                return GLFW_KEY_DOWN;
            default:
                return -1;
        }
    }

    /** The GLFW modifier bit of shift, ctrl, alt; -1 when unknown. */
    static int modifier(String name) {
        switch (name.toLowerCase(Locale.ROOT)) {
            case "shift":
                return GLFW_MOD_SHIFT;
            case "ctrl":
            case "control":
                return GLFW_MOD_CONTROL;
            case "alt":
                return GLFW_MOD_ALT;
            default:
                return -1;
        }
    }
}
