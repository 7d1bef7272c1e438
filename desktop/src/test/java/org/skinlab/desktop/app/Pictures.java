package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.nio.ByteBuffer;
import java.nio.IntBuffer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.joml.Vector4fc;
import org.lwjgl.stb.STBImage;
import org.lwjgl.system.MemoryStack;
import org.skinlab.desktop.render.FloorGrid;

/**
 * The viewer's pictures as the tests measure them: {@code skinlab view --screenshot} run in this
 * JVM, the PNG read back, the model's pixels told from the scene's, and the halves of a split view
 * compared. A pixel is the scene's when it is the background (the picture's top-left pixel, which
 * the framing leaves free) or the background with the floor's lines ({@link FloorGrid#COLOR})
 * blended over it at any opacity.
 */
final class Pictures {
    /** Colour levels (of 255, any channel) within which two pixels count as the same. */
    static final int TOLERANCE = 12;

    /** A picture's pixels, 0xRRGGBB row by row from the top. */
    record Picture(int width, int height, int[] rgb) {
        int at(int x, int y) {
            return rgb[y * width + x];
        }

        /** The left (0) or right (1) half of a split view. */
        Picture half(int which) {
            int w = width / 2;
            int[] out = new int[w * height];
            for (int y = 0; y < height; y++) {
                System.arraycopy(rgb, y * width + which * w, out, y * w, w);
            }
            return new Picture(w, height, out);
        }
    }

    private Pictures() {
    }

    /** Renders {@code skinlab view FILE ARGS... --hide-ui --size WxH --screenshot dir/name.png} and reads it. */
    static Picture view(Path dir, String name, Path file, int width, int height, String... args) {
        Path png = dir.resolve(name + ".png");
        List<String> command = new ArrayList<>(List.of("view", file.toString()));
        command.addAll(List.of(args));
        command.addAll(List.of("--hide-ui", "--size", width + "x" + height, "--screenshot", png.toString()));
        ViewerWindowTest.Run r = ViewerWindowTest.skinlab(command.toArray(new String[0]));
        assertEquals(0, r.status(), r::toString);
        return read(png);
    }

    static Path asset(String relative) {
        return Path.of(System.getProperty("skinlab.root", "..")).resolve("assets").resolve(relative);
    }

    static Picture read(Path png) {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer w = stack.mallocInt(1);
            IntBuffer h = stack.mallocInt(1);
            IntBuffer c = stack.mallocInt(1);
            ByteBuffer pixels = STBImage.stbi_load(png.toString(), w, h, c, 3);
            assertNotNull(pixels, png + ": " + STBImage.stbi_failure_reason());
            try {
                int[] rgb = new int[w.get(0) * h.get(0)];
                for (int i = 0; i < rgb.length; i++) {
                    rgb[i] = (pixels.get(3 * i) & 0xFF) << 16 | (pixels.get(3 * i + 1) & 0xFF) << 8
                            | (pixels.get(3 * i + 2) & 0xFF);
                }
                return new Picture(w.get(0), h.get(0), rgb);
            } finally {
                STBImage.stbi_image_free(pixels);
            }
        }
    }

    /** Per pixel (row by row), whether it shows the model. */
    static boolean[] model(Picture p) {
        int bg = p.at(0, 0);
        double br = red(bg);
        double bgg = green(bg);
        double bb = blue(bg);
        Vector4fc floor = FloorGrid.COLOR;
        double fr = 255 * floor.x() - br;
        double fg = 255 * floor.y() - bgg;
        double fb = 255 * floor.z() - bb;
        double ff = fr * fr + fg * fg + fb * fb;
        boolean[] model = new boolean[p.rgb().length];
        for (int i = 0; i < model.length; i++) {
            int c = p.rgb()[i];
            double dr = red(c) - br;
            double dg = green(c) - bgg;
            double db = blue(c) - bb;
            double a = ff > 0 ? Math.max(0, Math.min(1, (dr * fr + dg * fg + db * fb) / ff)) : 0;
            double off = Math.max(Math.abs(dr - a * fr), Math.max(Math.abs(dg - a * fg), Math.abs(db - a * fb)));
            model[i] = off > TOLERANCE;
        }
        return model;
    }

    /** The model's pixels of a picture. */
    static int count(boolean[] mask) {
        int n = 0;
        for (boolean m : mask) {
            n += m ? 1 : 0;
        }
        return n;
    }

    /**
     * Of the pixels either picture's model covers, the percent whose colours differ by more than
     * {@link #TOLERANCE} in some channel; 0 when neither shows a model.
     */
    static double differingPercent(Picture a, Picture b) {
        boolean[] ma = model(a);
        boolean[] mb = model(b);
        int union = 0;
        int differing = 0;
        for (int i = 0; i < ma.length; i++) {
            if (ma[i] || mb[i]) {
                union++;
                if (distance(a.rgb()[i], b.rgb()[i]) > TOLERANCE) {
                    differing++;
                }
            }
        }
        return union == 0 ? 0 : 100.0 * differing / union;
    }

    /**
     * Of the pixels both pictures' models cover, the percent whose colours differ by more than
     * {@link #TOLERANCE} in some channel (the surfaces' colours, outlines apart); 0 when they share none.
     */
    static double differingInsidePercent(Picture a, Picture b) {
        boolean[] ma = model(a);
        boolean[] mb = model(b);
        int both = 0;
        int differing = 0;
        for (int i = 0; i < ma.length; i++) {
            if (ma[i] && mb[i]) {
                both++;
                if (distance(a.rgb()[i], b.rgb()[i]) > TOLERANCE) {
                    differing++;
                }
            }
        }
        return both == 0 ? 0 : 100.0 * differing / both;
    }

    /** The largest difference of two colours in any channel (levels). */
    static int distance(int a, int b) {
        return Math.max(Math.abs(red(a) - red(b)),
                Math.max(Math.abs(green(a) - green(b)), Math.abs(blue(a) - blue(b))));
    }

    static int red(int c) {
        return c >> 16 & 0xFF;
    }

    static int green(int c) {
        return c >> 8 & 0xFF;
    }

    static int blue(int c) {
        return c & 0xFF;
    }
}
