package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * Animation import of third-party corpus files (../shared/corpus; skipped when absent).
 *
 * <p>How the expected numbers were derived, independently of the importer: a Python 3 script
 * using only xml.etree walked each file, followed every {@code <channel>} at any depth of
 * {@code <animation>} to its sampler, counted INPUT accessor {@code count} (keys) and OUTPUT
 * accessor {@code stride} (values per key), resolved the target's node id in the visual scene
 * (following {@code <instance_node>}) and its sid to a {@code <matrix>}, took the first and last
 * key time texts, and listed each {@code <animation_clip>} with its attributes and
 * {@code instance_animation} urls. It also checked that no keyed matrix has a bottom row other
 * than (0 0 0 1). The values quoted below are that script's output.
 */
class AnimationCorpusTest {
    /** Times and values are parsed from the same text: exact. */
    private static final float EXACT = 0f;

    private static Model read(String name) throws Exception {
        return ColladaImporter.read(TestPaths.corpusFileOrSkip(name));
    }

    /** No warning about animations (other parts of a file may warn; not this test's business). */
    private static void assertNoAnimationWarnings(Model m) {
        List<ImportWarning> w = m.warnings().stream()
                .filter(x -> x.element().contains("<channel") || x.element().contains("sampler")
                        || x.element().contains("<animation") || x.element().contains("<input"))
                .collect(Collectors.toList());
        assertEquals(List.of(), w);
    }

    @Test
    void s11NestedAnimationHasOneMatrixChannelOfFortyKeys() throws Exception {
        // Script: action_container-Armature (0 channels) > Armature_ArmatureAction_transform
        // (1 channel, Armature_Bone/transform), 40 keys, stride 16, times "0.04166662" ..
        // "1.666667", no <library_animation_clips>; key 0 = 1 0 0 1  0 1 0 -1  0 0 1 0  0 0 0 1.
        Model m = read("S11_box_nested_animation.dae");
        assertEquals(1, m.clips().size());
        AnimationClip clip = m.clips().get(0);
        assertEquals("default", clip.name());
        assertEquals(1, clip.channels().size());
        AnimationChannel c = clip.channels().get(0);
        assertEquals("Armature_Bone/transform", c.target());
        assertEquals(m.nodeById("Armature_Bone").orElseThrow().index(), c.node());
        assertEquals(0, c.valueOffset());
        assertEquals(16, c.valueCount());
        assertEquals(40, c.track().keyCount());
        assertEquals(0.04166662f, clip.start(), EXACT);
        assertEquals(1.666667f, clip.end(), EXACT);
        assertEquals(1f, c.track().value(0, 3), EXACT);
        assertEquals(-1f, c.track().value(0, 7), EXACT);
        assertNoAnimationWarnings(m);
    }

    @Test
    void s12HasTheClipsBendAndTurnWithSixChannelsEach() throws Exception {
        // Script: two <animation_clip>s without ids: "bend" start="0.041666666666666664"
        // end="0.625" over id-anim-13..18, "turn" start="0.0" end="0.8333333333333333" over
        // id-anim-19..24. 12 channels in all, one per animation, each a whole matrix (stride 16):
        // id-anim-13..18 have 15 keys (0.0 .. 0.5833333333333334), id-anim-19..24 have 21 keys
        // (0.0 .. 0.8333333333333333). Targets, in order: Armature, id-bone-7, -4, -5, -6, -3.
        Model m = read("S12_library_animation_clips.dae");
        assertEquals(2, m.clips().size());
        List<String> targets = List.of("Armature/transform", "id-bone-7/transform", "id-bone-4/transform",
                "id-bone-5/transform", "id-bone-6/transform", "id-bone-3/transform");

        AnimationClip bend = m.clips().get(0);
        assertEquals("bend", bend.name());
        assertNull(bend.id());
        assertEquals(0.041666666666666664f, bend.start(), EXACT);
        assertEquals(0.625f, bend.end(), EXACT);
        assertEquals(targets, bend.channels().stream().map(AnimationChannel::target).collect(Collectors.toList()));
        for (AnimationChannel c : bend.channels()) {
            assertEquals(15, c.track().keyCount(), c.target());
            assertEquals(16, c.valueCount(), c.target());
            assertEquals(0.5833333333333334f, c.track().endTime(), EXACT, c.target());
        }

        AnimationClip turn = m.clips().get(1);
        assertEquals("turn", turn.name());
        assertNull(turn.id());
        assertEquals(0f, turn.start(), EXACT);
        assertEquals(0.8333333333333333f, turn.end(), EXACT);
        assertEquals(targets, turn.channels().stream().map(AnimationChannel::target).collect(Collectors.toList()));
        for (AnimationChannel c : turn.channels()) {
            assertEquals(21, c.track().keyCount(), c.target());
            assertEquals(16, c.valueCount(), c.target());
        }
        assertNoAnimationWarnings(m);
    }

    @Test
    void s03StormtrooperHasSixtyFiveMatrixChannelsOf116Keys() throws Exception {
        // Script: 65 top-level animations with one channel each, every target node/transform on a
        // <matrix sid="transform"> of a node in the scene (65 different nodes), 116 keys per
        // channel, stride 16, times "0.0333333" .. "3.866667", no clips. First channel:
        // mixamorig_Hips/transform, key 0 translation y (value 7) = 1.793601.
        Model m = read("S03_stormtrooper.dae");
        assertEquals(1, m.clips().size());
        AnimationClip clip = m.clips().get(0);
        assertEquals("default", clip.name());
        assertEquals(65, clip.channels().size());
        for (AnimationChannel c : clip.channels()) {
            assertEquals(116, c.track().keyCount(), c.target());
            assertEquals(16, c.valueCount(), c.target());
            assertEquals(0, c.valueOffset(), c.target());
            assertTrue(c.target().endsWith("/transform"), c.target());
        }
        assertEquals(65, clip.channels().stream().map(AnimationChannel::node).distinct().count(),
                "one channel per node");
        assertEquals(0.0333333f, clip.start(), EXACT);
        assertEquals(3.866667f, clip.end(), EXACT);
        AnimationChannel hips = clip.channels().get(0);
        assertEquals("mixamorig_Hips/transform", hips.target());
        assertEquals(1.793601f, hips.track().value(0, 7), EXACT);
        assertNoAnimationWarnings(m);
    }
}
