package org.skinlab.desktop.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.skinlab.desktop.viewer.LiveStats;
import org.skinlab.desktop.viewer.MixerReadout;
import org.skinlab.desktop.viewer.ModelLibrary;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.mixer.Mixer;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.skinning.SkinningMethod;

import imgui.ImGui;
import imgui.ImGuiIO;
import imgui.flag.ImGuiMouseButton;

/**
 * The mixer panel in Dear ImGui without a window (no backend: the test feeds ImGui its display
 * size, time and mouse), on core's two-clip fixture: clicks on its items change the mixer as they
 * say, and once the JIT has settled a frame of the panel allocates nothing on the Java heap but the
 * draw-list wrapper imgui-java makes for the pad.
 */
class MixerPanelTest {
    private static final Path FIXTURE = Path.of(System.getProperty("skinlab.root", ".."))
            .resolve("core/src/test/resources/gltf/anim-interpolation.gltf");
    private static final float WIDTH = 1280f;
    private static final float HEIGHT = 900f;

    private Viewer viewer;
    private MixerPanel panel;
    private final Map<String, float[]> rects = new HashMap<>();
    private final PanelLayout layout = new PanelLayout();
    private SceneReadout scene;

    @BeforeEach
    void open() {
        ImGui.createContext();
        ImGuiIO io = ImGui.getIO();
        io.setIniFilename(null);
        io.setDisplaySize(WIDTH, HEIGHT);
        io.getFonts().build();
        viewer = new Viewer(ModelLibrary.find(), new AnimationConfig(), false);
        assertNull(viewer.openAndWait(FIXTURE));
        scene = readout(viewer);
        panel = new MixerPanel(new Widgets(rects, action -> { }));
        // ImGui lays an auto-sized window out over its first frames.
        frame();
        frame();
    }

    @AfterEach
    void close() {
        viewer.close();
        ImGui.destroyContext();
    }

    private void frame() {
        ImGui.getIO().setDeltaTime(1f / 60f);
        layout.decide(WIDTH, HEIGHT, 19f);
        ImGui.newFrame();
        panel.draw(scene, layout);
        ImGui.render();
    }

    /** Clicks the item remembered under {@code name} as a user would: move there, press, release, a frame each. */
    private void click(String name) {
        float[] r = rects.get(name);
        assertTrue(r != null, "no item " + name + " was drawn (drawn: " + rects.keySet() + ")");
        ImGui.getIO().addMousePosEvent((r[0] + r[2]) / 2, (r[1] + r[3]) / 2);
        frame();
        ImGui.getIO().addMouseButtonEvent(ImGuiMouseButton.Left, true);
        frame();
        ImGui.getIO().addMouseButtonEvent(ImGuiMouseButton.Left, false);
        frame();
        frame();
    }

    /** The mixer's state after the changes handed over so far, read where it lives (a step by hand). */
    private String layer(int index) {
        AtomicReference<String> text = new AtomicReference<>();
        viewer.current().mesh().direct(m -> text.set(describe(m, index)));
        viewer.current().mesh().step(1.0 / 60);
        return text.get();
    }

    private static String describe(Mixer m, int index) {
        return m.layers().size() + " layers; " + MixerReadout.layer(m, index);
    }

    @Test
    void clicksChangeTheMixer() {
        click("Add layer");
        assertEquals("2 layers; layer 1: nothing, weight 1.00, all joints, override", layer(1));
        click("layer 1 clip");
        click("layer 1 clip: clip-b");
        click("layer 1 weight");
        click("layer 1 additive");
        click("layer 1 mask");
        click("layer 1 mask: below joint1");
        assertEquals("2 layers; layer 1: clip-b 1.00, weight 0.50, below joint1, additive", layer(1));
        click("Cross-fade to");
        click("cross-fade to: clip-b");
        click("Cross-fade");
        assertEquals("2 layers; base: clip-a 1.00 + clip-b 0.00, weight 1.00, all joints, override, fading", layer(0));
        click("layer 1 remove");
        assertTrue(layer(0).startsWith("1 layers;"), layer(0));
        assertNull(viewer.current().mesh().failure());
    }

    @Test
    void aFrameOfThePanelAllocatesNothing() {
        click("Add layer");
        click("Blend pad");
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        // Warm-up: the JIT compiles what the frames run (interpreted code allocates).
        for (int i = 0; i < 3000; i++) {
            frame();
        }
        long before = threads.getThreadAllocatedBytes(thread);
        int frames = 1000;
        for (int i = 0; i < frames; i++) {
            frame();
        }
        long bytes = threads.getThreadAllocatedBytes(thread) - before;
        // imgui-java wraps the window's draw list (the pad's) in a new object on every call: 24 bytes.
        assertTrue(bytes <= frames * 32L, bytes / (double) frames + " bytes per frame");
    }

    /** A scene readout holding the viewer only: the panel reads nothing else. */
    private static SceneReadout readout(Viewer viewer) {
        LiveStats stats = new LiveStats();
        SceneArea area = new SceneArea();
        return new SceneReadout() {
            @Override
            public Viewer viewer() {
                return viewer;
            }

            @Override
            public LiveStats stats() {
                return stats;
            }

            @Override
            public int width() {
                return (int) WIDTH;
            }

            @Override
            public int height() {
                return (int) HEIGHT;
            }

            @Override
            public SceneArea sceneArea() {
                return area;
            }

            @Override
            public int views() {
                return 1;
            }

            @Override
            public SkinningMethod viewMethod(int view) {
                return SkinningMethod.LBS;
            }

            @Override
            public boolean viewOnCpu(int view) {
                return false;
            }

            @Override
            public boolean drewMesh() {
                return true;
            }

            @Override
            public boolean gpuSkinned() {
                return true;
            }

            @Override
            public double clipTime() {
                return 0;
            }

            @Override
            public int vertices() {
                return 0;
            }

            @Override
            public int shaderInfluences() {
                return 4;
            }

            @Override
            public int cappedVertices() {
                return 0;
            }

            @Override
            public double maxDifference() {
                return Double.NaN;
            }

            @Override
            public double differenceFull() {
                return Double.NaN;
            }

            @Override
            public double lbsVolume() {
                return Double.NaN;
            }

            @Override
            public double dqsVolume() {
                return Double.NaN;
            }

            @Override
            public String volumeNote() {
                return "";
            }
        };
    }
}
