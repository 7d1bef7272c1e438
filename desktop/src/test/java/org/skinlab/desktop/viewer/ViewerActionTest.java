package org.skinlab.desktop.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.*;

import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;

class ViewerActionTest {
    @Test
    void everyActionHasItsOwnKey() {
        Map<Long, ViewerAction> seen = new HashMap<>();
        for (ViewerAction a : ViewerAction.values()) {
            ViewerAction before = seen.put(((long) a.key() << 8) | a.mods(), a);
            assertEquals(null, before, a + " and " + before + " share " + a.keyName());
            assertEquals(a, ViewerAction.forKey(a.key(), a.mods()).orElseThrow(), a.toString());
            assertFalse(a.label().isBlank());
            assertFalse(a.description().isBlank());
        }
    }

    @Test
    void theThesisFunctionsAreThere() {
        for (String name : new String[] {"toggle-animation", "toggle-mesh-updates", "next-method", "next-interpolation",
                "slower", "faster", "previous-mesh", "next-mesh", "centre-camera"}) {
            assertTrue(ViewerAction.byName(name).isPresent(), name);
        }
    }

    @Test
    void namesLabelsAndSecondKeys() {
        assertEquals(ViewerAction.TOGGLE_SPLIT, ViewerAction.byName("Split view").orElseThrow());
        assertEquals(ViewerAction.NEXT_MESH, ViewerAction.byName("next_mesh").orElseThrow());
        assertFalse(ViewerAction.byName("no such thing").isPresent());
        assertEquals(ViewerAction.FASTER, ViewerAction.forKey(GLFW_KEY_KP_ADD, 0).orElseThrow());
        assertEquals(ViewerAction.TOGGLE_HELP, ViewerAction.forKey(GLFW_KEY_H, 0).orElseThrow());
        assertEquals(ViewerAction.PREVIOUS_JOINT, ViewerAction.forKey(GLFW_KEY_J, GLFW_MOD_SHIFT).orElseThrow());
        // Caps Lock changes nothing; Ctrl combinations are not the viewer's.
        assertEquals(ViewerAction.NEXT_JOINT, ViewerAction.forKey(GLFW_KEY_J, GLFW_MOD_CAPS_LOCK).orElseThrow());
        assertFalse(ViewerAction.forKey(GLFW_KEY_S, GLFW_MOD_CONTROL).isPresent());
    }
}
