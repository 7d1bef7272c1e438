package org.skinlab.desktop.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.lwjgl.stb.STBImage;
import org.lwjgl.stb.STBImageWrite;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.desktop.app.ViewerWindowTestAccess;

/**
 * Materials and textures reach the screen: a quad facing the camera whose lambert material takes
 * its diffuse colour from a two-colour PNG (red on the left half of the image, blue on the right,
 * so a flipped or unbound texture shows). COLLADA's texture coordinate (0, 0) is the image's
 * bottom left.
 */
class TexturedQuadTest {
    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    private static final String QUAD = """
            <?xml version="1.0" encoding="utf-8"?>
            <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
              <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
              <library_images><image id="img"><init_from>halves.png</init_from></image></library_images>
              <library_effects><effect id="fx"><profile_COMMON>
                <newparam sid="surf"><surface type="2D"><init_from>img</init_from></surface></newparam>
                <newparam sid="samp"><sampler2D><source>surf</source></sampler2D></newparam>
                <technique sid="common"><lambert><diffuse><texture texture="samp" texcoord="UV"/></diffuse></lambert>
                </technique></profile_COMMON></effect></library_effects>
              <library_materials><material id="mat"><instance_effect url="#fx"/></material></library_materials>
              <library_geometries><geometry id="quad"><mesh>
                <source id="p"><float_array id="pa" count="12">-1 -1 0 1 -1 0 1 1 0 -1 1 0</float_array>
                  <technique_common><accessor source="#pa" count="4" stride="3">
                  <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                  </accessor></technique_common></source>
                <source id="t"><float_array id="ta" count="8">0 0 1 0 1 1 0 1</float_array>
                  <technique_common><accessor source="#ta" count="4" stride="2">
                  <param name="S" type="float"/><param name="T" type="float"/></accessor></technique_common></source>
                <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
                <triangles material="m" count="2"><input semantic="VERTEX" source="#v" offset="0"/>
                  <input semantic="TEXCOORD" source="#t" offset="1" set="0"/>
                  <p>0 0 1 1 2 2 0 0 2 2 3 3</p></triangles>
              </mesh></geometry></library_geometries>
              <library_visual_scenes><visual_scene id="s"><node id="n">
                <instance_geometry url="#quad"><bind_material><technique_common>
                  <instance_material symbol="m" target="#mat">
                    <bind_vertex_input semantic="UV" input_semantic="TEXCOORD" input_set="0"/>
                  </instance_material></technique_common></bind_material></instance_geometry>
              </node></visual_scene></library_visual_scenes>
              <scene><instance_visual_scene url="#s"/></scene>
            </COLLADA>
            """;

    @Test
    void theTextureIsDrawnTheRightWayRound(@TempDir Path dir) throws Exception {
        // 8x8: left half red, right half blue, top row green (to tell up from down).
        int size = 8;
        ByteBuffer png = MemoryUtil.memAlloc(size * size * 3);
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                int o = 3 * (y * size + x);
                boolean top = y < 2;
                png.put(o, (byte) (top ? 0 : x < size / 2 ? 255 : 0));
                png.put(o + 1, (byte) (top ? 255 : 0));
                png.put(o + 2, (byte) (top ? 0 : x < size / 2 ? 0 : 255));
            }
        }
        assertTrue(STBImageWrite.stbi_write_png(dir.resolve("halves.png").toString(), size, size, 3, png, 3 * size));
        MemoryUtil.memFree(png);
        Path dae = dir.resolve("quad.dae");
        Files.writeString(dae, QUAD);
        Path shot = dir.resolve("shot.png");
        int status = ViewerWindowTestAccess.run("view", dae.toString(), "--hide-ui", "--size", "300x300",
                "--screenshot", shot.toString());
        assertEquals(0, status);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer w = stack.mallocInt(1);
            IntBuffer h = stack.mallocInt(1);
            IntBuffer c = stack.mallocInt(1);
            ByteBuffer pixels = STBImage.stbi_load(shot.toString(), w, h, c, 3);
            try {
                int[] left = rgb(pixels, w.get(0), 120, 170);
                int[] right = rgb(pixels, w.get(0), 180, 170);
                int[] top = rgb(pixels, w.get(0), 120, 75);
                assertTrue(left[0] > 100 && left[2] < 40, "left of the quad is red: " + java.util.Arrays.toString(left));
                assertTrue(right[2] > 100 && right[0] < 40, "right is blue: " + java.util.Arrays.toString(right));
                assertTrue(top[1] > 100 && top[0] < 40, "top is green: " + java.util.Arrays.toString(top));
            } finally {
                STBImage.stbi_image_free(pixels);
            }
        }
    }

    private static int[] rgb(ByteBuffer p, int width, int x, int y) {
        int o = 3 * (y * width + x);
        return new int[] {p.get(o) & 0xFF, p.get(o + 1) & 0xFF, p.get(o + 2) & 0xFF};
    }
}
