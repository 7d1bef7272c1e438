package org.skinlab.collada;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import com.code_intelligence.jazzer.junit.DictionaryEntries;
import com.code_intelligence.jazzer.junit.FuzzTest;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.skinlab.testing.ImporterFuzzing;

/**
 * Coverage-guided fuzzing of {@link ColladaImporter} with Jazzer: any bytes must give a model or a
 * {@link ColladaException} (the rule is {@link ImporterFuzzing#check}), quickly (5 s per input
 * when fuzzing).
 *
 * <p>{@code gradle test} runs it over its seeds (every {@code .dae} of our assets and fixtures)
 * and the committed findings in {@code ColladaImporterFuzzTestInputs/importGivesAModelOrARefusal/}
 * under the test resources (Jazzer's regression mode, a few seconds). {@code gradle fuzz
 * -Pminutes=N} fuzzes it with coverage guidance; a finding is written to that folder, where it
 * stays as a regression file. See {@code docs/importer.md}, "Fuzzing".
 */
class ColladaImporterFuzzTest {
    static Stream<Arguments> seeds() throws IOException {
        return ImporterFuzzing.seeds(".dae");
    }

    /*
     * The dictionary gives the mutator whole tokens of the format: element and attribute names
     * whose meaning the loaders switch on, semantics, and numbers at the edges of what they check.
     */
    @DictionaryEntries({
        "<COLLADA", "</COLLADA>", "<asset>", "<up_axis>", "<unit meter=\"", "<library_geometries>",
        "<geometry", "<mesh>", "<source", "<float_array", "<int_array", "<Name_array", "<IDREF_array",
        "<bool_array", "<technique_common>", "<accessor", "<param", "<vertices", "<input", "<triangles",
        "<polylist", "<polygons", "<tristrips", "<trifans", "<lines", "<vcount>", "<p>", "<ph>", "<h>",
        "<v>", "<library_controllers>", "<controller", "<skin", "<morph", "<bind_shape_matrix>",
        "<joints>", "<vertex_weights", "<targets>", "<library_visual_scenes>", "<visual_scene",
        "<node", "<instance_node", "<instance_geometry", "<instance_controller", "<skeleton>",
        "<bind_material>", "<instance_material", "<bind_vertex_input", "<matrix", "<translate",
        "<rotate", "<scale", "<lookat", "<skew", "<library_nodes>", "<library_animations>",
        "<animation", "<sampler", "<channel", "<library_animation_clips>", "<animation_clip",
        "<instance_animation", "<library_materials>", "<material", "<instance_effect",
        "<library_effects>", "<effect", "<profile_COMMON>", "<newparam", "<surface", "<sampler2D",
        "<init_from>", "<texture", "<library_images>", "<image", "<scene>", "<instance_visual_scene",
        " id=\"", " sid=\"", " name=\"", " url=\"", " source=\"", " target=\"", " count=\"",
        " stride=\"", " offset=\"", " set=\"", " semantic=\"", " symbol=\"", " type=\"", " material=\"",
        " start=\"", " end=\"", "VERTEX", "POSITION", "NORMAL", "TEXCOORD", "COLOR", "JOINT",
        "WEIGHT", "INV_BIND_MATRIX", "MORPH_TARGET", "MORPH_WEIGHT", "INPUT", "OUTPUT",
        "INTERPOLATION", "IN_TANGENT", "OUT_TANGENT", "LINEAR", "BEZIER", "HERMITE", "STEP",
        "float4x4", "Name", "IDREF", "NODE", "#", "/transform", "(0)(1)", ".X", ".ANGLE",
        "NaN", "INF", "-INF", "1.#QNAN", "0,5", "1e39", "-1", "2147483647", "4294967296",
    })
    // Regression mode: the first input also pays for Jazzer's setup (a class path scan, seconds on
    // a busy machine), hence 30 s; when fuzzing, gradle/fuzz.gradle bounds each input to 5 s.
    @Timeout(value = 30, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    @MethodSource("seeds")
    @FuzzTest
    void importGivesAModelOrARefusal(byte[] data) throws Throwable {
        ImporterFuzzing.check(data, "fuzz.dae", ColladaImporter::read, ColladaException.class);
    }
}
