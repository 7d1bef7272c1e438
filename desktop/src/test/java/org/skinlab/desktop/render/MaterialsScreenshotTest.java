package org.skinlab.desktop.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.lwjgl.stb.STBImage;
import org.lwjgl.system.MemoryStack;
import org.skinlab.desktop.app.ViewerWindowTestAccess;

/**
 * glTF materials reach the screen: {@code skinlab view --screenshot} of core's
 * {@code gltf/materials.glb} (tools/gltf/make-fixtures.py: unit quads in a 3 x 3 grid, one
 * material feature each), from the front and from behind, with colours checked at the quads'
 * quarter points; and {@code gltf/skin-textured.glb}, skinned and textured, at rest and slid, with
 * every method. The pictures stay in {@code desktop/build/materials-shots} to be looked at.
 *
 * <p>Lit colours are the base colour times about 0.8 to 1 (the viewer's key light, fill and
 * ambient on a quad facing the camera), so the checks ask for a dominant channel above 150 and
 * the others below 90; unlit colours are exact within 3 of 255.
 */
class MaterialsScreenshotTest {
    private static final int SIZE = 400;

    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    private static Path root() {
        for (Path d = Path.of("").toAbsolutePath(); d != null; d = d.getParent()) {
            if (Files.exists(d.resolve("settings.gradle"))) {
                return d;
            }
        }
        throw new IllegalStateException("no settings.gradle above " + Path.of("").toAbsolutePath());
    }

    private static Picture shoot(String name, String... options) throws Exception {
        return shootFile("materials.glb", name, options);
    }

    private static Picture shootFile(String file, String name, String... options) throws Exception {
        Path glb = root().resolve("core/src/test/resources/gltf/" + file);
        Path shot = root().resolve("desktop/build/materials-shots/" + name + ".png");
        Files.createDirectories(shot.getParent());
        String[] args = {"view", glb.toString(), "--hide-ui", "--size", SIZE + "x" + SIZE, "--screenshot",
                shot.toString()};
        String[] all = Arrays.copyOf(args, args.length + options.length);
        System.arraycopy(options, 0, all, args.length, options.length);
        assertEquals(0, ViewerWindowTestAccess.run(all));
        return new Picture(shot);
    }

    // Where the quads land in a 400 x 400 picture from the front (yaw 0; the viewer frames the
    // grid, looking slightly down): columns at x = 115, 200, 290, rows at y = 110, 200, 280.
    // Seen from behind (yaw 180) the columns swap sides.

    @Test
    void everyMaterialFeatureShowsFromTheFront() throws Exception {
        Picture p = shoot("front", "--yaw", "0");
        checkFront(p);
    }

    @Test
    void theCpuSkinnedPathDrawsTheSameMaterials() throws Exception {
        checkFront(shoot("front-cpu", "--yaw", "0", "--cpu"));
    }

    private static void checkFront(Picture p) {
        // The four-colour texture the right way up: red, green / blue, yellow.
        p.expect(100, 95, "quadrants top left", RED);
        p.expect(140, 95, "quadrants top right", GREEN);
        p.expect(100, 130, "quadrants bottom left", BLUE);
        p.expect(140, 130, "quadrants bottom right", YELLOW);
        // KHR_texture_transform, a quarter turn: glTF uv' = (v, 1 - u) turns the picture.
        p.expect(185, 95, "turned top left", BLUE);
        p.expect(222, 95, "turned top right", RED);
        p.expect(185, 130, "turned bottom left", YELLOW);
        p.expect(222, 130, "turned bottom right", GREEN);
        // MASK: the texture's left half (alpha 0.2) is cut out, the right half (0.9) is drawn opaque.
        p.expectBackground(272, 110, "cutout left half");
        p.expect(305, 110, "cutout right half", GREEN);
        // BLEND, listed before the opaque red quad behind it: drawn after it, blue over red.
        int[] glass = p.at(115, 200);
        assertTrue(glass[0] > 60 && glass[2] > 60 && glass[1] < 30 && Math.abs(glass[0] - glass[2]) < 40,
                "blue at alpha 0.5 over red: " + Arrays.toString(glass));
        // Emission added to a black base: green, whatever the light.
        p.expect(200, 200, "emissive", GREEN);
        // Unlit: the base colour (1, 0.5, 0) exactly.
        p.expectExactly(285, 200, "unlit", 255, 128, 0);
        // Quads facing away: single-sided culled, double-sided drawn.
        p.expectBackground(115, 280, "single-sided quad seen from behind");
        p.expect(200, 280, "double-sided quad seen from behind", YELLOW);
        // COLOR_0 (1, 0, 1) times a white base colour.
        p.expect(285, 280, "vertex colours", MAGENTA);
    }

    @Test
    void fromBehindSingleSidedQuadsFacingTheCameraAreCulled() throws Exception {
        Picture p = shoot("behind", "--yaw", "180");
        // The top row faces +Z: from behind, all three are culled.
        p.expectBackground(290, 110, "quadrants from behind");
        p.expectBackground(200, 110, "turned from behind");
        p.expectBackground(115, 110, "cutout from behind");
        // The quad facing -Z is now seen from its front; the double-sided one from either side.
        p.expect(285, 280, "single-sided quad facing the camera", CYAN);
        p.expect(200, 280, "double-sided quad from its back", YELLOW);
        p.expectBackground(115, 280, "vertex-coloured quad from behind");
        // The glass and the red quad behind it are single-sided too.
        p.expectBackground(285, 200, "glass and red quad from behind");
    }

    @Test
    void theWeightViewIgnoresAlphaButKeepsCulling() throws Exception {
        Picture p = shoot("weights", "--yaw", "0", "--view", "weights");
        int[] cut = p.at(272, 110);
        assertTrue(!p.isBackground(cut), "the cutout's masked half is coloured: " + Arrays.toString(cut));
        p.expectBackground(115, 280, "single-sided quad seen from behind");
    }

    /**
     * skin-textured.glb: a 1 x 2 strip with the four-colour picture whose upper half follows a
     * joint sliding 0.5 along +X by t = 1 (0.45 at t = 0.9; the clip loops at its end), skinned on
     * the GPU with each method and on the CPU. At rest the upper quarters are red and green, the
     * lower left blue; slid, the red and green move one quarter right (the viewer frames the rest
     * pose: upper quarters at x = 160 and 235, y = 120; the next quarter to the right at 310).
     */
    @Test
    void aSkinnedTexturedStripIsTexturedWhereItsJointsPutIt() throws Exception {
        String[][] runs = {{"lbs", "--gpu"}, {"dqs", "--gpu"}, {"cor", "--gpu"}, {"lbs", "--cpu"}};
        for (String[] run : runs) {
            String label = run[0] + run[1];
            Picture rest = shootFile("skin-textured.glb", "strip-rest-" + run[0] + run[1], "--yaw", "0", "--time", "0",
                    "--method", run[0], run[1]);
            rest.expect(160, 120, label + " upper left at rest", RED);
            rest.expect(235, 120, label + " upper right at rest", GREEN);
            rest.expect(160, 270, label + " lower left at rest", BLUE);
            Picture slid = shootFile("skin-textured.glb", "strip-slid-" + run[0] + run[1], "--yaw", "0", "--time", "0.9",
                    "--method", run[0], run[1]);
            slid.expectBackground(160, 120, label + " where the upper left was");
            slid.expect(235, 120, label + " upper left slid right", RED);
            slid.expect(310, 120, label + " upper right slid right", GREEN);
        }
    }

    private static final int[] RED = {1, 0, 0};
    private static final int[] GREEN = {0, 1, 0};
    private static final int[] BLUE = {0, 0, 1};
    private static final int[] YELLOW = {1, 1, 0};
    private static final int[] MAGENTA = {1, 0, 1};
    private static final int[] CYAN = {0, 1, 1};

    /** A decoded screenshot, RGB, row 0 at the top. */
    private static final class Picture {
        final int width;
        final int height;
        final byte[] rgb;

        Picture(Path png) {
            try (MemoryStack stack = MemoryStack.stackPush()) {
                IntBuffer w = stack.mallocInt(1);
                IntBuffer h = stack.mallocInt(1);
                IntBuffer c = stack.mallocInt(1);
                ByteBuffer pixels = STBImage.stbi_load(png.toString(), w, h, c, 3);
                assertTrue(pixels != null, "readable " + png);
                width = w.get(0);
                height = h.get(0);
                rgb = new byte[3 * width * height];
                pixels.duplicate().get(rgb);
                STBImage.stbi_image_free(pixels);
            }
        }

        int[] at(int x, int y) {
            int o = 3 * (y * width + x);
            return new int[] {rgb[o] & 0xFF, rgb[o + 1] & 0xFF, rgb[o + 2] & 0xFF};
        }

        /** Channels marked 1 above 150, channels marked 0 below 90. */
        void expect(int x, int y, String what, int[] channels) {
            int[] c = at(x, y);
            for (int i = 0; i < 3; i++) {
                boolean ok = channels[i] == 1 ? c[i] > 150 : c[i] < 90;
                assertTrue(ok, what + " at (" + x + ", " + y + ") should be " + Arrays.toString(channels) + ": "
                        + Arrays.toString(c));
            }
        }

        void expectExactly(int x, int y, String what, int r, int g, int b) {
            int[] c = at(x, y);
            assertTrue(Math.abs(c[0] - r) <= 3 && Math.abs(c[1] - g) <= 3 && Math.abs(c[2] - b) <= 3,
                    what + " at (" + x + ", " + y + "): " + Arrays.toString(c));
        }

        /** The viewer's dark blue-grey background (or its floor grid's lines). */
        boolean isBackground(int[] c) {
            return c[0] < 70 && c[1] < 70 && c[2] < 80 && Math.max(c[0], Math.max(c[1], c[2]))
                    - Math.min(c[0], Math.min(c[1], c[2])) < 30;
        }

        void expectBackground(int x, int y, String what) {
            int[] c = at(x, y);
            assertTrue(isBackground(c), what + " at (" + x + ", " + y + ") shows the background: " + Arrays.toString(c));
        }
    }
}
