package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.desktop.render.GlTestDisplay;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.render.Screenshot;
import org.skinlab.desktop.viewer.ModelLibrary;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * Directing the character in the window: the mixer panel driven by scripted clicks changes the
 * mixer's layers and cross-fades its base layer (read back from the simulation thread by the
 * script's expectations; on core's two-clip glTF fixture), and root motion moves the drawn model,
 * which the camera keeps in view (humanoid-moves walking: 1.2 m per loop).
 */
class MixerWindowTest {
    private static final Path FIXTURE = Path.of(System.getProperty("skinlab.root", ".."))
            .resolve("core/src/test/resources/gltf/anim-interpolation.gltf");
    private static final Path MOVER = Pictures.asset("characters/humanoid-moves.glb");

    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    @Test
    void scriptedClicksSetUpLayersAndCrossFade(@TempDir Path dir) throws IOException {
        Path script = dir.resolve("mixer.txt");
        Files.write(script, List.of(
                // The panel is drawn once the model is shown.
                "wait 3",
                "expect layers 1",
                "expect layer 0 base: clip-a 1.00, weight 1.00, all joints, override",
                "click Add layer", "wait 2",
                "expect layers 2",
                "expect layer 1 layer 1: nothing",
                // A combo's list is laid out over the frames after it opens.
                "click layer 1 clip", "wait 3", "click layer 1 clip: clip-b", "wait 2",
                "expect layer 1 layer 1: clip-b 1.00, weight 1.00",
                // The middle of the slider: half the weight.
                "click layer 1 weight", "wait 2",
                "expect layer 1 weight 0.50",
                "click layer 1 mask", "wait 3", "click layer 1 mask: below joint1", "wait 2",
                "click layer 1 additive", "wait 2",
                "expect layer 1 layer 1: clip-b 1.00, weight 0.50, below joint1, additive",
                "click Cross-fade to", "wait 3", "click cross-fade to: clip-b", "wait 2",
                // The middle of 0.1 to 2 s: about a second.
                "click Fade duration", "wait 2",
                "click Cross-fade", "wait 1",
                "expect layer 0 fading",
                "wait-seconds 2",
                "expect layer 0 base: clip-b 1.00, weight 1.00, all joints, override",
                "click layer 1 remove", "wait 2",
                "expect layers 1",
                "click Blend pad", "wait 2",
                "expect layer 0 blend space",
                "click Root motion", "wait 2",
                "expect layer 0 root motion",
                "screenshot mixer.png",
                "quit"));
        ViewerWindowTest.Run r = ViewerWindowTest.skinlab("view", FIXTURE.toString(), "--gl-debug", "--size",
                "1280x900", "--script", script.toString());
        assertEquals(0, r.status(), r::toString);
        assertTrue(r.out().contains("no OpenGL errors reported"), r::toString);
        assertTrue(Files.size(dir.resolve("mixer.png")) > 1000);
    }

    @Test
    void anExpectationOnALayerTheMixerLacksFailsTheRun(@TempDir Path dir) throws IOException {
        Path script = dir.resolve("bad.txt");
        Files.write(script, List.of("expect layer 3 anything", "quit"));
        ViewerWindowTest.Run r = ViewerWindowTest.skinlab("view", FIXTURE.toString(), "--hide-ui", "--size", "320x200",
                "--script", script.toString());
        assertEquals(1, r.status(), r::toString);
        assertTrue(r.err().contains(
                "line 1: expected layer 3 to contain \"anything\" but it reads \"no layer 3 (the mixer has 1)\""),
                r::toString);
    }

    @Test
    void rootMotionMovesTheDrawnModelAndTheCameraFollows() {
        int width = 640;
        int height = 480;
        AnimationConfig config = new AnimationConfig();
        try (GlWindow window = GlTestDisplay.window("skinlab", width, height, false);
                Viewer viewer = new Viewer(ModelLibrary.find(), config, false)) {
            assertNull(viewer.openAndWait(MOVER));
            SkeletalAnimatedMesh mesh = viewer.current().mesh();
            MutableSceneReadout readout = new MutableSceneReadout();
            readout.viewer = viewer;
            readout.area.set(0, 0, width, height);
            try (ScenePainter scene = new ScenePainter(window, viewer, config, null, readout, null)) {
                mesh.direct(m -> m.base().play("walk"));
                mesh.step(0);
                float[] before = centroid(scene, width, height);
                Vector3f targetBefore = new Vector3f(viewer.camera().target());
                mesh.direct(m -> m.setRootMotion("walk", true));
                // Two loops: 2.4 m forward, more than the model's height.
                for (int i = 0; i < 20; i++) {
                    mesh.step(0.1);
                }
                float[] after = centroid(scene, width, height);
                Matrix4f placement = new Matrix4f();
                try (Frame f = mesh.acquire()) {
                    f.placement(placement);
                }
                assertFalse(placement.equals(new Matrix4f(), 1e-4f), "root motion left the placement at identity");
                float moved = viewer.camera().target().distance(targetBefore);
                float radius = viewer.current().framing().radius();
                assertTrue(moved > 2f * radius, "the camera followed " + moved + " for a model of radius " + radius);
                // Drawn where the placement puts it, the model stays where the following camera looks.
                assertTrue(Math.abs(after[0] - before[0]) < 0.05f * width && Math.abs(after[1] - before[1]) < 0.05f
                        * height, "the model's pixels moved from " + before[0] + ", " + before[1] + " to " + after[0]
                        + ", " + after[1]);
            }
        }
    }

    /** Paints a frame into the whole window; the centre (x, y) of the model's pixels. */
    private static float[] centroid(ScenePainter scene, int width, int height) {
        glViewport(0, 0, width, height);
        glClearColor(0.17f, 0.18f, 0.21f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        MutableSceneReadout r = new MutableSceneReadout();
        r.area.set(0, 0, width, height);
        assertTrue(scene.paint(width, height, r.area));
        ByteBuffer rgba = Screenshot.read(0, 0, width, height);
        int[] rgb = new int[width * height];
        try {
            for (int y = 0; y < height; y++) {
                for (int x = 0; x < width; x++) {
                    int i = 4 * ((height - 1 - y) * width + x);
                    rgb[y * width + x] = (rgba.get(i) & 0xFF) << 16 | (rgba.get(i + 1) & 0xFF) << 8
                            | rgba.get(i + 2) & 0xFF;
                }
            }
        } finally {
            MemoryUtil.memFree(rgba);
        }
        boolean[] model = Pictures.model(new Pictures.Picture(width, height, rgb));
        double sx = 0;
        double sy = 0;
        int n = 0;
        for (int i = 0; i < model.length; i++) {
            if (model[i]) {
                sx += i % width;
                sy += i / width;
                n++;
            }
        }
        assertTrue(n > width * height / 100, "the model covers " + n + " pixels only");
        return new float[] {(float) (sx / n), (float) (sy / n)};
    }
}
