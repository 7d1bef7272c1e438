package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.cli.SkinlabCommand;
import org.skinlab.desktop.render.GlTestDisplay;

/**
 * The window itself under a real (virtual) display: it opens and draws, every view and switch
 * runs without an OpenGL error in a debug context, scripted input changes the mesh, and a bad
 * file dropped on it leaves the app running with the importer's message.
 */
class ViewerWindowTest {
    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    record Run(int status, String out, String err) {
        @Override
        public String toString() {
            return "status " + status + "\n--- stdout\n" + out + "--- stderr\n" + err;
        }
    }

    static Run skinlab(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = SkinlabCommand.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new Run(status, out.toString(), err.toString());
    }

    private static Path script(Path dir, String... lines) throws IOException {
        Path file = dir.resolve("script.txt");
        Files.write(file, java.util.List.of(lines));
        return file;
    }

    @Test
    void theWindowOpensAndDraws() {
        Run r = skinlab("--exit-after-frames", "20", "--size", "640x400");
        assertEquals(0, r.status(), r::toString);
        assertTrue(r.out().contains("20 frames") && r.out().contains("characters/humanoid-walk.dae"), r::toString);
        // The simulation thread stops with the window.
        assertTrue(Thread.getAllStackTraces().keySet().stream()
                .noneMatch(t -> t.isAlive() && t.getName().startsWith("skinlab-simulation")), "a simulation thread lives on");
    }

    @Test
    void everyViewMethodAndSwitchRunsWithoutGlErrors(@TempDir Path dir) throws IOException {
        Path s = script(dir, "action skeleton", "action wireframe", "action more-instances", "wait 2",
                "action view-weights", "action next-joint", "wait 2", "action view-difference", "action split view",
                "wait 3", "click Auto scale", "wait 3", "click Auto scale", "click Red at", "wait 2",
                "action view-checker", "action toggle-bind-pose", "wait 3", "action toggle-bind-pose",
                "action view-difference", "wait 2", "action toggle-gpu-skinning", "wait 5", "action next-method",
                "action next-interpolation", "action next-method", "expect method COR", "wait 3", "action toggle-gpu-skinning", "wait 3",
                "action toggle-mesh-updates", "wait 2", "action toggle-animation", "action step-forward", "wait 2",
                "action help", "action centre-camera", "drag 600 300 650 320", "scroll 2", "wait 2",
                "screenshot all.png", "quit");
        Run r = skinlab("view", "--gl-debug", "--size", "800x500", "--script", s.toString());
        assertEquals(0, r.status(), r::toString);
        assertTrue(r.out().contains("no OpenGL errors reported"), r::toString);
        assertTrue(Files.size(dir.resolve("all.png")) > 1000);
    }

    @Test
    void everyMethodIsAToolbarButtonAndDrawsOnEitherSideWithoutGlErrors(@TempDir Path dir) throws IOException {
        // GPU skinning first: methods without shader code are skinned on the CPU and drawn as such.
        java.util.List<String> steps = new java.util.ArrayList<>();
        for (String side : new String[] {"gpu", "cpu"}) {
            for (org.skinlab.skinning.SkinningMethod m : org.skinlab.skinning.SkinningMethod.values()) {
                steps.add("click " + m.name());
                steps.add("wait 3");
                steps.add("expect method " + m.key());
            }
            steps.add("action toggle-gpu-skinning");
            steps.add("wait 2");
        }
        steps.add("quit");
        Path s = script(dir, steps.toArray(new String[0]));
        Run r = skinlab("view", "--gl-debug", "--size", "800x500", "--script", s.toString());
        assertEquals(0, r.status(), r::toString);
        assertTrue(r.out().contains("no OpenGL errors reported"), r::toString);
    }

    @Test
    void scriptedNextMeshAndABadDrop(@TempDir Path dir) throws IOException {
        Files.writeString(dir.resolve("bad.dae"), "<COLLADA><oops");
        // Each asset's .glb twin comes right after its .dae.
        Path s = script(dir, "expect mesh characters/humanoid-walk.dae", "click Next mesh", "wait 4", "wait-loaded",
                "expect mesh characters/humanoid-walk.glb", "key PAGE_DOWN", "wait-loaded",
                "expect mesh characters/humanoid-moves.dae", "key M", "expect method DQS", "drop bad.dae",
                "wait-loaded", "wait 2", "expect status bad.dae", "expect mesh characters/humanoid-moves.dae", "wait 5", "quit");
        Run r = skinlab("view", "--size", "800x500", "--script", s.toString());
        assertEquals(0, r.status(), r::toString);
        assertTrue(r.out().contains("model characters/humanoid-moves.dae"), r::toString);
    }

    @Test
    void aFailedExpectationFailsTheRun(@TempDir Path dir) throws IOException {
        Path s = script(dir, "expect mesh nothing.dae", "quit");
        Run r = skinlab("view", "--size", "320x200", "--hide-ui", "--script", s.toString());
        assertEquals(1, r.status(), r::toString);
        assertTrue(r.err().contains("script.txt line 1: expected mesh nothing.dae"), r::toString);
    }

    @Test
    void aBadScriptIsRefusedBeforeTheWindowOpens(@TempDir Path dir) throws IOException {
        Run r = skinlab("view", "--script", script(dir, "fly 3").toString());
        assertEquals(1, r.status(), r::toString);
        assertTrue(r.err().contains("line 1: unknown verb fly"), r::toString);
    }
}
