package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.AnimationXml.animation;
import static org.skinlab.collada.AnimationXml.document;

import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;

/**
 * Clips: {@code <library_animation_clips>} read as named clips over the channels of the
 * animations they instance (nested ones included), the one "default" clip when a file has no
 * clips, a clip without end, and clips that are refused.
 */
class ClipImportTest {
    /** Start and end are copied from the file (as floats) or from key times: exact. */
    private static final float EXACT = 0f;

    private static final String NODE = """
                  <node id="N">
                    <translate sid="translate">0 0 0</translate>
                    <rotate sid="rotateX">1 0 0 0</rotate>
                  </node>
            """;

    /**
     * walk (no channel of its own) > walk-x (translate.X, 0..1 s) and walk-y (translate.Y,
     * 0..1.5 s); wave (rotateX.ANGLE, 0.25..2 s); idle (translate.Z, 0..3 s).
     */
    private static final String ANIMATIONS = "    <animation id=\"walk\">\n"
            + animation("walk-x", "N/translate.X", "0 0.5 1", "0 1 0", 1)
            + animation("walk-y", "N/translate.Y", "0 1.5", "0 1", 1)
            + "    </animation>\n"
            + animation("wave", "N/rotateX.ANGLE", "0.25 1 2", "0 45 0", 1)
            + animation("idle", "N/translate.Z", "0 3", "0 0.1", 1);

    private static List<String> targets(AnimationClip clip) {
        return clip.channels().stream().map(AnimationChannel::target).collect(Collectors.toList());
    }

    @Test
    void clipsWithIdsAndNamesWithIdsOnlyAndWithNeither() {
        String clips = """
                    <animation_clip id="clip-walk" name="Walk" start="0" end="1.5">
                      <instance_animation url="#walk"/>
                    </animation_clip>
                    <animation_clip id="Wave" start="0.25" end="2">
                      <instance_animation url="#wave"/>
                    </animation_clip>
                    <animation_clip start="0.5" end="2.75">
                      <instance_animation url="#idle"/>
                    </animation_clip>
                """;
        Model m = Fixtures.read("clips.dae", document(NODE, ANIMATIONS, clips));
        // Exactly the three clips of the file: no "default" clip beside them.
        assertEquals(3, m.clips().size());
        AnimationClip walk = m.clips().get(0);
        assertEquals("clip-walk", walk.id());
        assertEquals("Walk", walk.name());
        AnimationClip wave = m.clips().get(1);
        assertEquals("Wave", wave.id());
        assertEquals("Wave", wave.name());
        AnimationClip third = m.clips().get(2);
        assertNull(third.id());
        assertEquals("clip-3", third.name());
        // Start and end in seconds, as written (not frames, not clamped to the keys).
        assertEquals(0f, walk.start(), EXACT);
        assertEquals(1.5f, walk.end(), EXACT);
        assertEquals(0.25f, wave.start(), EXACT);
        assertEquals(2f, wave.end(), EXACT);
        assertEquals(0.5f, third.start(), EXACT);
        assertEquals(2.75f, third.end(), EXACT);
        assertEquals(2.25f, third.duration(), EXACT);
        assertEquals(m.clip("Walk").orElseThrow(), walk);
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void clipOfAParentAnimationIncludesItsNestedChannels() {
        String clips = """
                    <animation_clip id="walk-clip" start="0" end="1.5">
                      <instance_animation url="#walk"/>
                    </animation_clip>
                """;
        Model m = Fixtures.read("clip-nested.dae", document(NODE, ANIMATIONS, clips));
        assertEquals(1, m.clips().size());
        assertEquals(List.of("N/translate.X", "N/translate.Y"), targets(m.clips().get(0)));
        assertEquals(3, m.clips().get(0).channels().get(0).track().keyCount());
        assertEquals(2, m.clips().get(0).channels().get(1).track().keyCount());
    }

    @Test
    void clipThatInstancesAParentAndItsNestedAnimationHasEachChannelOnce() {
        // walk contains walk-x: instancing both must not drive translate.X twice.
        String clips = """
                    <animation_clip id="both" start="0" end="1.5">
                      <instance_animation url="#walk"/>
                      <instance_animation url="#walk-x"/>
                    </animation_clip>
                """;
        Model m = Fixtures.read("clip-overlap.dae", document(NODE, ANIMATIONS, clips));
        assertEquals(List.of("N/translate.X", "N/translate.Y"), targets(m.clips().get(0)));
    }

    @Test
    void twoClipsSelectDifferentSubsetsOfTheChannels() {
        // "upper" takes wave and the nested walk-y only; "lower" takes walk-x and idle.
        String clips = """
                    <animation_clip id="upper" start="0" end="2">
                      <instance_animation url="#wave"/>
                      <instance_animation url="#walk-y"/>
                    </animation_clip>
                    <animation_clip id="lower" start="0" end="3">
                      <instance_animation url="#walk-x"/>
                      <instance_animation url="#idle"/>
                    </animation_clip>
                """;
        Model m = Fixtures.read("clip-subsets.dae", document(NODE, ANIMATIONS, clips));
        assertEquals(2, m.clips().size());
        assertEquals(List.of("N/rotateX.ANGLE", "N/translate.Y"), targets(m.clip("upper").orElseThrow()));
        assertEquals(List.of("N/translate.X", "N/translate.Z"), targets(m.clip("lower").orElseThrow()));
        // The channel of walk-x in "lower" is the one read from the file: its 3 keys.
        assertEquals(3, m.clip("lower").orElseThrow().channels().get(0).track().keyCount());
    }

    @Test
    void withoutClipsOneDefaultClipSpansAllChannelsFromTheEarliestToTheLatestKey() {
        // "late" has keys 0.5..2 s, "early" 0.25..1 s: the start comes from one channel, the end
        // from the other.
        String animations = animation("late", "N/translate.X", "0.5 1 2", "0 1 2", 1)
                + animation("early", "N/translate.Y", "0.25 1", "0 1", 1);
        Model m = Fixtures.read("default-clip.dae", document(NODE, animations));
        assertEquals(1, m.clips().size());
        AnimationClip clip = m.clips().get(0);
        assertEquals(AnimationClip.DEFAULT_NAME, clip.name());
        assertEquals("default", clip.name());
        assertNull(clip.id());
        assertEquals(0.25f, clip.start(), EXACT);
        assertEquals(2f, clip.end(), EXACT);
        assertEquals(List.of("N/translate.X", "N/translate.Y"), targets(clip));
        assertEquals(List.of(), m.warnings());
    }

    @Test
    void defaultClipOfTheNestedTestAnimationsSpansZeroToThree() {
        // walk-x 0..1, walk-y 0..1.5 (both nested in walk), wave 0.25..2, idle 0..3 => 0..3.
        Model m = Fixtures.read("default-all.dae", document(NODE, ANIMATIONS));
        AnimationClip clip = m.clips().get(0);
        assertEquals(4, clip.channels().size());
        assertEquals(0f, clip.start(), EXACT);
        assertEquals(3f, clip.end(), EXACT);
    }

    @Test
    void aChannelWithoutKeysIsSkippedWithAWarningAndDoesNotStretchTheDefaultClip() {
        // "empty" has count="0" times and values; "keyed" runs from 1 to 2 s. Were the empty
        // channel kept, its start and end (0) would make the default clip start at 0.
        String animations = animation("empty", "N/translate.X", "", "", 1)
                + animation("keyed", "N/translate.Y", "1 2", "0 1", 1);
        Model m = Fixtures.read("empty-sampler.dae", document(NODE, animations));
        AnimationClip clip = m.clips().get(0);
        assertEquals(List.of("N/translate.Y"), targets(clip));
        assertEquals(1f, clip.start(), EXACT);
        assertEquals(2f, clip.end(), EXACT);
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        assertTrue(m.warnings().get(0).message().contains("no keys"), m.warnings()::toString);
    }

    @Test
    void noAnimationsMeansNoClips() {
        Model m = Fixtures.read("no-animation.dae", document(NODE, ""));
        assertEquals(List.of(), m.clips());
    }

    @Test
    void clipWithoutEndEndsAtItsLastKeyWithAWarning() {
        // walk: walk-x ends at 1 s, walk-y at 1.5 s => 1.5; idle (3 s) is not in the clip.
        String clips = """
                    <animation_clip id="open" start="0.5">
                      <instance_animation url="#walk"/>
                    </animation_clip>
                """;
        Model m = Fixtures.read("clip-no-end.dae", document(NODE, ANIMATIONS, clips));
        AnimationClip clip = m.clips().get(0);
        assertEquals(0.5f, clip.start(), EXACT);
        assertEquals(1.5f, clip.end(), EXACT);
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        assertTrue(m.warnings().get(0).element().startsWith("<animation_clip id=\"open\">"), m.warnings()::toString);
        assertTrue(m.warnings().get(0).message().contains("no end"), m.warnings()::toString);
    }

    // ----------------------------------------------------------------------------- refused

    @Test
    void instanceAnimationUrlThatRefersToNothingIsRefused() {
        String clips = """
                    <animation_clip id="broken" start="0" end="1">
                      <instance_animation url="#walk"/>
                      <instance_animation url="#run"/>
                    </animation_clip>
                """;
        ColladaException e = Fixtures.error("clip-dangling.dae", document(NODE, ANIMATIONS, clips));
        assertEquals("clip-dangling.dae", e.file());
        assertTrue(e.element().startsWith("<instance_animation> in <animation_clip id=\"broken\">"), e::getMessage);
        assertTrue(e.problem().contains("#run") && e.problem().contains("refers to nothing"), e::getMessage);
    }

    @Test
    void instanceAnimationUrlThatRefersToANodeIsRefused() {
        String clips = """
                    <animation_clip id="odd" start="0" end="1">
                      <instance_animation url="#N"/>
                    </animation_clip>
                """;
        ColladaException e = Fixtures.error("clip-node.dae", document(NODE, ANIMATIONS, clips));
        assertTrue(e.element().contains("<animation_clip id=\"odd\">"), e::getMessage);
        assertTrue(e.problem().contains("<node>"), e::getMessage);
    }

    @Test
    void clipThatEndsBeforeItStartsIsRefused() {
        String clips = """
                    <animation_clip id="backwards" start="2" end="1">
                      <instance_animation url="#wave"/>
                    </animation_clip>
                """;
        ColladaException e = Fixtures.error("clip-backwards.dae", document(NODE, ANIMATIONS, clips));
        assertTrue(e.element().startsWith("<animation_clip id=\"backwards\">"), e::getMessage);
        assertTrue(e.problem().contains("before start"), e::getMessage);
    }
}
