package org.skinlab.desktop.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.concurrent.atomic.AtomicReference;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.viewer.MixerControls.LayerChoice;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The mixer panel's choices without a window, on core's two-clip glTF fixture stepped by hand:
 * each choice reaches the mixer at the next step (read back there), a new model starts the
 * choices afresh, and what the mixer warns of comes back for the status line.
 */
class MixerControlsTest {
    private static final Path FIXTURE = Path.of(System.getProperty("skinlab.root", ".."))
            .resolve("core/src/test/resources/gltf/anim-interpolation.gltf");

    private static Viewer open(Path file) {
        Viewer v = new Viewer(ModelLibrary.find(), new AnimationConfig(), false);
        assertNull(v.openAndWait(file));
        return v;
    }

    /** Layer {@code index} as the mixer has it after the changes handed over so far (one step by hand). */
    private static String layer(SkeletalAnimatedMesh mesh, int index) {
        AtomicReference<String> text = new AtomicReference<>();
        mesh.direct(m -> text.set(MixerReadout.layer(m, index)));
        mesh.step(1.0 / 60);
        return text.get();
    }

    @Test
    void choicesReachTheMixerAtTheNextStep() {
        try (Viewer v = open(FIXTURE)) {
            MixerControls c = new MixerControls();
            c.show(v.current());
            SkeletalAnimatedMesh mesh = v.current().mesh();
            assertEquals(2, c.clipCount());
            assertEquals("base: clip-a 1.00, weight 1.00, all joints, override", layer(mesh, 0));
            assertEquals("all joints", c.maskLabel(0));
            assertEquals("below joint1", c.maskLabel(2));
            c.addLayer();
            LayerChoice l = c.layers().get(1);
            c.play(l, 1);
            c.setWeight(l, 0.254f);
            c.setMask(l, 2);
            c.setAdditive(l, true);
            assertEquals(0.25f, l.weight());
            assertEquals("layer 1: clip-b 1.00, weight 0.25, below joint1, additive", layer(mesh, 1));
            c.setAdditive(l, false);
            c.setMask(l, 0);
            assertEquals("layer 1: clip-b 1.00, weight 0.25, all joints, override", layer(mesh, 1));
            c.removeLayer(l);
            c.removeLayer(c.layers().get(0));
            assertEquals(1, c.layers().size(), "the base layer stays");
            assertEquals("no layer 1 (the mixer has 1)", layer(mesh, 1));
            assertNull(c.takeMessage());
        }
    }

    @Test
    void aCrossFadeThenThePadDriveTheBaseLayer() {
        try (Viewer v = open(FIXTURE)) {
            MixerControls c = new MixerControls();
            c.show(v.current());
            SkeletalAnimatedMesh mesh = v.current().mesh();
            c.setFadeTarget(1);
            c.setFadeSeconds(5f);
            assertEquals(MixerControls.MAX_FADE_SECONDS, c.fadeSeconds());
            c.setFadeSeconds(0.5f);
            c.crossFade();
            assertTrue(layer(mesh, 0).endsWith(", fading"), layer(mesh, 0));
            for (int i = 0; i < 30; i++) {
                mesh.step(1.0 / 60);
            }
            assertEquals("base: clip-b 1.00, weight 1.00, all joints, override", layer(mesh, 0));
            assertEquals(1, c.layers().get(0).clip());
            // Two clips: on a circle, clip-a at the top and clip-b at the bottom; the centre mixes them equally.
            BlendPad pad = c.pad();
            assertEquals(2, pad.clipCount());
            assertTrue(pad.space().isPlanar());
            c.movePad(0.5f, 0.5f);
            assertTrue(c.padDrives());
            assertEquals("base: clip-a 0.50 + clip-b 0.50, weight 1.00, all joints, override, blend space",
                    layer(mesh, 0));
            c.movePad(0.5f, 1f);
            assertEquals("base: clip-a 1.00 + clip-b 0.00, weight 1.00, all joints, override, blend space",
                    layer(mesh, 0));
            c.setRootMotion(true);
            assertTrue(c.rootMotion());
            assertTrue(layer(mesh, 0).endsWith("blend space, root motion"), layer(mesh, 0));
            c.play(c.layers().get(0), 0);
            assertFalse(c.padDrives());
            assertTrue(c.rootMotion(), "root motion is per clip: clip-a kept it");
            for (int i = 0; i < 60; i++) {
                mesh.step(1.0 / 60);
            }
            Matrix4f placement = new Matrix4f();
            try (Frame f = mesh.acquire()) {
                f.placement(placement);
            }
            assertFalse(placement.equals(new Matrix4f(), 1e-4f));
            c.resetPlacement();
            mesh.step(0);
            try (Frame f = mesh.acquire()) {
                assertTrue(f.placement(placement).equals(new Matrix4f(), 1e-6f), placement.toString());
            }
        }
    }

    @Test
    void aNewModelStartsTheChoicesAfresh() throws InterruptedException {
        try (Viewer v = open(FIXTURE)) {
            MixerControls c = new MixerControls();
            c.show(v.current());
            c.addLayer();
            c.setRootMotion(true);
            v.playClip(1);
            await(v);
            c.show(v.current());
            assertEquals(1, c.layers().size());
            assertEquals(1, c.layers().get(0).clip(), "the base plays the clip the model was loaded with");
            assertFalse(c.rootMotion());
            c.show(null);
            assertFalse(c.hasModel());
            c.addLayer();
            assertTrue(c.layers().isEmpty());
        }
    }

    private static void await(Viewer v) throws InterruptedException {
        LoadedModel before = v.current();
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (v.current() == before) {
            assertTrue(System.nanoTime() < deadline, "timed out; status: " + v.statusMessage());
            Thread.sleep(10);
            v.update();
        }
    }

    @Test
    void theMixersWarningComesBackForTheStatusLine(@TempDir Path dir) throws Exception {
        // The fixture with clip-b no longer animating joint2: blended with clip-a, it has no say there.
        ObjectMapper json = new ObjectMapper();
        JsonNode gltf = json.readTree(FIXTURE.toFile());
        for (JsonNode a : gltf.get("animations")) {
            if (a.get("name").asText().equals("clip-b")) {
                for (Iterator<JsonNode> it = a.get("channels").elements(); it.hasNext();) {
                    if (it.next().get("target").get("node").asInt() == 2) {
                        it.remove();
                    }
                }
            }
        }
        Path file = dir.resolve("partial.gltf");
        json.writeValue(file.toFile(), (ObjectNode) gltf);
        assertTrue(Files.size(file) > 0);
        try (Viewer v = open(file)) {
            MixerControls c = new MixerControls();
            c.show(v.current());
            c.movePad(0.5f, 0.5f);
            v.current().mesh().step(1.0 / 60);
            String message = c.takeMessage();
            assertTrue(message != null && message.contains("clip \"clip-b\" does not animate 1 joint")
                    && message.contains("joint2"), message);
            assertNull(c.takeMessage(), "each message once");
        }
    }
}
