package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL33C.*;

import java.nio.ByteBuffer;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.desktop.render.FloorGrid;
import org.skinlab.desktop.render.GlTestDisplay;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.render.Screenshot;
import org.skinlab.desktop.ui.ImGuiUi;
import org.skinlab.desktop.viewer.ModelLibrary;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.simulation.AnimationConfig;

/**
 * The toolbar, the numbers, the status line and the views' labels leave the model visible, down to
 * a 480x400 window (where even the toolbar collapses).
 * Each window frame is drawn as the app draws it (panels laid out, scene painted into the area they
 * leave, panels drawn over it), and the framebuffer is read twice: after the scene, where the
 * model's pixels are found, and after the interface, where those pixels must still hold the same
 * colours, every one of them (the views' labels have a row of their own under the scene).
 */
class PanelsLeaveTheModelVisibleTest {
    /** Colour levels (of 255, any channel) within which two pixels count as the same. */
    private static final int TOLERANCE = 12;
    /** ImGui lays its windows out over the first frames (an auto-sized window is measured, then placed). */
    private static final int FRAMES = 6;

    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    @ParameterizedTest(name = "{0}x{1}")
    @CsvSource({"480, 400", "640, 480", "800, 600", "1280, 800"})
    void noPanelCoversTheModel(int width, int height) {
        AnimationConfig config = new AnimationConfig();
        try (GlWindow window = GlTestDisplay.window("skinlab", width, height, false);
                Viewer viewer = new Viewer(ModelLibrary.find(), config, false)) {
            assertNull(viewer.openAndWait(viewer.library().defaultModel()));
            viewer.current().mesh().step(0.0);
            MutableSceneReadout readout = new MutableSceneReadout();
            readout.viewer = viewer;
            readout.width = width;
            readout.height = height;
            try (ScenePainter scene = new ScenePainter(window, viewer, config, null, readout, null);
                    ImGuiUi ui = new ImGuiUi(window, action -> { })) {
                int[] covered = null;
                for (int i = 0; i < FRAMES; i++) {
                    covered = drawAndCompare(scene, ui, readout, width, height);
                }
                int model = covered[0];
                assertTrue(model > width * height / 100, "the model covers " + model + " pixels only");
                assertEquals(0, covered[1], covered[1] + " of the model's " + model
                        + " pixels are covered by the interface at " + width + "x" + height);
            }
        }
    }

    /** One window frame; returns the model's pixels and how many of them the interface changed. */
    private static int[] drawAndCompare(ScenePainter scene, ImGuiUi ui, MutableSceneReadout readout, int width,
            int height) {
        readout.viewer.update();
        glViewport(0, 0, width, height);
        glClearColor(0.17f, 0.18f, 0.21f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        ui.layOut(width, height, readout.area);
        readout.drewMesh = scene.paint(width, height, readout.area);
        ByteBuffer before = Screenshot.read(0, 0, width, height);
        ui.render(readout);
        ByteBuffer after = Screenshot.read(0, 0, width, height);
        try {
            return modelPixelsCovered(before, after, width * height);
        } finally {
            MemoryUtil.memFree(before);
            MemoryUtil.memFree(after);
        }
    }

    private static int[] modelPixelsCovered(ByteBuffer before, ByteBuffer after, int pixels) {
        int[] background = rgb(before, 0);
        int model = 0;
        int covered = 0;
        for (int i = 0; i < pixels; i++) {
            int[] c = rgb(before, i);
            if (isBackgroundOrFloor(c, background)) {
                continue;
            }
            model++;
            int[] d = rgb(after, i);
            if (Math.max(Math.abs(c[0] - d[0]), Math.max(Math.abs(c[1] - d[1]), Math.abs(c[2] - d[2]))) > TOLERANCE) {
                covered++;
            }
        }
        return new int[] {model, covered};
    }

    /**
     * Whether a pixel is the background (the clear colour, in the corner the scene leaves to the
     * panels), or the floor's lines ({@link FloorGrid#COLOR}) blended over it at any opacity.
     */
    private static boolean isBackgroundOrFloor(int[] c, int[] background) {
        double[] floor = {255 * FloorGrid.COLOR.x() - background[0], 255 * FloorGrid.COLOR.y() - background[1],
                255 * FloorGrid.COLOR.z() - background[2]};
        double[] d = {c[0] - background[0], c[1] - background[1], c[2] - background[2]};
        double ff = floor[0] * floor[0] + floor[1] * floor[1] + floor[2] * floor[2];
        double a = Math.max(0, Math.min(1, (d[0] * floor[0] + d[1] * floor[1] + d[2] * floor[2]) / ff));
        double off = 0;
        for (int k = 0; k < 3; k++) {
            off = Math.max(off, Math.abs(d[k] - a * floor[k]));
        }
        return off <= TOLERANCE;
    }

    private static int[] rgb(ByteBuffer rgba, int pixel) {
        int o = 4 * pixel;
        return new int[] {rgba.get(o) & 0xFF, rgba.get(o + 1) & 0xFF, rgba.get(o + 2) & 0xFF};
    }
}
